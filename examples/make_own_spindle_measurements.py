"""Write ``own_spindle_measurements.csv``: synthetic run-in measurements of the
spindle described in ``own_spindle.toml``, beside this script.

    python3 examples/make_own_spindle_measurements.py

The "machine" is thermobear's own model of that file with one input changed
and kept from the calibration: Palmgren's lubrication factor f0 is 1.6, where
the file guesses 1.0. At four speeds up to 12,000 rpm it "measures" both
outer rings and the front housing (thermocouples, sigma 0.5 K) and the axial
growth at the nose (a probe, sigma 0.5 um), with Gaussian noise of those
sigmas drawn from a fixed seed, rounded to 0.01. The same seed gives the same
file on every run; the docs page how-to/own-spindle.md calibrates f0 on it.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import polars as pl

import thermobear as tb
from thermobear.diagnosis import synthetic_measurements

HERE = Path(__file__).resolve().parent
DESCRIPTION = HERE / "own_spindle.toml"
OUT = HERE / "own_spindle_measurements.csv"

#: The value the data are made with, hidden from the calibration.
HIDDEN_F0 = 1.6
SPEEDS_RPM = (3000.0, 6000.0, 9000.0, 12000.0)
QUANTITIES = (
    "front_outer_ring_temperature_c",
    "rear_outer_ring_temperature_c",
    "front_housing_temperature_c",
    "axial_growth_um",
)
#: Noise in units of each quantity's typical sigma, and its seed.
NOISE = 1.0
SEED = 7014


def truth() -> tb.SpindleModelSpec:
    """The model the data are made with: the described spindle as configured,
    f0 set to ``HIDDEN_F0``."""
    spindle = tb.Spindle.from_toml(DESCRIPTION)
    return tb.SpindleModelSpec.of_model(spindle).with_setting(lubrication_factor_f0=HIDDEN_F0)


def measurements() -> pl.DataFrame:
    """The measured table: one row per speed and quantity at the file's
    preload, ``value`` rounded to 0.01."""
    model = truth()
    plan = pl.DataFrame(
        {
            "speed_rpm": np.repeat(SPEEDS_RPM, len(QUANTITIES)),
            "preload_n": model.spindle.preload_n,
            "quantity": list(QUANTITIES) * len(SPEEDS_RPM),
        }
    )
    made = synthetic_measurements(model, plan, NOISE, seed=SEED)
    return made.with_columns(pl.col("value").round(2))


def csv_text() -> str:
    """The file's text: the header saying how it was made, then the table."""
    guess = tb.Spindle.from_toml(DESCRIPTION).parts["lubrication"].lubrication_factor_f0
    header = (
        "# Synthetic, not measured: made by examples/make_own_spindle_measurements.py from\n"
        f"# own_spindle.toml with lubrication_factor_f0 = {HIDDEN_F0} (the file says {guess}),"
        f" noise of\n# {NOISE:g} sigma (0.5 K, 0.5 um), seed {SEED}; values rounded to 0.01.\n"
    )
    rows = [
        f"{r['speed_rpm']:.1f},{r['preload_n']:.1f},{r['quantity']},{r['value']:.2f},{r['sigma']:g}"
        for r in measurements().iter_rows(named=True)
    ]
    return header + "speed_rpm,preload_n,quantity,value,sigma\n" + "\n".join(rows) + "\n"


def main() -> None:
    OUT.write_text(csv_text(), encoding="utf-8")
    print(f"wrote {OUT}")


if __name__ == "__main__":
    main()
