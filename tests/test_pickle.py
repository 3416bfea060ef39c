"""Everything pickles: the native classes through a
versioned serde envelope, the Python wrappers, the diagnosis model specs and
the result objects. Round trips are exact: the copy gives bit-identical
results."""

from __future__ import annotations

import math
import multiprocessing as mp
import pickle
from concurrent.futures import ProcessPoolExecutor

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear import _native


def _rt(obj):
    return pickle.loads(pickle.dumps(obj, protocol=pickle.HIGHEST_PROTOCOL))


def _identical(a, b, where="") -> None:
    """Assert ``a`` and ``b`` are equal to the last bit (NaN equal to NaN)."""
    if isinstance(a, pl.DataFrame):
        assert isinstance(b, pl.DataFrame) and a.columns == b.columns, where
        for c in a.columns:
            _identical(a[c].to_numpy(), b[c].to_numpy(), f"{where}.{c}")
    elif isinstance(a, dict):
        assert isinstance(b, dict) and list(a) == list(b), where
        for k in a:
            _identical(a[k], b[k], f"{where}.{k}")
    elif isinstance(a, np.ndarray):
        b = np.asarray(b)
        assert a.shape == b.shape and a.dtype == b.dtype, where
        if a.dtype.kind in "fc":
            assert a.tobytes() == b.tobytes(), where
        else:
            assert a.tolist() == b.tolist(), where
    elif isinstance(a, (list, tuple)):
        assert type(a) is type(b) and len(a) == len(b), where
        for i, (x, y) in enumerate(zip(a, b, strict=True)):
            _identical(x, y, f"{where}[{i}]")
    elif isinstance(a, float):
        assert isinstance(b, float), where
        assert (math.isnan(a) and math.isnan(b)) or a.hex() == b.hex(), (where, a, b)
    elif hasattr(a, "__dataclass_fields__"):
        assert type(a) is type(b), where
        for k in a.__dataclass_fields__:
            _identical(getattr(a, k), getattr(b, k), f"{where}.{k}")
    else:
        assert a == b, (where, a, b)


def _state(native) -> dict:
    fn, (state,) = native.__reduce__()
    assert fn is _native._restore
    return state


# ------------------------------------------------------------ native classes


def test_native_state_is_a_versioned_envelope():
    for obj, kind in (
        (_native.Material.preset("Si3N4"), "Material"),
        (_native.Bearing.preset("7009C-hybrid"), "Bearing"),
        (_native.GearPair.preset("seed-electric-drive"), "GearPair"),
        (_native.Spindle.preset("seed-steel-spindle"), "Spindle"),
    ):
        s = _state(obj)
        assert set(s) == {"format", "version", "kind", "data"}
        assert (s["format"], s["version"], s["kind"]) == ("thermobear", 1, kind)
        assert isinstance(s["data"], str)
        back = _rt(obj)
        assert type(back) is type(obj)
        assert _state(back) == s


@pytest.mark.parametrize("name", _native.Material.preset_names())
def test_material_presets_round_trip(name):
    m = tb.Material.preset(name)
    m2 = _rt(m)
    assert isinstance(m2, tb.Material)
    _identical(m.to_dict(), m2.to_dict())
    _identical(_state(m._m), _state(m2._m))


def test_custom_material_round_trip_exact():
    m = tb.Material("odd-steel", base="52100", youngs_modulus_gpa=0.1 + 207.2, poisson_ratio=1 / 3)
    m2 = _rt(m)
    _identical(m.to_dict(), m2.to_dict())
    assert m2.youngs_modulus_gpa == m.youngs_modulus_gpa


@pytest.mark.parametrize("name", tb.Bearing.preset_names())
def test_bearing_presets_solve_bit_identical(name):
    b = tb.Bearing.preset(name)
    b2 = _rt(b)
    assert isinstance(b2, tb.Bearing) and repr(b2) == repr(b)
    _identical(b.geometry, b2.geometry)
    for speed in (0.0, 15_000.0):
        _identical(b.solve(400.0, 150.0, speed_rpm=speed), b2.solve(400.0, 150.0, speed_rpm=speed))


def test_custom_ceramic_bearing_and_thermal_state_bit_identical():
    ceramic = tb.Material("my-si3n4", base="Si3N4", density_kg_m3=3190.5)
    b = tb.Bearing.angular_contact(
        ball_count=17,
        ball_diameter_mm=7.1438,
        pitch_diameter_mm=57.5,
        inner_conformity=0.52,
        outer_conformity=0.53,
        free_contact_angle_deg=15.0,
        bore_mm=45.0,
        outer_diameter_mm=75.0,
        width_mm=16.0,
        ring_material="52100",
        ball_material=ceramic,
        name="custom-hybrid",
    )
    b2 = _rt(b)
    assert b2.name == "custom-hybrid"
    _identical(b.ball_material.to_dict(), b2.ball_material.to_dict())
    _identical(b.solve(300.0, 0.0, speed_rpm=12_000.0), b2.solve(300.0, 0.0, speed_rpm=12_000.0))
    s1 = tb.thermal_state(b, 12_000.0, 300.0, 0.0)
    s2 = tb.thermal_state(b2, 12_000.0, 300.0, 0.0)
    _identical(s1, s2)
    _identical(s1, _rt(s1))  # the result itself pickles
    _identical(s1.temperatures, _rt(s1).temperatures)


