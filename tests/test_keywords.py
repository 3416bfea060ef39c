"""One rule for the arguments of every public call: an unknown keyword, a
missing required argument, too many positional arguments and a value of
the wrong type are a ``ConfigError`` naming the call and the argument (a
misspelt keyword with the closest known one), never Python's ``TypeError``.

The public calls are enumerated: everything in ``thermobear.__all__``, the
methods of its public classes and the figures of ``thermobear.plot``. A
call that takes ``**kwargs`` checks its extra keywords itself: each such
call has an entry in ``PASSED_ON`` that calls it with valid arguments and
a misspelt keyword.
"""

from __future__ import annotations

import inspect
from pathlib import Path
from typing import Any, Callable

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear import _keywords
from thermobear.cli import main
from thermobear.cli.main import EXIT_ERROR, EXIT_USAGE

#: The mark of a wrapped call (see ``thermobear._keywords``).
MARK = "__thermobear_arguments_checked__"


def _public_calls() -> list[tuple[str, Callable[..., Any], bool]]:
    """(name, callable, is an instance method) of every public call."""
    out: list[tuple[str, Callable[..., Any], bool]] = []
    for name in tb.__all__:
        obj = getattr(tb, name)
        if inspect.isfunction(obj):
            out.append((name, obj, False))
        elif inspect.isclass(obj) and not issubclass(obj, BaseException):
            for attr in dir(obj):
                if attr.startswith("_") and attr != "__init__":
                    continue
                raw = inspect.getattr_static(obj, attr)
                if isinstance(raw, (staticmethod, classmethod)):
                    out.append((f"{name}.{attr}", getattr(obj, attr), False))
                elif inspect.isfunction(raw) and raw.__qualname__.split(".")[0] != "object":
                    if attr == "__init__" and raw is object.__init__:
                        continue
                    call = name if attr == "__init__" else f"{name}.{attr}"
                    out.append((call, raw, True))
    for name in tb.plot.__all__:
        out.append((f"plot.{name}", getattr(tb.plot, name), False))
    return out


CALLS = _public_calls()


def _takes_var_keyword(fn: Callable[..., Any]) -> bool:
    params = inspect.signature(fn).parameters.values()
    return any(p.kind is p.VAR_KEYWORD for p in params)


def _keywords_of(fn: Callable[..., Any]) -> list[str]:
    params = inspect.signature(fn).parameters.values()
    kinds = (inspect.Parameter.POSITIONAL_OR_KEYWORD, inspect.Parameter.KEYWORD_ONLY)
    return [p.name for p in params if p.kind in kinds and p.name not in ("self", "cls")]


def _misspelt(name: str) -> str:
    """``name`` with one letter left out of its middle (close enough for a
    "did you mean")."""
    i = len(name) // 2
    return name[:i] + name[i + 1 :]


def _call(fn: Callable[..., Any], method: bool, *args: Any, **kwargs: Any) -> Any:
    """``fn`` called with a placeholder ``self`` for an instance method
    (the arguments are refused before the body runs)."""
    return fn(object(), *args, **kwargs) if method else fn(*args, **kwargs)


def test_the_public_surface_is_enumerated_and_wrapped():
    names = {n for n, _, _ in CALLS}
    for n in ("Bearing", "Bearing.solve", "Bearing.preset", "GearSystem", "predict", "transient",
              "diagnose", "Study", "CalibratedModel.summary", "Diagnosis.summary",
              "plot.stiffness_curve", "thermal_state", "Spindle.preset"):  # fmt: skip
        assert n in names, n
    assert len(CALLS) > 150
    unwrapped = [n for n, fn, _ in CALLS if not getattr(fn, MARK, False)]
    assert unwrapped == []


