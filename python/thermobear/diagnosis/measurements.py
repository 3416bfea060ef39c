"""Step 0 of [`thermobear.diagnose`][thermobear.diagnose]: the measured data. The bearing's
quantity registry (``QUANTITIES``), reading and checking a tidy
measurement table, typical uncertainties, synthetic measurements for tests,
and the held-out points."""

from __future__ import annotations

import difflib
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any, Optional, Sequence, Union

import numpy as np

from ..errors import ConfigError, DataError

if TYPE_CHECKING:
    import polars

#: Supported measured quantities: model column, scale to the quantity's
#: unit, plausible range (lo, hi) and a typical measurement uncertainty
#: (used for sigma when the data give none and to weigh the extra-
#: measurement suggestion): thermocouples +-0.5 K, stiffness and heat 2 %.
QUANTITIES: dict[str, tuple[str, float, tuple[float, float], float, bool]] = {
    # name: (column, scale, (lo, hi), typical sigma, sigma is relative)
    "shaft_temperature_c": ("shaft_temperature_c", 1.0, (-60.0, 250.0), 0.5, False),
    "inner_ring_temperature_c": ("inner_ring_temperature_c", 1.0, (-60.0, 250.0), 0.5, False),
    "ball_temperature_c": ("ball_temperature_c", 1.0, (-60.0, 250.0), 0.5, False),
    "outer_ring_temperature_c": ("outer_ring_temperature_c", 1.0, (-60.0, 250.0), 0.5, False),
    "housing_temperature_c": ("housing_temperature_c", 1.0, (-60.0, 250.0), 0.5, False),
    "radial_stiffness_seed_n_per_m": (
        "radial_stiffness_seed_n_per_m", 1.0, (1e5, 1e11), 0.02, True,
    ),
    "axial_stiffness_seed_n_per_m": ("axial_stiffness_seed_n_per_m", 1.0, (1e5, 1e11), 0.02, True),
    "k_xx_n_per_m": ("k_xx_n_per_m", 1.0, (1e5, 1e11), 0.02, True),
    "k_zz_n_per_m": ("k_zz_n_per_m", 1.0, (1e5, 1e11), 0.02, True),
    "heat_w": ("heat_w", 1.0, (0.0, 1e5), 0.02, True),
    "axial_displacement_um": ("axial_displacement_um", 1.0, (-1e4, 1e4), 0.5, False),
    "inner_contact_angle_deg": ("inner_contact_angle_max_deg", 1.0, (0.0, 90.0), 0.2, False),
    # a probe zeroed at a reference speed: the change of axial_displacement_um
    # from there (thermobear.diagnosis.relative; the model column is the absolute one)
    "axial_displacement_change_um": ("axial_displacement_um", 1.0, (-1e4, 1e4), 0.5, False),
}  # fmt: skip

#: The columns a measurement table may have; any other is refused (a
#: misspelt ``RADIAL_N`` must not become a radial load of 0).
KNOWN_COLUMNS = (
    "speed_rpm",
    "axial_n",
    "preload_n",
    "radial_n",
    "quantity",
    "value",
    "sigma",
    "run",
)

#: Accepted shaft speeds of a measurement [rpm]: above 0 for every quantity
#: that needs the shaft turning (temperatures, heat, growth, vibration;
#: ``STATIC_QUANTITIES`` may be measured at standstill), and at most
#: 500,000 rpm, beyond the fastest ball-bearing machines in service (dental
#: air turbines, turbomolecular pumps). A value past it is a unit mistake.
SPEED_RANGE_RPM = (0.0, 500_000.0)

#: Accepted loads of a measurement [N]: axial load or preload 0 .. 1e6 N,
#: radial load -1e6 .. 1e6 N (a meganewton is far past the static load
#: rating of any bearing a spindle or gearbox rig carries).
LOAD_LIMIT_N = 1e6

#: Quantities that can be measured with the shaft at rest (speed 0 allowed).
STATIC_QUANTITIES = frozenset(
    {
        "radial_stiffness_seed_n_per_m",
        "axial_stiffness_seed_n_per_m",
        "k_xx_n_per_m",
        "k_zz_n_per_m",
        "inner_contact_angle_deg",
    }
)

