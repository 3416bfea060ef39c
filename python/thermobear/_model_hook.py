"""The duck-typed hook through which a calibrated model stands for a
bearing or a spindle in every downstream call, without the lower layers
importing the diagnosis.

An object with a method ``_thermobear_model_()`` returning ``(machine,
options)`` -- a [`Bearing`][thermobear.Bearing] or
[`Spindle`][thermobear.Spindle] and the keyword options that reproduce its
calibrated setting (a [`CalibratedModel`][thermobear.CalibratedModel]) -- is
accepted in place of the machine by the entry points decorated with
``takes_calibrated``. The rules:

* each call takes the calibrated options it has a parameter for (and the
  ``extra`` names it passes on through ``**kwargs``); the others do not
  act on that call (the thermal options in the ``"speed"`` mode of
  ``stiffness_curve``, for one);
* an option given again explicitly with the same value is fine; with a
  different value it raises [`ConfigError`][thermobear.ConfigError] naming
  it, since it would silently undo the calibration (build a what-if from
  ``CalibratedModel.spec_at`` instead);
* the load scales (``axial_load_scale``, ``radial_load_scale``,
  ``preload_scale``, and per level ``<scale>@<N>``) multiply the stated
  load arguments of the call (``axial_n``, ``radial_n``, ``preload_n``), as
  the calibration applied them to the measured conditions, and one by one
  the stated loads of a sequence argument (``preloads_n``,
  ``radial_loads_n``);
* a model with several members (a tie or an "unresolved" verdict: one
  member per explanation, ``members``) stands for one of them: the one
  ``member=`` names (its index, its label, or the part of its label after
  ``": "``), or, without ``member=``, the first, with an
  [`AmbiguousModelWarning`][thermobear.AmbiguousModelWarning] naming the
  members and the one used. ``member=`` on a model without members, or on
  a machine that is no calibrated model, is a
  [`ConfigError`][thermobear.ConfigError]."""

from __future__ import annotations

import functools
import inspect
import warnings
from typing import Any, Callable, Collection, Optional, Protocol, TypeVar

from .errors import AmbiguousModelWarning, ConfigError

#: The name of the hook method.
MODEL_HOOK = "_thermobear_model_"

#: The keyword that picks the member of a model with several.
MEMBER = "member"

#: Load-scale option -> the stated-load argument it multiplies.
LOAD_SCALES = {
    "axial_load_scale": "axial_n",
    "radial_load_scale": "radial_n",
    "preload_scale": "preload_n",
}

#: Sequence argument of several stated loads -> the load-scale option that
#: multiplies each of them.
LOAD_SEQUENCES = {"preloads_n": "preload_scale", "radial_loads_n": "radial_load_scale"}

F = TypeVar("F", bound=Callable[..., Any])


class CalibratedMachine(Protocol):
    """What stands for a machine in a downstream call: an object with the
    hook ``_thermobear_model_()`` (a calibrated model)."""

    def _thermobear_model_(self) -> tuple[Any, dict[str, Any]]: ...


def is_calibrated(obj: Any) -> bool:
    """Whether ``obj`` carries the calibrated-model hook."""
    return hasattr(obj, MODEL_HOOK) and not isinstance(obj, type)


def member_of(obj: Any, member: Any = None) -> Any:
    """The model that stands for one machine: ``obj`` itself without
    members; else its member ``member`` (an index, a label, or the part of
    a label after ``": "`` when only one member's label ends so), or, with
    ``member`` None, the first with an
    [`AmbiguousModelWarning`][thermobear.AmbiguousModelWarning] naming the
    members. A ``member`` that matches none, or given for a model without
    members, raises [`ConfigError`][thermobear.ConfigError]."""
    members = tuple(getattr(obj, "members", ()) or ())
    if not members:
        if member is not None:
            raise ConfigError(
                f"invalid member = {member!r}: the model has no members (only a tie or an "
                '"unresolved" model has one per explanation)'
            )
        return obj
    labels = [str(getattr(m, "label", i)) for i, m in enumerate(members)]
    listed = ", ".join(f"{i}: {lab!r}" for i, lab in enumerate(labels))
    if member is None:
        from ._limits import _outside_stacklevel

        kind = getattr(obj, "kind", "calibrated")
        warnings.warn(
            f"a {kind} model with {len(members)} members ({listed}) stands for one machine: "
            f"member 0 ({labels[0]!r}) is used; pass member=<index or label> to choose "
            "(or pass the member itself, model.members[i])",
            AmbiguousModelWarning,
            stacklevel=_outside_stacklevel(),
        )
        return members[0]
    if isinstance(member, int) and not isinstance(member, bool):
        if -len(members) <= member < len(members):
            return members[member]
    elif isinstance(member, str):
        if member in labels:
            return members[labels.index(member)]
        tails = [i for i, lab in enumerate(labels) if lab.split(": ", 1)[-1] == member]
        if len(tails) == 1:
            return members[tails[0]]
    raise ConfigError(
        f"invalid member = {member!r}: an index 0..{len(members) - 1} or a label of {listed}"
    )


