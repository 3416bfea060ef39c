"""Nonlinear dynamics of the gear system: bifurcation diagrams (one
direction or a set), the motion regimes read off them, regime maps over
torque and speed, and the largest Lyapunov exponent."""

from __future__ import annotations

import logging
from typing import TYPE_CHECKING, Any, Callable, Mapping, Optional, Sequence, Union

import numpy as np
from numpy.typing import ArrayLike

from .. import _native
from .. import _validate as val
from .._deprecation import renamed_kwargs
from .._types import Direction, LyapunovMethod, LyapunovPer
from .pair import _config_error
from .system import GearSystem
from .tables import as_speeds

if TYPE_CHECKING:
    import polars

Progress = Optional[Callable[[int, int], Any]]

#: Classifier and sweep settings reachable as keyword arguments of
#: ``bifurcation``, ``bifurcation_set`` and ``regime_map``
#: (``None``: the default named in ``bifurcation``).
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


def _speeds(speeds_rpm: ArrayLike) -> np.ndarray:
    return as_speeds(speeds_rpm)


def _count(name: str, value: Any, minimum: int) -> int:
    return val.whole(name, value, minimum)


#: The most RK4 steps per mesh period a sweep or Lyapunov run takes (the
#: native sweeps refuse more too). The step rule needs about 270,000 / rpm
#: steps for the seed pair, so this covers speeds down to a few rpm; past
#: the need, RK4's error falls as the fourth power of the step and more
#: steps only add time.
MAX_STEPS_PER_PERIOD = 100_000

#: The most mesh periods in any one count of a sweep or Lyapunov run
#: (``transient_periods``, ``record_periods``, ``lyapunov_periods``,
#: ``periods``, ``max_transient_periods``, ``lyapunov_max_periods``). The
#: default classifier settles within 1,500 periods and decides a Lyapunov
#: exponent within 400; each recorded period is a row of the result.
MAX_PERIODS = 100_000

#: The most RK4 steps one call may plan, all cells together (``max_steps=``
#: raises it): cells x (transient + record + Lyapunov periods) x
#: steps_per_period. A step of the gear model takes about 80 ns on one
#: core (up to 140 ns on a busy machine; 20 to 30 ns a lane in the
#: lock-step batches), so 2e9 steps are a few minutes at most on one core.
MAX_STEPS = 2_000_000_000

_log = logging.getLogger("thermobear.gear")


def _bounded(name: str, value: Any, minimum: int, maximum: int, unit: str) -> int:
    """``value`` as a whole number in [minimum, maximum] (the bound named
    with its unit, a ConfigError past it)."""
    n = val.whole(name, value, minimum, None)
    if n > maximum:
        raise _config_error(
            f"invalid {name} = {value!r}: must be at most {maximum:,} {unit} (the bound of the "
            "gear dynamics; see the Limits page)"
        )
    return n


def _counts(transient: Any, record: Any, steps: Any, lyapunov: Any) -> tuple[int, int, int, int]:
    return (
        _bounded("transient_periods", transient, 0, MAX_PERIODS, "mesh periods"),
        _bounded("record_periods", record, 2, MAX_PERIODS, "mesh periods"),
        _bounded("steps_per_period", steps, 1, MAX_STEPS_PER_PERIOD, "steps per mesh period"),
        _bounded("lyapunov_periods", lyapunov, 0, MAX_PERIODS, "mesh periods"),
    )


def planned_steps(
    cells: int, transient_periods: int, record_periods: int, lyapunov_periods: int,
    steps_per_period: int,
) -> int:  # fmt: skip
    """The RK4 steps a sweep plans: ``cells x (transient_periods +
    record_periods + lyapunov_periods) x steps_per_period`` (the adaptive
    transient and the Lyapunov extension may add to it; a periodic cell
    skips its Lyapunov periods)."""
    return cells * (transient_periods + record_periods + lyapunov_periods) * steps_per_period


