//! Ball bearings: geometry, Hertz contact, statics, high-speed quasi-statics
//! and stiffness.
//!
//! * [`model`]: coordinates (ISO/TS 16281), [`BearingModel`] (a bearing
//!   prepared for the solvers), [`RacewayOffsets`] (thermal/fit offsets).
//! * [`statics`]: zero-speed solve and the thrust-only contact angle (A-4).
//! * [`quasi_static`]: Jones-Harris high-speed solve and the forward map
//!   q -> ring forces ([`BearingModel::ring_forces`]) for dynamics.
//! * [`kinematics`]: raceway-control kinematics and the derivation of the
//!   gyroscopic friction-couple sign.
//! * [`stiffness`]: the seed's axial/radial stiffness (A-39..A-42); the full
//!   5x5 matrix is part of every [`BearingState`].
//! * [`sweep`]: parallel speed sweeps and stiffness curves.
//! * [`batch`]: many operating points in one call, one result per point.
//!
//! ```
//! use thermobear::bearing::{BearingLoad, BearingModel, SolveOptions, stiffness_curve};
//! use thermobear::Bearing;
//!
//! let b = Bearing::preset("6208").unwrap();
//! // Seed A's 100 N m case with 300 N preload, at 16,000 rpm.
//! let s = b.solve(BearingLoad::new(2680.9, 1189.9, 0.0), 16_000.0, &SolveOptions::default()).unwrap();
//! assert!(s.balls.iter().all(|ball| ball.outer_load_n > ball.inner_load_n));
//! let m = BearingModel::new(&b).unwrap();
//! let curve = stiffness_curve(&m, &[6_500.0, 16_500.0], 2680.9, 1189.9, &SolveOptions::default()).unwrap();
//! assert!(curve[1].axial_stiffness_seed_n_per_m < curve[0].axial_stiffness_seed_n_per_m);
//! ```

pub mod batch;
pub mod contact;
pub mod dual;
pub mod geometry;
pub mod kinematics;
pub mod model;
pub mod presets;
pub mod quasi_static;
pub mod state;
pub mod statics;
pub mod stiffness;
pub mod sweep;

use std::f64::consts::PI;

use crate::error::{non_negative, Error, Result};
use crate::materials::{reduced_modulus, Material};
pub use batch::{solve_many, OperatingPoint, PointSummary};
pub use contact::{HertzContact, Raceway};
pub use geometry::{BearingGeometry, BearingType};
pub use kinematics::{ball_kinematics, BallKinematics};
pub use model::{inner_ring_expansion_per_omega2, BearingModel, RacewayOffsets};
pub use quasi_static::{ring_forces, RingForces, WarmStart};
pub use state::{BallState, BearingLoad, BearingState, GyroCoupleSign, RacewayControl, SolveOptions, Tilt};
pub use statics::{solve_static, thrust_contact_angle};
pub use stiffness::{contact_stiffness_n_per_m, seed_stiffness};
pub use sweep::{speed_sweep, stiffness_curve, StiffnessPoint};

/// One ball bearing: internal geometry, the materials of its parts and the
/// shaft it sits on (needed for centrifugal expansion, A-10).
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Bearing {
    /// Designation, e.g. `6208` or `7009C-hybrid` (the preset name).
    pub name: String,
    /// Internal geometry: ball set, pitch diameter, conformities, clearance,
    /// free contact angle and boundary dimensions.
    pub geometry: BearingGeometry,
    /// Inner-ring material: inner Hertz contact, centrifugal expansion of
    /// the ring (A-10) and its thermal properties in the heat model.
    pub inner_ring: Material,
    /// Outer-ring material: outer Hertz contact and its thermal properties in
    /// the heat model.
    pub outer_ring: Material,
    /// Ball material (bearing steel or Si3N4): both Hertz contacts, ball
    /// mass and inertia (density), ball conduction in the heat model.
    pub ball: Material,
    /// Shaft material (the inner ring is fitted on it).
    pub shaft: Material,
    /// Shaft bore diameter \[m\]; 0 for a solid shaft.
    pub shaft_bore_m: f64,
}

