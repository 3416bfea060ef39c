"""Gear dynamics inputs and settings from Python:
mesh tables round trips, coast mirror symmetry, bearing stiffness per
bearing or per shaft, backlash by name, classifier settings, Lyapunov units,
speeds in any order."""

from __future__ import annotations

import math
import pickle

import numpy as np
import polars as pl
import pytest

import thermobear as tb

#: A continuation sweep over these speeds at 20 N m, 10 um TE meets
#: period-1, period-2 and higher, quasi-periodic and chaotic motion.
SPEEDS = np.linspace(9000.0, 16000.0, 36)


@pytest.fixture(scope="module")
def pair() -> tb.GearPair:
    return tb.GearPair.preset("seed-electric-drive")


@pytest.fixture(scope="module")
def seed(pair: tb.GearPair) -> tb.GearSystem:
    return tb.GearSystem(pair)


@pytest.fixture(scope="module")
def light(pair: tb.GearPair) -> tb.GearSystem:
    """20 N m with a 10 um TE: both flanks hit, periodic, quasi-periodic
    and chaotic speeds between 9,000 and 16,000 rpm."""
    return tb.GearSystem(pair, torque_n_m=20.0, te_amplitude_um=10.0)


def _sweep(system: tb.GearSystem, speeds=SPEEDS, direction: str = "up", **kw) -> pl.DataFrame:
    return tb.bifurcation(system, speeds, direction, 100, 40, 64, **kw)


def _per_speed(pts: pl.DataFrame) -> pl.DataFrame:
    return pts.unique(subset=["speed_rpm"], maintain_order=True)


# ------------------------------------------------------------ mesh tables ----


def test_builtin_tables_round_trip_bit_for_bit(
    pair: tb.GearPair, seed: tb.GearSystem, light: tb.GearSystem
) -> None:
    """The model's own tables given back (frame, or per-phase callables
    returning the same samples) rebuild the same model: identical sweeps,
    also through the chaotic speeds where any difference would grow."""
    tab = light.mesh_tables()
    np.testing.assert_array_equal(tab["mesh_phase"].to_numpy(), np.arange(64) / 64)
    again = tb.GearSystem(
        pair, torque_n_m=20.0, mesh_stiffness_n_per_m=tab, transmission_error_um=tab
    )
    assert again.mesh_model == "table" and light.mesh_model == "potential-energy"
    assert again.mesh_tables().equals(tab)
    assert again.params["te_amplitude_um"] == pytest.approx(10.0, rel=1e-12)
    ref = _sweep(light)
    assert set(_per_speed(ref)["regime"]) >= {"chaotic", "period-1"}
    assert _sweep(again).equals(ref)
    # Callables returning the samples at each phase (TE in um, so 1e-16
    # rounding): at the seed torque (stable period-1) the sweeps agree to 1e-12.
    st = seed.mesh_tables()
    k, e = st["normal_stiffness_n_per_m"].to_numpy(), st["transmission_error_m"].to_numpy()
    by_callable = tb.GearSystem(
        pair,
        mesh_stiffness_n_per_m=lambda phase: k[np.rint(phase * 64).astype(int)],
        transmission_error_um=lambda phase: e[np.rint(phase * 64).astype(int)] * 1e6,
    )
    np.testing.assert_allclose(by_callable.mesh_tables()["transmission_error_m"], e, rtol=1e-15)
    a = _sweep(by_callable, [8000.0, 12000.0, 16000.0])
    b = _sweep(seed, [8000.0, 12000.0, 16000.0])
    assert set(b["regime"]) == {"period-1"}
    np.testing.assert_allclose(a["dte_um"], b["dte_um"], rtol=1e-12)


def test_callable_te_matches_the_builtin_harmonic(pair: tb.GearPair, seed: tb.GearSystem) -> None:
    """A callable 2 um cos(2 pi phase) is the default first-harmonic TE
    (also as a scalar function, called once per phase)."""
    sys = tb.GearSystem(pair, transmission_error_um=lambda ph: 2.0 * np.cos(2 * np.pi * ph))
    scalar = tb.GearSystem(pair, transmission_error_um=lambda ph: 2.0 * math.cos(2 * math.pi * ph))
    np.testing.assert_allclose(
        scalar.mesh_tables()["transmission_error_um"], sys.mesh_tables()["transmission_error_um"],
        rtol=0, atol=1e-14,
    )  # fmt: skip
    np.testing.assert_allclose(
        sys.mesh_tables()["transmission_error_um"], seed.mesh_tables()["transmission_error_um"],
        rtol=0, atol=1e-14,
    )  # fmt: skip
    a = _sweep(sys, [8000.0, 12000.0])["dte_um"].to_numpy()
    b = _sweep(seed, [8000.0, 12000.0])["dte_um"].to_numpy()
    np.testing.assert_allclose(a, b, rtol=1e-12)