#: The least default sigma of a quantity whose typical uncertainty is
#: relative, in the quantity's own unit, so that a reading of 0 (or near
#: it) never gets sigma 0: heat 0.5 W (the resolution of a heat balance on
#: a rig, assumed); stiffness 2,000 N/m (2 % of the least plausible
#: stiffness, 1e5 N/m); operating preload 1 N (a load washer's resolution,
#: assumed); vibration velocity 0.01 mm/s (a vibrometer's noise floor,
#: assumed). A relative quantity not listed here takes its typical fraction
#: of 1e-3 times the larger end of its plausible range.
SIGMA_FLOOR: dict[str, float] = {
    "heat_w": 0.5,
    "radial_stiffness_seed_n_per_m": 2e3,
    "axial_stiffness_seed_n_per_m": 2e3,
    "k_xx_n_per_m": 2e3,
    "k_zz_n_per_m": 2e3,
    "operating_preload_n": 1.0,
    "velocity_rms_mm_s": 0.01,
}

#: Older quantity names -> the current ones (accepted with a
#: ``DeprecationWarning`` for one release).
RENAMED_QUANTITIES: dict[str, str] = {
    "temperature_c:Ts": "shaft_temperature_c",
    "temperature_c:Ti": "inner_ring_temperature_c",
    "temperature_c:Tb": "ball_temperature_c",
    "temperature_c:To": "outer_ring_temperature_c",
    "temperature_c:Th": "housing_temperature_c",
    "radial_stiffness_n_per_m": "radial_stiffness_seed_n_per_m",
    "axial_stiffness_n_per_m": "axial_stiffness_seed_n_per_m",
    "temperature_c:front_outer": "front_outer_ring_temperature_c",
    "temperature_c:rear_outer": "rear_outer_ring_temperature_c",
    "temperature_c:front_inner": "front_inner_ring_temperature_c",
    "temperature_c:rear_inner": "rear_inner_ring_temperature_c",
    "temperature_c:front_housing": "front_housing_temperature_c",
    "temperature_c:rear_housing": "rear_housing_temperature_c",
}

#: Quantity registries whose operating condition is a preload (``preload_n``
#: column; a spindle's) rather than an axial load (a single bearing's).
PRELOAD_REGISTRIES: list[dict] = []

#: Quantity registries of gear pairs (transition speeds of their
#: bifurcation diagrams): a row's condition is its input torque, bearing
#: stiffness case and sweep direction, not a load
#: (``thermobear.diagnosis.gear_spec``).
GEAR_REGISTRIES: list[dict] = []

#: The columns of a gear measurement table.
GEAR_COLUMNS = (
    "speed_rpm",
    "torque_n_m",
    "stiffness",
    "direction",
    "quantity",
    "value",
    "sigma",
    "run",
)
#: The bearing stiffness cases and sweep directions a gear row may name.
GEAR_STIFFNESS_CASES = ("constant", "speed", "thermal", "any")
GEAR_DIRECTIONS = ("up", "down", "any")


def current_quantity(name: str, stacklevel: int = 3) -> str:
    """The current name of a quantity (an older one warns)."""
    new = RENAMED_QUANTITIES.get(name)
    if new is None:
        return name
    from .._deprecation import warn_renamed

    warn_renamed(f"quantity {name}", new, stacklevel=stacklevel)
    return new


def _current_quantities(df: Any) -> Any:
    """The ``quantity`` column with the current names (older ones warn once
    each)."""
    import polars as pl

    if "quantity" not in df.columns:
        return df
    df = df.with_columns(pl.col("quantity").cast(pl.Utf8))
    old = [q for q in df["quantity"].unique().to_list() if q in RENAMED_QUANTITIES]
    if not old:
        return df
    for q in sorted(old):
        current_quantity(q, stacklevel=5)
    return df.with_columns(pl.col("quantity").replace(RENAMED_QUANTITIES))


