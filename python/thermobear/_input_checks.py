"""Plausibility of inputs: a bearing's geometry, its lubrication supply and
oil temperature, a gear pair's load, backlash, transmission error, damping
and speed.

Each check warns ([`PlausibilityWarning`][thermobear.PlausibilityWarning],
the result is still computed) past what real machines do, or refuses
([`ConfigError`][thermobear.ConfigError]) what no machine can be. The
figures are module constants; the docs page "Limits" gives the source of
each. The API and the command line run the same checks (the commands build
their bearings, heat calls and gear systems through the same functions).
"""

from __future__ import annotations

import math
from typing import Any, Mapping, Optional

from .errors import ConfigError
from .plausibility import warn

# ---------------------------------------------------------------- bearing geometry

#: Fewest balls of a single-row angular-contact bearing in the makers' tables.
MIN_BALLS_ANGULAR_CONTACT = 7
#: Largest diametral clearance of a deep-groove bearing as a share of its
#: ball diameter (the coarsest ISO 5753-1 group, C5, stays below 1 %).
MAX_CLEARANCE_PER_BALL_DIAMETER = 0.02


def check_bearing_geometry(geometry: Mapping[str, float], bearing_type: str) -> None:
    """Warn on a bearing whose build no maker offers: too few balls for an
    angular-contact bearing, a deep-groove clearance past the coarsest
    clearance group, rings narrower than the balls."""
    d = float(geometry["ball_diameter_mm"])
    z = int(geometry["ball_count"])
    bearing_type = bearing_type.replace("-", "_")
    if bearing_type == "angular_contact" and z < MIN_BALLS_ANGULAR_CONTACT:
        warn(
            f"ball_count = {z}: an angular-contact bearing has at least "
            f"{MIN_BALLS_ANGULAR_CONTACT} balls in the makers' tables (limits: docs page Limits)"
        )
    pd = float(geometry["diametral_clearance_mm"])
    if bearing_type == "deep_groove" and pd > MAX_CLEARANCE_PER_BALL_DIAMETER * d:
        warn(
            f"diametral_clearance_mm = {pd:g} is {pd / d:.1%} of the {d:g} mm ball diameter, "
            f"past the {MAX_CLEARANCE_PER_BALL_DIAMETER:.0%} that the coarsest clearance group "
            "(ISO 5753-1 C5) stays well within (limits: docs page Limits)"
        )
    width = float(geometry["width_mm"])
    if width < d:
        warn(
            f"width_mm = {width:g} is narrower than the {d:g} mm balls: the rings of a ball "
            "bearing are wider than its balls (limits: docs page Limits)"
        )


# ---------------------------------------------------------------- lubrication supply

#: Largest jet oil flow per mm of bore [cm^3/min per mm].
MAX_JET_FLOW_CM3_PER_MIN_PER_MM_BORE = 100.0
#: Plausible grease fill of the free volume (share), outside very slow running.
GREASE_FILL_RANGE = (0.1, 0.5)
#: n dm [mm rpm] below which catalogues fill a bearing's free volume completely.
FULL_GREASE_FILL_MAX_NDM_MM_RPM = 50_000.0


