//! Involute helical gear pair geometry (docs/concepts/physics.md §7; seed A
//! section 3.2, Table 3). Formulas are the standard ones of ISO 21771 /
//! DIN 3960 (transverse module, involute function, operating pressure angle
//! with profile shift, contact ratios). Everything SI inside: metres,
//! radians, kilograms, N m.
//!
//! Conventions and assumptions (stated once, used everywhere):
//! * index 0 is the pinion (driving), index 1 the gear (driven);
//! * external gears, both with the same basic rack (addendum `ha*`,
//!   dedendum `hf*` in units of the normal module);
//! * the centre distance is *derived* from the profile-shift sum (zero
//!   backlash, no centre-distance tolerance): inv(alpha_wt) = inv(alpha_t) +
//!   2 (x1 + x2) tan(alpha_n) / (z1 + z2), a' = a cos(alpha_t) / cos(alpha_wt);
//! * tip radius r_a = r + m_n (ha* + x + k) with the tip alteration
//!   coefficient k (default 0, DIN 3960 "k m_n"); root radius
//!   r_f = r - m_n (hf* - x);
//! * the line-of-action angle phi of seed A (A-43..A-45, "angle between the
//!   action surface and the vertical") is taken for gear centres on a
//!   horizontal line (x axis), so the transverse line of action is inclined to
//!   the vertical y axis by the operating transverse pressure angle:
//!   phi = alpha_wt. Seed A gives no value for phi; this is the usual choice
//!   of the 8-DOF helical-pair models it follows.

use crate::error::{finite, in_range, non_negative, positive, Error, Result};
use std::f64::consts::PI;

/// Smallest tooth count accepted. Fewer teeth than this cannot form a
/// working involute tooth with a standard rack (the tooth is pointed or
/// undercut far into the active flank).
pub const MIN_TEETH: u32 = 6;

/// One wheel of the pair: the data that differ between pinion and gear.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct WheelSpec {
    /// Number of teeth z.
    pub teeth: u32,
    /// Profile shift coefficient x (in units of m_n). Default 0.
    pub profile_shift_coeff: f64,
    /// Tip alteration coefficient k (in units of m_n, usually <= 0). Default 0.
    pub tip_alteration_coeff: f64,
    /// Mass of the wheel (with whatever rotates rigidly with it) \[kg\].
    pub mass_kg: f64,
    /// Polar mass moment of inertia about the axis of rotation [kg m^2].
    pub polar_inertia_kg_m2: f64,
    /// Inner radius of the gear rim / bore \[m\], used by the fillet-foundation
    /// term of the mesh stiffness (Sainsot et al. 2004). `None` means "not
    /// known": the mesh model then assumes r_f / r_bore = 2.
    pub bore_radius_m: Option<f64>,
}

impl WheelSpec {
    /// A wheel with no profile shift or tip alteration and an unknown bore.
    pub fn new(teeth: u32, mass_kg: f64, polar_inertia_kg_m2: f64) -> Self {
        WheelSpec {
            teeth,
            profile_shift_coeff: 0.0,
            tip_alteration_coeff: 0.0,
            mass_kg,
            polar_inertia_kg_m2,
            bore_radius_m: None,
        }
    }
}

/// Input data of a helical gear pair (all SI). Build a validated
/// [`GearPair`] with [`GearPair::new`].
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct GearPairSpec {
    /// [pinion, gear].
    pub wheels: [WheelSpec; 2],
    /// Normal module m_n \[m\].
    pub normal_module_m: f64,
    /// Normal pressure angle alpha_n \[rad\].
    pub normal_pressure_angle_rad: f64,
    /// Helix angle at the reference cylinder beta \[rad\] (0 = spur).
    pub helix_angle_rad: f64,
    /// Common face width b \[m\].
    pub face_width_m: f64,
    /// Basic-rack addendum coefficient ha* (default 1.0, ISO 53 profile A).
    pub addendum_coeff: f64,
    /// Basic-rack dedendum coefficient hf* (default 1.25, ISO 53 profile A).
    pub dedendum_coeff: f64,
    /// Young's modulus of both wheels E \[Pa\].
    pub youngs_modulus_pa: f64,
    /// Poisson's ratio of both wheels nu [-].
    pub poisson_ratio: f64,
    /// Density of both wheels rho [kg/m^3].
    pub density_kg_m3: f64,
    /// Torque on the pinion [N m].
    pub input_torque_n_m: f64,
}

