"""Calibrating a gear pair against its bifurcation diagram: transition
speeds read off a sweep, the gear measurement table, the design-based
calibration recovering known inputs, and the calibrated gear model in
every downstream call."""

from __future__ import annotations

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear.gear.transitions import model_value, smoothed, speed_class, sweep_events

PAIR = tb.GearPair.preset("seed-electric-drive")


# -- transition speeds of one sweep -------------------------------------------


def test_speed_classes_follow_what_a_diagram_shows():
    assert speed_class("period-1", 1) == "P1"
    assert speed_class("period-2", 2) == "Pn"
    assert speed_class("period-4", 4) == "Pn"
    # five or more points per speed read as a cloud, as chaos does
    assert speed_class("period-5", 5) == "C"
    assert speed_class("chaotic", 0) == "C"
    assert speed_class("quasi-periodic", 0) == "C"


def test_a_single_odd_speed_between_agreeing_neighbours_is_absorbed():
    assert smoothed(["P1", "C", "P1", "P1"]) == ["P1", "P1", "P1", "P1"]
    # two in a row are a range and stay
    assert smoothed(["P1", "P1", "C", "C", "P1", "P1"]) == ["P1", "P1", "C", "C", "P1", "P1"]
    # an end entry unlike the next two (which agree) takes theirs
    assert smoothed(["C", "P1", "P1"]) == ["P1", "P1", "P1"]
    assert smoothed(["C", "P1", "Pn"]) == ["C", "P1", "Pn"]
    # a window narrower than the minimum inside chaos is part of the cloud
    assert smoothed(["C", "C", "P1", "P1", "C", "C"], min_window=3) == ["C"] * 6
    three = ["C", "C", "P1", "P1", "P1", "C", "C"]
    assert smoothed(three, min_window=3) == three


def test_events_of_a_hand_made_sweep():
    # speeds 1000 .. 10000 step 1000: P1 P1 P1 P2 P2 C C P1 C C (ascending)
    sp = np.arange(1000.0, 10001.0, 1000.0)
    regimes = ["period-1"] * 3 + ["period-2"] * 2 + ["chaotic"] * 2 + ["period-1"] + ["chaotic"] * 2
    periods = [1, 1, 1, 2, 2, 0, 0, 1, 0, 0]
    jumps = [False, True] + [False] * 8  # a jump from 2000 to the next speed of the sweep
    up = sweep_events(sp, regimes, periods, jumps, "up")
    assert up["period1_end_speed_rpm"].tolist() == [3500.0]
    assert up["jump_speed_rpm"].tolist() == [2500.0]
    assert up["period2_speed_rpm"].tolist() == [4000.0, 5000.0]
    assert up["multiperiod_end_speed_rpm"].tolist() == [5500.0]
    # the lone P1 at 8000 sits between C and C: absorbed, one chaotic range to the end
    assert up["chaos_start_speed_rpm"].tolist() == [5500.0]
    assert up["chaos_end_speed_rpm"].tolist() == [10000.0]
    assert up["window_start_speed_rpm"].size == 0
    # decelerating, the same jump flag points at the lower speed
    down = sweep_events(sp, regimes, periods, jumps, "down")
    assert down["jump_speed_rpm"].tolist() == [1500.0]


def test_a_periodic_window_open_at_the_top_of_the_sweep():
    sp = np.arange(1000.0, 6001.0, 1000.0)
    regimes = ["period-1", "chaotic", "chaotic", "period-1", "period-1", "period-1"]
    ev = sweep_events(sp, regimes, [1, 0, 0, 1, 1, 1], [False] * 6, "up")
    assert ev["window_start_speed_rpm"].tolist() == [3500.0]
    assert ev["window_end_speed_rpm"].tolist() == [6000.0]


def test_model_value_nearest_event_and_bounds():
    ev = {
        ("speed", "up"): {"jump_speed_rpm": np.array([6700.0, 10200.0])},
        ("speed", "down"): {"jump_speed_rpm": np.array([6600.0])},
        ("thermal", "down"): {"jump_speed_rpm": np.array([7200.0, 9000.0])},
    }
    assert model_value(ev, "jump_speed_rpm", 10000.0, "speed", "up") == 10200.0
    assert model_value(ev, "jump_speed_rpm", 7000.0, "any", "down") == 7200.0
    # "below 7500 in every case": each sweep's lowest jump, the highest of them
    assert model_value(ev, "jump_speed_rpm", 7500.0, "any", "down", "<=") == 7200.0
    assert np.isnan(model_value(ev, "jump_speed_rpm", 7000.0, "constant", "up"))


