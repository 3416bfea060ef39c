"""The command line and the demo (quick mode) run end to end and write
tables and figures."""

import polars as pl

import thermobear as tb
from thermobear.cli import main


def test_demo_quick_writes_tables_and_figures(tmp_path, capsys):
    assert main(["demo", "--out", str(tmp_path), "--quick"]) == 0
    printed = capsys.readouterr().out
    assert str(tmp_path.resolve()) in printed
    pngs = list(tmp_path.rglob("*.png"))
    parquets = list(tmp_path.rglob("*.parquet"))
    csvs = list(tmp_path.rglob("*.csv"))
    assert pngs and parquets and csvs
    # Every table has a CSV beside it, except the large Poincare point sets.
    for p in parquets:
        assert p.with_suffix(".csv").exists() or p.stem.startswith("poincare_"), p
    for p in parquets:
        df = pl.read_parquet(p)
        assert df.height > 0
        for c in df.columns:
            if df[c].dtype in (pl.Float64, pl.Float32):
                assert df[c].is_nan().sum() == 0, f"NaN in {p.name}:{c}"


def test_solve_command_on_a_seed_config(tmp_path):
    cfg = tmp_path / "system.toml"
    cfg.write_text(tb.seed_config("seed_a_6208"))
    assert main(["solve", str(cfg), "--out", str(tmp_path / "out")]) == 0
    balls = pl.read_parquet(tmp_path / "out" / "balls.parquet")
    assert balls.height == 9


def test_cli_reports_bad_config_without_traceback(tmp_path, capsys):
    cfg = tmp_path / "bad.toml"
    cfg.write_text('[bearing]\npreset = "6208"\nball_diameter = 3\n')
    assert main(["solve", str(cfg), "--out", str(tmp_path / "o")]) == 1  # a config error
    assert "ball_diameter" in capsys.readouterr().err
