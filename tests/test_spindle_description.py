"""A spindle from its parts: the ``[spindle]`` description (TOML and the
part dataclasses), the shipped preset files, exact round trips, named
errors, and the consumers of a spindle taking a described one unchanged."""

from __future__ import annotations

import pickle
from importlib import resources

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear import diagnosis as D
from thermobear.diagnosis.calibrated import CalibratedModel
from thermobear.spindle.description import from_si, to_si


def _config(sp: tb.Spindle) -> str:
    return sp._native.config_json()


@pytest.fixture(scope="module")
def custom() -> tb.Spindle:
    """A spindle unlike any preset: other layout, motor, cooling, rigid preload."""
    return tb.Spindle(
        name="grinding-spindle",
        shaft=tb.Shaft(front_span_mm=131.7, rear_span_mm=104.25, nose_length_mm=75.0),
        front=tb.BearingSet("7009C"),
        rear=tb.BearingSet("7008C"),
        preload=tb.Preload(kind="rigid", preload_n=280.0),
        housing=tb.Housing(sleeve_outer_diameter_mm=172.5, ambient_temperature_c=22.0),
        motor=tb.Motor(stator_copper_loss_w=310.0, windage_loss_w=65.0),
        cooling=tb.Cooling(jacket_flow_l_per_min=6.5, water_temperature_c=20.0),
        tool=tb.ToolLoad(radial_load_n=150.0),
    )


@pytest.mark.parametrize("name", tb.Spindle.preset_names())
def test_each_preset_file_gives_the_preset_bit_for_bit(name):
    preset = tb.Spindle.preset(name)
    path = resources.files("thermobear.configs").joinpath("spindles", f"{name}.toml")
    described = tb.Spindle.from_toml(str(path))
    assert described.name == name
    assert _config(described) == _config(preset)
    a, b = described.thermal_state(15000.0), preset.thermal_state(15000.0)
    assert a.equals(b)  # every column, equal floats
    ta = tb.transient(described, speed_rpm=12000.0, duration_s=120.0, dt_s=30.0)
    tp = tb.transient(preset, speed_rpm=12000.0, duration_s=120.0, dt_s=30.0)
    assert ta.equals(tp)


def test_a_preset_name_loads_its_shipped_file():
    a = tb.Spindle.from_toml("seed-steel-spindle")
    assert _config(a) == _config(tb.Spindle.preset("seed-steel-spindle"))


def test_the_default_parts_are_the_ceramic_preset():
    sp = tb.Spindle()
    assert sp.name == "custom"
    assert _config(sp) == _config(tb.Spindle.preset("seed-ceramic-spindle"))


def test_to_toml_from_toml_round_trips_bit_for_bit(custom):
    text = custom.to_toml()
    back = tb.Spindle.from_toml(text)
    assert back.name == "grinding-spindle"
    assert _config(back) == _config(custom)
    assert back.to_toml() == text
    assert back.thermal_state(9000.0).equals(custom.thermal_state(9000.0))
    # the parts give it back as well
    assert _config(tb.Spindle(**custom.parts)) == _config(custom)


def test_round_trip_keeps_pull_supply_and_options():
    sp = tb.Spindle(
        motor=tb.Motor(magnetic_pull=tb.MagneticPull(static_eccentricity_um=20.0)),
        lubrication=tb.Lubrication(oil_volume_cm3_per_h=5.0, heat_model="skf"),
    ).with_options(preload_n=333.3, radial_load_n=-40.0, spin_friction_coefficient=0.043)
    assert "unbalanced_magnetic_pull" in sp._native.effects
    text = sp.to_toml()
    assert "[spindle.motor.magnetic_pull]" in text and "oil_volume_cm3_per_h = 5.0" in text
    assert _config(tb.Spindle.from_toml(text)) == _config(sp)


