"""Figures of predictions with bands (``thermobear.plot.prediction_band``,
``regime_probability``, ``bifurcation`` with regime-boundary intervals).

The band figures draw a real ``tb.predict`` frame: a 7008C bearing (300 N
axial) whose extra heat is calibrated on noisy outer-ring temperatures at
three speeds (bounded least squares, linearised covariance: the way
a calibration builds its model; a fraction of a second), and a tie of
two explanations of the same temperatures. The regime figures draw
hand-made frames of the documented columns."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import numpy as np
import polars as pl
import pytest
from matplotlib.collections import PolyCollection
from scipy.optimize import least_squares

import thermobear as tb
from thermobear import diagnosis as D
from thermobear.diagnosis.calibrated import CalibratedModel, _Step, linear_covariance

TO = "outer_ring_temperature_c"
TRAIN_RPM = np.array([3000.0, 6000.0, 9000.0])
SPEEDS = {"speeds_rpm": [2000.0, 5000.0, 8000.0, 11000.0, 14000.0], "axial_n": 300.0}


@pytest.fixture(scope="module")
def base() -> D.BearingModelSpec:
    return D.BearingModelSpec(tb.Bearing.preset("7008C"))


@pytest.fixture(scope="module")
def measured(base) -> pl.DataFrame:
    cond = pl.DataFrame(
        {"speed_rpm": TRAIN_RPM, "axial_n": 300.0, "radial_n": 0.0, "quantity": [TO] * 3}
    )
    return D.synthetic_measurements(base.with_setting(lubrication_factor_f0=1.6), cond, 1.0, 0)


def _calibrated(base, measured, name: str, label: str = "") -> CalibratedModel:
    """``name`` calibrated on ``measured`` by bounded least squares, with
    the linearised covariance of the estimate."""
    cand = {c.name: c for c in base.candidate_list()}[name]
    lo, hi = np.array([cand.lower]), np.array([cand.upper])
    probe = CalibratedModel("calibration", label, base, [_Step(name, cand)], lo, np.zeros((1, 1)))
    y, s = measured["value"].to_numpy(), measured["sigma"].to_numpy()

    def resid(v):
        return (y - probe.spec_at(v).predict(measured)[TO]) / s

    x0 = np.clip([cand.null], lo + 1e-3 * (hi - lo), hi - 1e-3 * (hi - lo))
    fit = least_squares(resid, x0, bounds=(lo, hi), x_scale=hi - lo, diff_step=1e-5)
    cov = linear_covariance(fit.jac, max(1.0, 2.0 * fit.cost / (len(y) - 1)))
    return CalibratedModel("calibration", label, base, [_Step(name, cand)], fit.x, cov)


@pytest.fixture(scope="module")
def single(base, measured) -> CalibratedModel:
    return _calibrated(base, measured, "extra_heat_w")


@pytest.fixture(scope="module")
def tie(base, measured) -> CalibratedModel:
    members = [
        _calibrated(base, measured, "lubrication_factor_f0", "tie member 1: f0"),
        _calibrated(base, measured, "extra_heat_w", "tie member 2: extra heat"),
    ]
    return CalibratedModel("tie", "tie", base, [], [], np.zeros((0, 0)), members=members)


@pytest.fixture
def ax():
    fig, ax = plt.subplots()
    yield ax
    plt.close(fig)


def _bands(ax) -> list[PolyCollection]:
    return [c for c in ax.collections if isinstance(c, PolyCollection)]


def _bounds_of(band: PolyCollection, speeds: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The least and greatest y of the band's outline at each speed."""
    v = band.get_paths()[0].vertices
    lo = np.array([v[np.isclose(v[:, 0], s), 1].min() for s in speeds])
    hi = np.array([v[np.isclose(v[:, 0], s), 1].max() for s in speeds])
    return lo, hi


