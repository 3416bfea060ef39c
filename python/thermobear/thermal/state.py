"""Bearing heat, the thermal network and the coupled thermo-mechanical state.

:func:`thermal_state` solves the fixed point heat -> temperatures ->
thermal expansion -> raceway geometry -> contact loads -> heat for one
bearing in the seed A thermal network (Fig. 7). Objects with a
``_thermal_state(**kwargs)`` method (e.g. a spindle) are dispatched to it.

Effects (see :func:`thermobear.effects`): ``thermal_expansion_shaft``,
``_inner_ring``, ``_outer_ring``, ``_balls``, ``_housing``,
``temperature_dependent_viscosity`` and ``spin_friction`` switch the
thermal terms; ``centrifugal_force``, ``gyroscopic_moment`` and
``ring_centrifugal_expansion`` the high-speed terms. Default: all on.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Optional, Sequence

import numpy as np

from .. import _native
from ..bearing.ball_bearing import Bearing, BearingSolution, _effects_arg
from ..bearing.material import _native_material
from ..errors import ConfigError

#: Effects that make the coupled model differ from the isothermal one.
THERMAL_EFFECTS = (
    "thermal_expansion_shaft",
    "thermal_expansion_inner_ring",
    "thermal_expansion_outer_ring",
    "thermal_expansion_balls",
    "thermal_expansion_housing",
)


@dataclass(frozen=True)
class _HeatRows:
    """What every heat result shows (:class:`ThermalState`,
    :class:`~thermobear.IsothermalHeat`); SI inside ``raw``."""

    raw: dict

    @property
    def heat(self) -> "polars.DataFrame":  # noqa: F821
        """Heat by mechanism: ``source`` (Palmgren: load, viscous,
        inner_spin, outer_spin, extra, churning; SKF: rolling, sliding,
        seal, extra, churning), ``heat_w``."""
        import polars as pl

        return pl.DataFrame(
            {"source": list(self.raw["source"]), "heat_w": np.asarray(self.raw["heat_w"])}
        )

    @property
    def total_heat_w(self) -> float:
        """Total heat [W]."""
        return float(self.raw["total_heat_w"])

    @property
    def churning_w(self) -> float:
        """Ball drag ("churning") heat in the oil-air mixture [W] (0 unless
        ``churning_oil_fraction`` > 0)."""
        return float(self.raw["churning_w"])

    @property
    def solution(self) -> BearingSolution:
        """The bearing state the heat was evaluated on."""
        return BearingSolution(self.raw["solution"])

    @property
    def oil_temperature_c(self) -> float:
        """Temperature the oil's viscosity and density were taken at [C]."""
        return float(self.raw["oil_temperature_c"])

    @property
    def viscosity_cst(self) -> float:
        """Oil kinematic viscosity [mm^2/s]."""
        return float(self.raw["viscosity_cst"])


@dataclass(frozen=True)
class ThermalState(_HeatRows):
    """Coupled steady state of one bearing; SI inside ``raw``."""

    @property
    def temperatures(self) -> "polars.DataFrame":  # noqa: F821
        """Node temperatures: ``node``, ``temperature_c`` (boundaries included)."""
        import polars as pl

        return pl.DataFrame(
            {"node": list(self.raw["node"]), "temperature_c": np.asarray(self.raw["temperature_c"])}
        )

    def temperature_c(self, node: str) -> float:
        """Temperature of one node (``Ts``, ``Tci``, ``Ti``, ``Tb``, ``To``,
        ``Tco``, ``Th``, ``Tog``, ``Ta``)."""
        from ..errors import ConfigError

        names = list(self.raw["node"])
        if node not in names:
            raise ConfigError(f"invalid node = {node!r}: known: {', '.join(names)}")
        return float(np.asarray(self.raw["temperature_c"])[names.index(node)])

    @property
    def heat_split(self) -> "polars.DataFrame":  # noqa: F821
        """Heat by part (Burton-Staph, A-27): ``part``, ``heat_w``."""
        import polars as pl

        return pl.DataFrame(
            {"part": list(self.raw["part"]), "heat_w": np.asarray(self.raw["part_heat_w"])}
        )

    @property
    def boundary_flows(self) -> "polars.DataFrame":  # noqa: F821
        """Heat leaving through each fixed-temperature node: ``boundary``, ``heat_w``."""
        import polars as pl

        return pl.DataFrame(
            {
                "boundary": list(self.raw["boundary"]),
                "heat_w": np.asarray(self.raw["boundary_flow_w"]),
            }
        )

    @property
    def deformations(self) -> dict[str, float]:
        """Thermal offsets fed to the bearing (``radial_thermal_offset_um``,
        ``axial_thermal_offset_um``: A-38 with the ball growth projected on
        the free contact line), per-part growths, the centrifugal ring
        expansion and the ring displacements under load, all in um."""
        return {k: float(v) for k, v in self.raw["deformations"].items()}

    @property
    def iterations(self) -> int:
        return int(self.raw["iterations"])

    @property
    def residual(self) -> float:
        """Last largest node temperature change of the fixed point [K]."""
        return float(self.raw["residual_k"])

    def __repr__(self) -> str:
        t = dict(zip(self.raw["node"], np.asarray(self.raw["temperature_c"]), strict=False))
        return (
            f"ThermalState(heat={self.total_heat_w:.1f} W, Ti={t['Ti']:.1f} C, Tb={t['Tb']:.1f} C, "
            f"To={t['To']:.1f} C, iterations={self.iterations})"
        )


