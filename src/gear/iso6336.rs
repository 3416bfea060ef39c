//! Tooth stiffness after ISO 6336-1 Method B (section 9 of ISO 6336-1:2006
//! and :2019): single stiffness c' and mesh stiffnesses c_gamma_alpha,
//! c_gamma_beta.
//!
//! * Theoretical single stiffness c'_th = 1 / q', with the flexibility
//!   q' = C1 + C2/z_n1 + C3/z_n2 + C4 x1 + C5 x1/z_n1 + C6 x2 + C7 x2/z_n2 +
//!   C8 x1^2 + C9 x2^2 [mm um / N] (ISO 6336-1 Method B; C1..C9 in
//!   [`Q_COEFFS`]), z_n the virtual tooth numbers; ISO states it for x1 >= x2
//!   and x1 + x2 in [-0.5, 2].
//! * c' = c'_th C_M C_R C_B cos(beta) with C_M = 0.8 (theory-to-measurement
//!   correction), C_R = 1 + ln(b_s/b) / (5 exp(s_R / (5 m_n))) for webbed
//!   blanks (1 for solid disc gears; b_s/b clamped to [0.2, 1.2],
//!   s_R/m_n >= 1), C_B = [1 + 0.5 (1.2 - h_fP/m_n)] [1 - 0.02 (20 deg -
//!   alpha_Pn)] (basic rack factor, h_fP/m_n = hf*), and for light line loads
//!   (K_A F_t / b < 100 N/mm) the factor (K_A F_t / b / 100)^0.25.
//! * c_gamma_alpha = c' (0.75 eps_alpha + 0.25), c_gamma_beta = 0.85 c_gamma_alpha.
//!
//! ISO units are N/(mm um) per mm of face width; 1 N/(mm um) = 1e9 N/m per
//! metre of face width. The stiffness acts along the transverse line of
//! action (the helical factor cos(beta) is part of c').

use super::geometry::GearPair;
use crate::error::{in_range, positive, Result};

/// ISO 6336-1 Method B constants C1..C9 of the flexibility q' [mm um / N].
pub const Q_COEFFS: [f64; 9] = [
    0.04723, 0.15551, 0.25791, -0.00635, -0.11654, -0.00193, -0.24188, 0.00529, 0.00182,
];

/// Theory-to-measurement correction factor C_M (ISO 6336-1).
pub const C_M: f64 = 0.8;

/// 1 N/(mm um) in N/m per metre of face width.
pub const N_PER_MM_UM: f64 = 1e9;

/// Gear blank description for the factor C_R.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum GearBlank {
    /// Solid disc gear (C_R = 1).
    Solid,
    /// Webbed blank: web thickness / face width b_s/b, rim thickness / normal
    /// module s_R/m_n.
    Webbed {
        /// Web thickness over face width b_s/b [-]; clamped to [0.2, 1.2].
        web_to_face_ratio: f64,
        /// Rim thickness over normal module s_R/m_n [-]; values below 1 are
        /// taken as 1.
        rim_to_module_ratio: f64,
    },
}

/// Options of the ISO 6336-1 Method B stiffness.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IsoStiffnessOptions {
    /// Gear blank (default solid).
    pub blank: GearBlank,
    /// Application factor K_A for the line-load correction (default 1).
    pub application_factor: f64,
    /// Apply the light-load factor (K_A F_t/b / 100)^0.25 when K_A F_t / b <
    /// 100 N/mm (default true; F_t from the pair's input torque).
    pub light_load_correction: bool,
}

impl Default for IsoStiffnessOptions {
    fn default() -> Self {
        IsoStiffnessOptions {
            blank: GearBlank::Solid,
            application_factor: 1.0,
            light_load_correction: true,
        }
    }
}

/// ISO 6336-1 Method B stiffness of a pair; values in N/(mm um) and SI.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct IsoStiffness {
    /// Flexibility q' [mm um / N].
    pub flexibility_q: f64,
    /// Theoretical single stiffness c'_th [N/(mm um)].
    pub theoretical_single_n_per_mm_um: f64,
    /// C_R.
    pub blank_factor: f64,
    /// C_B.
    pub basic_rack_factor: f64,
    /// Line-load factor (1 when not applied).
    pub load_factor: f64,
    /// Single stiffness c' [N/(mm um)].
    pub single_n_per_mm_um: f64,
    /// Mesh stiffness c_gamma_alpha [N/(mm um)].
    pub mesh_alpha_n_per_mm_um: f64,
    /// Mesh stiffness c_gamma_beta [N/(mm um)].
    pub mesh_beta_n_per_mm_um: f64,
    /// Face width b \[m\] used for the totals.
    pub face_width_m: f64,
}

