"""A calibrated model stands for its machine everywhere: every public
function (and class) of ``thermobear`` whose first parameter is a machine
-- a bearing, a spindle, a gear pair or system, a model -- is found by
walking ``thermobear.__all__``, and each is called with a calibrated model
and compared, to the last bit, with the call on the machine with the
calibrated options written out by hand (the load scales applied to the
stated loads); a call that has no machine form is listed with its reason.
Every plot function draws a result: given a model it names the call that
computes that result instead of failing on it."""

from __future__ import annotations

import inspect
import pickle
import sys
from pathlib import Path
from typing import Any, Callable

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear.diagnosis.calibrated import _Step

sys.path.insert(0, str(Path(__file__).parent))
from diagnose_toy import Rig, conditions, measured  # noqa: E402

#: First-parameter names that take a machine (or a model of one).
MACHINE_PARAMETERS = {"bearing", "spindle", "gear", "system", "systems", "system_or_name",
                      "model", "machine"}  # fmt: skip

#: Public callables that take a machine first but are not called with a
#: calibrated model in place of a machine, and why.
EXCLUDED = {
    "BearingModelSpec": "builds the uncalibrated baseline spec of a bearing; a calibrated "
    "model's spec is CalibratedModel.spec (refused with a ConfigError, tested below)",
    "SpindleModelSpec": "the same for a spindle",
    "GearModelSpec": "the same for a gear pair",
    "diagnose_spindle": "deprecated alias of diagnose (which is covered)",
    "spindle_candidates": "deprecated alias of candidates (which is covered)",
    "predict": "takes a calibrated model by design: it has no machine form to compare with",
    "separating_measurement": "takes a calibrated tie by design: no machine form",
    "BearingSet": "a part of a spindle description: a bearing's geometry by name or a Bearing; "
    "a calibrated bearing's options are single-bearing heat settings, which the spindle's own "
    "lubrication and motor parts set",
}

#: Plot functions whose first parameter is no result of a model.
PLOT_EXCLUDED = {
    "axis_label": "takes a column name",
    "set_style": "takes matplotlib rc settings",
}


def _machine_first(obj: Any) -> bool:
    try:
        params = list(inspect.signature(obj).parameters)
    except (TypeError, ValueError):
        return False
    return bool(params) and params[0] in MACHINE_PARAMETERS


def public_machine_callables() -> list[str]:
    """The names in ``thermobear.__all__`` whose first parameter is a machine."""
    out = []
    for name in tb.__all__:
        obj = getattr(tb, name)
        if inspect.ismodule(obj):
            continue
        if callable(obj) and _machine_first(obj):
            out.append(name)
    return out


# ------------------------------------------------------------------ models


def _model(spec: Any, steps: list[tuple[str, float, float]], label: str) -> tb.CalibratedModel:
    """A calibrated model of ``spec`` with ``(name, value, variance)``
    estimates of its candidates (as a calibration gives them)."""
    cands = {c.name: c for c in spec.candidate_list(list(spec.quantities))}
    return tb.CalibratedModel(
        "calibration", label, spec, [_Step(n, cands[n]) for n, _, _ in steps],
        [v for _, v, _ in steps], np.diag([s for _, _, s in steps]),
    )  # fmt: skip


@pytest.fixture(scope="module")
def bearing_model() -> tb.CalibratedModel:
    """A 7008C with a churning loss and an axial load 10 % above the stated one."""
    spec = tb.BearingModelSpec(tb.Bearing.preset("7008C"))
    return _model(spec, [("churning_oil_fraction", 0.01, 1e-6), ("axial_load_scale", 1.1, 1e-3)],
                  "7008C rig")  # fmt: skip


