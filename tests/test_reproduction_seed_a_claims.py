"""Seed A's claims in words (papers/seed_a_claims.csv), the bearing inputs
they pin (papers/seed_a_bearing_model.json) and ours for every claim."""

from __future__ import annotations

import math

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear.diagnosis import bounds
from thermobear.glossary import GLOSSARY
from thermobear.studies import paper_numbers as pn
from thermobear.studies import reproduce_seed_a_thermal as fit_module
from thermobear.studies.seed_a_claim_values import tooth_pairs_in_mesh
from thermobear.studies.seed_a_thermal import seed_a_bearing_model


@pytest.fixture(scope="module")
def claims() -> pl.DataFrame:
    return pn.quotes("A", kind="claim")


@pytest.fixture(scope="module")
def model():
    return seed_a_bearing_model()


def _option_of(model) -> fit_module.BearingOption:
    bearing, options = model.model()
    return fit_module.BearingOption(
        bearing.ring_material.thermal_expansion_per_k,
        options["housing_material"],
        float(options["housing_conductance_scale"]),
    )


def _within(rows: pl.DataFrame, ours: dict) -> dict[str, bool]:
    """Each row met or not, by the reproduction table's own rule."""
    ev = pl.DataFrame(
        {"id": list(ours), "ours": list(ours.values()), "lower": [math.nan] * len(ours),
         "upper": [math.nan] * len(ours), "basis": [""] * len(ours)}
    )  # fmt: skip
    t = pn.number_table(rows, ev)
    return dict(zip(t["id"], t["within"], strict=True))


def test_the_claims_are_bounds_on_glossary_quantities(claims):
    assert claims.height == 44
    assert set(claims["quantity"]) <= set(GLOSSARY)
    assert set(claims["read"]) == {"text (in words)"}
    assert (claims["precision"] > 0).all()
    checked = claims.filter(pl.col("role") == "checked").height
    assert 3 * checked >= claims.height  # at least a third held out
    # Every figure in words has its rows; the gear's numbers are not here.
    assert set(claims["item"].str.extract(r"Fig\. (\d+)")) == {"6", "8", "10", "11", "13"}
    # Claim and number ids never collide (the table joins both kinds).
    assert pn.quotes("A", kind=None)["id"].n_unique() == pn.quotes("A", kind=None).height


def test_the_shipped_choice_is_the_argmax_of_the_fitted_claims(claims, model):
    """Recounted with the reproduction table's rule, no option meets more
    fitted claims than the shipped one, and redoing the choice gives it."""
    fitted = claims.filter(pl.col("role") == "fitted")
    rows = list(fitted.iter_rows(named=True))
    met = {}
    for o in fit_module.bearing_options():
        within = _within(fitted, fit_module.claim_values(fit_module.option_model(o), rows))
        met[o] = sum(within.values())
    chosen = _option_of(model)
    assert chosen in met and met[chosen] == max(met.values())
    again, _ = fit_module.choose_bearing(claims)
    assert again == chosen
    # The provenance names the fitted claims and the held-out ones.
    prov = model.provenance
    assert prov["data_sets"] == fitted["id"].to_list()
    assert prov["held_out"] == claims.filter(pl.col("role") == "checked")["id"].to_list()
    assert len(prov["options"]) == len(met)


def test_a_checked_claim_never_enters_the_choice(claims):
    option, scores = fit_module.choose_bearing(claims)
    # Move every checked bound far off: nothing of the choice changes.
    moved = claims.with_columns(
        pl.when(pl.col("role") == "checked")
        .then(pl.col("value") + 1e9)
        .otherwise(pl.col("value"))
        .alias("value")
    )
    option2, scores2 = fit_module.choose_bearing(moved)
    assert option2 == option
    assert [(s.label, s.met, s.shortfall_precisions) for s in scores2] == [
        (s.label, s.met, s.shortfall_precisions) for s in scores
    ]
    # A fitted bound moved the same way does change the scores.
    moved_fitted = claims.with_columns(
        pl.when(pl.col("id") == "A10b-close-6500")
        .then(pl.lit(1e9))
        .otherwise(pl.col("value"))
        .alias("value")
    )
    _, scores3 = fit_module.choose_bearing(moved_fitted)
    assert [s.met for s in scores3] != [s.met for s in scores]


def test_the_steel_readings_tie_and_the_papers_is_taken(claims, model):
    """1.36e-5 and 1.25e-5 1/K on the chosen housing meet the same fitted
    claims and miss the others within a reading precision of each other:
    the claims cannot tell them apart, so the paper's reading is taken."""
    _, scores = fit_module.choose_bearing(claims)
    chosen = _option_of(model)
    assert chosen.steel_expansion_per_k == pytest.approx(1.36e-5)
    group = {s.label for s in bounds.best_group(scores)}
    other = fit_module.BearingOption(1.25e-5, chosen.housing_material,
                                     chosen.housing_conductance_scale)  # fmt: skip
    assert {chosen.label, other.label} <= group


