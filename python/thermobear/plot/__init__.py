"""Figures, one module per topic (bearing, thermal, spindle, rotor, gear,
diagnosis, prediction). Every function takes ``ax=None`` (a new figure is made when
omitted), passes its ``**kwargs`` on to its main artist (lines, markers,
bars or mesh: ``color``, ``lw``, ``rasterized`` ...) and returns the matplotlib
Axes; matplotlib is imported lazily. Every figure is drawn in one style
(``set_style`` changes it); axes and legends name quantities in words with
their units (``axis_label``), and legends stand beside the axes."""

from .bearing import ball_loads, contact_angles, stiffness_cases, stiffness_curve
from .diagnosis import diagnosis_fit, diagnosis_residuals
from .gear import bifurcation, regime_map
from .labels import axis_label
from .prediction import prediction_band, regime_probability
from .rotor import campbell, spectrum, vibration
from .spindle import (
    compensation_preload,
    optimal_preload,
    spindle_temperatures,
    spindle_transient,
)
from .style import set_style
from .thermal import heat_vs_speed, node_temperatures, thermal_deformations

__all__ = [
    "axis_label",
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
    "set_style",
    "spectrum",
    "spindle_temperatures",
    "spindle_transient",
    "stiffness_cases",
    "stiffness_curve",
    "thermal_deformations",
    "vibration",
]
