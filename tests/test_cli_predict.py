"""``thermobear predict`` writes what ``tb.predict`` returns for a saved
calibrated model (from ``calibrate`` or ``diagnose --out``) with one band
figure per quantity and load condition; ``diagnose --out`` saves its
calibrated model and ``--verbose`` prints the long summary; ``effects
--parameters`` lists every name ``calibrate --parameters`` accepts; and
every name typed on the command line (or in a conditions dict) that is
close to a known one gets a "did you mean"."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear import diagnosis as D
from thermobear.cli import main
from thermobear.cli.calibrate import calibratable
from thermobear.cli.main import EXIT_ERROR, EXIT_OK, EXIT_USAGE
from thermobear.diagnosis.calibrated import _Step

SPEEDS = [6000.0, 9000.0, 12000.0, 15000.0]
QUANTITIES = ["outer_ring_temperature_c", "inner_ring_temperature_c"]


def _error_line(capsys, prefix: str = "thermobear: error: ") -> str:
    """The one line on stderr of a failed command (no traceback)."""
    err = capsys.readouterr().err
    lines = [ln for ln in err.splitlines() if ln.strip()]
    assert lines and lines[-1].startswith(prefix), err
    assert "Traceback" not in err
    return lines[-1]


@pytest.fixture(scope="module")
def seed_b(tmp_path_factory) -> tuple[Path, Path, D.BearingModelSpec, dict]:
    """The seed B system description and a measurement file of its bearing
    with the lubrication factor 1.5 (no load columns: the CLI takes them
    from [operating])."""
    folder = tmp_path_factory.mktemp("seed_b")
    path = folder / "system.toml"
    path.write_text(tb.seed_config("seed_b_7009c"))
    spec, op = D.model_from_toml(path)
    cond = pl.DataFrame(
        {
            "speed_rpm": SPEEDS * len(QUANTITIES),
            "quantity": [q for q in QUANTITIES for _ in SPEEDS],
            "axial_n": float(op["axial_n"]),
            "radial_n": float(op["radial_n"]),
        }
    )
    m = D.synthetic_measurements(spec.with_setting(lubrication_factor_f0=1.5), cond, seed=3)
    csv = folder / "rig.csv"
    m.drop("axial_n", "radial_n").write_csv(csv)
    return path, csv, spec, op


@pytest.fixture(scope="module")
def calibrated(seed_b, tmp_path_factory) -> Path:
    """calibrated_model.json written by ``thermobear calibrate``."""
    path, csv, _, _ = seed_b
    out = tmp_path_factory.mktemp("cal")
    argv = ["calibrate", str(csv), "--model", str(path), "--parameters",
            "lubrication_factor_f0", "--out", str(out), "--threads", "1"]  # fmt: skip
    assert main(argv) == EXIT_OK
    return out / "calibrated_model.json"


def _same_numbers(csv: pl.DataFrame, want: pl.DataFrame) -> None:
    """The CSV holds the frame's columns and, bit for bit, its numbers."""
    assert csv.columns == want.columns
    for c in want.columns:
        if want.schema[c].is_numeric():
            a, b = csv[c].cast(pl.Float64).to_numpy(), want[c].cast(pl.Float64).to_numpy()
            assert np.array_equal(a, b, equal_nan=True), c


# ------------------------------------------------------------------ predict