/// Quantities derived from a [`GearPairSpec`]. Arrays are [pinion, gear].
#[derive(Debug, Clone, PartialEq)]
pub struct GearGeometry {
    /// Transverse module m_t = m_n / cos(beta) \[m\].
    pub transverse_module_m: f64,
    /// Transverse pressure angle alpha_t = atan(tan(alpha_n) / cos(beta)) \[rad\].
    pub transverse_pressure_angle_rad: f64,
    /// Operating transverse pressure angle alpha_wt \[rad\].
    pub operating_pressure_angle_rad: f64,
    /// Base helix angle beta_b = atan(tan(beta) cos(alpha_t)) \[rad\].
    pub base_helix_angle_rad: f64,
    /// Reference centre distance a = r1 + r2 \[m\].
    pub reference_centre_distance_m: f64,
    /// Operating centre distance a' \[m\].
    pub centre_distance_m: f64,
    /// Reference pitch radii r = z m_t / 2 \[m\].
    pub pitch_radius_m: [f64; 2],
    /// Operating pitch radii r_w = r_b / cos(alpha_wt) \[m\].
    pub operating_pitch_radius_m: [f64; 2],
    /// Base radii r_b = r cos(alpha_t) \[m\].
    pub base_radius_m: [f64; 2],
    /// Tip radii \[m\].
    pub tip_radius_m: [f64; 2],
    /// Root radii \[m\].
    pub root_radius_m: [f64; 2],
    /// Half tooth thickness angle at the base circle (transverse) \[rad\]:
    /// psi_b = (pi/2 + 2 x tan(alpha_n)) / z + inv(alpha_t).
    pub base_half_tooth_angle_rad: [f64; 2],
    /// Virtual (equivalent spur) tooth numbers z_n = z / (cos^2(beta_b) cos(beta)).
    pub virtual_teeth: [f64; 2],
    /// Transverse base pitch p_bt = pi m_t cos(alpha_t) \[m\].
    pub transverse_base_pitch_m: f64,
    /// Length of the transverse path of contact g_alpha \[m\].
    pub path_of_contact_m: f64,
    /// Distance from the pinion's tangency point T1 to the start of contact A
    /// along the line of action \[m\].
    pub t1_to_start_m: f64,
    /// Distance T1 T2 = a' sin(alpha_wt) \[m\].
    pub t1_to_t2_m: f64,
    /// Transverse contact ratio eps_alpha = g_alpha / p_bt.
    pub transverse_contact_ratio: f64,
    /// Overlap ratio eps_beta = b sin(beta) / (pi m_n).
    pub overlap_ratio: f64,
    /// Total contact ratio eps_gamma = eps_alpha + eps_beta.
    pub total_contact_ratio: f64,
    /// Line-of-action angle phi of seed A \[rad\]; see module docs.
    pub line_of_action_angle_rad: f64,
}

/// Tooth force components at the reference cylinder (ISO 6336-1 convention).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ToothForces {
    /// Tangential force F_t = T / r_1 \[N\].
    pub tangential_n: f64,
    /// Radial force F_r = F_t tan(alpha_t) \[N\].
    pub radial_n: f64,
    /// Axial force F_a = F_t tan(beta) \[N\].
    pub axial_n: f64,
    /// Normal force F_n = F_t / (cos(alpha_n) cos(beta)) \[N\].
    pub normal_n: f64,
}

/// A validated helical gear pair with its derived geometry.
#[derive(Debug, Clone, PartialEq)]
pub struct GearPair {
    /// The validated input data (teeth, module, angles, face width,
    /// material, masses, input torque).
    pub spec: GearPairSpec,
    /// Geometry derived from `spec` (ISO 21771: radii, pressure angles,
    /// path of contact, contact ratios).
    pub geometry: GearGeometry,
}

/// Names accepted by [`GearPair::preset`].
pub const PRESETS: [&str; 1] = ["seed-electric-drive"];

/// Involute function inv(a) = tan(a) - a.
pub fn involute(angle_rad: f64) -> f64 {
    angle_rad.tan() - angle_rad
}

/// Inverse of the involute function on [0, pi/2), by Newton's method
/// (d inv / d a = tan^2 a) from the small-angle start a0 = (3 y)^(1/3).
pub fn inverse_involute(value: f64) -> Result<f64> {
    let y = non_negative("involute_value", value)?;
    if y == 0.0 {
        return Ok(0.0);
    }
    let mut a = (3.0 * y).cbrt().min(1.5);
    let tol = 1e-14;
    for _ in 0..60 {
        let t = a.tan();
        let f = t - a - y;
        let step = f / (t * t);
        a = (a - step).clamp(1e-12, PI / 2.0 - 1e-9);
        if step.abs() < tol * a.max(1e-3) {
            return Ok(a);
        }
    }
    let res = involute(a) - y;
    if res.abs() < 1e-12 {
        Ok(a)
    } else {
        Err(Error::convergence("inverse involute", 60, res.abs(), 1e-12))
    }
}

impl GearPairSpec {
    /// Seed A Table 3, first gear pair of the electric drive (Liu, Liu & Hu,
    /// Sensors 2021, 21, 309), with the table's unit typos corrected
    /// (docs/concepts/physics.md §8; see
    /// [`TableGearData::seed_electric_drive_as_printed`]):
    /// z = 29 / 78, m_n = 1.537 mm, alpha_n = 16.5 deg, beta = 31.2 deg,
    /// b = 33 mm, E = 206 GPa (printed 20,600 MPa), nu = 0.25,
    /// rho = 7800 kg/m^3 (printed 7.8e9 t/mm^3), masses 1.201 / 3.1 kg,
    /// inertias 0.1152 / 1.6 t mm^2 = 1.152e-4 / 1.6e-3 kg m^2, input torque
    /// 100 N m (seed A section 2.3). Profile shifts, tip alteration and bores
    /// are not published: x = 0, k = 0, bores unknown; basic rack 1.0 / 1.25.
    pub fn seed_electric_drive() -> Self {
        let mm = 1e-3;
        GearPairSpec {
            wheels: [WheelSpec::new(29, 1.201, 0.1152e-3), WheelSpec::new(78, 3.1, 1.6e-3)],
            normal_module_m: 1.537 * mm,
            normal_pressure_angle_rad: 16.5f64.to_radians(),
            helix_angle_rad: 31.2f64.to_radians(),
            face_width_m: 33.0 * mm,
            addendum_coeff: 1.0,
            dedendum_coeff: 1.25,
            youngs_modulus_pa: 206e9,
            poisson_ratio: 0.25,
            density_kg_m3: 7800.0,
            input_torque_n_m: 100.0,
        }
    }
}

