"""The choices of the public API as ``Literal`` types, one alias per option.

A type checker then rejects a misspelt choice (``direction="dwon"``) before
the code runs; at run time each function still checks its value and raises a
[`ConfigError`][thermobear.ConfigError] naming the field. Every alias lists exactly
the values its function accepts.
"""

from __future__ import annotations

from typing import Literal

#: Sweep direction of a gear bifurcation: speeds ascending with each speed
#: starting from the last state, descending, or every speed from rest.
Direction = Literal["up", "down", "independent"]

#: Which stiffness a curve or a gear system uses: zero-speed (static),
#: quasi-static at speed, or the coupled thermal state at speed.
StiffnessMode = Literal["constant", "speed", "thermal"]

#: The friction-heat model of a bearing.
HeatModel = Literal["palmgren", "skf"]

#: The lubrication method (sets f0 and the drag of the SKF-style model).
Lubrication = Literal["grease", "oil-air", "oil-mist", "jet", "oil-bath"]

#: The raceway on which the balls roll without spinning.
RacewayControl = Literal["outer", "inner"]

#: When the gear mesh damping acts.
MeshDamping = Literal["in-contact", "always"]

#: The mesh stiffness model of a gear pair.
MeshModel = Literal["potential-energy", "iso"]

#: What a bearing stiffness frame of a gear system holds.
BearingStiffnessPer = Literal["bearing", "shaft"]

#: The time unit of a Lyapunov exponent.
LyapunovPer = Literal["s", "mesh_period"]

#: How a largest Lyapunov exponent is estimated.
LyapunovMethod = Literal["benettin", "variational"]

#: How a vibration response is computed: steady unbalance response or time
#: integration.
ResponseMethod = Literal["frequency", "time"]

#: Which model a vibration response uses: the spindle's rotor, or seed B's
#: once-per-revolution orbit model.
VibrationModel = Literal["rotor", "seed-b"]

#: The rows of the effects registry.
EffectKind = Literal["switch", "term", "model"]

#: How a spindle's preload is applied.
PreloadKind = Literal["rigid", "spring"]

#: The kinds of design study.
StudyKind = Literal["bearing", "thermal", "spindle", "gear", "prediction", "regime_prediction"]

__all__ = [
    "BearingStiffnessPer",
    "Direction",
    "EffectKind",
    "HeatModel",
    "Lubrication",
    "LyapunovMethod",
    "LyapunovPer",
    "MeshDamping",
    "MeshModel",
    "PreloadKind",
    "RacewayControl",
    "ResponseMethod",
    "StiffnessMode",
    "StudyKind",
    "VibrationModel",
]
