"""One verb per task: the diagnosis verbs dispatch on the model they are
given (bearing or spindle), the deprecated spindle twins warn, the batch
thermal state has the same method and function form on every model,
every result object has ``summary()`` and a one-line repr, the defaults
are the documented ones, and sweeps check their settings before any work."""

from __future__ import annotations

import inspect
import time
from importlib import resources

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear import diagnosis as D
from thermobear.errors import ConfigError, DataError
from thermobear.gear.dynamics import DEFAULT_STEPS_PER_PERIOD, sweep_steps

SPEEDS_RPM = [3000.0, 6000.0, 9000.0, 12000.0]


@pytest.fixture(scope="module")
def bearing() -> tb.Bearing:
    return tb.Bearing.preset("7008C")


@pytest.fixture(scope="module")
def spindle() -> tb.Spindle:
    return tb.Spindle.preset("seed-ceramic-spindle")


@pytest.fixture(scope="module")
def bearing_data(bearing) -> pl.DataFrame:
    """Synthetic measurements of the bearing as configured: heat and one
    ring temperature at four speeds, noise at the typical sigma."""
    temp = next(q for q in D.QUANTITIES if "outer_ring" in q or q.endswith(":To"))
    cond = pl.DataFrame(
        {
            "speed_rpm": np.repeat(SPEEDS_RPM, 2),
            "axial_n": 300.0,
            "radial_n": 0.0,
            "quantity": ["heat_w", temp] * len(SPEEDS_RPM),
        }
    )
    return D.synthetic_measurements(D.BearingModelSpec(bearing), cond, noise=1.0, seed=3)


def _seed_b_raw() -> pl.DataFrame:
    """Seed B's measurement file as it is on disk (not yet checked)."""
    path = resources.files("thermobear.configs").joinpath("seed_b_measurements.csv")
    with resources.as_file(path) as p:
        return pl.read_csv(p, comment_prefix="#")


# -- dispatch on the model ----------------------------------------------------------


def test_load_measurements_recognises_bearing_and_spindle_data(bearing_data):
    # spindle data: recognised by their quantities, the same table as seed B's loader
    raw = _seed_b_raw()
    assert tb.load_measurements(raw).equals(tb.seed_b_measurements())
    assert tb.load_measurements(raw, model="spindle").equals(tb.seed_b_measurements())
    # bearing data: the bearing's registry
    got = tb.load_measurements(bearing_data)
    assert set(got["quantity"]) == set(bearing_data["quantity"]) and got.height == 8
    # the wrong model named: the error points to the other kind
    with pytest.raises(DataError, match="spindle quantity"):
        tb.load_measurements(raw, model="bearing")
    with pytest.raises(ConfigError, match="model"):
        tb.load_measurements(raw, model="gearbox")


def test_candidates_take_the_model_itself(bearing, spindle):
    assert tb.candidates(bearing).equals(tb.candidates(D.BearingModelSpec(bearing)))
    spec = tb.SpindleModelSpec(spindle, effects=list(spindle._native.effects))
    assert tb.candidates(spindle).equals(tb.candidates(spec))
    # the spindle as configured: an effect it leaves off is a candidate, one it has is not
    off = spindle.with_options(effects=["centrifugal_force"])
    names = tb.candidates(off)["name"].to_list()
    assert "gyroscopic_moment" in names and "centrifugal_force" not in names
    # a bearing's candidate list is not a spindle's
    assert "preload_scale" in tb.candidates(spindle)["name"].to_list()
    assert "preload_scale" not in tb.candidates(bearing)["name"].to_list()
    with pytest.raises(ConfigError, match="model"):
        tb.candidates("7008C")


