//! Bearing friction heat (docs/concepts/physics.md §4, eqs;
//! Palmgren's empirical moments as given by Harris & Kotzalas, *Rolling
//! Bearing Analysis*, 4th/5th ed., chapter "Friction in rolling bearings").
//!
//! Everything here takes plain per-bearing or per-contact numbers (loads,
//! contact angle, Hertz semi-major axes, elliptic integrals, spin speeds) so
//! that the quasi-static solver can feed it without sharing structs.
//!
//! * Load moment: `M1 = f1 P1 dm`, `f1 = z (P0 / C0)^y`.
//!   Harris' table of z and y: radial deep-groove ball bearing z = 0.0004 to
//!   0.0006, y = 0.55; angular-contact ball bearing z = 0.001, y = 0.33
//!   (also: thrust ball z = 0.0008, y = 0.33; self-aligning z = 0.0003,
//!   y = 0.40). We use z = 0.0005 (mid range) for deep-groove bearings.
//!   P1 (Harris): deep-groove `0.9 Fa cot(alpha) - 0.1 Fr`; single-row
//!   angular-contact `Fa - 0.1 Fr`; in both cases P1 >= Fr.
//!   docs/concepts/physics.md §4 quotes the deep-groove form for "ball
//!   bearings"; Harris uses the angular-contact form for 7000-series
//!   bearings and so do we.
//!   P0 is the ISO 76 static equivalent load `max(X0 Fr + Y0 Fa, Fr)`.
//! * Static load rating C0 (ISO 76:2006, radial ball bearings):
//!   `C0 = f0 i Z D^2 cos(alpha)` [N with D in mm], f0 tabulated against
//!   `D cos(alpha) / dm` (column for radial and angular-contact groove ball
//!   bearings, groove radii <= 0.52 D inner / 0.53 D outer).
//! * Viscous moment: `Mv = 1e-7 f0 (nu n)^(2/3) dm^3` if nu n >= 2000,
//!   else `160e-7 f0 dm^3` (nu cSt, n rpm, dm mm, Mv N mm). The two branches
//!   do not meet: at nu n = 2000, (2000)^(2/3) = 158.74 < 160, so the moment
//!   drops by 0.79 % when nu n crosses 2000 upwards. We keep Palmgren's
//!   published constants and document the step (tested).
//!   f0 (lubrication factor): oil mist / oil-air 1-2, oil bath 2-4
//!   (docs/concepts/physics.md §4; Harris table: deep groove oil mist 1,
//!   oil bath 2; angular contact oil mist 1.7, oil bath 3.3).
//! * Spin moment per contact: `Ms = (3/8) mu_s Q a E(kappa)`.
//! * Heat: `H = omega (M1 + Mv) + sum_j (|omega_si| Msi + |omega_so| Mso)`.
//! * Split (A-27, Burton & Staph): the rolling part omega (M1 + Mv) goes
//!   1/4 to the inner ring, 1/4 to the outer ring and 1/2 to the balls; the
//!   inner-contact spin heat goes 1/2 to the inner ring and 1/2 to the balls,
//!   the outer-contact spin heat 1/2 to the outer ring and 1/2 to the balls.
//! * Ball drag ("churning") in the oil-air mixture of the cage cavity
//!   (Harris & Kotzalas, *Rolling Bearing Analysis*, 5th ed., vol. 2
//!   *Advanced Concepts of Bearing Technology*, high-speed ball bearings,
//!   ball drag force in the oil-air mixture): each ball's centre moves
//!   at v = dm omega_c / 2 through a mixture of effective density
//!   rho_eff = X rho_oil (X the oil volume fraction of the cavity air), so
//!   `F_D = 0.5 rho_eff C_D (pi D^2 / 4) v^2 = (pi/32) C_D rho_eff D^2 (dm omega_c)^2`
//!   and the bearing dissipates `P = Z F_D v = Z (pi/64) C_D X rho_oil D^2 dm^3 omega_c^3`,
//!   see [`ball_drag_power_w`]. We use the plain quadratic drag law
//!   (dimensionally consistent; an empirical correction of the speed
//!   exponent would be absorbed by X). Not part of seed A's heat: a
//!   calibration term, off unless X > 0.