def load_measurements(
    data: Any,
    quantities: Optional[dict] = None,
    *,
    model: Any = None,
    duplicates: str = "error",
) -> polars.DataFrame:
    """Read and check a tidy measurement table (CSV or parquet path, or a
    polars/pandas frame) for a bearing or a spindle. The model the data are
    for: ``model`` (a model spec, a [`Bearing`][thermobear.Bearing] or
    [`Spindle`][thermobear.Spindle], or the kind ``"bearing"`` /
    ``"spindle"``), or ``quantities`` (a quantity registry, e.g. a spec's
    ``quantities`` attribute); given neither, the kind whose quantities
    name every quantity in the table (the spindle's when both do and the
    table has a ``preload_n`` column; otherwise the bearing's,
    ``QUANTITIES``).

    Columns: ``speed_rpm``; ``axial_n`` or ``preload_n`` (the preload is the
    axial load of a single bearing); optional ``radial_n`` (default 0);
    ``quantity`` (one of ``QUANTITIES``); ``value``; optional ``sigma``
    (same unit as the value; default: the quantity's typical uncertainty);
    optional ``run`` (label, kept as text: ``"1"`` and ``"01"`` are two
    runs). Raises [`DataError`][thermobear.DataError] for a missing column,
    an unknown column (``KNOWN_COLUMNS``; with the nearest known name), an
    unknown quantity, a non-numeric, boolean, NaN or infinite value, a
    sigma <= 0, a speed outside ``SPEED_RANGE_RPM`` (0 only for
    ``STATIC_QUANTITIES``), a load past ``LOAD_LIMIT_N``, values outside
    the quantity's plausible range (a ``temperature_c`` quantity whose
    values are all 200-500 is reported as given in kelvin; stiffness must
    be 1e5-1e11 N/m (values below look like N/um), heat 0-1e5 W, contact
    angle 0-90 deg), and duplicate rows (the same quantity at the same
    speed, loads and run), unless ``duplicates="mean"``: then they are
    averaged (sigma of the mean sqrt(sum sigma^2) / n). A default sigma is
    never below the quantity's ``SIGMA_FLOOR``. The unit and reading checks
    of ``thermobear.diagnosis.plausible_data`` run too: a stiffness whose
    every value is 1e4 N/m or less is refused as N/um; a displacement
    whose every value is below 0.2 um, a heat of 0 at speed and a change
    quantity (``axial_displacement_change_um``: the
    change from the lowest speed of that quantity at the same loads and
    run, ``thermobear.diagnosis.relative``) that does not read about 0
    there warn ([`PlausibilityWarning`][thermobear.PlausibilityWarning]).
    """
    if duplicates not in ("error", "mean"):
        raise ConfigError(f"invalid duplicates = {duplicates!r}: 'error' or 'mean'")
    df = _current_quantities(_read_table(data))
    table = _registry_for(df, quantities, model)
    if any(table is t for t in GEAR_REGISTRIES):
        return _gear_table(df, table, duplicates)
    _known_columns(df)
    preload = any(table is t for t in PRELOAD_REGISTRIES)
    df = _operating_columns(_preload_column(df) if preload else df)
    df = _numeric_columns(df)
    from .plausible_data import check_readings, check_units

    check_units(df.with_columns(df["quantity"].cast(str)), table)  # N/um, mm
    df = _checked_quantities(df, table)
    _checked_conditions(df, "preload_n" if preload else "axial_n")
    df = _without_duplicates(_with_sigma_and_run(df, table), duplicates)
    check_readings(df, STATIC_QUANTITIES)  # warnings: heat 0 at speed, a change not 0
    return df.rename({"axial_n": "preload_n"}) if preload else df


def _known_columns(df: Any, known: Sequence[str] = KNOWN_COLUMNS) -> None:
    """Every column one of ``known`` (a DataError naming the nearest known
    one otherwise)."""
    unknown = [c for c in df.columns if c not in known]
    if not unknown:
        return
    parts = []
    for c in unknown:
        near = difflib.get_close_matches(str(c).lower(), list(known), n=1, cutoff=0.6)
        parts.append(f"{c}: did you mean {near[0]}?" if near else f"{c}")
    raise DataError(
        f"invalid measurements: unknown column(s) {'; '.join(parts)} "
        f"(known columns: {', '.join(known)})"
    )


