"""Nonlinear dynamics of the gear system: bifurcation diagrams (one
direction or a set), the motion regimes read off them, regime maps over
torque and speed, and the largest Lyapunov exponent."""

from __future__ import annotations

from typing import Any, Callable, Mapping, Optional, Sequence, Union

import numpy as np

from .. import _native
from .pair import _config_error
from .system import GearSystem

Progress = Optional[Callable[[int, int], Any]]


def _speeds(speeds_rpm: Sequence[float]) -> np.ndarray:
    s = np.ascontiguousarray(np.asarray(speeds_rpm, dtype=float).ravel())
    if s.size == 0:
        raise _config_error("invalid speeds_rpm = []: give at least one speed")
    return s


def _check_system(system: Any) -> None:
    if not isinstance(system, GearSystem):
        raise _config_error(f"invalid system = {system!r}: must be a thermobear.GearSystem")


def _points_frame(
    cols: Mapping[str, Any], direction: str, case: Optional[str]
) -> "polars.DataFrame":  # noqa: F821
    import polars as pl

    counts = np.asarray(cols["poincare_count"])
    per_speed = {
        "speed_rpm": np.asarray(cols["speed_rpm"]),
        "regime": list(cols["regime"]),
        "period": np.asarray(cols["period"]),
        "impact": list(cols["impact"]),
        "lyapunov_per_period": list(cols["lyapunov_per_period"]),
        "dte_min_um": np.asarray(cols["dte_min_um"]),
        "dte_max_um": np.asarray(cols["dte_max_um"]),
        "jump_after": list(cols["jump_after"]),
    }
    speed_df = pl.DataFrame(per_speed, schema_overrides={"lyapunov_per_period": pl.Float64})
    idx = np.repeat(np.arange(len(counts)), counts)
    df = speed_df[idx].with_columns(pl.Series("dte_um", np.asarray(cols["poincare_dte_um"])))
    df = df.with_columns(pl.lit(direction).alias("direction"))
    if case is not None:
        df = df.with_columns(pl.lit(case).alias("case"))
    first = ["speed_rpm", "dte_um"]
    return df.select(first + [c for c in df.columns if c not in first])


def bifurcation(
    system: GearSystem,
    speeds_rpm: Sequence[float],
    direction: str = "up",
    transient_periods: int = 300,
    record_periods: int = 100,
    steps_per_period: int = 64,
    *,
    lyapunov_periods: int = 100,
    progress: Progress = None,
) -> "polars.DataFrame":  # noqa: F821
    """Speed sweep (A Figs. 14-15): ``"up"``/``"down"`` carry the state from
    speed to speed (continuation), ``"independent"`` starts every speed from
    the static state (parallel). One row per Poincare sample (once per mesh
    period): ``speed_rpm``, ``dte_um`` (dynamic transmission error
    ``delta_n - e`` along the mesh normal), and per-speed ``regime``
    (period-n / quasi-periodic / chaotic), ``period``, ``impact``
    (no-impact / single-sided / double-sided), ``lyapunov_per_period``
    (non-periodic speeds), ``dte_min_um``, ``dte_max_um``, ``jump_after``
    (amplitude jump to the next speed), ``direction``.
    GIL released; Ctrl-C interrupts; ``progress(done, total)``."""
    _check_system(system)
    cols = _native.bifurcation(
        system._s,
        _speeds(speeds_rpm),
        direction,
        int(transient_periods),
        int(record_periods),
        int(steps_per_period),
        int(lyapunov_periods),
        progress,
    )
    return _points_frame(cols, direction, None)


def bifurcation_set(
    systems: Mapping[str, GearSystem],
    speeds_rpm: Sequence[float],
    directions: Sequence[str] = ("up", "down"),
    transient_periods: int = 300,
    record_periods: int = 100,
    steps_per_period: int = 64,
    *,
    lyapunov_periods: int = 100,
    progress: Progress = None,
) -> "polars.DataFrame":  # noqa: F821
    """Every (case, direction) sweep over the same speeds in parallel
    (lock-step batches); the :func:`bifurcation` columns plus ``case``."""
    import polars as pl

    if not systems:
        raise _config_error("invalid systems = {}: give at least one")
    jobs = [(name, sys, d) for name, sys in systems.items() for d in directions]
    for _, sys, _ in jobs:
        _check_system(sys)
    res = _native.bifurcation_many(
        [j[1]._s for j in jobs],
        [j[2] for j in jobs],
        _speeds(speeds_rpm),
        int(transient_periods),
        int(record_periods),
        int(steps_per_period),
        int(lyapunov_periods),
        progress,
    )
    return pl.concat(
        [_points_frame(c, d, name) for (name, _, d), c in zip(jobs, res, strict=False)]
    )


def _per_speed_from_points(pts: Any, rel_tol: float = 1e-3, max_period: int = 16) -> Any:
    """Per-speed regime from bare Poincare samples: the smallest n with
    x[k+n] = x[k] (within rel_tol of the diagram's range) for all k."""
    import polars as pl

    span = float(pts["dte_um"].max() - pts["dte_um"].min()) or 1.0
    rows = []
    for (speed,), g in pts.group_by(["speed_rpm"], maintain_order=True):
        x = g["dte_um"].to_numpy()
        period = 0
        for n in range(1, min(max_period, len(x) - 1) + 1):
            if np.all(np.abs(x[n:] - x[:-n]) <= rel_tol * span):
                period = n
                break
        rows.append((speed, f"period-{period}" if period else "non-periodic", period))
    return pl.DataFrame(
        {
            "speed_rpm": [r[0] for r in rows],
            "regime": [r[1] for r in rows],
            "period": [r[2] for r in rows],
        }
    )


