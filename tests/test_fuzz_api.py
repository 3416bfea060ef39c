"""Property-based fuzz of the public entry points (hypothesis).

Every call starts from a valid set of arguments and replaces one to three
of them with a generated value: a wrong type (None, a string such as
``"1000"``, a bool, a list, an object), a huge, tiny or non-finite float, a
huge integer, or a plausible number. Each call must

* return a valid result or raise a ``thermobear.ThermobearError`` (never
  another exception type),
* hold no non-finite number in a successful result (nulls of failed rows
  in a batch frame are allowed: they are not numbers), and
* take no longer than ``CALL_BOUND_S``.

Profiles: the default (CI) runs the short counts of ``CASES`` (2,550 in
total: at least 2,000, under two minutes on a 2-core machine);
``THERMOBEAR_FUZZ=long`` runs the long ones (120,000 in total; with
``THERMOBEAR_FUZZ_SCALE`` a share of them, on the seed of
``pytest --hypothesis-seed=N``). The counts
of the last long run are on the docs page "Limits" (docs/concepts/limits.md).
"""

from __future__ import annotations

import math
import os
import time
import warnings
from typing import Any, Callable

import numpy as np
import polars as pl
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import thermobear as tb

LONG = os.environ.get("THERMOBEAR_FUZZ", "").lower() == "long"
#: A share of the long counts (``THERMOBEAR_FUZZ_SCALE=0.2``: a fifth), for a
#: run of a given size on a seed of one's own (``pytest --hypothesis-seed=N``).
SCALE = float(os.environ.get("THERMOBEAR_FUZZ_SCALE", "1"))

#: Slowest call allowed [s] (the slowest entry fuzzed here, a spindle steady
#: state near its runaway, takes well under a second on this machine).
CALL_BOUND_S = 10.0

#: Cases per group: (short profile, long profile). Short: 2,550 in total.
CASES = {
    "construct": (500, 20_000),
    "bearing": (800, 40_000),
    "thermal": (300, 15_000),
    "spindle": (150, 7_000),
    "gear": (150, 8_000),
    "study_predict": (200, 10_000),
    "rotor": (150, 8_000),
    "gear_table": (150, 6_000),
    "diagnosis": (150, 6_000),
}


#: Extra time allowed per Monte Carlo sample a call is asked for [s]: a
#: valid ``samples`` count is work the caller asked for (a sample of the
#: closed-form rig costs about 0.13 ms on this machine under load).
PER_SAMPLE_S = 3e-4


def _bound_s(kwargs: dict[str, Any]) -> float:
    """The time bound of one call: ``CALL_BOUND_S`` plus the requested
    samples' share."""
    n = kwargs.get("samples")
    extra = PER_SAMPLE_S * n if isinstance(n, int) and not isinstance(n, bool) and n > 0 else 0.0
    return CALL_BOUND_S + extra


def _cases(group: str) -> int:
    return max(1, int(CASES[group][1] * SCALE)) if LONG else CASES[group][0]


def _settings(group: str) -> Callable[[Any], Any]:
    return settings(
        max_examples=_cases(group),
        deadline=None,
        database=None,
        derandomize=not LONG,  # CI: the same cases every run
        suppress_health_check=list(HealthCheck),
    )


SPECIAL = [0.0, -0.0, 5e-324, 1e-300, -1e-300, 1e-12, 1e12, 1e300, -1e300, 1.7e308,
           math.nan, math.inf, -math.inf]  # fmt: skip

#: Any value a user might pass by mistake (or on purpose).
WILD = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.sampled_from(SPECIAL),
    st.floats(min_value=-1e5, max_value=1e5),
    st.integers(min_value=-(10**30), max_value=10**30),
    st.integers(min_value=-3, max_value=300),
    st.booleans(),
    st.none(),
    st.sampled_from(["1000", "nan", "", "outer", "grease", "speed", "spring"]),
    st.lists(st.floats(min_value=-1e4, max_value=1e4), max_size=3),
    st.sampled_from([object(), np.float32(3.0), np.int64(7), np.array([1.0, 2.0]), {"a": 1}]),
)