def _gear_table(df: Any, table: dict, duplicates: str) -> Any:
    """A gear measurement table checked: ``GEAR_COLUMNS`` only;
    ``speed_rpm`` (where the transition was read), ``quantity``, ``value``
    required; ``torque_n_m`` optional (null: the model's torque);
    ``stiffness`` and ``direction`` default ``"any"``; speeds and values in
    ``SPEED_RANGE_RPM``; sigma > 0 or the quantity's typical one."""
    import polars as pl

    _known_columns(df, GEAR_COLUMNS)
    for c in ("speed_rpm", "quantity", "value"):
        if c not in df.columns:
            raise DataError(f"invalid measurements: missing column {c!r} (have {df.columns})")
    if df.height == 0:
        raise DataError("invalid measurements: the table has no rows")
    for c, default in (("stiffness", "any"), ("direction", "any")):
        if c not in df.columns:
            df = df.with_columns(pl.lit(default).alias(c))
    if "torque_n_m" not in df.columns:
        df = df.with_columns(pl.lit(None, dtype=pl.Float64).alias("torque_n_m"))
    for c in ("speed_rpm", "value") + (("sigma",) if "sigma" in df.columns else ()):
        x = _numbers(df[c], c)
        if not np.all(np.isfinite(x)):
            i = int(np.argmax(~np.isfinite(x)))
            raise DataError(f"invalid {c} = {x[i]} in row {i}: NaN, infinite or missing")
        df = df.with_columns(pl.Series(c, x))
    torque = df["torque_n_m"]
    if torque.dtype != pl.Float64:
        got = torque.cast(pl.Utf8).str.strip_chars().replace("", None)
        df = df.with_columns(pl.Series("torque_n_m", _nullable_numbers(got, "torque_n_m")))
    for c, allowed in (("stiffness", GEAR_STIFFNESS_CASES), ("direction", GEAR_DIRECTIONS)):
        df = df.with_columns(pl.col(c).cast(pl.Utf8).str.strip_chars())
        bad = [v for v in df[c].to_list() if v not in allowed]
        if bad:
            raise DataError(f"invalid {c} = {bad[0]!r}: one of {', '.join(allowed)}")
    df = _checked_quantities(df, table)
    lo, hi = SPEED_RANGE_RPM
    for c in ("speed_rpm", "value"):
        x = df[c].to_numpy()
        bad = (x <= lo) | (x > hi)
        if bad.any():
            i = int(np.argmax(bad))
            raise DataError(
                f"invalid {c} = {x[i]:g} in row {i}: a transition speed in {lo:g} < rpm <= {hi:g}"
            )
    df = _with_sigma_and_run(df, table, GEAR_COLUMNS)
    key = ["speed_rpm", "torque_n_m", "stiffness", "direction", "quantity", "run"]
    n = df.group_by(key).len().filter(pl.col("len") > 1)
    if n.height and duplicates == "error":
        r = n.row(0, named=True)
        raise DataError(
            f"invalid measurements: {n.height} duplicated measurement(s): {r['quantity']} at "
            f"speed_rpm={r['speed_rpm']:g}, stiffness={r['stiffness']}, direction="
            f"{r['direction']}, run={r['run']!r}: {r['len']} rows; give each its own run label "
            'or load with duplicates="mean"'
        )
    if n.height:
        df = (
            df.group_by(key, maintain_order=True)
            .agg(pl.col("value").mean(), (pl.col("sigma").pow(2).sum().sqrt() / pl.len()))
            .select(list(GEAR_COLUMNS))
        )
    return df


def _nullable_numbers(col: Any, name: str) -> Any:
    """A text column as floats, empty entries null; other text a DataError."""
    import polars as pl

    got = col.cast(pl.Float64, strict=False)
    bad = (got.is_null() & col.is_not_null()).to_numpy()
    if bad.any():
        i = int(np.argmax(bad))
        raise DataError(f"invalid {name} = {col[i]!r} in row {i}: not numeric")
    x = got.to_numpy()
    if np.any(~np.isfinite(x[~np.isnan(x)])):
        raise DataError(f"invalid {name}: not finite")
    return got


def _checked_conditions(df: Any, load_name: str) -> None:
    """Speeds in ``SPEED_RANGE_RPM`` (above 0 unless every quantity at that
    row is static) and loads within ``LOAD_LIMIT_N``."""
    lo, hi = SPEED_RANGE_RPM
    speed = df["speed_rpm"].to_numpy()
    moving = ~np.isin(df["quantity"].to_numpy(), list(STATIC_QUANTITIES))
    bad = (speed > hi) | (moving & (speed <= lo))
    if bad.any():
        i = int(np.argmax(bad))
        raise DataError(
            f"invalid speed_rpm = {speed[i]:g} in row {i} ({df['quantity'][i]}): the accepted "
            f"range is {lo:g} < speed_rpm <= {hi:g} (speed 0 only for "
            f"{', '.join(sorted(STATIC_QUANTITIES))})"
        )
    for col, name, least in (("axial_n", load_name, 0.0), ("radial_n", "radial_n", -LOAD_LIMIT_N)):
        x = df[col].to_numpy()
        bad = (x < least) | (x > LOAD_LIMIT_N)
        if bad.any():
            i = int(np.argmax(bad))
            raise DataError(
                f"invalid {name} = {x[i]:g} in row {i}: the accepted range is "
                f"{least:g} .. {LOAD_LIMIT_N:g} N"
            )


