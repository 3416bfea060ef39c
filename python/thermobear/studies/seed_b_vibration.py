"""Seed B's spindle vibration study: Campbell diagram, vibration velocity
against speed (uncoupled, and thermally coupled through the raceway offsets
of [`thermobear.Spindle`][thermobear.Spindle]'s coupled steady state), the 12,000 rpm
spectrum, and the paper-vs-thermobear table.

The rotor's dimensions are the documented assumptions of
``src/rotor/presets.rs``; the thermal state is the fitted spindle's
(``reproduce_seed_b``); the unbalance is the one pinned by seed B's
simulated 1X amplitude, 7.53 mm/s at 12,000 rpm (``unbalance_g_mm`` of the
fitted model), far above any balance grade of a finished spindle.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from .. import rotor

if TYPE_CHECKING:
    import polars

__all__ = ["study_seed_b_vibration"]


def _paper_table(ours: dict) -> polars.DataFrame:
    import polars as pl

    rows = [
        (
            "velocity_18000rpm_coupled_sim_mm_s",
            18.78,
            ours["v18_coupled"],
            "ours: thermally coupled spindle (tb.Spindle offsets), fitted unbalance, RMS",
        ),
        (
            "coupling_raises_velocity_18000rpm_pct",
            100.0 * (18.78 - (18.92 - 2.82)) / (18.92 - 2.82),
            100.0 * (ours["v18_coupled"] / ours["v18_uncoupled"] - 1.0),
            "paper: uncoupled = measured - 2.82 mm/s max error; ours: coupled vs uncoupled",
        ),
        (
            "velocity_18000rpm_measured_mm_s",
            18.92,
            ours["v18_uncoupled"],
            "ours: uncoupled, fitted unbalance, RMS",
        ),
        (
            "uncoupled_mean_error_pct",
            11.1,
            np.nan,
            "not reproducible: no measured curve in the seed",
        ),
        ("coupled_mean_error_pct", 2.8, np.nan, "not reproducible: no measured curve in the seed"),
        ("spectrum_1x_frequency_hz", 196.6, ours["f1"], "196.6 Hz = 11,796 rpm, not 12,000"),
        (
            "spectrum_1x_velocity_mm_s",
            7.53,
            ours["x1"],
            "12,000 rpm, nonlinear balls; the unbalance is pinned by this number",
        ),
        ("spectrum_2x_frequency_hz", 393.2, 2 * ours["f1"], ""),
        ("spectrum_2x_velocity_mm_s", 0.398, ours["x2"], ""),
        (
            "spectrum_3x_frequency_hz",
            596.48,
            3 * ours["f1"],
            "paper's 3X is not 3 x 196.6 = 589.8 Hz",
        ),
        ("spectrum_3x_velocity_mm_s", 0.708, ours["x3"], ""),
        (
            "measured_1x_frequency_above_simulation_pct",
            3.3,
            0.0,
            "ours: 1X is the shaft speed by construction; the rig ran about 3 % faster",
        ),
        (
            "magnetic_pull_raises_1x_pct",
            np.nan,
            100.0 * (ours["x1_ump"] / ours["x1"] - 1.0),
            "Fig. 20b: measured 1X above the simulated; ours: unbalanced magnetic pull on",
        ),
        ("first_forward_critical_rpm", np.nan, ours["critical"], "not given in the seed"),
    ]
    return pl.DataFrame(
        {
            "quantity": [r[0] for r in rows],
            # "not given" / "not computed" is a null, never a NaN
            "paper": [None if np.isnan(r[1]) else float(r[1]) for r in rows],
            "thermobear": [None if np.isnan(r[2]) else float(r[2]) for r in rows],
            "note": [r[3] for r in rows],
        }
    )


def _spectrum_figure(
    name: str, spec: polars.DataFrame, duration_s: float, out: Path, unbalance_g_mm: float
) -> tuple:
    """Fig. 20: (a) the 12,000 rpm spectrum under the unbalance alone; (b)
    the counterpart of seed B's measured spectrum, which is not given as
    numbers: seed B attributes its excess at 1X and the scatter near 2X to
    the unbalanced magnetic pull of an eccentric rotor, so (b) is the same
    run with that pull on (``unbalanced_magnetic_pull``, the preset's
    assumed 30 µm static eccentricity)."""
    from .. import plot
    from .output import save_figure, write_table
    from .seed_b_figures import panels

    ump = ["unbalanced_magnetic_pull"]
    u = float(unbalance_g_mm)
    spec_b = rotor.spectrum(
        name, 12_000.0, duration_s, coupled=False, effects=ump, unbalance_g_mm=u
    )
    orders = rotor.spectrum_orders(
        name, 12_000.0, duration_s, coupled=False, effects=ump, unbalance_g_mm=u
    )
    files = write_table(spec_b, out, "seed_b_spectrum_12000rpm_magnetic_pull")
    files += write_table(orders, out, "seed_b_spectrum_orders_12000rpm_magnetic_pull")
    ax_a, ax_b = panels(2)
    plot.spectrum(spec, speed_rpm=12_000.0, max_frequency_hz=1_000.0, ax=ax_a)
    plot.spectrum(spec_b, speed_rpm=12_000.0, max_frequency_hz=1_000.0, ax=ax_b)
    ax_a.set_title(f"(a) unbalance {unbalance_g_mm:.0f} g mm", fontsize=10)
    ax_b.set_title("(b) with the unbalanced magnetic pull", fontsize=10)
    ax_a.figure.suptitle("Seed B Fig. 20: nose velocity spectrum at 12,000 rpm")
    files.append(save_figure(ax_a, out, "seed_b_fig20_spectrum_12000rpm"))
    return files, orders


def fitted_unbalance_g_mm() -> float:
    """The rotor unbalance pinned by seed B's 1X amplitude (7.53 mm/s at
    12,000 rpm) in the fitted model (``reproduce_seed_b``) [g mm]."""
    from .reproduce_seed_b import fitted_spindle

    return float(fitted_spindle().spec.options["unbalance_g_mm"])


ASSUMPTIONS = """\
Assumptions that differ from seed B (its spindle tables are missing):
- Spindle geometry, rotor core and tool holder: src/rotor/presets.rs (every dimension assumed).
- Rows: 7009C/7008C presets (hybrid = Si3N4 balls), back-to-back pairs, 400 N constant-force
  preload, quasi-static ball model linearised at each speed (no bearing damping; 2 % modal
  damping of the rotor-bearing modes).
