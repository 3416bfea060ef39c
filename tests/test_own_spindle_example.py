"""The worked example "your own spindle" (examples/own_spindle.toml, its
synthetic measurements and docs/how-to/own-spindle.md) holds what it claims:
the file round-trips, the thermal state balances its heat, the front pair is
two 7014C-hybrid bearings, the critical speeds lie on the Campbell diagram,
and the calibration on the synthetic measurements finds the value hidden in
them and predicts the unmeasured speeds within its band."""

from __future__ import annotations

import importlib.util
import re
import sys
import warnings
from pathlib import Path

import numpy as np
import polars as pl
import pytest

import thermobear as tb

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = ROOT / "examples"
DESCRIPTION = EXAMPLES / "own_spindle.toml"
MEASURED = EXAMPLES / "own_spindle_measurements.csv"
PAGE = ROOT / "docs" / "how-to" / "own-spindle.md"
SPEEDS_RPM = [3000.0, 9000.0, 18000.0]
#: Speeds the calibration predicts but was not given (the measured ones
#: reach 12,000 rpm).
UNMEASURED_RPM = [15000.0, 18000.0]


def _script():
    """examples/make_own_spindle_measurements.py as a module."""
    path = EXAMPLES / "make_own_spindle_measurements.py"
    spec = importlib.util.spec_from_file_location("make_own_spindle_measurements", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def script():
    return _script()


@pytest.fixture(scope="module")
def spindle() -> tb.Spindle:
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no plausibility warning on the example
        return tb.Spindle.from_toml(DESCRIPTION)


@pytest.fixture(scope="module")
def states(spindle: tb.Spindle) -> pl.DataFrame:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        return spindle.thermal_state_many({"speed_rpm": SPEEDS_RPM})


@pytest.fixture(scope="module")
def calibration(spindle: tb.Spindle):
    guess = spindle.parts["lubrication"].lubrication_factor_f0
    model = tb.SpindleModelSpec.of_model(spindle).with_setting(lubrication_factor_f0=guess)
    return tb.calibrate([(model, tb.load_measurements(MEASURED))], ["lubrication_factor_f0"]), model


def _page_file(title: str) -> str:
    found = re.search(rf'```\w+ title="{re.escape(title)}"\n(.*?)```', PAGE.read_text(), re.S)
    assert found, f"the page shows no file {title}"
    return found[1]


def test_the_page_shows_the_example_files():
    assert _page_file("own_spindle.toml") == DESCRIPTION.read_text(encoding="utf-8")
    assert _page_file("own_spindle_measurements.csv") == MEASURED.read_text(encoding="utf-8")


def test_every_line_of_the_description_says_what_it_is():
    for n, line in enumerate(DESCRIPTION.read_text().splitlines(), 1):
        if line.strip() and not line.startswith("#"):
            assert " # " in line, f"own_spindle.toml:{n} has no comment: {line!r}"


def test_the_measurement_file_is_what_the_script_makes(script):
    """The script makes the file: the same header and rows, each value the
    same to its last printed digit (a rounding flip from a last-bit change of
    the model is let through: 0.01 of slack)."""
    made, kept = script.csv_text().splitlines(), MEASURED.read_text(encoding="utf-8").splitlines()
    assert len(made) == len(kept)
    for a, b in zip(made, kept, strict=True):
        if a.startswith("#") or a.startswith("speed_rpm"):
            assert a == b
            continue
        *conditions, value, sigma = a.split(",")
        *conditions_b, value_b, sigma_b = b.split(",")
        assert (conditions, sigma) == (conditions_b, sigma_b)
        assert abs(float(value) - float(value_b)) <= 0.0101, (a, b)
    made = tb.load_measurements(MEASURED)
    assert made.height == len(script.SPEEDS_RPM) * len(script.QUANTITIES)
    assert made["speed_rpm"].max() == 12000.0


def test_the_description_round_trips_to_the_last_bit(spindle: tb.Spindle):
    text = spindle.to_toml()
    again = tb.Spindle.from_toml(text)
    assert again.to_toml() == text
    assert again._native.config_json() == spindle._native.config_json()
    assert again.rotor_layout == spindle.rotor_layout
    for speed in (6000.0, 15000.0):
        assert again.thermal_state(speed).equals(spindle.thermal_state(speed))


def test_the_parts_are_the_files(spindle: tb.Spindle):
    parts = spindle.parts
    assert (parts["front"], parts["rear"]) == ("7014C-hybrid", "7012C-hybrid")
    assert parts["preload"] == tb.Preload(kind="spring", preload_n=600.0, spring_rate_n_per_um=0.5)
    assert parts["lubrication"].oil_volume_cm3_per_h == 0.12
    assert spindle.rotor_layout is not None  # its own rotor, not the seed's


def test_the_thermal_state_balances_its_heat(states: pl.DataFrame):
    total, out = states["total_heat_w"].to_numpy(), states["boundary_flow_w"].to_numpy()
    np.testing.assert_allclose(out, total, rtol=1e-10)
    parts = states["motor_losses_w"] + states["bearing_heat_w"]
    np.testing.assert_allclose(parts.to_numpy(), total, rtol=1e-10)
    # the motor's losses are the file's four, each with its speed law (12,000 rpm reference)
    at_ref = states.filter(pl.col("speed_rpm") == 9000.0)["motor_losses_w"][0]
    assert at_ref == pytest.approx(420.0 + 160.0 + 300.0 * 0.75**1.5 + 90.0 * 0.75**2)
    # heat flows from the bearings out to the water
    for r in states.iter_rows(named=True):
        assert r["front_inner_ring_temperature_c"] > r["front_outer_ring_temperature_c"]
        assert r["front_outer_ring_temperature_c"] > r["front_housing_temperature_c"]
        assert r["front_housing_temperature_c"] > r["cooling_water_temperature_c"] == 20.0
    assert states["front_outer_ring_temperature_c"].is_sorted()
    assert states["operating_preload_n"].is_sorted() and states["operating_preload_n"][0] > 600.0


def test_the_front_pair_is_two_7014c_hybrid_bearings(spindle: tb.Spindle):
    cold = spindle.isothermal(3000.0)
    one = tb.Bearing.preset("7014C-hybrid").solve(
        axial_n=cold["operating_preload_n"][0], radial_n=0.0, speed_rpm=3000.0
    )
    assert cold["k_xx_n_per_m"][0] == pytest.approx(2.0 * one.k_xx_n_per_m, rel=1e-9)
    assert cold["k_zz_n_per_m"][0] == pytest.approx(2.0 * one.k_zz_n_per_m, rel=1e-9)
    # the seed's smaller 7009C-hybrid pair at the same preload is softer
    seed = tb.Spindle.preset("seed-ceramic-spindle").with_options(preload_n=600.0)
    seed_k = seed.isothermal(3000.0)
    assert seed_k["operating_preload_n"][0] == pytest.approx(cold["operating_preload_n"][0], 0.01)
    assert cold["k_xx_n_per_m"][0] > 1.1 * seed_k["k_xx_n_per_m"][0]
    assert cold["k_zz_n_per_m"][0] > seed_k["k_zz_n_per_m"][0]


def test_heat_stiffens_what_speed_softens(spindle: tb.Spindle, states: pl.DataFrame):
    cold = [spindle.isothermal(n)["k_xx_n_per_m"][0] for n in SPEEDS_RPM]
    assert cold[0] > cold[1] > cold[2]  # centrifugal force of the balls
    assert all(h > c for h, c in zip(states["k_xx_n_per_m"], cold, strict=True))  # growth, preload


def test_the_critical_speeds_lie_on_the_campbell_diagram(spindle: tb.Spindle):
    critical = tb.critical_speeds(spindle)
    assert critical.height >= 1
    first = critical.sort("speed_rpm").row(0, named=True)
    assert first["speed_rpm"] > 2 * 18000.0  # well above the top speed
    # at each crossing, the branch's own frequency is the speed's (1X)
    at = tb.campbell(spindle, speeds_rpm=critical["speed_rpm"].to_list(), modes=4)
    for r in critical.iter_rows(named=True):
        f = at.filter((pl.col("speed_rpm") == r["speed_rpm"]) & (pl.col("mode") == r["branch"]))
        assert f["whirl"][0] == r["whirl"]
        assert f["frequency_hz"][0] == pytest.approx(r["speed_rpm"] / 60.0, rel=1e-3)
    # and the mode lies above 1X below the first crossing, below it beyond
    grid = tb.campbell(spindle, speeds_rpm=[0.9 * first["speed_rpm"], 1.1 * first["speed_rpm"]])
    mode = grid.filter(pl.col("mode") == first["branch"])
    assert mode["frequency_hz"][0] > mode["speed_rpm"][0] / 60.0
    assert mode["frequency_hz"][1] < mode["speed_rpm"][1] / 60.0


def test_the_calibration_finds_the_hidden_value(calibration, script):
    cal, _ = calibration
    row = cal.parameters.row(0, named=True)
    assert row["name"] == "lubrication_factor_f0"
    assert row["lower_95"] <= script.HIDDEN_F0 <= row["upper_95"]
    assert not row["lower_95"] <= row["null"] <= row["upper_95"]  # the file's guess is out
    assert cal.chi2 < cal.chi2_before / 10


def test_the_prediction_band_holds_the_truth_at_unmeasured_speeds(calibration, script):
    cal, model = calibration
    grid = {"speeds_rpm": UNMEASURED_RPM, "preload_n": 600.0}
    prediction = tb.predict(cal, "measured", grid)
    conditions = pl.DataFrame({"speed_rpm": UNMEASURED_RPM, "preload_n": 600.0})
    truth = script.truth().predict(conditions)
    guess = model.predict(conditions)
    for q in script.QUANTITIES:
        rows = prediction.filter(pl.col("quantity") == q).sort("speed_rpm")
        lo, hi = rows["lower"].to_numpy(), rows["upper"].to_numpy()
        assert np.all((lo <= truth[q]) & (truth[q] <= hi)), q
        assert np.all((guess[q] < lo) | (guess[q] > hi)), q  # the file alone is outside
    beyond = prediction.filter(pl.col("quantity") == script.QUANTITIES[0]).sort("speed_rpm")
    assert beyond["speed_beyond_measured"].to_list() == [0.25, 0.5]
