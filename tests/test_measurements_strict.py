"""A measurement loader that refuses to guess: duplicate rows, unknown
columns, booleans as numbers, speeds and loads out of range are errors
that say what is wrong; run labels stay text; a default sigma is never 0."""

from __future__ import annotations

import warnings
from importlib import resources

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear.diagnosis.measurements import (
    KNOWN_COLUMNS,
    QUANTITIES,
    SIGMA_FLOOR,
    default_sigma,
    synthetic_measurements,
)


def _rows(**extra) -> dict:
    base = {
        "speed_rpm": [6000.0, 6000.0, 9000.0],
        "axial_n": [300.0, 300.0, 300.0],
        "radial_n": [0.0, 0.0, 0.0],
        "quantity": ["outer_ring_temperature_c", "heat_w", "outer_ring_temperature_c"],
        "value": [40.0, 50.0, 45.0],
    }
    base.update(extra)
    return base


def _csv(tmp_path, text: str):
    p = tmp_path / "m.csv"
    p.write_text(text)
    return p


def test_a_clean_table_loads():
    df = tb.load_measurements(pl.DataFrame(_rows()))
    assert df.height == 3 and df["run"].to_list() == ["1"] * 3


def test_duplicate_rows_are_an_error_naming_the_conflict():
    rows = _rows()
    dup = {k: v + [v[0]] for k, v in rows.items()}  # an exact copy of row 0
    with pytest.raises(tb.DataError, match="1 duplicated measurement.*2 rows, value 40"):
        tb.load_measurements(pl.DataFrame(dup))
    dup["value"][-1] = 43.0  # the copy disagrees
    with pytest.raises(tb.DataError, match="conflicting values 40, 43") as info:
        tb.load_measurements(pl.DataFrame(dup))
    msg = str(info.value)
    assert "outer_ring_temperature_c at speed_rpm=6000" in msg and 'duplicates="mean"' in msg


def test_duplicates_are_averaged_only_when_asked():
    rows = _rows()
    four = {k: v + [v[0]] * 3 for k, v in rows.items()}
    four["value"][-3:] = [41.0, 42.0, 43.0]
    four["sigma"] = [0.5, 1.0, 0.5, 0.5, 0.5, 0.5]
    df = tb.load_measurements(pl.DataFrame(four), duplicates="mean")
    assert df.height == 3  # counted once, not four times
    row = df.filter((pl.col("speed_rpm") == 6000.0) & (pl.col("quantity") != "heat_w"))
    assert row["value"][0] == pytest.approx(41.5)  # mean of 40, 41, 42, 43
    assert row["sigma"][0] == pytest.approx(0.5 / 2)  # sqrt(4 * 0.25) / 4: sigma / sqrt(n)
    with pytest.raises(tb.ConfigError, match="duplicates"):
        tb.load_measurements(pl.DataFrame(four), duplicates="first")


def test_repeats_with_their_own_run_labels_are_not_duplicates():
    rows = _rows()
    two = {k: v + [v[0]] for k, v in rows.items()}
    two["run"] = ["a", "a", "a", "b"]
    assert tb.load_measurements(pl.DataFrame(two)).height == 4


def test_an_unknown_column_is_named_with_its_near_miss():
    rows = _rows(RADIAL_N=[100.0, 100.0, 100.0])
    del rows["radial_n"]
    with pytest.raises(tb.DataError, match="RADIAL_N: did you mean radial_n\\?") as info:
        tb.load_measurements(pl.DataFrame(rows))
    assert "known columns: " + ", ".join(KNOWN_COLUMNS) in str(info.value)
    with pytest.raises(tb.DataError, match="unknown column.*sensor_id"):
        tb.load_measurements(pl.DataFrame(_rows(sensor_id=["x", "y", "z"])))


def test_run_labels_stay_text(tmp_path):
    p = _csv(
        tmp_path,
        "speed_rpm,axial_n,quantity,value,run\n"
        "6000,300,outer_ring_temperature_c,40,1\n"
        "6000,300,outer_ring_temperature_c,41,01\n",
    )
    df = tb.load_measurements(p)
    assert sorted(df["run"].to_list()) == ["01", "1"]  # two runs, not one duplicated point