impl Bearing {
    /// A bearing with all-steel rings and shaft and balls of `ball` material.
    pub fn new(name: impl Into<String>, geometry: BearingGeometry, rings: Material, ball: Material) -> Result<Self> {
        let b = Bearing {
            name: name.into(),
            geometry,
            inner_ring: rings.clone(),
            outer_ring: rings,
            ball,
            shaft: Material::shaft_steel(),
            shaft_bore_m: 0.0,
        };
        b.validate()?;
        Ok(b)
    }

    /// Check materials and the shaft.
    pub fn validate(&self) -> Result<()> {
        self.inner_ring.validate()?;
        self.outer_ring.validate()?;
        self.ball.validate()?;
        self.shaft.validate()?;
        non_negative("shaft_bore_mm", self.shaft_bore_m * 1e3)?;
        if self.shaft_bore_m >= self.geometry.bore_m {
            return Err(Error::config(
                "shaft_bore_mm",
                self.shaft_bore_m * 1e3,
                format!(
                    "must be smaller than the bearing bore {} mm",
                    self.geometry.bore_m * 1e3
                ),
            ));
        }
        Ok(())
    }

    /// Hertz contact of a ball on the inner raceway at contact angle `alpha` \[rad\].
    pub fn inner_contact(&self, alpha: f64) -> Result<HertzContact> {
        let g = &self.geometry;
        let c = contact::curvature(
            Raceway::Inner,
            g.ball_diameter_m,
            g.pitch_diameter_m,
            g.inner_conformity,
            alpha,
        );
        HertzContact::new(c, reduced_modulus(&self.ball, &self.inner_ring))
    }

    /// Hertz contact of a ball on the outer raceway at contact angle `alpha` \[rad\].
    pub fn outer_contact(&self, alpha: f64) -> Result<HertzContact> {
        let g = &self.geometry;
        let c = contact::curvature(
            Raceway::Outer,
            g.ball_diameter_m,
            g.pitch_diameter_m,
            g.outer_conformity,
            alpha,
        );
        HertzContact::new(c, reduced_modulus(&self.ball, &self.outer_ring))
    }

    /// Series load-deflection constant K_n of one ball between both raceways
    /// at contact angle `alpha` (A-3) [N/m^1.5].
    pub fn ball_constant(&self, alpha: f64) -> Result<f64> {
        Ok(contact::series_constant(
            self.inner_contact(alpha)?.k_load_deflection,
            self.outer_contact(alpha)?.k_load_deflection,
        ))
    }

    /// Ball mass m = rho pi D^3 / 6 \[kg\].
    pub fn ball_mass_kg(&self) -> f64 {
        self.ball.density_kg_m3 * PI * self.geometry.ball_diameter_m.powi(3) / 6.0
    }

    /// Ball polar moment of inertia J = rho pi D^5 / 60 [kg m^2].
    pub fn ball_inertia_kg_m2(&self) -> f64 {
        self.ball.density_kg_m3 * PI * self.geometry.ball_diameter_m.powi(5) / 60.0
    }

    /// "steel", "hybrid" (ceramic balls on steel rings) or "ceramic";
    /// "custom" for ceramic rings with steel balls.
    pub fn material_class(&self) -> &'static str {
        let ceramic = |m: &Material| m.name.eq_ignore_ascii_case("si3n4");
        match (
            ceramic(&self.ball),
            ceramic(&self.inner_ring) && ceramic(&self.outer_ring),
        ) {
            (false, false) => "steel",
            (true, false) => "hybrid",
            (true, true) => "ceramic",
            (false, true) => "custom",
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn hybrid_contact_is_stiffer() {
        let s = Bearing::preset("6208").unwrap();
        let h = Bearing::preset("6208-hybrid").unwrap();
        let a = s.geometry.free_contact_angle_rad;
        assert!(h.ball_constant(a).unwrap() > s.ball_constant(a).unwrap());
        assert_eq!(h.material_class(), "hybrid");
        assert_eq!(s.material_class(), "steel");
        // Si3N4 ball is about 40 % of the steel ball mass.
        let r = h.ball_mass_kg() / s.ball_mass_kg();
        assert!((r - 3200.0 / 7830.0).abs() < 1e-12);
    }
}
