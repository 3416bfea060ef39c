#!/usr/bin/env python3
"""Time the helical-pair equations (PHYSICS.md section 7, reduced to 7 DOF /
14 states as in src/dynamics/gear_model.rs) in Python and compare with the
Rust RK4 figure printed by `examples/rk4_step_timing.rs`.

Runs: NumPy fixed-step RK4 (64 steps per mesh period), SciPy solve_ivp
(RK45 and DOP853 at rtol 1e-8), numba RK4 if numba is importable. Prints
ns per step and the ratio to Rust. Seed-A parameters (Table 3) and the
defaults of HelicalPairParams::seed_a().

Also times the same model through the Python binding (thermobear.bifurcation,
computed seed mesh/bearing stiffness, GIL released, rayon threads): wall
time per RK4 step for an independent sweep (lock-step lanes across speeds)
and an accelerating (continuation, one lane) sweep, and with --full-set the
seed diagram set (1001 speeds x 2 or 3 stiffness cases x up/down, 300 + 100
periods, 64 steps per period).

Usage: python3 benches/dynamics_compare.py [--rust-steps N] [--full-set]
"""

import math
import subprocess
import sys
import time

import numpy as np

try:
    from scipy.integrate import solve_ivp
except ImportError:  # pragma: no cover
    solve_ivp = None
try:
    import numba
except ImportError:
    numba = None


def seed_a():
    beta = math.radians(31.2)
    alpha_t = math.atan(math.tan(math.radians(16.5)) / math.cos(beta))
    mn = 1.537e-3

    def rb(z):
        return z * mn / (2 * math.cos(beta)) * math.cos(alpha_t)

    rp, rg = rb(29), rb(78)
    mp, mg, ip, ig = 1.201, 3.1, 1.152e-4, 1.6e-3
    kr, ka, zb = 2.0e8, 5.0e7, 0.02
    s, c, sb, cb = math.sin(alpha_t), math.cos(alpha_t), math.sin(beta), math.cos(beta)
    a = np.array([s * cb, c * cb, sb, -s * cb, -c * cb, -sb, cb])
    me = 1.0 / (rp**2 / ip + rg**2 / ig)
    m = np.array([mp, mp, mp, mg, mg, mg, me])
    kb = np.array([kr, kr, ka, kr, kr, ka, 0.0])
    cbv = np.where(kb > 0, 2 * zb * np.sqrt(kb * m), 0.0)
    n = 64
    ph = 2 * np.pi * np.arange(n) / n
    km = 6.0e8 * (1 + 0.1 * np.cos(ph))
    te = 2.0e-6 * np.sin(ph)
    cm = 2 * 0.07 * math.sqrt(km.mean() * me / cb**2)
    g = np.zeros(7)
    g[6] = 100.0 / rp / me
    return dict(a=a, m=m, kb=kb, cb=cbv, km=km, te=te, cm=cm, g=g, b=50e-6, z=29)


def tables(p, speed_rpm, steps):
    """k_m, e, de/dt on the RK4 half-step grid (linear interpolation here;
    the Rust side uses Catmull-Rom: timing only, not a result comparison)."""
    T = 60.0 / (p["z"] * speed_rpm)
    gl = 2 * steps
    ph = np.arange(gl) / gl * len(p["km"])
    idx = np.arange(len(p["km"]))
    km = np.interp(ph, idx, p["km"], period=len(p["km"]))
    e = np.interp(ph, idx, p["te"], period=len(p["te"]))
    de = np.gradient(np.concatenate([e, e[:1]]))[:-1] * gl / T
    return T, km, e, de


def rhs_factory(p):
    a, am, kbm, cbm, g = p["a"], p["a"] / p["m"], p["kb"] / p["m"], p["cb"] / p["m"], p["g"]
    b, cm = p["b"], p["cm"]

    def rhs(x, km, e, ed):
        q, v = x[:7], x[7:]
        d = a @ q - e
        f = d - min(max(d, -b), b)
        fm = km * f + (cm * (a @ v - ed) if f != 0.0 else 0.0)
        return np.concatenate([v, g - kbm * q - cbm * v - am * fm])

    return rhs


def numpy_rk4(p, steps_total, speed=10000.0, spp=64):
    T, km, e, de = tables(p, speed, spp)
    h = T / spp
    rhs = rhs_factory(p)
    x = np.zeros(14)
    t0 = time.perf_counter()
    for k in range(steps_total):
        j = (2 * k) % (2 * spp)
        j1, j2 = j + 1, (j + 2) % (2 * spp)
        k1 = rhs(x, km[j], e[j], de[j])
        k2 = rhs(x + 0.5 * h * k1, km[j1], e[j1], de[j1])
        k3 = rhs(x + 0.5 * h * k2, km[j1], e[j1], de[j1])
        k4 = rhs(x + h * k3, km[j2], e[j2], de[j2])
        x = x + h / 6 * (k1 + 2 * (k2 + k3) + k4)
    return (time.perf_counter() - t0) / steps_total * 1e9


def scipy_run(p, method, periods=20, speed=10000.0, spp=64):
    T = 60.0 / (p["z"] * speed)
    rhs = rhs_factory(p)
    n = len(p["km"])

    def f(t, x):
        ph = (t / T) % 1.0 * n
        i = int(ph) % n
        u = ph - int(ph)
        km = p["km"][i] * (1 - u) + p["km"][(i + 1) % n] * u
        e = p["te"][i] * (1 - u) + p["te"][(i + 1) % n] * u
        ed = (p["te"][(i + 1) % n] - p["te"][i]) * n / T
        return rhs(x, km, e, ed)

    t0 = time.perf_counter()
    sol = solve_ivp(f, (0, periods * T), np.zeros(14), method=method, rtol=1e-8, atol=1e-12)
    dt = time.perf_counter() - t0
    # ns per equivalent RK4 step (same span at 64 steps per period) and per solver step
    return dt / (periods * spp) * 1e9, dt / max(len(sol.t) - 1, 1) * 1e9


