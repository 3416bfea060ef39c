"""Verdicts that say when nothing fits, and measured data that look wrong.

When the best named fit leaves the residual far above noise (the chi^2
test's p-value below 1e-6) the verdict says "not explained by any known
effect" and names the causes it can check (a quantity shifted by a
constant: ``tests/test_relative_displacement.py``; speeds given in rad/s:
here). The loader refuses or warns about units that look wrong."""

from __future__ import annotations

import warnings

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear import diagnosis as D
from thermobear.diagnosis.measurements import MeasuredData, cv_folds
from thermobear.diagnosis.plausible_data import (
    UNEXPLAINED_P_VALUE,
    constant_shifts,
    one_speed_note,
    speeds_look_like_rad_s,
    unexplained_words,
)
from thermobear.diagnosis.verdict import verdict_text

RPM = np.array([3000.0, 6000.0, 9000.0, 12000.0])
QUANTITIES = ["outer_ring_temperature_c", "heat_w"]


@pytest.fixture(scope="module")
def base() -> D.BearingModelSpec:
    return D.BearingModelSpec(tb.Bearing.preset("7008C"))


def _measured(base, speeds) -> pl.DataFrame:
    cond = pl.DataFrame({"speed_rpm": np.repeat(speeds, len(QUANTITIES)), "axial_n": 300.0,
                         "radial_n": 0.0, "quantity": QUANTITIES * len(speeds)})  # fmt: skip
    return D.synthetic_measurements(base, cond, 1.0, 3)


def _data(speeds, quantity, y, s) -> MeasuredData:
    df = pl.DataFrame({"speed_rpm": speeds, "axial_n": 300.0, "radial_n": 0.0,
                       "quantity": quantity, "value": y, "sigma": s, "run": "1"})  # fmt: skip
    return MeasuredData(
        df, np.asarray(quantity), np.asarray(y, dtype=float), np.asarray(s, dtype=float),
        df.select("speed_rpm", "axial_n", "radial_n"), np.zeros(df.height, dtype=bool),
        cv_folds(df),
    )  # fmt: skip


# ---------------------------------------------------------------- the rules


def test_speeds_look_like_rad_s_only_by_the_documented_rule():
    assert speeds_look_like_rad_s([314.0, 628.0, 942.0, 1257.0])  # 3000 .. 12000 rpm
    assert speeds_look_like_rad_s([314.159, 628.319, 1047.198])
    assert not speeds_look_like_rad_s([500.0, 1000.0, 1500.0])  # round rpm settings
    assert not speeds_look_like_rad_s([314.0, 628.0, 2513.0])  # one at 2000 or more
    assert not speeds_look_like_rad_s([314.0])  # one speed says nothing
    assert not speeds_look_like_rad_s([123.0, 456.0, 789.0])  # not round rpm as rad/s


def test_a_constant_shift_is_found_and_a_shape_is_not():
    speeds = np.repeat(RPM, 2)
    q = np.array(["axial_displacement_um", "outer_ring_temperature_c"] * 4)
    pred = np.where(q == "axial_displacement_um", 120.0 + speeds / 1e3, 30.0 + speeds / 1e3)
    s = np.full(8, 0.5)
    zeroed = np.where(q == "axial_displacement_um", pred - pred[0], pred + 0.1)
    got = constant_shifts(_data(speeds, q, zeroed, s), pred)
    assert [g["quantity"] for g in got] == ["axial_displacement_um"]
    assert got[0]["offset"] == pytest.approx(-pred[0])
    assert got[0]["zero_speed_rpm"] == 3000.0
    assert got[0]["change"] == "axial_displacement_change_um"
    # a residual that grows with speed is no constant shift
    ramp = np.where(q == "axial_displacement_um", pred + 2.0 * (speeds - 3000.0) / 1e3, pred)
    assert constant_shifts(_data(speeds, q, ramp, s), pred) == []


