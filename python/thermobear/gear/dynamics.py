"""Nonlinear dynamics of the gear system: bifurcation diagrams (one
direction or a set), the motion regimes read off them, regime maps over
torque and speed, and the largest Lyapunov exponent."""

from __future__ import annotations

from typing import Any, Callable, Mapping, Optional, Sequence, Union

import numpy as np

from .. import _native
from .pair import _config_error
from .system import GearSystem
from .tables import as_speeds

Progress = Optional[Callable[[int, int], Any]]

#: Classifier and sweep settings reachable as keyword arguments of
#: :func:`bifurcation`, :func:`bifurcation_set` and :func:`regime_map`
#: (``None``: the default named in :func:`bifurcation`).
SETTING_NAMES = (
    "max_transient_periods",
    "max_period",
    "period_rel_tol",
    "converging_ratio",
    "lyapunov_block_periods",
    "lyapunov_max_periods",
    "lyapunov_sigmas",
    "lyapunov_threshold_per_mesh_period",
    "zero_one_threshold",
    "jump_rel_amplitude",
    "jump_trend_factor",
    "jump_window_speeds",
)

#: Per-speed columns of a sweep (everything but the Poincare samples).
PER_SPEED_COLUMNS = (
    "regime",
    "period",
    "impact",
    "lyapunov_per_mesh_period",
    "lyapunov_stderr_per_mesh_period",
    "lyapunov_per_s",
    "lyapunov_stderr_per_s",
    "zero_one_k",
    "transient_periods",
    "settled",
    "dte_min_um",
    "dte_max_um",
    "jump_after",
    "transition_after",
    "transition_dte_min_change_um",
    "transition_dte_max_change_um",
)

_NULLABLE = {
    "lyapunov_per_mesh_period": "f",
    "lyapunov_stderr_per_mesh_period": "f",
    "lyapunov_per_s": "f",
    "lyapunov_stderr_per_s": "f",
    "zero_one_k": "f",
    "transition_after": "s",
    "transition_dte_min_change_um": "f",
    "transition_dte_max_change_um": "f",
}


def _speeds(speeds_rpm: Sequence[float]) -> np.ndarray:
    return as_speeds(speeds_rpm)


def _count(name: str, value: Any, minimum: int) -> int:
    if isinstance(value, bool) or not isinstance(value, (int, np.integer)):
        if not (isinstance(value, float) and value.is_integer()):
            raise _config_error(f"invalid {name} = {value!r}: must be a whole number")
    if int(value) < minimum:
        raise _config_error(f"invalid {name} = {value!r}: must be at least {minimum}")
    return int(value)


def _counts(transient: Any, record: Any, steps: Any, lyapunov: Any) -> tuple[int, ...]:
    return (
        _count("transient_periods", transient, 0),
        _count("record_periods", record, 2),
        _count("steps_per_period", steps, 1),
        _count("lyapunov_periods", lyapunov, 0),
    )


def _settings(given: Mapping[str, Any]) -> dict[str, Any]:
    """The classifier settings that were given (the others keep their defaults)."""
    return {k: given[k] for k in SETTING_NAMES if given.get(k) is not None}


def _check_system(system: Any) -> None:
    if not isinstance(system, GearSystem):
        raise _config_error(f"invalid system = {system!r}: must be a thermobear.GearSystem")