def test_table_abscissae_and_units_are_equivalent(pair: tb.GearPair, seed: tb.GearSystem) -> None:
    """The same period as mesh_phase, mesh_phase_deg with the closing point
    at 360 deg, pinion_angle_deg (360/z_p per mesh period) and transverse
    stiffness (k_t = k_n cos^2 beta) gives the same samples."""
    tab = seed.mesh_tables()
    kn = tab["normal_stiffness_n_per_m"].to_numpy()
    ph = tab["mesh_phase"].to_numpy()
    cb2 = math.cos(math.radians(pair.geometry["helix_angle_deg"])) ** 2
    deg = {
        "mesh_phase_deg": np.append(ph, 1.0) * 360.0,
        "normal_stiffness_n_per_m": np.append(kn, kn[0]),
    }
    pin = {"pinion_angle_deg": ph * 360.0 / 29, "transverse_stiffness_n_per_m": kn * cb2}
    for given in (deg, pin):
        sys = tb.GearSystem(pair, mesh_stiffness_n_per_m=given)
        np.testing.assert_allclose(sys.mesh_tables()["normal_stiffness_n_per_m"], kn, rtol=1e-13)
    # GearPair.mesh_stiffness carries both directions; they agree, normal is used.
    ms = pair.mesh_stiffness(64)
    sys = tb.GearSystem(pair, mesh_stiffness_n_per_m=ms)
    np.testing.assert_array_equal(
        sys.mesh_tables()["normal_stiffness_n_per_m"], ms["normal_stiffness_n_per_m"]
    )
    # A non-uniform table is resampled once: a constant stays constant.
    rng = np.random.default_rng(3)
    x = np.sort(rng.uniform(0.0, 1.0, 7))
    flat = tb.GearSystem(
        pair, mesh_stiffness_n_per_m={"mesh_phase": x, "normal_stiffness_n_per_m": np.full(7, 5e8)}
    )
    np.testing.assert_array_equal(flat.mesh_tables()["normal_stiffness_n_per_m"], np.full(64, 5e8))
    assert flat.params["mesh_stiffness_mean_n_per_m"] == 5e8


def test_bad_tables_raise_config_error(pair: tb.GearPair) -> None:
    ok = {"mesh_phase": [0.0, 0.25, 0.5, 0.75], "normal_stiffness_n_per_m": [5e8] * 4}
    cases = [
        ({"normal_stiffness_n_per_m": [5e8] * 4}, "abscissa"),
        ({**ok, "mesh_phase_deg": [0.0, 90.0, 180.0, 270.0]}, "exactly one abscissa"),
        ({**ok, "mesh_phase": [0.0, 0.5, 0.25, 0.75]}, "strictly ascending"),
        ({**ok, "mesh_phase": [0.0, 0.5, 1.0, 1.5]}, "mesh periods"),
        (
            {
                **ok,
                "mesh_phase": [0.0, 0.4, 0.7, 1.0],
                "normal_stiffness_n_per_m": [5e8, 5e8, 5e8, 6e8],
            },
            "not periodic",
        ),
        ({**ok, "normal_stiffness_n_per_m": [5e8, -1.0, 5e8, 5e8]}, "mesh_stiffness_n_per_m"),
        ({"mesh_phase": ok["mesh_phase"], "stiffness": [1.0] * 4}, "value column"),
        (lambda ph: np.ones(3), "shape"),
    ]
    for given, msg in cases:
        with pytest.raises(tb.ConfigError, match=msg):
            tb.GearSystem(pair, mesh_stiffness_n_per_m=given)
    with pytest.raises(tb.ConfigError, match="mesh_model"):
        tb.GearSystem(pair, mesh_stiffness_n_per_m=ok, mesh_model="iso")
    with pytest.raises(tb.ConfigError, match="te_amplitude_um"):
        tb.GearSystem(pair, te_amplitude_um=3.0, transmission_error_um=lambda ph: 0 * ph)
    with pytest.raises(tb.ConfigError, match="transmission_error_um"):
        tb.GearSystem(pair, transmission_error_um=lambda ph: ph * np.nan)


