"""Seed A's 6208 deep-groove bearing: ball loads and stiffness against speed
(constant vs speed-dependent)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from ..bearing import Bearing
from ..config import read_toml, seed_config, sweep_speeds
from ..thermal import stiffness_curve
from .output import save_figure, write_table


def _contact_summary(df_list: list, labels: list) -> Any:
    import polars as pl

    return pl.concat(
        [
            d.with_columns(pl.lit(lab).alias("case"))
            for d, lab in zip(df_list, labels, strict=False)
        ],
        how="diagonal",
    )


def table1_bearing(b: Bearing) -> Any:
    """Seed A Table 1 (the 6208's parameters) as printed beside the values
    the preset uses, with the note where they differ."""
    import polars as pl

    g = b.geometry
    d = g["ball_diameter_mm"]
    expansion = b.ring_material.to_dict()["thermal_expansion_per_k"]
    rows = [
        ("number of balls", 9.0, g["ball_count"], ""),
        ("ball diameter [mm]", 12.0, d, ""),
        ("bore diameter [mm]", 40.0, g["bore_mm"], ""),
        ("outside diameter [mm]", 80.0, g["outer_diameter_mm"], ""),
        ("inner groove radius [mm]", 6.24, g["inner_conformity"] * d, "f_i D"),
        ("outer groove radius [mm]", 6.36, g["outer_conformity"] * d, "f_o D"),
        (
            "linear expansion coefficient [1/K]",
            1.36e-7,
            expansion,
            "typo in the paper: bearing steel expands about 1.2e-5 1/K; the preset keeps "
            "52100's, the seed A bearing model takes 1.36e-5, the nearer reading",
        ),
        (
            "initial contact angle [deg]",
            14.8351,
            g["free_contact_angle_deg"],
            "computed: cos a0 = 1 - Pd / (2 (f_i + f_o - 1) D)",
        ),
        ("initial clearance [mm]", 0.04, g["diametral_clearance_mm"], "diametral"),
        ("pitch diameter [mm]", 60.0, g["pitch_diameter_mm"], ""),
    ]
    return pl.DataFrame(rows, schema=["parameter", "paper", "thermobear", "note"], orient="row")


def study_seed_a_bearing(out: Path, quick: bool = False) -> list[Path]:
    """Seed A's 6208 deep-groove bearing: ball loads at the 100 N m load
    case, stiffness against speed (constant vs speed-dependent)."""
    from .. import plot

    text = seed_config("seed_a_6208")
    cfg = read_toml(text)
    b = Bearing.from_toml(text)
    op = cfg["operating"]
    files: list[Path] = write_table(table1_bearing(b), out, "seed_a_table1_bearing")
    sol_static = b.solve(axial_n=op["axial_n"], radial_n=op["radial_n"], speed_rpm=0.0)
    sol_speed = b.solve(axial_n=op["axial_n"], radial_n=op["radial_n"], speed_rpm=op["speed_rpm"])
    import polars as pl

    balls = pl.concat(
        [
            sol_static.balls.with_columns(pl.lit(0.0).alias("speed_rpm")),
            sol_speed.balls.with_columns(pl.lit(float(op["speed_rpm"])).alias("speed_rpm")),
        ],
        how="diagonal",
    )
    files += write_table(balls, out, "seed_a_ball_loads")
    files.append(save_figure(plot.ball_loads(sol_speed), out, "seed_a_ball_loads"))
    speeds = sweep_speeds(cfg, quick)
    const = stiffness_curve(b, speeds, op["axial_n"], op["radial_n"], mode="constant")
    speed = stiffness_curve(b, speeds, op["axial_n"], op["radial_n"], mode="speed")
    both = _contact_summary([const, speed], ["constant", "speed"])
    files += write_table(both, out, "seed_a_stiffness_vs_speed")
    ax = plot.stiffness_cases(
        [const, speed], ["constant", "speed, no thermal"], column="radial_stiffness_seed_n_per_m"
    )
    ax.set_title("6208, Fa = 2680.9 N, Fr = 1189.9 N: radial stiffness")
    files.append(save_figure(ax, out, "seed_a_radial_stiffness"))
    ax = plot.stiffness_cases(
        [const, speed], ["constant", "speed, no thermal"], column="axial_stiffness_seed_n_per_m"
    )
    ax.set_title("6208: axial stiffness")
    files.append(save_figure(ax, out, "seed_a_axial_stiffness"))
    ax = plot.contact_angles(speed)
    ax.set_title("6208: contact angles vs speed")
    files.append(save_figure(ax, out, "seed_a_contact_angles"))
    return files
