"""The selectable heat models and the lubrication method from Python
(docs/concepts/physics.md §9): defaults per method, the SKF-style model
against the catalogue's constant-friction estimate, drag limits, heat
balance in the bearing and spindle states, bad input."""

from __future__ import annotations

import numpy as np
import pytest

import thermobear as tb


@pytest.fixture(scope="module")
def b7009():
    return tb.Bearing.preset("7009C")


def test_lubrication_defaults_per_method():
    # Palmgren f0 (Harris & Kotzalas' table): angular-contact oil mist 1.7,
    # bath 3.3, jet 6.6, grease 2; deep-groove 1, 2, 4
    ac = {m: tb.lubrication_defaults(m, "angular_contact") for m in
          ("grease", "oil-air", "oil-mist", "jet", "oil-bath")}  # fmt: skip
    assert [ac[m]["lubrication_factor_f0"] for m in ("oil-mist", "oil-bath", "jet", "grease")] == [
        1.7, 3.3, 6.6, 2.0,
    ]  # fmt: skip
    dg = tb.lubrication_defaults("jet", "deep_groove")
    assert dg["lubrication_factor_f0"] == 4.0 and dg["replenishment_krs"] == 3e-8
    assert ac["oil-air"]["replenishment_krs"] == 6e-8
    x = [ac[m]["oil_volume_fraction"] for m in ("grease", "oil-mist", "oil-air", "jet", "oil-bath")]
    assert x == sorted(x) and x[0] == 0.0
    for d in ac.values():
        lo, hi = d["oil_fraction_bounds"]
        assert lo <= d["oil_volume_fraction"] <= hi
    with pytest.raises(tb.ConfigError, match="lubrication"):
        tb.lubrication_defaults("honey", "deep_groove")


def test_method_sets_f0_and_drag_unless_given(b7009):
    # lubrication=None is the seeds' model: f0 = 1, no drag
    s0 = tb.thermal_state(b7009, 12_000, 400.0, 0.0)
    assert s0.churning_heat_w == 0.0
    explicit = tb.thermal_state(
        b7009, 12_000, 400.0, 0.0, lubrication_factor_f0=6.6, churning_oil_fraction=0.03
    )
    jet = tb.thermal_state(b7009, 12_000, 400.0, 0.0, lubrication="jet")
    assert jet.total_heat_w == pytest.approx(explicit.total_heat_w, rel=1e-12)
    # a value given beats the method's default
    dry = tb.thermal_state(b7009, 12_000, 400.0, 0.0, lubrication="jet", churning_oil_fraction=0.0)
    assert dry.churning_heat_w == 0.0 and jet.churning_heat_w > 10.0


def test_skf_model_state_balances_heat_and_reports_its_terms(b7009):
    s = tb.thermal_state(
        b7009, 15_000, 400.0, 100.0, heat_model="skf", lubrication="oil-air", lubricant="ISO VG 32"
    )
    h = dict(zip(s.heat["source"], s.heat["heat_w"], strict=True))
    assert set(h) == {"rolling", "sliding", "seal", "extra", "churning"}
    assert h["rolling"] > 0 and h["sliding"] > 0 and h["seal"] == 0.0
    assert sum(h.values()) == pytest.approx(s.total_heat_w, rel=1e-9)
    assert s.boundary_flows["heat_w"].sum() == pytest.approx(s.total_heat_w, rel=1e-6)
    assert 0 < s.raw["skf_phi_ish"] < 1 and 0 < s.raw["skf_phi_rs"] < 1
    # a seal moment adds omega M_seal at the same state
    sealed = tb.thermal_state(
        b7009, 15_000, 400.0, 100.0, heat_model="skf", lubrication="oil-air",
        lubricant="ISO VG 32", seal_moment_n_m=0.02,
    )  # fmt: skip
    hs = dict(zip(sealed.heat["source"], sealed.heat["heat_w"], strict=True))
    assert hs["seal"] == pytest.approx(0.020 * 15_000 * 2 * np.pi / 60, rel=1e-12)