def test_table_system_pickles(pair: tb.GearPair) -> None:
    sys = tb.GearSystem(
        pair, torque_n_m=-30.0, transmission_error_um=lambda ph: 3.0 * np.cos(4 * np.pi * ph)
    )
    back = pickle.loads(pickle.dumps(sys))
    assert back.mesh_tables().equals(sys.mesh_tables())
    assert back.params == sys.params and back.params["torque_n_m"] == -30.0


# ---------------------------------------------------------------- coast ----


def test_coast_mirrors_drive(pair: tb.GearPair, light: tb.GearSystem) -> None:
    """The backlash dead zone is odd, so (q, T, e) -> (-q, -T, -e) maps
    solutions onto solutions: torque -T with TE -e gives exactly the
    negated dynamic TE of +T with +e (static state, every Poincare sample,
    extremes) and the same regimes and contact regimes."""
    tab = light.mesh_tables()
    neg = tab.with_columns(-pl.col("transmission_error_um"), -pl.col("transmission_error_m"))
    coast = tb.GearSystem(pair, torque_n_m=-20.0, transmission_error_um=neg)
    assert coast.bearing_loads_n == light.bearing_loads_n
    np.testing.assert_array_equal(coast.static_state_m(9600.0), -light.static_state_m(9600.0))
    d, c = _sweep(light), _sweep(coast)
    np.testing.assert_array_equal(c["dte_um"].to_numpy(), -d["dte_um"].to_numpy())
    pd, pc = _per_speed(d), _per_speed(c)
    np.testing.assert_array_equal(pc["dte_min_um"].to_numpy(), -pd["dte_max_um"].to_numpy())
    assert pc["impact"].to_list() == pd["impact"].to_list()
    periodic = [r.startswith("period-") for r in pd["regime"]]
    assert any(periodic) and not all(periodic)
    for rd, rc, p in zip(pd["regime"], pc["regime"], periodic, strict=True):
        assert rc == rd if p else not rc.startswith("period-")


def test_coast_at_seed_torque_sits_on_the_back_flank(
    pair: tb.GearPair, seed: tb.GearSystem
) -> None:
    """-100 N m with the same TE: no impacts, the mean DTE is -(b + F_n/k_m)."""
    coast = tb.GearSystem(pair, torque_n_m=-100.0)
    per = _per_speed(_sweep(coast, [8000.0, 12000.0]))
    assert set(per["impact"]) == {"no-impact"} and set(per["regime"]) == {"period-1"}
    p = coast.params
    fn = 100.0 / (p["pinion_base_radius_m"] * math.cos(math.radians(p["helix_angle_deg"])))
    static_um = fn / p["mesh_stiffness_mean_n_per_m"] * 1e6
    mid = 0.5 * (per["dte_min_um"] + per["dte_max_um"]).to_numpy()
    np.testing.assert_allclose(mid, -(p["half_backlash_um"] + static_um), rtol=0.05)
    rm = tb.regime_map(seed, [-100.0, 100.0], [12000.0], transient_periods=100, record_periods=20)
    assert rm["mean_dte_um"][0] == pytest.approx(-rm["mean_dte_um"][1], rel=0.05)


# ------------------------------------------------------ bearing, backlash ----


def _frame(kr: float, ka: float, prefix: str = "") -> pl.DataFrame:
    return pl.DataFrame(
        {
            "speed_rpm": [5000.0, 15000.0],
            f"{prefix}radial_stiffness_n_per_m": [kr, 0.8 * kr],
            f"{prefix}axial_stiffness_n_per_m": [ka, 1.1 * ka],
        }
    )