def _mutated(draw: Any, base: dict[str, Any], most: int = 3) -> dict[str, Any]:
    """``base`` with one to ``most`` arguments replaced by wild values."""
    keys = draw(st.lists(st.sampled_from(sorted(base)), min_size=1, max_size=most, unique=True))
    out = dict(base)
    for k in keys:
        out[k] = draw(WILD, label=k)
    return out


# -- the checks -------------------------------------------------------------------


def _nonfinite(obj: Any, path: str = "result", depth: int = 0) -> list[str]:
    """Paths of the non-finite numbers in a result (nulls are not numbers)."""
    if depth > 6:
        return []
    if isinstance(obj, pl.DataFrame):
        bad = []
        for c in obj.columns:
            if obj[c].dtype.is_float():
                s = obj[c].drop_nulls()
                if (s.is_nan() | s.is_infinite()).any():
                    bad.append(f"{path}[{c}]")
        return bad
    if isinstance(obj, np.ndarray):
        if obj.dtype.kind in "fc" and not np.all(np.isfinite(obj)):
            return [path]
        return []
    if isinstance(obj, float):
        return [] if math.isfinite(obj) else [path]
    if isinstance(obj, dict):
        return [p for k, v in obj.items() for p in _nonfinite(v, f"{path}.{k}", depth + 1)]
    if isinstance(obj, (list, tuple)):
        return [p for i, v in enumerate(obj) for p in _nonfinite(v, f"{path}[{i}]", depth + 1)]
    raw = getattr(obj, "raw", None)
    if isinstance(raw, dict):
        return _nonfinite(raw, path, depth + 1)
    return []


def _call(label: str, fn: Callable[..., Any], *args: Any, **kwargs: Any) -> Any:
    """``fn(*args, **kwargs)`` under the three rules; the result or None."""
    t0 = time.perf_counter()
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            out = fn(*args, **kwargs)
    except tb.ThermobearError as e:
        out = None
        assert str(e), f"{label}: an empty message"
    except BaseException as e:  # noqa: BLE001 - the point of the test
        if isinstance(e, KeyboardInterrupt) and not isinstance(e, tb.Interrupted):
            raise
        raise AssertionError(f"{label}({args}, {kwargs}) raised {type(e).__name__}: {e}") from e
    elapsed = time.perf_counter() - t0
    assert elapsed < _bound_s(kwargs), f"{label}({kwargs}) took {elapsed:.1f} s"
    if out is not None:
        bad = _nonfinite(out)
        assert not bad, f"{label}({kwargs}) returned non-finite numbers at {bad[:5]}"
    return out


# -- fixtures (module-level: hypothesis calls the tests many times) ---------------

BEARINGS = {name: tb.Bearing.preset(name) for name in ("6208", "7009C-hybrid", "7008C")}
SPINDLE = tb.Spindle.preset("seed-ceramic-spindle")
GEAR = tb.GearPair.preset("seed-electric-drive")

GEOMETRY = dict(
    ball_count=9, ball_diameter_mm=12.0, pitch_diameter_mm=60.0, inner_conformity=0.52,
    outer_conformity=0.53, bore_mm=40.0, outer_diameter_mm=80.0, width_mm=18.0,
)  # fmt: skip


# -- constructors -----------------------------------------------------------------


@st.composite
def constructor_calls(draw: Any) -> tuple[str, Callable[..., Any], dict[str, Any]]:
    which = draw(st.sampled_from(["deep_groove", "angular_contact", "material", "with_options"]))
    if which == "deep_groove":
        base = {**GEOMETRY, "diametral_clearance_mm": 0.04}
        return which, tb.Bearing.deep_groove, _mutated(draw, base)
    if which == "angular_contact":
        base = {**GEOMETRY, "free_contact_angle_deg": 15.0}
        return which, tb.Bearing.angular_contact, _mutated(draw, base)
    if which == "material":
        base = dict(youngs_modulus_gpa=208.0, poisson_ratio=0.3, density_kg_m3=7830.0,
                    thermal_expansion_per_k=1.25e-5, conductivity_w_mk=42.7,
                    specific_heat_j_kgk=458.0)  # fmt: skip
        return which, lambda **k: tb.Material("x", **k), _mutated(draw, base)
    base = dict(preload_n=400.0, preload_kind="spring", spring_rate_n_per_um=0.36,
                radial_load_n=0.0, spin_friction_coefficient=0.05,
                lubrication="oil-air", lubrication_factor_f0=1.0)  # fmt: skip
    return which, SPINDLE.with_options, _mutated(draw, base)