@pytest.fixture(scope="module")
def spindle_model() -> tb.CalibratedModel:
    """The seed spindle with more spin friction and a preload 10 % above the stated one."""
    spec = tb.SpindleModelSpec.of_model(tb.Spindle.preset("seed-ceramic-spindle"))
    return _model(spec, [("spin_friction_coefficient", 0.08, 1e-4), ("preload_scale", 1.1, 1e-3)],
                  "spindle rig")  # fmt: skip


@pytest.fixture(scope="module")
def gear_model() -> tb.CalibratedModel:
    """The seed e-drive pair with a larger transmission error and more mesh damping."""
    spec = tb.GearModelSpec(tb.GearPair.preset("seed-electric-drive"))
    return _model(spec, [("te_amplitude_um", 5.0, 0.1), ("mesh_damping_ratio", 0.1, 1e-4)],
                  "gear rig")  # fmt: skip


def _bearing_hand(m: tb.CalibratedModel) -> tuple[Any, dict[str, Any]]:
    """The bearing and the calibrated options by hand (no load scale)."""
    spec = m.spec
    return spec.bearing, {"effects": list(spec.effects), **spec.thermal_options()}


def _spindle_hand(m: tb.CalibratedModel) -> tuple[Any, dict[str, Any]]:
    """The spindle as configured by the calibration (at its stated preload
    scaled) and its effects and unbalance."""
    spec = m.spec
    return spec.configured(spec.spindle.preload_n), {
        "effects": list(spec.effects),
        "unbalance_grade": float(spec.options["unbalance_grade"]),
    }


def _gear_system(m: tb.CalibratedModel) -> tb.GearSystem:
    """The gear system of the calibrated inputs, written out."""
    opts = m.spec.system_options()
    opts.pop("torque_n_m", None)
    return tb.GearSystem(m.spec.gear, bearings=m.spec.bearing_model(),
                         stiffness=m.spec.options["stiffness"], **opts)  # fmt: skip


def _only(options: dict[str, Any], fn: Callable[..., Any]) -> dict[str, Any]:
    """The options ``fn`` has a parameter for (the hook's rule)."""
    names = set(inspect.signature(fn).parameters)
    return {k: v for k, v in options.items() if k in names}


# ------------------------------------------------------------------ comparisons


def _same(a: Any, b: Any) -> None:
    """Bit for bit the same result: frames, thermal states, systems, numbers."""
    if isinstance(a, pl.DataFrame):
        assert a.columns == b.columns
        assert a.equals(b), (a, b)
    elif hasattr(a, "raw") and isinstance(a.raw, dict):  # ThermalState, IsothermalHeat
        assert pickle.dumps(a.raw) == pickle.dumps(b.raw)
    elif isinstance(a, tb.GearSystem):
        assert pickle.dumps(a) == pickle.dumps(b)
        _same(a.stiffness_schedule, b.stiffness_schedule)
    elif isinstance(a, tb.Diagnosis):
        assert a.verdict == b.verdict and a.accepted == b.accepted
        _same(a.gap, b.gap)
    else:
        assert a == b, (a, b)


SPEEDS = [4000.0, 12000.0]
POINTS = {"speed_rpm": SPEEDS, "axial_n": [300.0, 500.0]}
TOY_CONDITIONS = conditions(np.linspace(2000.0, 16000.0, 6))