use crate::bearing::{BearingGeometry, BearingType};
use crate::error::{finite, in_range, non_negative, positive, Error, Result};

/// ISO 76:2006 Table (radial ball bearings, deep-groove and angular-contact
/// column): factor f0 against gamma = D cos(alpha) / dm, in steps of 0.01.
const ISO76_F0: [f64; 41] = [
    14.7, 14.9, 15.1, 15.3, 15.5, 15.7, 15.9, 16.1, 16.3, 16.5, 16.4, 16.1, 15.9, 15.6, 15.4, 15.2, 14.9, 14.7, 14.4,
    14.2, 14.0, 13.7, 13.5, 13.2, 13.0, 12.8, 12.5, 12.3, 12.1, 11.8, 11.6, 11.4, 11.2, 10.9, 10.7, 10.5, 10.3, 10.0,
    9.8, 9.6, 9.4,
];

/// ISO 76 factor f0 for radial ball bearings at gamma = D cos(alpha)/dm,
/// linearly interpolated in the table (0 <= gamma <= 0.40).
pub fn iso76_f0(gamma: f64) -> Result<f64> {
    finite("ball_pitch_ratio", gamma)?;
    if !(0.0..=0.40).contains(&gamma) {
        return Err(Error::config(
            "ball_pitch_ratio",
            gamma,
            "ISO 76 tabulates f0 for D cos(alpha)/dm in [0, 0.40]",
        ));
    }
    let x = gamma * 100.0;
    let i = (x.floor() as usize).min(ISO76_F0.len() - 2);
    let t = x - i as f64;
    Ok(ISO76_F0[i] + t * (ISO76_F0[i + 1] - ISO76_F0[i]))
}

/// Basic static radial load rating C0 of a single-row radial ball bearing
/// (ISO 76: C0 = f0 i Z D^2 cos(alpha), N with D in mm, i = 1 row) \[N\].
pub fn static_load_rating_n(geometry: &BearingGeometry) -> Result<f64> {
    let alpha = geometry.free_contact_angle_rad;
    let d_mm = geometry.ball_diameter_m * 1e3;
    let gamma = geometry.ball_diameter_m * alpha.cos() / geometry.pitch_diameter_m;
    let f0 = iso76_f0(gamma)?;
    Ok(f0 * geometry.ball_count as f64 * d_mm * d_mm * alpha.cos())
}

/// ISO 76 static equivalent radial load P0 = max(X0 Fr + Y0 Fa, Fr) \[N\].
/// X0, Y0: deep-groove 0.6 / 0.5; single-row angular-contact 0.5 and Y0 by
/// nominal contact angle 15/20/25/30/35/40/45 deg -> 0.46/0.42/0.38/0.33/
/// 0.29/0.26/0.22 (linear between table angles).
pub fn static_equivalent_load_n(geometry: &BearingGeometry, axial_n: f64, radial_n: f64) -> Result<f64> {
    non_negative("axial_load_n", axial_n)?;
    non_negative("radial_load_n", radial_n)?;
    let (x0, y0) = match geometry.bearing_type {
        BearingType::DeepGroove => (0.6, 0.5),
        BearingType::AngularContact => {
            const ANGLES: [f64; 7] = [15.0, 20.0, 25.0, 30.0, 35.0, 40.0, 45.0];
            const Y0: [f64; 7] = [0.46, 0.42, 0.38, 0.33, 0.29, 0.26, 0.22];
            let a = geometry.free_contact_angle_rad.to_degrees().clamp(15.0, 45.0);
            let i = (((a - 15.0) / 5.0).floor() as usize).min(5);
            let t = (a - ANGLES[i]) / 5.0;
            (0.5, Y0[i] + t * (Y0[i + 1] - Y0[i]))
        }
    };
    Ok((x0 * radial_n + y0 * axial_n).max(radial_n))
}

