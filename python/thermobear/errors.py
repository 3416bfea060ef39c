"""The exception hierarchy (defined in Rust, in one place: src/python/errors.rs).

``ThermobearError`` is the base; ``ConfigError`` names the field and value
of bad input; ``ConvergenceError`` gives the residual a solver reached;
``ThermalRunawayError`` (a ``ConvergenceError``) reports heat and preload
growing together; ``DataError`` rejects unusable measured data;
``Interrupted`` stops long work whose progress callback returned False
(attributes ``done`` and ``total``; Ctrl-C raises ``KeyboardInterrupt``).

``ThreadsWarning`` (a ``RuntimeWarning``) says that a ``threads`` argument
above the number of available cores was capped to it.
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

__all__ = [
    "ConfigError",
    "ConvergenceError",
    "DataError",
    "Interrupted",
    "ThermalRunawayError",
    "ThermobearError",
    "ThreadsWarning",
]