@_settings("construct")
@given(call=constructor_calls())
def test_constructors(call):
    label, fn, kwargs = call
    out = _call(label, fn, **kwargs)
    if isinstance(out, tb.Bearing):
        assert all(math.isfinite(v) for v in out.geometry.values())


# -- the bearing ---------------------------------------------------------------------


@st.composite
def bearing_calls(draw: Any) -> tuple[str, Callable[..., Any], dict[str, Any]]:
    b = BEARINGS[draw(st.sampled_from(sorted(BEARINGS)))]
    which = draw(st.sampled_from(["solve", "solve", "solve", "contact", "ring_forces",
                                  "solve_many"]))  # fmt: skip
    if which == "solve":
        base = dict(axial_n=500.0, radial_n=200.0, moment_n_m=0.0, speed_rpm=12000.0,
                    misalignment_rad=0.0, raceway_control="outer", effects=None)  # fmt: skip
        return which, b.solve, _mutated(draw, base)
    if which == "contact":
        base = dict(raceway="inner", contact_angle_deg=20.0, load_n=1000.0, exact=True)
        return which, b.contact, _mutated(draw, base)
    if which == "ring_forces":
        base = dict(displacement=[0.0, 0.0, 2e-5, 0.0, 0.0], speed_rpm=6000.0)
        return which, b.ring_forces, _mutated(draw, base, 2)
    base = dict(points={"axial_n": [500.0, 800.0], "speed_rpm": [1000.0, 9000.0]},
                misalignment_rad=0.0, threads=1, raceway_control="outer")  # fmt: skip
    return which, b.solve_many, _mutated(draw, base, 2)


@_settings("bearing")
@given(call=bearing_calls())
def test_bearing_entry_points(call):
    label, fn, kwargs = call
    _call(label, fn, **kwargs)


# -- heat and thermal state -----------------------------------------------------------


@st.composite
def thermal_calls(draw: Any) -> tuple[str, Callable[..., Any], dict[str, Any]]:
    b = BEARINGS[draw(st.sampled_from(sorted(BEARINGS)))]
    which = draw(st.sampled_from(["thermal_state", "isothermal_heat", "stiffness_curve",
                                  "stiffness_constant"]))  # fmt: skip
    common = dict(speed_rpm=9000.0, axial_n=400.0, radial_n=100.0)
    if which == "thermal_state":
        base = dict(common, lubrication="oil-air", heat_model="palmgren",
                    oil_air_temperature_c=28.0, extra_heat_w=0.0, misalignment_rad=0.0,
                    lubrication_factor_f0=None, churning_oil_fraction=None)  # fmt: skip
        return which, lambda **k: tb.thermal_state(b, **k), _mutated(draw, base)
    if which == "isothermal_heat":
        base = dict(common, oil_temperature_c=40.0, lubrication="jet", heat_model="skf",
                    spin_friction_coefficient=0.05)  # fmt: skip
        return which, lambda **k: tb.isothermal_heat(b, **k), _mutated(draw, base)
    mode = "constant" if which == "stiffness_constant" else "speed"
    base = dict(speeds_rpm=[1000.0, 8000.0], axial_n=400.0, radial_n=100.0, mode=mode,
                misalignment_rad=0.0)  # fmt: skip
    return which, lambda **k: tb.stiffness_curve(b, **k), _mutated(draw, base, 2)