/// Palmgren load-friction constants z, y of f1 = z (P0/C0)^y.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadFrictionConstants {
    /// Coefficient z [-] (Harris: deep-groove 0.0004 to 0.0006, angular-contact 0.001).
    pub z: f64,
    /// Exponent y of the load ratio P0/C0 [-] (Harris: deep-groove 0.55, angular-contact 0.33).
    pub y: f64,
}

impl LoadFrictionConstants {
    /// Harris & Kotzalas' table values (see module docs).
    pub fn harris(bearing_type: BearingType) -> Self {
        match bearing_type {
            BearingType::DeepGroove => LoadFrictionConstants { z: 0.0005, y: 0.55 },
            BearingType::AngularContact => LoadFrictionConstants { z: 0.001, y: 0.33 },
        }
    }
}

/// Load-dependent friction factor f1 = z (P0/C0)^y [-].
pub fn load_friction_factor(constants: LoadFrictionConstants, p0_n: f64, c0_n: f64) -> Result<f64> {
    non_negative("static_equivalent_load_n", p0_n)?;
    positive("static_load_rating_n", c0_n)?;
    Ok(constants.z * (p0_n / c0_n).powf(constants.y))
}

/// Load of the friction moment P1 (Harris) \[N\]; `contact_angle_rad` is the
/// operating contact angle (needed for deep-groove bearings under thrust).
pub fn friction_load_p1_n(
    bearing_type: BearingType,
    axial_n: f64,
    radial_n: f64,
    contact_angle_rad: f64,
) -> Result<f64> {
    non_negative("axial_load_n", axial_n)?;
    non_negative("radial_load_n", radial_n)?;
    finite("contact_angle_deg", contact_angle_rad.to_degrees())?;
    let p1 = match bearing_type {
        BearingType::DeepGroove => {
            if axial_n == 0.0 {
                0.0
            } else {
                let s = contact_angle_rad.sin();
                if s <= 1e-6 {
                    return Err(Error::config(
                        "contact_angle_deg",
                        contact_angle_rad.to_degrees(),
                        "a thrust-loaded deep-groove bearing needs a contact angle above zero",
                    ));
                }
                0.9 * axial_n * contact_angle_rad.cos() / s - 0.1 * radial_n
            }
        }
        BearingType::AngularContact => axial_n - 0.1 * radial_n,
    };
    Ok(p1.max(radial_n))
}

/// Load friction moment M1 = f1 P1 dm with Harris' z, y and the
/// ISO 76 rating of `geometry` [N m].
pub fn load_moment_n_m(geometry: &BearingGeometry, axial_n: f64, radial_n: f64, contact_angle_rad: f64) -> Result<f64> {
    let c0 = static_load_rating_n(geometry)?;
    let p0 = static_equivalent_load_n(geometry, axial_n, radial_n)?;
    let f1 = load_friction_factor(LoadFrictionConstants::harris(geometry.bearing_type), p0, c0)?;
    let p1 = friction_load_p1_n(geometry.bearing_type, axial_n, radial_n, contact_angle_rad)?;
    Ok(f1 * p1 * geometry.pitch_diameter_m)
}

/// Viscous friction moment Mv (A-21) [N m]. Palmgren's formula is in
/// N mm with nu in cSt, n in rpm and dm in mm; the conversion happens here.
pub fn viscous_moment_n_m(
    lubrication_factor_f0: f64,
    kinematic_viscosity_cst: f64,
    speed_rpm: f64,
    pitch_diameter_m: f64,
) -> Result<f64> {
    positive("lubrication_factor_f0", lubrication_factor_f0)?;
    positive("kinematic_viscosity_cst", kinematic_viscosity_cst)?;
    non_negative("speed_rpm", speed_rpm)?;
    let dm_mm = positive("pitch_diameter_mm", pitch_diameter_m * 1e3)?;
    let nu_n = kinematic_viscosity_cst * speed_rpm;
    let m_nmm = if nu_n >= 2000.0 {
        1e-7 * lubrication_factor_f0 * nu_n.powf(2.0 / 3.0) * dm_mm.powi(3)
    } else {
        160e-7 * lubrication_factor_f0 * dm_mm.powi(3)
    };
    Ok(m_nmm * 1e-3)
}

