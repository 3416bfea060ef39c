"""Bounded work of the gear dynamics: the bounds on each count, the cap on
the planned RK4 steps of a call (``max_steps=``), and Ctrl-C inside one
long cell."""

from __future__ import annotations

import logging
import time
from typing import Any, Callable

import numpy as np
import pytest
from test_limits import sigint_latency

import thermobear as tb
from thermobear.gear import dynamics as dyn

#: A stop must end the call within 1 s; the assertion allows more for a
#: loaded machine (the figure measured is printed with -s).
STOP_BOUND_S = 5.0


@pytest.fixture(scope="module")
def gs() -> tb.GearSystem:
    return tb.GearSystem(tb.GearPair.preset("seed-electric-drive"), stiffness="constant")


# ------------------------------------------------------------ the bounds ----


@pytest.mark.parametrize(
    "kw, name",
    [
        (dict(transient_periods=1e9), "transient_periods"),
        (dict(steps_per_period=1e6), "steps_per_period"),
        (dict(record_periods=200_000), "record_periods"),
        (dict(lyapunov_periods=10**7), "lyapunov_periods"),
    ],
)
def test_bifurcation_refuses_a_count_past_its_bound(gs, kw, name):
    with pytest.raises(tb.ConfigError, match=rf"invalid {name} = .*at most 100,000") as info:
        tb.bifurcation(gs, [10_000.0], **kw)
    assert "Limits" in str(info.value)


def test_bounds_are_inclusive_and_the_settings_caps_are_bounded(gs):
    # 100,000 steps per period is allowed (refused only by the total here).
    with pytest.raises(tb.ConfigError, match="max_steps = 1,000"):
        tb.bifurcation(gs, [10_000.0], steps_per_period=100_000, max_steps=1000)
    with pytest.raises(tb.ConfigError, match="max_transient_periods.*100000"):
        tb.bifurcation(gs, [10_000.0], **TINY, max_transient_periods=200_000)
    with pytest.raises(tb.ConfigError, match="lyapunov_max_periods.*100000"):
        tb.bifurcation(gs, [10_000.0], **TINY, lyapunov_max_periods=200_000)


def test_the_reported_regime_map_call_is_refused_before_any_work(gs):
    t0 = time.perf_counter()
    with pytest.raises(tb.ConfigError, match=r"invalid steps_per_period = 1000000: .*100,000"):
        tb.regime_map(gs, [10.0, 20.0], [2000.0, 3000.0], transient_periods=0,
                      record_periods=10, steps_per_period=10**6, lyapunov_periods=10)  # fmt: skip
    assert time.perf_counter() - t0 < 5.0  # refused up front, not after a cell


def test_speeds_that_need_more_steps_than_the_bound_are_refused(gs):
    # The step rule needs about 270,000 / rpm steps for this pair.
    with pytest.raises(tb.ConfigError, match=r"speeds_rpm = 1 rpm \(the slowest\): it needs 2"):
        tb.bifurcation(gs, [1.0, 2.0, 10_000.0])


def test_largest_lyapunov_bounds_its_counts_and_total(gs):
    with pytest.raises(tb.ConfigError, match="steps_per_period = 1000000"):
        tb.largest_lyapunov(gs, 10_000.0, steps_per_period=10**6)
    with pytest.raises(tb.ConfigError, match="transient_periods = 1000000000"):
        tb.largest_lyapunov(gs, 10_000.0, transient_periods=10**9)
    with pytest.raises(
        tb.ConfigError,
        match=r"1 speed x \(300 transient_periods \+ 200 periods\) x 64 steps_per_period "
        r"= 32,000 RK4 steps: more than max_steps = 31,999",
    ):
        tb.largest_lyapunov(gs, 10_000.0, max_steps=31_999)
    assert np.isfinite(tb.largest_lyapunov(gs, 10_000.0, periods=20, transient_periods=10,
                                           max_steps=30 * 64))  # fmt: skip


# ----------------------------------------------------- the cap on the total ----

#: One cell of a tiny sweep: 1 x (0 + 4 + 0) x 64 = 256 RK4 steps.
TINY = dict(transient_periods=0, record_periods=4, steps_per_period=64, lyapunov_periods=0)