def test_the_band_is_the_predicted_interval_with_the_measured_points(single, measured, ax):
    pred = tb.predict(single, "temperatures", SPEEDS)
    assert tb.plot.prediction_band(pred, TO, measured=measured, ax=ax) is ax
    rows = pred.filter(pl.col("quantity") == TO).sort("speed_rpm")
    sp = rows["speed_rpm"].to_numpy()
    (band,) = _bands(ax)
    lo, hi = _bounds_of(band, sp)
    assert np.allclose(lo, rows["lower"].to_numpy()) and np.allclose(hi, rows["upper"].to_numpy())
    assert np.all(hi - lo > 0.0)
    (line,) = [ln for ln in ax.get_lines() if ln.get_label() == "prediction"]
    assert np.allclose(line.get_ydata(), rows["value"].to_numpy())
    # the measured points with sigma error bars
    (eb,) = ax.containers
    assert np.allclose(eb.lines[0].get_xdata(), measured["speed_rpm"].to_numpy())
    seg = np.array(eb.lines[2][0].get_segments())
    assert np.allclose(seg[:, 1, 1] - seg[:, 0, 1], 2.0 * measured["sigma"].to_numpy())
    # the measured speed range is marked: outside it the band is extrapolated
    (span,) = [p for p in ax.patches if p.get_label() == "measured speeds"]
    x = span.get_patch_transform().transform(span.get_path().vertices)[:, 0]
    assert (x.min(), x.max()) == (TRAIN_RPM.min(), TRAIN_RPM.max())
    assert ax.get_ylabel() == "outer ring temperature [°C]"
    labels = set(ax.get_legend_handles_labels()[1])
    assert {"band (delta method)", "prediction", "measured (± sigma)", "measured speeds"} <= labels


def test_a_stiffness_band_reads_in_newton_per_micrometre(single, ax):
    pred = tb.predict(single, "stiffness", SPEEDS)
    tb.plot.prediction_band(pred, "k_xx_n_per_m", ax=ax)
    rows = pred.filter(pl.col("quantity") == "k_xx_n_per_m").sort("speed_rpm")
    lo, hi = _bounds_of(_bands(ax)[0], rows["speed_rpm"].to_numpy())
    assert np.allclose(lo, rows["lower"].to_numpy() * 1e-6)
    assert np.allclose(hi, rows["upper"].to_numpy() * 1e-6)
    assert ax.get_ylabel() == "radial stiffness $k_{xx}$ [N/µm]"
    assert not ax.containers  # no measured points given


def test_under_a_tie_each_member_has_its_curve_inside_the_envelope(tie, ax):
    pred = tb.predict(tie, "temperatures", SPEEDS, band="envelope")
    tb.plot.prediction_band(pred, TO, ax=ax)
    env = pred.filter((pl.col("quantity") == TO) & (pl.col("member") == "envelope"))
    env = env.sort("speed_rpm")
    (band,) = _bands(ax)
    lo, hi = _bounds_of(band, env["speed_rpm"].to_numpy())
    assert np.allclose(lo, env["lower"].to_numpy()) and np.allclose(hi, env["upper"].to_numpy())
    assert band.get_label() == "envelope of the explanations' bands"
    for m in tie.members:
        own = pred.filter((pl.col("quantity") == TO) & (pl.col("member") == m.label))
        (line,) = [ln for ln in ax.get_lines() if ln.get_label() == m.label]
        assert np.allclose(line.get_ydata(), own.sort("speed_rpm")["value"].to_numpy())
    assert len(ax.get_lines()) == len(tie.members)  # no line for the envelope's mean
    # the explanations part at the top speed: their curves differ there
    top = [ln.get_ydata()[-1] for ln in ax.get_lines()]
    assert abs(top[0] - top[1]) > 0.1


def test_measured_points_at_another_load_are_left_out(single, measured, ax):
    other = measured.with_columns(pl.lit(600.0).alias("axial_n"), pl.col("speed_rpm") + 500.0)
    pred = tb.predict(single, "temperatures", SPEEDS)
    tb.plot.prediction_band(pred, TO, measured=pl.concat([measured, other]), ax=ax)
    (eb,) = ax.containers
    assert np.allclose(eb.lines[0].get_xdata(), TRAIN_RPM)


def test_bad_input_names_the_field(single):
    pred = tb.predict(single, "temperatures", {"speeds_rpm": [3000.0], "axial_n": [200.0, 400.0]})
    with pytest.raises(tb.ConfigError, match="quantity = 'heat_w'"):
        tb.plot.prediction_band(pred, "heat_w")
    with pytest.raises(tb.ConfigError, match="several axial_n"):
        tb.plot.prediction_band(pred, TO)
    with pytest.raises(tb.ConfigError, match="regime_probability"):
        tb.plot.prediction_band(_regimes("", TABLE), "regime_probability")
    plt.close("all")


def _regimes(member: str, table: dict[float, dict[str, float]]) -> pl.DataFrame:
    rows = [
        (s, r, p) for s, probs in table.items() for r, p in probs.items()
    ]  # only the regimes seen at a speed have a row
    return pl.DataFrame(
        {
            "speed_rpm": [r[0] for r in rows],
            "quantity": "regime_probability",
            "regime": [r[1] for r in rows],
            "value": [r[2] for r in rows],
            "lower": [max(0.0, r[2] - 0.1) for r in rows],
            "upper": [min(1.0, r[2] + 0.1) for r in rows],
            "unit": "1",
            "member": member,
            "method": "sampling",
        }
    )