def test_diagnose_and_calibrate_take_a_bearing_as_its_spec(bearing, bearing_data):
    kw = {"candidates": ["extra_heat_w"], "holdout": None, "outliers": False, "control": False}
    a = tb.diagnose(bearing, bearing_data, **kw)
    b = tb.diagnose(D.BearingModelSpec(bearing), bearing_data, **kw)
    assert a.verdict == b.verdict
    assert a.points["model_before"].to_list() == b.points["model_before"].to_list()
    c1 = tb.calibrate([(bearing, bearing_data)], ["extra_heat_w"])
    c2 = tb.calibrate([(D.BearingModelSpec(bearing), bearing_data)], ["extra_heat_w"])
    assert c1.parameters["value"].to_list() == c2.parameters["value"].to_list()
    # data made by the model as configured: no extra heat needed (0 W in the interval)
    row = c1.parameters.row(0, named=True)
    assert row["lower_95"] <= 0.0 + 1e-9 <= row["upper_95"] or row["value"] < 1.0


def test_diagnose_takes_a_spindle_as_its_spec(spindle):
    sp = spindle.with_options(effects=["centrifugal_force"])
    data = tb.seed_b_measurements()
    kw = {"candidates": ["thermal_expansion_shaft"], "holdout": None, "outliers": False}
    a = tb.diagnose(sp, data, **kw)
    b = tb.diagnose(tb.SpindleModelSpec(spindle, effects=["centrifugal_force"]), data, **kw)
    assert a.verdict == b.verdict
    assert a.points["model_before"].to_list() == b.points["model_before"].to_list()


# -- deprecated twins ---------------------------------------------------------------


def test_deprecated_spindle_twins_warn_and_name_the_verb(spindle, bearing):
    raw = _seed_b_raw()
    with pytest.warns(DeprecationWarning, match="`load_measurements`"):
        old = tb.load_spindle_measurements(raw)
    assert old.equals(tb.load_measurements(raw))
    spec = tb.SpindleModelSpec(spindle, effects=[])
    with pytest.warns(DeprecationWarning, match="`candidates`"):
        cands = tb.spindle_candidates(spec)
    assert cands.equals(tb.candidates(spec))
    with pytest.warns(DeprecationWarning, match="`diagnose`"):
        with pytest.raises(ConfigError, match="SpindleModelSpec"):
            tb.diagnose_spindle(D.BearingModelSpec(bearing), raw)


# -- one form for the batch thermal state --------------------------------------------


def test_thermal_state_many_is_a_method_and_a_function_on_every_model(bearing, spindle):
    pts = {"speed_rpm": [5000.0, 8000.0], "axial_n": 300.0}
    assert bearing.thermal_state_many(pts).equals(tb.thermal_state_many(bearing, pts))
    one = bearing.thermal_state(8000.0, 300.0)
    assert one.total_heat_w == tb.thermal_state(bearing, 8000.0, 300.0).total_heat_w
    sp_pts = {"speed_rpm": [12000.0, 18000.0]}
    m = spindle.thermal_state_many(sp_pts)
    assert m.equals(tb.thermal_state_many(spindle, sp_pts))
    single = spindle.thermal_state(18000.0)
    assert m.row(1, named=True)["front_outer_ring_temperature_c"] == pytest.approx(
        single["front_outer_ring_temperature_c"][0], rel=0, abs=0
    )
    # heat grows with speed: the outer ring runs warmer at 18,000 rpm
    t = m["front_outer_ring_temperature_c"].to_list()
    assert t[1] > t[0] and m["ok"].all()


def test_a_failed_point_of_a_batch_keeps_the_finished_rows():
    # far beyond its speed limit the 6208 runs away: that row carries its
    # error, the other rows their results
    b = tb.Bearing.preset("6208")
    pts = {"speed_rpm": [4000.0, 200_000.0, 9000.0], "axial_n": 300.0, "radial_n": 500.0}
    df = b.thermal_state_many(pts, lubricant="ISO VG 32")
    assert df["ok"].to_list() == [True, False, True]
    assert df["error_kind"][1] == "ThermalRunawayError" and df["heat_w"][1] is None
    assert df["heat_w"][2] > df["heat_w"][0] > 0.0


