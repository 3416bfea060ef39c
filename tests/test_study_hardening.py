"""A study that cannot run away or be fooled: a grid's size is counted from
its specs before any value is made and refused past a cap that a keyword
raises; a stored chunk whose rows are not its record's points is not
merged, even when its checksum was re-signed; a second process is refused
while the first holds the folder, even after the lock file was deleted; a
folder that cannot be written is a ConfigError naming it."""

from __future__ import annotations

import json
import math
import os
import pickle
import re
import shutil
import subprocess
import sys
import tracemalloc
import warnings
from pathlib import Path
from typing import Any

import polars as pl
import pytest
from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st
from polars.testing import assert_frame_equal

import thermobear as tb
from thermobear.study.grid import MAX_POINTS, dimension_size
from thermobear.study.store import LOCK, Store, file_sha256

LONG = os.environ.get("THERMOBEAR_FUZZ", "").lower() == "long"

# -- bounded work -------------------------------------------------------------


def _refused_small(call: Any) -> tb.ConfigError:
    """The ConfigError ``call()`` raises, and that it raised with a peak of
    traced memory (Python objects and numpy arrays) below 20 MB."""
    tracemalloc.start()
    try:
        with pytest.raises(tb.ConfigError) as info:
            call()
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < 20e6, f"{peak / 1e6:.0f} MB allocated before refusing"
    return info.value


@pytest.mark.parametrize(
    "spec, size",
    [
        ({"start": 0, "stop": 1e12, "step": 1}, "1,000,000,000,001"),
        ({"start": 0, "stop": 1000, "num": 10**12}, "1,000,000,000,000"),
        ({"start": -1e308, "stop": 1e308, "step": 1}, "more than 1e308"),
        (range(10**20), "1e+20"),
    ],
)
def test_a_huge_axis_is_refused_before_anything_is_made(spec, size):
    err = _refused_small(lambda: tb.Study("bearing", {"speed_rpm": spec}))
    msg = str(err)
    assert msg.startswith("invalid grid.speed_rpm = ")
    assert f"{size} points" in msg
    assert "more than max_points = 1,000,000" in msg
    assert "max_points=" in msg and "--max-points" in msg


def test_a_product_past_the_cap_names_its_largest_axis():
    grid = {"axial_n": [300.0, 600.0], "speed_rpm": list(range(1001)), "radial_n": range(500)}
    msg = str(_refused_small(lambda: tb.Study("bearing", grid)))
    assert msg.startswith("invalid grid.speed_rpm = <list of 1,001 values>: 1,001 values")
    assert "1,001,000 points (axial_n[2] x speed_rpm[1,001] x radial_n[500])" in msg


def test_the_keyword_raises_the_cap_and_the_size_is_stated():
    grid = {"speed_rpm": {"start": 1000, "stop": 2000, "num": 4}, "axial_n": [300.0, 600.0, 900.0]}
    with pytest.raises(tb.ConfigError, match=r"12 points .* more than max_points = 11;"):
        tb.Study("bearing", grid, max_points=11)
    study = tb.Study("bearing", grid, max_points=12)
    assert len(study) == 12 and study.points().height == 12
    assert "12 points" in repr(study) and study.summary() == repr(study)
    # The cap travels with the study (a Dask worker or a pickle rebuilds it).
    assert pickle.loads(pickle.dumps(study)).max_points == 12
    big = tb.Study(
        "bearing", {"speed_rpm": {"start": 0, "stop": 1.5e6, "step": 1}}, max_points=2_000_000
    )
    assert big.n_points == 1_500_001 == MAX_POINTS + 500_001
    # The cap is not part of what the results are: the same grid hash.
    assert study.grid_hash == tb.Study("bearing", grid).grid_hash


@pytest.mark.parametrize("cap", [0, -1, 2.5, True, "1000", None, math.inf])
def test_a_bad_cap_is_a_config_error_naming_it(cap):
    with pytest.raises(tb.ConfigError, match="invalid max_points = "):
        tb.Study("bearing", {"speed_rpm": [1000.0]}, max_points=cap)
    with pytest.raises(tb.ConfigError, match="invalid max_steps = "):
        tb.Study("gear", {"speed_rpm": [1000.0]}, max_steps=cap)


def test_a_gear_study_states_and_caps_its_time_steps():
    study = tb.Study("gear", {"speed_rpm": [3000.0, 6000.0], "record_periods": [100, 200]})
    # (300 + 100) x 64 + (300 + 200) x 64 steps, at each of the 2 speeds
    assert study.grid.n_steps == 2 * (400 + 500) * 64
    assert "4 points (115,200 time steps or more)" in repr(study)
    fixed = tb.Study("gear", {"speed_rpm": [3000.0]}, {"steps_per_period": 100})
    assert "(40,000 time steps)" in repr(fixed)
    huge = {"record_periods": 10**9}
    grid = {"speed_rpm": [3000.0, 6000.0]}
    err = _refused_small(lambda: tb.Study("gear", grid, huge))
    assert "128,000,038,400 time steps or more, more than max_steps = 10,000,000,000" in str(err)
    assert "max_steps=" in str(err) and "--max-steps" in str(err)
    assert tb.Study("gear", grid, huge, max_steps=10**12).grid.n_steps == 128_000_038_400


