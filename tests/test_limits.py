"""Limits that protect the machine: thread counts above the cores are capped
with a warning and leave no thread behind; a progress callback that returns
False, or Ctrl-C, stops every long call.

The target for a stop is 0.2 s (each long call checks every 20 ms and
stops at its next item or time step); the tests assert 0.5 s so that a
loaded 2-core machine does not make them flaky, which is still far below
the seconds of work each call is given."""

from __future__ import annotations

import os
import signal
import threading
import time
import warnings
from typing import Any

import numpy as np
import polars as pl
import pytest

import thermobear as tb
from thermobear._limits import available_cores, cap_threads

#: Seconds a stop may take here (the target is 0.2 s).
STOP_BOUND_S = 0.5


def _threads() -> int:
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("Threads:"):
                return int(line.split()[1])
    raise AssertionError("no Threads: line in /proc/self/status")


def _settled_threads(at_most: int, wait_s: float = 3.0) -> int:
    """The thread count once it is at most ``at_most`` (released pools end
    their threads asynchronously), or after ``wait_s``."""
    end = time.monotonic() + wait_s
    n = _threads()
    while n > at_most and time.monotonic() < end:
        time.sleep(0.05)
        n = _threads()
    return n


@pytest.fixture(scope="module")
def bearing() -> tb.Bearing:
    return tb.Bearing.preset("7009C")


@pytest.fixture(scope="module")
def spindle() -> tb.Spindle:
    return tb.Spindle.preset("seed-ceramic-spindle")


def _points(n: int) -> pl.DataFrame:
    return pl.DataFrame(
        {
            "axial_n": np.full(n, 800.0),
            "radial_n": np.linspace(0.0, 2000.0, n),
            "speed_rpm": np.linspace(1000.0, 20000.0, n),
        }
    )


# ------------------------------------------------------------------ threads


@pytest.mark.skipif(available_cores() >= 500, reason="needs fewer than 500 cores")
def test_threads_far_above_the_cores_are_capped_and_leave_no_thread(bearing):
    pts = _points(8)
    expected = bearing.solve_many(pts)  # starts the global pool
    baseline = _threads()
    cores = available_cores()
    t0 = time.perf_counter()
    with pytest.warns(tb.ThreadsWarning, match=f"threads=2000 exceeds the {cores} available"):
        got = bearing.solve_many(pts, threads=2000)
    # Uncapped, 2000 threads took seconds to start for eight points.
    assert time.perf_counter() - t0 < 2.0
    assert got.equals(expected)
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        for _ in range(3):
            bearing.solve_many(pts, threads=500)
        tb.thermal_state_many(bearing, pts.head(2), threads=1000)
    assert [type(w.message) for w in seen] == [tb.ThreadsWarning] * 4
    assert all(w.filename == __file__ for w in seen)  # points at the caller
    assert _settled_threads(baseline) <= baseline


@pytest.mark.skipif(available_cores() < 2, reason="needs 2 cores")
def test_a_thread_count_below_the_cores_keeps_one_pool(bearing):
    pts = _points(8)
    expected = bearing.solve_many(pts)
    baseline = _threads()
    for _ in range(5):
        with warnings.catch_warnings():
            warnings.simplefilter("error")  # no warning below the cores
            assert bearing.solve_many(pts, threads=1).equals(expected)
    # One kept pool of one thread, not five.
    assert _settled_threads(baseline + 1) <= baseline + 1


def test_threads_below_one_are_a_config_error(bearing):
    with pytest.raises(tb.ConfigError, match="threads"):
        bearing.solve_many(_points(2), threads=0)
    for bad in (0, -3, 1.5, True):
        with pytest.raises(tb.ConfigError, match="threads"):
            cap_threads(bad)


def test_python_side_pools_are_capped_too():
    assert cap_threads(None) is None and cap_threads(1) == 1
    s = tb.Study("spindle", {"speed_rpm": [8000.0, 9000.0]}, {"preload_kind": "spring"})
    with pytest.warns(tb.ThreadsWarning, match="threads=2000"):
        df = s.run(threads=2000, progress=False)
    assert df.height == 2 and df["ok"].all()


# ------------------------------------------------------------------ stops


def _gear_system() -> tb.GearSystem:
    g = tb.GearPair.preset(tb.GearPair.preset_names()[0])
    return tb.GearSystem(g, stiffness="speed", torque_n_m=20.0, te_amplitude_um=10.0)