def _points_frame(
    cols: Mapping[str, Any], direction: str, case: Optional[str]
) -> "polars.DataFrame":  # noqa: F821
    import polars as pl

    counts = np.asarray(cols["poincare_count"])
    per_speed: dict[str, Any] = {"speed_rpm": np.asarray(cols["speed_rpm"])}
    for c in PER_SPEED_COLUMNS:
        v = cols[c]
        per_speed[c] = list(v) if isinstance(v, list) else np.asarray(v)
    types = {c: (pl.Float64 if t == "f" else pl.Utf8) for c, t in _NULLABLE.items()}
    speed_df = pl.DataFrame(per_speed, schema_overrides=types)
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
    max_transient_periods: Optional[int] = None,
    max_period: Optional[int] = None,
    period_rel_tol: Optional[float] = None,
    converging_ratio: Optional[float] = None,
    lyapunov_block_periods: Optional[int] = None,
    lyapunov_max_periods: Optional[int] = None,
    lyapunov_sigmas: Optional[float] = None,
    lyapunov_threshold_per_mesh_period: Optional[float] = None,
    zero_one_threshold: Optional[float] = None,
    jump_rel_amplitude: Optional[float] = None,
    jump_trend_factor: Optional[float] = None,
    jump_window_speeds: Optional[int] = None,
) -> "polars.DataFrame":  # noqa: F821
    """Speed sweep (A Figs. 14-15). ``"up"``/``"down"`` carry the state from
    speed to speed (continuation), ``"independent"`` starts every speed from
    the static state (parallel). ``speeds_rpm`` in any order (distinct): they
    are sorted and swept ascending for ``"up"``/``"independent"``, descending
    for ``"down"``; the rows come in that sweep order.

    One row per Poincare sample (once per mesh period): ``speed_rpm``,
    ``dte_um`` (dynamic transmission error ``delta_n - e``), and per speed:
    ``regime`` (period-n / quasi-periodic / chaotic), ``period``, ``impact``,
    ``lyapunov_per_mesh_period`` / ``lyapunov_per_s`` and their standard
    errors ``lyapunov_stderr_per_mesh_period`` / ``lyapunov_stderr_per_s``
    (non-periodic speeds; per s = per mesh period x mesh frequency),
    ``zero_one_k`` (0-1 test K), ``transient_periods`` (run, incl. the
    adaptive extension), ``settled`` (False: the section was still
    converging at ``max_transient_periods``; the label is provisional),
    ``dte_min_um``, ``dte_max_um``, ``jump_after`` (amplitude jump to the
    next speed in sweep order, same non-chaotic regime family only),
    ``transition_after`` (regime-family change to the next speed:
    ``enters-chaos``, ``exits-chaos``, ``enters-quasi-periodic``,
    ``exits-quasi-periodic``) with its size ``transition_dte_min_change_um``,
    ``transition_dte_max_change_um``, and ``direction``.

    Classifier settings (keyword-only, ``None`` = default):
    ``max_transient_periods`` [mesh periods] cap of the adaptive transient
    (default max(1500, 5 x transient_periods); = transient_periods turns the
    extension off); ``max_period`` [mesh periods] largest period tested
    (default 32, needs 2 x max_period <= record_periods); ``period_rel_tol``
    [-] tolerance of the period and settling tests relative to the orbit's
    peak-to-peak DTE (1e-4); ``converging_ratio`` [-] a mismatch shrinking
    below this fraction of its first-quarter value is still settling (0.9);
    ``lyapunov_block_periods`` [mesh periods] block length of the Lyapunov
    standard error (10); ``lyapunov_max_periods`` [mesh periods] longest
    Lyapunov run while undecided (max(400, 4 x lyapunov_periods));
    ``lyapunov_sigmas`` [-] chaos needs the exponent above the threshold by
    this many standard errors (3); ``lyapunov_threshold_per_mesh_period``
    [1/mesh period] (1e-3); ``zero_one_threshold`` [-] 0-1 test K for chaos
    (0.5, used with >= 200 section points); ``jump_rel_amplitude`` [-] jump
    step relative to the amplitude (0.2); ``jump_trend_factor`` [-] jump
    step relative to the local median step (5), taken over
    ``jump_window_speeds`` [speeds] neighbouring steps on each side (5).
    Bad values raise ConfigError
    naming the setting. GIL released; Ctrl-C interrupts; ``progress(done,
    total)``."""
    _check_system(system)
    cols = _native.bifurcation(
        system._s,
        _speeds(speeds_rpm),
        direction,
        *_counts(transient_periods, record_periods, steps_per_period, lyapunov_periods),
        progress,
        _settings(locals()),
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
    max_transient_periods: Optional[int] = None,
    max_period: Optional[int] = None,
    period_rel_tol: Optional[float] = None,
    converging_ratio: Optional[float] = None,
    lyapunov_block_periods: Optional[int] = None,
    lyapunov_max_periods: Optional[int] = None,
    lyapunov_sigmas: Optional[float] = None,
    lyapunov_threshold_per_mesh_period: Optional[float] = None,
    zero_one_threshold: Optional[float] = None,
    jump_rel_amplitude: Optional[float] = None,
    jump_trend_factor: Optional[float] = None,
    jump_window_speeds: Optional[int] = None,
) -> "polars.DataFrame":  # noqa: F821
    """Every (case, direction) sweep over the same speeds in parallel
    (lock-step batches); the :func:`bifurcation` columns (each sweep in its
    sweep order) plus ``case``. Settings as in :func:`bifurcation`."""
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
        *_counts(transient_periods, record_periods, steps_per_period, lyapunov_periods),
        progress,
        _settings(locals()),
    )
    return pl.concat(
        [_points_frame(c, d, name) for (name, _, d), c in zip(jobs, res, strict=False)]
    )


