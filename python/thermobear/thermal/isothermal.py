"""Bearing heat at a fixed oil temperature: the friction model alone.

:func:`isothermal_heat` evaluates the heat model of
:func:`~thermobear.thermal_state` (Palmgren or the SKF-style four-term
moment, ball drag, spin) on the isothermal bearing state, with the oil --
and so its viscosity and density -- held at ``oil_temperature_c``, and no
thermal network. For conditions that fix the bearing temperature, such as
the ISO 15312 reference conditions behind catalogue reference speeds
(docs/concepts/physics.md §9, "Reference speed")."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Optional, Sequence

from .. import _native
from ..bearing.ball_bearing import _effects_arg
from .state import _check_bearing_call, _HeatRows, _model_kwargs


@dataclass(frozen=True)
class IsothermalHeat(_HeatRows):
    """Heat of one bearing at one operating point and oil temperature
    (``heat``, ``total_heat_w``, ``churning_w``, ``viscosity_cst``,
    ``oil_temperature_c``, ``solution``: the isothermal bearing state); SI
    inside ``raw``."""

    def __repr__(self) -> str:
        return (
            f"IsothermalHeat(heat={self.total_heat_w:.2f} W, {self.raw['heat_model']}, "
            f"nu={self.viscosity_cst:.2f} mm^2/s at {self.oil_temperature_c:.1f} C)"
        )


def isothermal_heat(
    bearing: Any,
    speed_rpm: float,
    axial_n: Optional[float] = None,
    radial_n: Optional[float] = None,
    *,
    oil_temperature_c: float,
    effects: Optional[Sequence[str]] = None,
    lubricant: str = "e-drive ATF",
    lubrication_factor_f0: Optional[float] = None,
    spin_friction: float = 0.06,
    raceway_control: str = "outer",
    misalignment_rad: Optional[float] = 0.0,
    extra_heat_w: float = 0.0,
    churning_oil_fraction: Optional[float] = None,
    heat_model: str = "palmgren",
    lubrication: Optional[str] = None,
    **heat: Any,
) -> IsothermalHeat:
    """Heat of ``bearing`` at ``speed_rpm`` under ``axial_n`` and
    ``radial_n`` [N] with the ``lubricant`` at ``oil_temperature_c`` [C]
    (its viscosity and density taken there), no thermal expansion and no
    thermal network: the heat model options of
    :func:`~thermobear.thermal_state` (``heat_model``, ``lubrication``,
    ``lubrication_factor_f0``, ``spin_friction``, ``churning_oil_fraction``,
    ``extra_heat_w`` and the SKF keywords of :data:`HEAT_MODEL_OPTIONS`).
    A temperature outside the lubricant's data raises ``ConfigError``
    naming ``oil_temperature_c``."""
    _check_bearing_call(bearing, {})  # unknown keywords: _model_kwargs names them
    # the network's boundary temperatures are not used here: neutral 40 C
    neutral = (40.0, 40.0, "aluminium")
    args = (lubricant, lubrication_factor_f0, spin_friction, *neutral, raceway_control,
            misalignment_rad, extra_heat_w, 1.0, churning_oil_fraction)  # fmt: skip
    options = _model_kwargs(*args, heat_model=heat_model, lubrication=lubrication, **heat)
    raw = _native.isothermal_heat(
        bearing._b,
        float(speed_rpm),
        float(0.0 if axial_n is None else axial_n),
        float(0.0 if radial_n is None else radial_n),
        float(oil_temperature_c),
        _effects_arg(effects),
        options,
    )
    return IsothermalHeat(raw)
