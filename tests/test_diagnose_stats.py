"""The statistics of ``thermobear.diagnose`` (calibration, model selection, hold-out, ties) on
the closed-form rig of ``diagnose_toy``: cross-validation and information
criteria, the generic control, the outlier audit, profile intervals, ties,
joint calibration. Each statistic is checked against an independent
computation (brute force, a textbook formula) or a known truth."""

from __future__ import annotations

import dataclasses

import numpy as np
import polars as pl
import pytest
from diagnose_toy import Q, Rig, conditions, measured

import thermobear as tb
from thermobear.diagnosis.acceptance import select
from thermobear.diagnosis.candidates import candidate_pool
from thermobear.diagnosis.control import generic_control
from thermobear.diagnosis.identifiability import envelope_grid
from thermobear.diagnosis.measurements import MAX_FOLDS, cv_folds, prepare_measurements
from thermobear.diagnosis.outliers import flag_outliers, loo_deviation
from thermobear.diagnosis.screening import aicc_penalty, candidate_curves, cv_chi2, screen
from thermobear.diagnosis.setting import _predict, _Setting
from thermobear.diagnosis.statistics import _chi2, fisher_identifiability

SPEEDS = np.linspace(4000.0, 16000.0, 6)
BASE = Rig(["centrifugal"])


def _data(truth, seed=1, holdout="highest_speeds", **kw):
    cond = conditions(SPEEDS, **kw)
    return prepare_measurements(measured(truth, cond, seed), Q, holdout)


def _screen(truth, names, seed=1):
    d = _data(truth, seed)
    pool = candidate_pool(BASE, d.quantity, names)
    curves, _, _ = candidate_curves(BASE, _Setting(), pool, d, dict(BASE.options))
    r = d.residual(_predict(BASE, _Setting(), d.cond, d.quantity))
    rows, fits = screen(curves, d, _chi2(r), _chi2(r[d.held]), 10.0)
    return d, curves, {row["candidate"]: row for row in rows}, fits


# -- item 2: cross-validation and information criteria ----------------------------


def test_folds_hold_out_whole_operating_cells():
    cond = conditions(SPEEDS, loads=(300.0, 800.0), runs=("a", "b"))
    df = measured(BASE, cond, 0).with_columns(pl.col("axial_n").alias("axial_n"))
    folds = cv_folds(df)
    cells = df.select("speed_rpm", "axial_n", "run").with_columns(pl.Series("f", folds))
    # every quantity of a cell shares its fold; 24 cells > MAX_FOLDS: interleaved
    assert cells.group_by("speed_rpm", "axial_n", "run").agg(pl.col("f").n_unique())["f"].max() == 1
    assert len(set(folds.tolist())) == MAX_FOLDS
    small = measured(BASE, conditions(SPEEDS), 0)
    assert sorted(set(cv_folds(small).tolist())) == list(range(len(SPEEDS)))


def test_cv_chi2_equals_brute_force_refits():
    truth = BASE.with_setting(extra_heat_w=4.0)
    d, curves, _, _ = _screen(truth, ["extra_heat_w"])
    cu = curves["extra_heat_w"]
    grid = np.linspace(cu.values.min(), cu.values.max(), 601)
    brute = 0.0
    for f in np.unique(d.folds):
        test = d.folds == f
        chi = [_chi2(((d.y - cu.at(np.array([v]))[0]) / d.s)[~test]) for v in grid]
        v = grid[int(np.argmin(chi))]
        brute += _chi2(((d.y - cu.at(np.array([v]))[0]) / d.s)[test])
    total, tested = cv_chi2(cu, d.y, d.s, d.folds)
    assert total == pytest.approx(brute, rel=1e-9) and tested == len(np.unique(d.folds))


def test_information_criteria_on_all_points():
    truth = BASE.with_setting(extra_heat_w=4.0)
    d, _, rows, _ = _screen(truth, ["extra_heat_w"])
    row = rows["extra_heat_w"]
    chi_base = row["cv_chi2_before"]  # the setting has nothing to refit: its chi^2
    assert row["delta_bic"] == pytest.approx(chi_base - row["chi2"] - np.log(d.n))
    assert row["delta_aicc"] == pytest.approx(chi_base - row["chi2"] - 2.0 - 4.0 / (d.n - 2))
    # AICc of k parameters on n points: 2k + 2k(k+1)/(n-k-1) (Hurvich & Tsai 1989)
    assert aicc_penalty(2, 10) == pytest.approx(4.0 + 12.0 / 7.0)
    assert aicc_penalty(3, 4) == np.inf


