"""Ball drag ("churning") heat of the coupled thermal model: the balls
orbiting through the oil-air mixture of the bearing cavity (Harris &
Kotzalas, ball drag), P = Z (pi/64) C_D X rho_oil D^2 dm^3 omega_c^3."""

from __future__ import annotations

import math

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear import diagnosis as D

SPEED_RPM = 18000.0
AXIAL_N = 300.0
FRACTION = 0.01
# Sphere drag coefficient, subcritical Reynolds range (White, Fluid
# Mechanics: sphere, laminar boundary layer, 0.47); the model's constant.
C_D = 0.47
# "e-drive ATF" preset: 845 kg/m^3 at 15 C, density law rho15 (1 - 6.4e-4 (T - 15))
# (src/thermal/lubricant.rs).
RHO_15C_KG_M3 = 845.0
BETA_PER_K = 6.4e-4


@pytest.fixture(scope="module")
def bearing() -> tb.Bearing:
    return tb.Bearing.preset("7008C")


@pytest.fixture(scope="module")
def states(bearing):
    return {
        x: tb.thermal.thermal_state(bearing, SPEED_RPM, AXIAL_N, 0.0, churning_oil_fraction=x)
        for x in (0.0, FRACTION)
    }


def _drag_by_hand(bearing: tb.Bearing, s, x: float) -> float:
    """F_D = 0.5 X rho C_D (pi D^2 / 4) v^2 at v = dm omega_c / 2, times v and Z."""
    g = bearing.geometry
    d_m = g["ball_diameter_mm"] * 1e-3
    dm_m = g["pitch_diameter_mm"] * 1e-3
    z = int(g["ball_count"])
    omega_c = float(np.mean(s.solution.balls["orbit_speed_rpm"].to_numpy())) * math.pi / 30.0
    rho = RHO_15C_KG_M3 * (1.0 - BETA_PER_K * (s.oil_temperature_c - 15.0))
    v = 0.5 * dm_m * omega_c
    force = 0.5 * x * rho * C_D * (math.pi * d_m**2 / 4.0) * v**2
    return z * force * v


def test_churning_heat_is_the_ball_drag_closed_form_at_the_solved_cage_speed(bearing, states):
    s = states[FRACTION]
    p = _drag_by_hand(bearing, s, FRACTION)
    assert p > 1.0
    assert s.churning_heat_w == pytest.approx(p, rel=1e-9)
    heat = s.heat
    assert heat.filter(pl.col("source") == "churning")["heat_w"][0] == pytest.approx(p, rel=1e-9)
    # The heat leaves through the boundaries: the sources, churning included, balance.
    assert s.boundary_flows["heat_w"].sum() == pytest.approx(heat["heat_w"].sum(), rel=1e-6)
    assert s.total_heat_w == pytest.approx(heat["heat_w"].sum(), rel=1e-12)
    # Off by default.
    assert states[0.0].churning_heat_w == 0.0


def test_temperatures_rise_with_oil_in_the_cavity(states):
    off, on = states[0.0], states[FRACTION]
    for node in ("Ti", "Tb", "To", "Th"):
        assert on.temperature_c(node) > off.temperature_c(node), node
    assert on.total_heat_w > off.total_heat_w


def test_curve_column_grows_like_speed_cubed_unlike_viscous_heat(bearing, states):
    c = tb.thermal.thermal_stiffness_curve(
        bearing, [9000.0, SPEED_RPM], AXIAL_N, churning_oil_fraction=FRACTION
    ).sort("speed_rpm")
    churn = c["churning_heat_w"].to_numpy()
    visc = c["viscous_heat_w"].to_numpy()
    # The curve's point is the single-point state (each speed is solved alone).
    assert churn[1] == pytest.approx(states[FRACTION].churning_heat_w, rel=1e-12)
    # Doubling the speed: drag ~ omega_c^3 -> about 8 (the cage speed ratio
    # is about 2; the slightly lower density of the hotter oil takes a little
    # off); Palmgren's omega Mv grows at most by 2^(5/3) = 3.17.
    assert churn[1] / churn[0] > 7.0
    assert visc[1] / visc[0] < 2.0 ** (5.0 / 3.0)
    assert churn[1] / churn[0] > 2.0 * visc[1] / visc[0]
    base = tb.thermal.thermal_stiffness_curve(bearing, [9000.0], AXIAL_N)
    assert base["churning_heat_w"][0] == 0.0


@pytest.mark.parametrize("bad", [-0.01, 1.5, float("nan")])
def test_fraction_outside_zero_one_is_a_config_error(bearing, bad):
    with pytest.raises(tb.ConfigError, match="churning_oil_fraction"):
        tb.thermal.thermal_state(bearing, SPEED_RPM, AXIAL_N, 0.0, churning_oil_fraction=bad)
    with pytest.raises(tb.ConfigError, match="churning_oil_fraction"):
        tb.thermal.thermal_stiffness_curve(bearing, [SPEED_RPM], AXIAL_N, churning_oil_fraction=bad)


def test_model_section_carries_the_oil_fraction():
    seed_b = tb.seed_config("seed_b_7009c")
    # Seed B states its oil-air supply ([model.oil_supply], the last table):
    # the drag follows it, and the fixed fraction is the override beside it.
    assert D.model_from_toml(seed_b)[0].options["churning_oil_fraction"] is None
    fixed = "[model]\nchurning_oil_fraction = 0.02"
    with pytest.raises(tb.ConfigError, match="churning_oil_fraction"):
        D.model_from_toml(seed_b.replace("[model]", fixed, 1))
    text = seed_b.split("[model.oil_supply]")[0].replace("[model]", fixed, 1)
    # model_from_toml checks the text with the Rust parser (unknown keys are
    # rejected there), then passes the value on to the thermal options.
    spec, _ = D.model_from_toml(text)
    assert spec.options["churning_oil_fraction"] == 0.02
