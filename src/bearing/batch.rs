//! Many operating points of one bearing in one call: each point solved on
//! its own (static at zero speed, quasi-static above), in parallel with
//! rayon, one `Result` per point so a point that fails does not take the
//! others with it.
//!
//! A point is solved exactly as a single solve would solve it (same start,
//! same iteration), so batch and single results are bit-identical and do not
//! depend on the thread count or on the other points of the batch.

use rayon::prelude::*;

use super::model::BearingModel;
use super::state::{BallState, BearingState, SolveOptions};
use crate::error::{non_negative, Result};

/// One operating point of a batch.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OperatingPoint {
    /// Load on the inner ring [Fx, Fy, Fz, Mx, My] (N, N m).
    pub load: [f64; 5],
    /// Inner-ring (shaft) speed \[rpm\]; 0 gives the static solve.
    pub speed_rpm: f64,
    /// Solver options of this point (effects, raceway control, tilt).
    pub options: SolveOptions,
}

/// Solve one point: the static equilibrium at zero speed, the quasi-static
/// one (started from the static solution) above.
pub fn solve_point(model: &BearingModel, point: &OperatingPoint) -> Result<BearingState> {
    let speed = non_negative("speed_rpm", point.speed_rpm)?;
    if speed == 0.0 {
        model.solve_static(&point.load, &point.options)
    } else {
        model.solve(&point.load, speed, &point.options)
    }
}

/// Solve every point in parallel; the result at index i belongs to point i.
pub fn solve_many(model: &BearingModel, points: &[OperatingPoint]) -> Vec<Result<BearingState>> {
    points.par_iter().map(|p| solve_point(model, p)).collect()
}

/// The scalar outputs of a solved point that a results table keeps (one
/// row per point); SI except where the name says otherwise.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointSummary {
    /// Seed A axial stiffness \[N/m\].
    pub axial_stiffness_seed_n_per_m: f64,
    /// Seed A radial stiffness \[N/m\].
    pub radial_stiffness_seed_n_per_m: f64,
    /// Diagonal of the 5x5 tangent stiffness (N/m for x, y, z; N m/rad for
    /// the tilts).
    pub stiffness_diagonal: [f64; 5],
    /// Axial displacement of the inner ring \[m\].
    pub axial_displacement_m: f64,
    /// Radial displacement of the inner ring (length of dx, dy) \[m\].
    pub radial_displacement_m: f64,
    /// Tilt of the inner ring (length of theta_x, theta_y) \[rad\].
    pub tilt_rad: f64,
    /// Largest and smallest inner contact angle over the balls \[rad\].
    pub inner_contact_angle_range_rad: (f64, f64),
    /// Largest and smallest outer contact angle over the balls \[rad\].
    pub outer_contact_angle_range_rad: (f64, f64),
    /// Largest inner-raceway ball load \[N\].
    pub inner_load_max_n: f64,
    /// Largest outer-raceway ball load \[N\].
    pub outer_load_max_n: f64,
    /// Ball centrifugal force (largest over the balls) \[N\].
    pub centrifugal_force_n: f64,
    /// Cage speed: mean orbit speed of the balls \[rad/s\].
    pub cage_speed_rad_s: f64,
    /// Ring Newton iterations used.
    pub iterations: usize,
    /// Final relative force residual.
    pub residual: f64,
}

fn range(balls: &[BallState], f: impl Fn(&BallState) -> f64) -> (f64, f64) {
    balls
        .iter()
        .map(f)
        .fold((f64::NEG_INFINITY, f64::INFINITY), |(hi, lo), v| (hi.max(v), lo.min(v)))
}