def _per_speed_from_points(pts: Any, rel_tol: float, max_period: int) -> Any:
    """Per-speed regime from bare Poincare samples: the smallest n <=
    max_period (with at least 2 n samples) with x[k+n] = x[k] within
    rel_tol of the diagram's range for all k."""
    import polars as pl

    span = float(pts["dte_um"].max() - pts["dte_um"].min()) or 1.0
    rows = []
    for (speed,), g in pts.group_by(["speed_rpm"], maintain_order=True):
        x = g["dte_um"].to_numpy()
        period = 0
        for n in range(1, min(max_period, len(x) // 2) + 1):
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


def _per_speed(pts: Any, keys: list[str], rel_tol: float, max_period: int) -> Any:
    """One row per (case, direction, speed) with the per-speed columns."""
    import polars as pl

    if "regime" in pts.columns:
        cols = ["speed_rpm", "regime"] + [c for c in PER_SPEED_COLUMNS[1:] if c in pts.columns]
        return pts.select(keys + cols).unique(
            subset=keys + ["speed_rpm"], keep="first", maintain_order=True
        )
    if "dte_um" not in pts.columns:
        raise _config_error("invalid pts = frame without 'regime' or 'dte_um'")
    parts = []
    groups = pts.group_by(keys, maintain_order=True) if keys else [((), pts)]
    for key, g in groups:
        p = _per_speed_from_points(g, rel_tol, max_period)
        for k, v in zip(keys, key if isinstance(key, tuple) else (key,), strict=False):
            p = p.with_columns(pl.lit(v).alias(k))
        parts.append(p)
    return pl.concat(parts)


def _range_row(c: dict[str, list], start: int, i: int, end: bool) -> dict[str, Any]:
    """One range (rows start..i of one sweep); ``end``: another range follows."""

    def get(k: str, j: int, default: Any = None) -> Any:
        return c[k][j] if k in c else default

    def at_end(k: str) -> Any:
        return get(k, i) if end else None

    rng = range(start, i + 1)
    lyap = [v for v in (get("lyapunov_per_mesh_period", k) for k in rng) if v is not None]
    se = [v for v in (get("lyapunov_stderr_per_mesh_period", k) for k in rng) if v is not None]
    unsettled = [float(c["speed_rpm"][k]) for k in rng if get("settled", k, True) is False]
    return dict(
        speed_from_rpm=float(c["speed_rpm"][start]),
        speed_to_rpm=float(c["speed_rpm"][i]),
        regime=c["regime"][i],
        period=int(get("period", i, 0)),
        impact=get("impact", i, "unknown"),
        speeds=i - start + 1,
        jump_at_end=bool(get("jump_after", i, False)) and end,
        transition_at_end=at_end("transition_after"),
        transition_dte_min_change_um=at_end("transition_dte_min_change_um"),
        transition_dte_max_change_um=at_end("transition_dte_max_change_um"),
        lyapunov_per_mesh_period_min=min(lyap, default=None),
        lyapunov_stderr_per_mesh_period_max=max(se, default=None),
        unsettled_speeds=len(unsettled),
        unsettled_speeds_rpm=", ".join(f"{v:g}" for v in unsettled),
    )


def _ranges(g: Any, base: dict[str, Any]) -> list[dict[str, Any]]:
    """Ranges of one sweep (rows in sweep order) with one regime and impact,
    closed early by a jump."""
    c = {k: g[k].to_list() for k in g.columns}
    n = len(c["speed_rpm"])
    imp = c.get("impact", [None] * n)
    jump = c.get("jump_after", [False] * n)
    out, start = [], 0
    for i in range(n):
        last = i == n - 1
        if last or jump[i] or c["regime"][i + 1] != c["regime"][i] or imp[i + 1] != imp[i]:
            out.append(dict(base, **_range_row(c, start, i, not last)))
            start = i + 1
    return out


def regimes(pts: Any, *, max_period: int = 32, period_rel_tol: float = 1e-3) -> "polars.DataFrame":  # noqa: F821
    """Collapse a :func:`bifurcation` frame into speed ranges of one regime
    and impact, in sweep order (``"down"``: descending speed, so
    ``speed_from_rpm`` > ``speed_to_rpm``), per ``case``/``direction`` when
    present: ``speed_from_rpm``, ``speed_to_rpm``, ``regime``, ``period``,
    ``impact``, ``speeds`` (count), ``jump_at_end`` (amplitude jump to the
    next range), ``transition_at_end`` (``enters-chaos``, ``exits-chaos``,
    ``enters-quasi-periodic``, ``exits-quasi-periodic`` or null) with
    ``transition_dte_min_change_um``/``transition_dte_max_change_um``,
    ``lyapunov_per_mesh_period_min`` and
    ``lyapunov_stderr_per_mesh_period_max`` over the range (null when none
    was computed), ``unsettled_speeds`` (count) and ``unsettled_speeds_rpm`` (the
    speeds whose transient did not settle, comma-separated: provisional
    labels; per speed see the ``settled`` column of the sweep). A frame with only
    ``speed_rpm`` and ``dte_um`` is classified by the period of its samples:
    the smallest n <= ``max_period`` [mesh periods] (needing 2 n samples)
    with every sample repeating after n within ``period_rel_tol`` [-] of the
    frame's DTE range, else ``non-periodic``."""
    import polars as pl

    if "speed_rpm" not in pts.columns:
        raise _config_error("invalid pts = frame without 'speed_rpm'")
    keys = [k for k in ("case", "direction") if k in pts.columns]
    max_period = _count("max_period", max_period, 1)
    if not 0.0 < float(period_rel_tol) < 1.0:
        raise _config_error(f"invalid period_rel_tol = {period_rel_tol!r}: must lie in (0, 1)")
    per = _per_speed(pts, keys, float(period_rel_tol), max_period)
    out = []
    groups = per.group_by(keys, maintain_order=True) if keys else [((), per)]
    for key, g in groups:
        base = dict(zip(keys, key if isinstance(key, tuple) else (key,), strict=False))
        g = g.sort("speed_rpm", descending=base.get("direction") == "down")
        out += _ranges(g, base)
    schema = {
        "transition_at_end": pl.Utf8,
        "transition_dte_min_change_um": pl.Float64,
        "transition_dte_max_change_um": pl.Float64,
        "lyapunov_per_mesh_period_min": pl.Float64,
        "lyapunov_stderr_per_mesh_period_max": pl.Float64,
    }
    return pl.DataFrame(out, schema_overrides=schema)


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
    max_transient_periods: Optional[int] = None,
    max_period: Optional[int] = None,
    period_rel_tol: Optional[float] = None,
    converging_ratio: Optional[float] = None,
    lyapunov_block_periods: Optional[int] = None,
    lyapunov_max_periods: Optional[int] = None,
    lyapunov_sigmas: Optional[float] = None,
    lyapunov_threshold_per_mesh_period: Optional[float] = None,
    zero_one_threshold: Optional[float] = None,
    jump_rel_amplitude: Optional[float] = None,
    jump_trend_factor: Optional[float] = None,
    jump_window_speeds: Optional[int] = None,
) -> "polars.DataFrame":  # noqa: F821
    """Motion regime over input torque x speed (x TE scale), every cell from
    its static state; speeds in any order (sorted ascending). Columns:
    ``torque_nm`` (negative: coast), ``te_scale``, ``te_amplitude_um``,
    ``speed_rpm``, ``regime``, ``period``, ``impact``, ``amplitude_um``,
    ``mean_dte_um``, ``lyapunov_per_mesh_period``, ``lyapunov_per_s`` and
    their ``lyapunov_stderr_*``, ``zero_one_k``, ``transient_periods``,
    ``settled``. The bearing stiffness schedule stays the system's. Settings
    as in :func:`bifurcation` (the jump settings are not used here)."""
    import polars as pl

    _check_system(system)
    torques = [float(t) for t in np.asarray(torques_nm, dtype=float).ravel()]
    scales = [float(e) for e in np.asarray(te_scales, dtype=float).ravel()]
    cols = _native.regime_map(
        system._s,
        torques,
        scales,
        _speeds(speeds_rpm),
        *_counts(transient_periods, record_periods, steps_per_period, lyapunov_periods),
        progress,
        _settings(locals()),
    )
    types = {c: (pl.Float64 if t == "f" else pl.Utf8) for c, t in _NULLABLE.items() if c in cols}
    df = pl.DataFrame(
        {k: (np.asarray(v) if not isinstance(v, list) else v) for k, v in cols.items()},
        schema_overrides=types,
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
    block_periods: int = 10,
    per: str = "s",
    return_stderr: bool = False,
) -> Union[float, tuple[float, float]]:
    """Largest Lyapunov exponent.

    Reference systems by name, per unit time: ``"lorenz"`` (sigma 10, rho
    28, beta 8/3; published 0.9056) and ``"duffing-ueda"`` (x'' + 0.05 x' +
    x^3 = 7.5 cos t; about 0.10), ``method="benettin"`` or
    ``"variational"``.

    For a :class:`GearSystem` give ``speed_rpm``: Benettin renormalisation
    once per mesh period over ``periods`` mesh periods after
    ``transient_periods`` from the static state, in blocks of
    ``block_periods`` (``periods`` rounded down to whole blocks, at least
    2). ``per="s"`` (default) gives 1/s, ``per="mesh_period"`` 1/mesh period
    (= 1/s divided by the mesh frequency, the unit of the sweeps'
    ``lyapunov_per_mesh_period``). ``return_stderr=True`` returns
    ``(exponent, standard error)`` in that unit (batch means over the
    blocks)."""
    if isinstance(system_or_name, str):
        if per != "s" or return_stderr:
            raise _config_error(
                f"invalid per = {per!r} / return_stderr = {return_stderr!r}: a reference system "
                "has no mesh period or blocks; its exponent is per unit time"
            )
        return float(
            _native.largest_lyapunov_reference(system_or_name, time, step, transient_time, method)
        )
    _check_system(system_or_name)
    if speed_rpm is None:
        raise _config_error("invalid speed_rpm = None: a gear system needs a speed")
    if per not in ("s", "mesh_period"):
        raise _config_error(f"invalid per = {per!r}: must be 's' or 'mesh_period'")
    d = _native.largest_lyapunov_gear(
        system_or_name._s,
        float(speed_rpm),
        _count("periods", periods, 2),
        _count("transient_periods", transient_periods, 0),
        _count("steps_per_period", steps_per_period, 1),
        _count("block_periods", block_periods, 1),
    )
    unit = "per_s" if per == "s" else "per_mesh_period"
    value = float(d[f"lyapunov_{unit}"])
    return (value, float(d[f"lyapunov_stderr_{unit}"])) if return_stderr else value
