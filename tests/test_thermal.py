"""Coupled thermo-mechanical bearing model through Python (seed A network)."""

import numpy as np
import pytest

import thermobear as tb
from thermobear.thermal import THERMAL_EFFECTS

# Seed A (Sensors 2021, 21, 309, sec. 2.3): 300 N preload plus the 100 N m
# case's 2380.9 N axial and 1189.9 N radial load.
FA = 300.0 + 2380.9
FR = 1189.9


@pytest.fixture(scope="module")
def b6208():
    return tb.Bearing.preset("6208")


def _effects_without_thermal():
    return [n for n in tb.effects("switch")["name"].to_list() if n not in THERMAL_EFFECTS]


def test_heat_balance(b6208):
    s = tb.thermal_state(b6208, speed_rpm=12_000, axial_n=FA, radial_n=FR)
    sources = s.heat["heat_w"].sum()
    parts = s.heat_split["heat_w"].sum()
    out = s.boundary_flows["heat_w"].sum()
    assert sources > 0
    assert parts == pytest.approx(sources, rel=1e-12)
    assert out == pytest.approx(sources, rel=1e-6)
    assert s.residual <= 1e-6 and s.iterations >= 2
    # Every free node is hotter than the hotter boundary (oil-air 28 C).
    t = s.temperatures.filter(~s.temperatures["node"].is_in(["oil_air", "ambient"]))
    assert (t["temperature_c"] > 28.0).all()


def test_zero_heat_limit_equals_isothermal(b6208):
    eff = _effects_without_thermal()
    s = tb.thermal_state(b6208, speed_rpm=9_000, axial_n=FA, radial_n=FR, effects=eff)
    full = b6208.solve(axial_n=FA, radial_n=FR, speed_rpm=9_000, effects=eff)
    np.testing.assert_array_equal(s.solution.stiffness, full.stiffness)
    np.testing.assert_array_equal(s.solution.displacement, full.displacement)
    iso = tb.stiffness_curve(b6208, [9_000.0], FA, FR, mode="speed", effects=eff)
    k = s.solution.stiffness
    assert k[0, 0] == iso["k_xx_n_per_m"][0] and k[2, 2] == iso["k_zz_n_per_m"][0]
    assert s.solution.axial_displacement_um == iso["axial_displacement_um"][0]
    assert s.solution.radial_stiffness_seed_n_per_m == iso["radial_stiffness_seed_n_per_m"][0]
    assert s.deformations["radial_thermal_offset_um"] == 0.0


def test_thermal_mode_equals_speed_mode_when_thermal_effects_off(b6208):
    eff = _effects_without_thermal()
    speeds = [6_500.0, 11_500.0, 16_500.0]
    th = tb.stiffness_curve(b6208, speeds, FA, FR, mode="thermal", effects=eff)
    sp = tb.stiffness_curve(b6208, speeds, FA, FR, mode="speed", effects=eff)
    for c in ("axial_stiffness_seed_n_per_m", "radial_stiffness_seed_n_per_m", "k_xx_n_per_m"):
        np.testing.assert_array_equal(th[c].to_numpy(), sp[c].to_numpy())
    assert (th["heat_w"].to_numpy() > 0).all()


def test_trends_heat_and_temperature(b6208):
    # Seed A Fig. 6 and 8a: heat and node temperatures rise with speed and
    # heat with preload (more load, more Palmgren M1 and spin moment).
    df = tb.stiffness_curve(b6208, [7_000.0, 12_000.0, 17_000.0], 300.0, 0.0, mode="thermal")
    for c in (
        "heat_w",
        "ball_temperature_c",
        "inner_ring_temperature_c",
        "outer_ring_temperature_c",
    ):
        assert np.all(np.diff(df[c].to_numpy()) > 0), c
    h = [tb.thermal_state(b6208, 10_000, fa, 0.0).total_heat_w for fa in (300.0, 600.0, 900.0)]
    assert h[0] < h[1] < h[2]


def test_unknown_effect_is_config_error(b6208):
    with pytest.raises(tb.ConfigError, match="thermal_expansion_cage"):
        tb.thermal_state(b6208, 10_000, FA, FR, effects=["thermal_expansion_cage"])


def test_bad_inputs_name_the_item(b6208):
    with pytest.raises(tb.ConfigError, match="lubricant"):
        tb.thermal_state(b6208, 10_000, FA, FR, lubricant="olive oil")
    with pytest.raises(tb.ConfigError, match="conductivity_w_mk"):
        bad = tb.Material("bad-aluminium", base="aluminium", conductivity_w_mk=-5.0)
        tb.thermal_state(b6208, 10_000, FA, FR, housing_material=bad)
    with pytest.raises(tb.ConfigError, match="speed_rpm"):
        tb.thermal_state(b6208, -5.0, FA, FR)
    with pytest.raises(tb.ConfigError, match="oil_temperature_c"):
        tb.thermal_state(b6208, 10_000, FA, FR, oil_air_temperature_c=-80.0)
    with pytest.raises(tb.ConfigError, match="mode"):
        tb.stiffness_curve(b6208, [1000.0], FA, FR, mode="hot")


def test_speed_beyond_lubricant_range_is_runaway(b6208):
    # Far beyond the 6208's limiting speed the nodes pass the oil's data
    # range: the error names the node and the lubricant.
    with pytest.raises(tb.ThermalRunawayError, match="lubricant 'e-drive ATF'"):
        tb.thermal_state(b6208, 200_000, FA, FR)


def test_dispatch_to_objects_with_thermal_state():
    class Fake:
        def _thermal_state(self, **kw):
            return kw

    kw = tb.thermal_state(Fake(), speed_rpm=5.0, axial_n=1.0, radial_n=2.0, effects=None, extra=3)
    # Only what was given is passed on (a spindle keeps its own loads otherwise).
    assert kw == {"speed_rpm": 5.0, "axial_n": 1.0, "radial_n": 2.0, "extra": 3}
    assert tb.thermal_state(Fake(), speed_rpm=5.0) == {"speed_rpm": 5.0}


def test_network_newton_agrees_with_scipy_fsolve(b6208):
    # Two independent solvers of the same seed A node balances (Fig. 7).
    from scipy.optimize import fsolve

    from thermobear import _native

    net = _native.seed_a_network_links(b6208._b, 10_000.0)
    names = list(net["node"])
    fixed = dict(net["boundary_temperature_c"])
    free = [i for i, n in enumerate(names) if n not in fixed]
    src = np.zeros(len(names))
    src[names.index("Ti")], src[names.index("Tb")], src[names.index("To")] = 60.0, 90.0, 30.0
    base = np.array([fixed.get(n, 0.0) for n in names])

    def residual(x):
        t = base.copy()
        t[free] = x
        r = src.copy()
        for _, a, b, g, nat in net["links"]:
            q = g * (t[a] - t[b]) + nat * abs(t[a] - t[b]) ** 0.25 * (t[a] - t[b])
            r[a] -= q
            r[b] += q
        return r[free]

    x = fsolve(residual, np.full(len(free), 40.0), xtol=1e-12)
    ours = _native.seed_a_steady_temperatures(b6208._b, 10_000.0, 60.0, 90.0, 30.0)
    np.testing.assert_allclose(np.asarray(ours["temperature_c"])[free], x, atol=1e-8)
    # Heat balance: everything leaves through oil-air and ambient, so the
    # free nodes sit above both boundaries.
    assert np.all(x > 28.0)
