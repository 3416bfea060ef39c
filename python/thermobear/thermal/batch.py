"""Coupled thermal states of many operating points in one native call."""

from __future__ import annotations

import functools
from typing import TYPE_CHECKING, Any, Callable, Optional, Sequence, TypeVar

import numpy as np

from .. import _native, plausibility
from .._deprecation import renamed_kwargs
from .._input_checks import check_supply
from .._limits import cap_threads
from .._model_hook import (
    LOAD_SCALES,
    MEMBER,
    is_calibrated,
    member_of,
    scaled_load,
    takes_calibrated,
    unpack_model,
)
from .._types import HeatModel, Lubrication, RacewayControl
from ..bearing.ball_bearing import Bearing, _effects_arg, register_task
from .heat_law import HEAT_LAW_OPTIONS, has_heat_law, heat_law_w, pop_heat_law
from .state import DEFAULT_SPIN_FRICTION_COEFFICIENT, HEAT_MODEL_OPTIONS, _model_kwargs

if TYPE_CHECKING:
    import polars

F = TypeVar("F", bound=Callable[..., Any])

#: The operating columns of a points frame (a bearing's and a spindle's).
_POINT_COLUMNS = ("speed_rpm", "axial_n", "radial_n", "preload_n")


def _scaled_points(fn: F) -> F:
    """Decorate a many-points call whose first argument may be a
    calibrated model: the stated loads of its points (``axial_n``,
    ``radial_n``, ``preload_n`` columns) are multiplied by the model's load
    scales row by row (as ``thermal_state`` scales its loads), and the
    result carries the stated loads as the points gave them. Of a model
    with several members the one ``member=`` names stands for the machine
    (``member_of``: picked once, here)."""

    @functools.wraps(fn)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        if not args or not is_calibrated(args[0]):
            return fn(*args, **kwargs)
        import polars as pl

        from ..bearing.batch import operating_frame

        model = member_of(args[0], kwargs.pop(MEMBER, None))
        _, options = unpack_model(model)
        rest = list(args[1:])
        given = rest.pop(0) if rest else kwargs.pop("points", None)
        stated = operating_frame(given, _POINT_COLUMNS)
        columns = []
        for scale, arg in LOAD_SCALES.items():
            if arg not in stated.columns or not (
                scale in options or any(k.startswith(scale + "@") for k in options)
            ):
                continue
            values = [None if x is None else scaled_load(options, scale, float(x))
                      for x in stated[arg].to_list()]  # fmt: skip
            columns.append(pl.Series(arg, values, dtype=pl.Float64))
        scaled = stated.with_columns(columns) if columns else stated
        out = fn(model, scaled, *rest, **kwargs)
        changed = [c for c in stated.columns if not scaled[c].equals(stated[c])]
        return out.with_columns(stated[c] for c in changed) if changed else out

    return wrapper  # type: ignore[return-value]


