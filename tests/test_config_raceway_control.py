"""``[model] raceway_control`` of a system description reaches the solve it
configures (``thermobear solve``), and a name other than "outer" or
"inner" is refused when the description is loaded, naming the key."""

from __future__ import annotations

from importlib import resources

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear.cli.main import EXIT_ERROR, EXIT_OK, main
from thermobear.config import load_config


def _seed_a(control: str) -> str:
    path = resources.files("thermobear.configs").joinpath("seed_a_6208.toml")
    text = path.read_text()
    assert 'raceway_control = "outer"' in text
    text = text.replace('raceway_control = "outer"', f'raceway_control = "{control}"')
    # A short sweep keeps the test quick.
    return text.replace("speed_count = 101", "speed_count = 3")


@pytest.mark.parametrize("control", ["outer", "inner"])
def test_the_solve_of_a_description_follows_its_raceway_control(control, tmp_path):
    cfg = tmp_path / "system.toml"
    cfg.write_text(_seed_a(control))
    assert main(["solve", str(cfg), "--out", str(tmp_path / "o")]) == EXIT_OK
    balls = pl.read_csv(tmp_path / "o" / "balls.csv")
    b = tb.Bearing.preset("6208")
    effects = ["centrifugal_force", "gyroscopic_moment", "ring_centrifugal_expansion"]
    kw = dict(axial_n=2680.9, radial_n=1189.9, speed_rpm=16000.0, effects=effects)
    mine = b.solve(**kw, raceway_control=control).balls
    other = b.solve(**kw, raceway_control="inner" if control == "outer" else "outer").balls
    col = "inner_contact_angle_deg"
    np.testing.assert_allclose(balls[col].to_numpy(), mine[col].to_numpy(), rtol=1e-12)
    # The two controls differ at 16,000 rpm (the gyroscopic couple sits at
    # the other raceway), so the file could not match both.
    assert np.max(np.abs(mine[col].to_numpy() - other[col].to_numpy())) > 1e-6


def test_an_unknown_raceway_control_is_refused_naming_the_key(tmp_path, capsys):
    with pytest.raises(tb.ConfigError, match="raceway_control.*middle"):
        load_config(_seed_a("middle"))
    cfg = tmp_path / "system.toml"
    cfg.write_text(_seed_a("middle"))
    assert main(["solve", str(cfg), "--out", str(tmp_path / "o")]) == EXIT_ERROR
    err = capsys.readouterr().err
    assert "raceway_control" in err and "middle" in err and "Traceback" not in err
