"""Hypothesis fuzzing of the Python constructors: any input either builds a
valid object or raises a thermobear ConfigError (never a panic, never
another exception type)."""

import math

from hypothesis import given, settings
from hypothesis import strategies as st

import thermobear as tb

floats = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True, width=64),
    st.floats(min_value=-1e3, max_value=1e3),
    st.floats(min_value=0.0, max_value=200.0),
)


@settings(max_examples=300, deadline=None)
@given(
    z=st.integers(min_value=-5, max_value=300),
    d=floats,
    dm=floats,
    fi=floats,
    fo=floats,
    pd=floats,
    bore=floats,
    od=floats,
    w=floats,
)
def test_deep_groove_constructor_never_panics(z, d, dm, fi, fo, pd, bore, od, w):
    try:
        b = tb.Bearing.deep_groove(
            ball_count=z,
            ball_diameter_mm=d,
            pitch_diameter_mm=dm,
            inner_conformity=fi,
            outer_conformity=fo,
            diametral_clearance_mm=pd,
            bore_mm=bore,
            outer_diameter_mm=od,
            width_mm=w,
        )
    except tb.ConfigError as e:
        assert "=" in str(e)  # names field and value
        return
    g = b.geometry
    assert all(math.isfinite(v) for v in g.values())
    assert g["free_contact_angle_deg"] >= 0.0


@settings(max_examples=200, deadline=None)
@given(z=st.integers(min_value=-5, max_value=300), a0=floats, d=floats, dm=floats)
def test_angular_contact_constructor_never_panics(z, a0, d, dm):
    try:
        tb.Bearing.angular_contact(
            ball_count=z,
            ball_diameter_mm=d,
            pitch_diameter_mm=dm,
            inner_conformity=0.52,
            outer_conformity=0.53,
            free_contact_angle_deg=a0,
            bore_mm=45,
            outer_diameter_mm=75,
            width_mm=16,
        )
    except tb.ConfigError:
        return


@settings(max_examples=200, deadline=None)
@given(e=floats, nu=floats, rho=floats, alpha=floats, k=floats, c=floats)
def test_material_constructor_never_panics(e, nu, rho, alpha, k, c):
    try:
        m = tb.Material(
            "x",
            youngs_modulus_gpa=e,
            poisson_ratio=nu,
            density_kg_m3=rho,
            thermal_expansion_per_k=alpha,
            conductivity_w_mk=k,
            specific_heat_j_kgk=c,
        )
    except tb.ConfigError:
        return
    assert m.youngs_modulus_gpa > 0 and 0 <= m.poisson_ratio < 0.5


@settings(max_examples=150, deadline=None)
@given(
    preset=st.sampled_from(["6208", "7009C-hybrid", "7008C"]),
    fa=st.one_of(st.floats(min_value=-5e3, max_value=2e4), st.just(float("nan"))),
    fr=st.floats(min_value=-5e3, max_value=2e4),
    speed=st.one_of(st.floats(min_value=-100.0, max_value=60000.0), st.just(float("inf"))),
)
def test_solve_never_panics_or_returns_nan(preset, fa, fr, speed):
    """Any load and speed gives a finite solution or a thermobear error."""
    import numpy as np

    b = tb.Bearing.preset(preset)
    try:
        s = b.solve(axial_n=fa, radial_n=fr, speed_rpm=speed)
    except (tb.ConfigError, tb.ConvergenceError):
        return
    assert np.all(np.isfinite(s.displacement))
    assert np.all(np.isfinite(s.stiffness))
    for col in s.balls.columns:
        assert np.all(np.isfinite(s.balls[col].to_numpy())), col