def test_the_unexplained_words_follow_the_fit_and_join_the_verdict():
    speeds = np.repeat(RPM, 2)
    q = np.array(["axial_displacement_um", "outer_ring_temperature_c"] * 4)
    pred = np.where(q == "axial_displacement_um", 120.0, 30.0) + speeds / 1e3
    s = np.full(8, 0.5)
    fits = _data(speeds, q, pred + 0.3 * np.sin(np.arange(8.0)), s)
    assert unexplained_words(fits, pred, []) == ""  # within noise
    data = _data(speeds, q, np.where(q == "axial_displacement_um", pred - pred[0], pred), s)
    words = unexplained_words(data, pred, [])
    assert words.startswith("not explained by any known effect (the best named fit leaves")
    assert "likely cause: axial_displacement_um looks shifted by a constant" in words
    # a screened candidate that fits far better decides: then nothing to say
    better = pl.DataFrame({"candidate": ["x", "generic_control"], "kind": ["parameter", "control"],
                           "chi2": [1.0, 0.5]})  # fmt: skip
    assert unexplained_words(data, pred, [better]) == ""
    assert UNEXPLAINED_P_VALUE == 1e-6
    # in the verdict: after what was found, or after "structured residual"
    assert verdict_text([], [], 1e-9, unexplained=words) == f"structured residual {words}"
    tied = verdict_text([], ["a", "b"], 1e-9, unexplained=words)
    assert tied.startswith("tie: a | b") and tied.endswith(words)
    assert verdict_text([], [], 1e-3) == "structured residual not explained by any known effect"


# ---------------------------------------------------------------- diagnoses


def test_speeds_given_in_rad_s_are_flagged(base):
    rad_s = _measured(base, RPM).with_columns(
        (pl.col("speed_rpm") * np.pi / 30.0).round(0).alias("speed_rpm")
    )
    assert sorted(set(rad_s["speed_rpm"])) == [314.0, 628.0, 942.0, 1257.0]
    d = tb.diagnose(base, rad_s)
    assert "not explained by any known effect" in d.verdict, d.verdict
    assert "speed_rpm looks like rad/s" in d.verdict and "30/pi" in d.verdict


def test_data_the_baseline_explains_get_no_unexplained_words(base):
    d = tb.diagnose(base, _measured(base, RPM))
    assert "not explained" not in d.verdict and "likely cause" not in d.verdict, d.verdict


# ---------------------------------------------------------------- data that look wrong


def _table(quantity, values, speeds=(3000.0, 6000.0, 9000.0)) -> pl.DataFrame:
    return pl.DataFrame({"speed_rpm": list(speeds), "axial_n": 300.0, "quantity": quantity,
                         "value": list(values)})  # fmt: skip


def test_a_stiffness_in_n_per_um_is_refused_naming_the_unit():
    with pytest.raises(tb.DataError, match=r"invalid value = 180 for k_xx_n_per_m: .*N/um"):
        tb.load_measurements(_table("k_xx_n_per_m", [180.0, 175.0, 170.0]))
    spindle = pl.DataFrame({"speed_rpm": [3000.0, 6000.0], "preload_n": 300.0,
                            "quantity": "k_xx_n_per_m", "value": [150.0, 140.0]})  # fmt: skip
    with pytest.raises(tb.DataError, match="looks like N/um"):  # the spindle's range starts at 0
        tb.load_measurements(spindle, model="spindle")
    tb.load_measurements(_table("k_xx_n_per_m", [1.8e8, 1.75e8, 1.7e8]))  # N/m: fine


def test_a_temperature_in_kelvin_is_refused():
    with pytest.raises(tb.DataError, match="looks like kelvin"):
        tb.load_measurements(_table("outer_ring_temperature_c", [303.0, 306.0, 309.0]))


def test_readings_that_look_wrong_warn():
    with pytest.warns(tb.PlausibilityWarning, match=r"axial_displacement_um .* in mm\?"):
        tb.load_measurements(_table("axial_displacement_um", [0.012, 0.0123, 0.0126]))
    with pytest.warns(tb.PlausibilityWarning, match=r"heat_w = 0 at speed_rpm = 6000"):
        tb.load_measurements(_table("heat_w", [20.0, 0.0, 60.0]))
    # one speed is no mistake for a calibration (no warning); the diagnosis,
    # which compares speed laws, notes it
    one_speed = _table("heat_w", [20.0, 21.0, 22.0], speeds=[6000.0] * 3)
    one_speed = tb.load_measurements(one_speed.with_columns(pl.Series("run", ["a", "b", "c"])))
    note = one_speed_note(one_speed)
    assert note is not None and note.startswith("every row is at speed_rpm = 6000")
    assert one_speed_note(tb.load_measurements(_table("heat_w", [20.0, 40.0, 60.0]))) is None
    with warnings.catch_warnings():  # plausible readings: silent
        warnings.simplefilter("error", tb.PlausibilityWarning)
        tb.load_measurements(_table("axial_displacement_um", [120.0, 123.0, 126.0]))
        tb.load_measurements(_table("heat_w", [20.0, 40.0, 60.0]))
        static = _table("k_xx_n_per_m", [1.8e8, 1.8e8, 1.8e8], speeds=[0.0] * 3)
        tb.load_measurements(static.with_columns(pl.Series("run", ["a", "b", "c"])))