def _without_duplicates(df: Any, duplicates: str) -> Any:
    """The table with one row per quantity, speed, loads and run: repeats
    are a DataError naming them (conflicting values shown), or averaged
    with ``duplicates="mean"``."""
    import polars as pl

    key = ["speed_rpm", "axial_n", "radial_n", "quantity", "run"]
    groups = df.group_by(key, maintain_order=True).agg(
        pl.len().alias("n"),
        pl.col("value").mean().alias("mean"),
        (pl.col("sigma").pow(2).sum().sqrt() / pl.len()).alias("sigma_mean"),
        pl.col("value").alias("values"),
    )
    repeated = groups.filter(pl.col("n") > 1)
    if repeated.height == 0:
        return df
    if duplicates == "mean":
        return groups.select(
            key[:4] + [pl.col("mean").alias("value"), pl.col("sigma_mean").alias("sigma"), "run"]
        )
    shown = []
    for r in repeated.head(3).iter_rows(named=True):
        vals = sorted(set(r["values"]))
        what = (
            "conflicting values " + ", ".join(f"{v:g}" for v in vals)
            if len(vals) > 1
            else (f"value {vals[0]:g}")
        )
        shown.append(
            f"{r['quantity']} at speed_rpm={r['speed_rpm']:g}, axial/preload={r['axial_n']:g} N, "
            f"radial_n={r['radial_n']:g}, run={r['run']!r}: {r['n']} rows, {what}"
        )
    more = f" (and {repeated.height - 3} more)" if repeated.height > 3 else ""
    raise DataError(
        f"invalid measurements: {repeated.height} duplicated measurement(s): "
        f"{'; '.join(shown)}{more}; give each repeat its own run label, remove the copies, "
        'or load with duplicates="mean" to average them'
    )


def _preload_column(df: Any) -> Any:
    """A spindle table: its preload is ``preload_n``; an older ``axial_n``
    column for it warns and is read as ``preload_n``."""
    if "axial_n" in df.columns and "preload_n" not in df.columns:
        from .._deprecation import warn_renamed

        what = "the preload column of spindle data"
        warn_renamed("axial_n", "preload_n", stacklevel=4, what=what)
        df = df.rename({"axial_n": "preload_n"})
    return df


def _registry_for(df: Any, quantities: Optional[dict], model: Any) -> dict:
    """The quantity registry a table is checked against: ``quantities``,
    else ``model``'s, else the kind recognised from the table's quantities
    (``thermobear.diagnosis.protocol.kind_of_quantities``)."""
    from .protocol import MODEL_KINDS, kind_of_quantities, quantities_of

    if quantities is not None and model is not None:
        raise ConfigError("invalid model: give model or quantities, not both")
    if quantities is not None:
        return quantities
    if model is not None:
        return quantities_of(model)
    if "quantity" not in df.columns or not MODEL_KINDS:
        return QUANTITIES  # the checks name the missing column
    names = [str(q) for q in df["quantity"].unique().to_list()]
    kind = kind_of_quantities(names, has_preload="preload_n" in df.columns)
    return MODEL_KINDS[kind][2]


def _read_table(data: Any) -> Any:
    """A polars frame from a CSV or parquet path, a polars or a pandas frame."""
    import polars as pl

    if isinstance(data, (str, Path)):
        p = Path(data)
        try:
            if p.suffix == ".parquet":
                return pl.read_parquet(p)
            # Every column as text: run labels stay as written ("01"), and
            # numbers are parsed (and refused) by the checks, not guessed.
            return pl.read_csv(p, infer_schema=False, comment_prefix="#")
        except Exception as e:  # noqa: BLE001  (polars raises several types)
            raise DataError(f"invalid measurements = {p}: cannot read: {e}") from None
    if isinstance(data, pl.DataFrame):
        return data
    if hasattr(data, "to_dict") and hasattr(data, "columns"):
        return pl.from_pandas(data)
    raise DataError(f"invalid measurements = {type(data).__name__}: give a path or a frame")


def _operating_columns(df: Any) -> Any:
    """The required columns present; ``preload_n`` stored as ``axial_n``;
    ``radial_n`` 0 when missing; at least one row."""
    import polars as pl

    cols = set(df.columns)
    for c in ("speed_rpm", "quantity", "value"):
        if c not in cols:
            raise DataError(f"invalid measurements: missing column {c!r} (have {sorted(cols)})")
    if "axial_n" not in cols and "preload_n" not in cols:
        raise DataError("invalid measurements: missing column 'axial_n' or 'preload_n'")
    if "axial_n" not in cols:
        df = df.rename({"preload_n": "axial_n"})
    elif "preload_n" in cols:
        raise DataError("invalid measurements: give 'axial_n' or 'preload_n', not both")
    if "radial_n" not in df.columns:
        df = df.with_columns(pl.lit(0.0).alias("radial_n"))
    if df.height == 0:
        raise DataError("invalid measurements: the table has no rows")
    return df


