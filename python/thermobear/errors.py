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


__all__ = [
    "ConfigError",
    "ConvergenceError",
    "DataError",
    "Interrupted",
    "PlausibilityWarning",
    "ThermalRunawayError",
    "ThermobearError",
    "ThreadsWarning",
]
