"""The rotor, gear-table, diagnosis and prediction entry points check their
arguments in the one validation layer: a wrong type, a non-finite or an
out-of-range value is a ``ConfigError`` naming the argument, the value and
what is accepted (never a TypeError, ValueError or OverflowError from
``float()`` or numpy)."""

from __future__ import annotations

import math
import warnings

import numpy as np
import polars as pl
import pytest
from diagnose_toy import Rig, conditions, measured

import thermobear as tb

ROTOR = "seed-ceramic-spindle"


def _refused(fn, *args, match: str, **kwargs) -> str:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", tb.PlausibilityWarning)
        with pytest.raises(tb.ConfigError, match=match) as e:
            fn(*args, **kwargs)
    return str(e.value)


@pytest.mark.parametrize(
    ("fn", "kwargs", "match"),
    [
        (tb.spectrum, dict(speed_rpm="12000"), r"speed_rpm = '12000'.*not a str"),
        (tb.spectrum_orders, dict(duration_s=None), r"duration_s = None"),
        (tb.spectrum, dict(unbalance_grade=[1.0]), r"unbalance_grade"),
        (tb.vibration, dict(unbalance_grade=1e300), r"unbalance_grade = 1e\+300.*4000"),
        (tb.vibration, dict(unbalance_g_mm=-1.0), r"unbalance_g_mm = -1"),
        (tb.vibration, dict(method=3), r"method = 3.*'frequency', 'time'"),
        (tb.vibration, dict(model=None), r"model = None.*'rotor', 'seed-b'"),
        (tb.vibration, dict(coupled=np.array([1.0, 2.0])), r"coupled.*True or False"),
        (tb.campbell, dict(modes=93), r"modes = 93.*\[1, 92\]"),
        (tb.campbell, dict(modes=10**30), r"modes"),
        (tb.campbell, dict(effects=3.0), r"effects = 3.*sequence of names"),
        (tb.critical_speeds, dict(harmonic="1"), r"harmonic = '1'"),
        (tb.critical_speeds, dict(speeds_rpm=[0.0, math.nan]), r"speeds_rpm\[1\] = nan"),
        (tb.rotor.displacement_vibration, dict(runout_um=None), r"runout_um = None"),
        (tb.rotor.displacement_vibration, dict(speeds_rpm=[0.0]), r"speeds_rpm.*> 0 rpm"),
    ],
)
def test_rotor_arguments_are_named(fn, kwargs, match):
    _refused(fn, ROTOR, coupled=kwargs.pop("coupled", False), match=match, **kwargs)


def test_a_time_response_past_the_step_cap_names_duration_and_speed():
    """64 steps a revolution: 300 s at 60,000 rpm is 19.2 million steps, past
    the 10 million a run may take; refused before any step is taken."""
    msg = _refused(tb.spectrum, ROTOR, 60000.0, 300.0, coupled=False, match="duration_s = 300")
    assert "speed_rpm = 60000" in msg and "1.92e+07 steps" in msg


def test_orbit_velocity_refuses_text():
    _refused(tb.rotor.orbit_velocity_mm_s, "1000", 2.0, match=r"speed_rpm = '1000'")
    v = tb.rotor.orbit_velocity_mm_s(60.0, 1000.0)  # 1 rev/s on a 1 mm orbit: 2 pi mm/s
    assert float(v) == pytest.approx(2.0 * math.pi)


SEED_TABLE = dict(
    pinion_teeth=29, gear_teeth=78, normal_module_mm=1.537, normal_pressure_angle_deg=16.5,
    helix_angle_deg=31.2, face_width_mm=33.0, youngs_modulus_mpa=206_000.0, poisson_ratio=0.25,
    density_t_per_mm3=7.8e-9, mass_kg=(1.201, 3.1), polar_inertia_t_mm2=(0.1152, 1.6),
    input_torque_n_m=100.0,
)  # fmt: skip


@pytest.mark.parametrize(
    ("change", "match"),
    [
        ({"pinion_teeth": "29"}, r"pinion_teeth = '29'"),
        ({"gear_teeth": 78.5}, r"gear_teeth = 78.5.*whole number"),
        ({"normal_module_mm": math.inf}, r"normal_module_mm = inf"),
        ({"mass_kg": [1.2]}, r"mass_kg.*two finite numbers"),
        ({"polar_inertia_t_mm2": None}, r"polar_inertia_t_mm2 = None"),
        ({"input_torque_n_m": True}, r"input_torque_n_m = True"),
    ],
)
def test_gear_pair_from_table_names_the_field(change, match):
    _refused(tb.GearPair.from_table, match=match, **{**SEED_TABLE, **change})


def test_the_same_table_as_numbers_builds_the_preset_pair():
    pair = tb.GearPair.from_table(**SEED_TABLE)
    preset = tb.GearPair.preset("seed-electric-drive")
    assert pair.geometry["transverse_contact_ratio"] == pytest.approx(
        preset.geometry["transverse_contact_ratio"]
    )