def test_unit_conversion_is_exact_both_ways():
    # every SI value a description gives is written back to the last bit
    rng = np.random.default_rng(7)
    for x in rng.uniform(1e-3, 1e3, 300):
        for exponent in (-3, -6, 6):
            si = to_si(float(x), exponent)
            assert to_si(from_si(si, exponent), exponent) == si
    # a decimal in mm is the decimal in m, as the Rust presets write it
    assert to_si(79.4, -3) == 0.0794 and to_si(0.3, -3) == 0.3e-3


def test_the_parts_change_the_physics(custom):
    base = tb.Spindle()
    more_water = tb.Spindle(cooling=tb.Cooling(jacket_flow_l_per_min=20.0))
    a, b = base.thermal_state(12000.0), more_water.thermal_state(12000.0)
    # a stronger jacket flow cools the stator; the heat still all leaves
    assert b["stator_temperature_c"][0] < a["stator_temperature_c"][0]
    assert b["boundary_flow_w"][0] == pytest.approx(b["total_heat_w"][0], rel=1e-6)
    # the tool load reaches the pairs by the lever rule: front F (1 + a/L)
    row = custom.thermal_state(6000.0)
    lever = 150.0 * (1.0 + 75.0 / (131.7 + 104.25))
    assert row["front_pair_radial_x_n"][0] == pytest.approx(lever, rel=1e-9)
    assert row["preload_kind"][0] == "rigid"


@pytest.mark.parametrize(
    ("make", "words"),
    [
        (lambda: tb.BearingSet("7009C", arrangement="DF"), "not modelled"),
        (lambda: tb.BearingSet("7009C", arrangement="DT"), "not modelled"),
        (lambda: tb.BearingSet("7009C", rows=1), "not modelled"),
        (lambda: tb.BearingSet("7009C", rows=4), "not modelled"),
        (lambda: tb.BearingSet("6208"), "not modelled"),
        (lambda: tb.BearingSet("7009X"), "7009"),
        (lambda: tb.Preload(kind="rigid", spring_rate_n_per_um=0.4), "spring_rate_n_per_um"),
        (lambda: tb.Shaft(front_span_mm=0.0), "front_span_mm"),
        (lambda: tb.Cooling(jacket_wetted_fraction=1.5), "jacket_wetted_fraction"),
        (lambda: tb.Spindle(motor=tb.Motor(rotor_length_mm=260.0)), "rotor_length_mm = 260"),
        (lambda: tb.Spindle(housing=tb.Housing(sleeve_outer_diameter_mm=130.0)), "sleeve"),
        (lambda: tb.Spindle(effects=["unbalanced_magnetic_pull"]), "magnetic_pull"),
        (lambda: tb.Spindle(lubrication=tb.Lubrication(lubricant="VG 1000")), "lubricant"),
    ],
)
def test_bad_parts_are_named_config_errors(make, words):
    with pytest.raises(tb.ConfigError, match=words):
        make()


def test_a_bad_file_names_file_line_and_key(tmp_path):
    good = tb.Spindle.from_toml("seed-ceramic-spindle").to_toml()
    path = tmp_path / "spindle.toml"
    path.write_text(good.replace("front_span_mm = 120.0", "front_span_mm = -5.0"))
    line = 1 + path.read_text().splitlines().index("front_span_mm = -5.0")
    with pytest.raises(tb.ConfigError) as info:
        tb.Spindle.from_toml(path)
    assert str(info.value).startswith(f"{path}:{line}: key spindle.shaft.front_span_mm: ")
    path.write_text(good.replace("[spindle.cooling]", "[spindle.cooling]\njacket_flow_l_min = 3"))
    with pytest.raises(tb.ConfigError, match="did you mean jacket_flow_l_per_min") as info:
        tb.Spindle.from_toml(path)
    assert info.value.key == "spindle.cooling.jacket_flow_l_min"
    path.write_text(good.replace('arrangement = "DB"', 'arrangement = "DF"', 1))
    with pytest.raises(tb.ConfigError, match="not modelled") as info:
        tb.Spindle.from_toml(path)
    assert info.value.key == "spindle.front.arrangement"
    path.write_text(good.replace("rotor_length_mm = 150.0", "rotor_length_mm = 250.0"))
    with pytest.raises(tb.ConfigError) as info:
        tb.Spindle.from_toml(path)
    assert info.value.key == "spindle.motor.rotor_length_mm"