impl IsoStiffness {
    /// Single stiffness c' per metre of face width [N/m per m].
    pub fn single_n_per_m_per_m(&self) -> f64 {
        self.single_n_per_mm_um * N_PER_MM_UM
    }
    /// c_gamma_alpha per metre of face width [N/m per m].
    pub fn mesh_alpha_n_per_m_per_m(&self) -> f64 {
        self.mesh_alpha_n_per_mm_um * N_PER_MM_UM
    }
    /// Total mesh stiffness c_gamma_alpha b [N/m].
    pub fn mesh_alpha_n_per_m(&self) -> f64 {
        self.mesh_alpha_n_per_m_per_m() * self.face_width_m
    }
    /// Total mesh stiffness c_gamma_beta b [N/m].
    pub fn mesh_beta_n_per_m(&self) -> f64 {
        self.mesh_beta_n_per_mm_um * N_PER_MM_UM * self.face_width_m
    }
}

/// q' from the virtual tooth numbers and profile shifts (ISO 6336-1 Method B).
pub fn flexibility_q(zn1: f64, zn2: f64, x1: f64, x2: f64) -> Result<f64> {
    positive("virtual_teeth_pinion", zn1)?;
    positive("virtual_teeth_gear", zn2)?;
    let c = Q_COEFFS;
    let q = c[0]
        + c[1] / zn1
        + c[2] / zn2
        + c[3] * x1
        + c[4] * x1 / zn1
        + c[5] * x2
        + c[6] * x2 / zn2
        + c[7] * x1 * x1
        + c[8] * x2 * x2;
    positive("iso6336_flexibility_q", q)
}

/// C_R for a gear blank.
pub fn blank_factor(blank: GearBlank) -> Result<f64> {
    match blank {
        GearBlank::Solid => Ok(1.0),
        GearBlank::Webbed {
            web_to_face_ratio,
            rim_to_module_ratio,
        } => {
            let bs = positive("web_to_face_ratio", web_to_face_ratio)?.clamp(0.2, 1.2);
            let sr = positive("rim_to_module_ratio", rim_to_module_ratio)?.max(1.0);
            Ok(1.0 + bs.ln() / (5.0 * (sr / 5.0).exp()))
        }
    }
}

/// C_B for a basic rack of dedendum coefficient hf* and pressure angle alpha_Pn \[rad\].
pub fn basic_rack_factor(dedendum_coeff: f64, rack_pressure_angle_rad: f64) -> f64 {
    (1.0 + 0.5 * (1.2 - dedendum_coeff)) * (1.0 - 0.02 * (20.0 - rack_pressure_angle_rad.to_degrees()))
}