def test_per_shaft_equals_twice_per_bearing(pair: tb.GearPair) -> None:
    kw = dict(torque_n_m=20.0, te_amplitude_um=10.0)
    one = _frame(1.5e8, 4e7)
    per_bearing = tb.GearSystem(pair, stiffness=one, bearing_stiffness_per="bearing", **kw)
    per_shaft = tb.GearSystem(pair, stiffness=_frame(3e8, 8e7), bearing_stiffness_per="shaft", **kw)
    assert per_bearing.bearings_per_shaft == 2 and per_shaft.bearings_per_shaft is None
    assert per_bearing.stiffness_schedule.equals(per_shaft.stiffness_schedule)
    assert _sweep(per_bearing).equals(_sweep(per_shaft))
    three = tb.GearSystem(
        pair,
        stiffness=_frame(1e8, 8e7 / 3),
        bearing_stiffness_per="bearing",
        bearings_per_shaft=3,
        **kw,
    )
    assert three.bearing_stiffness_at(5000.0) == pytest.approx((3e8, 8e7), rel=1e-15)
    # The schedule frame (support_* columns) is per shaft by its names.
    again = tb.GearSystem(pair, stiffness=per_bearing.stiffness_schedule, **kw)
    assert again.stiffness_schedule.equals(per_bearing.stiffness_schedule)
    # The computed case is one bearing's stiffness times the count.
    c1 = tb.GearSystem(pair, bearings_per_shaft=1)
    c2 = tb.GearSystem(pair)
    assert c2.bearing_stiffness_at(1.0) == pytest.approx(
        tuple(2 * k for k in c1.bearing_stiffness_at(1.0)), rel=1e-15
    )
    with pytest.raises(tb.ConfigError, match="bearing_stiffness_per"):
        tb.GearSystem(pair, stiffness=one)
    with pytest.raises(tb.ConfigError, match="bearings_per_shaft"):
        tb.GearSystem(pair, stiffness=one, bearing_stiffness_per="shaft", bearings_per_shaft=2)
    with pytest.raises(tb.ConfigError, match="bearing_stiffness_per"):
        tb.GearSystem(pair, stiffness="constant", bearing_stiffness_per="shaft")
    with pytest.raises(tb.ConfigError, match="bearing_stiffness_per"):
        tb.GearSystem(pair, stiffness=one, bearing_stiffness_per="pair")


def test_half_and_total_backlash_are_one_input(pair: tb.GearPair) -> None:
    kw = dict(torque_n_m=20.0, te_amplitude_um=10.0)
    half = tb.GearSystem(pair, half_backlash_um=40.0, **kw)
    total = tb.GearSystem(pair, backlash_total_um=80.0, **kw)
    assert half.params["half_backlash_um"] == pytest.approx(40.0, rel=1e-15)
    assert _sweep(half).equals(_sweep(total))
    with pytest.warns(DeprecationWarning, match="backlash_total_um"):
        old = tb.GearSystem(pair, backlash_um=80.0, **kw)
    assert old.params == total.params
    assert tb.GearSystem(pair).params["half_backlash_um"] == pytest.approx(50.0)
    with pytest.raises(tb.ConfigError, match="exactly one"):
        tb.GearSystem(pair, half_backlash_um=40.0, backlash_total_um=80.0)
    with pytest.raises(tb.ConfigError, match="backlash_total_um"):
        tb.GearSystem(pair, backlash_total_um=-1.0)


# --------------------------------------------------- settings and columns ----


def test_settings_are_validated_by_name(seed: tb.GearSystem) -> None:
    bad = [
        ("max_period", 0),
        ("max_period", 30),  # needs 2 x 30 > 40 recorded periods
        ("period_rel_tol", 0.0),
        ("period_rel_tol", 1.5),
        ("converging_ratio", 1.0),
        ("lyapunov_block_periods", 0),
        ("lyapunov_max_periods", 50),  # below lyapunov_periods = 100
        ("lyapunov_sigmas", -1.0),
        ("lyapunov_threshold_per_mesh_period", float("nan")),
        ("zero_one_threshold", 1.2),
        ("jump_rel_amplitude", 0.0),
        ("jump_trend_factor", -1.0),
        ("jump_window_speeds", 0),
        ("max_transient_periods", 50),  # below transient_periods = 100
    ]
    for name, value in bad:
        with pytest.raises(tb.ConfigError, match=name):
            _sweep(seed, [10_000.0], **{name: value})
        if name.startswith("jump"):
            continue
        with pytest.raises(tb.ConfigError, match=name):
            tb.regime_map(
                seed, [50.0], [10_000.0], transient_periods=100, record_periods=40, **{name: value}
            )
    for name, value in (
        ("record_periods", 1),
        ("transient_periods", -3),
        ("steps_per_period", 2.5),
    ):
        with pytest.raises(tb.ConfigError, match=name):
            tb.bifurcation(seed, [10_000.0], **{name: value})
    with pytest.raises(tb.ConfigError, match="speeds_rpm"):
        tb.bifurcation(seed, [10_000.0, -5.0])


