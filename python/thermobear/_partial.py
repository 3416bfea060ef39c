"""Partial results of speed sweeps that fail or are stopped part-way.

The native sweeps attach what they finished to the exception they raise
(private attributes ``_sweep_*`` / ``_map_*``); the functions here turn
those into the public attributes every sweep error carries:

- ``partial``: a ``polars.DataFrame`` of the finished rows, with the columns
  of a complete result;
- ``failed``: a ``polars.DataFrame`` with ``speed_rpm`` and ``message`` (plus
  the sweep's keys, e.g. ``case``/``direction``) of every failed speed;
- ``not_run``: a ``polars.DataFrame`` of the speeds never run (after the
  failed speed of a continuation sweep, or after a stop).

The exception keeps its class (``ConvergenceError``, ``ConfigError``,
``Interrupted``, ``KeyboardInterrupt`` ...); its message gains how many
speeds finished and which failed.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional, Sequence, Union

if TYPE_CHECKING:
    import numpy as np
    import polars

#: The private attributes the native layer attaches.
_PRIVATE = (
    "_sweep_partial",
    "_sweep_failed",
    "_sweep_not_run",
    "_sweep_finished_index",
    "_map_partial",
    "_map_failed",
    "_map_not_run",
)


def has_partial(e: BaseException) -> bool:
    """True when the native layer attached a partial result to ``e``."""
    return any(hasattr(e, a) for a in _PRIVATE)


def _rpm(v: float) -> str:
    return f"{v:g} rpm"


def finish(
    e: BaseException,
    partial: polars.DataFrame,
    failed: polars.DataFrame,
    not_run: polars.DataFrame,
    *,
    finished: int,
    total: int,
    unit: str = "speeds",
    failed_labels: Sequence[str] = (),
    note: str = "",
) -> None:
    """Set ``partial``/``failed``/``not_run`` on ``e``, drop the private
    attributes and append the tally to its message."""
    for a in _PRIVATE:
        if hasattr(e, a):
            delattr(e, a)
    e.partial = partial  # type: ignore[attr-defined]
    e.failed = failed  # type: ignore[attr-defined]
    e.not_run = not_run  # type: ignore[attr-defined]
    parts = [f"{finished} of {total} {unit} finished (rows in .partial)"]
    if failed_labels:
        shown = ", ".join(failed_labels[:5]) + (" ..." if len(failed_labels) > 5 else "")
        parts.append(f"failed: {shown} (.failed)")
    if not_run.height:
        parts.append(f"{not_run.height} not run (.not_run){note}")
    tally = "; ".join(parts)
    msg = str(e.args[0]) if e.args else ""
    e.args = (f"{msg}; {tally}" if msg else tally,) + tuple(e.args[1:])


def speed_frames(
    e: BaseException, speeds: Union[Sequence[float], np.ndarray], frame_of: Any
) -> Optional[tuple[polars.DataFrame, polars.DataFrame]]:
    """For a per-speed native loop (every speed runs; the failed ones are
    left out): the partial frame (``frame_of(columns, finished_speeds)``)
    and the failed frame; None when nothing was attached."""
    import polars as pl

    if not hasattr(e, "_sweep_finished_index"):
        return None
    idx = list(e._sweep_finished_index)
    finished = [float(speeds[i]) for i in idx]
    partial = frame_of(dict(e._sweep_partial), finished)  # type: ignore[attr-defined]
    rows = list(e._sweep_failed)  # type: ignore[attr-defined]
    failed = pl.DataFrame(
        {"speed_rpm": [float(r[0]) for r in rows], "message": [str(r[1]) for r in rows]},
        schema={"speed_rpm": pl.Float64, "message": pl.Utf8},
    )
    not_run = pl.DataFrame(schema={"speed_rpm": pl.Float64})
    finish(
        e,
        partial,
        failed,
        not_run,
        finished=len(idx),
        total=len(speeds),
        failed_labels=[_rpm(r[0]) for r in rows],
    )
    return partial, failed
