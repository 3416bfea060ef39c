"""The Rust crate and the Python package share their defaults: the same
bearing under the same load and speed, solved with the core's
``SolveOptions::default()`` untouched and with the Python defaults, moves by
the same displacements. The Rust side of this check is ``tests/defaults.rs``."""

from __future__ import annotations

import inspect

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear import _native

# Seed A's 100 N m case: axial load (with the 300 N preload) and radial load.
AXIAL_N = 2680.9
RADIAL_N = 1189.9


def _core(bearing: tb.Bearing, speed_rpm: float) -> dict:
    return _native.solve_with_default_options(bearing._b, AXIAL_N, RADIAL_N, 0.0, float(speed_rpm))


def test_python_signature_defaults_are_the_core_defaults() -> None:
    core = _native.default_solve_options()
    params = inspect.signature(tb.Bearing.solve).parameters
    # The ring is held level in both.
    assert core["tilt"] == "held"
    assert core["theta_x_rad"] == 0.0
    assert core["theta_y_rad"] == params["misalignment_rad"].default == 0.0
    assert core["raceway_control"] == params["raceway_control"].default == "outer"
    # effects=None leaves the core's set, every effect on; it holds every
    # bearing switch that tb.effects() lists.
    assert params["effects"].default is None
    e = tb.effects()
    switches = e.filter((pl.col("kind") == "switch") & pl.col("models").str.contains("bearing"))
    assert set(switches["name"].to_list()) <= set(core["effects"])
    for name in ("solve_many",):
        p = inspect.signature(getattr(tb.Bearing, name)).parameters
        assert p["misalignment_rad"].default == 0.0
        assert p["raceway_control"].default == "outer"


@pytest.mark.parametrize("name", ["6208", "7009C"])
@pytest.mark.parametrize("speed_rpm", [0.0, 16000.0])
def test_same_bearing_same_load_same_displacements(name: str, speed_rpm: float) -> None:
    b = tb.Bearing.preset(name)
    core = _core(b, speed_rpm)
    py = b.solve(axial_n=AXIAL_N, radial_n=RADIAL_N, speed_rpm=speed_rpm)
    q_core = np.asarray(core["displacement"])
    q_py = py.displacement
    # Translations to 1e-9 relative; the held tilts are exactly zero in both.
    scale = np.abs(q_core[:3]).max()
    np.testing.assert_allclose(q_py[:3], q_core[:3], rtol=1e-9, atol=1e-9 * scale)
    assert py.tilt_rad == 0.0
    assert np.all(q_core[3:] == 0.0)
    # The holding moment is the same reaction in both (negative about y:
    # the radial load presses the balls near psi = 0).
    m_core = np.asarray(core["applied_load"])[4]
    assert m_core < 0.0
    assert py.applied_load[4] == pytest.approx(m_core, rel=1e-9)
    # solve_many uses the same defaults, point for point.
    frame = b.solve_many(
        pl.DataFrame({"axial_n": [AXIAL_N], "radial_n": [RADIAL_N], "speed_rpm": [speed_rpm]})
    )
    radial_um = float(np.hypot(q_core[0], q_core[1]) * 1e6)
    assert frame["radial_displacement_um"][0] == pytest.approx(radial_um, rel=1e-9)
    assert frame["axial_displacement_um"][0] == pytest.approx(q_core[2] * 1e6, rel=1e-9)
    assert frame["tilt_rad"][0] == 0.0


@pytest.mark.parametrize("name", ["6208", "7009C"])
def test_free_tilt_is_an_option_that_moves_the_ring_more(name: str) -> None:
    # A ring free to tilt under combined load without moment tilts, and its
    # radial displacement grows several times over the level one.
    b = tb.Bearing.preset(name)
    held = b.solve(axial_n=AXIAL_N, radial_n=RADIAL_N, speed_rpm=16000.0)
    free = b.solve(axial_n=AXIAL_N, radial_n=RADIAL_N, speed_rpm=16000.0, misalignment_rad=None)
    assert free.tilt_rad > 1e-4
    assert abs(free.applied_load[4]) < 1e-6
    r_held = np.hypot(*held.displacement[:2])
    r_free = np.hypot(*free.displacement[:2])
    assert r_free > 2.0 * r_held
