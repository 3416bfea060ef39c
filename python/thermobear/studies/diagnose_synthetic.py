"""``thermobear demo`` study: the discrepancy workflow on a synthetic
hidden-effect case.

A 7008C angular-contact bearing under 300 N preload (seed B's rear bearing
size, steel) is "measured" by the full model plus a churning loss the
baseline leaves out: ball drag in an oil-air mixture of 1 % oil by volume
(``churning_oil_fraction`` = 0.01, ~17 W at 18,000 rpm against ~190 W of
friction heat), with typical noise (0.5 K thermocouples, 2 % stiffness and
heat). The baseline diagnoses it; a miscalibrated Palmgren f0 or an extra
constant heat are among the rivals it must beat (their heat grows like
speed^(2/3) or not at all, the drag like speed^3). Tables: the residual
audit, screening, held-out gap before/after and the verdict; figures:
measured vs model before/after and residual/sigma vs speed.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..bearing import Bearing
from .output import save_figure, write_table

#: Hidden in the synthetic measurements: oil volume fraction of the cavity.
CHURNING_HIDDEN = 0.01
PRELOAD_N = 300.0


def study_diagnose(out: Path, quick: bool) -> list[Path]:
    import polars as pl

    from .. import plot
    from ..diagnosis import BearingModelSpec, diagnose, synthetic_measurements

    bearing = Bearing.preset("7008C")
    baseline = BearingModelSpec(bearing)
    truth = baseline.with_setting(churning_oil_fraction=CHURNING_HIDDEN)
    # seed B's test speeds: 6000-18,000 rpm in 1000 rpm steps
    speeds = np.arange(6000.0, 18001.0, 2000.0 if quick else 1000.0)
    qs = [
        "outer_ring_temperature_c",
        "inner_ring_temperature_c",
        "ball_temperature_c",
        "radial_stiffness_seed_n_per_m",
        "heat_w",
    ]
    cond = pl.DataFrame(
        {
            "speed_rpm": np.repeat(speeds, len(qs)),
            "axial_n": PRELOAD_N,
            "radial_n": 0.0,
            "quantity": qs * len(speeds),
        }
    )
    # typical uncertainties (thermobear.diagnosis.QUANTITIES), a fixed seed
    measured = synthetic_measurements(truth, cond, 1.0, seed=20260601)
    d = diagnose(baseline, measured)
    files = write_table(measured, out, "diagnose_synthetic_measured")
    files += write_table(d.audit, out, "diagnose_synthetic_audit")
    files += write_table(
        pl.concat(d.screening, how="diagonal"), out, "diagnose_synthetic_screening"
    )
    files += write_table(d.gap, out, "diagnose_synthetic_gap")
    verdict = out / "diagnose_synthetic_verdict.txt"
    verdict.write_text(
        f"hidden: churning_oil_fraction = {CHURNING_HIDDEN} (baseline 0)\n" + d.summary() + "\n"
    )
    files.append(verdict)
    files.append(save_figure(plot.diagnosis_fit(d, "ball_temperature_c"), out, "diagnose_fit_Tb"))
    files.append(save_figure(plot.diagnosis_residuals(d), out, "diagnose_residuals"))
    return files