def test_a_study_file_and_the_command_line_set_the_cap(tmp_path, capsys):
    from thermobear.cli.main import main

    grid = tmp_path / "grid.toml"
    grid.write_text(
        "[study]\nkind = 'bearing'\nmax_points = 3\n"
        "[grid]\nspeed_rpm = {start = 4000, stop = 12000, num = 5}\naxial_n = [300]\n"
    )
    assert tb.load_study(grid, max_points=5).n_points == 5
    with pytest.raises(tb.ConfigError, match="more than max_points = 3;"):
        tb.load_study(grid)
    out = tmp_path / "results"
    assert main(["study", str(grid), "--out", str(out), "--no-progress"]) == 1
    err = capsys.readouterr().err
    assert "grid.toml:" in err and "5 points (speed_rpm[5] x axial_n[1])" in err
    assert not out.exists()
    argv = ["study", str(grid), "--out", str(out), "--no-progress", "--max-points", "5"]
    assert main(argv) == 0
    first = capsys.readouterr().out.splitlines()[0]
    assert first.startswith("thermobear study: Study('bearing', speed_rpm[5], axial_n[1]: 5 points")
    huge = tmp_path / "huge.toml"
    huge.write_text(
        "[study]\nkind = 'bearing'\n[grid]\nspeed_rpm = {start = 0, stop = 1e12, step = 1}\n"
    )
    assert main(["study", str(huge), "--out", str(out)]) == 1
    assert "1,000,000,000,001 points" in capsys.readouterr().err


# -- stored chunks are checked by their rows ------------------------------------


def _study() -> tb.Study:
    return tb.Study(
        "bearing",
        {"speed_rpm": [3000.0, 5000.0, 7000.0, 9000.0], "axial_n": [300.0, 600.0]},
        chunk_size=2,
    )  # 8 points, 4 chunks


def _chunk(root: Path, index: int) -> Path:
    return root / "chunks" / f"chunk-{index:06d}.parquet"


def _resign(root: Path, index: int) -> None:
    """Write a chunk record's checksum anew for the file now there."""
    path = root / "chunks" / f"chunk-{index:06d}.check.json"
    rec = json.loads(path.read_text())
    rec["sha256"] = file_sha256(_chunk(root, index))
    path.write_text(json.dumps(rec))


def _swap_rows(root: Path) -> None:
    # Another chunk's file under chunk 2's name, its record re-signed.
    shutil.copy(_chunk(root, 0), _chunk(root, 2))
    _resign(root, 2)


def _change_an_axis(root: Path) -> None:
    # The right points, another axial load, re-signed.
    frame = pl.read_parquet(_chunk(root, 2))
    frame.with_columns(pl.col("axial_n") * 2).write_parquet(_chunk(root, 2))
    _resign(root, 2)


@pytest.mark.parametrize(
    "tamper, why",
    [
        (_swap_rows, "its point column (2 rows from 0) is not the points 4..5 of its record"),
        (_change_an_axis, "its axial_n column does not hold this grid's values at points 4..5"),
    ],
)
def test_a_re_signed_chunk_of_other_rows_is_recomputed(tmp_path, tamper, why):
    out = tmp_path / "out"
    clean = _study().run(out, progress=False)
    tamper(out)
    again = _study()
    with pytest.warns(UserWarning, match="chunk-000002.parquet fails its check") as caught:
        df = again.run(out, progress=False)
    assert why in str(caught[0].message)
    assert again.report.computed == 1 and again.report.reused == 3
    assert_frame_equal(df, clean)
    assert_frame_equal(pl.read_parquet(_chunk(out, 2)), clean.slice(4, 2))


def test_a_chunk_changed_during_the_run_is_not_merged(tmp_path):
    out = tmp_path / "out"
    _study().run(out, progress=False)
    _chunk(out, 3).unlink()  # the second run computes chunk 3 and reuses 0..2

    def tamper(index: int, frame: pl.DataFrame) -> None:
        _swap_rows(out)  # after the reused chunks were checked

    with pytest.raises(tb.ConfigError, match=r"chunk-000002\.parquet: it changed during the run"):
        _study().run(out, progress=False, on_chunk=tamper)


# -- one run per folder, whatever happens to the lock file -------------------------

_SECOND = """
import thermobear as tb
s = tb.Study("bearing", {"speed_rpm": [3000.0, 5000.0, 7000.0, 9000.0],
                         "axial_n": [300.0, 600.0]}, chunk_size=2)
try:
    s.run(%r, progress=False)
except tb.ThermobearError as e:
    print("refused:", e)
else:
    print("ran")
"""


