"""Explanations weighed by how well they predict, and the unknown term shaped
by physics (``thermobear.diagnosis.weights``,
``thermobear.diagnosis.unknown_heat``, the mixture band of
``thermobear.predict``).

Independent checks: the leave-one-out identities against refitting with the
point removed (linear least squares and a Gaussian process), the stacking
weights against a general-purpose optimiser of the same objective, the
mixture's quantiles against its distribution function; then the physics: an
unknown heat source fitted to temperatures predicts the stiffness with a
finite band that covers the truth, and a source outside the registry gets
the larger weight."""

from __future__ import annotations

import numpy as np
import polars as pl
import pytest
from scipy.stats import norm

import thermobear as tb
from thermobear import diagnosis as D
from thermobear.diagnosis import weights as W
from thermobear.diagnosis.discrepancy import Hyperparameters, kernel_matrix, posterior
from thermobear.diagnosis.unknown_heat import unknown_heat_w
from thermobear.predict.band import mixture_quantile

# -- leave-one-out identities ---------------------------------------------------------


def test_linear_leave_one_out_equals_refitting_without_the_point():
    rng = np.random.default_rng(4)
    n, p = 12, 3
    x = rng.normal(size=(n, p))
    s = rng.uniform(0.5, 2.0, n)
    y = x @ np.array([1.0, -2.0, 0.5]) + s * rng.normal(size=n)
    coef = np.linalg.lstsq(x / s[:, None], y / s, rcond=None)[0]
    e = y - x @ coef
    # the Jacobian of the weighted residuals (y - x c) / s
    d, var = W.smoother_loo(e, W.hat_matrix(-x / s[:, None], s), s)
    for i in range(n):
        keep = np.arange(n) != i
        a = x[keep] / s[keep, None]
        c = np.linalg.lstsq(a, y[keep] / s[keep], rcond=None)[0]
        pred = x[i] @ c
        cov = np.linalg.inv(a.T @ a)
        # the residual of y_i against the refit, its variance sigma^2 + x C x^T
        assert d[i] == pytest.approx(y[i] - pred, rel=1e-9, abs=1e-12)
        assert var[i] == pytest.approx(s[i] ** 2 + x[i] @ cov @ x[i], rel=1e-9)


def test_gaussian_process_leave_one_out_equals_the_posterior_without_the_point():
    rng = np.random.default_rng(7)
    x = np.linspace(0.2, 1.0, 7)
    s = np.full(7, 0.3)
    r = np.sin(3 * x) + s * rng.normal(size=7)
    hp = Hyperparameters(1.0, 0.4, 1.0)
    kf = kernel_matrix(x, x, hp, "matern52")
    smooth = kf @ np.linalg.inv(kf + np.diag(s * s))
    d, var = W.smoother_loo(r - smooth @ r, smooth, s)
    for i in range(7):
        keep = np.arange(7) != i
        m, v = posterior(x[keep], r[keep], s[keep], hp, x[i : i + 1], "matern52")
        assert d[i] == pytest.approx(r[i] - m[0], rel=1e-8, abs=1e-10)
        assert var[i] == pytest.approx(v[0] + s[i] ** 2, rel=1e-8)


def test_a_fit_and_a_process_on_its_residual_left_out_together():
    """A straight line fitted by least squares and a Gaussian process on its
    residuals, both refitted without point i (the process's hyperparameters
    held): the combined smoother's leave-one-out residual is exactly the
    refit's at a point where the fit's leverage is small, and close where
    it is not (the process saw the point through the line)."""
    rng = np.random.default_rng(11)
    x = np.linspace(0.1, 1.0, 9)
    s = np.full(9, 0.2)
    y = 1.0 + 2.0 * x + 0.3 * np.sin(6 * x) + s * rng.normal(size=9)
    a = np.column_stack([np.ones(9), x])
    hp = Hyperparameters(0.3, 0.2, 0.0)

    def fit(keep, at):
        c = np.linalg.lstsq(a[keep] / s[keep, None], y[keep] / s[keep], rcond=None)[0]
        e = y[keep] - a[keep] @ c
        m, _ = posterior(x[keep], e, s[keep], hp, x[at], "matern52")
        return a[at] @ c + m

    hat = W.hat_matrix(-a / s[:, None], s)
    kf = kernel_matrix(x, x, hp, "matern52")
    smooth = kf @ np.linalg.inv(kf + np.diag(s * s))
    e = y - a @ np.linalg.lstsq(a / s[:, None], y / s, rcond=None)[0]
    d, _ = W.smoother_loo(e - smooth @ e, W.member_smoother(hat, smooth), s)
    refit = np.array([y[i] - fit(np.arange(9) != i, [i])[0] for i in range(9)])
    assert np.corrcoef(d, refit)[0, 1] > 0.95
    assert np.max(np.abs(d - refit)) < 0.5 * np.max(np.abs(refit))


