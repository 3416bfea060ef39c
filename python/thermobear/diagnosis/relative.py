"""Relative displacement quantities: a displacement measured as its change
from a reference speed.

A displacement probe is often zeroed with the machine running (at the
first speed of a test): it then reads the displacement at each speed minus
the displacement at that reference speed, never the displacement itself.
Such readings are given as a change quantity (``CHANGE_OF``):

* ``axial_displacement_change_um`` (a bearing): ``axial_displacement_um``
  at the row's speed minus at the reference speed, the loads the same;
* ``axial_growth_change_um``, ``radial_displacement_change_um`` (a
  spindle): the same of ``axial_growth_um`` and ``radial_displacement_um``
  at the same preload.

The reference speed of a measured row is the lowest speed at which that
quantity is measured at the same loads and run: the speed where the probe
was zeroed, whose reading (0 for a probe zeroed there) belongs in the table
as a row (``reference_speeds``). In a prediction, whose conditions carry no
quantity, it is the lowest speed of the conditions at the same loads,
unless the conditions carry a ``reference_speed_rpm`` column
(``with_changes``)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Callable, Mapping, MutableMapping, TypeVar

import numpy as np

if TYPE_CHECKING:
    import polars

P = TypeVar("P", bound=MutableMapping[str, Any])

#: Change quantity -> the absolute quantity it is the change of.
CHANGE_OF: dict[str, str] = {
    "axial_displacement_change_um": "axial_displacement_um",
    "axial_growth_change_um": "axial_growth_um",
    "radial_displacement_change_um": "radial_displacement_um",
}

#: The absolute quantity -> its change quantity.
CHANGE_FOR: dict[str, str] = {v: k for k, v in CHANGE_OF.items()}

#: The conditions column of a row's reference speed [rpm] (added by the
#: measurement preparation; optional in the conditions of a prediction).
REFERENCE_SPEED = "reference_speed_rpm"

#: The operating columns that, with the speed, make a row's condition.
_LOADS = ("axial_n", "radial_n", "preload_n")


def _loads(conditions: polars.DataFrame) -> list[np.ndarray]:
    return [
        np.asarray(conditions[c].cast(float).to_numpy(), dtype=float)
        for c in _LOADS
        if c in conditions.columns
    ]


def lowest_speeds(speeds: np.ndarray, keys: list[np.ndarray]) -> np.ndarray:
    """Each row's lowest speed among the rows with the same ``keys``."""
    groups: dict[tuple, float] = {}
    rows = list(zip(*(k.tolist() for k in keys), strict=True)) if keys else [()] * len(speeds)
    for g, s in zip(rows, speeds.tolist(), strict=True):
        groups[g] = min(groups.get(g, np.inf), s)
    return np.array([groups[g] for g in rows], dtype=float)


def reference_of(conditions: polars.DataFrame) -> np.ndarray:
    """The reference speed of each row of a prediction's ``conditions``:
    its ``reference_speed_rpm`` where given (finite), else the lowest speed
    of the conditions at the same loads."""
    sp = np.asarray(conditions["speed_rpm"].cast(float).to_numpy(), dtype=float)
    ref = lowest_speeds(sp, _loads(conditions))
    if REFERENCE_SPEED in conditions.columns:
        given = conditions[REFERENCE_SPEED].cast(float).fill_null(np.nan).to_numpy()
        given = np.asarray(given, dtype=float)
        ref = np.where(np.isfinite(given), given, ref)
    return ref


def with_changes(
    pred: P,
    conditions: polars.DataFrame,
    predict: Callable[[polars.DataFrame], Mapping[str, Any]],
) -> P:
    """``pred`` (a spec's prediction at each row of ``conditions``) with
    every change quantity it holds set to its absolute quantity minus that
    quantity at the row's reference speed (``reference_of``), the loads
    the same; ``predict`` runs the spec where a reference condition is not
    among the rows."""
    import polars as pl

    names = [q for q in CHANGE_OF if q in pred and CHANGE_OF[q] in pred]
    if not names or conditions.height == 0:
        return pred
    sp = np.asarray(conditions["speed_rpm"].cast(float).to_numpy(), dtype=float)
    loads = _loads(conditions)
    ref = reference_of(conditions)
    rows = list(zip(sp.tolist(), *(x.tolist() for x in loads), strict=True))
    at: dict[tuple, int] = {}
    for i, key in enumerate(rows):
        at.setdefault(key, i)
    wanted = list(zip(ref.tolist(), *(x.tolist() for x in loads), strict=True))
    missing = list(dict.fromkeys(k for k in wanted if k not in at))
    extra: Mapping[str, Any] = {}
    if missing:
        cols = ["speed_rpm"] + [c for c in _LOADS if c in conditions.columns]
        frame = pl.DataFrame(missing, schema=dict.fromkeys(cols, pl.Float64), orient="row")
        extra = predict(frame)
    where = {k: j for j, k in enumerate(missing)}
    for q in names:
        absolute = np.asarray(pred[CHANGE_OF[q]], dtype=float)
        more = np.asarray(extra[CHANGE_OF[q]], dtype=float) if missing else np.zeros(0)
        zero = np.asarray(
            [absolute[at[k]] if k in at else more[where[k]] for k in wanted], dtype=np.float64
        )
        pred[q] = absolute - zero
    return pred


def reference_speeds(df: polars.DataFrame) -> np.ndarray:
    """The reference speed of each row of a checked measurement table
    (``load_measurements``): for a change quantity the lowest speed of that
    quantity at the same loads and run, NaN for any other quantity."""
    q = df["quantity"].to_numpy()
    sp = np.asarray(df["speed_rpm"].to_numpy(), dtype=float)
    keys = [q.astype(str)] + [
        np.asarray(df[c].to_numpy()) for c in ("axial_n", "radial_n", "run") if c in df.columns
    ]
    ref = lowest_speeds(sp, keys)
    return np.where(np.isin(q, list(CHANGE_OF)), ref, np.nan)


def has_changes(quantities: Any) -> bool:
    """Whether any of ``quantities`` is a change quantity."""
    return any(str(x) in CHANGE_OF for x in np.asarray(quantities).tolist())
