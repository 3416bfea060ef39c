"""Seed A thermal network steady state: SciPy ``fsolve`` on the node heat
balances (links exported by ``_native.seed_a_network_links``) against
thermobear's Newton solver (``_native.seed_a_steady_temperatures``); check
they agree and print the time ratio.

    python3 benches/thermal_scipy.py
"""

from __future__ import annotations

import time

import numpy as np
from scipy.optimize import fsolve

import thermobear as tb
from thermobear import _native

SPEED = 12_000.0
# Heat on Ti, Tb, To [W] (Burton-Staph split of a 12,000 rpm seed A point).
HEAT = {"inner_ring_w": 95.0, "balls_w": 135.0, "outer_ring_w": 40.0}


def best_of(fn, repeat: int) -> float:
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def scipy_solver(b: tb.Bearing):
    net = _native.seed_a_network_links(b._b, SPEED)
    names = list(net["node"])
    fixed = dict(net["boundary_temperature_c"])
    free = [i for i, n in enumerate(names) if n not in fixed]
    links = net["links"]
    src = np.zeros(len(names))
    src[names.index("Ti")] = HEAT["inner_ring_w"]
    src[names.index("Tb")] = HEAT["balls_w"]
    src[names.index("To")] = HEAT["outer_ring_w"]
    t_all = np.array([fixed.get(n, 0.0) for n in names])

    def residual(x: np.ndarray) -> np.ndarray:
        t = t_all.copy()
        t[free] = x
        r = src.copy()
        for _, a, bb, g, nat in links:
            dt = t[a] - t[bb]
            q = g * dt + nat * abs(dt) ** 0.25 * dt
            r[a] -= q
            r[bb] += q
        return r[free]

    def solve() -> np.ndarray:
        x = fsolve(residual, np.full(len(free), 40.0), xtol=1e-12)
        t = t_all.copy()
        t[free] = x
        return t

    return names, solve


def main() -> None:
    b = tb.Bearing.preset("6208")
    names, solve = scipy_solver(b)
    t_ref = solve()
    ours = _native.seed_a_steady_temperatures(b._b, SPEED, **HEAT)
    t_tb = np.asarray(ours["temperature_c"])
    assert list(ours["node"]) == names
    err = float(np.max(np.abs(t_ref - t_tb)))
    print("node  scipy_c  thermobear_c")
    for n, a, c in zip(names, t_ref, t_tb, strict=False):
        print(f"{n:4s} {a:8.3f} {c:12.3f}")
    print(f"max |difference| = {err:.2e} K")
    assert err < 1e-6, err
    t_scipy = best_of(solve, 20)
    t_ours = best_of(lambda: _native.seed_a_steady_temperatures(b._b, SPEED, **HEAT), 200)
    print(
        f"SciPy fsolve: {t_scipy * 1e3:.3f} ms; "
        f"thermobear: {t_ours * 1e6:.1f} us (incl. network build)"
    )
    print(f"ratio: {t_scipy / t_ours:.1f}x")


if __name__ == "__main__":
    main()
