"""The effect ``preload_change_from_axial_growth`` through the Python API:
the spindle's axial thermal growth compresses the preload spring only with
the effect on (spring law F = F0 + k_s x), and the effects registry tells
the models each effect acts in."""

import pytest

import thermobear as tb

EFFECT = "preload_change_from_axial_growth"
SPEED_RPM = 15_000.0


@pytest.fixture(scope="module")
def states():
    sp = tb.Spindle.preset("seed-ceramic-spindle")
    assert sp.preload_kind == "spring" and sp.preload_n == 400.0
    # the spindle default: every effect but the magnetic pull
    names = [n for n in tb.effects("switch")["name"] if n != "unbalanced_magnetic_pull"]
    on = sp.thermal_state(SPEED_RPM).row(0, named=True)
    off = sp.with_options(effects=[n for n in names if n != EFFECT])
    return sp, on, off.thermal_state(SPEED_RPM).row(0, named=True)


def test_growth_reaches_the_spring_only_with_the_effect_on(states):
    sp, on, off = states
    ks = sp.spring_rate_n_per_um  # N/um
    for s in (on, off):
        # The growth between the sets is computed either way.
        assert s["axial_growth_um"] > 10.0
        # Spring law: operating preload = F0 + k_s x.
        expect = s["preload_n"] + ks * s["spring_compression_um"]
        assert s["operating_preload_n"] == pytest.approx(expect, rel=1e-6)
    # Off: the spring takes only the pair's own axial approach change, far
    # less than the growth (nominal 400 N up to k_s x of that change).
    assert off["spring_compression_um"] < 0.5 * off["axial_growth_um"]
    # On: the growth adds k_s u to both pairs' preload (3 %: bearings in
    # series with the spring, and the warmer bearings shift u a little).
    grow = ks * on["axial_growth_um"]
    for col in ("operating_preload_n", "rear_operating_preload_n"):
        assert on[col] - off[col] == pytest.approx(grow, rel=0.03)


def test_rigid_preload_ignores_the_effect():
    sp = tb.Spindle.preset("seed-ceramic-spindle").with_options(preload_kind="rigid")
    # the spindle default: every effect but the magnetic pull
    names = [n for n in tb.effects("switch")["name"] if n != "unbalanced_magnetic_pull"]
    on = sp.thermal_state(SPEED_RPM)
    off = sp.with_options(effects=[n for n in names if n != EFFECT]).thermal_state(SPEED_RPM)
    assert on["axial_growth_um"][0] > 10.0
    assert on["operating_preload_n"][0] == off["operating_preload_n"][0]
    assert on["front_ball_temperature_c"][0] == off["front_ball_temperature_c"][0]


def test_registry_lists_models():
    df = tb.effects("switch")
    assert {"name", "description", "models"} <= set(df.columns)
    models = dict(zip(df["name"], df["models"], strict=False))
    assert models[EFFECT] == "spindle"
    assert models["unbalanced_magnetic_pull"] == "spindle,rotor"
    assert "rotor" in models["centrifugal_force"].split(",")
    known = {"bearing", "spindle", "rotor"}
    for m in df["models"]:
        assert m and set(m.split(",")) <= known
