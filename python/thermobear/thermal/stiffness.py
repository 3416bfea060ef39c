"""Bearing stiffness against speed under the three models of seed A Fig. 11:
``"constant"`` (the static stiffness), ``"speed"`` (the high-speed
quasi-static model) and ``"thermal"`` (the coupled thermo-mechanical state).
:func:`stiffness_curve` is the bearing's curve; it sits here, above
:mod:`thermobear.bearing`, because its thermal mode is the thermal network's
:func:`thermal_stiffness_curve`."""

from __future__ import annotations

from typing import Any, Callable, Optional, Sequence

import numpy as np

from .. import _native
from ..bearing.ball_bearing import Bearing, _effects_arg
from ..errors import ConfigError
from .state import _model_kwargs


def stiffness_curve(
    bearing: Bearing,
    speeds_rpm: Sequence[float],
    axial_n: float = 0.0,
    radial_n: float = 0.0,
    moment_nmm: float = 0.0,
    *,
    mode: str = "speed",
    effects: Optional[Sequence[str]] = None,
    raceway_control: str = "outer",
    misalignment_rad: Optional[float] = 0.0,
    progress: Optional[Callable[[int, int], None]] = None,
    **thermal_options: Any,
) -> "polars.DataFrame":  # noqa: F821
    """Bearing stiffness against speed, solved in parallel (rayon) with the
    GIL released; deterministic for any thread count.

    ``mode="speed"``: the high-speed quasi-static model at each speed.
    ``mode="constant"``: the zero-speed (static) stiffness repeated at every
    speed (seed A Fig. 11, case 1).
    ``mode="thermal"``: the coupled thermo-mechanical state at each speed
    (seed A Fig. 11, case 3; see :func:`thermobear.thermal.thermal_stiffness_curve`
    for the extra columns and ``thermal_options``: ``lubricant``,
    ``lubrication_factor_f0``, ``spin_friction``, ``oil_air_temperature_c``,
    ``ambient_temperature_c``, ``housing_material``).
    ``progress(done, total)`` is called between chunks; Ctrl-C interrupts.
    Columns (SI): ``speed_rpm``, ``axial_stiffness_n_per_m``,
    ``radial_stiffness_n_per_m``, ``k_xx_n_per_m`` ... , displacements in mm,
    extreme contact angles in degrees and loads in N.
    """
    import polars as pl

    if mode not in ("speed", "constant", "thermal"):
        raise ConfigError(f'invalid mode = {mode!r}: must be "speed", "constant" or "thermal"')
    if mode == "thermal":
        if moment_nmm != 0.0:
            raise ConfigError(
                f"invalid moment_nmm = {moment_nmm}: "
                "the thermal mode takes axial and radial loads only"
            )
        return thermal_stiffness_curve(
            bearing,
            speeds_rpm,
            axial_n,
            radial_n,
            effects=effects,
            raceway_control=raceway_control,
            misalignment_rad=misalignment_rad,
            progress=progress,
            **thermal_options,
        )
    if thermal_options:
        raise ConfigError(
            f"invalid argument = {sorted(thermal_options)[0]!r}: "
            "only the thermal mode takes thermal options"
        )
    speeds = np.ascontiguousarray(np.asarray(speeds_rpm, dtype=float).ravel())
    if speeds.size == 0:
        raise ConfigError("invalid speeds_rpm = []: give at least one speed")
    native_speeds = np.zeros_like(speeds) if mode == "constant" else speeds
    cols = _native.stiffness_curve(
        bearing._b,
        native_speeds,
        float(axial_n),
        float(radial_n),
        float(moment_nmm),
        _effects_arg(effects),
        raceway_control,
        None if misalignment_rad is None else float(misalignment_rad),
        progress,
    )
    df = pl.DataFrame({k: np.asarray(v) for k, v in cols.items()})
    return df.with_columns(pl.Series("speed_rpm", speeds)).with_columns(pl.lit(mode).alias("mode"))


def thermal_stiffness_curve(
    bearing: Bearing,
    speeds_rpm: Sequence[float],
    axial_n: float = 0.0,
    radial_n: float = 0.0,
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
    progress: Optional[Callable[[int, int], None]] = None,
    **heat: Any,
) -> "polars.DataFrame":  # noqa: F821
    """The coupled state at every speed (parallel, deterministic): the
    stiffness columns of :func:`thermobear.stiffness_curve` plus
    ``shaft/inner_ring/ball/outer_ring/housing_temperature_c``, ``heat_w``
    (and ``load_/viscous_/spin_heat_w``), ``radial_thermal_offset_um``,
    ``axial_thermal_offset_um``, ``ball_growth_um``, ``extra_heat_w``,
    ``churning_w`` (ball drag heat at ``churning_oil_fraction``, a volume
    fraction 0..1; see :func:`thermal_state`), ``centrifugal_expansion_um``,
    ``thermal_iterations``. ``heat``: the heat-model keywords of
    :func:`thermal_state` (``heat_model``, ``lubrication``, ``skf_series``,
    ``sliding_friction_ehl``, ``replenishment_krs``, ``seal_moment_nmm``)."""
    import polars as pl

    speeds = np.ascontiguousarray(np.asarray(speeds_rpm, dtype=float).ravel())
    if speeds.size == 0:
        raise ConfigError("invalid speeds_rpm = []: give at least one speed")
    cols = _native.thermal_stiffness_curve(
        bearing._b,
        speeds,
        float(axial_n),
        float(radial_n),
        _effects_arg(effects),
        _model_kwargs(
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
            **heat,
        ),
        progress=progress,
    )
    df = pl.DataFrame({k: np.asarray(v) for k, v in cols.items()})
    return df.with_columns(pl.Series("speed_rpm", speeds)).with_columns(
        pl.lit("thermal").alias("mode")
    )
