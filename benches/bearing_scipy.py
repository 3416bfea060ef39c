"""Time one high-speed quasi-static solve of the seed A 6208 bearing with
thermobear (Rust) and with the same equations in NumPy + SciPy ``fsolve``
(``reference_bearing.py``), check they agree, and print the ratio.

    python3 benches/bearing_scipy.py
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))

from reference_bearing import ReferenceBearing  # noqa: E402

import thermobear as tb  # noqa: E402

FA, FR, SPEED = 2680.9, 1189.9, 16000.0


def best_of(fn, repeat: int) -> float:
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def main() -> None:
    ref = ReferenceBearing()
    start = ref.solve(FA, FR, 0.0)["x"]
    r = ref.solve(FA, FR, SPEED, x0=start)
    b = tb.Bearing.preset("6208")
    effects = ["centrifugal_force", "gyroscopic_moment"]
    s = b.solve(axial_n=FA, radial_n=FR, speed_rpm=SPEED, effects=effects)
    balls = s.balls
    dq = np.max(np.abs(balls["inner_load_n"].to_numpy() - r["inner_load_n"]))
    print(f"max inner-load difference Rust vs SciPy: {dq:.3e} N")
    t_scipy = best_of(lambda: ref.solve(FA, FR, SPEED, x0=start), 5)
    t_rust = best_of(lambda: b.solve(axial_n=FA, radial_n=FR, speed_rpm=SPEED, effects=effects), 50)
    print(f"SciPy fsolve (warm start from static): {t_scipy * 1e3:8.3f} ms")
    print(f"thermobear (incl. Python call, cold):   {t_rust * 1e3:8.3f} ms")
    print(f"ratio SciPy / thermobear: {t_scipy / t_rust:8.1f}x")
    speeds = np.linspace(6500, 16500, 1001)
    t_curve = best_of(lambda: tb.stiffness_curve(b, speeds, FA, FR), 3)
    print(f"thermobear 1001-speed stiffness curve: {t_curve * 1e3:8.1f} ms")


if __name__ == "__main__":
    main()
