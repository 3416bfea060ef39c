//! Single-degree-of-freedom torsional mesh model ("classic 1-DOF" backlash
//! oscillator of Kahraman & Singh, J. Sound Vib. 142 (1990) 49-75) built from
//! a [`GearPair`] and its [`MeshStiffness`].
//!
//! With the dynamic transmission error along the transverse line of action
//! x = r_b1 theta_1 - r_b2 theta_2 - e(t), the pair obeys
//!
//! m_e x'' + c x' + k(t) f(x) = F_m - m_e e''(t),
//!
//! m_e = I_1 I_2 / (I_1 r_b2^2 + I_2 r_b1^2) (equivalent mass on the line of
//! action), F_m = T_1 / r_b1 (mean transmitted base-circle force), f the
//! backlash dead zone of half width b. Scaling x = b xbar, t = tau /
//! omega_n with omega_n = sqrt(k_mean / m_e) gives
//!
//! xbar'' + 2 zeta xbar' + kbar(tau) f(xbar) = Fbar_m + ebar Omega^2 cos(Omega tau + theta),
//!
//! kbar = k / k_mean, zeta = c / (2 m_e omega_n), Fbar_m = F_m / (k_mean b),
//! ebar = e_1 / b for a first-harmonic error e_1 cos(omega_z t + theta),
//! Omega = omega_z / omega_n (omega_z = 2 pi f_z the mesh frequency).

use super::geometry::GearPair;
use super::mesh::MeshStiffness;
use crate::error::{in_range, positive, Result};
use std::f64::consts::PI;

/// Dimensional and nondimensional data of the 1-DOF torsional mesh model.
#[derive(Debug, Clone, PartialEq)]
pub struct TorsionalMesh {
    /// Equivalent mass on the line of action m_e \[kg\].
    pub equivalent_mass_kg: f64,
    /// Mean mesh stiffness k_mean [N/m] (transverse line of action).
    pub mean_stiffness_n_per_m: f64,
    /// omega_n = sqrt(k_mean / m_e) [rad/s].
    pub natural_frequency_rad_s: f64,
    /// Mean transmitted force F_m = T_1 / r_b1 \[N\].
    pub mean_force_n: f64,
    /// Backlash half width b \[m\].
    pub backlash_half_m: f64,
    /// Viscous mesh damping ratio zeta [-].
    pub damping_ratio: f64,
    /// Mesh damping c = 2 zeta m_e omega_n [N s/m].
    pub damping_n_s_per_m: f64,
    /// Fbar_m = F_m / (k_mean b) [-].
    pub mean_force_nondim: f64,
    /// Relative stiffness harmonics (a_k, b_k) / k_mean of kbar(phase) [-].
    pub stiffness_harmonics_nondim: Vec<(f64, f64)>,
    /// Tooth count of the pinion (mesh frequency = z1 n1 / 60).
    pinion_teeth: u32,
}

impl TorsionalMesh {
    /// Build the model. `damping_ratio` in [0, 1), `backlash_half_m` > 0,
    /// `harmonics` of the relative stiffness to keep.
    pub fn new(
        pair: &GearPair,
        stiffness: &MeshStiffness,
        damping_ratio: f64,
        backlash_half_m: f64,
        harmonics: usize,
    ) -> Result<Self> {
        let zeta = in_range("damping_ratio", damping_ratio, 0.0, 0.999)?;
        let b = positive("backlash_half_m", backlash_half_m)?;
        let [i1, i2] = pair.polar_inertia_kg_m2();
        let [r1, r2] = pair.base_radius_m();
        let me = i1 * i2 / (i1 * r2 * r2 + i2 * r1 * r1);
        let (mean, coeffs) = stiffness.fourier(harmonics);
        let k = positive("mean_stiffness_n_per_m", mean)?;
        let wn = (k / me).sqrt();
        let fm = pair.input_torque_n_m() / r1;
        Ok(TorsionalMesh {
            equivalent_mass_kg: me,
            mean_stiffness_n_per_m: k,
            natural_frequency_rad_s: wn,
            mean_force_n: fm,
            backlash_half_m: b,
            damping_ratio: zeta,
            damping_n_s_per_m: 2.0 * zeta * me * wn,
            mean_force_nondim: fm / (k * b),
            stiffness_harmonics_nondim: coeffs.into_iter().map(|(a, c)| (a / k, c / k)).collect(),
            pinion_teeth: pair.spec.wheels[0].teeth,
        })
    }

    /// Omega = omega_z / omega_n for a pinion speed \[rpm\].
    pub fn frequency_ratio(&self, pinion_speed_rpm: f64) -> Result<f64> {
        let n = positive("pinion_speed_rpm", pinion_speed_rpm)?;
        Ok(2.0 * PI * self.pinion_teeth as f64 * n / 60.0 / self.natural_frequency_rad_s)
    }

    /// Pinion speed \[rpm\] at which the mesh frequency equals omega_n (Omega = 1).
    pub fn resonance_speed_rpm(&self) -> f64 {
        self.natural_frequency_rad_s * 60.0 / (2.0 * PI * self.pinion_teeth as f64)
    }

    /// Relative stiffness kbar at a mesh phase, from the kept harmonics.
    pub fn stiffness_nondim(&self, mesh_phase: f64) -> f64 {
        1.0 + self
            .stiffness_harmonics_nondim
            .iter()
            .enumerate()
            .map(|(k, (a, b))| {
                let w = 2.0 * PI * (k + 1) as f64 * mesh_phase;
                a * w.cos() + b * w.sin()
            })
            .sum::<f64>()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gear::mesh::MeshOptions;

    #[test]
    fn equivalent_mass_and_scales() {
        let p = GearPair::preset("seed-electric-drive").unwrap();
        let opts = MeshOptions {
            table_points: 128,
            path_points: 41,
            quadrature_intervals: 32,
        };
        let k = MeshStiffness::potential_energy_with(&p, &opts).unwrap();
        let t = TorsionalMesh::new(&p, &k, 0.05, 10e-6, 4).unwrap();
        // m_e is the series combination of the two reduced masses I / r_b^2.
        let [i1, i2] = p.polar_inertia_kg_m2();
        let [r1, r2] = p.base_radius_m();
        let series = 1.0 / (r1 * r1 / i1 + r2 * r2 / i2);
        assert!((t.equivalent_mass_kg - series).abs() < 1e-12 * series);
        assert!(
            (t.natural_frequency_rad_s.powi(2) * t.equivalent_mass_kg / t.mean_stiffness_n_per_m - 1.0).abs() < 1e-12
        );
        // Fbar_m b k_mean = F_m = T / r_b1.
        assert!((t.mean_force_nondim * t.backlash_half_m * t.mean_stiffness_n_per_m - 100.0 / r1).abs() < 1e-9);
        // Omega = 1 at the resonance speed; linear in speed.
        assert!((t.frequency_ratio(t.resonance_speed_rpm()).unwrap() - 1.0).abs() < 1e-12);
        let o1 = t.frequency_ratio(6500.0).unwrap();
        assert!((t.frequency_ratio(13000.0).unwrap() - 2.0 * o1).abs() < 1e-12);
        // kbar has unit mean.
        let mean: f64 = (0..64).map(|i| t.stiffness_nondim(i as f64 / 64.0)).sum::<f64>() / 64.0;
        assert!((mean - 1.0).abs() < 1e-12);
        assert!(TorsionalMesh::new(&p, &k, 1.5, 10e-6, 4).is_err());
        assert!(TorsionalMesh::new(&p, &k, 0.05, 0.0, 4).is_err());
    }
}