@_settings("thermal")
@given(call=thermal_calls())
def test_thermal_entry_points(call):
    label, fn, kwargs = call
    _call(label, fn, **kwargs)


# -- spindle -------------------------------------------------------------------------


@st.composite
def spindle_calls(draw: Any) -> tuple[str, Callable[..., Any], dict[str, Any]]:
    which = draw(st.sampled_from(["steady", "steady", "transient", "isothermal"]))
    if which == "steady":
        base = dict(speed_rpm=12000.0, preload_n=400.0, radial_n=0.0)
        return which, lambda **k: tb.thermal_state(SPINDLE, **k), _mutated(draw, base, 2)
    if which == "isothermal":
        return which, SPINDLE.isothermal, _mutated(draw, dict(speed_rpm=12000.0), 1)
    base = dict(speed_rpm=12000.0, duration_s=20.0, dt_s=10.0, record_every=1,
                initial_temperature_c=None, mechanics_update_k=0.05)  # fmt: skip
    kwargs = _mutated(draw, base, 2)
    # keep a generated run short: at most 200 steps (the step cap has its own test)
    d, dt = kwargs["duration_s"], kwargs["dt_s"]
    if all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in (d, dt)):
        if math.isfinite(d) and math.isfinite(dt) and dt > 0 and d / dt > 200:
            kwargs["duration_s"] = 200 * dt
    return which, lambda **k: tb.transient(SPINDLE, **k), kwargs


@_settings("spindle")
@given(call=spindle_calls())
def test_spindle_entry_points(call):
    label, fn, kwargs = call
    _call(label, fn, **kwargs)


# -- gears ---------------------------------------------------------------------------


@st.composite
def gear_calls(draw: Any) -> tuple[str, Callable[..., Any], dict[str, Any]]:
    base = dict(stiffness="constant", torque_n_m=20.0, te_amplitude_um=10.0,
                half_backlash_um=50.0, mesh_damping_ratio=0.05)  # fmt: skip
    return "GearSystem", lambda **k: tb.GearSystem(GEAR, **k), _mutated(draw, base)


@_settings("gear")
@given(call=gear_calls())
def test_gear_system_construction(call):
    label, fn, kwargs = call
    _call(label, fn, **kwargs)


# -- design studies and predictions -------------------------------------------------


def _calibrated_model() -> Any:
    from thermobear.diagnosis.calibrated import CalibratedModel, _Step

    spec = tb.BearingModelSpec(BEARINGS["7008C"])
    pool = {c.name: c for c in spec.candidate_list()}
    steps = [_Step("extra_heat_w", pool["extra_heat_w"])]
    return CalibratedModel("calibration", "", spec, steps, np.array([5.0]), np.eye(1))


MODEL = _calibrated_model()


@st.composite
def study_predict_calls(draw: Any) -> tuple[str, Callable[..., Any], dict[str, Any]]:
    if draw(st.booleans()):
        base = dict(kind="bearing", grid={"speed_rpm": [1000.0, 2000.0], "axial_n": [300.0]},
                    fixed={"bearing": "7008C"}, chunk_size=2)  # fmt: skip
        kwargs = _mutated(draw, base, 2)
        if draw(st.booleans()):  # a wild value inside the grid
            kwargs["grid"] = {"speed_rpm": [draw(WILD)], "axial_n": [300.0]}
        return "Study", tb.Study, kwargs
    conditions = {"speeds_rpm": [4000.0], "axial_n": 300.0}
    if draw(st.booleans()):
        conditions = dict(conditions, **{draw(st.sampled_from(sorted(conditions))): draw(WILD)})
    base = dict(what="temperatures", conditions=conditions, level=0.95, method="delta")
    kwargs = _mutated(draw, base, 1) if draw(st.booleans()) else base
    return "predict", lambda **k: tb.predict(MODEL, **k), kwargs


@_settings("study_predict")
@given(call=study_predict_calls())
def test_study_and_predict_entry_points(call):
    label, fn, kwargs = call
    _call(label, fn, **kwargs)


# -- the rotor --------------------------------------------------------------------

