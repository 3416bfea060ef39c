"""Motorized spindle (seed B): two back-to-back angular-contact bearing
pairs on one shaft, rigid or spring preload, coupled with the spindle's
thermal network (motor losses, water jacket, oil-air).

``Spindle.preset("seed-ceramic-spindle")`` has hybrid bearings (Si3N4 balls,
steel rings), ``"seed-steel-spindle"`` all-steel ones. Every assumption
(dimensions, losses, fits, preload model) is listed by
``Spindle.assumptions``. All functions return polars DataFrames with
unit-suffixed columns; sweeps run in Rust across threads with the GIL
released (Ctrl-C works, ``progress(done, total)`` is called between chunks).
"""

from .operation import compensation_preload, optimal_preload, spindle_grid, transient
from .parts import (
    BearingSet,
    Cooling,
    Housing,
    Lubrication,
    MagneticPull,
    Motor,
    Preload,
    Shaft,
    ShaftSegment,
    ToolLoad,
)
from .spindle import SEED_B_SPRING_RATE_N_PER_UM, Spindle

__all__ = [
    "SEED_B_SPRING_RATE_N_PER_UM",
    "BearingSet",
    "Cooling",
    "Housing",
    "Lubrication",
    "MagneticPull",
    "Motor",
    "Preload",
    "Shaft",
    "ShaftSegment",
    "Spindle",
    "ToolLoad",
    "compensation_preload",
    "optimal_preload",
    "spindle_grid",
    "transient",
]
