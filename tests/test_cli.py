"""The command line follows the conventions: --version, exit status 0 / 1
(data, model, convergence) / 2 (usage) / 130 (interrupted), a reader that
stops early ends it quietly, errors on one line naming the file, the line
and the key (or column), --threads on every computing subcommand, diagnose
--candidates / --holdout, and calibrate writing what tb.calibrate finds."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear import diagnosis as D
from thermobear.cli import main
from thermobear.cli.main import (
    EXIT_BROKEN_PIPE,
    EXIT_ERROR,
    EXIT_INTERRUPTED,
    EXIT_OK,
    EXIT_USAGE,
    build_parser,
)

SEED_A = tb.seed_config("seed_a_6208")
SPEEDS = [6000.0, 9000.0, 12000.0, 15000.0]
QUANTITIES = ["outer_ring_temperature_c", "inner_ring_temperature_c"]


def _run(*args: str) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "thermobear", *args],
        capture_output=True,
        text=True,
        timeout=300,
    )


def _error_line(capsys) -> str:
    """The one line on stderr of a failed command (and no traceback)."""
    err = capsys.readouterr().err
    lines = [ln for ln in err.splitlines() if ln.strip()]
    assert len(lines) == 1, err
    assert lines[0].startswith("thermobear: error: ")
    assert "Traceback" not in err
    return lines[0]


@pytest.fixture(scope="module")
def seed_b(tmp_path_factory) -> tuple[Path, D.BearingModelSpec, dict]:
    path = tmp_path_factory.mktemp("seed_b") / "system.toml"
    path.write_text(tb.seed_config("seed_b_7009c"))
    spec, op = D.model_from_toml(path)
    return path, spec, op


def _measurements(spec, op, f0: float, seed: int) -> pl.DataFrame:
    """Synthetic measurements of the bearing of ``spec`` with the
    lubrication factor ``f0``, without load columns (the CLI takes them
    from [operating])."""
    cond = pl.DataFrame(
        {
            "speed_rpm": SPEEDS * len(QUANTITIES),
            "quantity": [q for q in QUANTITIES for _ in SPEEDS],
            "axial_n": float(op["axial_n"]),
            "radial_n": float(op["radial_n"]),
        }
    )
    m = D.synthetic_measurements(spec.with_setting(lubrication_factor_f0=f0), cond, seed=seed)
    return m.drop("axial_n", "radial_n")


# ------------------------------------------------------------- version, help, usage


def test_version_prints_the_version_and_exits_0(capsys):
    assert main(["--version"]) == EXIT_OK
    assert capsys.readouterr().out.strip() == f"thermobear {tb.__version__}"
    r = _run("--version")
    assert r.returncode == 0 and r.stdout.strip() == f"thermobear {tb.__version__}"


def test_help_documents_the_exit_status(capsys):
    assert main(["--help"]) == EXIT_OK
    out = capsys.readouterr().out
    assert "exit status:" in out
    for code in ("0 ", "1 ", "2 ", "130 "):
        assert f"\n  {code}" in out
    assert main(["calibrate", "--help"]) == EXIT_OK
    assert "130" in capsys.readouterr().out


@pytest.mark.parametrize(
    "argv",
    [
        [],
        ["no-such-command"],
        ["solve"],
        ["solve", "x.toml", "--no-such-option"],
        ["solve", "x.toml", "--threads", "0"],
        ["solve", "x.toml", "--threads", "many"],
        ["diagnose", "m.csv"],  # no baseline
        ["diagnose", "m.csv", "--model", "s.toml", "--spindle", "seed-ceramic-spindle"],
        ["diagnose", "m.csv", "--model", "s.toml", "--holdout", "2"],
        ["diagnose", "m.csv", "--model", "s.toml", "--holdout", "highest"],
        ["calibrate", "m.csv", "--model", "s.toml", "--out", "o"],  # no --parameters
        ["calibrate", "m.csv", "--model", "s.toml", "--parameters", "extra_heat_w"],  # no --out
    ],
)
def test_usage_errors_exit_2(argv, capsys):
    assert main(argv) == EXIT_USAGE
    assert "usage: thermobear" in capsys.readouterr().err


def test_usage_error_exit_2_from_the_installed_command():
    r = _run("solve", "x.toml", "--threads", "-3")
    assert r.returncode == 2
    assert "--threads" in r.stderr and "Traceback" not in r.stderr


# ------------------------------------------------------------- errors: file, line, key


def test_toml_syntax_error_names_file_and_line(tmp_path, capsys):
    cfg = tmp_path / "broken.toml"
    cfg.write_text(SEED_A.replace("[bearing]", "[bearing"))  # line 5
    assert main(["solve", str(cfg), "--out", str(tmp_path / "o")]) == EXIT_ERROR
    line = _error_line(capsys)
    assert f"{cfg}:5:" in line and "TOML" in line


def test_toml_syntax_error_in_a_key_names_its_line_and_key(tmp_path, capsys):
    cfg = tmp_path / "broken.toml"
    cfg.write_text('[bearing]\npreset = "6208"\nring_material = = "52100"\n')
    assert main(["solve", str(cfg)]) == EXIT_ERROR
    line = _error_line(capsys)
    assert f"{cfg}:3:" in line and "key bearing.ring_material" in line


@pytest.mark.parametrize(
    ("old", "new", "line", "key"),
    [
        ("speed_count = 101", "speed_count = 0", 19, "sweep.speed_count"),
        ("speed_rpm = 16000.0", 'speed_rpm = "fast"', 11, "operating.speed_rpm"),
        ('preset = "6208" ', 'preset = "6208"\nwidgets = 3 ', 7, "bearing.widgets"),
        ('ring_material = "52100"', 'ring_material = "cheese"', 7, "bearing.ring_material"),
        ('"centrifugal_force",', '"centrifugal_forse",', 22, "model.effects"),
    ],
)
def test_config_value_error_names_file_line_and_key(tmp_path, capsys, old, new, line, key):
    assert old in SEED_A
    cfg = tmp_path / "system.toml"
    cfg.write_text(SEED_A.replace(old, new))
    assert SEED_A.replace(old, new).splitlines()[line - 1].strip().startswith(key.split(".")[1])
    assert main(["solve", str(cfg), "--out", str(tmp_path / "o")]) == EXIT_ERROR
    msg = _error_line(capsys)
    assert msg.startswith(f"thermobear: error: {cfg}:{line}: key {key}: ")


def test_config_errors_of_the_library_name_line_and_key_too(tmp_path):
    cfg = tmp_path / "system.toml"
    cfg.write_text(SEED_A.replace("speed_count = 101", "speed_count = 0"))
    with pytest.raises(tb.ConfigError) as e:
        tb.load_config(cfg)
    assert (e.value.path, e.value.line, e.value.key) == (str(cfg), 19, "sweep.speed_count")
    with pytest.raises(tb.ConfigError, match=r"^line 19: key sweep\.speed_count: "):
        tb.load_config(cfg.read_text())


def test_missing_file_is_a_data_error_naming_it(tmp_path, capsys):
    missing = tmp_path / "nowhere.toml"
    assert main(["solve", str(missing)]) == EXIT_ERROR
    line = _error_line(capsys)
    assert str(missing) in line and "cannot read" in line


def test_study_file_error_names_file_line_and_key(tmp_path, capsys):
    grid = tmp_path / "grid.toml"
    grid.write_text("[study]\nkind = 'bearing'\n\n[grid]\nspeed_rpm = [1000.0]\nspeeds = [1.0]\n")
    assert main(["study", str(grid), "--out", str(tmp_path / "r")]) == EXIT_ERROR
    assert f"{grid}:6: key grid.speeds: " in _error_line(capsys)


def _bad_csv(tmp_path: Path, good: pl.DataFrame, row: int, column: str, cell: str) -> Path:
    """``good`` as CSV behind two comment lines, one cell replaced; the
    cell's row ends up on line ``row + 4`` (2 comments, the header, from 1)."""
    text = good.with_columns(pl.col(column).cast(pl.Utf8)).with_columns(
        pl.when(pl.int_range(pl.len()) == row)
        .then(pl.lit(cell or None))  # "": an empty cell
        .otherwise(pl.col(column))
        .alias(column)
    )
    path = tmp_path / f"bad_{column}_{row}.csv"
    path.write_text("# a rig\n# two comment lines\n" + text.write_csv())
    return path


