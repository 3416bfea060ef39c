"""Rates of ``thermobear.diagnose`` over fixed seeds (the statistics targets),
on cases built unlike the other rate tests: 4-8 speeds, 2-4 quantities,
one or two load levels and runs, effects scaled to 3 sigma at the top speed.

Two models: the closed-form rig of ``diagnose_toy`` for the large seed
counts (every prediction a formula), and the real bearing model on a
deep-groove 6208 under radial load and a hybrid 7008C at two preloads for a
smaller set (the model runs once per configuration; seeds only change the
noise).

Asserted: at most 5 % false discoveries over >= 100 null seeds; the hidden
candidate named, or in a tie (a tie with an unknown smooth effect included:
the "unresolved" verdict), in >= 90 % of the seeds when it exceeds 3 sigma
at the top speed, and a wrong single name in <= 5 %; 95 % intervals cover
the truth in >= 90 %; a 16-sigma outlier reported as an outlier."""

from __future__ import annotations

import numpy as np
import polars as pl
import pytest
from diagnose_rates import hidden_runs, outcome, top_speed_sigma_real
from diagnose_toy import Rig, conditions, measured, top_speed_sigma

import thermobear as tb
from thermobear import diagnosis as D

BASE = Rig(["centrifugal"])
RICH = conditions(np.linspace(2000.0, 18000.0, 8), loads=(200.0, 900.0))
#: (speeds, loads, quantities, runs): the null designs, in turn
DESIGNS = [
    (np.linspace(3000.0, 15000.0, 4), (500.0,), ("heat_w", "inner_ring_temperature_c"), ("1",)),
    (np.linspace(2000.0, 18000.0, 8), (200.0, 900.0), ("heat_w", "axial_stiffness_seed_n_per_m"),
     ("1",)),
    (np.linspace(5000.0, 12000.0, 5), (400.0,),
     ("outer_ring_temperature_c", "axial_stiffness_seed_n_per_m", "heat_w"), ("a", "b")),
    (np.linspace(4000.0, 16000.0, 6), (300.0, 600.0),
     ("heat_w", "inner_ring_temperature_c", "outer_ring_temperature_c",
      "axial_stiffness_seed_n_per_m"), ("1",)),
]  # fmt: skip


def _at_3_sigma(option, null, step, cond):
    """The truth with ``option`` moved so that the largest change at the
    top speed is 3 typical sigma (the rig is linear in each option)."""
    one = top_speed_sigma(BASE.with_setting(**{option: null + step}), BASE, cond)
    return BASE.with_setting(**{option: null + 3.0 * step / one})


def test_null_false_discovery_over_200_seeds_on_varied_designs():
    found = 0
    for seed in range(200):
        sp, loads, qs, runs = DESIGNS[seed % len(DESIGNS)]
        cond = conditions(sp, loads=loads, quantities=qs, runs=runs)
        d = tb.diagnose(BASE, measured(BASE, cond, 10_000 + seed), suggest=False)
        found += d.verdict != "no missing effect supported"
    assert found <= 10


# (candidate, option, baseline value, a step of the option)
HIDDEN = [
    ("drag_coefficient", "drag_coefficient", 0.0, 0.1),
    ("lubrication_factor_f0", "lubrication_factor_f0", 1.0, 0.1),
    ("extra_heat_w", "extra_heat_w", 0.0, 1.0),
    ("ambient_temperature_offset_k", "ambient_temperature_c", 25.0, 1.0),
]


@pytest.mark.parametrize("name,option,null,step", HIDDEN)
def test_hidden_candidate_at_3_sigma_named_or_tied(name, option, null, step):
    truth = _at_3_sigma(option, null, step, RICH)
    out = [
        outcome(tb.diagnose(BASE, measured(truth, RICH, 20_000 + s), suggest=False), name)
        for s in range(30)
    ]
    assert out.count("right") + out.count("tie") >= 27, out
    assert out.count("wrong") <= 1, out


def test_sensor_offsets_named_not_physics():
    """A thermocouple offset of 3 sigma on To, a 6 % heat-meter gain error."""
    to = pl.col("quantity") == "outer_ring_temperature_c"
    heat = pl.col("quantity") == "heat_w"
    cases = [
        ("sensor_offset:outer_ring_temperature_c", pl.when(to).then(pl.col("value") + 1.5)),
        ("sensor_offset:heat_w", pl.when(heat).then(pl.col("value") * 1.06)),
    ]
    for name, change in cases:
        out = []
        for s in range(30):
            m = measured(BASE, RICH, 30_000 + s)
            m = m.with_columns(change.otherwise(pl.col("value")).alias("value"))
            out.append(outcome(tb.diagnose(BASE, m, suggest=False), name))
        assert out.count("right") + out.count("tie") >= 27 and out.count("wrong") <= 1, out


def test_an_unknown_smooth_effect_is_not_given_a_known_name():
    """A heat source ~ n^1.5 on the heat meter only, of a shape no candidate
    has (e.g. a seal): the workflow may say unresolved, tie with the generic
    control or unexplained -- it names a known effect in <= 5 % of seeds."""
    heat = pl.col("quantity") == "heat_w"
    named = 0
    for s in range(40):
        m = measured(BASE, RICH, 40_000 + s)
        n = m["speed_rpm"] / 1e4
        m = m.with_columns(
            pl.when(heat).then(pl.col("value") + 2.0 * n**1.5).otherwise(pl.col("value"))
        )
        named += bool(tb.diagnose(BASE, m, suggest=False).accepted)
    assert named <= 2


