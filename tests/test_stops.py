"""Long calls can always be stopped: a transient's step count is capped
before any memory is taken (a ConfigError naming ``dt_s`` and
``duration_s``), Ctrl-C delivered while it runs stops it within the stop
bound, and its progress callback can stop it like the sweeps'."""

from __future__ import annotations

import _thread
import signal
import threading
import time

import numpy as np
import pytest

import thermobear as tb

#: Seconds a stop may take here (target 0.2 s; margin for a loaded machine).
STOP_BOUND_S = 0.5


@pytest.fixture(scope="module")
def spindle() -> tb.Spindle:
    return tb.Spindle.preset("seed-ceramic-spindle")


def test_a_step_far_too_small_is_refused_at_once_naming_both_times(spindle):
    t0 = time.perf_counter()
    with pytest.raises(tb.ConfigError, match="dt_s") as info:
        tb.transient(spindle, speed_rpm=12000, duration_s=375, dt_s=1e-300)
    assert time.perf_counter() - t0 < 1.0
    msg = str(info.value)
    assert "duration_s = 375" in msg and "1e-300" in msg and "10000000" in msg


def test_the_step_cap_sits_at_ten_million_steps(spindle):
    # 10 million steps and one more: the first would run, the second not.
    with pytest.raises(tb.ConfigError, match="dt_s"):
        tb.transient(spindle, speed_rpm=12000, duration_s=10_000_001.0, dt_s=1.0)
    # Too many recorded rows names record_every (and the value that fits).
    with pytest.raises(tb.ConfigError, match="record_every >= 3"):
        tb.transient(spindle, speed_rpm=12000, duration_s=2_500_000.0, dt_s=1.0)


def _long_transient(spindle, **kw):
    # Sixty days of simulated time: minutes of work if not stopped.
    return tb.transient(
        spindle, speed_rpm=12000.0, duration_s=60 * 86400.0, dt_s=1.0, record_every=100, **kw
    )


def test_sigint_from_a_thread_stops_a_long_transient_quickly(spindle):
    fired: dict = {}

    def fire() -> None:
        fired["t"] = time.perf_counter()
        _thread.interrupt_main(signal.SIGINT)

    previous = signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(0.3, fire)
    try:
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            _long_transient(spindle)
        latency = time.perf_counter() - fired["t"]
    finally:
        timer.cancel()
        timer.join()
        signal.signal(signal.SIGINT, previous)
    assert latency < STOP_BOUND_S, f"the transient took {latency:.3f} s to stop"


def test_a_timer_signal_stops_a_long_transient_quickly(spindle):
    fired: dict = {}

    def on_alarm(signum, frame):
        fired["t"] = time.perf_counter()
        raise KeyboardInterrupt

    previous = signal.signal(signal.SIGALRM, on_alarm)
    try:
        signal.setitimer(signal.ITIMER_REAL, 0.3)
        with pytest.raises(KeyboardInterrupt):
            _long_transient(spindle)
        latency = time.perf_counter() - fired["t"]
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0.0)
        signal.signal(signal.SIGALRM, previous)
    assert latency < STOP_BOUND_S, f"the transient took {latency:.3f} s to stop"


def test_a_transient_reports_its_steps_and_stops_on_false(spindle):
    seen: list[tuple[int, int]] = []
    df = tb.transient(
        spindle,
        speed_rpm=12000.0,
        duration_s=200.0,
        dt_s=10.0,
        progress=lambda d, t: seen.append((d, t)),
    )
    assert seen[-1] == (20, 20) and all(t == 20 for _, t in seen)
    assert [d for d, _ in seen] == sorted(d for d, _ in seen)
    # The callback does not change the result.
    ref = tb.transient(spindle, speed_rpm=12000.0, duration_s=200.0, dt_s=10.0)
    assert df.equals(ref)

    state: dict = {}

    def stop(done: int, total: int) -> bool:
        state.setdefault("t", time.perf_counter())
        state["total"] = total
        return False

    with pytest.raises(tb.Interrupted, match="returned False") as info:
        _long_transient(spindle, progress=stop)
    assert time.perf_counter() - state["t"] < STOP_BOUND_S
    assert info.value.total == 60 * 86400 and info.value.done < info.value.total


def test_critical_speeds_are_the_crossings_of_the_campbell_branches(spindle):
    # Critical speeds run one speed per item (so Ctrl-C can stop them): the
    # crossings must be those of the Campbell branches over the same grid,
    # f_k(n) = n / 60, found here by linear interpolation from the diagram.
    speeds = np.linspace(0.0, 120000.0, 41)
    cs = tb.critical_speeds(spindle, speeds, modes=4)
    camp = tb.campbell(spindle, speeds, modes=4)
    expected = []
    for k in range(4):
        f = camp.filter(camp["mode"] == k).sort("speed_rpm")["frequency_hz"].to_numpy()
        g = f - speeds / 60.0
        for i in range(len(speeds) - 1):
            if g[i] == 0.0 or g[i] * g[i + 1] < 0.0:
                t = g[i] / (g[i] - g[i + 1])
                expected.append(speeds[i] + t * (speeds[i + 1] - speeds[i]))
    assert len(expected) > 0
    np.testing.assert_allclose(np.sort(cs["speed_rpm"].to_numpy()), np.sort(expected), rtol=1e-12)
