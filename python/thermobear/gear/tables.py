"""User inputs of the gear system: mesh stiffness and transmission error
over one mesh period (tables or callables), bearing support stiffness per
bearing or per shaft, backlash by name.

A mesh-period table is a polars DataFrame or a mapping of equal-length
columns with ONE abscissa column

* ``mesh_phase`` [-]: fraction of a mesh period, t / T_mesh (0 .. 1),
* ``mesh_phase_deg`` [deg]: 360 per mesh period,
* ``pinion_angle_deg`` [deg]: pinion rotation, 360 / z_p per mesh period,

and the value column named with its unit (``normal_stiffness_n_per_m`` or
``transverse_stiffness_n_per_m``, converted with k_n = k_t / cos^2(beta), for
the mesh stiffness; ``transmission_error_m`` or ``transmission_error_um``
for the TE). When both of a pair are present they must agree (to 1e-9) and
the first named is used, so the frames of
[`GearSystem.mesh_tables`][thermobear.GearSystem.mesh_tables]
and [`GearPair.mesh_stiffness`][thermobear.GearPair.mesh_stiffness] can be given back directly. The
abscissa must be strictly ascending and span at most one mesh period; a last
point exactly one period after the first closes the period and must repeat
the first value. Tables on the uniform phases ``i / n`` starting at phase 0
(as [`GearSystem.mesh_tables`][thermobear.GearSystem.mesh_tables] returns them) are used as they
are; others are resampled once onto ``table_points`` uniform phases by periodic
linear interpolation. A callable gets the numpy array of the
``table_points`` phases ``i / table_points`` (``mesh_phase``) and returns
the values in the unit of the keyword (N/m along the normal deflection, um);
a function of one float (not taking arrays) is called once per phase.
The Rust core interpolates the uniform samples (periodic Catmull-Rom).
"""

from __future__ import annotations

import math
import warnings
from typing import Any, Callable, Optional, Union

import numpy as np
from numpy.typing import ArrayLike

from .pair import _config_error

#: Abscissa columns of a mesh-period table and their length of one period
#: (``None``: 360 / z_p, the pinion's angular pitch in degrees).
PHASE_COLUMNS = {"mesh_phase": 1.0, "mesh_phase_deg": 360.0, "pinion_angle_deg": None}

MeshInput = Union[Any, Callable[[np.ndarray], Any]]


def _columns(table: Any) -> list[str]:
    cols = getattr(table, "columns", None)
    if cols is None and hasattr(table, "keys"):
        cols = table.keys()
    return [str(c) for c in cols] if cols is not None else []


def _phases(field: str, table: Any, pinion_teeth: int) -> np.ndarray:
    cols = _columns(table)
    given = [c for c in PHASE_COLUMNS if c in cols]
    if len(given) != 1:
        raise _config_error(
            f"invalid {field} = table with columns {cols}: give exactly one abscissa column "
            f"of {list(PHASE_COLUMNS)}"
        )
    period = PHASE_COLUMNS[given[0]] or 360.0 / pinion_teeth
    x = np.asarray(table[given[0]], dtype=float).ravel()
    if not np.all(np.isfinite(x)) or np.any(np.diff(x) <= 0.0):
        raise _config_error(
            f"invalid {field}.{given[0]} = {x.tolist()[:6]}...: must be finite and strictly "
            "ascending"
        )
    return x / period


def _uniform(field: str, phase: np.ndarray, values: np.ndarray, points: int) -> np.ndarray:
    """Samples at the phases i / n: as given when the table already lies on
    them, else periodic linear interpolation onto ``points`` phases."""
    if phase[-1] - phase[0] > 1.0 + 1e-9:
        raise _config_error(
            f"invalid {field} = table spanning {phase[-1] - phase[0]:.6g} mesh periods: the model "
            "repeats one mesh period; give one period (tooth-to-tooth variation over a revolution "
            "cannot be represented)"
        )
    if abs(phase[-1] - phase[0] - 1.0) <= 1e-9:
        scale = max(float(np.max(np.abs(values))), 1e-300)
        if abs(values[-1] - values[0]) > 1e-9 * scale:
            raise _config_error(
                f"invalid {field} = table whose last point (one period after the first) has value "
                f"{values[-1]!r} != first value {values[0]!r}: not periodic"
            )
        phase, values = phase[:-1], values[:-1]
    n = len(phase)
    if n < 2:
        raise _config_error(f"invalid {field} = table of {n} point(s): need at least 2 per period")
    if abs(phase[0]) <= 1e-12 and np.allclose(phase, np.arange(n) / n, rtol=0.0, atol=1e-12):
        return values.copy()
    grid = np.arange(points) / points
    return np.interp(grid, np.mod(phase, 1.0), values, period=1.0)