def _numeric_columns(df: Any) -> Any:
    """Speeds, loads, values (and sigmas) as finite floats; speeds and
    axial loads not negative."""
    import polars as pl

    for c in ("speed_rpm", "axial_n", "radial_n", "value") + (
        ("sigma",) if "sigma" in df.columns else ()
    ):
        x = _numbers(df[c], c)
        bad = ~np.isfinite(x)
        if bad.any():
            i = int(np.argmax(bad))
            raise DataError(f"invalid {c} = {x[i]} in row {i}: NaN, infinite or missing")
        df = df.with_columns(pl.Series(c, x))
    if (df["speed_rpm"] < 0).any():
        raise DataError(f"invalid speed_rpm = {df['speed_rpm'].min()}: negative")
    if (df["axial_n"] < 0).any():
        raise DataError(f"invalid axial_n = {df['axial_n'].min()}: negative")
    return df


def _numbers(col: Any, name: str) -> np.ndarray:
    """A column as floats: numbers, or text that reads as a number;
    booleans (also written ``true``) and other text are a DataError naming
    the first such value."""
    import polars as pl

    if col.dtype == pl.Boolean:
        raise DataError(f"invalid {name}: booleans are not numbers (dtype Boolean)")
    if col.dtype == pl.Utf8:
        col = col.str.strip_chars()
    try:
        got = col.cast(pl.Float64, strict=False)
    except Exception:  # noqa: BLE001  (a dtype polars cannot cast at all)
        raise DataError(f"invalid {name}: not numeric (dtype {col.dtype})") from None
    bad = (got.is_null() & col.is_not_null()).to_numpy()
    if bad.any():
        i = int(np.argmax(bad))
        raise DataError(f"invalid {name} = {col[i]!r} in row {i}: not numeric")
    return got.to_numpy()


def _checked_quantities(df: Any, table: dict) -> Any:
    """Every quantity known to ``table`` and its values in the plausible
    range (temperatures all in 200-500 are reported as kelvin)."""
    import polars as pl

    df = df.with_columns(pl.col("quantity").cast(pl.Utf8))
    for q in df["quantity"].unique().to_list():
        if q not in table:
            raise DataError(
                f"invalid quantity = {q!r}: known: {', '.join(table)}{_other_kind_hint(q, table)}"
            )
        v = df.filter(pl.col("quantity") == q)["value"].to_numpy()
        lo, hi = table[q][2]
        if q.endswith("temperature_c") and np.all((v > 200.0) & (v < 500.0)):
            raise DataError(
                f"invalid value = {v[0]} for {q}: looks like kelvin; give deg C (subtract 273.15)"
            )
        if np.any(v < lo) or np.any(v > hi):
            w = v[(v < lo) | (v > hi)][0]
            raise DataError(f"invalid value = {w} for {q}: outside the plausible {lo:g}..{hi:g}")
    return df


def _other_kind_hint(quantity: str, table: dict) -> str:
    """A hint naming the model kind that knows ``quantity`` (empty when none)."""
    from .protocol import MODEL_KINDS

    for kind, (_, _, other) in MODEL_KINDS.items():
        if other is not table and quantity in other:
            return f"; {quantity!r} is a {kind} quantity: give model={kind!r} or a {kind} model"
    return ""


def _with_sigma_and_run(
    df: Any,
    table: dict,
    columns: Sequence[str] = ("speed_rpm", "axial_n", "radial_n", "quantity", "value", "sigma",
                              "run"),
) -> Any:  # fmt: skip
    """Sigma checked (> 0) or the typical one; run labels as text ("1"
    when missing); the tidy ``columns`` in order."""
    import polars as pl

    if "sigma" in df.columns:
        if (df["sigma"] <= 0).any():
            raise DataError(f"invalid sigma = {df['sigma'].min()}: must be > 0")
    else:
        s = default_sigma(table, df["quantity"].to_list(), df["value"].to_numpy())
        df = df.with_columns(pl.Series("sigma", s))
    if "run" not in df.columns:
        df = df.with_columns(pl.lit("1").alias("run"))
    df = df.with_columns(pl.col("run").cast(pl.Utf8))
    return df.select(list(columns))


def typical_sigma(table: dict, quantities: Sequence[str], values: np.ndarray) -> np.ndarray:
    """Typical measurement uncertainty of each value, from a quantity
    registry (``table[q][3]``: absolute, or relative when ``table[q][4]``)."""
    typ = np.array([table[q][3] for q in quantities], dtype=float)
    rel = np.array([table[q][4] for q in quantities], dtype=bool)
    return np.where(rel, typ * np.abs(np.asarray(values, dtype=float)), typ)