TABLE = {
    1000.0: {"period-1": 1.0},
    2000.0: {"period-1": 0.75, "period-2": 0.25},
    3000.0: {"period-2": 0.5, "chaotic": 0.5},
    4000.0: {"chaotic": 0.875, "quasi-periodic": 0.125},
}


def _layer_at(ax, speed: float, y: float) -> list[str]:
    """The layers of the stack that hold the point (speed, y)."""
    return [c.get_label() for c in _bands(ax) if c.get_paths()[0].contains_point((speed, y))]


def _stacks_to_one(ax) -> bool:
    return all(len(_layer_at(ax, s, 0.999)) == 1 and not _layer_at(ax, s, 1.001) for s in TABLE)


def test_regime_probabilities_stack_to_one(ax):
    assert tb.plot.regime_probability(_regimes("", TABLE), ax=ax) is ax
    labels = [c.get_label() for c in _bands(ax)]
    assert labels == ["period-1", "period-2", "quasi-periodic", "chaotic"]
    assert _stacks_to_one(ax)
    # each layer holds its regime's probability at each speed, in order
    for s, probs in TABLE.items():
        cum = 0.0
        for r in labels:
            p = probs.get(r, 0.0)
            if p > 0.0:
                assert _layer_at(ax, s, cum + 0.5 * p) == [r], (s, r)
            cum += p
    assert _layer_at(ax, 3000.0, 0.01) == ["period-2"]  # period-1 is absent there: 0
    assert ax.get_ylim() == (0.0, 1.0)


def test_regime_probabilities_of_members_mix_or_pick_one(ax):
    other = {s: {"chaotic": 0.5, "period-3": 0.25, "period-7": 0.25} for s in TABLE}
    pred = pl.concat([_regimes("a", TABLE), _regimes("b", other), _regimes("envelope", other)])
    tb.plot.regime_probability(pred, ax=ax)
    assert _stacks_to_one(ax)  # the envelope rows are not a member
    assert _layer_at(ax, 2000.0, 0.37) == ["period-1"]  # half of member a's 0.75
    assert _layer_at(ax, 2000.0, 0.38) == ["period-2"]
    ax.clear()
    tb.plot.regime_probability(pred, ax=ax, member="b")
    # the periods of 3 or more share a layer
    assert [c.get_label() for c in _bands(ax)] == ["period-n (n ≥ 3)", "chaotic"]
    assert _layer_at(ax, 2000.0, 0.49) == ["period-n (n ≥ 3)"] and _stacks_to_one(ax)
    with pytest.raises(tb.ConfigError, match="member 'c'"):
        tb.plot.regime_probability(pred, ax=ax, member="c")


def test_bifurcation_marks_each_regime_boundary_interval(ax):
    sp = np.repeat(np.linspace(8000.0, 14000.0, 61), 4)
    pts = pl.DataFrame({"speed_rpm": sp, "dte_um": np.sin(sp), "settled": True})
    bounds = pl.DataFrame(
        {
            "from_regime": ["period-1", "period-2", "chaotic"],
            "to_regime": ["period-2", "chaotic", "period-1"],
            "speed_rpm": [9500.0, 11500.0, 12500.0],
            "lower_rpm": [9300.0, 11200.0, 12400.0],
            "upper_rpm": [9800.0, 11900.0, 12600.0],
            "probability": [1.0, 0.8, 0.25],
        }
    )
    assert tb.plot.bifurcation(pts, bounds, ax=ax) is ax
    spans = [p for p in ax.patches if p.get_gid() == "regime-boundary"]
    assert len(spans) == 2  # the change a quarter of the samples show is left out
    bounds = bounds.head(2)
    for p, lo, hi in zip(spans, bounds["lower_rpm"], bounds["upper_rpm"], strict=True):
        x = p.get_patch_transform().transform(p.get_path().vertices)[:, 0]
        assert np.isclose(x.min(), lo) and np.isclose(x.max(), hi)
    texts = [t.get_text() for t in ax.texts]
    assert texts == ["P1 \u2192 P2", "P2 \u2192 chaos (p 0.80)"]
    # without boundaries (and with the Axes passed second, as before): no span
    fig, other = plt.subplots()
    assert tb.plot.bifurcation(pts, other) is other
    assert not [p for p in other.patches if p.get_gid() == "regime-boundary"]
    plt.close(fig)
