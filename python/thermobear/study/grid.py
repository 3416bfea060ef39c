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

#: The most points a study grid may have (``Study(max_points=...)`` raises
#: it). A million rows is a large study for one machine: its input and result
#: frames take a few hundred MB in memory, and at the slower kinds (a
#: thermal state takes about a millisecond, a gear point about 0.1 s) it is
#: hours to days of work on one core. Counted from the dimension specs before
#: any value is made.
MAX_POINTS = 1_000_000

#: The most integration time steps a study of a kind with time steps (``gear``:
#: ``(transient_periods + record_periods) x steps_per_period`` RK4 steps a
#: point) may take in all (``Study(max_steps=...)`` raises it). 10^10 steps
#: at about 0.7 us a step (a seed A speed sweep on one core) is about two
#: hours on one core, more with the Lyapunov exponent's periods.
MAX_STEPS = 10_000_000_000

#: The keyword, the study-file key and the command-line option of each cap.
_RAISE = {
    "max_points": "pass max_points= to Study (max_points under [study] in a study file, "
    "--max-points on the command line) to raise it",
    "max_steps": "pass max_steps= to Study (max_steps under [study] in a study file, "
    "--max-steps on the command line) to raise it",
}


def _n(count: int) -> str:
    """A count for a message: grouped digits, or powers of ten when huge."""
    if count < 10**15:
        return f"{count:,}"
    if count >= 2**1023:  # a range of a step too fine for its span to be a float
        return "more than 1e308"
    return f"{float(count):.3g}"


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
        if isinstance(value, float) and not value.is_integer():
            raise ConfigError(f"invalid {where} = {value!r}: must be a whole number")
        out = int(value)
    else:
        try:
            out = float(value)
        except OverflowError:  # an int past the largest float
            out = math.inf
        if not math.isfinite(out):
            raise ConfigError(f"invalid {where} = {value!r}: must be a finite number")
    if p.check is not None:
        p.check(out)
    return out


def range_values(spec: Mapping[str, Any], where: str) -> list[float]:
    """The values of a range table ``{start, stop, num}`` or ``{start, stop, step}``."""
    count = range_size(spec, where)
    start, stop = _bound(spec, "start", where), _bound(spec, "stop", where)
    if "num" in spec:
        return [float(v) for v in np.linspace(start, stop, count)]
    step = _bound(spec, "step", where)
    return [start + i * step for i in range(count)]


def _bound(spec: Mapping[str, Any], key: str, where: str) -> float:
    """``spec[key]`` of a range table as a finite float."""
    value = spec[key]
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise ConfigError(f"invalid {key} = {value!r} in {where}: must be a number")
    try:
        out = float(value)
    except OverflowError:
        out = math.inf
    if not math.isfinite(out):
        raise ConfigError(f"invalid {key} = {value!r} in {where}: must be a finite number")
    return out


def range_size(spec: Mapping[str, Any], where: str) -> int:
    """How many values the range table ``spec`` holds, by arithmetic alone
    (its keys checked, nothing made)."""
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
    start, stop = _bound(spec, "start", where), _bound(spec, "stop", where)
    if "num" in spec:
        num = spec["num"]
        if isinstance(num, np.integer):
            num = int(num)
        if isinstance(num, bool) or not isinstance(num, int) or num < 1:
            raise ConfigError(f"invalid num = {num!r} in {where}: must be a whole number >= 1")
        return num
    step = _bound(spec, "step", where)
    if not step > 0 or stop < start:
        raise ConfigError(
            f"invalid step = {spec['step']!r} in {where}: needs step > 0, stop >= start"
        )
    span = (stop - start) / step
    if not math.isfinite(span):  # (stop - start) overflows, or a step near 0
        return 2**1023
    # A stop that is a whole number of steps away counts despite rounding
    # (0.3 / 0.1 = 2.9999999999999996); the allowance stays below one step.
    return int(math.floor(span + min(span * 1e-12, 0.5))) + 1


def _is_scalar(spec: Any) -> bool:
    return isinstance(spec, (str, bytes)) or np.ndim(spec) == 0


def dimension_size(spec: Any, where: str) -> int:
    """How many values a dimension spec gives, without making them: a range
    table's by arithmetic, a ``range``'s and a sequence's by their length."""
    if isinstance(spec, Mapping):
        return range_size(spec, where)
    if isinstance(spec, range):
        step = spec.step
        n = (spec.stop - spec.start + step - (1 if step > 0 else -1)) // step
        return max(0, n)
    if _is_scalar(spec):
        return 1
    if isinstance(spec, np.ndarray):
        return int(spec.shape[0])
    try:
        return len(spec)
    except (TypeError, OverflowError):
        return 2**63  # no cheap length: counted as too many to make


def _spec_shown(spec: Any, count: int) -> str:
    """A dimension spec for a message: a range table as given, a long
    list by its length."""
    if isinstance(spec, Mapping):
        return repr(dict(spec))
    if isinstance(spec, range) or count <= 8:
        return repr(spec)
    return f"<{type(spec).__name__} of {_n(count)} values>"