@pytest.mark.parametrize(
    ("name", "fn", "method"),
    [c for c in CALLS if not _takes_var_keyword(c[1])],
    ids=[c[0] for c in CALLS if not _takes_var_keyword(c[1])],
)
def test_an_unknown_keyword_is_a_config_error_with_did_you_mean(name, fn, method):
    known = _keywords_of(fn)
    if not known:
        with pytest.raises(tb.ConfigError, match=rf"invalid argument = 'bogus': .*{name}\(\)"):
            _call(fn, method, bogus=1)
        return
    target = max(known, key=len)
    bad = _misspelt(target)
    with pytest.raises(tb.ConfigError) as info:
        _call(fn, method, **{bad: 1})
    message = str(info.value)
    assert f"invalid argument = {bad!r}" in message
    assert f"not an argument of {name}()" in message
    assert message.endswith(f"did you mean {target}?"), message


@pytest.mark.parametrize(
    ("name", "fn", "method"),
    [c for c in CALLS if not _takes_var_keyword(c[1])],
    ids=[c[0] for c in CALLS if not _takes_var_keyword(c[1])],
)
def test_too_many_positional_arguments_are_a_config_error(name, fn, method):
    params = inspect.signature(fn).parameters.values()
    if any(p.kind is p.VAR_POSITIONAL for p in params):
        pytest.skip("takes any number of positional arguments")
    n = sum(p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD) for p in params)
    n -= 1 if method else 0
    with pytest.raises(tb.ConfigError, match=rf"invalid call {name}\(\): it takes at most {n} "):
        _call(fn, method, *([None] * (n + 1)))


@pytest.mark.parametrize(
    ("name", "fn", "method"),
    [c for c in CALLS if not _takes_var_keyword(c[1])],
    ids=[c[0] for c in CALLS if not _takes_var_keyword(c[1])],
)
def test_a_missing_required_argument_is_a_config_error(name, fn, method):
    params = inspect.signature(fn).parameters.values()
    required = [
        p.name for p in params
        if p.default is p.empty and p.kind not in (p.VAR_POSITIONAL, p.VAR_KEYWORD)
        and p.name not in ("self", "cls")
    ]  # fmt: skip
    if not required:
        pytest.skip("no required argument")
    with pytest.raises(tb.ConfigError) as info:
        _call(fn, method)
    message = str(info.value)
    assert f"invalid call {name}(): the required argument {required[0]!r} is missing" in message
    assert "(it takes: " in message


def test_a_value_given_twice_is_a_config_error():
    b = tb.Bearing.preset("7008C")
    with pytest.raises(tb.ConfigError, match=r"argument 'axial_n' given twice"):
        b.solve(300.0, axial_n=300.0)


# -- calls that take **kwargs: each checks its extra keywords itself ----------------

BEARING = tb.Bearing.preset("7008C")
SPINDLE = tb.Spindle.preset("seed-ceramic-spindle")
GEAR = tb.GearPair.preset("seed-electric-drive")
POINTS = {"speed_rpm": [3000.0], "axial_n": [300.0]}

