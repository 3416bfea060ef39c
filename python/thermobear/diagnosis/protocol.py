"""The model-spec protocol :func:`thermobear.diagnose` runs on, whatever
the machine: ``quantities`` (the quantity registry: name -> (model column,
scale, plausible range, typical sigma, sigma is relative)),
``candidate_list(quantities)``, ``predict(conditions)`` (every quantity at
each row: name -> array), ``with_setting(add_effects, **options)`` (a copy
sharing the cache), ``options`` and ``effects``.

:class:`ModelSpec` is the base of the specs in this package (one module per
machine: :mod:`.bearing_spec`, :mod:`.spindle_spec`); any object with the
protocol's attributes is accepted."""

from __future__ import annotations

from typing import Any, Sequence

import numpy as np

from ..errors import ConfigError

#: The attributes :func:`thermobear.diagnose` needs of a model spec.
SPEC_PROTOCOL = ("quantities", "candidate_list", "predict", "with_setting", "options", "effects")


class ModelSpec:
    """A baseline model in the diagnosis protocol. Subclasses set
    ``quantities`` and, per instance, ``effects``, ``options`` and the
    ``_cache`` their copies (:meth:`with_setting`) share."""

    quantities: dict = {}
    effects: tuple[str, ...] = ()
    options: dict = {}
    _cache: dict

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
        shared by the copies of :meth:`with_setting`)."""
        return len(self._cache)

    def _key(self) -> tuple:
        return (self.effects, tuple(sorted((k, str(v)) for k, v in self.options.items())))


def check_spec(model: Any) -> None:
    """Raise :class:`~thermobear.ConfigError` unless ``model`` has every
    attribute of :data:`SPEC_PROTOCOL`."""
    if not all(hasattr(model, a) for a in SPEC_PROTOCOL):
        raise ConfigError(
            f"invalid model = {model!r}: give a thermobear.BearingModelSpec or "
            "SpindleModelSpec (or an object with " + ", ".join(SPEC_PROTOCOL) + ")"
        )