def dimension_values(p: Param, spec: Any, where: str) -> list:
    """A dimension's values from a list, an array, a ``range`` or a range table."""
    if isinstance(spec, Mapping):
        raw: list = range_values(spec, where)
    elif _is_scalar(spec):
        raw = [spec]
    else:
        raw = list(spec.tolist() if isinstance(spec, np.ndarray) else spec)
    if not raw:
        raise ConfigError(f"invalid {where} = []: a dimension needs at least one value")
    return [_scalar(p, v, where) for v in raw]


#: Kinds whose points integrate in time: the inputs that set a point's
#: steps, ``(transient_periods + record_periods) x steps_per_period``.
TIME_STEPS = {"gear": ("transient_periods", "record_periods", "steps_per_period")}


def _too_many_points(dims: Mapping[str, Any], sizes: dict[str, int], cap: int) -> ConfigError:
    """The error of a grid of more than ``cap`` points, naming its largest
    dimension, the grid's size and the keyword that raises the cap."""
    name = max(sizes, key=lambda k: sizes[k])
    count, total = sizes[name], math.prod(sizes.values())
    shape = " x ".join(f"{k}[{_n(v)}]" for k, v in sizes.items())
    return ConfigError(
        f"invalid grid.{name} = {_spec_shown(dims[name], count)}: {_n(count)} values make a "
        f"grid of {_n(total)} points ({shape}), more than max_points = {_n(cap)}; "
        + _RAISE["max_points"]
    )


class Grid:
    """The points of a study: ``dims`` (name -> values, product order) and
    ``fixed`` (name -> value) over one kind's inputs.

    Its size is counted from the dimension specs before any value is made:
    more than ``max_points`` points (or, for a kind with time steps, more
    than ``max_steps`` time steps in all) is a ConfigError naming the
    largest dimension and the size; None does not check (a grid rebuilt
    from a description that was checked)."""

    def __init__(
        self,
        kind: Kind,
        dims: Mapping[str, Any],
        fixed: Optional[Mapping] = None,
        *,
        max_points: Optional[int] = None,
        max_steps: Optional[int] = None,
    ):
        for label, given in (("grid", dims), ("fixed", fixed)):
            if not isinstance(given, Mapping) and not (label == "fixed" and given is None):
                raise ConfigError(
                    f"invalid {label} = {given!r}: must be a mapping of input name to "
                    + ("values" if label == "grid" else "value")
                )
        fixed = dict(fixed or {})
        self.kind = kind
        sizes: dict[str, int] = {}
        for name, spec in dims.items():
            kind.param(name)
            sizes[name] = dimension_size(spec, f"grid.{name}")
            if sizes[name] == 0:  # before any other dimension is made
                raise ConfigError(f"invalid grid.{name} = []: a dimension needs at least one value")
        if max_points is not None and math.prod(sizes.values()) > max_points:
            raise _too_many_points(dims, sizes, max_points)
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
        self.n_points = math.prod(self.shape)
        #: Time steps in all (kinds with time steps; None for the others),
        #: and whether that is a floor (``steps_per_period`` None: 64, or
        #: more where a point's speed needs them).
        self.n_steps, self.steps_at_least = self._time_steps()
        if max_steps is not None and self.n_steps is not None and self.n_steps > max_steps:
            raise self._too_many_steps(max_steps)

    def _step_inputs(self) -> dict[str, list]:
        """The values of each input that sets a point's time steps."""
        return {
            n: self.dims[n] if n in self.dims else [self.value(self.kind.param(n))]
            for n in TIME_STEPS.get(self.kind.name, ())
        }

    def _time_steps(self) -> tuple[Optional[int], bool]:
        """Time steps summed over the points (exact, by the sums of the step
        inputs' values), and whether a default step count makes it a floor."""
        given = self._step_inputs()
        if not given:
            return None, False
        from ..gear.dynamics import DEFAULT_STEPS_PER_PERIOD

        transient, record, steps = given.values()
        floor = any(v is None for v in steps)
        t = [max(0, int(v)) for v in transient]
        r = [max(0, int(v)) for v in record]
        s = [DEFAULT_STEPS_PER_PERIOD if v is None else max(0, int(v)) for v in steps]
        others = self.n_points // (len(t) * len(r) * len(s))
        return others * (sum(t) * len(r) + sum(r) * len(t)) * sum(s), floor

    def _too_many_steps(self, cap: int) -> ConfigError:
        names = TIME_STEPS[self.kind.name]
        shape = " x ".join(f"{k}[{_n(len(v))}]" for k, v in self.dims.items()) or "one point"
        per = ", ".join(
            (f"{n} = {v[0]}" if v[0] is not None else f"{n} = None (64 or more)")
            if len(v) == 1
            else f"{n} up to {max(x or 0 for x in v)}"
            for n, v in self._step_inputs().items()
        )
        return ConfigError(
            f"invalid grid = {shape}: {_n(self.n_points)} points of ({names[0]} + {names[1]}) "
            f"x {names[2]} time steps each ({per}) make {_n(self.n_steps or 0)} time steps"
            f"{' or more' if self.steps_at_least else ''}, more than max_steps = {_n(cap)}; "
            + _RAISE["max_steps"]
        )

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
