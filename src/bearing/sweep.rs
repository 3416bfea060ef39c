//! Speed sweeps of the quasi-static solve and stiffness curves (seed A
//! Fig. 11: 6500..16,500 rpm), in parallel with rayon.
//!
//! Every speed is solved from the same start (the static solution, computed
//! once), never from a neighbouring speed, so each result depends only on its
//! own speed and the results are bit-identical for any thread count.

use rayon::prelude::*;

use super::model::BearingModel;
use super::quasi_static::{static_start_q, WarmStart};
use super::state::{BearingState, SolveOptions};
use crate::error::Result;

/// Quasi-static states at each speed \[rpm\] under the load [Fx, Fy, Fz, Mx, My]
/// (N, N m). A speed that fails to solve gives its own `Err`.
pub fn speed_sweep(
    model: &BearingModel,
    speeds_rpm: &[f64],
    load: &[f64; 5],
    opts: &SolveOptions,
) -> Result<Vec<Result<BearingState>>> {
    let start = static_start_q(model, load, opts)?;
    Ok(speeds_rpm
        .par_iter()
        .map(|&n| model.solve_from(load, n, opts, start, &mut WarmStart::new()))
        .collect())
}

/// Stiffness of the bearing at one speed.
#[derive(Debug, Clone, PartialEq)]
pub struct StiffnessPoint {
    /// Inner-ring (shaft) speed \[rpm\]; the outer ring is stationary.
    pub speed_rpm: f64,
    /// Seed formula A-39, A-40 [N/m].
    pub axial_stiffness_seed_n_per_m: f64,
    /// Seed formula A-41, A-42 [N/m].
    pub radial_stiffness_seed_n_per_m: f64,
    /// Full tangent stiffness K = -d(reaction)/dq (N/m, N/rad, N m/m, N m/rad).
    pub stiffness_matrix: [[f64; 5]; 5],
    /// Inner-ring displacement [dx, dy, dz, theta_x, theta_y] (m, rad).
    pub displacement: [f64; 5],
    /// Inner contact angle of each ball \[rad\].
    pub inner_contact_angles_rad: Vec<f64>,
    /// Outer contact angle of each ball \[rad\].
    pub outer_contact_angles_rad: Vec<f64>,
}

impl From<&BearingState> for StiffnessPoint {
    fn from(s: &BearingState) -> Self {
        StiffnessPoint {
            speed_rpm: s.speed_rpm,
            axial_stiffness_seed_n_per_m: s.axial_stiffness_seed_n_per_m,
            radial_stiffness_seed_n_per_m: s.radial_stiffness_seed_n_per_m,
            stiffness_matrix: s.stiffness_matrix,
            displacement: s.displacement,
            inner_contact_angles_rad: s.balls.iter().map(|b| b.inner_contact_angle_rad).collect(),
            outer_contact_angles_rad: s.balls.iter().map(|b| b.outer_contact_angle_rad).collect(),
        }
    }
}

/// Stiffness versus speed under an axial and a radial load (seed A Fig. 11).
/// Fails with the error of the first (lowest-index) speed that does not solve. With the
/// default free tilt the ring tilts under the combined load; pass
/// `tilt: Tilt::held_level()` in `opts` for a ring held level by its shaft
/// (the usual axial/radial bearing model).
pub fn stiffness_curve(
    model: &BearingModel,
    speeds_rpm: &[f64],
    axial_n: f64,
    radial_n: f64,
    opts: &SolveOptions,
) -> Result<Vec<StiffnessPoint>> {
    let load = [radial_n, 0.0, axial_n, 0.0, 0.0];
    let start = static_start_q(model, &load, opts)?;
    let points: Vec<Result<StiffnessPoint>> = speeds_rpm
        .par_iter()
        .map(|&n| {
            model
                .solve_from(&load, n, opts, start, &mut WarmStart::new())
                .map(|s| StiffnessPoint::from(&s))
        })
        .collect();
    // Collect sequentially so that the error reported is always the one of
    // the lowest-index failing speed, whatever the thread count.
    points.into_iter().collect()
}