def test_skf_deep_groove_matches_the_catalogue_constant_friction_estimate():
    # SKF "estimating the frictional moment": M = 0.5 mu P d, mu = 0.0015
    # deep-groove (P ~ 0.1 C, good lubrication). A 6208 (d = 40 mm) at
    # Fr = 3 kN and 3000 rpm in ISO VG 32 supplied at 50 C (~20 cSt; the
    # viscosity is taken at the supply temperature without the
    # temperature_dependent_viscosity effect): 90 N mm, i.e. 28.3 W. The
    # four-term model lands within 30 %.
    b = tb.Bearing.preset("6208")
    s = tb.thermal_state(
        b, 3000, 0.0, 3000.0, heat_model="skf", lubricant="ISO VG 32", effects=[],
        oil_air_temperature_c=50.0,
    )  # fmt: skip
    assert 18.0 < s.viscosity_cst < 23.0
    h = dict(zip(s.heat["source"], s.heat["heat_w"], strict=True))
    friction_w = h["rolling"] + h["sliding"]
    estimate_w = 0.5 * 0.0015 * 3000.0 * 0.040 * 3000 * 2 * np.pi / 60
    assert friction_w == pytest.approx(estimate_w, rel=0.3), (friction_w, s.viscosity_cst)


def test_drag_vanishes_with_the_oil_fraction_and_grows_with_speed(b7009):
    speeds = [6000.0, 12000.0, 18000.0]
    kw = dict(heat_model="skf", lubrication="jet")
    dry = tb.thermal.thermal_stiffness_curve(
        b7009, speeds, 400.0, 0.0, churning_oil_fraction=0.0, **kw
    )
    wet = tb.thermal.thermal_stiffness_curve(b7009, speeds, 400.0, 0.0, **kw)
    assert np.all(dry["churning_heat_w"].to_numpy() == 0.0)
    assert np.all(np.diff(wet["churning_heat_w"].to_numpy()) > 0.0)
    # exactly cubic in the solved cage speed, linear in the oil density
    a, b = (tb.thermal_state(b7009, n, 400.0, 0.0, **kw).raw for n in (12000.0, 18000.0))
    ratio = (b["cage_speed_rad_s"] / a["cage_speed_rad_s"]) ** 3 * (
        b["oil_density_kg_m3"] / a["oil_density_kg_m3"]
    )
    assert b["churning_w"] / a["churning_w"] == pytest.approx(ratio, rel=1e-9)
    # and close to the shaft-speed cube (the cage/shaft ratio moves a little)
    assert b["churning_w"] / a["churning_w"] == pytest.approx(1.5**3, rel=0.1)


def test_spindle_heat_model_and_lubrication(b7009):
    sp = tb.Spindle.preset("seed-ceramic-spindle")
    base = sp.thermal_state(12_000)
    skf = sp.with_options(heat_model="skf", lubrication="oil-air")
    a = skf.assumptions
    assert a["heat_model"] == "skf" and a["lubrication"] == "oil-air"
    assert a["lubrication_factor_f0"] == 1.7 and a["churning_oil_fraction"] == 0.01
    row = skf.thermal_state(12_000)
    assert row["bearing_drag_heat_w"][0] > 0.0 and base["bearing_drag_heat_w"][0] == 0.0
    # heat balance of the spindle network with the new model
    assert row["boundary_flow_w"][0] == pytest.approx(row["total_heat_w"][0], rel=1e-4)
    assert row["bearing_heat_w"][0] != base["bearing_heat_w"][0]
    # the dispatch of tb.thermal_state carries the keywords
    row2 = tb.thermal_state(sp, 12_000, heat_model="skf", lubrication="oil-air")
    assert row2["bearing_heat_w"][0] == row["bearing_heat_w"][0]
    with pytest.raises(tb.ConfigError, match="heat_model"):
        sp.with_options(heat_model="magic")
    with pytest.raises(tb.ConfigError, match="churning_oil_fraction"):
        sp.with_options(churning_oil_fraction=2.0)