def test_a_bearing_that_is_no_preset_is_not_written():
    b = tb.Bearing.angular_contact(
        ball_count=16, ball_diameter_mm=8.0, pitch_diameter_mm=60.0, inner_conformity=0.52,
        outer_conformity=0.53, free_contact_angle_deg=15.0, bore_mm=45.0,
        outer_diameter_mm=75.0, width_mm=16.0, name="my-7009",
    )  # fmt: skip
    sp = tb.Spindle(front=tb.BearingSet(b))
    assert sp.thermal_state(6000.0)["total_heat_w"][0] > 0.0
    with pytest.raises(tb.ConfigError, match="not a bearing preset"):
        sp.to_toml()


def test_a_described_spindle_pickles(custom):
    back = pickle.loads(pickle.dumps(custom))
    assert back.name == custom.name and _config(back) == _config(custom)


# -- the consumers take a described spindle unchanged ----------------------------


def test_thermal_network_of_a_described_spindle(custom):
    assert custom.node_names == tb.Spindle.preset("seed-ceramic-spindle").node_names
    h = custom.convection_coefficients([6000.0])
    assert h.height > 0 and (h["film_coefficient_w_per_m2_k"] > 0).all()


def test_transient_of_a_described_spindle_approaches_its_steady_state(custom):
    steady = custom.thermal_state(6000.0)
    run = tb.transient(custom, speed_rpm=6000.0, duration_s=4 * 3600.0, dt_s=60.0)
    late = run.filter(pl.col("time_s") == run["time_s"].max())
    col = "stator_temperature_c"
    assert late[col][0] == pytest.approx(steady[col][0], abs=0.5)


def test_diagnosis_spec_and_prediction_of_a_described_spindle(custom):
    spec = D.SpindleModelSpec(custom, effects=[])
    cond = pl.DataFrame({"speed_rpm": [6000.0], "axial_n": [280.0]})
    p = spec.predict(cond)
    row = custom.thermal_state(6000.0, effects=[])
    assert p["front_outer_ring_temperature_c"][0] == row["front_outer_ring_temperature_c"][0]
    cm = CalibratedModel("nothing", "baseline", spec, [], [], np.zeros((0, 0)))
    df = tb.predict(cm, "temperatures", {"speeds_rpm": [6000.0], "preload_n": 280.0})
    front = df.filter(pl.col("quantity") == "front_outer_ring_temperature_c")
    # no calibration: the prediction is the described spindle's own state
    assert front["value"][0] == p["front_outer_ring_temperature_c"][0]


def test_parts_of_a_calibrated_spindle_carry_its_scaled_bearings():
    """A spindle whose balls a calibration scaled has no preset bearings:
    its parts give them back as Bearings, ``Spindle(...)`` takes them and
    solves the same state (to rounding: the parts are in mm), a description
    file refuses them by name, and the preset's name is refused for it."""
    from thermobear.studies.reproduce_seed_b import fitted_spindle

    fitted = fitted_spindle().model()[0]
    parts = fitted.parts
    assert isinstance(parts["front"], tb.Bearing) and isinstance(parts["rear"], tb.Bearing)
    with pytest.raises(tb.ConfigError, match="name of your own"):
        tb.Spindle(**parts)
    again = tb.Spindle(**{**parts, "name": "fitted-seed-b"})
    a, b = again.thermal_state(15000.0), fitted.thermal_state(15000.0)
    for col in ("front_ball_temperature_c", "axial_growth_um", "k_xx_n_per_m", "total_heat_w"):
        assert a[col][0] == pytest.approx(b[col][0], rel=1e-12), col
    with pytest.raises(tb.ConfigError, match="not a bearing preset"):
        fitted.to_toml()