def _check_work(
    call: str,
    cells: str,
    n_cells: int,
    counts: tuple[int, int, int, int],
    max_steps: Any,
    names: tuple[str, str, str] = ("transient_periods", "record_periods", "lyapunov_periods"),
) -> int:
    """State (log, ``thermobear.gear`` at INFO) and check the work of a
    call before it starts: ConfigError naming the arguments and the total
    when it plans more than ``max_steps`` RK4 steps (None: ``MAX_STEPS``).
    ``counts``: transient, record, steps per period, Lyapunov periods."""
    transient, record, steps, lyapunov = counts
    cap = MAX_STEPS if max_steps is None else val.whole("max_steps", max_steps, 1, None)
    total = planned_steps(n_cells, transient, record, lyapunov, steps)
    periods = " + ".join(
        f"{n} {name}" for n, name in zip(counts[:2] + counts[3:], names, strict=True) if name
    )
    work = f"{cells} x ({periods}) x {steps:,} steps_per_period = {total:,} RK4 steps"
    if total > cap:
        raise _config_error(
            f"invalid {call} work = {work}: more than max_steps = {cap:,} (the default, "
            f"{MAX_STEPS:,}, is a few minutes on one core); use fewer cells, periods or "
            "steps, or pass max_steps= to raise the cap"
        )
    _log.info("%s: %s (max_steps = %s)", call, work, f"{cap:,}")
    return total


def _settings(given: Mapping[str, Any]) -> dict[str, Any]:
    """The classifier settings that were given (the others keep their defaults)."""
    return {k: given[k] for k in SETTING_NAMES if given.get(k) is not None}


def _check_system(system: Any) -> GearSystem:
    """The gear system of ``system``: a [`GearSystem`][thermobear.GearSystem]
    as it is; a calibrated gear model becomes ``GearSystem(model)`` (its
    calibrated inputs, in its own stiffness case, at its own torque)."""
    from .._model_hook import is_calibrated

    if isinstance(system, GearSystem):
        return system
    if is_calibrated(system):
        return GearSystem(system)
    raise _config_error(
        f"invalid system = {system!r}: must be a thermobear.GearSystem or a calibrated gear model"
    )


#: RK4 steps per mesh period of the sweeps when none is given; raised to
#: the fewest the swept speeds need when that is more (``sweep_steps``).
DEFAULT_STEPS_PER_PERIOD = 64


def sweep_steps(systems: Sequence[GearSystem], speeds: Any, steps_per_period: Any) -> int:
    """The RK4 steps per mesh period of a sweep, checked at every speed of
    every system before any work. The rule (the native model's): at least
    16 steps per mesh period, and a step no longer than 0.1 x the shortest
    natural period at the speed's bearing stiffness -- so the need grows
    as the speed falls (longer mesh periods). ``None``: the default
    ``DEFAULT_STEPS_PER_PERIOD``, raised to the fewest every speed
    needs. A number that is too small at some speeds raises ConfigError
    naming them and the number needed, before any speed is run."""
    import re

    from .._input_checks import check_gear_speed
    from ..errors import ConfigError

    for sys in systems:  # the fastest speed of the sweep
        check_gear_speed(sys.gear.geometry, float(np.max(np.asarray(speeds, dtype=float))))
    given = steps_per_period is not None
    steps = (
        _bounded(
            "steps_per_period", steps_per_period, 1, MAX_STEPS_PER_PERIOD, "steps per mesh period"
        )
        if given
        else DEFAULT_STEPS_PER_PERIOD
    )
    need, short = steps, []
    for sys in systems:
        for v in np.asarray(speeds, dtype=float):
            try:
                sys.check_steps(float(v), steps if given else need)
                continue
            except ConfigError as e:
                m = re.search(r"at least (\d+)", str(e))
                if m is None:
                    raise
                n = int(m.group(1))
            short.append(float(v))
            need = max(need, n)
            sys.check_steps(float(v), need)  # the stated need passes
    if given and short:
        raise _config_error(
            f"invalid steps_per_period = {steps}: too coarse at {len(short)} of "
            f"{len(speeds) * len(systems)} speeds ({min(short):g}-{max(short):g} rpm: the step "
            f"must stay within 0.1 x the shortest natural period); use at least {need}, or "
            "leave steps_per_period=None to have it chosen"
        )
    if need > MAX_STEPS_PER_PERIOD:
        raise _config_error(
            f"invalid speeds_rpm = {min(short):g} rpm (the slowest): it needs {need:,} "
            f"steps_per_period, more than the bound of {MAX_STEPS_PER_PERIOD:,} (the mesh period "
            "is too long against the shortest natural period); sweep faster speeds"
        )
    return need


