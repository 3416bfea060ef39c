"""The model-spec protocol [`thermobear.diagnose`][thermobear.diagnose] runs on, whatever
the machine: ``quantities`` (the quantity registry: name -> (model column,
scale, plausible range, typical sigma, sigma is relative)),
``candidate_list(quantities)``, ``predict(conditions)`` (every quantity at
each row: name -> array), ``with_setting(add_effects, **options)`` (a copy
sharing the cache), ``options`` and ``effects``.

``ModelSpec`` is the base of the specs in this package (one module per
machine: ``thermobear.diagnosis.bearing_spec``, ``thermobear.diagnosis.spindle_spec``); any object
with the
protocol's attributes is accepted."""

from __future__ import annotations

from typing import Any, Sequence

import numpy as np

from ..errors import ConfigError

#: The attributes ``thermobear.diagnose`` needs of a model spec.
SPEC_PROTOCOL = ("quantities", "candidate_list", "predict", "with_setting", "options", "effects")


class ModelSpec:
    """A baseline model in the diagnosis protocol. Subclasses set
    ``quantities`` and, per instance, ``effects``, ``options`` and the
    ``_cache`` their copies (``with_setting``) share."""

    quantities: dict = {}
    effects: tuple[str, ...] = ()
    options: dict = {}
    _cache: dict

    @classmethod
    def of_model(cls, model: Any) -> ModelSpec:
        """The spec of a model object of its kind (e.g. a ``Bearing``) as
        configured."""
        raise NotImplementedError

    def __getstate__(self) -> dict:
        """Pickle without the solve cache: the copy solves again (the model
        objects pickle exactly, so its results are bit-identical)."""
        state = dict(self.__dict__)
        if "_cache" in state:
            state["_cache"] = {}
        return state

    def candidate_list(self, quantities: Sequence[str] = ()) -> list:
        """The candidates against this baseline, with a sensor-offset decoy
        per measured quantity in ``quantities``."""
        raise NotImplementedError

    def predict(self, conditions: Any) -> dict[str, np.ndarray]:
        """Every supported quantity at each row of ``conditions``."""
        raise NotImplementedError

    def with_setting(self, add_effects: Sequence[str] = (), **options: Any) -> ModelSpec:
        """A copy with effects added and options replaced (shares the cache)."""
        raise NotImplementedError

    @property
    def model_runs(self) -> int:
        """Model sweeps solved so far (one per configuration and load case;
        shared by the copies of ``with_setting``)."""
        return len(self._cache)

    def _key(self) -> tuple:
        return (self.effects, tuple(sorted((k, str(v)) for k, v in self.options.items())))


def check_spec(model: Any) -> None:
    """Raise [`ConfigError`][thermobear.ConfigError] unless ``model`` has every
    attribute of ``SPEC_PROTOCOL``."""
    if not all(hasattr(model, a) for a in SPEC_PROTOCOL):
        raise ConfigError(
            f"invalid model = {model!r}: give a thermobear.BearingModelSpec or "
            "SpindleModelSpec (or an object with " + ", ".join(SPEC_PROTOCOL) + ")"
        )


#: Model kinds the diagnosis verbs dispatch on, in registration order:
#: kind name -> (model class, spec class, quantity registry). Each spec
#: module registers its machine (``register_kind``), so that
#: ``thermobear.diagnose``, ``thermobear.load_measurements``,
#: ``thermobear.candidates`` and ``thermobear.calibrate`` take a
#: bearing or a spindle alike.
MODEL_KINDS: dict[str, tuple[type, type[ModelSpec], dict]] = {}


def register_kind(
    kind: str, model_class: type, spec_class: type[ModelSpec], quantities: dict
) -> None:
    """Register a machine: its model class (e.g. ``Bearing``), the spec
    class that wraps it and the spec's quantity registry."""
    MODEL_KINDS[kind] = (model_class, spec_class, quantities)


def as_spec(model: Any) -> Any:
    """The model spec of ``model``: a spec is returned as it is; a model
    object of a registered kind (a [`Bearing`][thermobear.Bearing], a
    [`Spindle`][thermobear.Spindle]) becomes its spec with the model as
    configured (the spec's default options, every effect of the model on);
    a calibrated model ([`CalibratedModel`][thermobear.CalibratedModel])
    gives its spec at the estimate (its ``spec``). Anything else raises
    [`ConfigError`][thermobear.ConfigError]."""
    if hasattr(model, "spec_at") and hasattr(model, "spec"):
        model = model.spec
    for _, (model_class, spec_class, _) in MODEL_KINDS.items():
        if isinstance(model, spec_class):
            return model
        if isinstance(model, model_class):
            return spec_class.of_model(model)
    check_spec(model)
    return model


def quantities_of(model: Any) -> dict:
    """The quantity registry of ``model``: a spec or model object (as
    ``as_spec``) or a kind name (``"bearing"``, ``"spindle"``)."""
    if isinstance(model, str):
        if model not in MODEL_KINDS:
            raise ConfigError(f"invalid model = {model!r}: known kinds: {', '.join(MODEL_KINDS)}")
        return MODEL_KINDS[model][2]
    return as_spec(model).quantities


def kind_of_quantities(names: Sequence[str], has_preload: bool = False) -> str:
    """The registered kind whose quantity registry knows every name in
    ``names`` (a measured table's quantities); of several, the spindle when
    the table states a ``preload_n`` column, else the bearing. When none knows them all, the kind
    that knows most
    (its checks then name the unknown quantity)."""
    known = {k: _known_count(names, q) for k, (_, _, q) in MODEL_KINDS.items()}
    full = [k for k, n in known.items() if n == len(set(names))]
    if len(full) > 1 and has_preload and "spindle" in full:
        return "spindle"
    if full:
        return "bearing" if "bearing" in full else full[0]
    return max(known, key=lambda k: known[k])


def _known_count(names: Sequence[str], table: dict) -> int:
    """How many distinct ``names`` ``table`` knows, directly or by the
    deprecated ``temperature_c:<node>`` form of a temperature quantity."""
    return sum(1 for n in set(names) if n in table or _current_name(n) in table)


def _current_name(name: str) -> str:
    """The current name of a deprecated ``temperature_c:<node>`` quantity
    (``temperature_c:To`` -> ``outer_ring_temperature_c``,
    ``temperature_c:front_outer`` -> ``front_outer_ring_temperature_c``);
    other names unchanged."""
    from .._names import BEARING_SYMBOLS, spindle_node, temperature_column

    if not name.startswith("temperature_c:"):
        return name
    node = name.split(":", 1)[1]
    return temperature_column(BEARING_SYMBOLS.get(node) or spindle_node(node))