def test_settings_reach_the_classifier(light: tb.GearSystem) -> None:
    """max_period 1 turns a period-2 orbit non-periodic (not a period-1 one); a
    huge sigma requirement leaves no speed chaotic; a transient cap equal to
    the transient never extends it."""
    base = _per_speed(_sweep(light))
    regime = dict(zip(base["speed_rpm"], base["regime"], strict=True))
    two = [s for s, r in regime.items() if r == "period-2"]
    one = [s for s, r in regime.items() if r == "period-1"]
    assert two and one and "chaotic" in regime.values()
    p1 = dict(_per_speed(_sweep(light, max_period=1)).select("speed_rpm", "regime").rows())
    assert p1[two[0]] in ("quasi-periodic", "chaotic") and p1[one[0]] == "period-1"
    calm = _per_speed(_sweep(light, lyapunov_sigmas=1e6))
    assert "chaotic" not in set(calm["regime"])
    fixed = _per_speed(_sweep(light, max_transient_periods=100))
    assert set(fixed["transient_periods"]) == {100}
    assert set(base["transient_periods"]) >= {100}


def test_jump_settings_reach_the_detector(seed: tb.GearSystem) -> None:
    """The steep amplitude change near 6,700 rpm at 100 N m is a jump on a
    100 rpm grid; no step can exceed 2 x the larger amplitude, so
    jump_rel_amplitude = 10 flags none, nor does a huge trend factor."""
    speeds = np.arange(6500.0, 8001.0, 100.0)

    def jumps(**kw) -> list:
        per = _per_speed(_sweep(seed, speeds, **kw))
        return per.filter(pl.col("jump_after"))["speed_rpm"].to_list()

    assert jumps()
    assert jumps(jump_rel_amplitude=10.0) == []
    assert jumps(jump_trend_factor=1e6) == []
    assert jumps(jump_window_speeds=3, jump_rel_amplitude=10.0) == []


def test_lyapunov_units(light: tb.GearSystem) -> None:
    """Per mesh period = per second / mesh frequency (z_p n / 60)."""
    s = 15800.0
    f_mesh = 29 * s / 60.0
    per_s, se_s = tb.largest_lyapunov(light, s, periods=100, return_stderr=True)
    per_t, se_t = tb.largest_lyapunov(light, s, periods=100, per="mesh_period", return_stderr=True)
    assert per_t == pytest.approx(per_s / f_mesh, rel=1e-12)
    assert se_t == pytest.approx(se_s / f_mesh, rel=1e-12) and se_s > 0.0
    assert light.mesh_period_s(s) == pytest.approx(1.0 / f_mesh, rel=1e-15)
    assert per_t > 3 * se_t  # chaotic there, beyond its error
    per = _per_speed(_sweep(light)).filter(pl.col("lyapunov_per_s").is_not_null())
    assert per.height >= 1
    f = 29 * per["speed_rpm"].to_numpy() / 60.0
    np.testing.assert_allclose(
        per["lyapunov_per_mesh_period"], per["lyapunov_per_s"] / f, rtol=1e-12
    )
    np.testing.assert_allclose(
        per["lyapunov_stderr_per_mesh_period"], per["lyapunov_stderr_per_s"] / f, rtol=1e-12
    )
    rm = tb.regime_map(light, [20.0], [s], transient_periods=100, record_periods=40)
    assert rm["regime"][0] == "chaotic" and rm["settled"][0]
    assert rm["lyapunov_per_mesh_period"][0] == pytest.approx(
        rm["lyapunov_per_s"][0] / f_mesh, rel=1e-12
    )
    assert rm["lyapunov_per_mesh_period"][0] > 3 * rm["lyapunov_stderr_per_mesh_period"][0]
    with pytest.raises(tb.ConfigError, match="per"):
        tb.largest_lyapunov(light, s, per="hour")
    with pytest.raises(tb.ConfigError, match="per"):
        tb.largest_lyapunov("lorenz", per="mesh_period")
    with pytest.raises(tb.ConfigError, match="periods"):
        tb.largest_lyapunov(light, s, periods=10, block_periods=10)


