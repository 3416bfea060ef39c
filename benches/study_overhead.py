"""Cost of the study machinery and of the batch entry points.

    python benches/study_overhead.py [--quick] [--no-dask]

1. Bearing points: a ``Study`` run into parquet against the bare work, one
   ``Bearing.solve_many`` call over the same points (target: < 5 % more).
2. ``Bearing.solve_many`` per point (one thread) against the native solve
   of the same points (``cargo run --release --example batch_timing``;
   target: within 1.5x).
3. A 20,000-point thermal grid on a Dask LocalCluster with 2 worker
   processes against 1 (one thread each; target: >= 1.7x faster).

Each timing is the best of a few repeats, interleaved, and the load
average is printed with it. On a shared machine wall time moves with the
other work, so 1. and 2. also compare CPU time (the process's, all its
threads; the native loop's from the child process), which the load leaves
nearly alone.
"""

from __future__ import annotations

import argparse
import os
import re
import resource
import subprocess
import tempfile
import time
from pathlib import Path

import numpy as np
import polars as pl

import thermobear as tb

ROOT = Path(__file__).resolve().parents[1]


def best(fn, repeats: int) -> tuple[float, float]:
    """Least (wall, CPU) seconds of ``repeats`` calls."""
    wall, cpu = [], []
    for _ in range(repeats):
        t, c = time.perf_counter(), time.process_time()
        fn()
        wall.append(time.perf_counter() - t)
        cpu.append(time.process_time() - c)
    return min(wall), min(cpu)


def load() -> str:
    return "load average {:.2f} {:.2f} {:.2f}".format(*os.getloadavg())


def study_overhead(n_speeds: int, repeats: int) -> None:
    grid = {
        "speed_rpm": {"start": 1000, "stop": 20000, "num": n_speeds},
        "axial_n": list(np.linspace(200.0, 1000.0, 20)),
        "radial_n": list(np.linspace(0.0, 500.0, 25)),
    }
    study = tb.Study("bearing", grid)
    points = study.points().select("speed_rpm", "axial_n", "radial_n")
    b = tb.Bearing.preset("7008C")

    def bare():
        b.solve_many(points)

    def studied():
        with tempfile.TemporaryDirectory() as d:
            tb.Study("bearing", grid).run(d, progress=False)

    runs = [(best(bare, 1), best(studied, 1)) for _ in range(repeats)]
    bare_t = [min(r[0][i] for r in runs) for i in (0, 1)]
    study_t = [min(r[1][i] for r in runs) for i in (0, 1)]
    n = study.n_points
    print(f"\n1. bearing study, {n} points, {study.n_chunks} chunks, parquet ({load()})")
    for i, what in enumerate(("wall", "CPU")):
        print(
            f"   {what:4s}: bare solve_many {bare_t[i] / n * 1e6:7.2f} us/point, "
            f"study.run {study_t[i] / n * 1e6:7.2f} us/point, "
            f"overhead {100 * (study_t[i] / bare_t[i] - 1):6.2f} %  (target < 5 %)"
        )


def native_timing(n: int) -> tuple[float, float] | None:
    """(wall, CPU) microseconds per point of the bare native solve, one thread."""
    exe = (
        Path(os.environ.get("CARGO_TARGET_DIR", ROOT / "target")) / "release/examples/batch_timing"
    )
    if not exe.exists():
        print("   (build the native timing: cargo build --release --example batch_timing)")
        return None
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    out = subprocess.run([str(exe), str(n), "single"], capture_output=True, text=True, check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime) / n * 1e6
    m = re.search(r"native solve, 1 thread:\s+([\d.]+) us/point", out.stdout)
    return (float(m.group(1)), cpu) if m else None


def solve_many_vs_native(n: int, repeats: int) -> None:
    b = tb.Bearing.preset("7008C")
    at = np.arange(n) / (n - 1)
    # The points of examples/batch_timing.rs (ring held level).
    points = pl.DataFrame(
        {"axial_n": np.full(n, 500.0), "radial_n": 500.0 * at, "speed_rpm": 1000 + 19000 * at}
    )
    py, native = [], []
    for _ in range(repeats):
        wall, cpu = best(lambda: b.solve_many(points, threads=1), 1)
        py.append((wall / n * 1e6, cpu / n * 1e6))
        t = native_timing(n)
        if t is not None:
            native.append(t)
    print(f"\n2. solve_many against the native solve, {n} points, one thread ({load()})")
    for i, what in enumerate(("wall", "CPU")):
        p = min(r[i] for r in py)
        line = f"   {what:4s}: Python solve_many {p:7.2f} us/point"
        if native:
            nat = min(r[i] for r in native)
            line += f", native solve {nat:7.2f} us/point, ratio {p / nat:5.3f} (target <= 1.5)"
        print(line)
    wall, _ = best(lambda: b.solve_many(points), 1)
    print(f"   solve_many on all {os.cpu_count()} cores: {wall / n * 1e6:7.2f} us/point (wall)")


def _worker_cpu() -> float:
    r = resource.getrusage(resource.RUSAGE_SELF)
    return r.ru_utime + r.ru_stime


def dask_scaling(n_speeds: int) -> None:
    from dask.distributed import Client, LocalCluster

    grid = {
        "speed_rpm": {"start": 2000, "stop": 20000, "num": n_speeds},
        "axial_n": list(np.linspace(200.0, 1100.0, 10)),
        "radial_n": list(np.linspace(0.0, 950.0, 20)),
    }
    n = tb.Study("thermal", grid).n_points
    print(f"\n3. thermal grid of {n} points on a LocalCluster, 1 thread per worker")
    times, frames, cpus = {}, {}, {}
    for workers in (1, 2):
        with (
            LocalCluster(
                n_workers=workers, processes=True, threads_per_worker=1, dashboard_address=":0"
            ) as cluster,
            Client(cluster) as client,
        ):
            client.run(lambda: tb.Bearing.preset("7008C"))  # workers up and imported
            cpu0 = client.run(_worker_cpu)
            s = tb.Study("thermal", grid)
            before = load()
            t = time.perf_counter()
            frames[workers] = s.run(engine=client, progress=False)
            times[workers] = time.perf_counter() - t
            cpu = [client.run(_worker_cpu)[w] - cpu0[w] for w in cpu0]
            print(
                f"   {workers} worker(s): {times[workers]:7.2f} s wall, worker CPU "
                + " + ".join(f"{c:.1f}" for c in cpu)
                + f" s  ({before} before)"
            )
            cpus[workers] = cpu
    assert frames[1].equals(frames[2]), "results differ between 1 and 2 workers"
    print(f"   speed-up 2 vs 1:  {times[1] / times[2]:7.2f}x wall  (target >= 1.7x)")
    # On two free cores a worker's wall time is its CPU time: the speed-up
    # is then the one worker's CPU over the busier of the two.
    est = sum(cpus[1]) / max(cpus[2])
    print(f"   on two free cores (CPU of 1 worker / busier of 2): {est:5.2f}x (estimate)")


def main() -> None:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--quick", action="store_true", help="smaller grids")
    p.add_argument("--no-dask", action="store_true", help="skip the LocalCluster scaling")
    a = p.parse_args()
    print(f"thermobear {tb.__version__}, {os.cpu_count()} cores")
    study_overhead(20 if a.quick else 100, 2 if a.quick else 3)
    solve_many_vs_native(2000 if a.quick else 20000, 2 if a.quick else 3)
    if not a.no_dask:
        dask_scaling(10 if a.quick else 100)


if __name__ == "__main__":
    main()
