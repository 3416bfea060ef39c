"""The one place where the Python entry points check their arguments.

Each function takes the argument's public name and the value as given and
returns it converted (``float``, ``int``, a numpy array), or raises a
[`ConfigError`][thermobear.ConfigError] that names the argument, the value
and what is accepted. The rules are the same everywhere:

* a number is an ``int``, a ``float`` or a numpy number; ``bool`` is not a
  number, and neither is a string (``"1000"`` is refused, not parsed);
* a real must be finite and, where a range is given, inside it;
* a whole number (a count) may be written ``9`` or ``9.0``, not ``9.5``.

The native core checks the physics of what it receives as well (the Rust
counterpart is ``src/error.rs``: ``finite``, ``positive``, ``in_range``).
"""

from __future__ import annotations

import math
import numbers
from typing import Any, Iterable, Optional, Sequence

import numpy as np

from .errors import ConfigError, ConvergenceError

INF = math.inf

#: Types accepted as a real number without a look at ``numbers.Real``.
_FAST_REAL = (float, int)


def _shown(value: Any) -> str:
    """``value`` as a message shows it: short, and a number in ``%g``."""
    if isinstance(value, float):
        return f"{value:g}"
    text = repr(value)
    return text if len(text) <= 60 else text[:57] + "..."


def _bounds(lo: float, hi: float, open_lo: bool) -> str:
    """The accepted range in words."""
    if lo == -INF and hi == INF:
        return "a finite number"
    if hi == INF:
        return f"a finite number {'>' if open_lo else '>='} {lo:g}"
    if lo == -INF:
        return f"a finite number <= {hi:g}"
    return f"a finite number in {'(' if open_lo else '['}{lo:g}, {hi:g}]"


def close_name(value: Any, known: Iterable[Any]) -> Optional[str]:
    """The one of ``known`` closest to ``value`` when it is close (a
    misspelling: ``difflib`` ratio at least 0.6, case ignored), else None."""
    import difflib

    if not isinstance(value, str):
        return None
    by_lower = {str(k).lower(): str(k) for k in known}
    near = difflib.get_close_matches(value.lower(), list(by_lower), n=1, cutoff=0.6)
    return by_lower[near[0]] if near else None


def did_you_mean(value: Any, known: Iterable[Any]) -> str:
    """``"; did you mean <name>?"`` for a ``value`` close to one of
    ``known`` (see ``close_name``), else ``""``: the tail of an error
    about an unknown name."""
    near = close_name(value, known)
    return f"; did you mean {near}?" if near is not None and near != value else ""


def fail(name: str, value: Any, accepted: str) -> ConfigError:
    """The error for ``name = value``, saying what is ``accepted``."""
    return ConfigError(f"invalid {name} = {_shown(value)}: must be {accepted}")


def is_number(value: Any) -> bool:
    """True for an int, float or numpy number; False for bool and str."""
    if type(value) in _FAST_REAL:
        return True
    return isinstance(value, (numbers.Real, np.number)) and not isinstance(value, (bool, np.bool_))


def real(
    name: str, value: Any, lo: float = -INF, hi: float = INF, *, open_lo: bool = False
) -> float:
    """``value`` as a finite float in ``[lo, hi]`` (``(lo, hi]`` with
    ``open_lo``, e.g. ``real("ball_diameter_mm", d, 0, open_lo=True)``)."""
    if type(value) is float or type(value) is int:  # the common case, fast
        x = float(value)
    elif is_number(value):
        try:
            x = float(value)
        except (OverflowError, ValueError):
            raise fail(name, value, _bounds(lo, hi, open_lo)) from None
    else:
        raise fail(name, value, _bounds(lo, hi, open_lo) + f", not a {type(value).__name__}")
    if not (x - x == 0.0) or x < lo or x > hi or (open_lo and x == lo):
        raise fail(name, value, _bounds(lo, hi, open_lo))
    return x


def optional_real(
    name: str, value: Any, lo: float = -INF, hi: float = INF, *, open_lo: bool = False
) -> Optional[float]:
    """Like [`real`][thermobear._validate.real], with ``None`` passed through."""
    return None if value is None else real(name, value, lo, hi, open_lo=open_lo)


#: The largest count any entry takes (a native 32-bit count).
MAX_COUNT = 2**31 - 1


def whole(name: str, value: Any, lo: int = 0, hi: Optional[int] = MAX_COUNT) -> int:
    """``value`` as an int in ``[lo, hi]``: a whole number (``9`` or ``9.0``)."""
    accepted = f"a whole number >= {lo}" if hi is None else f"a whole number in [{lo}, {hi}]"
    if not is_number(value):
        raise fail(name, value, accepted + f", not a {type(value).__name__}")
    try:
        n = int(value)
    except (OverflowError, ValueError):
        raise fail(name, value, accepted) from None
    if n != value or n < lo or (hi is not None and n > hi):
        raise fail(name, value, accepted)
    return n


def optional_whole(
    name: str, value: Any, lo: int = 0, hi: Optional[int] = MAX_COUNT
) -> Optional[int]:
    """Like [`whole`][thermobear._validate.whole], with ``None`` passed through."""
    return None if value is None else whole(name, value, lo, hi)


