//! Unbalanced magnetic pull (UMP) of an eccentric motor rotor in its air gap.
//!
//! Linear model (e.g. Früchtenicht, Jordan & Seinsch, Archiv f. Elektrotechnik
//! 65 (1982) 271-281; the "simple" model discussed by Smith & Dorrell, IEE
//! Proc. Electr. Power Appl. 143 (1996) 193-201): with a constant MMF the
//! air-gap flux density varies inversely with the local gap
//! g(phi) = g0 (1 - eps cos phi), B(phi) = B0 / (1 - eps cos phi)
//! ~ B0 (1 + eps cos phi); integrating the Maxwell pressure B^2 / (2 mu0)
//! over the rotor surface R dphi L gives to first order in eps = e / g0
//!
//!   F = pi R L B0^2 e / (mu0 g0) = k_ump e,   k_ump = pi R L B0^2 / (mu0 g0),
//!
//! directed towards the narrowest gap: a negative stiffness. B0 is the RMS
//! air-gap flux density (time average of the rotating field's B^2). The
//! factor `reduction_factor` (<= 1) accounts for saturation and equalising
//! currents in parallel paths/rotor cage, which Smith & Dorrell show reduce
//! the pull; 1.0 is the conservative bound.

use std::f64::consts::PI;

use crate::error::{in_range, non_negative, positive, Result};

/// Vacuum permeability mu0 [H/m] (CODATA 2018: 1.25663706212e-6).
pub const MU0_H_PER_M: f64 = 1.256_637_062_12e-6;

/// Unbalanced magnetic pull of the motor rotor, switchable.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct UnbalancedMagneticPull {
    /// Include the pull (negative stiffness and static-eccentricity force)?
    pub enabled: bool,
    /// Axial position of the rotor-core node that carries the pull \[m\].
    pub position_m: f64,
    /// Rotor outer radius R \[m\].
    pub rotor_radius_m: f64,
    /// Active (stack) length L \[m\].
    pub core_length_m: f64,
    /// Nominal radial air gap g0 \[m\].
    pub air_gap_m: f64,
    /// RMS air-gap flux density B0 \[T\].
    pub flux_density_t: f64,
    /// Static eccentricity of the rotor in the stator bore, along +x \[m\].
    pub static_eccentricity_m: f64,
    /// Empirical reduction of the ideal pull (saturation, parallel paths) [-].
    pub reduction_factor: f64,
}

impl UnbalancedMagneticPull {
    /// Check the inputs (eccentricity must stay inside the gap).
    pub fn validate(&self) -> Result<()> {
        positive("rotor_radius_m", self.rotor_radius_m)?;
        positive("core_length_m", self.core_length_m)?;
        positive("air_gap_m", self.air_gap_m)?;
        non_negative("flux_density_t", self.flux_density_t)?;
        in_range(
            "static_eccentricity_m",
            self.static_eccentricity_m,
            -0.5 * self.air_gap_m,
            0.5 * self.air_gap_m,
        )?;
        in_range("reduction_factor", self.reduction_factor, 0.0, 1.0)?;
        Ok(())
    }

    /// Magnitude of the negative stiffness k_ump = pi R L B0^2 / (mu0 g0) [N/m]
    /// (0 when disabled).
    pub fn stiffness_n_per_m(&self) -> f64 {
        if !self.enabled {
            return 0.0;
        }
        self.reduction_factor * PI * self.rotor_radius_m * self.core_length_m * self.flux_density_t.powi(2)
            / (MU0_H_PER_M * self.air_gap_m)
    }

    /// Constant pull from the static eccentricity, along +x \[N\] (0 when disabled).
    pub fn static_force_n(&self) -> f64 {
        self.stiffness_n_per_m() * self.static_eccentricity_m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ump() -> UnbalancedMagneticPull {
        UnbalancedMagneticPull {
            enabled: true,
            position_m: 0.1,
            rotor_radius_m: 0.035,
            core_length_m: 0.12,
            air_gap_m: 3e-4,
            flux_density_t: 0.6,
            static_eccentricity_m: 3e-5,
            reduction_factor: 1.0,
        }
    }

    #[test]
    fn linear_pull_matches_integrated_maxwell_pressure_for_small_eccentricity() {
        // Integrate B^2/(2 mu0) cos(phi) R L dphi with B = B0 g0 / g(phi)
        // numerically at eps = 1e-4: the linear k_ump must match.
        let u = ump();
        let e = 1e-4 * u.air_gap_m;
        let n = 20_000;
        let mut f = 0.0;
        for i in 0..n {
            let phi = 2.0 * PI * (i as f64 + 0.5) / n as f64;
            let b = u.flux_density_t / (1.0 - (e / u.air_gap_m) * phi.cos());
            f += b * b / (2.0 * MU0_H_PER_M) * phi.cos() * u.rotor_radius_m * u.core_length_m * (2.0 * PI / n as f64);
        }
        let k = u.stiffness_n_per_m();
        assert!((f / e - k).abs() / k < 1e-3, "{} vs {}", f / e, k);
        assert!((u.static_force_n() - k * 3e-5).abs() < 1e-9 * k);
        let off = UnbalancedMagneticPull {
            enabled: false,
            ..ump()
        };
        assert_eq!(off.stiffness_n_per_m(), 0.0);
        assert!(UnbalancedMagneticPull {
            static_eccentricity_m: 2e-4,
            ..ump()
        }
        .validate()
        .is_err());
    }
}
