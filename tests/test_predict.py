"""Predictions with uncertainty bands (``thermobear.predict``) on synthetic
truth: one bearing (7008C, 300 N axial) whose friction heat is off from the
baseline's by a known Palmgren f0 and a known extra heat; measured
outer-ring temperatures (and heat) at the lower speeds, plus Gaussian noise
of the typical sigma (0.5 K, 2 % of the heat).

The calibrated models are built here the way a calibration builds them:
bounded least squares of the weighted residuals on the model itself, the
linearised covariance ``phi (J^T J)^-1`` of ``CalibratedModel``. (A
calibration is a few dozen model runs of five speeds, about 0.2 s: cheap
enough for the coverage over 60 seeds.)"""

from __future__ import annotations

import numpy as np
import polars as pl
import pytest
from scipy.optimize import least_squares

import thermobear as tb
from thermobear import diagnosis as D
from thermobear.diagnosis.calibrated import CalibratedModel, _Step, linear_covariance

TRUTH = {"lubrication_factor_f0": 1.6, "extra_heat_w": 5.0}
TRAIN_RPM = np.linspace(2000.0, 10000.0, 5)
TO = "outer_ring_temperature_c"


@pytest.fixture(scope="module")
def base() -> D.BearingModelSpec:
    return D.BearingModelSpec(tb.Bearing.preset("7008C"))


def _measured(truth, speeds, quantities, seed, noise=1.0) -> pl.DataFrame:
    cond = pl.DataFrame(
        {
            "speed_rpm": np.repeat(speeds, len(quantities)),
            "axial_n": 300.0,
            "radial_n": 0.0,
            "quantity": list(quantities) * len(speeds),
        }
    )
    return D.synthetic_measurements(truth, cond, noise, seed)


def _calibrated(base, measured, names, label="") -> CalibratedModel:
    """Least-squares calibration of ``names`` on ``measured`` with the
    linearised covariance (stretched by phi = max(1, chi^2 / (n - p)))."""
    pool = {c.name: c for c in base.candidate_list()}
    steps = [_Step(n, pool[n]) for n in names]
    lo = np.array([pool[n].lower for n in names])
    hi = np.array([pool[n].upper for n in names])
    probe = CalibratedModel("calibration", label, base, steps, lo, np.zeros((len(names),) * 2))
    y, s = measured["value"].to_numpy(), measured["sigma"].to_numpy()
    q = measured["quantity"].to_numpy()

    def resid(v):
        p = probe.spec_at(v).predict(measured)
        return (y - np.array([p[qq][i] for i, qq in enumerate(q)])) / s

    x0 = np.clip([pool[n].null for n in names], lo + 1e-3 * (hi - lo), hi - 1e-3 * (hi - lo))
    fit = least_squares(resid, x0, bounds=(lo, hi), x_scale=hi - lo, diff_step=1e-5)
    phi = max(1.0, 2.0 * fit.cost / max(len(y) - len(names), 1))
    return CalibratedModel(
        "calibration", label, base, steps, fit.x, linear_covariance(fit.jac, phi)
    )


def _width(df: pl.DataFrame, quantity: str = TO) -> np.ndarray:
    d = df.filter(pl.col("quantity") == quantity).sort("speed_rpm")
    return (d["upper"] - d["lower"]).to_numpy()


def test_the_frame_is_tidy_with_units_and_methods(base):
    cm = _calibrated(
        base, _measured(base.with_setting(**TRUTH), TRAIN_RPM, [TO], 0), ["extra_heat_w"]
    )
    df = tb.predict(cm, "measured", {"speeds_rpm": [4000.0, 12000.0], "axial_n": 300.0})
    assert df.columns == ["speed_rpm", "axial_n", "radial_n", "quantity", "value", "lower",
                          "upper", "unit", "member", "method", "weight", "speed_beyond_measured",
                          "axial_load_beyond_measured", "radial_load_beyond_measured"]  # fmt: skip
    # "measured": every quantity but the changes from a reference speed ("growth" has them)
    assert df.height == 2 * len([q for q in base.quantities if not q.endswith("_change_um")])
    assert set(df["member"]) == {""} and set(df["method"]) == {"delta"}
    units = dict(zip(df["quantity"], df["unit"], strict=True))
    assert units[TO] == "C" and units["k_xx_n_per_m"] == "N/m" and units["heat_w"] == "W"
    assert (df["lower"] <= df["value"]).all() and (df["value"] <= df["upper"]).all()
    # the value is the spec's own prediction at the estimate
    at = cm.spec.predict(pl.DataFrame({"speed_rpm": [12000.0], "axial_n": 300.0, "radial_n": 0.0}))
    row = df.filter((pl.col("quantity") == TO) & (pl.col("speed_rpm") == 12000.0))
    assert row["value"][0] == at[TO][0]
    assert set(tb.predict(cm, "stiffness", {"speeds_rpm": [5000.0], "axial_n": 300.0})[
        "quantity"]) == {"radial_stiffness_seed_n_per_m", "axial_stiffness_seed_n_per_m",
                         "k_xx_n_per_m", "k_zz_n_per_m"}  # fmt: skip


