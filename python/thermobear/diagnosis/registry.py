"""The effects registry (``thermobear.effects()``) and the bearing's
calibratable inputs with their physical bounds and baseline values."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Optional

from .._types import EffectKind
from ..errors import ConfigError
from ..thermal.oil_supply import SUPPLY_OPTIONS

if TYPE_CHECKING:
    import polars

# Parameter candidates: (name, option, unit, lo, hi, offset?, description).
# Bounds: f0 0.5-6 spans Palmgren's f0 for oil-air / oil-mist (1-2) up to
# oil bath and jet (4-6) (Harris & Kotzalas, Rolling Bearing Analysis,
# table of f0); spin friction coefficient 0-0.3 (boundary to dry contact);
# oil-air and ambient temperatures +-10/+20 K (cooling-air supply drift);
# extra bearing heat 0-100 W (up to about the whole friction heat of a
# 40-45 mm angular-contact bearing at 18000 rpm, the seed B magnetic-pull
# friction being a fraction of it); housing-to-ambient conductance scale
# 0.1-10 (a decade either way of natural convection from the bare cylinder:
# an enclosed, insulated housing below, a finned or ventilated one or one
# conducting into the machine frame above; natural and slow forced air
# convection coefficients differ by about a decade, 5-10 vs 25-100 W/m^2K);
# churning oil volume fraction X of the cavity mixture 0-5 % (0: dry air;
# our assumed upper end for a jet-lubricated, partly flooded cavity -- an oil
# bath is the f0 range above; at 5 % a 7008C at 18,000 rpm dissipates
# ~90 W of ball drag, about half its total friction heat). With a
# lubrication method in the baseline (``lubrication="jet"`` ...) the f0 and X
# bounds are the method's (``thermobear.lubrication_defaults``,
# docs/concepts/physics.md §9); applied-load scales 0.7-1.3 (a load cell or
# a preload set by spring length or spacer grinding off by up to 30 %: the
# spread of preload measured on assembled spindles against the catalogue
# class is of that order; bounds are our assumption).
_PARAMETERS = (
    # (name, option, unit, lower, upper, offset?, role, description)
    ("lubrication_factor_f0", "lubrication_factor_f0", "1", 0.5, 6.0, False, "calibration",
     "viscous friction moment scale (Palmgren f0)"),
    ("spin_friction_coefficient", "spin_friction_coefficient", "1", 0.0, 0.3, False,
     "calibration",
     "spin friction coefficient mu_s (needs the spin_friction effect on)"),
    ("oil_air_temperature_offset_k", "oil_air_temperature_c", "K", -10.0, 20.0, True,
     "calibration", "oil-air (cooling) temperature differs from the assumed one"),
    ("ambient_temperature_offset_k", "ambient_temperature_c", "K", -10.0, 20.0, True,
     "calibration", "ambient temperature differs from the assumed one"),
    ("extra_heat_w", "extra_heat_w", "W", 0.0, 100.0, False, "effect",
     "extra heat at the bearing (e.g. magnetic-pull friction), split like rolling heat"),
    ("housing_conductance_scale", "housing_conductance_scale", "1", 0.1, 10.0, False, "effect",
     "housing-to-ambient conductance differs from the bare natural-convection cylinder"),
    ("churning_oil_fraction", "churning_oil_fraction", "1", 0.0, 0.05, False, "effect",
     "churning: drag of the balls in the oil-air mixture, ~ speed^3 (oil volume fraction X)"),
    ("axial_load_scale", "axial_load_scale", "1", 0.7, 1.3, False, "calibration",
     "applied axial load (preload) differs from the stated one by a factor"),
    ("radial_load_scale", "radial_load_scale", "1", 0.7, 1.3, False, "calibration",
     "applied radial load differs from the stated one by a factor"),
)  # fmt: skip

#: Bounds of a per-load-level scale (as the load scales above).
LOAD_SCALE_BOUNDS = (0.7, 1.3)

# Oil-supply candidates (docs/concepts/physics.md §9, eq. 9.10), offered
# when the baseline states a jet, oil-air or oil-mist flow; they replace the
# fixed drag fraction X of ``_PARAMETERS``. Bounds (our assumptions, argued
# in docs/concepts/diagnosis.md): the flow reaching the cavity 0.2-5 times
# the stated one -- a rig's flowmeter reads within a few per cent, but the
# stated flow is often the pump's setting shared by several outlets, and of
# a jet at DN above 1 million only part passes the air curtain the cage and
# balls drive (it depends on the jet's position and velocity, which the
# correlation does not carry); a factor 5 either way is 1.8x the drag at
# Parker's W^0.37. The
# speed exponent of the cavity fraction 0.5-1.5 about Parker's 1: a film
# thrown off at a rate proportional to the speed gives 1, a film thinned
# by centrifugal drainage against viscosity (Nusselt film, h ~ (nu Q /
# (omega^2 r))^(1/3)) 2/3; we allow half a unit either way of the published
# value. The exponent tilts X about 10,000 rpm (eq. 9.10), so it changes
# the drag's speed slope (about n^(3-e)) and the flow scale its level.
SUPPLY_PARAMETERS = (
    # (name/option, unit, lower, upper, null, description)
    ("oil_flow_scale", "1", 0.2, 5.0, 1.0,
     "oil flow reaching the cavity differs from the stated supply by a factor: drag ~ W^0.37 n^2"),
    ("cavity_fraction_speed_exponent", "1", 0.5, 1.5, 1.0,
     "cavity oil fraction falls with speed faster or slower than Parker's 1/n: drag ~ n^(3-e)"),
)  # fmt: skip

#: Supply keywords that state a flow (jet, oil-air, oil-mist): with one of
#: them the drag follows the supply and ``SUPPLY_PARAMETERS`` apply.
FLOW_KEYWORDS = ("oil_flow_cm3_per_min", "oil_volume_cm3_per_h")


def supply_given(options: dict) -> bool:
    """Whether ``options`` carry an oil-supply keyword (not None)."""
    return any(options.get(k) is not None for k in SUPPLY_OPTIONS)


#: The heat models (docs/concepts/physics.md §9): name -> description.
HEAT_MODELS = {
    "palmgren": "Palmgren load + viscous moments and spin heat (A-20..A-23): the seeds' model",
    "skf": "SKF-style four-term moment: rolling (inlet shear, starvation) + sliding + seal",
}

#: SKF-model inputs calibrated when the baseline uses it: mu_EHL 0.02-0.15
#: (the catalogue gives 0.04 synthetic, 0.05 mineral, 0.1 transmission
#: fluids; we widen by a half each way for additive packages) and K_rs
#: 1e-8-1.2e-7 (the catalogue's 3e-8 and 6e-8 for the two supply classes,
#: a factor 3 / 2 beyond them).
SKF_PARAMETERS = (
    ("sliding_friction_ehl", "1", 0.02, 0.15, "SKF full-film sliding coefficient mu_EHL"),
    ("replenishment_krs", "1", 1e-8, 1.2e-7, "SKF kinematic replenishment constant K_rs"),
)


#: ``affects`` of an effect that acts only in the spindle or rotor model.
NOT_IN_BEARING = "not in the single-bearing model"


_HOUSING_MATERIALS = ("aluminium", "cast-iron", "shaft-steel")


#: The default of each thermal option of a bearing model: a number, a name,
#: or None (left unset: thermal_state's own default).
_THERMAL_DEFAULTS: dict[str, Any] = {
    "lubricant": "e-drive ATF",
    "lubrication_factor_f0": 1.0,
    "spin_friction_coefficient": 0.05,
    "oil_air_temperature_c": 28.0,
    "ambient_temperature_c": 26.0,
    "housing_material": "aluminium",
    "raceway_control": "outer",
    "extra_heat_w": 0.0,
    "housing_conductance_scale": 1.0,
    "churning_oil_fraction": 0.0,
    "axial_load_scale": 1.0,
    "radial_load_scale": 1.0,
    "heat_model": "palmgren",
    "lubrication": None,
    "sliding_friction_ehl": None,
    "replenishment_krs": None,
    **SUPPLY_OPTIONS,
}

#: Options of the bearing spec that are not thermal_state keywords: they
#: scale the applied loads of the measured conditions.
LOAD_SCALE_OPTIONS = ("axial_load_scale", "radial_load_scale")


#: Effects that are switches and also have a calibratable coefficient:
#: name -> (option, unit, lower, upper); bounds as in ``_PARAMETERS``.
_SWITCH_COEFFICIENTS = {"spin_friction": ("spin_friction_coefficient", "1", 0.0, 0.3)}


#: Switches that are off in the default models (the rotor's default leaves
#: the magnetic pull out: its inputs are an assumption about the motor).
_OFF_BY_DEFAULT = ("unbalanced_magnetic_pull",)


def effect_registry(kind: Optional[EffectKind] = None) -> polars.DataFrame:
    """The effects registry (``thermobear.effects()``): one row per physical
    effect. ``name``; ``kind``: "switch" (a named effect, on when listed in
    ``effects=[...]``), "term" (an input whose ``off`` value leaves the
    term out, e.g. ``extra_heat_w`` = 0) or "model" (an alternative model of
    a term chosen by an option, e.g. ``heat_model:skf``,
    docs/concepts/physics.md §9); ``models``: the models it acts in
    (comma-joined: bearing, spindle, rotor); ``parameter``, ``unit``,
    ``lower``, ``upper``: the calibratable input and its physical bounds
    ("on", 0-1 for a plain switch); ``default``: its value in the default
    model; ``off``: the value without the effect; ``description``."""
    import polars as pl

    from .. import _native

    if kind not in (None, "switch", "term", "model"):
        raise ConfigError(f"invalid kind = {kind!r}: None, 'switch', 'term' or 'model'")
    rows = []
    for name, desc, models in _native.effects():
        on = 0.0 if name in _OFF_BY_DEFAULT else 1.0
        if name in _SWITCH_COEFFICIENTS:
            opt, unit, lo, hi = _SWITCH_COEFFICIENTS[name]
            rows.append(
                (name, "switch", ",".join(models), opt, unit, lo, hi,
                 float(_THERMAL_DEFAULTS[opt]) * on, 0.0, desc)
            )  # fmt: skip
        else:
            rows.append((name, "switch", ",".join(models), "on", "1", 0.0, 1.0, on, 0.0, desc))
    for name, opt, unit, lo, hi, _off, role, desc in _PARAMETERS:
        if role == "effect":
            null = float(_THERMAL_DEFAULTS[opt])
            rows.append((name, "term", "bearing", opt, unit, lo, hi, null, null, desc))
    for hm, desc in HEAT_MODELS.items():
        if hm != _THERMAL_DEFAULTS["heat_model"]:
            rows.append((f"heat_model:{hm}", "model", "bearing,spindle", "heat_model", "1", 0.0,
                         1.0, 0.0, 0.0, desc))  # fmt: skip
    df = pl.DataFrame(
        rows,
        schema=["name", "kind", "models", "parameter", "unit", "lower", "upper", "default",
                "off", "description"],
        orient="row",
    )  # fmt: skip
    return df if kind is None else df.filter(pl.col("kind") == kind)


#: Older option names of the model specs -> the current ones.
RENAMED_OPTIONS = {"spin_friction": "spin_friction_coefficient"}


def current_option_names(options: dict) -> None:
    """Rename older option names in ``options`` in place (each warns)."""
    from .._deprecation import warn_renamed

    for old, new in RENAMED_OPTIONS.items():
        if old in options:
            if new in options:
                raise TypeError(f"got both `{old}` (deprecated) and `{new}`; pass only `{new}`")
            warn_renamed(old, new, stacklevel=5)
            options[new] = options.pop(old)
