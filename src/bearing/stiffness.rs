//! Bearing stiffness (docs/concepts/physics.md §6).
//!
//! Two measures are offered:
//!
//! * the seed's axial/radial formula (A-39..A-42): per ball, the tangent
//!   contact stiffnesses k = 1.5 K^(2/3) Q^(1/3) of the inner and outer
//!   contacts projected on the axial (sin^2 a) or radial (cos^2 a) direction,
//!   in series, summed over the balls (radial weighted by cos^2 psi_j);
//! * the full 5x5 tangent stiffness K = -d(reaction)/dq at the solved state,
//!   computed in the solvers from exact derivatives (per-ball equilibrium
//!   condensed by the implicit-function theorem at speed); see
//!   [`super::BearingState::stiffness_matrix`].
//!
//! The seed's formula ignores the change of the contact angles with the
//! displacement (the geometric stiffness Q/L) and the coupling terms, so it
//! differs from the diagonal of the 5x5 matrix; both are reported.

use super::model::BearingModel;
use super::state::BallState;

/// Tangent contact stiffness dQ/d delta = 1.5 K^(2/3) Q^(1/3) (A-1) [N/m].
#[inline]
pub fn contact_stiffness_n_per_m(k_load_deflection: f64, load_n: f64) -> f64 {
    if load_n > 0.0 {
        1.5 * k_load_deflection.powf(2.0 / 3.0) * load_n.cbrt()
    } else {
        0.0
    }
}

fn series(a: f64, b: f64) -> f64 {
    if a > 0.0 && b > 0.0 {
        a * b / (a + b)
    } else {
        0.0
    }
}

/// Axial and radial stiffness of the seed [N/m].
pub fn seed_stiffness(model: &BearingModel, balls: &[BallState]) -> (f64, f64) {
    let mut ka = 0.0;
    let mut kr = 0.0;
    for b in balls {
        let (si, ci) = b.inner_contact_angle_rad.sin_cos();
        let (so, co) = b.outer_contact_angle_rad.sin_cos();
        let kin = model.inner.k(super::dual::Dual::<1>::cst(ci)).v;
        let kout = model.outer.k(super::dual::Dual::<1>::cst(co)).v;
        let k_i = contact_stiffness_n_per_m(kin, b.inner_load_n);
        let k_o = contact_stiffness_n_per_m(kout, b.outer_load_n);
        ka += series(k_i * si * si, k_o * so * so);
        kr += series(k_i * ci * ci, k_o * co * co) * b.azimuth_rad.cos().powi(2);
    }
    (ka, kr)
}
