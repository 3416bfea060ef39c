"""Gear regimes under a calibrated bearing model's uncertainty
(``thermobear.predict(model, "regimes", ...)``, ``regime_boundaries``).

The seed gear pair at 20 N m with a 5 um transmission error, on a 6208
bearing model whose extra friction heat is calibrated: a hotter bearing
changes its thermal stiffness schedule and so the speeds where the gear
leaves chaos. The models are built directly (one calibrated value with a
stated covariance), as a calibration builds them."""

from __future__ import annotations

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear import diagnosis as D
from thermobear.diagnosis.calibrated import CalibratedModel, _Step
from thermobear.predict.regimes import changes, wilson

GEAR_OPTIONS = {"torque_n_m": 20.0, "te_amplitude_um": 5.0}
SPEEDS_RPM = np.linspace(9000.0, 16000.0, 36)
EXTRA_HEAT_W = 20.0


@pytest.fixture(scope="module")
def base() -> D.BearingModelSpec:
    return D.BearingModelSpec(tb.Bearing.preset("6208"))


def _model(base, value=EXTRA_HEAT_W, sd=0.0, label="") -> CalibratedModel:
    pool = {c.name: c for c in base.candidate_list()}
    step = _Step("extra_heat_w", pool["extra_heat_w"])
    return CalibratedModel("calibration", label, base, [step], [value], [[sd * sd]])


def _predict(model, samples=16, **kw) -> pl.DataFrame:
    return tb.predict(
        model, "regimes", {"speeds_rpm": SPEEDS_RPM}, gear_options=GEAR_OPTIONS,
        samples=samples, **kw,
    )  # fmt: skip


def _plain_sweep(model) -> pl.DataFrame:
    """The sweep of the calibrated model itself, by hand."""
    gear = tb.GearPair.preset("seed-electric-drive")
    system = tb.GearSystem(gear, bearings=model, stiffness="thermal", **GEAR_OPTIONS)
    return tb.bifurcation(system, SPEEDS_RPM, direction="down")


def _probabilities(df: pl.DataFrame) -> pl.DataFrame:
    return df.filter(pl.col("quantity") == "regime_probability")


@pytest.fixture(scope="module")
def certain(base):
    """A model whose covariance is zero: its prediction and its own sweep."""
    m = _model(base)
    return m, _predict(m), _plain_sweep(m)


@pytest.fixture(scope="module")
def uncertain(base):
    return _predict(_model(base, sd=10.0))


def test_the_frame_is_tidy(uncertain):
    assert uncertain.columns == ["speed_rpm", "quantity", "regime", "value", "lower", "upper",
                                 "unit", "member", "method"]  # fmt: skip
    assert set(uncertain["quantity"]) == {
        "regime_probability", "regime_boundary_rpm", "regime_change_probability",
    }  # fmt: skip
    assert set(uncertain["method"]) == {"sampling"} and set(uncertain["member"]) == {""}
    units = dict(uncertain.select("quantity", "unit").unique().iter_rows())
    assert units == {"regime_probability": "1", "regime_boundary_rpm": "rpm",
                     "regime_change_probability": "1"}  # fmt: skip
    p = _probabilities(uncertain)
    assert p["speed_rpm"].n_unique() == len(SPEEDS_RPM)
    assert p.height == len(SPEEDS_RPM) * p["regime"].n_unique()  # every regime at every speed


@pytest.mark.parametrize("which", ["certain", "uncertain"])
def test_probabilities_at_each_speed_sum_to_one(which, certain, uncertain):
    df = certain[1] if which == "certain" else uncertain
    sums = _probabilities(df).group_by("speed_rpm").agg(pl.col("value").sum())
    assert np.allclose(sums["value"].to_numpy(), 1.0, atol=1e-12)
    p = _probabilities(df)
    assert (p["lower"] <= p["value"]).all() and (p["value"] <= p["upper"]).all()


def test_with_zero_covariance_the_probabilities_are_the_plain_sweep(certain):
    _, pred, plain = certain
    p = _probabilities(pred)
    assert set(p["value"].unique().to_list()) <= {0.0, 1.0}
    got = dict(p.filter(pl.col("value") == 1.0).select("speed_rpm", "regime").iter_rows())
    want = dict(plain.unique("speed_rpm", keep="first").select("speed_rpm", "regime").iter_rows())
    assert got == want
    assert len(set(want.values())) >= 2  # the sweep does change regime