def test_the_delta_method_and_sampling_agree_on_the_width_of_a_smooth_output(base):
    """Outer-ring temperature at three speeds (inside and beyond the measured
    ones) of a two-parameter calibration (f0 and extra heat). 256 scrambled
    Sobol points: the 2.5 % and 97.5 % quantiles lean on the few points in
    each tail, and Sobol's stratification keeps their error at a few
    per cent of the width from about a hundred points up (plain Monte Carlo
    would need several times more for the same error)."""
    truth = base.with_setting(**TRUTH)
    cm = _calibrated(base, _measured(truth, TRAIN_RPM, [TO, "heat_w"], 0), list(TRUTH))
    cond = {"speeds_rpm": [6000.0, 12000.0, 16000.0], "axial_n": 300.0}
    delta = tb.predict(cm, "temperatures", cond, method="delta")
    sampled = tb.predict(cm, "temperatures", cond, method="sampling", samples=256, seed=3)
    assert set(delta["method"]) == {"delta"} and set(sampled["method"]) == {"sampling"}
    wd, ws = _width(delta), _width(sampled)
    assert np.all(wd > 0.0)
    assert np.all(np.abs(ws / wd - 1.0) < 0.10), (wd, ws)
    # "auto" is the delta method for these smooth outputs
    assert tb.predict(cm, "temperatures", cond).equals(delta)


@pytest.fixture(scope="module")
def tie(base) -> CalibratedModel:
    """A tie: the same temperatures explained by a higher f0 or by an extra
    heat, each calibrated on them."""
    m = _measured(base.with_setting(lubrication_factor_f0=1.6), TRAIN_RPM, [TO], 1)
    members = [
        _calibrated(base, m, ["lubrication_factor_f0"], "tie member 1: lubrication_factor_f0"),
        _calibrated(base, m, ["extra_heat_w"], "tie member 2: extra_heat_w"),
    ]
    return CalibratedModel("tie", "tie", base, [], [], np.zeros((0, 0)), members=members)


def test_under_a_tie_the_band_contains_each_members_prediction(tie):
    cond = {"speeds_rpm": [2000.0, 8000.0, 14000.0, 18000.0], "axial_n": 300.0}
    df = tb.predict(tie, "temperatures", cond, band="envelope")
    labels = [m.label for m in tie.members]
    assert df["member"].unique(maintain_order=True).to_list() == [*labels, "envelope"]
    env = df.filter(pl.col("member") == "envelope").sort("quantity", "speed_rpm")
    assert set(env["method"]) == {"envelope"}
    for m in tie.members:
        own = df.filter(pl.col("member") == m.label).sort("quantity", "speed_rpm")
        assert (env["lower"] <= own["lower"]).all() and (own["upper"] <= env["upper"]).all()
        assert (env["lower"] <= own["value"]).all() and (own["value"] <= env["upper"]).all()
    # the explanations part beyond the measured speeds: f0's viscous heat grows
    # with speed, a constant extra heat does not
    to = df.filter(pl.col("quantity") == TO)
    gap = {
        s: abs(float(np.diff(to.filter(pl.col("speed_rpm") == s).head(2)["value"].to_numpy())[0]))
        for s in (8000.0, 18000.0)
    }
    assert gap[18000.0] > 2.0 * gap[8000.0]


def test_the_separating_measurement_is_where_the_members_differ_most(tie):
    grid = {"speeds_rpm": np.linspace(1000.0, 18000.0, 18), "axial_n": [300.0, 600.0]}
    row = tb.separating_measurement(tie, grid, sigma={TO: 0.5, "heat_w": 2.0})
    assert row.height == 1
    r = row.row(0, named=True)
    assert r["speed_rpm"] == 18000.0 and r["unit"] in ("C", "W")
    spread = np.sqrt(r["sigma"] ** 2 + r["sd_a"] ** 2 + r["sd_b"] ** 2)
    assert r["sd_a"] > 0.0 and r["sd_b"] > 0.0  # the members' own bands count
    assert r["separation"] == pytest.approx(abs(r["value_a"] - r["value_b"]) / spread)
    # no other condition of the envelope separates them better: the members'
    # values and bands as predict gives them (value +- 1.96 sd)
    z = 1.959963984540054
    p = tb.predict(tie, "measured", grid).with_columns(
        ((pl.col("upper") - pl.col("lower")) / (2.0 * z)).alias("sd")
    )
    keys = ["speed_rpm", "axial_n", "radial_n", "quantity"]
    a, b = (p.filter(pl.col("member") == m.label) for m in tie.members)
    both = a.join(b, on=keys, suffix="_b").filter(pl.col("quantity").is_in([TO, "heat_w"]))
    sig = np.where(both["quantity"].to_numpy() == TO, 0.5, 2.0)
    sep = np.abs(both["value"] - both["value_b"]).to_numpy() / np.sqrt(
        sig**2 + both["sd"].to_numpy() ** 2 + both["sd_b"].to_numpy() ** 2
    )
    assert r["separation"] == pytest.approx(float(sep.max()), rel=1e-6)
    with pytest.raises(tb.ConfigError, match="two explanations"):
        tb.separating_measurement(tie.members[0], grid, 0.5)


