"""Inputs past what real machines are built or run with: each is warned
(``PlausibilityWarning``) or refused (``ConfigError``, ``DataError``) with
its field named, and a plausible neighbour is not (the docs page "Limits",
"Inputs past what real machines are built or run with")."""

from __future__ import annotations

import inspect
import sys
import warnings
from pathlib import Path

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear import _input_checks as checks

sys.path.insert(0, str(Path(__file__).parent))
from diagnose_toy import Rig, conditions, measured  # noqa: E402


def _quiet(call):
    """``call()`` with any PlausibilityWarning an error: the neighbour is plausible."""
    with warnings.catch_warnings():
        warnings.simplefilter("error", tb.PlausibilityWarning)
        return call()


# ------------------------------------------------------------------ bearing geometry

AC = dict(ball_count=16, ball_diameter_mm=7.938, pitch_diameter_mm=54.0, inner_conformity=0.52,
          outer_conformity=0.53, free_contact_angle_deg=15.0, bore_mm=40.0,
          outer_diameter_mm=68.0, width_mm=15.0)  # fmt: skip
DG = dict(ball_count=9, ball_diameter_mm=11.906, pitch_diameter_mm=60.0, inner_conformity=0.52,
          outer_conformity=0.53, diametral_clearance_mm=0.03, bore_mm=40.0,
          outer_diameter_mm=80.0, width_mm=18.0)  # fmt: skip


@pytest.mark.parametrize(
    ("build", "changed", "field"),
    [
        (tb.Bearing.angular_contact, {"ball_count": 3}, "ball_count"),
        (tb.Bearing.deep_groove, {"diametral_clearance_mm": 1.0}, "diametral_clearance_mm"),
        (tb.Bearing.angular_contact, {"width_mm": 0.01}, "width_mm"),
        (tb.Bearing.deep_groove, {"width_mm": 0.01}, "width_mm"),
    ],
)
def test_an_implausible_bearing_build_warns(build, changed, field):
    base = AC if build == tb.Bearing.angular_contact else DG
    with pytest.warns(tb.PlausibilityWarning, match=field):
        build(**{**base, **changed})


def test_plausible_bearing_builds_do_not_warn():
    _quiet(lambda: tb.Bearing.angular_contact(**{**AC, "ball_count": 7}))
    _quiet(lambda: tb.Bearing.deep_groove(**{**DG, "diametral_clearance_mm": 0.2}))  # 1.7 %
    _quiet(lambda: tb.Bearing.deep_groove(**{**DG, "width_mm": 12.0}))


def test_a_system_description_is_checked_as_the_constructor_checks():
    """``from_toml`` (the commands' way to a bearing) runs the same check."""
    text = '[bearing]\npreset = "7008C"\nball_count = {}\n'
    assert _quiet(lambda: tb.Bearing.from_toml(text.format(12))).geometry["ball_count"] == 12
    with pytest.warns(tb.PlausibilityWarning, match="ball_count = 3"):
        tb.Bearing.from_toml(text.format(3))


# ------------------------------------------------------------------ lubrication and oil


@pytest.fixture(scope="module")
def b7008() -> tb.Bearing:
    return tb.Bearing.preset("7008C")


def _heat(b, **kw):
    t = kw.pop("oil_temperature_c", 40.0)
    return tb.isothermal_heat(b, 10000.0, 500.0, oil_temperature_c=t, **kw).total_heat_w