def test_skf_series_single_row_angular_contact_names(b7009):
    # SKF General Catalogue 6000 (2006), friction chapter, table 3 (p. 92):
    # one row of constants for every single-row angular-contact series, so
    # "72B" and "73B" (which used to hold the double-row row) name it, and
    # it is the angular-contact default; table 3a (p. 93) groups 60/630.
    kw = {"heat_model": "skf", "lubrication": "jet", "lubricant": "ISO VG 32"}
    heats = [
        tb.thermal_state(b7009, 15_000, 400.0, 0.0, skf_series=s, **kw).total_heat_w
        for s in (None, "angular-single-row", "72B", "73B", "73 b")
    ]
    assert heats == [heats[0]] * 5
    b6208 = tb.Bearing.preset("6208")
    a, b = (tb.thermal_state(b6208, 3000, 0.0, 3000.0, skf_series=s, **kw).total_heat_w
            for s in ("60", "630"))  # fmt: skip
    assert a == b
    with pytest.raises(tb.ConfigError, match=r"angular-single-row \(72B, 73B\)"):
        tb.thermal_state(b7009, 6000, 400.0, 0.0, heat_model="skf", skf_series="33D")


def test_bad_heat_model_input_names_the_field(b7009):
    with pytest.raises(tb.ConfigError, match="heat_model"):
        tb.thermal_state(b7009, 6000, 400.0, 0.0, heat_model="harris")
    with pytest.raises(tb.ConfigError, match="skf_series"):
        tb.thermal_state(b7009, 6000, 400.0, 0.0, heat_model="skf", skf_series="99")
    with pytest.raises(tb.ConfigError, match="sliding_friction_ehl"):
        tb.thermal_state(b7009, 6000, 400.0, 0.0, heat_model="skf", sliding_friction_ehl=0.9)
    with pytest.raises(tb.ConfigError, match="lubrication"):
        tb.thermal_state(b7009, 6000, 400.0, 0.0, lubrication="water")


def test_isothermal_heat_is_the_friction_model_at_the_given_oil_temperature():
    import numpy as np

    b = tb.Bearing.preset("6208")
    h = tb.isothermal_heat(b, 6000.0, 300.0, 1000.0, oil_temperature_c=60.0, lubricant="ISO VG 32")
    # Palmgren viscous heat by hand: 1e-7 f0 (nu n)^(2/3) dm^3 [N mm] x omega
    nu, dm = h.viscosity_cst, b.geometry["pitch_diameter_mm"]
    mv = 1e-7 * 1.0 * (nu * 6000.0) ** (2 / 3) * dm**3 * 1e-3
    viscous = h.heat.filter(h.heat["source"] == "viscous")["heat_w"][0]
    assert viscous == pytest.approx(mv * 6000.0 * np.pi / 30.0, rel=1e-12)
    assert h.heat["heat_w"].sum() == pytest.approx(h.total_heat_w, rel=1e-12)
    # thinner oil, less heat; the rows of the SKF model sum to its total too
    hot = tb.isothermal_heat(
        b, 6000.0, 300.0, 1000.0, oil_temperature_c=90.0, lubricant="ISO VG 32"
    )
    assert hot.viscosity_cst < nu and hot.total_heat_w < h.total_heat_w
    skf = tb.isothermal_heat(b, 6000.0, 300.0, 1000.0, oil_temperature_c=60.0,
                             lubricant="ISO VG 32", heat_model="skf")  # fmt: skip
    assert list(skf.heat["source"]) == ["rolling", "sliding", "seal", "extra", "churning"]
    assert skf.heat["heat_w"].sum() == pytest.approx(skf.total_heat_w, rel=1e-12)
    with pytest.raises(tb.ConfigError, match="oil_temperature_c"):
        tb.isothermal_heat(b, 6000.0, 300.0, 1000.0, oil_temperature_c=float("nan"))
    with pytest.raises(tb.ConfigError, match="speed_rpm"):
        tb.isothermal_heat(b, -1.0, 300.0, 1000.0, oil_temperature_c=60.0)
    with pytest.raises(tb.ConfigError, match="no_such"):
        tb.isothermal_heat(b, 6000.0, oil_temperature_c=60.0, no_such=1.0)