impl GearPair {
    /// Validate the specification and derive the geometry.
    ///
    /// Errors (`Error::Config` naming the field): non-positive module, face
    /// width, mass, inertia, modulus or density; teeth below [`MIN_TEETH`];
    /// pressure angle outside (0, 45] deg, helix angle outside [0, 45) deg;
    /// Poisson ratio outside (0, 0.5); density or modulus or inertia that is
    /// physically impossible (with the likely intended value, see
    /// [`plausibility_error`]); pointed tooth tips; involute interference;
    /// transverse contact ratio below 1.
    pub fn new(spec: GearPairSpec) -> Result<Self> {
        validate_spec(&spec)?;
        let geometry = derive(&spec)?;
        validate_geometry(&spec, &geometry)?;
        Ok(GearPair { spec, geometry })
    }

    /// Built-in pairs: `"seed-electric-drive"` ([`GearPairSpec::seed_electric_drive`]).
    pub fn preset(name: &str) -> Result<Self> {
        match name {
            "seed-electric-drive" => GearPair::new(GearPairSpec::seed_electric_drive()),
            _ => Err(Error::config(
                "gear_preset",
                name,
                format!("unknown gear pair; known: {}", PRESETS.join(", ")),
            )),
        }
    }

    /// Base radii [pinion, gear] \[m\].
    pub fn base_radius_m(&self) -> [f64; 2] {
        self.geometry.base_radius_m
    }

    /// Helix angle beta at the reference cylinder \[rad\].
    pub fn helix_angle_rad(&self) -> f64 {
        self.spec.helix_angle_rad
    }

    /// Base helix angle beta_b \[rad\].
    pub fn base_helix_angle_rad(&self) -> f64 {
        self.geometry.base_helix_angle_rad
    }

    /// Line-of-action angle phi of seed A \[rad\] (= alpha_wt, module docs).
    pub fn line_of_action_angle_rad(&self) -> f64 {
        self.geometry.line_of_action_angle_rad
    }

    /// Masses [pinion, gear] \[kg\].
    pub fn mass_kg(&self) -> [f64; 2] {
        [self.spec.wheels[0].mass_kg, self.spec.wheels[1].mass_kg]
    }

    /// Polar inertias [pinion, gear] [kg m^2].
    pub fn polar_inertia_kg_m2(&self) -> [f64; 2] {
        [
            self.spec.wheels[0].polar_inertia_kg_m2,
            self.spec.wheels[1].polar_inertia_kg_m2,
        ]
    }

    /// Torque on the pinion [N m].
    pub fn input_torque_n_m(&self) -> f64 {
        self.spec.input_torque_n_m
    }

    /// Torque on the gear at equilibrium (lossless): T2 = T1 z2 / z1 [N m].
    pub fn output_torque_n_m(&self) -> f64 {
        self.spec.input_torque_n_m * self.gear_ratio()
    }

    /// Gear ratio u = z2 / z1.
    pub fn gear_ratio(&self) -> f64 {
        self.spec.wheels[1].teeth as f64 / self.spec.wheels[0].teeth as f64
    }

    /// Tooth mesh frequency f_z = z1 n1 / 60 \[Hz\] for a pinion speed \[rpm\].
    pub fn mesh_frequency_hz(&self, pinion_speed_rpm: f64) -> Result<f64> {
        let n = positive("pinion_speed_rpm", pinion_speed_rpm)?;
        Ok(self.spec.wheels[0].teeth as f64 * n / 60.0)
    }

    /// Mesh period T_z = 1 / f_z \[s\] for a pinion speed \[rpm\].
    pub fn mesh_period_s(&self, pinion_speed_rpm: f64) -> Result<f64> {
        Ok(1.0 / self.mesh_frequency_hz(pinion_speed_rpm)?)
    }

    /// Tooth forces from the input torque (reference cylinder, ISO 6336-1).
    pub fn tooth_forces(&self) -> ToothForces {
        let g = &self.geometry;
        let s = &self.spec;
        let ft = s.input_torque_n_m / g.pitch_radius_m[0];
        ToothForces {
            tangential_n: ft,
            radial_n: ft * g.transverse_pressure_angle_rad.tan(),
            axial_n: ft * s.helix_angle_rad.tan(),
            normal_n: ft / (s.normal_pressure_angle_rad.cos() * s.helix_angle_rad.cos()),
        }
    }

    /// Pinion (0) and gear (1) roll distances rho_i = |T_i P| of the contact
    /// point at a position `s_m` measured along the transverse path of
    /// contact from its start A (0 <= s <= g_alpha) \[m\].
    pub fn roll_distances_m(&self, s_m: f64) -> [f64; 2] {
        let g = &self.geometry;
        let rho1 = g.t1_to_start_m + s_m;
        [rho1, g.t1_to_t2_m - rho1]
    }
}

fn validate_spec(s: &GearPairSpec) -> Result<()> {
    for (i, w) in s.wheels.iter().enumerate() {
        let name = ["pinion", "gear"][i];
        if w.teeth < MIN_TEETH {
            return Err(Error::config(
                format!("{name}_teeth"),
                w.teeth,
                format!("at least {MIN_TEETH} teeth are needed for a working involute tooth"),
            ));
        }
        finite(&format!("{name}_profile_shift_coeff"), w.profile_shift_coeff)?;
        in_range(
            &format!("{name}_tip_alteration_coeff"),
            w.tip_alteration_coeff,
            -1.0,
            0.5,
        )?;
        positive(&format!("{name}_mass_kg"), w.mass_kg)?;
        positive(&format!("{name}_polar_inertia_kg_m2"), w.polar_inertia_kg_m2)?;
        if let Some(rb) = w.bore_radius_m {
            positive(&format!("{name}_bore_radius_m"), rb)?;
        }
    }
    positive("normal_module_m", s.normal_module_m)?;
    positive("face_width_m", s.face_width_m)?;
    let an = s.normal_pressure_angle_rad;
    if !(an > 0.0 && an <= 45f64.to_radians()) {
        return Err(Error::config(
            "normal_pressure_angle_rad",
            an,
            "must lie in (0, 45 deg]",
        ));
    }
    let b = s.helix_angle_rad;
    if !(b.is_finite() && (0.0..45f64.to_radians()).contains(&b)) {
        return Err(Error::config("helix_angle_rad", b, "must lie in [0, 45 deg)"));
    }
    in_range("addendum_coeff", s.addendum_coeff, 0.5, 1.5)?;
    in_range("dedendum_coeff", s.dedendum_coeff, s.addendum_coeff, 2.0)?;
    positive("youngs_modulus_pa", s.youngs_modulus_pa)?;
    positive("density_kg_m3", s.density_kg_m3)?;
    let nu = s.poisson_ratio;
    if !(nu > 0.0 && nu < 0.5) {
        return Err(Error::config("poisson_ratio", nu, "must lie in (0, 0.5)"));
    }
    non_negative("input_torque_n_m", s.input_torque_n_m)?;
    plausibility_error(s)
}