@pytest.mark.parametrize(
    ("column", "cell", "what"),
    [
        ("value", "abc", "not numeric"),
        ("value", "900.0", "outside the plausible"),
        ("quantity", "no_such_temperature_c", "invalid quantity"),
        ("sigma", "-1.0", "invalid sigma"),
        ("speed_rpm", "", "NaN, infinite or missing"),
    ],
)
def test_measurement_error_names_file_line_and_column(tmp_path, capsys, seed_b, column, cell, what):
    path, spec, op = seed_b
    csv = _bad_csv(tmp_path, _measurements(spec, op, 1.0, 0), 5, column, cell)
    assert main(["diagnose", str(csv), "--model", str(path)]) == EXIT_ERROR
    msg = _error_line(capsys)
    assert msg.startswith(f"thermobear: error: {csv}:9: column {column}: "), msg
    assert what in msg


def test_missing_column_names_file_and_header_line(tmp_path, capsys, seed_b):
    path, spec, op = seed_b
    csv = tmp_path / "m.csv"
    csv.write_text("# comment\n" + _measurements(spec, op, 1.0, 0).drop("value").write_csv())
    assert main(["calibrate", str(csv), "--model", str(path), "--parameters",
                 "lubrication_factor_f0", "--out", str(tmp_path / "o")]) == EXIT_ERROR  # fmt: skip
    msg = _error_line(capsys)
    assert f"{csv}:2: " in msg and "'value'" in msg


