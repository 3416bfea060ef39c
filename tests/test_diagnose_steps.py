"""Each step of ``thermobear.diagnose`` on its own, on constructed
inputs: a toy model spec (closed-form predictions, no solver) whose
ground truth is known, and hand-made residuals and screening rows."""

from __future__ import annotations

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear.diagnosis import NOT_IN_BEARING, Candidate, ModelSpec, sensor_offset_candidates
from thermobear.diagnosis.acceptance import accepted_record, select
from thermobear.diagnosis.audit import audit, gap_table
from thermobear.diagnosis.candidates import candidate_pool, split_evaluable
from thermobear.diagnosis.identifiability import identifiability
from thermobear.diagnosis.measurements import holdout_mask, prepare_measurements
from thermobear.diagnosis.protocol import check_spec
from thermobear.diagnosis.screening import candidate_curves, screen, screening_table
from thermobear.diagnosis.setting import _predict, _Setting
from thermobear.diagnosis.statistics import _chi2, noise_p_value
from thermobear.diagnosis.verdict import verdict_text

#: The toy's quantities (registry layout of thermobear.diagnosis.QUANTITIES).
Q = {
    "heat_w": ("heat_w", 1.0, (0.0, 1e5), 0.02, True),
    "inner_ring_temperature_c": ("ti", 1.0, (-60.0, 250.0), 0.5, False),
}


class Toy(ModelSpec):
    """Heat 50 + 40 n (+ extra heat) (+ drag 30 n^3), n = speed / 10^4 rpm;
    inner ring 30 C + 0.2 K/W x heat. ``twin_drag`` acts exactly like drag."""

    quantities = Q

    def __init__(self, effects=(), **options):
        self.effects = tuple(sorted(effects))
        self.options = {"extra_heat_w": 0.0, **options}
        self._cache = {}

    def with_setting(self, add_effects=(), **options):
        new = Toy(set(self.effects) | set(add_effects), **{**self.options, **options})
        new._cache = self._cache
        return new

    def predict(self, conditions):
        n = conditions["speed_rpm"].to_numpy() / 1e4
        heat = 50.0 + 40.0 * n + float(self.options["extra_heat_w"])
        if "drag" in self.effects:
            heat = heat + 30.0 * n**3
        if "twin_drag" in self.effects:
            heat = heat + 30.0 * n**3
        self._cache[self._key()] = True
        return {"heat_w": heat, "inner_ring_temperature_c": 30.0 + 0.2 * heat}

    def candidate_list(self, quantities=()):
        allq = tuple(Q)
        out = [
            Candidate("drag", "switch", "model", "drag_on", "1", 0.0, 1.0, 0.0, "ball drag",
                      allq, effect="drag"),
            Candidate("twin_drag", "switch", "model", "twin_drag_on", "1", 0.0, 1.0, 0.0,
                      "a look-alike of drag", allq, effect="twin_drag"),
            Candidate("extra_heat_w", "parameter", "model", "extra_heat_w", "W", 0.0, 100.0,
                      0.0, "extra heat", allq, option="extra_heat_w"),
        ]  # fmt: skip
        return out + sensor_offset_candidates(quantities, Q)


SPEEDS = np.linspace(6_000.0, 18_000.0, 9)


def measured(truth: Toy, noise: float = 0.0, seed: int = 1) -> pl.DataFrame:
    """The toy's truth at 9 speeds, heat and inner ring temperature, with
    the typical sigma and ``noise`` times that sigma of Gaussian noise."""
    cond = pl.DataFrame(
        {
            "speed_rpm": np.repeat(SPEEDS, 2),
            "axial_n": 300.0,
            "radial_n": 0.0,
            "quantity": ["heat_w", "inner_ring_temperature_c"] * len(SPEEDS),
        }
    )
    df = tb.diagnosis.synthetic_measurements(truth, cond, noise=1.0, seed=seed)
    if noise == 0.0:
        p = truth.predict(cond)
        exact = [p[q][i] for i, q in enumerate(cond["quantity"].to_list())]
        df = df.with_columns(pl.Series("value", exact))
    return df


