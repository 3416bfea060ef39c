"""Cost of regime-boundary intervals for the seed gear pair.

    python benches/predict_regimes.py [--samples 32] [--speeds 201]

Seed A's gearbox bearing (6208) under the seed gear loads at 20 N m
(776 N axial, 238 N radial), calibrated on two values (Palmgren f0 and an
extra heat) from outer-ring temperatures and heat measured at five speeds
(synthetic, with noise); its bearing stiffness (the thermal schedule) is
then uncertain through those two values. The seed gear pair at 20 N m and
a 5 um transmission error on those bearings is swept down over ``--speeds``
speeds of the seed study's range (6,500 to 16,500 rpm), once per
scrambled Sobol sample of the calibrated values, all samples' sweeps in
parallel, with the sweep's default settings (300 transient and 100 record
mesh periods, 100 Lyapunov periods; adaptive transient).

Printed: the regime boundaries with their intervals, the wall time of the
whole prediction (target: 30 s or less on 2 cores), and the cost of one
sample (its bearing's thermal stiffness schedule and its sweep, alone).
The load average is printed with the timings: the machine may be shared.
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np
import polars as pl

import thermobear as tb
from thermobear import diagnosis as D
from thermobear.predict.sweeps import regime_system

TORQUE_N_M = 20.0
GEAR_OPTIONS = {"torque_n_m": TORQUE_N_M, "te_amplitude_um": 5.0}
SPEED_RANGE_RPM = (6500.0, 16500.0)
TRUTH = {"lubrication_factor_f0": 1.6, "extra_heat_w": 5.0}
AXIAL_N, RADIAL_N = 776.18, 237.98  # the seed gear bearing loads at 20 N m


def calibrated() -> tb.CalibratedModel:
    """The two-value calibration's model (``Calibration.model``)."""
    base = D.BearingModelSpec(tb.Bearing.preset("6208"))
    truth = base.with_setting(**TRUTH)
    speeds = np.linspace(2000.0, 10000.0, 5)
    quantities = ["outer_ring_temperature_c", "heat_w"]
    cond = pl.DataFrame(
        {
            "speed_rpm": np.repeat(speeds, 2),
            "axial_n": AXIAL_N,
            "radial_n": RADIAL_N,
            "quantity": quantities * len(speeds),
        }
    )
    measured = D.synthetic_measurements(truth, cond, 1.0, 0)
    t = time.perf_counter()
    cal = tb.calibrate([(base, measured)], list(TRUTH))
    print(f"calibration: {time.perf_counter() - t:.2f} s  {cal!r}")
    return cal.model


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--samples", type=int, default=32)
    ap.add_argument("--speeds", type=int, default=201)
    args = ap.parse_args()
    cm = calibrated()
    print(cm.summary())
    speeds = np.linspace(*SPEED_RANGE_RPM, args.speeds)
    gear = tb.GearPair.preset("seed-electric-drive")
    print(f"load average {os.getloadavg()[0]:.2f}, {os.cpu_count()} CPUs")
    t = time.perf_counter()
    pred = tb.predict(
        cm, "regimes", {"speeds_rpm": speeds}, gear=gear, gear_options=GEAR_OPTIONS,
        direction="down", samples=args.samples, seed=0,
    )  # fmt: skip
    t_all = time.perf_counter() - t
    t = time.perf_counter()
    one = regime_system(cm, cm.values, gear, GEAR_OPTIONS)
    t_schedule = time.perf_counter() - t
    t = time.perf_counter()
    tb.bifurcation(one, speeds, direction="down")
    t_sweep = time.perf_counter() - t
    with pl.Config(tbl_rows=40, tbl_cols=10, tbl_width_chars=140):
        print(tb.regime_boundaries(pred).filter(pl.col("probability") >= 0.25))
    print(
        f"regime-boundary intervals, {args.speeds} speeds, {args.samples} samples: "
        f"{t_all:6.2f} s  (target <= 30 s)"
    )
    print(
        f"one sample alone: thermal stiffness schedule {t_schedule:.3f} s + sweep "
        f"{t_sweep:.3f} s = {t_schedule + t_sweep:.3f} s"
    )
    print(f"load average {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
