"""Rates over fixed seeds for a load stated wrongly at one load level
(the candidate list: "applied load and preload miscalibration (per load
level)"), and for other inputs hidden in turn (a global load scale, the
housing conductance, a churning loss, a displacement-probe gain), on designs
unlike the other rate tests: a steel 7009C under two axial loads (4 speeds,
3 quantities) and a hybrid deep-groove 6208 under two radial loads (8
speeds, 2 quantities).

With no candidate names given, ``tb.diagnose`` screens one load-scale
candidate per measured load level beside the global scale. Asserted: the
per-level error (sized to 3.2-3.7 typical sigma at the top speed) is named
or in a tie in at least 90 % of 40 seeds with at most 2 wrong names, its
95 % interval covers the truth in at least 90 % of the seeds that give one,
and with nothing hidden at most 5 of 100 seeds name an effect although the
pool grew by the per-level candidates.
"""

from __future__ import annotations

import numpy as np
import polars as pl
import pytest
from diagnose_rates import hidden_runs, top_speed_sigma_real

import thermobear as tb
from thermobear import diagnosis as D

_SPECS: dict = {}


def _base(preset: str) -> D.BearingModelSpec:
    if preset not in _SPECS:
        _SPECS[preset] = D.BearingModelSpec(tb.Bearing.preset(preset))
    return _SPECS[preset]


def _conditions(speeds, loads, quantities) -> pl.DataFrame:
    rows = [(s, a, r, q) for a, r in loads for s in speeds for q in quantities]
    return pl.DataFrame(rows, schema=["speed_rpm", "axial_n", "radial_n", "quantity"], orient="row")


# (preset, conditions, hidden per-level candidate, its true value)
DESIGNS = {
    "7009C": (
        _conditions(
            np.linspace(4000.0, 16000.0, 4),
            [(400.0, 0.0), (900.0, 0.0)],
            ["outer_ring_temperature_c", "heat_w", "axial_displacement_um"],
        ),
        "axial_load_scale@900",
        1.08,
    ),
    "6208-hybrid": (
        _conditions(
            np.linspace(1500.0, 12000.0, 8),
            [(0.0, 1500.0), (0.0, 3000.0)],
            ["inner_ring_temperature_c", "radial_stiffness_seed_n_per_m"],
        ),
        "radial_load_scale@3000",
        0.8,
    ),
}


def test_per_level_candidates_are_screened_only_with_two_levels():
    base = _base("7009C")
    two, _, _ = DESIGNS["7009C"]
    d = tb.diagnose(base, D.synthetic_measurements(base, two, 1.0, 0), suggest=False)
    screened = set(d.screening[0]["candidate"].to_list())
    assert {"axial_load_scale", "axial_load_scale@400", "axial_load_scale@900"} <= screened
    one = two.filter(pl.col("axial_n") == 400.0)
    d = tb.diagnose(base, D.synthetic_measurements(base, one, 1.0, 0), suggest=False)
    screened = set(d.screening[0]["candidate"].to_list())
    assert "axial_load_scale" in screened
    assert not any("@" in n for n in screened)


@pytest.mark.parametrize("preset", sorted(DESIGNS))
def test_a_load_wrong_at_one_level_is_named_or_tied_and_covered(preset):
    cond, name, value = DESIGNS[preset]
    base = _base(preset)
    truth = base.with_setting(**{name: value})
    assert 3.0 < top_speed_sigma_real(truth, base, cond) < 4.0
    out, covered, n = hidden_runs(
        base,
        lambda s: D.synthetic_measurements(truth, cond, 1.0, s),
        name,
        value,
        range(90_000, 90_040),
    )
    assert out.count("right") + out.count("tie") >= 36 and out.count("wrong") <= 2, out
    assert n >= 36 and covered >= 0.9 * n, (covered, n)


@pytest.mark.parametrize("preset", sorted(DESIGNS))
def test_null_with_per_level_candidates_over_100_seeds(preset):
    cond, _, _ = DESIGNS[preset]
    base = _base(preset)
    found = 0
    for s in range(100):
        d = tb.diagnose(base, D.synthetic_measurements(base, cond, 1.0, 95_000 + s), suggest=False)
        found += d.verdict != "no missing effect supported"
    assert found <= 5


def _at_sigma(base, cond, option, null, step, target=3.5):
    """``option`` moved so that the largest change at the top speed is
    ``target`` typical sigma (the change is close to linear in the option)."""
    one = top_speed_sigma_real(base.with_setting(**{option: null + step}), base, cond)
    return null + target * step / one


@pytest.mark.parametrize(
    "preset,option,null,step",
    [
        ("7009C", "housing_conductance_scale", 1.0, -0.1),
        ("6208-hybrid", "radial_load_scale", 1.0, 0.1),
        ("6208-hybrid", "churning_oil_fraction", 0.0, 0.005),
    ],
)
def test_other_hidden_inputs_named_or_tied_and_covered(preset, option, null, step):
    cond, _, _ = DESIGNS[preset]
    base = _base(preset)
    value = _at_sigma(base, cond, option, null, step)
    truth = base.with_setting(**{option: value})
    assert 3.0 < top_speed_sigma_real(truth, base, cond) < 4.0
    out, covered, n = hidden_runs(
        base,
        lambda s: D.synthetic_measurements(truth, cond, 1.0, s),
        option,
        value,
        range(91_000, 91_040),
    )
    assert out.count("right") + out.count("tie") >= 36 and out.count("wrong") <= 2, out
    assert n >= 36 and covered >= 0.9 * n, (covered, n)


def test_a_displacement_probe_gain_error_is_named_or_tied_and_covered():
    """The axial displacement probe of the 7009C reads (1 + g) times the
    displacement, g sized to 3.5 typical sigma at the top speed (a
    thermocouple's gain, within its 2 % bound, cannot reach 3 sigma on
    these temperatures). On ~150 um a 1.2 % gain is nearly an offset, so
    most outcomes are ties with the probe's offset; over 240 seeds about
    8 % name a wrong input instead (an ambient temperature offset, which
    moves the thermal part of the displacement, the housing conductance or
    the axial load scale) -- the rate asserted is the target's 90 %
    right-or-tie, which this case meets with little margin."""
    cond, _, _ = DESIGNS["7009C"]
    base = _base("7009C")
    name, q = "sensor_gain:axial_displacement_um", "axial_displacement_um"
    pred = base.predict(cond)[q]
    rows = (cond["quantity"] == q).to_numpy()
    top = rows & (cond["speed_rpm"].to_numpy() == cond["speed_rpm"].max())
    sig = D.typical_sigma(base.quantities, cond["quantity"].to_list(), pred)
    g = float(3.5 * sig[top][0] / pred[top][0])
    assert 0.0 < g < 0.10  # inside the candidate's bounds
    gain = pl.when(pl.col("quantity") == q).then(pl.col("value") * (1.0 + g))

    def measured(seed):
        m = D.synthetic_measurements(base, cond, 1.0, seed)
        return m.with_columns(gain.otherwise(pl.col("value")))

    out, covered, n = hidden_runs(base, measured, name, g, range(93_000, 93_240))
    assert out.count("right") + out.count("tie") >= 0.9 * len(out), out
    assert covered >= 0.9 * n, (covered, n)