def test_speeds_in_any_order_and_sweep_order_rows(light: tb.GearSystem) -> None:
    """Shuffled speeds give the sorted sweep; rows in sweep order (down:
    descending); jumps and transitions refer to the next row's speed."""
    speeds = np.linspace(9000.0, 16000.0, 15)
    shuffled = np.random.default_rng(7).permutation(speeds)
    for direction in ("up", "down", "independent"):
        a = tb.bifurcation(light, shuffled, direction, 100, 40, 64)
        assert a.equals(tb.bifurcation(light, speeds, direction, 100, 40, 64))
        per = _per_speed(a)
        s = per["speed_rpm"].to_numpy()
        assert np.all(np.diff(s) < 0) if direction == "down" else np.all(np.diff(s) > 0)
        rows = per.rows(named=True)
        fam = lambda r: "periodic" if r.startswith("period-") else r  # noqa: E731
        kinds = 0
        for r, nxt in zip(rows[:-1], rows[1:], strict=True):
            t = r["transition_after"]
            assert (t is not None) == (fam(r["regime"]) != fam(nxt["regime"]))
            if t is None:
                continue
            kinds += 1
            assert (t == "enters-chaos") == (nxt["regime"] == "chaotic" != r["regime"])
            assert (t == "exits-chaos") == (r["regime"] == "chaotic" != nxt["regime"])
            assert r["transition_dte_max_change_um"] == pytest.approx(
                nxt["dte_max_um"] - r["dte_max_um"]
            )
            assert r["transition_dte_min_change_um"] == pytest.approx(
                nxt["dte_min_um"] - r["dte_min_um"]
            )
            assert not r["jump_after"]
        assert kinds >= 1
        assert rows[-1]["transition_after"] is None and not rows[-1]["jump_after"]


def test_regimes_of_bare_samples_take_the_period_settings() -> None:
    """A period-20 sequence: period-20 with the default max_period 32,
    non-periodic with max_period 16; a 2 % wobble matches only with a loose
    tolerance."""
    x = np.tile(np.arange(20.0), 3)
    df = pl.DataFrame({"speed_rpm": np.full(60, 1.0), "dte_um": x})
    assert tb.regimes(df)["regime"].to_list() == ["period-20"]
    assert tb.regimes(df, max_period=16)["regime"].to_list() == ["non-periodic"]
    wobble = pl.DataFrame(
        {"speed_rpm": np.full(40, 1.0), "dte_um": 10.0 + 0.2 * (np.arange(40) % 2)}
    )
    wobble = wobble.vstack(pl.DataFrame({"speed_rpm": [2.0] * 40, "dte_um": [0.0] * 40}))
    assert tb.regimes(wobble)["regime"].to_list() == ["period-2", "period-1"]
    assert tb.regimes(wobble, period_rel_tol=0.05)["regime"].to_list() == ["period-1"]
    with pytest.raises(tb.ConfigError, match="max_period"):
        tb.regimes(df, max_period=0)
    with pytest.raises(tb.ConfigError, match="period_rel_tol"):
        tb.regimes(df, period_rel_tol=2.0)


def test_regimes_report_transitions_and_unsettled_speeds() -> None:
    df = pl.DataFrame(
        {
            "speed_rpm": [4.0, 3.0, 2.0, 1.0],
            "dte_um": [1.0, 2.0, 3.0, 4.0],
            "direction": ["down"] * 4,
            "regime": ["period-1", "period-1", "chaotic", "chaotic"],
            "period": [1, 1, 0, 0],
            "impact": ["double-sided"] * 4,
            "lyapunov_per_mesh_period": [None, None, 0.2, 0.3],
            "lyapunov_stderr_per_mesh_period": [None, None, 0.01, 0.05],
            "settled": [True, False, True, True],
            "jump_after": [False] * 4,
            "transition_after": [None, "enters-chaos", None, None],
            "transition_dte_min_change_um": [None, -2.5, None, None],
            "transition_dte_max_change_um": [None, 1.5, None, None],
        }
    )
    reg = tb.regimes(df)
    assert reg.select("speed_from_rpm", "speed_to_rpm", "regime").rows() == [
        (4.0, 3.0, "period-1"),
        (2.0, 1.0, "chaotic"),
    ]
    first, second = reg.rows(named=True)
    assert first["transition_at_end"] == "enters-chaos"
    assert first["transition_dte_min_change_um"] == -2.5
    assert first["unsettled_speeds"] == 1 and first["unsettled_speeds_rpm"] == "3"
    assert second["transition_at_end"] is None and second["unsettled_speeds"] == 0
    assert second["lyapunov_per_mesh_period_min"] == 0.2
    assert second["lyapunov_stderr_per_mesh_period_max"] == 0.05