def _cases(b: Any, s: Any, g: Any) -> dict[str, tuple[Callable[[], Any], Callable[[], Any]]]:
    """Per public name: (the call with the calibrated model, the same call
    on the machine with the calibrated options by hand)."""
    bearing, bo = _bearing_hand(b)
    spindle, so = _spindle_hand(s)
    system = _gear_system(g)
    scaled = {**POINTS, "axial_n": [300.0 * 1.1, 500.0 * 1.1]}
    gear_sweep = {"transient_periods": 5, "record_periods": 5}
    lyapunov = {"periods": 20, "transient_periods": 5}
    toy = _model(Rig(), [("lubrication_factor_f0", 1.2, 0.01)], "toy")
    toy_data = measured(Rig(lubrication_factor_f0=1.2, extra_heat_w=20.0), TOY_CONDITIONS, 0)
    return {
        "isothermal_heat": (
            lambda: tb.isothermal_heat(b, 8000.0, 300.0, 0.0, oil_temperature_c=40.0),
            lambda: tb.isothermal_heat(
                bearing, 8000.0, 330.0, 0.0, oil_temperature_c=40.0, **_only(bo, tb.isothermal_heat)
            ),
        ),  # fmt: skip
        "stiffness_curve": (
            lambda: tb.stiffness_curve(b, SPEEDS, 300.0, 0.0, mode="thermal"),
            lambda: tb.stiffness_curve(bearing, SPEEDS, 330.0, 0.0, mode="thermal", **bo),
        ),
        "thermal_state": (
            lambda: tb.thermal_state(b, 8000.0, 300.0, 0.0),
            lambda: tb.thermal_state(bearing, 8000.0, 330.0, 0.0, **bo),
        ),
        "thermal_state_many": (
            lambda: tb.thermal_state_many(b, POINTS),
            # the rows carry the stated loads
            lambda: tb.thermal_state_many(bearing, scaled, **bo).with_columns(
                axial_n=pl.Series(POINTS["axial_n"])
            ),
        ),
        "transient": (
            lambda: tb.transient(s, speed_rpm=12000.0, duration_s=20.0, dt_s=10.0),
            lambda: tb.transient(spindle, speed_rpm=12000.0, duration_s=20.0, dt_s=10.0),
        ),
        "spindle_grid": (
            lambda: tb.spindle_grid(s, speeds_rpm=[12000.0], preloads_n=[300.0, 500.0]),
            lambda: tb.spindle_grid(
                spindle, speeds_rpm=[12000.0], preloads_n=[300.0 * 1.1, 500.0 * 1.1]
            ),
        ),  # fmt: skip
        "optimal_preload": (
            lambda: tb.optimal_preload(s, speeds_rpm=[12000.0], preloads_n=[300.0, 500.0]),
            lambda: tb.optimal_preload(
                spindle, speeds_rpm=[12000.0], preloads_n=[300.0 * 1.1, 500.0 * 1.1]
            ),
        ),  # fmt: skip
        "compensation_preload": (
            lambda: tb.compensation_preload(s, speeds_rpm=[12000.0]),
            lambda: tb.compensation_preload(spindle, speeds_rpm=[12000.0]),
        ),
        "campbell": (
            lambda: tb.campbell(s, [0.0, 12000.0], 2),
            lambda: tb.campbell(spindle, [0.0, 12000.0], 2, **_only(so, tb.campbell)),
        ),
        "critical_speeds": (
            lambda: tb.critical_speeds(s, [0.0, 60000.0, 120000.0], 2),
            lambda: tb.critical_speeds(
                spindle, [0.0, 60000.0, 120000.0], 2, **_only(so, tb.critical_speeds)
            ),
        ),  # fmt: skip
        "spectrum": (
            lambda: tb.spectrum(s, 12000.0, 0.02),
            lambda: tb.spectrum(spindle, 12000.0, 0.02, **_only(so, tb.spectrum)),
        ),
        "spectrum_orders": (
            lambda: tb.spectrum_orders(s, 12000.0, 0.02),
            lambda: tb.spectrum_orders(spindle, 12000.0, 0.02, **_only(so, tb.spectrum_orders)),
        ),
        "vibration": (
            lambda: tb.vibration(s, [12000.0]),
            lambda: tb.vibration(spindle, [12000.0], **_only(so, tb.vibration)),
        ),
        "GearSystem": (lambda: tb.GearSystem(g), lambda: system),
        "bifurcation": (
            lambda: tb.bifurcation(g, [2000.0, 3000.0], **gear_sweep),
            lambda: tb.bifurcation(system, [2000.0, 3000.0], **gear_sweep),
        ),
        "bifurcation_set": (
            lambda: tb.bifurcation_set({"rig": g}, [2000.0], **gear_sweep),
            lambda: tb.bifurcation_set({"rig": system}, [2000.0], **gear_sweep),
        ),
        "regime_map": (
            lambda: tb.regime_map(g, [10.0], [2000.0], **gear_sweep),
            lambda: tb.regime_map(system, [10.0], [2000.0], **gear_sweep),
        ),
        "largest_lyapunov": (
            lambda: tb.largest_lyapunov(g, 6000.0, **lyapunov),
            lambda: tb.largest_lyapunov(system, 6000.0, **lyapunov),
        ),
        # the verbs on a model spec take the calibrated model's spec
        "candidates": (lambda: tb.candidates(b), lambda: tb.candidates(b.spec)),
        "diagnose": (
            lambda: tb.diagnose(toy, toy_data, holdout=None),
            lambda: tb.diagnose(toy.spec, toy_data, holdout=None),
        ),
    }


