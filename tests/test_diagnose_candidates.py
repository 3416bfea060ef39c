"""The diagnosis candidates (missing effects, miscalibrated inputs), each
hidden in synthetic data and
recovered by name: an applied-load (preload) scale -- global and per load
level --, a sensor gain, the SKF-style heat model, on the spindle a preload
scale and the shaft runout a non-contact vibration probe sees; the bounds
of the drag oil fraction follow the lubrication method."""

from __future__ import annotations

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear import diagnosis as D

SPEEDS = np.linspace(2000.0, 18000.0, 6)
QS = ["outer_ring_temperature_c", "inner_ring_temperature_c", "axial_displacement_um"]
SEEDS = range(3)


@pytest.fixture(scope="module")
def base() -> D.BearingModelSpec:
    full = [e for e in tb.effects("switch")["name"].to_list() if e != "unbalanced_magnetic_pull"]
    return D.BearingModelSpec(tb.Bearing.preset("7008C"), effects=full)


def _cond(levels=(300.0,)) -> pl.DataFrame:
    rows = [(n, a, q) for a in levels for n in SPEEDS for q in QS]
    return pl.DataFrame(
        {
            "speed_rpm": [r[0] for r in rows],
            "axial_n": [r[1] for r in rows],
            "radial_n": 0.0,
            "quantity": [r[2] for r in rows],
        }
    )


def _measured(truth, cond, seed, sigma_k=0.3, gain=None):
    """Truth + noise: thermocouples sigma_k, displacement 0.2 um; ``gain``
    (quantity, g) multiplies one sensor's readings by 1 + g."""
    p = truth.predict(cond)
    q = np.array(cond["quantity"].to_list())
    v = np.array([p[qq][i] for i, qq in enumerate(q)])
    if gain is not None:
        v[q == gain[0]] *= 1.0 + gain[1]
    s = np.where(np.char.endswith(q.astype(str), "temperature_c"), sigma_k, 0.2)
    rng = np.random.default_rng(seed)
    return cond.with_columns(
        pl.Series("value", v + rng.normal(size=len(v)) * s), pl.Series("sigma", s)
    )


def _named(d) -> list[str]:
    return [a["name"] for a in d.accepted] + list(d.tie)


def test_new_candidates_are_listed_with_roles_and_bounds(base):
    c = tb.candidates(base, QS)
    row = {r["name"]: r for r in c.iter_rows(named=True)}
    assert row["axial_load_scale"]["role"] == "calibration"
    assert (row["axial_load_scale"]["lower"], row["axial_load_scale"]["upper"]) == (0.7, 1.3)
    assert row["heat_model:skf"]["role"] == "effect"
    assert row["sensor_gain:outer_ring_temperature_c"]["role"] == "measurement"
    assert row["sensor_gain:outer_ring_temperature_c"]["upper"] == 0.02
    assert row["sensor_gain:axial_displacement_um"]["upper"] == 0.10
    # a jet-lubricated baseline: f0 and drag bounds of the method
    jet = D.BearingModelSpec(base.bearing, effects=list(base.effects), lubrication="jet")
    assert jet.options["lubrication_factor_f0"] == 6.6
    assert jet.options["churning_oil_fraction"] == 0.03
    cj = {r["name"]: r for r in tb.candidates(jet, QS).iter_rows(named=True)}
    assert (cj["churning_oil_fraction"]["lower"], cj["churning_oil_fraction"]["upper"]) == (
        0.005, 0.1,
    )  # fmt: skip
    assert (cj["lubrication_factor_f0"]["lower"], cj["lubrication_factor_f0"]["upper"]) == (
        3.3, 13.2,
    )  # fmt: skip
    # the SKF baseline calibrates its own inputs and offers Palmgren back
    skf = base.with_setting(heat_model="skf")
    cs = set(tb.candidates(skf, QS)["name"])
    assert {"heat_model:palmgren", "sliding_friction_ehl", "replenishment_krs"} <= cs
    assert "heat_model:skf" not in cs
    with pytest.raises(tb.ConfigError, match="option"):
        D.BearingModelSpec(base.bearing, magic_scale=1.0)


def test_load_scale_moves_only_the_applied_load(base):
    cond = _cond((300.0,)).filter(pl.col("quantity") == "axial_displacement_um")
    scaled = base.with_setting(axial_load_scale=1.2).predict(cond)
    direct = base.predict(cond.with_columns(pl.lit(360.0).alias("axial_n")))
    np.testing.assert_array_equal(scaled["axial_displacement_um"], direct["axial_displacement_um"])
    per_level = base.with_setting(**{"axial_load_scale@300": 1.2}).predict(cond)
    np.testing.assert_array_equal(
        per_level["outer_ring_temperature_c"], direct["outer_ring_temperature_c"]
    )


def test_preload_20_percent_high_is_a_preload_scale_not_a_sensor_offset(base):
    truth = base.with_setting(axial_load_scale=1.2)
    for levels in ((300.0,), (300.0, 600.0)):
        cond = _cond(levels)
        for seed in SEEDS:
            d = tb.diagnose(base, _measured(truth, cond, seed))
            assert _named(d) == ["axial_load_scale"], d.verdict
            a = d.accepted[0]
            assert a["lower_95"] <= 1.2 <= a["upper_95"], d.verdict


