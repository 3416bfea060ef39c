//! Rotor supports from the bearing solver: angular-contact rows in
//! back-to-back pairs under a constant-force preload, linearised at the
//! quasi-static operating point (for the Campbell diagram and the steady
//! unbalance response) or as full nonlinear ball forces (for the time
//! response), with an explicit seam for the thermal coupling.
//!
//! # Convention mapping (bearing -> rotor)
//!
//! The bearing solver (src/bearing/model.rs) uses the inner-ring
//! displacement q = [dx, dy, dz, theta_x, theta_y] relative to the outer
//! ring, right-hand rotations (the tilt enters the axial groove-centre
//! distance as R_i (theta_x sin psi - theta_y cos psi), i.e. theta x p with
//! p = R_i (cos psi, sin psi, 0)), and K = -d(reaction)/dq with the
//! reaction of the balls ON the inner ring. The rotor (src/rotor/support.rs)
//! uses right-hand rotations too (theta_y = +du_x/dz, theta_x = -du_y/dz)
//! and adds the bearing stiffness K to the shaft stiffness, i.e. the force
//! on the shaft is -K q. The inner ring moves with the shaft and the outer
//! ring with the (rigid) housing, so for a row whose axial direction (the
//! direction of the axial load it carries) is +z of the shaft the mapping
//! is the identity.
//!
//! The second row of a back-to-back pair is the mirror image z -> -z. A
//! translation transforms as a polar vector (dz flips), a rotation as an
//! axial vector (theta' = det(P) P theta: theta_x and theta_y flip), and the
//! same for forces and moments, so q_row = T q_shaft, f_shaft = T f_row and
//! K_shaft = T K_row T with T = diag(1, 1, -1, -1, -1).
//!
//! Which row is mirrored follows from the arrangement: in the row frame
//! the contact lines meet the axis at z = -R_i tan(alpha) (the row's
//! pressure centre, K_x,theta_y / K_xx of the row), so the row on the
//! smaller-z side of each pair is taken unmirrored and the other mirrored,
//! which puts both pressure centres outside the pair: back-to-back (DB,
//! "O" arrangement). The test `back_to_back_pair_is_stiffer_in_tilt_than_face_to_face`
//! checks that this makes the pair's tilt stiffness the larger one.
//!
//! # Thermal seam
//!
//! Each pair takes an [`OffsetTable`] of [`RacewayOffsets`] (radial and
//! axial groove-centre offsets u_Tr, u_Ta of A-38) against speed, supplied
//! by the thermal model of the spindle; zero offsets give the uncoupled
//! model exactly. Under a constant-force (spring) preload the axial offset
//! only shifts the axial position of the inner ring (the solver finds the
//! dz that carries the preload), so it leaves the stiffness unchanged; the
//! radial offset changes the contact angles and the stiffness.
//!
//! # Damping
//!
//! The ball model has no damping (no EHL film damping): the supports have
//! zero damping matrices and the rotor's modal damping ratio carries the
//! dissipation (src/rotor/presets.rs).

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use nalgebra::{DVector, Matrix4, Matrix5};

use super::support::{BearingCoefficients, BearingModel as SupportModel};
use super::transient::NonlinearForce;
use super::{LateralDof, Rotor};
use crate::bearing::{Bearing, BearingModel as BallModel, BearingType, RacewayOffsets, SolveOptions, WarmStart};
use crate::error::{finite, positive, Error, Result};

/// Mirror z -> -z on [x, y, z, theta_x, theta_y] (polar translations, axial rotations).
pub const MIRROR_Z: [f64; 5] = [1.0, 1.0, -1.0, -1.0, -1.0];

/// Raceway offsets against speed (linear interpolation, held constant
/// outside the table). The thermal model's output enters here.
#[derive(Debug, Clone, PartialEq)]
pub struct OffsetTable {
    speeds_rpm: Vec<f64>,
    offsets: Vec<RacewayOffsets>,
}