#: call -> (a call with valid arguments and the keyword given, the keyword meant)
PASSED_ON: dict[str, tuple[Callable[..., Any], str]] = {
    "limits": (lambda k: tb.limits(**{k: 1.0}).__enter__(), "max_misalignment_rad"),
    "set_limits": (lambda k: tb.set_limits(**{k: 1.0}), "max_misalignment_rad"),
    "Bearing.thermal_state": (lambda k: BEARING.thermal_state(3000.0, 300.0, **{k: 1}),
                              "lubricant"),
    "Bearing.thermal_state_many": (lambda k: BEARING.thermal_state_many(POINTS, **{k: 1}),
                                   "lubricant"),
    "Material": (lambda k: tb.Material("x", base="52100", **{k: 0.3}), "poisson_ratio"),
    "Material.replace": (lambda k: BEARING.ring_material.replace(**{k: 0.3}), "poisson_ratio"),
    "isothermal_heat": (lambda k: tb.isothermal_heat(BEARING, 3000.0, 300.0,
                                                     oil_temperature_c=40.0, **{k: 1}),
                        "heat_model"),
    "stiffness_curve": (lambda k: tb.stiffness_curve(BEARING, [1000.0], 300.0, **{k: 1}),
                        "heat_model"),
    "thermal_state": (lambda k: tb.thermal_state(BEARING, 3000.0, 300.0, **{k: 1}), "lubricant"),
    "thermal_state_many": (lambda k: tb.thermal_state_many(BEARING, POINTS, **{k: 1}),
                           "lubricant"),
    "Spindle.thermal_state": (lambda k: SPINDLE.thermal_state(3000.0, **{k: 1}), "preload_kind"),
    "Spindle.thermal_state_many": (lambda k: SPINDLE.thermal_state_many(
        {"speed_rpm": [3000.0]}, **{k: 1}), "preload_kind"),
    "Spindle.with_options": (lambda k: SPINDLE.with_options(**{k: 1}), "lubrication_factor_f0"),
    "BearingModelSpec": (lambda k: tb.BearingModelSpec(BEARING, **{k: 1}), "extra_heat_w"),
    "BearingModelSpec.with_setting": (lambda k: tb.BearingModelSpec(BEARING).with_setting(
        **{k: 1}), "extra_heat_w"),
    "GearModelSpec": (lambda k: tb.GearModelSpec(GEAR, **{k: 1}), "torque_n_m"),
    "GearModelSpec.with_setting": (lambda k: tb.GearModelSpec(GEAR).with_setting(**{k: 1}),
                                   "torque_n_m"),
    "SpindleModelSpec": (lambda k: tb.SpindleModelSpec(SPINDLE, **{k: 1}), "runout_um"),
    "SpindleModelSpec.with_setting": (lambda k: tb.SpindleModelSpec(SPINDLE).with_setting(
        **{k: 1}), "runout_um"),
    "diagnose_spindle": (lambda k: tb.diagnose_spindle(tb.SpindleModelSpec(SPINDLE), None,
                                                       **{k: 1}), "holdout"),
}  # fmt: skip

#: Figures that pass their extra keywords on to matplotlib (checked by the
#: same rule as the entries of PASSED_ON; a few are drawn below).
TO_MATPLOTLIB = {f"plot.{n}" for n in tb.plot.__all__ if _takes_var_keyword(getattr(tb.plot, n))}


def test_every_call_taking_keywords_has_an_entry():
    varkw = {n for n, fn, _ in CALLS if _takes_var_keyword(fn)}
    assert varkw - set(PASSED_ON) - TO_MATPLOTLIB == set()


@pytest.mark.filterwarnings("ignore:`diagnose_spindle` is deprecated:DeprecationWarning")
@pytest.mark.parametrize("name", sorted(PASSED_ON))
def test_a_misspelt_keyword_passed_on_is_named_with_did_you_mean(name):
    call, meant = PASSED_ON[name]
    bad = _misspelt(meant)
    with pytest.raises(tb.ConfigError) as info:
        call(bad)
    assert bad in str(info.value) and f"did you mean {meant}?" in str(info.value)


def test_a_figure_names_a_keyword_matplotlib_refuses():
    import matplotlib

    matplotlib.use("Agg")
    curve = tb.stiffness_curve(BEARING, [1000.0, 2000.0], 300.0)
    with pytest.raises(tb.ConfigError) as info:
        tb.plot.stiffness_curve(curve, lable="x")
    message = str(info.value)
    assert "invalid argument = 'lable'" in message and "plot.stiffness_curve()" in message
    assert message.endswith("did you mean label?")
    ax = tb.plot.stiffness_curve(curve, linewidth=2.0)  # a keyword matplotlib takes
    assert ax.lines[0].get_linewidth() == 2.0


# -- a value of the wrong type: named, never a TypeError ---------------------------