@pytest.mark.parametrize(
    ("options", "field"),
    [
        ({"lubrication": "jet", "oil_flow_cm3_per_min": 0.0}, "oil_flow_cm3_per_min"),
        ({"lubrication": "jet", "oil_flow_cm3_per_min": 1e5}, "oil_flow_cm3_per_min"),
        ({"lubrication": "oil-air", "oil_volume_cm3_per_h": 0.0, "air_flow_l_per_min": 20.0},
         "oil_volume_cm3_per_h"),
        ({"lubrication": "oil-air", "oil_volume_cm3_per_h": 0.1, "air_flow_l_per_min": 0.0},
         "air_flow_l_per_min"),
        ({"lubrication": "oil-bath", "oil_level_mm": 500.0}, "oil_level_mm"),
        ({"lubrication": "grease", "grease_fill_fraction": 0.0}, "grease_fill_fraction"),
        ({"lubrication": "grease", "grease_fill_fraction": 1.0}, "grease_fill_fraction"),
        ({"oil_temperature_c": -40.0}, "oil_temperature_c"),
    ],
)  # fmt: skip
def test_an_implausible_supply_or_oil_temperature_warns(b7008, options, field):
    with pytest.warns(tb.PlausibilityWarning, match=field):
        _heat(b7008, **options)


@pytest.mark.parametrize(
    "options",
    [
        {"lubrication": "jet", "oil_flow_cm3_per_min": 500.0},
        {"lubrication": "oil-air", "oil_volume_cm3_per_h": 0.1, "air_flow_l_per_min": 20.0},
        {"lubrication": "oil-bath", "oil_level_mm": 30.0},
        {"lubrication": "grease", "grease_fill_fraction": 0.3},
        {"oil_temperature_c": -30.0},
    ],
)
def test_a_plausible_supply_or_oil_temperature_does_not_warn(b7008, options):
    assert _quiet(lambda: _heat(b7008, **options)) > 0.0


def test_the_grease_warning_says_the_fill_does_not_change_the_heat(b7008):
    """The fill is not in the heat model: 0, 0.3 and 1 give the same heat,
    and the warning says so rather than pretend."""
    with pytest.warns(tb.PlausibilityWarning, match="does not enter the heat model"):
        empty = _heat(b7008, lubrication="grease", grease_fill_fraction=0.0)
    full = _heat(b7008, lubrication="grease", grease_fill_fraction=0.3)
    assert empty == full
    # a complete fill is catalogue practice at very low n dm: no warning there
    slow = tb.isothermal_heat(b7008, 500.0, 500.0, oil_temperature_c=40.0, lubrication="grease",
                              grease_fill_fraction=1.0)  # fmt: skip
    assert _quiet(lambda: slow) is slow


def test_the_pour_points_are_the_native_lubricants(b7008):
    """The pour points of the check are the native model's lowest
    temperatures: one degree below is refused there."""
    for name, pour in (("ISO VG 32", -30.0), ("ISO VG 68", -24.0), ("e-drive ATF", -45.0)):
        with pytest.raises(tb.ConfigError, match="oil_temperature_c"):
            _heat(b7008, lubricant=name, oil_temperature_c=pour - 1.0)
        with pytest.warns(tb.PlausibilityWarning, match="pour point"):
            _heat(b7008, lubricant=name, oil_temperature_c=pour)
        _quiet(lambda n=name, p=pour: _heat(b7008, lubricant=n, oil_temperature_c=p + 10.0))


# ------------------------------------------------------------------ gears


@pytest.fixture(scope="module")
def pair() -> tb.GearPair:
    return tb.GearPair.preset("seed-electric-drive")


@pytest.mark.parametrize(
    ("bad", "good", "field"),
    [
        ({"torque_n_m": 1e5}, {"torque_n_m": 500.0}, "torque_n_m"),
        ({"half_backlash_um": 1000.0}, {"half_backlash_um": 150.0}, "half_backlash_um"),
        ({"te_amplitude_um": 1e4}, {"te_amplitude_um": 20.0}, "te_amplitude_um"),
        ({"mesh_damping_ratio": 5.0}, {"mesh_damping_ratio": 0.15}, "mesh_damping_ratio"),
        ({"bearing_damping_ratio": 5.0}, {"bearing_damping_ratio": 0.05}, "bearing_damping_ratio"),
    ],
)
def test_an_implausible_gear_input_warns(pair, bad, good, field):
    with pytest.warns(tb.PlausibilityWarning, match=field):
        tb.GearSystem(pair, **bad)
    _quiet(lambda: tb.GearSystem(pair, **good))


