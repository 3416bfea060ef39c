"""The contact-past-the-groove check on every row of a batch: ``solve_many``
and ``stiffness_curve`` refuse a row exactly where ``Bearing.solve``
refuses the same point, at no cost for ordinary rows."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import thermobear as tb
from thermobear import plausibility


@pytest.fixture(scope="module")
def bearing() -> tb.Bearing:
    return tb.Bearing.preset("6208")


def _solve_error(b: tb.Bearing, **point: float) -> str | None:
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", tb.PlausibilityWarning)
            b.solve(**point)
    except tb.ConfigError as e:
        return str(e)
    return None


def test_solve_many_fails_a_row_exactly_where_solve_refuses_the_point(bearing):
    """Axial loads from 1 kN to 10 MN at rest, at 10,000 and at 1e6 rpm: the
    batch's failed rows are the points ``solve`` refuses, with its message;
    both kinds occur (the check is neither always on nor always off)."""
    axial = np.repeat(np.geomspace(1e3, 1e7, 9), 3)
    speed = np.tile([0.0, 1e4, 1e6], 9)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", tb.PlausibilityWarning)
        df = bearing.solve_many({"axial_n": axial, "speed_rpm": speed}, threads=1)
    refused = 0
    for row in df.iter_rows(named=True):
        expected = _solve_error(bearing, axial_n=row["axial_n"], speed_rpm=row["speed_rpm"])
        if expected is None:
            assert row["ok"], row["error"]
        else:
            refused += 1
            assert not row["ok"] and row["error_kind"] == "ConfigError"
            assert row["error"] == expected and "past the groove" in expected
            assert row["k_xx_n_per_m"] is None  # a failed row has null outputs
    assert 0 < refused < len(axial)


def test_the_bound_flags_no_ordinary_row(bearing):
    """The benchmark's 2,000 operating points (6208 up to 3 kN, 1.5 kN and
    16,000 rpm): the vectorised bound flags none, so no row is solved twice."""
    rng = np.random.default_rng(0)
    n = 2000
    arrays = [rng.uniform(500.0, 3000.0, n), rng.uniform(0.0, 1500.0, n), np.zeros(n),
              rng.uniform(1000.0, 16000.0, n)]  # fmt: skip
    raw = tb._native.solve_many(bearing._b, *arrays, None, "outer", 0.0, 1, None)
    assert len(plausibility._rows_near_the_groove(bearing, raw)) == 0


def test_the_bound_holds_the_exact_ellipse_edge(bearing):
    """The bound of the semi-major axis (a / Q^(1/3), the largest over the
    contact angles) is at least the exact Hertz axis at any angle and load,
    and at most 10 % above the largest."""
    for race in ("inner", "outer"):
        c = plausibility._axis_factor(bearing, race)
        for deg in (0.0, 15.0, 40.0, 75.0):
            for q in (10.0, 1e3, 1e5):
                a_mm = bearing.contact(race, deg, q)["semi_major_m"] * 1e3
                assert a_mm <= c * q ** (1.0 / 3.0)
        top = max(bearing.contact(race, d, 1e3)["semi_major_m"] * 1e3 for d in range(90))
        assert c * 1e3 ** (1.0 / 3.0) <= 1.10 * top


def test_stiffness_curve_refuses_a_speed_past_the_groove(bearing):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", tb.PlausibilityWarning)
        with pytest.raises(tb.ConfigError, match=r"past the groove.*speeds_rpm\[1\]"):
            tb.stiffness_curve(bearing, [1000.0, 1e6], axial_n=500.0)
        with pytest.raises(tb.ConfigError, match=r"axial_n = 3e\+06.*past the groove"):
            tb.stiffness_curve(bearing, [0.0, 5000.0], axial_n=3e6, mode="constant")
        ok = tb.stiffness_curve(bearing, [1000.0, 16000.0], axial_n=3000.0)
    assert ok.height == 2
