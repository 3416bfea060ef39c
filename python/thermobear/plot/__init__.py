"""Figures, one module per topic (bearing, thermal, spindle, rotor, gear,
diagnosis, prediction). Every function takes ``ax=None`` (a new figure is made when
omitted) and returns the matplotlib Axes; matplotlib is imported lazily."""

from .bearing import ball_loads, contact_angles, stiffness_cases, stiffness_curve
from .diagnosis import diagnosis_fit, diagnosis_residuals
from .gear import bifurcation, regime_map
from .prediction import prediction_band, regime_probability
from .rotor import campbell, spectrum, vibration
from .spindle import (
    compensation_preload,
    optimal_preload,
    spindle_temperatures,
    spindle_transient,
)
from .thermal import heat_vs_speed, node_temperatures, thermal_deformations

__all__ = [
    "ball_loads",
    "bifurcation",
    "campbell",
    "compensation_preload",
    "contact_angles",
    "diagnosis_fit",
    "diagnosis_residuals",
    "heat_vs_speed",
    "node_temperatures",
    "optimal_preload",
    "prediction_band",
    "regime_map",
    "regime_probability",
    "spectrum",
    "spindle_temperatures",
    "spindle_transient",
    "stiffness_cases",
    "stiffness_curve",
    "thermal_deformations",
    "vibration",
]