# -- pseudo-BMA+ weights -------------------------------------------------------------


def test_pseudo_bma_weights_limits():
    # the same lead at every point: the bootstrap changes nothing, the
    # weights are the plain softmax of the summed densities
    lpd = np.column_stack([np.full(6, -1.0), np.full(6, -1.2), np.full(6, -1.5)])
    elpd = lpd.sum(axis=0)
    want = np.exp(elpd - elpd.max()) / np.exp(elpd - elpd.max()).sum()
    assert W.pseudo_bma_weights(lpd) == pytest.approx(want, rel=1e-12)
    # identical members: equal weights; a far better member: all of it
    assert np.allclose(W.pseudo_bma_weights(np.zeros((4, 3))), 1.0 / 3.0)
    far = np.column_stack([np.zeros(8), np.full(8, -10.0)])
    assert W.pseudo_bma_weights(far)[0] == pytest.approx(1.0, abs=1e-12)


def test_a_lead_resting_on_one_point_counts_less_than_a_spread_one():
    """The same summed lead (2 nats) spread over ten points or held by one:
    the bootstrap sees the second as luck, so its weight is nearer 1/2."""
    spread = np.column_stack([np.full(10, -1.0), np.full(10, -1.2)])
    lucky = np.column_stack([np.full(10, -1.0), np.r_[np.full(9, -1.0), -3.0]])
    ws, wl = W.pseudo_bma_weights(spread)[0], W.pseudo_bma_weights(lucky)[0]
    assert ws == pytest.approx(1.0 / (1.0 + np.exp(-2.0)), rel=1e-12)
    assert 0.5 < wl < ws


# -- the mixture band -----------------------------------------------------------------


def test_mixture_quantiles_solve_the_mixtures_distribution_function():
    mean = np.array([[10.0, 14.0], [5.0, 5.0], [0.0, 3.0]])
    sd = np.array([[1.0, 0.5], [2.0, 2.0], [1.0, 0.0]])
    w = np.array([[0.3, 0.7], [0.5, 0.5], [0.8, 0.2]])
    for p in (0.025, 0.5, 0.975):
        q = mixture_quantile(mean, sd, w, p)
        cdf = [np.sum(w[i, :2] * norm.cdf((q[i] - mean[i, :2]) / sd[i, :2])) for i in range(2)]
        assert cdf == pytest.approx([p, p], abs=1e-9)
    # one member alone (or two identical): the normal's own quantile
    assert mixture_quantile(mean[1:2], sd[1:2], w[1:2], 0.975)[0] == pytest.approx(
        5.0 + 2.0 * norm.ppf(0.975), rel=1e-9
    )
    # a point mass of weight 0.2 at 3 above a N(0, 1) of weight 0.8: the
    # 97.5 % quantile is the point itself
    assert mixture_quantile(mean[2:], sd[2:], w[2:], 0.975)[0] == pytest.approx(3.0, abs=1e-6)


# -- the unknown heat source --------------------------------------------------------


def test_the_unknown_heat_law_and_its_clip():
    opts = {"unknown_heat_linear_w": 10.0, "unknown_heat_quadratic_w": -20.0,
            "unknown_heat_reference_rpm": 10000.0}  # fmt: skip
    got = unknown_heat_w(opts, [0.0, 2500.0, 5000.0, 10000.0])
    assert got.tolist() == pytest.approx([0.0, 1.25, 0.0, 0.0])


SPEEDS = np.array([4000.0, 6000.0, 8000.0, 10000.0])
QUANTITIES = ["outer_ring_temperature_c", "inner_ring_temperature_c", "ball_temperature_c"]
FAR = [12500.0, 14500.0]  # a quarter and 45 % beyond the top measured speed