def flag(name: str, value: Any) -> bool:
    """``value`` as a bool: ``True`` or ``False`` (numpy bools too), nothing else."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise fail(name, value, "True or False")


def choice(name: str, value: Any, options: Iterable[Any]) -> Any:
    """``value`` if it is one of ``options``."""
    opts = tuple(options)
    if isinstance(value, (str, int, float, type(None))) and not isinstance(value, bool):
        if value in opts:  # plain values only: an array's == is element-wise
            return value
    raise fail(
        name, value, "one of " + ", ".join(repr(o) for o in opts) + did_you_mean(value, opts)
    )


def optional_callback(name: str, value: Any) -> Any:
    """``value`` if it is None or callable (a ``progress(done, total)``)."""
    if value is None or callable(value):
        return value
    raise fail(
        name, value, f"None or a callable such as f(done, total), not a {type(value).__name__}"
    )


def text(name: str, value: Any) -> str:
    """``value`` if it is a string."""
    if isinstance(value, str):
        return value
    raise fail(name, value, f"a string, not a {type(value).__name__}")


def reals(
    name: str, values: Any, lo: float = -INF, hi: float = INF, *, allow_empty: bool = False
) -> np.ndarray:
    """``values`` (a number or a sequence of numbers) as a contiguous 1-D
    float array, every entry finite and in ``[lo, hi]``; the first bad
    entry is named with its index."""
    if isinstance(values, (str, bytes)) or isinstance(values, (bool, np.bool_)):
        raise fail(name, values, "a sequence of finite numbers")
    try:
        arr = np.asarray(values)
    except (TypeError, ValueError):
        raise fail(name, values, "a sequence of finite numbers") from None
    if arr.dtype.kind not in "iuf" or arr.dtype.kind == "b":
        if arr.dtype.kind == "O":
            if arr.ndim == 0:  # one value, not a number
                raise fail(name, values, "a sequence of finite numbers")
            for i, v in enumerate(arr.ravel()):
                if not is_number(v):
                    raise fail(f"{name}[{i}]", v, "a finite number")
        else:
            raise fail(name, values, "a sequence of finite numbers")
    try:
        out = np.ascontiguousarray(arr, dtype=float).ravel()
    except (TypeError, ValueError, OverflowError):
        raise fail(name, values, "a sequence of finite numbers") from None
    if out.size == 0 and not allow_empty:
        raise fail(name, values, "at least one value")
    bad = ~np.isfinite(out) | (out < lo) | (out > hi)
    if bad.any():
        i = int(np.argmax(bad))
        raise fail(f"{name}[{i}]", float(out[i]), _bounds(lo, hi, False))
    return out


def names(name: str, values: Any, *, one: bool = False) -> list[str]:
    """``values`` (a sequence of strings; with ``one``, a single string
    too) as a list of strings; the first entry that is not a string is
    named with its index."""
    if isinstance(values, str):
        if one:
            return [values]
        raise fail(name, values, "a sequence of names (a list of strings), not a str")
    if isinstance(values, (bytes, dict)) or not isinstance(values, Iterable):
        raise fail(name, values, f"a sequence of names, not a {type(values).__name__}")
    out = list(values)
    for i, x in enumerate(out):
        if not isinstance(x, str):
            raise fail(f"{name}[{i}]", x, f"a name (a string), not a {type(x).__name__}")
    return out


def optional_names(name: str, values: Any, *, one: bool = False) -> Optional[list[str]]:
    """Like [`names`][thermobear._validate.names], with ``None`` passed through."""
    return None if values is None else names(name, values, one=one)


def pair(name: str, values: Any, lo: float = -INF, hi: float = INF) -> tuple[float, float]:
    """``values`` as two finite floats in ``[lo, hi]`` (a pair per shaft,
    per gear, ...)."""
    arr = reals(name, values, lo, hi)
    if arr.size != 2:
        raise fail(name, values, "two finite numbers")
    return float(arr[0]), float(arr[1])


def finite_result(result: Any, inputs: dict[str, Any]) -> Any:
    """``result`` (a number or an array) if every value is finite; else a
    ``ConfigError`` naming the ``inputs`` that made it overflow (finite
    inputs too large together, e.g. a speed of 1e306 rpm)."""
    if np.all(np.isfinite(result)):
        return result
    shown = ", ".join(f"{k} = {_shown(x)}" for k, x in inputs.items())
    raise ConfigError(f"invalid {shown}: the result is not a finite number (the inputs overflow)")


def keys_known(name: str, given: Sequence[str], known: Sequence[str]) -> None:
    """Refuse the first of ``given`` not in ``known`` (unknown keywords)."""
    for k in given:
        if k not in known:
            raise ConfigError(
                f"invalid {name} = {k!r}: not a known argument (known: {', '.join(known)})"
                + did_you_mean(k, known)
            )


def name_inputs(error: BaseException, inputs: dict[str, Any]) -> None:
    """Add the ``inputs`` that made a solve impossible to a
    ``ConvergenceError``'s message (in place: its type and attributes stay);
    other errors are left as they are."""
    if not isinstance(error, ConvergenceError) or not inputs or "(inputs: " in str(error):
        return
    shown = ", ".join(f"{k} = {_shown(x)}" for k, x in inputs.items())
    error.args = (f"{error} (inputs: {shown})", *error.args[1:])
