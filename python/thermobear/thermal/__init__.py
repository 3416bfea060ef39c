"""Bearing heat, the seed A thermal network and the coupled
thermo-mechanical state; stiffness against speed under the constant, speed
and thermal models (crate: ``src/thermal``, bindings
``src/python/thermal.rs``)."""

from .batch import thermal_state_many
from .isothermal import IsothermalHeat, isothermal_heat
from .state import (
    HEAT_MODEL_OPTIONS,
    THERMAL_EFFECTS,
    ThermalState,
    lubrication_defaults,
    thermal_state,
)
from .stiffness import stiffness_curve, thermal_stiffness_curve

__all__ = [
    "HEAT_MODEL_OPTIONS",
    "IsothermalHeat",
    "THERMAL_EFFECTS",
    "ThermalState",
    "isothermal_heat",
    "lubrication_defaults",
    "stiffness_curve",
    "thermal_state",
    "thermal_state_many",
    "thermal_stiffness_curve",
]
