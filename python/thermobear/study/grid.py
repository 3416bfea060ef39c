"""A declarative grid: each dimension a list or a range of one input of a
kind, every other input fixed (given or default); the points are the
Cartesian product, the first dimension outermost. The grid's canonical form
(and its hash) identifies a study's results on disk."""

from __future__ import annotations

import hashlib
import json
import math
from typing import Any, Mapping, Optional

import numpy as np

from ..errors import ConfigError
from .kinds import Kind, Param

#: Keys of a range given as a table: start and stop with num (inclusive
#: linspace) or step (start, start + step, ... up to stop).
RANGE_KEYS = ("start", "stop", "num", "step")


def _scalar(p: Param, value: Any, where: str) -> Any:
    """``value`` as the parameter's type (ints accepted for floats)."""
    if p.convert is not None:
        value = p.convert(value)
    if isinstance(value, np.generic):
        value = value.item()
    if p.type is str:
        if not isinstance(value, str):
            raise ConfigError(f"invalid {where} = {value!r}: must be a string")
        out: Any = value
    elif isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ConfigError(f"invalid {where} = {value!r}: must be a number")
    elif p.type is int:
        if float(value) != int(value):
            raise ConfigError(f"invalid {where} = {value!r}: must be a whole number")
        out = int(value)
    else:
        out = float(value)
        if not math.isfinite(out):
            raise ConfigError(f"invalid {where} = {value!r}: must be a finite number")
    if p.check is not None:
        p.check(out)
    return out


def range_values(spec: Mapping[str, Any], where: str) -> list[float]:
    """The values of a range table ``{start, stop, num}`` or ``{start, stop, step}``."""
    unknown = [k for k in spec if k not in RANGE_KEYS]
    if unknown:
        raise ConfigError(
            f"invalid key = {unknown[0]!r} in {where}: a range has start, stop and num or step"
        )
    for k in ("start", "stop"):
        if k not in spec:
            raise ConfigError(f"invalid {where} = {dict(spec)}: a range needs {k!r}")
    if ("num" in spec) == ("step" in spec):
        raise ConfigError(f"invalid {where} = {dict(spec)}: give exactly one of num, step")
    start, stop = float(spec["start"]), float(spec["stop"])
    if "num" in spec:
        num = spec["num"]
        if isinstance(num, bool) or not isinstance(num, int) or num < 1:
            raise ConfigError(f"invalid num = {num!r} in {where}: must be a whole number >= 1")
        return [float(v) for v in np.linspace(start, stop, num)]
    step = float(spec["step"])
    if not step > 0 or stop < start:
        raise ConfigError(
            f"invalid step = {spec['step']!r} in {where}: needs step > 0, stop >= start"
        )
    count = int(math.floor((stop - start) / step * (1 + 1e-12))) + 1
    return [start + i * step for i in range(count)]


def dimension_values(p: Param, spec: Any, where: str) -> list:
    """A dimension's values from a list, an array, a ``range`` or a range table."""
    if isinstance(spec, Mapping):
        raw: list = range_values(spec, where)
    elif isinstance(spec, (str, bytes)) or np.ndim(spec) == 0:
        raw = [spec]
    else:
        raw = list(spec.tolist() if isinstance(spec, np.ndarray) else spec)
    if not raw:
        raise ConfigError(f"invalid {where} = []: a dimension needs at least one value")
    return [_scalar(p, v, where) for v in raw]


class Grid:
    """The points of a study: ``dims`` (name -> values, product order) and
    ``fixed`` (name -> value) over one kind's inputs."""

    def __init__(self, kind: Kind, dims: Mapping[str, Any], fixed: Optional[Mapping] = None):
        for label, given in (("grid", dims), ("fixed", fixed)):
            if not isinstance(given, Mapping) and not (label == "fixed" and given is None):
                raise ConfigError(
                    f"invalid {label} = {given!r}: must be a mapping of input name to "
                    + ("values" if label == "grid" else "value")
                )
        fixed = dict(fixed or {})
        self.kind = kind
        self.dims: dict[str, list] = {}
        for name, spec in dims.items():
            p = kind.param(name)
            self.dims[name] = dimension_values(p, spec, f"grid.{name}")
        self.fixed: dict[str, Any] = {}
        for name, value in fixed.items():
            p = kind.param(name)
            if name in self.dims:
                raise ConfigError(f"invalid fixed.{name}: {name!r} is also a grid dimension")
            if value is None and p.default is None:  # "the preset's own value"
                self.fixed[name] = None
                continue
            self.fixed[name] = _scalar(p, value, f"fixed.{name}")
        self.shape = tuple(len(v) for v in self.dims.values())
        self.n_points = int(np.prod(self.shape, dtype=np.int64)) if self.shape else 1

    def spec(self) -> dict:
        """The canonical, JSON-able description (what the hash covers)."""
        return {
            "kind": self.kind.name,
            "dims": [[k, v] for k, v in self.dims.items()],
            "fixed": {p.name: self.value(p) for p in self.kind.params if p.name not in self.dims},
        }

    def value(self, p: Param) -> Any:
        return self.fixed.get(p.name, p.default)

    def columns(self) -> list[str]:
        """Input columns in table order: the dimensions, then the others."""
        rest = [p.name for p in self.kind.params if p.name not in self.dims]
        return list(self.dims) + rest

    def frame(self, start: int = 0, stop: Optional[int] = None) -> Any:
        """Input rows ``start <= point < stop``: ``point`` and every input."""
        import polars as pl

        stop = self.n_points if stop is None else stop
        idx = np.arange(start, stop, dtype=np.int64)
        unravelled = np.unravel_index(idx, self.shape) if self.shape else ()
        cols: dict[str, Any] = {"point": pl.Series("point", idx)}
        types = {p.name: p.type for p in self.kind.params}
        for (name, values), at in zip(self.dims.items(), unravelled, strict=True):
            if types[name] is str:
                shown = [self._shown(self.kind.param(name), v) for v in values]
                cols[name] = pl.Series(
                    name, np.asarray(shown, dtype=object)[at].tolist(), dtype=pl.String
                )
            else:
                cols[name] = pl.Series(name, np.asarray(values)[at])
        frame = pl.DataFrame(cols)
        dtype = {str: pl.String, int: pl.Int64, float: pl.Float64}
        rest = [
            pl.lit(self._shown(p, self.value(p)), dtype=dtype[p.type]).alias(p.name)
            for p in self.kind.params
            if p.name not in self.dims
        ]
        return frame.with_columns(rest).select(["point"] + self.columns())

    @staticmethod
    def _shown(p: Param, value: Any) -> Any:
        """What the input column holds of a stored value."""
        return value if p.show is None or value is None else p.show(value)


def grid_hash(spec: Mapping[str, Any]) -> str:
    """SHA-256 of the canonical JSON of a study description (floats are
    written with their shortest exact repr)."""
    text = json.dumps(spec, sort_keys=True, separators=(",", ":"), allow_nan=False)
    return hashlib.sha256(text.encode()).hexdigest()