@renamed_kwargs(spin_friction="spin_friction_coefficient")
@_scaled_points
@takes_calibrated(lambda given: (*HEAT_MODEL_OPTIONS, *HEAT_LAW_OPTIONS))
def thermal_state_many(
    bearing: Bearing,
    points: Any,
    *,
    effects: Optional[Sequence[str]] = None,
    lubricant: str = "e-drive ATF",
    lubrication_factor_f0: Optional[float] = None,
    spin_friction_coefficient: float = DEFAULT_SPIN_FRICTION_COEFFICIENT,
    oil_air_temperature_c: float = 28.0,
    ambient_temperature_c: float = 26.0,
    housing_material: Any = "aluminium",
    raceway_control: RacewayControl = "outer",
    misalignment_rad: Optional[float] = 0.0,
    extra_heat_w: float = 0.0,
    housing_conductance_scale: float = 1.0,
    churning_oil_fraction: Optional[float] = None,
    heat_model: HeatModel = "palmgren",
    lubrication: Optional[Lubrication] = None,
    threads: Optional[int] = None,
    progress: Any = None,
    **heat: Any,
) -> polars.DataFrame:
    """[`thermal_state`][thermobear.thermal_state] at many operating points in one native call
    (rayon threads, GIL released, Ctrl-C within 50 ms), each point as the single call computes it.
    ``points``: a polars DataFrame (or mapping of columns) with any of ``speed_rpm``, ``axial_n``,
    ``radial_n`` (absent: 0); other columns are carried through. Model options (the heat model's
    included) as in [`thermal_state`][thermobear.thermal_state], shared by every point; ``threads``
    (default: all cores), ``progress(done, total)``.

    Returns the input columns followed by the bearing outputs of
    [`solve_many`][thermobear.Bearing.solve_many] at the converged temperatures,
    ``shaft_temperature_c``, ``inner_ring_temperature_c``, ``ball_temperature_c``,
    ``outer_ring_temperature_c``, ``housing_temperature_c``, ``oil_temperature_c``,
    ``viscosity_cst``, ``heat_w`` (total), ``load_heat_w``, ``viscous_heat_w``, ``spin_heat_w``,
    ``churning_heat_w``, ``radial_thermal_offset_um``, ``axial_thermal_offset_um``,
    ``ball_growth_um``, ``centrifugal_expansion_um``, ``thermal_residual_k``,
    ``thermal_iterations``, then ``ok``, ``error_kind``, ``error``: a point that runs away
    (``ThermalRunawayError``) or does not converge is a row with its error and null outputs;
    nothing is raised for it. The same as the method ``thermobear.Bearing.thermal_state_many``; a
    [`Spindle`][thermobear.Spindle] goes to ``thermobear.Spindle.thermal_state_many``. A
    calibrated model ([`CalibratedModel`][thermobear.CalibratedModel]) stands for its machine: each
    row is what [`thermal_state`][thermobear.thermal_state] gives for it (its options, its load
    scales on the points' stated loads; the rows carry the stated loads)."""
    from ..bearing.batch import join_inputs, operating_frame, result_frame
    from ..errors import ConfigError

    if hasattr(bearing, "_thermal_state_many") and not isinstance(bearing, Bearing):
        given = {"effects": effects, "lubrication": lubrication,
                 "heat_model": None if heat_model == "palmgren" else heat_model,
                 "lubrication_factor_f0": lubrication_factor_f0,
                 "churning_oil_fraction": churning_oil_fraction, "progress": progress}  # fmt: skip
        return _other_model(bearing, points, given, heat)
    if not isinstance(bearing, Bearing):
        raise ConfigError(f"invalid bearing = {bearing!r}: give a thermobear.Bearing")
    names = ("speed_rpm", "axial_n", "radial_n")
    frame = operating_frame(points, names)
    law = pop_heat_law(heat)
    options = _model_kwargs(
        lubricant, lubrication_factor_f0, spin_friction_coefficient, oil_air_temperature_c,
        ambient_temperature_c, housing_material, raceway_control, misalignment_rad,
        extra_heat_w, housing_conductance_scale, churning_oil_fraction,
        heat_model=heat_model, lubrication=lubrication, **heat,
    )  # fmt: skip
    speed = _speed_and_loads(frame)[0]
    top = float(np.nanmax(speed)) if speed.size and np.isfinite(speed).any() else 0.0
    check_supply(
        plausibility._geometry(bearing), options["lubrication"], options["oil_supply"], top
    )
    if has_heat_law(law):
        return join_inputs(frame, _with_heat_law(bearing, frame, effects, options, law, threads))
    raw = _native.thermal_state_many(
        bearing._b,
        *_speed_and_loads(frame),
        _effects_arg(effects),
        options,
        threads=cap_threads(threads),
        progress=progress,
    )
    return join_inputs(frame, result_frame(raw))


def _with_heat_law(
    bearing: Bearing, frame: Any, effects: Any, options: dict[str, Any], law: Any, threads: Any
) -> Any:
    """The result rows of ``frame`` with an extra heat of its own speed law
    (``heat_law``): the points of each speed in one native call with that
    speed's extra heat, put back in the points' order."""
    import numpy as np
    import polars as pl

    from ..bearing.batch import result_frame

    speed, fa, fr = _speed_and_loads(frame)
    parts, order = [], []
    values, group = np.unique(speed, return_inverse=True)
    for k, n in enumerate(values):
        rows = np.flatnonzero(group == k)
        extra = float(options["extra_heat_w"]) + float(heat_law_w(law, n))
        raw = _native.thermal_state_many(
            bearing._b, speed[rows], fa[rows], fr[rows], _effects_arg(effects),
            {**options, "extra_heat_w": extra}, threads=cap_threads(threads), progress=None,
        )  # fmt: skip
        parts.append(result_frame(raw))
        order.append(rows)
    if not parts:
        return result_frame(
            _native.thermal_state_many(bearing._b, speed, fa, fr, _effects_arg(effects),
                                       options, threads=cap_threads(threads), progress=None)
        )  # fmt: skip
    back = np.argsort(np.concatenate(order), kind="stable")
    return pl.concat(parts, how="vertical_relaxed")[back]


def _other_model(model: Any, points: Any, given: dict[str, Any], heat: dict[str, Any]) -> Any:
    """``thermal_state_many`` of another model kind: any object with a
    ``_thermal_state_many(points, **options)`` method gets ``points``, the
    options that were given (not None) and the remaining keyword arguments."""
    given = {k: v for k, v in given.items() if v is not None}
    return model._thermal_state_many(points, **given, **heat)


register_task("thermal_state_many", thermal_state_many)


def _speed_and_loads(frame: Any) -> tuple[Any, Any, Any]:
    """The float64 columns ``speed_rpm``, ``axial_n``, ``radial_n`` of an
    operating frame, in the order the native call takes them."""
    from ..bearing.batch import column_array

    return (
        column_array(frame, "speed_rpm"),
        column_array(frame, "axial_n"),
        column_array(frame, "radial_n"),
    )
