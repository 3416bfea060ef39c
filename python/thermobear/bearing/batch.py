"""Many operating points in one native call: the frame in, the frame out.

The native batch functions take one float array per operating quantity and
return one array per output plus ``ok``, ``error_kind`` (the exception class
name, e.g. ``"ConvergenceError"``) and ``error`` (its message) per point. A
failed point's outputs become nulls here (never NaN)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Mapping, Sequence

import numpy as np

if TYPE_CHECKING:
    import polars

#: Columns of the error report of a batch result, after the outputs.
ERROR_COLUMNS = ("ok", "error_kind", "error")


def operating_frame(points: Any, columns: Sequence[str]) -> polars.DataFrame:
    """``points`` as a polars DataFrame: a DataFrame, or a mapping of column
    name to values (scalars are broadcast). At least one of ``columns`` must
    be present; every column present must be numeric."""
    import polars as pl

    from ..errors import ConfigError

    if isinstance(points, pl.DataFrame):
        frame = points
    elif isinstance(points, Mapping):
        points = {k: _flat_column(k, v) for k, v in points.items()}
        lengths = {len(np.atleast_1d(v)) for v in points.values() if np.ndim(v) > 0}
        if len(lengths) > 1:
            raise ConfigError(f"invalid points = columns of lengths {sorted(lengths)}: need one")
        n = lengths.pop() if lengths else 1
        frame = pl.DataFrame(
            {k: np.broadcast_to(np.asarray(v), (n,)).copy() for k, v in points.items()}
        )
    else:
        raise ConfigError(
            f"invalid points = {type(points).__name__}: give a polars DataFrame or a mapping "
            f"of columns ({', '.join(columns)})"
        )
    if not any(c in frame.columns for c in columns):
        raise ConfigError(
            f"invalid points = frame with columns {frame.columns}: needs at least one of "
            + ", ".join(columns)
        )
    for c in columns:
        if c in frame.columns and not frame.schema[c].is_numeric():
            raise ConfigError(f"invalid {c} = column of {frame.schema[c]}: must be numeric")
    return frame


def _flat_column(name: Any, values: Any) -> Any:
    """A column of a mapping of points: one value or a flat sequence of
    values (an array of them); nested lists are refused by name."""
    from .._validate import fail

    if isinstance(values, (str, bytes)):
        return values  # a text column, carried through
    try:
        arr = np.asarray(values)
    except (ValueError, TypeError):  # ragged nesting
        arr = None
    if arr is None or arr.ndim > 1 or (arr.dtype == object and any(np.ndim(x) for x in arr.flat)):
        raise fail(str(name), values, "one value or a flat sequence of values, one per point")
    return arr


def column_array(frame: Any, name: str, default: float = 0.0) -> np.ndarray:
    """A contiguous float64 array of one column (``default`` where absent)."""
    if name not in frame.columns:
        return np.full(frame.height, float(default))
    values = frame[name].cast(float).to_numpy()
    return np.ascontiguousarray(values, dtype=np.float64)


def result_frame(raw: Mapping[str, Any]) -> polars.DataFrame:
    """The native columns as a DataFrame: outputs (nulls where a point
    failed), then ``ok``, ``error_kind``, ``error``."""
    import polars as pl

    from .._names import renamed_columns

    outputs = renamed_columns({k: raw[k] for k in raw if k not in ERROR_COLUMNS})
    ok = np.asarray(raw["ok"], dtype=bool)
    data: dict[str, Any] = {}
    for k, values in outputs.items():
        data[k] = pl.Series(k, values).scatter(np.flatnonzero(~ok), None)
    data["ok"] = pl.Series("ok", ok)
    data["error_kind"] = pl.Series("error_kind", list(raw["error_kind"]), dtype=pl.String)
    data["error"] = pl.Series("error", list(raw["error"]), dtype=pl.String)
    return pl.DataFrame(data)


def join_inputs(frame: Any, result: Any) -> polars.DataFrame:
    """The input frame's columns followed by the result's; a name in both is
    an error (it would hide an input)."""
    from ..errors import ConfigError

    clash = [c for c in result.columns if c in frame.columns]
    if clash:
        raise ConfigError(
            f"invalid points = frame with column {clash[0]!r}: the name of an output column"
        )
    return frame.hstack(result)