def test_a_backlash_of_a_whole_pitch_is_refused(pair):
    with pytest.raises(tb.ConfigError, match="half_backlash_um"):
        tb.GearSystem(pair, half_backlash_um=1e6)  # 1 m


def test_a_sweep_past_the_fastest_gears_warns(pair):
    system = tb.GearSystem(pair)
    with pytest.warns(tb.PlausibilityWarning, match="speed_rpm = 1e"):
        tb.bifurcation(system, [1e6], transient_periods=1, record_periods=2)
    _quiet(lambda: tb.bifurcation(system, [20000.0], transient_periods=1, record_periods=2))


# ------------------------------------------------------------------ calibration


def _toy_data(speeds, quantities=("heat_w",)):
    truth = Rig().with_setting(lubrication_factor_f0=1.3, extra_heat_w=10.0)
    return measured(truth, conditions(speeds, quantities=quantities), seed=1)


def test_a_calibration_of_more_values_than_points_is_refused():
    data = _toy_data([10000.0])
    assert data.height == 1
    with pytest.raises(tb.ConfigError, match="invalid parameters .*2 value.* from 1 measured"):
        tb.calibrate([(Rig(), data)], ["lubrication_factor_f0", "extra_heat_w"])


def test_an_ill_conditioned_calibration_warns_with_its_condition_number():
    """Heat at one speed, measured twice: f0 and the extra heat move it
    alike; at four speeds their speed laws tell them apart."""
    same = pl.concat([_toy_data([10000.0]), _toy_data([10000.0]).with_columns(run=pl.lit("2"))])
    with pytest.warns(tb.PlausibilityWarning, match=r"parameters .*condition number"):
        cal = tb.calibrate([(Rig(), same)], ["lubrication_factor_f0", "extra_heat_w"])
    assert cal.condition_number > 1e6
    good = _toy_data([4000.0, 8000.0, 12000.0, 16000.0])
    cal = _quiet(lambda: tb.calibrate([(Rig(), good)], ["lubrication_factor_f0", "extra_heat_w"]))
    assert cal.condition_number <= 1e6


# ------------------------------------------------------------------ predict


@pytest.fixture(scope="module")
def calibration():
    data = _toy_data([4000.0, 8000.0, 12000.0], ("heat_w", "inner_ring_temperature_c"))
    return tb.calibrate([(Rig(), data)], ["lubrication_factor_f0"])


def test_predict_refuses_an_unknown_conditions_key_and_column(calibration):
    with pytest.raises(tb.ConfigError, match="speedz.*did you mean speeds_rpm"):
        tb.predict(calibration, "measured", {"speeds_rpm": [5000.0], "speedz": 1})
    frame = pl.DataFrame({"speed_rpm": [5000.0], "axial_n": [300.0], "radial_n": [0.0]})
    with pytest.raises(tb.ConfigError, match="radial_nn.*did you mean radial_n"):
        tb.predict(calibration, "measured", frame.with_columns(radial_nn=pl.lit(1.0)))
    with pytest.raises(tb.ConfigError, match="extra"):
        tb.predict(calibration, "measured", frame.with_columns(extra=pl.lit(1.0)))
    df = tb.predict(calibration, "measured", frame)  # the plausible neighbour
    assert df.height > 0


@pytest.mark.parametrize("level", [1e-12, 0.3, 0.9999])
def test_predict_refuses_a_band_level_outside_the_range(calibration, level):
    with pytest.raises(tb.ConfigError, match="level"):
        tb.predict(calibration, "measured", {"speeds_rpm": [5000.0], "axial_n": 300.0},
                   level=level)  # fmt: skip


@pytest.mark.parametrize("level", [0.5, 0.95, 0.999])
def test_predict_takes_a_band_level_in_the_range(calibration, level):
    df = tb.predict(calibration, "measured", {"speeds_rpm": [5000.0], "axial_n": 300.0},
                    level=level)  # fmt: skip
    assert df.height > 0


# ------------------------------------------------------------------ diagnose: CLI = API


