"""Rates of the default prediction band of a spindle whose heat has an
unknown source (the figures on the Prediction page, "Spindle case").

The seed ceramic spindle at 400 N; a hidden heat at the front bearing set
of 60 W (n / 15,000 rpm)^1.5, a law no registry input has; the front
outer, inner and ball and the rear outer-ring temperatures measured at
6,000-15,000 rpm (sigma 0.3 K); predictions at 18,000 rpm. For each seed:
the diagnosis, its verdict, the default (mixture) band of the front
outer-ring temperature and of k_xx; printed: coverage of the noise-free
truth, exclusion of the uncalibrated baseline, mean half-width and the
unknown member's mean weight.

    python3 benches/predict_spindle_unknown_case.py 30        # seeds 0-29
    python3 benches/predict_spindle_unknown_case.py 30 30     # seeds 30-59
"""

from __future__ import annotations

import sys
import time
import warnings

import numpy as np
import polars as pl

import thermobear as tb
from thermobear import diagnosis as D

SPEEDS = [6000.0, 9000.0, 12000.0, 15000.0]
FAR = [18000.0]
QUANTITIES = [
    "front_outer_ring_temperature_c",
    "front_inner_ring_temperature_c",
    "front_ball_temperature_c",
    "rear_outer_ring_temperature_c",
]
SHOWN = {"k_xx_n_per_m": "stiffness", "front_outer_ring_temperature_c": "temperatures"}
SIGMA_K = 0.3


def _measured(base: D.SpindleModelSpec) -> tuple[pl.DataFrame, np.ndarray, dict, dict]:
    """Conditions, exact values, truth and baseline at the far speed."""

    def truth(n: float) -> D.SpindleModelSpec:
        return base.with_setting(extra_heat_w=float(60.0 * (n / 15000.0) ** 1.5))

    cond = pl.DataFrame([(n, 400.0, q) for n in SPEEDS for q in QUANTITIES],
                        schema=["speed_rpm", "preload_n", "quantity"], orient="row")  # fmt: skip
    exact = np.array([
        truth(n).predict(cond[i].rename({"preload_n": "axial_n"}))[q][0]
        for i, (n, q) in enumerate(zip(cond["speed_rpm"], cond["quantity"], strict=True))
    ])  # fmt: skip
    far = pl.DataFrame({"speed_rpm": FAR, "axial_n": 400.0})
    true_far = {q: float(truth(FAR[0]).predict(far)[q][0]) for q in SHOWN}
    base_far = {q: float(base.predict(far)[q][0]) for q in SHOWN}
    return cond, exact, true_far, base_far


def main(seeds: int, first: int = 0) -> None:
    warnings.simplefilter("ignore")
    base = D.SpindleModelSpec(tb.Spindle.preset("seed-ceramic-spindle"))
    cond, exact, true_far, base_far = _measured(base)
    rows = []
    for seed in range(first, first + seeds):
        t0 = time.perf_counter()
        noise = np.random.default_rng(seed).normal(size=exact.size)
        data = cond.with_columns(pl.Series("value", exact + noise * SIGMA_K),
                                 pl.Series("sigma", np.full(exact.size, SIGMA_K)))  # fmt: skip
        d = tb.diagnose(base, data)
        members = list(d.model.members or [])
        unknown = [m for m in members if "unknown heat source" in m.label]
        for q, what in SHOWN.items():
            p = tb.predict(d.model, what, {"speeds_rpm": FAR, "preload_n": 400.0})
            r = p.filter((pl.col("quantity") == q) & (pl.col("member") == ("mixture" if members
                                                                            else "")))  # fmt: skip
            lo, hi = r["lower"][0], r["upper"][0]
            rows.append({"seed": seed, "quantity": q, "kind": d.model.kind,
                         "cover": lo is not None and lo <= true_far[q] <= hi,
                         "exclude_baseline": lo is not None and not lo <= base_far[q] <= hi,
                         "half_width": None if lo is None else (hi - lo) / 2.0,
                         "unknown_weight": unknown[0].weight if unknown else None})  # fmt: skip
        print(f"seed {seed} ({time.perf_counter() - t0:.1f} s): {d.verdict}", flush=True)
    with pl.Config(tbl_rows=20, tbl_width_chars=160):
        print(pl.DataFrame(rows).group_by("quantity").agg(
            pl.col("cover").mean(), pl.col("exclude_baseline").mean(),
            pl.col("half_width").mean(), pl.col("unknown_weight").mean(),
            pl.len().alias("seeds")))  # fmt: skip


if __name__ == "__main__":
    args = sys.argv[1:]
    main(int(args[0]) if args else 10, int(args[1]) if len(args) > 1 else 0)