def test_speed_growing_effect_found_although_the_top_speeds_hide_most_of_it():
    """A drag ~ n^3 worth 5 sigma on heat at the top speed, below 2 sigma
    on the training speeds of the extrapolation check: calibrated on all
    points and cross-validated, it is named; the extrapolation check is
    reported apart."""
    truth = BASE.with_setting(drag_coefficient=0.05)
    named = 0
    for seed in range(20):
        d = tb.diagnose(BASE, measured(truth, conditions(SPEEDS), seed), suggest=False)
        named += [a["name"] for a in d.accepted + d.unresolved] == ["drag_coefficient"]
        named += "drag_coefficient" in d.tie  # f0 ~ n^(2/3) is a partial look-alike
        row = d.screening[0].filter(pl.col("candidate") == "drag_coefficient")
        assert row["heldout_chi2_after"][0] >= 0.0  # the extrapolation check, reported
        assert not d.accepted or d.accepted[0]["name"] == "drag_coefficient"
    assert named >= 18


# -- item 3: the generic control ----------------------------------------------------


def test_generic_control_fits_a_smooth_unknown_term_exactly():
    d = _data(BASE)
    pred = _predict(BASE, _Setting(), d.cond, d.quantity)
    x = d.cond["speed_rpm"].to_numpy() / SPEEDS.max()
    hot = d.quantity == "outer_ring_temperature_c"
    term = np.where(hot, 3.0 * x + 2.0 * x**2, 0.0)
    exact = dataclasses.replace(d, y=pred + term)  # the term and no noise
    ctrl = generic_control(exact, pred)
    assert ctrl.quantities == ("outer_ring_temperature_c",) and ctrl.n_parameters == 2
    np.testing.assert_allclose(ctrl.shift, term, atol=1e-9)
    assert ctrl.chi2 == pytest.approx(0.0, abs=1e-12)


def test_unknown_effect_is_not_named_as_a_known_one():
    """A heat source ~ n^1.5 that no candidate models, on heat only (e.g.
    a seal): no named candidate, the verdict says the data cannot tell a
    known from an unknown effect, or that the residual is unexplained."""

    def seal(df):
        n = df["speed_rpm"] / 1e4
        on = pl.col("quantity") == "heat_w"
        return df.with_columns(
            pl.when(on).then(pl.col("value") * (1.0 + 0.08 * n**1.5)).otherwise(pl.col("value"))
        )

    named = 0
    for seed in range(20):
        m = seal(measured(BASE, conditions(SPEEDS), seed))
        d = tb.diagnose(BASE, m, suggest=False)
        named += bool(d.accepted)
        assert d.verdict.startswith(("unresolved", "structured residual", "tie")), d.verdict
    assert named == 0


def test_named_effect_against_the_controls():
    """f0 off by 15 %: against the per-quantity control alone (no carrier
    among the candidates) f0 is named -- one value for four quantities
    beats two per quantity; with the extra-heat carrier (a heat source with
    a free quadratic speed law) the data may not tell f0's own law from it
    over 4000-16000 rpm -- the noiseless truth lies within 0.7 sigma of the
    carrier's best fit (chi^2 0.43 over 24 points), so no noise realisation
    can: then the verdict is "unresolved" (f0 listed), never another name."""
    truth = BASE.with_setting(lubrication_factor_f0=1.15)
    no_carrier = ["lubrication_factor_f0", "drag_coefficient", "ambient_temperature_offset_k"]
    named = unresolved = 0
    for s in range(20):
        m = measured(truth, conditions(SPEEDS), s)
        d = tb.diagnose(BASE, m, no_carrier, suggest=False)
        named += [a["name"] for a in d.accepted] == ["lubrication_factor_f0"]
        d = tb.diagnose(BASE, m, suggest=False)
        assert [a["name"] for a in d.accepted + d.unresolved] == ["lubrication_factor_f0"] or (
            "lubrication_factor_f0" in d.tie
        ), d.verdict
        unresolved += bool(d.unresolved)
    assert named >= 18 and unresolved >= 1


# -- item 4: outliers ---------------------------------------------------------------


def test_loo_deviation_is_the_leave_one_out_line_residual():
    rng = np.random.default_rng(4)
    x = np.linspace(0.0, 1.0, 7)
    r = 2.0 + x + rng.normal(size=7)
    t = loo_deviation(x, r)
    for i in range(7):
        keep = np.arange(7) != i
        c = np.polyfit(x[keep], r[keep], 1)
        a = np.vander(x[keep], 2)
        xi = np.vander(x[i : i + 1], 2)
        var = 1.0 + (xi @ np.linalg.inv(a.T @ a) @ xi.T)[0, 0]  # prediction variance + noise
        assert t[i] == pytest.approx((r[i] - np.polyval(c, x[i])) / np.sqrt(var))