def check_supply(
    geometry: Mapping[str, float],
    lubrication: Optional[str],
    supply: Mapping[str, Any],
    speed_rpm: float,
) -> None:
    """Warn on a supply keyword (``supply``: the checked supply keywords,
    None where not given) no machine runs with: no oil reaching a jet- or
    oil-air lubricated bearing, a jet flow far past a bearing's size, an
    oil-air supply without air, an oil level above the whole bearing, a
    grease fill outside the catalogue range."""
    flow = supply.get("oil_flow_cm3_per_min")
    if flow is not None and lubrication == "jet":
        top = MAX_JET_FLOW_CM3_PER_MIN_PER_MM_BORE * float(geometry["bore_mm"])
        if flow == 0.0:
            warn(
                "oil_flow_cm3_per_min = 0 with lubrication='jet': no oil reaches the bearing, "
                "which then runs dry; the friction model assumes a lubricated contact (the heat "
                "is that of a lubricated bearing without ball drag)"
            )
        elif flow > top:
            warn(
                f"oil_flow_cm3_per_min = {flow:g} is past the {top:.3g} cm^3/min "
                f"({MAX_JET_FLOW_CM3_PER_MIN_PER_MM_BORE:g} per mm of the {geometry['bore_mm']:g} "
                "mm bore) that jet-lubricated bearings take (limits: docs page Limits)"
            )
    if lubrication in ("oil-air", "oil-mist"):
        oil, air = supply.get("oil_volume_cm3_per_h"), supply.get("air_flow_l_per_min")
        if oil == 0.0:
            warn(
                f"oil_volume_cm3_per_h = 0 with lubrication={lubrication!r}: no oil reaches the "
                "bearing, which then runs dry; the friction model assumes a lubricated contact"
            )
        if air == 0.0:
            warn(
                f"air_flow_l_per_min = 0 with lubrication={lubrication!r}: no air carries the oil "
                "to the contacts (the model takes the air flow only into the drag's Reynolds "
                "number, so the heat hardly changes)"
            )
    level = supply.get("oil_level_mm")
    if level is not None and lubrication == "oil-bath":
        top = (
            0.5 * (geometry["pitch_diameter_mm"] + geometry["ball_diameter_mm"])
            + 0.5 * (geometry["outer_diameter_mm"])
        )
        if level > top:
            warn(
                f"oil_level_mm = {level:g} is above the top of the bearing ({top:.3g} mm above "
                "the lowest point of the lowest ball): the bearing is submerged, and an oil bath "
                "keeps its level at about the middle of the lowest ball (limits: docs page Limits)"
            )
    fill = supply.get("grease_fill_fraction")
    if fill is not None and lubrication == "grease":
        lo, hi = GREASE_FILL_RANGE
        ndm = abs(speed_rpm) * float(geometry["pitch_diameter_mm"])
        slow = ndm <= FULL_GREASE_FILL_MAX_NDM_MM_RPM
        if fill < lo or (fill > hi and not slow):
            warn(
                f"grease_fill_fraction = {fill:g} is outside the {lo:g}-{hi:g} of the free volume "
                "that bearings are filled with (completely only below n dm = "
                f"{FULL_GREASE_FILL_MAX_NDM_MM_RPM:g} mm rpm); note that the fill does not enter "
                "the heat model (grease has no steady drag there): the heat is the same for any "
                "fill (limits: docs page Limits)"
            )


# ---------------------------------------------------------------- oil temperature

#: Pour points of the lubricant presets [C] (their data sheets; the native
#: model refuses a temperature below them).
POUR_POINTS_C = {"isovg32": -30.0, "isovg68": -24.0, "edriveatf": -45.0}
#: Aliases of the presets (as the native model accepts them).
_ALIASES = {"vg32": "isovg32", "vg68": "isovg68", "atf": "edriveatf"}
#: Margin above the pour point [K] within which the oil warns.
POUR_POINT_MARGIN_K = 10.0


def check_oil_temperature(lubricant: str, oil_temperature_c: float) -> None:
    """Warn on an oil temperature within ``POUR_POINT_MARGIN_K`` of the
    lubricant's pour point (the native model refuses one below it)."""
    key = "".join(c for c in str(lubricant) if c.isascii() and c.isalnum()).lower()
    pour = POUR_POINTS_C.get(_ALIASES.get(key, key))
    if pour is not None and pour <= oil_temperature_c < pour + POUR_POINT_MARGIN_K:
        warn(
            f"oil_temperature_c = {oil_temperature_c:g} is within {POUR_POINT_MARGIN_K:g} K of "
            f"the pour point of {lubricant} ({pour:g} C): wax makes the oil thicker than the "
            "viscosity law extrapolated from 40 and 100 C gives, and a bearing turning at speed "
            "does not stay this cold (limits: docs page Limits)"
        )


# ---------------------------------------------------------------- gears

#: Largest unit load Ft / (b m_n) of a gear mesh [N/mm^2].
MAX_GEAR_UNIT_LOAD_N_PER_MM2 = 650.0
#: Largest total backlash as a share of the normal module (warning).
MAX_BACKLASH_PER_MODULE = 0.25
#: Largest damping ratio of a mesh or a bearing support (warning).
MAX_DAMPING_RATIO = 0.3
#: Largest pitch-line velocity of a gear pair [m/s].
MAX_PITCH_LINE_VELOCITY_M_PER_S = 200.0


