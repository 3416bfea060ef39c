"""What argument validation and the plausibility checks cost.

Times ``Bearing.solve`` (one Python-level solve) and ``Bearing.solve_many``
(50,000 points) with the checks active and with them replaced by no-ops, in
one run, interleaved, best of several repeats. Targets: under 5 % on one
solve, under 2 % on ``solve_many``.

    python benches/validation_overhead.py [--points 50000] [--repeats 7]
"""

from __future__ import annotations

import argparse
import contextlib
import time
import warnings
from typing import Any, Iterator

import numpy as np

import thermobear as tb
from thermobear import _validate, plausibility
from thermobear.bearing import ball_bearing


class _Passthrough:
    """``_validate`` with every check a conversion only (``float``/``int``)."""

    INF = _validate.INF

    @staticmethod
    def real(name: str, value: Any, *a: Any, **k: Any) -> float:
        return float(value)

    @staticmethod
    def optional_real(name: str, value: Any, *a: Any, **k: Any) -> Any:
        return None if value is None else float(value)

    @staticmethod
    def choice(name: str, value: Any, options: Any) -> Any:
        return value

    def __getattr__(self, name: str) -> Any:
        return getattr(_validate, name)


@contextlib.contextmanager
def checks_off() -> Iterator[None]:
    """The bearing wrapper with validation and plausibility as no-ops."""
    saved = (
        ball_bearing.v,
        plausibility.check_solution,
        plausibility.check_speeds,
        plausibility.rows_past_the_groove,
    )
    ball_bearing.v = _Passthrough()  # type: ignore[assignment]
    plausibility.check_solution = lambda *a, **k: None  # type: ignore[assignment]
    plausibility.check_speeds = lambda *a, **k: None  # type: ignore[assignment]
    plausibility.rows_past_the_groove = lambda *a, **k: {}  # type: ignore[assignment]
    try:
        yield
    finally:
        (
            ball_bearing.v,
            plausibility.check_solution,
            plausibility.check_speeds,
            plausibility.rows_past_the_groove,
        ) = saved


def _single(b: tb.Bearing, n: int) -> float:
    t0 = time.perf_counter()
    for _ in range(n):
        b.solve(axial_n=2680.9, radial_n=1189.9, speed_rpm=16000.0)
    return (time.perf_counter() - t0) / n


def _many(b: tb.Bearing, points: dict[str, np.ndarray]) -> float:
    t0 = time.perf_counter()
    b.solve_many(points)
    return time.perf_counter() - t0


def _checks_alone(b: tb.Bearing, n: int) -> float:
    """The checks of one ``solve`` by themselves (on a solved state), per call [s]."""
    raw = b._b.solve(2680.9, 1189.9, 0.0, 16000.0, None, "outer", 0.0)
    v = ball_bearing.v
    t0 = time.perf_counter()
    for _ in range(n):
        loads = {
            "axial_n": v.real("axial_n", 2680.9),
            "radial_n": v.real("radial_n", 1189.9),
            "moment_n_m": v.real("moment_n_m", 0.0),
            "speed_rpm": v.real("speed_rpm", 16000.0, 0.0),
        }
        tilt = b._tilt(0.0)
        ball_bearing._effects_arg(None)
        v.choice("raceway_control", "outer", ball_bearing._CONTROLS)
        plausibility.check_solution(b, raw, loads, tilt)
    return (time.perf_counter() - t0) / n


def _native_alone(b: tb.Bearing, n: int) -> float:
    """The native solve alone, per call [s]."""
    t0 = time.perf_counter()
    for _ in range(n):
        b._b.solve(2680.9, 1189.9, 0.0, 16000.0, None, "outer", 0.0)
    return (time.perf_counter() - t0) / n


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=50_000)
    ap.add_argument("--repeats", type=int, default=7)
    ap.add_argument("--single", type=int, default=3000, help="solves per single-solve timing")
    args = ap.parse_args()
    warnings.simplefilter("ignore", tb.PlausibilityWarning)
    b = tb.Bearing.preset("6208")
    rng = np.random.default_rng(0)
    points = {
        "axial_n": rng.uniform(500.0, 3000.0, args.points),
        "radial_n": rng.uniform(0.0, 1500.0, args.points),
        "speed_rpm": rng.uniform(1000.0, 16000.0, args.points),
    }
    on_1, off_1, on_m, off_m = [], [], [], []
    _single(b, 200)  # warm up
    for _ in range(10 * args.repeats):  # small alternating batches: load spikes hit both
        on_1.append(_single(b, args.single // 10))
        with checks_off():
            off_1.append(_single(b, args.single // 10))
    for _ in range(args.repeats):
        on_m.append(_many(b, points))
        with checks_off():
            off_m.append(_many(b, points))
    alone = min(_checks_alone(b, 2000) for _ in range(args.repeats))
    native = min(_native_alone(b, 2000) for _ in range(args.repeats))
    print(f"the checks alone: {alone * 1e6:.2f} us per solve, {100 * alone / native:.2f} % of "
          f"the native solve ({native * 1e6:.1f} us)")  # fmt: skip
    speeds = points["speed_rpm"]
    arrays = [points["axial_n"], points["radial_n"], np.zeros(args.points), speeds]
    raw = tb._native.solve_many(b._b, *arrays, None, "outer", 0.0, 1, None)
    rows = dict(zip(("axial_n", "radial_n", "moment_n_m", "speed_rpm"), arrays, strict=True))
    options = {"effects": None, "raceway_control": "outer", "misalignment_rad": 0.0}
    t0 = time.perf_counter()
    for _ in range(100):
        b._tilt(0.0)
        plausibility.check_speeds(speeds, b._pitch_mm(), None)
        plausibility.rows_past_the_groove(b, raw, rows, options)  # the per-row contact check
    batch_checks = (time.perf_counter() - t0) / 100
    print(f"the checks of solve_many alone: {batch_checks * 1e6:.1f} us, "
          f"{100 * batch_checks / min(on_m):.4f} % of the call")  # fmt: skip
    one = min(on_1) / min(off_1) - 1.0
    many = min(on_m) / min(off_m) - 1.0
    print(f"solve: {min(off_1) * 1e6:.1f} us without checks, {min(on_1) * 1e6:.1f} us with: "
          f"{100 * one:+.2f} %")  # fmt: skip
    print(f"solve_many ({args.points} points): {min(off_m):.3f} s without, {min(on_m):.3f} s "
          f"with: {100 * many:+.2f} %")  # fmt: skip


if __name__ == "__main__":
    main()
