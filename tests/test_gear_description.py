"""A gear system as a description file: the shipped seed A file gives the
default seed A system bit for bit in each stiffness case, ``to_toml`` ->
``from_toml`` round trips to the last bit, a changed value moves the
physics the right way, and a bad file is a ConfigError naming file, line
and key."""

from __future__ import annotations

import json
import re
import tomllib
from importlib import resources

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear.gear.description import NOTES, SYSTEM_CHECKS, TABLES, in_unit
from thermobear.glossary import GLOSSARY, UNIT_SUFFIXES

SEED = "seed-a-gear-system"
CASES = ("constant", "speed", "thermal")


def _state(obj) -> dict:
    return json.loads(obj.__reduce__()[1][0]["data"])


def _seed_text() -> str:
    return resources.files("thermobear.configs").joinpath("gears", f"{SEED}.toml").read_text()


def _with(text: str, old: str, new: str) -> str:
    assert text.count(old) == 1, old
    return text.replace(old, new)


def _short_sweep(system: tb.GearSystem) -> pl.DataFrame:
    return tb.bifurcation(
        system, [5000.0, 9000.0], transient_periods=20, record_periods=6, steps_per_period=64
    )


def _assert_same(a: tb.GearSystem, b: tb.GearSystem) -> None:
    assert _state(a._s) == _state(b._s)
    assert a.params == b.params
    for speed in (1500.0, 7000.0, 16000.0):
        assert np.array_equal(a.mass_matrix_kg(speed), b.mass_matrix_kg(speed))
        assert np.array_equal(a.stiffness_matrix_n_per_m(speed), b.stiffness_matrix_n_per_m(speed))
    assert a.mesh_tables().equals(b.mesh_tables())
    assert a.stiffness_schedule.equals(b.stiffness_schedule)
    assert (a.stiffness_case, a.bearings_per_shaft) == (b.stiffness_case, b.bearings_per_shaft)


# -- the shipped file is the default seed A system --------------------------------


@pytest.fixture(scope="module")
def seed_pair() -> tb.GearPair:
    return tb.GearPair.preset("seed-electric-drive")


@pytest.mark.parametrize("case", CASES)
def test_the_seed_file_gives_the_default_system_bit_for_bit(case, seed_pair, tmp_path):
    default = tb.GearSystem(seed_pair, stiffness=case)
    path = tmp_path / f"{SEED}.toml"
    path.write_text(_with(_seed_text(), 'stiffness = "speed"', f'stiffness = "{case}"'))
    described = tb.GearSystem.from_toml(path)
    _assert_same(described, default)
    # the pair itself: the preset's numbers (its notes on Table 3 as printed aside)
    assert _state(described.gear._g)["spec"] == _state(seed_pair._g)["spec"]
    assert described.gear.geometry == seed_pair.geometry
    assert _short_sweep(described).equals(_short_sweep(default))


def test_the_seed_file_loads_by_name_and_is_the_default(seed_pair):
    by_name = tb.GearSystem.from_toml(SEED)
    _assert_same(by_name, tb.GearSystem(seed_pair))
    assert by_name.stiffness_case == "speed"
    # the default writes the same description as the file gives
    assert by_name.to_toml() == tb.GearSystem(seed_pair).to_toml()


def test_the_seed_file_is_commented_and_its_names_are_the_glossary_s():
    text = _seed_text()
    for line in text.splitlines():  # every line says what it holds, in what unit
        assert not line.strip() or "#" in line, line
    doc = tomllib.loads(text)["gear_system"]
    keys = [k for k in doc if k != "gear"] + list(doc["gear"])
    with_unit = [k for k in keys if any(k.endswith(s) for s in UNIT_SUFFIXES)]
    assert with_unit and all(k in GLOSSARY for k in with_unit)
    every = [*SYSTEM_CHECKS, *TABLES, *(c for t in TABLES.values() for c in t), *NOTES]
    assert [k for k in every if any(k.endswith(s) for s in UNIT_SUFFIXES)
            and k not in GLOSSARY] == []  # fmt: skip


# -- round trips -----------------------------------------------------------------


@pytest.fixture(scope="module")
def custom() -> tb.GearSystem:
    """A system unlike the seed in every value a description holds."""
    pair = tb.GearPair.from_table(
        pinion_teeth=23, gear_teeth=61, normal_module_mm=2.25, normal_pressure_angle_deg=20.0,
        helix_angle_deg=17.5, face_width_mm=28.4, youngs_modulus_mpa=210000.0,
        poisson_ratio=0.3, density_t_per_mm3=7.85e-9, mass_kg=(0.93, 4.2),
        polar_inertia_t_mm2=(0.21, 3.7), input_torque_n_m=80.0,
        profile_shift_coeff=(0.15, -0.1), addendum_coeff=1.0, dedendum_coeff=1.3,
    )  # fmt: skip
    return tb.GearSystem(
        pair, tb.Bearing.preset("6208-hybrid"), "thermal", bearings_per_shaft=1,
        backlash_total_um=73.0, mesh_damping_ratio=0.045, mesh_damping="always",
        bearing_damping_ratio=0.031, te_amplitude_um=3.3, torque_n_m=-42.5, mesh_model="iso",
        table_points=48, stiffness_speeds_rpm=[2000.0, 7500.0, 13000.0, 18500.0],
        mesh_stiffness_scale=1.07,
    )  # fmt: skip


