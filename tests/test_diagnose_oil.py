"""The oil-supply calibration candidates (flow scale, speed exponent of the
cavity oil fraction; docs/concepts/diagnosis.md) and what the diagnosis can
tell apart with them: a drag error from an f0 error.

The fingerprints differ: at a stated flow the ball drag grows at least as
n^2 (cavity fraction ~ 1/n times the drag power ~ n^3), the viscous moment's
heat as n^(5/3) at a fixed viscosity (Palmgren, (nu n)^(2/3) n) and slower
as the oil heats up. On a jet-lubricated 7008C at
DN (n d_m) 1-2 million the data hidden with a wrong flow name the drag and
not f0, and the reverse; below DN 0.5 million the drag is too small to
leave its own shape and the two tie (tested too: that is the limit)."""

from __future__ import annotations

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear import diagnosis as D

HIGH = np.linspace(18000.0, 38000.0, 11)  # n d_m 0.97-2.05 million mm/min
LOW = np.linspace(4000.0, 10000.0, 11)  # n d_m 0.22-0.54 million
QS = ("heat_w", "outer_ring_temperature_c")
DRAG = {"oil_flow_scale", "cavity_fraction_speed_exponent"}
FLOW_CM3_PER_MIN = 1000.0  # the stated jet flow of the baseline


@pytest.fixture(scope="module")
def base() -> D.BearingModelSpec:
    return D.BearingModelSpec(
        tb.Bearing.preset("7008C-hybrid"), lubrication="jet", oil_flow_cm3_per_min=FLOW_CM3_PER_MIN
    )


def _measured(truth, speeds, seed: int, heat_sigma: float = 0.02) -> pl.DataFrame:
    """``truth`` at ``speeds`` under a 300 N preload with noise: the heat
    (e.g. from the oil's temperature rise) with a relative sigma, the outer
    ring's thermocouple 0.5 K."""
    cond = pl.DataFrame(
        {
            "speed_rpm": np.repeat(speeds, len(QS)),
            "axial_n": 300.0,
            "radial_n": 0.0,
            "quantity": list(QS) * len(speeds),
        }
    )
    p = truth.predict(cond)
    q = cond["quantity"].to_list()
    v = np.array([p[qq][i] for i, qq in enumerate(q)])
    s = np.array([heat_sigma * x if qq == "heat_w" else 0.5 for qq, x in zip(q, v, strict=True)])
    rng = np.random.default_rng(seed)
    return cond.with_columns(
        pl.Series("value", v + rng.normal(size=len(v)) * s), pl.Series("sigma", s)
    )


def _named(d) -> set[str]:
    """Every candidate the verdict names: accepted, tied or unresolved
    against an unknown smooth source (the generic control left out)."""
    names = {a["name"] for a in d.accepted} | set(d.tie) | {r["name"] for r in d.unresolved}
    return names - {"generic_control"}


def test_supply_candidates_have_sourced_bounds_and_replace_the_fixed_fraction(base):
    rows = {r["name"]: r for r in tb.candidates(base, list(QS)).iter_rows(named=True)}
    flow, expo = rows["oil_flow_scale"], rows["cavity_fraction_speed_exponent"]
    assert (flow["lower"], flow["upper"], flow["default"]) == (0.2, 5.0, 1.0)
    assert (expo["lower"], expo["upper"], expo["default"]) == (0.5, 1.5, 1.0)
    assert flow["role"] == expo["role"] == "calibration"
    # the drag follows the supply: no fixed-fraction candidate beside it
    assert "churning_oil_fraction" not in rows
    assert base.options["churning_oil_fraction"] is None
    # without a stated flow there is nothing to scale: the fixed fraction stays
    fixed = D.BearingModelSpec(base.bearing, lubrication="jet")
    names = set(tb.candidates(fixed, list(QS))["name"])
    assert "churning_oil_fraction" in names and not names & DRAG
    # a system TOML's [model.oil_supply] reaches the spec
    spec, _ = D.model_from_toml(
        '[bearing]\npreset = "7008C"\n[model]\nlubrication = "jet"\n'
        "[model.oil_supply]\noil_flow_cm3_per_min = 800.0\n"
    )
    assert spec.options["oil_flow_cm3_per_min"] == 800.0
    assert DRAG <= set(tb.candidates(spec)["name"])


