"""Benchmark of the discrepancy workflow (issue 6 target: a diagnosis over
10 candidates on 60 measured points under 10 s on 2 threads).

60 points: 12 speeds x 5 quantities of a 7008C bearing at 300 N preload,
data from the full model with a hidden churning loss (ball drag in a 1 %
oil-air mixture) and noise; the first 10 candidates that act in the
single-bearing model (spin friction switch, then the calibratable inputs and
terms, the housing materials and sensor offsets).
Reports the cold time (every model configuration solved) and the warm time
(same conditions, new noise: the cached configurations are reused).

    RAYON_NUM_THREADS=2 python benches/diagnose_bench.py
"""

from __future__ import annotations

import time

import numpy as np
import polars as pl

import thermobear as tb
from thermobear import diagnosis as D


def main() -> None:
    b = tb.Bearing.preset("7008C")
    full = tb.effects("switch")["name"].to_list()
    # baseline without spin friction: the switch joins the parameter candidates
    base_eff = [e for e in full if e != "spin_friction"]
    qs = [
        "temperature_c:To",
        "temperature_c:Ti",
        "temperature_c:Tb",
        "radial_stiffness_n_per_m",
        "heat_w",
    ]
    speeds = np.linspace(2000.0, 18000.0, 12)
    cond = pl.DataFrame(
        {
            "speed_rpm": np.repeat(speeds, len(qs)),
            "axial_n": 300.0,
            "radial_n": 0.0,
            "quantity": qs * len(speeds),
        }
    )
    truth = D.BearingModelSpec(b, effects=base_eff, churning_oil_fraction=0.01)
    table = tb.candidates(D.BearingModelSpec(b, effects=base_eff), qs)
    names = table.filter(pl.col("affects") != D.NOT_IN_BEARING)["name"].to_list()[:10]
    spec = D.BearingModelSpec(b, effects=base_eff)
    for label in ("cold", "warm"):
        # half the typical noise; the warm run gets new noise on the same conditions
        meas = D.synthetic_measurements(truth, cond, 0.5, seed=0 if label == "cold" else 1)
        t0 = time.perf_counter()
        d = tb.diagnose(spec, meas, candidates=names)
        dt = time.perf_counter() - t0
        print(
            f"{label}: {len(names)} candidates, {meas.height} points: {dt:.2f} s "
            f"({spec.model_runs} model sweeps) -> {d.verdict}"
        )


def spindle() -> None:
    """The seed B spindle: 7 speeds x 2 preloads x 9 quantities (126 points,
    vibration included), the model without thermal displacement."""
    from thermobear.diagnosis import SPINDLE_QUANTITIES

    sp = tb.Spindle.preset("seed-ceramic-spindle")
    full = tb.SpindleModelSpec(sp)
    base = tb.SpindleModelSpec(sp, effects=[e for e in full.effects if "thermal_exp" not in e])
    qs = list(SPINDLE_QUANTITIES)
    speeds = np.arange(6000.0, 18001.0, 2000.0)
    cond = pl.concat(
        pl.DataFrame(
            {
                "speed_rpm": np.repeat(speeds, len(qs)),
                "axial_n": p,
                "radial_n": 0.0,
                "quantity": qs * len(speeds),
            }
        )
        for p in (250.0, 400.0)
    )
    meas = D.synthetic_measurements(full, cond, 1.0, seed=0)
    t0 = time.perf_counter()
    d = tb.diagnose(base, meas)
    n = len(d.screening[0])
    print(
        f"spindle cold: {n} candidates, {meas.height} points: {time.perf_counter() - t0:.2f} s "
        f"-> {d.verdict}"
    )


if __name__ == "__main__":
    main()
    spindle()
