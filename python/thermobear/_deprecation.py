"""Renamed names keep working for one release, with a ``DeprecationWarning``
that names the new one.

``renamed_kwargs`` wraps a function whose keyword arguments were renamed;
``warn_renamed`` is for every other place a name changed (a measurement
quantity, a property, a column asked for by name).
"""

from __future__ import annotations

import functools
import warnings
from collections.abc import Callable
from typing import Any, TypeVar

F = TypeVar("F", bound=Callable[..., Any])

Rename = str | tuple[str, Callable[[Any], Any]]


def warn_renamed(old: str, new: str, *, stacklevel: int = 2, what: str = "") -> None:
    """Warn that ``old`` is deprecated in favour of ``new``.

    ``stacklevel`` counts as in ``warnings.warn`` from the caller of
    this function: the default 2 points at whoever called the function that
    calls ``warn_renamed``; the warning points at least as far out as the
    first line outside thermobear (the user's line, past the argument
    checks every public call goes through). ``what`` adds a short note,
    for example the unit change (``"value in N m, not N mm"``).
    """
    from ._limits import _outside_stacklevel

    note = f" ({what})" if what else ""
    warnings.warn(
        f"`{old}` is deprecated; use `{new}`{note}",
        DeprecationWarning,
        stacklevel=max(stacklevel + 1, _outside_stacklevel()),
    )


def renamed_kwargs(**old_to_new: Rename) -> Callable[[F], F]:
    """Decorator: accept the old keyword names of a function.

    Each keyword is ``old="new"``, or ``old=("new", convert)`` when the unit
    changed too (``moment_nmm=("moment_n_m", lambda v: v / 1000.0)``): the
    old value is passed through ``convert`` before it reaches the function.
    Passing an old name warns (``DeprecationWarning``, pointing at the
    caller); passing both the old and the new name raises ``ConfigError``.
    """
    table: dict[str, tuple[str, Callable[[Any], Any] | None]] = {}
    for old, spec in old_to_new.items():
        if isinstance(spec, tuple):
            new, convert = spec
            table[old] = (new, convert)
        else:
            table[old] = (spec, None)

    def decorate(func: F) -> F:
        @functools.wraps(func)
        def wrapper(*args: Any, **kwargs: Any) -> Any:
            for old, (new, convert) in table.items():
                if old not in kwargs:
                    continue
                if new in kwargs:
                    from .errors import ConfigError

                    raise ConfigError(
                        f"invalid {old} = {kwargs[old]!r}: {func.__qualname__}() got both "
                        f"`{old}` (deprecated) and `{new}`; pass only `{new}`"
                    )
                value = kwargs.pop(old)
                warn_renamed(old, new, stacklevel=2)
                kwargs[new] = convert(value) if convert is not None else value
            return func(*args, **kwargs)

        wrapper.__renamed_kwargs__ = dict(table)  # type: ignore[attr-defined]
        return wrapper  # type: ignore[return-value]

    return decorate


__all__ = ["renamed_kwargs", "warn_renamed"]