impl OffsetTable {
    /// A table; speeds finite and strictly increasing, one offset per speed.
    pub fn new(speeds_rpm: Vec<f64>, offsets: Vec<RacewayOffsets>) -> Result<Self> {
        if speeds_rpm.is_empty() || speeds_rpm.len() != offsets.len() {
            return Err(Error::config(
                "offset_speeds_rpm",
                speeds_rpm.len(),
                format!("need one speed per offset ({} offsets given)", offsets.len()),
            ));
        }
        for s in &speeds_rpm {
            finite("offset_speeds_rpm", *s)?;
        }
        for w in speeds_rpm.windows(2) {
            if w[1].partial_cmp(&w[0]) != Some(std::cmp::Ordering::Greater) {
                return Err(Error::config("offset_speeds_rpm", w[1], "must be strictly increasing"));
            }
        }
        for o in &offsets {
            finite("raceway_offsets.radial_m", o.radial_m)?;
            finite("raceway_offsets.axial_m", o.axial_m)?;
        }
        Ok(OffsetTable { speeds_rpm, offsets })
    }

    /// Offsets at `speed_rpm`.
    pub fn at(&self, speed_rpm: f64) -> RacewayOffsets {
        let s = &self.speeds_rpm;
        let n = s.len();
        if speed_rpm <= s[0] {
            return self.offsets[0];
        }
        if speed_rpm >= s[n - 1] {
            return self.offsets[n - 1];
        }
        let i = s.partition_point(|&x| x <= speed_rpm) - 1;
        let t = (speed_rpm - s[i]) / (s[i + 1] - s[i]);
        let (a, b) = (self.offsets[i], self.offsets[i + 1]);
        RacewayOffsets {
            axial_m: a.axial_m + t * (b.axial_m - a.axial_m),
            radial_m: a.radial_m + t * (b.radial_m - a.radial_m),
        }
    }
}

/// Quasi-static state of one row (in its own frame) at one speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RowOperatingPoint {
    /// Speed of the solve \[rpm\], always >= 0 (the quasi-static ball model
    /// ignores the direction of rotation).
    pub speed_rpm: f64,
    /// Inner-ring displacement carrying the preload, row frame [m, rad].
    pub displacement: [f64; 5],
    /// Ball reaction on the inner ring at that point, row frame [N, N m].
    pub reaction: [f64; 5],
    /// Tangent stiffness -d(reaction)/dq, row frame (SI blocks).
    pub stiffness_si: Matrix5<f64>,
    /// Mean orbital (cage) speed of the balls [rad/s].
    pub cage_speed_rad_s: f64,
    /// Raceway offsets used \[m\].
    pub offsets: RacewayOffsets,
}

/// Most operating points one [`PreloadedRow`] keeps (one per speed): a
/// Campbell diagram or a response sweep asks each speed several times in a
/// row (both rows of a pair, the matrices and the solve), and no sweep of
/// the studies has more than a few hundred speeds, so the bound keeps every
/// hit while a long-lived row cannot grow without limit.
pub const ROW_CACHE_CAPACITY: usize = 512;

/// Operating points by speed, at most [`ROW_CACHE_CAPACITY`]; when full the
/// least recently used one is dropped.
#[derive(Default)]
struct PointCache {
    points: HashMap<u64, (RowOperatingPoint, u64)>,
    clock: u64,
}

impl PointCache {
    fn get(&mut self, key: u64) -> Option<RowOperatingPoint> {
        self.clock += 1;
        let now = self.clock;
        self.points.get_mut(&key).map(|(p, used)| {
            *used = now;
            *p
        })
    }

    fn insert(&mut self, key: u64, point: RowOperatingPoint) {
        if self.points.len() >= ROW_CACHE_CAPACITY && !self.points.contains_key(&key) {
            let oldest = self.points.iter().min_by_key(|(_, (_, used))| *used).map(|(k, _)| *k);
            if let Some(k) = oldest {
                self.points.remove(&k);
            }
        }
        self.clock += 1;
        self.points.insert(key, (point, self.clock));
    }
}

/// One angular-contact row type of a pair under a constant-force preload,
/// solved in its own frame (both rows of the pair share it), with a
/// bounded per-speed cache ([`ROW_CACHE_CAPACITY`]).
pub struct PreloadedRow {
    model: BallModel,
    preload_n: f64,
    options: SolveOptions,
    offsets: Option<OffsetTable>,
    cache: Mutex<PointCache>,
}