ROTOR = "seed-ceramic-spindle"

#: Time steps a generated time response may take (the step cap has its own test).
_FUZZ_STEPS = 20_000


#: The speeds a time response runs without ``speeds_rpm`` (``tb.vibration``'s
#: default grid) [rpm].
_DEFAULT_SPEEDS = np.linspace(3_000.0, 30_000.0, 10)


def _short_record(kwargs: dict[str, Any], speeds: Any) -> dict[str, Any]:
    """``kwargs`` with a numeric ``duration_s`` cut to ``_FUZZ_STEPS`` steps of
    1/64 revolution in all, over every numeric speed (the default grid
    without speeds; wild values stay)."""
    d = kwargs.get("duration_s")
    arr = np.atleast_1d(np.asarray(speeds if speeds is not None else _DEFAULT_SPEEDS, dtype=object))
    nums = [float(x) for x in arr.ravel() if type(x) in (int, float) and abs(x) < 1e300]
    if type(d) in (int, float) and math.isfinite(d) and d > 0 and nums:
        revs_per_s = max(sum(abs(x) for x in nums), 1.0) / 60.0
        kwargs["duration_s"] = min(d, _FUZZ_STEPS / 64.0 / revs_per_s)
    return kwargs


@st.composite
def rotor_calls(draw: Any) -> tuple[str, Callable[..., Any], dict[str, Any]]:
    which = draw(st.sampled_from(["campbell", "critical_speeds", "vibration", "vibration_time",
                                  "spectrum", "spectrum_orders", "displacement",
                                  "orbit"]))  # fmt: skip
    spindle = draw(st.sampled_from([ROTOR, "seed-steel-spindle", SPINDLE]))
    common = dict(spindle=spindle, coupled=spindle is SPINDLE, effects=None)
    if which in ("campbell", "critical_speeds"):
        base = dict(common, speeds_rpm=[1000.0, 60000.0], modes=2)
        if which == "critical_speeds":
            base["harmonic"] = 1.0
        return which, getattr(tb, which), _mutated(draw, base)
    if which in ("vibration", "vibration_time"):
        base = dict(common, speeds_rpm=[12000.0], unbalance_grade=None, unbalance_g_mm=None,
                    method="time" if which == "vibration_time" else "frequency",
                    duration_s=0.01, model="rotor")  # fmt: skip
        kwargs = _mutated(draw, base)
        return which, tb.vibration, _short_record(kwargs, kwargs["speeds_rpm"])
    if which in ("spectrum", "spectrum_orders"):
        base = dict(common, speed_rpm=12000.0, duration_s=0.01, nonlinear=False,
                    unbalance_grade=2.5, unbalance_g_mm=None)  # fmt: skip
        kwargs = _mutated(draw, base)
        return which, getattr(tb, which), _short_record(kwargs, kwargs["speed_rpm"])
    if which == "displacement":
        base = dict(spindle=spindle, speeds_rpm=[12000.0], coupled=False, radial_load_n=None,
                    runout_um=0.0)  # fmt: skip
        return which, tb.rotor.displacement_vibration, _mutated(draw, base)
    base = dict(speed_rpm=[1000.0, 2000.0], displacement_um=2.0)
    return which, tb.rotor.orbit_velocity_mm_s, _mutated(draw, base, 1)


@_settings("rotor")
@given(call=rotor_calls())
def test_rotor_entry_points(call):
    label, fn, kwargs = call
    _call(label, fn, **kwargs)


# -- gear pair from a table, its curves and the linear system ------------------------

GEAR_TABLE = dict(
    pinion_teeth=29, gear_teeth=78, normal_module_mm=1.537, normal_pressure_angle_deg=16.5,
    helix_angle_deg=31.2, face_width_mm=33.0, youngs_modulus_mpa=206_000.0, poisson_ratio=0.25,
    density_t_per_mm3=7.8e-9, mass_kg=(1.201, 3.1), polar_inertia_t_mm2=(0.1152, 1.6),
    input_torque_n_m=100.0, profile_shift_coeff=(0.0, 0.0), addendum_coeff=1.0,
    dedendum_coeff=1.25,
)  # fmt: skip