def _points_frame(cols: Mapping[str, Any], direction: str, case: Optional[str]) -> polars.DataFrame:
    import polars as pl

    counts = np.asarray(cols["poincare_count"])
    per_speed: dict[str, Any] = {"speed_rpm": np.asarray(cols["speed_rpm"])}
    for c in PER_SPEED_COLUMNS:
        v = cols[c]
        per_speed[c] = list(v) if isinstance(v, list) else np.asarray(v)
    types: dict[str, type[pl.DataType]] = {
        c: (pl.Float64 if t == "f" else pl.Utf8) for c, t in _NULLABLE.items()
    }
    # The list columns of a partial sweep may be empty: give them their types.
    types.update(regime=pl.Utf8, impact=pl.Utf8, settled=pl.Boolean, jump_after=pl.Boolean)
    speed_df = pl.DataFrame(per_speed, schema_overrides=types)
    idx = np.repeat(np.arange(len(counts)), counts)
    df = speed_df[idx].with_columns(pl.Series("dte_um", np.asarray(cols["poincare_dte_um"])))
    df = df.with_columns(pl.lit(direction).alias("direction"))
    if case is not None:
        df = df.with_columns(pl.lit(case).alias("case"))
    first = ["speed_rpm", "dte_um"]
    return df.select(first + [c for c in df.columns if c not in first])


def _sweep_partial(e: BaseException, jobs: Sequence[tuple[str, Optional[str]]]) -> None:
    """Turn the finished speeds the native sweep attached to ``e`` into its
    ``partial``, ``failed`` and ``not_run`` frames (see ``thermobear._partial``).
    ``jobs``: ``(direction, case)`` per sweep, in the native order."""
    import polars as pl

    from .. import _partial

    if not hasattr(e, "_sweep_partial"):
        return
    dicts = list(e._sweep_partial)
    frames = [_points_frame(c, d, case) for (d, case), c in zip(jobs, dicts, strict=False)]
    filled = [f for f in frames if f.height]
    partial = pl.concat(filled) if filled else frames[0]
    with_case = any(case is not None for _, case in jobs)

    def rows(items: list[Any], extra: dict[str, Any]) -> pl.DataFrame:
        cols: dict[str, Any] = {"speed_rpm": [float(r[1]) for r in items]}
        schema: dict[str, Any] = {"speed_rpm": pl.Float64}
        for name, (key, dtype) in extra.items():
            cols[name] = [key(r) for r in items]
            schema[name] = dtype
        cols["direction"] = [jobs[r[0]][0] for r in items]
        schema["direction"] = pl.Utf8
        if with_case:
            cols["case"] = [jobs[r[0]][1] for r in items]
            schema["case"] = pl.Utf8
        return pl.DataFrame(cols, schema=schema)

    failed_rows = list(e._sweep_failed)  # type: ignore[attr-defined]
    failed = rows(failed_rows, {"message": (lambda r: str(r[2]), pl.Utf8)})
    not_run = rows(list(e._sweep_not_run), {})  # type: ignore[attr-defined]
    labels = [
        f"{r[1]:g} rpm" + (f" ({jobs[r[0]][1]}, {jobs[r[0]][0]})" if len(jobs) > 1 else "")
        for r in failed_rows
    ]
    continuation = any(jobs[r[0]][0] in ("up", "down") for r in failed_rows)
    _partial.finish(
        e,
        partial,
        failed,
        not_run,
        finished=sum(len(c["speed_rpm"]) for c in dicts),
        total=sum(len(c["speed_rpm"]) for c in dicts) + failed.height + not_run.height,
        failed_labels=labels,
        note=": a continuation sweep stops at its failed speed" if continuation else "",
    )


