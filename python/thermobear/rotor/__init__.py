"""Rotor dynamics of the seed B motorized spindle on bearing-solver rows.

Every function takes a ``spindle`` argument, either

* a preset name: ``"seed-ceramic-spindle"`` (7009C/7008C hybrid rows, Si3N4
  balls) or ``"seed-steel-spindle"`` (all-steel rows), back-to-back pairs
  under a 400 N constant-force preload (seed B's test), or
* any object following the **spindle protocol**:

  - ``rotor_preset_name: str`` — one of the two preset names above (the
    shaft, rotor core, tool holder and bearing positions of
    ``src/rotor/presets.rs``, every assumed dimension documented there);
  - or ``rotor_layout: dict`` — the spindle's own rotor (shaft steps, row
    positions, motor core, bearings), as ``thermobear.Spindle.rotor_layout``
    lays it out from a described spindle (None: use ``rotor_preset_name``);
  - optional ``preload_n: float`` — axial preload of each pair [N] (400 N);
  - optional ``raceway_offsets(speed_rpm: float) -> dict`` returning
    ``{"front": (radial_m, axial_m), "rear": (radial_m, axial_m)}``: the
    thermal groove-centre offsets u_Tr, u_Ta (A-38) of the front (7009C)
    and rear (7008C) pairs at that speed, from the spindle's thermal model.
    This is the seam of the thermal coupling: ``coupled=True`` calls it at
    every requested speed and solves the rows with those offsets; zero
    offsets reproduce the uncoupled model exactly.

The vibration is the x velocity of the tool nose (shaft end). Amplitudes of
1X/2X/3X and of the spectrum are single-sided peak amplitudes [mm/s].
"""

from .displacement import displacement_vibration, orbit_velocity_mm_s
from .modes import campbell, critical_speeds
from .response import spectrum, spectrum_orders, vibration
from .supports import SPINDLE_PRESETS

__all__ = [
    "SPINDLE_PRESETS",
    "campbell",
    "critical_speeds",
    "displacement_vibration",
    "orbit_velocity_mm_s",
    "spectrum",
    "spectrum_orders",
    "vibration",
]