def test_preload_off_at_one_level_is_named_with_its_level(base):
    cond = _cond((300.0, 600.0))
    truth = base.with_setting(**{"axial_load_scale@600": 1.2})
    names = tb.candidates(base, QS)["name"].to_list() + [
        "axial_load_scale@300",
        "axial_load_scale@600",
    ]
    for seed in SEEDS:
        d = tb.diagnose(base, _measured(truth, cond, seed), candidates=names)
        assert _named(d) == ["axial_load_scale@600"], d.verdict


def test_hidden_sensor_gain_is_named_as_gain(base):
    cond = _cond()
    for seed in SEEDS:
        d = tb.diagnose(
            base,
            _measured(base, cond, seed, sigma_k=0.05, gain=("inner_ring_temperature_c", 0.015)),
        )
        assert _named(d) == ["sensor_gain:inner_ring_temperature_c"], d.verdict
        assert d.accepted[0]["lower_95"] <= 0.015 <= d.accepted[0]["upper_95"]


def test_hidden_skf_heat_model_is_named(base):
    cond = _cond()
    truth = base.with_setting(heat_model="skf")
    for seed in SEEDS:
        d = tb.diagnose(base, _measured(truth, cond, seed))
        assert _named(d) == ["heat_model:skf"], d.verdict
        assert d.verdict.startswith("missing effect heat_model:skf")


# ------------------------------------------------------------------ spindle

SPINDLE_SPEEDS = np.arange(6000.0, 18001.0, 2000.0)


@pytest.fixture(scope="module")
def spindle_base() -> D.SpindleModelSpec:
    return D.SpindleModelSpec(tb.Spindle.preset("seed-ceramic-spindle"))


def _spindle_measured(truth, quantities, seed):
    cond = pl.DataFrame(
        {
            "speed_rpm": np.repeat(SPINDLE_SPEEDS, len(quantities)),
            "preload_n": 400.0,
            "quantity": list(quantities) * len(SPINDLE_SPEEDS),
        }
    )
    p = truth.predict(cond.rename({"preload_n": "axial_n"}))
    q = cond["quantity"].to_list()
    v = np.array([p[qq][i] for i, qq in enumerate(q)])
    rel = {"velocity_rms_mm_s": 0.05, "operating_preload_n": 0.02}
    s = np.array([rel[qq] * x if qq in rel else 0.2 for qq, x in zip(q, v, strict=True)])
    rng = np.random.default_rng(seed)
    return cond.with_columns(
        pl.Series("value", v + rng.normal(size=len(v)) * s), pl.Series("sigma", s)
    )


def test_runout_reads_as_omega_times_epsilon(spindle_base):
    cond = pl.DataFrame({"speed_rpm": [6000.0, 18000.0], "axial_n": 400.0, "radial_n": 0.0})
    v0 = spindle_base.predict(cond)["velocity_rms_mm_s"]
    v = spindle_base.with_setting(runout_um=20.0).predict(cond)["velocity_rms_mm_s"]
    omega = 2 * np.pi * np.array([6000.0, 18000.0]) / 60
    np.testing.assert_allclose(v**2 - v0**2, (omega * 20e-3) ** 2 / 2, rtol=1e-9)
    # a 20 um runout at 18,000 rpm alone reads 26.7 mm/s RMS
    assert v[1] == pytest.approx(26.66, abs=0.05)


def test_hidden_runout_on_the_vibration_is_named_as_runout(spindle_base):
    qs = ["front_outer_ring_temperature_c", "rear_outer_ring_temperature_c", "velocity_rms_mm_s",
          "axial_growth_um"]  # fmt: skip
    truth = spindle_base.with_setting(runout_um=20.0)
    for seed in SEEDS:
        d = tb.diagnose(spindle_base, _spindle_measured(truth, qs, seed))
        assert _named(d) == ["runout_um"], d.verdict
        assert d.accepted[0]["role"] == "measurement"
        assert d.accepted[0]["lower_95"] <= 20.0 <= d.accepted[0]["upper_95"]


def test_spindle_preload_20_percent_high_is_named_preload_scale(spindle_base):
    qs = ["front_inner_ring_temperature_c", "rear_inner_ring_temperature_c", "axial_growth_um",
          "operating_preload_n"]  # fmt: skip
    truth = spindle_base.with_setting(preload_scale=1.2)
    for seed in SEEDS:
        d = tb.diagnose(spindle_base, _spindle_measured(truth, qs, seed))
        assert _named(d) == ["preload_scale"], d.verdict


@pytest.mark.parametrize(
    "setting,name",
    [({"unbalance_grade": 5.0}, "unbalance_grade"), ({"heat_model": "skf"}, "heat_model:skf")],
)
def test_hidden_unbalance_and_heat_model_on_the_spindle(spindle_base, setting, name):
    # a G5 rotor against the G2.5 baseline grows like the unbalance response
    # (not like the omega x runout of the probe); the SKF-style heat model
    # against Palmgren shows in the temperatures and the axial growth
    qs = ["front_outer_ring_temperature_c", "rear_outer_ring_temperature_c", "velocity_rms_mm_s",
          "axial_growth_um"]  # fmt: skip
    truth = spindle_base.with_setting(**setting)
    for seed in SEEDS:
        d = tb.diagnose(spindle_base, _spindle_measured(truth, qs, seed))
        assert _named(d) == [name], d.verdict
