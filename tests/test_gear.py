"""Helical gear pair dynamics through the Python binding: physical checks."""

from __future__ import annotations

import math
import re

import numpy as np
import polars as pl
import pytest

import thermobear as tb

SEED = dict(
    pinion_teeth=29,
    gear_teeth=78,
    normal_module_mm=1.537,
    normal_pressure_angle_deg=16.5,
    helix_angle_deg=31.2,
    face_width_mm=33.0,
    youngs_modulus_mpa=206_000.0,
    poisson_ratio=0.25,
    density_t_per_mm3=7.8e-9,
    mass_kg=(1.201, 3.1),
    polar_inertia_t_mm2=(0.1152, 1.6),
    input_torque_n_m=100.0,
)


@pytest.fixture(scope="module")
def pair() -> tb.GearPair:
    return tb.GearPair.preset("seed-electric-drive")


@pytest.fixture(scope="module")
def seed_system(pair: tb.GearPair) -> tb.GearSystem:
    return tb.GearSystem(pair, stiffness="constant")


def _projection(phi: float, beta: float) -> np.ndarray:
    # delta_n = (dx sin phi + dy cos phi) cos beta + dz sin beta, with
    # the rotations through u = R_p theta_p - R_g theta_g.
    s, c, sb, cb = math.sin(phi), math.cos(phi), math.sin(beta), math.cos(beta)
    return np.array([s * cb, c * cb, sb, -s * cb, -c * cb, -sb, cb])


def test_linear_limit_eigenfrequencies_match_numpy(seed_system: tb.GearSystem) -> None:
    """M and K rebuilt here from the model's numbers: eig(M^-1 K) gives the
    binding's natural frequencies; with rigid bearings the torsional mode is
    sqrt(k_m cos^2(beta) / m_e)."""
    p = seed_system.params
    kr, ka = seed_system.bearing_stiffness_at(10_000.0)
    me = 1.0 / (
        p["pinion_base_radius_m"] ** 2 / p["pinion_inertia_kg_m2"]
        + p["gear_base_radius_m"] ** 2 / p["gear_inertia_kg_m2"]
    )
    m = np.diag([p["pinion_mass_kg"]] * 3 + [p["gear_mass_kg"]] * 3 + [me])
    a = _projection(math.radians(p["line_of_action_angle_deg"]), math.radians(p["helix_angle_deg"]))
    km = p["mesh_stiffness_mean_n_per_m"]
    k = np.diag([kr, kr, ka, kr, kr, ka, 0.0]) + km * np.outer(a, a)
    w2 = np.sort(np.linalg.eigvals(np.linalg.solve(m, k)).real)
    f_numpy = np.sqrt(w2) / (2 * math.pi)
    f_model = seed_system.natural_frequencies_hz(10_000.0)
    np.testing.assert_allclose(f_model, f_numpy, rtol=1e-9)
    np.testing.assert_allclose(seed_system.mass_matrix_kg(10_000.0), m, rtol=1e-12)

    # Rigid bearings (1e14 N/m): the only soft mode is the torsional one.
    df = pl.DataFrame(
        {
            "speed_rpm": [0.0],
            "radial_stiffness_seed_n_per_m": [5e13],
            "axial_stiffness_seed_n_per_m": [5e13],
        }
    )
    rigid = tb.GearSystem(seed_system.gear, stiffness=df, bearing_stiffness_per="bearing")
    f0 = rigid.natural_frequencies_hz(10_000.0)[0]
    cb = math.cos(math.radians(p["helix_angle_deg"]))
    expect = math.sqrt(km * cb * cb / me) / (2 * math.pi)
    assert f0 == pytest.approx(expect, rel=1e-3)


