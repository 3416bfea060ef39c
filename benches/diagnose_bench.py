"""Benchmark of the discrepancy workflow (issue 6 target: a diagnosis over
10 candidates on 60 measured points under 10 s on 2 threads).

60 points: 12 speeds x 5 quantities of a 7008C bearing at 300 N preload,
data from the full model with a hidden churning loss (f0 = 1.4) and noise.
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
    full = [e for e in tb.effects("switch")["name"].to_list() if e != "unbalanced_magnetic_pull"]
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
    truth = D.BearingModelSpec(b, effects=base_eff, lubrication_factor_f0=1.4)
    allq = truth.predict(cond)
    q = cond["quantity"].to_list()
    val = np.array([allq[qq][i] for i, qq in enumerate(q)])
    sig = np.array([0.3 if qq.startswith("temp") else 0.01 * v for qq, v in zip(q, val)])
    names = [
        n
        for n in tb.candidates(D.BearingModelSpec(b, effects=base_eff), qs)["name"]
        if n != "unbalanced_magnetic_pull"
    ][:10]
    spec = D.BearingModelSpec(b, effects=base_eff)
    for label in ("cold", "warm"):
        rng = np.random.default_rng(0 if label == "cold" else 1)
        meas = cond.with_columns(
            pl.Series("value", val + rng.normal(size=len(val)) * sig), pl.Series("sigma", sig)
        )
        t0 = time.perf_counter()
        d = tb.diagnose(spec, meas, candidates=names)
        dt = time.perf_counter() - t0
        print(
            f"{label}: {len(names)} candidates, {meas.height} points: {dt:.2f} s "
            f"({spec.model_runs} model sweeps) -> {d.verdict}"
        )


if __name__ == "__main__":
    main()
