"""Synthetic measurements stay physical: a quantity whose uncertainty is a
fraction of itself (a vibration velocity, a stiffness, a heat) is positive,
so its noise is log-normal and never drives it below zero, whatever the
noise level; to first order in sigma/value it is the Gaussian noise of the
quantity's typical sigma. The seed B spindle's vibration at 6,000 rpm is
some 0.001 mm/s: the case that must stay positive and pass the loader's
plausibility check (0..1000 mm/s)."""

from __future__ import annotations

import numpy as np
import polars as pl

from thermobear.diagnosis import load_measurements, synthetic_measurements
from thermobear.diagnosis.spindle_spec import SpindleModelSpec
from thermobear.spindle import Spindle


def _conditions(n_speeds: int) -> pl.DataFrame:
    speeds = np.linspace(6000.0, 18000.0, n_speeds)
    qs = ["velocity_rms_mm_s", "front_outer_ring_temperature_c"]
    return pl.DataFrame(
        {
            "speed_rpm": np.repeat(speeds, len(qs)),
            "preload_n": 400.0,
            "radial_n": 0.0,
            "quantity": qs * n_speeds,
        }
    )


def test_a_small_vibration_stays_positive_at_any_noise_level():
    spec = SpindleModelSpec(Spindle.preset("seed-ceramic-spindle"))
    cond = _conditions(7)
    for noise in (1.0, 10.0, 40.0):  # 40 x 5 %: a spread of twice the value
        m = synthetic_measurements(spec, cond, noise, seed=20261122)
        v = m.filter(pl.col("quantity") == "velocity_rms_mm_s")["value"].to_numpy()
        assert v.min() > 0.0, noise
        load_measurements(m, model=spec)  # within the plausible range: no DataError


def test_log_normal_noise_has_the_typical_relative_spread_and_median():
    spec = SpindleModelSpec(Spindle.preset("seed-ceramic-spindle"))
    cond = _conditions(3)
    truth = synthetic_measurements(spec, cond, 1e-12, seed=0)["value"].to_numpy()
    ratios, shifts = [], []
    for seed in range(400):
        m = synthetic_measurements(spec, cond, 1.0, seed=seed)["value"].to_numpy()
        ratios.append(np.log(m[0::2] / truth[0::2]))  # vibration: relative, 5 %
        shifts.append(m[1::2] - truth[1::2])  # temperature: absolute, 0.5 K, Gaussian
    ratios_a, shifts_a = np.concatenate(ratios), np.concatenate(shifts)
    n = ratios_a.size  # 1200 draws: the sample spread is within 3/sqrt(2n) ~ 6 %
    assert abs(np.std(ratios_a) - 0.05) < 0.05 * 3 / np.sqrt(2 * n)
    assert abs(np.median(ratios_a)) < 3 * 0.05 * 1.25 / np.sqrt(n)  # median = the truth
    assert abs(np.std(shifts_a) - 0.5) < 0.5 * 3 / np.sqrt(2 * n)
    assert abs(np.mean(shifts_a)) < 3 * 0.5 / np.sqrt(n)
