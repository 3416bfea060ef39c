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


# Centrifugal force as the only speed effect: a ball at the edge of the load
# zone carrying a few newtons statically against a centrifugal force of
# 20..150 N stalled the ball equilibrium iteration from its static position
# (about 1 point in 160 failed). The reported point, then the failures of a
# random search (numpy default_rng(1), 400 points per preset over 0..5 kN
# axial and radial and 0..20,000 rpm, rounded to 0.1 N and 1 rpm).
CENTRIFUGAL_ONLY = ["centrifugal_force"]
CENTRIFUGAL_ONLY_FAILURES = [
    ("6208", 1698.6, 3073.8, 17844.0),
    ("6208", 1082.3, 2073.3, 9265.0),
    ("6208", 1356.1, 3133.4, 16058.0),
    ("6208", 488.2, 1882.0, 9128.0),
    ("6208", 209.0, 540.8, 10376.0),
    ("7008C", 2841.1, 4543.1, 18258.0),
    ("7008C", 1044.8, 2549.4, 6394.0),
    ("7008C", 804.1, 1995.5, 9051.0),
    ("7008C", 1610.4, 3804.9, 15109.0),
    ("7008C", 2747.6, 4427.4, 17432.0),
]
TOLERANCE = 1e-9  # the solver's default relative force tolerance


def _assert_balanced(sol, axial_n, radial_n, what):
    """Physical checks of a centrifugal-only state (outer-raceway control, no
    gyroscopic moment, so no friction force): the inner contact forces
    Q_i n_i summed over the balls balance the applied load to the solver's
    tolerance (relative to the largest load, at least 1 N), and each ball is
    in equilibrium under its two contact loads and its centrifugal force."""
    raw = sol.raw
    assert raw["residual"] <= TOLERANCE, what
    balls = raw["balls"]
    qi, qo = np.asarray(balls["inner_load_n"]), np.asarray(balls["outer_load_n"])
    fc = np.asarray(balls["centrifugal_force_n"])
    ai = np.radians(np.asarray(balls["inner_contact_angle_deg"]))
    ao = np.radians(np.asarray(balls["outer_contact_angle_deg"]))
    psi = np.radians(np.asarray(balls["azimuth_deg"]))
    ref = max(abs(axial_n), abs(radial_n), 1.0)
    fx = np.sum(qi * np.cos(ai) * np.cos(psi))
    fy = np.sum(qi * np.cos(ai) * np.sin(psi))
    fz = np.sum(qi * np.sin(ai))
    worst = max(abs(fx - radial_n), abs(fy), abs(fz - axial_n))
    assert worst <= TOLERANCE * ref * (1 + 1e-6), f"{what}: ({fx}, {fy}, {fz}) N"
    r_ax = qi * np.sin(ai) - qo * np.sin(ao)
    r_rad = qi * np.cos(ai) - qo * np.cos(ao) + fc
    assert np.all(np.maximum(abs(r_ax), abs(r_rad)) <= 1e-8 * (qi + qo + fc) + 1e-12), what


@pytest.mark.parametrize("preset, axial_n, radial_n, speed_rpm", CENTRIFUGAL_ONLY_FAILURES)
def test_centrifugal_only_load_zone_edge_points(preset, axial_n, radial_n, speed_rpm):
    b = tb.Bearing.preset(preset)
    what = f"{preset} {axial_n} N + {radial_n} N at {speed_rpm} rpm"
    sol = b.solve(axial_n, radial_n, 0.0, speed_rpm, effects=CENTRIFUGAL_ONLY)
    _assert_balanced(sol, axial_n, radial_n, what)
    # Opposite the radial load the balls still touch the inner raceway,
    # pressed outwards with their contact lines bent by degrees.
    balls = sol.raw["balls"]
    bend = np.asarray(balls["inner_contact_angle_deg"]) - np.asarray(
        balls["outer_contact_angle_deg"]
    )
    assert np.any((np.asarray(balls["inner_load_n"]) > 0.0) & (bend > 5.0)), what


@pytest.mark.parametrize("preset", ["6208", "7008C"])
def test_centrifugal_only_random_sweep_balances(preset):
    """200 random centrifugal-only points per bearing (numpy default_rng(3),
    0..5 kN axial and radial, 0..20,000 rpm) all converge and balance their
    load; 3 of the 200 failed on each bearing before."""
    b = tb.Bearing.preset(preset)
    rng = np.random.default_rng(3)
    n = 200
    points = np.column_stack(
        [rng.uniform(0, 5000, n), rng.uniform(0, 5000, n), rng.uniform(0, 20000, n)]
    )
    for k, (axial_n, radial_n, speed_rpm) in enumerate(points):
        what = f"{preset} #{k}: {axial_n} N + {radial_n} N at {speed_rpm} rpm"
        sol = b.solve(axial_n, radial_n, 0.0, speed_rpm, effects=CENTRIFUGAL_ONLY)
        _assert_balanced(sol, axial_n, radial_n, what)
