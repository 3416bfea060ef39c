//! Steady-state unbalance response in the frequency domain.
//!
//! An unbalance U = m_u r_u [kg m] at angle phi on the rotor spinning at
//! Omega produces the rotating force F_x = U Omega^2 cos(Omega t + phi),
//! F_y = U Omega^2 sin(Omega t + phi), i.e. the phasors
//! F_x = U Omega^2 e^{i phi}, F_y = -i U Omega^2 e^{i phi}. The steady
//! response q(t) = Re(Q e^{i Omega t}) solves the complex linear system
//! (K - Omega^2 M + i Omega (C + Omega G)) Q = F (Friswell et al. 2010, 6.2).
//!
//! Balance quality (ISO 21940-11:2016, formerly ISO 1940-1): grade G
//! [mm/s] = e_per Omega_max, so the permissible specific unbalance is
//! e_per = G / Omega_max and the permissible residual unbalance U = m e_per.

use nalgebra::{Complex, DMatrix, DVector};
use rayon::prelude::*;

use super::modal::dynamic_stiffness;
use super::{LateralDof, Rotor, SystemMatrices};
use crate::error::{finite, non_negative, positive, Error, Result};
use crate::units::rpm_to_rad_s;

/// A point unbalance on the rotor.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unbalance {
    /// Axial position (a mesh node) \[m\].
    pub position_m: f64,
    /// Unbalance U = mass x radius [kg m].
    pub unbalance_kg_m: f64,
    /// Angular position at t = 0 \[rad\].
    pub phase_rad: f64,
}

impl Unbalance {
    /// Permissible residual unbalance of balance grade `grade_mm_per_s`
    /// (e.g. 2.5 for G2.5) for a rotor of mass `rotor_mass_kg` at its maximum
    /// service speed `max_speed_rpm` (ISO 21940-11): U = m G / Omega_max.
    pub fn from_balance_grade(
        position_m: f64,
        grade_mm_per_s: f64,
        rotor_mass_kg: f64,
        max_speed_rpm: f64,
        phase_rad: f64,
    ) -> Result<Self> {
        positive("grade_mm_per_s", grade_mm_per_s)?;
        positive("rotor_mass_kg", rotor_mass_kg)?;
        positive("max_speed_rpm", max_speed_rpm)?;
        let e_per_m = grade_mm_per_s * 1e-3 / rpm_to_rad_s(max_speed_rpm);
        Ok(Unbalance {
            position_m,
            unbalance_kg_m: rotor_mass_kg * e_per_m,
            phase_rad,
        })
    }

    fn validate(&self) -> Result<()> {
        finite("unbalance.position_m", self.position_m)?;
        non_negative("unbalance.unbalance_kg_m", self.unbalance_kg_m)?;
        finite("unbalance.phase_rad", self.phase_rad)?;
        Ok(())
    }
}

/// Complex force amplitude vector (per Omega^2 = 1) of a set of unbalances.
pub fn unbalance_phasor(rotor: &Rotor, unbalances: &[Unbalance]) -> Result<DVector<Complex<f64>>> {
    let mut f = DVector::from_element(rotor.dof_count(), Complex::new(0.0, 0.0));
    for u in unbalances {
        u.validate()?;
        let node = rotor.node_at(u.position_m)?;
        let p = Complex::from_polar(u.unbalance_kg_m, u.phase_rad);
        f[rotor.dof(node, LateralDof::X)] += p;
        f[rotor.dof(node, LateralDof::Y)] += Complex::new(0.0, -1.0) * p;
    }
    Ok(f)
}

/// Steady response at one probe node and speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HarmonicResponse {
    /// Shaft speed \[rpm\]; the unbalance excites 1X, Omega = 2 pi speed / 60.
    pub speed_rpm: f64,
    /// x(t) = Re(X e^{i Omega t}) \[m\].
    pub displacement_x_m: Complex<f64>,
    /// y(t) = Re(Y e^{i Omega t}) \[m\].
    pub displacement_y_m: Complex<f64>,
    /// Major semi-axis of the orbit |R_f| + |R_b| \[m\].
    pub orbit_major_m: f64,
    /// Peak velocity in x, Omega |X| [m/s].
    pub velocity_peak_x_m_per_s: f64,
    /// RMS velocity in x, Omega |X| / sqrt 2 [m/s].
    pub velocity_rms_x_m_per_s: f64,
}

/// Solve (K - W^2 M + i W (C + W G)) Q = W^2 F_u for the steady state.
pub fn harmonic_solution(m: &SystemMatrices, unit_force: &DVector<Complex<f64>>) -> Result<DVector<Complex<f64>>> {
    let w = m.spin_speed_rad_s;
    let d = dynamic_stiffness(m, Complex::new(0.0, w));
    let rhs = unit_force * Complex::new(w * w, 0.0);
    d.lu().solve(&rhs).ok_or_else(|| {
        Error::config(
            "speed_rpm",
            crate::units::rad_s_to_rpm(w),
            "dynamic stiffness is singular (undamped resonance)",
        )
    })
}

