"""A sweep that fails or is stopped part-way keeps its finished speeds.

The failure is forced at a known speed: the seed gear system needs more RK4
steps per mesh period as the speed falls (at 3000 rpm at least 90, at 5000
rpm 64 suffice), so 64 steps with the up-front check bypassed make 3000 rpm
fail inside the native sweep while 5000-7000 rpm run. The finished rows
must equal the same speeds of a complete run bit for bit.
"""

from __future__ import annotations

import numpy as np
import pytest

import thermobear as tb
import thermobear.gear.dynamics as dyn

SPEEDS = [3000.0, 5000.0, 6000.0, 7000.0]
GOOD = SPEEDS[1:]
KW = dict(transient_periods=20, record_periods=8, lyapunov_periods=0, max_transient_periods=20)


@pytest.fixture(scope="module")
def system() -> tb.GearSystem:
    return tb.GearSystem(tb.GearPair.preset("seed-electric-drive"), stiffness="constant")


@pytest.fixture
def too_coarse(monkeypatch: pytest.MonkeyPatch) -> None:
    """Skip the up-front steps check: 64 steps reach the native sweep."""
    monkeypatch.setattr(dyn, "sweep_steps", lambda systems, speeds, steps: 64)


def test_the_forced_failure_is_real(system: tb.GearSystem) -> None:
    system.check_steps(5000.0, 64)
    with pytest.raises(tb.ConfigError, match="use at least 90"):
        system.check_steps(3000.0, 64)
    # Without the bypass the check stops the sweep before any work.
    with pytest.raises(tb.ConfigError, match="too coarse at 1 of 4 speeds"):
        tb.bifurcation(system, SPEEDS, "down", steps_per_period=64, **KW)


@pytest.mark.parametrize("direction", ["down", "independent"])
def test_finished_speeds_equal_a_complete_run(
    system: tb.GearSystem, too_coarse: None, direction: str
) -> None:
    with pytest.raises(tb.ConfigError, match="use at least 90") as info:
        tb.bifurcation(system, SPEEDS, direction, **KW)
    e = info.value
    full = tb.bifurcation(system, GOOD, direction, **KW)
    assert e.partial.columns == full.columns
    assert e.partial.equals(full)  # bit for bit, every column
    assert e.failed["speed_rpm"].to_list() == [3000.0]
    assert "steps_per_period" in e.failed["message"][0]
    assert e.not_run.height == 0
    assert "3 of 4 speeds finished" in str(e) and "failed: 3000 rpm" in str(e)


def test_continuation_stops_at_the_failed_speed(system: tb.GearSystem, too_coarse: None) -> None:
    # "up" meets 3000 rpm first: nothing can continue from it.
    with pytest.raises(tb.ConfigError) as info:
        tb.bifurcation(system, SPEEDS, "up", **KW)
    e = info.value
    full = tb.bifurcation(system, GOOD, "up", **KW)
    assert e.partial.height == 0 and e.partial.columns == full.columns
    assert e.partial.schema == full.schema
    assert e.failed["speed_rpm"].to_list() == [3000.0]
    assert e.not_run["speed_rpm"].to_list() == GOOD
    assert "0 of 4 speeds finished" in str(e)
    assert "continuation sweep stops at its failed speed" in str(e)


def test_bifurcation_set_names_each_failed_sweep(system: tb.GearSystem, too_coarse: None) -> None:
    with pytest.raises(tb.ConfigError) as info:
        tb.bifurcation_set({"seed": system}, SPEEDS, ("up", "down"), **KW)
    e = info.value
    assert sorted(e.failed["direction"].to_list()) == ["down", "up"]
    assert set(e.failed["case"].to_list()) == {"seed"}
    assert e.failed["speed_rpm"].to_list() == [3000.0, 3000.0]
    down = tb.bifurcation(system, GOOD, "down", **KW)
    kept = e.partial.drop("case")
    assert kept.equals(down)  # "up" finished nothing, "down" its three speeds
    assert e.not_run["speed_rpm"].to_list() == GOOD
    assert "3 of 8 speeds finished" in str(e)


def test_regime_map_keeps_the_other_cells(system: tb.GearSystem, too_coarse: None) -> None:
    with pytest.raises(tb.ConfigError) as info:
        tb.regime_map(system, [100.0], SPEEDS, **KW)
    e = info.value
    full = tb.regime_map(system, [100.0], GOOD, **KW)
    assert e.partial.equals(full)
    assert e.failed.select("torque_n_m", "te_scale", "speed_rpm").rows() == [(100.0, 1.0, 3000.0)]
    assert "3 of 4 cells finished" in str(e)


def test_a_stop_from_the_callback_keeps_the_finished_speeds(system: tb.GearSystem) -> None:
    speeds = np.linspace(5000.0, 7200.0, 12)
    full = tb.bifurcation(system, speeds, "up", **KW)

    def stop(done: int, total: int) -> bool:
        return done < 1

    with pytest.raises(tb.Interrupted) as info:
        tb.bifurcation(system, speeds, "up", progress=stop, **KW)
    e = info.value
    kept = e.partial["speed_rpm"].unique(maintain_order=True).to_list()
    assert len(kept) >= 1
    # A prefix of the sweep, each row equal to the complete run's.
    assert kept == sorted(speeds.tolist())[: len(kept)]
    assert e.partial.equals(full.filter(full["speed_rpm"].is_in(kept)))
    assert e.failed.height == 0
    assert e.not_run["speed_rpm"].to_list() == sorted(speeds.tolist())[len(kept) :]
    assert f"{len(kept)} of 12 speeds finished" in str(e)


def test_gear_study_uses_the_sweep_default_steps() -> None:
    from thermobear.study.kinds import GEAR

    assert GEAR.param("steps_per_period").default is None
    assert dyn.DEFAULT_STEPS_PER_PERIOD == 64


def test_stiffness_curve_keeps_the_speeds_that_solved() -> None:
    # The coupled thermal state has no meaning at rest: 0 rpm fails on its
    # own inside the native loop while 3000 rpm solves.
    bearing = tb.Bearing.preset("6208")
    with pytest.raises(tb.ConfigError, match="speed_rpm = 0") as info:
        tb.stiffness_curve(bearing, [0.0, 3000.0], axial_n=500.0, mode="thermal")
    e = info.value
    full = tb.stiffness_curve(bearing, [3000.0], axial_n=500.0, mode="thermal")
    assert e.partial.equals(full)
    assert e.failed["speed_rpm"].to_list() == [0.0]
    assert "1 of 2 speeds finished" in str(e) and "failed: 0 rpm" in str(e)