def test_predict_writes_exactly_what_tb_predict_returns(calibrated, tmp_path, capsys):
    out = tmp_path / "pred"
    argv = ["predict", str(calibrated), "--what", "temperatures", "--speeds", "5000,10000,15000",
            "--loads", "300", "--loads", "500,100", "--format", "png,svg", "--out", str(out),
            "--threads", "1"]  # fmt: skip
    assert main(argv) == EXIT_OK
    printed = capsys.readouterr().out
    model = tb.CalibratedModel.load(calibrated)
    cond = {"speeds_rpm": [5000.0, 10000.0, 15000.0], "loads": [(300.0, 0.0), (500.0, 100.0)]}
    want = tb.predict(model, "temperatures", cond)
    got = pl.read_parquet(out / "prediction.parquet")
    assert got.equals(want) and got.schema == want.schema
    _same_numbers(pl.read_csv(out / "prediction.csv"), want)
    # the calibration acts: the band has a width and the frame is not the baseline's
    assert (want["upper"] - want["lower"]).min() > 0.0
    # one figure per quantity and load condition, in each format
    quantities = want["quantity"].unique().to_list()
    assert len(quantities) >= 4
    figures = sorted(p.name for p in out.iterdir() if p.suffix in (".png", ".svg"))
    assert len(figures) == len(quantities) * 2 * 2
    for q in quantities:
        for suffix in ("axial_300n_radial_0n", "axial_500n_radial_100n"):
            for ext in ("png", "svg"):
                f = out / f"prediction_{q}_{suffix}.{ext}"
                assert f.stat().st_size > 1000, f
    assert f"{len(figures) + 2} files written" in printed


def test_predict_level_and_one_load_condition(calibrated, tmp_path):
    out = tmp_path / "pred"
    argv = ["predict", str(calibrated), "--what", "stiffness", "--speeds", "4000,12000",
            "--loads", "300", "--level", "0.5", "--out", str(out)]  # fmt: skip
    assert main(argv) == EXIT_OK
    model = tb.CalibratedModel.load(calibrated)
    cond = {"speeds_rpm": [4000.0, 12000.0], "axial_n": 300.0}
    half = tb.predict(model, "stiffness", cond, level=0.5)
    assert pl.read_parquet(out / "prediction.parquet").equals(half)
    wide = tb.predict(model, "stiffness", cond)
    assert ((half["upper"] - half["lower"]) < (wide["upper"] - wide["lower"])).all()
    # one load condition: the figures carry no load in their names
    for q in half["quantity"].unique().to_list():
        assert (out / f"prediction_{q}.png").is_file()


def test_predict_a_spindle_model_takes_preloads(tmp_path, capsys):
    sp = tb.Spindle.preset("seed-ceramic-spindle")
    spec = tb.SpindleModelSpec.of_model(sp).with_setting(spin_friction_coefficient=0.08)
    model = tb.CalibratedModel("nothing", "baseline", spec, [], [], np.zeros((0, 0)))
    path = model.save(tmp_path / "spindle.json")
    out = tmp_path / "pred"
    base = ["predict", str(path), "--what", "vibration", "--speeds", "8000,12000",
            "--out", str(out)]  # fmt: skip
    assert main(base + ["--preloads", "300,500"]) == EXIT_OK
    cond = {"speeds_rpm": [8000.0, 12000.0], "preload_n": [300.0, 500.0]}
    want = tb.predict(model, "vibration", cond)
    got = pl.read_parquet(out / "prediction.parquet")
    assert got.equals(want) and sorted(set(got["preload_n"])) == [300.0, 500.0]
    assert (out / "prediction_velocity_rms_mm_s_preload_300n.png").is_file()
    # a bearing's --loads on a spindle model is a usage error saying what to give
    capsys.readouterr()
    assert main(base + ["--loads", "300"]) == EXIT_USAGE
    line = _error_line(capsys, "thermobear predict: error: ")
    assert "--preloads" in line and "spindle" in line


def _tie_model() -> tb.CalibratedModel:
    """A tie of two explanations of one 7008C (an extra heat, a larger f0),
    each with its value and variance."""
    spec = tb.BearingModelSpec(tb.Bearing.preset("7008C"))
    cands = {c.name: c for c in spec.candidate_list(QUANTITIES)}
    members = [
        tb.CalibratedModel("named", f"named: {n}", spec, [_Step(n, cands[n])], [v], [[var]])
        for n, v, var in (("extra_heat_w", 5.0, 1.0), ("lubrication_factor_f0", 1.3, 0.01))
    ]
    m = members[0]
    return tb.CalibratedModel("tie", "tie", spec, m._steps, m.values, m.covariance,
                              members=members)  # fmt: skip