def test_the_command_and_the_api_refuse_one_speed_alike(tmp_path, capsys):
    """Two values at one speed: the API's default hold-out refuses them, and
    so does ``thermobear diagnose`` (it takes the same default)."""
    from thermobear.cli.main import build_parser, main
    from thermobear.diagnosis import model_from_toml, synthetic_measurements

    system = tmp_path / "system.toml"
    system.write_text(tb.seed_config("seed_b_7009c"))
    spec, _ = model_from_toml(system)
    quantities = ["outer_ring_temperature_c", "inner_ring_temperature_c"]
    cond = pl.DataFrame({"speed_rpm": [10000.0, 10000.0], "axial_n": 300.0, "radial_n": 0.0,
                         "quantity": quantities})  # fmt: skip
    data = synthetic_measurements(spec, cond, seed=0)
    csv = tmp_path / "m.csv"
    data.write_csv(csv)
    with pytest.raises(tb.DataError, match="distinct speeds") as api:
        tb.diagnose(spec, data)
    assert main(["diagnose", str(csv), "--model", str(system)]) == 1
    err = capsys.readouterr().err
    assert "distinct speeds" in err and str(api.value).split(": ", 1)[1] in err
    default = inspect.signature(tb.diagnose).parameters["holdout"].default
    args = build_parser().parse_args(["diagnose", "m.csv", "--model", "s.toml"])
    assert args.holdout == default


# ------------------------------------------------------------------ the limits page


def test_every_input_limit_is_on_the_limits_page():
    page = (Path(__file__).resolve().parents[1] / "docs" / "concepts" / "limits.md").read_text()
    for name in ("MIN_BALLS_ANGULAR_CONTACT", "MAX_CLEARANCE_PER_BALL_DIAMETER",
                 "MAX_JET_FLOW_CM3_PER_MIN_PER_MM_BORE", "GREASE_FILL_RANGE",
                 "FULL_GREASE_FILL_MAX_NDM_MM_RPM", "POUR_POINT_MARGIN_K",
                 "MAX_GEAR_UNIT_LOAD_N_PER_MM2", "MAX_BACKLASH_PER_MODULE", "MAX_DAMPING_RATIO",
                 "MAX_PITCH_LINE_VELOCITY_M_PER_S", "COND_MAX", "LEVEL_RANGE"):  # fmt: skip
        assert f"`{name}`" in page, name
    assert checks.MIN_BALLS_ANGULAR_CONTACT == 7 and "fewer than 7 balls" in page
    assert checks.MAX_PITCH_LINE_VELOCITY_M_PER_S == 200.0 and "above 200 m/s" in page
    assert checks.MAX_GEAR_UNIT_LOAD_N_PER_MM2 == 650.0 and "above 650 N/mm²" in page
    assert checks.coarsest_pitch_deviation_um(1.537, 140.16) == pytest.approx(66.5, abs=0.5)
    assert np.isclose(checks.POUR_POINT_MARGIN_K, 10.0) and "within 10 K" in page


@pytest.mark.parametrize("call", ["thermal_state", "thermal_state_many", "stiffness_curve"])
def test_the_batch_paths_apply_the_supply_rules_too(b7008, call):
    """The same supply rule on every thermal path: a jet without oil warns
    from the single state, the batch and the thermal stiffness curve; a
    plausible jet does not."""
    runs = {
        "thermal_state": lambda **kw: tb.thermal_state(b7008, 8000.0, 500.0, **kw),
        "thermal_state_many": lambda **kw: tb.thermal_state_many(
            b7008, {"speed_rpm": [6000.0, 8000.0], "axial_n": 500.0}, **kw
        ),
        "stiffness_curve": lambda **kw: tb.stiffness_curve(
            b7008, [6000.0, 8000.0], 500.0, mode="thermal", **kw
        ),
    }
    with pytest.warns(tb.PlausibilityWarning, match="oil_flow_cm3_per_min"):
        runs[call](lubrication="jet", oil_flow_cm3_per_min=0.0)
    _quiet(lambda: runs[call](lubrication="jet", oil_flow_cm3_per_min=500.0))