def test_to_toml_from_toml_round_trips_bit_for_bit(custom):
    text = custom.to_toml()
    assert "stiffness_speeds_rpm = [2000.0, 7500.0, 13000.0, 18500.0]" in text
    back = tb.GearSystem.from_toml(text)
    _assert_same(back, custom)
    assert _state(back.gear._g)["spec"] == _state(custom.gear._g)["spec"]
    assert back.to_toml() == text
    assert _short_sweep(back).equals(_short_sweep(custom))


def test_tables_round_trip_bit_for_bit(seed_pair):
    phase = np.linspace(0.0, 1.0, 17) ** 1.3  # not on the 40 phases i/40: resampled once
    stiffness = {
        "mesh_phase": phase,
        "normal_stiffness_n_per_m": 9e8 + 4e7 * np.cos(2 * np.pi * phase),
    }
    system = tb.GearSystem(
        seed_pair, stiffness="constant", table_points=40, mesh_stiffness_n_per_m=stiffness,
        transmission_error_um=lambda p: 1.5 * np.sin(2 * np.pi * p) + 0.4 * np.cos(4 * np.pi * p),
    )  # fmt: skip
    text = system.to_toml()
    assert "[gear_system.mesh_stiffness_n_per_m]" in text and "te_amplitude_um" not in text
    assert "mesh_model" not in text
    back = tb.GearSystem.from_toml(text)
    _assert_same(back, system)
    assert back.mesh_model == "table"


def test_to_toml_writes_the_file_it_returns(custom, tmp_path):
    path = tmp_path / "mine.toml"
    text = custom.to_toml(path)
    assert path.read_text() == text
    _assert_same(tb.GearSystem.from_toml(path), custom)
    _assert_same(tb.GearSystem.from_toml(str(path)), custom)


def test_values_are_written_as_the_core_converts_them():
    # 50 um is held as 50 * 1e-6 (not the nearest float to 5e-5): 50 is written back
    assert in_unit(50.0 * 1e-6, lambda x: x * 1e-6, "half_backlash_um") == 50.0
    rng = np.random.default_rng(3)
    for x in rng.uniform(1e-3, 1e3, 300):
        for f in (lambda v: v * 1e-3, lambda v: v * 1e-6, lambda v: v * 1e12, np.radians):
            si = float(f(float(x)))
            assert float(f(in_unit(si, f, "x"))) == si


def test_what_a_description_cannot_hold_is_refused(seed_pair):
    frame = tb.GearSystem(seed_pair).stiffness_schedule
    with pytest.raises(tb.ConfigError, match="stiffness frame cannot be written"):
        tb.GearSystem(seed_pair, stiffness=frame).to_toml()
    from thermobear.studies.seed_a_gear import seed_a_bearing

    jet = tb.GearSystem(seed_pair, seed_a_bearing(), stiffness="thermal")  # oil-jet drag heat
    with pytest.raises(tb.ConfigError, match="would not give it back .*schedule"):
        jet.to_toml()


# -- a changed value moves the physics the right way -------------------------------


def _force_amplitude_n(system: tb.GearSystem, speeds: list[float]) -> np.ndarray:
    """Half the swing of the dynamic mesh deflection times the mean mesh
    stiffness, per speed: the amplitude of the dynamic mesh force [N]."""
    df = tb.bifurcation(system, speeds, transient_periods=60, record_periods=10)
    per = df.group_by("speed_rpm", maintain_order=True).agg(
        ((pl.col("dte_max_um") - pl.col("dte_min_um")).first() * 0.5e-6).alias("swing_m")
    )
    return per["swing_m"].to_numpy() * system.params["mesh_stiffness_mean_n_per_m"]


def test_a_changed_value_moves_the_result_the_right_way():
    text = _seed_text()
    base = tb.GearSystem.from_toml(text)
    speeds = [3000.0, 6000.0, 9000.0]
    more_te = tb.GearSystem.from_toml(_with(text, "te_amplitude_um = 2.0", "te_amplitude_um = 6.0"))
    assert np.all(_force_amplitude_n(more_te, speeds) > _force_amplitude_n(base, speeds))
    wider = tb.GearSystem.from_toml(_with(text, "face_width_mm = 33.0", "face_width_mm = 40.0"))
    k = "mesh_stiffness_mean_n_per_m"
    assert wider.params[k] > base.params[k]
    stiffer = tb.GearSystem.from_toml(
        _with(text, "mesh_stiffness_scale = 1.0", "mesh_stiffness_scale = 1.5")
    )
    assert stiffer.natural_frequencies_hz()[-1] > base.natural_frequencies_hz()[-1]
    wide_play = tb.GearSystem.from_toml(
        _with(text, "half_backlash_um = 50.0", "half_backlash_um = 80.0")
    )
    assert wide_play.params["half_backlash_um"] == pytest.approx(80.0, rel=1e-12)
    one_bearing = tb.GearSystem.from_toml(
        _with(text, "bearings_per_shaft = 2", "bearings_per_shaft = 1")
    )
    kr = one_bearing.bearing_stiffness_at(9000.0)[0]
    assert kr == pytest.approx(0.5 * base.bearing_stiffness_at(9000.0)[0], rel=1e-12)