#: Long calls with a progress callback, each given seconds of work.
WITH_PROGRESS = {
    "solve_many": lambda b, sp, cb: b.solve_many(_points(100_000), progress=cb),
    "thermal_state_many": lambda b, sp, cb: tb.thermal_state_many(b, _points(20_000), progress=cb),
    "stiffness_curve": lambda b, sp, cb: tb.stiffness_curve(
        b, np.linspace(0.0, 20000.0, 50_000), axial_n=800.0, progress=cb
    ),
    "spindle_grid": lambda b, sp, cb: tb.spindle_grid(
        sp,
        speeds_rpm=np.linspace(2000.0, 18000.0, 30),
        preloads_n=np.linspace(200.0, 1500.0, 20),
        progress=cb,
    ),
    "campbell": lambda b, sp, cb: tb.campbell(sp, np.linspace(0.0, 30000.0, 2000), progress=cb),
    "vibration_time": lambda b, sp, cb: tb.vibration(
        sp,
        np.linspace(3000.0, 30000.0, 20),
        coupled=False,
        method="time",
        duration_s=0.5,
        progress=cb,
    ),
    "bifurcation": lambda b, sp, cb: tb.bifurcation(
        _gear_system(), np.linspace(1000.0, 6000.0, 200), progress=cb
    ),
    "regime_map": lambda b, sp, cb: tb.regime_map(
        _gear_system(), [10.0, 20.0, 40.0], np.linspace(1000.0, 6000.0, 100), progress=cb
    ),
}

#: Long calls without a callback (Ctrl-C only): one long time integration.
WITHOUT_PROGRESS = {
    "transient": lambda b, sp, cb: tb.transient(
        sp, speed_rpm=12000.0, duration_s=30 * 86400.0, dt_s=5.0
    ),
    "spectrum": lambda b, sp, cb: tb.spectrum(sp, 12000.0, duration_s=5.0, coupled=False),
}


@pytest.mark.parametrize("name", sorted(WITH_PROGRESS))
def test_a_callback_returning_false_stops_the_call_quickly(name, bearing, spindle):
    state: dict = {"calls": 0, "after": 0}

    def stop(done: int, total: int) -> bool:
        if "t" in state:
            state["after"] += 1
        state["calls"] += 1
        state.setdefault("t", time.perf_counter())
        return False

    with pytest.raises(tb.Interrupted, match="returned False") as info:
        WITH_PROGRESS[name](bearing, spindle, stop)
    latency = time.perf_counter() - state["t"]
    assert state["after"] == 0  # never called again after False
    e = info.value
    assert isinstance(e, tb.ThermobearError)
    assert 0 <= e.done < e.total  # stopped early: most of the work skipped
    assert latency < STOP_BOUND_S, f"{name} took {latency:.3f} s to stop"


def test_a_callback_returning_none_or_true_goes_on(bearing):
    calls = []
    df = bearing.solve_many(_points(50), progress=lambda d, t: calls.append((d, t)))
    assert df.height == 50 and calls[-1] == (50, 50)
    assert bearing.solve_many(_points(5), progress=lambda d, t: True).height == 5


def sigint_latency(call: Any, after_s: float) -> float:
    """Seconds from a real SIGINT, sent from a timer thread ``after_s``
    into ``call()``, to the KeyboardInterrupt it must raise (the test
    fails if ``call`` returns instead)."""
    fired: dict = {}
    finished = threading.Event()

    def interrupt() -> None:
        if not finished.is_set():
            fired["t"] = time.perf_counter()
            os.kill(os.getpid(), signal.SIGINT)

    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(after_s, interrupt)
    try:
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            try:
                call()
            finally:
                finished.set()
        return time.perf_counter() - fired["t"]
    finally:
        timer.cancel()
        timer.join()
        signal.signal(signal.SIGINT, previous)


@pytest.mark.parametrize("name", sorted(WITH_PROGRESS) + sorted(WITHOUT_PROGRESS))
def test_ctrl_c_stops_the_call_quickly(name, bearing, spindle):
    """A real SIGINT from another thread, 0.15 s into seconds of work."""
    call = {**WITH_PROGRESS, **WITHOUT_PROGRESS}[name]
    latency = sigint_latency(lambda: call(bearing, spindle, None), 0.15)
    assert latency < STOP_BOUND_S, f"{name} took {latency:.3f} s to stop"


def test_on_chunk_returning_false_stops_a_study(tmp_path):
    s = tb.Study("thermal", {"speed_rpm": [4000.0, 5000.0, 6000.0, 7000.0]}, chunk_size=1)
    with pytest.raises(tb.Interrupted, match="on_chunk"):
        s.run(tmp_path, progress=False, on_chunk=lambda index, frame: False)
    assert s.report.interrupted and s.report.computed == 1
    assert len(list((tmp_path / "chunks").glob("chunk-*.parquet"))) == 1
