"""The exception hierarchy (defined in Rust, in one place: src/python/errors.rs).

``ThermobearError`` is the base; ``ConfigError`` names the field and value
of bad input; ``ConvergenceError`` gives the residual a solver reached;
``ThermalRunawayError`` (a ``ConvergenceError``) reports heat and preload
growing together; ``DataError`` rejects unusable measured data.
"""

from ._native import (
    ConfigError,
    ConvergenceError,
    DataError,
    ThermalRunawayError,
    ThermobearError,
)

__all__ = [
    "ConfigError",
    "ConvergenceError",
    "DataError",
    "ThermalRunawayError",
    "ThermobearError",
]
