"""Bearing statics and high-speed quasi-statics through the Python API."""

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import thermobear as tb

SEED_A = {"axial_n": 2680.9, "radial_n": 1189.9}
MECH = ["centrifugal_force", "gyroscopic_moment"]


@pytest.fixture(scope="module")
def b6208():
    return tb.Bearing.preset("6208")


def test_equilibrium_of_solved_state(b6208):
    # The balls' inner-contact forces balance the applied load (A-8).
    for speed in (0.0, 16000.0):
        s = b6208.solve(**SEED_A, speed_rpm=speed)
        balls = s.balls
        psi = np.radians(balls["azimuth_deg"].to_numpy())
        ai = np.radians(balls["inner_contact_angle_deg"].to_numpy())
        qi = balls["inner_load_n"].to_numpy()
        assert np.sum(qi * np.sin(ai)) == pytest.approx(SEED_A["axial_n"], rel=1e-6)
        assert np.sum(qi * np.cos(ai) * np.cos(psi)) == pytest.approx(SEED_A["radial_n"], rel=1e-6)
        assert s.residual < 1e-6


def test_agrees_with_independent_scipy_implementation(b6208):
    """Two independent implementations of the same equations (PHYSICS.md 3):
    the Rust solver and a NumPy/SciPy fsolve written from the equations."""
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benches"))
    from reference_bearing import ReferenceBearing

    ref = ReferenceBearing()
    r0 = ref.solve(SEED_A["axial_n"], SEED_A["radial_n"], 0.0)
    for speed, start in ((0.0, None), (16000.0, r0["x"])):
        r = ref.solve(SEED_A["axial_n"], SEED_A["radial_n"], speed, x0=start)
        s = b6208.solve(**SEED_A, speed_rpm=speed, effects=MECH)
        balls = s.balls
        np.testing.assert_allclose(balls["inner_load_n"].to_numpy(), r["inner_load_n"], rtol=2e-4)
        np.testing.assert_allclose(balls["outer_load_n"].to_numpy(), r["outer_load_n"], rtol=2e-4)
        np.testing.assert_allclose(
            balls["inner_contact_angle_deg"].to_numpy(), r["inner_contact_angle_deg"], atol=2e-3
        )
        np.testing.assert_allclose(
            balls["outer_contact_angle_deg"].to_numpy(), r["outer_contact_angle_deg"], atol=2e-3
        )
        assert s.axial_displacement_um / 1000.0 == pytest.approx(r["dz_m"] * 1e3, rel=1e-4)
        assert s.radial_displacement_um / 1000.0 == pytest.approx(abs(r["dx_m"]) * 1e3, rel=1e-3)


def test_zero_speed_stiffness_is_symmetric(b6208):
    k = b6208.solve(**SEED_A).stiffness
    assert k.shape == (5, 5)
    scale = np.max(np.abs(k[:3, :3]))
    # Translational block: symmetric to the accuracy the angle-dependent K allows.
    assert np.max(np.abs(k[:3, :3] - k[:3, :3].T)) < 1e-4 * scale
    assert np.all(np.diag(k)[:3] > 0)


def test_centrifugal_force_raises_outer_load_and_separates_angles(b6208):
    s0 = b6208.solve(axial_n=2000.0, speed_rpm=0.0)
    s1 = b6208.solve(axial_n=2000.0, speed_rpm=20000.0)
    b0, b1 = s0.balls, s1.balls
    assert b1["outer_load_n"].mean() > b0["outer_load_n"].mean()
    # Harris: the ball is pushed outward, the outer contact angle falls and the
    # inner one rises.
    assert b1["outer_contact_angle_deg"].mean() < b0["outer_contact_angle_deg"].mean()
    assert b1["inner_contact_angle_deg"].mean() > b0["inner_contact_angle_deg"].mean()
    # Fc = m dm omega_c^2 / 2
    m = tb.Bearing.preset("6208").geometry["ball_mass_g"] * 1e-3
    wc = b1["orbit_speed_rpm"].to_numpy() * np.pi / 30
    np.testing.assert_allclose(b1["centrifugal_force_n"], 0.5 * m * 0.060 * wc**2, rtol=1e-9)


def test_effects_off_gives_static_model(b6208):
    s_static = b6208.solve(**SEED_A, speed_rpm=0.0)
    s_off = b6208.solve(**SEED_A, speed_rpm=16000.0, effects=[])
    np.testing.assert_allclose(
        s_off.balls["inner_load_n"], s_static.balls["inner_load_n"], rtol=1e-7
    )
    assert s_off.axial_displacement_um / 1000.0 == pytest.approx(
        s_static.axial_displacement_um / 1000.0, rel=1e-8
    )