def bifurcation(
    system: GearSystem,
    speeds_rpm: ArrayLike,
    direction: Direction = "down",
    transient_periods: int = 300,
    record_periods: int = 100,
    steps_per_period: Optional[int] = None,
    *,
    lyapunov_periods: int = 100,
    progress: Progress = None,
    max_steps: Optional[int] = None,
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
) -> polars.DataFrame:
    """Speed sweep (A Figs. 14-15). ``"down"`` (default: a run-down from the top speed) and ``"up"``
    carry the state from speed to speed (continuation), ``"independent"`` starts every speed from
    the static state (parallel). ``speeds_rpm`` in any order (distinct): they are sorted and swept
    ascending for ``"up"``/``"independent"``, descending for ``"down"``; the rows come in that
    sweep order.

    One row per Poincare sample (once per mesh period): ``speed_rpm``, ``dte_um`` (dynamic
    transmission error ``delta_n - e``), and per speed: ``regime`` (period-n / quasi-periodic /
    chaotic), ``period``, ``impact``, ``lyapunov_per_mesh_period`` / ``lyapunov_per_s`` and their
    standard errors ``lyapunov_stderr_per_mesh_period`` / ``lyapunov_stderr_per_s`` (non-periodic
    speeds; per s = per mesh period x mesh frequency), ``zero_one_k`` (0-1 test K),
    ``transient_periods`` (run, incl. the adaptive extension), ``settled`` (False: the section was
    still converging at ``max_transient_periods``; the label is provisional), ``dte_min_um``,
    ``dte_max_um``, ``jump_after`` (amplitude jump to the next speed in sweep order, same
    non-chaotic regime family only), ``transition_after`` (regime-family change to the next speed:
    ``enters-chaos``, ``exits-chaos``, ``enters-quasi-periodic``, ``exits-quasi-periodic``) with
    its size ``transition_dte_min_change_um``, ``transition_dte_max_change_um``, and ``direction``.

    Classifier settings (keyword-only, ``None`` = default): ``max_transient_periods`` [mesh
    periods] cap of the adaptive transient (default max(1500, 5 x transient_periods); =
    transient_periods turns the extension off); ``max_period`` [mesh periods] largest period tested
    (default 32, needs 2 x max_period <= record_periods); ``period_rel_tol`` [-] tolerance of the
    period and settling tests relative to the orbit's peak-to-peak DTE (1e-4); ``converging_ratio``
    [-] a mismatch shrinking below this fraction of its first-quarter value is still settling
    (0.9); ``lyapunov_block_periods`` [mesh periods] block length of the Lyapunov standard error
    (10); ``lyapunov_max_periods`` [mesh periods] longest Lyapunov run while undecided (max(400, 4
    x lyapunov_periods)); ``lyapunov_sigmas`` [-] chaos needs the exponent above the threshold by
    this many standard errors (3); ``lyapunov_threshold_per_mesh_period`` [1/mesh period] (1e-3);
    ``zero_one_threshold`` [-] 0-1 test K for chaos (0.5, used with >= 200 section points);
    ``jump_rel_amplitude`` [-] jump step relative to the amplitude (0.2); ``jump_trend_factor`` [-]
    jump step relative to the local median step (5), taken over ``jump_window_speeds`` [speeds]
    neighbouring steps on each side (5). Bad values raise ConfigError naming the setting.
    ``steps_per_period`` (RK4 steps per mesh period; None: 64, or more when a swept speed needs
    more) is checked at every speed before the sweep starts (``sweep_steps``).

    Bounded work (``planned_steps``, ``MAX_STEPS_PER_PERIOD``, ``MAX_PERIODS``): the planned
    RK4 steps are logged (``thermobear.gear``, INFO) and refused past ``max_steps`` (None:
    ``MAX_STEPS``, 2e9) with a ConfigError naming the arguments and the total. GIL released;
    Ctrl-C interrupts, also inside one long speed; ``progress(done, total)``."""
    system = _check_system(system)
    speeds = _speeds(speeds_rpm)
    counts = _counts(transient_periods, record_periods, steps_per_period or 1, lyapunov_periods)
    steps = sweep_steps([system], speeds, steps_per_period)
    counts = counts[:2] + (steps,) + counts[3:]
    _check_work("bifurcation", f"{len(speeds)} speeds", len(speeds), counts, max_steps)
    settings = _settings(locals())
    try:
        cols = _native.bifurcation(system._s, speeds, direction, *counts, progress, settings)
    except BaseException as e:
        _sweep_partial(e, [(direction, None)])
        raise
    return _points_frame(cols, direction, None)