def test_booleans_are_not_numbers(tmp_path):
    p = _csv(
        tmp_path,
        "speed_rpm,axial_n,quantity,value\n6000,true,outer_ring_temperature_c,40\n",
    )
    with pytest.raises(tb.DataError, match="invalid axial_n = 'true' in row 0: not numeric"):
        tb.load_measurements(p)
    frame = pl.DataFrame(_rows(axial_n=[True, True, True]))
    with pytest.raises(tb.DataError, match="invalid axial_n: booleans are not numbers"):
        tb.load_measurements(frame)


@pytest.mark.parametrize(
    ("speed", "quantity", "match"),
    [
        (0.0, "outer_ring_temperature_c", "speed_rpm = 0 in row 0 .*0 < speed_rpm <= 500000"),
        (1e7, "outer_ring_temperature_c", "speed_rpm = 1e\\+07 .*accepted range"),
        (1e7, "k_xx_n_per_m", "speed_rpm = 1e\\+07"),
    ],
)
def test_speeds_are_range_checked_on_load(speed, quantity, match):
    value = 40.0 if quantity.endswith("_c") else 1e8
    frame = pl.DataFrame(
        {"speed_rpm": [speed], "axial_n": [300.0], "quantity": [quantity], "value": [value]}
    )
    with pytest.raises(tb.DataError, match=match):
        tb.load_measurements(frame)


def test_a_static_stiffness_may_be_measured_at_standstill():
    frame = pl.DataFrame(
        {"speed_rpm": [0.0], "axial_n": [300.0], "quantity": ["k_xx_n_per_m"], "value": [1e8]}
    )
    assert tb.load_measurements(frame).height == 1


def test_loads_are_range_checked_on_load():
    with pytest.raises(tb.DataError, match="invalid axial_n = 2e\\+06 .*0 .. 1e\\+06 N"):
        tb.load_measurements(pl.DataFrame(_rows(axial_n=[300.0, 300.0, 2e6])))
    with pytest.raises(tb.DataError, match="invalid radial_n = -5e\\+06"):
        tb.load_measurements(pl.DataFrame(_rows(radial_n=[0.0, 0.0, -5e6])))


def test_a_zero_heat_reading_gets_a_positive_sigma_in_its_unit():
    df = tb.load_measurements(pl.DataFrame(_rows(value=[40.0, 0.0, 45.0])))
    heat = df.filter(pl.col("quantity") == "heat_w")
    assert heat["sigma"][0] == SIGMA_FLOOR["heat_w"] == 0.5
    # Every quantity of every registry: a default sigma > 0 even at value 0.
    from thermobear.diagnosis.spindle_spec import SPINDLE_QUANTITIES

    for table in (QUANTITIES, SPINDLE_QUANTITIES):
        names = list(table)
        assert (default_sigma(table, names, np.zeros(len(names))) > 0).all()
    # Above the floor the relative sigma holds: 2 % of 100 W.
    assert default_sigma(QUANTITIES, ["heat_w"], np.array([100.0]))[0] == pytest.approx(2.0)


def test_a_zero_heat_reading_diagnoses_without_a_linear_algebra_error():
    truth = tb.BearingModelSpec(tb.Bearing.preset("7008C"))
    cond = pl.DataFrame(
        {
            "speed_rpm": [6000.0, 9000.0, 12000.0, 15000.0] * 2,
            "axial_n": [300.0] * 8,
            "radial_n": [0.0] * 8,
            "quantity": ["outer_ring_temperature_c"] * 4 + ["heat_w"] * 4,
        }
    )
    data = synthetic_measurements(truth, cond, noise=1.0, seed=1).drop("sigma")
    data = data.with_columns(
        pl.when(pl.col("quantity") == "heat_w").then(0.0).otherwise(pl.col("value")).alias("value")
    )
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        d = tb.diagnose(truth, data, holdout=None)
    assert d.verdict


def test_the_data_files_shipped_with_the_package_still_load():
    df = tb.seed_b_measurements()
    assert df.height >= 3 and (df["sigma"] > 0).all()
    path = resources.files("thermobear.configs").joinpath("seed_b_measurements.csv")
    with resources.as_file(path) as p:
        from thermobear.diagnosis.spindle_spec import SPINDLE_QUANTITIES

        assert tb.load_measurements(p, SPINDLE_QUANTITIES).equals(df)