def test_member_picks_one_explanation_and_names_a_close_label(tmp_path, capsys):
    model = _tie_model()
    path = model.save(tmp_path / "tie.json")
    out = tmp_path / "pred"
    base = ["predict", str(path), "--what", "temperatures", "--speeds", "6000,12000",
            "--loads", "300", "--out", str(out)]  # fmt: skip
    assert main(base + ["--member", "named: extra_heat_w"]) == EXIT_OK
    loaded = tb.CalibratedModel.load(path)
    cond = {"speeds_rpm": [6000.0, 12000.0], "axial_n": 300.0}
    whole = tb.predict(loaded, "temperatures", cond, band="envelope")
    assert set(whole["member"]) == {"named: extra_heat_w", "named: lubrication_factor_f0",
                                    "envelope"}  # fmt: skip
    got = pl.read_parquet(out / "prediction.parquet")
    assert got.height and got.equals(whole.filter(pl.col("member") == "named: extra_heat_w"))
    # the combined rows: --member envelope reads the members' bands that way
    assert main(base + ["--member", "envelope"]) == EXIT_OK
    got = pl.read_parquet(out / "prediction.parquet")
    assert got.height and got.equals(whole.filter(pl.col("member") == "envelope"))
    capsys.readouterr()
    assert main(base + ["--member", "envelope", "--band", "mixture"]) == EXIT_ERROR
    assert "--band mixture" in _error_line(capsys)
    assert main(base + ["--member", "named: extra_heat"]) == EXIT_ERROR
    assert "did you mean named: extra_heat_w?" in _error_line(capsys)
    # a single model has no members to pick from
    single = model.members[0].save(tmp_path / "single.json")
    assert main(["predict", str(single), *base[2:], "--member", "envelope"]) == EXIT_ERROR
    assert "single explanation" in _error_line(capsys)


@pytest.mark.parametrize(
    ("extra", "needle"),
    [
        (["--what", "stiffnes", "--loads", "300"], "did you mean stiffness?"),
        (["--what", "regimes", "--loads", "300"], "invalid what = 'regimes'"),
        (["--loads", "300", "--level", "1.5"], "level"),
        (["--loads", "300,0,5"], "AXIAL_N or AXIAL_N,RADIAL_N"),
        (["--loads", "300", "--preloads", "400"], "not allowed with argument"),
        (["--loads", "300", "--format", "jpg"], "invalid format"),
        ([], "needs --loads"),
        (["--preloads", "400"], "--preloads is for a spindle model"),
    ],
)
def test_usage_errors_exit_2_naming_the_option(calibrated, tmp_path, capsys, extra, needle):
    argv = ["predict", str(calibrated), "--speeds", "5000", "--out", str(tmp_path / "o"), *extra]
    assert main(argv) == EXIT_USAGE
    assert needle in _error_line(capsys, "thermobear predict: error: ")
    assert not (tmp_path / "o").exists()


def test_a_file_that_is_no_model_is_an_error_naming_it(tmp_path, capsys):
    bad = tmp_path / "calibration.json"
    bad.write_text('{"parameters": []}')
    argv = ["predict", str(bad), "--speeds", "5000", "--loads", "300", "--out", str(tmp_path)]
    assert main(argv) == EXIT_ERROR
    line = _error_line(capsys)
    assert str(bad) in line and "thermobear-calibrated-model" in line
    assert main(["predict", str(tmp_path / "none.json"), *argv[2:]]) == EXIT_ERROR
    assert "none.json" in _error_line(capsys)


# ------------------------------------------------------------------ diagnose


