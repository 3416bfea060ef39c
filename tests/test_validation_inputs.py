"""Bad input is refused by name, implausible physics is warned about, and
physics past the model is refused: the reproducers of stray exceptions and
silently accepted physics, each as a test, and the validation layer's rules.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

import thermobear as tb
from thermobear import _validate as v
from thermobear import plausibility


@pytest.fixture(scope="module")
def b6208() -> tb.Bearing:
    return tb.Bearing.preset("6208")


# -- the validation layer ----------------------------------------------------------


@pytest.mark.parametrize("bad", [None, "1000", True, False, [1.0], math.nan, math.inf, object()])
def test_a_real_refuses_non_numbers_and_non_finite_values_by_name(bad):
    with pytest.raises(tb.ConfigError, match=r"invalid speed_rpm = .*must be a finite number"):
        v.real("speed_rpm", bad, 0.0)


def test_a_real_accepts_numpy_numbers_and_states_its_range():
    assert v.real("x", np.float32(2.5)) == 2.5 and v.real("x", np.int64(3)) == 3.0
    with pytest.raises(tb.ConfigError, match=r"x = -1: must be a finite number >= 0"):
        v.real("x", -1, 0.0)
    with pytest.raises(tb.ConfigError, match=r"in \(0, 1\]"):
        v.real("x", 0.0, 0.0, 1.0, open_lo=True)


def test_a_whole_number_takes_9_and_9_0_but_not_9_5_or_true():
    assert v.whole("ball_count", 9.0, 1) == 9
    for bad in (9.5, True, "9", -1, math.inf, math.nan):
        with pytest.raises(tb.ConfigError, match="ball_count"):
            v.whole("ball_count", bad, 1)


def test_a_sequence_names_its_first_bad_entry():
    with pytest.raises(tb.ConfigError, match=r"speeds_rpm\[2\] = nan"):
        v.reals("speeds_rpm", [1.0, 2.0, math.nan], 0.0)
    with pytest.raises(tb.ConfigError, match=r"speeds_rpm = '1000'"):
        v.reals("speeds_rpm", "1000", 0.0)


# -- errors that name nothing (now they name the argument) --------------------------


def test_speed_none_is_a_config_error_naming_speed(b6208):
    with pytest.raises(tb.ConfigError, match=r"invalid speed_rpm = None"):
        b6208.solve(speed_rpm=None)


def test_a_string_speed_is_refused_by_bearing_and_spindle_alike(b6208):
    with pytest.raises(tb.ConfigError, match=r"speed_rpm = '1000'.*not a str"):
        b6208.solve(speed_rpm="1000")
    sp = tb.Spindle.preset("seed-ceramic-spindle")
    with pytest.raises(tb.ConfigError, match=r"speed_rpm = '1000'.*not a str"):
        tb.thermal_state(sp, speed_rpm="1000")


def test_record_every_minus_one_is_a_named_config_error():
    sp = tb.Spindle.preset("seed-ceramic-spindle")
    with pytest.raises(tb.ConfigError, match=r"invalid record_every = -1: must be a whole"):
        tb.transient(sp, speed_rpm=12000, duration_s=20.0, dt_s=10.0, record_every=-1)


def test_threads_that_are_not_a_count_are_config_errors(b6208):
    for bad in (math.nan, math.inf, [], "2"):
        with pytest.raises(tb.ConfigError, match="threads"):
            b6208.solve_many({"axial_n": [500.0]}, threads=bad)


def test_a_huge_finite_load_names_the_input_and_shows_it_short(b6208):
    """1e300 N is a finite number: the solve cannot be done, and the error
    says which input made it impossible, in exponent form."""
    with pytest.raises(tb.ThermobearError) as e:
        b6208.solve(radial_n=1e300)
    assert "radial_n = 1e+300" in str(e.value), str(e.value)
    with pytest.raises(tb.ThermobearError) as e:
        b6208.solve(axial_n=1e300)
    assert "1e300" in str(e.value) or "1e+300" in str(e.value)
    assert len(str(e.value)) < 300


# -- physics accepted silently (now a warning or an error) --------------------------


def test_a_million_rpm_is_past_any_lubrication_and_past_the_model(b6208):
    """At 1e6 rpm (n dm = 6e7 mm rpm, 17 times the fastest jet-lubricated
    bearings) the balls' centrifugal load spreads the outer contact past
    the groove: a warning for the speed, then an error naming the inputs
    (not an axial stiffness of 2.6 N/m)."""
    with pytest.warns(tb.PlausibilityWarning, match=r"n dm = 6e\+07"):
        with pytest.raises(tb.ConfigError, match=r"speed_rpm = 1e\+06.*past the groove"):
            b6208.solve(axial_n=500, speed_rpm=1e6)


def test_ten_meganewton_thrust_is_contact_past_the_groove(b6208):
    """1e7 N on a 6208 gave 2.1 mm of displacement: the contact ellipse's
    semi-major axis (15 mm) exceeds the ball (12 mm), the Hertz model's
    premise of a small contact is gone."""
    with pytest.raises(tb.ConfigError, match=r"axial_n = 1e\+07.*past the groove"):
        b6208.solve(axial_n=1e7)


def test_misalignment_of_ten_radians_is_past_the_groove(b6208):
    """The groove at the balls moves by tilt x dm/2; past A = (fi + fo - 1) D
    (0.6 mm on a 6208, 0.02 rad) the contact leaves the groove."""
    limit = plausibility.groove_tilt_rad(b6208.geometry)
    assert limit == pytest.approx(0.05 * 12.0 / 30.0)
    with pytest.raises(tb.ConfigError, match=r"invalid misalignment_rad = 10"):
        b6208.solve(axial_n=500, misalignment_rad=10)
    with pytest.raises(tb.ConfigError, match=r"misalignment_rad"):
        tb.thermal_state(b6208, speed_rpm=6000, axial_n=500, misalignment_rad=10)


def test_a_few_milliradians_warn_and_a_tighter_limit_warns_earlier(b6208):
    with warnings.catch_warnings():
        warnings.simplefilter("error", tb.PlausibilityWarning)
        b6208.solve(axial_n=500, misalignment_rad=1e-3)  # within 3 mrad: silent
    with pytest.warns(tb.PlausibilityWarning, match="misalignment_rad = 0.005"):
        b6208.solve(axial_n=500, misalignment_rad=5e-3)
    with tb.limits(max_misalignment_rad=5e-4):
        with pytest.warns(tb.PlausibilityWarning, match="misalignment"):
            b6208.solve(axial_n=500, misalignment_rad=1e-3)
    assert tb.get_limits().max_misalignment_rad == 3e-3  # the block's change is undone


def test_isothermal_heat_at_a_million_rpm_is_not_silent(b6208):
    """182 kW from one 6208 at 1e6 rpm: the speed is past any lubrication
    and the state past the model."""
    with pytest.warns(tb.PlausibilityWarning, match="n dm"):
        with pytest.raises(tb.ConfigError, match="speed_rpm = 1e\\+06"):
            tb.isothermal_heat(b6208, speed_rpm=1e6, axial_n=500, oil_temperature_c=40.0)


def test_grease_warns_at_a_lower_speed_than_jet(b6208):
    """n dm limits by lubrication: 20,000 rpm on a 60 mm pitch is 1.2e6."""
    with pytest.warns(tb.PlausibilityWarning, match="grease lubrication"):
        tb.isothermal_heat(
            b6208, speed_rpm=20000, axial_n=500, oil_temperature_c=40.0, lubrication="grease"
        )
    with warnings.catch_warnings():
        warnings.simplefilter("error", tb.PlausibilityWarning)
        tb.isothermal_heat(
            b6208, speed_rpm=20000, axial_n=500, oil_temperature_c=40.0, lubrication="jet"
        )


@pytest.mark.parametrize("bad", [math.nan, -5.0, "x"])
def test_constant_stiffness_checks_the_speeds_before_dropping_them(b6208, bad):
    with pytest.raises(tb.ConfigError, match=r"speeds_rpm"):
        tb.stiffness_curve(b6208, speeds_rpm=[1000.0, bad], axial_n=500, mode="constant")


def test_constant_stiffness_at_a_billion_rpm_warns(b6208):
    with pytest.warns(tb.PlausibilityWarning, match=r"speed_rpm = 1e\+09"):
        df = tb.stiffness_curve(b6208, speeds_rpm=[1e9], axial_n=500, mode="constant")
    assert np.isfinite(df["k_xx_n_per_m"].to_numpy()).all()


# -- the contact-pressure limit is ISO 76's ------------------------------------------


def test_the_pressure_limit_sits_at_the_catalogue_static_rating(b6208):
    """ISO 76 defines the basic static radial load rating C0 of a ball
    bearing as the load giving 4,200 MPa at the most loaded contact; a 6208
    has C0 = 19.0 kN (SKF catalogue). Solved with clearance, the maximum
    pressure at C0 is 4,200 MPa within 3 %: silent below 0.9 C0, warned
    above 1.1 C0 (p0 grows as the load to the 1/3)."""
    c0 = 19_000.0
    with warnings.catch_warnings():
        warnings.simplefilter("error", tb.PlausibilityWarning)
        b6208.solve(radial_n=0.9 * c0)
    with pytest.warns(tb.PlausibilityWarning, match=r"is 4[2-4]\d\d MPa, past the 4200"):
        b6208.solve(radial_n=1.1 * c0)
    s = b6208.solve(radial_n=c0)
    q = float(np.max(s.raw["balls"]["inner_load_n"]))
    p = b6208.contact("inner", 0.0, q)["max_pressure_pa"]
    assert p / 1e6 == pytest.approx(4200.0, rel=0.03)


def test_limits_can_be_tightened_silenced_and_restored(b6208):
    before = tb.set_limits(max_contact_pressure_mpa=2000.0)
    try:
        with pytest.warns(tb.PlausibilityWarning, match="past the 2000 MPa"):
            b6208.solve(radial_n=5000.0)
        with warnings.catch_warnings():
            warnings.filterwarnings("error")
            warnings.filterwarnings("ignore", category=tb.PlausibilityWarning)
            b6208.solve(radial_n=5000.0)  # silenced by the user's filter
    finally:
        tb.set_limits()
    assert tb.get_limits() == before == tb.Limits()
    with pytest.raises(tb.ConfigError, match="max_pressure"):
        tb.set_limits(max_pressure=1.0)
    with pytest.raises(tb.ConfigError, match="max_contact_pressure_mpa"):
        tb.set_limits(max_contact_pressure_mpa=-1.0)


def test_every_limit_is_on_the_docs_page_with_a_source():
    from dataclasses import fields
    from pathlib import Path

    page = (Path(__file__).resolve().parents[1] / "docs" / "concepts" / "limits.md").read_text()
    for f in fields(tb.Limits):
        assert f"`{f.name}`" in page, f.name


def test_a_vanishing_speed_is_the_zero_speed_state(b6208):
    """Found by the long fuzz: at 1e-300 rpm the forward map's stiffness was
    NaN (omega^2 products underflow). Below about 1e-8 rpm the speed effects
    are far below the contact forces' resolution: the result is that at 0."""
    q = [0.0, 0.0, 2e-5, 0.0, 0.0]
    r0, k0 = b6208.ring_forces(q, 0.0)
    for tiny in (1e-300, 1e-100, 1e-12):
        r, k = b6208.ring_forces(q, tiny)
        assert np.array_equal(r, r0) and np.array_equal(k, k0)


def test_a_contact_larger_than_the_ball_is_refused(b6208):
    """Found by the long fuzz: at 3e305 N the ellipse axes overflowed. A
    Hertz contact whose semi-major axis exceeds the ball is no contact the
    theory describes (1e6 N gives 15 mm on a 12 mm ball)."""
    assert b6208.contact("inner", 20.0, 1000.0)["semi_major_m"] < 2e-3
    for load in (1e6, 3.45e305):
        with pytest.raises(tb.ConfigError, match=r"invalid load_n = .*fits the ball"):
            b6208.contact("inner", 20.0, load)
