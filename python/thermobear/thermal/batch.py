"""Coupled thermal states of many operating points in one native call."""

from __future__ import annotations

from typing import Any, Optional, Sequence

from .. import _native
from ..bearing.ball_bearing import Bearing, _effects_arg
from .state import _model_kwargs


def thermal_state_many(
    bearing: Bearing,
    points: Any,
    *,
    effects: Optional[Sequence[str]] = None,
    lubricant: str = "e-drive ATF",
    lubrication_factor_f0: Optional[float] = None,
    spin_friction: float = 0.06,
    oil_air_temperature_c: float = 28.0,
    ambient_temperature_c: float = 26.0,
    housing_material: Any = "aluminium",
    raceway_control: str = "outer",
    misalignment_rad: Optional[float] = 0.0,
    extra_heat_w: float = 0.0,
    housing_conductance_scale: float = 1.0,
    churning_oil_fraction: Optional[float] = None,
    heat_model: str = "palmgren",
    lubrication: Optional[str] = None,
    threads: Optional[int] = None,
    progress: Any = None,
    **heat: Any,
) -> "polars.DataFrame":  # noqa: F821
    """:func:`~thermobear.thermal_state` of a bearing at many operating
    points in one native call (rayon threads, GIL released, Ctrl-C within
    50 ms), each point exactly as the single call computes it.

    ``points``: a polars DataFrame (or mapping of columns) with any of
    ``speed_rpm``, ``axial_n``, ``radial_n`` (absent: 0); other columns are
    carried through. Model options (the heat model's included) as in
    :func:`~thermobear.thermal_state`, shared by every point; ``threads`` (default: all cores),
    ``progress(done, total)``.

    Returns the input columns followed by the bearing outputs of
    :meth:`~thermobear.Bearing.solve_many` at the converged temperatures,
    ``shaft_temperature_c``, ``inner_ring_temperature_c``,
    ``ball_temperature_c``, ``outer_ring_temperature_c``,
    ``housing_temperature_c``, ``oil_temperature_c``, ``viscosity_cst``,
    ``heat_w`` (total), ``load_heat_w``, ``viscous_heat_w``, ``spin_heat_w``,
    ``churning_w``, ``radial_thermal_offset_um``, ``axial_thermal_offset_um``,
    ``ball_growth_um``, ``centrifugal_expansion_um``, ``thermal_residual_k``,
    ``thermal_iterations``, then ``ok``, ``error_kind``, ``error``: a point
    that runs away (``ThermalRunawayError``) or does not converge is a row
    with its error and null outputs; nothing is raised for it."""
    from ..bearing.batch import column_array, join_inputs, operating_frame, result_frame
    from ..errors import ConfigError

    if not isinstance(bearing, Bearing):
        raise ConfigError(f"invalid bearing = {bearing!r}: give a thermobear.Bearing")
    names = ("speed_rpm", "axial_n", "radial_n")
    frame = operating_frame(points, names)
    options = _model_kwargs(
        lubricant,
        lubrication_factor_f0,
        spin_friction,
        oil_air_temperature_c,
        ambient_temperature_c,
        housing_material,
        raceway_control,
        misalignment_rad,
        extra_heat_w,
        housing_conductance_scale,
        churning_oil_fraction,
        heat_model=heat_model,
        lubrication=lubrication,
        **heat,
    )
    raw = _native.thermal_state_many(
        bearing._b,
        *(column_array(frame, c) for c in names),
        _effects_arg(effects),
        options,
        threads=None if threads is None else int(threads),
        progress=progress,
    )
    return join_inputs(frame, result_frame(raw))