GEAR_SYSTEM = tb.GearSystem(GEAR, stiffness="constant", torque_n_m=20.0)

#: The linear-system methods of a GearSystem and their arguments.
_SYSTEM_METHODS = {
    "bearing_stiffness_at": dict(speed_rpm=5000.0),
    "mass_matrix_kg": dict(speed_rpm=5000.0),
    "stiffness_matrix_n_per_m": dict(speed_rpm=5000.0, mesh_stiffness_n_per_m=None),
    "natural_frequencies_hz": dict(speed_rpm=5000.0, mesh_stiffness_n_per_m=9e8),
    "static_state_m": dict(speed_rpm=5000.0),
    "mesh_period_s": dict(speed_rpm=5000.0),
    "check_steps": dict(speed_rpm=5000.0, steps_per_period=64),
}


@st.composite
def gear_table_calls(draw: Any) -> tuple[str, Callable[..., Any], dict[str, Any]]:
    which = draw(st.sampled_from(["from_table", "from_table", "mesh_stiffness",
                                  "mesh_frequency_hz", "system", "regimes"]))  # fmt: skip
    if which == "from_table":
        return which, tb.GearPair.from_table, _mutated(draw, GEAR_TABLE)
    if which == "mesh_stiffness":
        base = dict(points=16, model="potential-energy")
        return which, GEAR.mesh_stiffness, _mutated(draw, base, 2)
    if which == "mesh_frequency_hz":
        return which, GEAR.mesh_frequency_hz, _mutated(draw, dict(speed_rpm=5000.0), 1)
    if which == "system":
        name = draw(st.sampled_from(sorted(_SYSTEM_METHODS)))
        return name, getattr(GEAR_SYSTEM, name), _mutated(draw, _SYSTEM_METHODS[name], 2)
    pts = pl.DataFrame({"speed_rpm": [5000.0] * 8, "dte_um": [1.0, 2.0] * 4})
    base = dict(pts=pts, max_period=4, period_rel_tol=1e-3)
    return which, tb.regimes, _mutated(draw, base, 2)


@_settings("gear_table")
@given(call=gear_table_calls())
def test_gear_table_and_system_entry_points(call):
    label, fn, kwargs = call
    _call(label, fn, **kwargs)


# -- diagnosis, calibration and the prediction arguments -----------------------------


def _diagnosis_fixtures() -> tuple[Any, Any, Any, Any]:
    """The closed-form rig of ``diagnose_toy`` (no solver: a diagnosis takes
    tens of ms), refusing conditions outside its range as a model does;
    measurements of an extra heat on it; its calibration of that heat; and
    a tie of two calibrated explanations on it."""
    from diagnose_toy import Rig, conditions, measured

    from thermobear.diagnosis.calibrated import CalibratedModel, _Step

    class BoundedRig(Rig):
        def predict(self, conditions: Any) -> dict[str, Any]:
            n = conditions["speed_rpm"].to_numpy()
            f = conditions["axial_n"].to_numpy()
            if not (np.all((0.0 <= n) & (n <= 1e5)) and np.all(np.abs(f) <= 1e6)):
                raise tb.ConfigError("invalid conditions: outside the rig's range")
            return super().predict(conditions)

        def with_setting(self, add_effects: Any = (), **options: Any) -> Any:
            new = BoundedRig(set(self.effects) | set(add_effects), **{**self.options, **options})
            new._cache = self._cache
            return new

    rig = BoundedRig()
    data = measured(Rig(extra_heat_w=30.0), conditions(np.linspace(2000.0, 16000.0, 6)), 1)
    spec = rig
    pool = {c.name: c for c in spec.candidate_list()}
    members = [
        CalibratedModel("calibration", f"tie member {i}: {n}", spec, [_Step(n, pool[n])],
                        np.array([v]), np.eye(1) * 0.01 * v)
        for i, (n, v) in enumerate([("extra_heat_w", 5.0), ("lubrication_factor_f0", 1.3)])
    ]  # fmt: skip
    tie = CalibratedModel("tie", "tie", spec, [], np.array([]), np.zeros((0, 0)), members=members)
    return rig, data, members[0], tie


