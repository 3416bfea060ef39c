"""thermobear: how the heat in a rolling bearing changes its stiffness, and
with it the vibration of the machine it carries.

Rust core (``thermobear._native``) with a Python front that returns polars
DataFrames and draws matplotlib figures. Units are in every name:
``speed_rpm``, ``axial_n``, ``ball_diameter_mm``, ``stiffness_n_per_m``.
Results are SI unless the name says otherwise.
"""

from __future__ import annotations

from typing import Optional

from . import _native
from .bearing import Bearing, BearingSolution, Material, stiffness_curve
from .config import load_config, seed_config, seed_config_names
from .diagnosis import BearingModelSpec, Diagnosis, candidates, diagnose, load_measurements
from .diagnosis_spindle import (
    SpindleModelSpec,
    diagnose_spindle,
    load_spindle_measurements,
    seed_b_measurements,
    spindle_candidates,
)
from .errors import (
    ConfigError,
    ConvergenceError,
    DataError,
    ThermalRunawayError,
    ThermobearError,
)
from .gear import (
    GearPair,
    GearSystem,
    bifurcation,
    bifurcation_set,
    gear_defaults,
    largest_lyapunov,
    regime_map,
    regimes,
)
from .rotor import campbell, critical_speeds, spectrum, spectrum_orders, vibration
from .spindle import (
    Spindle,
    compensation_preload,
    optimal_preload,
    spindle_grid,
    transient,
)
from .thermal import ThermalState, thermal_state

__version__: str = _native.__version__


def effects(kind: Optional[str] = None) -> "polars.DataFrame":  # noqa: F821
    """The effects registry: every physical effect a model can include or
    leave out, one row each (see :func:`thermobear.diagnosis.effect_registry`
    for the columns). ``kind="switch"``: the named effects for
    ``effects=[...]``; ``kind="term"``: the terms with a calibratable input
    whose null value leaves them out (extra heat, housing conductance ...)."""
    from .diagnosis import effect_registry

    return effect_registry(kind)


from . import plot  # noqa: E402  (plot imports matplotlib lazily)

__all__ = [
    "campbell",
    "critical_speeds",
    "spectrum",
    "spectrum_orders",
    "vibration",
    "Bearing",
    "BearingModelSpec",
    "BearingSolution",
    "Diagnosis",
    "candidates",
    "diagnose",
    "load_measurements",
    "SpindleModelSpec",
    "diagnose_spindle",
    "load_spindle_measurements",
    "seed_b_measurements",
    "spindle_candidates",
    "ConfigError",
    "ConvergenceError",
    "DataError",
    "GearPair",
    "GearSystem",
    "Material",
    "ThermalRunawayError",
    "ThermalState",
    "ThermobearError",
    "bifurcation",
    "bifurcation_set",
    "effects",
    "gear_defaults",
    "largest_lyapunov",
    "load_config",
    "plot",
    "regime_map",
    "regimes",
    "seed_config",
    "seed_config_names",
    "stiffness_curve",
    "Spindle",
    "compensation_preload",
    "optimal_preload",
    "spindle_grid",
    "thermal_state",
    "transient",
]