def data_for(truth: Toy, holdout="highest_speeds", noise: float = 0.0):
    return prepare_measurements(measured(truth, noise), Q, holdout)


# -- step 0: measurements ---------------------------------------------------------


def test_prepare_measurements_splits_off_the_highest_speeds():
    d = data_for(Toy(["drag"]))
    held_speeds = sorted(set(d.df["speed_rpm"].to_numpy()[d.held].tolist()))
    assert held_speeds == [16_500.0, 18_000.0]  # a quarter of 9 speeds, rounded: 2
    assert d.n_train == 14 and (d.train == ~d.held).all()
    assert d.cond.columns == ["speed_rpm", "axial_n", "radial_n"]
    np.testing.assert_allclose(d.residual(d.y), 0.0)


def test_holdout_mask_by_run_and_its_errors():
    df = pl.DataFrame({"speed_rpm": [1.0, 2.0, 3.0, 4.0], "run": ["a", "a", "b", "b"]})
    assert holdout_mask(df, "b").tolist() == [False, False, True, True]
    assert not holdout_mask(df, None).any()
    with pytest.raises(tb.DataError, match="every point is held out"):
        holdout_mask(df, ["a", "b"])
    with pytest.raises(tb.DataError, match="runs in the data"):
        holdout_mask(df, "c")
    with pytest.raises(tb.ConfigError, match="fraction"):
        holdout_mask(df, 1.5)
    with pytest.raises(tb.ConfigError, match="invalid holdout = True"):
        holdout_mask(df, True)  # a bool is neither a fraction nor run labels


# -- candidates -------------------------------------------------------------------------


def test_candidate_pool_restricts_to_known_names():
    d = data_for(Toy())
    pool = candidate_pool(Toy(), d.quantity, None)
    assert {"drag", "extra_heat_w", "sensor_offset:heat_w"} <= {c.name for c in pool}
    assert [c.name for c in candidate_pool(Toy(), d.quantity, ["drag"])] == ["drag"]
    with pytest.raises(tb.ConfigError, match="invalid candidate = 'nope'"):
        candidate_pool(Toy(), d.quantity, ["nope"])


def test_split_evaluable_sets_aside_effects_outside_the_model():
    inside = Toy().candidate_list()[0]
    outside = Candidate(
        "rotor_thing", "switch", "model", "x", "1", 0.0, 1.0, 0.0, "", (NOT_IN_BEARING,)
    )
    pool, names = split_evaluable([inside, outside])
    assert pool == [inside] and names == ["rotor_thing"]


def test_check_spec_names_the_protocol():
    check_spec(Toy())
    with pytest.raises(tb.ConfigError, match="candidate_list, predict"):
        check_spec(object())


# -- step 1: audit ---------------------------------------------------------------------


def test_audit_flags_the_large_residual_block():
    df = pl.DataFrame(
        {
            "speed_rpm": np.tile(np.linspace(1_000.0, 9_000.0, 9), 2),
            "quantity": ["heat_w"] * 9 + ["inner_ring_temperature_c"] * 9,
        }
    )
    r = np.zeros(18)
    r[6:9] = 12.0  # heat, the highest third of the speeds
    table = audit(df, r)
    assert table.height == 6  # 2 quantities x 3 speed bands
    big = table.filter(pl.col("mean_residual_sigma").abs() > 1.0)
    assert big.select("quantity", "speed_band").rows() == [("heat_w", "6333-9000 rpm")]
    assert big["rms_residual_sigma"][0] == pytest.approx(12.0)
    shapes = dict(table.select("quantity", "shape").unique().rows())
    assert shapes["inner_ring_temperature_c"] == "none" and shapes["heat_w"] != "none"