def test_a_16_sigma_outlier_is_an_outlier_over_seeds():
    rng = np.random.default_rng(5)
    reported = 0
    for s in range(40):
        m = measured(BASE, RICH, 50_000 + s)
        i = int(rng.integers(m.height))
        bump = 16.0 * m["sigma"][i] * (1 if rng.random() < 0.5 else -1)
        m = m.with_columns(pl.Series("value", m["value"].to_numpy() + bump * np.eye(m.height)[i]))
        d = tb.diagnose(BASE, m, suggest=False)
        reported += d.outliers.height == 1 and bool(d.points["outlier"][i])
        assert not d.accepted and "structured residual" not in d.verdict
    assert reported >= 36


def test_intervals_cover_over_100_seeds():
    cases = [
        (_at_3_sigma("lubrication_factor_f0", 1.0, 0.1, RICH), "lubrication_factor_f0", None),
        (BASE.with_setting(ambient_temperature_c=26.0), "ambient_temperature_offset_k", 1.0),
    ]
    for truth, name, value in cases:
        value = truth.options["lubrication_factor_f0"] if value is None else value
        covered = 0
        for s in range(100):
            d = tb.diagnose(BASE, measured(truth, RICH, 60_000 + s), [name], suggest=False)
            rec = (d.accepted or d.unresolved)[:1]  # nothing: counted as a miss
            covered += any(a["lower_95"] <= value <= a["upper_95"] for a in rec)
        assert covered >= 90, (name, covered)


# -- the real bearing model ----------------------------------------------------------------

_REAL: dict = {}


def _real(preset, **options):
    key = (preset, tuple(sorted(options.items())))
    if key not in _REAL:
        _REAL[key] = D.BearingModelSpec(tb.Bearing.preset(preset), **options)
    return _REAL[key]


def _real_conditions(preset) -> pl.DataFrame:
    if preset == "6208":  # deep-groove under radial load, 5 speeds, 3 quantities
        qs = [
            "outer_ring_temperature_c",
            "inner_ring_temperature_c",
            "radial_stiffness_seed_n_per_m",
        ]
        sp, loads = np.linspace(2000.0, 10000.0, 5), [(100.0, 2500.0)]
    else:  # hybrid angular-contact, two preloads, 6 speeds, 4 quantities
        qs = ["outer_ring_temperature_c", "ball_temperature_c", "heat_w", "axial_displacement_um"]
        sp, loads = np.linspace(3000.0, 15000.0, 6), [(500.0, 0.0), (1000.0, 0.0)]
    rows = [(s, a, r, q) for a, r in loads for s in sp for q in qs]
    return pl.DataFrame(rows, schema=["speed_rpm", "axial_n", "radial_n", "quantity"], orient="row")


@pytest.mark.parametrize("preset", ["6208", "7008C-hybrid"])
def test_real_model_null_over_100_seeds(preset):
    base, cond = _real(preset), _real_conditions(preset)
    found = sum(
        tb.diagnose(base, D.synthetic_measurements(base, cond, 1.0, s), suggest=False).verdict
        != "no missing effect supported"
        for s in range(100)
    )
    assert found <= 5


@pytest.mark.parametrize(
    "preset,option,value,name",
    [
        ("6208", "lubrication_factor_f0", 1.25, "lubrication_factor_f0"),
        ("7008C-hybrid", "extra_heat_w", 15.0, "extra_heat_w"),
        ("7008C-hybrid", "ambient_temperature_c", 28.0, "ambient_temperature_offset_k"),
    ],
)
def test_real_model_hidden_input_named_or_tied_and_covered(preset, option, value, name):
    base, cond = _real(preset), _real_conditions(preset)
    truth = _real(preset, **{option: value})
    assert top_speed_sigma_real(truth, base, cond) > 3.0
    truth_value = value - base.options[option] if name.endswith("_offset_k") else value
    out, covered, n = hidden_runs(
        base,
        lambda s: D.synthetic_measurements(truth, cond, 1.0, s),
        name,
        truth_value,
        range(70_000, 70_060),
    )
    assert out.count("right") + out.count("tie") >= 54 and out.count("wrong") <= 3, out
    assert n >= 54 and covered >= 0.9 * n, (covered, n)


def test_real_model_thermocouple_offset_interval_covers():
    """A +2 K thermocouple offset on the outer ring of a deep-groove 6208:
    named, or tied with its look-alike (an ambient temperature offset
    moves To most), and its 95 % interval covers 2 K."""
    base, cond = _real("6208"), _real_conditions("6208")
    to = pl.col("quantity") == "outer_ring_temperature_c"
    name = "sensor_offset:outer_ring_temperature_c"

    def offset(seed):
        m = D.synthetic_measurements(base, cond, 1.0, seed)
        return m.with_columns(pl.when(to).then(pl.col("value") + 2.0).otherwise(pl.col("value")))

    out, covered, n = hidden_runs(base, offset, name, 2.0, range(80_000, 80_060))
    assert out.count("right") + out.count("tie") >= 54 and out.count("wrong") <= 3, out
    assert n >= 54 and covered >= 0.9 * n, (covered, n)
