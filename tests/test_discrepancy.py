"""The unknown smooth term of an "unresolved" verdict as a model-discrepancy
term (``thermobear.diagnosis.discrepancy``): the Gaussian process's closed
forms, its band narrow at the measured speeds and widening away from them,
covering the truth beyond the measured range, through ``tb.predict`` and
``tb.separating_measurement``, and kept to the last bit by save, load and
pickle."""

from __future__ import annotations

import pickle

import numpy as np
import polars as pl
import pytest
from diagnose_toy import Rig, conditions, measured
from scipy.stats import multivariate_normal

import thermobear as tb
from thermobear.diagnosis.calibrated import CalibratedModel, _Step
from thermobear.diagnosis.discrepancy import (
    Hyperparameters,
    discrepancy_at,
    fit_discrepancy,
    fit_hyperparameters,
    hyperparameter_bounds,
    kernel_matrix,
    log_marginal_likelihood,
    posterior,
)

TO = "outer_ring_temperature_c"
SPEEDS = [2000.0, 4000.0, 6000.0, 8000.0, 10000.0, 12000.0, 14000.0, 16000.0]
KERNELS = ["matern52", "squared_exponential"]
Z95 = 1.959963984540054
X = np.array([0.1, 0.25, 0.4, 0.55, 0.7, 0.85, 1.0])


# -- the Gaussian process's closed forms ----------------------------------------------


def test_the_kernels_at_one_length_scale():
    hp = Hyperparameters(2.0, 0.5)
    se = kernel_matrix([0.0], [0.5], hp, "squared_exponential")[0, 0]
    m52 = kernel_matrix([0.0], [0.5], hp, "matern52")[0, 0]
    assert se == pytest.approx(4.0 * np.exp(-0.5))
    assert m52 == pytest.approx(4.0 * (1.0 + np.sqrt(5.0) + 5.0 / 3.0) * np.exp(-np.sqrt(5.0)))
    # the speed power scales the prior standard deviation: a (x x')^p
    k = kernel_matrix([0.5], [0.5], Hyperparameters(2.0, 0.5, 1.5), "matern52")[0, 0]
    assert k == pytest.approx(4.0 * 0.5**3)
    with pytest.raises(tb.ConfigError, match="kernel"):
        kernel_matrix([0.0], [1.0], hp, "cubic")  # type: ignore[arg-type]


@pytest.mark.parametrize("kernel", KERNELS)
def test_posterior_interpolates_noise_free_data(kernel):
    r = np.sin(3.0 * X) + X
    hp = Hyperparameters(1.5, 0.3, 1.0)
    mean, var = posterior(X, r, np.full(X.size, 1e-6), hp, X, kernel)
    np.testing.assert_allclose(mean, r, atol=1e-5)
    assert np.all(var < 1e-8)
    # between the points the term is uncertain, though less than a priori
    mid = 0.5 * (X[:-1] + X[1:])
    hp = Hyperparameters(1.5, 0.1, 1.0)
    _, vmid = posterior(X, r, np.full(X.size, 1e-6), hp, mid, kernel)
    prior = kernel_matrix(mid, mid, hp, kernel).diagonal()
    assert np.all(vmid > 1e-6) and np.all(vmid < prior)


@pytest.mark.parametrize("kernel", KERNELS)
def test_far_from_the_data_the_posterior_is_the_prior(kernel):
    r = np.cos(2.0 * X)
    for p in (0.0, 1.0):
        hp = Hyperparameters(0.8, 0.2, p)
        far = np.array([20.0, 50.0])
        mean, var = posterior(X, r, np.full(X.size, 0.05), hp, far, kernel)
        np.testing.assert_allclose(mean, 0.0, atol=1e-12)
        np.testing.assert_allclose(var, 0.64 * far ** (2 * p), rtol=1e-12)