#: Keyword options of the heat model (docs/concepts/physics.md §9) and
#: their defaults: ``heat_model`` "palmgren" (the seeds') or "skf" (four-term
#: SKF-style moment); ``lubrication`` None (the seeds' oil-air with f0 = 1
#: and no ball drag) or "grease", "oil-air", "oil-mist", "jet", "oil-bath"
#: (its defaults then fill ``lubrication_factor_f0`` and
#: ``churning_oil_fraction`` when not given; :func:`lubrication_defaults`);
#: SKF model: ``skf_series`` (SKF General Catalogue 6000, 2006, tables 3a
#: and 3: deep-groove "60", "62", "63", "64" (also "630", "622", "623");
#: "angular-single-row" for every single-row angular-contact series, also
#: accepted as "72B" or "73B"; None: 62 deep-groove, angular-single-row
#: angular-contact), ``sliding_friction_ehl`` (mu_EHL; None:
#: 0.1 for a transmission fluid such as "e-drive ATF", else 0.05),
#: ``replenishment_krs`` (None: from the lubrication method),
#: ``seal_moment_nmm`` (N mm, 0 = open bearing).
HEAT_MODEL_OPTIONS = {
    "heat_model": "palmgren",
    "lubrication": None,
    "skf_series": None,
    "sliding_friction_ehl": None,
    "replenishment_krs": None,
    "seal_moment_nmm": 0.0,
}


def _opt_float(v: Any) -> Optional[float]:
    return None if v is None else float(v)


def _model_kwargs(
    lubricant: str,
    lubrication_factor_f0: Optional[float],
    spin_friction: float,
    oil_air_temperature_c: float,
    ambient_temperature_c: float,
    housing_material: Any,
    raceway_control: str,
    misalignment_rad: Optional[float],
    extra_heat_w: float = 0.0,
    housing_conductance_scale: float = 1.0,
    churning_oil_fraction: Optional[float] = None,
    **heat: Any,
) -> dict:
    for k in heat:
        if k not in HEAT_MODEL_OPTIONS:
            raise ConfigError(f"invalid argument = {k!r}: not a thermal or heat-model option")
    h = {**HEAT_MODEL_OPTIONS, **heat}
    return {
        "lubricant": str(lubricant),
        "lubrication_factor_f0": _opt_float(lubrication_factor_f0),
        "spin_friction": float(spin_friction),
        "oil_air_temperature_c": float(oil_air_temperature_c),
        "ambient_temperature_c": float(ambient_temperature_c),
        "housing_material": _native_material(housing_material),
        "raceway_control": str(raceway_control),
        "misalignment_rad": None if misalignment_rad is None else float(misalignment_rad),
        "extra_heat_w": float(extra_heat_w),
        "housing_conductance_scale": float(housing_conductance_scale),
        "churning_oil_fraction": _opt_float(churning_oil_fraction),
        "heat_model": str(h["heat_model"]),
        "lubrication": None if h["lubrication"] is None else str(h["lubrication"]),
        "skf_series": None if h["skf_series"] is None else str(h["skf_series"]),
        "sliding_friction_ehl": _opt_float(h["sliding_friction_ehl"]),
        "replenishment_krs": _opt_float(h["replenishment_krs"]),
        "seal_moment_nmm": float(h["seal_moment_nmm"]),
    }


def lubrication_defaults(lubrication: str, bearing_type: str = "angular_contact") -> dict:
    """What a lubrication method sets (docs/concepts/physics.md §9) for a
    ``bearing_type`` ("deep_groove" or "angular_contact"): the Palmgren
    factor ``lubrication_factor_f0`` and its ``f0_bounds`` (Harris &
    Kotzalas' table), the ball-drag oil volume fraction
    ``oil_volume_fraction`` and its ``oil_fraction_bounds`` (dimensionless),
    the SKF ``replenishment_krs``."""
    return dict(_native.lubrication_defaults(str(lubrication), str(bearing_type).replace("-", "_")))


