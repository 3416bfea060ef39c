"""The rotor of a spindle laid out from its own description: the presets
keep the seed rotor bit for bit, a described spindle gets its own Campbell
diagram, critical speeds and unbalance vibration, and they follow the
physics of its dimensions."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

import thermobear as tb
from thermobear.errors import ConfigError

STEEL_E_PA = 206e9  # shaft steel (src/materials.rs)
STEEL_RHO_KG_M3 = 7800.0
CORE_RHO_KG_M3 = 7600.0


def _first_hz(sp: tb.Spindle) -> float:
    """Lowest natural frequency at rest [Hz]."""
    d = tb.campbell(sp, [0.0], modes=2)
    return float(d["frequency_hz"][0])


def _spindle(**shaft_motor: float) -> tb.Spindle:
    shaft = {k: v for k, v in shaft_motor.items() if k in ("front_span_mm", "rear_span_mm")}
    motor = {k: v for k, v in shaft_motor.items() if k.startswith("rotor_")}
    return tb.Spindle(name="my-spindle", shaft=tb.Shaft(**shaft), motor=tb.Motor(**motor))


@pytest.mark.parametrize("name", ["seed-ceramic-spindle", "seed-steel-spindle"])
def test_a_preset_keeps_the_seed_rotor_bit_for_bit(name):
    sp = tb.Spindle.from_toml(name)
    assert sp.rotor_layout is None
    s = [0.0, 15000.0]
    a, b = tb.campbell(sp, s, modes=4), tb.campbell(name, s, modes=4)
    assert a.equals(b)


def test_a_described_spindle_gets_its_own_rotor():
    sp = _spindle(front_span_mm=150.0)
    lay = sp.rotor_layout
    assert lay is not None
    # rows one bearing width apart about the pair centres, spans as described
    f, r = lay["front_rows_m"], lay["rear_rows_m"]
    assert (f[1] - f[0], r[1] - r[0]) == pytest.approx((0.016, 0.015), abs=1e-15)
    core = 0.5 * (lay["core_span_m"][0] + lay["core_span_m"][1])
    assert core - 0.5 * (f[0] + f[1]) == pytest.approx(0.150, abs=1e-15)
    assert json.loads(lay["front_bearing_json"])["name"] == "7009C-hybrid"
    # a preset's name on other dimensions would be taken for the preset: refused
    with pytest.raises(tb.ConfigError, match="name of your own.*shaft"):
        tb.Spindle(name="seed-ceramic-spindle", shaft=tb.Shaft(front_span_mm=150.0))
    # the full-ceramic preset, which the seed rotor has no rows for, gets its own
    full = tb.Spindle.preset("seed-full-ceramic-spindle").rotor_layout
    assert full is not None and json.loads(full["front_bearing_json"])["name"] == "7009C-ceramic"
    crit = tb.critical_speeds(sp, np.linspace(0.0, 120_000.0, 25), modes=4)
    assert crit.height > 0 and (crit["speed_rpm"] > 0.0).all()
    v = tb.vibration(sp, [6000.0, 12000.0], unbalance_grade=2.5)
    assert (v["velocity_rms_mm_s"] > 0.0).all()
    # steady 1X response: RMS = peak / sqrt 2
    assert np.allclose(v["velocity_rms_mm_s"] * math.sqrt(2.0), v["velocity_peak_mm_s"], rtol=1e-12)


def test_longer_span_and_heavier_motor_rotor_lower_the_first_mode():
    base = _first_hz(_spindle())
    assert _first_hz(_spindle(front_span_mm=160.0, rear_span_mm=160.0)) < base
    assert _first_hz(_spindle(rotor_diameter_mm=95.0)) < base


def test_first_bending_mode_is_near_the_simply_supported_estimate():
    """Closed form: the motor seat as a simply supported beam between the
    pair centres carrying the core at mid span (Dunkerley:
    1/f^2 = 1/f_beam^2 + 1/f_mass^2). The derived rotor adds the nose
    overhang, the tool holder and finite bearing stiffness (all lower it)
    and the stiffer bearing seats (raise it): within 25 % (it lies 4 %
    above for this spindle)."""
    sp = _spindle(front_span_mm=160.0, rear_span_mm=160.0)
    lay = sp.rotor_layout
    assert lay is not None
    _, od, di = lay["sections_m"][2]
    span = 0.320
    i_m4 = math.pi * (od**4 - di**4) / 64.0
    area = math.pi * (od**2 - di**2) / 4.0
    ei = STEEL_E_PA * i_m4
    f_beam = math.pi / (2.0 * span**2) * math.sqrt(ei / (STEEL_RHO_KG_M3 * area))
    (z0, z1), do = lay["core_span_m"], lay["core_outer_diameter_m"]
    core_kg = (
        CORE_RHO_KG_M3 * math.pi * (do**2 - lay["core_inner_diameter_m"] ** 2) / 4.0 * (z1 - z0)
    )
    f_mass = math.sqrt(48.0 * ei / span**3 / core_kg) / (2.0 * math.pi)
    estimate = 1.0 / math.sqrt(1.0 / f_beam**2 + 1.0 / f_mass**2)
    d = tb.campbell(sp, [0.0], modes=8)
    # the lowest mode at rest
    f = float(d["frequency_hz"][0])
    assert 0.8 < f / estimate < 1.25, (f, estimate)


def test_a_rotor_that_does_not_fit_is_a_named_config_error():
    with pytest.raises(ConfigError, match="rotor_length_mm"):
        _ = _spindle(front_span_mm=60.0, rear_span_mm=60.0, rotor_length_mm=150.0).rotor_layout