def default_sigma(table: dict, quantities: Sequence[str], values: np.ndarray) -> np.ndarray:
    """The sigma a value without one gets: its ``typical_sigma``, never
    below the quantity's ``sigma_floor`` (so always > 0)."""
    floor = np.array([sigma_floor(table, q) for q in quantities], dtype=float)
    s = np.maximum(typical_sigma(table, quantities, values), floor)
    bad = ~(s > 0)
    if bad.any():
        q = list(quantities)[int(np.argmax(bad))]
        raise DataError(
            f"invalid sigma for {q}: its registry gives no positive typical sigma; "
            "give a sigma column"
        )
    return s


def sigma_floor(table: dict, quantity: str) -> float:
    """The least default sigma of ``quantity`` in its own unit
    (``SIGMA_FLOOR``; for a relative quantity not listed there, its typical
    fraction of 1e-3 times the larger end of its plausible range)."""
    if quantity in SIGMA_FLOOR:
        return SIGMA_FLOOR[quantity]
    typ, rel = table[quantity][3], table[quantity][4]
    if not rel:
        return float(typ)
    lo, hi = table[quantity][2]
    return float(typ) * 1e-3 * max(abs(lo), abs(hi), 1.0)


def synthetic_measurements(
    truth: Any,
    conditions: polars.DataFrame,
    noise: float = 1.0,
    seed: int = 0,
) -> polars.DataFrame:
    """Synthetic "measurements" for testing a diagnosis: ``truth``'s
    prediction of each row of ``conditions`` (operating columns and
    ``quantity``; ``preload_n`` may stand for ``axial_n``) plus noise of
    ``noise`` times the quantity's typical uncertainty (``typical_sigma``
    over ``truth.quantities``), with that sigma as the ``sigma`` column;
    reproducible by ``seed``. The noise is Gaussian, and log-normal for a
    quantity whose uncertainty is relative, so that a positive quantity
    stays positive."""
    import polars as pl

    conditions = _current_quantities(conditions)
    cond = conditions
    if "preload_n" in cond.columns:
        cond = cond.rename({"preload_n": "axial_n"})
    p = truth.predict(cond)
    q = conditions["quantity"].to_list()
    value = np.array([p[qq][i] for i, qq in enumerate(q)])
    sig = noise * typical_sigma(truth.quantities, q, value)
    z = np.random.default_rng(seed).normal(size=len(value))
    relative = np.array([truth.quantities[qq][4] for qq in q], dtype=bool)
    return conditions.with_columns(
        pl.Series("value", _noisy_values(value, z, sig, relative)), pl.Series("sigma", sig)
    )


def _noisy_values(value: Any, z: Any, sigma: Any, relative: Any) -> Any:
    """``value`` with ``z`` standard-normal draws of noise of spread
    ``sigma``: ``value + z sigma``, except where ``relative`` (a quantity
    whose uncertainty is a fraction of itself: a stiffness, a heat, a
    vibration velocity, all positive) and the value is positive, where the
    noise is log-normal, ``value exp(z sigma / value)``: the same to first
    order in ``sigma / value``, but never negative (additive noise can turn
    a small vibration velocity negative, which no sensor reads)."""
    value, sigma = np.asarray(value, dtype=float), np.asarray(sigma, dtype=float)
    positive = np.asarray(relative, dtype=bool) & (value > 0.0)
    spread = np.where(positive, sigma / np.where(positive, value, 1.0), 0.0)
    return np.where(positive, value * np.exp(z * spread), value + z * sigma)


def holdout_mask(
    df: polars.DataFrame, holdout: Union[str, float, Sequence[str], None]
) -> np.ndarray:
    from .. import _validate as val

    speed = df["speed_rpm"].to_numpy()
    if holdout is None or (isinstance(holdout, str) and holdout == "none"):
        return np.zeros(len(speed), dtype=bool)
    if not (val.is_number(holdout) or isinstance(holdout, (str, list, tuple, np.ndarray))):
        raise val.fail(
            "holdout", holdout, "'highest_speeds', a fraction of the distinct speeds in (0, 1), "
            "run label(s) or None",
        )  # fmt: skip
    if isinstance(holdout, str) and holdout == "highest_speeds":
        holdout = 0.25
    if val.is_number(holdout):
        frac = val.real("holdout", holdout)
        if not 0.0 < frac < 1.0:
            raise val.fail("holdout", holdout, "a fraction of the distinct speeds in (0, 1)")
        us = np.unique(speed)
        if len(us) < 3:
            raise DataError(
                f"invalid measurements: {len(us)} distinct speeds; holding out the highest "
                "speeds needs at least 3 (holdout=None, --holdout none on the command line, "
                "diagnoses without the extrapolation check)"
            )
        k = min(max(1, int(round(frac * len(us)))), len(us) - 2)
        return speed >= us[-k]
    runs = val.names("holdout", holdout, one=True)  # run labels are text
    have = set(df["run"].to_list())
    for r in runs:
        if r not in have:
            raise DataError(f"invalid holdout run = {r!r}: runs in the data: {sorted(have)}")
    mask = np.isin(df["run"].to_numpy(), runs)
    if mask.all():
        raise DataError("invalid holdout: every point is held out; no training data left")
    return mask