def test_gap_table_reports_before_and_after_on_the_masked_rows():
    df = pl.DataFrame({"speed_rpm": [1.0, 2.0, 3.0, 4.0], "quantity": ["heat_w"] * 4})
    mask = np.array([False, False, True, True])
    g = gap_table(df, np.array([9.0, 9.0, 3.0, 4.0]), np.array([9.0, 9.0, 0.0, 0.0]), mask)
    assert g["n"].sum() == 2
    assert g["rms_after_sigma"].max() == 0.0
    assert g["rms_before_sigma"].max() == pytest.approx(np.sqrt((9.0 + 16.0) / 2.0))


# -- step 2: identifiability -----------------------------------------------------------


def test_identifiability_pairs_every_candidate_and_finds_the_look_alike():
    model, d = Toy(), data_for(Toy(["drag"]))
    pool = [c for c in candidate_pool(model, d.quantity, None) if c.side == "model"]
    curves, dropped, _ = candidate_curves(model, _Setting(), pool, d, dict(model.options))
    assert not dropped
    fp, la = identifiability(model, _Setting(), curves, d, dict(model.options), 0.95, True)
    assert fp.height == 3  # 3 candidates, 3 pairs
    assert la.select("a", "b").rows() == [("drag", "twin_drag")]
    assert la["cosine"][0] == pytest.approx(1.0)
    assert la["suggest_quantity"][0] in Q


def test_candidate_curves_drop_a_candidate_without_effect():
    class Deaf(Toy):
        def candidate_list(self, quantities=()):
            return [
                Candidate("deaf", "switch", "model", "deaf_on", "1", 0.0, 1.0, 0.0, "",
                          tuple(Q), effect="deaf")
            ]  # fmt: skip

    model, d = Deaf(), data_for(Toy())
    curves, dropped, notes = candidate_curves(
        model, _Setting(), model.candidate_list(), d, dict(model.options)
    )
    assert curves == {} and dropped == ["deaf"]
    assert notes == ["deaf: no effect on the measured quantities"]


# -- step 3: screening -----------------------------------------------------------------


def test_screening_ranks_the_injected_candidate_first():
    model, d = Toy(), data_for(Toy(["drag"]), noise=1.0)
    pool = [c for c in candidate_pool(model, d.quantity, None) if c.name != "twin_drag"]
    curves, _, _ = candidate_curves(model, _Setting(), pool, d, dict(model.options))
    r = d.residual(_predict(model, _Setting(), d.cond, d.quantity))
    rows, fits = screen(curves, d, _chi2(r[d.train]), _chi2(r[d.held]), 10.0)
    table = screening_table(rows, 0)
    assert table["candidate"][0] == "drag"
    assert table["passes"][0] and table["round"].to_list() == [1] * table.height
    assert table["delta_bic"].to_list() == sorted(table["delta_bic"].to_list(), reverse=True)
    assert set(fits) == {row["candidate"] for row in rows}
    # the calibrated extra heat absorbs part of the drag but stays behind it
    extra = table.filter(pl.col("candidate") == "extra_heat_w")
    assert extra["delta_bic"][0] < table["delta_bic"][0]


def test_screening_calibrates_an_injected_parameter():
    model, d = Toy(), data_for(Toy(extra_heat_w=40.0))
    pool = [c for c in candidate_pool(model, d.quantity, ["extra_heat_w"])]
    curves, _, _ = candidate_curves(model, _Setting(), pool, d, dict(model.options))
    r = d.residual(_predict(model, _Setting(), d.cond, d.quantity))
    rows, _ = screen(curves, d, _chi2(r[d.train]), _chi2(r[d.held]), 10.0)
    (row,) = rows
    assert row["value"] == pytest.approx(40.0, abs=1e-3)
    assert row["lower_95"] < 40.0 < row["upper_95"] and row["passes"]


def test_screening_table_of_an_empty_round_is_empty():
    assert screening_table([], 2).height == 0


# -- step 4: acceptance ------------------------------------------------------------------


def _row(name, dbic, passes=True):
    return {"candidate": name, "delta_bic": dbic, "passes": passes}