def numba_rk4(p, steps_total, speed=10000.0, spp=64):
    T, km, e, de = tables(p, speed, spp)
    a, am, kbm, cbm, g = p["a"], p["a"] / p["m"], p["kb"] / p["m"], p["cb"] / p["m"], p["g"]
    b, cm, h = p["b"], p["cm"], T / spp

    @numba.njit(cache=False, fastmath=False)
    def run(nsteps, x):
        k = np.zeros((4, 14))
        y = np.empty(14)
        for s in range(nsteps):
            j0 = (2 * s) % (2 * spp)
            js = (j0, j0 + 1, j0 + 1, (j0 + 2) % (2 * spp))
            for st in range(4):
                cst = 0.0 if st == 0 else (0.5 if st < 3 else 1.0)
                for i in range(14):
                    y[i] = x[i] + cst * h * (k[st - 1, i] if st > 0 else 0.0)
                j = js[st]
                d = 0.0
                dv = 0.0
                for i in range(7):
                    d += a[i] * y[i]
                    dv += a[i] * y[7 + i]
                d -= e[j]
                f = d - min(max(d, -b), b)
                fm = km[j] * f + (cm * (dv - de[j]) if f != 0.0 else 0.0)
                for i in range(7):
                    k[st, i] = y[7 + i]
                    k[st, 7 + i] = g[i] - kbm[i] * y[i] - cbm[i] * y[7 + i] - am[i] * fm
            for i in range(14):
                x[i] += h / 6 * (k[0, i] + 2 * (k[1, i] + k[2, i]) + k[3, i])
        return x

    run(10, np.zeros(14))
    t0 = time.perf_counter()
    run(steps_total, np.zeros(14))
    return (time.perf_counter() - t0) / steps_total * 1e9


def rust_ns(steps):
    cmd = ["cargo", "run", "--release", "--quiet", "--example", "rk4_step_timing", "--", str(steps)]
    try:
        out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
    except (OSError, subprocess.CalledProcessError) as exc:
        print(f"rust timing unavailable: {exc}")
        return None, None
    # `key value` lines; the per-instruction-set table lines have more fields.
    pairs = (line.split() for line in out.splitlines())
    vals = dict(p for p in pairs if len(p) == 2)
    return float(vals["ns_per_step"]), float(vals.get("batch_ns_per_lane_step", "nan"))


def binding_ns(full_set=False):
    """Wall ns per RK4 step through thermobear.bifurcation (no Lyapunov runs)."""
    try:
        import thermobear as tb
    except ImportError as exc:  # pragma: no cover
        print(f"python binding unavailable: {exc}")
        return []
    g = tb.GearPair.preset("seed-electric-drive")
    sys_c = tb.GearSystem(g, stiffness="constant")
    tr, rec, spp = 300, 100, 64
    rows = []
    for direction, n in (("independent", 64), ("up", 16)):
        speeds = np.linspace(6500.0, 16500.0, n)
        t0 = time.perf_counter()
        tb.bifurcation(sys_c, speeds, direction, tr, rec, spp, lyapunov_periods=0)
        dt = time.perf_counter() - t0
        rows.append(
            (f"binding sweep {direction} (wall, all threads)", dt / (n * (tr + rec) * spp) * 1e9)
        )
    if full_set:
        systems = {}
        for case in ("constant", "speed", "thermal"):
            try:
                systems[case] = tb.GearSystem(g, stiffness=case)
            except tb.ConfigError:
                print(f"stiffness case {case!r} unavailable in this build: skipped")
        speeds = np.linspace(6500.0, 16500.0, 1001)
        t0 = time.perf_counter()
        tb.bifurcation_set(systems, speeds, ("up", "down"), tr, rec, spp)
        dt = time.perf_counter() - t0
        jobs = 2 * len(systems)
        print(f"seed diagram set via binding: {jobs} sweeps x 1001 speeds in {dt:.2f} s wall")
        rows.append(
            ("binding seed set (wall, all threads)", dt / (jobs * 1001 * (tr + rec) * spp) * 1e9)
        )
    return rows


def main():
    steps = 5_000_000
    if "--rust-steps" in sys.argv:
        steps = int(sys.argv[sys.argv.index("--rust-steps") + 1])
    p = seed_a()
    rust, rust_batch = rust_ns(steps)
    rows = [("numpy RK4", numpy_rk4(p, 20_000))]
    if solve_ivp is not None:
        for meth in ("RK45", "DOP853"):
            per_equiv, per_step = scipy_run(p, meth)
            rows.append((f"scipy solve_ivp {meth} (per 64/period step)", per_equiv))
            rows.append((f"scipy solve_ivp {meth} (per solver step)", per_step))
    else:
        print("scipy not importable: skipped")
    if numba is not None:
        rows.append(("numba RK4", numba_rk4(p, 2_000_000)))
    else:
        print("numba not importable: skipped")
    rows += binding_ns("--full-set" in sys.argv)
    if rust is not None:
        print(f"{'rust RK4 scalar':48s} {rust:12.1f} ns/step")
        print(f"{'rust RK4 lock-step (per lane)':48s} {rust_batch:12.1f} ns/step")
    for name, ns in rows:
        ratio = f"{ns / rust:10.0f} x rust scalar" if rust else ""
        print(f"{name:48s} {ns:12.1f} ns/step {ratio}")


if __name__ == "__main__":
    main()