def test_drag_and_viscous_fingerprints_differ_in_their_speed_law(base):
    """The extra heat of a doubled flow grows with speed far faster than
    that of a 30 % higher f0: over 18,000-38,000 rpm (a factor 2.1) their
    ratio grows by more than the speed ratio."""
    cond = pl.DataFrame({"speed_rpm": HIGH, "axial_n": 300.0, "radial_n": 0.0})
    h0 = base.predict(cond)["heat_w"]
    drag = base.with_setting(oil_flow_scale=2.0).predict(cond)["heat_w"] - h0
    visc = base.with_setting(lubrication_factor_f0=6.6 * 1.3).predict(cond)["heat_w"] - h0
    assert np.all(drag > 0) and np.all(visc > 0)
    ratio = drag / visc
    assert ratio[-1] / ratio[0] > HIGH[-1] / HIGH[0]
    # log-log slopes over the range: the drag at least n^2 (n^3 X with X ~ 1/n;
    # steeper still as centrifugal force flattens the outer contact and the
    # cage speeds up from 0.43 to 0.50 of the shaft's), the viscous change
    # far below (n^(5/3) at a fixed viscosity, about n^1.1 as the oil heats up)
    slope = lambda y: np.polyfit(np.log(HIGH), np.log(y), 1)[0]  # noqa: E731
    assert 2.0 < slope(drag) < 3.2, slope(drag)
    assert slope(visc) < 1.4 < slope(drag) - 0.6, slope(visc)


@pytest.mark.parametrize("heat_sigma", [0.01, 0.03])
def test_twice_the_flow_at_high_dn_is_named_drag_not_f0(base, heat_sigma):
    truth = base.with_setting(oil_flow_scale=2.0)
    for seed in range(3):
        d = tb.diagnose(base, _measured(truth, HIGH, seed, heat_sigma))
        named = _named(d)
        assert "oil_flow_scale" in named and named <= DRAG, d.verdict
        for a in d.accepted:  # when accepted outright, the flow is recovered
            assert a["lower_95"] <= 2.0 <= a["upper_95"], d.verdict


@pytest.mark.parametrize("heat_sigma", [0.01, 0.03])
def test_a_wrong_f0_at_high_dn_is_named_f0_not_drag(base, heat_sigma):
    truth = base.with_setting(lubrication_factor_f0=6.6 * 1.3)
    for seed in range(3):
        d = tb.diagnose(base, _measured(truth, HIGH, seed, heat_sigma))
        assert _named(d) == {"lubrication_factor_f0"}, d.verdict


def test_a_faster_falling_cavity_fraction_is_named_its_exponent(base):
    truth = base.with_setting(cavity_fraction_speed_exponent=0.8)
    for seed in range(3):
        d = tb.diagnose(base, _measured(truth, HIGH, seed))
        assert [a["name"] for a in d.accepted] == ["cavity_fraction_speed_exponent"], d.verdict
        assert d.accepted[0]["lower_95"] <= 0.8 <= d.accepted[0]["upper_95"]


def test_below_dn_half_a_million_drag_and_f0_cannot_be_told_apart(base):
    """The limit: at n d_m 0.2-0.5 million the drag is a few per cent of the
    heat and its n^2 shape is lost in the noise; the diagnosis says so (a
    tie that holds both) rather than picking one."""
    truth = base.with_setting(oil_flow_scale=2.0)
    for seed in range(2):
        d = tb.diagnose(base, _measured(truth, LOW, seed))
        assert {"oil_flow_scale", "lubrication_factor_f0"} <= set(d.tie), d.verdict
        assert not d.accepted