def bifurcation_set(
    systems: Mapping[str, GearSystem],
    speeds_rpm: ArrayLike,
    directions: Sequence[str] = ("up", "down"),
    transient_periods: int = 300,
    record_periods: int = 100,
    steps_per_period: Optional[int] = None,
    *,
    lyapunov_periods: int = 100,
    progress: Progress = None,
    max_steps: Optional[int] = None,
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
) -> polars.DataFrame:
    """Every (case, direction) sweep over the same speeds in parallel
    (lock-step batches); the [`bifurcation`][thermobear.bifurcation] columns (each sweep in its
    sweep order) plus ``case``. Settings, bounds and ``max_steps`` (cells: systems x directions x
    speeds) as in [`bifurcation`][thermobear.bifurcation]."""
    import polars as pl

    if not systems:
        raise _config_error("invalid systems = {}: give at least one")
    systems = {name: _check_system(sys) for name, sys in systems.items()}
    jobs = [(name, sys, d) for name, sys in systems.items() for d in directions]
    speeds = _speeds(speeds_rpm)
    counts = _counts(transient_periods, record_periods, steps_per_period or 1, lyapunov_periods)
    steps = sweep_steps(list(systems.values()), speeds, steps_per_period)
    counts = counts[:2] + (steps,) + counts[3:]
    cells = f"{len(systems)} systems x {len(directions)} directions x {len(speeds)} speeds"
    _check_work("bifurcation_set", cells, len(jobs) * len(speeds), counts, max_steps)
    settings = _settings(locals())
    try:
        res = _native.bifurcation_many(
            [j[1]._s for j in jobs],
            [j[2] for j in jobs],
            speeds,
            *counts,
            progress,
            settings,
        )
    except BaseException as e:
        _sweep_partial(e, [(d, name) for name, _, d in jobs])
        raise
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


def _range_row(c: dict[str, list[Any]], start: int, i: int, end: bool) -> dict[str, Any]:
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