impl std::fmt::Debug for PreloadedRow {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("PreloadedRow")
            .field("bearing", &self.model.bearing().name)
            .field("preload_n", &self.preload_n)
            .field("offsets", &self.offsets)
            .finish_non_exhaustive()
    }
}

impl PreloadedRow {
    /// An angular-contact row under the axial preload `preload_n` (each row
    /// of a back-to-back pair carries it), with optional thermal offsets.
    pub fn new(bearing: &Bearing, preload_n: f64, options: SolveOptions, offsets: Option<OffsetTable>) -> Result<Self> {
        positive("preload_n", preload_n)?;
        if bearing.geometry.bearing_type != BearingType::AngularContact {
            return Err(Error::config(
                "bearing",
                bearing.name.clone(),
                "a preloaded spindle row must be an angular-contact bearing",
            ));
        }
        Ok(PreloadedRow {
            model: BallModel::new(bearing)?,
            preload_n,
            options,
            offsets,
            cache: Mutex::new(PointCache::default()),
        })
    }

    /// Operating points held in the cache (at most [`ROW_CACHE_CAPACITY`]).
    pub fn cached_points(&self) -> usize {
        self.cache.lock().map_or(0, |c| c.points.len())
    }

    /// The ball model.
    pub fn ball_model(&self) -> &BallModel {
        &self.model
    }

    /// Solve options at `speed_rpm` (offsets from the table, else zero).
    pub fn options_at(&self, speed_rpm: f64) -> SolveOptions {
        SolveOptions {
            offsets: self
                .offsets
                .as_ref()
                .map_or(RacewayOffsets::default(), |t| t.at(speed_rpm)),
            ..self.options
        }
    }

    /// Operating point at `speed_rpm` (cached; the speed's sign is the
    /// direction of rotation, which the quasi-static ball model ignores).
    pub fn operating_point(&self, speed_rpm: f64) -> Result<RowOperatingPoint> {
        finite("speed_rpm", speed_rpm)?;
        let speed_rpm = speed_rpm.abs();
        let key = speed_rpm.to_bits();
        if let Some(p) = self.cache.lock().map_err(|_| poisoned())?.get(key) {
            return Ok(p);
        }
        let p = self.solve_point(speed_rpm)?;
        self.cache.lock().map_err(|_| poisoned())?.insert(key, p);
        Ok(p)
    }

    fn solve_point(&self, speed_rpm: f64) -> Result<RowOperatingPoint> {
        let opts = self.options_at(speed_rpm);
        let load = [0.0, 0.0, self.preload_n, 0.0, 0.0];
        let state = self.model.solve(&load, speed_rpm, &opts)?;
        let q = state.displacement;
        let mut warm = WarmStart::new();
        let f = self.model.ring_forces(&q, speed_rpm, &opts, &mut warm)?;
        let balls = self.model.ball_states(&q, speed_rpm, &opts, &warm)?;
        let cage = balls.iter().map(|b| b.orbit_speed_rad_s).sum::<f64>() / balls.len().max(1) as f64;
        Ok(RowOperatingPoint {
            speed_rpm,
            displacement: q,
            reaction: f.reaction,
            stiffness_si: Matrix5::from_fn(|i, j| f.stiffness_matrix[i][j]),
            cage_speed_rad_s: cage,
            offsets: opts.offsets,
        })
    }
}

fn poisoned() -> Error {
    Error::config("bearing_cache", "mutex", "poisoned by a panic in another thread")
}

/// K_shaft = T K_row T (T = diag(MIRROR_Z)) for a mirrored row, else K_row.
pub fn to_shaft_frame(k_row: &Matrix5<f64>, mirrored: bool) -> Matrix5<f64> {
    if !mirrored {
        return *k_row;
    }
    Matrix5::from_fn(|i, j| MIRROR_Z[i] * k_row[(i, j)] * MIRROR_Z[j])
}

