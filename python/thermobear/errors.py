"""The exception hierarchy (defined in Rust, in one place: src/python/errors.rs).

``ThermobearError`` is the base; ``ConfigError`` names the field and value
of bad input; ``ConvergenceError`` gives the residual a solver reached;
``ThermalRunawayError`` (a ``ConvergenceError``) reports heat and preload
growing together; ``DataError`` rejects unusable measured data;
``Interrupted`` stops long work whose progress callback returned False
(attributes ``done`` and ``total``; Ctrl-C raises ``KeyboardInterrupt``).

``ThreadsWarning`` (a ``RuntimeWarning``) says that a ``threads`` argument
above the number of available cores was capped to it.

``PlausibilityWarning`` (a ``UserWarning``, defined here in Python) says
that an input or a result lies past what real machines do (the limits of
[`thermobear.plausibility`][thermobear.plausibility], listed with their
sources in the docs page "Limits"); the result is still returned.

``ExtrapolationWarning`` (a ``UserWarning``) says that a prediction of a
calibrated model reaches far past the conditions it was calibrated at;
``AmbiguousModelWarning`` (a ``UserWarning``) says that a calibrated model
with several members (a tie, an "unresolved" verdict) stood for one machine
and which member was used.
"""

from ._native import (
    ConfigError,
    ConvergenceError,
    DataError,
    Interrupted,
    ThermalRunawayError,
    ThermobearError,
    ThreadsWarning,
)


class PlausibilityWarning(UserWarning):
    """An input or a result past what real machines do (a speed past what
    the lubrication supports, a contact pressure past the material's static
    limit, a misalignment past a few milliradians): the model still holds
    and the result is returned. Silence it with ``warnings.filterwarnings
    ("ignore", category=thermobear.PlausibilityWarning)``; tighten or widen
    the limits with [`set_limits`][thermobear.set_limits]."""


class ExtrapolationWarning(UserWarning):
    """A prediction of a calibrated model at conditions far past those it
    was calibrated at (more than ``MAX_BEYOND_MEASURED`` of
    ``thermobear.predict.extrapolation`` beyond the measured speeds or
    loads; the docs page "Limits" gives the rule). The prediction is still
    returned, with the distance in its ``*_beyond_measured`` columns.
    Silence it with ``warnings.filterwarnings("ignore",
    category=thermobear.ExtrapolationWarning)``."""


class AmbiguousModelWarning(UserWarning):
    """A calibrated model with several members (a tie or an "unresolved"
    verdict: one member per explanation) stood for one machine without
    ``member=``: the message names the members and the one used (the
    first). Pass ``member=`` (a label or an index) to choose."""


__all__ = [
    "AmbiguousModelWarning",
    "ConfigError",
    "ConvergenceError",
    "DataError",
    "ExtrapolationWarning",
    "Interrupted",
    "PlausibilityWarning",
    "ThermalRunawayError",
    "ThermobearError",
    "ThreadsWarning",
]