def test_select_takes_the_best_passing_row():
    best, rivals = select([_row("a", 20.0), _row("b", 35.0), _row("c", 10.0, False)], 2.0)
    assert best["candidate"] == "b" and rivals == []
    # a row that fails the other rules but scores higher still makes a tie
    best, rivals = select([_row("b", 35.0), _row("c", 50.0, False)], 2.0)
    assert best["candidate"] == "b" and rivals == ["c"]


def test_select_reports_rivals_within_the_tie_margin_passing_or_not():
    rows = [_row("a", 30.0), _row("b", 29.0, False), _row("c", 27.0)]
    best, rivals = select(rows, 2.0)
    assert best["candidate"] == "a" and rivals == ["b"]


def test_select_without_a_passing_row():
    assert select([_row("a", 30.0, False)], 2.0) == (None, [])
    assert select([], 2.0) == (None, [])


def test_accepted_record_carries_the_candidate_and_its_fit():
    c = Toy().candidate_list()[2]
    best = {"value": 40.0, "lower_95": 38.0, "upper_95": 42.0, "delta_bic": 99.0}
    a = accepted_record(c, best, 0)
    assert a["name"] == "extra_heat_w" and a["round"] == 1 and a["role"] == "effect"
    assert (a["value"], a["lower_95"], a["upper_95"]) == (40.0, 38.0, 42.0)


# -- step 5: verdict ----------------------------------------------------------------------


def test_verdict_names_each_accepted_candidate_by_role():
    effect = {"name": "drag", "role": "effect", "unit": "1", "lower_95": None, "value": 1.0}
    cal = {
        "name": "f0", "role": "calibration", "unit": "1", "parameter": "lubrication_factor_f0",
        "value": 2.0, "lower_95": 1.8, "upper_95": 2.2, "null": 1.0,
    }  # fmt: skip
    sensor = {
        "name": "sensor_offset:heat_w", "role": "measurement", "unit": "W", "value": 3.0,
        "lower_95": 2.0, "upper_95": 4.0,
    }  # fmt: skip
    text = verdict_text([effect, cal, sensor], [], 0.5)
    assert text.startswith("missing effect drag; ")
    assert "; miscalibrated baseline parameter f0: lubrication_factor_f0 = 2 (baseline 1; " in text
    assert text.endswith("; measurement-side sensor_offset:heat_w = 3 W (95 % [2, 4])")


def test_verdict_without_accepted_candidates():
    assert verdict_text([], ["a", "b"], 0.5) == "tie: a | b (the data cannot tell them apart)"
    assert verdict_text([], [], 1e-4) == "structured residual not explained by any known effect"
    assert verdict_text([], [], 0.3) == "no missing effect supported"


def test_noise_p_value_is_the_chi2_tail():
    assert noise_p_value(0.0, 5) == pytest.approx(1.0)
    assert noise_p_value(5.0, 5) == pytest.approx(0.4159, abs=1e-4)
    assert noise_p_value(100.0, 5) < 1e-15


# -- the sequence ----------------------------------------------------------------------------


def test_diagnose_runs_the_steps_on_any_spec():
    d = tb.diagnose(Toy(), measured(Toy(["drag"]), noise=1.0), ["drag", "extra_heat_w"])
    assert d.verdict == "missing effect drag"
    assert [a["name"] for a in d.accepted] == ["drag"]
    assert d.screening[0]["candidate"][0] == "drag"
    assert d.gap["rms_after_sigma"].max() < d.gap["rms_before_sigma"].min()


def test_diagnose_reports_a_tie_between_look_alikes():
    d = tb.diagnose(Toy(), measured(Toy(["drag"])), ["drag", "twin_drag"], suggest=False)
    assert set(d.tie) == {"drag", "twin_drag"} and d.accepted == []
    assert d.verdict.startswith("tie: ")


def test_diagnose_finds_nothing_in_noise():
    d = tb.diagnose(Toy(), measured(Toy(), noise=1.0, seed=3), suggest=False)
    assert d.verdict == "no missing effect supported" and d.accepted == []
