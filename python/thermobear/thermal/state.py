"""Bearing heat, the thermal network and the coupled thermo-mechanical state.

[`thermal_state`][thermobear.thermal_state] solves the fixed point heat -> temperatures ->
thermal expansion -> raceway geometry -> contact loads -> heat for one
bearing in the seed A thermal network (Fig. 7). Objects with a
``_thermal_state(**kwargs)`` method (e.g. a spindle) are dispatched to it.

Effects (see [`thermobear.effects`][thermobear.effects]): ``thermal_expansion_shaft``,
``_inner_ring``, ``_outer_ring``, ``_balls``, ``_housing``,
``temperature_dependent_viscosity`` and ``spin_friction`` switch the
thermal terms; ``centrifugal_force``, ``gyroscopic_moment`` and
``ring_centrifugal_expansion`` the high-speed terms. Default: all on.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, Optional, Sequence

import numpy as np

from .. import _native, plausibility
from .. import _validate as val
from .._deprecation import renamed_kwargs, warn_renamed
from .._input_checks import check_supply
from .._model_hook import takes_calibrated
from .._names import BEARING_NODES, BEARING_SYMBOLS
from .._types import HeatModel, Lubrication, RacewayControl
from ..bearing.ball_bearing import Bearing, BearingSolution, _effects_arg, register_task
from ..bearing.material import _native_material
from ..errors import ConfigError, ConvergenceError
from .heat_law import HEAT_LAW_OPTIONS, plus_heat_law, pop_heat_law
from .oil_supply import SUPPLY_OPTIONS, supply_dict

if TYPE_CHECKING:
    import polars

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
    """What every heat result shows ([`ThermalState`][thermobear.ThermalState],
    [`IsothermalHeat`][thermobear.IsothermalHeat]); SI inside ``raw``."""

    raw: dict[str, Any]

    @property
    def heat(self) -> polars.DataFrame:
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
    def churning_heat_w(self) -> float:
        """Ball drag ("churning") heat in the oil-air mixture [W] (0 unless
        ``churning_oil_fraction`` > 0)."""
        return float(self.raw["churning_w"])

    @property
    def churning_w(self) -> float:
        """Deprecated: ``churning_heat_w``."""
        warn_renamed("churning_w", "churning_heat_w")
        return self.churning_heat_w

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
    def temperatures(self) -> polars.DataFrame:
        """Node temperatures (boundaries included): ``node`` (the long name,
        e.g. ``"outer_ring"``), ``symbol`` (the physics docs', e.g. ``"To"``),
        ``temperature_c``."""
        import polars as pl

        symbols = [str(s) for s in self.raw["node"]]
        return pl.DataFrame(
            {
                "node": [BEARING_SYMBOLS.get(s, s) for s in symbols],
                "symbol": symbols,
                "temperature_c": np.asarray(self.raw["temperature_c"], dtype=float),
            }
        )

    def temperature_c(self, node: str) -> float:
        """Temperature of one node [C], by its name (``shaft``,
        ``inner_contact``, ``inner_ring``, ``ball``, ``outer_ring``,
        ``outer_contact``, ``housing``, ``oil_air``, ``ambient``) or its
        symbol (``Ts``, ``Tci``, ``Ti``, ``Tb``, ``To``, ``Tco``, ``Th``,
        ``Tog``, ``Ta``)."""
        from ..errors import ConfigError

        symbols = [str(s) for s in self.raw["node"]]
        symbol = BEARING_NODES.get(node, node)
        if symbol not in symbols:
            known = [BEARING_SYMBOLS.get(s, s) for s in symbols]
            raise ConfigError(f"invalid node = {node!r}: known: {', '.join(known)}")
        return float(np.asarray(self.raw["temperature_c"])[symbols.index(symbol)])

    @property
    def heat_split(self) -> polars.DataFrame:
        """Heat by part (Burton-Staph, A-27): ``part``, ``heat_w``."""
        import polars as pl

        return pl.DataFrame(
            {"part": list(self.raw["part"]), "heat_w": np.asarray(self.raw["part_heat_w"])}
        )

    @property
    def boundary_flows(self) -> polars.DataFrame:
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

    def summary(self) -> str:
        """The steady state in a few lines: each node's temperature, the
        heat by mechanism, the bearing state and the convergence."""
        from .._names import BEARING_SYMBOLS

        temps = np.asarray(self.raw["temperature_c"])
        lines = [f"thermal steady state: heat {self.total_heat_w:.4g} W"]
        for sym, t in zip(self.raw["node"], temps, strict=False):
            name = BEARING_SYMBOLS.get(str(sym), str(sym))
            lines.append(f"  {name + '_temperature_c':30s} {float(t):8.2f}  ({sym})")
        lines.append(_heat_line(self))
        sol = self.solution
        lines.append(
            f"  bearing: k_xx {sol.k_xx_n_per_m:.4g} N/m, k_zz {sol.k_zz_n_per_m:.4g} N/m, "
            f"oil {self.oil_temperature_c:.1f} C, {self.viscosity_cst:.3g} mm^2/s"
        )
        lines.append(f"  converged in {self.iterations} iterations, residual {self.residual:.3g} K")
        return "\n".join(lines)


def _heat_line(result: _HeatRows) -> str:
    """The heat by mechanism of a heat result as one line of a summary."""
    parts = [
        f"{src} {float(w):.3g} W"
        for src, w in zip(result.raw["source"], np.asarray(result.raw["heat_w"]), strict=False)
    ]
    return "  heat: " + ", ".join(parts)


#: Keyword options of the heat model (docs/concepts/physics.md §9) and
#: their defaults: ``heat_model`` "palmgren" (the seeds') or "skf" (four-term
#: SKF-style moment); ``lubrication`` None (the seeds' oil-air with f0 = 1
#: and no ball drag) or "grease", "oil-air", "oil-mist", "jet", "oil-bath"
#: (its defaults then fill ``lubrication_factor_f0`` and
#: ``churning_oil_fraction`` when not given; ``lubrication_defaults``);
#: SKF model: ``skf_series`` (SKF General Catalogue 6000, 2006, tables 3a
#: and 3: deep-groove "60", "62", "63", "64" (also "630", "622", "623");
#: "angular-single-row" for every single-row angular-contact series, also
#: accepted as "72B" or "73B"; None: 62 deep-groove, angular-single-row
#: angular-contact), ``sliding_friction_ehl`` (mu_EHL; None:
#: 0.1 for a transmission fluid such as "e-drive ATF", else 0.05),
#: ``replenishment_krs`` (None: from the lubrication method),
#: ``seal_moment_n_m`` (N m, 0 = open bearing; the older ``seal_moment_nmm``
#: in N mm is deprecated and converted).
HEAT_MODEL_OPTIONS = {
    "heat_model": "palmgren",
    "lubrication": None,
    "skf_series": None,
    "sliding_friction_ehl": None,
    "replenishment_krs": None,
    "seal_moment_n_m": 0.0,
    **SUPPLY_OPTIONS,
}

#: Spin friction coefficient mu_s of the spin moment (3/8) mu_s Q a E: one
#: default for a single bearing and a spindle. Neither seed gives a value;
#: EHL traction at the spin-dominated sliding of a loaded ball contact is
#: 0.03-0.07 for mineral and transmission oils, and we take the middle.
DEFAULT_SPIN_FRICTION_COEFFICIENT = 0.05


def seal_moment_option(heat: dict[str, Any]) -> dict[str, Any]:
    """``heat`` with an older ``seal_moment_nmm`` (N mm) as ``seal_moment_n_m``."""
    if "seal_moment_nmm" not in heat:
        return heat
    heat = dict(heat)
    old = heat.pop("seal_moment_nmm")
    if heat.get("seal_moment_n_m") is not None:
        raise TypeError("got both `seal_moment_nmm` (deprecated) and `seal_moment_n_m`")
    warn_renamed("seal_moment_nmm", "seal_moment_n_m", stacklevel=4, what="value in N m")
    heat["seal_moment_n_m"] = None if old is None else float(old) / 1000.0
    return heat


def _opt_float(value: Any, name: str = "argument", lo: float = -val.INF) -> Optional[float]:
    return val.optional_real(name, value, lo)


def _model_kwargs(
    lubricant: str,
    lubrication_factor_f0: Optional[float],
    spin_friction_coefficient: float,
    oil_air_temperature_c: float,
    ambient_temperature_c: float,
    housing_material: Any,
    raceway_control: str,
    misalignment_rad: Optional[float],
    extra_heat_w: float = 0.0,
    housing_conductance_scale: float = 1.0,
    churning_oil_fraction: Optional[float] = None,
    **heat: Any,
) -> dict[str, Any]:
    heat = seal_moment_option(heat)
    for k in heat:
        if k not in HEAT_MODEL_OPTIONS:
            import inspect

            known = [*HEAT_MODEL_OPTIONS, *inspect.signature(_model_kwargs).parameters]
            raise ConfigError(
                f"invalid argument = {k!r}: not a thermal or heat-model option"
                + val.did_you_mean(k, known)
            )
    h = {**HEAT_MODEL_OPTIONS, **heat}
    kelvin = -273.15
    return {
        "lubricant": val.text("lubricant", lubricant),
        "lubrication_factor_f0": _opt_float(lubrication_factor_f0, "lubrication_factor_f0", 0),
        "spin_friction": val.real("spin_friction_coefficient", spin_friction_coefficient, 0.0),
        "oil_air_temperature_c": val.real("oil_air_temperature_c", oil_air_temperature_c, kelvin),
        "ambient_temperature_c": val.real("ambient_temperature_c", ambient_temperature_c, kelvin),
        "housing_material": _native_material(housing_material),
        "raceway_control": val.choice("raceway_control", raceway_control, ("outer", "inner")),
        "misalignment_rad": _opt_float(misalignment_rad, "misalignment_rad"),
        "extra_heat_w": val.real("extra_heat_w", extra_heat_w),
        "housing_conductance_scale": val.real(
            "housing_conductance_scale", housing_conductance_scale, 0.0
        ),
        "churning_oil_fraction": _opt_float(churning_oil_fraction, "churning_oil_fraction", 0),
        "heat_model": val.choice("heat_model", h["heat_model"], ("palmgren", "skf")),
        "lubrication": None
        if h["lubrication"] is None
        else val.choice("lubrication", h["lubrication"], LUBRICATIONS),
        "skf_series": None if h["skf_series"] is None else val.text("skf_series", h["skf_series"]),
        "sliding_friction_ehl": _opt_float(h["sliding_friction_ehl"], "sliding_friction_ehl", 0),
        "replenishment_krs": _opt_float(h["replenishment_krs"], "replenishment_krs", 0),
        "seal_moment_n_m": val.real("seal_moment_n_m", h["seal_moment_n_m"], 0.0),
        "oil_supply": supply_dict(h),
    }


#: The lubrication methods (``Lubrication``).
LUBRICATIONS = ("grease", "oil-air", "oil-mist", "jet", "oil-bath")


def check_plausible(
    bearing: Bearing, solution: Any, inputs: dict[str, Any], options: dict[str, Any]
) -> None:
    """The plausibility checks of a bearing's heat or thermal state: its
    solved bearing state (``raw["solution"]``) with the lubrication
    method's speed limit."""
    plausibility.check_solution(
        bearing, solution, inputs, options["misalignment_rad"], options["lubrication"]
    )


def operating_point(speed_rpm: Any, axial_n: Any, radial_n: Any) -> dict[str, float]:
    """Speed and loads of a bearing call, checked (None load: 0)."""
    return {
        "speed_rpm": val.real("speed_rpm", speed_rpm, 0.0),
        "axial_n": val.real("axial_n", 0.0 if axial_n is None else axial_n),
        "radial_n": val.real("radial_n", 0.0 if radial_n is None else radial_n),
    }


def lubrication_defaults(
    lubrication: Lubrication, bearing_type: str = "angular_contact"
) -> dict[str, Any]:
    """What a lubrication method sets (docs/concepts/physics.md §9) for a
    ``bearing_type`` ("deep_groove" or "angular_contact"): the Palmgren
    factor ``lubrication_factor_f0`` and its ``f0_bounds`` (Harris &
    Kotzalas' table), the ball-drag oil volume fraction
    ``oil_volume_fraction`` and its ``oil_fraction_bounds`` (dimensionless),
    the SKF ``replenishment_krs``."""
    return dict(_native.lubrication_defaults(str(lubrication), str(bearing_type).replace("-", "_")))


@renamed_kwargs(spin_friction="spin_friction_coefficient")
@takes_calibrated(lambda given: (*HEAT_MODEL_OPTIONS, *HEAT_LAW_OPTIONS))
def thermal_state(
    bearing: Any,
    speed_rpm: float,
    axial_n: Optional[float] = None,
    radial_n: Optional[float] = None,
    *,
    effects: Optional[Sequence[str]] = None,
    lubricant: str = "e-drive ATF",
    lubrication_factor_f0: Optional[float] = None,
    spin_friction_coefficient: Optional[float] = None,
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
    **kwargs: Any,
) -> Any:
    """Coupled thermal steady state at ``speed_rpm`` under ``axial_n``
    (preload included) and ``radial_n``.

    For a [`Bearing`][thermobear.Bearing]: the seed A network (oil-air
    ``oil_air_temperature_c``, ambient ``ambient_temperature_c``, housing
    of ``housing_material``, ``lubricant`` preset: "ISO VG 32", "ISO VG 68",
    "e-drive ATF"), Palmgren friction with ``lubrication_factor_f0`` (None:
    1, or the ``lubrication`` method's) and the spin friction coefficient
    ``spin_friction_coefficient`` (None: ``DEFAULT_SPIN_FRICTION_COEFFICIENT``,
    0.05, the same default as a spindle's). Calibration inputs:
    ``extra_heat_w`` (W, >= 0; heat at the bearing beyond the modelled
    friction, e.g. from a magnetic pull load, split like rolling heat
    1/4 : 1/2 : 1/4 to inner ring, balls, outer ring) and
    ``housing_conductance_scale`` (> 0, default 1; scales the housing-to-
    ambient convection link) and ``churning_oil_fraction`` (the oil volume
    fraction X of the oil-air mixture in the bearing cavity: dimensionless,
    0..1, default 0 = off; adds the ball drag heat
    Z (pi/64) C_D X rho_oil D^2 dm^3 omega_c^3, C_D = 0.47, at the solved
    cage speed omega_c, which grows like speed^3; split like rolling heat;
    reported as ``churning_heat_w`` and the ``churning`` row of
    ``ThermalState.heat``). ``heat_model`` ("palmgren" or "skf": heat
    rows rolling, sliding, seal, extra, churning), ``lubrication`` (sets the
    defaults of f0 and X) and the SKF keywords: ``HEAT_MODEL_OPTIONS``.
    An extra heat with its own speed law: ``unknown_heat_linear_w``,
    ``unknown_heat_quadratic_w`` [W] and ``unknown_heat_reference_rpm``
    (``max(0, a x + b x^2)``, ``x = speed_rpm / reference``, added to
    ``extra_heat_w``; the unknown heat source of a diagnosis). The
    defaults reproduce the baseline. Returns a
    [`ThermalState`][thermobear.ThermalState]. Raises ``ThermalRunawayError`` when a node passes
    the lubricant's highest temperature or heat, temperatures and contact
    loads grow together, ``ConvergenceError`` when the fixed point stalls.

    Any object with a ``_thermal_state(**kwargs)`` method (a
    [`Spindle`][thermobear.Spindle]) is dispatched to it with ``speed_rpm``, the
    loads and ``effects`` that were given, and the remaining keyword
    arguments (for a spindle: ``preload_n``, ``preload_kind``; its extra
    heat and speed law act at the front bearing set). A calibrated
    model ([`CalibratedModel`][thermobear.CalibratedModel]) stands for its machine."""
    if hasattr(bearing, "_thermal_state") and not isinstance(bearing, Bearing):
        given = {"axial_n": axial_n, "radial_n": radial_n, "effects": effects,
                 "lubrication": lubrication, "extra_heat_w": extra_heat_w or None,
                 "heat_model": None if heat_model == "palmgren" else heat_model,
                 "lubrication_factor_f0": lubrication_factor_f0,
                 "spin_friction_coefficient": spin_friction_coefficient,
                 "churning_oil_fraction": churning_oil_fraction}  # fmt: skip
        return _dispatch(bearing, speed_rpm, given, kwargs)
    heat = {k: kwargs.pop(k) for k in list(kwargs) if k in HEAT_MODEL_OPTIONS}
    law = pop_heat_law(kwargs)
    _check_bearing_call(bearing, kwargs)
    extra_heat_w = plus_heat_law(extra_heat_w, law, speed_rpm)  # a speed law's heat
    if spin_friction_coefficient is None:
        spin_friction_coefficient = DEFAULT_SPIN_FRICTION_COEFFICIENT
    args = (lubricant, lubrication_factor_f0, spin_friction_coefficient, oil_air_temperature_c,
            ambient_temperature_c, housing_material, raceway_control, misalignment_rad,
            extra_heat_w, housing_conductance_scale, churning_oil_fraction)  # fmt: skip
    options = _model_kwargs(*args, heat_model=heat_model, lubrication=lubrication, **heat)
    return ThermalState(_checked_state(bearing, speed_rpm, axial_n, radial_n, effects, options))


def _checked_state(
    bearing: Bearing, speed_rpm: Any, axial_n: Any, radial_n: Any, effects: Any, options: Any
) -> dict[str, Any]:
    """The native thermal state with the operating point checked before and
    the plausibility of the state after; a convergence failure names the
    operating point."""
    point = operating_point(speed_rpm, axial_n, radial_n)
    return dict(checked_native(_native.thermal_state, bearing, point, (), effects, options))


def checked_native(
    fn: Any,
    bearing: Bearing,
    point: dict[str, float],
    extra: tuple[float, ...],
    effects: Any,
    options: Any,
) -> Any:
    """``fn(bearing, speed, axial, radial, *extra, effects, options)`` (a
    native single-bearing heat call) with the misalignment checked before,
    the plausibility of the solved state after, and a convergence failure
    naming the operating point."""
    plausibility.check_misalignment(options["misalignment_rad"], plausibility._geometry(bearing))
    check_supply(
        plausibility._geometry(bearing), options["lubrication"], options["oil_supply"],
        point["speed_rpm"],
    )  # fmt: skip
    try:
        raw = fn(bearing._b, point["speed_rpm"], point["axial_n"], point["radial_n"], *extra,
                 _effects_arg(effects), options)  # fmt: skip
    except ConvergenceError as e:
        val.name_inputs(e, point)
        raise
    check_plausible(bearing, raw["solution"], point, options)
    return raw


def _dispatch(machine: Any, speed_rpm: float, given: dict[str, Any], kwargs: dict[str, Any]) -> Any:
    """``machine._thermal_state`` with the arguments that were given."""
    given = {k: v for k, v in given.items() if v is not None}
    return machine._thermal_state(speed_rpm=speed_rpm, **given, **kwargs)


def _check_bearing_call(bearing: Any, kwargs: dict[str, Any]) -> None:
    """A [`Bearing`][thermobear.Bearing] and no option beyond the bearing's."""
    from ..errors import ConfigError

    if kwargs:
        import inspect

        k = sorted(kwargs)[0]
        known = [*inspect.signature(thermal_state).parameters, *HEAT_MODEL_OPTIONS]
        raise ConfigError(
            f"invalid argument = {k!r}: not a thermal_state option for a Bearing"
            + val.did_you_mean(k, [n for n in known if n != "kwargs"])
        )
    if not isinstance(bearing, Bearing):
        raise ConfigError(f"invalid bearing = {bearing!r}: give a thermobear.Bearing")


register_task("thermal_state", thermal_state)