/// One row of a pair on the shaft: the shared row solution, mirrored or not.
#[derive(Debug, Clone)]
pub struct SpindleRow {
    /// The row solution (with its cache), shared by both rows of a pair.
    pub row: Arc<PreloadedRow>,
    /// Row's load direction is -z of the shaft (second row of a DB pair).
    pub mirrored: bool,
}

impl SupportModel for SpindleRow {
    fn coefficients(&self, speed_rpm: f64) -> Result<BearingCoefficients> {
        let p = self.row.operating_point(speed_rpm)?;
        Ok(BearingCoefficients {
            stiffness_si: to_shaft_frame(&p.stiffness_si, self.mirrored),
            damping_si: Matrix5::zeros(),
        })
    }
}

/// The lateral shaft displacement [x, y, theta_x, theta_y] of a row, as a
/// row-frame displacement increment in the cage frame rotated by `cage_rad`.
fn lateral_to_row_cage(u: &[f64; 4], mirrored: bool, cage_rad: f64) -> [f64; 5] {
    let m = if mirrored { MIRROR_Z } else { [1.0; 5] };
    let (s, c) = cage_rad.sin_cos();
    // Row frame (T on [x, y, ., tx, ty]), then rotate by -cage about z.
    let (x, y, tx, ty) = (m[0] * u[0], m[1] * u[1], m[3] * u[2], m[4] * u[3]);
    [c * x + s * y, -s * x + c * y, 0.0, c * tx + s * ty, -s * tx + c * ty]
}

/// A cage-frame row force [Fx, Fy, Fz, Mx, My] back to the shaft frame
/// (rotate by +cage, then mirror), lateral part [Fx, Fy, Mx, My].
fn cage_to_shaft_lateral(f: &[f64; 5], mirrored: bool, cage_rad: f64) -> [f64; 4] {
    let m = if mirrored { MIRROR_Z } else { [1.0; 5] };
    let (s, c) = cage_rad.sin_cos();
    [
        m[0] * (c * f[0] - s * f[1]),
        m[1] * (s * f[0] + c * f[1]),
        m[3] * (c * f[3] - s * f[4]),
        m[4] * (s * f[3] + c * f[4]),
    ]
}

/// State of one row in the nonlinear force.
struct NonlinearRow {
    row: Arc<PreloadedRow>,
    mirrored: bool,
    /// Physical DOFs [x, y, theta_x, theta_y] of the row's node.
    dofs: [usize; 4],
    point: RowOperatingPoint,
    options: SolveOptions,
    /// Linear lateral stiffness already in the rotor model (shaft frame).
    linear: Matrix4<f64>,
    warm: Mutex<WarmStart>,
}

/// Full nonlinear ball forces of the spindle rows for the time response.
///
/// The rotor keeps the linearised supports (they define its modal basis
/// and damping), so this force adds f_balls(q) - f_balls(0) + K_lin q, the
/// part of the ball forces beyond the linearisation. The axial DOF of each
/// row is held at its operating point (the lateral rotor model has no
/// axial DOF; under a spring preload the axial motion is decoupled to first
/// order).
///
/// Ball passage: the bearing solver places ball j at the fixed azimuth
/// psi_j = 2 pi j / Z. With the cage turned by phi = omega_c t the balls sit
/// at psi_j + phi, and A2 = dx cos(psi_j + phi) + dy sin(psi_j + phi) =
/// dx' cos psi_j + dy' sin psi_j with (dx', dy') = R(-phi) (dx, dy); the
/// tilt term of A1 transforms the same way with (theta_x, theta_y). So the
/// displacement is rotated into the cage frame, the solver evaluates the
/// balls at their fixed azimuths, and the reaction (Fx, Fy) and (Mx, My) is
/// rotated back by R(+phi). The stiffness of the row then varies with the
/// cage angle at the ball-pass frequency Z omega_c by itself.
pub struct NonlinearBearingForces {
    rows: Vec<NonlinearRow>,
    speed_rpm: f64,
    /// Rotate the ball set with the cage (false: balls at fixed azimuths).
    pub cage_rotation: bool,
}

