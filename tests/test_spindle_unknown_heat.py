"""An extra heat at a spindle's front bearing set, constant
(``extra_heat_w``) or with its own speed law (``unknown_heat_*``): the
heat balance it enters, the paths a user reaches it by, and the unknown
heat source of an "unresolved" spindle diagnosis acting through it, so
that the member predicts the stiffness from temperatures alone."""

from __future__ import annotations

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear import diagnosis as D

SPEED = 12_000.0
LAW = {
    "unknown_heat_linear_w": 30.0,
    "unknown_heat_quadratic_w": 20.0,
    "unknown_heat_reference_rpm": 10_000.0,
}


@pytest.fixture(scope="module")
def spindle() -> tb.Spindle:
    return tb.Spindle.preset("seed-ceramic-spindle")


def _row(sp, **kw) -> dict:
    return tb.thermal_state(sp, speed_rpm=SPEED, **kw).row(0, named=True)


def _numbers(row: dict) -> dict:
    return {k: v for k, v in row.items() if isinstance(v, float)}


def test_extra_heat_closes_the_heat_balance_and_warms_the_front_set(spindle):
    """The heat reported for the bearings carries the extra heat; sources
    equal motor plus bearing heat; the front set warms more than the rear."""
    base, hot = _row(spindle), _row(spindle.with_options(extra_heat_w=80.0))
    assert hot["total_heat_w"] == pytest.approx(hot["motor_losses_w"] + hot["bearing_heat_w"])
    # each front bearing carries 40 W more, less the friction the warmer,
    # thinner oil no longer makes (the exact 40 W: the core's own test)
    assert 0.0 < hot["front_bearing_heat_w"] - base["front_bearing_heat_w"] < 40.0
    rise_front = hot["front_outer_ring_temperature_c"] - base["front_outer_ring_temperature_c"]
    rise_rear = hot["rear_outer_ring_temperature_c"] - base["rear_outer_ring_temperature_c"]
    assert rise_front > rise_rear > 0.0
    # zero is the spindle as it was, bit for bit
    assert _row(spindle.with_options(extra_heat_w=0.0)) == base


def test_the_law_is_the_extra_heat_of_its_speed_on_every_path(spindle):
    """30 x + 20 x^2 at x = 1.2: 64.8 W, through with_options, through the
    thermal_state keywords, and as a constant extra heat: the same state."""
    want = _numbers(_row(spindle.with_options(extra_heat_w=64.8)))
    assert _numbers(_row(spindle.with_options(**LAW))) == pytest.approx(want, rel=1e-12)
    assert _numbers(_row(spindle, **LAW)) == pytest.approx(want, rel=1e-12)
    assert _numbers(_row(spindle, extra_heat_w=64.8)) == want


@pytest.mark.parametrize(
    "kw, field",
    [
        ({"extra_heat_w": -1.0}, "extra_heat_w"),
        ({"extra_heat_w": float("nan")}, "extra_heat_w"),
        ({"unknown_heat_linear_w": 5.0}, "unknown_heat_reference_rpm"),
    ],
)
def test_bad_extra_heat_is_named(spindle, kw, field):
    with pytest.raises(tb.ConfigError, match=field):
        spindle.with_options(**kw)


def test_a_spindle_with_extra_heat_has_no_description(spindle):
    """A description file has no part for the heat: writing one is refused
    by name rather than dropping the heat."""
    with pytest.raises(tb.ConfigError, match="extra_heat_w"):
        spindle.with_options(extra_heat_w=10.0).to_toml()
    with pytest.raises(tb.ConfigError, match="unknown_heat_linear_w"):
        spindle.with_options(**LAW).to_toml()
    assert spindle.with_options(extra_heat_w=0.0).to_toml() == spindle.to_toml()


SPEEDS = [6000.0, 9000.0, 12000.0, 15000.0]
FAR = [18000.0]
QUANTITIES = [
    "front_outer_ring_temperature_c",
    "front_inner_ring_temperature_c",
    "front_ball_temperature_c",
    "rear_outer_ring_temperature_c",
]


def test_an_unknown_heat_source_predicts_spindle_stiffness_from_temperatures(spindle):
    """Temperatures alone and a hidden heat at the front set growing like
    n^1.5 (no registry input has that law): the unknown member of the
    diagnosis is a heat source acting through the spindle's heat balance,
    so the k_xx it predicts beyond the measured speeds has a finite,
    non-zero band that covers the truth; downstream, the member's spindle
    is the spec's model."""
    base = D.SpindleModelSpec(spindle)

    def truth(n: float) -> D.SpindleModelSpec:
        return base.with_setting(extra_heat_w=float(60.0 * (n / 15000.0) ** 1.5))

    cond = pl.DataFrame(
        [(n, 400.0, q) for n in SPEEDS for q in QUANTITIES],
        schema=["speed_rpm", "preload_n", "quantity"],
        orient="row",
    )
    values = np.array(
        [truth(n).predict(cond[i].rename({"preload_n": "axial_n"}))[q][0]
         for i, (n, q) in enumerate(zip(cond["speed_rpm"], cond["quantity"], strict=True))]
    )  # fmt: skip
    sigma = np.full(values.size, 0.3)
    noise = np.random.default_rng(7).normal(size=values.size)
    data = cond.with_columns(pl.Series("value", values + noise * sigma), pl.Series("sigma", sigma))
    d = tb.diagnose(base, data)
    unknown = [m for m in d.model.members if "unknown heat source" in m.label]
    assert d.model.kind in ("unresolved", "tie") and len(unknown) == 1, d.verdict
    member = unknown[0]
    pred = tb.predict(d.model, "stiffness", {"speeds_rpm": FAR, "preload_n": 400.0})
    k = pred.filter((pl.col("quantity") == "k_xx_n_per_m") & (pl.col("member") == member.label))
    lo, hi = float(k["lower"][0]), float(k["upper"][0])
    exact = float(truth(FAR[0]).predict(pl.DataFrame({"speed_rpm": FAR, "axial_n": 400.0}))[
        "k_xx_n_per_m"][0])  # fmt: skip
    assert np.isfinite(lo) and np.isfinite(hi) and hi > lo
    assert lo <= exact <= hi
    # the member's spindle carries the law: its thermal state is the spec's
    sp, _ = member.model()
    got = tb.thermal_state(d.model, speed_rpm=FAR[0], member=member.label).row(0, named=True)
    want = member.spec.predict(pl.DataFrame({"speed_rpm": FAR, "axial_n": 400.0}))
    assert got["front_outer_ring_temperature_c"] == pytest.approx(
        float(want["front_outer_ring_temperature_c"][0]), rel=1e-12
    )
    assert float(sp.assumptions["unknown_heat_reference_rpm"]) == max(SPEEDS)