- Excitation: an unbalance at the rotor core, pinned by seed B's simulated 1X amplitude (7.53 mm/s
  at 12,000 rpm; reproduce_seed_b): some 600 times the ISO 21940 G2.5 a finished spindle is balanced
  to, so seed B's excitation is not a residual unbalance; below the first critical speed the
  response grows as n^3, which takes the 7.53 mm/s 1X amplitude to about 18 mm/s RMS at 18,000
  rpm, seed B's Fig. 21 level.
- Coupled case: the raceway offsets of the coupled thermal steady state of the fitted spindle
  (spring preload 400 N) at each speed, applied to the rotor's rows, which keep a constant 400 N
  preload (the spring's compensation is not passed) and the preset's ball size.
- Seed B's 1X of 196.6 Hz corresponds to 11,796 rpm; we run at exactly 12,000 rpm (200 Hz).
"""


def study_seed_b_vibration(out: Path, quick: bool = False) -> list[Path]:
    """Campbell diagram, vibration vs speed, 12,000 rpm spectrum and the
    paper-vs-thermobear table of seed B's ceramic spindle."""
    import polars as pl

    from .. import plot
    from .output import save_figure, write_table

    files: list[Path] = []
    name = "seed-ceramic-spindle"
    n_campbell = 7 if quick else 31
    camp = rotor.campbell(name, np.linspace(0.0, 30_000.0, n_campbell), modes=6)
    files += write_table(camp, out, "seed_b_campbell")
    ax = plot.campbell(camp)
    ax.set_title("Seed B ceramic spindle: Campbell diagram (solver rows, 400 N)")
    files.append(save_figure(ax, out, "seed_b_campbell"))
    crit = rotor.critical_speeds(name, np.linspace(0.0, 120_000.0, 25 if quick else 121), modes=2)
    files += write_table(crit, out, "seed_b_critical_speeds")

    from .reproduce_seed_b import fitted_spindle

    u = fitted_unbalance_g_mm()
    speeds = np.linspace(6_000.0, 18_000.0, 3 if quick else 13)
    frames, labels = [], []
    for variant in ("ceramic", "steel"):
        preset = f"seed-{variant}-spindle"
        unc = rotor.vibration(preset, speeds, coupled=False, unbalance_g_mm=u)
        sp = fitted_spindle(variant).model()[0]  # the fitted thermal state's offsets
        cpl = rotor.vibration(sp, speeds, coupled=True, unbalance_g_mm=u)
        frames += [unc, cpl]
        labels += [f"{preset}: uncoupled", f"{preset}: thermally coupled"]
    table = pl.concat(
        [f.with_columns(pl.lit(lab).alias("case")) for f, lab in zip(frames, labels, strict=False)],
        how="diagonal",
    )
    files += write_table(table, out, "seed_b_vibration_vs_speed")
    ax = plot.vibration(frames, labels)
    ax.set_title("Seed B Fig. 21: shaft-end vibration velocity (RMS), fitted unbalance")
    files.append(save_figure(ax, out, "seed_b_fig21_vibration_vs_speed"))

    duration = 0.05 if quick else 0.25
    spec = rotor.spectrum(name, 12_000.0, duration, coupled=False, unbalance_g_mm=u)
    orders = rotor.spectrum_orders(name, 12_000.0, duration, coupled=False, unbalance_g_mm=u)
    files += write_table(spec, out, "seed_b_spectrum_12000rpm")
    files += write_table(orders, out, "seed_b_spectrum_orders_12000rpm")
    f, orders_ump = _spectrum_figure(name, spec, duration, out, u)
    files += f

    def at18(df: polars.DataFrame) -> float:
        return float(df.filter(pl.col("speed_rpm") == 18_000.0)["velocity_rms_mm_s"][0])

    fwd = crit.filter(pl.col("whirl") == "forward")
    ours = {
        "v18_uncoupled": at18(frames[0]),
        "v18_coupled": at18(frames[1]),
        "f1": 200.0,
        "x1": float(orders["velocity_mm_s"][0]),
        "x2": float(orders["velocity_mm_s"][1]),
        "x3": float(orders["velocity_mm_s"][2]),
        "critical": float(fwd["speed_rpm"][0]) if fwd.height else np.nan,
        "x1_ump": float(orders_ump["velocity_mm_s"][0]),
        "x2_ump": float(orders_ump["velocity_mm_s"][1]),
    }
    files += write_table(_paper_table(ours), out, "paper_vs_thermobear_seed_b_vibration")
    out.mkdir(parents=True, exist_ok=True)
    note = out / "paper_vs_thermobear_seed_b_vibration_assumptions.txt"
    note.write_text(
        ASSUMPTIONS + f"\nThe fitted {u:.0f} g mm give {ours['v18_uncoupled']:.4g} mm/s RMS "
        f"at 18,000 rpm uncoupled and {ours['v18_coupled']:.4g} mm/s coupled (ceramic), against "
        "the measured 18.92 mm/s.\n"
    )
    files.append(note)
    return files