# -- results: summary() and a one-line repr -------------------------------------------


def _one_line(obj) -> str:
    r = repr(obj)
    assert "\n" not in r and len(r) <= 160, r
    return r


def test_every_result_object_has_a_summary_and_a_one_line_repr(bearing, bearing_data):
    from thermobear.study.study import RunReport
    from thermobear.validation.result import SetResult

    sol = bearing.solve(axial_n=300.0, radial_n=200.0, speed_rpm=9000.0)
    assert "BearingSolution" in _one_line(sol)
    assert f"{sol.radial_displacement_um:.4g} um" in sol.summary()
    th = tb.thermal_state(bearing, 9000.0, 300.0)
    assert "ThermalState" in _one_line(th)
    assert "outer_ring_temperature_c" in th.summary() and f"{th.total_heat_w:.4g} W" in th.summary()
    ih = tb.isothermal_heat(bearing, 9000.0, 300.0, oil_temperature_c=40.0)
    assert "IsothermalHeat" in _one_line(ih) and f"{ih.total_heat_w:.4g} W" in ih.summary()
    kw = {"candidates": ["extra_heat_w"], "holdout": None, "outliers": False, "control": False}
    d = tb.diagnose(bearing, bearing_data, **kw)
    assert "Diagnosis" in _one_line(d) and d.verdict in d.summary()
    c = tb.calibrate([(bearing, bearing_data)], ["extra_heat_w"])
    assert "Calibration(extra_heat_w=" in _one_line(c)
    assert "extra_heat_w [all]" in c.summary() and "95 %" in c.summary()
    points = pl.DataFrame(
        {"value": [1.0, 2.0], "sigma": [0.1, 0.1], "model_before": [1.5, 2.0],
         "model_after": [1.05, 2.0], "heldout": [True, False]}
    )  # fmt: skip
    sr = SetResult("demo", "a demo set", "none", points, "no missing effect supported")
    assert "SetResult('demo', 2 points, passes)" == _one_line(sr)
    assert "baseline max |model - value| / sigma 5" in sr.summary()
    rr = RunReport(points=12, chunks=3, computed=2, reused=1, failed_points=2)
    assert "RunReport" in _one_line(rr) and "2 failed points" in rr.summary()


# -- defaults are the documented ones ---------------------------------------------------


def test_gear_defaults_are_the_documented_ones():
    pair = tb.GearPair.preset("seed-electric-drive")
    assert tb.GearSystem(pair).stiffness_case == "speed"
    assert inspect.signature(tb.bifurcation).parameters["direction"].default == "down"
    from pathlib import Path

    readme = (Path(__file__).resolve().parents[1] / "README.md").read_text()
    assert 'stiffness="speed"' in readme and 'direction="down"' in readme


# -- sweeps check their settings before any work ------------------------------------------


def test_bifurcation_checks_steps_at_every_speed_before_any_work():
    pair = tb.GearPair.preset("seed-electric-drive")
    gs = tb.GearSystem(pair, stiffness="constant", te_amplitude_um=10.0)
    speeds = list(range(1000, 20001, 100))  # 191 speeds; the slow ones need more steps
    calls = []
    t0 = time.perf_counter()
    with pytest.raises(ConfigError, match=r"steps_per_period = 64: too coarse at .*use at least"):
        tb.bifurcation(gs, speeds, steps_per_period=64, progress=lambda d, n: calls.append(d))
    assert time.perf_counter() - t0 < 2.0 and calls == []
    # the default adapts: the fewest steps every speed needs, and no fewer
    need = sweep_steps([gs], speeds, None)
    assert need > DEFAULT_STEPS_PER_PERIOD
    gs.check_steps(1000.0, need)
    with pytest.raises(ConfigError, match="steps_per_period"):
        gs.check_steps(1000.0, need - 1)
    # at high speeds the default stays 64
    assert sweep_steps([gs], [12000.0, 16000.0], None) == DEFAULT_STEPS_PER_PERIOD