def test_a_16_sigma_outlier_is_reported_and_left_out():
    cond = conditions(SPEEDS)
    m = measured(BASE, cond, 5)
    i = int(np.flatnonzero((cond["quantity"] == "inner_ring_temperature_c").to_numpy())[3])
    m = m.with_columns(pl.Series("value", m["value"].to_numpy() + 16.0 * np.eye(m.height)[i] * 0.5))
    d = tb.diagnose(BASE, m, suggest=False)
    assert d.verdict.startswith("no missing effect supported; 1 outlier left out: ")
    assert "inner_ring_temperature_c at 11200 rpm" in d.verdict
    assert d.outliers.height == 1 and d.outliers["robust_z"][0] > 5.0
    assert d.points["outlier"].sum() == 1 and d.points["outlier"][i]


def test_outlier_beside_a_real_effect_and_no_false_flags_in_noise():
    truth = BASE.with_setting(extra_heat_w=5.0)
    cond = conditions(SPEEDS)
    flagged = 0
    for seed in range(100):
        d = prepare_measurements(measured(BASE, cond, seed), Q, None)
        flagged += flag_outliers(d.df, d.residual(_predict(BASE, _Setting(), d.cond, d.quantity)))[
            0
        ].any()
    assert flagged <= 2  # the rule is at 5 robust sigma: none expected
    m = measured(truth, cond, 3)
    m = m.with_columns(pl.Series("value", m["value"].to_numpy() + 8.0 * np.eye(m.height)[2]))
    d = tb.diagnose(BASE, m, suggest=False)
    assert [a["name"] for a in d.accepted] == ["extra_heat_w"] and d.outliers.height == 1


def test_a_steep_smooth_rise_is_not_an_outlier():
    # a strong n^3 term left unexplained: the top point is far from a
    # straight line but not alone -- its neighbours rise too
    cond = conditions(SPEEDS, quantities=("heat_w",))
    d = prepare_measurements(measured(BASE.with_setting(drag_coefficient=2.0), cond, 1), Q, None)
    r = d.residual(_predict(BASE, _Setting(), d.cond, d.quantity))
    assert r.max() > 30.0 and not flag_outliers(d.df, r)[0].any()


# -- item 5: intervals ----------------------------------------------------------------


@pytest.mark.parametrize("sigma_scale", [1.0, 0.5])
def test_profile_intervals_cover_the_truth(sigma_scale):
    """95 % profile intervals of a thermocouple offset and of f0 cover the
    truth in >= 90 % of 60 seeds -- also when the stated sigma is half the
    true noise (the interval widens with the reduced chi^2)."""
    cond = conditions(SPEEDS, loads=(300.0, 800.0))
    cases = [
        (BASE.with_setting(lubrication_factor_f0=1.2), "lubrication_factor_f0", 1.2),
        (BASE.with_setting(ambient_temperature_c=27.0), "ambient_temperature_offset_k", 2.0),
    ]
    for truth, name, value in cases:
        covered = 0
        for seed in range(60):
            m = measured(truth, cond, 700 + seed, sigma_scale=sigma_scale)
            d = tb.diagnose(BASE, m, [name], suggest=False, control=False)
            a = d.accepted[0]
            covered += a["lower_95"] <= value <= a["upper_95"]
        assert covered >= 54, (name, covered)


# -- item 6: ties ----------------------------------------------------------------------


def _row(name, dbic, passes=True, at_bound=False):
    return {"candidate": name, "delta_bic": dbic, "passes": passes, "at_bound": at_bound}


def test_a_rival_at_its_bound_makes_no_tie():
    best, rivals = select([_row("a", 30.0), _row("b", 29.5, at_bound=True)], 2.0)
    assert best["candidate"] == "a" and rivals == []
    best, rivals = select([_row("a", 30.0), _row("b", 29.5)], 2.0)
    assert rivals == ["b"]


