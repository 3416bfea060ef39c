"""A displacement probe zeroed at a reference speed reads the change of the
displacement from there: the relative quantities
(``axial_displacement_change_um``; a spindle's ``axial_growth_change_um``,
``radial_displacement_change_um``) are predicted as that change, diagnosed
as such, and the same readings given as the absolute quantity get the
zeroed-probe hint."""

from __future__ import annotations

import warnings

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear import diagnosis as D
from thermobear.diagnosis.relative import CHANGE_OF, REFERENCE_SPEED, reference_speeds

CHANGE = "axial_displacement_change_um"
ABSOLUTE = "axial_displacement_um"
SPEEDS_RPM = np.linspace(2000.0, 12000.0, 6)
QUANTITIES = ["outer_ring_temperature_c", "heat_w", CHANGE]
F0_TRUE = 2.0


@pytest.fixture(scope="module")
def base() -> D.BearingModelSpec:
    return D.BearingModelSpec(tb.Bearing.preset("7008C"))


@pytest.fixture(scope="module")
def measured(base) -> pl.DataFrame:
    """Outer-ring temperature, heat and the axial displacement of a probe
    zeroed at the lowest speed, made by the model with f0 = 2 (the
    baseline's is 1), typical noise."""
    cond = pl.DataFrame({"speed_rpm": np.repeat(SPEEDS_RPM, len(QUANTITIES)), "axial_n": 300.0,
                         "radial_n": 0.0, "quantity": QUANTITIES * len(SPEEDS_RPM)})  # fmt: skip
    return D.synthetic_measurements(base.with_setting(lubrication_factor_f0=F0_TRUE), cond, 1.0, 0)


def test_the_change_is_the_displacement_less_its_value_at_the_lowest_speed(base):
    speeds = [4000.0, 2000.0, 6000.0, 3000.0, 9000.0]
    loads = [300.0, 300.0, 300.0, 600.0, 600.0]
    cond = pl.DataFrame({"speed_rpm": speeds, "axial_n": loads, "radial_n": 0.0})
    p = base.predict(cond)
    a = p[ABSOLUTE]
    expected = [a[0] - a[1], 0.0, a[2] - a[1], 0.0, a[4] - a[3]]  # per load level
    np.testing.assert_allclose(p[CHANGE], expected, rtol=0, atol=1e-12)
    assert abs(a[1]) > 50.0  # the absolute displacement is far from 0 there


def test_a_reference_speed_column_sets_the_zero_even_off_the_rows(base):
    cond = pl.DataFrame({"speed_rpm": [4000.0, 6000.0], "axial_n": 300.0, "radial_n": 0.0,
                         REFERENCE_SPEED: [1000.0, None]})  # fmt: skip
    p = base.predict(cond)
    at_ref = base.predict(pl.DataFrame({"speed_rpm": [1000.0], "axial_n": 300.0,
                                        "radial_n": 0.0}))[ABSOLUTE][0]  # fmt: skip
    assert p[CHANGE][0] == pytest.approx(p[ABSOLUTE][0] - at_ref, abs=1e-12)
    assert p[CHANGE][1] == pytest.approx(p[ABSOLUTE][1] - p[ABSOLUTE][0], abs=1e-12)


def test_a_spindle_predicts_the_change_of_its_growth_and_radial_displacement():
    spec = D.SpindleModelSpec(tb.Spindle.preset("seed-ceramic-spindle"))
    assert {"axial_growth_change_um", "radial_displacement_change_um"} <= set(spec.quantities)
    p = spec.predict(pl.DataFrame({"speed_rpm": [3000.0, 9000.0], "preload_n": 300.0}))
    for change in ("axial_growth_change_um", "radial_displacement_change_um"):
        absolute = p[CHANGE_OF[change]]
        np.testing.assert_allclose(p[change], absolute - absolute[0], rtol=0, atol=1e-12)
    assert p["axial_growth_change_um"][1] > 1.0  # the shaft grows with speed


def test_the_loader_takes_the_change_and_knows_its_reference(measured):
    df = tb.load_measurements(measured, model="bearing")
    ref = reference_speeds(df)
    is_change = (df["quantity"] == CHANGE).to_numpy()
    assert np.all(ref[is_change] == SPEEDS_RPM[0]) and np.all(np.isnan(ref[~is_change]))
    # a change quantity that does not read 0 at its lowest speed: its zero is missing
    late = measured.filter(pl.col("speed_rpm") > SPEEDS_RPM[0])
    with pytest.warns(tb.PlausibilityWarning, match=f"{CHANGE} reads .* at speed_rpm = 4000"):
        tb.load_measurements(late, model="bearing")
    with warnings.catch_warnings():
        warnings.simplefilter("error", tb.PlausibilityWarning)
        tb.load_measurements(measured, model="bearing")


def test_a_zeroed_probe_diagnoses_as_its_effect_as_the_relative_quantity(base, measured):
    d = tb.diagnose(base, measured)
    assert [a["name"] for a in d.accepted] == ["lubrication_factor_f0"], d.verdict
    a = d.accepted[0]
    assert a["lower_95"] <= F0_TRUE <= a["upper_95"], d.verdict
    assert "not explained" not in d.verdict and "structured" not in d.verdict
    # its prediction: 0 at the lowest speed, the measured change elsewhere
    p = tb.predict(d, "growth").filter(pl.col("quantity") == CHANGE).sort("speed_rpm")
    got = measured.filter(pl.col("quantity") == CHANGE).sort("speed_rpm")
    assert p["value"][0] == 0.0
    assert np.all(
        np.abs(p["value"].to_numpy() - got["value"].to_numpy()) < 4.0 * got["sigma"].to_numpy()
    )


def test_the_same_readings_as_the_absolute_quantity_get_the_zeroed_probe_hint(base, measured):
    absolute = measured.with_columns(pl.col("quantity").replace({CHANGE: ABSOLUTE}))
    d = tb.diagnose(base, absolute)
    assert "not explained by any known effect" in d.verdict, d.verdict
    hint = d.verdict.split("likely cause: ", 1)[1]
    assert hint.startswith(f"{ABSOLUTE} looks shifted by a constant"), d.verdict
    assert "zeroed at that speed" in hint and f"reads about 0 at {SPEEDS_RPM[0]:g} rpm" in hint
    assert CHANGE in hint
    assert d.model.provenance["verdict"] == d.verdict