def test_mesh_stiffness_is_normal_direction(pair: tb.GearPair, seed_system: tb.GearSystem) -> None:
    """k_n = k_t / cos^2(beta): F_t = F_n cos(beta), delta_n = delta_t cos(beta)."""
    ms = pair.mesh_stiffness(64)
    beta = math.radians(pair.geometry["helix_angle_deg"])
    np.testing.assert_allclose(
        ms["normal_stiffness_n_per_m"].to_numpy() * math.cos(beta) ** 2,
        ms["transverse_stiffness_n_per_m"].to_numpy(),
        rtol=1e-12,
    )
    assert seed_system.params["mesh_stiffness_mean_n_per_m"] == pytest.approx(
        ms["normal_stiffness_n_per_m"].mean(), rel=1e-9
    )
    # Contact ratios of seed A's pair (Table 3 data): eps_alpha > 1, and
    # eps_beta = b sin(beta) / (pi m_n) = 33 sin 31.2 / (pi 1.537) = 3.540.
    assert pair.transverse_contact_ratio > 1.0
    assert pair.overlap_ratio == pytest.approx(33 * math.sin(beta) / (math.pi * 1.537), rel=1e-9)


def test_bearing_support_is_two_bearings_in_parallel(pair: tb.GearPair) -> None:
    """The "speed" schedule (solved in Rust) equals twice the binding's
    stiffness_curve of one 6208 under the seed loads with the ring held level,
    and a frame of those values gives the same model."""
    grid = np.array([6500.0, 11500.0, 16500.0])
    sys = tb.GearSystem(pair, stiffness="speed", stiffness_speeds_rpm=grid)
    one = tb.stiffness_curve(
        tb.Bearing.preset("6208"), grid, axial_n=2680.9, radial_n=1189.9, mode="speed"
    )
    sched = sys.stiffness_schedule
    np.testing.assert_allclose(
        sched["support_radial_stiffness_n_per_m"].to_numpy(),
        2 * one["radial_stiffness_seed_n_per_m"].to_numpy(),
        rtol=1e-6,
    )
    np.testing.assert_allclose(
        sched["support_axial_stiffness_n_per_m"].to_numpy(),
        2 * one["axial_stiffness_seed_n_per_m"].to_numpy(),
        rtol=1e-6,
    )
    via_frame = tb.GearSystem(pair, stiffness=one, bearing_stiffness_per="bearing")
    for s in (7000.0, 12000.0):
        assert via_frame.bearing_stiffness_at(s) == pytest.approx(sys.bearing_stiffness_at(s))


def test_lorenz_and_duffing_lyapunov_match_published_values() -> None:
    # Lorenz sigma 10, rho 28, beta 8/3: lambda_1 = 0.9056 (Sprott, Chaos and
    # Time-Series Analysis, OUP 2003, Appendix A); finite-time scatter ~1 %.
    assert tb.largest_lyapunov("lorenz") == pytest.approx(0.9056, abs=0.03)
    assert tb.largest_lyapunov("lorenz", method="variational") == pytest.approx(0.9056, abs=0.03)
    # Ueda's Duffing x'' + 0.05 x' + x^3 = 7.5 cos t: lambda_1 ~ 0.0999
    # (Sprott 2003, pp. 182-183); slow convergence, 12 % tolerance.
    assert tb.largest_lyapunov("duffing-ueda") == pytest.approx(0.0999, abs=0.012)
    with pytest.raises(tb.ConfigError, match="name"):
        tb.largest_lyapunov("rossler")


def test_typo_errors_name_the_likely_value(pair: tb.GearPair) -> None:
    with pytest.raises(tb.ConfigError) as e:
        tb.GearPair.from_table(**{**SEED, "youngs_modulus_mpa": 20_600.0})
    msg = str(e.value)
    assert "youngs_modulus_mpa" in msg
    likely = float(re.search(r"likely intended ([0-9.e+-]+)", msg).group(1))
    assert likely == pytest.approx(206_000.0)
    with pytest.raises(tb.ConfigError) as e:
        tb.GearPair.from_table(**{**SEED, "density_t_per_mm3": 7.8e9})
    msg = str(e.value)
    assert "density_t_per_mm3" in msg
    likely = float(re.search(r"likely intended ([0-9.e+-]+)", msg).group(1))
    assert likely == pytest.approx(7.8e-9)
    # The corrected table builds the same pair as the preset.
    ok = tb.GearPair.from_table(**SEED)
    assert ok.transverse_contact_ratio == pytest.approx(pair.transverse_contact_ratio, rel=1e-12)
    # The preset reports the printed table's two typos.
    w = pair.typo_warnings
    got = dict(zip(w["field"].to_list(), w["likely_intended"].to_list(), strict=False))
    assert got["youngs_modulus_mpa"] == pytest.approx(206_000.0)
    assert got["density_t_per_mm3"] == pytest.approx(7.8e-9)