RIG, RIG_DATA, RIG_MODEL, TIE = _diagnosis_fixtures()


@st.composite
def diagnosis_calls(draw: Any) -> tuple[str, Callable[..., Any], dict[str, Any]]:
    which = draw(st.sampled_from(["diagnose", "diagnose", "calibrate", "candidates", "predict",
                                  "separating_measurement", "regime_boundaries"]))  # fmt: skip
    if which == "diagnose":
        base = dict(candidates=None, holdout="highest_speeds", max_rounds=2, delta_bic_min=10.0,
                    tie_delta_bic=2.0, lookalike_cosine=0.95, suggest=False,
                    envelope={"speed_rpm": (2000.0, 16000.0)}, outliers=False,
                    control=True)  # fmt: skip
        kwargs = _mutated(draw, base)
        if draw(st.booleans()):  # a wild value inside the envelope
            kwargs["envelope"] = {"speed_rpm": (draw(WILD), 16000.0), "axial_n": [draw(WILD)]}
        return which, lambda **k: tb.diagnose(RIG, RIG_DATA, **k), kwargs
    if which == "calibrate":
        base = dict(datasets=[(RIG, RIG_DATA)], parameters=["extra_heat_w"], per_set=())
        return which, tb.calibrate, _mutated(draw, base, 2)
    if which == "candidates":
        base = dict(model=draw(st.sampled_from([None, RIG])), quantities=("heat_w",))
        return which, tb.candidates, _mutated(draw, base, 1)
    if which == "predict":
        base = dict(what="measured", conditions={"speeds_rpm": [4000.0], "axial_n": 300.0},
                    level=0.9, method="sampling", samples=8, seed=0)  # fmt: skip
        return which, lambda **k: tb.predict(RIG_MODEL, **k), _mutated(draw, base, 2)
    if which == "separating_measurement":
        env = {"speeds_rpm": [4000.0, 8000.0], "axial_n": 300.0}
        base = dict(envelope_conditions=env, sigma=None, what="measured")
        kwargs = _mutated(draw, base, 2)
        if draw(st.booleans()):  # a wild sigma for one quantity
            kwargs["sigma"] = {"outer_ring_temperature_c": draw(WILD)}
        return which, lambda **k: tb.separating_measurement(TIE, **k), kwargs
    frames = [pl.DataFrame(), pl.DataFrame({"speed_rpm": [1.0]}), pl.DataFrame({"a": ["x"]})]
    prediction = draw(st.one_of(WILD, st.sampled_from(frames)))
    return which, tb.regime_boundaries, {"prediction": prediction}


@_settings("diagnosis")
@given(call=diagnosis_calls())
def test_diagnosis_and_prediction_arguments(call):
    label, fn, kwargs = call
    _call(label, fn, **kwargs)


def test_the_short_profile_is_at_least_2000_cases():
    assert sum(short for short, _ in CASES.values()) >= 2000
    assert sum(long for _, long in CASES.values()) >= 100_000


@pytest.mark.parametrize("bad", [None, "1000", True, [1.0], math.nan, 1e300])
def test_a_stray_speed_is_a_named_config_error(bad):
    """The fuzz's own rules on one hand-picked argument, for every bearing
    entry that takes a speed."""
    b = BEARINGS["6208"]
    for fn in (b.solve, lambda **k: tb.isothermal_heat(b, oil_temperature_c=40.0, **k)):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            try:
                fn(speed_rpm=bad)
            except tb.ConfigError as e:
                assert "speed_rpm" in str(e)
            except tb.ConvergenceError as e:  # 1e300: solvable input, impossible solve
                assert "speed_rpm = 1e+300" in str(e)
            else:
                pytest.fail(f"speed_rpm = {bad!r} accepted")
