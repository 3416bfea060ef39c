"""Model-vs-measurement discrepancy workflow (issue 6): find where the model
misses measured data, name the missing effect the data support, show the gap
shrink -- and refuse to name one the data cannot support.

Pipeline of :func:`diagnose`:

1. residual audit per quantity and speed band (mean residual/sigma, chi^2)
   and the residual's shape per quantity: polynomial bases in speed (none,
   offset, slope, growth = quadratic) and a local feature (offset + one
   point) compared by AIC = chi^2 + 2 k (Gaussian errors, known sigma);
2. identifiability: each candidate's fingerprint (its prediction change over
   sigma on the measured points, finite difference at the null value),
   pairwise cosine similarity, look-alike pairs (|cos| > 0.95) and the
   quantity/speed (on a speed grid over all supported quantities) where
   the two best-matched fingerprints differ most;
3. screening: each candidate added alone to the baseline and calibrated
   within its bounds on the training points, scored by BIC = chi^2 + k ln n
   and by chi^2 on held-out points (highest speeds or given runs);
4. acceptance: delta-BIC >= 10 against the baseline, held-out chi^2
   improved, the 95 % profile interval (chi^2 rise 3.84) inside the bounds
   and excluding the null value, no rival within delta-BIC 2 (else a tie
   set). Accepted effects join the baseline and the screening repeats while
   the reduced chi^2 of the training residual fails the chi^2 test at 1 %;
5. a verdict that says what each accepted candidate is: a missing effect
   (a registry switch or a term the baseline leaves out), a miscalibrated
   baseline input (f0, spin friction coefficient, cooling and ambient
   temperatures, housing material), or a measurement-side sensor offset;
   a tie set; "no missing effect supported"; or "structured residual not
   explained by any known effect";
6. the held-out gap before/after per quantity and speed band.

Model specs: :class:`BearingModelSpec` (one bearing, quantities
:data:`QUANTITIES`) and :class:`thermobear.SpindleModelSpec` (the seed B
spindle with its rotor) follow one protocol -- ``quantities``,
``candidate_list(quantities)``, ``predict(conditions)``,
``with_setting(add_effects, **options)``, ``options``, ``effects`` -- and
:func:`diagnose` runs the same statistics on either.

Speed: every model configuration (effects + options + parameter value) is
evaluated once on the measured conditions and cached in the
:class:`BearingModelSpec`; a parameter candidate is evaluated on a fixed grid
of values over its bounds and calibrated on a cubic interpolant of the
predictions, so re-diagnosing new noise on the same conditions costs no
model run.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Optional, Sequence, Union

import numpy as np

from .errors import ConfigError, DataError, ThermobearError

__all__ = [
    "BearingModelSpec",
    "Diagnosis",
    "QUANTITIES",
    "candidates",
    "diagnose",
    "load_measurements",
    "synthetic_measurements",
    "typical_sigma",
]

#: Supported measured quantities: model column, scale to the quantity's
#: unit, plausible range (lo, hi) and a typical measurement uncertainty
#: (used for sigma when the data give none and to weigh the extra-
#: measurement suggestion): thermocouples +-0.5 K, stiffness and heat 2 %.
QUANTITIES: dict[str, tuple[str, float, tuple[float, float], float, bool]] = {
    # name: (column, scale, (lo, hi), typical sigma, sigma is relative)
    "temperature_c:Ts": ("shaft_temperature_c", 1.0, (-60.0, 250.0), 0.5, False),
    "temperature_c:Ti": ("inner_ring_temperature_c", 1.0, (-60.0, 250.0), 0.5, False),
    "temperature_c:Tb": ("ball_temperature_c", 1.0, (-60.0, 250.0), 0.5, False),
    "temperature_c:To": ("outer_ring_temperature_c", 1.0, (-60.0, 250.0), 0.5, False),
    "temperature_c:Th": ("housing_temperature_c", 1.0, (-60.0, 250.0), 0.5, False),
    "radial_stiffness_n_per_m": ("radial_stiffness_n_per_m", 1.0, (1e5, 1e11), 0.02, True),
    "axial_stiffness_n_per_m": ("axial_stiffness_n_per_m", 1.0, (1e5, 1e11), 0.02, True),
    "heat_w": ("heat_w", 1.0, (0.0, 1e5), 0.02, True),
    "axial_displacement_um": ("axial_displacement_mm", 1000.0, (-1e4, 1e4), 0.5, False),
    "inner_contact_angle_deg": ("inner_contact_angle_max_deg", 1.0, (0.0, 90.0), 0.2, False),
}

_NODE_NAMES = {
    "Ts": "shaft",
    "Ti": "inner ring",
    "Tb": "balls",
    "To": "outer ring",
    "Th": "housing",
}

# Parameter candidates: (name, option, unit, lo, hi, offset?, description).
# Bounds: f0 0.5-6 spans Palmgren's f0 for oil-air / oil-mist (1-2) up to
# oil bath and jet (4-6) (Harris & Kotzalas, Rolling Bearing Analysis,
# table of f0); spin friction coefficient 0-0.3 (boundary to dry contact);
# oil-air and ambient temperatures +-10/+20 K (cooling-air supply drift);
# extra bearing heat 0-100 W (up to about the whole friction heat of a
# 40-45 mm angular-contact bearing at 18000 rpm, the seed B magnetic-pull
# friction being a fraction of it); housing-to-ambient conductance scale
# 0.1-10 (a decade either way of natural convection from the bare cylinder:
# an enclosed, insulated housing below, a finned or ventilated one or one
# conducting into the machine frame above; natural and slow forced air
# convection coefficients differ by about a decade, 5-10 vs 25-100 W/m^2K);
# churning oil volume fraction X of the cavity mixture 0-5 % (0: dry air;
# our assumed upper end for a jet-lubricated, partly flooded cavity -- an oil
# bath is the f0 range above; at 5 % a 7008C at 18,000 rpm dissipates
# ~90 W of ball drag, about half its total friction heat).
_PARAMETERS = (
    # (name, option, unit, lower, upper, offset?, role, description)
    ("lubrication_factor_f0", "lubrication_factor_f0", "1", 0.5, 6.0, False, "calibration",
     "viscous friction moment scale (Palmgren f0)"),
    ("spin_friction_coefficient", "spin_friction", "1", 0.0, 0.3, False, "calibration",
     "spin friction coefficient mu_s (needs the spin_friction effect on)"),
    ("oil_air_temperature_offset_k", "oil_air_temperature_c", "K", -10.0, 20.0, True,
     "calibration", "oil-air (cooling) temperature differs from the assumed one"),
    ("ambient_temperature_offset_k", "ambient_temperature_c", "K", -10.0, 20.0, True,
     "calibration", "ambient temperature differs from the assumed one"),
    ("extra_heat_w", "extra_heat_w", "W", 0.0, 100.0, False, "effect",
     "extra heat at the bearing (e.g. magnetic-pull friction), split like rolling heat"),
    ("housing_conductance_scale", "housing_conductance_scale", "1", 0.1, 10.0, False, "effect",
     "housing-to-ambient conductance differs from the bare natural-convection cylinder"),
    ("churning_oil_fraction", "churning_oil_fraction", "1", 0.0, 0.05, False, "effect",
     "churning: drag of the balls in the oil-air mixture, ~ speed^3 (oil volume fraction X)"),
)  # fmt: skip

#: ``affects`` of an effect that acts only in the spindle or rotor model.
_NOT_IN_BEARING = "not in the single-bearing model"
_HOUSING_MATERIALS = ("aluminium", "cast-iron", "shaft-steel")
_THERMAL_DEFAULTS = {
    "lubricant": "e-drive ATF",
    "lubrication_factor_f0": 1.0,
    "spin_friction": 0.06,
    "oil_air_temperature_c": 28.0,
    "ambient_temperature_c": 26.0,
    "housing_material": "aluminium",
    "raceway_control": "outer",
    "extra_heat_w": 0.0,
    "housing_conductance_scale": 1.0,
    "churning_oil_fraction": 0.0,
}


#: Effects that are switches and also have a calibratable coefficient:
#: name -> (option, unit, lower, upper); bounds as in :data:`_PARAMETERS`.
_SWITCH_COEFFICIENTS = {"spin_friction": ("spin_friction", "1", 0.0, 0.3)}
#: Switches that are off in the default models (the rotor's default leaves
#: the magnetic pull out: its inputs are an assumption about the motor).
_OFF_BY_DEFAULT = ("unbalanced_magnetic_pull",)


def effect_registry(kind: Optional[str] = None) -> "polars.DataFrame":  # noqa: F821
    """The effects registry (``thermobear.effects()``): one row per physical
    effect. ``name``; ``kind``: "switch" (a named effect, on when listed in
    ``effects=[...]``) or "term" (an input whose ``off`` value leaves the
    term out, e.g. ``extra_heat_w`` = 0); ``models``: the models it acts in
    (comma-joined: bearing, spindle, rotor); ``parameter``, ``unit``,
    ``lower``, ``upper``: the calibratable input and its physical bounds
    ("on", 0-1 for a plain switch); ``default``: its value in the default
    model; ``off``: the value without the effect; ``description``."""
    import polars as pl

    from . import _native

    if kind not in (None, "switch", "term"):
        raise ConfigError(f"invalid kind = {kind!r}: None, 'switch' or 'term'")
    rows = []
    for name, desc, models in _native.effects():
        on = 0.0 if name in _OFF_BY_DEFAULT else 1.0
        if name in _SWITCH_COEFFICIENTS:
            opt, unit, lo, hi = _SWITCH_COEFFICIENTS[name]
            rows.append(
                (name, "switch", ",".join(models), opt, unit, lo, hi,
                 float(_THERMAL_DEFAULTS[opt]) * on, 0.0, desc)
            )  # fmt: skip
        else:
            rows.append((name, "switch", ",".join(models), "on", "1", 0.0, 1.0, on, 0.0, desc))
    for name, opt, unit, lo, hi, _off, role, desc in _PARAMETERS:
        if role == "effect":
            null = float(_THERMAL_DEFAULTS[opt])
            rows.append((name, "term", "bearing", opt, unit, lo, hi, null, null, desc))
    df = pl.DataFrame(
        rows,
        schema=["name", "kind", "models", "parameter", "unit", "lower", "upper", "default",
                "off", "description"],
        orient="row",
    )  # fmt: skip
    return df if kind is None else df.filter(pl.col("kind") == kind)


# --------------------------------------------------------------------------
# measured data


def load_measurements(data: Any, quantities: Optional[dict] = None) -> "polars.DataFrame":  # noqa: F821
    """Read and check a tidy measurement table (CSV or parquet path, or a
    polars/pandas frame). ``quantities``: the quantity registry of the model
    the data are for (default :data:`QUANTITIES`, the single bearing's; a
    model spec's is its ``quantities`` attribute).

    Columns: ``speed_rpm``; ``axial_n`` or ``preload_n`` (the preload is the
    axial load of a single bearing); optional ``radial_n`` (default 0);
    ``quantity`` (one of :data:`QUANTITIES`); ``value``; optional ``sigma``
    (same unit as the value; default: the quantity's typical uncertainty);
    optional ``run`` (label). Raises :class:`DataError` for a missing column,
    an unknown quantity, a non-numeric, NaN or infinite value, a sigma <= 0,
    a negative speed, and values outside the quantity's plausible range: a
    ``temperature_c`` quantity whose values are all 200-500 is reported as
    given in kelvin; stiffness must be 1e5-1e11 N/m (values below look like
    N/um), heat 0-1e5 W, contact angle 0-90 deg.
    """
    import polars as pl

    if isinstance(data, (str, Path)):
        p = Path(data)
        try:
            df = pl.read_parquet(p) if p.suffix == ".parquet" else pl.read_csv(p)
        except Exception as e:  # noqa: BLE001  (polars raises several types)
            raise DataError(f"invalid measurements = {p}: cannot read: {e}") from None
    elif isinstance(data, pl.DataFrame):
        df = data
    elif hasattr(data, "to_dict") and hasattr(data, "columns"):
        df = pl.from_pandas(data)
    else:
        raise DataError(f"invalid measurements = {type(data).__name__}: give a path or a frame")
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
    for c in ("speed_rpm", "axial_n", "radial_n", "value") + (
        ("sigma",) if "sigma" in df.columns else ()
    ):
        try:
            x = df[c].cast(pl.Float64, strict=True).to_numpy()
        except Exception:  # noqa: BLE001
            raise DataError(f"invalid {c}: not numeric (dtype {df[c].dtype})") from None
        bad = ~np.isfinite(x)
        if bad.any():
            i = int(np.argmax(bad))
            raise DataError(f"invalid {c} = {x[i]} in row {i}: NaN, infinite or missing")
        df = df.with_columns(pl.Series(c, x))
    if (df["speed_rpm"] < 0).any():
        raise DataError(f"invalid speed_rpm = {df['speed_rpm'].min()}: negative")
    if (df["axial_n"] < 0).any():
        raise DataError(f"invalid axial_n = {df['axial_n'].min()}: negative")
    table = QUANTITIES if quantities is None else quantities
    df = df.with_columns(pl.col("quantity").cast(pl.Utf8))
    for q in df["quantity"].unique().to_list():
        if q not in table:
            raise DataError(f"invalid quantity = {q!r}: known: {', '.join(table)}")
        v = df.filter(pl.col("quantity") == q)["value"].to_numpy()
        lo, hi = table[q][2]
        if q.startswith("temperature_c") and np.all((v > 200.0) & (v < 500.0)):
            raise DataError(
                f"invalid value = {v[0]} for {q}: looks like kelvin; give deg C (subtract 273.15)"
            )
        if np.any(v < lo) or np.any(v > hi):
            w = v[(v < lo) | (v > hi)][0]
            raise DataError(f"invalid value = {w} for {q}: outside the plausible {lo:g}..{hi:g}")
    if "sigma" in df.columns:
        if (df["sigma"] <= 0).any():
            raise DataError(f"invalid sigma = {df['sigma'].min()}: must be > 0")
    else:
        s = typical_sigma(table, df["quantity"].to_list(), df["value"].to_numpy())
        df = df.with_columns(pl.Series("sigma", s))
    if "run" not in df.columns:
        df = df.with_columns(pl.lit("1").alias("run"))
    df = df.with_columns(pl.col("run").cast(pl.Utf8))
    return df.select(["speed_rpm", "axial_n", "radial_n", "quantity", "value", "sigma", "run"])


def typical_sigma(table: dict, quantities: Sequence[str], values: np.ndarray) -> np.ndarray:
    """Typical measurement uncertainty of each value, from a quantity
    registry (``table[q][3]``: absolute, or relative when ``table[q][4]``)."""
    typ = np.array([table[q][3] for q in quantities], dtype=float)
    rel = np.array([table[q][4] for q in quantities], dtype=bool)
    return np.where(rel, typ * np.abs(np.asarray(values, dtype=float)), typ)


def synthetic_measurements(
    truth: Any,
    conditions: "polars.DataFrame",  # noqa: F821
    noise: float = 1.0,
    seed: int = 0,
) -> "polars.DataFrame":  # noqa: F821
    """Synthetic "measurements" for testing a diagnosis: ``truth``'s
    prediction of each row of ``conditions`` (operating columns and
    ``quantity``; ``preload_n`` may stand for ``axial_n``) plus Gaussian
    noise of ``noise`` times the quantity's typical uncertainty
    (:func:`typical_sigma` over ``truth.quantities``), with that sigma as
    the ``sigma`` column; reproducible by ``seed``."""
    import polars as pl

    cond = conditions
    if "preload_n" in cond.columns:
        cond = cond.rename({"preload_n": "axial_n"})
    p = truth.predict(cond)
    q = conditions["quantity"].to_list()
    value = np.array([p[qq][i] for i, qq in enumerate(q)])
    sig = noise * typical_sigma(truth.quantities, q, value)
    rng = np.random.default_rng(seed)
    return conditions.with_columns(
        pl.Series("value", value + rng.normal(size=len(value)) * sig), pl.Series("sigma", sig)
    )


# --------------------------------------------------------------------------
# the model


class BearingModelSpec:
    """The baseline model of one bearing: :class:`~thermobear.Bearing`,
    ``effects`` (names; None = all) and the keyword options of
    :func:`thermobear.thermal_state` (``lubricant``,
    ``lubrication_factor_f0``, ``spin_friction``, ``oil_air_temperature_c``,
    ``ambient_temperature_c``, ``housing_material``, ``raceway_control``,
    ``extra_heat_w``, ``housing_conductance_scale``).
    Evaluates every quantity of :data:`QUANTITIES` at given conditions; each
    configuration is solved once per set of conditions (cached).

    The protocol :func:`diagnose` uses (a spec of another machine, such as
    :class:`thermobear.SpindleModelSpec`, provides the same): ``quantities``
    (the quantity registry), ``candidate_list(quantities)``,
    ``predict(conditions)``, ``with_setting(add_effects, **options)``,
    ``options``, ``effects``."""

    #: The quantities this model predicts (see :data:`QUANTITIES`).
    quantities = QUANTITIES

    def __init__(self, bearing: Any, effects: Optional[Sequence[str]] = None, **options: Any):
        from . import _native
        from .bearing import Bearing

        if not isinstance(bearing, Bearing):
            raise ConfigError(f"invalid bearing = {bearing!r}: give a thermobear.Bearing")
        known = [n for n, *_ in _native.effects()]
        eff = list(known) if effects is None else [str(e) for e in effects]
        for e in eff:
            if e not in known:
                raise ConfigError(f"invalid effect = {e!r}: known: {', '.join(known)}")
        for k in options:
            if k not in _THERMAL_DEFAULTS:
                raise ConfigError(
                    f"invalid option = {k!r}: known: {', '.join(sorted(_THERMAL_DEFAULTS))}"
                )
        self.bearing = bearing
        self.effects = tuple(sorted(eff))
        self.options = {**_THERMAL_DEFAULTS, **options}
        self._cache: dict = {}

    def with_setting(self, add_effects: Sequence[str] = (), **options: Any) -> "BearingModelSpec":
        """A copy with effects added and options replaced (shares the cache)."""
        new = object.__new__(BearingModelSpec)
        new.bearing = self.bearing
        new.effects = tuple(sorted(set(self.effects) | set(add_effects)))
        new.options = {**self.options, **options}
        new._cache = self._cache
        return new

    @property
    def model_runs(self) -> int:
        """Model sweeps solved so far (one per configuration and load case;
        shared by the copies of :meth:`with_setting`)."""
        return len(self._cache)

    def _key(self) -> tuple:
        return (self.effects, tuple(sorted((k, str(v)) for k, v in self.options.items())))

    def predict(self, conditions: "polars.DataFrame") -> dict[str, np.ndarray]:  # noqa: F821
        """Every supported quantity at each row of ``conditions``
        (``speed_rpm``, ``axial_n``, ``radial_n``): name -> array."""
        from .thermal import thermal_stiffness_curve

        sp = conditions["speed_rpm"].to_numpy()
        ax = conditions["axial_n"].to_numpy()
        ra = conditions["radial_n"].to_numpy()
        out = {q: np.empty(len(sp)) for q in QUANTITIES}
        for a, r in sorted(set(zip(ax.tolist(), ra.tolist()))):
            rows = np.flatnonzero((ax == a) & (ra == r))
            speeds = np.unique(sp[rows])
            key = (self._key(), a, r, tuple(speeds.tolist()))
            if key not in self._cache:
                try:
                    df = thermal_stiffness_curve(
                        self.bearing, speeds, a, r, effects=list(self.effects), **self.options
                    )
                except ThermobearError as e:  # a failing configuration fails every time
                    self._cache[key] = e
                    raise
                self._cache[key] = {
                    q: df[c].to_numpy() * s for q, (c, s, *_rest) in QUANTITIES.items()
                }
            res = self._cache[key]
            if isinstance(res, ThermobearError):
                raise res
            idx = np.searchsorted(speeds, sp[rows])
            for q in QUANTITIES:
                out[q][rows] = res[q][idx]
        return out

    def candidate_list(self, quantities: Sequence[str] = ()) -> list["Candidate"]:
        """The candidates against this baseline, with a sensor-offset decoy
        per measured quantity in ``quantities``."""
        return _candidate_list(self, quantities)

    def __repr__(self) -> str:
        return f"BearingModelSpec({self.bearing!r}, effects={list(self.effects)})"


# --------------------------------------------------------------------------
# candidates


@dataclass(frozen=True)
class Candidate:
    name: str
    kind: str  # "switch" | "parameter"
    side: str  # "model" | "measurement"
    parameter: str
    unit: str
    lower: float
    upper: float
    null: float
    description: str
    affects: tuple[str, ...]
    option: str = ""
    offset: bool = False
    quantity: str = ""
    effect: str = ""
    #: "effect" (a physical term the baseline leaves out), "calibration" (a
    #: baseline input whose value may be off) or "measurement" (a decoy on
    #: the measurement side)
    role: str = "effect"
    relative: bool = False  # measurement offsets: relative (x (1 + v)) or additive


def _candidate_list(
    model: Optional[BearingModelSpec], quantities: Sequence[str] = ()
) -> list[Candidate]:
    from . import _native

    base_eff = set(model.effects) if model is not None else set()
    opts = model.options if model is not None else _THERMAL_DEFAULTS
    temps = tuple(q for q in QUANTITIES if q.startswith("temperature_c"))
    mech = tuple(q for q in QUANTITIES if not q.startswith("temperature_c"))
    out = []
    for name, desc, models in _native.effects():
        if name in base_eff:
            continue
        affects = tuple(QUANTITIES) if "bearing" in models else (_NOT_IN_BEARING,)
        out.append(
            Candidate(
                name,
                "switch",
                "model",
                f"{name}_on",
                "1",
                0.0,
                1.0,
                0.0,
                desc,
                affects,
                effect=name,
            )
        )
    for name, opt, unit, lo, hi, is_off, role, desc in _PARAMETERS:
        base = float(opts[opt])
        if is_off:
            null, lo_, hi_ = 0.0, lo, hi
        else:
            null, lo_, hi_ = base, min(lo, base), max(hi, base)
        out.append(
            Candidate(
                name,
                "parameter",
                "model",
                f"{name}" if is_off else f"{opt}",
                unit,
                lo_,
                hi_,
                null,
                desc,
                tuple(QUANTITIES),
                option=opt,
                offset=is_off,
                role=role,
            )
        )
    for mat in _HOUSING_MATERIALS:
        if mat != str(opts["housing_material"]):
            name = f"housing_material:{mat}"
            out.append(
                Candidate(
                    name,
                    "switch",
                    "model",
                    "housing_is_" + mat.replace("-", "_"),
                    "1",
                    0.0,
                    1.0,
                    0.0,
                    f"housing conductance/expansion of {mat}",
                    temps + mech,
                    option="housing_material",
                    role="calibration",
                )
            )
    out += sensor_offset_candidates(quantities, QUANTITIES)
    return out


def sensor_offset_candidates(quantities: Sequence[str], table: dict) -> list:
    """The measurement-side decoys: a constant offset per measured quantity
    (+-10 typical sigma, or +-20 % for relative quantities); ``table`` maps a
    quantity to its registry row (typical sigma at [3], relative flag at [4])."""
    out = []
    for q in quantities:
        typ, rel = table[q][3], table[q][4]
        unit = "K" if q.startswith("temperature_c") else q.rsplit("_", 1)[-1]
        bound = 10.0 * typ if not rel else 0.2
        out.append(
            Candidate(
                f"sensor_offset:{q}",
                "parameter",
                "measurement",
                "offset" if not rel else "relative_offset",
                "1" if rel else unit,
                -bound,
                bound,
                0.0,
                f"decoy: constant sensor offset on {q}",
                (q,),
                offset=True,
                quantity=q,
                role="measurement",
                relative=bool(rel),
            )
        )
    return out


def candidates(
    model: Optional[BearingModelSpec] = None, quantities: Sequence[str] = ()
) -> "polars.DataFrame":  # noqa: F821
    """The candidate registry against a baseline: ``name``, ``kind``
    ("switch" or "parameter"), ``role`` ("effect": a physical term the
    baseline leaves out; "calibration": a baseline input whose value may be
    off; "measurement": a sensor-offset decoy, one per measured quantity in
    ``quantities``), ``side`` ("model" or "measurement"), ``parameter``,
    ``unit``, ``lower``, ``upper`` (physical bounds), ``default`` (the null
    value: the baseline's), ``description``, ``affects``. Without ``model``
    the baseline is the default :func:`thermobear.thermal_state` options
    with no effect switched on (every effect is listed)."""
    import polars as pl

    table = QUANTITIES if model is None else model.quantities
    for q in quantities:
        if q not in table:
            raise ConfigError(f"invalid quantity = {q!r}: known: {', '.join(table)}")
    cs = _candidate_list(None, quantities) if model is None else model.candidate_list(quantities)
    return pl.DataFrame(
        {
            "name": [c.name for c in cs],
            "kind": [c.kind for c in cs],
            "role": [c.role for c in cs],
            "side": [c.side for c in cs],
            "parameter": [c.parameter for c in cs],
            "unit": [c.unit for c in cs],
            "lower": [c.lower for c in cs],
            "upper": [c.upper for c in cs],
            "default": [c.null for c in cs],
            "description": [c.description for c in cs],
            "affects": [", ".join(c.affects) for c in cs],
        }
    )


# --------------------------------------------------------------------------
# settings: the baseline plus applied candidates


@dataclass(frozen=True)
class _Setting:
    effects: tuple[str, ...] = ()
    options: tuple[tuple[str, Any], ...] = ()
    offsets: tuple[tuple[str, float, bool], ...] = ()  # (quantity, value, relative)

    def apply(self, c: Candidate, value: float, base_options: dict) -> "_Setting":
        opts = dict(self.options)
        if c.side == "measurement":
            return _Setting(
                self.effects, self.options, self.offsets + ((c.quantity, value, c.relative),)
            )
        if c.kind == "switch":
            if c.effect:
                return (
                    _Setting(
                        tuple(sorted(set(self.effects) | {c.effect})), self.options, self.offsets
                    )
                    if value >= 0.5
                    else self
                )
            if value < 0.5:
                return self
            opts[c.option] = c.name.split(":", 1)[1]
        else:
            cur = float(opts.get(c.option, base_options[c.option]))
            opts[c.option] = cur + value if c.offset else value
        return _Setting(self.effects, tuple(sorted(opts.items())), self.offsets)


def _predict(model: BearingModelSpec, st: _Setting, cond: Any, quantity: np.ndarray) -> np.ndarray:
    """Prediction of each measured row (its own quantity) under a setting."""
    m = model.with_setting(st.effects, **dict(st.options))
    allq = m.predict(cond)
    y = np.empty(len(quantity))
    for q in np.unique(quantity):
        rows = quantity == q
        y[rows] = allq[q][rows]
    for q, v, rel in st.offsets:
        rows = quantity == q
        y[rows] = y[rows] * (1.0 + v) if rel else y[rows] + v
    return y


# --------------------------------------------------------------------------
# statistics helpers


def _chi2(r: np.ndarray) -> float:
    return float(np.sum(r * r))


def _speed_bands(speed: np.ndarray, n_bands: int = 3) -> np.ndarray:
    lo, hi = float(speed.min()), float(speed.max())
    if hi <= lo:
        return np.array(["all"] * len(speed), dtype=object)
    edges = np.linspace(lo, hi, n_bands + 1)
    idx = np.clip(np.searchsorted(edges, speed, side="right") - 1, 0, n_bands - 1)
    names = [f"{edges[i]:.0f}-{edges[i + 1]:.0f} rpm" for i in range(n_bands)]
    return np.array([names[i] for i in idx], dtype=object)


def _band_key(band: str) -> float:
    return float(band.split("-")[0]) if band != "all" else 0.0


def _unit(u: str) -> str:
    return "" if u == "1" else f" {u}"


def residual_shape(speed: np.ndarray, r: np.ndarray) -> tuple[str, dict[str, float]]:
    """Shape of a residual (in sigma) against speed, chosen by AIC among
    none (k=0), offset (1), slope (2: 1, x), growth (3: 1, x, x^2 with
    x the speed scaled to [-1, 1]) and local feature (offset + the one point
    that helps most; k=3: the chosen location counts as a parameter)."""
    x = speed.astype(float)
    span = x.max() - x.min()
    x = (x - x.min()) / span * 2.0 - 1.0 if span > 0 else np.zeros_like(x)
    n = len(r)
    aic = {"none": _chi2(r)}
    bases = {"offset": [np.ones(n)], "slope": [np.ones(n), x], "growth": [np.ones(n), x, x * x]}
    for name, cols in bases.items():
        if n <= len(cols):
            continue
        a = np.column_stack(cols)
        coef, *_ = np.linalg.lstsq(a, r, rcond=None)
        aic[name] = _chi2(r - a @ coef) + 2.0 * len(cols)
    if n > 3:
        best = np.inf
        for i in range(n):
            e = np.zeros(n)
            e[i] = 1.0
            a = np.column_stack([np.ones(n), e])
            coef, *_ = np.linalg.lstsq(a, r, rcond=None)
            best = min(best, _chi2(r - a @ coef))
        aic["local feature"] = best + 6.0
    return min(aic, key=aic.get), aic


def _cosine(a: np.ndarray, b: np.ndarray) -> float:
    na, nb = np.linalg.norm(a), np.linalg.norm(b)
    if na == 0 or nb == 0:
        return 0.0
    return float(a @ b / (na * nb))


# --------------------------------------------------------------------------
# screening of one candidate


_GRID = 13  # parameter values evaluated per candidate (cubic interpolant between)
_DENSE = 601
_CHI2_95 = 3.841  # chi^2(1) 95 % quantile: profile interval


@dataclass
class _Curve:
    """Predictions of the measured rows against one candidate's parameter."""

    cand: Candidate
    values: np.ndarray  # parameter values with a model evaluation
    preds: np.ndarray  # (len(values), n_rows)

    def _spline(self) -> Any:
        if not hasattr(self, "_cs"):
            from scipy.interpolate import CubicSpline

            self._cs = CubicSpline(self.values, self.preds, axis=0)
        return self._cs

    def at(self, v: np.ndarray) -> np.ndarray:
        if self.cand.kind == "switch":
            idx = np.clip(np.rint(v), 0, 1).astype(int)
            return self.preds[idx]
        return self._spline()(v)

    def slope(self) -> np.ndarray:
        """d prediction / d parameter at the null value (switch: on - off)."""
        if self.cand.kind == "switch":
            return self.preds[-1] - self.preds[0]
        return self._spline()(self.cand.null, 1)


def _grid_with_null(grid: np.ndarray, null: float) -> np.ndarray:
    """The grid with the null value put on it: a grid point within a tiny
    fraction of the span of the null is replaced by it (two abscissae that
    differ only by rounding would break the interpolant)."""
    tol = 1e-6 * (grid[-1] - grid[0])
    keep = grid[np.abs(grid - null) > tol]
    return np.unique(np.concatenate([keep, [null]]))


def _curve(model, st, c, cond, quantity, base_options) -> Optional[_Curve]:
    from .errors import ThermobearError

    if c.kind == "switch":
        vals = np.array([0.0, 1.0])
    elif c.lower > 0.0 and c.upper >= 20.0 * c.lower:
        # A positive scale over decades: the response goes like 1/scale
        # (a conductance), so a geometric grid keeps the interpolant accurate
        # at the low end.
        vals = _grid_with_null(np.geomspace(c.lower, c.upper, _GRID), c.null)
    else:
        vals = _grid_with_null(np.linspace(c.lower, c.upper, _GRID), c.null)
    good, preds = [], []
    for v in vals:
        try:
            preds.append(_predict(model, st.apply(c, float(v), base_options), cond, quantity))
            good.append(v)
        except ThermobearError:
            continue
    if c.kind == "switch" and len(good) < 2 or c.kind != "switch" and len(good) < 4:
        return None
    return _Curve(c, np.asarray(good), np.asarray(preds))


def _fit(curve: _Curve, y, s, train) -> dict:
    c = curve.cand
    if c.kind == "switch":
        r = (y - curve.preds[-1]) / s
        return {
            "value": 1.0,
            "chi2": _chi2(r[train]),
            "lower_95": None,
            "upper_95": None,
            "pred": curve.preds[-1],
            "at_bound": False,
            "excludes_null": True,
        }
    lo, hi = curve.values.min(), curve.values.max()
    grid = np.linspace(lo, hi, _DENSE)
    p = curve.at(grid)
    chi = np.sum(((y[train] - p[:, train]) / s[train]) ** 2, axis=1)
    i = int(np.argmin(chi))
    from scipy.optimize import minimize_scalar

    a, b = grid[max(i - 1, 0)], grid[min(i + 1, _DENSE - 1)]
    best_v, best_c = grid[i], chi[i]
    if b > a:
        res = minimize_scalar(
            lambda v: float(
                np.sum(((y[train] - curve.at(np.array([v]))[0][train]) / s[train]) ** 2)
            ),
            bounds=(a, b),
            method="bounded",
            options={"xatol": (hi - lo) * 1e-6},
        )
        if res.fun < best_c:
            best_v, best_c = float(res.x), float(res.fun)

    # contiguous 95 % profile interval around the best value; the edges are
    # refined by root finding on the interpolant (the dense grid is coarse)
    def excess(v: float) -> float:
        p1 = curve.at(np.array([v]))[0]
        return float(np.sum(((y[train] - p1[train]) / s[train]) ** 2)) - best_c - _CHI2_95

    lo95 = _profile_edge(excess, grid, chi, best_v, best_c, -1)
    hi95 = _profile_edge(excess, grid, chi, best_v, best_c, +1)
    tol = (hi - lo) * 0.01
    return {
        "value": float(best_v),
        "chi2": float(best_c),
        "lower_95": lo95,
        "upper_95": hi95,
        "pred": curve.at(np.array([best_v]))[0],
        "at_bound": bool(best_v <= lo + tol or best_v >= hi - tol),
        "excludes_null": bool(not (lo95 <= c.null <= hi95)),
    }


def _profile_edge(excess, grid, chi, best_v, best_c, direction) -> float:
    """Edge of the contiguous 95 % profile interval around ``best_v`` on one
    side: the nearest dense-grid point beyond which chi^2 exceeds the
    minimum by 3.84 brackets the root of ``excess`` with the last point
    inside (or ``best_v`` itself when the interval is narrower than the
    grid spacing); the interval reaches the bound when no point is outside."""
    from scipy.optimize import brentq

    out = chi > best_c + _CHI2_95
    side = grid < best_v if direction < 0 else grid > best_v
    idx = np.flatnonzero(out & side)
    if idx.size == 0:
        return float(grid[0] if direction < 0 else grid[-1])
    j = int(idx[-1] if direction < 0 else idx[0])
    inner = grid[j + 1] if direction < 0 else grid[j - 1]
    inner = max(inner, best_v) if direction > 0 else min(inner, best_v)
    a, b = (grid[j], inner) if direction < 0 else (inner, grid[j])
    fa, fb = excess(a), excess(b)
    if fa * fb > 0.0:  # rounding at the bracket: the grid point is the edge
        return float(grid[j])
    return float(brentq(excess, a, b))


# --------------------------------------------------------------------------
# the workflow


@dataclass
class Diagnosis:
    """Result of :func:`diagnose` (tables are polars DataFrames).

    ``audit``: residual per quantity and speed band of the baseline
    (``n``, ``mean_residual_sigma``, ``rms_residual_sigma``) with the
    quantity's residual ``shape``; ``fingerprints``: pairwise cosine
    similarity of the candidates' fingerprints; ``lookalikes``: pairs with
    |cos| > 0.95 and the extra measurement (quantity, speed) that separates
    them best; ``screening``: one table per round (candidate, calibrated
    value, 95 % interval, delta_bic, held-out chi^2, passes); ``accepted``:
    the accepted candidates with value and interval; ``tie``: names of a
    tie set; ``verdict``: text; ``gap``: held-out rms residual/sigma per
    quantity and speed band before and after; ``points``: the measured rows
    with ``model_before``, ``model_after``, ``heldout``."""

    audit: Any
    fingerprints: Any
    lookalikes: Any
    screening: list
    accepted: list
    tie: list
    verdict: str
    gap: Any
    points: Any
    not_evaluable: list = field(default_factory=list)
    notes: list = field(default_factory=list)

    def summary(self) -> str:
        lines = [f"verdict: {self.verdict}"]
        for a in self.accepted:
            interval = (
                f" [{a['lower_95']:.4g}, {a['upper_95']:.4g}]{_unit(a['unit'])}"
                if a["lower_95"] is not None
                else " (switched on)"
            )
            lines.append(
                f"  accepted {a['name']}: {a['parameter']} = {a['value']:.4g}{interval}, "
                f"delta-BIC {a['delta_bic']:.1f}"
            )
        if self.tie:
            lines.append("  tie set: " + ", ".join(self.tie))
        for row in self.lookalikes.iter_rows(named=True):
            lines.append(
                f"  look-alikes {row['a']} ~ {row['b']} (cos {row['cosine']:.3f}): measure "
                f"{row['suggest_quantity']} at {row['suggest_speed_rpm']:.0f} rpm"
            )
        lines.append("held-out gap (rms residual / sigma):")
        for row in self.gap.iter_rows(named=True):
            lines.append(
                f"  {row['quantity']:28s} {row['speed_band']:18s} n={row['n']:3d} "
                f"before {row['rms_before_sigma']:8.2f}  after {row['rms_after_sigma']:8.2f}"
            )
        lines += [f"note: {n}" for n in self.notes]
        return "\n".join(lines)

    def __repr__(self) -> str:
        return f"Diagnosis(verdict={self.verdict!r})"


def _holdout_mask(df, holdout) -> np.ndarray:
    speed = df["speed_rpm"].to_numpy()
    if holdout is None or holdout == "none":
        return np.zeros(len(speed), dtype=bool)
    if isinstance(holdout, str) and holdout == "highest_speeds":
        holdout = 0.25
    if isinstance(holdout, (float, int)) and not isinstance(holdout, bool):
        frac = float(holdout)
        if not 0.0 < frac < 1.0:
            raise ConfigError(f"invalid holdout = {holdout}: a fraction in (0, 1)")
        us = np.unique(speed)
        if len(us) < 3:
            raise DataError(
                f"invalid measurements: {len(us)} distinct speeds; holding out the highest "
                "speeds needs at least 3"
            )
        k = min(max(1, int(round(frac * len(us)))), len(us) - 2)
        return speed >= us[-k]
    runs = [str(r) for r in (holdout if not isinstance(holdout, str) else [holdout])]
    have = set(df["run"].to_list())
    for r in runs:
        if r not in have:
            raise DataError(f"invalid holdout run = {r!r}: runs in the data: {sorted(have)}")
    mask = np.isin(df["run"].to_numpy(), runs)
    if mask.all():
        raise DataError("invalid holdout: every point is held out; no training data left")
    return mask


def _gap_table(df, r0, r1, mask):
    import polars as pl

    bands = _speed_bands(df["speed_rpm"].to_numpy())
    q = df["quantity"].to_numpy()
    rows = []
    for qq in sorted(set(q[mask].tolist())):
        for b in sorted(set(bands[mask & (q == qq)].tolist()), key=_band_key):
            m = mask & (q == qq) & (bands == b)
            rows.append(
                (
                    qq,
                    b,
                    int(m.sum()),
                    float(np.sqrt(np.mean(r0[m] ** 2))),
                    float(np.sqrt(np.mean(r1[m] ** 2))),
                )
            )
    return pl.DataFrame(
        rows,
        schema=["quantity", "speed_band", "n", "rms_before_sigma", "rms_after_sigma"],
        orient="row",
    )


def _audit(df, r):
    import polars as pl

    sp, q = df["speed_rpm"].to_numpy(), df["quantity"].to_numpy()
    bands = _speed_bands(sp)
    rows = []
    for qq in sorted(set(q.tolist())):
        mq = q == qq
        shape, _ = residual_shape(sp[mq], r[mq])
        for b in sorted(set(bands[mq].tolist()), key=_band_key):
            m = mq & (bands == b)
            rows.append(
                (
                    qq,
                    b,
                    int(m.sum()),
                    float(np.mean(r[m])),
                    float(np.sqrt(np.mean(r[m] ** 2))),
                    shape,
                )
            )
    return pl.DataFrame(
        rows,
        schema=[
            "quantity",
            "speed_band",
            "n",
            "mean_residual_sigma",
            "rms_residual_sigma",
            "shape",
        ],
        orient="row",
    )


def _suggest(model, st, ca, cb, fa, fb, df, base_options):
    """Quantity and speed where two look-alike fingerprints (b scaled to
    match a on the measured rows) differ most, over all supported
    quantities on a speed grid, in units of the typical uncertainty."""
    import polars as pl

    sp = df["speed_rpm"].to_numpy()
    grid = np.linspace(sp.min(), sp.max() * 1.25, 8)
    cond = pl.DataFrame(
        {
            "speed_rpm": grid,
            "axial_n": [float(df["axial_n"][0])] * 8,
            "radial_n": [float(df["radial_n"][0])] * 8,
        }
    )

    table = model.quantities

    def response(c):
        step = 1.0 if c.kind == "switch" else 0.05 * (c.upper - c.lower)
        v0 = 0.0 if c.kind == "switch" else c.null
        v1 = v0 + step if v0 + step <= c.upper else v0 - step
        out = {}
        for q in table:
            qa = np.array([q] * len(grid))
            p0 = _predict(model, st.apply(c, v0, base_options), cond, qa)
            p1 = _predict(model, st.apply(c, v1, base_options), cond, qa)
            out[q] = (p1 - p0) / (v1 - v0)
        return out

    from .errors import ThermobearError

    try:
        ra, rb = response(ca), response(cb)
    except ThermobearError:
        return "", float("nan")
    scale = float(fa @ fb / (fb @ fb)) if fb @ fb > 0 else 0.0
    best, where = -1.0, ("", float("nan"))
    for q in table:
        typ, rel = table[q][3], table[q][4]
        base = _predict(model, st, cond, np.array([q] * len(grid)))
        sig = np.abs(base) * typ if rel else np.full(len(grid), typ)
        d = np.abs(ra[q] - scale * rb[q]) / np.maximum(sig, 1e-300)
        i = int(np.argmax(d))
        if d[i] > best:
            best, where = float(d[i]), (q, float(grid[i]))
    return where


def _joint_refit(model, cands, accepted, cond, quantity, y, s, train, base_options):
    """Re-calibrate every accepted continuous parameter together (bounded
    least squares on the model itself, not the interpolant) once two or more
    are accepted: an effect calibrated alone absorbs part of the next one.
    Intervals: +-1.96 standard errors from the Jacobian, (J^T J)^-1.
    Updates ``accepted`` in place; returns (setting, prediction) or None."""
    from scipy.optimize import least_squares

    idx = [i for i, c in enumerate(cands) if c.kind == "parameter"]
    if len(idx) < 2:
        return None

    def setting(theta):
        st = _Setting((), (), ())
        vals = {i: t for i, t in zip(idx, theta)}
        for i, c in enumerate(cands):
            st = st.apply(c, float(vals.get(i, accepted[i]["value"])), base_options)
        return st

    def resid(theta):
        return ((y - _predict(model, setting(theta), cond, quantity)) / s)[train]

    x0 = np.array([accepted[i]["value"] for i in idx])
    lo = np.array([cands[i].lower for i in idx])
    hi = np.array([cands[i].upper for i in idx])
    try:
        res = least_squares(
            resid,
            np.clip(x0, lo, hi),
            bounds=(lo, hi),
            diff_step=1e-4,
            x_scale=hi - lo,
            max_nfev=60,
        )
        cov = np.linalg.inv(res.jac.T @ res.jac)
    except (ThermobearError, np.linalg.LinAlgError):
        return None
    se = np.sqrt(np.clip(np.diag(cov), 0.0, None))
    for k, i in enumerate(idx):
        accepted[i].update(
            value=float(res.x[k]),
            lower_95=float(max(lo[k], res.x[k] - 1.96 * se[k])),
            upper_95=float(min(hi[k], res.x[k] + 1.96 * se[k])),
            joint=True,
        )
    st = setting(res.x)
    return st, _predict(model, st, cond, quantity)


_SPEC_PROTOCOL = ("quantities", "candidate_list", "predict", "with_setting", "options", "effects")


def diagnose(
    model: BearingModelSpec,
    measured: Any,
    candidates: Optional[Sequence[str]] = None,
    holdout: Union[str, float, Sequence[str], None] = "highest_speeds",
    *,
    max_rounds: int = 3,
    delta_bic_min: float = 10.0,
    tie_delta_bic: float = 2.0,
    lookalike_cosine: float = 0.95,
    suggest: bool = True,
) -> Diagnosis:
    """Diagnose the gap between ``model`` (a :class:`BearingModelSpec`,
    the baseline) and ``measured`` (anything :func:`load_measurements`
    reads). ``candidates``: names from :func:`candidates` (default: all of
    them, with a sensor-offset decoy per measured quantity); ``holdout``:
    ``"highest_speeds"`` (the top quarter of the distinct speeds), a fraction
    of the distinct speeds, run label(s), or None. See the module docstring
    for the statistics; returns a :class:`Diagnosis`."""
    import polars as pl
    from scipy.stats import chi2 as chi2_dist

    if not all(hasattr(model, a) for a in _SPEC_PROTOCOL):
        raise ConfigError(
            f"invalid model = {model!r}: give a thermobear.BearingModelSpec or "
            "SpindleModelSpec (or an object with " + ", ".join(_SPEC_PROTOCOL) + ")"
        )
    df = load_measurements(measured, model.quantities)
    quantity = df["quantity"].to_numpy()
    y, s = df["value"].to_numpy(), df["sigma"].to_numpy()
    cond = df.select(["speed_rpm", "axial_n", "radial_n"])
    held = _holdout_mask(df, holdout)
    train = ~held
    n_train = int(train.sum())
    pool = model.candidate_list(sorted(set(quantity.tolist())))
    if candidates is not None:
        names = {c.name for c in pool}
        for n in candidates:
            if n not in names:
                raise ConfigError(f"invalid candidate = {n!r}: known: {', '.join(sorted(names))}")
        pool = [c for c in pool if c.name in set(candidates)]
    base_options = dict(model.options)
    # the spec already carries the baseline effects and options; a setting adds to them
    st = _Setting((), (), ())
    pred0 = _predict(model, st, cond, quantity)
    r0 = (y - pred0) / s
    audit = _audit(df, r0)
    notes, screening, accepted, tie = [], [], [], []
    not_evaluable = [c.name for c in pool if c.affects == (_NOT_IN_BEARING,)]
    pool = [c for c in pool if c.name not in not_evaluable]
    if not_evaluable:
        notes.append("not in the single-bearing model: " + ", ".join(not_evaluable))
    pred = pred0
    accepted_cands: list[Candidate] = []
    fingerprints = lookalikes = None
    verdict = ""
    for rnd in range(max_rounds):
        r = (y - pred) / s
        chi_base = _chi2(r[train])
        chi_held = _chi2(r[held]) if held.any() else 0.0
        p_noise = float(chi2_dist.sf(chi_base, n_train))
        if rnd > 0 and p_noise > 0.01:
            break
        curves = {}
        for c in pool:
            cu = _curve(model, st, c, cond, quantity, base_options)
            if cu is None:
                not_evaluable.append(c.name)
                continue
            if np.max(np.abs(cu.slope() / s)) < 1e-9:
                not_evaluable.append(c.name)
                notes.append(f"{c.name}: no effect on the measured quantities")
                continue
            curves[c.name] = cu
        pool = [c for c in pool if c.name in curves]
        # identifiability (first round: fingerprints around the baseline)
        fp = {n: cu.slope() / s for n, cu in curves.items()}
        if fingerprints is None:
            names = list(fp)
            pairs, la = [], []
            for i, a in enumerate(names):
                for b in names[i + 1 :]:
                    cs = _cosine(fp[a], fp[b])
                    pairs.append((a, b, cs))
                    if abs(cs) > lookalike_cosine:
                        q, v = ("", float("nan"))
                        if suggest:
                            q, v = _suggest(
                                model,
                                st,
                                curves[a].cand,
                                curves[b].cand,
                                fp[a],
                                fp[b],
                                df,
                                base_options,
                            )
                        la.append((a, b, cs, q, v))
            fingerprints = pl.DataFrame(pairs, schema=["a", "b", "cosine"], orient="row")
            lookalikes = pl.DataFrame(
                la,
                schema={
                    "a": pl.Utf8,
                    "b": pl.Utf8,
                    "cosine": pl.Float64,
                    "suggest_quantity": pl.Utf8,
                    "suggest_speed_rpm": pl.Float64,
                },
                orient="row",
            )
        # screening
        bic0 = chi_base
        rows, fits = [], {}
        for name, cu in curves.items():
            f = _fit(cu, y, s, train)
            fits[name] = f
            rr = (y - f["pred"]) / s
            bic = f["chi2"] + np.log(n_train)
            held_after = _chi2(rr[held]) if held.any() else 0.0
            held_ok = (held_after < chi_held) if held.any() else True
            dbic = bic0 - bic
            interval_ok = cu.cand.kind == "switch" or (f["excludes_null"] and not f["at_bound"])
            rows.append(
                {
                    "candidate": name,
                    "kind": cu.cand.kind,
                    "side": cu.cand.side,
                    "value": f["value"],
                    "lower_95": f["lower_95"],
                    "upper_95": f["upper_95"],
                    "null": cu.cand.null,
                    "chi2_train": f["chi2"],
                    "delta_bic": dbic,
                    "heldout_chi2_before": chi_held,
                    "heldout_chi2_after": held_after,
                    "passes": bool(dbic >= delta_bic_min and held_ok and interval_ok),
                }
            )
        table = pl.DataFrame(rows).sort("delta_bic", descending=True) if rows else pl.DataFrame()
        screening.append(table.with_columns(pl.lit(rnd + 1).alias("round")) if rows else table)
        passing = [row for row in rows if row["passes"]]
        if not passing:
            break
        best = max(passing, key=lambda row: row["delta_bic"])
        rivals = [
            row["candidate"]
            for row in rows
            if row["candidate"] != best["candidate"]
            and best["delta_bic"] - row["delta_bic"] < tie_delta_bic
        ]
        if rivals:
            tie = [best["candidate"]] + rivals
            break
        cu = curves[best["candidate"]]
        c = cu.cand
        accepted.append(
            {
                "name": c.name,
                "side": c.side,
                "role": c.role,
                "parameter": c.parameter,
                "null": c.null,
                "unit": c.unit,
                "value": best["value"],
                "lower_95": best["lower_95"],
                "upper_95": best["upper_95"],
                "delta_bic": best["delta_bic"],
                "round": rnd + 1,
            }
        )
        st = st.apply(c, best["value"], base_options)
        pred = fits[c.name]["pred"]
        pool = [p for p in pool if p.name != c.name]
        accepted_cands.append(c)
        joint = _joint_refit(
            model, accepted_cands, accepted, cond, quantity, y, s, train, base_options
        )
        if joint is not None:
            st, pred = joint
    r1 = (y - pred) / s
    p_final = float(chi2_dist.sf(_chi2(r1[train]), n_train))
    parts = [_verdict_part(a) for a in accepted]
    if tie:
        parts.append("tie: " + " | ".join(tie) + " (the data cannot tell them apart)")
    if parts:
        verdict = "; ".join(parts)
    elif p_final < 0.01:
        verdict = "structured residual not explained by any known effect"
    else:
        verdict = "no missing effect supported"
    if accepted and p_final < 0.01:
        notes.append(f"residual after the accepted effects still above noise (p = {p_final:.2g})")
    gap = _gap_table(df, r0, r1, held if held.any() else np.ones(len(y), dtype=bool))
    if not held.any():
        notes.append("no held-out points: the gap table uses all points")
    points = df.with_columns(
        pl.Series("model_before", pred0),
        pl.Series("model_after", pred),
        pl.Series("heldout", held),
    )
    return Diagnosis(
        audit,
        fingerprints,
        lookalikes,
        screening,
        accepted,
        tie,
        verdict,
        gap,
        points,
        sorted(set(not_evaluable)),
        notes,
    )


def _verdict_part(a: dict) -> str:
    """One accepted candidate in words, by its role."""
    u = _unit(a["unit"])
    if a["lower_95"] is None:
        interval = ""
    else:
        interval = f"95 % [{a['lower_95']:.4g}, {a['upper_95']:.4g}]"
    if a["role"] == "measurement":
        return f"measurement-side {a['name']} = {a['value']:.4g}{u} ({interval})"
    if a["role"] == "calibration":
        return (
            f"miscalibrated baseline parameter {a['name']}: {a['parameter']} = "
            f"{a['value']:.4g}{u} (baseline {a['null']:.4g}{u}; {interval})"
            if interval
            else f"miscalibrated baseline setting {a['name']}"
        )
    return f"missing effect {a['name']}" + (
        f" ({a['parameter']} = {a['value']:.4g}{u}, {interval})" if interval else ""
    )


# --------------------------------------------------------------------------
# system descriptions and the command line


def model_from_toml(path_or_text: Union[str, Path]) -> tuple[BearingModelSpec, dict]:
    """The baseline :class:`BearingModelSpec` of a system description
    ([bearing], [model] effects, raceway_control, extra_heat_w and
    housing_conductance_scale; the other thermal options take their
    :func:`thermobear.thermal_state` defaults) and its [operating]
    table (loads for measurements that give none)."""
    from .bearing import Bearing
    from .config import load_config
    from .demo import _toml

    text = load_config(path_or_text)
    cfg = _toml(text)
    mdl = cfg.get("model", {})
    opts = {}
    if "raceway_control" in mdl:
        opts["raceway_control"] = mdl["raceway_control"]
    for key in ("extra_heat_w", "housing_conductance_scale", "churning_oil_fraction"):
        if key in mdl:
            opts[key] = float(mdl[key])
    spec = BearingModelSpec(Bearing.from_toml(text), effects=mdl.get("effects"), **opts)
    return spec, cfg.get("operating", {})


def diagnose_files(
    measured: Union[str, Path],
    system: Union[str, Path, None] = None,
    out: Optional[Path] = None,
    *,
    spindle: Optional[str] = None,
    without: Sequence[str] = (),
) -> tuple[Diagnosis, list[Path]]:
    """``thermobear diagnose``: diagnose a measurement file (CSV lines
    starting with ``#`` are comments) against a baseline -- a bearing system
    description (``system``, TOML) or a spindle preset (``spindle``, e.g.
    "seed-ceramic-spindle") -- with the effects in ``without`` (names, or
    "thermal_displacement" for a spindle) switched off; write tables (gap,
    audit, screening, points) and figures into ``out`` when given."""
    import polars as pl

    if (system is None) == (spindle is None):
        raise ConfigError("invalid baseline: give a system description (--model) or --spindle")
    p = Path(measured)
    try:
        df = pl.read_parquet(p) if p.suffix == ".parquet" else pl.read_csv(p, comment_prefix="#")
    except Exception as e:  # noqa: BLE001
        raise DataError(f"invalid measurements = {p}: cannot read: {e}") from None
    if spindle is not None:
        from .diagnosis_spindle import SpindleModelSpec
        from .spindle import Spindle

        full = SpindleModelSpec(Spindle.preset(spindle))
        drop = set(full._expand(list(without))) if without else set()
        spec: Any = SpindleModelSpec(
            full.spindle, effects=[e for e in full.effects if e not in drop]
        )
    else:
        spec, op = model_from_toml(system)
        for w in without:
            if w not in spec.effects:
                raise ConfigError(
                    f"invalid without = {w!r}: not an effect of the baseline "
                    f"({', '.join(spec.effects)})"
                )
        spec = BearingModelSpec(
            spec.bearing, effects=[e for e in spec.effects if e not in set(without)], **spec.options
        )
        if "axial_n" not in df.columns and "preload_n" not in df.columns:
            df = df.with_columns(pl.lit(float(op.get("axial_n", 0.0))).alias("axial_n"))
        if "radial_n" not in df.columns:
            df = df.with_columns(pl.lit(float(op.get("radial_n", 0.0))).alias("radial_n"))
    n_speeds = df["speed_rpm"].n_unique() if "speed_rpm" in df.columns else 0
    d = diagnose(spec, df, holdout="highest_speeds" if n_speeds >= 3 else None)
    files: list[Path] = []
    if out is not None:
        from . import plot
        from .demo import save_figure, write_table

        files += write_table(d.gap, out, "diagnosis_gap")
        files += write_table(d.audit, out, "diagnosis_audit")
        files += write_table(pl.concat(d.screening, how="diagonal"), out, "diagnosis_screening")
        files += write_table(d.points, out, "diagnosis_points")
        for i, q in enumerate(sorted(set(d.points["quantity"].to_list()))):
            files.append(save_figure(plot.diagnosis_fit(d, q), out, f"diagnosis_fit_{i}"))
        files.append(save_figure(plot.diagnosis_residuals(d), out, "diagnosis_residuals"))
    return d, files