WRONG_TYPE: list[tuple[str, Callable[[], Any], str]] = [
    ("Bearing.preset", lambda: tb.Bearing.preset(None), "name"),
    ("Bearing.preset", lambda: tb.Bearing.preset(7008), "name"),
    ("Bearing.solve", lambda: BEARING.solve(axial_n="300"), "axial_n"),
    ("Bearing.solve", lambda: BEARING.solve(effects=5), "effects"),
    ("Bearing.solve_many", lambda: BEARING.solve_many(POINTS, progress=5), "progress"),
    ("Bearing.solve_many", lambda: BEARING.solve_many(POINTS, threads="2"), "threads"),
    ("thermal_state_many", lambda: tb.thermal_state_many(BEARING, POINTS, progress=5),
     "progress"),
    ("stiffness_curve", lambda: tb.stiffness_curve(BEARING, [1000.0], 300.0, progress=5),
     "progress"),
    ("stiffness_curve", lambda: tb.stiffness_curve(BEARING, "fast", 300.0), "speeds_rpm"),
    ("thermal_state", lambda: tb.thermal_state(BEARING, [3000.0], 300.0), "speed_rpm"),
    ("Spindle.preset", lambda: tb.Spindle.preset(3), "name"),
    ("GearPair.preset", lambda: tb.GearPair.preset(None), "name"),
    ("GearSystem", lambda: tb.GearSystem(GEAR, torque_n_m="100"), "torque_n_m"),
    ("Material", lambda: tb.Material("x", base="52100", poisson_ratio="0.3"), "poisson_ratio"),
    ("plot.stiffness_curve", lambda: tb.plot.stiffness_curve(None), "df"),
    ("set_limits", lambda: tb.set_limits(max_misalignment_rad="1"), "max_misalignment_rad"),
]  # fmt: skip


@pytest.mark.parametrize(("name", "call", "argument"), WRONG_TYPE,
                         ids=[f"{n}-{a}" for n, _, a in WRONG_TYPE])  # fmt: skip
def test_a_value_of_the_wrong_type_is_named(name, call, argument):
    with pytest.raises(tb.ConfigError) as info:
        call()
    assert f"invalid {argument} " in str(info.value), str(info.value)


def test_preset_lists_the_presets_and_names_a_close_one():
    with pytest.raises(tb.ConfigError) as info:
        tb.Bearing.preset(None)
    assert all(n in str(info.value) for n in tb.Bearing.preset_names())
    with pytest.raises(tb.ConfigError, match=r"did you mean 7009C\?"):
        tb.Bearing.preset("7080C")


def test_nested_lists_in_solve_many_are_named():
    for nested in ([[300.0, 400.0], [500.0]], [[300.0, 400.0], [500.0, 600.0]], [1.0, [2.0]]):
        with pytest.raises(tb.ConfigError, match=r"invalid axial_n = .*flat sequence"):
            BEARING.solve_many({"axial_n": nested, "speed_rpm": 1000.0})
    ok = BEARING.solve_many({"axial_n": np.array([300.0, 400.0]), "speed_rpm": 1000.0})
    assert ok["ok"].to_list() == [True, True]


def test_the_deprecated_and_the_new_name_together_are_a_config_error():
    with pytest.raises(tb.ConfigError, match=r"invalid moment_nmm = 1.0: .*moment_n_m"):
        BEARING.solve(moment_nmm=1.0, moment_n_m=1.0)


# -- the wrappers keep what help() and an IDE show, and cost nothing on success ----


def test_signatures_and_docs_are_those_of_the_definitions():
    from thermobear.bearing.ball_bearing import Bearing

    solve = inspect.getattr_static(Bearing, "solve")
    assert list(inspect.signature(tb.Bearing.solve).parameters)[1:5] == [
        "axial_n", "radial_n", "moment_n_m", "speed_rpm"]  # fmt: skip
    assert solve.__wrapped__.__doc__ == tb.Bearing.solve.__doc__
    assert tb.Bearing.solve.__name__ == "solve"
    assert inspect.signature(tb.diagnose) == inspect.signature(tb.diagnose.__wrapped__)


