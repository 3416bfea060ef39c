"""The oil supply as a model input: the cavity oil fraction follows the
supply and the speed (Parker's correlation), the oil bath takes the SKF drag
form, and every heat output splits its heat into rolling, sliding, spin,
drag, churning, seal and extra parts that sum to the total."""

from __future__ import annotations

import numpy as np
import pytest

import thermobear as tb

SPLIT = (
    "rolling_heat_w",
    "sliding_heat_w",
    "spin_heat_w",
    "drag_heat_w",
    "ring_cage_churning_heat_w",
    "seal_heat_w",
    "extra_heat_w",
)
FA, FR = 2680.9, 1189.9


@pytest.fixture(scope="module")
def b6208() -> tb.Bearing:
    return tb.Bearing.preset("6208")


def _iso(b: tb.Bearing, n: float, **kw: object) -> dict:
    return tb.isothermal_heat(b, n, FA, FR, oil_temperature_c=60.0, **kw).raw


@pytest.mark.parametrize(
    "kw",
    [
        {},
        {"lubrication": "jet"},
        {"lubrication": "jet", "oil_flow_cm3_per_min": 400.0, "jet_count": 2},
        {"lubrication": "oil-bath"},
        {"lubrication": "oil-bath", "oil_level_mm": 20.0, "heat_model": "skf"},
        {"lubrication": "oil-air", "oil_volume_cm3_per_h": 0.6, "air_flow_l_per_min": 40.0},
        {"lubrication": "grease", "grease_fill_fraction": 0.3, "extra_heat_w": 4.0},
    ],
)
def test_split_sums_to_the_total_in_isothermal_and_thermal_state(b6208, kw):
    r = _iso(b6208, 7000.0, **kw)
    assert sum(r[k] for k in SPLIT) == pytest.approx(r["total_heat_w"], rel=1e-12)
    s = tb.thermal_state(b6208, speed_rpm=7000.0, axial_n=FA, radial_n=FR, **kw).raw
    assert sum(s[k] for k in SPLIT) == pytest.approx(s["total_heat_w"], rel=1e-12)


def test_split_sums_to_the_total_in_the_thermal_stiffness_frame(b6208):
    df = tb.stiffness_curve(
        b6208, [6500.0, 12000.0], FA, FR, mode="thermal", lubrication="jet",
        oil_flow_cm3_per_min=300.0,
    )  # fmt: skip
    parts = sum(df[k].to_numpy() for k in SPLIT)
    np.testing.assert_allclose(parts, df["heat_w"].to_numpy(), rtol=1e-12)
    x = df["cavity_oil_fraction"].to_numpy()
    assert x[0] / x[1] == pytest.approx(12000.0 / 6500.0, rel=1e-12)


@pytest.mark.filterwarnings("ignore:oil_flow_cm3_per_min = 0:thermobear.PlausibilityWarning")
def test_zero_flow_no_drag_and_the_fraction_follows_flow_and_speed(b6208):
    assert _iso(b6208, 12000.0, lubrication="jet", oil_flow_cm3_per_min=0.0)["drag_heat_w"] == 0.0
    x = {
        (w, n): _iso(b6208, n, lubrication="jet", oil_flow_cm3_per_min=w)["cavity_oil_fraction"]
        for w in (200.0, 800.0)
        for n in (6000.0, 12000.0)
    }
    assert x[(200.0, 6000.0)] / x[(200.0, 12000.0)] == pytest.approx(2.0, rel=1e-12)
    assert x[(800.0, 6000.0)] / x[(200.0, 6000.0)] == pytest.approx(4.0**0.37, rel=1e-12)


def test_bath_drag_grows_as_speed_squared(b6208):
    d = [_iso(b6208, n, lubrication="oil-bath")["drag_heat_w"] for n in (2000.0, 4000.0)]
    # Moment ~ n^2, so the power ~ n^3.
    assert d[1] / d[0] == pytest.approx(8.0, rel=1e-9)


def test_supply_keywords_are_checked(b6208):
    with pytest.raises(tb.ConfigError, match="oil_level_mm"):
        _iso(b6208, 7000.0, lubrication="jet", oil_level_mm=10.0)
    with pytest.raises(tb.ConfigError, match="churning_oil_fraction"):
        _iso(b6208, 7000.0, lubrication="jet", oil_flow_cm3_per_min=10.0, churning_oil_fraction=0.1)
    with pytest.raises(tb.ConfigError, match="oil_flow_cm3_per_min"):
        _iso(b6208, 7000.0, lubrication="jet", jet_count=2)
    with pytest.raises(tb.ConfigError, match="oil_flow_cm3_per_min"):
        _iso(b6208, 7000.0, lubrication="jet", oil_flow_cm3_per_min=-5.0)


def test_spindle_rows_split_sums_to_each_bearing_heat():
    sp = tb.Spindle.preset("seed-ceramic-spindle").with_options(
        lubrication="oil-air", oil_volume_cm3_per_h=0.6, air_flow_l_per_min=40.0
    )
    raw = sp._native.steady_state(12000.0)
    assert min(raw["drag_heat_w"]) > 0.0
    heat = np.asarray(raw["bearing_heat_w"])
    parts = sum(np.asarray(raw[k]) for k in SPLIT)
    np.testing.assert_allclose(parts, heat, rtol=1e-12)