def mesh_period_samples(
    field: str,
    value_columns: dict[str, float],
    callable_factor: float,
    given: MeshInput,
    pinion_teeth: int,
    points: int,
) -> np.ndarray:
    """Uniform SI samples over one mesh period from a table (value column
    name -> factor to SI) or a callable (its values times
    ``callable_factor``)."""
    if callable(given):
        out = _sample_callable(field, given, points) * callable_factor
    else:
        out = _table_values(field, value_columns, given, pinion_teeth, points)
    if not np.all(np.isfinite(out)):
        raise _config_error(f"invalid {field} = values {out.tolist()[:6]}...: must be finite")
    return out


def _sample_callable(field: str, f: Callable[..., Any], points: int) -> np.ndarray:
    """``f`` on the phases i / points: called once with the array, or, if it
    does not take arrays, once per phase."""
    grid = np.arange(points) / points
    try:
        v = np.asarray(f(grid), dtype=float)
    except Exception:
        v = None
    if v is None or v.shape == ():
        try:
            v = np.array([float(f(float(p))) for p in grid])
        except Exception as e:
            raise _config_error(
                f"invalid {field} = {f!r}: calling it on mesh_phase failed: {e}"
            ) from e
    if v.shape != grid.shape:
        raise _config_error(
            f"invalid {field} = {f!r}: returned shape {v.shape}, need {grid.shape} "
            "(one value per mesh_phase)"
        )
    return v


def _table_values(
    field: str, value_columns: dict[str, float], given: Any, pinion_teeth: int, points: int
) -> np.ndarray:
    """SI samples of a table: the first value column present (in the order
    of ``value_columns``) is used; any other present must agree with it to
    1e-9 of the largest value."""
    cols = _columns(given)
    have = [c for c in value_columns if c in cols]
    if not have:
        raise _config_error(
            f"invalid {field} = table with columns {cols}: give a value column of "
            f"{list(value_columns)}"
        )
    phase = _phases(field, given, pinion_teeth)
    si = [np.asarray(given[c], dtype=float).ravel() * value_columns[c] for c in have]
    if any(v.shape != phase.shape for v in si):
        raise _config_error(f"invalid {field} = table with columns of different lengths")
    tol = 1e-9 * max(float(np.max(np.abs(si[0]))), 1e-300)
    for c, v in zip(have[1:], si[1:], strict=False):
        if np.max(np.abs(v - si[0])) > tol:
            raise _config_error(
                f"invalid {field} = table whose {c!r} disagrees with {have[0]!r}: give one"
            )
    raw = np.asarray(given[have[0]], dtype=float).ravel()
    out = _uniform(field, phase, raw, points)
    return out if value_columns[have[0]] == 1.0 else out * value_columns[have[0]]


def backlash_half_um(
    half_backlash_um: Optional[float],
    backlash_total_um: Optional[float],
    backlash_um: Optional[float],
    default_half_um: float,
) -> float:
    """The half backlash b [um] from exactly one of the names (default:
    ``default_half_um``). ``backlash_um`` is the deprecated name of the
    total clearance 2b."""
    if backlash_um is not None:
        from .._limits import _outside_stacklevel

        warnings.warn(
            "backlash_um is deprecated: it is the total clearance 2b; use backlash_total_um "
            "(or half_backlash_um for b)",
            DeprecationWarning,
            stacklevel=_outside_stacklevel(),
        )
    given = {
        k: v
        for k, v in (
            ("half_backlash_um", half_backlash_um),
            ("backlash_total_um", backlash_total_um),
            ("backlash_um", backlash_um),
        )
        if v is not None
    }
    if len(given) > 1:
        raise _config_error(
            f"invalid backlash = {given}: give exactly one of half_backlash_um (b) or "
            "backlash_total_um (2b)"
        )
    if not given:
        return default_half_um
    name, value = next(iter(given.items()))
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise _config_error(f"invalid {name} = {value!r}: must be a number") from None
    if not math.isfinite(v) or v <= 0.0:
        raise _config_error(f"invalid {name} = {value!r}: must be a positive number of um")
    return v if name == "half_backlash_um" else 0.5 * v


