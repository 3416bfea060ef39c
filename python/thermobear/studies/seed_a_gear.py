"""Seed A section 3 (Figs. 14-15): bifurcation diagrams of the helical gear
pair for three bearing-stiffness cases, accelerating and decelerating, the
regimes beside the paper's reported ranges, and a torque x speed x TE regime
map ("where is my drive safe?").

Seed A gives no backlash, damping, TE or mesh stiffness; the mesh stiffness
here is computed (potential-energy method) and the rest are the documented
defaults (table ``gear_defaults``). The structure is compared, not the
digits; nothing is tuned to match.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Optional

import numpy as np

from .. import gear as tbg
from .. import plot
from .output import save_figure, write_table

#: Speed range of seed A's sweeps [rpm].
SPEED_RANGE_RPM = (6500.0, 16500.0)
#: A light, strongly excited operating point where the teeth separate
#: (fixed before looking at any result; not tuned): 20 N m, TE 10 um.
LIGHT_TORQUE_NM = 20.0
LIGHT_TE_UM = 10.0

#: What seed A reports (section 3.3, Figs. 14-15). Point values are given as
#: from = to. The text's "chaotic motion in 14,950-16,040 ... and it proceeds
#: into a chaotic motion during other speed ranges" is ambiguous (the
#: decelerating paragraph calls the matching windows periodic); quoted as printed.
PAPER_ROWS = [
    ("constant", "up", "periodic window", 9644, 9644),
    ("speed", "up", "periodic window", 9933, 10140),
    ("thermal", "up", "periodic window", 10040, 10440),
    ("constant", "up", "jump (step)", 6978, 6978),
    ("speed", "up", "jump (step)", 10140, 10140),
    ("thermal", "up", "jump (step)", 10440, 10440),
    ("constant", "up", "chaotic", 11750, 12460),
    ("constant", "up", "period-2", 12840, 12840),
    ("speed", "up", "period-2", 11550, 11550),
    ("thermal", "up", "period-2", 12960, 12960),
    ("constant", "up", "chaotic (as printed)", 14950, 16040),
    ("speed", "up", "chaotic (as printed)", 12960, 13270),
    ("speed", "up", "chaotic (as printed)", 15690, 15990),
    ("thermal", "up", "chaotic (as printed)", 14380, 14580),
    ("thermal", "up", "chaotic (as printed)", 16100, 16500),
    ("constant", "down", "jump (spike)", 6978, 6978),
    ("speed", "down", "jump (spike)", 6702, 6702),
    ("thermal", "down", "jump (spike)", 6600, 6600),
    ("constant", "down", "period-2", 12840, 12840),
    ("speed", "down", "period-2", 11550, 11550),
    ("thermal", "down", "period-2", 12960, 12960),
    ("constant", "down", "periodic window", 14270, 14620),
    ("constant", "down", "periodic window", 14990, 15690),
    ("speed", "down", "periodic window", 12960, 13270),
    ("speed", "down", "periodic window", 15580, 15880),
    ("thermal", "down", "periodic window", 14380, 14590),
]


def _systems(g: tbg.GearPair, **kw: Any) -> tuple[dict, list]:
    """The three stiffness cases; "thermal" only if the bearing module
    offers ``stiffness_curve(mode="thermal")`` (reported otherwise)."""
    from ..errors import ConfigError

    systems, notes = {}, []
    for case in ("constant", "speed", "thermal"):
        try:
            systems[case] = tbg.GearSystem(g, stiffness=case, **kw)
        except ConfigError as e:
            notes.append((case, str(e)))
    return systems, notes


def _ours(per_speed: Any, case: str, direction: str, lo: float, hi: float, step: float) -> str:
    import polars as pl

    sub = per_speed.filter(
        (pl.col("case") == case)
        & (pl.col("direction") == direction)
        & (pl.col("speed_rpm") >= lo - 0.5 * step)
        & (pl.col("speed_rpm") <= hi + 0.5 * step)
    )
    if sub.height == 0:
        return "not computed"
    parts = []
    for r, imp in sub.select("regime", "impact").unique(maintain_order=True).rows():
        parts.append(f"{r} ({imp})")
    jumps = sub.filter(pl.col("jump_after"))["speed_rpm"].to_list()
    text = ", ".join(parts)
    if jumps:
        text += "; jump after " + ", ".join(f"{s:.0f}" for s in jumps) + " rpm"
    return text


def _comparison(per_seed: Any, per_light: Any, step: float) -> Any:
    import polars as pl

    rows = []
    for case, d, feature, lo, hi in PAPER_ROWS:
        rows.append(
            {
                "case": case,
                "direction": d,
                "paper_feature": feature,
                "paper_from_rpm": float(lo),
                "paper_to_rpm": float(hi),
                "ours_seed_100nm": _ours(per_seed, case, d, lo, hi, step),
                f"ours_light_{LIGHT_TORQUE_NM:.0f}nm_te{LIGHT_TE_UM:.0f}um": _ours(
                    per_light, case, d, lo, hi, step
                ),
            }
        )
    return pl.DataFrame(rows)


def _per_speed(pts: Any) -> Any:
    return pts.drop("dte_um").unique(subset=["case", "direction", "speed_rpm"], maintain_order=True)


def _hysteresis(per_speed: Any, torque_n_m: float) -> Any:
    """Speed ranges where the accelerating and decelerating sweeps end on
    different motions (regime or impact differ, or the peak-to-peak
    dynamic TE differs by more than 20 %): coexisting solutions."""
    import polars as pl

    rows = []
    for (case,), g in per_speed.group_by(["case"], maintain_order=True):
        cols = ["speed_rpm", "regime", "impact", "dte_min_um", "dte_max_um"]
        up = g.filter(pl.col("direction") == "up").select(cols)
        down = g.filter(pl.col("direction") == "down").select(cols)
        j = up.join(down, on="speed_rpm", suffix="_down").sort("speed_rpm")
        pp_up = (j["dte_max_um"] - j["dte_min_um"]).to_numpy()
        pp_dn = (j["dte_max_um_down"] - j["dte_min_um_down"]).to_numpy()
        amp = abs(pp_up - pp_dn) > 0.2 * np.maximum(np.maximum(pp_up, pp_dn), 1e-9)
        differ = (
            (j["regime"] != j["regime_down"]).to_numpy()
            | (j["impact"] != j["impact_down"]).to_numpy()
            | amp
        )
        s = j["speed_rpm"].to_numpy()
        i = 0
        while i < len(s):
            if not differ[i]:
                i += 1
                continue
            k = i
            while k + 1 < len(s) and differ[k + 1]:
                k += 1
            rows.append(
                {
                    "torque_n_m": torque_n_m,
                    "case": case,
                    "speed_from_rpm": float(s[i]),
                    "speed_to_rpm": float(s[k]),
                    "speeds": k - i + 1,
                    "up_regimes": ", ".join(sorted(set(j["regime"][i : k + 1].to_list()))),
                    "down_regimes": ", ".join(sorted(set(j["regime_down"][i : k + 1].to_list()))),
                }
            )
            i = k + 1
    schema = {
        "torque_n_m": pl.Float64,
        "case": pl.Utf8,
        "speed_from_rpm": pl.Float64,
        "speed_to_rpm": pl.Float64,
        "speeds": pl.Int64,
        "up_regimes": pl.Utf8,
        "down_regimes": pl.Utf8,
    }
    return pl.DataFrame(rows, schema=schema)


def _diagrams(pts: Any, out: Path, stem: str, title: str) -> list[Path]:
    files = []
    for (case, d), sub in pts.group_by(["case", "direction"], maintain_order=True):
        ax = plot.bifurcation(sub)
        word = "accelerating" if d == "up" else "decelerating"
        ax.set_title(f"{title}: {case} bearing stiffness, {word}")
        files.append(save_figure(ax, out, f"{stem}_{case}_{d}"))
    return files


def study_seed_a_gear(out: Path, quick: bool = False, progress: Optional[Any] = None) -> list[Path]:
    """Seed A's six bifurcation diagrams, regime tables and a regime map."""
    g = tbg.GearPair.preset("seed-electric-drive")
    n_speeds = 41 if quick else 1001
    transient, record = (300, 50) if quick else (300, 100)
    speeds = np.linspace(*SPEED_RANGE_RPM, n_speeds)
    step = float(speeds[1] - speeds[0])
    files = _gear_data(g, out)
    f, seed, light = _support_stiffness(g, out)
    files += f
    f, pts, pts_l = _bifurcations(seed, light, speeds, (transient, record), progress, out)
    files += f
    files += _regime_tables(pts, pts_l, step, out)
    files += _regime_map(seed, quick, (transient, record), progress, out)
    return files