/// ISO 6336-1 Method B single and mesh stiffness of a pair.
pub fn iso_stiffness(pair: &GearPair, opts: &IsoStiffnessOptions) -> Result<IsoStiffness> {
    let g = &pair.geometry;
    let s = &pair.spec;
    in_range("application_factor", opts.application_factor, 1.0, 4.0)?;
    let q = flexibility_q(
        g.virtual_teeth[0],
        g.virtual_teeth[1],
        s.wheels[0].profile_shift_coeff,
        s.wheels[1].profile_shift_coeff,
    )?;
    let cth = 1.0 / q;
    let cr = blank_factor(opts.blank)?;
    let cb = basic_rack_factor(s.dedendum_coeff, s.normal_pressure_angle_rad);
    // Material: ISO scales c' by E / E_steel for other materials; E_steel =
    // 206,000 N/mm^2 (ISO 6336-1, steel/steel reference).
    let material = s.youngs_modulus_pa / 206e9;
    let line_load_n_per_mm = opts.application_factor * pair.tooth_forces().tangential_n / (s.face_width_m * 1e3);
    let load_factor = if opts.light_load_correction && line_load_n_per_mm < 100.0 {
        (line_load_n_per_mm / 100.0).max(0.0).powf(0.25)
    } else {
        1.0
    };
    let c1 = cth * C_M * cr * cb * s.helix_angle_rad.cos() * material * load_factor;
    let cga = c1 * (0.75 * g.transverse_contact_ratio + 0.25);
    Ok(IsoStiffness {
        flexibility_q: q,
        theoretical_single_n_per_mm_um: cth,
        blank_factor: cr,
        basic_rack_factor: cb,
        load_factor,
        single_n_per_mm_um: c1,
        mesh_alpha_n_per_mm_um: cga,
        mesh_beta_n_per_mm_um: 0.85 * cga,
        face_width_m: s.face_width_m,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gear::geometry::tests::kisssoft_nrel_stage3;

    /// KISSsoft 03/2017, ISO 6336:2006 Method B, report `@NREL_5MW/stage_03.rtf`
    /// of github.com/gfsReboucas/Drivetrain: CM 0.800, CR 0.898 (bs/b = 0.25,
    /// sr/mn = 5), CBS 0.975, c' = 13.832, cgalf = 18.632, cgbet = 15.837
    /// N/(mm um), line load 666.85 N/mm (no light-load factor).
    #[test]
    fn kisssoft_worked_example() {
        let pair = GearPair::new(kisssoft_nrel_stage3()).unwrap();
        let opts = IsoStiffnessOptions {
            blank: GearBlank::Webbed {
                web_to_face_ratio: 0.25,
                rim_to_module_ratio: 5.0,
            },
            ..Default::default()
        };
        let k = iso_stiffness(&pair, &opts).unwrap();
        assert!((k.blank_factor - 0.898).abs() < 5e-4, "{}", k.blank_factor);
        assert!((k.basic_rack_factor - 0.975).abs() < 1e-12);
        assert_eq!(k.load_factor, 1.0);
        assert!((k.single_n_per_mm_um - 13.832).abs() < 2e-3, "{}", k.single_n_per_mm_um);
        assert!(
            (k.mesh_alpha_n_per_mm_um - 18.632).abs() < 0.01,
            "{}",
            k.mesh_alpha_n_per_mm_um
        );
        assert!((k.mesh_beta_n_per_mm_um - 15.837).abs() < 0.01);
        // SI conversion: 1 N/(mm um) = 1e9 N/m^2; total = per width x b.
        assert!((k.mesh_alpha_n_per_m() - k.mesh_alpha_n_per_mm_um * 1e9 * 0.36).abs() < 1.0);
    }

    #[test]
    fn basic_rack_limits() {
        // ISO 53 profile A (hf* = 1.25, 20 deg): 0.975; hf* = 1.2, 20 deg: 1.
        assert!((basic_rack_factor(1.25, 20f64.to_radians()) - 0.975).abs() < 1e-12);
        assert!((basic_rack_factor(1.2, 20f64.to_radians()) - 1.0).abs() < 1e-12);
        assert_eq!(blank_factor(GearBlank::Solid).unwrap(), 1.0);
        // b_s/b = 1 means a solid blank: ln 1 = 0.
        let full = GearBlank::Webbed {
            web_to_face_ratio: 1.0,
            rim_to_module_ratio: 3.0,
        };
        assert!((blank_factor(full).unwrap() - 1.0).abs() < 1e-15);
    }

    #[test]
    fn rack_limit_of_flexibility() {
        // Unshifted rack-rack limit (z_n -> infinity): q' = C1, c'_th = 21.17 N/(mm um).
        let q = flexibility_q(1e12, 1e12, 0.0, 0.0).unwrap();
        assert!((1.0 / q - 1.0 / 0.04723).abs() < 1e-6);
        assert!(flexibility_q(0.0, 30.0, 0.0, 0.0).is_err());
    }

    #[test]
    fn seed_pair_light_load() {
        let pair = GearPair::preset("seed-electric-drive").unwrap();
        let k = iso_stiffness(&pair, &IsoStiffnessOptions::default()).unwrap();
        // Ft = 100 N m / 26.05 mm = 3838 N over 33 mm = 116 N/mm: no light-load factor.
        assert_eq!(k.load_factor, 1.0);
        // Half the torque: 58 N/mm, factor (0.58)^0.25.
        let mut s = pair.spec.clone();
        s.input_torque_n_m = 50.0;
        let half = GearPair::new(s).unwrap();
        let kh = iso_stiffness(&half, &IsoStiffnessOptions::default()).unwrap();
        let w = 0.5 * pair.tooth_forces().tangential_n / 33.0;
        assert!((kh.load_factor - (w / 100.0).powf(0.25)).abs() < 1e-12);
    }
}