def test_each_tie_member_reports_its_value_interval_and_gap():
    # extra heat and an ambient offset move Ti alike (a constant shift)
    cond = conditions(SPEEDS, quantities=("inner_ring_temperature_c",))
    m = measured(BASE.with_setting(extra_heat_w=10.0), cond, 2)
    d = tb.diagnose(BASE, m, ["extra_heat_w", "ambient_temperature_offset_k"])
    assert set(d.tie) == {"extra_heat_w", "ambient_temperature_offset_k"}
    t = d.ties
    assert t["candidate"].to_list()[0] == d.tie[0] and t.height == 2
    assert (t["lower_95"] <= t["value"]).all() and (t["value"] <= t["upper_95"]).all()
    assert (t["rms_after_sigma"] < 0.5 * t["rms_before_sigma"]).all()  # each closes the gap
    assert (t["p_noise"] > 0.01).all()
    assert set(d.tie_gap["candidate"]) == set(d.tie)
    heat = t.filter(pl.col("candidate") == "extra_heat_w")
    assert heat["lower_95"][0] < 10.0 < heat["upper_95"][0]
    # the separating measurement lies inside the measured envelope
    sep = t.filter(pl.col("separate_quantity") != "")
    assert sep.height == 1 and sep["separate_quantity"][0] in Q
    assert SPEEDS.min() <= sep["separate_speed_rpm"][0] <= SPEEDS.max()
    assert "tie member extra_heat_w" in d.summary()


def test_envelope_grid_stays_in_the_declared_range():
    df = measured(BASE, conditions(SPEEDS, loads=(300.0, 800.0)), 0)
    g = envelope_grid(df)
    assert g["speed_rpm"].min() == SPEEDS.min() and g["speed_rpm"].max() == SPEEDS.max()
    assert sorted(set(g["axial_n"].to_list())) == [300.0, 800.0]
    g = envelope_grid(df, {"speed_rpm": (1000.0, 20000.0), "axial_n": (100.0, 900.0)})
    assert g["speed_rpm"].max() == 20000.0 and sorted(set(g["axial_n"])) == [100.0, 900.0]


# -- item 7: joint calibration ------------------------------------------------------------


def _two_rigs(seed, f0=1.3, offset_b=1.0):
    rig_a, rig_b = BASE, Rig(["centrifugal"], ambient_temperature_c=20.0)
    cond = conditions(SPEEDS[::2], loads=(300.0, 800.0))
    ma = measured(rig_a.with_setting(lubrication_factor_f0=f0), cond, seed)
    mb = measured(rig_b.with_setting(lubrication_factor_f0=f0), cond, 1000 + seed)
    to = pl.col("quantity") == "outer_ring_temperature_c"
    mb = mb.with_columns(pl.when(to).then(pl.col("value") + offset_b).otherwise(pl.col("value")))
    return {"A": (rig_a, ma), "B": (rig_b, mb)}


def test_joint_calibration_shared_and_per_set_parameters():
    c = tb.calibrate(
        _two_rigs(0),
        ["lubrication_factor_f0", "sensor_offset:outer_ring_temperature_c"],
        per_set=["sensor_offset:outer_ring_temperature_c"],
    )
    p = c.parameters
    assert p.select("name", "set").rows() == [
        ("lubrication_factor_f0", "all"),
        ("sensor_offset:outer_ring_temperature_c", "A"),
        ("sensor_offset:outer_ring_temperature_c", "B"),
    ]
    truth = [1.3, 0.0, 1.0]
    assert all(lo <= t <= hi for lo, t, hi in zip(p["lower_95"], truth, p["upper_95"], strict=True))
    assert p["identified"].all() and not c.not_identified and c.condition_number < 1e3
    assert c.chi2 < c.chi2_before and c.points["set"].unique().sort().to_list() == ["A", "B"]


def test_joint_calibration_coverage_over_seeds():
    covered = 0
    for seed in range(40):
        c = tb.calibrate(_two_rigs(seed, offset_b=0.0), ["lubrication_factor_f0"])
        covered += c.parameters["lower_95"][0] <= 1.3 <= c.parameters["upper_95"][0]
    assert covered >= 36


def test_joint_calibration_says_what_the_data_do_not_identify():
    # on Ti alone, extra heat (0.25 K/W) and an ambient offset move it alike
    cond = conditions(SPEEDS, quantities=("inner_ring_temperature_c",))
    m = measured(BASE.with_setting(extra_heat_w=5.0), cond, 1)
    c = tb.calibrate([(BASE, m)], ["extra_heat_w", "ambient_temperature_offset_k"])
    assert set(c.not_identified) == {"extra_heat_w@0", "ambient_temperature_offset_k@0"} or set(
        c.not_identified
    ) == {"extra_heat_w@all", "ambient_temperature_offset_k@all"}
    assert not c.parameters["identified"].any() and c.condition_number > 1e6
    assert "not identified" in c.notes[0]