def _gear_data(g: Any, out: Path) -> list[Path]:
    """Gear data: geometry, ISO and potential-energy mesh stiffness, the
    printed table's typos, the defaults."""
    import polars as pl

    files: list[Path] = []
    geo = g.geometry
    geo.update({f"iso_{k}": v for k, v in g.iso_stiffness.items()})
    ms = g.mesh_stiffness(64)
    geo["pe_transverse_mean_n_per_m"] = float(ms["transverse_stiffness_n_per_m"].mean())
    geo["pe_normal_mean_n_per_m"] = float(ms["normal_stiffness_n_per_m"].mean())
    geo["pe_normal_peak_to_peak_n_per_m"] = float(
        ms["normal_stiffness_n_per_m"].max() - ms["normal_stiffness_n_per_m"].min()
    )
    files += write_table(
        pl.DataFrame({"quantity": list(geo), "value": [float(v) for v in geo.values()]}),
        out,
        "gear_pair",
    )
    files += write_table(ms, out, "mesh_stiffness")
    files += write_table(g.typo_warnings, out, "gear_table_typos")
    files += write_table(tbg.gear_defaults(), out, "gear_defaults")
    return files


def _support_stiffness(g: Any, out: Path) -> tuple:
    """The systems at the seed operating point and a light one; the bearing
    support stiffness schedules (and the cases that could not be built)."""
    import polars as pl

    files: list[Path] = []
    seed, notes = _systems(g)
    light, _ = _systems(g, torque_n_m=LIGHT_TORQUE_NM, te_amplitude_um=LIGHT_TE_UM)
    sched = pl.concat(
        [s.stiffness_schedule.with_columns(pl.lit(c).alias("case")) for c, s in seed.items()]
    )
    files += write_table(sched, out, "bearing_support_stiffness")
    if notes:
        files += write_table(
            pl.DataFrame({"case": [n[0] for n in notes], "note": [n[1] for n in notes]}),
            out,
            "missing_cases",
        )
    return files, seed, light


