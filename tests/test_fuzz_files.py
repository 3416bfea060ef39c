"""Property-based fuzz of what a user types or writes that the entry points
read: the command line's files (system descriptions, study files,
measurement tables, calibrated models), the conditions of ``predict`` and
the arguments of a regime map (hypothesis).

Each file starts from a valid one and is damaged the ways files are: a line
deleted, a value replaced by a wrong one (``nan``, ``1e400``, a string, a
bracket), a stray line, a truncation, or bytes that are no text at all.
Every command must end with exit status 0, 1 or 2 and no traceback; every
API call must return a finite result or raise a
``thermobear.ThermobearError``. Profiles as in ``test_fuzz_api.py``: the
short counts in CI, ``THERMOBEAR_FUZZ=long`` for the long ones (and
``pytest --hypothesis-seed=N`` for a seed of one's own).
"""

from __future__ import annotations

import contextlib
import io
import warnings
from pathlib import Path
from typing import Any

import numpy as np
import polars as pl
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from test_fuzz_api import LONG, MODEL, SCALE, WILD, _call

import thermobear as tb
from thermobear.cli.main import main

pytestmark = pytest.mark.filterwarnings("ignore")

#: Cases per group: (short profile, long profile).
FILE_CASES = {"system": (60, 3000), "study": (40, 2000), "measurements": (60, 3000),
              "model": (40, 2000), "conditions": (150, 8000), "regime_map": (60, 3000)}  # fmt: skip


def _file_settings(group: str) -> Any:
    """The project's fuzz profile (``test_fuzz_api._settings``) at this
    group's count."""
    count = max(1, int(FILE_CASES[group][1] * SCALE)) if LONG else FILE_CASES[group][0]
    return settings(max_examples=count, deadline=None, database=None, derandomize=not LONG,
                    suppress_health_check=list(HealthCheck))  # fmt: skip


SYSTEM = """[bearing]
preset = "6208"
ring_material = "52100"
ball_material = "52100"

[operating]
speed_rpm = 12000.0
axial_n = 800.0
radial_n = 500.0

[sweep]
speed_start_rpm = 6000.0
speed_stop_rpm = 12000.0
speed_count = 3

[model]
effects = ["centrifugal_force", "gyroscopic_moment"]
raceway_control = "outer"
lubrication_factor_f0 = 1.0
"""

STUDY = """[study]
kind = "bearing"
chunk_size = 2

[grid]
speed_rpm = [2000.0, 4000.0]
axial_n = { start = 200, stop = 400, num = 2 }

[fixed]
bearing = "7008C"
"""

MEASUREMENTS = """speed_rpm,axial_n,radial_n,quantity,value,sigma
4000,400,0,outer_ring_temperature_c,31.2,0.5
6000,400,0,outer_ring_temperature_c,34.9,0.5
8000,400,0,outer_ring_temperature_c,39.8,0.5
"""

#: Replacement values of the damaged files (TOML and CSV alike).
BAD_VALUES = ["nan", "inf", "-inf", "-1", "0", "1e400", "1e308", "-0.0", '"x"', '"7008X"',
              "[", "[]", "{}", "true", "1_000", '"1000"', "\u00e9", "", "1e-320",
              "999999999999"]  # fmt: skip
#: Lines a damaged file may gain.
STRAY_LINES = ["foo = 1", "[bar]", "speed_rpm = 1e9", "[[grid]]", "preset = 7", "=", "\x00",
               "axial_n = -5", "[model]", "kind = \"gear\""]  # fmt: skip


@st.composite
def damaged(draw: Any, text: str) -> bytes:
    """``text`` damaged one to three times, as bytes."""
    if draw(st.integers(0, 9)) == 0:  # no text at all
        return draw(st.binary(min_size=1, max_size=200))
    lines = text.splitlines()
    for _ in range(draw(st.integers(1, 3))):
        how = draw(st.sampled_from(["delete", "replace", "insert", "truncate", "swap"]))
        i = draw(st.integers(0, max(len(lines) - 1, 0)))
        if not lines:
            break
        if how == "delete":
            del lines[i]
        elif how == "replace":
            sep = "=" if "=" in lines[i] else ","
            parts = lines[i].split(sep)
            j = draw(st.integers(0, len(parts) - 1))
            parts[j] = draw(st.sampled_from(BAD_VALUES)) if j else parts[j]
            if sep == "=" and len(parts) > 1:
                parts[-1] = " " + draw(st.sampled_from(BAD_VALUES))
            lines[i] = sep.join(parts)
        elif how == "insert":
            lines.insert(i, draw(st.sampled_from(STRAY_LINES)))
        elif how == "truncate":
            lines[i] = lines[i][: draw(st.integers(0, len(lines[i])))]
            lines = lines[: i + 1]
        else:
            k = draw(st.integers(0, len(lines) - 1))
            lines[i], lines[k] = lines[k], lines[i]
    return ("\n".join(lines) + "\n").encode()


def _run(argv: list[str]) -> tuple[int, str]:
    """The command line on ``argv`` in this process: exit status, stderr."""
    err, out = io.StringIO(), io.StringIO()
    with (
        contextlib.redirect_stderr(err),
        contextlib.redirect_stdout(out),
        warnings.catch_warnings(),
    ):
        warnings.simplefilter("ignore")
        code = main(argv)
    return code, err.getvalue()