def test_coverage_of_the_95_percent_band_over_60_seeds(base):
    """Calibrate f0 and the extra heat on the outer-ring temperature at 2000 to
    10,000 rpm (noisy), predict 12,000 to 16,000 rpm: the 95 % band covers
    the noise-free truth at 90 to 99 % of the 180 predicted points (60
    seeds x 3 speeds); too wide a band fails as well as too narrow a one.
    (About 0.2 s a seed: the calibration's model runs; the band is five.)"""
    truth = base.with_setting(**TRUTH)
    cond = {"speeds_rpm": [12000.0, 14000.0, 16000.0], "axial_n": 300.0}
    frame = pl.DataFrame({"speed_rpm": cond["speeds_rpm"], "axial_n": 300.0, "radial_n": 0.0})
    exact = truth.predict(frame)[TO]
    hits = []
    for seed in range(60):
        cm = _calibrated(base, _measured(truth, TRAIN_RPM, [TO], 1000 + seed), list(TRUTH))
        d = tb.predict(cm, "temperatures", cond).filter(pl.col("quantity") == TO)
        hits.append((d["lower"].to_numpy() <= exact) & (exact <= d["upper"].to_numpy()))
    rate = float(np.mean(hits))
    assert 0.90 <= rate <= 0.99, rate


def test_bands_narrow_as_data_grow(base):
    """Noise-free data (phi = 1): nine measured speeds give a narrower band
    at 16,000 rpm than three over the same range, and a tighter sigma a
    narrower one still."""
    truth = base.with_setting(**TRUTH)
    widths = []
    for n, noise in ((3, 1.0), (9, 1.0), (9, 0.5)):
        m = _measured(truth, np.linspace(2000.0, 10000.0, n), [TO], 0, noise=0.0)
        m = m.with_columns(pl.lit(0.5 * noise).alias("sigma"))
        cm = _calibrated(base, m, list(TRUTH))
        widths.append(_width(tb.predict(cm, "temperatures", {"speeds_rpm": [16000.0],
                                                             "axial_n": 300.0}))[0])  # fmt: skip
    assert widths[0] > 1.3 * widths[1] > 0.0
    assert widths[2] == pytest.approx(0.5 * widths[1], rel=0.02)


def test_bad_input_names_the_field(base):
    cm = _calibrated(base, _measured(base, TRAIN_RPM, [TO], 0), ["extra_heat_w"])
    cond = {"speeds_rpm": [5000.0], "axial_n": 300.0}
    with pytest.raises(tb.ConfigError, match="level"):
        tb.predict(cm, "temperatures", cond, level=95)
    with pytest.raises(tb.ConfigError, match="method"):
        tb.predict(cm, "temperatures", cond, method="bootstrap")  # type: ignore[arg-type]
    with pytest.raises(tb.ConfigError, match="what"):
        tb.predict(cm, "spectra", cond)  # type: ignore[arg-type]
    with pytest.raises(tb.ConfigError, match="what"):
        tb.predict(cm, "vibration", cond)  # a bearing has no vibration quantity
    with pytest.raises(tb.ConfigError, match="speed_rpm"):
        tb.predict(cm, "temperatures", {"speeds_rpm": [-1.0], "axial_n": 300.0})
    with pytest.raises(tb.ConfigError, match="samples"):
        tb.predict(cm, "temperatures", cond, method="sampling", samples=2)
    with pytest.raises(tb.ConfigError, match="model"):
        tb.predict(base, "temperatures", cond)


def test_a_calibration_predicts_at_its_measured_conditions_by_default(base):
    """The model of ``tb.calibrate`` (and the calibration itself, standing
    for it) gives its band at the measured speeds when no conditions are
    given; its values there are the calibration's ``model_after``."""
    m = _measured(base.with_setting(**TRUTH), TRAIN_RPM[:4], [TO], 2)
    cal = tb.calibrate([(base, m)], ["extra_heat_w"])
    df = tb.predict(cal, "temperatures").filter(pl.col("quantity") == TO).sort("speed_rpm")
    assert df["speed_rpm"].to_list() == TRAIN_RPM[:4].tolist()
    after = cal.points.sort("speed_rpm")["model_after"].to_numpy()
    np.testing.assert_allclose(df["value"].to_numpy(), after, rtol=0, atol=1e-9)
    assert (df["upper"] - df["lower"] > 0.0).all()
    with pytest.raises(tb.ConfigError, match="conditions"):
        tb.predict(cal.model, "temperatures")
