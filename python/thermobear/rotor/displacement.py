"""Seed B's own vibration model, beside the physical rotor model of
``thermobear.rotor.response``: the shaft-end vibration velocity as the
once-per-revolution velocity of the front bearing's radial displacement,
v = omega (delta_r + u_Tr) (docs/concepts/spindle-rotor.md, "Seed B's
displacement vibration model").

Assumptions (seed B gives its eqs. 20-22 only in words; every choice below
is ours where its text is silent):

1. The vibration velocity is the 1X velocity amplitude of a circular orbit
   whose radius is the bearing's total radial displacement: v = omega e.
   Seed B writes that the bearing radial displacement "is the main factor
   causing bearing unbalance" and that it is "directly related to bearing
   vibration"; v = omega e is the kinematics that turns its displacement
   numbers (6.5 um at 12,000 r/min, 1.56 x 6.5 um at 18,000 r/min) into its
   velocities (8.2 and 19.1 mm/s against its 7.53 mm/s 1X and 18.78 mm/s).
   Physically a steady deflection under a fixed-direction load is not an
   orbit: treating it as one is the model's central assumption.
2. e = delta_r + u_Tr (seed B eq. 22): delta_r the radial displacement of
   the front pair under its radial load without thermal deformation, u_Tr
   the radial thermal displacement of the front bearing (A-38); both from
   [`thermobear.Spindle`][thermobear.Spindle]'s coupled steady state. Uncoupled: u_Tr = 0.
3. The radial load is the spindle's (``radial_load_n``; seed B does not
   state one); ``runout_um`` adds a mechanical eccentricity to e.
4. Seed B does not say whether its velocity is RMS or peak; the column
   ``velocity_mm_s`` is the amplitude omega e; ``velocity_rms_mm_s`` is
   omega e / sqrt 2 (a sinusoid's RMS) for comparison with
   [`thermobear.vibration`][thermobear.vibration].
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional

import numpy as np
from numpy.typing import ArrayLike

from .. import _validate as val
from ..errors import ConfigError

if TYPE_CHECKING:
    import polars


def orbit_velocity_mm_s(speed_rpm: Any, displacement_um: Any) -> np.ndarray:
    """The kernel of seed B's model: the velocity amplitude omega e [mm/s]
    of a once-per-revolution orbit of radius ``displacement_um`` [um] at
    ``speed_rpm`` [rpm] (omega = 2 pi n / 60)."""
    val.reals("speed_rpm", speed_rpm, allow_empty=True)  # numbers only, finite
    val.reals("displacement_um", displacement_um, allow_empty=True)
    n, e = np.asarray(speed_rpm, float), np.asarray(displacement_um, float)
    try:
        with np.errstate(over="ignore"):  # an overflow is refused below, by name
            v = 2.0 * np.pi * n / 60.0 * (e * 1e-3)
    except ValueError:  # shapes that do not broadcast
        raise val.fail("displacement_um", displacement_um, f"one value or {n.size}") from None
    return val.finite_result(v, {"speed_rpm": speed_rpm, "displacement_um": displacement_um})


def displacement_vibration(
    spindle: Any,
    speeds_rpm: Optional[ArrayLike] = None,
    coupled: bool = True,
    *,
    radial_load_n: Optional[float] = None,
    runout_um: float = 0.0,
) -> polars.DataFrame:
    """Seed B's vibration model (module doc): shaft-end velocity
    ``omega (delta_r + u_Tr + runout)`` of a [`thermobear.Spindle`][thermobear.Spindle] (or
    a spindle preset name) at each speed [rpm]. ``coupled``: include the
    radial thermal displacement u_Tr; ``radial_load_n``: the radial load at
    the nose [N] (default: the spindle's); ``runout_um``: an added
    once-per-revolution eccentricity [um].

    Columns ``speed_rpm, mechanical_radial_displacement_um,
    thermal_radial_displacement_um, runout_um, radial_displacement_um,
    velocity_mm_s`` (amplitude omega e) and ``velocity_rms_mm_s``."""
    import polars as pl

    from ..spindle import Spindle
    from .supports import _speeds

    sp = Spindle.preset(spindle) if isinstance(spindle, str) else spindle
    if not isinstance(sp, Spindle):
        raise ConfigError(f"invalid spindle = {spindle!r}: give a Spindle or a preset name")
    runout_um = val.real("runout_um", runout_um, 0.0)
    if radial_load_n is not None:
        sp = sp.with_options(radial_load_n=val.real("radial_load_n", radial_load_n))
    s = _speeds(speeds_rpm, np.array([6_000.0, 12_000.0, 18_000.0]), positive=True)
    coupled = val.flag("coupled", coupled)
    mech, therm = np.empty(s.size), np.empty(s.size)
    for i, v in enumerate(s):
        if coupled:  # the coupled steady state: its deflection and u_Tr
            row = sp.thermal_state(float(v)).row(0, named=True)
            therm[i] = row["thermal_radial_displacement_um"]
        else:  # the front pair without thermal effects
            row = sp.isothermal(float(v)).row(0, named=True)
            therm[i] = 0.0
        mech[i] = abs(row["radial_displacement_um"])
    e_um = mech + therm + runout_um
    v = orbit_velocity_mm_s(s, e_um)
    return pl.DataFrame(
        {
            "speed_rpm": s,
            "mechanical_radial_displacement_um": mech,
            "thermal_radial_displacement_um": therm,
            "runout_um": np.full(s.size, runout_um),
            "radial_displacement_um": e_um,
            "velocity_mm_s": v,
            "velocity_rms_mm_s": v / np.sqrt(2.0),
        }
    )