@pytest.fixture(scope="module")
def cases(bearing_model, spindle_model, gear_model):
    return _cases(bearing_model, spindle_model, gear_model)


def test_every_public_call_that_takes_a_machine_is_covered_or_excused(cases):
    found = public_machine_callables()
    # the walk finds what it must (a guard against a walk that finds nothing)
    assert {"thermal_state", "thermal_state_many", "stiffness_curve", "vibration",
            "GearSystem", "BearingModelSpec"} <= set(found)  # fmt: skip
    missing = sorted(set(found) - set(cases) - set(EXCLUDED))
    assert not missing, f"public calls taking a machine with no calibrated-model case: {missing}"
    stale = sorted((set(cases) | set(EXCLUDED)) - set(found))
    assert not stale, f"cases or exclusions of names the walk does not find: {stale}"


@pytest.mark.parametrize("name", sorted(set(public_machine_callables()) - set(EXCLUDED)))
def test_a_calibrated_model_gives_the_call_with_its_options_by_hand(cases, name):
    with_model, by_hand = cases[name]
    _same(with_model(), by_hand())


def test_the_calibration_acts_on_the_calls(bearing_model, spindle_model, gear_model):
    """The comparisons above are not between two baselines: the
    calibrated values change each kind of call."""
    bearing = bearing_model.spec.bearing
    a = tb.thermal_state(bearing_model, 8000.0, 300.0, 0.0).temperatures
    assert not a.equals(tb.thermal_state(bearing, 8000.0, 300.0, 0.0).temperatures)
    many = tb.thermal_state_many(bearing_model, POINTS)
    assert many["axial_n"].to_list() == POINTS["axial_n"]  # stated loads kept
    one = tb.thermal_state(bearing_model, 12000.0, 500.0, 0.0)
    assert many["outer_ring_temperature_c"][1] == one.temperature_c("outer_ring")
    sp = tb.Spindle.preset("seed-ceramic-spindle")
    grid = tb.spindle_grid(spindle_model, speeds_rpm=[12000.0], preloads_n=[300.0])
    assert not grid.equals(tb.spindle_grid(sp, speeds_rpm=[12000.0], preloads_n=[300.0]))
    cal, base = tb.GearSystem(gear_model), tb.GearSystem(tb.GearPair.preset("seed-electric-drive"))
    assert pickle.dumps(cal) != pickle.dumps(base)


