"""``thermobear demo``: the seed studies, written as tables (parquet + CSV)
and figures (PNG) into an output folder.

Each study is a function ``study_*(out: Path, quick: bool) -> list[Path]``.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path
from typing import Any, Callable

import numpy as np

from .bearing import Bearing, stiffness_curve
from .config import load_config, seed_config


def _toml(text: str) -> dict:
    if sys.version_info >= (3, 11):
        import tomllib
    else:  # pragma: no cover
        import tomli as tomllib
    return tomllib.loads(text)


def write_table(df: Any, out: Path, stem: str) -> list[Path]:
    """Write a polars DataFrame as parquet and CSV."""
    out.mkdir(parents=True, exist_ok=True)
    pq, csv = out / f"{stem}.parquet", out / f"{stem}.csv"
    df.write_parquet(pq)
    df.write_csv(csv)
    return [pq, csv]


def save_figure(ax: Any, out: Path, stem: str) -> Path:
    import matplotlib.pyplot as plt

    out.mkdir(parents=True, exist_ok=True)
    fig = ax.figure
    fig.tight_layout()
    path = out / f"{stem}.png"
    fig.savefig(path, dpi=120)
    plt.close(fig)
    return path


def _speeds(cfg: dict, quick: bool) -> np.ndarray:
    sw = cfg.get("sweep", {})
    if "speeds_rpm" in sw:
        return np.asarray(sw["speeds_rpm"], dtype=float)
    n = int(sw.get("speed_count", 51))
    if quick:
        n = min(n, 11)
    return np.linspace(float(sw["speed_start_rpm"]), float(sw["speed_stop_rpm"]), n)


def _contact_summary(df_list: list, labels: list) -> Any:
    import polars as pl

    return pl.concat(
        [d.with_columns(pl.lit(lab).alias("case")) for d, lab in zip(df_list, labels)],
        how="diagonal",
    )


def study_seed_a_bearing(out: Path, quick: bool = False) -> list[Path]:
    """Seed A's 6208 deep-groove bearing: ball loads at the 100 N m load
    case, stiffness against speed (constant vs speed-dependent)."""
    from . import plot

    text = seed_config("seed_a_6208")
    cfg = _toml(text)
    b = Bearing.from_toml(text)
    op = cfg["operating"]
    files: list[Path] = []
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
    speeds = _speeds(cfg, quick)
    const = stiffness_curve(b, speeds, op["axial_n"], op["radial_n"], mode="constant")
    speed = stiffness_curve(b, speeds, op["axial_n"], op["radial_n"], mode="speed")
    both = _contact_summary([const, speed], ["constant", "speed"])
    files += write_table(both, out, "seed_a_stiffness_vs_speed")
    ax = plot.stiffness_cases(
        [const, speed], ["constant", "speed, no thermal"], column="radial_stiffness_n_per_m"
    )
    ax.set_title("6208, Fa = 2680.9 N, Fr = 1189.9 N: radial stiffness")
    files.append(save_figure(ax, out, "seed_a_radial_stiffness"))
    ax = plot.stiffness_cases(
        [const, speed], ["constant", "speed, no thermal"], column="axial_stiffness_n_per_m"
    )
    ax.set_title("6208: axial stiffness")
    files.append(save_figure(ax, out, "seed_a_axial_stiffness"))
    ax = plot.contact_angles(speed)
    ax.set_title("6208: contact angles vs speed")
    files.append(save_figure(ax, out, "seed_a_contact_angles"))
    return files


def study_seed_b_bearing(out: Path, quick: bool = False) -> list[Path]:
    """Seed B's front 7009C bearing (hybrid and steel) under preload:
    contact angles and stiffness against speed."""
    from . import plot

    text = seed_config("seed_b_7009c")
    cfg = _toml(text)
    speeds = _speeds(cfg, quick)
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
    ax = plot.stiffness_cases(frames[:3], labels[:3], column="radial_stiffness_n_per_m")
    ax.set_title("7009C hybrid: radial stiffness vs speed and preload")
    files.append(save_figure(ax, out, "seed_b_radial_stiffness"))
    ax = plot.contact_angles(frames[0])
    ax.set_title("7009C hybrid, 300 N: contact angles vs speed")
    files.append(save_figure(ax, out, "seed_b_contact_angles"))
    return files


# Each study: (name, "module:function") inside this package, imported when
# run (study modules import the table/figure helpers from here).
STUDIES: list[tuple[str, str]] = [
    ("seed_a_bearing", "demo:study_seed_a_bearing"),
    ("seed_b_bearing", "demo:study_seed_b_bearing"),
    ("seed_a_gear", "studies_seed_a_gear:study_seed_a_gear"),
    ("seed_b_vibration", "studies_seed_b_vibration:study_seed_b_vibration"),
    ("seed_b_spindle", "studies_seed_b:study_seed_b_spindle"),
    ("seed_a_thermal", "studies_seed_a:study_seed_a_thermal"),
    ("diagnose_synthetic", "studies_diagnose:study_diagnose"),
    ("diagnose_seed_b", "studies_diagnose_seed_b:study_diagnose_seed_b"),
]


def study_function(spec: str) -> Callable[[Path, bool], list[Path]]:
    """Resolve a ``"module:function"`` study reference."""
    import importlib

    module, func = spec.split(":")
    return getattr(importlib.import_module(f"thermobear.{module}"), func)


def run_demo(out: Path, quick: bool = False) -> Path:
    """Run every study into ``out`` and return it."""
    out.mkdir(parents=True, exist_ok=True)
    for name, spec in STUDIES:
        t0 = time.perf_counter()
        files = study_function(spec)(out / name, quick)
        print(f"  {name}: {len(files)} files in {time.perf_counter() - t0:.1f} s", flush=True)
    return out


def solve_config(path: Path, out: Path) -> Path:
    """Solve the operating point and the speed sweep of a system description."""
    text = load_config(path)
    cfg = _toml(text)
    b = Bearing.from_toml(text)
    op = cfg.get("operating", {})
    effects = cfg.get("model", {}).get("effects")
    control = cfg.get("model", {}).get("raceway_control", "outer")
    out.mkdir(parents=True, exist_ok=True)
    sol = b.solve(
        axial_n=op.get("axial_n", 0.0),
        radial_n=op.get("radial_n", 0.0),
        moment_nmm=op.get("moment_nmm", 0.0),
        speed_rpm=op.get("speed_rpm", 0.0),
        effects=effects,
        raceway_control=control,
    )
    write_table(sol.balls, out, "balls")
    np.savetxt(out / "stiffness_matrix_si.csv", sol.stiffness, delimiter=",")
    if "sweep" in cfg:
        df = stiffness_curve(
            b,
            _speeds(cfg, False),
            op.get("axial_n", 0.0),
            op.get("radial_n", 0.0),
            op.get("moment_nmm", 0.0),
            effects=effects,
            raceway_control=control,
        )
        write_table(df, out, "stiffness_vs_speed")
    return out
