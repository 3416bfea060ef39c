"""Two spindle inputs a study may leave out: the factor on Palmgren's
load-friction factor f1 (``load_friction_scale``) and the contact
conductance of the outer rings' seats (``outer_ring_contact_w_per_m2_k``).
Each is checked against a limit it must meet, through every path a user
reaches it by (with_options, the description parts and file, the
calibration candidates)."""

from __future__ import annotations

import numpy as np
import pytest

import thermobear as tb
from thermobear.diagnosis.spindle_spec import UNSTATED_BOUNDS, SpindleModelSpec
from thermobear.spindle.dimensions import with_dimensions

SPEED = 15_000.0


@pytest.fixture(scope="module")
def spindle() -> tb.Spindle:
    return tb.Spindle.preset("seed-ceramic-spindle")


def _state(sp: tb.Spindle, preload_n: float = 400.0) -> dict:
    return tb.thermal_state(sp.with_options(preload_n=preload_n), speed_rpm=SPEED).row(
        0, named=True
    )


def test_load_friction_scale_one_is_the_preset_and_zero_removes_the_load_heat(spindle):
    """Factor 1 changes nothing (bit for bit); the heat's preload
    dependence grows with the factor: the load moment is the term that
    carries it (the viscous moment does not see the load)."""
    assert _state(spindle.with_options(load_friction_scale=1.0)) == _state(spindle)

    def preload_rise(s: float) -> float:
        sp = spindle.with_options(load_friction_scale=s)
        return _state(sp, 500.0)["front_bearing_heat_w"] - _state(sp, 300.0)["front_bearing_heat_w"]

    rises = [preload_rise(s) for s in (0.0, 1.0, 4.0)]
    assert rises[0] < rises[1] < rises[2]
    # the load part grows in proportion: (r4 - r0) = 4 (r1 - r0) within the
    # few per cent the hotter oil's lower viscosity takes off the viscous heat
    assert (rises[2] - rises[0]) / (rises[1] - rises[0]) == pytest.approx(4.0, rel=0.1)
    # the energy balance still closes
    s = _state(spindle.with_options(load_friction_scale=4.0))
    assert s["total_heat_w"] == pytest.approx(s["boundary_flow_w"], rel=1e-6)


def test_load_friction_scale_is_checked_and_palmgren_only(spindle):
    with pytest.raises(tb.ConfigError, match="load_friction_scale"):
        spindle.with_options(load_friction_scale=-1.0)
    with pytest.raises(tb.ConfigError, match="load_friction_scale"):
        spindle.with_options(heat_model="skf", load_friction_scale=2.0)


def test_a_perfect_seat_is_the_limit_of_a_rising_conductance(spindle):
    """The seat's resistance 1/(h pi D 2B) vanishes as h grows: a very
    large h gives the perfect-contact default; a smaller h raises the outer
    ring above its housing, monotonically."""
    base = _state(spindle)
    stiff = _state(with_dimensions(spindle, outer_ring_contact_w_per_m2_k=1e12))
    assert stiff["front_outer_ring_temperature_c"] == pytest.approx(
        base["front_outer_ring_temperature_c"], abs=1e-6
    )
    lift = [
        _state(with_dimensions(spindle, outer_ring_contact_w_per_m2_k=h)) for h in (1e4, 2e3, 500.0)
    ]
    gaps = [s["front_outer_ring_temperature_c"] - s["front_housing_temperature_c"] for s in lift]
    base_gap = base["front_outer_ring_temperature_c"] - base["front_housing_temperature_c"]
    assert base_gap < gaps[0] < gaps[1] < gaps[2]
    for s in lift:
        assert s["total_heat_w"] == pytest.approx(s["boundary_flow_w"], rel=1e-6)
    with pytest.raises(tb.ConfigError, match="outer_ring_contact_w_per_m2_k"):
        with_dimensions(spindle, outer_ring_contact_w_per_m2_k=0.0)


def test_both_inputs_round_trip_through_the_description_file():
    parts = {
        "lubrication": tb.Lubrication(load_friction_scale=3.0),
        "housing": tb.Housing(outer_ring_contact_w_per_m2_k=2500.0),
    }
    sp = tb.Spindle(name="seat-and-friction", **parts)
    text = sp.to_toml()
    assert "load_friction_scale = 3.0" in text
    assert "outer_ring_contact_w_per_m2_k = 2500.0" in text
    back = tb.Spindle.from_toml(text)
    assert back.to_toml() == text
    a, b = back.thermal_state(SPEED), sp.thermal_state(SPEED)
    assert a.equals(b)
    with pytest.raises(tb.ConfigError, match="outer_ring_contact_w_per_m2_k"):
        tb.Housing(outer_ring_contact_w_per_m2_k=-5.0)


def test_both_are_calibration_candidates_when_declared(spindle):
    spec = SpindleModelSpec(spindle, load_friction_scale=1.0, outer_ring_contact_w_per_m2_k=3e4)
    cands = {c.name: c for c in spec.candidate_list()}
    for name in ("load_friction_scale", "outer_ring_contact_w_per_m2_k"):
        assert (cands[name].lower, cands[name].upper) == UNSTATED_BOUNDS[name]
    plain = {c.name for c in SpindleModelSpec(spindle).candidate_list()}
    assert "load_friction_scale" not in plain
    # declared at 1 the load friction changes nothing
    cond = {"speed_rpm": [SPEED], "preload_n": [400.0]}
    import polars as pl

    ref = SpindleModelSpec(spindle).predict(pl.DataFrame(cond))
    got = SpindleModelSpec(spindle, load_friction_scale=1.0).predict(pl.DataFrame(cond))
    for q in ("front_ball_temperature_c", "axial_growth_um"):
        assert np.array_equal(ref[q], got[q])