/// Physically impossible material or inertia values, with the likely
/// intended value in the message (docs/concepts/physics.md §8):
/// * density outside 500..25,000 kg/m^3 (no engineering solid lies outside;
///   osmium, the densest element, is 22,590 kg/m^3) — a value like 7.8e21
///   kg/m^3 (7.8e9 t/mm^3) is a sign-of-exponent typo for 7800 kg/m^3;
/// * Young's modulus below 1e8 Pa or above 1.2e12 Pa (diamond) — a value
///   near 2.06e5 "Pa" is 206,000 MPa given in MPa;
/// * polar inertia above m r_a^2, impossible for a body whose mass lies
///   inside its tip radius — t mm^2 or kg mm^2 taken for kg m^2.
pub fn plausibility_error(s: &GearPairSpec) -> Result<()> {
    let rho = s.density_kg_m3;
    if !(500.0..=25_000.0).contains(&rho) {
        let hint = match flip_exponent_into(rho * 1e-12, 5e-10, 2.5e-8) {
            Some(t_mm3) => format!(
                "no solid has this density; likely intended {:.4e} kg/m^3 ({t_mm3:.2e} t/mm^3, the sign of the exponent flipped)",
                t_mm3 * 1e12
            ),
            None => "no engineering solid has a density outside 500..25000 kg/m^3".to_string(),
        };
        return Err(Error::config("density_kg_m3", rho, hint));
    }
    let e = s.youngs_modulus_pa;
    if !(1e8..=1.2e12).contains(&e) {
        let hint = if (1e8..=1.2e12).contains(&(e * 1e6)) {
            format!("likely given in MPa: intended {:.4e} Pa", e * 1e6)
        } else if (1e8..=1.2e12).contains(&(e * 1e9)) {
            format!("likely given in GPa: intended {:.4e} Pa", e * 1e9)
        } else {
            "Young's modulus of a gear material lies in 1e8..1.2e12 Pa".to_string()
        };
        return Err(Error::config("youngs_modulus_pa", e, hint));
    }
    // Tip radius bound needs the geometry; use a conservative outer radius.
    let cos_b = s.helix_angle_rad.cos();
    for (i, w) in s.wheels.iter().enumerate() {
        let name = ["pinion", "gear"][i];
        let r_out = 0.5 * w.teeth as f64 * s.normal_module_m / cos_b
            + s.normal_module_m * (s.addendum_coeff + w.profile_shift_coeff.max(0.0) + 0.5);
        let i_max = w.mass_kg * r_out * r_out;
        if w.polar_inertia_kg_m2 > i_max {
            let hint = if w.polar_inertia_kg_m2 * 1e-3 <= i_max {
                format!(
                    "exceeds m r_a^2 = {i_max:.3e} kg m^2; likely given in t mm^2: intended {:.4e} kg m^2 (1 t mm^2 = 1e-3 kg m^2)",
                    w.polar_inertia_kg_m2 * 1e-3
                )
            } else if w.polar_inertia_kg_m2 * 1e-6 <= i_max {
                format!(
                    "exceeds m r_a^2 = {i_max:.3e} kg m^2; likely given in kg mm^2: intended {:.4e} kg m^2",
                    w.polar_inertia_kg_m2 * 1e-6
                )
            } else {
                format!("exceeds m r_a^2 = {i_max:.3e} kg m^2, impossible for this mass and size")
            };
            return Err(Error::config(
                format!("{name}_polar_inertia_kg_m2"),
                w.polar_inertia_kg_m2,
                hint,
            ));
        }
    }
    Ok(())
}

/// If `value` = m 10^e lies outside [lo, hi] but m 10^(-e) lies inside,
/// return m 10^(-e) (the printed exponent lost its minus sign).
fn flip_exponent_into(value: f64, lo: f64, hi: f64) -> Option<f64> {
    if !(value.is_finite() && value > 0.0) {
        return None;
    }
    let e = value.log10().floor();
    let mantissa = value / 10f64.powf(e);
    let flipped = mantissa * 10f64.powf(-e);
    (lo..=hi).contains(&flipped).then_some(flipped)
}