def unpack_model(obj: Any, member: Any = None) -> tuple[Any, dict[str, Any]]:
    """``(machine, options)`` of a calibrated model (of its member
    ``member``: ``member_of``); any other object is returned as it is with
    no options (``member`` must then be None)."""
    if not is_calibrated(obj):
        if member is not None:
            raise ConfigError(
                f"invalid member = {member!r}: only a calibrated model (a tie or an "
                '"unresolved" one) has members; the machine given is a '
                f"{type(obj).__name__}"
            )
        return obj, {}
    machine, options = getattr(member_of(obj, member), MODEL_HOOK)()
    return machine, dict(options)


def scaled_load(options: dict[str, Any], scale: str, stated: float) -> float:
    """The load a calibrated model applies for a ``stated`` load: times the
    global ``scale`` option and the scale of that level
    (``<scale>@<stated:g>``), in that order (bit for bit the diagnosis'
    own rule)."""
    return stated * float(options.get(scale, 1.0)) * float(options.get(f"{scale}@{stated:g}", 1.0))


def _same(a: Any, b: Any) -> bool:
    if isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)):
        return sorted(map(str, a)) == sorted(map(str, b))
    try:
        return bool(a == b)
    except Exception:  # noqa: BLE001 -- arrays and the like: not the same option
        return False


def merge_options(
    options: dict[str, Any], explicit: dict[str, Any], accepted: Collection[str]
) -> dict[str, Any]:
    """The call's keyword arguments: ``explicit`` (what the caller gave)
    with the calibrated ``options`` among ``accepted`` added, the stated
    loads scaled. Raises [`ConfigError`][thermobear.ConfigError] when an
    explicit argument contradicts a calibrated option."""
    out = dict(explicit)
    for k, v in options.items():
        if k in LOAD_SCALES or "@" in k or k not in accepted:
            continue
        if k in explicit and explicit[k] is not None and not _same(explicit[k], v):
            raise ConfigError(
                f"invalid {k} = {explicit[k]!r}: the calibrated model sets {k} = {v!r}; "
                "giving it again would undo the calibration (use CalibratedModel.spec_at "
                "for a what-if)"
            )
        out[k] = v
    for scale, arg in LOAD_SCALES.items():
        if out.get(arg) is not None and (
            scale in options or any(k.startswith(scale + "@") for k in options)
        ):
            out[arg] = scaled_load(options, scale, float(out[arg]))
    for arg, scale in LOAD_SEQUENCES.items():
        if out.get(arg) is not None and (
            scale in options or any(k.startswith(scale + "@") for k in options)
        ):
            out[arg] = _scaled_sequence(options, scale, out[arg])
    return out


def _scaled_sequence(options: dict[str, Any], scale: str, values: Any) -> Any:
    """Each stated load of ``values`` scaled (``scaled_load``); values
    that are not numbers are left for the call's own check to name."""
    try:
        return [scaled_load(options, scale, float(x)) for x in values]
    except (TypeError, ValueError):
        return values


def takes_calibrated(
    extra: Optional[Callable[[dict[str, Any]], Collection[str]]] = None,
) -> Callable[[F], F]:
    """Decorator of an entry point whose first argument is a machine: a
    calibrated model there is unpacked (``merge_options``). The options
    taken are those the function has a named parameter for, plus
    ``extra(explicit)`` (names it passes on through ``**kwargs``;
    ``explicit``: the arguments the caller gave, by name). The entry point
    also takes a keyword ``member`` (``member_of``): which member of a
    model with several stands for the machine."""

    def decorate(fn: F) -> F:
        sig = inspect.signature(fn)
        params = list(sig.parameters.values())
        named = {p.name for p in params[1:] if p.kind is not p.VAR_KEYWORD}
        var_kw = next((p.name for p in params if p.kind is p.VAR_KEYWORD), None)
        own_member = MEMBER in sig.parameters

        @functools.wraps(fn)
        def wrapper(*args: Any, **kwargs: Any) -> Any:
            member = None if own_member else kwargs.pop(MEMBER, None)
            if not args or not is_calibrated(args[0]):
                if member is not None:
                    unpack_model(args[0] if args else None, member)  # names the mistake
                return fn(*args, **kwargs)
            machine, options = unpack_model(args[0], member)
            bound = sig.bind_partial(machine, *args[1:], **kwargs)
            explicit = dict(bound.arguments)
            explicit.pop(params[0].name)
            if var_kw is not None:
                explicit.update(explicit.pop(var_kw, None) or {})
            accepted = named | set(extra(explicit) if extra is not None else ())
            merged = merge_options(options, explicit, accepted)
            return fn(machine, **merged)

        if not own_member:  # the signature shows the keyword the wrapper takes
            extra_param = inspect.Parameter(
                MEMBER,
                inspect.Parameter.KEYWORD_ONLY,
                default=None,
                annotation="Union[int, str, None]",
            )
            shown = [p for p in params if p.kind is not p.VAR_KEYWORD] + [extra_param]
            shown += [p for p in params if p.kind is p.VAR_KEYWORD]
            wrapper.__signature__ = sig.replace(parameters=shown)  # type: ignore[attr-defined]
        return wrapper  # type: ignore[return-value]

    return decorate