/// Spin friction moment of one contact Ms = (3/8) mu_s Q a E(kappa)
/// [N m]; `elliptic_e` is the complete elliptic integral of the second kind.
pub fn spin_moment_n_m(spin_friction_coefficient: f64, load_n: f64, semi_major_m: f64, elliptic_e: f64) -> f64 {
    0.375 * spin_friction_coefficient * load_n * semi_major_m * elliptic_e
}

/// One ball-raceway contact as seen by the heat model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpinContact {
    /// Normal contact load Q \[N\].
    pub load_n: f64,
    /// Hertz semi-major axis a \[m\].
    pub semi_major_m: f64,
    /// Complete elliptic integral of the second kind E(kappa) [-].
    pub elliptic_e: f64,
    /// Spin speed of the ball relative to the raceway, omega_s [rad/s].
    pub spin_speed_rad_s: f64,
}

/// Heat generated in one bearing, by mechanism \[W\].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BearingHeat {
    /// omega (M1 + Mv) \[W\].
    pub rolling_w: f64,
    /// Sum over inner contacts of |omega_si| Msi \[W\].
    pub inner_spin_w: f64,
    /// Sum over outer contacts of |omega_so| Mso \[W\].
    pub outer_spin_w: f64,
}

/// Heat delivered to each part \[W\].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeatSplit {
    /// Heat into the inner ring: 1/4 of the rolling heat + 1/2 of the inner spin heat \[W\].
    pub inner_ring_w: f64,
    /// Heat into the balls (all of them): 1/2 of the rolling heat + 1/2 of all spin heat \[W\].
    pub balls_w: f64,
    /// Heat into the outer ring: 1/4 of the rolling heat + 1/2 of the outer spin heat \[W\].
    pub outer_ring_w: f64,
}

impl BearingHeat {
    /// Total heat H \[W\].
    pub fn total_w(&self) -> f64 {
        self.rolling_w + self.inner_spin_w + self.outer_spin_w
    }

    /// Burton-Staph split: rolling heat 1/4 inner ring, 1/2 balls,
    /// 1/4 outer ring; each contact's spin heat half to its ring, half to
    /// the balls.
    pub fn split(&self) -> HeatSplit {
        HeatSplit {
            inner_ring_w: 0.25 * self.rolling_w + 0.5 * self.inner_spin_w,
            balls_w: 0.5 * self.rolling_w + 0.5 * (self.inner_spin_w + self.outer_spin_w),
            outer_ring_w: 0.25 * self.rolling_w + 0.5 * self.outer_spin_w,
        }
    }
}

/// Drag coefficient of a smooth sphere in the subcritical Reynolds range
/// (about 1e3 < Re < 2e5, laminar boundary layer separating ahead of the
/// equator): C_D = 0.47 (F. M. White, *Fluid Mechanics*, drag of
/// three-dimensional bodies, sphere with a laminar boundary layer; the
/// sphere drag curve is flat at 0.4..0.5 in this range, Schlichting,
/// *Boundary-Layer Theory*). Assumption: a ball orbiting at v = dm
/// omega_c / 2 of 5..40 m/s with D ~ 8..13 mm has Re = v D / nu ~ 1e3..3e4
/// in air (nu ~ 1.6e-5 m^2/s) as in light oil (nu ~ 1e-5..3e-5 m^2/s), so
/// subcritical at every speed of interest; cage-pocket crowding and the
/// wake of the ball ahead are not modelled (they are what the calibrated
/// oil fraction absorbs).
pub const SPHERE_DRAG_COEFFICIENT: f64 = 0.47;