def test_diagnose_saves_its_model_and_prints_the_cli_advice(seed_b, tmp_path, capsys):
    path, csv, spec, op = seed_b
    out = tmp_path / "diag"
    names = ["lubrication_factor_f0", "extra_heat_w"]
    argv = ["diagnose", str(csv), "--model", str(path), "--candidates", ",".join(names),
            "--holdout", "none", "--out", str(out), "--threads", "1"]  # fmt: skip
    assert main(argv + ["--verbose"]) == EXIT_OK
    printed = capsys.readouterr().out
    loads = {"axial_n": float(op["axial_n"]), "radial_n": float(op["radial_n"])}
    data = pl.read_csv(csv).with_columns(**{k: pl.lit(v) for k, v in loads.items()})
    d = tb.diagnose(spec, data, candidates=names, holdout=None)
    assert d.summary(verbose=True) in printed and "note: " in d.summary(verbose=True)
    # the model file: the diagnosis' calibrated model, which predict takes
    saved = tb.CalibratedModel.load(out / "calibrated_model.json")
    assert saved.kind == d.model.kind and saved.names == d.model.names
    assert saved.values.tobytes() == d.model.values.tobytes()
    assert "calibrated_model.json" in {p.name for p in out.iterdir()}
    # the short summary's advice to see more is the option, not the Python call
    from thermobear.cli.diagnose import cli_summary

    assert "summary(verbose=True)" in d.summary()
    short = cli_summary(d)
    assert "--verbose" in short and "summary(verbose=True)" not in short
    pred = tmp_path / "pred"
    argv = ["predict", str(out / "calibrated_model.json"), "--what", "temperatures",
            "--speeds", "8000,16000", "--loads", "300", "--out", str(pred)]  # fmt: skip
    assert main(argv) == EXIT_OK
    want = tb.predict(saved, "temperatures", {"speeds_rpm": [8000.0, 16000.0], "axial_n": 300.0})
    assert pl.read_parquet(pred / "prediction.parquet").equals(want)


# ------------------------------------------------------------------ names


def test_effects_parameters_lists_every_name_calibrate_accepts(capsys):
    assert main(["effects", "--parameters"]) == EXIT_OK
    listed = [ln.split()[0] for ln in capsys.readouterr().out.splitlines()]
    assert len(listed) == len(set(listed))
    bearing = tb.candidates(tb.BearingModelSpec(tb.Bearing.preset("7008C")),
                            list(tb.BearingModelSpec.quantities))  # fmt: skip
    want = set(bearing.filter(pl.col("kind") == "parameter")["name"])
    for name in tb.Spindle.preset_names():
        spec = tb.SpindleModelSpec(tb.Spindle.preset(name))
        want |= {c.name for c in calibratable(spec)}
    assert set(listed) == want
    for name in ("lubrication_factor_f0", "axial_load_scale", "preload_scale",
                 "sensor_offset:outer_ring_temperature_c", "sensor_gain:outer_ring_temperature_c",
                 "churning_oil_fraction", "extra_heat_w"):  # fmt: skip
        assert name in listed
    # a switch is screened by diagnose but not calibrated
    assert "heat_model:skf" not in listed
    # one baseline: only its names
    assert main(["effects", "--parameters", "--spindle", "seed-ceramic-spindle"]) == EXIT_OK
    own = {ln.split()[0] for ln in capsys.readouterr().out.splitlines()}
    assert "preload_scale" in own and "lubrication_factor_f0" not in own


def test_effects_baseline_options_go_with_parameters(capsys):
    assert main(["effects", "--spindle", "seed-ceramic-spindle"]) == EXIT_USAGE
    assert "--parameters" in _error_line(capsys, "thermobear effects: error: ")


@pytest.mark.parametrize(
    ("argv", "near"),
    [
        (["--parameters", "lubrication_factor_fo"], "lubrication_factor_f0"),
        (
            ["--parameters", "lubrication_factor_f0", "--per-set", "lubrication_factor_fo"],
            "lubrication_factor_f0",
        ),
        (["--parameters", "axial_load_scal"], "axial_load_scale"),
        (["--parameters", "extra_heat_w", "--without", "spin_fricton"], "spin_friction"),
    ],
)
def test_calibrate_names_a_close_parameter(seed_b, tmp_path, capsys, argv, near):
    path, csv, _, _ = seed_b
    full = ["calibrate", str(csv), "--model", str(path), "--out", str(tmp_path / "c"), *argv]
    assert main(full) == EXIT_ERROR
    line = _error_line(capsys)
    assert f"did you mean {near}?" in line
    assert not (tmp_path / "c").exists()  # refused before any work


