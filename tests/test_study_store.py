"""A results folder you can trust: every stored chunk is checked against its
record (grid hash, index, point range, SHA-256) before it is reused, and a
chunk that fails (swapped with another valid chunk, truncated, zeroed) is
recomputed with a warning naming its file, so the result equals a clean
run; one run owns a folder at a time; ``overwrite=True`` recovers from
whatever the folder holds."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import textwrap
import time
import warnings
from pathlib import Path

import polars as pl
import pytest
from polars.testing import assert_frame_equal

import thermobear as tb


def _study() -> tb.Study:
    return tb.Study(
        "thermal",
        {"speed_rpm": [3000.0, 5000.0, 7000.0, 9000.0], "axial_n": [300.0, 600.0]},
        {"radial_n": 200.0},
        chunk_size=2,
    )  # 8 points, 4 chunks


@pytest.fixture(scope="module")
def clean() -> pl.DataFrame:
    return _study().run(progress=False)


def _chunk(root: Path, index: int) -> Path:
    return root / "chunks" / f"chunk-{index:06d}.parquet"


def _swap_file(root: Path) -> None:
    # A valid chunk copied over another: its checksum no longer matches.
    shutil.copy(_chunk(root, 0), _chunk(root, 2))


def _swap_file_and_record(root: Path) -> None:
    # ... with its record too: the index and point range tell them apart.
    shutil.copy(_chunk(root, 0), _chunk(root, 2))
    rec0 = json.loads((root / "chunks" / "chunk-000000.check.json").read_text())
    (root / "chunks" / "chunk-000002.check.json").write_text(json.dumps(rec0))


def _truncate(root: Path) -> None:
    data = _chunk(root, 2).read_bytes()
    _chunk(root, 2).write_bytes(data[: len(data) // 2])


def _zero(root: Path) -> None:
    _chunk(root, 2).write_bytes(bytes(_chunk(root, 2).stat().st_size))


@pytest.mark.parametrize("damage", [_swap_file, _swap_file_and_record, _truncate, _zero])
def test_a_damaged_chunk_is_recomputed_with_a_warning_naming_its_file(tmp_path, clean, damage):
    _study().run(tmp_path, progress=False)
    damage(tmp_path)
    again = _study()
    with pytest.warns(UserWarning, match="chunk-000002.parquet fails its check"):
        df = again.run(tmp_path, progress=False)
    assert (again.report.computed, again.report.reused) == (1, 3)
    assert_frame_equal(df, clean)  # bit for bit a clean run
    # Repaired on disk: a third run reuses everything, silently.
    third = _study()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert_frame_equal(third.run(tmp_path, progress=False), clean)
    assert (third.report.computed, third.report.reused) == (0, 4)
    assert df["point"].n_unique() == df.height == 8


def test_a_chunk_of_another_grid_under_the_right_name_is_not_merged(tmp_path, clean):
    other = tb.Study("thermal", {"speed_rpm": [4000.0] * 8}, {"radial_n": 200.0}, chunk_size=2)
    other.run(tmp_path / "other", progress=False)
    _study().run(tmp_path / "mine", progress=False)
    for name in ("chunk-000001.parquet", "chunk-000001.check.json"):
        shutil.copy(tmp_path / "other" / "chunks" / name, tmp_path / "mine" / "chunks" / name)
    with pytest.warns(UserWarning, match="chunk-000001.parquet fails its check: .*grid_hash"):
        df = _study().run(tmp_path / "mine", progress=False)
    assert_frame_equal(df, clean)


def test_a_chunk_without_its_record_is_recomputed(tmp_path, clean):
    _study().run(tmp_path, progress=False)
    (tmp_path / "chunks" / "chunk-000003.check.json").unlink()
    with pytest.warns(UserWarning, match="chunk-000003.parquet .* no check record"):
        assert_frame_equal(_study().run(tmp_path, progress=False), clean)


def test_overwrite_recovers_whatever_the_folder_holds(tmp_path, clean):
    _study().run(tmp_path, progress=False)
    (tmp_path / "manifest.json").write_text("{ not json")
    (tmp_path / "chunks" / "junk.parquet").write_bytes(b"\0" * 100)
    _truncate(tmp_path)
    with pytest.raises(tb.ConfigError, match="unreadable manifest.*overwrite=True"):
        _study().run(tmp_path, progress=False)
    s = _study()
    assert_frame_equal(s.run(tmp_path, progress=False, overwrite=True), clean)
    assert s.report.computed == 4 and not (tmp_path / "chunks" / "junk.parquet").exists()
    # A manifest that is a directory, chunks/ that is a file: still recovered.
    shutil.rmtree(tmp_path / "chunks")
    (tmp_path / "chunks").write_text("junk")
    (tmp_path / "manifest.json").unlink()
    (tmp_path / "manifest.json").mkdir()
    assert_frame_equal(_study().run(tmp_path, progress=False, overwrite=True), clean)


def test_overwrite_from_the_command_line_recovers_too(tmp_path):
    toml = tmp_path / "grid.toml"
    toml.write_text('[study]\nkind = "thermal"\n[grid]\nspeed_rpm = [3000.0, 5000.0]\n')
    out = tmp_path / "out"
    out.mkdir()
    (out / "manifest.json").write_text("garbage")
    cmd = [sys.executable, "-m", "thermobear", "study", str(toml), "--out", str(out)]
    bad = subprocess.run([*cmd, "--no-progress"], capture_output=True, text=True)
    assert bad.returncode != 0 and "overwrite" in bad.stderr
    assert "Traceback" not in bad.stderr
    good = subprocess.run([*cmd, "--no-progress", "--overwrite"], capture_output=True, text=True)
    assert good.returncode == 0, good.stderr
    assert pl.read_parquet(out / "chunks" / "chunk-000000.parquet").height == 2


def test_a_run_leaves_other_runs_temporary_files_alone(tmp_path, clean):
    _study().run(tmp_path, progress=False)
    theirs = tmp_path / "chunks" / ".chunk-000009.parquet.999-other.tmp"
    theirs.write_bytes(b"in flight")
    _chunk(tmp_path, 1).unlink()
    assert_frame_equal(_study().run(tmp_path, progress=False), clean)
    assert theirs.read_bytes() == b"in flight"
    # Its own temporary files are gone (written by rename only).
    assert [p.name for p in tmp_path.rglob("*.tmp")] == [theirs.name]


_FIRST = textwrap.dedent(
    """
    import sys, time, pathlib
    import thermobear as tb
    sys.path.insert(0, {tests!r})
    from test_study_store import _study
    out, flag = pathlib.Path({out!r}), pathlib.Path({flag!r})

    def hold(index, frame):
        if index == 0:  # owns the folder now: let the other run try, then go on
            (flag / "started").write_text("1")
            end = time.monotonic() + 60
            while not (flag / "tried").exists() and time.monotonic() < end:
                time.sleep(0.02)

    _study().run(out, progress=False, on_chunk=hold)
    """
)


def test_a_second_run_on_the_same_folder_is_refused_and_the_first_finishes(tmp_path, clean):
    out, flag = tmp_path / "out", tmp_path / "flags"
    flag.mkdir()
    code = _FIRST.format(tests=str(Path(__file__).parent), out=str(out), flag=str(flag))
    first = subprocess.Popen([sys.executable, "-c", code], stderr=subprocess.PIPE, text=True)
    try:
        end = time.monotonic() + 60
        while not (flag / "started").exists() and time.monotonic() < end:
            assert first.poll() is None, first.stderr.read() if first.stderr else ""
            time.sleep(0.02)
        second = _study()
        with pytest.raises(
            tb.ConfigError, match=f"another run is using it \\(process {first.pid} "
        ):
            second.run(out, progress=False)
        with pytest.raises(tb.ConfigError, match="another run"):
            second.run(out, progress=False, overwrite=True)  # not even to overwrite
    finally:
        (flag / "tried").write_text("1")
        _, err = first.communicate(timeout=120)
    assert first.returncode == 0, err
    # The first finished alone: bit for bit a solo run, every chunk its own.
    frames = [pl.read_parquet(_chunk(out, i)) for i in range(4)]
    assert_frame_equal(pl.concat(frames), clean)
    # Released: the next run reuses everything.
    third = _study()
    assert_frame_equal(third.run(out, progress=False), clean)
    assert third.report.reused == 4
    lock = json.loads((out / ".thermobear-study.lock").read_text())
    assert lock["pid"] == os.getpid() and lock["host"]