def test_the_posterior_and_likelihood_agree_with_the_textbook_forms():
    """A single point: mean k(x*, x0) r0 / (k00 + s^2), variance k** -
    k(x*, x0)^2 / (k00 + s^2); the log marginal likelihood is the normal
    log density of the residuals with covariance K + diag(s^2)."""
    hp = Hyperparameters(1.2, 0.4, 0.5)
    k0s = kernel_matrix([0.5], [0.8], hp)[0, 0]
    k00 = kernel_matrix([0.5], [0.5], hp)[0, 0]
    kss = kernel_matrix([0.8], [0.8], hp)[0, 0]
    mean, var = posterior([0.5], [0.7], [0.3], hp, [0.8])
    assert mean[0] == pytest.approx(k0s * 0.7 / (k00 + 0.09))
    assert var[0] == pytest.approx(kss - k0s**2 / (k00 + 0.09))
    r, s = np.sin(5.0 * X), np.linspace(0.1, 0.3, X.size)
    cov = kernel_matrix(X, X, hp) + np.diag(s * s)
    lml = log_marginal_likelihood(X, r, s, hp)
    assert lml == pytest.approx(multivariate_normal(np.zeros(X.size), cov).logpdf(r))


def test_the_fitted_hyperparameters_maximise_the_likelihood_within_bounds():
    rng = np.random.default_rng(3)
    x = np.repeat(np.linspace(0.1, 1.0, 12), 2)
    true = Hyperparameters(2.0, 0.3, 1.0)
    s = np.full(x.size, 0.1)
    r = rng.multivariate_normal(np.zeros(x.size), kernel_matrix(x, x, true) + np.diag(s * s))
    hp, lml = fit_hyperparameters(x, r, s)
    assert lml == pytest.approx(log_marginal_likelihood(x, r, s, hp))
    bounds = hyperparameter_bounds(x, r, s)
    assert bounds[0][0] <= hp.amplitude <= bounds[0][1]
    assert bounds[1][0] <= hp.length_scale <= bounds[1][1]
    assert bounds[2][0] <= hp.speed_power <= bounds[2][1]
    for fa, fl, dp in ((1.3, 1.0, 0.0), (0.7, 1.0, 0.0), (1.0, 1.3, 0.0), (1.0, 0.7, 0.0),
                       (1.0, 1.0, 0.3), (1.0, 1.0, -0.3)):  # fmt: skip
        other = Hyperparameters(hp.amplitude * fa, hp.length_scale * fl, hp.speed_power + dp)
        if not (bounds[1][0] <= other.length_scale <= bounds[1][1]):
            continue
        if not (bounds[2][0] <= other.speed_power <= bounds[2][1]):
            continue
        assert log_marginal_likelihood(x, r, s, other) <= lml + 1e-6


def test_fit_discrepancy_per_quantity_and_its_checks():
    sp = np.tile([2000.0, 4000.0, 6000.0, 8000.0], 2)
    q = ["a"] * 4 + ["b"] * 4
    fit = fit_discrepancy(sp, q, np.linspace(0.0, 1.0, 8), np.full(8, 0.1))
    assert fit["speed_scale_rpm"] == 8000.0 and set(fit["terms"]) == {"a", "b"}
    assert discrepancy_at(fit, "c", [1000.0]) is None
    few = fit_discrepancy([1000.0, 2000.0], ["a", "a"], [0.1, 0.2], [0.1, 0.1])
    assert few["terms"] == {}  # fewer than three distinct speeds: no term
    with pytest.raises(tb.ConfigError, match="sigmas > 0"):
        fit_discrepancy(sp, q, np.zeros(8), np.zeros(8))
    with pytest.raises(tb.ConfigError, match="kernel"):
        fit_discrepancy(sp, q, np.zeros(8), np.ones(8), "cubic")  # type: ignore[arg-type]


# -- the member of the unknown smooth term ------------------------------------------


@pytest.fixture(scope="module")
def unresolved() -> tb.Diagnosis:
    """One quantity, a hidden ball drag (the temperature rises ~ n^3 over
    the baseline): "unresolved" between the drag and an unknown source;
    the two highest speeds held out."""
    cond = conditions(SPEEDS, loads=(300.0, 1000.0), quantities=(TO,))
    d = tb.diagnose(Rig(), measured(Rig().with_setting(drag_coefficient=0.3), cond, 10))
    assert d.verdict.startswith("unresolved")
    return d


def _control(d: tb.Diagnosis):
    m = d.model
    assert m.kind == "unresolved" and m.members[-1].label.startswith("generic_control")
    return m, m.members[-1]