def regimes(pts: Any) -> "polars.DataFrame":  # noqa: F821
    """Collapse a :func:`bifurcation` frame into speed ranges of one regime:
    ``speed_from_rpm``, ``speed_to_rpm``, ``regime``, ``period``, ``impact``,
    ``speeds`` (count), ``jump_at_end`` (amplitude jump to the next range),
    per ``case``/``direction`` when present. A frame with only ``speed_rpm``
    and ``dte_um`` is classified by the period of its samples."""
    import polars as pl

    if "speed_rpm" not in pts.columns:
        raise _config_error("invalid pts = frame without 'speed_rpm'")
    keys = [k for k in ("case", "direction") if k in pts.columns]
    if "regime" in pts.columns:
        cols = ["speed_rpm", "regime"] + [
            c for c in ("period", "impact", "jump_after") if c in pts.columns
        ]
        per = pts.select(keys + cols).unique(
            subset=keys + ["speed_rpm"], keep="first", maintain_order=True
        )
    else:
        if "dte_um" not in pts.columns:
            raise _config_error("invalid pts = frame without 'regime' or 'dte_um'")
        parts = []
        groups = pts.group_by(keys, maintain_order=True) if keys else [((), pts)]
        for key, g in groups:
            p = _per_speed_from_points(g)
            for k, v in zip(keys, key if isinstance(key, tuple) else (key,), strict=False):
                p = p.with_columns(pl.lit(v).alias(k))
            parts.append(p)
        per = pl.concat(parts)
    if "period" not in per.columns:
        per = per.with_columns(pl.lit(0).alias("period"))
    if "impact" not in per.columns:
        per = per.with_columns(pl.lit("unknown").alias("impact"))
    if "jump_after" not in per.columns:
        per = per.with_columns(pl.lit(False).alias("jump_after"))
    out = []
    groups = per.group_by(keys, maintain_order=True) if keys else [((), per)]
    for key, g in groups:
        g = g.sort("speed_rpm")
        s = g["speed_rpm"].to_numpy()
        reg = g["regime"].to_list()
        per_n = g["period"].to_list()
        imp = g["impact"].to_list()
        jump = g["jump_after"].to_list()
        start = 0
        for i in range(len(s)):
            last = i == len(s) - 1
            if last or jump[i] or reg[i + 1] != reg[i] or imp[i + 1] != imp[i]:
                row = dict(zip(keys, key if isinstance(key, tuple) else (key,), strict=False))
                row.update(
                    speed_from_rpm=float(s[start]),
                    speed_to_rpm=float(s[i]),
                    regime=reg[i],
                    period=int(per_n[i]),
                    impact=imp[i],
                    speeds=i - start + 1,
                    jump_at_end=bool(jump[i]) and not last,
                )
                out.append(row)
                start = i + 1
    return pl.DataFrame(out)


def regime_map(
    system: GearSystem,
    torques_nm: Sequence[float],
    speeds_rpm: Sequence[float],
    te_scales: Sequence[float] = (1.0,),
    transient_periods: int = 300,
    record_periods: int = 100,
    steps_per_period: int = 64,
    *,
    lyapunov_periods: int = 100,
    progress: Progress = None,
) -> "polars.DataFrame":  # noqa: F821
    """Motion regime over input torque x speed (x TE scale), every cell from
    its static state: ``torque_nm``, ``te_scale``, ``te_amplitude_um``,
    ``speed_rpm``, ``regime``, ``period``, ``impact``, ``amplitude_um``,
    ``mean_dte_um``. The bearing stiffness schedule stays the system's."""
    import polars as pl

    _check_system(system)
    torques = [float(t) for t in np.asarray(torques_nm, dtype=float).ravel()]
    scales = [float(e) for e in np.asarray(te_scales, dtype=float).ravel()]
    cols = _native.regime_map(
        system._s,
        torques,
        scales,
        _speeds(speeds_rpm),
        int(transient_periods),
        int(record_periods),
        int(steps_per_period),
        int(lyapunov_periods),
        progress,
    )
    df = pl.DataFrame(
        {k: (np.asarray(v) if not isinstance(v, list) else v) for k, v in cols.items()}
    )
    te = system.params["te_amplitude_um"]
    return df.with_columns((pl.col("te_scale") * te).alias("te_amplitude_um"))


def largest_lyapunov(
    system_or_name: Union[str, GearSystem],
    speed_rpm: Optional[float] = None,
    *,
    time: Optional[float] = None,
    step: Optional[float] = None,
    transient_time: Optional[float] = None,
    method: str = "benettin",
    periods: int = 200,
    transient_periods: int = 300,
    steps_per_period: int = 64,
) -> float:
    """Largest Lyapunov exponent per unit time.

    Reference systems by name: ``"lorenz"`` (sigma 10, rho 28, beta 8/3;
    published 0.9056) and ``"duffing-ueda"`` (x'' + 0.05 x' + x^3 = 7.5 cos t;
    about 0.10), ``method="benettin"`` or ``"variational"``. For a
    :class:`GearSystem` give ``speed_rpm``; the exponent is in 1/s (Benettin,
    renormalised once per mesh period)."""
    if isinstance(system_or_name, str):
        return float(
            _native.largest_lyapunov_reference(system_or_name, time, step, transient_time, method)
        )
    _check_system(system_or_name)
    if speed_rpm is None:
        raise _config_error("invalid speed_rpm = None: a gear system needs a speed")
    return float(
        _native.largest_lyapunov_gear(
            system_or_name._s,
            float(speed_rpm),
            int(periods),
            int(transient_periods),
            int(steps_per_period),
        )
    )
