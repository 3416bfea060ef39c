"""Helical gear pair nonlinear dynamics (seed A, docs/concepts/physics.md §7).

* [`GearPair`][thermobear.GearPair]: geometry, contact ratios, ISO 6336-1 stiffness, the
  time-varying mesh stiffness (potential-energy method), typo checks of
  paper-style tables.
* [`GearSystem`][thermobear.GearSystem]: the 8-DOF model (A-43 .. A-52; the two rotations
  reduced to the relative mesh coordinate, 7 DOF) with the computed mesh
  stiffness (normal direction, ``k_t / cos^2(beta)``) and the bearings'
  support stiffness against speed (``"constant"``, ``"speed"``,
  ``"thermal"``: one bearing's, times ``bearings_per_shaft`` = 2 in
  parallel; or a user frame ``bearing_stiffness_per="bearing"`` or
  ``"shaft"``). Mesh stiffness and transmission error may be given as
  tables or callables (``thermobear.gear.tables``); negative torque is
  coast.
* [`bifurcation`][thermobear.bifurcation], [`bifurcation_set`][thermobear.bifurcation_set],
[`regimes`][thermobear.regimes],
  [`regime_map`][thermobear.regime_map], [`largest_lyapunov`][thermobear.largest_lyapunov].

Every value the seed omits has a documented default ([`gear_defaults`][thermobear.gear_defaults]):
half backlash b = 50 um (``half_backlash_um``; total clearance
``backlash_total_um`` = 100 um), mesh damping ratio 0.07
acting only while the teeth touch (A-46 as printed; ``mesh_damping="always"``
for the docs/concepts/physics.md §7 form), bearing damping ratio 0.02, first-harmonic
transmission error 2 um.
"""

from .dynamics import bifurcation, bifurcation_set, largest_lyapunov, regime_map, regimes
from .pair import GearPair, gear_defaults
from .system import GearSystem

__all__ = [
    "GearPair",
    "GearSystem",
    "bifurcation",
    "bifurcation_set",
    "gear_defaults",
    "largest_lyapunov",
    "regime_map",
    "regimes",
]