def _check_command(argv: list[str]) -> None:
    code, err = _run(argv)
    assert code in (0, 1, 2), f"{argv}: exit {code}\n{err}"
    assert "Traceback" not in err, f"{argv}: a traceback\n{err}"
    if code:
        assert err.strip(), f"{argv}: exit {code} without a message"
        assert len(err.strip().splitlines()) <= 3, f"{argv}: a long error\n{err}"


@pytest.fixture(scope="module")
def folder(tmp_path_factory: Any) -> Path:
    return tmp_path_factory.mktemp("fuzz_files")


def _write(folder: Path, name: str, data: bytes) -> str:
    path = folder / name
    path.write_bytes(data)
    return str(path)


def test_the_undamaged_files_run(folder):
    """The starting points are valid: what the fuzz damages works as given."""
    system = _write(folder, "s.toml", SYSTEM.encode())
    study = _write(folder, "t.toml", STUDY.encode())
    for argv in (["solve", system, "--out", str(folder / "o")],
                 ["study", study, "--out", str(folder / "p")]):  # fmt: skip
        code, err = _run(argv)
        assert code == 0, err
    got = tb.load_measurements(_write(folder, "m.csv", MEASUREMENTS.encode()))
    assert got.height == 3


@_file_settings("system")
@given(data=damaged(SYSTEM))
def test_a_damaged_system_description(folder, data):
    path = _write(folder, "system.toml", data)
    _check_command(["solve", path, "--out", str(folder / "solve-out")])


@_file_settings("study")
@given(data=damaged(STUDY))
def test_a_damaged_study_file(folder, data):
    path = _write(folder, "study.toml", data)
    out = folder / "study-out"
    import shutil

    shutil.rmtree(out, ignore_errors=True)  # a fresh study each time, not a resumed one
    _check_command(["study", path, "--out", str(out)])


@_file_settings("measurements")
@given(data=damaged(MEASUREMENTS))
def test_a_damaged_measurement_table(folder, data):
    path = _write(folder, "measured.csv", data)
    _call("load_measurements", tb.load_measurements, path)


@_file_settings("model")
@given(data=damaged(MODEL.to_json()))
def test_a_damaged_model_file_on_the_command_line(folder, data):
    path = _write(folder, "model.json", data)
    argv = ["predict", path, "--what", "temperatures", "--speeds", "4000", "--loads", "300",
            "--out", str(folder / "predict-out")]  # fmt: skip
    _check_command(argv)


#: Condition keys a user may write, right and wrong.
CONDITION_KEYS = ["speeds_rpm", "speed_rpm", "axial_n", "radial_n", "preload_n", "preloads_n",
                  "radial_loads_n", "axial_loads_n", "speeds", "rpm", "torque_n_m"]  # fmt: skip


@st.composite
def conditions(draw: Any) -> Any:
    """A conditions mapping or frame with keys right and wrong, values wild
    or plausible."""
    keys = draw(st.lists(st.sampled_from(CONDITION_KEYS), min_size=0, max_size=4, unique=True))
    listed = st.lists(st.floats(0.0, 12000.0), min_size=1, max_size=3)
    plausible = st.one_of(st.floats(1000.0, 12000.0), listed)
    out = {k: draw(st.one_of(plausible, WILD)) for k in keys}
    if draw(st.booleans()):
        return out
    # a frame: each value made a column of one length (skip what cannot be one)
    n = draw(st.integers(1, 3))
    cols = {}
    for k, v in out.items():
        if isinstance(v, (int, float)) and not isinstance(v, bool):
            cols[k.rstrip("s") if k == "speeds_rpm" else k] = [float(v)] * n
    return pl.DataFrame(cols) if cols else pl.DataFrame()


@_file_settings("conditions")
@given(cond=conditions(), what=st.sampled_from(["temperatures", "stiffness", "measured", "all"]))
def test_predict_conditions(cond, what):
    _call("predict", tb.predict, MODEL, what, cond)


GEAR_SYSTEM = tb.GearSystem(tb.GearPair.preset("seed-electric-drive"))


@st.composite
def regime_map_calls(draw: Any) -> dict[str, Any]:
    base: dict[str, Any] = dict(torques_n_m=[50.0], speeds_rpm=[8000.0, 9000.0], te_scales=[1.0],
                                transient_periods=4, record_periods=8, steps_per_period=32,
                                lyapunov_periods=0)  # fmt: skip
    keys = draw(st.lists(st.sampled_from(sorted(base)), min_size=1, max_size=2, unique=True))
    for k in keys:
        base[k] = draw(st.one_of(WILD, st.integers(0, 10**7)), label=k)
    return base


@_file_settings("regime_map")
@given(kwargs=regime_map_calls())
def test_regime_map_arguments(kwargs):
    _call("regime_map", tb.regime_map, GEAR_SYSTEM, **kwargs)


def test_the_file_profile_is_short():
    """The short profile stays small (it runs in CI beside the API fuzz)."""
    assert sum(c[0] for c in FILE_CASES.values()) <= 500
    assert np.all([c[1] >= 20 * c[0] for c in FILE_CASES.values()])


@pytest.mark.parametrize("speeds", ["", "8000", [[8000.0, "x"]], None])
def test_speeds_that_are_no_numbers_are_named(speeds):
    """A stray of a fuzz run: text as the speeds of a regime map was a
    ValueError of numpy's; it is a ConfigError naming ``speeds_rpm``."""
    with pytest.raises(tb.ConfigError, match="speeds_rpm"):
        tb.regime_map(GEAR_SYSTEM, [50.0], speeds, transient_periods=4, record_periods=8,
                      steps_per_period=32, lyapunov_periods=0)  # fmt: skip
