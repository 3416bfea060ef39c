"""One rule for the arguments of every public call: an unknown keyword, a
missing required argument, too many positional arguments or an argument
given twice raise a [`ConfigError`][thermobear.ConfigError] that names the
call, the argument and what the call takes (with the closest known keyword
for a misspelt one), never Python's own ``TypeError``; and a ``TypeError``
raised past the arguments (a value of the wrong type reaching a conversion)
becomes a ``ConfigError`` naming the call.

``guard_namespace`` wraps the public functions of a namespace and the
methods of its public classes once, at import (``thermobear/__init__.py``).
A wrapper costs one extra Python frame on a call that succeeds: the
arguments are checked against the signature only once the call has failed
with a ``TypeError``, which Python raises before the body runs when the
arguments do not fit. The wrappers keep the signature, name and docstring
(``functools.wraps``), so ``help()`` and ``inspect.signature`` are
unchanged; type checkers see the definitions themselves.
"""

from __future__ import annotations

import functools
import inspect
import re
from typing import Any, Callable, Optional

from ._validate import close_name, fail
from .errors import ConfigError

#: Set on a wrapper so that a function is wrapped once.
_MARK = "__thermobear_arguments_checked__"

_NO_NAME = (inspect.Parameter.VAR_POSITIONAL, inspect.Parameter.VAR_KEYWORD)


def _shown_params(sig: inspect.Signature) -> str:
    """The parameters of ``sig`` as a reader writes the call (names only;
    ``*`` before the keyword-only ones)."""
    out: list[str] = []
    star = False
    for p in sig.parameters.values():
        if p.name in ("self", "cls"):
            continue
        if p.kind is p.VAR_POSITIONAL:
            out.append(f"*{p.name}")
            star = True
        elif p.kind is p.VAR_KEYWORD:
            out.append(f"**{p.name}")
        else:
            if p.kind is p.KEYWORD_ONLY and not star:
                out.append("*")
                star = True
            out.append(p.name if p.default is p.empty else f"{p.name}=...")
    return ", ".join(out)


def _renamed(func: Callable[..., Any]) -> dict[str, str]:
    """Old keyword -> new keyword for a function wrapped by
    ``renamed_kwargs`` (anywhere in its ``__wrapped__`` chain)."""
    out: dict[str, str] = {}
    f: Any = func
    while f is not None:
        for old, spec in getattr(f, "__renamed_kwargs__", {}).items():
            out[old] = spec[0] if isinstance(spec, tuple) else spec
        f = getattr(f, "__wrapped__", None)
    return out


def argument_error(
    call: str, func: Callable[..., Any], args: tuple[Any, ...], kwargs: dict[str, Any]
) -> Optional[ConfigError]:
    """The ``ConfigError`` for ``call(*args, **kwargs)`` when the arguments
    do not fit the signature of ``func``, else None."""
    try:
        sig = inspect.signature(func)
    except (TypeError, ValueError):  # no signature to check against
        return None
    renamed = _renamed(func)
    given = {renamed.get(k, k): v for k, v in kwargs.items()}
    try:
        sig.bind(*args, **given)
        return None
    except TypeError as e:
        reason = str(e)
    params = list(sig.parameters.values())
    takes = f"(it takes: {_shown_params(sig)})"
    by_name = {p.name: p for p in params if p.kind not in _NO_NAME}
    keywords = [n for n, p in by_name.items() if p.kind is not p.POSITIONAL_ONLY]
    keywords = [n for n in keywords if n not in ("self", "cls")]
    if not any(p.kind is p.VAR_KEYWORD for p in params):
        for k in kwargs:
            if renamed.get(k, k) not in keywords:
                near = close_name(k, keywords)
                hint = f"; did you mean {near}?" if near is not None else ""
                return ConfigError(
                    f"invalid argument = {k!r}: not an argument of {call}() {takes}{hint}"
                )
    positional = [p for p in params if p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD)]
    if not any(p.kind is p.VAR_POSITIONAL for p in params) and len(args) > len(positional):
        bound = 1 if positional and positional[0].name in ("self", "cls") else 0
        n, m = len(positional) - bound, len(args) - bound
        return ConfigError(
            f"invalid call {call}(): it takes at most {n} positional argument"
            f"{'' if n == 1 else 's'}, {m} given {takes}"
        )
    for p in positional[: len(args)]:
        if p.name in given:
            return ConfigError(
                f"invalid call {call}(): argument {p.name!r} given twice "
                f"(by position and by keyword) {takes}"
            )
    missing = re.search(r"'(\w+)'", reason) if "missing" in reason else None
    if missing is not None:
        return ConfigError(
            f"invalid call {call}(): the required argument {missing.group(1)!r} is missing {takes}"
        )
    return ConfigError(f"invalid call {call}(): {reason} {takes}")