def _bifurcations(
    seed: dict, light: dict, speeds: Any, periods: tuple, progress: Any, out: Path
) -> tuple:
    """Bifurcation diagrams, sweeping up and down: seed operating point and a light one."""
    transient, record = periods
    files: list[Path] = []
    pts = tbg.bifurcation_set(
        seed, speeds, ("up", "down"), transient, record, 64, progress=progress
    )
    files += write_table(pts, out, "poincare_seed_100nm")
    files += _diagrams(pts, out, "bifurcation_seed_100nm", "seed A, 100 N m")
    pts_l = tbg.bifurcation_set(
        light, speeds, ("up", "down"), transient, record, 64, progress=progress
    )
    files += write_table(pts_l, out, "poincare_light")
    files += _diagrams(
        pts_l, out, "bifurcation_light", f"{LIGHT_TORQUE_NM:.0f} N m, TE {LIGHT_TE_UM:.0f} um"
    )
    return files, pts, pts_l


def _regime_tables(pts: Any, pts_l: Any, step: float, out: Path) -> list[Path]:
    """Regime tables, the comparison with the paper and the hysteresis."""
    import polars as pl

    files: list[Path] = []
    reg = pl.concat(
        [
            tbg.regimes(pts).with_columns(pl.lit(100.0).alias("torque_n_m")),
            tbg.regimes(pts_l).with_columns(pl.lit(LIGHT_TORQUE_NM).alias("torque_n_m")),
        ]
    )
    files += write_table(reg, out, "regimes")
    per_seed, per_light = _per_speed(pts), _per_speed(pts_l)
    files += write_table(_comparison(per_seed, per_light, step), out, "regimes_vs_paper")
    hyst = pl.concat([_hysteresis(per_seed, 100.0), _hysteresis(per_light, LIGHT_TORQUE_NM)])
    files += write_table(hyst, out, "hysteresis")
    return files


def _regime_map(seed: dict, quick: bool, periods: tuple, progress: Any, out: Path) -> list[Path]:
    """Regime map: torque x speed x TE amplitude (constant bearing stiffness),
    one figure per TE amplitude, and its summary."""
    import polars as pl

    transient, record = periods
    files: list[Path] = []
    if quick:
        torques, scales, map_speeds = (
            [10.0, 30.0, 100.0],
            [1.0, 5.0],
            np.linspace(*SPEED_RANGE_RPM, 11),
        )
    else:
        torques = [5.0, 10.0, 20.0, 30.0, 50.0, 75.0, 100.0, 150.0]
        scales = [1.0, 2.5, 5.0]
        map_speeds = np.linspace(*SPEED_RANGE_RPM, 81)
    rmap = tbg.regime_map(
        seed["constant"], torques, map_speeds, te_scales=scales,
        transient_periods=transient, record_periods=record, progress=progress,
    )  # fmt: skip
    files += write_table(rmap, out, "regime_map")
    for te, sub in rmap.group_by(["te_amplitude_um"], maintain_order=True):
        ax = plot.regime_map(sub)
        ax.set_title(f"motion regime, TE {te[0]:.1f} um (constant bearing stiffness)")
        files.append(save_figure(ax, out, f"regime_map_te{te[0]:.0f}um"))
    safe = (
        rmap.group_by("torque_n_m", "te_amplitude_um")
        .agg(
            (pl.col("regime") == "period-1").mean().alias("period_1_fraction"),
            (pl.col("impact") == "no-impact").mean().alias("no_impact_fraction"),
            pl.col("speed_rpm")
            .filter(pl.col("regime") == "chaotic")
            .min()
            .alias("first_chaos_rpm"),
        )
        .sort("te_amplitude_um", "torque_n_m")
    )
    files += write_table(safe, out, "regime_map_summary")
    return files