def coarsest_pitch_deviation_um(normal_module_mm: float, pitch_diameter_mm: float) -> float:
    """The single pitch tolerance of ISO 1328-1's coarsest accuracy grade
    (12) [um]: 0.3 (m_n + 0.4 sqrt(d)) + 4 at grade 5, times sqrt(2) a grade."""
    grade5 = 0.3 * (normal_module_mm + 0.4 * math.sqrt(pitch_diameter_mm)) + 4.0
    return grade5 * 2.0 ** ((12 - 5) / 2.0)


def check_gear_system(geometry: Mapping[str, float], params: Mapping[str, float]) -> None:
    """Refuse a backlash wider than the tooth pitch; warn on a torque, a
    backlash, a transmission error or a damping ratio past what gear pairs
    run with (``geometry``: the pair's, mm; ``params``: the system's)."""
    mn = float(geometry["normal_module_mm"])
    mt = float(geometry["transverse_module_mm"])
    b = float(params["half_backlash_um"])
    if 2.0 * b * 1e-3 >= math.pi * mt:
        raise ConfigError(
            f"invalid half_backlash_um = {b:g}: the total backlash 2b must be less than the "
            f"transverse pitch pi m_t = {math.pi * mt:.3g} mm (a tooth and a tooth space): "
            "past it no tooth is left"
        )
    if 2.0 * b * 1e-3 > MAX_BACKLASH_PER_MODULE * mn:
        warn(
            f"half_backlash_um = {b:g}: a total backlash of {2e-3 * b:.3g} mm is past "
            f"{MAX_BACKLASH_PER_MODULE:g} of the normal module ({mn:g} mm), several times what "
            "gear pairs are made with (limits: docs page Limits)"
        )
    torque = float(params["torque_n_m"])
    r_mm = float(geometry["pinion_pitch_radius_mm"])
    unit = abs(torque) * 1e3 / r_mm / (float(geometry["face_width_mm"]) * mn)
    if unit > MAX_GEAR_UNIT_LOAD_N_PER_MM2:
        warn(
            f"torque_n_m = {torque:g} gives a unit load Ft / (b m_n) of {unit:.3g} N/mm^2, past "
            f"the {MAX_GEAR_UNIT_LOAD_N_PER_MM2:g} N/mm^2 at which case-hardened teeth break "
            "(ISO 6336; limits: docs page Limits)"
        )
    d = 2.0 * max(r_mm, float(geometry["gear_pitch_radius_mm"]))
    te = abs(float(params["te_amplitude_um"]))
    top = coarsest_pitch_deviation_um(mn, d)
    if te > top:
        warn(
            f"te_amplitude_um = {te:g} is past the {top:.3g} um single pitch tolerance of "
            "ISO 1328-1's coarsest grade (12) for this pair (limits: docs page Limits)"
        )
    for name in ("mesh_damping_ratio", "bearing_damping_ratio"):
        zeta = float(params[name])
        if zeta > MAX_DAMPING_RATIO:
            warn(
                f"{name} = {zeta:g} is past {MAX_DAMPING_RATIO:g}: measured damping ratios of "
                "gear meshes are 0.03-0.17, of rolling bearing supports lower still "
                "(limits: docs page Limits)"
            )


def check_gear_speed(geometry: Mapping[str, float], speed_rpm: float) -> None:
    """Warn on a pinion speed whose pitch-line velocity is past what gear
    pairs run at."""
    v = abs(speed_rpm) * 2.0 * math.pi / 60.0 * float(geometry["pinion_pitch_radius_mm"]) * 1e-3
    if v > MAX_PITCH_LINE_VELOCITY_M_PER_S:
        warn(
            f"speed_rpm = {speed_rpm:g} gives a pitch-line velocity of {v:.3g} m/s, past the "
            f"{MAX_PITCH_LINE_VELOCITY_M_PER_S:g} m/s of the fastest (turbo) gear pairs "
            "(limits: docs page Limits)"
        )