@pytest.fixture(scope="module")
def base() -> D.BearingModelSpec:
    return D.BearingModelSpec(tb.Bearing.preset("7008C"))


def _conditions() -> pl.DataFrame:
    rows = [(s, 400.0, 0.0, q) for s in SPEEDS for q in QUANTITIES]
    return pl.DataFrame(rows, schema=["speed_rpm", "axial_n", "radial_n", "quantity"], orient="row")


def _measured(truth_at, seed: int, base) -> pl.DataFrame:
    cond = _conditions()
    vals = np.empty(cond.height)
    for sp in SPEEDS:
        rows = (cond["speed_rpm"] == sp).to_numpy()
        p = truth_at(sp).predict(cond.filter(rows))
        vals[rows] = [p[q][i] for i, q in enumerate(cond.filter(rows)["quantity"])]
    sig = D.typical_sigma(base.quantities, cond["quantity"].to_list(), vals)
    noise = np.random.default_rng(seed).normal(size=vals.size)
    return cond.with_columns(pl.Series("value", vals + noise * sig), pl.Series("sigma", sig))


def _far(spec) -> dict:
    return spec.predict(pl.DataFrame({"speed_rpm": FAR, "axial_n": 400.0, "radial_n": 0.0}))


def test_an_unknown_heat_source_predicts_stiffness_from_temperatures(base):
    """Temperatures alone, a hidden source outside the registry (heat ~
    n^1.5): the unknown member acts through the heat balance, so the
    stiffness k_xx it predicts has a finite, non-zero band -- here one that
    covers the truth beyond the measured speeds -- where a discrepancy term
    alone could say nothing."""

    def truth_at(sp):
        return base.with_setting(extra_heat_w=float(30.0 * (sp / 10000.0) ** 1.5))

    d = tb.diagnose(base, _measured(truth_at, 3, base))
    m = d.model
    assert m.kind in ("unresolved", "tie"), d.verdict
    unknown = [x for x in m.members if "unknown heat source" in x.label]
    assert len(unknown) == 1
    pred = tb.predict(m, "stiffness", {"speeds_rpm": FAR, "axial_n": 400.0})
    k = pred.filter((pl.col("quantity") == "k_xx_n_per_m") & (pl.col("member") == unknown[0].label))
    width = (k["upper"] - k["lower"]).to_numpy()
    assert np.all(np.isfinite(width)) and np.all(width > 0.0)
    exact = np.array([_far(truth_at(s))["k_xx_n_per_m"][i] for i, s in enumerate(FAR)])
    k = k.sort("speed_rpm")
    assert np.all((k["lower"].to_numpy() <= exact) & (exact <= k["upper"].to_numpy()))
    # the weights sum to one, the verdict says which is favoured, and the
    # mixture rows are the default combined reading
    ws = [x.weight for x in m.members]
    assert sum(ws) == pytest.approx(1.0) and all(0.0 <= w <= 1.0 for w in ws)
    assert "weight" in d.verdict and ("favoured" in d.verdict or "most weight" in d.verdict)
    assert set(pred["member"]) == {*(x.label for x in m.members), "mixture"}
    # downstream, the member stands for its bearing with its heat law
    _, opts = unknown[0].model()
    heat = float(unknown_heat_w(opts, FAR[0]))
    assert heat > 0.0
    got = tb.thermal_state(m, FAR[0], 400.0, member=unknown[0].label)
    assert all(float(opts.get(k, 1.0)) == 1.0 for k in ("axial_load_scale", "radial_load_scale"))
    rest = {k: v for k, v in opts.items() if not k.startswith(("unknown_heat", "axial_load",
                                                                "radial_load"))}  # fmt: skip
    want = tb.thermal_state(base.bearing, FAR[0], 400.0, **{**rest, "extra_heat_w": heat})
    assert got.temperatures.equals(want.temperatures)
    # saved and loaded, the weights and the unknown member's law come back
    back = tb.CalibratedModel.from_json(m.to_json())
    assert [x.weight for x in back.members] == ws
    assert back == m