def support_from_frame(
    df: Any, per: Optional[str], bearings_per_shaft: Optional[int]
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Support stiffness of one shaft (speed, kr, ka) from a frame. Per
    bearing: columns ``radial_stiffness_seed_n_per_m``/``axial_stiffness_seed_n_per_m``
    (as [`thermobear.stiffness_curve`][thermobear.stiffness_curve] returns them; the older
    ``radial_stiffness_n_per_m``/``axial_stiffness_n_per_m`` warn) times
    ``bearings_per_shaft`` (default 2); per shaft: the same columns or
    ``support_radial_stiffness_n_per_m``/``support_axial_stiffness_n_per_m``
    (as [`GearSystem.stiffness_schedule`][thermobear.GearSystem.stiffness_schedule] returns them),
    used as given."""
    cols = _columns(df)
    support = all(
        c in cols for c in ("support_radial_stiffness_n_per_m", "support_axial_stiffness_n_per_m")
    )
    if per is None:
        if not support:
            raise _config_error(
                "invalid bearing_stiffness_per = None: a stiffness frame needs "
                "bearing_stiffness_per='bearing' (values of ONE bearing, multiplied by "
                "bearings_per_shaft) or 'shaft' (the support of the whole shaft)"
            )
        per = "shaft"
    n = _bearing_count(per, bearings_per_shaft)
    if support and per == "shaft":
        need = ["speed_rpm", "support_radial_stiffness_n_per_m", "support_axial_stiffness_n_per_m"]
    else:
        need = ["speed_rpm", *_bearing_stiffness_columns(cols)]
    for col in need:
        if col not in cols:
            raise _config_error(
                f"invalid stiffness = frame without {col!r}: need {', '.join(need)} (per {per})"
            )
    s = np.asarray(df["speed_rpm"], dtype=float)
    order = np.argsort(s, kind="stable")
    kr = np.asarray(df[need[1]], dtype=float)[order] * n
    ka = np.asarray(df[need[2]], dtype=float)[order] * n
    return s[order], kr, ka


def _bearing_stiffness_columns(cols: Any) -> list[str]:
    """The radial and axial stiffness columns of one bearing in a frame:
    the seed formula's (older names warn)."""
    new = ["radial_stiffness_seed_n_per_m", "axial_stiffness_seed_n_per_m"]
    old = ["radial_stiffness_n_per_m", "axial_stiffness_n_per_m"]
    if all(c in cols for c in new) or not all(c in cols for c in old):
        return new
    from .._deprecation import warn_renamed

    for o, n in zip(old, new, strict=True):
        warn_renamed(o, n, stacklevel=6, what="stiffness frame column")
    return old


def _bearing_count(per: str, bearings_per_shaft: Optional[int]) -> int:
    if per not in ("bearing", "shaft"):
        raise _config_error(
            f"invalid bearing_stiffness_per = {per!r}: must be 'bearing' or 'shaft'"
        )
    if per == "shaft":
        if bearings_per_shaft is not None:
            raise _config_error(
                f"invalid bearings_per_shaft = {bearings_per_shaft!r}: with "
                "bearing_stiffness_per='shaft' the frame is the whole support; leave it out"
            )
        return 1
    return bearing_count(bearings_per_shaft)


def bearing_count(bearings_per_shaft: Optional[int]) -> int:
    """Identical bearings per shaft acting in parallel (default 2, seed A)."""
    if bearings_per_shaft is None:
        return 2
    if isinstance(bearings_per_shaft, bool) or int(bearings_per_shaft) != bearings_per_shaft:
        raise _config_error(f"invalid bearings_per_shaft = {bearings_per_shaft!r}: a whole number")
    if int(bearings_per_shaft) < 1:
        raise _config_error(f"invalid bearings_per_shaft = {bearings_per_shaft!r}: at least 1")
    return int(bearings_per_shaft)


def as_speeds(speeds_rpm: ArrayLike) -> np.ndarray:
    """Speeds [rpm] sorted ascending (any given order), distinct and positive."""
    from .. import _validate as val

    s = val.reals("speeds_rpm", speeds_rpm, allow_empty=True)  # numbers, not text
    if s.size == 0:
        raise _config_error("invalid speeds_rpm = []: give at least one speed")
    if not np.all(np.isfinite(s)) or np.any(s <= 0.0):
        bad = s[~(np.isfinite(s) & (s > 0.0))][0]
        raise _config_error(f"invalid speeds_rpm = {bad!r}: speeds must be positive and finite")
    s = np.sort(s)
    dup = s[1:][np.diff(s) == 0.0]
    if dup.size:
        raise _config_error(
            f"invalid speeds_rpm = {dup[0]!r}: given twice; speeds must be distinct"
        )
    return np.ascontiguousarray(s)