def test_the_control_member_carries_a_process_fitted_on_the_training_points(unresolved):
    _, ctrl = _control(unresolved)
    gp = ctrl.discrepancy["gaussian_process"]
    term = gp["terms"][TO]
    held = unresolved.points["heldout"].to_numpy()
    train = unresolved.points.filter(pl.Series(~held))
    assert gp["speed_scale_rpm"] == train["speed_rpm"].max() == 12000.0
    assert sorted(term["speeds_rpm"]) == sorted(train["speed_rpm"].to_list())
    # the residuals are the baseline's, the sigmas the measured ones
    base = Rig().predict(train)[TO]
    np.testing.assert_allclose(sorted(term["residuals"]), sorted(train["value"] - base), 1e-9)
    assert sorted(term["sigmas"]) == sorted(train["sigma"].to_list())
    assert term["amplitude"] > 0.0 and term["length_scale"] > 0.0


def _band(d: tb.Diagnosis, speeds, axial_n=300.0) -> pl.DataFrame:
    m, ctrl = _control(d)
    cond = {"speeds_rpm": speeds, "axial_n": axial_n}
    p = tb.predict(m, "measured", cond).filter(
        (pl.col("member") == ctrl.label) & (pl.col("quantity") == TO)
    )
    assert (p["method"] == "discrepancy").all()
    return p.with_columns(((pl.col("upper") - pl.col("lower")) / 2.0).alias("half"))


def test_the_band_widens_away_from_the_measured_speeds(unresolved):
    inside = _band(unresolved, np.arange(2000.0, 12001.0, 1000.0))
    outside = _band(unresolved, [13000.0, 14000.0, 16000.0, 20000.0, 24000.0])
    # narrow where measured (sigma 0.5 K), wider beyond, growing with distance
    assert inside["half"].max() < 2.0 * 0.5
    half = outside["half"].to_numpy()
    assert half[0] > inside["half"].max() and np.all(np.diff(half) > 0.0)
    assert half[-1] > 10.0 * inside["half"].max()
    # the baseline plus the process's posterior mean and variance
    _, ctrl = _control(unresolved)
    mean, var = discrepancy_at(ctrl.discrepancy["gaussian_process"], TO, outside["speed_rpm"])
    base = Rig().predict(outside)[TO]
    np.testing.assert_allclose(outside["value"], base + mean, rtol=1e-12)
    np.testing.assert_allclose(outside["half"], Z95 * np.sqrt(var), rtol=1e-9)


def test_the_band_covers_the_truth_at_the_heldout_speeds(unresolved):
    truth = Rig().with_setting(drag_coefficient=0.3)
    for load in (300.0, 1000.0):
        b = _band(unresolved, [14000.0, 16000.0], load)
        exact = truth.predict(b)[TO]
        lo, hi = b["lower"].to_numpy(), b["upper"].to_numpy()
        assert np.all((lo <= exact) & (exact <= hi))
        # the baseline alone is far off there: the band is not trivially wide
        base = Rig().predict(b)[TO]
        assert np.all(np.abs(exact - base) > 2.0 * 0.5)


@pytest.mark.parametrize(
    "truth", [{"drag_coefficient": 0.3}, {"lubrication_factor_f0": 1.3}], ids=["drag", "f0"]
)
def test_coverage_beyond_the_measured_range_over_seeds(truth):
    """Fitted to the baseline's residuals at 2000-12,000 rpm, the 95 %
    band of the term covers the true discrepancy at 14,000 and 16,000 rpm
    (1.17 and 1.33 times the highest measured speed) in at least 80 % of
    40 seeds (observed here: 91 % for the cubic drag, 96 % for f0's
    n^(2/3); 83-88 % and 95 % over seeds 0-59); where measured, it stays
    within the measurement sigma."""
    true = Rig().with_setting(**truth)
    cond = conditions(SPEEDS[:6], loads=(300.0, 1000.0), quantities=(TO,))
    far = pl.DataFrame({"speed_rpm": [14000.0, 16000.0] * 2, "axial_n": [300.0] * 2 + [1e3] * 2})
    delta = true.predict(far)[TO] - Rig().predict(far)[TO]
    hits, inside = [], []
    for seed in range(40):
        df = measured(true, cond, 500 + seed)
        r = df["value"].to_numpy() - Rig().predict(df)[TO]
        fit = fit_discrepancy(df["speed_rpm"], df["quantity"], r, df["sigma"])
        mean, var = discrepancy_at(fit, TO, far["speed_rpm"])
        hits.append(np.abs(mean - delta) <= Z95 * np.sqrt(var))
        inside.append(np.sqrt(discrepancy_at(fit, TO, SPEEDS[:6])[1]).max())
    assert np.mean(hits) >= 0.80, np.mean(hits, axis=0)
    assert np.median(inside) < 0.5


