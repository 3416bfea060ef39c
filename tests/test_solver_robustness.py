"""Robustness of the coupled thermal / quasi-static bearing solver over the
effect switches: every "all effects but one" set solves over 2,000..18,000 rpm
at 300 N and 100 N axial load (7008C, seed A network). Switching the
centrifugal force off used to fail at high speed (thermal offsets open the
gaps, the ring Newton step was rejected; light loads had no equilibrium with
Jones's full gyroscopic couple on a just-touching ball)."""

import numpy as np
import pytest

import thermobear as tb
from thermobear.thermal import THERMAL_EFFECTS, thermal_stiffness_curve

# UMP is a rotor effect: always off for a bare bearing.
BASE = [n for n in tb.effects("switch")["name"].to_list() if n != "unbalanced_magnetic_pull"]
DROPPED = [
    "centrifugal_force",
    "gyroscopic_moment",
    *THERMAL_EFFECTS,
    "temperature_dependent_viscosity",
    "spin_friction",
    "ring_centrifugal_expansion",
]
SPEEDS_RPM = np.linspace(2000.0, 18000.0, 10)
AMBIENT_C = 26.0


@pytest.fixture(scope="module")
def b7008c():
    return tb.Bearing.preset("7008C")


def _all_but(name):
    assert name in BASE
    return [e for e in BASE if e != name]


@pytest.mark.parametrize("dropped", DROPPED)
@pytest.mark.parametrize("axial_n", [300.0, 100.0])
def test_all_but_one_effect_solves_over_speed(b7008c, dropped, axial_n):
    df = thermal_stiffness_curve(b7008c, SPEEDS_RPM, axial_n, 0.0, effects=_all_but(dropped))
    assert df.height == SPEEDS_RPM.size
    for col in (
        "axial_stiffness_seed_n_per_m",
        "radial_stiffness_seed_n_per_m",
        "heat_w",
        "ball_temperature_c",
    ):
        v = df[col].to_numpy()
        assert np.all(np.isfinite(v)), col
    # A preloaded bearing resists axial and radial displacement.
    assert np.all(df["axial_stiffness_seed_n_per_m"].to_numpy() > 0.0)
    assert np.all(df["radial_stiffness_seed_n_per_m"].to_numpy() > 0.0)
    # Friction heat is positive and leaves through the cooler boundaries:
    # the balls run above the ambient air.
    assert np.all(df["heat_w"].to_numpy() > 0.0)
    assert np.all(df["ball_temperature_c"].to_numpy() > AMBIENT_C)


@pytest.mark.parametrize("dropped", DROPPED)
def test_light_load_top_speed_balances(b7008c, dropped):
    """At 18,000 rpm and 100 N: the heat of the bearing leaves through the
    boundaries, and with outer-raceway control (no friction couple at the
    inner contact) the inner contact loads alone carry the axial load:
    sum_j Q_ij sin(a_ij) = Fa (A-8)."""
    fa = 100.0
    s = tb.thermal_state(b7008c, 18_000.0, fa, 0.0, effects=_all_but(dropped))
    out = s.boundary_flows["heat_w"].sum()
    assert out == pytest.approx(s.total_heat_w, rel=1e-6)
    balls = s.solution.raw["balls"]
    qi = balls["inner_load_n"]
    ai = np.radians(balls["inner_contact_angle_deg"])
    assert np.sum(qi * np.sin(ai)) == pytest.approx(fa, rel=1e-6)
    if dropped == "centrifugal_force":
        # Without centrifugal force the only other force on a ball is the
        # raceway friction that holds its gyroscopic moment, and by Coulomb
        # it is at most mu (Q_i + Q_o) (default mu = 0.1):
        # |Q_i n_i - Q_o n_o| <= 0.1 (Q_i + Q_o).
        qo = balls["outer_load_n"]
        ao = np.radians(balls["outer_contact_angle_deg"])
        fx = qi * np.sin(ai) - qo * np.sin(ao)
        fy = qi * np.cos(ai) - qo * np.cos(ao)
        assert np.all(np.hypot(fx, fy) <= 0.1 * (qi + qo) * (1 + 1e-9))


def test_light_load_low_speed_free_balls_solve():
    """6208 under 0.25 N axial + 6 N radial at 1..100 rpm (balls off the
    load zone ride on the outer raceway under a vanishing centrifugal
    force): solves, and the inner contact loads carry the radial load
    (outer-raceway control: no friction couple at the inner contact)."""
    b = tb.Bearing.preset("6208")
    for rpm in (1.0, 2.0, 5.0, 10.0, 25.0, 50.0, 100.0):
        s = b.solve(speed_rpm=rpm, axial_n=0.25, radial_n=6.0)
        balls = s.raw["balls"]
        qi = balls["inner_load_n"]
        ai = np.radians(balls["inner_contact_angle_deg"])
        psi = np.radians(balls["azimuth_deg"])
        assert np.sum(qi * np.cos(ai) * np.cos(psi)) == pytest.approx(6.0, rel=1e-6)
        assert np.sum(qi * np.sin(ai)) == pytest.approx(0.25, rel=1e-6)
