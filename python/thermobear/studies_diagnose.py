"""``thermobear demo`` study: the discrepancy workflow on a synthetic
hidden-effect case.

A 7008C angular-contact bearing under 300 N preload (seed B's rear bearing
size; its steel variant, because the coupled solver of the 7009C hybrid at
400 N fails to converge at some speed for several f0 values, which would
drop whole configurations from the screening) is "measured" by the full
model with a churning loss 1.5 times the baseline's (Palmgren f0 = 1.5
instead of 1) plus noise (0.3 K thermocouples, 1 % stiffness and heat);
the baseline diagnoses it. Tables: the residual audit,
screening, held-out gap before/after and the verdict; figures: measured vs
model before/after and residual/sigma vs speed.

Not here (yet): a diagnosis of seed B's own measurements (front/rear outer
ring 33.7/30.1 C at 12,000 rpm, 18.92 mm/s at 18,000 rpm): they are spindle
quantities, and the workflow evaluates single-bearing models only.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from .bearing import Bearing
from .demo import save_figure, write_table

F0_HIDDEN = 1.5
PRELOAD_N = 300.0


def study_diagnose(out: Path, quick: bool) -> list[Path]:
    import polars as pl

    from . import plot
    from .diagnosis import BearingModelSpec, diagnose

    bearing = Bearing.preset("7008C")
    baseline = BearingModelSpec(bearing)
    truth = baseline.with_setting(lubrication_factor_f0=F0_HIDDEN)
    # seed B's test speeds: 6000-18,000 rpm in 1000 rpm steps
    speeds = np.arange(6000.0, 18001.0, 2000.0 if quick else 1000.0)
    qs = [
        "temperature_c:To",
        "temperature_c:Ti",
        "temperature_c:Tb",
        "radial_stiffness_n_per_m",
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
    allq = truth.predict(cond)
    q = cond["quantity"].to_list()
    val = np.array([allq[qq][i] for i, qq in enumerate(q)])
    sig = np.array([0.3 if qq.startswith("temperature") else 0.01 * v for qq, v in zip(q, val)])
    rng = np.random.default_rng(20260601)
    measured = cond.with_columns(
        pl.Series("value", val + rng.normal(size=len(val)) * sig), pl.Series("sigma", sig)
    )
    d = diagnose(baseline, measured)
    files = write_table(measured, out, "diagnose_synthetic_measured")
    files += write_table(d.audit, out, "diagnose_synthetic_audit")
    files += write_table(
        pl.concat(d.screening, how="diagonal"), out, "diagnose_synthetic_screening"
    )
    files += write_table(d.gap, out, "diagnose_synthetic_gap")
    verdict = out / "diagnose_synthetic_verdict.txt"
    verdict.write_text(
        f"hidden: lubrication_factor_f0 = {F0_HIDDEN} (baseline 1.0)\n" + d.summary() + "\n"
    )
    files.append(verdict)
    files.append(save_figure(plot.diagnosis_fit(d, "temperature_c:Tb"), out, "diagnose_fit_Tb"))
    files.append(save_figure(plot.diagnosis_residuals(d), out, "diagnose_residuals"))
    return files