/// Drag ("churning") power of the balls orbiting through the oil-air
/// mixture of the bearing cavity \[W\] (Harris & Kotzalas, ball drag; module
/// docs): per ball `F_D = (pi/32) C_D rho_eff D^2 (dm omega_c)^2` with
/// `rho_eff = X rho_oil`, power `F_D v` at the ball-centre speed
/// `v = dm |omega_c| / 2`, times the ball count Z:
/// `P = Z (pi/64) C_D X rho_oil D^2 dm^3 |omega_c|^3`.
///
/// `oil_volume_fraction` X is the oil volume fraction of the cavity
/// mixture (0..1, dimensionless); `drag_coefficient` C_D, e.g.
/// [`SPHERE_DRAG_COEFFICIENT`].
pub fn ball_drag_power_w(
    ball_count: usize,
    ball_diameter_m: f64,
    pitch_diameter_m: f64,
    cage_speed_rad_s: f64,
    oil_density_kg_m3: f64,
    oil_volume_fraction: f64,
    drag_coefficient: f64,
) -> Result<f64> {
    positive("ball_diameter_m", ball_diameter_m)?;
    positive("pitch_diameter_m", pitch_diameter_m)?;
    finite("cage_speed_rad_s", cage_speed_rad_s)?;
    positive("oil_density_kg_m3", oil_density_kg_m3)?;
    in_range("oil_volume_fraction", oil_volume_fraction, 0.0, 1.0)?;
    non_negative("drag_coefficient", drag_coefficient)?;
    let rho_eff = oil_volume_fraction * oil_density_kg_m3;
    let v = 0.5 * pitch_diameter_m * cage_speed_rad_s.abs();
    let force_n = std::f64::consts::PI / 32.0
        * drag_coefficient
        * rho_eff
        * ball_diameter_m
        * ball_diameter_m
        * (pitch_diameter_m * cage_speed_rad_s).powi(2);
    Ok(ball_count as f64 * force_n * v)
}

fn spin_heat(field: &str, spin_friction_coefficient: f64, contacts: &[SpinContact]) -> Result<f64> {
    let mut h = 0.0;
    for (j, c) in contacts.iter().enumerate() {
        non_negative(&format!("{field}[{j}].load_n"), c.load_n)?;
        non_negative(&format!("{field}[{j}].semi_major_m"), c.semi_major_m)?;
        positive(&format!("{field}[{j}].elliptic_e"), c.elliptic_e)?;
        finite(&format!("{field}[{j}].spin_speed_rad_s"), c.spin_speed_rad_s)?;
        h += c.spin_speed_rad_s.abs()
            * spin_moment_n_m(spin_friction_coefficient, c.load_n, c.semi_major_m, c.elliptic_e);
    }
    Ok(h)
}