@pytest.mark.parametrize("name", sorted(EXCLUDED))
def test_excluded_calls_refuse_or_take_the_model_cleanly(name, bearing_model, spindle_model,
                                                          gear_model):  # fmt: skip
    """The spec classes refuse a calibrated model with a ConfigError (never
    a raw TypeError); the verbs of a calibrated model take it."""
    models = {"BearingModelSpec": bearing_model, "SpindleModelSpec": spindle_model,
              "GearModelSpec": gear_model}  # fmt: skip
    if name in models:
        with pytest.raises(tb.ConfigError, match="invalid"):
            getattr(tb, name)(models[name])
    elif name == "predict":
        df = tb.predict(bearing_model, "temperatures", {"speeds_rpm": [8000.0], "axial_n": 300.0})
        assert df.height > 0 and (df["upper"] > df["lower"]).all()
    elif name == "separating_measurement":
        with pytest.raises(tb.ConfigError, match="two explanations"):
            tb.separating_measurement(bearing_model, {"speeds_rpm": [8000.0], "axial_n": 300.0})
    elif name == "BearingSet":
        with pytest.raises(tb.ConfigError, match="invalid bearing"):
            tb.BearingSet(bearing_model)
    else:
        assert name in ("diagnose_spindle", "spindle_candidates")


def test_a_model_argument_past_the_first_takes_a_calibrated_model_too():
    """``load_measurements(model=...)`` and the data sets of ``calibrate``
    take a calibrated model as its spec: the same table and the same
    calibration as with the spec."""
    toy = _model(Rig(), [("lubrication_factor_f0", 1.2, 0.01)], "toy")
    data = measured(Rig(lubrication_factor_f0=1.2, extra_heat_w=20.0), TOY_CONDITIONS, 0)
    _same(tb.load_measurements(data, model=toy), tb.load_measurements(data, model=toy.spec))
    a = tb.calibrate([(toy, data)], ["extra_heat_w"])
    b = tb.calibrate([(toy.spec, data)], ["extra_heat_w"])
    _same(a.parameters, b.parameters)
    # the calibrated f0 acts: from the bare rig the estimate differs
    c = tb.calibrate([(Rig(), data)], ["extra_heat_w"])
    assert a.parameters["value"][0] != c.parameters["value"][0]


# ------------------------------------------------------------------ plots


def public_plots() -> list[str]:
    return [n for n in tb.plot.__all__ if callable(getattr(tb.plot, n))]


@pytest.mark.parametrize("name", sorted(set(public_plots()) - set(PLOT_EXCLUDED)))
@pytest.mark.parametrize("which", ["calibrated", "machine"])
def test_a_plot_given_a_model_names_the_call_that_computes_its_result(name, which, bearing_model):
    from thermobear.plot.style import COMPUTED_BY

    given = bearing_model if which == "calibrated" else bearing_model.spec.bearing
    fn = getattr(tb.plot, name)
    params = list(inspect.signature(fn).parameters)
    # the second positional of frames-and-labels plots: the labels
    args = (given, ["a"]) if params[1] == "labels" else (given,)
    with pytest.raises(tb.ConfigError) as e:
        fn(*args)
    text = str(e.value)
    assert text.startswith(f"invalid {params[0]} = ") and f"thermobear.plot.{name}" in text
    assert COMPUTED_BY[name] in text


def test_every_plot_is_listed_with_the_call_that_computes_its_result():
    from thermobear.plot.style import COMPUTED_BY

    assert set(public_plots()) - set(PLOT_EXCLUDED) == set(COMPUTED_BY)


def test_a_frame_of_a_calibrated_model_draws_as_the_frame_by_hand(bearing_model):
    """What a plot draws of a calibrated model's frame is that of the
    frame by hand: the same lines, point for point."""
    bearing, hand = _bearing_hand(bearing_model)
    mech = {"effects": hand["effects"], "raceway_control": hand["raceway_control"]}
    a = tb.plot.stiffness_curve(tb.stiffness_curve(bearing_model, SPEEDS, 300.0))
    b = tb.plot.stiffness_curve(tb.stiffness_curve(bearing, SPEEDS, 330.0, **mech))
    la, lb = a.get_lines(), b.get_lines()
    assert len(la) == len(lb) >= 2
    for x, y in zip(la, lb, strict=True):
        assert np.array_equal(x.get_xydata(), y.get_xydata())