def test_the_cap_is_exact_and_max_steps_lifts_it(gs):
    with pytest.raises(tb.ConfigError) as info:
        tb.bifurcation(gs, [10_000.0], **TINY, max_steps=255)
    msg = str(info.value)
    for part in ("bifurcation", "1 speeds", "0 transient_periods", "4 record_periods",
                 "0 lyapunov_periods", "64 steps_per_period", "= 256 RK4 steps",
                 "max_steps = 255", "pass max_steps="):  # fmt: skip
        assert part in msg, (part, msg)
    df = tb.bifurcation(gs, [10_000.0], **TINY, max_steps=256)
    assert df.height == 4


@pytest.mark.parametrize(
    "call, cells",
    [
        (lambda gs, **kw: tb.regime_map(gs, [10.0, 20.0], [2000.0, 3000.0], **kw),
         "2 torques x 1 te_scales x 2 speeds"),
        (lambda gs, **kw: tb.bifurcation_set({"a": gs}, [2000.0, 3000.0], **kw),
         "1 systems x 2 directions x 2 speeds"),
    ],
)  # fmt: skip
def test_the_default_cap_refuses_a_long_call_naming_the_total(gs, call, cells):
    # 4 cells x (20,000 + 10 + 10) x 100,000 = 8.0e9 steps, past the 2e9 default.
    kw = dict(transient_periods=20_000, record_periods=10, steps_per_period=100_000,
              lyapunov_periods=10)  # fmt: skip
    with pytest.raises(tb.ConfigError) as info:
        call(gs, **kw)
    msg = str(info.value)
    assert cells in msg and "= 8,008,000,000 RK4 steps" in msg, msg
    assert f"max_steps = {dyn.MAX_STEPS:,}" in msg
    # (max_steps= lifts it: the Ctrl-C tests below run 5e9-step calls.)


def test_the_planned_work_is_logged(gs, caplog):
    with caplog.at_level(logging.INFO, logger="thermobear.gear"):
        tb.bifurcation(gs, [10_000.0, 11_000.0], **TINY)
    msgs = [r.getMessage() for r in caplog.records if r.name == "thermobear.gear"]
    assert any("bifurcation: 2 speeds" in m and "= 512 RK4 steps" in m for m in msgs), msgs
    assert dyn.planned_steps(2, 0, 4, 0, 64) == 512


# ------------------------------------------------ Ctrl-C inside one cell ----

#: One cell of 50,000 x 100,000 = 5e9 RK4 steps: minutes of work unless
#: stopped (past the default cap: max_steps= lifts it).
HUGE = dict(transient_periods=50_000, record_periods=10, steps_per_period=100_000,
            lyapunov_periods=10)  # fmt: skip

ONE_CELL: dict[str, Callable[..., Any]] = {
    # lock-step batch integration (independent cells)
    "regime_map": lambda gs, **kw: tb.regime_map(gs, [100.0], [10_000.0], **HUGE, **kw),
    # scalar integration (a continuation sweep)
    "bifurcation_up": lambda gs, **kw: tb.bifurcation(gs, [10_000.0], "up", **HUGE, **kw),
    "bifurcation_set": lambda gs, **kw: tb.bifurcation_set(
        {"a": gs}, [10_000.0], ("independent",), **HUGE, **kw
    ),
    # the transient before a Lyapunov estimate
    "largest_lyapunov": lambda gs, **kw: tb.largest_lyapunov(
        gs, 10_000.0, periods=20, transient_periods=50_000, steps_per_period=100_000, **kw
    ),
}  # fmt: skip


@pytest.mark.parametrize("name", sorted(ONE_CELL))
def test_sigint_stops_a_single_huge_cell(gs, name):
    """A real SIGINT from a timer thread 0.3 s into a one-cell call that
    would run for minutes: KeyboardInterrupt, well within the bound."""
    with pytest.raises(tb.ConfigError, match="5,00.,000,000 RK4 steps: more than max_steps"):
        ONE_CELL[name](gs)  # refused at the default cap
    latency = sigint_latency(lambda: ONE_CELL[name](gs, max_steps=10**10), 0.3)
    print(f"{name}: stopped {latency * 1e3:.1f} ms after SIGINT")
    assert latency < STOP_BOUND_S, f"{name} took {latency:.3f} s to stop"