# -- the measurement table -----------------------------------------------------


def _table(**over):
    d = {
        "speed_rpm": [9000.0, 12000.0],
        "torque_n_m": [100.0, 100.0],
        "stiffness": ["speed", "thermal"],
        "direction": ["up", "any"],
        "quantity": ["period1_end_speed_rpm", "period2_speed_rpm"],
        "value": [9000.0, 12000.0],
    }
    d.update(over)
    return pl.DataFrame(d)


def test_gear_measurements_are_recognised_and_checked():
    df = tb.load_measurements(_table())
    assert df.columns == ["speed_rpm", "torque_n_m", "stiffness", "direction", "quantity",
                          "value", "sigma", "run"]  # fmt: skip
    assert (df["sigma"] == 50.0).all()  # a speed read off a diagram (the typical sigma)
    with pytest.raises(tb.DataError, match="stiffness"):
        tb.load_measurements(_table(stiffness=["speed", "warm"]))
    with pytest.raises(tb.DataError, match="direction"):
        tb.load_measurements(_table(direction=["up", "sideways"]))
    with pytest.raises(tb.DataError, match="did you mean stiffness"):
        tb.load_measurements(_table().rename({"stiffness": "stifness"}))
    with pytest.raises(tb.DataError, match="duplicated"):
        tb.load_measurements(pl.concat([_table(), _table()]))


# -- calibration recovers known inputs -------------------------------------------

#: A quick grid and sweep for the synthetic "paper".
GRID = np.arange(9000.0, 14001.0, 100.0).tolist()
SWEEP = {"transient_periods": 150, "record_periods": 64, "lyapunov_periods": 50}


def _spec(**options):
    return tb.GearModelSpec(
        PAIR, torque_n_m=100.0, sweep_speeds_rpm=GRID, sweep_options=SWEEP, **options
    )


@pytest.fixture(scope="module")
def synthetic_paper():
    """A "paper" made with known inputs (TE 30 um, mesh stiffness 0.9 of
    the computed, mesh damping 0.1): the transitions a reader takes off its
    diagrams outside the chaotic fine structure -- the end of the low-speed
    period-1 motion, the first jump, the first period-2 speed, in both
    sweep directions -- read off a figure (sigma 150 rpm, the reading
    scatter drawn with a fixed seed) and printed to 10 rpm."""
    truth = _spec(te_amplitude_um=30.0, mesh_stiffness_scale=0.9, mesh_damping_ratio=0.1)
    cond = pl.DataFrame({"speed_rpm": [10000.0] * 2, "torque_n_m": [100.0] * 2,
                         "stiffness": ["speed"] * 2, "direction": ["up", "down"]})  # fmt: skip
    rows = []
    for (_, d), e in truth.events(cond).items():
        for q in ("period1_end_speed_rpm", "jump_speed_rpm", "period2_speed_rpm"):
            rows += [(float(e[q][0]), d, q)] if e[q].size else []
    assert len(rows) >= 4, "the truth must show transitions in the grid"
    read = np.array([r[0] for r in rows]) + np.random.default_rng(5).normal(0.0, 150.0, len(rows))
    value = np.round(read, -1)
    return truth, pl.DataFrame(
        {"speed_rpm": value, "torque_n_m": 100.0, "stiffness": "speed",
         "direction": [r[1] for r in rows], "quantity": [r[2] for r in rows], "value": value,
         "sigma": 150.0},
    )  # fmt: skip


def test_calibration_recovers_the_inputs_of_a_synthetic_paper(synthetic_paper):
    """The two inputs the synthetic paper was made with lie inside their
    95 % intervals (the chi^2 of transition speeds is rough; the interval
    spans its bowl, see thermobear.diagnosis.gear_calibration)."""
    _, measured = synthetic_paper
    base = _spec(mesh_damping_ratio=0.1)
    cal = tb.calibrate([(base, measured)], ["te_amplitude_um", "mesh_stiffness_scale"],
                       design_points=32, refine_points=16, refine_rounds=2)  # fmt: skip
    p = {r["name"]: r for r in cal.parameters.iter_rows(named=True)}
    for name, true in (("te_amplitude_um", 30.0), ("mesh_stiffness_scale", 0.9)):
        assert p[name]["lower_95"] <= true <= p[name]["upper_95"], (name, p[name])
        # and the interval says something: narrower than half the bounds
        assert p[name]["upper_95"] - p[name]["lower_95"] < 0.5 * (
            p[name]["upper"] - p[name]["lower"]
        )
    # the fit is better than the baseline's, and every point of the design is kept
    assert cal.chi2 < cal.chi2_before
    assert cal.design.height >= 1 + 32 + 2 * 16
    assert cal.design["within_95"].sum() >= 1