def thermal_state(
    bearing: Any,
    speed_rpm: float,
    axial_n: Optional[float] = None,
    radial_n: Optional[float] = None,
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
    **kwargs: Any,
) -> Any:
    """Coupled thermal steady state at ``speed_rpm`` under ``axial_n``
    (preload included) and ``radial_n``.

    For a :class:`~thermobear.Bearing`: the seed A network (oil-air
    ``oil_air_temperature_c``, ambient ``ambient_temperature_c``, housing
    of ``housing_material``, ``lubricant`` preset: "ISO VG 32", "ISO VG 68",
    "e-drive ATF"), Palmgren friction with ``lubrication_factor_f0`` (None:
    1, or the ``lubrication`` method's) and spin friction coefficient
    ``spin_friction``. Calibration inputs:
    ``extra_heat_w`` (W, >= 0; heat at the bearing beyond the modelled
    friction, e.g. from a magnetic pull load, split like rolling heat
    1/4 : 1/2 : 1/4 to inner ring, balls, outer ring) and
    ``housing_conductance_scale`` (> 0, default 1; scales the housing-to-
    ambient convection link) and ``churning_oil_fraction`` (the oil volume
    fraction X of the oil-air mixture in the bearing cavity: dimensionless,
    0..1, default 0 = off; adds the ball drag heat
    Z (pi/64) C_D X rho_oil D^2 dm^3 omega_c^3, C_D = 0.47, at the solved
    cage speed omega_c, which grows like speed^3; split like rolling heat;
    reported as ``churning_w`` and the ``churning`` row of
    :attr:`ThermalState.heat`). ``heat_model`` ("palmgren" or "skf": heat
    rows rolling, sliding, seal, extra, churning), ``lubrication`` (sets the
    defaults of f0 and X) and the SKF keywords: :data:`HEAT_MODEL_OPTIONS`.
    The defaults reproduce the baseline. Returns a
    :class:`ThermalState`. Raises ``ThermalRunawayError`` when a node passes
    the lubricant's highest temperature or heat, temperatures and contact
    loads grow together, ``ConvergenceError`` when the fixed point stalls.

    Any object with a ``_thermal_state(**kwargs)`` method (a
    :class:`~thermobear.Spindle`) is dispatched to it with ``speed_rpm``, the
    loads and ``effects`` that were given, and the remaining keyword
    arguments (for a spindle: ``preload_n``, ``preload_kind``)."""
    if hasattr(bearing, "_thermal_state") and not isinstance(bearing, Bearing):
        given = {"axial_n": axial_n, "radial_n": radial_n, "effects": effects,
                 "lubrication": lubrication,
                 "heat_model": None if heat_model == "palmgren" else heat_model,
                 "lubrication_factor_f0": lubrication_factor_f0,
                 "churning_oil_fraction": churning_oil_fraction}  # fmt: skip
        return _dispatch(bearing, speed_rpm, given, kwargs)
    heat = {k: kwargs.pop(k) for k in list(kwargs) if k in HEAT_MODEL_OPTIONS}
    _check_bearing_call(bearing, kwargs)
    args = (lubricant, lubrication_factor_f0, spin_friction, oil_air_temperature_c,
            ambient_temperature_c, housing_material, raceway_control, misalignment_rad,
            extra_heat_w, housing_conductance_scale, churning_oil_fraction)  # fmt: skip
    options = _model_kwargs(*args, heat_model=heat_model, lubrication=lubrication, **heat)
    loads = (
        float(0.0 if axial_n is None else axial_n),
        float(0.0 if radial_n is None else radial_n),
    )
    raw = _native.thermal_state(
        bearing._b, float(speed_rpm), *loads, _effects_arg(effects), options
    )
    return ThermalState(raw)


def _dispatch(machine: Any, speed_rpm: float, given: dict, kwargs: dict) -> Any:
    """``machine._thermal_state`` with the arguments that were given."""
    given = {k: v for k, v in given.items() if v is not None}
    return machine._thermal_state(speed_rpm=speed_rpm, **given, **kwargs)


def _check_bearing_call(bearing: Any, kwargs: dict) -> None:
    """A :class:`~thermobear.Bearing` and no option beyond the bearing's."""
    from ..errors import ConfigError

    if kwargs:
        raise ConfigError(
            f"invalid argument = {sorted(kwargs)[0]!r}: not a thermal_state option for a Bearing"
        )
    if not isinstance(bearing, Bearing):
        raise ConfigError(f"invalid bearing = {bearing!r}: give a thermobear.Bearing")