def test_a_call_that_fits_is_not_inspected(monkeypatch):
    """The signature is looked at only once a call failed."""

    def refuse(*a: Any, **k: Any) -> Any:
        raise AssertionError("inspect.signature on a call that fits")

    monkeypatch.setattr(_keywords.inspect, "signature", refuse)
    assert BEARING.solve(axial_n=300.0).iterations >= 0


# -- the diagnosis leaves no NaN placeholder -----------------------------------------


def test_lookalikes_without_a_suggestion_hold_nulls():
    from diagnose_toy import Rig, conditions, measured

    data = measured(Rig(extra_heat_w=30.0), conditions(np.linspace(2000.0, 16000.0, 6)), 1)
    d = tb.diagnose(Rig(), data, suggest=False, lookalike_cosine=0.0)
    la = d.lookalikes
    assert la.height > 0
    for c in ("suggest_quantity", "suggest_speed_rpm", "suggest_axial_n"):
        assert la[c].null_count() == la.height, c
    assert la["suggest_speed_rpm"].is_nan().sum() == 0
    assert "no separating measurement found" in d.summary(verbose=True)


# -- the command line ---------------------------------------------------------------


def _stderr_line(capsys: Any) -> str:
    err = capsys.readouterr().err
    lines = [ln for ln in err.splitlines() if ln.strip()]
    assert len(lines) == 1 and "Traceback" not in err, err
    return lines[0]


def test_a_binary_file_given_as_toml_is_one_line_and_a_usage_error(tmp_path, capsys):
    binary = tmp_path / "system.toml"
    binary.write_bytes(b"\x9d\xff\x00\x01binary" * 20)
    for argv in (["solve", str(binary), "--out", str(tmp_path / "o")],
                 ["study", str(binary), "--out", str(tmp_path / "s")]):  # fmt: skip
        assert main(argv) == EXIT_USAGE
        line = _stderr_line(capsys)
        assert str(binary) in line and "not a UTF-8 text file" in line
    with pytest.raises(tb.ConfigError, match="not a UTF-8 text file"):
        tb.load_config(binary)


def test_a_misspelt_preset_in_a_toml_file_gets_did_you_mean(tmp_path, capsys):
    path = tmp_path / "system.toml"
    path.write_text(tb.seed_config("seed_b_7009c").replace('"7009C-hybrid"', '"7009C-hybird"'))
    assert main(["solve", str(path), "--out", str(tmp_path / "o")]) == EXIT_ERROR
    line = _stderr_line(capsys)
    assert "key bearing.preset" in line and line.endswith("did you mean 7009C-hybrid?")
    text = tb.seed_config("seed_a_6208").replace('ring_material = "52100"',
                                                 'ring_material = "52010"')  # fmt: skip
    with pytest.raises(tb.ConfigError, match=r"did you mean 52100\?") as info:
        tb.load_config(text)
    assert info.value.key == "bearing.ring_material"


def test_predict_what_the_model_cannot_predict_is_a_usage_error(tmp_path, capsys):
    spec = tb.BearingModelSpec(tb.Bearing.preset("7008C"))
    model = tb.CalibratedModel("nothing", "baseline", spec, [], [], np.zeros((0, 0)))
    path = model.save(tmp_path / "bearing.json")
    argv = ["predict", str(path), "--what", "vibration", "--speeds", "5000", "--loads", "300",
            "--out", str(tmp_path / "p")]  # fmt: skip
    assert main(argv) == EXIT_USAGE
    line = _stderr_line(capsys)
    assert line.startswith("thermobear predict: error: --what vibration") and "predicts" in line
    assert not Path(tmp_path / "p" / "prediction.parquet").exists()


def test_polars_frames_pass_through_the_wrappers():
    frame = pl.DataFrame(POINTS)
    out = BEARING.solve_many(frame)
    assert out.height == 1 and out["ok"][0]