@pytest.mark.parametrize(
    "supply",
    [
        {"lubrication": "oil-bath"},
        {"lubrication": "jet", "oil_flow_cm3_per_min": 500.0},
        {"lubrication": "oil-air", "oil_volume_cm3_per_h": 5.0},
    ],
)
def test_the_bearing_spec_runs_thermal_states_own_drag(supply):
    """One implementation: the spec's heat and temperatures at a supply are
    those of ``thermal_state`` with the same keywords, to the last bit (an
    oil bath included: the SKF bath drag, not the fixed 10 % fraction)."""
    b = tb.Bearing.preset("6208")
    spec = D.BearingModelSpec(b, **supply)
    assert spec.options["churning_oil_fraction"] is None
    speeds = [4000.0, 8000.0]
    p = spec.predict(pl.DataFrame({"speed_rpm": speeds, "axial_n": 300.0, "radial_n": 200.0}))
    for i, n in enumerate(speeds):
        ts = tb.thermal_state(b, n, 300.0, 200.0, **supply)
        t = dict(zip(ts.temperatures["node"], ts.temperatures["temperature_c"], strict=True))
        assert p["heat_w"][i] == ts.total_heat_w
        assert p["outer_ring_temperature_c"][i] == t["outer_ring"]
        assert ts.raw["drag_heat_w"] > 0.0
    if supply["lubrication"] == "oil-bath":  # the fixed fraction stays the explicit override
        fixed = tb.thermal_state(b, 8000.0, 300.0, 200.0, churning_oil_fraction=0.1, **supply)
        assert fixed.raw["drag_heat_w"] > 10.0 * ts.raw["drag_heat_w"]
        over = D.BearingModelSpec(b, churning_oil_fraction=0.1, **supply)
        assert over.predict(
            pl.DataFrame({"speed_rpm": [8000.0], "axial_n": 300.0, "radial_n": 200.0})
        )["heat_w"][0] == pytest.approx(fixed.total_heat_w, rel=1e-12)


def test_the_spindle_spec_keeps_the_spindles_oil_supply():
    """A spindle given an oil-air supply (seed B: 5 mL/h) keeps it through
    its spec: the configured spindle's drag heat is the spindle's own, the
    supply's candidates are offered, and a fixed fraction given to the spec
    replaces the supply (one or the other, as ``Spindle.with_options``)."""
    sp = tb.Spindle.preset("seed-ceramic-spindle").with_options(oil_volume_cm3_per_h=5.0)
    spec = D.SpindleModelSpec.of_model(sp)
    assert spec.options["oil_volume_cm3_per_h"] == 5.0
    assert spec.options["churning_oil_fraction"] is None
    own = sp.thermal_state(12000.0).row(0, named=True)
    row = spec.configured(sp.preload_n).thermal_state(12000.0).row(0, named=True)
    assert own["bearing_drag_heat_w"] > 1.0  # the supply's drag, not the preset's zero
    assert row["bearing_drag_heat_w"] == own["bearing_drag_heat_w"]
    pred = spec.predict(pl.DataFrame({"speed_rpm": [12000.0], "preload_n": sp.preload_n}))
    assert pred["front_outer_ring_temperature_c"][0] == own["front_outer_ring_temperature_c"]
    rows = {r["name"]: r for r in tb.candidates(spec).iter_rows(named=True)}
    assert DRAG <= set(rows) and rows["oil_flow_scale"]["default"] == 1.0
    twice = spec.with_setting(oil_flow_scale=2.0).configured(sp.preload_n)
    assert twice.thermal_state(12000.0)["bearing_drag_heat_w"][0] > own["bearing_drag_heat_w"]
    dry = spec.with_setting(churning_oil_fraction=0.0).configured(sp.preload_n)
    assert dry.thermal_state(12000.0)["bearing_drag_heat_w"][0] == 0.0
    with pytest.raises(tb.ConfigError, match="churning_oil_fraction"):
        D.SpindleModelSpec(sp, churning_oil_fraction=0.01, oil_volume_cm3_per_h=5.0)
    # a spindle without a stated flow: no supply candidates
    bare = D.SpindleModelSpec.of_model(tb.Spindle.preset("seed-ceramic-spindle"))
    assert not DRAG & set(tb.candidates(bare)["name"])