@pytest.fixture(scope="module")
def rig_data():
    return Rig(), measured(Rig(extra_heat_w=30.0), conditions(np.linspace(2e3, 16e3, 6)), 1)


@pytest.mark.parametrize(
    ("kwargs", "match"),
    [
        (dict(max_rounds=2.5), r"max_rounds = 2.5"),
        (dict(max_rounds="3"), r"max_rounds = '3'"),
        (dict(delta_bic_min=None), r"delta_bic_min = None"),
        (dict(tie_delta_bic=-1.0), r"tie_delta_bic = -1"),
        (dict(lookalike_cosine=2.0), r"lookalike_cosine = 2.*\[0, 1\]"),
        (dict(suggest=1), r"suggest = 1.*True or False"),
        (dict(outliers=None), r"outliers = None"),
        (dict(candidates=3.0), r"candidates = 3"),
        (dict(candidates=["extra_heat_w", 7]), r"candidates\[1\] = 7"),
        (dict(holdout=object()), r"holdout = <object"),
        (dict(holdout=np.int64(7)), r"holdout = np.int64\(7\).*\(0, 1\)"),
        (dict(envelope={"speed_rpm": (math.nan, 1.0)}), r"envelope\['speed_rpm'\]"),
        (dict(envelope=[1.0]), r"envelope = \[1.0\]"),
    ],
)
def test_diagnose_arguments_are_named(rig_data, kwargs, match):
    _refused(tb.diagnose, *rig_data, match=match, **kwargs)


def test_calibrate_candidates_and_predict_arguments_are_named(rig_data):
    rig, data = rig_data
    _refused(tb.calibrate, 3, ["extra_heat_w"], match=r"datasets = 3")
    _refused(tb.calibrate, [(rig, data)], None, match=r"parameters = None")
    _refused(tb.calibrate, [(rig, data)], ["extra_heat_w"], per_set=1.0, match=r"per_set = 1")
    _refused(tb.candidates, None, quantities=None, match=r"quantities = None")
    # one name is a name, not a sequence of its letters
    one = tb.calibrate([(rig, data)], "extra_heat_w")
    assert one.parameters["name"].to_list() == ["extra_heat_w"]
    cal = tb.calibrate([(rig, data)], ["extra_heat_w"])
    for kwargs, match in [
        (dict(seed=-1), r"seed = -1.*>= 0"),
        (dict(seed=math.nan), r"seed = nan"),
        (dict(samples=10**30), r"samples = .*\[8, 1048576\]"),
        (dict(samples=8.0), r"samples = 8.0"),
    ]:
        _refused(tb.predict, cal, "measured", None, method="sampling", match=match, **kwargs)


def test_gear_regimes_refuses_a_non_frame():
    _refused(tb.regimes, None, match=r"pts = None.*DataFrame")
    assert tb.regimes(pl.DataFrame({"speed_rpm": [5e3] * 8, "dte_um": [1.0, 2.0] * 4})).height


def test_finite_inputs_that_overflow_are_named():
    """Strays the fuzz found: finite inputs whose result overflows."""
    _refused(tb.rotor.orbit_velocity_mm_s, [1e5], 1e308, match=r"speed_rpm.*displacement_um")
    _refused(tb.rotor.orbit_velocity_mm_s, [1.0, 2.0], [1.0, 2.0, 3.0], match=r"displacement_um")
    pair = tb.GearPair.preset("seed-electric-drive")
    _refused(pair.mesh_frequency_hz, 6.2e306, match=r"speed_rpm = 6.2e\+306.*not a finite")
    # z_p n / 60: 29 teeth at 6,000 rpm mesh 2,900 times a second
    assert pair.mesh_frequency_hz(6000.0) == pytest.approx(2900.0)


def test_a_separating_measurement_sigma_is_checked_per_quantity(rig_data):
    """A sigma of None or text for one quantity is named (it was a TypeError)."""
    from thermobear.diagnosis.calibrated import CalibratedModel, _Step

    rig, _ = rig_data
    pool = {c.name: c for c in rig.candidate_list()}
    members = [
        CalibratedModel("calibration", n, rig, [_Step(n, pool[n])], np.array([v]), np.eye(1))
        for n, v in [("extra_heat_w", 5.0), ("lubrication_factor_f0", 1.3)]
    ]
    tie = CalibratedModel("tie", "tie", rig, [], np.array([]), np.zeros((0, 0)), members=members)
    env = {"speeds_rpm": [4000.0, 8000.0], "axial_n": 300.0}
    q = "outer_ring_temperature_c"
    _refused(tb.separating_measurement, tie, env, {q: None}, match=rf"sigma\['{q}'\] = None")
    _refused(tb.separating_measurement, tie, env, "", match=r"sigma = ''")
    _refused(tb.separating_measurement, tie, env, -0.5, match=r"sigma = -0.5.*> 0")
    assert tb.separating_measurement(tie, env, {q: 0.5})["quantity"].to_list() == [q]