# -- a bad file names file, line and key ------------------------------------------

BAD = [
    ("face_width_mm = 33.0", "face_width_mm = -5.0", "gear_system.gear.face_width_mm", "> 0"),
    ("face_width_mm = 33.0", 'face_width_mm = "33"', "gear_system.gear.face_width_mm", "str"),
    ("pinion_teeth = 29", "pinion_teeth = 4", "gear_system.gear.pinion_teeth", ">= 6"),
    ("gear_teeth = 78", "gear_teeth = 78.5", "gear_system.gear.gear_teeth", "whole"),
    (
        "helix_angle_deg = 31.2",
        "helix_angle_deg = 90.0",
        "gear_system.gear.helix_angle_deg",
        r"\[0, 45\)",
    ),
    (
        "face_width_mm = 33.0",
        "face_widht_mm = 33.0",
        "gear_system.gear.face_widht_mm",
        "did you mean face_width_mm",
    ),
    ("mass_kg = [1.201, 3.1]", "mass_kg = [1.201, -3.1]", "gear_system.gear.mass_kg", ">= 0"),
    (
        "youngs_modulus_mpa = 206000.0",
        "youngs_modulus_mpa = 20600.0",
        "gear_system.gear.youngs_modulus_mpa",
        "likely intended",
    ),
    (
        "polar_inertia_t_mm2 = [0.1152, 1.6]",
        "polar_inertia_t_mm2 = [115.2, 1.6]",
        "gear_system.gear.polar_inertia_t_mm2",
        "likely",
    ),
    ("half_backlash_um = 50.0", "half_backlash_um = -1.0", "gear_system.half_backlash_um", "> 0"),
    (
        "half_backlash_um = 50.0",
        "half_backlash_mm = 0.05",
        "gear_system.half_backlash_mm",
        "did you mean half_backlash_um",
    ),
    ('stiffness = "speed"', 'stiffness = "sped"', "gear_system.stiffness", "did you mean speed"),
    ('bearings = "6208"', 'bearings = "6280X"', "gear_system.bearings", "not a bearing preset"),
    (
        "bearings_per_shaft = 2",
        "bearings_per_shaft = true",
        "gear_system.bearings_per_shaft",
        "bool",
    ),
    ("table_points = 64", "table_points = 1", "gear_system.table_points", "whole"),
    ("input_torque_n_m = 100.0", "", "gear_system.gear", "input_torque_n_m"),
    ("[gear_system]", "[gear_sytem]", "gear_sytem", "did you mean gear_system"),
    ("[gear_system.gear]", "[gear_system.gears]", "gear_system.gears", "did you mean gear"),
]


@pytest.mark.parametrize(("old", "new", "key", "words"), BAD, ids=[b[1] or b[0] for b in BAD])
def test_a_bad_file_names_file_line_and_key(old, new, key, words, tmp_path):
    path = tmp_path / "gears.toml"
    text = _with(_seed_text(), old, new)
    path.write_text(text)
    with pytest.raises(tb.ConfigError) as info:
        tb.GearSystem.from_toml(path)
    message = str(info.value)
    assert info.value.key == key, message
    line = info.value.line
    assert line is not None and message.startswith(f"{path}:{line}: key {key}: "), message
    shown = text.splitlines()[line - 1]
    assert (new or "[gear_system.gear]").split("=")[0].strip() in shown, (shown, message)
    if words is not None:
        assert re.search(words, message), message


def test_bad_tables_and_combinations_are_named(tmp_path):
    seed = _seed_text()
    table = "\n[gear_system.transmission_error_um]\nmesh_phase = [0.0, 0.5, 0.25]\n"
    table += "transmission_error_um = [1.0, -1.0, 0.0]\n"
    path = tmp_path / "gears.toml"
    path.write_text(_with(seed, "te_amplitude_um = 2.0", "") + table)
    with pytest.raises(tb.ConfigError, match="ascending") as info:
        tb.GearSystem.from_toml(path)
    assert info.value.key == "gear_system.transmission_error_um.mesh_phase"
    path.write_text(seed + table.replace("[0.0, 0.5, 0.25]", "[0.0, 0.25, 0.5]"))
    with pytest.raises(tb.ConfigError, match="either te_amplitude_um") as info:
        tb.GearSystem.from_toml(path)
    assert info.value.key == "gear_system.te_amplitude_um"
    both = _with(seed, "half_backlash_um = 50.0", "half_backlash_um = 50.0\nbacklash_total_um = 90")
    path.write_text(both)
    with pytest.raises(tb.ConfigError, match="not both") as info:
        tb.GearSystem.from_toml(path)
    assert info.value.key == "gear_system.backlash_total_um"
    with pytest.raises(tb.ConfigError, match="cannot read"):
        tb.GearSystem.from_toml(tmp_path / "missing.toml")