def test_data_errors_of_the_installed_command_exit_1_on_one_line(tmp_path, seed_b):
    path, spec, op = seed_b
    csv = _bad_csv(tmp_path, _measurements(spec, op, 1.0, 0), 2, "value", "warm")
    r = _run("diagnose", str(csv), "--model", str(path))
    assert r.returncode == 1
    assert r.stderr.splitlines() == [
        f"thermobear: error: {csv}:6: column value: invalid value = 'warm' in row 2: not numeric"
    ]
    r = _run("--debug", "diagnose", str(csv), "--model", str(path))
    assert r.returncode == 1 and "Traceback" in r.stderr


def test_model_and_convergence_errors_exit_1(monkeypatch, capsys):
    from thermobear.bearing import Bearing

    def fails() -> list[str]:
        raise tb.ConvergenceError("thermal state: residual 3.2e-2 K after 200 iterations")

    monkeypatch.setattr(Bearing, "preset_names", staticmethod(fails))
    assert main(["presets"]) == EXIT_ERROR
    assert "residual 3.2e-2 K" in _error_line(capsys)
    assert main(["diagnose", "m.csv", "--spindle", "no-such-spindle"]) == EXIT_ERROR
    assert "no-such-spindle" in _error_line(capsys)


def test_interrupt_exits_130(monkeypatch, capsys):
    from thermobear.bearing import Bearing

    def interrupted() -> list[str]:
        raise KeyboardInterrupt

    monkeypatch.setattr(Bearing, "preset_names", staticmethod(interrupted))
    assert main(["presets"]) == EXIT_INTERRUPTED
    err = capsys.readouterr().err
    assert err.strip() == "thermobear: interrupted"
    # a real SIGINT, delivered while the command runs
    code = (
        "import os, signal\n"
        "from thermobear.bearing import Bearing\n"
        "from thermobear.cli import main\n"
        "Bearing.preset_names = staticmethod(lambda: os.kill(os.getpid(), signal.SIGINT) or [])\n"
        "raise SystemExit(main(['presets']))\n"
    )
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == EXIT_INTERRUPTED
    assert r.stderr.strip() == "thermobear: interrupted"