fn derive(s: &GearPairSpec) -> Result<GearGeometry> {
    let beta = s.helix_angle_rad;
    let an = s.normal_pressure_angle_rad;
    let mn = s.normal_module_m;
    let mt = mn / beta.cos();
    let at = (an.tan() / beta.cos()).atan();
    let beta_b = (beta.tan() * at.cos()).atan();
    let z = [s.wheels[0].teeth as f64, s.wheels[1].teeth as f64];
    let x = [s.wheels[0].profile_shift_coeff, s.wheels[1].profile_shift_coeff];
    let k = [s.wheels[0].tip_alteration_coeff, s.wheels[1].tip_alteration_coeff];
    let r = [0.5 * z[0] * mt, 0.5 * z[1] * mt];
    let rb = [r[0] * at.cos(), r[1] * at.cos()];
    let inv_wt = involute(at) + 2.0 * (x[0] + x[1]) * an.tan() / (z[0] + z[1]);
    if inv_wt <= 0.0 {
        return Err(Error::config(
            "profile_shift_coeff_sum",
            x[0] + x[1],
            "negative profile-shift sum too large: no operating pressure angle exists",
        ));
    }
    let awt = inverse_involute(inv_wt)?;
    let a_ref = r[0] + r[1];
    let a = a_ref * at.cos() / awt.cos();
    let rw = [rb[0] / awt.cos(), rb[1] / awt.cos()];
    let ra = [
        r[0] + mn * (s.addendum_coeff + x[0] + k[0]),
        r[1] + mn * (s.addendum_coeff + x[1] + k[1]),
    ];
    let rf = [
        r[0] - mn * (s.dedendum_coeff - x[0]),
        r[1] - mn * (s.dedendum_coeff - x[1]),
    ];
    let psi_b = [
        (PI / 2.0 + 2.0 * x[0] * an.tan()) / z[0] + involute(at),
        (PI / 2.0 + 2.0 * x[1] * an.tan()) / z[1] + involute(at),
    ];
    let zn_factor = beta_b.cos().powi(2) * beta.cos();
    let pbt = PI * mt * at.cos();
    let t1t2 = a * awt.sin();
    let t2a = (ra[1] * ra[1] - rb[1] * rb[1]).max(0.0).sqrt();
    let t1e = (ra[0] * ra[0] - rb[0] * rb[0]).max(0.0).sqrt();
    let g_alpha = t1e + t2a - t1t2;
    let eps_a = g_alpha / pbt;
    let eps_b = s.face_width_m * beta.sin() / (PI * mn);
    Ok(GearGeometry {
        transverse_module_m: mt,
        transverse_pressure_angle_rad: at,
        operating_pressure_angle_rad: awt,
        base_helix_angle_rad: beta_b,
        reference_centre_distance_m: a_ref,
        centre_distance_m: a,
        pitch_radius_m: r,
        operating_pitch_radius_m: rw,
        base_radius_m: rb,
        tip_radius_m: ra,
        root_radius_m: rf,
        base_half_tooth_angle_rad: psi_b,
        virtual_teeth: [z[0] / zn_factor, z[1] / zn_factor],
        transverse_base_pitch_m: pbt,
        path_of_contact_m: g_alpha,
        t1_to_start_m: t1t2 - t2a,
        t1_to_t2_m: t1t2,
        transverse_contact_ratio: eps_a,
        overlap_ratio: eps_b,
        total_contact_ratio: eps_a + eps_b,
        line_of_action_angle_rad: awt,
    })
}

fn validate_geometry(s: &GearPairSpec, g: &GearGeometry) -> Result<()> {
    for i in 0..2 {
        let name = ["pinion", "gear"][i];
        if g.root_radius_m[i] <= 0.0 {
            return Err(Error::config(
                format!("{name}_teeth"),
                s.wheels[i].teeth,
                "root circle radius is not positive",
            ));
        }
        let a_tip = (g.base_radius_m[i] / g.tip_radius_m[i]).acos();
        let psi_tip = g.base_half_tooth_angle_rad[i] - involute(a_tip);
        if psi_tip <= 0.0 {
            return Err(Error::config(
                format!("{name}_profile_shift_coeff"),
                s.wheels[i].profile_shift_coeff,
                "the tooth tip is pointed (zero or negative tip thickness)",
            ));
        }
    }
    // The contact path must stay between the tangency points T1, T2, else the
    // tip of one wheel cuts the non-involute root of the other (interference).
    if g.t1_to_start_m < 0.0 {
        return Err(Error::config(
            "pinion_teeth",
            s.wheels[0].teeth,
            "involute interference: the gear tip passes the pinion's tangency point T1",
        ));
    }
    if g.t1_to_start_m + g.path_of_contact_m > g.t1_to_t2_m {
        return Err(Error::config(
            "gear_teeth",
            s.wheels[1].teeth,
            "involute interference: the pinion tip passes the gear's tangency point T2",
        ));
    }
    if g.transverse_contact_ratio < 1.0 {
        return Err(Error::config(
            "transverse_contact_ratio",
            format!("{:.4}", g.transverse_contact_ratio),
            "below 1: the pair does not mesh continuously (check teeth, addendum, shifts)",
        ));
    }
    Ok(())
}

/// One suspicious value in a table of gear data, with the value most likely
/// meant (docs/concepts/physics.md §8).
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct TypoWarning {
    /// Field name with its unit as printed (e.g. `youngs_modulus_mpa`).
    pub field: String,
    /// The value as printed.
    pub given: f64,
    /// The value most likely intended, in the same unit.
    pub likely_intended: f64,
    /// Why the value is suspicious and which slip (sign of the exponent,
    /// unit, digit) most likely produced it.
    pub reason: String,
}

/// Gear material and mass data in the tonne-millimetre-second units of a
/// paper table (E in MPa = N/mm^2, density in t/mm^3, inertia in t mm^2).
/// [`TableGearData::warnings`] flags seed-style typos;
/// [`TableGearData::into_si`] refuses a table that has any.
#[derive(Debug, Clone, PartialEq)]
pub struct TableGearData {
    /// Young's modulus E as printed [MPa = N/mm^2]; steel is 190,000..220,000.
    pub youngs_modulus_mpa: f64,
    /// Density as printed [t/mm^3]; steel is 6.9e-9..8.1e-9 (7.8e-9 t/mm^3 =
    /// 7800 kg/m^3).
    pub density_t_per_mm3: f64,
    /// [pinion, gear] \[kg\].
    pub mass_kg: [f64; 2],
    /// [pinion, gear] [t mm^2] (1 t mm^2 = 1e-3 kg m^2).
    pub polar_inertia_t_mm2: [f64; 2],
    /// [pinion, gear] outer (tip) radii \[mm\], used to bound the inertia.
    pub tip_radius_mm: [f64; 2],
}