def _passed_on(
    call: str, func: Callable[..., Any], error: Exception, kwargs: dict[str, Any]
) -> Optional[ConfigError]:
    """The ``ConfigError`` for a keyword that a call taking ``**kwargs``
    passed on to a callee that refused it (a matplotlib artist, an inner
    step), else None."""
    m = re.search(r"unexpected keyword argument '(\w+)'", str(error))
    if m is None or m.group(1) not in kwargs:
        return None
    sig = inspect.signature(func)
    known = [n for n, p in sig.parameters.items() if p.kind not in _NO_NAME]
    known = [n for n in known if n not in ("self", "cls")]
    near = close_name(m.group(1), known)
    hint = f"; did you mean {near}?" if near is not None else ""
    return ConfigError(
        f"invalid argument = {m.group(1)!r}: not an argument of {call}() "
        f"(it takes: {_shown_params(sig)}; passed on, it was refused: {error}){hint}"
    )


def _given(func: Callable[..., Any], args: tuple[Any, ...], kwargs: dict[str, Any]) -> dict:
    """The arguments given to ``func`` by name (those gathered by
    ``**kwargs`` too; ``self`` and ``cls`` left out)."""
    try:
        sig = inspect.signature(func)
        bound = sig.bind(*args, **kwargs).arguments
    except (TypeError, ValueError):
        return dict(kwargs)
    out: dict[str, Any] = {}
    for name, value in bound.items():
        kind = sig.parameters[name].kind
        if kind is inspect.Parameter.VAR_KEYWORD:
            out.update(value)
        elif kind is not inspect.Parameter.VAR_POSITIONAL and name not in ("self", "cls"):
            out[name] = value
    return out


def _body_error(
    call: str, func: Callable[..., Any], error: TypeError, args: tuple[Any, ...], kwargs: dict
) -> ConfigError:
    """A ``TypeError`` from past the arguments (a value of the wrong type
    met a conversion) as a ``ConfigError`` naming the call and, when one
    given argument has the type the message names, that argument."""
    text = str(error)
    named = re.match(r"argument '(\w+)': (.*)", text, re.S)  # the native core's wording
    if named is not None:
        return ConfigError(f"invalid {named.group(1)} for {call}(): {named.group(2)}")
    types = set(re.findall(r"'(\w+)' object|not (?:an? )?'?(\w+)'?$", text))
    types_named = {t for pair in types for t in pair if t}
    hits = [
        (k, x) for k, x in _given(func, args, kwargs).items() if type(x).__name__ in types_named
    ]
    if len(hits) == 1:
        name, value = hits[0]
        return fail(name, value, f"a value of another type for {call}() ({text})")
    return ConfigError(f"invalid argument to {call}(): a value of the wrong type ({text})")


def checked(call: str, func: Callable[..., Any]) -> Callable[..., Any]:
    """``func`` with its argument errors raised as ``ConfigError`` (see the
    module's docstring); ``call`` names it in messages (``Bearing.solve``)."""
    if getattr(func, _MARK, False):
        return func

    @functools.wraps(func)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        try:
            return func(*args, **kwargs)
        except TypeError as e:
            error = (
                argument_error(call, func, args, kwargs)
                or _passed_on(call, func, e, kwargs)
                or _body_error(call, func, e, args, kwargs)
            )
            raise error from e
        except AttributeError as e:  # matplotlib refusing a keyword passed on
            passed = _passed_on(call, func, e, kwargs)
            if passed is None:
                raise
            raise passed from e

    setattr(wrapper, _MARK, True)
    return wrapper


def _guard_class(cls: type, name: str) -> None:
    """Wrap the public methods (and ``__init__``) of ``cls`` and of its
    bases from this package, in place."""
    for klass in cls.__mro__:
        if not klass.__module__.startswith("thermobear."):
            continue
        for attr, raw in list(vars(klass).items()):
            if attr.startswith("_") and attr not in ("__init__", "__call__"):
                continue
            call = name if attr == "__init__" else f"{name}.{attr}"
            if isinstance(raw, (staticmethod, classmethod)):
                inner = raw.__func__
                if getattr(inner, _MARK, False):
                    continue
                wrapped: Any = type(raw)(checked(call, inner))
            elif inspect.isfunction(raw):
                if getattr(raw, _MARK, False):
                    continue
                wrapped = checked(call, raw)
            else:  # properties, constants, nested classes
                continue
            setattr(klass, attr, wrapped)


def guard_namespace(namespace: dict[str, Any], names: list[str], prefix: str = "") -> None:
    """Wrap, in place, the functions of ``namespace`` listed in ``names``
    and the methods of the classes listed there (exceptions and warnings
    are left alone); ``prefix`` goes before the names in messages."""
    for name in names:
        obj = namespace.get(name)
        if inspect.isclass(obj):
            if not issubclass(obj, BaseException):
                _guard_class(obj, prefix + name)
        elif inspect.isfunction(obj):
            namespace[name] = checked(prefix + name, obj)
