"""Every subcommand piped into a reader that stops early (``| head -c 1``,
or a pipe closed before the first byte) ends quietly: exit status 0 (all
written before the reader left) or 141, and no traceback, no
BrokenPipeError on stderr."""

from __future__ import annotations

import argparse
import shutil
import subprocess
import sys
from importlib import resources
from pathlib import Path

import pytest

from thermobear.cli.main import EXIT_BROKEN_PIPE, build_parser


def _config(name: str) -> str:
    with resources.as_file(resources.files("thermobear.configs").joinpath(name)) as p:
        return str(p)


def _paper(name: str) -> str:
    with resources.as_file(resources.files("thermobear.studies.papers").joinpath(name)) as p:
        return str(p)


def _runs(tmp: Path) -> dict[str, list[str]]:
    """One real, small run of every subcommand."""
    grid = tmp / "grid.toml"
    grid.write_text('[study]\nkind = "thermal"\n[grid]\nspeed_rpm = [3000.0, 5000.0]\n')
    data = _config("seed_b_measurements.csv")
    offset = "sensor_offset:front_outer_ring_temperature_c"
    spindle = ["--spindle", "seed-ceramic-spindle"]
    return {
        "demo": ["demo", "--quick", "--out", str(tmp / "demo")],
        "solve": ["solve", _config("seed_a_6208.toml"), "--out", str(tmp / "solve")],
        "presets": ["presets"],
        "effects": ["effects"],
        "diagnose": [
            "diagnose",
            data,
            *spindle,
            "--candidates",
            offset,
            "--holdout",
            "none",
            "--out",
            str(tmp / "diag"),
        ],  # fmt: skip
        "calibrate": [
            "calibrate",
            data,
            *spindle,
            "--parameters",
            offset,
            "--out",
            str(tmp / "cal"),
        ],  # fmt: skip
        "predict": [
            "predict",
            _paper("seed_a_bearing_model.json"),
            "--what",
            "temperatures",
            "--speeds",
            "5000",
            "--loads",
            "300",
            "--out",
            str(tmp / "pred"),
        ],
        "study": ["study", str(grid), "--out", str(tmp / "study"), "--no-progress"],
        "validate": ["validate", "skf_reference_speed_60", "--out", str(tmp / "val")],
    }


def _subcommands() -> list[str]:
    p = build_parser()
    [sub] = [a for a in p._actions if isinstance(a, argparse._SubParsersAction)]
    return sorted(sub.choices)


def _quiet(err: str) -> bool:
    return "Traceback" not in err and "BrokenPipe" not in err and "Broken pipe" not in err


def test_every_subcommand_is_covered(tmp_path):
    assert sorted(_runs(tmp_path)) == _subcommands()


def _closed_pipe(argv: list[str], cwd: Path) -> tuple[int, str]:
    p = subprocess.Popen(
        [sys.executable, "-m", "thermobear", *argv],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        cwd=cwd,
    )
    assert p.stdout is not None and p.stderr is not None
    p.stdout.close()  # the reader is gone before the first byte
    err = p.stderr.read().decode()
    return p.wait(timeout=600), err


@pytest.mark.parametrize("name", _subcommands())
def test_a_subcommand_into_a_closed_pipe_ends_quietly(name, tmp_path):
    code, err = _closed_pipe(_runs(tmp_path)[name], tmp_path)
    assert code in (0, EXIT_BROKEN_PIPE), err
    assert _quiet(err), err


@pytest.mark.parametrize(
    "argv", [["--help"], ["--version"]] + [[s, "--help"] for s in _subcommands()]
)
def test_help_into_a_closed_pipe_ends_quietly(argv, tmp_path):
    code, err = _closed_pipe(argv, tmp_path)
    assert code in (0, EXIT_BROKEN_PIPE) and err == "", err


@pytest.mark.skipif(shutil.which("head") is None, reason="needs head")
@pytest.mark.parametrize("name", ["effects", "presets", "solve", "study"])
def test_a_subcommand_into_head_ends_quietly(name, tmp_path):
    cmd = " ".join(f"'{a}'" for a in [sys.executable, "-m", "thermobear", *_runs(tmp_path)[name]])
    r = subprocess.run(
        ["bash", "-c", f"set -o pipefail; {cmd} | head -c 1 >/dev/null"],
        capture_output=True,
        text=True,
        timeout=600,
        cwd=tmp_path,
    )
    assert r.returncode in (0, EXIT_BROKEN_PIPE), r.stderr
    assert _quiet(r.stderr), r.stderr