#: At most this many cross-validation folds (operating cells beyond it share folds).
MAX_FOLDS = 20


def cv_folds(df: polars.DataFrame) -> np.ndarray:
    """Cross-validation fold of each row: one fold per operating cell (a
    speed, load and run: every quantity measured there is held out
    together, so a fold removes a whole condition, not one sensor), cells in
    order of speed, then load and run; beyond ``MAX_FOLDS`` cells the
    folds take the cells in turn (interleaved, so that every fold spans the
    speed range)."""
    keys = list(
        zip(
            df["speed_rpm"].to_list(),
            df["axial_n"].to_list(),
            df["radial_n"].to_list(),
            df["run"].to_list(),
            strict=False,
        )
    )
    cells = sorted(set(keys))
    index = {k: i % MAX_FOLDS for i, k in enumerate(cells)}
    return np.array([index[k] for k in keys], dtype=int)


@dataclass(frozen=True)
class MeasuredData:
    """The checked measurements of one diagnosis: the tidy table ``df``,
    each row's ``quantity``, value ``y`` and ``sigma`` ``s``, the operating
    conditions ``cond`` (``speed_rpm``, ``axial_n``, ``radial_n``), the
    held-out mask ``held`` (the extrapolation check), the cross-validation
    ``folds`` (``cv_folds``) and whether the table gave its sigmas."""

    df: Any
    quantity: np.ndarray
    y: np.ndarray
    s: np.ndarray
    cond: Any
    held: np.ndarray
    folds: np.ndarray
    sigma_given: bool = True

    @property
    def train(self) -> np.ndarray:
        """The training points of the extrapolation check (not held out)."""
        return ~self.held

    @property
    def n_train(self) -> int:
        return int(self.train.sum())

    @property
    def n(self) -> int:
        return len(self.y)

    def residual(self, pred: np.ndarray) -> np.ndarray:
        """(value - prediction) / sigma of every row."""
        return (self.y - pred) / self.s

    def subset(self, keep: np.ndarray) -> "MeasuredData":
        """The rows of ``keep`` (a boolean mask), folds renumbered."""
        df = self.df.filter(keep)
        return MeasuredData(
            df,
            self.quantity[keep],
            self.y[keep],
            self.s[keep],
            self.cond.filter(keep),
            self.held[keep],
            cv_folds(df),
            self.sigma_given,
        )


def prepare_measurements(measured: Any, quantities: dict, holdout: Any) -> MeasuredData:
    """Step 0: read and check ``measured`` against a quantity registry
    ([`load_measurements`][thermobear.load_measurements]), split off the held-out points of the
    extrapolation check (``holdout_mask``) and assign the
    cross-validation folds (``cv_folds``)."""
    given = _has_sigma(measured)
    df = load_measurements(measured, quantities)
    if "preload_n" in df.columns:  # a spindle's: the conditions keep one name inside
        df = df.rename({"preload_n": "axial_n"})
    return MeasuredData(
        df,
        df["quantity"].to_numpy(),
        df["value"].to_numpy(),
        df["sigma"].to_numpy(),
        with_reference_speeds(df, df.select(["speed_rpm", "axial_n", "radial_n"])),
        holdout_mask(df, holdout),
        cv_folds(df),
        given,
    )


def with_reference_speeds(df: polars.DataFrame, cond: polars.DataFrame) -> polars.DataFrame:
    """The conditions ``cond`` of a table ``df`` with a change quantity
    (``thermobear.diagnosis.relative``) with each row's reference speed
    (``reference_speed_rpm``: null on the other quantities' rows); as they
    are without one."""
    import polars as pl

    from .relative import REFERENCE_SPEED, has_changes, reference_speeds

    if not has_changes(df["quantity"].to_numpy()):
        return cond
    ref = pl.Series(REFERENCE_SPEED, reference_speeds(df), dtype=pl.Float64)
    return cond.with_columns(ref.fill_nan(None))


def _has_sigma(measured: Any) -> bool:
    """Whether a measured table (frame or path) has a ``sigma`` column."""
    if isinstance(measured, (str, Path)):
        try:
            return "sigma" in _read_table(measured).columns
        except DataError:
            return True  # load_measurements reports the unreadable file
    return "sigma" in list(getattr(measured, "columns", []))