impl From<&BearingState> for PointSummary {
    fn from(s: &BearingState) -> Self {
        let q = &s.displacement;
        let n = s.balls.len().max(1) as f64;
        PointSummary {
            axial_stiffness_seed_n_per_m: s.axial_stiffness_seed_n_per_m,
            radial_stiffness_seed_n_per_m: s.radial_stiffness_seed_n_per_m,
            stiffness_diagonal: std::array::from_fn(|i| s.stiffness_matrix[i][i]),
            axial_displacement_m: q[2],
            radial_displacement_m: q[0].hypot(q[1]),
            tilt_rad: q[3].hypot(q[4]),
            inner_contact_angle_range_rad: range(&s.balls, |b| b.inner_contact_angle_rad),
            outer_contact_angle_range_rad: range(&s.balls, |b| b.outer_contact_angle_rad),
            inner_load_max_n: range(&s.balls, |b| b.inner_load_n).0,
            outer_load_max_n: range(&s.balls, |b| b.outer_load_n).0,
            centrifugal_force_n: range(&s.balls, |b| b.centrifugal_force_n).0,
            cage_speed_rad_s: s.balls.iter().map(|b| b.orbit_speed_rad_s).sum::<f64>() / n,
            iterations: s.iterations,
            residual: s.residual,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearing::state::Tilt;
    use crate::Bearing;

    fn points() -> Vec<OperatingPoint> {
        let held = SolveOptions {
            tilt: Tilt::held_level(),
            ..Default::default()
        };
        let mut v = Vec::new();
        for &speed in &[0.0, 6_000.0, 16_000.0] {
            for &fa in &[300.0, 2680.9] {
                v.push(OperatingPoint {
                    load: [1189.9, 0.0, fa, 0.0, 0.0],
                    speed_rpm: speed,
                    options: held,
                });
            }
        }
        // A point that cannot be solved: negative speed.
        v.push(OperatingPoint {
            load: [0.0, 0.0, 500.0, 0.0, 0.0],
            speed_rpm: -1.0,
            options: held,
        });
        v
    }

    #[test]
    fn batch_equals_single_solves_and_keeps_failures_per_point() {
        let b = Bearing::preset("6208").unwrap();
        let m = BearingModel::new(&b).unwrap();
        let pts = points();
        let many = solve_many(&m, &pts);
        assert_eq!(many.len(), pts.len());
        for (p, r) in pts.iter().zip(&many) {
            let single = if p.speed_rpm < 0.0 {
                Err(crate::Error::config("speed_rpm", p.speed_rpm, "must not be negative"))
            } else if p.speed_rpm == 0.0 {
                m.solve_static(&p.load, &p.options)
            } else {
                m.solve(&p.load, p.speed_rpm, &p.options)
            };
            assert_eq!(&single, r);
        }
        let err = many.last().unwrap().as_ref().unwrap_err().to_string();
        assert!(err.contains("speed_rpm") && err.contains("-1"), "{err}");
    }

    #[test]
    fn summary_is_consistent_with_the_state() {
        let b = Bearing::preset("7008C").unwrap();
        let m = BearingModel::new(&b).unwrap();
        let p = OperatingPoint {
            load: [0.0, 0.0, 800.0, 0.0, 0.0],
            speed_rpm: 12_000.0,
            options: SolveOptions::default(),
        };
        let s = solve_point(&m, &p).unwrap();
        let sum = PointSummary::from(&s);
        // Pure axial load: every ball alike, so the angle range collapses
        // and the cage turns at the orbit speed of any ball.
        let (hi, lo) = sum.inner_contact_angle_range_rad;
        assert!((hi - lo).abs() < 1e-9 * hi.abs().max(1.0), "{hi} {lo}");
        assert!((sum.cage_speed_rad_s - s.balls[0].orbit_speed_rad_s).abs() < 1e-9 * sum.cage_speed_rad_s);
        // Outer loads exceed inner loads by the centrifugal force at speed.
        assert!(sum.outer_load_max_n > sum.inner_load_max_n);
        assert_eq!(sum.stiffness_diagonal[2], s.stiffness_matrix[2][2]);
    }
}
