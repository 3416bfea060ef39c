"""``thermobear demo`` study: the discrepancy workflow on seed B's own
reported measurements (configs/seed_b_measurements.csv: front/rear outer
ring 33.7/30.1 C at 12,000 rpm, shaft-end vibration 18.92 mm/s at
18,000 rpm), starting from the spindle model WITHOUT thermal displacement
(the five thermal-expansion effects off), as the paper's uncoupled model.

The temperatures are the maxima over 20 min of running; they are compared
with our steady state (an assumption: the paper's text does not say whether
Fig. 19a has levelled off by then). Nothing is tuned to the paper: the
diagnosis reports what the three numbers support. Our rotor carries an
ISO 21940 G2.5 residual unbalance; its
shaft-end velocity at 18,000 rpm is some 0.02-0.03 mm/s, hundreds of times
below the measured 18.92 mm/s (the paper's uncoupled simulation gives
16.10 mm/s, its coupled one 18.78 mm/s: its excitation is not stated and
evidently far larger than G2.5). No candidate in the registry can close
that gap (the sensor-offset decoy is bounded to 20 %), and the verdict says
so. Tables: measured points, model with and without thermal displacement
at those points next to the paper's simulations, residual audit,
screening, gap before/after, verdict; figures: measured vs model per
quantity, residual/sigma, and the two models' outer-ring temperatures and
vibration against speed (coarse speeds in quick mode).

Then the same story with the effect hidden on purpose
(``synthetic_seed_b``): data from our model with thermal displacement,
diagnosed from the model without it, with its before/after gap.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..diagnosis import diagnose
from ..diagnosis.spindle_spec import (
    THERMAL_DISPLACEMENT_EFFECTS,
    SpindleModelSpec,
    seed_b_measurements,
)
from ..spindle import Spindle
from .output import save_figure, write_table
from .seed_b_spindle import SUPPLY

#: Seed B's simulated values quoted beside the measurements ("Experimental
#: results and analysis"): coupled vibration 18.78 mm/s at 18,000 r/min;
#: uncoupled: the maximum error 2.82 mm/s there, so 18.92 - 2.82 = 16.10;
#: front/rear outer-ring simulation 2.7 % / 1.3 % below 33.7 / 30.1 C.
PAPER_SIMULATION = {
    "front_outer_ring_temperature_c": (33.7 / 1.027, 33.7 / 1.027),
    "rear_outer_ring_temperature_c": (30.1 / 1.013, 30.1 / 1.013),
    "velocity_rms_mm_s": (18.92 - 2.82, 18.78),
}


#: Left out of seed B's baseline besides the thermal expansions: the paper's
#: models have no magnetic pull (its text blames the pull for the hotter
#: front bearing afterwards), so the pull is a candidate, not a given.
SEED_B_LEFT_OUT = ("unbalanced_magnetic_pull",)


def baseline_without_thermal_displacement(spindle: Spindle) -> SpindleModelSpec:
    """The spindle model with every effect except the thermal expansions
    and the magnetic pull (seed B's uncoupled model)."""
    full = SpindleModelSpec(spindle)
    left_out = set(THERMAL_DISPLACEMENT_EFFECTS) | set(SEED_B_LEFT_OUT)
    return SpindleModelSpec(spindle, effects=[e for e in full.effects if e not in left_out])


def study_diagnose_seed_b(out: Path, quick: bool) -> list[Path]:
    import polars as pl

    from .. import plot

    # seed B's stated lubrication (oil-air, 5 mL/h): the ball drag follows it
    spindle = Spindle.preset("seed-ceramic-spindle").with_options(**SUPPLY)
    base = baseline_without_thermal_displacement(spindle)
    coupled = base.with_setting(["thermal_displacement"])
    measured = seed_b_measurements()
    # two distinct speeds only: no held-out speed band is possible; the gap
    # table is over all three points
    d = diagnose(base, measured, holdout=None)

    q = measured["quantity"].to_list()
    p0, p1 = base.predict(measured), coupled.predict(measured)
    y = measured["value"].to_numpy()
    ours0 = np.array([p0[qq][i] for i, qq in enumerate(q)])
    ours1 = np.array([p1[qq][i] for i, qq in enumerate(q)])
    compare = measured.select(["speed_rpm", "quantity", "value", "sigma"]).with_columns(
        pl.Series("ours_without_thermal_displacement", ours0),
        pl.Series("ours_with_thermal_displacement", ours1),
        pl.Series("paper_uncoupled", [PAPER_SIMULATION[qq][0] for qq in q]),
        pl.Series("paper_coupled", [PAPER_SIMULATION[qq][1] for qq in q]),
        pl.Series("measured_over_ours_without", y / ours0),
    )
    files = write_table(measured, out, "diagnose_seed_b_measured")
    files += write_table(compare, out, "diagnose_seed_b_models")
    files += write_table(d.audit, out, "diagnose_seed_b_audit")
    files += write_table(pl.concat(d.screening, how="diagonal"), out, "diagnose_seed_b_screening")
    files += write_table(d.gap, out, "diagnose_seed_b_gap")

    vib = [i for i, qq in enumerate(q) if qq == "velocity_rms_mm_s"][0]
    text = [
        "Seed B's measurements diagnosed from the spindle model without thermal displacement.",
        d.summary(),
        "",
        "In plain words: "
        + plain_reading(d, y[vib], ours0[vib], ours1[vib], PAPER_SIMULATION["velocity_rms_mm_s"]),
    ]
    verdict = out / "diagnose_seed_b_verdict.txt"
    verdict.write_text("\n".join(text) + "\n")
    files.append(verdict)

    for i, qq in enumerate(sorted(set(q))):
        files.append(save_figure(plot.diagnosis_fit(d, qq), out, f"diagnose_seed_b_fit_{i}"))
    files.append(save_figure(plot.diagnosis_residuals(d), out, "diagnose_seed_b_residuals"))
    files += _curves(base, coupled, measured, out, quick)
    files += synthetic_seed_b(base, out, quick)
    return files


#: Quantities of the synthetic seed B case: the paper's (outer-ring
#: temperatures, shaft-end vibration) plus the axial growth, the measurement
#: the look-alike check suggests for separating thermal displacement from a
#: vibrometer gain error.
SYNTHETIC_QUANTITIES = (
    "front_outer_ring_temperature_c",
    "rear_outer_ring_temperature_c",
    "velocity_rms_mm_s",
    "axial_growth_um",
)


def synthetic_seed_b(base: SpindleModelSpec, out: Path, quick: bool) -> list[Path]:
    """Seed B's story with the effect hidden on purpose: "measurements" made
    by our model WITH thermal displacement at seed B's test speeds and
    preload (typical noise: 0.5 K, 5 % vibration, 0.5 µm), diagnosed from
    the model without it. Writes the verdict and the gap before/after."""
    import polars as pl

    from .. import plot
    from ..diagnosis import synthetic_measurements

    truth = base.with_setting(["thermal_displacement"])
    speeds = np.arange(6000.0, 18001.0, 3000.0 if quick else 1000.0)
    qs = list(SYNTHETIC_QUANTITIES)
    cond = pl.DataFrame(
        {
            "speed_rpm": np.repeat(speeds, len(qs)),
            "preload_n": 400.0,
            "radial_n": 0.0,
            "quantity": qs * len(speeds),
        }
    )
    # typical noise (SPINDLE_QUANTITIES), a fixed seed
    measured = synthetic_measurements(truth, cond, 1.0, seed=20261122)
    d = diagnose(base, measured)
    files = write_table(measured, out, "diagnose_seed_b_synthetic_measured")
    files += write_table(d.gap, out, "diagnose_seed_b_synthetic_gap")
    files += write_table(
        pl.concat(d.screening, how="diagonal"), out, "diagnose_seed_b_synthetic_screening"
    )
    text = out / "diagnose_seed_b_synthetic_verdict.txt"
    text.write_text(
        "hidden: thermal displacement (the five thermal-expansion effects), diagnosed from the "
        "spindle model without it\n" + d.summary() + "\n"
    )
    files.append(text)
    files.append(
        save_figure(plot.diagnosis_fit(d, "axial_growth_um"), out, "diagnose_seed_b_synthetic_fit")
    )
    files.append(
        save_figure(plot.diagnosis_residuals(d), out, "diagnose_seed_b_synthetic_residuals")
    )
    return files


def plain_reading(d, measured_mm_s, ours_mm_s, ours_coupled_mm_s, paper) -> str:
    """One honest paragraph on the verdict and the vibration gap."""
    ratio = measured_mm_s / ours_mm_s
    s = (
        f"the measured vibration {measured_mm_s:.2f} mm/s at 18,000 rpm is {ratio:.0f} times "
        f"our model's {ours_mm_s:.4f} mm/s without thermal displacement "
        f"({ours_coupled_mm_s:.4f} mm/s with it; the paper's models give {paper[0]:.2f} and "
        f"{paper[1]:.2f}). Our rotor is excited by a G2.5 residual unbalance only and its "
        "steady response is linear in the unbalance: matching 18.92 mm/s would take grade "
        f"G{2.5 * ratio:.0f}, far outside the G0.4-G6.3 bounds of the unbalance candidate "
        "(which ends at its upper bound without support). No physical effect of the model "
        "comes near a factor of that size. "
    )
    s += _runout_reading(d)
    if d.accepted:
        names = ", ".join(a["name"] for a in d.accepted)
        s += (
            f"The workflow accepts {names}; with one temperature point per sensor a constant "
            "sensor offset and a real local heat source at the front bearing cannot be told "
            "apart from these data. "
        )
    ump = d.screening[0].filter(d.screening[0]["candidate"] == "unbalanced_magnetic_pull")
    if ump.height:
        s += (
            "The paper blames the unbalanced magnetic pull for the hotter front bearing; in our "
            "model the pull (static eccentricity 10 % of the air gap) loads both bearing sets "
            "alike (the rotor core sits mid-span) and warms the front outer ring by hundredths "
            f"of a kelvin: switched on alone it moves delta-BIC by {ump['delta_bic'][0]:+.2f}, "
            "so these data do not support it. "
        )
    elif d.tie:
        s += "The temperature points do not single out one candidate (tie). "
    td = d.screening[0].filter(d.screening[0]["candidate"] == "thermal_displacement")
    if any(a["name"] == "thermal_displacement" for a in d.accepted):
        s += "Thermal displacement is accepted, as the paper concludes."
    elif td.height:
        s += (
            "Thermal displacement is NOT supported by these three numbers, unlike the paper's "
            f"conclusion: switched on alone it moves delta-BIC by {td['delta_bic'][0]:+.2f}; in "
            "our model it changes the predictions far less than the measurement gap."
        )
    return s


def _runout_reading(d) -> str:
    """The vibration gap against the runout candidate (a measurement-side
    reading of the non-contact probe)."""
    run = [a for a in d.accepted if a["name"] == "runout_um"]
    if not run:
        return "The vibration residual stays unexplained. "
    a = run[0]
    return (
        f"It is what a shaft runout of {a['value']:.1f} µm (95 % [{a['lower_95']:.1f}, "
        f"{a['upper_95']:.1f}]) reads on a non-contact vibrometer at 18,000 rpm "
        "(1X velocity omega x runout): the measured number is explained on the measurement "
        "side, not by the rotor's dynamics. With one vibration point this is a one-parameter "
        "fit; a second speed would test its omega scaling. "
    )


_CURVE_COLUMNS = {
    "front_outer_ring_temperature_c": "front_outer_ring_temperature_{}_thermal_displacement_c",
    "rear_outer_ring_temperature_c": "rear_outer_ring_temperature_{}_thermal_displacement_c",
    "velocity_rms_mm_s": "velocity_rms_{}_thermal_displacement_mm_s",
}


def _curves(base, coupled, measured, out: Path, quick: bool) -> list[Path]:
    """Both models against speed with the measured points."""
    import polars as pl

    from ..plot.axes import get_axes
    from ..plot.labels import axis_label
    from ..plot.style import place_legend

    speeds = np.arange(6000.0, 18001.0, 6000.0 if quick else 1000.0)
    cond = pl.DataFrame({"speed_rpm": speeds, "preload_n": 400.0, "radial_n": 0.0})
    rows = {"speed_rpm": speeds}
    for label, m in (("without", base), ("with", coupled)):
        p = m.predict(cond)
        for qq, col in _CURVE_COLUMNS.items():
            rows[col.format(label)] = p[qq]
    table = pl.DataFrame(rows)
    files = write_table(table, out, "diagnose_seed_b_curves")
    mq, my = measured["quantity"].to_list(), measured["value"].to_numpy()
    ms = measured["speed_rpm"].to_numpy()
    ax = get_axes(None)
    for i, part in enumerate(("front_outer", "rear_outer")):
        for label, ls in (("without", "--"), ("with", "-")):
            col = _CURVE_COLUMNS[f"{part}_ring_temperature_c"].format(label)
            ax.plot(
                speeds,
                table[col].to_numpy(),
                ls,
                color=f"C{i}",
                label=f"{part.replace('_', ' ')} ring, {label} thermal displacement",
            )
        k = [j for j, qq in enumerate(mq) if qq == f"{part}_ring_temperature_c"]
        ax.plot(
            ms[k],
            my[k],
            "o",
            color=f"C{i}",
            label=f"{part.replace('_', ' ')} ring, seed B measured",
        )
    ax.set_xlabel(axis_label("speed_rpm"))
    ax.set_ylabel("outer-ring temperature [°C]")
    ax.grid(True, alpha=0.3)
    place_legend(ax)
    files.append(save_figure(ax, out, "diagnose_seed_b_temperatures"))
    ax = get_axes(None)
    for label, ls in (("without", "--"), ("with", "-")):
        col = _CURVE_COLUMNS["velocity_rms_mm_s"].format(label)
        ax.semilogy(speeds, table[col].to_numpy(), ls, label=f"ours, {label} thermal displacement")
    k = [j for j, qq in enumerate(mq) if qq == "velocity_rms_mm_s"]
    ax.semilogy(ms[k], my[k], "ko", label="seed B measured")
    ax.semilogy(
        [18000.0, 18000.0],
        list(PAPER_SIMULATION["velocity_rms_mm_s"]),
        "x",
        color="C3",
        label="seed B simulation (uncoupled, coupled)",
    )
    ax.set_xlabel(axis_label("speed_rpm"))
    ax.set_ylabel("shaft-end " + axis_label("velocity_rms_mm_s"))
    ax.grid(True, which="both", alpha=0.3)
    place_legend(ax)
    files.append(save_figure(ax, out, "diagnose_seed_b_vibration"))
    return files
