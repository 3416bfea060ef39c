"""Running a spindle: warm-up transients, preload grids, the optimal and the
compensating preload against speed."""

from __future__ import annotations

from typing import Any, Callable, Optional

import numpy as np
from numpy.typing import ArrayLike

from .. import _validate as val
from .._deprecation import renamed_kwargs
from .._model_hook import takes_calibrated
from .._names import renamed_spindle_columns, spindle_node, temperature_column
from .spindle import SEED_B_SPRING_RATE_N_PER_UM, Spindle, _check


@renamed_kwargs(initial_c="initial_temperature_c")
@takes_calibrated()
def transient(
    spindle: Spindle,
    *,
    speed_rpm: float,
    duration_s: float,
    dt_s: float = 5.0,
    record_every: int = 1,
    initial_temperature_c: Optional[float] = None,
    mechanics_update_k: float = 0.05,
    progress: Optional[Callable[[int, int], Any]] = None,
) -> Any:
    """Temperatures in time from a uniform start ``initial_temperature_c``
    (default: ambient) at constant speed: ``time_s`` and one
    ``<node>_temperature_c`` column per node (``front_outer_ring_temperature_c``
    ...; the nodes of [`Spindle.node_names`][thermobear.Spindle.node_names]). The
    bearing heat follows the temperatures (quasi-steady mechanics, re-solved
    when a node moved more than ``mechanics_update_k``).

    At most 10 million steps (``duration_s / dt_s``, a ``ConfigError``
    naming both beyond) and a million recorded rows (raise
    ``record_every``). Ctrl-C stops the run within a step, and so does
    ``progress(steps_done, steps)`` returning ``False``
    (``thermobear.Interrupted``)."""
    import polars as pl

    sp = _check(spindle)
    d = sp._native.transient(
        val.real("speed_rpm", speed_rpm, 0.0),
        val.real("duration_s", duration_s, 0.0, open_lo=True),
        dt_s=val.real("dt_s", dt_s, 0.0, open_lo=True),
        record_every=val.whole("record_every", record_every, 1),
        initial_c=val.optional_real("initial_temperature_c", initial_temperature_c, -273.15),
        mechanics_update_k=val.real("mechanics_update_k", mechanics_update_k, 0.0, open_lo=True),
        progress=progress,
    )
    t = np.asarray(d["temperatures_c"])
    cols: dict[str, Any] = {"time_s": np.asarray(d["time_s"])}
    for i, name in enumerate(d["node_names"]):
        cols[temperature_column(spindle_node(name))] = t[:, i]
    return pl.DataFrame(cols)


@takes_calibrated()
def spindle_grid(
    spindle: Spindle,
    *,
    speeds_rpm: ArrayLike,
    preloads_n: ArrayLike,
    radial_loads_n: Optional[ArrayLike] = None,
    progress: Optional[Callable[[int, int], Any]] = None,
) -> Any:
    """Speed x preload x load grid of coupled steady states (threads, GIL
    released): temperatures, operating preload, heat, radial displacements
    (mechanical, thermal, total) and radial stiffness with and without
    thermal effects (``k_xx_n_per_m``, ``k_xx_isothermal_n_per_m``: the front
    pair's entry of the full tangent stiffness). A calibrated model
    ([`CalibratedModel`][thermobear.CalibratedModel]) stands for its spindle,
    its preload scale on each of ``preloads_n`` (the grid reports the
    preload it solved at)."""
    import polars as pl

    sp = _check(spindle)
    loads = [sp.radial_load_n] if radial_loads_n is None else radial_loads_n
    d = sp._native.grid(
        list(val.reals("speeds_rpm", speeds_rpm, 0.0)),
        list(val.reals("preloads_n", preloads_n, 0.0)),
        list(val.reals("radial_loads_n", loads)),
        progress,
    )
    return pl.DataFrame({k: np.asarray(v) for k, v in renamed_spindle_columns(dict(d)).items()})


@takes_calibrated()
def optimal_preload(
    spindle: Spindle,
    *,
    speeds_rpm: ArrayLike,
    preloads_n: ArrayLike,
    radial_n: Optional[float] = None,
    progress: Optional[Callable[[int, int], Any]] = None,
) -> Any:
    """Preload with the least total radial displacement (mechanical under the
    working radial load, cold geometry at speed, plus the radial thermal
    displacement; seed B Figs. 15-16) at each speed: ``speed_rpm``,
    ``optimal_preload_n``, ``min_radial_displacement_um`` and the parts."""
    import polars as pl

    sp = _check(spindle)
    if radial_n is not None:
        sp = sp.with_options(radial_load_n=radial_n)
    grid = spindle_grid(sp, speeds_rpm=speeds_rpm, preloads_n=preloads_n, progress=progress)
    best = (
        grid.sort(["speed_rpm", "total_radial_displacement_um", "preload_n"])
        .group_by("speed_rpm", maintain_order=True)
        .first()
    )
    return best.select(
        pl.col("speed_rpm"),
        pl.col("preload_n").alias("optimal_preload_n"),
        pl.col("total_radial_displacement_um").alias("min_radial_displacement_um"),
        pl.col("mechanical_radial_displacement_um"),
        pl.col("thermal_radial_displacement_um"),
        pl.col("front_ball_temperature_c"),
        pl.col("radial_load_n"),
    )


@takes_calibrated()
def compensation_preload(
    spindle: Spindle,
    *,
    speeds_rpm: ArrayLike,
    spring_rate_n_per_um: float = SEED_B_SPRING_RATE_N_PER_UM,
    progress: Optional[Callable[[int, int], Any]] = None,
) -> Any:
    """Seed B Fig. 17: with a spring preload the spindle's axial thermal
    growth compresses the spring, dF = k_s u_axial. Columns ``speed_rpm``,
    ``axial_growth_um``, ``compensation_preload_n`` (k_s u),
    ``solved_preload_change_n`` (coupled solve, spring in series with the
    bearings), ``spring_rate_n_per_um``. With the effect
    ``preload_change_from_axial_growth`` off both preload columns are ~0."""
    import polars as pl

    sp = _check(spindle)
    d = sp._native.compensation(
        list(val.reals("speeds_rpm", speeds_rpm, 0.0)),
        val.real("spring_rate_n_per_um", spring_rate_n_per_um, 0.0, open_lo=True),
        progress,
    )
    df = pl.DataFrame({k: np.asarray(v) for k, v in d.items()})
    return df.with_columns(pl.lit(float(spring_rate_n_per_um)).alias("spring_rate_n_per_um"))
