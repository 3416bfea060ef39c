"""Rates of the default prediction band over noise seeds, on cases of our own
making (the figures on the Prediction page, "The unknown member").

A 7008C angular-contact bearing at 400 N axial preload; outer, inner and
ball temperatures and the heat measured at 4,000-10,000 rpm with the
typical sigmas; predictions at 12,500 and 14,500 rpm (a quarter and 45 %
beyond the top measured speed). Two hidden truths:

* ``f0``: the Palmgren factor at 1.5 (a registry candidate);
* ``source``: an extra heat growing like n (30 W at 10,000 rpm, no
  registry candidate has that law), to see whether the weights let a real
  unknown show.

For each seed: the diagnosis, its verdict, the default (mixture) band of
the outer-ring temperature and of k_xx; printed: coverage of the
noise-free truth, exclusion of the uncalibrated baseline, mean half-width,
and how often the unknown member has the largest weight.

    python3 benches/predict_weights_case.py f0 50
    python3 benches/predict_weights_case.py source 30
    python3 benches/predict_weights_case.py f0 50 50    # seeds 50-99
"""

from __future__ import annotations

import sys
import time
import warnings

import numpy as np
import polars as pl

import thermobear as tb
from thermobear import diagnosis as D

SPEEDS = np.array([4000.0, 6000.0, 8000.0, 10000.0])
FAR = np.array([12500.0, 14500.0])
QUANTITIES = ["outer_ring_temperature_c", "inner_ring_temperature_c", "ball_temperature_c",
              "heat_w"]  # fmt: skip
SHOWN = ("outer_ring_temperature_c", "k_xx_n_per_m")


class _Source:
    """The bearing with an extra heat ``watts * (n / 10,000 rpm)^power``."""

    def __init__(self, base: D.BearingModelSpec, watts: float, power: float):
        self.base, self.watts, self.power = base, watts, power
        self.quantities = base.quantities

    def predict(self, cond: pl.DataFrame) -> dict:
        out = {q: np.empty(cond.height) for q in self.quantities}
        sp = cond["speed_rpm"].to_numpy()
        for s in np.unique(sp):
            rows = sp == s
            heat = float(self.watts * (s / 10000.0) ** self.power)
            got = self.base.with_setting(extra_heat_w=heat).predict(cond.filter(pl.Series(rows)))
            for q in out:
                out[q][rows] = got[q]
        return out


def main(case: str, seeds: int, first: int = 0) -> None:
    warnings.simplefilter("ignore")
    base = D.BearingModelSpec(tb.Bearing.preset("7008C"))
    if case == "f0":
        truth = base.with_setting(lubrication_factor_f0=1.5)
    elif case == "source":
        truth = _Source(base, 30.0, 1.0)
    else:
        raise SystemExit("case: f0 or source")
    cols = ["speed_rpm", "axial_n", "radial_n", "quantity"]
    grid = [(s, 400.0, 0.0, q) for s in SPEEDS for q in QUANTITIES]
    cond = pl.DataFrame(grid, schema=cols, orient="row")
    got = truth.predict(cond)
    exact = np.array([got[q][i] for i, q in enumerate(cond["quantity"])])
    sigma = D.typical_sigma(base.quantities, cond["quantity"].to_list(), exact)
    far = pl.DataFrame({"speed_rpm": FAR, "axial_n": 400.0, "radial_n": 0.0})
    true_far, base_far = truth.predict(far), base.predict(far)
    rows, unknown_first = [], []
    for seed in range(first, first + seeds):
        t0 = time.perf_counter()
        noise = np.random.default_rng(seed).normal(size=exact.size)
        data = cond.with_columns(
            pl.Series("value", exact + noise * sigma), pl.Series("sigma", sigma)
        )
        d = tb.diagnose(base, data)
        members = list(d.model.members)
        if members:
            top = max(members, key=lambda m: float(m.weight or 0.0))
            unknown_first.append("unknown heat source" in top.label)
        pred = tb.predict(d.model, "measured", {"speeds_rpm": FAR.tolist(), "axial_n": 400.0})
        combined = "mixture" if members else ""
        for q in SHOWN:
            r = pred.filter((pl.col("quantity") == q) & (pl.col("member") == combined))
            r = r.sort("speed_rpm")
            lo, hi = r["lower"].to_numpy(), r["upper"].to_numpy()
            rows.append({"seed": seed, "quantity": q, "kind": d.model.kind,
                         "cover": np.mean((lo <= true_far[q]) & (true_far[q] <= hi)),
                         "exclude_baseline": np.mean((base_far[q] < lo) | (base_far[q] > hi)),
                         "half_width": float(np.mean((hi - lo) / 2.0))})  # fmt: skip
        print(f"seed {seed} ({time.perf_counter() - t0:.1f} s): {d.verdict}", flush=True)
    table = pl.DataFrame(rows)
    with pl.Config(tbl_rows=20, tbl_width_chars=160):
        print(table.group_by("quantity").agg(
            pl.col("cover").mean(), pl.col("exclude_baseline").mean(),
            pl.col("half_width").mean(), pl.len().alias("seeds")))  # fmt: skip
        print(table.group_by("quantity", "kind").agg(pl.col("cover").mean(), pl.len()))
    if unknown_first:
        print(f"unknown member weighed highest in {np.mean(unknown_first):.0%} "
              f"of {len(unknown_first)} seeds with members")  # fmt: skip


if __name__ == "__main__":
    args = sys.argv[1:]
    main(args[0] if args else "f0", int(args[1]) if len(args) > 1 else 10,
         int(args[2]) if len(args) > 2 else 0)  # fmt: skip
