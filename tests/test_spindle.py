"""Spindle (seed B) from Python: physical truths through the bindings."""

from __future__ import annotations

import math

import polars as pl
import pytest

import thermobear as tb


@pytest.fixture(scope="module")
def ceramic() -> tb.Spindle:
    return tb.Spindle.preset("seed-ceramic-spindle").with_options(
        preload_kind="spring", spring_rate_n_per_um=0.36
    )


def test_presets_and_assumptions() -> None:
    sp = tb.Spindle.preset("seed-ceramic-spindle")
    a = sp.assumptions
    assert a["ball_material"].lower() == "si3n4"
    assert (
        tb.Spindle.preset("seed-steel-spindle").assumptions["ball_material"] != a["ball_material"]
    )
    assert a["front_bearing"].startswith("7009C") and a["rear_bearing"].startswith("7008C")
    with pytest.raises(tb.ConfigError, match="spindle"):
        tb.Spindle.preset("seed-gold-spindle")
    with pytest.raises(tb.ConfigError, match="preload_kind"):
        sp.with_options(preload_kind="magnetic")


def test_thermal_state_heat_balance_and_dispatch(ceramic: tb.Spindle) -> None:
    df = tb.thermal_state(ceramic, speed_rpm=12_000.0)
    assert isinstance(df, pl.DataFrame) and df.height == 1
    row = df.row(0, named=True)
    # All heat generated leaves through water, air and oil-air.
    assert row["boundary_flow_w"] == pytest.approx(row["total_heat_w"], rel=1e-6)
    assert row["total_heat_w"] == pytest.approx(
        row["motor_losses_w"] + row["bearing_heat_w"], rel=1e-9
    )
    # Seed B's ordering: balls hotter than inner ring hotter than outer ring.
    assert (
        row["front_ball_temperature_c"]
        > row["front_inner_ring_temperature_c"]
        > row["front_outer_ring_temperature_c"]
        > 25.0
    )
    assert all(
        c.endswith(("_c", "_n", "_w", "_um", "_deg", "_rpm", "_m", "_k", "_n_per_m"))
        or c in ("preload_kind", "iterations")
        for c in df.columns
    )


def test_temperatures_rise_with_speed_and_preload(ceramic: tb.Spindle) -> None:
    t = [
        tb.thermal_state(ceramic, speed_rpm=n)["front_ball_temperature_c"][0]
        for n in (6_000.0, 18_000.0)
    ]
    assert t[1] > t[0]
    p = [
        tb.thermal_state(ceramic, speed_rpm=12_000.0, preload_n=f)["front_ball_temperature_c"][0]
        for f in (250.0, 500.0)
    ]
    assert p[1] > p[0]


def test_ceramic_balls_less_thermal_displacement() -> None:
    kw = dict(preload_kind="spring", spring_rate_n_per_um=0.36)
    c = tb.Spindle.preset("seed-ceramic-spindle").with_options(**kw)
    s = tb.Spindle.preset("seed-steel-spindle").with_options(**kw)
    dc = tb.thermal_state(c, speed_rpm=18_000.0)["thermal_radial_displacement_um"][0]
    ds = tb.thermal_state(s, speed_rpm=18_000.0)["thermal_radial_displacement_um"][0]
    assert 0.0 < dc < ds


def test_transient_approaches_steady(ceramic: tb.Spindle) -> None:
    steady = tb.thermal_state(ceramic, speed_rpm=12_000.0)
    df = tb.transient(ceramic, speed_rpm=12_000.0, duration_s=8_000.0, dt_s=40.0, record_every=10)
    assert df.columns[0] == "time_s" and all(c.endswith("_temperature_c") for c in df.columns[1:])
    assert df["time_s"][-1] == pytest.approx(8_000.0)
    for node in (
        "front_ball_temperature_c",
        "front_inner_ring_temperature_c",
        "rotor_temperature_c",
    ):
        assert df[node][-1] == pytest.approx(steady[node][0], abs=0.05)
    # Starts at ambient (25 C) and warms up.
    assert (
        df["rotor_temperature_c"][0] == pytest.approx(25.0) and df["rotor_temperature_c"][-1] > 30.0
    )


def test_compensation_preload_is_rate_times_growth(ceramic: tb.Spindle) -> None:
    df = tb.compensation_preload(
        ceramic, speeds_rpm=[12_000.0, 18_000.0], spring_rate_n_per_um=0.36
    )
    assert list(df["speed_rpm"]) == [12_000.0, 18_000.0]
    for u, f in zip(df["axial_growth_um"], df["compensation_preload_n"], strict=False):
        assert f == pytest.approx(0.36 * u, rel=1e-12)
    # Hotter at higher speed: more growth, more compensation.
    assert df["axial_growth_um"][1] > df["axial_growth_um"][0] > 0.0


def test_optimal_preload_is_grid_minimum(ceramic: tb.Spindle) -> None:
    calls: list[tuple[int, int]] = []
    loaded = ceramic.with_options(radial_load_n=500.0)
    grid = tb.spindle_grid(
        loaded,
        speeds_rpm=[12_000.0],
        preloads_n=[200.0, 400.0, 600.0],
        progress=lambda d, t: calls.append((d, t)),
    )
    assert calls and calls[-1] == (3, 3)
    # More preload: stiffer (less mechanical displacement), hotter (more thermal displacement).
    g = grid.sort("preload_n")
    assert g["mechanical_radial_displacement_um"].is_sorted(descending=True)
    assert g["thermal_radial_displacement_um"].is_sorted()
    best = tb.optimal_preload(loaded, speeds_rpm=[12_000.0], preloads_n=[200.0, 400.0, 600.0])
    i = int(g["total_radial_displacement_um"].arg_min())
    assert best["optimal_preload_n"][0] == g["preload_n"][i]
    assert best["min_radial_displacement_um"][0] == pytest.approx(
        g["total_radial_displacement_um"].min()
    )
    assert not math.isnan(best["min_radial_displacement_um"][0])


def test_bad_input(ceramic: tb.Spindle) -> None:
    with pytest.raises(tb.ConfigError, match="speed_rpm"):
        tb.thermal_state(ceramic, speed_rpm=-1.0)
    with pytest.raises(tb.ConfigError, match="dt_s"):
        tb.transient(ceramic, speed_rpm=12_000.0, duration_s=60.0, dt_s=0.0)
    with pytest.raises(tb.ConfigError):
        tb.transient("not a spindle", speed_rpm=1.0, duration_s=1.0)
    with pytest.raises(tb.ConfigError, match="preloads_n"):
        tb.spindle_grid(ceramic, speeds_rpm=[12_000.0], preloads_n=[-5.0])


def test_rigid_steel_runaway_reported() -> None:
    sp = tb.Spindle.preset("seed-steel-spindle").with_options(preload_kind="rigid", preload_n=300.0)
    assert sp.preload_kind == "rigid"
    with pytest.raises(tb.ThermalRunawayError, match="preload grew"):
        tb.thermal_state(sp, speed_rpm=18_000.0)


def test_thermal_state_dispatches_to_a_spindle():
    sp = tb.Spindle.preset("seed-ceramic-spindle")
    a = tb.thermal_state(sp, speed_rpm=9000.0)
    b = sp.thermal_state(speed_rpm=9000.0)
    assert a.equals(b)
    with pytest.raises(tb.ConfigError, match="axial_n"):
        tb.thermal_state(sp, speed_rpm=9000.0, axial_n=100.0)