impl NonlinearBearingForces {
    /// Nonlinear forces of the rows `rows` (axial position \[m\], row) of
    /// `rotor` at `speed_rpm`; each position must be a node of the rotor.
    pub fn new(rotor: &Rotor, rows: &[(f64, SpindleRow)], speed_rpm: f64) -> Result<Self> {
        let mut out = Vec::with_capacity(rows.len());
        for (position_m, r) in rows {
            let node = rotor.node_at(*position_m)?;
            let point = r.row.operating_point(speed_rpm)?;
            let linear = r.coefficients(speed_rpm)?.lateral_stiffness();
            out.push(NonlinearRow {
                row: r.row.clone(),
                mirrored: r.mirrored,
                dofs: [
                    rotor.dof(node, LateralDof::X),
                    rotor.dof(node, LateralDof::Y),
                    rotor.dof(node, LateralDof::ThetaX),
                    rotor.dof(node, LateralDof::ThetaY),
                ],
                options: r.row.options_at(speed_rpm),
                point,
                linear,
                warm: Mutex::new(WarmStart::new()),
            });
        }
        Ok(NonlinearBearingForces {
            rows: out,
            speed_rpm,
            cage_rotation: true,
        })
    }
}

impl NonlinearForce for NonlinearBearingForces {
    fn add_force(&self, time_s: f64, q: &DVector<f64>, _qd: &DVector<f64>, force: &mut DVector<f64>) -> Result<()> {
        for r in &self.rows {
            let u = [q[r.dofs[0]], q[r.dofs[1]], q[r.dofs[2]], q[r.dofs[3]]];
            let cage = if self.cage_rotation {
                r.point.cage_speed_rad_s * time_s
            } else {
                0.0
            };
            let du = lateral_to_row_cage(&u, r.mirrored, cage);
            let mut qr = r.point.displacement;
            for (a, d) in qr.iter_mut().zip(du) {
                *a += d;
            }
            let f = {
                let mut warm = r.warm.lock().map_err(|_| poisoned())?;
                r.row.model.ring_forces(&qr, self.speed_rpm, &r.options, &mut warm)?
            };
            let mut delta = f.reaction;
            for (d, f0) in delta.iter_mut().zip(r.point.reaction) {
                *d -= f0;
            }
            let fl = cage_to_shaft_lateral(&delta, r.mirrored, cage);
            let ku = r.linear * nalgebra::Vector4::from(u);
            for k in 0..4 {
                force[r.dofs[k]] += fl[k] + ku[k];
            }
        }
        Ok(())
    }