def test_with_zero_covariance_the_boundaries_are_those_of_regimes(certain):
    _, pred, plain = certain
    b = tb.regime_boundaries(pred)
    ranges = tb.regimes(plain).rows(named=True)
    want = [
        (r["regime"], n["regime"], n["speed_from_rpm"], r["speed_to_rpm"])
        for r, n in zip(ranges, ranges[1:], strict=False)
        if r["regime"] != n["regime"]
    ]
    got = [
        (r["from_regime"], r["to_regime"], r["lower_rpm"], r["upper_rpm"])
        for r in b.iter_rows(named=True)
    ]
    assert got == want and want
    assert (b["probability"] == 1.0).all()
    assert np.allclose(b["speed_rpm"], 0.5 * (b["lower_rpm"] + b["upper_rpm"]))


def test_with_uncertainty_the_boundary_interval_holds_the_nominal_boundary(certain, uncertain):
    """Every change of the nominal sweep that at least half the samples
    show (matched by labels and order) has its nominal speed inside the
    sampled interval; the uncertainty widens the interval beyond the grid
    step, and makes some speeds' regime uncertain."""
    _, nominal, plain = certain
    b = tb.regime_boundaries(uncertain)
    per = plain.unique("speed_rpm", keep="first", maintain_order=True)
    step = float(SPEEDS_RPM[1] - SPEEDS_RPM[0])
    checked = 0
    for (frm, to, k), (lo, hi) in changes(per["speed_rpm"].to_numpy(), per["regime"]).items():
        rows = b.filter((pl.col("from_regime") == frm) & (pl.col("to_regime") == to))
        if rows.height <= k or rows["probability"][k] < 0.5:
            continue
        r = rows.row(k, named=True)
        assert r["lower_rpm"] <= 0.5 * (lo + hi) <= r["upper_rpm"], (r, lo, hi)
        checked += 1
    assert checked >= 1
    assert (b["upper_rpm"] - b["lower_rpm"]).max() > 2 * step
    p = _probabilities(uncertain)
    assert ((p["value"] > 0.0) & (p["value"] < 1.0)).any()


def test_members_and_their_envelope(base):
    """Two explanations (a hotter and a cooler bearing, each without
    uncertainty): each member's rows are its own sweep's, the envelope
    spans both members' probabilities."""
    hot = _model(base, 40.0, label="tie member 1: hot")
    cool = _model(base, 0.0, label="tie member 2: cool")
    tie = CalibratedModel(
        "tie", "tie: hot | cool", base, hot._steps, hot.values, hot.covariance, members=[hot, cool]
    )
    df = _predict(tie, samples=8)
    assert set(df["member"]) == {hot.label, cool.label, "envelope"}
    p = _probabilities(df)
    env = p.filter(pl.col("member") == "envelope")
    for m in (hot, cool):
        mine = p.filter(pl.col("member") == m.label)
        assert set(mine["value"].unique().to_list()) <= {0.0, 1.0}
        j = env.join(mine, on=["speed_rpm", "regime"], suffix="_m")
        assert j.height == env.height
        assert (j["lower"] <= j["value_m"]).all() and (j["value_m"] <= j["upper"]).all()
    a = p.filter(pl.col("member") == hot.label)["value"].to_numpy()
    c = p.filter(pl.col("member") == cool.label)["value"].to_numpy()
    assert np.array_equal(env["value"].to_numpy(), 0.5 * (a + c))
    assert (a != c).any()  # the explanations differ somewhere in the sweep
    assert set(tb.regime_boundaries(df)["member"]) <= {hot.label, cool.label}


def test_wilson_interval_is_scipys():
    from scipy.stats import binomtest

    k = np.array([0, 3, 16, 32])
    lo, hi = wilson(k, 32, 0.9)
    for i, kk in enumerate(k):
        ci = binomtest(int(kk), 32).proportion_ci(confidence_level=0.9, method="wilson")
        assert (lo[i], hi[i]) == pytest.approx((ci.low, ci.high), abs=1e-12)


@pytest.mark.parametrize(
    "kw, match",
    [
        ({"method": "delta"}, "not smooth"),
        ({"gear_options": {"stiffness": "speed"}}, "gear_options stiffness"),
        ({"sweep_options": {"speeds": 3}}, "sweep_options speeds"),
        ({"direction": "sideways"}, "direction"),
        ({"gear": "seed"}, "gear"),
    ],
)
def test_bad_input_names_the_field(base, kw, match):
    m = _model(base)
    args = {"gear_options": GEAR_OPTIONS, "samples": 8} | kw
    with pytest.raises(tb.ConfigError, match=match):
        tb.predict(m, "regimes", {"speeds_rpm": SPEEDS_RPM}, **args)
    with pytest.raises(tb.ConfigError, match="speeds_rpm"):
        tb.predict(m, "regimes", None)
    with pytest.raises(tb.ConfigError, match="regime prediction"):
        tb.regime_boundaries(pl.DataFrame({"a": [1]}))