/// Steady unbalance response at `probe_position_m` over `speeds_rpm`
/// (parallel over speeds, deterministic).
pub fn unbalance_response(
    rotor: &Rotor,
    unbalances: &[Unbalance],
    speeds_rpm: &[f64],
    probe_position_m: f64,
) -> Result<Vec<HarmonicResponse>> {
    let f = unbalance_phasor(rotor, unbalances)?;
    let probe = rotor.node_at(probe_position_m)?;
    let (ix, iy) = (rotor.dof(probe, LateralDof::X), rotor.dof(probe, LateralDof::Y));
    speeds_rpm
        .par_iter()
        .map(|&speed_rpm| {
            let m = rotor.matrices(speed_rpm)?;
            let q = harmonic_solution(&m, &f)?;
            Ok(probe_response(speed_rpm, m.spin_speed_rad_s, q[ix], q[iy]))
        })
        .collect()
}

fn probe_response(speed_rpm: f64, w: f64, x: Complex<f64>, y: Complex<f64>) -> HarmonicResponse {
    let i = Complex::new(0.0, 1.0);
    let rf = (x + i * y).norm() / 2.0;
    let rb = (x - i * y).norm() / 2.0;
    HarmonicResponse {
        speed_rpm,
        displacement_x_m: x,
        displacement_y_m: y,
        orbit_major_m: rf + rb,
        velocity_peak_x_m_per_s: w * x.norm(),
        velocity_rms_x_m_per_s: w * x.norm() / std::f64::consts::SQRT_2,
    }
}

/// Static deflection under the constant forces (UMP of a static
/// eccentricity): K q = f_static [m, rad].
pub fn static_deflection(m: &SystemMatrices) -> Result<DVector<f64>> {
    let k: &DMatrix<f64> = &m.stiffness_si;
    k.clone().lu().solve(&m.static_force_si).ok_or_else(|| {
        Error::config(
            "bearings",
            "stiffness",
            "the supported rotor has no static equilibrium (singular or unstable stiffness)",
        )
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::materials::Material;
    use crate::rotor::{BearingCoefficients, BearingSupport, RotorSpec, ShaftSection};
    use std::sync::Arc;

    #[test]
    fn balance_grade_g2_5() {
        // ISO 21940-11: G2.5, 3 kg, 30,000 rpm -> e_per = 2.5 / 3141.6 mm = 0.796 um.
        let u = Unbalance::from_balance_grade(0.0, 2.5, 3.0, 30_000.0, 0.0).unwrap();
        assert!(
            (u.unbalance_kg_m / 3.0 - 7.9577e-7).abs() < 1e-10,
            "{}",
            u.unbalance_kg_m
        );
        assert!(Unbalance::from_balance_grade(0.0, -1.0, 3.0, 1.0, 0.0).is_err());
    }

    #[test]
    fn rigid_rotor_far_above_resonance_spins_about_its_mass_centre() {
        // Soft isotropic supports (rigid modes ~4 rad/s, first bending mode
        // ~1.4e5 rad/s, spin 1047 rad/s): far above the rigid-body modes the mass
        // centre stays put and the geometric centre orbits at e = U / m
        // (Jeffcott limit), here for a symmetric rotor with U at the centre.
        let k = 10.0;
        let spring = Arc::new(BearingCoefficients::diagonal(k, 0.0, 0.0, 0.0).unwrap());
        let r = Rotor::new(RotorSpec {
            sections: vec![ShaftSection::new(0.1, 0.05, 0.0, Material::shaft_steel()).unwrap()],
            disks: vec![],
            bearings: vec![
                BearingSupport::new("a", 0.0, spring.clone()),
                BearingSupport::new("b", 0.1, spring),
            ],
            magnetic_pull: None,
            modal_damping_ratio: 0.0,
            max_element_length_m: 0.025,
        })
        .unwrap();
        let u = Unbalance {
            position_m: 0.05,
            unbalance_kg_m: 1e-5,
            phase_rad: 0.0,
        };
        let resp = unbalance_response(&r, &[u], &[10_000.0], 0.05).unwrap()[0];
        let e = 1e-5 / r.mass_kg();
        // x = -e cos(Wt): phasor -e; orbit is a forward circle of radius e.
        assert!(
            (resp.displacement_x_m.re + e).abs() < 1e-3 * e,
            "{:?} vs {e}",
            resp.displacement_x_m
        );
        assert!((resp.orbit_major_m - e).abs() < 1e-3 * e);
    }
}
