"""Bearing heat at a fixed oil temperature: the friction model alone.

[`isothermal_heat`][thermobear.isothermal_heat] evaluates the heat model of
[`thermal_state`][thermobear.thermal_state] (Palmgren or the SKF-style four-term
moment, ball drag, spin) on the isothermal bearing state, with the oil --
and so its viscosity and density -- held at ``oil_temperature_c``, and no
thermal network. For conditions that fix the bearing temperature, such as
the ISO 15312 reference conditions behind catalogue reference speeds
(docs/concepts/physics.md §9, "Reference speed")."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Optional, Sequence

from .. import _native
from .. import _validate as val
from .._deprecation import renamed_kwargs
from .._input_checks import check_oil_temperature
from .._model_hook import takes_calibrated
from .._types import HeatModel, Lubrication, RacewayControl
from .heat_law import HEAT_LAW_OPTIONS, plus_heat_law, pop_heat_law
from .state import (
    DEFAULT_SPIN_FRICTION_COEFFICIENT,
    HEAT_MODEL_OPTIONS,
    _check_bearing_call,
    _heat_line,
    _HeatRows,
    _model_kwargs,
    checked_native,
    operating_point,
)


@dataclass(frozen=True)
class IsothermalHeat(_HeatRows):
    """Heat of one bearing at one operating point and oil temperature
    (``heat``, ``total_heat_w``, ``churning_heat_w``, ``viscosity_cst``,
    ``oil_temperature_c``, ``solution``: the isothermal bearing state); SI
    inside ``raw``."""

    def __repr__(self) -> str:
        return (
            f"IsothermalHeat(heat={self.total_heat_w:.2f} W, {self.raw['heat_model']}, "
            f"nu={self.viscosity_cst:.2f} mm^2/s at {self.oil_temperature_c:.1f} C)"
        )

    def summary(self) -> str:
        """The heat in a few lines: total, by mechanism, the oil and the
        bearing state it was evaluated on."""
        sol = self.solution
        return "\n".join(
            [
                f"isothermal heat ({self.raw['heat_model']}): {self.total_heat_w:.4g} W at "
                f"{sol.speed_rpm:g} rpm",
                _heat_line(self),
                f"  oil at {self.oil_temperature_c:.1f} C: {self.viscosity_cst:.3g} mm^2/s",
                f"  bearing: k_xx {sol.k_xx_n_per_m:.4g} N/m, k_zz {sol.k_zz_n_per_m:.4g} N/m",
            ]
        )


@renamed_kwargs(spin_friction="spin_friction_coefficient")
@takes_calibrated(lambda given: (*HEAT_MODEL_OPTIONS, *HEAT_LAW_OPTIONS))
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
    spin_friction_coefficient: float = DEFAULT_SPIN_FRICTION_COEFFICIENT,
    raceway_control: RacewayControl = "outer",
    misalignment_rad: Optional[float] = 0.0,
    extra_heat_w: float = 0.0,
    churning_oil_fraction: Optional[float] = None,
    heat_model: HeatModel = "palmgren",
    lubrication: Optional[Lubrication] = None,
    **heat: Any,
) -> IsothermalHeat:
    """Heat of ``bearing`` at ``speed_rpm`` under ``axial_n`` and
    ``radial_n`` [N] with the ``lubricant`` at ``oil_temperature_c`` [C]
    (its viscosity and density taken there), no thermal expansion and no
    thermal network: the heat model options of
    [`thermal_state`][thermobear.thermal_state] (``heat_model``, ``lubrication``,
    ``lubrication_factor_f0``, ``spin_friction_coefficient``, ``churning_oil_fraction``,
    ``extra_heat_w``, the speed law of ``unknown_heat_linear_w``,
    ``unknown_heat_quadratic_w``, ``unknown_heat_reference_rpm`` and the SKF
    keywords of ``HEAT_MODEL_OPTIONS``).
    A temperature outside the lubricant's data raises ``ConfigError``
    naming ``oil_temperature_c``. A calibrated model
    ([`CalibratedModel`][thermobear.CalibratedModel]) stands for its bearing
    (its heat-model options; the network's do not act here)."""
    _check_bearing_call(bearing, {})  # unknown keywords: _model_kwargs names them
    law = pop_heat_law(heat)
    extra_heat_w = plus_heat_law(extra_heat_w, law, speed_rpm)  # a speed law's heat
    # the network's boundary temperatures are not used here: neutral 40 C
    neutral = (40.0, 40.0, "aluminium")
    args = (lubricant, lubrication_factor_f0, spin_friction_coefficient, *neutral, raceway_control,
            misalignment_rad, extra_heat_w, 1.0, churning_oil_fraction)  # fmt: skip
    options = _model_kwargs(*args, heat_model=heat_model, lubrication=lubrication, **heat)
    point = operating_point(speed_rpm, axial_n, radial_n)
    oil_c = val.real("oil_temperature_c", oil_temperature_c, -273.15)
    check_oil_temperature(options["lubricant"], oil_c)
    raw = checked_native(_native.isothermal_heat, bearing, point, (oil_c,), effects, options)
    return IsothermalHeat(raw)