/// Heat of one bearing: `speed_rad_s` is the ring relative speed
/// omega, the moments come from [`load_moment_n_m`] and
/// [`viscous_moment_n_m`], `spin_friction_coefficient` is mu_s, and the contact slices
/// hold one entry per ball (may be empty when no quasi-static solution is
/// available: then only the rolling heat is counted).
pub fn bearing_heat(
    speed_rad_s: f64,
    load_moment_n_m: f64,
    viscous_moment_n_m: f64,
    spin_friction_coefficient: f64,
    inner_contacts: &[SpinContact],
    outer_contacts: &[SpinContact],
) -> Result<BearingHeat> {
    finite("speed_rad_s", speed_rad_s)?;
    non_negative("load_moment_n_m", load_moment_n_m)?;
    non_negative("viscous_moment_n_m", viscous_moment_n_m)?;
    non_negative("spin_friction_coefficient", spin_friction_coefficient)?;
    Ok(BearingHeat {
        rolling_w: speed_rad_s.abs() * (load_moment_n_m + viscous_moment_n_m),
        inner_spin_w: spin_heat("inner_contacts", spin_friction_coefficient, inner_contacts)?,
        outer_spin_w: spin_heat("outer_contacts", spin_friction_coefficient, outer_contacts)?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearing::Bearing;
    use crate::units::rpm_to_rad_s;

    fn contacts(n: usize, q: f64, ws: f64) -> Vec<SpinContact> {
        (0..n)
            .map(|j| SpinContact {
                load_n: q * (1.0 + 0.1 * j as f64),
                semi_major_m: 1e-3,
                elliptic_e: 1.1,
                spin_speed_rad_s: ws,
            })
            .collect()
    }

    #[test]
    fn split_sums_to_total_and_follows_burton_staph() {
        let h = bearing_heat(
            1000.0,
            0.05,
            0.03,
            0.1,
            &contacts(9, 300.0, 200.0),
            &contacts(9, 350.0, -80.0),
        )
        .unwrap();
        let s = h.split();
        let sum = s.inner_ring_w + s.balls_w + s.outer_ring_w;
        assert!((sum - h.total_w()).abs() < 1e-12 * h.total_w());
        // Without spin: 1/4, 1/2, 1/4 of omega (M1 + Mv) = 80 W.
        let r = bearing_heat(1000.0, 0.05, 0.03, 0.1, &[], &[]).unwrap().split();
        assert!((r.inner_ring_w - 20.0).abs() < 1e-12 && (r.balls_w - 40.0).abs() < 1e-12);
        // Spin heat is the sum of |omega_s| (3/8) mu Q a E.
        let c = contacts(1, 100.0, -50.0);
        let h = bearing_heat(0.0, 0.0, 0.0, 0.2, &c, &[]).unwrap();
        assert!((h.total_w() - 50.0 * 0.375 * 0.2 * 100.0 * 1e-3 * 1.1).abs() < 1e-15);
    }

    #[test]
    fn viscous_moment_hand_value_and_regime_step() {
        // f0 = 2, nu = 20 cSt, n = 10000 rpm, dm = 60 mm:
        // 1e-7 * 2 * (2e5)^(2/3) * 60^3 N mm = 147.74 N mm.
        let m = viscous_moment_n_m(2.0, 20.0, 10_000.0, 0.060).unwrap();
        let hand = 1e-7 * 2.0 * 2e5f64.powf(2.0 / 3.0) * 216_000.0 * 1e-3;
        assert!((m - hand).abs() < 1e-12 && (m - 0.14774).abs() < 1e-4, "{m}");
        // Documented step at nu n = 2000: high branch 0.79 % below the low one.
        let below = viscous_moment_n_m(1.5, 20.0, 99.999, 0.05).unwrap();
        let above = viscous_moment_n_m(1.5, 20.0, 100.0, 0.05).unwrap();
        let step = 1.0 - above / below;
        assert!((step - (1.0 - 2000f64.powf(2.0 / 3.0) / 160.0)).abs() < 1e-6 && (step - 0.00786).abs() < 1e-4);
    }

    #[test]
    fn scaling_laws() {
        // Mv ~ n^(2/3) at fixed viscosity, so heat omega Mv ~ n^(5/3).
        let h = |n: f64| rpm_to_rad_s(n) * viscous_moment_n_m(1.5, 10.0, n, 0.06).unwrap();
        let ratio = h(16_000.0) / h(8_000.0);
        assert!((ratio - 2f64.powf(5.0 / 3.0)).abs() < 1e-12);
        // Angular contact: f1 ~ P0^0.33 and P1 = Fa, so M1 ~ Fa^1.33 under thrust.
        let g = Bearing::preset("7009C").unwrap().geometry;
        let a = g.free_contact_angle_rad;
        let m1 = |fa: f64| load_moment_n_m(&g, fa, 0.0, a).unwrap();
        assert!((m1(800.0) / m1(400.0) - 2f64.powf(1.33)).abs() < 1e-12);
        // Spin heat is linear in Q.
        let s = |q: f64| {
            bearing_heat(0.0, 0.0, 0.0, 0.1, &contacts(5, q, 30.0), &[])
                .unwrap()
                .total_w()
        };
        assert!((s(600.0) / s(200.0) - 3.0).abs() < 1e-12);
    }

    #[test]
    fn iso76_static_rating_of_a_6208() {
        // A catalogue 6208 has 9 balls of 1/2 in (12.7 mm) on dm = 60 mm;
        // SKF lists C0 = 19.0 kN. ISO 76 with gamma = 0.2117 -> f0 = 13.73:
        // 13.73 * 9 * 12.7^2 = 19.93 kN (within catalogue rounding, 5 %).
        let g = BearingGeometry::deep_groove(9, 12.7e-3, 60e-3, 0.52, 0.53, 0.02e-3, 40e-3, 80e-3, 18e-3).unwrap();
        let c0 = static_load_rating_n(&g).unwrap();
        assert!((c0 - 19_000.0).abs() / 19_000.0 < 0.06, "{c0}");
        // Table endpoints and interpolation.
        assert_eq!(iso76_f0(0.0).unwrap(), 14.7);
        assert!((iso76_f0(0.095).unwrap() - 16.45).abs() < 1e-12);
        assert!(iso76_f0(0.45).is_err());
    }

    #[test]
    fn p1_rules() {
        // Radial load only: P1 = Fr for both types.
        assert_eq!(
            friction_load_p1_n(BearingType::DeepGroove, 0.0, 500.0, 0.0).unwrap(),
            500.0
        );
        // Deep groove under thrust needs a contact angle.
        assert!(friction_load_p1_n(BearingType::DeepGroove, 100.0, 0.0, 0.0).is_err());
        let p = friction_load_p1_n(BearingType::DeepGroove, 1000.0, 100.0, 0.26).unwrap();
        assert!((p - (0.9 * 1000.0 / 0.26f64.tan() - 10.0)).abs() < 1e-9);
        assert_eq!(
            friction_load_p1_n(BearingType::AngularContact, 300.0, 100.0, 0.26).unwrap(),
            290.0
        );
    }

    #[test]
    fn ball_drag_power_closed_form_and_scaling() {
        // Z = 10 balls of D = 10 mm on dm = 50 mm, omega_c = 1000 rad/s,
        // rho_oil = 850 kg/m^3, X = 0.02, C_D = 0.5. By hand: v = 25 m/s,
        // rho_eff = 17 kg/m^3, frontal area pi D^2 / 4 = 7.8540e-5 m^2,
        // F_D = 0.5 * 17 * 0.5 * 7.8540e-5 * 625 = 0.208622 N,
        // P = 10 * 0.208622 * 25 = 52.1553 W.
        let p = |z: usize, w: f64, x: f64| ball_drag_power_w(z, 0.010, 0.050, w, 850.0, x, 0.5).unwrap();
        let hand = 52.1553;
        assert!((p(10, 1000.0, 0.02) - hand).abs() < 1e-4, "{}", p(10, 1000.0, 0.02));
        // Cubic in the cage speed (the sign of omega_c does not matter).
        assert!((p(10, 2000.0, 0.02) / p(10, 1000.0, 0.02) - 8.0).abs() < 1e-12);
        assert!((p(10, -1000.0, 0.02) - p(10, 1000.0, 0.02)).abs() < 1e-12);
        // Linear in X and in Z; nothing at X = 0 (dry air neglected).
        assert!((p(10, 1000.0, 0.06) / p(10, 1000.0, 0.02) - 3.0).abs() < 1e-12);
        assert!((p(5, 1000.0, 0.02) / p(10, 1000.0, 0.02) - 0.5).abs() < 1e-12);
        assert_eq!(p(10, 1000.0, 0.0), 0.0);
        // Out-of-range fraction names its field.
        for x in [-0.1, 1.5, f64::NAN] {
            match ball_drag_power_w(10, 0.01, 0.05, 1000.0, 850.0, x, 0.5) {
                Err(Error::Config { field, .. }) => assert_eq!(field, "oil_volume_fraction"),
                other => panic!("{x}: {other:?}"),
            }
        }
    }
}