def _second_process(out: Path) -> str:
    run = subprocess.run(
        [sys.executable, "-c", _SECOND % str(out)], capture_output=True, text=True, timeout=300
    )
    assert run.returncode == 0, run.stderr
    return run.stdout.strip()


def test_a_second_process_is_refused_after_the_lock_file_is_deleted(tmp_path):
    out = tmp_path / "out"
    study = _study()
    first = Store(out, study.manifest(), expected=study.grid.frame)  # the first run holds it
    try:
        (out / LOCK).unlink()
        said = _second_process(out)
        assert said.startswith(f"refused: invalid out = {str(out)!r}: another run is using it")
        assert f"lock file {LOCK} was removed" in said
        (out / LOCK).write_text("")  # deleted and made anew: still held
        assert "another run is using it" in _second_process(out)
        with pytest.raises(tb.ConfigError, match="another run is using it"):
            _study().run(out, progress=False)
    finally:
        first.close()
    assert _second_process(out) == "ran"  # released: the next run goes ahead


# -- a folder that cannot be written ---------------------------------------------


def _read_only_folder(tmp_path: Path) -> Path:
    """A folder this process cannot create files in: chmod 555 as a user;
    as root (chmod does not stop root) an existing read-only place."""
    if os.name != "posix":
        pytest.skip("POSIX permissions")
    if os.geteuid() != 0:
        folder = tmp_path / "ro"
        folder.mkdir()
        folder.chmod(0o555)
        return folder
    for candidate in (Path("/sys/kernel"), Path("/proc/sys")):
        try:
            os.close(os.open(candidate / LOCK, os.O_RDWR | os.O_CREAT, 0o644))
        except PermissionError:
            return candidate
        except OSError:
            continue
        (candidate / LOCK).unlink()
    pytest.skip("running as root with no read-only folder to write to")


def test_a_read_only_folder_is_a_config_error_naming_it(tmp_path):
    folder = _read_only_folder(tmp_path)
    try:
        with pytest.raises(tb.ConfigError) as info:
            _study().run(folder, progress=False)
    finally:
        if folder.is_relative_to(tmp_path):
            folder.chmod(0o755)
    msg = str(info.value)
    assert msg.startswith(f"invalid out = {str(folder)!r}: cannot write to this folder")
    assert "give a folder this user may write to" in msg


def test_a_folder_under_a_file_is_a_config_error_naming_it(tmp_path):
    (tmp_path / "a-file").write_text("")
    out = tmp_path / "a-file" / "results"
    with pytest.raises(tb.ConfigError, match=re.escape(f"invalid out = {str(out)!r}: ")):
        _study().run(out, progress=False)


# -- property: any grid spec is a Study of its stated size or a ConfigError -----------

_NUMBERS = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True),
    st.integers(min_value=-(10**20), max_value=10**20),
    st.sampled_from([0, 1, 1e-320, 1e12, 1e308, -1e308, True, None, "5", 10**400]),
)
_RANGE = st.dictionaries(
    st.sampled_from(["start", "stop", "num", "step", "stride"]),
    st.one_of(_NUMBERS, st.integers(min_value=-3, max_value=3000)),
    max_size=4,
)
_SPEC = st.one_of(
    _RANGE,
    st.fixed_dictionaries(
        {"start": st.floats(0, 1e4), "stop": st.floats(0, 1e5), "num": st.integers(-1, 10**13)}
    ),
    st.fixed_dictionaries(
        {"start": st.floats(0, 1e4), "stop": st.floats(0, 1e5), "step": st.floats(-1, 1e3)}
    ),
    st.lists(st.one_of(st.floats(0, 1e4), _NUMBERS), max_size=5),
    st.builds(range, st.integers(0, 10), st.integers(-10, 10**14), st.integers(1, 10**6)),
    _NUMBERS,
)
_AXES = st.dictionaries(
    st.sampled_from(["speed_rpm", "axial_n", "radial_n", "preload_n", "speeds"]), _SPEC, max_size=3
)


@settings(
    max_examples=5000 if LONG else 400,
    deadline=None,
    database=None,
    derandomize=not LONG,
    suppress_health_check=list(HealthCheck),
)
@given(axes=_AXES, cap=st.integers(1, 2000))
def test_any_grid_spec_is_a_study_of_its_stated_size_or_a_config_error(axes, cap):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            study = tb.Study("bearing", axes, max_points=cap)
        except tb.ConfigError:
            event("refused")
            return
    event("a study")
    counted = math.prod(dimension_size(spec, name) for name, spec in axes.items())
    assert study.n_points == counted <= cap
    assert f": {counted} points, " in repr(study) or not axes
    assert study.points().height == counted
