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
  the calibration applied them to the measured conditions."""

from __future__ import annotations

import functools
import inspect
from typing import Any, Callable, Collection, Optional, Protocol, TypeVar

from .errors import ConfigError

#: The name of the hook method.
MODEL_HOOK = "_thermobear_model_"

#: Load-scale option -> the stated-load argument it multiplies.
LOAD_SCALES = {
    "axial_load_scale": "axial_n",
    "radial_load_scale": "radial_n",
    "preload_scale": "preload_n",
}

F = TypeVar("F", bound=Callable[..., Any])


class CalibratedMachine(Protocol):
    """What stands for a machine in a downstream call: an object with the
    hook ``_thermobear_model_()`` (a calibrated model)."""

    def _thermobear_model_(self) -> tuple[Any, dict[str, Any]]: ...


def is_calibrated(obj: Any) -> bool:
    """Whether ``obj`` carries the calibrated-model hook."""
    return hasattr(obj, MODEL_HOOK) and not isinstance(obj, type)


def unpack_model(obj: Any) -> tuple[Any, dict[str, Any]]:
    """``(machine, options)`` of a calibrated model; any other object is
    returned as it is with no options."""
    if not is_calibrated(obj):
        return obj, {}
    machine, options = getattr(obj, MODEL_HOOK)()
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
    return out


def takes_calibrated(
    extra: Optional[Callable[[dict[str, Any]], Collection[str]]] = None,
) -> Callable[[F], F]:
    """Decorator of an entry point whose first argument is a machine: a
    calibrated model there is unpacked (``merge_options``). The options
    taken are those the function has a named parameter for, plus
    ``extra(explicit)`` (names it passes on through ``**kwargs``;
    ``explicit``: the arguments the caller gave, by name)."""

    def decorate(fn: F) -> F:
        sig = inspect.signature(fn)
        params = list(sig.parameters.values())
        named = {p.name for p in params[1:] if p.kind is not p.VAR_KEYWORD}
        var_kw = next((p.name for p in params if p.kind is p.VAR_KEYWORD), None)

        @functools.wraps(fn)
        def wrapper(*args: Any, **kwargs: Any) -> Any:
            if not args or not is_calibrated(args[0]):
                return fn(*args, **kwargs)
            machine, options = unpack_model(args[0])
            bound = sig.bind_partial(machine, *args[1:], **kwargs)
            explicit = dict(bound.arguments)
            explicit.pop(params[0].name)
            if var_kw is not None:
                explicit.update(explicit.pop(var_kw, None) or {})
            accepted = named | set(extra(explicit) if extra is not None else ())
            merged = merge_options(options, explicit, accepted)
            return fn(machine, **merged)

        return wrapper  # type: ignore[return-value]

    return decorate