def test_calibrated_gear_model_downstream(synthetic_paper):
    _, measured = synthetic_paper
    cal = tb.calibrate([(_spec(), measured)], ["te_amplitude_um"], design_points=4,
                       refine_points=0, refine_rounds=0)  # fmt: skip
    model = cal.model
    te = float(model.values[0])
    # saved and loaded like a bearing's
    again = tb.CalibratedModel.from_json(model.to_json())
    assert again == model
    # a system of it uses the calibrated input, in any stiffness case
    gs = tb.GearSystem(model, stiffness="constant")
    assert gs.params["te_amplitude_um"] == pytest.approx(te)
    assert gs.stiffness_case == "constant"
    # giving the input again with another value would undo the calibration
    with pytest.raises(tb.ConfigError, match="te_amplitude_um"):
        tb.GearSystem(model, te_amplitude_um=te + 1.0)
    # the sweep of the model is the sweep of its system
    speeds = [10000.0, 11000.0, 12000.0]
    a = tb.bifurcation(model, speeds, "up", **SWEEP)
    b = tb.bifurcation(tb.GearSystem(model), speeds, "up", **SWEEP)
    assert a.equals(b)
    rm = tb.regime_map(model, [100.0], [11000.0], **SWEEP)
    assert rm.height == 1


def test_predictions_of_a_calibrated_gear_model(synthetic_paper):
    """``predict`` on a calibrated gear model: the regimes sampled over its
    inputs, and each measured transition's sampled band (never the delta
    method: the transitions jump with the inputs)."""
    _, measured = synthetic_paper
    cal = tb.calibrate([(_spec(), measured)], ["te_amplitude_um"], design_points=8,
                       refine_points=8, refine_rounds=1)  # fmt: skip
    model = cal.model
    reg = tb.predict(model, "regimes", {"speeds_rpm": [10000.0, 11000.0, 12000.0]}, samples=8,
                     direction="up", sweep_options=SWEEP)  # fmt: skip
    prob = reg.filter(pl.col("quantity") == "regime_probability")
    # at every speed the regimes' shares add up to one
    for (_,), g in prob.group_by(["speed_rpm"]):
        assert g["value"].sum() == pytest.approx(1.0)
    cond = measured.select("speed_rpm", "torque_n_m", "stiffness", "direction")
    band = tb.predict(model, "measured", cond, samples=8)
    assert set(band["method"]) == {"sampling"}
    got = band.drop_nulls(["lower", "upper"]).filter(pl.col("lower").is_not_nan())
    assert got.height > 0 and (got["lower"] <= got["upper"]).all()
    with pytest.raises(tb.ConfigError, match="delta"):
        tb.predict(model, "measured", cond, method="delta")


def test_bad_gear_calibration_input_is_named(synthetic_paper):
    _, measured = synthetic_paper
    with pytest.raises(tb.ConfigError, match="sweep_step"):
        tb.GearModelSpec(PAIR, sweep_step_typo=10.0)
    with pytest.raises(tb.ConfigError, match="stiffness"):
        tb.GearModelSpec(PAIR, stiffness="warm")
    with pytest.raises(tb.ConfigError, match="effects"):
        tb.GearModelSpec(PAIR, effects=["centrifugal_force"])
    spec = _spec()
    with pytest.raises(tb.ConfigError, match="parameter = 'te_um'"):
        tb.calibrate([(spec, measured)], ["te_um"], design_points=2)
    with pytest.raises(tb.ConfigError, match="design_points"):
        tb.calibrate([(spec, measured)], ["te_amplitude_um"], design_points=0)
    with pytest.raises(tb.ConfigError, match="per_set"):
        tb.calibrate([(spec, measured)], ["te_amplitude_um"], per_set=["te_amplitude_um"])
    bearing = tb.BearingModelSpec(tb.Bearing.preset("6208"))
    with pytest.raises(tb.ConfigError, match="gear pair cannot share"):
        tb.calibrate([(spec, measured), (bearing, measured)], ["te_amplitude_um"])
    with pytest.raises(tb.ConfigError, match="design_points"):
        tb.calibrate([(bearing, measured)], ["lubrication_factor_f0"], design_points=8)
