"""Benchmark of the discrepancy workflow (target: a diagnosis over
10 candidates on 60 measured points under 10 s on 2 threads).

60 points: 12 speeds x 5 quantities of a 7008C bearing at 300 N preload,
data from the full model with a hidden churning loss (ball drag in a 1 %
oil-air mixture) and noise; the first 10 candidates that act in the
single-bearing model (spin friction switch, then the calibratable inputs and
terms, the housing materials and sensor offsets).
Reports the cold time (every model configuration solved) and the warm time
(same conditions, new noise: the cached configurations are reused).

The statistics and validation targets, also measured here: a diagnosis
with 12 candidates on 100 points under 5 s (a hybrid 6208 at two radial loads, 10 speeds, 5
quantities; a lubrication factor 30 % high and a +1.5 K thermocouple offset
on the outer ring hidden together, so the two-parameter joint refit with
its profile intervals runs too), and ``thermobear validate`` on every
published set under 2 minutes.

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
        "outer_ring_temperature_c",
        "inner_ring_temperature_c",
        "ball_temperature_c",
        "radial_stiffness_seed_n_per_m",
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


def twelve_on_hundred() -> None:
    """12 candidates, 100 points, two effects hidden (the statistics target)."""
    b = tb.Bearing.preset("6208-hybrid")
    qs = [
        "outer_ring_temperature_c",
        "inner_ring_temperature_c",
        "ball_temperature_c",
        "heat_w",
        "radial_stiffness_seed_n_per_m",
    ]
    speeds = np.linspace(2000.0, 12000.0, 10)
    cond = pl.concat(
        pl.DataFrame(
            {
                "speed_rpm": np.repeat(speeds, len(qs)),
                "axial_n": 0.0,
                "radial_n": fr,
                "quantity": qs * len(speeds),
            }
        )
        for fr in (1500.0, 3000.0)
    )
    spec = D.BearingModelSpec(b)
    truth = spec.with_setting(lubrication_factor_f0=1.3)
    to = (cond["quantity"] == "outer_ring_temperature_c").to_numpy()
    names = [
        "lubrication_factor_f0",
        "extra_heat_w",
        "ambient_temperature_offset_k",
        "housing_conductance_scale",
        "spin_friction_coefficient",
        "churning_oil_fraction",
        "radial_load_scale",
        "radial_load_scale@1500",
        "radial_load_scale@3000",
        "sensor_offset:outer_ring_temperature_c",
        "sensor_gain:inner_ring_temperature_c",
        "heat_model:skf",
    ]
    for label, seed in (("cold", 0), ("warm", 1)):
        meas = D.synthetic_measurements(truth, cond, 1.0, seed=seed)
        meas = meas.with_columns(pl.col("value") + pl.Series(np.where(to, 1.5, 0.0)))
        t0 = time.perf_counter()
        d = tb.diagnose(spec, meas, candidates=names)
        dt = time.perf_counter() - t0
        print(
            f"target {label}: {len(names)} candidates, {meas.height} points: {dt:.2f} s "
            f"-> {d.verdict}"
        )


def validate_all() -> None:
    """``thermobear validate`` on every published set (the validation target)."""
    import tempfile
    from pathlib import Path

    with tempfile.TemporaryDirectory() as tmp:
        t0 = time.perf_counter()
        results = tb.validate(out=Path(tmp))
        print(f"validate: {len(results)} sets in {time.perf_counter() - t0:.2f} s")


if __name__ == "__main__":
    main()
    spindle()
    twelve_on_hundred()
    validate_all()
