"""``thermobear solve``: the operating point and the speed sweep of a system
description, written as tables."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..bearing import Bearing
from ..config import load_config, located_config_errors, read_toml, sweep_speeds
from ..studies.output import write_table
from ..thermal import stiffness_curve


def _moment_n_m(op: dict) -> float:
    """The [operating] tilting moment in N m (``moment_n_m``, or the
    ``moment_nmm`` of older descriptions converted)."""
    if "moment_n_m" in op:
        return float(op["moment_n_m"])
    if "moment_nmm" in op:
        from .._deprecation import warn_renamed

        warn_renamed("moment_nmm", "moment_n_m", what="[operating] key; value in N m, not N mm")
    return float(op.get("moment_nmm", 0.0)) / 1000.0


def solve_config(path: Path, out: Path) -> Path:
    """Solve the operating point and the speed sweep of a system
    description; a ``ConfigError`` names its file, line and key."""
    with located_config_errors(path):
        return _solve(path, out)


def _solve(path: Path, out: Path) -> Path:
    text = load_config(path)
    cfg = read_toml(text)
    b = Bearing.from_toml(text)
    op = cfg.get("operating", {})
    effects = cfg.get("model", {}).get("effects")
    control = cfg.get("model", {}).get("raceway_control", "outer")
    out.mkdir(parents=True, exist_ok=True)
    sol = b.solve(
        axial_n=op.get("axial_n", 0.0),
        radial_n=op.get("radial_n", 0.0),
        moment_n_m=_moment_n_m(op),
        speed_rpm=op.get("speed_rpm", 0.0),
        effects=effects,
        raceway_control=control,
    )
    write_table(sol.balls, out, "balls")
    np.savetxt(out / "stiffness_matrix_si.csv", sol.stiffness, delimiter=",")
    if "sweep" in cfg:
        df = stiffness_curve(
            b,
            sweep_speeds(cfg, False),
            op.get("axial_n", 0.0),
            op.get("radial_n", 0.0),
            _moment_n_m(op),
            effects=effects,
            raceway_control=control,
        )
        write_table(df, out, "stiffness_vs_speed")
    return out