def test_reader_that_stops_early_ends_quietly(monkeypatch):
    class ClosedPipe:
        def write(self, s: str) -> int:
            raise BrokenPipeError(32, "Broken pipe")

        def flush(self) -> None:
            raise BrokenPipeError(32, "Broken pipe")

    monkeypatch.setattr(sys, "stdout", ClosedPipe())
    assert main(["effects"]) == EXIT_BROKEN_PIPE
    # the installed command with its reader gone before it writes: no traceback
    p = subprocess.Popen(
        [sys.executable, "-m", "thermobear", "effects"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
    )
    p.stdout.close()  # the reader stops before the first line arrives
    err = p.stderr.read().decode()
    assert p.wait(timeout=120) == EXIT_BROKEN_PIPE
    assert err == ""


# ------------------------------------------------------------------------ threads


@pytest.mark.parametrize(
    "argv",
    [
        ["demo", "--quick"],
        ["solve", "x.toml"],
        ["diagnose", "m.csv", "--model", "s.toml"],
        ["calibrate", "m.csv", "--model", "s.toml", "--parameters", "a", "--out", "o"],
        ["study", "grid.toml", "--out", "r"],
        ["validate"],
    ],
)
def test_every_computing_subcommand_takes_threads(argv):
    args = build_parser().parse_args(argv + ["--threads", "1"])
    assert args.threads == 1


def test_threads_limit_the_native_pool_during_the_command(tmp_path, monkeypatch, capsys):
    import thermobear.cli.solve as solve

    seen = []

    def record(path, out):
        seen.append(os.environ.get("RAYON_NUM_THREADS"))
        return out

    monkeypatch.delenv("RAYON_NUM_THREADS", raising=False)
    monkeypatch.setattr(solve, "solve_config", record)
    assert main(["solve", "x.toml", "--threads", "1"]) == EXIT_OK
    assert main(["solve", "x.toml", "--threads", "100000"]) == EXIT_OK
    cores = len(os.sched_getaffinity(0))
    assert seen == ["1", str(cores)]
    assert f"above the {cores} cores" in capsys.readouterr().err
    assert "RAYON_NUM_THREADS" not in os.environ  # restored after the command


def test_threads_run_a_solve_and_a_study(tmp_path, capsys):
    cfg = tmp_path / "system.toml"
    cfg.write_text(SEED_A.replace("speed_count = 101", "speed_count = 5"))
    r = _run("solve", str(cfg), "--out", str(tmp_path / "o"), "--threads", "1")
    assert r.returncode == 0, r.stderr
    assert pl.read_parquet(tmp_path / "o" / "stiffness_vs_speed.parquet").height == 5
    grid = tmp_path / "grid.toml"
    grid.write_text("[study]\nkind = 'bearing'\n[grid]\nspeed_rpm = [4000.0, 8000.0]\n")
    out = tmp_path / "r"
    assert main(["study", str(grid), "--out", str(out), "--no-progress", "--threads", "1"]) == 0
    assert pl.scan_parquet(out / "chunks" / "*.parquet").collect().height == 2


# ------------------------------------------------------------- diagnose, calibrate


def test_diagnose_candidates_and_holdout_as_the_python_call(tmp_path, capsys, seed_b):
    path, spec, op = seed_b
    meas = _measurements(spec, op, 1.6, 1).with_columns(
        run=pl.when(pl.col("speed_rpm") == SPEEDS[-1]).then(pl.lit("b")).otherwise(pl.lit("a"))
    )
    csv = tmp_path / "m.csv"
    meas.write_csv(csv)
    names = ["lubrication_factor_f0", "extra_heat_w"]
    out = tmp_path / "out"
    argv = ["diagnose", str(csv), "--model", str(path), "--candidates", ",".join(names)]
    assert main(argv + ["--holdout", "run:b", "--out", str(out), "--threads", "1"]) == 0
    text = capsys.readouterr().out
    loads = pl.read_csv(csv).with_columns(axial_n=pl.lit(float(op["axial_n"])), radial_n=0.0)
    d = tb.diagnose(spec, loads, candidates=names, holdout=["b"])
    assert d.verdict in text
    screened = pl.read_csv(out / "diagnosis_screening.csv")["candidate"].unique().to_list()
    assert set(screened) - {"generic_control"} <= set(names)
    held = pl.read_csv(out / "diagnosis_points.csv")
    assert held.filter(pl.col("heldout"))["speed_rpm"].unique().to_list() == [SPEEDS[-1]]
    # no hold-out: the gap table uses every point
    assert main(argv + ["--holdout", "none"]) == 0
    assert "no held-out points" in capsys.readouterr().out
    # an unknown candidate is a model error naming it
    assert main(argv[:-1] + ["no_such_candidate"]) == EXIT_ERROR
    assert "no_such_candidate" in _error_line(capsys)


def test_calibrate_writes_what_tb_calibrate_finds(tmp_path, capsys, seed_b):
    path, spec, op = seed_b
    files = []
    for i, f0 in enumerate((1.5, 1.5)):
        f = tmp_path / f"run{i}.csv"
        _measurements(spec, op, f0, 10 + i).write_csv(f)
        files.append(f)
    out = tmp_path / "cal"
    argv = ["calibrate", *map(str, files), "--model", str(path), "--out", str(out)]
    argv += ["--parameters", "lubrication_factor_f0", "--threads", "1"]
    assert main(argv) == EXIT_OK
    printed = capsys.readouterr().out
    loads = {"axial_n": float(op["axial_n"]), "radial_n": float(op["radial_n"])}
    sets = {
        f.stem: (spec, pl.read_csv(f).with_columns(**{k: pl.lit(v) for k, v in loads.items()}))
        for f in files
    }
    cal = tb.calibrate(sets, ["lubrication_factor_f0"])
    want = cal.parameters
    assert 1.0 < want["lower_95"][0] < 1.5 < want["upper_95"][0] < 2.0  # a real estimate
    doc = json.loads((out / "calibration.json").read_text())
    got = pl.DataFrame(doc["parameters"])
    assert got.columns == want.columns
    assert got.rows() == want.rows()  # the same numbers, bit for bit
    assert doc["chi2"] == cal.chi2 and doc["n"] == cal.n == 16
    assert doc["condition_number"] == pytest.approx(cal.condition_number, rel=1e-12)
    assert doc["sets"] == {f.stem: str(f) for f in files}
    table = pl.read_csv(out / "calibration_parameters.csv")
    for c in ("value", "lower_95", "upper_95"):
        np.testing.assert_allclose(table[c].to_numpy(), want[c].to_numpy(), rtol=1e-15)
    assert pl.read_parquet(out / "calibration_parameters.parquet").equals(want)
    assert pl.read_parquet(out / "calibration_points.parquet").equals(cal.points)
    summary = (out / "calibration_summary.txt").read_text().strip()
    assert summary == doc["summary"] and summary in printed
    assert "lubrication_factor_f0" in summary
    model = tb.CalibratedModel.load(out / "calibrated_model.json")
    assert model.values.tolist() == want["value"].to_list()  # the same estimate, bit for bit
