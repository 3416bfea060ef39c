"""Bearing stiffness against speed under the three models of seed A Fig. 11:
``"constant"`` (the static stiffness), ``"speed"`` (the high-speed
quasi-static model) and ``"thermal"`` (the coupled thermo-mechanical state).
[`stiffness_curve`][thermobear.stiffness_curve] is the bearing's curve; it sits here, above
[`thermobear.bearing`][thermobear.bearing], because its thermal mode is the thermal network's
``thermal_stiffness_curve``."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Callable, Optional, Sequence

import numpy as np
from numpy.typing import ArrayLike

from .. import _native, plausibility
from .. import _validate as val
from .._deprecation import renamed_kwargs
from .._input_checks import check_supply
from .._model_hook import takes_calibrated
from .._names import renamed_columns
from .._partial import speed_frames
from .._types import RacewayControl, StiffnessMode
from ..bearing.ball_bearing import Bearing, _effects_arg
from ..errors import ConfigError, ThermobearError
from .heat_law import HEAT_LAW_OPTIONS, has_heat_law, heat_law_w, pop_heat_law
from .state import DEFAULT_SPIN_FRICTION_COEFFICIENT, HEAT_MODEL_OPTIONS, _model_kwargs

if TYPE_CHECKING:
    import polars


#: The thermal options of the thermal mode (``thermal_stiffness_curve``'s
#: keywords beyond the loads, effects and raceway settings).
THERMAL_OPTIONS = (
    "lubricant", "lubrication_factor_f0", "spin_friction_coefficient", "oil_air_temperature_c",
    "ambient_temperature_c", "housing_material", "extra_heat_w", "housing_conductance_scale",
    "churning_oil_fraction", *HEAT_MODEL_OPTIONS, *HEAT_LAW_OPTIONS,
)  # fmt: skip


def _thermal_option_names(given: dict[str, Any]) -> tuple[str, ...]:
    """The calibrated options a ``stiffness_curve`` call takes beyond its
    named parameters: the thermal options in the thermal mode, none in the
    others (they do not act there)."""
    return THERMAL_OPTIONS if given.get("mode") == "thermal" else ()


@renamed_kwargs(moment_nmm=("moment_n_m", lambda v: float(v) / 1000.0))
@takes_calibrated(_thermal_option_names)
def stiffness_curve(
    bearing: Bearing,
    speeds_rpm: ArrayLike,
    axial_n: float = 0.0,
    radial_n: float = 0.0,
    moment_n_m: float = 0.0,
    *,
    mode: StiffnessMode = "speed",
    effects: Optional[Sequence[str]] = None,
    raceway_control: RacewayControl = "outer",
    misalignment_rad: Optional[float] = 0.0,
    progress: Optional[Callable[[int, int], None]] = None,
    **thermal_options: Any,
) -> polars.DataFrame:
    """Bearing stiffness against speed, solved in parallel (rayon) with the
    GIL released; deterministic for any thread count.

    ``mode="speed"``: the high-speed quasi-static model at each speed.
    ``mode="constant"``: the zero-speed (static) stiffness repeated at every
    speed (seed A Fig. 11, case 1).
    ``mode="thermal"``: the coupled thermo-mechanical state at each speed
    (seed A Fig. 11, case 3; see ``thermobear.thermal.thermal_stiffness_curve``
    for the extra columns and ``thermal_options``: ``lubricant``,
    ``lubrication_factor_f0``, ``spin_friction_coefficient``, ``oil_air_temperature_c``,
    ``ambient_temperature_c``, ``housing_material``).
    ``progress(done, total)`` is called between chunks; Ctrl-C interrupts.
    Columns: ``speed_rpm``; the entries of the full 5x5 tangent stiffness
    ``k_xx_n_per_m``, ``k_yy_n_per_m``, ``k_zz_n_per_m``, ``k_xz_n_per_m``,
    ``k_rxrx_n_m_per_rad``, ``k_ryry_n_m_per_rad``, ``k_xry_n_per_rad`` (the
    physically complete stiffness); seed A's simplified series formula
    ``radial_stiffness_seed_n_per_m`` and ``axial_stiffness_seed_n_per_m``
    (it leaves out how the contact angles change under load and speed, so it
    falls much less with speed than ``k_xx``); ``radial_displacement_um``,
    ``axial_displacement_um``, ``tilt_rad``; extreme contact angles in
    degrees and loads in N. ``moment_n_m`` is in N m (the older
    ``moment_nmm`` in N mm is deprecated and converted). A
    [`CalibratedModel`][thermobear.CalibratedModel] stands for its bearing
    (its thermal options act in the thermal mode only).
    """
    val.choice("mode", mode, ("speed", "constant", "thermal"))
    if mode == "thermal":
        if val.real("moment_n_m", moment_n_m) != 0.0:
            raise ConfigError(
                f"invalid moment_n_m = {moment_n_m}: "
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
            + val.did_you_mean(sorted(thermal_options)[0], THERMAL_OPTIONS)
        )
    return _mechanical_stiffness_curve(
        bearing,
        speeds_rpm,
        (
            val.real("axial_n", axial_n),
            val.real("radial_n", radial_n),
            val.real("moment_n_m", moment_n_m),
        ),
        mode,
        effects,
        raceway_control,
        misalignment_rad,
        progress,
    )


def _mechanical_stiffness_curve(
    bearing: Bearing,
    speeds_rpm: ArrayLike,
    loads: tuple[float, float, float],
    mode: StiffnessMode,
    effects: Optional[Sequence[str]],
    raceway_control: RacewayControl,
    misalignment_rad: Optional[float],
    progress: Optional[Callable[[int, int], None]],
) -> polars.DataFrame:
    """The speed and constant modes of ``stiffness_curve``: the native sweep
    (``loads``: axial N, radial N, moment N m), its columns renamed; a speed
    that fails keeps the finished rows on the error."""
    import polars as pl

    speeds = val.reals("speeds_rpm", speeds_rpm, 0.0)  # checked before "constant" drops them
    native_speeds = np.zeros_like(speeds) if mode == "constant" else speeds
    tilt = bearing._tilt(misalignment_rad)
    plausibility.check_speeds(speeds, bearing._pitch_mm(), None)

    def frame(cols: Any, at: Any) -> polars.DataFrame:
        df = pl.DataFrame(renamed_columns(dict(cols)))
        s = pl.Series("speed_rpm", np.asarray(at, dtype=float))
        return df.with_columns(s).with_columns(pl.lit(mode).alias("mode"))

    try:
        cols = _native.stiffness_curve(
            bearing._b,
            native_speeds,
            *loads,
            _effects_arg(effects),
            val.choice("raceway_control", raceway_control, ("outer", "inner")),
            tilt,
            progress,
        )
    except ThermobearError as e:
        speed_frames(e, speeds, frame)
        raise
    _refuse_past_the_groove(bearing, cols, native_speeds, loads, (effects, raceway_control, tilt))
    return frame(cols, speeds)


def _refuse_past_the_groove(
    bearing: Bearing,
    cols: Any,
    speeds: np.ndarray,
    loads: tuple[float, float, float],
    options: tuple[Any, ...],
) -> None:
    """The contact check of ``solve`` on every row of a curve: a
    [`ConfigError`][thermobear.ConfigError] for the first speed whose
    contact reaches past the groove (``plausibility.rows_past_the_groove``)."""
    n = len(speeds)
    points = {
        k: np.full(n, x) for k, x in zip(("axial_n", "radial_n", "moment_n_m"), loads, strict=True)
    }
    keys = ("effects", "raceway_control", "misalignment_rad")
    past = plausibility.rows_past_the_groove(
        bearing, cols, {**points, "speed_rpm": speeds}, dict(zip(keys, options, strict=True))
    )
    if past:
        i = min(past)
        raise ConfigError(f"{past[i]} (speeds_rpm[{i}] of the curve)")


@renamed_kwargs(spin_friction="spin_friction_coefficient")
def thermal_stiffness_curve(
    bearing: Bearing,
    speeds_rpm: ArrayLike,
    axial_n: float = 0.0,
    radial_n: float = 0.0,
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
    progress: Optional[Callable[[int, int], None]] = None,
    **heat: Any,
) -> polars.DataFrame:
    """The coupled state at every speed (parallel, deterministic): the
    stiffness columns of [`thermobear.stiffness_curve`][thermobear.stiffness_curve] plus
    ``shaft/inner_ring/ball/outer_ring/housing_temperature_c``, ``heat_w``
    (and ``load_/viscous_/spin_heat_w``), ``radial_thermal_offset_um``,
    ``axial_thermal_offset_um``, ``ball_growth_um``, ``extra_heat_w``,
    ``churning_heat_w`` (ball drag heat at ``churning_oil_fraction``, a volume
    fraction 0..1; see [`thermal_state`][thermobear.thermal_state]), ``centrifugal_expansion_um``,
    ``thermal_iterations``. ``heat``: the heat-model keywords of
    [`thermal_state`][thermobear.thermal_state] (``heat_model``, ``lubrication``, ``skf_series``,
    ``sliding_friction_ehl``, ``replenishment_krs``, ``seal_moment_n_m``) and
    an extra heat with its own speed law (``unknown_heat_linear_w``,
    ``unknown_heat_quadratic_w``, ``unknown_heat_reference_rpm``: see
    [`thermal_state`][thermobear.thermal_state]; each speed then solves with its
    own extra heat, one speed at a time)."""
    import polars as pl

    speeds = val.reals("speeds_rpm", speeds_rpm, 0.0)
    law = pop_heat_law(heat)
    settings = _model_kwargs(
        lubricant,
        lubrication_factor_f0,
        spin_friction_coefficient,
        oil_air_temperature_c,
        ambient_temperature_c,
        housing_material,
        raceway_control,
        misalignment_rad,
        extra_heat_w,
        housing_conductance_scale,
        churning_oil_fraction,
        **heat,
    )
    plausibility.check_misalignment(settings["misalignment_rad"], plausibility._geometry(bearing))
    plausibility.check_speeds(speeds, bearing._pitch_mm(), settings["lubrication"])
    top = float(speeds.max()) if speeds.size else 0.0
    check_supply(
        plausibility._geometry(bearing), settings["lubrication"], settings["oil_supply"], top
    )

    def frame(cols: Any, at: Any) -> polars.DataFrame:
        df = pl.DataFrame(renamed_columns(dict(cols)))
        s = pl.Series("speed_rpm", np.asarray(at, dtype=float))
        return df.with_columns(s).with_columns(pl.lit("thermal").alias("mode"))

    fa, fr = val.real("axial_n", axial_n), val.real("radial_n", radial_n)
    eff = _effects_arg(effects)
    if has_heat_law(law):  # each speed with its own extra heat
        extra = float(settings["extra_heat_w"]) + heat_law_w(law, speeds)
        parts = []
        for i, (n, h) in enumerate(zip(speeds.tolist(), extra.tolist(), strict=True)):
            one = {**settings, "extra_heat_w": h}
            parts.append(_curve(bearing, np.array([n]), fa, fr, eff, one, frame, None))
            if progress is not None:
                progress(i + 1, speeds.size)
        return pl.concat(parts)
    return _curve(bearing, speeds, fa, fr, eff, settings, frame, progress)


def _curve(
    bearing: Bearing, speeds: Any, fa: float, fr: float, eff: Any, settings: Any, frame: Any,
    progress: Any,
) -> polars.DataFrame:  # fmt: skip
    """One native thermal stiffness curve as a frame; a failure carries
    the speeds that finished (``speed_frames``)."""
    try:
        cols = _native.thermal_stiffness_curve(
            bearing._b, speeds, fa, fr, eff, settings, progress=progress
        )
    except ThermobearError as e:
        speed_frames(e, speeds, frame)
        raise
    return frame(cols, speeds)