def test_bad_input_raises_config_error(pair: tb.GearPair, seed_system: tb.GearSystem) -> None:
    with pytest.raises(tb.ConfigError, match="pinion_mass_kg"):
        tb.GearPair.from_table(**{**SEED, "mass_kg": (0.0, 3.1)})
    with pytest.raises(tb.ConfigError, match="gear_polar_inertia_t_mm2"):
        tb.GearPair.from_table(**{**SEED, "polar_inertia_t_mm2": (0.1152, -1.6)})
    # Short teeth on a small spur pair at 25 deg: transverse contact ratio 0.71.
    stub = {
        **SEED,
        "pinion_teeth": 12,
        "gear_teeth": 12,
        "normal_pressure_angle_deg": 25.0,
        "helix_angle_deg": 0.0,
        "addendum_coeff": 0.5,
        "polar_inertia_t_mm2": (0.001, 0.001),
    }
    with pytest.raises(tb.ConfigError, match="transverse_contact_ratio"):
        tb.GearPair.from_table(**stub)
    with pytest.raises(tb.ConfigError, match="steps_per_period"):
        seed_system.check_steps(10_000.0, 8)
    with pytest.raises(tb.ConfigError, match="steps_per_period"):
        tb.bifurcation(seed_system, [10_000.0], "up", 10, 4, steps_per_period=8)
    bad = pl.DataFrame(
        {
            "speed_rpm": [0.0],
            "radial_stiffness_seed_n_per_m": [-1e8],
            "axial_stiffness_seed_n_per_m": [1e8],
        }
    )
    with pytest.raises(tb.ConfigError, match="kr_n_per_m"):
        tb.GearSystem(pair, stiffness=bad, bearing_stiffness_per="bearing")
    with pytest.raises(tb.ConfigError, match="half_backlash"):
        tb.GearSystem(pair, half_backlash_um=0.0)
    with pytest.raises(tb.ConfigError, match="mesh_damping"):
        tb.GearSystem(pair, mesh_damping="sometimes")
    with pytest.raises(tb.ConfigError, match="stiffness"):
        tb.GearSystem(pair, stiffness="stiff")
    with pytest.raises(tb.ConfigError, match="direction"):
        tb.bifurcation(seed_system, [10_000.0], "sideways")
    with pytest.raises(tb.ConfigError, match="speeds"):
        tb.bifurcation(seed_system, [12_000.0, 10_000.0, 12_000.0], "up", 10, 4)


def test_seed_torque_is_period_one_without_impacts(seed_system: tb.GearSystem) -> None:
    """Seed A's 100 N m: static mesh deflection F/k_m ~ 4.9 um exceeds the
    dynamic swing, so the teeth never separate (the expected regime)."""
    speeds = np.linspace(6500.0, 16500.0, 11)
    pts = tb.bifurcation(seed_system, speeds, "up", 300, 20, 64)
    per = pts.unique(subset=["speed_rpm"])
    assert per.height == 11
    assert set(per["regime"]) == {"period-1"}
    assert set(per["impact"]) == {"no-impact"}
    # The mean deflection is the static one: F_t / (k_n cos^2 beta) / cos beta ... in
    # the normal direction, F_n / k_n with F_n = T / (r_b cos beta).
    p = seed_system.params
    fn = 100.0 / (p["pinion_base_radius_m"] * math.cos(math.radians(p["helix_angle_deg"])))
    static_um = fn / p["mesh_stiffness_mean_n_per_m"] * 1e6
    mid = 0.5 * (per["dte_min_um"] + per["dte_max_um"]).to_numpy()
    # dte = delta_n - e includes the dead zone: contact at delta_n - e = b + F/k.
    np.testing.assert_allclose(mid, p["half_backlash_um"] + static_um, rtol=0.05)
    # A stable periodic orbit has a negative largest exponent.
    assert tb.largest_lyapunov(seed_system, 12_000.0, periods=100) < 0.0


