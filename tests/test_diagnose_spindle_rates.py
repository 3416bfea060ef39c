"""Rates of the discrepancy workflow on the seed B spindle over fixed seeds:
every effect of the registry that acts in the spindle (thermal model) or its
rotor, hidden in turn, plus the null case over 100 seeds.

Synthetic measurements: the full spindle model (every effect on, magnetic
pull included) with one effect switched off in the baseline, Gaussian noise
at multiples of each quantity's typical uncertainty (thermocouples 0.5 K,
vibrometer 5 %, axial growth probe 0.5 um, preload load washer 2 %; see
thermobear.diagnosis.SPINDLE_QUANTITIES). The design is a spindle
test rig's: front/rear outer and inner ring and housing temperatures, axial
growth, front operating preload and shaft-end vibration at 7 speeds
(6,000-18,000 rpm) and two spring preloads (250 and 400 N), 126 points.

Effects whose fingerprints are alike on these quantities are reported as a
tie, never as a wrong single name: the magnetic pull scales the vibration
almost like a larger residual unbalance or a vibrometer gain error.
"""

from __future__ import annotations

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear.diagnosis import SPINDLE_QUANTITIES, SpindleModelSpec, synthetic_measurements

SPEEDS_RPM = np.arange(6000.0, 18001.0, 2000.0)
PRELOADS_N = (250.0, 400.0)
#: A rig's sensors (the registry also holds what only a simulation reports).
DESIGN = [
    "front_outer_ring_temperature_c",
    "rear_outer_ring_temperature_c",
    "front_inner_ring_temperature_c",
    "rear_inner_ring_temperature_c",
    "front_housing_temperature_c",
    "rear_housing_temperature_c",
    "axial_growth_um",
    "operating_preload_n",
    "velocity_rms_mm_s",
]
assert set(DESIGN) <= set(SPINDLE_QUANTITIES)
HIGH_SNR, TYPICAL = 0.2, 1.0

_SPECS: dict = {}


def _spindle():
    return tb.Spindle.preset("seed-ceramic-spindle")


def _spec(effects=None) -> SpindleModelSpec:
    key = None if effects is None else tuple(sorted(effects))
    if key not in _SPECS:
        _SPECS[key] = SpindleModelSpec(_spindle(), effects=effects)
    return _SPECS[key]


FULL = list(_spec().effects)


def _conditions() -> pl.DataFrame:
    n = len(DESIGN) * len(SPEEDS_RPM)
    return pl.concat(
        pl.DataFrame(
            {
                "speed_rpm": np.repeat(SPEEDS_RPM, len(DESIGN)),
                "preload_n": [p] * n,
                "quantity": DESIGN * len(SPEEDS_RPM),
            }
        )
        for p in PRELOADS_N
    )


def _runs(baseline, truth, noise, seeds):
    cond = _conditions()
    return [
        tb.diagnose(baseline, synthetic_measurements(truth, cond, noise, s), suggest=False)
        for s in seeds
    ]


def _named(d) -> list[str]:
    return [a["name"] for a in d.accepted]


def test_null_false_discovery_at_most_5_percent_over_100_seeds():
    runs = _runs(_spec(), _spec(), TYPICAL, range(100))
    assert sum(d.verdict != "no missing effect supported" for d in runs) <= 5


#: Effects named alone at high SNR in at least 90 % of the seeds.
SEPARABLE = [
    "centrifugal_force",
    "gyroscopic_moment",
    "ring_centrifugal_expansion",
    "spin_friction",
    "temperature_dependent_viscosity",
    "thermal_expansion_housing",
    "thermal_expansion_inner_ring",
    "thermal_expansion_outer_ring",
    "thermal_expansion_shaft",
]
#: Effects with a look-alike on these quantities: (effect, look-alikes).
LOOKALIKE = {
    # the preload spring law: growth reaching the spring ~ a stiffer spring
    "preload_change_from_axial_growth": {"spring_rate_n_per_um", "spin_friction_coefficient"},
    # the pull raises the vibration ~ like a larger unbalance or vibrometer gain
    "unbalanced_magnetic_pull": {"unbalance_grade", "sensor_offset:velocity_rms_mm_s"},
    # 0.2-0.4 um of ball growth: barely above the noise even at high SNR
    "thermal_expansion_balls": {"unbalance_grade", "sensor_offset:velocity_rms_mm_s"},
}


def test_every_spindle_effect_is_covered():
    models = dict(zip(tb.effects("switch")["name"], tb.effects("switch")["models"], strict=False))
    acting = {n for n, m in models.items() if {"spindle", "rotor"} & set(m.split(","))}
    assert acting == set(SEPARABLE) | set(LOOKALIKE)
    assert acting <= set(FULL)


@pytest.mark.parametrize("effect", SEPARABLE)
def test_hidden_effect_named_at_high_snr(effect):
    runs = _runs(_spec([e for e in FULL if e != effect]), _spec(), HIGH_SNR, range(20))
    right = sum(_named(d) == [effect] for d in runs)
    assert right >= 18, [d.verdict for d in runs][:4]


@pytest.mark.parametrize("effect", sorted(LOOKALIKE))
def test_lookalike_effect_is_never_replaced_by_a_wrong_physical_effect(effect):
    runs = _runs(_spec([e for e in FULL if e != effect]), _spec(), HIGH_SNR, range(20))
    allowed = {effect} | LOOKALIKE[effect]
    for d in runs:
        # a named physical effect is the hidden one or one of its look-alikes
        assert set(_named(d)) <= allowed, d.verdict
    # and the hidden effect is named or in the tie set most of the time
    assert sum(effect in _named(d) + d.tie for d in runs) >= 10


def test_thermal_displacement_group_named_at_typical_noise():
    # seed B's story: the model without thermal displacement, the data with
    base = _spec([e for e in FULL if not e.startswith("thermal_expansion_")])
    runs = _runs(base, _spec(), TYPICAL, range(20))
    assert sum(_named(d)[:1] == ["thermal_displacement"] for d in runs) >= 18
    g = runs[0].points.filter(pl.col("heldout") & (pl.col("quantity") == "axial_growth_um"))
    before = ((g["value"] - g["model_before"]) / g["sigma"]).abs().max()
    after = ((g["value"] - g["model_after"]) / g["sigma"]).abs().max()
    assert before > 100.0 and after < 4.0