def test_a_misspelt_name_far_from_any_gets_no_guess(seed_b, tmp_path, capsys):
    path, csv, _, _ = seed_b
    argv = ["calibrate", str(csv), "--model", str(path), "--out", str(tmp_path / "c"),
            "--parameters", "qqqq"]  # fmt: skip
    assert main(argv) == EXIT_ERROR
    line = _error_line(capsys)
    assert "qqqq" in line and "did you mean" not in line and "effects --parameters" in line


@pytest.mark.parametrize(
    ("argv", "near"),
    [
        (["diagnose", "m.csv", "--spindle", "seed-ceramic-spindel"], "seed-ceramic-spindle"),
        (
            [
                "calibrate",
                "m.csv",
                "--spindle",
                "seed-steel-spinde",
                "--parameters",
                "x",
                "--out",
                "o",
            ],
            "seed-steel-spindle",
        ),
        (
            [
                "diagnose",
                "m.csv",
                "--spindle",
                "seed-ceramic-spindle",
                "--without",
                "thermal_displacment",
            ],
            "thermal_displacement",
        ),
        (["validate", "seed_b_spindel"], "seed_b_spindle"),
    ],
)
def test_presets_effects_and_sets_get_a_guess(argv, near, capsys):
    assert main(argv) == EXIT_ERROR
    assert f"did you mean {near}?" in _error_line(capsys)


def test_diagnose_candidates_get_a_guess(seed_b, capsys):
    path, csv, _, _ = seed_b
    argv = ["diagnose", str(csv), "--model", str(path), "--candidates", "extra_heat"]
    assert main(argv) == EXIT_ERROR
    assert "did you mean extra_heat_w?" in _error_line(capsys)


@pytest.mark.parametrize(
    ("argv", "near"),
    [
        (["demo", "--format", "pnf"], "png"),
        (["diagnose", "m.csv", "--model", "s.toml", "--holdout", "highest"], "highest_speeds"),
    ],
)
def test_cli_vocabulary_gets_a_guess_as_a_usage_error(argv, near, capsys):
    assert main(argv) == EXIT_USAGE
    assert f"did you mean {near}?" in capsys.readouterr().err


def test_a_conditions_dict_with_a_near_miss_names_the_key():
    spec = tb.BearingModelSpec(tb.Bearing.preset("7008C"))
    model = tb.CalibratedModel("nothing", "baseline", spec, [], [], np.zeros((0, 0)))
    for bad, near in (({"speed_rpm": [5000.0], "axial_n": 300.0}, "speeds_rpm"),
                      ({"speeds_rpm": [5000.0], "axial_N": 300.0}, "axial_n"),
                      ({"speeds_rpm": [5000.0], "axial_n": 300.0, "radial": 10.0}, "radial_n"),
                      ({"speeds_rpm": [5000.0], "load": [(300.0, 0.0)]}, "loads")):  # fmt: skip
        key = next(k for k in bad if k not in ("speeds_rpm", "axial_n"))
        with pytest.raises(tb.ConfigError, match=rf"invalid conditions key = '{key}'.*"
                           rf"did you mean {near}\?"):  # fmt: skip
            tb.predict(model, "temperatures", bad)
    # a spindle's preload stands for a bearing's axial load, as before
    ok = tb.predict(model, "temperatures", {"speeds_rpm": [5000.0], "preload_n": 300.0})
    assert ok["axial_n"].to_list() == [300.0] * ok.height


def test_data_errors_give_the_command_line_advice(seed_b, tmp_path, capsys):
    """A duplicated measurement is refused with advice the command line can
    follow (the file), not the Python loader's keyword."""
    path, csv, _, _ = seed_b
    twice = tmp_path / "twice.csv"
    rows = pl.read_csv(csv)
    pl.concat([rows, rows.with_columns(pl.col("value") + 0.1)]).write_csv(twice)
    assert main(["diagnose", str(twice), "--model", str(path), "--holdout", "none"]) == EXIT_ERROR
    line = _error_line(capsys)
    assert "duplicated measurement" in line and str(twice) in line
    assert "average them in the file" in line and "duplicates=" not in line
