"""What a prediction is of and where: the quantities of each ``what``, the
operating conditions as a frame the model spec reads, and the unit of each
quantity (the tidy band frame carries it in a ``unit`` column)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Literal, Mapping, Sequence

import numpy as np

from .. import _validate
from ..errors import ConfigError
from ..glossary import GLOSSARY, SUFFIX_UNITS, UNIT_SUFFIXES

if TYPE_CHECKING:
    import polars

#: What [`predict`][thermobear.predict.band.predict] can predict.
What = Literal["measured", "stiffness", "temperatures", "growth", "vibration", "regimes"]
WHATS: tuple[str, ...] = ("measured", "stiffness", "temperatures", "growth", "vibration", "regimes")

#: The quantities of "growth": thermal growth and bearing displacements.
_GROWTH = ("axial_growth_um", "axial_displacement_um", "radial_displacement_um")


def unit_of_quantity(name: str) -> str:
    """The unit of a quantity: the glossary's, else that of its suffix
    (``"1"`` without one)."""
    if name in GLOSSARY:
        return GLOSSARY[name].unit
    for s in UNIT_SUFFIXES:
        if name.endswith(s):
            return SUFFIX_UNITS[s]
    return "1"


def is_spindle(spec: Any) -> bool:
    """Whether the spec's operating condition is a preload (a spindle's)
    rather than an axial and a radial load (a single bearing's)."""
    from ..diagnosis.measurements import PRELOAD_REGISTRIES

    return any(spec.quantities is r for r in PRELOAD_REGISTRIES)


def condition_columns(spec: Any) -> tuple[str, ...]:
    """The operating columns of the spec's conditions (a spec that names
    its own, as a gear pair's ``conditions``, gives those)."""
    own = getattr(spec, "conditions", None)
    if isinstance(own, tuple):
        return own
    return ("speed_rpm", "preload_n") if is_spindle(spec) else ("speed_rpm", "axial_n", "radial_n")


def _numeric(col: str) -> bool:
    """Whether a condition column holds a number (its name ends in a unit)."""
    return col.endswith(tuple(UNIT_SUFFIXES))


def quantities_for(spec: Any, what: str) -> list[str]:
    """The quantities of ``what`` the spec predicts, in its registry's
    order; [`ConfigError`][thermobear.ConfigError] when it predicts none."""
    if not isinstance(what, str) or what not in WHATS:
        raise ConfigError(f"invalid what = {what!r}: one of {', '.join(WHATS)}")
    if what == "regimes":
        raise ConfigError(
            "invalid what = 'regimes': gear regimes are no quantity of the bearing model; "
            "predict them with thermobear.predict(model, 'regimes', ...)"
        )
    from ..diagnosis.relative import CHANGE_OF

    names = list(spec.quantities)
    if what == "measured":  # the change quantities are derived: "growth" gives them
        pick = [q for q in names if q not in CHANGE_OF]
    elif what == "stiffness":
        pick = [q for q in names if q.endswith(("_n_per_m", "_n_m_per_rad", "_n_per_rad"))]
    elif what == "temperatures":
        pick = [q for q in names if q.endswith("_temperature_c")]
    elif what == "growth":
        pick = [q for q in names if q in _GROWTH or q in CHANGE_OF]
    else:
        pick = [q for q in names if q.startswith("velocity_")]
    if not pick:
        raise ConfigError(
            f"invalid what = {what!r}: the model ({type(spec).__name__}) predicts none of its "
            f"quantities; it predicts {', '.join(names)}"
        )
    return pick


def condition_frame(spec: Any, conditions: Any, default: Any = None) -> polars.DataFrame:
    """The conditions as a frame of the spec's operating columns, one row
    per distinct condition: a DataFrame (``preload_n`` and ``axial_n`` stand
    for each other), a mapping (``speeds_rpm`` with the loads: ``axial_n``,
    ``radial_n`` or ``preload_n``, each a number or a sequence -- every
    combination; or ``loads``, a sequence of (axial_n, radial_n) pairs or of
    preloads), or None for ``default`` (the measured conditions)."""
    import polars as pl

    if conditions is None:
        conditions = default
        if conditions is None:
            raise ConfigError(
                "invalid conditions = None: the calibrated model does not carry its measured "
                "conditions; give a frame or {'speeds_rpm': [...], ...}"
            )
    cols = condition_columns(spec)
    if isinstance(conditions, Mapping):
        df = _grid(cols, conditions)
    elif isinstance(conditions, pl.DataFrame):
        if conditions is not default:  # the user's frame: no column it would ignore
            _validate.keys_known("conditions column", conditions.columns, _frame_columns(cols))
        df = _frame(cols, conditions)
    else:
        raise ConfigError(
            f"invalid conditions = {type(conditions).__name__}: give a polars DataFrame or a dict "
            "with speeds_rpm and the loads"
        )
    for c in cols:
        if not _numeric(c):
            continue
        v = df[c].to_numpy()
        if c == "torque_n_m":  # a torque may be negative (coast) or null (the model's)
            v = v[~np.isnan(v)]
            if not np.all(np.isfinite(v)):
                raise ConfigError(f"invalid conditions {c}: not finite")
            continue
        if not np.all(np.isfinite(v)) or np.any(v < 0.0):
            bad = v[~np.isfinite(v) | (v < 0.0)][0]
            raise ConfigError(f"invalid conditions {c} = {bad}: finite and >= 0")
    return df.unique(maintain_order=True)


def _frame_columns(cols: Sequence[str]) -> tuple[str, ...]:
    """The columns a conditions frame may hold: the operating columns (a
    bearing's ``axial_n`` and a spindle's ``preload_n`` standing for each
    other) and ``comparison``."""
    return (*grid_keys(cols)[1:-1], *cols[:1], "comparison")


def _frame(cols: Sequence[str], df: polars.DataFrame) -> polars.DataFrame:
    import polars as pl

    if "preload_n" in cols and "preload_n" not in df.columns and "axial_n" in df.columns:
        df = df.rename({"axial_n": "preload_n"})
    if "axial_n" in cols and "axial_n" not in df.columns and "preload_n" in df.columns:
        df = df.rename({"preload_n": "axial_n"})
    if "radial_n" in cols and "radial_n" not in df.columns:
        df = df.with_columns(pl.lit(0.0).alias("radial_n"))
    missing = [c for c in cols if c not in df.columns]
    if missing:
        raise ConfigError(f"invalid conditions: no column {missing[0]} (give {', '.join(cols)})")
    keep = [pl.col(c) for c in ("comparison",) if c in df.columns and c not in cols]
    return df.select(
        [pl.col(c).cast(pl.Float64) if _numeric(c) else pl.col(c).cast(pl.Utf8) for c in cols]
        + keep
    )


def grid_keys(cols: Sequence[str]) -> tuple[str, ...]:
    """The keys a conditions dict of a spec with condition columns ``cols``
    may hold: ``speeds_rpm``, ``loads`` and the load columns (a bearing's
    ``axial_n`` and a spindle's ``preload_n`` standing for each other)."""
    loads = list(cols[1:])
    for a, b in (("axial_n", "preload_n"), ("preload_n", "axial_n")):
        if a in loads and b not in loads:
            loads.append(b)
    return ("speeds_rpm", *loads, "loads")


def _grid(cols: Sequence[str], spec: Mapping[str, Any]) -> polars.DataFrame:
    import polars as pl

    known = grid_keys(cols)
    for key in spec:
        if key not in known:
            raise ConfigError(
                f"invalid conditions key = {key!r}: not a condition of this model (known: "
                f"{', '.join(known)}){_validate.did_you_mean(key, known)}"
            )
    if "speeds_rpm" not in spec:
        raise ConfigError(f"invalid conditions = {dict(spec)!r}: give speeds_rpm")
    speeds = _validate.reals("speeds_rpm", spec["speeds_rpm"]).tolist()  # sign: below
    loads = list(cols[1:])
    if "loads" in spec:
        if isinstance(spec["loads"], (str, bytes)) or not hasattr(spec["loads"], "__iter__"):
            raise ConfigError(f"invalid loads = {spec['loads']!r}: a sequence of load tuples")
        combos = [tuple(_validate.reals("loads", x).tolist()) for x in spec["loads"]]
        if any(len(c) != len(loads) for c in combos):
            raise ConfigError(f"invalid loads = {spec['loads']!r}: each is ({', '.join(loads)})")
    else:
        axes = [_load_values(spec, c, len(loads)) for c in loads]
        mesh = np.meshgrid(*axes, indexing="ij")
        combos = list(zip(*(m.reshape(-1).tolist() for m in mesh), strict=True))
    rows = [(s, *c) for c in combos for s in speeds]
    return pl.DataFrame(rows, schema=list(cols), orient="row")


def _load_values(spec: Mapping[str, Any], name: str, n_loads: int) -> np.ndarray:
    """The values of load column ``name`` in a conditions dict (a spindle's
    ``preload_n`` and a bearing's ``axial_n`` stand for each other; a
    bearing's ``radial_n`` defaults to 0)."""
    other = {"preload_n": "axial_n", "axial_n": "preload_n"}.get(name, "")
    v = spec.get(name, spec.get(other))
    if v is None and name == "radial_n":
        v = 0.0
    if v is None:
        raise ConfigError(f"invalid conditions = {dict(spec)!r}: give {name} (or loads)")
    return _validate.reals(name, v)
