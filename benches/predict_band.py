"""Cost of a prediction band.

    python benches/predict_band.py [--samples 64] [--repeats 2]

A 7008C bearing (300 N axial) calibrated on two values (Palmgren f0 and an
extra heat) from outer-ring temperatures and heat at five speeds; then the
95 % band of its thermal stiffness curve (k_xx, k_zz and the seed formula's
two stiffnesses) at 101 speeds from 1,000 to 20,000 rpm:

1. by the delta method (1 + 2 p = 5 model runs of the 101 speeds);
2. by sampling (``--samples`` scrambled Sobol points, one run each);
3. the cost of one sample: one model run of the 101 speeds at a new
   vector of calibrated values.

Target: the band in 10 s or less on 2 cores. Each timing starts from an
empty solve cache (the spec caches every configuration it solved) and is
the best of ``--repeats``; the load average is printed with it.
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np
import polars as pl

import thermobear as tb
from thermobear import diagnosis as D

SPEEDS_RPM = np.linspace(1000.0, 20000.0, 101)
TRUTH = {"lubrication_factor_f0": 1.6, "extra_heat_w": 5.0}


def calibrated(base: D.BearingModelSpec):
    """The two-value calibration's model (``Calibration.model``)."""
    truth = base.with_setting(**TRUTH)
    speeds = np.linspace(2000.0, 10000.0, 5)
    quantities = ["outer_ring_temperature_c", "heat_w"]
    cond = pl.DataFrame(
        {
            "speed_rpm": np.repeat(speeds, 2),
            "axial_n": 300.0,
            "radial_n": 0.0,
            "quantity": quantities * len(speeds),
        }
    )
    measured = D.synthetic_measurements(truth, cond, 1.0, 0)
    t = time.perf_counter()
    cal = tb.calibrate([(base, measured)], list(TRUTH))
    print(f"calibration: {time.perf_counter() - t:.2f} s  {cal!r}")
    return cal.model


def timed(fn, repeats: int, clear) -> float:
    best = np.inf
    for _ in range(repeats):
        clear()
        t = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t)
    return best


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--samples", type=int, default=64)
    ap.add_argument("--repeats", type=int, default=2)
    args = ap.parse_args()
    base = D.BearingModelSpec(tb.Bearing.preset("7008C"))
    cm = calibrated(base)
    cond = {"speeds_rpm": SPEEDS_RPM, "axial_n": 300.0}
    clear = base._cache.clear  # the specs of the calibrated model share it
    print(f"load average {os.getloadavg()[0]:.2f}, {os.cpu_count()} CPUs")

    def band(method: str) -> pl.DataFrame:
        return tb.predict(cm, "stiffness", cond, method=method, samples=args.samples)  # type: ignore[arg-type]

    t_delta = timed(lambda: band("delta"), args.repeats, clear)
    t_samp = timed(lambda: band("sampling"), args.repeats, clear)
    rng = np.random.default_rng(1)
    std = np.sqrt(np.diag(cm.covariance))
    frame = pl.DataFrame({"speed_rpm": SPEEDS_RPM, "axial_n": 300.0, "radial_n": 0.0})
    t_one = timed(
        lambda: cm.spec_at(cm.values + rng.normal(size=len(std)) * std).predict(frame),
        max(args.repeats, 3),
        clear,
    )
    df = band("delta").filter(pl.col("quantity") == "k_xx_n_per_m")
    top = df.filter(pl.col("speed_rpm") == SPEEDS_RPM[-1]).row(0, named=True)
    print(
        f"k_xx at {SPEEDS_RPM[-1]:.0f} rpm: {top['value'] / 1e6:.2f} N/um, 95 % band "
        f"[{top['lower'] / 1e6:.2f}, {top['upper'] / 1e6:.2f}]"
    )
    print(f"95 % band, 101 speeds, delta method (5 runs):      {t_delta:6.2f} s  (target <= 10 s)")
    print(
        f"95 % band, 101 speeds, sampling ({args.samples} samples): {t_samp:6.2f} s  "
        "(target <= 10 s)"
    )
    print(f"one sample (one model run of 101 speeds):          {t_one:6.3f} s")
    print(f"load average {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