def test_a_discrepancy_only_member_is_unconstrained_where_it_was_not_measured():
    """Outside the heat balance (a model without the heat source), the
    unknown member is its discrepancy term alone: a quantity that was not
    measured has null bounds and method "unconstrained", never zero width;
    the mixture, holding that member's weight, is unconstrained too."""
    from thermobear.predict.band import mixture

    cols = ["speed_rpm"]
    a = pl.DataFrame({"speed_rpm": [1.0], "quantity": ["q"], "value": [2.0], "lower": [1.0],
                      "upper": [3.0], "unit": ["1"], "member": ["a"], "method": ["delta"],
                      "weight": [0.7]})  # fmt: skip
    b = a.with_columns(pl.lit(None, dtype=pl.Float64).alias("lower"),
                       pl.lit(None, dtype=pl.Float64).alias("upper"),
                       pl.lit("b").alias("member"), pl.lit("unconstrained").alias("method"),
                       pl.lit(0.3).alias("weight"))  # fmt: skip
    got = mixture([a, b], cols, 0.95)
    assert got["method"][0] == "unconstrained" and got["lower"][0] is None
    # a negligible weight on the unconstrained member: the other's band alone
    got = mixture([a.with_columns(pl.lit(1.0).alias("weight")),
                   b.with_columns(pl.lit(0.0).alias("weight"))], cols, 0.95)  # fmt: skip
    assert got["method"][0] == "mixture"
    assert (got["lower"][0], got["upper"][0]) == pytest.approx((1.0, 3.0), rel=1e-9)


def test_band_choice_is_checked():
    with pytest.raises(tb.ConfigError, match="invalid band = 'union'"):
        tb.predict(object(), band="union")  # type: ignore[arg-type]


def test_the_unknown_member_stands_for_its_bearing_in_the_thermal_calls(base):
    """The unknown heat source acts downstream too: ``thermal_state``,
    ``thermal_state_many``, ``isothermal_heat`` and the thermal stiffness
    curve of the member carry its heat H(n) at each speed, equal to the
    bearing solved by hand with that heat as ``extra_heat_w``, and to the
    member's own prediction (two paths: the hook and the model spec)."""
    law = {"unknown_heat_linear_w": 12.0, "unknown_heat_quadratic_w": 20.0,
           "unknown_heat_reference_rpm": 10000.0}  # fmt: skip
    spec = base.with_setting(**law)
    bearing = base.bearing
    for n in FAR:
        heat = float(unknown_heat_w(law, n))
        assert heat == pytest.approx(12.0 * n / 1e4 + 20.0 * (n / 1e4) ** 2)
        by_hand = tb.thermal_state(bearing, n, 400.0, extra_heat_w=heat)
        got = tb.thermal_state(bearing, n, 400.0, **law)
        assert got.temperatures.equals(by_hand.temperatures)
        extra = got.heat.filter(pl.col("source") == "extra")["heat_w"]
        assert extra.to_list() == pytest.approx([heat], rel=1e-12)
        iso = tb.isothermal_heat(bearing, n, 400.0, oil_temperature_c=50.0, **law)
        iso_hand = tb.isothermal_heat(bearing, n, 400.0, oil_temperature_c=50.0, extra_heat_w=heat)
        assert iso.total_heat_w == pytest.approx(iso_hand.total_heat_w, rel=1e-12)
    many = tb.thermal_state_many(bearing, {"speed_rpm": [FAR[1], FAR[0], FAR[1]], "axial_n": 400.0},
                                 **law)  # fmt: skip
    one = [tb.thermal_state(bearing, n, 400.0, **law) for n in (FAR[1], FAR[0], FAR[1])]
    got_t = many["outer_ring_temperature_c"].to_numpy()
    want_t = [s.temperature_c("outer_ring") for s in one]
    assert got_t == pytest.approx(want_t, abs=1e-6)
    curve = tb.stiffness_curve(bearing, FAR, 400.0, mode="thermal", **law)
    assert curve["outer_ring_temperature_c"].to_numpy() == pytest.approx(want_t[1::-1], abs=1e-6)
    # the model spec's prediction (the path of the diagnosis) agrees
    pred = spec.predict(pl.DataFrame({"speed_rpm": FAR, "axial_n": 400.0, "radial_n": 0.0}))
    assert pred["outer_ring_temperature_c"] == pytest.approx(want_t[1::-1], abs=1e-6)
    # a law needs its reference speed
    with pytest.raises(tb.ConfigError, match="unknown_heat_reference_rpm"):
        tb.thermal_state(bearing, 5000.0, 400.0, unknown_heat_linear_w=5.0)