def test_joint_calibration_checks_its_input():
    m = measured(BASE, conditions(SPEEDS), 0)
    with pytest.raises(tb.ConfigError, match="1 to 4"):
        tb.calibrate([(BASE, m)], ["extra_heat_w", "drag_coefficient", "a", "b", "c"])
    with pytest.raises(tb.ConfigError, match="not a calibratable"):
        tb.calibrate([(BASE, m)], ["centrifugal"])
    with pytest.raises(tb.ConfigError, match="per_set"):
        tb.calibrate([(BASE, m)], ["extra_heat_w"], per_set=["drag_coefficient"])
    with pytest.raises(tb.ConfigError, match="model, measured"):
        tb.calibrate([BASE], ["extra_heat_w"])


def test_fisher_identifiability_finds_the_blind_combination():
    rng = np.random.default_rng(0)
    a = rng.normal(size=(30, 1))
    ortho = np.column_stack([np.arange(30) < 15, np.arange(30) >= 15]).astype(float)
    cond, weak = fisher_identifiability(ortho, np.array([1.0, 5.0]))  # disjoint rows
    assert cond == pytest.approx(1.0) and weak == set()
    # the third parameter moves the residual exactly as twice the first
    jac = np.column_stack([a[:, 0], rng.normal(size=30), 2.0 * a[:, 0]])
    cond, weak = fisher_identifiability(jac, np.array([1.0, 1.0, 3.0]))
    assert cond > 1e6 and weak == {0, 2}
    cond, weak = fisher_identifiability(np.column_stack([a[:, 0], np.zeros(30)]), np.ones(2))
    assert weak == {1}


def test_without_a_sigma_column_the_intervals_stretch_with_the_scatter():
    """No sigma given: the typical sigma is assumed and a note says so;
    data twice as noisy give intervals about twice as wide (phi)."""
    cond = conditions(SPEEDS, loads=(300.0, 800.0))
    truth = BASE.with_setting(lubrication_factor_f0=1.2)
    widths = []
    for noise in (1.0, 2.0):
        m = measured(truth, cond, 3, noise=noise).drop("sigma")
        d = tb.diagnose(BASE, m, ["lubrication_factor_f0"], suggest=False, control=False)
        assert any("no sigma column" in n for n in d.notes)
        a = d.accepted[0]
        assert a["lower_95"] <= 1.2 <= a["upper_95"]
        widths.append(a["upper_95"] - a["lower_95"])
    assert 1.5 < widths[1] / widths[0] < 2.6


def test_in_diagnosis_joint_refit_gives_the_profile_intervals_of_calibrate():
    """Two effects accepted in one diagnosis (a lubrication factor 30 % high
    and a +1.5 K outer-ring thermocouple offset on a hybrid 6208) are
    re-calibrated together; their values and 95 % intervals are those of
    ``thermobear.calibrate`` on the same points (profile likelihood,
    the other parameter re-fitted at each trial value), and cover the truth."""
    from thermobear import diagnosis as D

    qs = ["outer_ring_temperature_c", "inner_ring_temperature_c", "heat_w"]
    sp = np.linspace(2000.0, 12000.0, 6)
    cond = pl.DataFrame(
        {"speed_rpm": np.repeat(sp, len(qs)), "axial_n": 0.0, "radial_n": 2000.0,
         "quantity": qs * len(sp)}
    )  # fmt: skip
    spec = D.BearingModelSpec(tb.Bearing.preset("6208-hybrid"))
    to = (cond["quantity"] == "outer_ring_temperature_c").to_numpy()
    meas = D.synthetic_measurements(spec.with_setting(lubrication_factor_f0=1.3), cond, 1.0, 3)
    meas = meas.with_columns(pl.col("value") + pl.Series(np.where(to, 1.5, 0.0)))
    d = tb.diagnose(spec, meas, holdout=None, suggest=False)
    names = [a["name"] for a in d.accepted]
    assert sorted(names) == ["lubrication_factor_f0", "sensor_offset:outer_ring_temperature_c"]
    assert all(a["joint"] for a in d.accepted)
    c = tb.calibrate([(spec, meas)], names).parameters
    truth = {"lubrication_factor_f0": 1.3, "sensor_offset:outer_ring_temperature_c": 1.5}
    for a in d.accepted:
        row = c.filter(pl.col("name") == a["name"]).row(0, named=True)
        width = row["upper_95"] - row["lower_95"]
        assert abs(a["value"] - row["value"]) < 0.01 * width
        assert abs(a["lower_95"] - row["lower_95"]) < 0.02 * width
        assert abs(a["upper_95"] - row["upper_95"]) < 0.02 * width
        assert a["lower_95"] <= truth[a["name"]] <= a["upper_95"]