/// Material data converted to SI by [`TableGearData::into_si`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SiGearData {
    /// Young's modulus E \[Pa\] (MPa x 1e6).
    pub youngs_modulus_pa: f64,
    /// Density [kg/m^3] (t/mm^3 x 1e12).
    pub density_kg_m3: f64,
    /// [pinion, gear] polar moments of inertia [kg m^2] (t mm^2 x 1e-3).
    pub polar_inertia_kg_m2: [f64; 2],
}

/// Steel (and cast iron) density band [t/mm^3]: 6.9e-9 .. 8.1e-9.
const STEEL_DENSITY_T_MM3: (f64, f64) = (6.9e-9, 8.1e-9);
/// Steel Young's modulus band [MPa]: 190,000 .. 220,000 (handbook values of
/// carbon and alloy steels).
const STEEL_MODULUS_MPA: (f64, f64) = (190_000.0, 220_000.0);

impl TableGearData {
    /// Seed A Table 3 exactly as printed: E = 20,600 MPa, density 7.8e9
    /// t/mm^3, masses 1.201 / 3.1 kg, inertias 0.1152 / 1.6 t mm^2; tip radii
    /// from the Table 3 geometry (27.59 / 71.62 mm).
    pub fn seed_electric_drive_as_printed() -> Self {
        TableGearData {
            youngs_modulus_mpa: 20_600.0,
            density_t_per_mm3: 7.8e9,
            mass_kg: [1.201, 3.1],
            polar_inertia_t_mm2: [0.1152, 1.6],
            tip_radius_mm: [27.59, 71.62],
        }
    }

    /// Suspicious values and what they most likely were meant to be.
    pub fn warnings(&self) -> Vec<TypoWarning> {
        let mut out = Vec::new();
        let mut rho = self.density_t_per_mm3;
        if !(5e-10..=2.5e-8).contains(&rho) {
            if let Some(f) = flip_exponent_into(rho, 5e-10, 2.5e-8) {
                out.push(TypoWarning {
                    field: "density_t_per_mm3".into(),
                    given: rho,
                    likely_intended: f,
                    reason: format!(
                        "no solid is this dense; the exponent lost its minus sign ({f:.2e} t/mm^3 = {:.0} kg/m^3)",
                        f * 1e12
                    ),
                });
                rho = f;
            }
        }
        let steel = (STEEL_DENSITY_T_MM3.0..=STEEL_DENSITY_T_MM3.1).contains(&rho);
        let e = self.youngs_modulus_mpa;
        if steel && !(STEEL_MODULUS_MPA.0..=STEEL_MODULUS_MPA.1).contains(&e) {
            for factor in [10.0, 0.1, 1e3, 1e-3] {
                let cand = e * factor;
                if (STEEL_MODULUS_MPA.0..=STEEL_MODULUS_MPA.1).contains(&cand) {
                    out.push(TypoWarning {
                        field: "youngs_modulus_mpa".into(),
                        given: e,
                        likely_intended: cand,
                        reason: format!(
                            "the density is that of steel, whose modulus is 190,000-220,000 MPa; a factor {factor} (digit slip) gives {cand:.0} MPa"
                        ),
                    });
                    break;
                }
            }
        }
        for i in 0..2 {
            let name = ["pinion", "gear"][i];
            let i_si = self.polar_inertia_t_mm2[i] * 1e-3;
            let ra = self.tip_radius_mm[i] * 1e-3;
            let i_max = self.mass_kg[i] * ra * ra;
            if i_si > i_max {
                out.push(TypoWarning {
                    field: format!("{name}_polar_inertia_t_mm2"),
                    given: self.polar_inertia_t_mm2[i],
                    likely_intended: self.polar_inertia_t_mm2[i] * 1e-3,
                    reason: format!(
                        "{i_si:.3e} kg m^2 exceeds m r_a^2 = {i_max:.3e} kg m^2; likely kg mm^2 printed as t mm^2"
                    ),
                });
            }
        }
        out
    }

    /// Convert to SI (E \[Pa\] = MPa x 1e6, rho [kg/m^3] = t/mm^3 x 1e12,
    /// I [kg m^2] = t mm^2 x 1e-3). Refuses the table if [`Self::warnings`]
    /// finds anything: the error names the field and the likely intended value.
    pub fn into_si(&self) -> Result<SiGearData> {
        if let Some(w) = self.warnings().into_iter().next() {
            return Err(Error::config(
                w.field,
                w.given,
                format!("likely intended {:.6e}: {}", w.likely_intended, w.reason),
            ));
        }
        Ok(SiGearData {
            youngs_modulus_pa: self.youngs_modulus_mpa * 1e6,
            density_kg_m3: self.density_t_per_mm3 * 1e12,
            polar_inertia_kg_m2: [self.polar_inertia_t_mm2[0] * 1e-3, self.polar_inertia_t_mm2[1] * 1e-3],
        })
    }