def test_thrust_only_matches_seed_free_angle_limit(b6208):
    # Displacements from the concentric position (ISO/TS 16281): a tiny thrust
    # needs about A sin(alpha0) = 0.6 mm x sin(14.835 deg) of axial travel.
    s = b6208.solve(axial_n=1e-3)
    assert s.axial_displacement_um / 1000.0 == pytest.approx(
        0.6 * np.sin(np.radians(14.8351)), rel=1e-3
    )


def test_constant_mode_repeats_static(b6208):
    speeds = [6500.0, 11000.0, 16500.0]
    const = tb.stiffness_curve(b6208, speeds, **SEED_A, mode="constant")
    st = b6208.solve(**SEED_A)
    np.testing.assert_allclose(
        const["axial_stiffness_seed_n_per_m"], st.axial_stiffness_seed_n_per_m
    )
    np.testing.assert_allclose(
        const["radial_stiffness_seed_n_per_m"], st.radial_stiffness_seed_n_per_m
    )
    assert const["speed_rpm"].to_list() == speeds


def test_progress_is_reported(b6208):
    calls = []
    tb.stiffness_curve(
        b6208,
        np.linspace(1000, 16000, 40),
        **SEED_A,
        progress=lambda done, total: calls.append((done, total)),
    )
    assert calls and calls[-1] == (40, 40)
    assert all(a <= b for (a, _), (b, _) in zip(calls, calls[1:], strict=False))


_SCRIPT = """
import json, numpy as np, thermobear as tb
b = tb.Bearing.preset("6208")
df = tb.stiffness_curve(b, np.linspace(6500, 16500, 64), 2680.9, 1189.9)
r, a = df["radial_stiffness_seed_n_per_m"], df["axial_stiffness_seed_n_per_m"]
print(json.dumps(r.to_list() + a.to_list()))
"""


def test_results_do_not_depend_on_thread_count():
    out = []
    for n in ("1", "2"):
        env = dict(os.environ, RAYON_NUM_THREADS=n)
        r = subprocess.run(
            [sys.executable, "-c", _SCRIPT], env=env, capture_output=True, text=True, check=True
        )
        out.append(json.loads(r.stdout))
    assert out[0] == out[1]  # bit-identical


@pytest.mark.parametrize(
    "kwargs, field",
    [
        ({"speed_rpm": float("nan")}, "speed_rpm"),
        ({"speed_rpm": -10.0}, "speed_rpm"),
        ({"axial_n": float("inf")}, "axial_n"),
        ({"effects": ["warp_drive"]}, "warp_drive"),
        ({"raceway_control": "cage"}, "raceway_control"),
        ({"moment_n_m": 1.0}, "moment_n_m"),
    ],
)
def test_bad_solve_input_names_field(b6208, kwargs, field):
    args = {"axial_n": 1000.0, "radial_n": 500.0}
    args.update(kwargs)
    with pytest.raises(tb.ConfigError, match=field):
        b6208.solve(**args)


def test_free_tilt_carries_a_moment(b6208):
    s = b6208.solve(axial_n=2000.0, moment_n_m=20.0, misalignment_rad=None)
    assert s.tilt_rad > 0
    assert s.applied_load[4] == pytest.approx(20.0, rel=1e-6)  # N m about y


def test_forward_map_balances_the_solved_state(b6208):
    """ring_forces at the solved displacement returns minus the applied load,
    and its tangent stiffness matches central finite differences."""
    s = b6208.solve(**SEED_A, speed_rpm=12000.0)
    q = s.displacement
    f, k = b6208.ring_forces(q, 12000.0)
    np.testing.assert_allclose(f[:3], -s.applied_load[:3], rtol=1e-6, atol=1e-6)
    for j, h in ((0, 1e-8), (2, 1e-8)):
        qp, qm = q.copy(), q.copy()
        qp[j] += h
        qm[j] -= h
        fd = -(b6208.ring_forces(qp, 12000.0)[0] - b6208.ring_forces(qm, 12000.0)[0]) / (2 * h)
        np.testing.assert_allclose(k[:3, j], fd[:3], rtol=1e-4, atol=1e-3 * np.abs(k[j, j]))


def test_python_example_runs():
    ex = Path(__file__).resolve().parents[1] / "examples" / "quickstart.py"
    r = subprocess.run([sys.executable, str(ex)], capture_output=True, text=True, check=True)
    assert "radial stiffness" in r.stdout