def test_bifurcation_plot_marks_unsettled_speeds() -> None:
    df = pl.DataFrame(
        {
            "speed_rpm": [1.0, 1.0, 2.0, 2.0],
            "dte_um": [1.0, 2.0, 3.0, 4.0],
            "settled": [True, True, False, False],
        }
    )
    ax = tb.plot.bifurcation(df)
    sets = [c.get_offsets() for c in ax.collections]
    assert [len(o) for o in sets] == [2, 2]
    np.testing.assert_array_equal(sets[1][:, 1], [3.0, 4.0])
    assert len(tb.plot.bifurcation(df, unsettled_color=None).collections) == 1


@pytest.mark.parametrize(
    ("key", "value"),
    [("helix_angle_deg", -30.0), ("helix_angle_deg", 45.0), ("helix_angle_deg", 60.0),
     ("normal_pressure_angle_deg", 50.0), ("normal_pressure_angle_deg", 0.0)],
)  # fmt: skip
def test_gear_angles_outside_the_models_range_are_named_in_degrees(key, value):
    """The tooth model takes helix angles in [0, 45) deg and normal pressure
    angles in (0, 45] deg; a value outside is named in the caller's field
    and unit, not the core's radians."""
    kw = {
        "pinion_teeth": 26, "gear_teeth": 41, "normal_module_mm": 2.0,
        "normal_pressure_angle_deg": 20.0, "helix_angle_deg": 20.0, "face_width_mm": 25.0,
        "youngs_modulus_mpa": 206000.0, "poisson_ratio": 0.3, "density_t_per_mm3": 7.8e-9,
        "mass_kg": (0.5, 1.2), "polar_inertia_t_mm2": (0.1, 0.6), "input_torque_n_m": 100.0,
    }  # fmt: skip
    with pytest.raises(tb.ConfigError, match=rf"invalid {key} = "):
        tb.GearPair.from_table(**{**kw, key: value})
    tb.GearPair.from_table(**kw)  # the same pair inside the ranges builds


def test_mesh_tables_of_unequal_lengths_keep_each_tables_samples():
    """A stiffness table on 16 points and a TE table on 40 give one frame
    on the union of the two phase grids (48 phases), each column null where
    its table has no sample; the stiffness column, nulls dropped, rebuilds
    the model's stiffness table bit for bit."""
    pair = tb.GearPair.preset("seed-electric-drive")
    base = tb.GearSystem(pair).mesh_tables()
    ph16, ph40 = np.arange(16) / 16, np.arange(40) / 40
    grid = base["mesh_phase"].to_numpy()
    k = np.interp(ph16, grid, base["normal_stiffness_n_per_m"].to_numpy())
    te = np.interp(ph40, grid, base["transmission_error_um"].to_numpy())
    system = tb.GearSystem(
        pair,
        mesh_stiffness_n_per_m=pl.DataFrame({"mesh_phase": ph16, "normal_stiffness_n_per_m": k}),
        transmission_error_um=pl.DataFrame({"mesh_phase": ph40, "transmission_error_um": te}),
    )
    t = system.mesh_tables()
    assert t.height == len(np.union1d(ph16, ph40)) == 48
    assert t["normal_stiffness_n_per_m"].null_count() == 32
    assert t["transmission_error_um"].null_count() == 8
    kk = t.drop_nulls("normal_stiffness_n_per_m").select("mesh_phase", "normal_stiffness_n_per_m")
    back = tb.GearSystem(pair, mesh_stiffness_n_per_m=kk)
    got = back.mesh_tables()["normal_stiffness_n_per_m"].drop_nulls().to_numpy()
    assert np.array_equal(got, kk["normal_stiffness_n_per_m"].to_numpy())
