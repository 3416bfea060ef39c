"""Where a prediction stands against the conditions its model was
calibrated at.

Every frame of [`predict`][thermobear.predict.band.predict] carries, per
row, how far its operating condition lies outside the measured range of
that condition, as a fraction:

* ``speed_beyond_measured``: 0 when the row's speed lies within the
  measured speeds [lo, hi]; above them (speed - hi) / hi, below them
  (lo - speed) / hi. Both directions count as positive: the number says how
  far, the speed itself says which side. 0.5 is half the top measured
  speed past the top (or below the bottom) measured one.
* ``axial_load_beyond_measured``, ``radial_load_beyond_measured`` (a
  bearing's loads) and ``preload_beyond_measured`` (a spindle's): the same
  rule on the load, scaled by the largest measured magnitude of that load;
  a load measured only at 0 is scaled by the largest measured load of the
  machine (axial and radial together). With nothing to scale by (every
  measured load 0), a row at another load is 1: all of it lies beyond.

A model that carries no measured conditions (a ``CalibratedModel`` on its
own: pass the [`Calibration`][thermobear.Calibration] or
[`Diagnosis`][thermobear.Diagnosis], which know their points) gets null
columns and no warning; so does a condition the measured table has no
column for.

An [`ExtrapolationWarning`][thermobear.ExtrapolationWarning] says when any
row lies more than ``MAX_BEYOND_MEASURED`` (50 %) beyond the measured
speeds or loads (the docs page "Limits" gives the reason for the figure)."""

from __future__ import annotations

import warnings
from typing import TYPE_CHECKING, Any, Optional

import numpy as np

from .._limits import _outside_stacklevel
from ..errors import ExtrapolationWarning

if TYPE_CHECKING:
    import polars

#: Condition column -> the column that says how far beyond the measured
#: range a row lies (a fraction, see the module text).
BEYOND_COLUMNS: dict[str, str] = {
    "speed_rpm": "speed_beyond_measured",
    "axial_n": "axial_load_beyond_measured",
    "radial_n": "radial_load_beyond_measured",
    "preload_n": "preload_beyond_measured",
}

#: The load columns (scaled by the machine's largest measured load when
#: measured only at 0).
LOAD_COLUMNS = ("axial_n", "radial_n", "preload_n")

#: How far beyond the measured range (a fraction of the largest measured
#: value of that condition) a prediction may reach before an
#: ``ExtrapolationWarning``: speeds and loads alike.
MAX_BEYOND_MEASURED = 0.5

#: A spindle's preload and a bearing's axial load stand for each other.
_ALIASES = {"preload_n": "axial_n", "axial_n": "preload_n"}


def measured_values(measured: Any, column: str) -> Optional[np.ndarray]:
    """The finite measured values of a condition ``column`` (its alias:
    ``preload_n`` for ``axial_n`` and back), or None when the measured
    table has no such column or no finite value in it."""
    if measured is None or not hasattr(measured, "columns"):
        return None
    for name in (column, _ALIASES.get(column)):
        if name is not None and name in measured.columns:
            v = np.asarray(measured[name].cast(float).to_numpy(), dtype=float)
            v = v[np.isfinite(v)]
            return v if v.size else None
    return None


def beyond_measured(
    values: np.ndarray, measured: np.ndarray, scale: Optional[float] = None
) -> np.ndarray:
    """How far each of ``values`` lies outside [min, max] of ``measured``,
    as a fraction of ``scale`` (default: the largest measured magnitude):
    0 inside, (x - max) / scale above, (min - x) / scale below; 1 outside
    when the scale is 0 (the measured values all 0: the whole value lies
    beyond them); NaN where ``values`` is NaN."""
    x = np.asarray(values, dtype=float)
    lo, hi = float(np.min(measured)), float(np.max(measured))
    s = float(np.max(np.abs(measured))) if scale is None else float(scale)
    gap = np.maximum(np.maximum(x - hi, lo - x), 0.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        out = np.where(gap > 0.0, gap / s if s > 0.0 else 1.0, 0.0)
    return np.where(np.isnan(x), np.nan, out)


def _machine_load_scale(measured: Any) -> float:
    """The largest measured magnitude of any load column (0 without one)."""
    got = [measured_values(measured, c) for c in LOAD_COLUMNS]
    return max((float(np.max(np.abs(v))) for v in got if v is not None), default=0.0)


def beyond_frame(frame: polars.DataFrame, measured: Any) -> polars.DataFrame:
    """``frame`` with a ``*_beyond_measured`` column (``BEYOND_COLUMNS``)
    for each of its condition columns: null where the measured conditions
    (``measured``, a frame; None: not known) give nothing to compare with."""
    import polars as pl

    cols = []
    for cond, name in BEYOND_COLUMNS.items():
        if cond not in frame.columns:
            continue
        ref = measured_values(measured, cond)
        if ref is None:
            cols.append(pl.lit(None, dtype=pl.Float64).alias(name))
            continue
        scale = None
        if cond in LOAD_COLUMNS and float(np.max(np.abs(ref))) == 0.0:
            scale = _machine_load_scale(measured)
        x = np.asarray(frame[cond].cast(pl.Float64).fill_null(np.nan).to_numpy(), dtype=float)
        got = beyond_measured(x, ref, scale)
        series = pl.Series(name, got, dtype=pl.Float64)
        cols.append(pl.when(series.is_nan()).then(None).otherwise(series).alias(name))
    return frame.with_columns(cols) if cols else frame


def warn_beyond(frame: polars.DataFrame, measured: Any, limit: float = MAX_BEYOND_MEASURED) -> None:
    """An [`ExtrapolationWarning`][thermobear.ExtrapolationWarning] naming
    each condition whose farthest row lies more than ``limit`` beyond the
    measured range (the row's value, the measured range, the distance)."""
    parts = []
    for cond, name in BEYOND_COLUMNS.items():
        if name not in frame.columns or cond not in frame.columns:
            continue
        d = np.asarray(frame[name].fill_null(0.0).to_numpy(), dtype=float)
        if d.size == 0 or not np.any(d > limit):
            continue
        i = int(np.argmax(d))
        ref = measured_values(measured, cond)
        span = "" if ref is None else f" (measured {np.min(ref):g}..{np.max(ref):g})"
        parts.append(f"{cond} = {float(frame[cond][i]):g} lies {100.0 * d[i]:.0f} % beyond{span}")
    if parts:
        warnings.warn(
            "prediction far outside the calibrated conditions: "
            + "; ".join(parts)
            + f" (more than {100.0 * limit:.0f} %); the calibrated values were not fitted "
            "there -- see the *_beyond_measured columns",
            ExtrapolationWarning,
            stacklevel=_outside_stacklevel(),
        )


def with_extrapolation(frame: polars.DataFrame, model: Any) -> polars.DataFrame:
    """``frame`` (a prediction of ``model``) with its ``*_beyond_measured``
    columns against the measured conditions of the calibrated model, or
    else of ``model`` itself (a calibration or a diagnosis: its points;
    ``measured_conditions``), warning past ``MAX_BEYOND_MEASURED``; null
    columns and no warning when neither carries them."""
    from .model_input import as_calibrated, measured_conditions

    found = (measured_conditions(x) for x in (as_calibrated(model), model))
    measured = next((m for m in found if m is not None), None)
    out = beyond_frame(frame, measured)
    if measured is not None:
        warn_beyond(out, measured)
    return out