    /// The same table with every warning replaced by its likely intended value.
    pub fn corrected(&self) -> Self {
        let mut t = self.clone();
        for _ in 0..3 {
            let w = t.warnings();
            if w.is_empty() {
                break;
            }
            for w in w {
                match w.field.as_str() {
                    "density_t_per_mm3" => t.density_t_per_mm3 = w.likely_intended,
                    "youngs_modulus_mpa" => t.youngs_modulus_mpa = w.likely_intended,
                    "pinion_polar_inertia_t_mm2" => t.polar_inertia_t_mm2[0] = w.likely_intended,
                    "gear_polar_inertia_t_mm2" => t.polar_inertia_t_mm2[1] = w.likely_intended,
                    _ => {}
                }
            }
        }
        t
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// KISSsoft 03/2017 report of a helical pair (ISO 6336:2006 method B,
    /// DIN 3960 geometry), stage 3 of the NREL 5 MW drivetrain in
    /// github.com/gfsReboucas/Drivetrain, file `@NREL_5MW/stage_03.rtf`:
    /// m_n = 14 mm, alpha_n = 20 deg, beta = 10 deg, z = 24 / 95,
    /// x = 0.4800 / 0.6691, k m_n = -0.938 mm, b = 360 mm.
    pub(crate) fn kisssoft_nrel_stage3() -> GearPairSpec {
        let mm = 1e-3;
        let mut p = WheelSpec::new(24, 100.0, 1.5);
        p.profile_shift_coeff = 0.48;
        p.tip_alteration_coeff = -0.938 / 14.0;
        let mut g = WheelSpec::new(95, 1000.0, 200.0);
        g.profile_shift_coeff = 0.6691;
        g.tip_alteration_coeff = -0.938 / 14.0;
        GearPairSpec {
            wheels: [p, g],
            normal_module_m: 14.0 * mm,
            normal_pressure_angle_rad: 20f64.to_radians(),
            helix_angle_rad: 10f64.to_radians(),
            face_width_m: 360.0 * mm,
            addendum_coeff: 1.0,
            dedendum_coeff: 1.25,
            youngs_modulus_pa: 206e9,
            poisson_ratio: 0.3,
            density_kg_m3: 7830.0,
            input_torque_n_m: 40953.0,
        }
    }

    #[test]
    fn kisssoft_report_geometry_is_reproduced() {
        let p = GearPair::new(kisssoft_nrel_stage3()).unwrap();
        let g = &p.geometry;
        let close = |a: f64, b: f64, tol: f64| (a - b).abs() <= tol;
        // Report values: mt 14.216 mm, alft 20.284 deg, alfwt 22.856 deg,
        // betab 9.391 deg, a 861.000 mm, ad 845.850 mm, db 320.026 / 1266.770,
        // da 380.747 / 1395.376, df 319.623 / 1334.252, dw 347.294,
        // pbt 41.891 mm, ga 61.276 mm, eps_a 1.463, eps_b 1.421, zn 25.037 / 99.104.
        assert!(close(g.transverse_module_m * 1e3, 14.216, 5e-4));
        assert!(close(g.transverse_pressure_angle_rad.to_degrees(), 20.284, 5e-4));
        assert!(close(g.operating_pressure_angle_rad.to_degrees(), 22.856, 1e-3));
        assert!(close(g.base_helix_angle_rad.to_degrees(), 9.391, 5e-4));
        assert!(
            close(g.centre_distance_m * 1e3, 861.000, 0.01),
            "{}",
            g.centre_distance_m
        );
        assert!(close(g.reference_centre_distance_m * 1e3, 845.850, 5e-3));
        assert!(close(2e3 * g.base_radius_m[0], 320.026, 5e-3));
        assert!(close(2e3 * g.base_radius_m[1], 1266.770, 5e-3));
        assert!(close(2e3 * g.tip_radius_m[0], 380.747, 0.01));
        assert!(close(2e3 * g.tip_radius_m[1], 1395.376, 0.01));
        assert!(close(2e3 * g.root_radius_m[0], 319.623, 0.01));
        assert!(close(2e3 * g.root_radius_m[1], 1334.252, 0.01));
        assert!(close(2e3 * g.operating_pitch_radius_m[0], 347.294, 0.01));
        assert!(close(g.transverse_base_pitch_m * 1e3, 41.891, 5e-3));
        assert!(
            close(g.path_of_contact_m * 1e3, 61.276, 0.02),
            "{}",
            g.path_of_contact_m
        );
        assert!(close(g.transverse_contact_ratio, 1.463, 1e-3));
        assert!(close(g.overlap_ratio, 1.421, 1e-3));
        assert!(close(g.virtual_teeth[0], 25.037, 1e-3));
        assert!(close(g.virtual_teeth[1], 99.104, 1e-3));
        // Forces at the reference circle: Ft 240064.4 N, Fa 42329.8 N, Fr 88724.2 N.
        let f = p.tooth_forces();
        assert!(close(f.tangential_n, 240_064.4, 5.0), "{}", f.tangential_n);
        assert!(close(f.axial_n, 42_329.8, 2.0));
        assert!(close(f.radial_n, 88_724.2, 2.0));
        assert!(close(f.normal_n, 259_412.2, 5.0));
    }

    #[test]
    fn involute_inverse_round_trips() {
        for deg in [0.5f64, 5.0, 14.5, 20.0, 22.856, 35.0, 60.0] {
            let a = deg.to_radians();
            let back = inverse_involute(involute(a)).unwrap();
            assert!((back - a).abs() < 1e-12, "{deg}: {back}");
        }
        assert!(inverse_involute(-1.0).is_err());
    }

    #[test]
    fn seed_pair_geometry_and_forces() {
        let p = GearPair::preset("seed-electric-drive").unwrap();
        let g = &p.geometry;
        let s = &p.spec;
        // Zero shift: operating = reference.
        assert!((g.centre_distance_m - g.reference_centre_distance_m).abs() < 1e-12);
        assert!((g.operating_pressure_angle_rad - g.transverse_pressure_angle_rad).abs() < 1e-12);
        // Closed forms: tan(beta_b) = tan(beta) cos(alpha_t); sin(beta_b) = sin(beta) cos(alpha_n).
        assert!(
            (g.base_helix_angle_rad.sin() - s.helix_angle_rad.sin() * s.normal_pressure_angle_rad.cos()).abs() < 1e-12
        );
        // eps_beta = b tan(beta_b) / p_bt (overlap along the plane of action).
        let eb = s.face_width_m * g.base_helix_angle_rad.tan() / g.transverse_base_pitch_m;
        assert!((eb - g.overlap_ratio).abs() < 1e-12);
        assert!(g.transverse_contact_ratio > 1.0 && g.transverse_contact_ratio < 2.0);
        // Force balance: F_n^2 = F_t^2 + F_r^2 + F_a^2.
        let f = p.tooth_forces();
        let sum = f.tangential_n.powi(2) + f.radial_n.powi(2) + f.axial_n.powi(2);
        assert!((sum.sqrt() - f.normal_n).abs() < 1e-9 * f.normal_n);
        // Seed A section 2.3: 100 N m gives Fa = 2380.9 N on the bearing; the
        // reference-circle tooth force F_t tan(beta) is within 3 % of it.
        assert!((f.axial_n - 2380.9).abs() / 2380.9 < 0.03, "Fa = {}", f.axial_n);
        // Mesh frequency: z1 n / 60.
        assert!((p.mesh_frequency_hz(6000.0).unwrap() - 2900.0).abs() < 1e-9);
        assert!((p.mesh_period_s(6000.0).unwrap() * 2900.0 - 1.0).abs() < 1e-12);
        assert!(p.mesh_frequency_hz(-1.0).is_err());
    }

    #[test]
    fn bad_inputs_name_the_field() {
        let field = |s: GearPairSpec| match GearPair::new(s).unwrap_err() {
            Error::Config { field, .. } => field,
            e => panic!("{e}"),
        };
        let mut s = GearPairSpec::seed_electric_drive();
        s.wheels[0].mass_kg = 0.0;
        assert_eq!(field(s), "pinion_mass_kg");
        let mut s = GearPairSpec::seed_electric_drive();
        s.wheels[1].polar_inertia_kg_m2 = -1.0;
        assert_eq!(field(s), "gear_polar_inertia_kg_m2");
        let mut s = GearPairSpec::seed_electric_drive();
        s.normal_module_m = 0.0;
        assert_eq!(field(s), "normal_module_m");
        let mut s = GearPairSpec::seed_electric_drive();
        s.wheels[0].teeth = 5;
        assert_eq!(field(s), "pinion_teeth");
        let mut s = GearPairSpec::seed_electric_drive();
        s.youngs_modulus_pa = -1.0;
        assert_eq!(field(s), "youngs_modulus_pa");
        // Short addendum: eps_alpha < 1.
        let mut s = GearPairSpec::seed_electric_drive();
        s.addendum_coeff = 0.5;
        s.dedendum_coeff = 0.75;
        assert_eq!(field(s), "transverse_contact_ratio");
        assert!(GearPair::preset("nope").is_err());
    }

    #[test]
    fn unphysical_si_values_name_the_likely_intended_one() {
        let mut s = GearPairSpec::seed_electric_drive();
        s.density_kg_m3 = 7.8e9 * 1e12; // 7.8e9 t/mm^3 converted faithfully
        let e = GearPair::new(s).unwrap_err().to_string();
        assert!(e.contains("density_kg_m3") && e.contains("7.8000e3"), "{e}");
        let mut s = GearPairSpec::seed_electric_drive();
        s.youngs_modulus_pa = 206_000.0; // MPa number given as Pa
        let e = GearPair::new(s).unwrap_err().to_string();
        assert!(e.contains("2.0600e11"), "{e}");
        let mut s = GearPairSpec::seed_electric_drive();
        s.wheels[0].polar_inertia_kg_m2 = 0.1152; // t mm^2 number given as kg m^2
        let e = GearPair::new(s).unwrap_err().to_string();
        assert!(
            e.contains("pinion_polar_inertia_kg_m2") && e.contains("1.1520e-4"),
            "{e}"
        );
    }

    #[test]
    fn seed_table_typos_are_flagged_and_corrected() {
        let t = TableGearData::seed_electric_drive_as_printed();
        let w = t.warnings();
        assert_eq!(w.len(), 2, "{w:?}");
        let rho = w.iter().find(|w| w.field == "density_t_per_mm3").unwrap();
        assert!((rho.likely_intended - 7.8e-9).abs() < 1e-20);
        let e = w.iter().find(|w| w.field == "youngs_modulus_mpa").unwrap();
        assert!((e.likely_intended - 206_000.0).abs() < 1e-6);
        let err = t.into_si().unwrap_err().to_string();
        assert!(err.contains("likely intended"), "{err}");
        let si = t.corrected().into_si().unwrap();
        assert!((si.density_kg_m3 - 7800.0).abs() < 1e-6);
        assert!((si.youngs_modulus_pa - 206e9).abs() < 1.0);
        assert!((si.polar_inertia_kg_m2[0] - 1.152e-4).abs() < 1e-15);
        // The corrected table is exactly the preset.
        let s = GearPairSpec::seed_electric_drive();
        assert_eq!(si.youngs_modulus_pa, s.youngs_modulus_pa);
        assert!((si.density_kg_m3 - s.density_kg_m3).abs() < 1e-9);
        assert!((si.polar_inertia_kg_m2[1] - s.wheels[1].polar_inertia_kg_m2).abs() < 1e-15);
        // Tip radii quoted in the table match the preset geometry.
        let p = GearPair::preset("seed-electric-drive").unwrap();
        for i in 0..2 {
            assert!((p.geometry.tip_radius_m[i] * 1e3 - t.tip_radius_mm[i]).abs() < 0.01);
        }
    }
}