def regimes(pts: Any, *, max_period: int = 32, period_rel_tol: float = 1e-3) -> polars.DataFrame:
    """Collapse a [`bifurcation`][thermobear.bifurcation] frame into speed ranges of one regime
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

    if not isinstance(pts, pl.DataFrame):
        raise val.fail("pts", pts, "a polars DataFrame (a sweep of bifurcation)")
    if "speed_rpm" not in pts.columns:
        raise _config_error("invalid pts = frame without 'speed_rpm'")
    keys: list[str] = [k for k in ("case", "direction") if k in pts.columns]
    max_period = _count("max_period", max_period, 1)
    tol = val.real("period_rel_tol", period_rel_tol, 0.0, 1.0, open_lo=True)
    if tol == 1.0:
        raise _config_error(f"invalid period_rel_tol = {period_rel_tol!r}: must lie in (0, 1)")
    per = _per_speed(pts, keys, tol, max_period)
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


@renamed_kwargs(torques_nm="torques_n_m")
def regime_map(
    system: GearSystem,
    torques_n_m: ArrayLike,
    speeds_rpm: ArrayLike,
    te_scales: ArrayLike = (1.0,),
    transient_periods: int = 300,
    record_periods: int = 100,
    steps_per_period: Optional[int] = None,
    *,
    lyapunov_periods: int = 100,
    progress: Progress = None,
    max_steps: Optional[int] = None,
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
) -> polars.DataFrame:
    """Motion regime over input torque x speed (x TE scale), every cell from
    its static state; speeds in any order (sorted ascending). Columns:
    ``torque_n_m`` (negative: coast), ``te_scale``, ``te_amplitude_um``,
    ``speed_rpm``, ``regime``, ``period``, ``impact``, ``amplitude_um``,
    ``mean_dte_um``, ``lyapunov_per_mesh_period``, ``lyapunov_per_s`` and
    their ``lyapunov_stderr_*``, ``zero_one_k``, ``transient_periods``,
    ``settled``. The bearing stiffness schedule stays the system's. Settings
    as in [`bifurcation`][thermobear.bifurcation] (the jump settings are not used here), and so
    are the bounds, ``max_steps`` (cells: torques x TE scales x speeds) and Ctrl-C."""

    system = _check_system(system)
    torques = val.reals("torques_n_m", torques_n_m).tolist()
    scales = val.reals("te_scales", te_scales).tolist()
    speeds = _speeds(speeds_rpm)
    counts = _counts(transient_periods, record_periods, steps_per_period or 1, lyapunov_periods)
    steps = sweep_steps([system], speeds, steps_per_period)
    counts = counts[:2] + (steps,) + counts[3:]
    cells = f"{len(torques)} torques x {len(scales)} te_scales x {len(speeds)} speeds"
    _check_work("regime_map", cells, len(torques) * len(scales) * len(speeds), counts, max_steps)
    settings = _settings(locals())
    try:
        cols = _native.regime_map(
            system._s,
            torques,
            scales,
            speeds,
            *counts,
            progress,
            settings,
        )
    except BaseException as e:
        _map_partial(e, system)
        raise
    return _map_frame(cols, system)


def _map_partial(e: BaseException, system: GearSystem) -> None:
    """``partial``/``failed``/``not_run`` frames of a regime map that failed
    or was stopped part-way (every other cell still ran)."""
    import polars as pl

    from .. import _partial

    if not hasattr(e, "_map_partial"):
        return
    partial = _map_frame(dict(e._map_partial), system)
    keys = {"torque_n_m": pl.Float64, "te_scale": pl.Float64, "speed_rpm": pl.Float64}
    f_rows = list(e._map_failed)  # type: ignore[attr-defined]
    n_rows = list(e._map_not_run)  # type: ignore[attr-defined]
    failed = pl.DataFrame(
        [tuple(float(v) for v in r[:3]) + (str(r[3]),) for r in f_rows],
        schema={**keys, "message": pl.Utf8},
        orient="row",
    )
    not_run = pl.DataFrame([tuple(float(v) for v in r) for r in n_rows], schema=keys, orient="row")
    _partial.finish(
        e,
        partial,
        failed,
        not_run,
        finished=partial.height,
        total=partial.height + failed.height + not_run.height,
        unit="cells",
        failed_labels=[f"{r[2]:g} rpm at {r[0]:g} N m x{r[1]:g}" for r in f_rows],
    )


def _map_frame(cols: Mapping[str, Any], system: GearSystem) -> polars.DataFrame:
    import polars as pl

    types: dict[str, Any] = {
        c: (pl.Float64 if t == "f" else pl.Utf8) for c, t in _NULLABLE.items() if c in cols
    }
    types.update(regime=pl.Utf8, impact=pl.Utf8, settled=pl.Boolean)
    df = pl.DataFrame(
        {
            ("torque_n_m" if k == "torque_nm" else k): (
                np.asarray(v) if not isinstance(v, list) else v
            )
            for k, v in cols.items()
        },
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
    method: LyapunovMethod = "benettin",
    periods: int = 200,
    transient_periods: int = 300,
    steps_per_period: int = 64,
    block_periods: int = 10,
    per: LyapunovPer = "s",
    return_stderr: bool = False,
    max_steps: Optional[int] = None,
) -> Union[float, tuple[float, float]]:
    """Largest Lyapunov exponent.

    Reference systems by name, per unit time: ``"lorenz"`` (sigma 10, rho
    28, beta 8/3; published 0.9056) and ``"duffing-ueda"`` (x'' + 0.05 x' +
    x^3 = 7.5 cos t; about 0.10), ``method="benettin"`` or
    ``"variational"``.

    For a [`GearSystem`][thermobear.GearSystem] give ``speed_rpm``: Benettin renormalisation
    once per mesh period over ``periods`` mesh periods after
    ``transient_periods`` from the static state, in blocks of
    ``block_periods`` (``periods`` rounded down to whole blocks, at least
    2). ``per="s"`` (default) gives 1/s, ``per="mesh_period"`` 1/mesh period
    (= 1/s divided by the mesh frequency, the unit of the sweeps'
    ``lyapunov_per_mesh_period``). ``return_stderr=True`` returns
    ``(exponent, standard error)`` in that unit (batch means over the
    blocks). Bounds as in [`bifurcation`][thermobear.bifurcation]:
    ``steps_per_period`` <= 100,000, ``periods`` and ``transient_periods``
    <= 100,000, and (``transient_periods`` + ``periods``) x
    ``steps_per_period`` <= ``max_steps`` (None: ``MAX_STEPS``). GIL
    released; Ctrl-C interrupts (KeyboardInterrupt) within a fraction of a
    second."""
    if isinstance(system_or_name, str):
        if per != "s" or return_stderr:
            raise _config_error(
                f"invalid per = {per!r} / return_stderr = {return_stderr!r}: a reference system "
                "has no mesh period or blocks; its exponent is per unit time"
            )
        return float(
            _native.largest_lyapunov_reference(system_or_name, time, step, transient_time, method)
        )
    system_or_name = _check_system(system_or_name)
    if speed_rpm is None:
        raise _config_error("invalid speed_rpm = None: a gear system needs a speed")
    if per not in ("s", "mesh_period"):
        raise _config_error(f"invalid per = {per!r}: must be 's' or 'mesh_period'")
    n_periods = _bounded("periods", periods, 2, MAX_PERIODS, "mesh periods")
    n_transient = _bounded("transient_periods", transient_periods, 0, MAX_PERIODS, "mesh periods")
    n_steps = _bounded(
        "steps_per_period", steps_per_period, 1, MAX_STEPS_PER_PERIOD, "steps per mesh period"
    )
    blocks = _bounded("block_periods", block_periods, 1, MAX_PERIODS, "mesh periods")
    speed = val.real("speed_rpm", speed_rpm, 0.0, open_lo=True)
    _check_work(
        "largest_lyapunov", "1 speed", 1, (n_transient, 0, n_steps, n_periods), max_steps,
        names=("transient_periods", "", "periods"),
    )  # fmt: skip
    d = _native.largest_lyapunov_gear(
        system_or_name._s, speed, n_periods, n_transient, n_steps, blocks
    )
    unit = "per_s" if per == "s" else "per_mesh_period"
    value = float(d[f"lyapunov_{unit}"])
    return (value, float(d[f"lyapunov_stderr_{unit}"])) if return_stderr else value
