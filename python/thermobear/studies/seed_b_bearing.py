"""Seed B's front 7009C bearing (hybrid and steel) under preload: contact
angles and stiffness against speed."""

from __future__ import annotations

from pathlib import Path

from ..bearing import Bearing
from ..config import read_toml, seed_config, sweep_speeds
from ..thermal import stiffness_curve
from .output import save_figure, write_table


def study_seed_b_bearing(out: Path, quick: bool = False) -> list[Path]:
    """Seed B's front 7009C bearing (hybrid and steel) under preload:
    contact angles and stiffness against speed."""
    from .. import plot

    text = seed_config("seed_b_7009c")
    cfg = read_toml(text)
    speeds = sweep_speeds(cfg, quick)
    files: list[Path] = []
    frames, labels = [], []
    for preset in ("7009C-hybrid", "7009C"):
        b = Bearing.preset(preset)
        for preload in (300.0, 400.0, 500.0):
            df = stiffness_curve(b, speeds, axial_n=preload)
            import polars as pl

            frames.append(
                df.with_columns(pl.lit(preset).alias("bearing"), pl.lit(preload).alias("preload_n"))
            )
            labels.append(f"{preset} {preload:.0f} N")
    import polars as pl

    table = pl.concat(frames, how="diagonal")
    files += write_table(table, out, "seed_b_7009c_vs_speed")
    ax = plot.stiffness_cases(frames[:3], labels[:3], column="radial_stiffness_seed_n_per_m")
    ax.set_title("7009C hybrid: radial stiffness vs speed and preload")
    files.append(save_figure(ax, out, "seed_b_radial_stiffness"))
    ax = plot.contact_angles(frames[0])
    ax.set_title("7009C hybrid, 300 N: contact angles vs speed")
    files.append(save_figure(ax, out, "seed_b_contact_angles"))
    return files