def test_spindle_with_changed_preload_bit_identical():
    sp = tb.Spindle.preset("seed-ceramic-spindle").with_options(
        preload_n=650.0, preload_kind="rigid", radial_load_n=120.0
    )
    sp2 = _rt(sp)
    assert isinstance(sp2, tb.Spindle)
    assert (sp2.name, sp2.preload_n, sp2.preload_kind, sp2.radial_load_n) == (
        sp.name,
        650.0,
        "rigid",
        120.0,
    )
    _identical(sp.thermal_state(9_000.0), sp2.thermal_state(9_000.0))
    _identical(sp.isothermal(9_000.0), sp2.isothermal(9_000.0))


def test_gear_pair_and_gear_system_with_settings_bit_identical():
    pair = tb.GearPair.preset("seed-electric-drive")
    p2 = _rt(pair)
    assert repr(p2) == repr(pair)
    _identical(pair.typo_warnings, p2.typo_warnings)
    _identical(pair._g.typo_warnings(), p2._g.typo_warnings())
    system = tb.GearSystem(
        pair,
        backlash_total_um=60.0,
        mesh_damping="always",
        mesh_damping_ratio=0.05,
        bearing_damping_ratio=0.03,
        te_amplitude_um=3.5,
        torque_n_m=120.0,
    )
    s2 = _rt(system)
    assert isinstance(s2, tb.GearSystem)
    _identical(system._s.params(), s2._s.params())
    _identical(system._s.schedule(), s2._s.schedule())
    speeds = [8_000.0, 12_000.0]
    _identical(
        tb.bifurcation(system, speeds, "up", 20, 8, steps_per_period=64),
        tb.bifurcation(s2, speeds, "up", 20, 8, steps_per_period=64),
    )


# --------------------------------------------------- specs and other results


def test_bearing_model_spec_and_diagnosis_round_trip():
    spec = tb.BearingModelSpec(tb.Bearing.preset("7008C"), lubrication_factor_f0=1.2)
    cond = pl.DataFrame(
        {
            "speed_rpm": np.repeat([4_000.0, 8_000.0, 12_000.0, 16_000.0], 2),
            "axial_n": 300.0,
            "radial_n": 0.0,
            "quantity": ["outer_ring_temperature_c", "radial_stiffness_seed_n_per_m"] * 4,
        }
    )
    before = spec.predict(cond)  # fills the cache: the pickle leaves it behind
    spec2 = _rt(spec)
    assert isinstance(spec2, tb.BearingModelSpec) and spec2._cache == {}
    assert (spec2.effects, spec2.options) == (spec.effects, spec.options)
    _identical(before, spec2.predict(cond))
    truth = spec.with_setting(lubrication_factor_f0=1.5)
    p = truth.predict(cond)
    meas = cond.with_columns(
        pl.Series("value", [p[q][i] for i, q in enumerate(cond["quantity"])]),
        pl.Series("sigma", [0.3, 0.01 * p["radial_stiffness_seed_n_per_m"][1]] * 4),
    )
    d = tb.diagnose(spec, meas)
    assert isinstance(d, tb.Diagnosis)
    d2 = _rt(d)
    _identical(d, d2)
    assert d2.summary() == d.summary()


def test_spindle_model_spec_round_trip():
    spec = tb.SpindleModelSpec(
        tb.Spindle.preset("seed-steel-spindle").with_options(preload_n=500.0),
        effects=["thermal_displacement"],
        spin_friction_coefficient=0.05,
    )
    spec2 = _rt(spec)
    assert isinstance(spec2, tb.SpindleModelSpec)
    assert (spec2.effects, spec2.options) == (spec.effects, spec.options)
    cond = pl.DataFrame({"speed_rpm": [9_000.0], "axial_n": 500.0, "radial_n": 0.0})
    _identical(spec.predict(cond), spec2.predict(cond))


# -------------------------------------------------------------- bad payloads


@pytest.mark.parametrize(
    "field,value", [("version", 2), ("version", 0), ("kind", "Turbine"), ("format", "other")]
)
def test_unknown_version_kind_or_format_raises_config_error(field, value):
    state = dict(_state(_native.Bearing.preset("6208")))
    state[field] = value
    with pytest.raises(tb.ConfigError, match=rf"{field}.*{value}"):
        _native._restore(state)

    class Tampered:
        def __reduce__(self):
            return _native._restore, (state,)

    with pytest.raises(tb.ConfigError, match=field):
        pickle.loads(pickle.dumps(Tampered()))


def test_missing_field_or_bad_data_raises_config_error():
    state = dict(_state(_native.Material.preset("52100")))
    del state["version"]
    with pytest.raises(tb.ConfigError, match="version"):
        _native._restore(state)
    state = dict(_state(_native.Material.preset("52100")), data='{"name": 1}')
    with pytest.raises(tb.ConfigError, match="data"):
        _native._restore(state)


# ----------------------------------------------------------- multiprocessing

SPEEDS_RPM = [0.0, 6_000.0, 12_000.0, 18_000.0]


def _solve_at(bearing: tb.Bearing, speed_rpm: float) -> dict:
    return bearing.solve(500.0, 200.0, speed_rpm=speed_rpm).raw


def test_process_pool_solves_equal_in_process_bit_for_bit():
    b = tb.Bearing.preset("7009C-hybrid")
    local = [_solve_at(b, s) for s in SPEEDS_RPM]
    ctx = mp.get_context("spawn")  # no fork of a process with running threads
    with ProcessPoolExecutor(max_workers=2, mp_context=ctx) as pool:
        remote = list(pool.map(_solve_at, [b] * len(SPEEDS_RPM), SPEEDS_RPM))
    for x, y in zip(local, remote, strict=True):
        _identical(x, y)