def test_the_separating_measurement_weighs_the_difference_by_both_bands(unresolved):
    m, ctrl = _control(unresolved)
    grid = {"speeds_rpm": np.arange(2000.0, 24001.0, 1000.0), "axial_n": [300.0, 1000.0]}
    row = tb.separating_measurement(m, grid, sigma={TO: 0.5}).row(0, named=True)
    assert {row["member_a"], row["member_b"]} == {m.members[0].label, ctrl.label}
    spread = np.sqrt(0.5**2 + row["sd_a"] ** 2 + row["sd_b"] ** 2)
    assert row["separation"] == pytest.approx(abs(row["value_a"] - row["value_b"]) / spread)
    # the unknown term's band counts: beyond the measured range it is wider
    # than the named effect's, and no condition of the envelope does better
    assert row["sd_b"] > row["sd_a"] > 0.0
    p = tb.predict(m, "measured", grid).filter(pl.col("quantity") == TO)
    p = p.with_columns(((pl.col("upper") - pl.col("lower")) / (2.0 * Z95)).alias("sd"))
    keys = ["speed_rpm", "axial_n", "radial_n", "quantity"]
    a = p.filter(pl.col("member") == m.members[0].label)
    both = a.join(p.filter(pl.col("member") == ctrl.label), on=keys, suffix="_b")
    sep = (both["value"] - both["value_b"]).abs() / np.sqrt(
        0.25 + both["sd"] ** 2 + both["sd_b"] ** 2
    )
    assert row["separation"] == pytest.approx(float(sep.max()), rel=1e-6)
    # without the bands the pair would look far more separable than it is
    assert row["separation"] < float(((both["value"] - both["value_b"]).abs() / 0.5).max())


def _bearing_unresolved() -> tb.CalibratedModel:
    """An "unresolved" model of a real bearing (7008C, 300 N), built as a
    diagnosis builds it: an extra heat calibrated, and the unknown term's
    member -- the baseline with a process fitted to its residuals on
    outer-ring temperatures that run hot by a higher Palmgren f0."""
    base = tb.BearingModelSpec(tb.Bearing.preset("7008C"))
    speeds = np.linspace(2000.0, 10000.0, 5)
    frame = pl.DataFrame({"speed_rpm": speeds, "axial_n": 300.0, "radial_n": 0.0})
    rng = np.random.default_rng(7)
    y = base.with_setting(lubrication_factor_f0=1.6).predict(frame)[TO] + rng.normal(0, 0.5, 5)
    fit = fit_discrepancy(speeds, [TO] * 5, y - base.predict(frame)[TO], np.full(5, 0.5))
    heat = {c.name: c for c in base.candidate_list()}["extra_heat_w"]
    named = CalibratedModel("named", "named: extra_heat_w", base, [_Step("extra_heat_w", heat)],
                            [4.0], [[1.0]], [(2.0, 6.0)])  # fmt: skip
    disc = {"label": "an unknown smooth term", "gaussian_process": fit}
    ctrl = CalibratedModel("named", "generic_control: unknown", base, [], [], np.zeros((0, 0)),
                           discrepancy=disc)  # fmt: skip
    return CalibratedModel("unresolved", "unresolved: named: extra_heat_w", base, named._steps,
                           named.values, named.covariance, members=[named, ctrl])  # fmt: skip


def test_save_load_and_pickle_keep_the_discrepancy_predictions(tmp_path):
    m = _bearing_unresolved()
    cond = {"speeds_rpm": [3000.0, 9000.0, 14000.0, 18000.0], "axial_n": 300.0}
    before = tb.predict(m, "temperatures", cond)
    rows = before.filter(pl.col("method") == "discrepancy")
    assert set(rows["quantity"]) == {TO}  # the measured quantity only
    half = ((rows["upper"] - rows["lower"]) / 2.0).to_numpy()
    assert np.all(np.diff(half[1:]) > 0.0) and half[-1] > half[0]
    loaded = tb.CalibratedModel.load(m.save(tmp_path / "unresolved.json"))
    pickled = pickle.loads(pickle.dumps(m))
    for other in (loaded, pickled):
        assert other == m
        assert other.members[-1].discrepancy == m.members[-1].discrepancy
        after = tb.predict(other, "temperatures", cond)
        assert after.equals(before)
        for c in ("value", "lower", "upper"):
            assert after[c].to_numpy().tobytes() == before[c].to_numpy().tobytes()