    fn dofs(&self) -> Vec<usize> {
        self.rows.iter().flat_map(|r| r.dofs).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(name: &str, offsets: Option<OffsetTable>) -> Arc<PreloadedRow> {
        Arc::new(PreloadedRow::new(&Bearing::preset(name).unwrap(), 400.0, SolveOptions::default(), offsets).unwrap())
    }

    #[test]
    fn row_coupling_puts_the_pressure_centre_at_minus_r_tan_alpha() {
        // Zero speed: each ball's approach is delta = |A| - A with
        // d(delta)/dx = cos(a) cos(psi), d(delta)/d(theta_y) = -R_i sin(a) cos(psi),
        // so the row acts as a radial spring at z = -R_i tan(a) of its
        // centre: K_x,ty / K_xx = -R_i tan(a) up to the geometric
        // (load x angle-change) terms, which are a few % at 400 N.
        let r = row("7009C", None);
        let p = r.operating_point(0.0).unwrap();
        let k = p.stiffness_si;
        let state = r
            .model
            .solve(&[0.0, 0.0, 400.0, 0.0, 0.0], 0.0, &SolveOptions::default())
            .unwrap();
        let alpha = state.balls[0].inner_contact_angle_rad;
        let d = k[(0, 4)] / k[(0, 0)];
        let expect = -r.model.r_groove * alpha.tan();
        assert!(k[(0, 0)] > 0.0 && k[(4, 4)] > 0.0 && d < 0.0, "{k}");
        assert!((d / expect - 1.0).abs() < 0.1, "{d} vs {expect}");
        // Symmetric tangent, isotropic in x/y.
        assert!((k[(0, 4)] - k[(4, 0)]).abs() < 1e-4 * k[(0, 4)].abs(), "{k}");
        assert!((k[(0, 0)] - k[(1, 1)]).abs() < 1e-6 * k[(0, 0)]);
    }

    #[test]
    fn tilted_shaft_gives_the_moment_and_force_signs_the_rotor_expects() {
        // Tilt the shaft by +theta_y (right-hand, +z towards +x) through an
        // unmirrored row: the balls push back with a negative moment M_y,
        // and because the pressure centre sits at z_p = -R tan(a) < 0 where
        // the shaft moves by z_p theta_y < 0, the radial force on the shaft
        // is +x. The rotor adds K to its stiffness (force = -K q): both
        // signs must come out of -K q with the mapped K, and from the full
        // ball forces directly.
        let r = row("7009C-hybrid", None);
        let speed = 12_000.0;
        let p = r.operating_point(speed).unwrap();
        let th = 2e-6;
        for mirrored in [false, true] {
            let sr = SpindleRow {
                row: r.clone(),
                mirrored,
            };
            let k = sr.coefficients(speed).unwrap().lateral_stiffness();
            let u = nalgebra::Vector4::new(0.0, 0.0, 0.0, th);
            let f_lin = -(k * u);
            let dq = lateral_to_row_cage(&[0.0, 0.0, 0.0, th], mirrored, 0.0);
            let mut q = p.displacement;
            for (a, d) in q.iter_mut().zip(dq) {
                *a += d;
            }
            let f = r
                .model
                .ring_forces(&q, speed, &r.options_at(speed), &mut WarmStart::new())
                .unwrap();
            let delta: Vec<f64> = f.reaction.iter().zip(p.reaction).map(|(a, b)| a - b).collect();
            let f_full = cage_to_shaft_lateral(&[delta[0], delta[1], delta[2], delta[3], delta[4]], mirrored, 0.0);
            assert!(f_lin[3] < 0.0 && f_full[3] < 0.0, "restoring moment {f_lin} {f_full:?}");
            // Unmirrored: pressure centre on -z, force +x; mirrored: on +z, force -x.
            let sign = if mirrored { -1.0 } else { 1.0 };
            assert!(
                sign * f_lin[0] > 0.0 && sign * f_full[0] > 0.0,
                "{mirrored} {f_lin} {f_full:?}"
            );
            for i in [0, 3] {
                assert!(
                    (f_full[i] - f_lin[i]).abs() < 0.02 * f_lin[i].abs(),
                    "{i}: {f_full:?} vs {f_lin}"
                );
            }
        }
    }

    #[test]
    fn back_to_back_pair_is_stiffer_in_tilt_than_face_to_face() {
        // Rigid tilt theta of the shaft about the pair centre: row i at
        // e_i = z_i - z_mid moves by x_i = e_i theta, so the pair's tilt
        // stiffness is sum(K_xx e^2 + 2 K_x,ty e + K_ty,ty). Back-to-back
        // (smaller-z row unmirrored) puts the pressure centres outside the
        // rows and must beat face-to-face, and beat the spacing alone.
        let r = row("7009C", None);
        let half = 0.008;
        let tilt = |first_mirrored: bool| {
            [(-half, first_mirrored), (half, !first_mirrored)]
                .iter()
                .map(|&(e, m)| {
                    let k = SpindleRow {
                        row: r.clone(),
                        mirrored: m,
                    }
                    .coefficients(6_000.0)
                    .unwrap()
                    .lateral_stiffness();
                    k[(0, 0)] * e * e + 2.0 * k[(0, 3)] * e + k[(3, 3)]
                })
                .sum::<f64>()
        };
        let (db, df) = (tilt(false), tilt(true));
        let k = r.operating_point(6_000.0).unwrap().stiffness_si;
        let spacing_only = 2.0 * k[(0, 0)] * half * half + 2.0 * k[(4, 4)];
        assert!(db > spacing_only && spacing_only > df, "{db} {spacing_only} {df}");
    }

    #[test]
    fn zero_offsets_equal_uncoupled_and_radial_offset_stiffens() {
        let zero = OffsetTable::new(vec![0.0, 20_000.0], vec![RacewayOffsets::default(); 2]).unwrap();
        let plain = row("7008C", None).operating_point(15_000.0).unwrap();
        let coupled = row("7008C", Some(zero)).operating_point(15_000.0).unwrap();
        assert_eq!(plain, coupled);
        // A positive radial offset (thermal growth of the inner ring) lowers
        // the contact angle under the same axial preload, so each ball
        // carries Fa / (Z sin a), more load, and the radial stiffness rises.
        let hot = OffsetTable::new(
            vec![15_000.0],
            vec![RacewayOffsets {
                axial_m: 0.0,
                radial_m: 4e-6,
            }],
        )
        .unwrap();
        let warm = row("7008C", Some(hot)).operating_point(15_000.0).unwrap();
        assert!(warm.stiffness_si[(0, 0)] > 1.05 * plain.stiffness_si[(0, 0)]);
        // An axial offset under a constant-force preload only shifts dz.
        let ax = OffsetTable::new(
            vec![15_000.0],
            vec![RacewayOffsets {
                axial_m: 3e-6,
                radial_m: 0.0,
            }],
        )
        .unwrap();
        let shifted = row("7008C", Some(ax)).operating_point(15_000.0).unwrap();
        assert!((shifted.displacement[2] - (plain.displacement[2] - 3e-6)).abs() < 1e-9);
        assert!((shifted.stiffness_si[(0, 0)] / plain.stiffness_si[(0, 0)] - 1.0).abs() < 1e-6);
        assert!(OffsetTable::new(vec![1.0, 1.0], vec![RacewayOffsets::default(); 2]).is_err());
    }

    #[test]
    fn turning_the_cage_by_one_ball_pitch_repeats_the_ball_forces() {
        // The ball set is invariant under a rotation by 2 pi / Z, so the
        // force on a radially displaced shaft is periodic in the cage angle
        // with the ball pitch (the ball-pass frequency), and differs at half
        // a pitch (ball on the load line vs. straddling it). The ripple is
        // small for 16 preloaded balls: 2e-7 of the force at 6 um
        // (measured), against a solver noise of ~1e-14.
        let r = row("7009C", None);
        let speed = 10_000.0;
        let p = r.operating_point(speed).unwrap();
        let opts = r.options_at(speed);
        let z = r.model.ball_count() as f64;
        let u = [6e-6, 0.0, 0.0, 0.0];
        let force = |cage: f64| {
            let mut q = p.displacement;
            for (a, d) in q.iter_mut().zip(lateral_to_row_cage(&u, false, cage)) {
                *a += d;
            }
            let f = r.model.ring_forces(&q, speed, &opts, &mut WarmStart::new()).unwrap();
            cage_to_shaft_lateral(&f.reaction, false, cage)
        };
        let pitch = 2.0 * std::f64::consts::PI / z;
        let (a, b, c) = (force(0.1), force(0.1 + pitch), force(0.1 + 0.5 * pitch));
        assert!(a[0] < -100.0, "restoring force {a:?}");
        for i in 0..4 {
            assert!((a[i] - b[i]).abs() < 1e-10 * a[0].abs(), "{a:?} vs {b:?}");
        }
        assert!((a[0] - c[0]).abs() > 1e-7 * a[0].abs(), "{a:?} vs {c:?}");
    }

    #[test]
    fn cage_rotation_round_trip_is_a_rotation() {
        // Rotating into the cage frame and back is the identity on lateral
        // vectors, and the mirror flips tilts only.
        let u = [1.0, -2.0, 0.3, 0.7];
        for m in [false, true] {
            let q = lateral_to_row_cage(&u, m, 0.83);
            let back = cage_to_shaft_lateral(&q, m, 0.83);
            for i in 0..4 {
                assert!((back[i] - u[i]).abs() < 1e-15);
            }
        }
        let q = lateral_to_row_cage(&u, true, 0.0);
        assert_eq!(q, [1.0, -2.0, 0.0, -0.3, -0.7]);
    }
}