def test_ours_for_every_claim_and_the_counts(claims):
    ev = fit_module.evaluate(pn.quotes("A", kind=None), quick=True)
    assert set(ev["id"]) == set(claims["id"])  # the claims only, not the gear's numbers
    assert ev.columns == ["id", *pn.EVALUATION_COLUMNS]
    assert ev["lower"].is_nan().all() and ev["upper"].is_nan().all()
    full = fit_module.evaluate(claims, quick=False)
    both = full.join(ev, on="id", suffix="_quick")
    assert both.height == claims.height and (both["ours"] == both["ours_quick"]).all()
    table = pn.number_table(claims, ev)
    c = pn.counts(table, "A", kind="claim")
    assert (c["fitted"], c["checked"]) == ((23, 27), (16, 17))
    missed = set(table.filter(~pl.col("within"))["id"])
    # The ball is not the hottest node, the axial deformation does not grow
    # on a clearance that closes, and the no-thermal seed formula falls at
    # 100 N m (Fig. 11's restatement).
    assert missed == {"A08-ball-hottest-noload", "A08-ball-hottest-load", "A10a-thermal-grows",
                      "A10a-combined-grows", "A11-radial-rises"}  # fmt: skip


def test_the_shipped_model_carries_the_gear_systems_thermal_case(model):
    assert tb.CalibratedModel.from_json(model.to_json()) == model
    pair = tb.GearPair.preset("seed-electric-drive")
    system = tb.GearSystem(pair, bearings=model, stiffness="thermal")
    sched = system.stiffness_schedule
    grid = sched["speed_rpm"].to_numpy()
    one = tb.stiffness_curve(model, grid, 300.0 + 2380.9, 1189.9, mode="thermal")
    # Two bearings in parallel on each shaft.
    np.testing.assert_allclose(
        sched["support_radial_stiffness_n_per_m"].to_numpy(),
        2.0 * one["radial_stiffness_seed_n_per_m"].to_numpy(),
        rtol=1e-12,
    )
    # The cool cast-iron housing closes the clearance: stiffer radially
    # than the default aluminium housing at every speed of the sweep.
    default = tb.GearSystem(pair, stiffness="thermal").stiffness_schedule
    at = (grid >= 6500.0) & (grid <= 16500.0)
    assert np.all(
        sched["support_radial_stiffness_n_per_m"].to_numpy()[at]
        > default["support_radial_stiffness_n_per_m"].to_numpy()[at]
    )


def test_tooth_pairs_in_mesh_is_the_whole_part_of_the_contact_ratio():
    geo = tb.GearPair.preset("seed-electric-drive").geometry
    eps = geo["transverse_contact_ratio"] + geo["overlap_ratio"]
    assert tooth_pairs_in_mesh() == math.floor(eps)


def test_the_choice_by_bounds():
    c = [bounds.Claim("a", ">=", 0.0, 0.0, 0.5), bounds.Claim("b", "=", 1.0, 0.2, 0.05)]
    assert bounds.shortfall(c[0], -1.0) == 1.0 and bounds.shortfall(c[1], 1.1) == 0.0
    assert bounds.shortfall(c[1], 1.5) == pytest.approx(0.3)
    assert bounds.shortfall(c[0], math.nan) == math.inf
    s = [
        bounds.score_option("x", c, {"a": 1.0, "b": 2.0}),  # meets a
        bounds.score_option("y", c, {"a": 1.0, "b": 1.0}),  # meets both
        bounds.score_option("z", c, {"a": 2.0, "b": 1.1}),  # meets both
    ]
    # y and z meet the same claims and miss none: tied; preference decides.
    assert bounds.choose(s, ["z", "y", "x"]).label == "z"
    assert bounds.choose(s, ["x", "y", "z"]).label == "y"
    # Missing the same claim by amounts within a precision: still tied;
    # more than a precision apart: the smaller shortfall wins.
    near = [bounds.score_option("p", c[:1], {"a": -0.6}),
            bounds.score_option("q", c[:1], {"a": -0.3})]  # fmt: skip
    assert bounds.choose(near, ["p", "q"]).label == "p"
    far = [bounds.score_option("p", c[:1], {"a": -2.0}),
           bounds.score_option("q", c[:1], {"a": -0.3})]  # fmt: skip
    assert bounds.choose(far, ["p", "q"]).label == "q"
    with pytest.raises(tb.ConfigError, match="comparison"):
        bounds.Claim("c", "<", 0.0, 0.0, 1.0)
    with pytest.raises(tb.ConfigError, match="precision"):
        bounds.Claim("c", "<=", 0.0, 0.0, 0.0)
