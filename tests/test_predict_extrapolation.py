"""Where a prediction stands: every frame of ``thermobear.predict`` says per
row how far its speed and loads lie outside the conditions the model was
calibrated at, and an ``ExtrapolationWarning`` fires past 50 %."""

from __future__ import annotations

import types
import warnings

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear import diagnosis as D
from thermobear.diagnosis.calibrated import CalibratedModel, _Step
from thermobear.predict.extrapolation import (
    MAX_BEYOND_MEASURED,
    beyond_frame,
    beyond_measured,
)

TO = "outer_ring_temperature_c"
TRAIN_RPM = np.array([2000.0, 4000.0, 6000.0, 8000.0])
BEYOND = ["speed_beyond_measured", "axial_load_beyond_measured", "radial_load_beyond_measured"]


@pytest.fixture(scope="module")
def base() -> D.BearingModelSpec:
    return D.BearingModelSpec(tb.Bearing.preset("7008C"))


@pytest.fixture(scope="module")
def cal(base):
    cond = pl.DataFrame({"speed_rpm": TRAIN_RPM, "axial_n": 300.0, "radial_n": 0.0, "quantity": TO})
    m = D.synthetic_measurements(base.with_setting(extra_heat_w=5.0), cond, 1.0, 0)
    return tb.calibrate([(base, m)], ["extra_heat_w"])


def _silent(fn, *args, **kwargs):
    """``fn(...)`` with an ExtrapolationWarning turned into an error."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", tb.ExtrapolationWarning)
        return fn(*args, **kwargs)


def test_the_distance_is_zero_inside_and_a_fraction_of_the_top_outside():
    measured = np.array([2000.0, 5000.0, 8000.0])
    got = beyond_measured(np.array([2000.0, 6000.0, 8000.0, 12000.0, 1000.0, np.nan]), measured)
    np.testing.assert_allclose(got[:5], [0.0, 0.0, 0.0, 0.5, 0.125], rtol=0, atol=1e-15)
    assert np.isnan(got[5])
    # a load measured only at 0, nothing to scale by: all of another load lies beyond
    assert beyond_measured(np.array([0.0, 100.0]), np.zeros(3)).tolist() == [0.0, 1.0]
    assert beyond_measured(np.array([100.0]), np.zeros(3), scale=400.0).tolist() == [0.25]


def test_a_load_measured_only_at_zero_is_scaled_by_the_machines_largest_load():
    measured = pl.DataFrame({"speed_rpm": [1000.0, 2000.0], "axial_n": [300.0, 600.0],
                             "radial_n": 0.0})  # fmt: skip
    frame = pl.DataFrame({"speed_rpm": [1500.0], "axial_n": [450.0], "radial_n": [150.0]})
    got = beyond_frame(frame, measured).row(0, named=True)
    assert got["speed_beyond_measured"] == 0.0 and got["axial_load_beyond_measured"] == 0.0
    assert got["radial_load_beyond_measured"] == pytest.approx(150.0 / 600.0)
    # no measured conditions: null columns
    none = beyond_frame(frame, None)
    assert all(none[c].null_count() == 1 for c in BEYOND)


def test_a_calibration_prediction_carries_how_far_each_row_lies(cal):
    grid = {"speeds_rpm": [1000.0, 5000.0, 10000.0], "axial_n": [300.0, 400.0]}
    df = _silent(tb.predict, cal, "temperatures", grid)  # 25 % and 33 % beyond: no warning
    assert set(BEYOND) <= set(df.columns)
    rows = df.filter(pl.col("quantity") == TO).sort("axial_n", "speed_rpm")
    np.testing.assert_allclose(
        rows["speed_beyond_measured"].to_numpy(), [1000.0 / 8000.0, 0.0, 0.25] * 2, atol=1e-12
    )
    np.testing.assert_allclose(
        rows["axial_load_beyond_measured"].to_numpy(), [0.0] * 3 + [100.0 / 300.0] * 3
    )
    assert (rows["radial_load_beyond_measured"] == 0.0).all()


def test_past_half_the_top_measured_speed_or_load_the_prediction_warns(cal):
    assert MAX_BEYOND_MEASURED == 0.5
    with pytest.warns(tb.ExtrapolationWarning, match=r"speed_rpm = 14000 lies 75 % beyond"):
        df = tb.predict(cal, "temperatures", {"speeds_rpm": [14000.0], "axial_n": 300.0})
    assert df["speed_beyond_measured"].to_list() == [0.75] * df.height  # still returned
    with pytest.warns(tb.ExtrapolationWarning, match=r"axial_n = 500 lies 67 % beyond"):
        tb.predict(cal, "temperatures", {"speeds_rpm": [4000.0], "axial_n": 500.0})
    _silent(tb.predict, cal, "temperatures", {"speeds_rpm": [11900.0], "axial_n": 300.0})


def test_a_model_without_measured_conditions_gets_null_columns_and_no_warning(cal):
    df = _silent(tb.predict, cal.model, "temperatures", {"speeds_rpm": [30000.0],
                                                         "axial_n": 300.0})  # fmt: skip
    assert set(BEYOND) <= set(df.columns)
    assert all(df[c].null_count() == df.height for c in BEYOND)


def test_every_member_row_of_a_tie_carries_the_columns(base):
    pool = {c.name: c for c in base.candidate_list()}
    members = [
        CalibratedModel("named", f"tie member {i}: {n}", base, [_Step(n, pool[n])], [v],
                        np.zeros((1, 1)))
        for i, (n, v) in enumerate([("extra_heat_w", 5.0), ("lubrication_factor_f0", 1.5)], 1)
    ]  # fmt: skip
    m0 = members[0]
    tie = CalibratedModel("tie", "tie", base, m0._steps, m0.values, m0.covariance, members=members)
    measured = pl.DataFrame({"speed_rpm": TRAIN_RPM, "axial_n": 300.0, "radial_n": 0.0})
    carrier = types.SimpleNamespace(model=tie, points=measured)  # a diagnosis stands so
    with pytest.warns(tb.ExtrapolationWarning, match="16000"):
        df = tb.predict(carrier, "temperatures", {"speeds_rpm": [4000.0, 16000.0],
                                                  "axial_n": 300.0})  # fmt: skip
    assert set(df["member"]) >= {m.label for m in members}
    assert df["speed_beyond_measured"].null_count() == 0
    by_speed = dict(zip(df["speed_rpm"], df["speed_beyond_measured"], strict=True))
    assert by_speed == {4000.0: 0.0, 16000.0: 1.0}


def test_a_spindle_prediction_measures_its_preload():
    spec = D.SpindleModelSpec(tb.Spindle.preset("seed-ceramic-spindle"))
    cm = CalibratedModel("nothing", "baseline", spec, [], [], np.zeros((0, 0)))
    measured = pl.DataFrame({"speed_rpm": [3000.0, 6000.0], "preload_n": [200.0, 400.0]})
    carrier = types.SimpleNamespace(model=cm, points=measured)
    with pytest.warns(tb.ExtrapolationWarning, match="preload_n = 700"):
        df = tb.predict(carrier, "temperatures", {"speeds_rpm": [6000.0], "preload_n": 700.0})
    assert "axial_load_beyond_measured" not in df.columns
    assert df["preload_beyond_measured"].to_list() == [pytest.approx(0.75)] * df.height
    assert df["speed_beyond_measured"].to_list() == [0.0] * df.height