def test_chaos_at_light_torque_and_large_error(pair: tb.GearPair) -> None:
    """20 N m with a 10 um TE: the teeth hit both flanks and the motion is
    chaotic near 14,000 rpm (positive Lyapunov exponent by two methods: the
    sweep's per-period estimate and a separate run from the static state)."""
    light = tb.GearSystem(pair, stiffness="constant", torque_n_m=20.0, te_amplitude_um=10.0)
    speeds = [13_500.0, 14_000.0, 14_500.0]
    pts = tb.bifurcation(light, speeds, "independent", 300, 100, 64)
    per = pts.unique(subset=["speed_rpm"], maintain_order=True)
    chaotic = per.filter(pl.col("regime") == "chaotic")
    assert chaotic.height >= 1, per
    assert (chaotic["impact"] == "double-sided").all()
    assert (chaotic["lyapunov_per_mesh_period"] > 0.01).all()
    s = chaotic["speed_rpm"][0]
    assert tb.largest_lyapunov(light, s, periods=200) > 0.0


def test_independent_sweep_is_deterministic(pair: tb.GearPair) -> None:
    light = tb.GearSystem(pair, torque_n_m=20.0, te_amplitude_um=10.0)
    speeds = np.linspace(9000.0, 15000.0, 9)
    a = tb.bifurcation(light, speeds, "independent", 100, 30, 64)
    b = tb.bifurcation(light, speeds, "independent", 100, 30, 64)
    assert a.equals(b)
    seen = []
    tb.bifurcation(
        light, speeds, "independent", 20, 4, 64, progress=lambda d, t: seen.append((d, t))
    )
    assert seen and seen[-1] == (9, 9)


def test_progress_exception_stops_the_sweep(seed_system: tb.GearSystem) -> None:
    def stop(done: int, total: int) -> None:
        raise KeyboardInterrupt

    speeds = np.linspace(6500.0, 16500.0, 64)
    with pytest.raises(KeyboardInterrupt):
        tb.bifurcation(seed_system, speeds, "up", 300, 100, 64, progress=stop)


def test_regimes_on_a_constructed_frame() -> None:
    """Speeds 1-3: one value (period-1); 4-5: two alternating (period-2);
    6: irregular (non-periodic)."""
    rng = np.random.default_rng(1)
    rows = []
    for s in (1.0, 2.0, 3.0):
        rows += [(s, 5.0)] * 8
    for s in (4.0, 5.0):
        rows += [(s, v) for v in [1.0, 9.0] * 4]
    rows += [(6.0, v) for v in rng.uniform(0, 10, 40)]
    df = pl.DataFrame({"speed_rpm": [r[0] for r in rows], "dte_um": [r[1] for r in rows]})
    reg = tb.regimes(df)
    assert reg.select("speed_from_rpm", "speed_to_rpm", "regime", "period").rows() == [
        (1.0, 3.0, "period-1", 1),
        (4.0, 5.0, "period-2", 2),
        (6.0, 6.0, "non-periodic", 0),
    ]
    # With per-speed metadata a jump closes a range even inside one regime.
    df2 = pl.DataFrame(
        {
            "speed_rpm": [1.0, 2.0, 3.0, 4.0],
            "dte_um": [1.0, 1.0, 5.0, 5.0],
            "regime": ["period-1"] * 4,
            "period": [1] * 4,
            "impact": ["no-impact"] * 4,
            "jump_after": [False, True, False, False],
        }
    )
    reg2 = tb.regimes(df2)
    assert reg2.select("speed_from_rpm", "speed_to_rpm", "jump_at_end").rows() == [
        (1.0, 2.0, True),
        (3.0, 4.0, False),
    ]


