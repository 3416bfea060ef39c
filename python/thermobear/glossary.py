"""The glossary: every physical quantity of the package once, with its one
name, unit and symbol.

A name ends in its unit (``_n`` newton, ``_n_m`` newton metre, ``_m``,
``_mm``, ``_um``, ``_c`` deg C, ``_k`` kelvin difference, ``_w``, ``_rpm``,
``_hz``, ``_s``, ``_rad``, ``_deg``, ``_n_per_m``, ``_n_m_per_rad``,
``_n_per_rad``, ``_cst`` mm^2/s, ``_w_per_m2_k`` W/(m^2 K)). Every public
parameter, result attribute and frame column that carries a unit is one of
these names. The same table is docs/glossary.md (a test keeps the two equal).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, NamedTuple

if TYPE_CHECKING:
    import polars


class Entry(NamedTuple):
    """One quantity: unit, symbol (as in the physics docs) and description."""

    unit: str
    symbol: str
    description: str


#: (name, unit, symbol, description), in the order of docs/glossary.md.
_ROWS: tuple[tuple[str, str, str, str], ...] = (
    ("speed_rpm", "rpm", "n", "shaft (inner-ring) speed"),
    ("speeds_rpm", "rpm", "n", "shaft speeds of a sweep"),
    ("axial_n", "N", "F_a", "external axial load on a single bearing"),
    ("radial_n", "N", "F_r", "external radial load on a bearing (along x)"),
    ("moment_n_m", "N m", "M", "tilting moment on the inner ring (about y)"),
    ("preload_n", "N", "F_p", "axial preload of a spindle's bearing pairs (stated)"),
    ("preloads_n", "N", "F_p", "preloads of a spindle grid"),
    ("operating_preload_n", "N", "F_p,op", "front pair's preload at the operating state"),
    ("rear_operating_preload_n", "N", "F_p,op,rear", "rear pair's preload at the operating state"),
    ("effective_preload_n", "N", "F_p,eff", "stated preload times the preload scale"),
    ("optimal_preload_n", "N", "F_p,opt", "preload with the least total radial displacement"),
    (
        "compensation_preload_n",
        "N",
        "dF_p",
        "preload change from the axial growth compressing the spring (k_s u)",
    ),
    (
        "solved_preload_change_n",
        "N",
        "dF_p",
        "preload change of the coupled solve (spring in series)",
    ),
    ("radial_load_n", "N", "F_r", "working radial load at the spindle nose"),
    ("radial_loads_n", "N", "F_r", "radial loads of a spindle grid"),
    ("load_n", "N", "Q", "contact load of one ball"),
    ("inner_load_n", "N", "Q_i", "inner-raceway contact load of a ball"),
    ("outer_load_n", "N", "Q_o", "outer-raceway contact load of a ball"),
    ("inner_load_max_n", "N", "Q_i,max", "largest inner-raceway contact load"),
    ("outer_load_max_n", "N", "Q_o,max", "largest outer-raceway contact load"),
    ("centrifugal_force_n", "N", "F_c", "centrifugal force on one ball"),
    ("gyroscopic_moment_n_m", "N m", "M_g", "gyroscopic moment on one ball"),
    ("magnetic_pull_n", "N", "F_ump", "static unbalanced magnetic pull of the motor"),
    (
        "front_pair_radial_x_n",
        "N",
        "F_x,front",
        "radial load the front pair carries along x (nose load side)",
    ),
    (
        "front_pair_radial_y_n",
        "N",
        "F_y,front",
        "radial load the front pair carries along y (magnetic pull side)",
    ),
    ("rear_pair_radial_x_n", "N", "F_x,rear", "radial load the rear pair carries along x"),
    ("rear_pair_radial_y_n", "N", "F_y,rear", "radial load the rear pair carries along y"),
    (
        "lift_off_force_n",
        "N",
        "F_lo",
        "axial force at which a preloaded pair's unloaded bearing lifts off",
    ),
    ("torque_n_m", "N m", "T", "input torque on the pinion (negative: coast)"),
    ("torques_n_m", "N m", "T", "input torques of a regime map"),
    ("input_torque_n_m", "N m", "T", "input torque of a gear pair's table"),
    ("seal_moment_n_m", "N m", "M_seal", "seal friction moment (SKF model)"),
    (
        "radial_stiffness_seed_n_per_m",
        "N/m",
        "K_r,seed",
        "radial stiffness by seed A's simplified series formula",
    ),
    (
        "axial_stiffness_seed_n_per_m",
        "N/m",
        "K_a,seed",
        "axial stiffness by seed A's simplified series formula",
    ),
    ("k_xx_n_per_m", "N/m", "K_xx", "radial entry of the full 5x5 tangent stiffness"),
    ("k_yy_n_per_m", "N/m", "K_yy", "second radial entry of the full 5x5 tangent stiffness"),
    ("k_zz_n_per_m", "N/m", "K_zz", "axial entry of the full 5x5 tangent stiffness"),
    ("k_xz_n_per_m", "N/m", "K_xz", "radial-axial coupling entry of the full tangent stiffness"),
    ("k_rxrx_n_m_per_rad", "N m/rad", "K_rxrx", "tilt entry about x of the full tangent stiffness"),
    ("k_ryry_n_m_per_rad", "N m/rad", "K_ryry", "tilt entry about y of the full tangent stiffness"),
    (
        "k_xry_n_per_rad",
        "N/rad",
        "K_xry",
        "radial-tilt coupling entry of the full tangent stiffness",
    ),
    (
        "k_xx_isothermal_n_per_m",
        "N/m",
        "K_xx,iso",
        "radial entry of the full tangent stiffness without thermal effects",
    ),
    (
        "support_radial_stiffness_n_per_m",
        "N/m",
        "k_r,shaft",
        "radial support stiffness of one shaft (all its bearings)",
    ),
    (
        "support_axial_stiffness_n_per_m",
        "N/m",
        "k_a,shaft",
        "axial support stiffness of one shaft (all its bearings)",
    ),
    ("mesh_stiffness_n_per_m", "N/m", "k_m", "gear mesh stiffness along the normal deflection"),
    (
        "normal_stiffness_n_per_m",
        "N/m",
        "k_n",
        "gear mesh stiffness along the normal deflection (table column)",
    ),
    ("transverse_stiffness_n_per_m", "N/m", "k_t", "gear mesh stiffness in the transverse plane"),
    (
        "mesh_stiffness_mean_n_per_m",
        "N/m",
        "k_m,mean",
        "mean gear mesh stiffness over a mesh period",
    ),
    ("spring_rate_n_per_um", "N/um", "k_s", "preload spring rate"),
    ("radial_displacement_um", "um", "delta_r", "radial displacement of the inner ring"),
    ("axial_displacement_um", "um", "delta_a", "axial displacement of the inner ring"),
    ("tilt_rad", "rad", "theta", "tilt of the inner ring"),
    ("misalignment_rad", "rad", "theta_0", "inner-ring tilt held fixed (None: free)"),
    (
        "max_contact_pressure_mpa",
        "MPa",
        "p_0,lim",
        "plausibility limit: maximum Hertz contact pressure (ISO 76 static limit)",
    ),
    ("max_misalignment_rad", "rad", "theta_lim", "plausibility limit: inner-ring tilt"),
    (
        "youngs_modulus_mpa",
        "MPa",
        "E",
        "Young's modulus of the gear material (seed A table, N/mm^2)",
    ),
    (
        "max_ndm_grease_mm_rpm",
        "mm rpm",
        "(n dm)_lim",
        "plausibility limit: speed factor n dm, grease",
    ),
    (
        "max_ndm_oil_bath_mm_rpm",
        "mm rpm",
        "(n dm)_lim",
        "plausibility limit: speed factor n dm, oil bath",
    ),
    (
        "max_ndm_oil_mist_mm_rpm",
        "mm rpm",
        "(n dm)_lim",
        "plausibility limit: speed factor n dm, oil mist",
    ),
    (
        "max_ndm_oil_air_mm_rpm",
        "mm rpm",
        "(n dm)_lim",
        "plausibility limit: speed factor n dm, oil-air",
    ),
    (
        "max_ndm_jet_mm_rpm",
        "mm rpm",
        "(n dm)_lim",
        "plausibility limit: speed factor n dm, oil jet",
    ),
    (
        "mechanical_radial_displacement_um",
        "um",
        "delta_r,mech",
        "radial displacement along the load (+ with it), cold geometry at speed",
    ),
    (
        "thermal_radial_displacement_um",
        "um",
        "delta_r,th",
        "radial thermal displacement of the front bearing",
    ),
    (
        "total_radial_displacement_um",
        "um",
        "delta_r,tot",
        "mechanical plus thermal radial displacement",
    ),
    (
        "min_radial_displacement_um",
        "um",
        "delta_r,min",
        "least total radial displacement over the preloads",
    ),
    ("spring_compression_um", "um", "u_s", "compression of the preload spring"),
    ("axial_growth_um", "um", "u_a", "axial thermal growth of the spindle shaft"),
    ("ball_growth_um", "um", "dD", "thermal growth of the ball diameter"),
    (
        "rear_thermal_radial_displacement_um",
        "um",
        "delta_r,th,rear",
        "radial thermal displacement of the rear bearing",
    ),
    (
        "front_axial_thermal_displacement_um",
        "um",
        "delta_a,th,front",
        "axial thermal offset of the front bearing's groove centres (positive: more interference)",
    ),
    (
        "rear_axial_thermal_displacement_um",
        "um",
        "delta_a,th,rear",
        "axial thermal offset of the rear bearing's groove centres (positive: more interference)",
    ),
    (
        "front_inner_groove_centre_um",
        "um",
        "u_ic,front",
        "radial thermal growth of the front inner groove centre",
    ),
    (
        "front_outer_groove_centre_um",
        "um",
        "u_oc,front",
        "radial thermal growth of the front outer groove centre",
    ),
    (
        "rear_inner_groove_centre_um",
        "um",
        "u_ic,rear",
        "radial thermal growth of the rear inner groove centre",
    ),
    (
        "rear_outer_groove_centre_um",
        "um",
        "u_oc,rear",
        "radial thermal growth of the rear outer groove centre",
    ),
    ("rear_ball_growth_um", "um", "dD,rear", "thermal growth of the rear bearing's ball diameter"),
    (
        "inner_contact_angle_isothermal_deg",
        "deg",
        "alpha_i,iso",
        "inner contact angle without thermal effects",
    ),
    (
        "outer_contact_angle_isothermal_deg",
        "deg",
        "alpha_o,iso",
        "outer contact angle without thermal effects",
    ),
    (
        "inner_load_max_isothermal_n",
        "N",
        "Q_i,max,iso",
        "largest inner-raceway contact load without thermal effects",
    ),
    (
        "outer_load_max_isothermal_n",
        "N",
        "Q_o,max,iso",
        "largest outer-raceway contact load without thermal effects",
    ),
    (
        "film_coefficient_w_per_m2_k",
        "W/(m^2 K)",
        "h",
        "convection film coefficient of a thermal-network link",
    ),
    (
        "temperature_difference_k",
        "K",
        "dT_h",
        "temperature difference across a natural-convection link",
    ),
    (
        "axial_position_mm",
        "mm",
        "z",
        "axial position along the spindle (0: front pair centre, towards the rear)",
    ),
    ("radial_position_mm", "mm", "r", "radial position from the spindle axis"),
    (
        "radial_thermal_offset_um",
        "um",
        "dr_th",
        "radial thermal offset of the groove curvature centres",
    ),
    (
        "axial_thermal_offset_um",
        "um",
        "da_th",
        "axial thermal offset of the groove curvature centres",
    ),
    ("centrifugal_expansion_um", "um", "u_c", "centrifugal expansion of the inner ring"),
    ("inner_deflection_um", "um", "delta_i", "inner contact deflection of a ball"),
    ("outer_deflection_um", "um", "delta_o", "outer contact deflection of a ball"),
    ("runout_um", "um", "e", "shaft runout seen by a vibration probe"),
    ("inner_semi_major_mm", "mm", "a_i", "semi-major axis of the inner contact ellipse"),
    ("outer_semi_major_mm", "mm", "a_o", "semi-major axis of the outer contact ellipse"),
    ("ball_diameter_mm", "mm", "D", "ball diameter"),
    ("pitch_diameter_mm", "mm", "d_m", "pitch diameter"),
    ("diametral_clearance_mm", "mm", "P_d", "diametral clearance"),
    ("bore_mm", "mm", "d", "bore diameter"),
    ("outer_diameter_mm", "mm", "D_o", "outside diameter"),
    ("width_mm", "mm", "B", "bearing width"),
    ("free_contact_angle_deg", "deg", "alpha_0", "free (unloaded) contact angle"),
    ("contact_angle_deg", "deg", "alpha", "contact angle of a raceway contact"),
    ("inner_contact_angle_deg", "deg", "alpha_i", "inner contact angle (mean over the balls)"),
    ("outer_contact_angle_deg", "deg", "alpha_o", "outer contact angle (mean over the balls)"),
    ("inner_contact_angle_max_deg", "deg", "alpha_i,max", "largest inner contact angle"),
    ("inner_contact_angle_min_deg", "deg", "alpha_i,min", "smallest inner contact angle"),
    ("outer_contact_angle_max_deg", "deg", "alpha_o,max", "largest outer contact angle"),
    ("outer_contact_angle_min_deg", "deg", "alpha_o,min", "smallest outer contact angle"),
    ("azimuth_deg", "deg", "psi", "azimuth of a ball (0: direction of the radial load)"),
    ("attitude_angle_deg", "deg", "beta", "attitude angle of a ball's spin axis"),
    ("orbit_speed_rpm", "rpm", "n_c", "orbit speed of a ball"),
    ("spin_speed_rpm", "rpm", "n_s", "spin speed of a ball"),
    ("cage_speed_rpm", "rpm", "n_c", "cage speed"),
    ("temperature_c", "C", "T", "temperature of a node"),
    ("shaft_temperature_c", "C", "Ts", "shaft temperature"),
    (
        "inner_contact_temperature_c",
        "C",
        "Tci",
        "temperature of the inner ring's contact with the shaft",
    ),
    ("inner_ring_temperature_c", "C", "Ti", "inner raceway temperature"),
    ("ball_temperature_c", "C", "Tb", "ball temperature"),
    ("outer_ring_temperature_c", "C", "To", "outer raceway temperature"),
    (
        "outer_contact_temperature_c",
        "C",
        "Tco",
        "temperature of the outer ring's contact with the housing",
    ),
    ("housing_temperature_c", "C", "Th", "housing temperature"),
    ("oil_air_temperature_c", "C", "Tog", "oil-air (cooling) supply temperature"),
    ("ambient_temperature_c", "C", "Ta", "ambient temperature"),
    ("oil_temperature_c", "C", "T_oil", "temperature the oil's viscosity and density are taken at"),
    ("initial_temperature_c", "C", "T_0", "uniform start temperature of a transient"),
    (
        "front_shaft_temperature_c",
        "C",
        "Ts,front",
        "spindle shaft temperature at the front bearings",
    ),
    ("rear_shaft_temperature_c", "C", "Ts,rear", "spindle shaft temperature at the rear bearings"),
    ("rotor_temperature_c", "C", "T_rotor", "motor rotor temperature"),
    ("stator_temperature_c", "C", "T_stator", "motor stator temperature"),
    ("sleeve_temperature_c", "C", "T_sleeve", "cooling sleeve temperature"),
    ("cooling_water_temperature_c", "C", "T_water", "cooling water temperature"),
    ("front_inner_ring_temperature_c", "C", "Ti,front", "front bearing inner raceway temperature"),
    ("front_ball_temperature_c", "C", "Tb,front", "front bearing ball temperature"),
    ("front_outer_ring_temperature_c", "C", "To,front", "front bearing outer raceway temperature"),
    ("rear_inner_ring_temperature_c", "C", "Ti,rear", "rear bearing inner raceway temperature"),
    ("rear_ball_temperature_c", "C", "Tb,rear", "rear bearing ball temperature"),
    ("rear_outer_ring_temperature_c", "C", "To,rear", "rear bearing outer raceway temperature"),
    ("front_housing_temperature_c", "C", "Th,front", "housing temperature at the front bearings"),
    ("rear_housing_temperature_c", "C", "Th,rear", "housing temperature at the rear bearings"),
    ("temperature_change_k", "K", "dT", "last largest node temperature change of the fixed point"),
    (
        "mechanics_update_k",
        "K",
        "dT_mech",
        "node temperature change that re-solves the bearing mechanics",
    ),
    ("heat_w", "W", "H", "total friction heat of a bearing"),
    ("total_heat_w", "W", "H", "total heat"),
    ("load_heat_w", "W", "H_l", "heat of the load moment"),
    ("viscous_heat_w", "W", "H_v", "heat of the viscous moment"),
    ("spin_heat_w", "W", "H_s", "spin friction heat"),
    ("churning_heat_w", "W", "H_d", "ball drag (churning) heat in the oil-air mixture"),
    ("extra_heat_w", "W", "H_x", "extra heat at the bearing beyond the modelled friction"),
    ("bearing_heat_w", "W", "H_b", "heat of all spindle bearings"),
    ("front_bearing_heat_w", "W", "H_b,front", "heat of one front bearing"),
    ("front_spin_heat_w", "W", "H_s,front", "spin heat of one front bearing"),
    ("bearing_drag_heat_w", "W", "H_d", "ball drag heat of all spindle bearings"),
    ("motor_losses_w", "W", "P_loss", "motor losses (copper, iron, mechanical)"),
    ("boundary_flow_w", "W", "Q_b", "heat leaving through the fixed-temperature nodes"),
    ("viscosity_cst", "mm^2/s", "nu", "oil kinematic viscosity"),
    (
        "spin_friction_coefficient",
        "1",
        "mu_s",
        "spin (traction) friction coefficient of the spin moment",
    ),
    ("lubrication_factor_f0", "1", "f0", "Palmgren lubrication factor of the viscous moment"),
    ("churning_oil_fraction", "1", "X", "oil volume fraction of the oil-air mixture"),
    (
        "rolling_heat_w",
        "W",
        "H_r",
        "rolling heat of a bearing (Palmgren: omega (M1 + Mv); SKF: omega M_rr)",
    ),
    ("sliding_heat_w", "W", "H_sl", "sliding heat of a bearing (SKF: omega M_sl; Palmgren: 0)"),
    ("drag_heat_w", "W", "H_d", "drag heat: balls in the oil-air mixture, or the oil-bath drag"),
    ("ring_cage_churning_heat_w", "W", "H_ch", "churning heat of the rings and the cage"),
    ("seal_heat_w", "W", "H_seal", "seal friction heat"),
    ("cavity_oil_fraction", "1", "X", "oil volume fraction of the bearing cavity used by the drag"),
    ("oil_flow_cm3_per_min", "cm^3/min", "W_oil", "jet oil flow into the bearing"),
    ("jet_count", "1", "n_jet", "number of oil jets"),
    ("jet_velocity_m_per_s", "m/s", "v_jet", "oil jet velocity"),
    (
        "oil_volume_cm3_per_h",
        "cm^3/h",
        "V_oil",
        "oil volume per hour of an oil-air or oil-mist supply",
    ),
    ("air_flow_l_per_min", "l/min", "Q_air", "carrier air flow of an oil-air or oil-mist supply"),
    ("oil_level_mm", "mm", "H", "static oil-bath level above the lowest point of the lowest ball"),
    ("grease_fill_fraction", "1", "f_g", "share of the free volume filled with grease"),
    ("oil_flow_scale", "1", "s_W", "scale on the oil flow reaching the cavity"),
    (
        "cavity_fraction_speed_exponent",
        "1",
        "e_n",
        "speed exponent of the cavity oil fraction (Parker: 1)",
    ),
    ("housing_conductance_scale", "1", "s_h", "scale of the housing-to-ambient conductance"),
    ("time_s", "s", "t", "time"),
    ("duration_s", "s", "t_end", "duration of a transient"),
    ("dt_s", "s", "dt", "time step"),
    ("velocity_rms_mm_s", "mm/s", "v_rms", "RMS vibration velocity"),
    ("frequency_hz", "Hz", "f", "frequency"),
    ("te_amplitude_um", "um", "e_TE", "first-harmonic transmission error amplitude"),
    ("transmission_error_um", "um", "e", "transmission error"),
    ("half_backlash_um", "um", "b", "half the gear backlash"),
    ("backlash_total_um", "um", "2b", "total gear backlash"),
    ("backlash_um", "um", "2b", "total gear backlash (short form)"),
    ("amplitude_um", "um", "A", "dynamic transmission error amplitude"),
    ("mean_dte_um", "um", "e_mean", "mean dynamic transmission error"),
    ("lyapunov_per_s", "1/s", "lambda", "largest Lyapunov exponent per second"),
    ("free_gap_change_um", "um", "ds", "change of the free gap between the raceways"),
    (
        "groove_centre_radial_um",
        "um",
        "dr_g",
        "radial offset of the groove curvature centres (before projection)",
    ),
    (
        "groove_centre_axial_um",
        "um",
        "da_g",
        "axial offset of the groove curvature centres (before projection)",
    ),
    ("inner_groove_centre_um", "um", "u_i", "radial growth of the inner groove centre"),
    ("outer_groove_centre_um", "um", "u_o", "radial growth of the outer groove centre"),
    ("shaft_surface_um", "um", "u_s", "radial growth of the shaft surface"),
    ("housing_bore_um", "um", "u_h", "radial growth of the housing bore"),
    ("dte_um", "um", "e_d", "dynamic transmission error"),
    ("dte_min_um", "um", "e_d,min", "smallest dynamic transmission error of a speed"),
    ("dte_max_um", "um", "e_d,max", "largest dynamic transmission error of a speed"),
    (
        "transition_dte_min_change_um",
        "um",
        "de_d,min",
        "change of the smallest dynamic transmission error at a transition",
    ),
    (
        "transition_dte_max_change_um",
        "um",
        "de_d,max",
        "change of the largest dynamic transmission error at a transition",
    ),
    (
        "lyapunov_stderr_per_s",
        "1/s",
        "s_lambda",
        "standard error of the largest Lyapunov exponent per second",
    ),
    ("face_width_mm", "mm", "b_w", "gear face width"),
    ("helix_angle_deg", "deg", "beta_h", "gear helix angle"),
    ("normal_module_mm", "mm", "m_n", "gear normal module"),
    ("normal_pressure_angle_deg", "deg", "alpha_n", "gear normal pressure angle"),
    (
        "stiffness_speeds_rpm",
        "rpm",
        "n",
        "speeds at which the bearing stiffness schedule is computed",
    ),
    ("regime_boundary_rpm", "rpm", "n_b", "speed where the gear's motion regime changes"),
    ("lower_rpm", "rpm", "n_b,lo", "lower end of a regime boundary's interval"),
    ("upper_rpm", "rpm", "n_b,hi", "upper end of a regime boundary's interval"),
    ("unbalance_g_mm", "g mm", "U", "residual unbalance of the rotor"),
    ("velocity_peak_mm_s", "mm/s", "v_peak", "peak vibration velocity"),
    ("x1_mm_s", "mm/s", "v_1x", "vibration velocity amplitude at once per revolution"),
    ("x2_mm_s", "mm/s", "v_2x", "vibration velocity amplitude at twice per revolution"),
    ("x3_mm_s", "mm/s", "v_3x", "vibration velocity amplitude at three times per revolution"),
)

#: name -> ``Entry``.
GLOSSARY: dict[str, Entry] = {name: Entry(u, s, d) for name, u, s, d in _ROWS}

#: Unit suffix tokens, longest first (a name ends in one of them).
UNIT_SUFFIXES: tuple[str, ...] = (
    "_w_per_m2_k",
    "_cm3_per_min",
    "_cm3_per_h",
    "_l_per_min",
    "_m_per_s",
    "_n_m_per_rad",
    "_mm_rpm",
    "_mpa",
    "_n_per_rad",
    "_n_per_um",
    "_n_per_m",
    "_mm_s",
    "_n_m",
    "_cst",
    "_rpm",
    "_deg",
    "_rad",
    "_hz",
    "_mm",
    "_um",
    "_n",
    "_m",
    "_c",
    "_k",
    "_w",
    "_s",
)


#: The unit each suffix token stands for (a name the glossary does not
#: hold takes its unit from its suffix).
SUFFIX_UNITS: dict[str, str] = {
    "_w_per_m2_k": "W/(m^2 K)", "_cm3_per_min": "cm^3/min", "_cm3_per_h": "cm^3/h",
    "_l_per_min": "l/min", "_m_per_s": "m/s", "_n_m_per_rad": "N m/rad", "_mm_rpm": "mm rpm",
    "_mpa": "MPa", "_n_per_rad": "N/rad", "_n_per_um": "N/um", "_n_per_m": "N/m",
    "_mm_s": "mm/s", "_n_m": "N m", "_cst": "mm^2/s", "_rpm": "rpm", "_deg": "deg",
    "_rad": "rad", "_hz": "Hz", "_mm": "mm", "_um": "um", "_n": "N", "_m": "m", "_c": "C",
    "_k": "K", "_w": "W", "_s": "s",
}  # fmt: skip
assert set(SUFFIX_UNITS) == set(UNIT_SUFFIXES)


def glossary() -> polars.DataFrame:
    """The glossary as a DataFrame: ``name``, ``unit``, ``symbol``,
    ``description``, one row per quantity."""
    import polars as pl

    return pl.DataFrame(
        {
            "name": [r[0] for r in _ROWS],
            "unit": [r[1] for r in _ROWS],
            "symbol": [r[2] for r in _ROWS],
            "description": [r[3] for r in _ROWS],
        }
    )


def unit_of(name: str) -> str:
    """The unit of a glossary name; ``KeyError`` naming it when unknown."""
    try:
        return GLOSSARY[name].unit
    except KeyError:
        raise KeyError(f"{name!r} is not in the glossary (thermobear.glossary)") from None


__all__ = ["GLOSSARY", "SUFFIX_UNITS", "UNIT_SUFFIXES", "Entry", "glossary", "unit_of"]
