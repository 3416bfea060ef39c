"""Unbalanced magnetic pull as a bearing load of the thermal spindle model.

Seed B ("Experimental results and analysis") blames the front bearing's
excess temperature on the unbalanced magnetic pull (UMP) of the eccentric
rotor. With the ``unbalanced_magnetic_pull`` effect on, the static pull
k_ump e_static of the rotor preset's air gap acts on the shaft at the rotor
core (along y, perpendicular to the nose load) and loads both bearing pairs
by the lever rule of a rigid shaft: more load friction (A-20), a warmer
front pair.
"""

from __future__ import annotations

import pytest

import thermobear as tb

UMP = "unbalanced_magnetic_pull"
SPEED_RPM = 12_000.0


@pytest.fixture(scope="module")
def spindle() -> tb.Spindle:
    return tb.Spindle.preset("seed-ceramic-spindle")


@pytest.fixture(scope="module")
def rows(spindle: tb.Spindle) -> tuple[dict, dict]:
    every = tb.effects("switch")["name"].to_list()
    on = spindle.with_options(effects=every).thermal_state(SPEED_RPM)
    off = spindle.with_options(effects=[e for e in every if e != UMP]).thermal_state(SPEED_RPM)
    return on.row(0, named=True), off.row(0, named=True)


def test_pull_is_in_static_equilibrium_on_the_shaft(spindle: tb.Spindle, rows) -> None:
    on, off = rows
    a = spindle.assumptions
    assert off["magnetic_pull_n"] == 0.0
    f = on["magnetic_pull_n"]
    assert f == pytest.approx(a["magnetic_pull_static_n"], rel=1e-12) and f > 0.0
    # Force balance: the two pairs carry the whole pull (y) between them,
    # and nothing along x (no nose load).
    tol = 1e-6 * spindle.preload_n
    assert on["front_pair_radial_y_n"] + on["rear_pair_radial_y_n"] == pytest.approx(f, abs=tol)
    assert abs(on["front_pair_radial_x_n"]) < tol and abs(on["rear_pair_radial_x_n"]) < tol
    # Moment balance about the front pair centre: rear reaction x span = pull x
    # its lever (the core c behind the front pair).
    span_mm = a["front_span_mm"] + a["rear_span_mm"]
    c_mm = a["magnetic_pull_core_from_front_pair_mm"]
    assert 0.0 < c_mm < span_mm
    assert on["rear_pair_radial_y_n"] * span_mm == pytest.approx(f * c_mm, abs=tol * span_mm)
    # Without the pull the pairs carry no radial load at all.
    assert abs(off["front_pair_radial_y_n"]) < tol and abs(off["rear_pair_radial_y_n"]) < tol


def test_pull_heats_the_front_pair(spindle: tb.Spindle, rows) -> None:
    on, off = rows
    rise_k = on["front_outer_ring_temperature_c"] - off["front_outer_ring_temperature_c"]
    print(
        f"\nUMP {on['magnetic_pull_n']:.1f} N at {SPEED_RPM:.0f} rpm: front outer ring "
        f"{off['front_outer_ring_temperature_c']:.3f} -> "
        f"{on['front_outer_ring_temperature_c']:.3f} C ({rise_k:+.4f} K), "
        f"front bearing heat {off['front_bearing_heat_w']:.3f} -> "
        f"{on['front_bearing_heat_w']:.3f} W"
    )
    # More radial load, more load friction in the front bearings.
    assert on["front_bearing_heat_w"] > off["front_bearing_heat_w"]
    assert on["bearing_heat_w"] > off["bearing_heat_w"]
    assert rise_k > 0.0
    assert on["front_ball_temperature_c"] > off["front_ball_temperature_c"]
    # The larger contact loads: the most loaded ball presses harder.
    assert on["inner_load_max_n"] > off["inner_load_max_n"]
    # Still a steady state: all heat leaves through the boundaries.
    assert on["boundary_flow_w"] == pytest.approx(on["total_heat_w"], rel=1e-6)


def test_pull_is_off_by_default_as_in_the_rotor_model(spindle: tb.Spindle, rows) -> None:
    _, off = rows
    default = spindle.thermal_state(SPEED_RPM).row(0, named=True)
    assert default["magnetic_pull_n"] == 0.0
    assert default["front_outer_ring_temperature_c"] == off["front_outer_ring_temperature_c"]