def test_regime_map_and_set_columns(seed_system: tb.GearSystem, pair: tb.GearPair) -> None:
    rm = tb.regime_map(
        seed_system, [100.0, 10.0], [8000.0, 12000.0], te_scales=[1.0, 5.0],
        transient_periods=300, record_periods=20,
    )  # fmt: skip
    assert rm.height == 8
    for c in ("torque_n_m", "te_scale", "speed_rpm", "regime", "period", "impact"):
        assert c in rm.columns
    heavy = rm.filter((pl.col("torque_n_m") == 100.0) & (pl.col("te_scale") == 1.0))
    assert set(heavy["impact"]) == {"no-impact"}
    light = rm.filter((pl.col("torque_n_m") == 10.0) & (pl.col("te_scale") == 5.0))
    assert (light["impact"] != "no-impact").any()
    # The set runner gives what single sweeps give (lanes are independent).
    sys2 = tb.GearSystem(pair, torque_n_m=20.0, te_amplitude_um=10.0)
    speeds = [9000.0, 10000.0, 11000.0]
    both = tb.bifurcation_set({"a": seed_system, "b": sys2}, speeds, ("up", "down"), 50, 10, 64)
    one = tb.bifurcation(sys2, speeds, "down", 50, 10, 64)
    sub = both.filter((pl.col("case") == "b") & (pl.col("direction") == "down")).drop("case")
    assert sub.equals(one)


def test_quick_demo_study_writes_its_tables(tmp_path) -> None:
    from thermobear.studies.demo import STUDIES, study_function

    fn = study_function(dict(STUDIES)["seed_a_gear"])
    files = fn(tmp_path, True)
    names = {f.name for f in files}
    for stem in (
        "gear_defaults",
        "regimes",
        "regimes_vs_paper",
        "regime_map",
    ):
        assert f"{stem}.parquet" in names and f"{stem}.csv" in names
    # Poincare point sets are large: parquet only.
    assert "poincare_seed_100_n_m.parquet" in names and "poincare_seed_100_n_m.csv" not in names
    assert sum(n.startswith("seed_a_fig1") and "_bifurcation_100_n_m_" in n for n in names) >= 4
    reg = pl.read_parquet(tmp_path / "regimes.parquet")
    stated = reg.filter(pl.col("inputs") == "stated")
    # The seed operating point with the stated inputs: period-1 without
    # impacts everywhere; with the inputs calibrated on the paper's
    # transition speeds, the teeth separate and the motion leaves period-1.
    assert set(stated["regime"]) == {"period-1"} and set(stated["impact"]) == {"no-impact"}
    fitted = reg.filter(pl.col("inputs") == "calibrated")
    assert (fitted["regime"] != "period-1").any() and (fitted["impact"] != "no-impact").any()
    assert "seed_a_thermal_shift.png" in names and "seed_a_calibrated_gear_inputs.csv" in names
    d = pl.read_parquet(tmp_path / "gear_defaults.parquet")
    assert d.filter(pl.col("parameter") == "backlash_total_um")["value"][0] == pytest.approx(100.0)
    assert d.filter(pl.col("parameter") == "half_backlash_um")["value"][0] == pytest.approx(50.0)


def test_ctrl_c_interrupts_a_long_sweep(seed_system: tb.GearSystem) -> None:
    """A signal whose handler raises KeyboardInterrupt (as SIGINT's does),
    delivered by the OS 0.3 s into the GIL-released sweep, stops it within a
    fraction of its run time (about 7 s) and raises KeyboardInterrupt. An OS
    timer, not a Python thread: a thread that must first win the GIL can be
    starved on a loaded machine until the sweep has finished."""
    import signal
    import time

    previous = signal.signal(signal.SIGALRM, signal.default_int_handler)
    try:
        signal.setitimer(signal.ITIMER_REAL, 0.3)
        t0 = time.perf_counter()
        with pytest.raises(KeyboardInterrupt):
            tb.bifurcation(seed_system, np.linspace(6500.0, 16500.0, 5000), "up", 300, 100, 64)
        assert time.perf_counter() - t0 < 10.0
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0.0)
        signal.signal(signal.SIGALRM, previous)
