//! Zero-speed bearing statics (seed A section 2.1, A-2..A-7; Harris &
//! Kotzalas, Essential Concepts, ch. 7; Jones 1960) and the damped Newton
//! iteration on the ring equilibrium shared with the high-speed model.
//!
//! At zero speed a ball is a two-force member: both contacts lie on the
//! line through the two groove curvature centres, at the same contact angle
//! alpha_j = atan2(A1j, A2j), and the total Hertz approach is
//! delta_j = sqrt(A1j^2 + A2j^2) - A. The ball load is
//! Q_j = K_n(alpha_j) delta_j^1.5 for delta_j > 0 and zero otherwise (A-2,
//! A-3), and the ring equilibrium A-8 is solved for the displacement q.
//!
//! The groove is modelled as a full circular arc on both sides of the ball
//! (deep-groove geometry); an angular-contact bearing therefore also carries
//! a ball on its low shoulder under tilt or radial load. Negative axial loads
//! on angular-contact bearings are rejected (see [`BearingModel`]).
//!
//! Zero load: the displacement is not unique inside the clearance; the
//! solvers return the concentric position q = 0 with all balls unloaded (and
//! at speed, resting on the outer raceway under their centrifugal force).

use nalgebra::{Matrix5, Vector5};

use super::dual::Dual;
use super::model::BearingModel;
use super::model::RacewayOffsets;
use super::state::{BallState, BearingState, SolveOptions, Tilt};
use super::stiffness::seed_stiffness;
use crate::error::{Error, Result};

/// Contact angle of a thrust-loaded bearing:
/// Fa / (Z K_n (B_f D)^1.5) = sin(a) (cos(a0) / cos(a) - 1)^1.5, with K_n
/// evaluated at the contact angle a itself; safeguarded Newton \[rad\].
pub fn thrust_contact_angle(model: &BearingModel, axial_n: f64) -> Result<f64> {
    crate::error::non_negative("axial_n", axial_n)?;
    let a0 = model.bearing.geometry.free_contact_angle_rad;
    if axial_n == 0.0 {
        return Ok(a0);
    }
    let z = model.ball_count() as f64;
    let scale = model.a0.powf(1.5);
    let f = |a: f64| -> Dual<1> {
        let x = Dual::<1>::var(a, 0);
        let (s, c) = (sin_d(x), cos_d(x));
        let kn = model.kn(c);
        let stretch = (c.recip() * a0.cos() - 1.0).pow1_5_pos();
        kn * s * stretch * (z * scale) - axial_n
    };
    let (mut lo, mut hi) = (a0, 85f64.to_radians());
    if f(hi).v < 0.0 {
        return Err(Error::config(
            "axial_n",
            axial_n,
            "thrust load drives the contact angle beyond 85 deg",
        ));
    }
    // Small-angle estimate of A-4, sin a (cos a0 / cos a - 1)^1.5 ~
    // a ((a^2 - a0^2) / 2)^1.5, taken 10 % high: f is convex and increasing
    // there, so Newton from above approaches the root monotonically.
    let c = axial_n / (z * model.ball_constant(a0) * scale);
    let a_small = (2f64.powf(1.5) * c).powf(0.25);
    let a_est = (a0 * a0 + 2.0 * (c / a_small.max(a0)).powf(2.0 / 3.0)).sqrt();
    let mut a = (1.1 * a_est.max(a_small)).clamp(lo + 1e-9, hi);
    for _ in 0..200 {
        let r = f(a);
        if r.v > 0.0 {
            hi = a;
        } else {
            lo = a;
        }
        let mut next = a - r.v / r.d[0];
        if !(next > lo && next < hi && next.is_finite()) {
            next = 0.5 * (lo + hi);
        }
        if (next - a).abs() < 1e-15 || hi - lo < 1e-15 {
            return Ok(next);
        }
        a = next;
    }
    Err(Error::convergence("thrust contact angle", 200, hi - lo, 1e-15))
}

fn sin_d(x: Dual<1>) -> Dual<1> {
    Dual {
        v: x.v.sin(),
        d: [x.d[0] * x.v.cos()],
    }
}

fn cos_d(x: Dual<1>) -> Dual<1> {
    Dual {
        v: x.v.cos(),
        d: [-x.d[0] * x.v.sin()],
    }
}

/// Generalised reaction (f1, f2) of a ball at zero speed on the inner ring
/// along the groove-centre directions A1 (axial), A2 (radial), as functions
/// of (A1, A2): f = -Q (sin a, cos a).
#[inline]
pub(crate) fn static_ball(model: &BearingModel, a1: f64, a2: f64) -> (Dual<2>, Dual<2>, Dual<2>) {
    let (x, y) = (Dual::<2>::var(a1, 0), Dual::<2>::var(a2, 1));
    let l = (x * x + y * y).sqrt();
    let (s, c) = (x / l, y / l);
    let kn = model.kn(c);
    let q = kn * (l - model.a0).pow1_5_pos();
    (-(q * s), -(q * c), q)
}

/// Reaction of all balls on the inner ring at displacement q, zero speed,
/// and the stiffness K = -d(reaction)/dq.
pub(crate) fn static_ring(model: &BearingModel, q: &[f64; 5], opts: &SolveOptions) -> ([f64; 5], [[f64; 5]; 5]) {
    let mut reaction = [0.0; 5];
    let mut k = [[0.0; 5]; 5];
    for j in 0..model.ball_count() {
        let (a1, a2) = model.groove_distances(j, q, 0.0, &opts.offsets);
        let (f1, f2, _) = static_ball(model, a1, a2);
        let (g1, g2) = model.groove_gradients(j);
        assemble(&mut reaction, &mut k, (f1.v, f2.v), [f1.d, f2.d], (&g1, &g2));
    }
    (reaction, k)
}

/// Add one ball's generalised reaction (f1, f2) with derivatives df/dp
/// (p = (A1, A2)) to the ring reaction and stiffness.
#[inline]
pub(crate) fn assemble(
    reaction: &mut [f64; 5],
    k: &mut [[f64; 5]; 5],
    f: (f64, f64),
    dfdp: [[f64; 2]; 2],
    (g1, g2): (&[f64; 5], &[f64; 5]),
) {
    for r in 0..5 {
        reaction[r] += f.0 * g1[r] + f.1 * g2[r];
    }
    // d f / d q = df/dp * [g1; g2]
    let mut df1 = [0.0; 5];
    let mut df2 = [0.0; 5];
    for c in 0..5 {
        df1[c] = dfdp[0][0] * g1[c] + dfdp[0][1] * g2[c];
        df2[c] = dfdp[1][0] * g1[c] + dfdp[1][1] * g2[c];
    }
    for r in 0..5 {
        if g1[r] == 0.0 && g2[r] == 0.0 {
            continue;
        }
        for c in 0..5 {
            k[r][c] -= g1[r] * df1[c] + g2[r] * df2[c];
        }
    }
}

/// Per-ball states of the static solution.
pub(crate) fn static_balls(model: &BearingModel, q: &[f64; 5], opts: &SolveOptions) -> Vec<BallState> {
    (0..model.ball_count())
        .map(|j| {
            let (a1, a2) = model.groove_distances(j, q, 0.0, &opts.offsets);
            let (_, _, qd) = static_ball(model, a1, a2);
            let load = qd.v;
            let l = a1.hypot(a2);
            let alpha = a1.atan2(a2);
            let c = a2 / l;
            let ki = model.inner.k(Dual::<1>::cst(c)).v;
            let ko = model.outer.k(Dual::<1>::cst(c)).v;
            let (di, dd) = if load > 0.0 {
                ((load / ki).powf(2.0 / 3.0), (load / ko).powf(2.0 / 3.0))
            } else {
                let gap = l - model.a0;
                (0.5 * gap, 0.5 * gap)
            };
            BallState {
                azimuth_rad: model.bearing.geometry.azimuth(j),
                inner_load_n: load,
                outer_load_n: load,
                inner_contact_angle_rad: alpha,
                outer_contact_angle_rad: alpha,
                inner_deflection_m: di,
                outer_deflection_m: dd,
                inner_semi_major_m: model.inner.semi_major_m(c, load),
                outer_semi_major_m: model.outer.semi_major_m(c, load),
                ..BallState::default()
            }
        })
        .collect()
}

/// Solve the zero-speed equilibrium for the load [Fx, Fy, Fz, Mx, My]
/// (N, N m) on the inner ring.
pub fn solve_static(model: &BearingModel, load: &[f64; 5], opts: &SolveOptions) -> Result<BearingState> {
    model.check_load(load)?;
    check_moment_with_tilt(load, opts)?;
    let sol = static_displacement(model, load, opts)?;
    let balls = static_balls(model, &sol.q, opts);
    let (ka, kr) = seed_stiffness(model, &balls);
    BearingState {
        displacement: sol.q,
        applied_load: sol.load,
        balls,
        stiffness_matrix: sol.k,
        axial_stiffness_seed_n_per_m: ka,
        radial_stiffness_seed_n_per_m: kr,
        iterations: sol.iterations,
        residual: sol.residual,
        speed_rpm: 0.0,
    }
    .checked("static bearing equilibrium")
}

/// The zero-speed ring equilibrium only (no per-ball output).
pub(crate) fn static_displacement(model: &BearingModel, load: &[f64; 5], opts: &SolveOptions) -> Result<RingSolution> {
    model.check_load(load)?;
    check_options(opts)?;
    let q0 = initial_guess(model, load, opts)?;
    solve_ring(model, load, q0, 0.0, opts, "static bearing equilibrium", &mut |q| {
        Ok(static_ring(model, q, opts))
    })
}

/// A held tilt ([`Tilt::Fixed`], the default) makes the moments reactions:
/// an applied moment Mx or My would be ignored, so it is refused with the
/// way out (a free tilt carries it), as in the Python package.
pub(crate) fn check_moment_with_tilt(load: &[f64; 5], opts: &SolveOptions) -> Result<()> {
    if matches!(opts.tilt, Tilt::Fixed { .. }) {
        for (i, name) in [(3, "moment_x_n_m"), (4, "moment_y_n_m")] {
            if load[i] != 0.0 {
                return Err(Error::config(
                    name,
                    load[i],
                    "a moment needs a free tilt: set SolveOptions::tilt to Tilt::Free (with the default held tilt the moments are reactions)",
                ));
            }
        }
    }
    Ok(())
}

pub(crate) fn check_options(opts: &SolveOptions) -> Result<()> {
    crate::error::positive("tolerance", opts.tolerance)?;
    if opts.max_iterations == 0 {
        return Err(Error::config("max_iterations", 0, "must be at least 1"));
    }
    crate::error::finite("offsets.axial_m", opts.offsets.axial_m)?;
    crate::error::finite("offsets.radial_m", opts.offsets.radial_m)?;
    crate::error::in_range("traction_coefficient", opts.traction_coefficient, 0.0, 1.0)?;
    if let Tilt::Fixed {
        theta_x_rad,
        theta_y_rad,
    } = opts.tilt
    {
        crate::error::finite("theta_x_rad", theta_x_rad)?;
        crate::error::finite("theta_y_rad", theta_y_rad)?;
    }
    Ok(())
}

/// A start for the ring Newton iteration that engages the balls that will
/// carry the load: axial part from the thrust solution, radial part
/// from Stribeck's Q_max = 5 Fr / Z plus the radial clearance, tilt from
/// the thrust solution for the equivalent axial load 4 M / R_i.
pub(crate) fn initial_guess(model: &BearingModel, load: &[f64; 5], opts: &SolveOptions) -> Result<[f64; 5]> {
    let z = model.ball_count() as f64;
    let mut q = [0.0; 5];
    let fa = load[2].abs();
    let mut axial_engaged = false;
    if fa > 0.0 {
        let a = thrust_contact_angle(model, fa)?;
        q[2] = load[2].signum() * model.a0_radial * a.tan();
        axial_engaged = true;
    }
    let fr = load[0].hypot(load[1]);
    if fr > 0.0 {
        let kn = model.ball_constant(0.0);
        let delta = (5.0 * fr / (z * kn)).powf(2.0 / 3.0);
        let take_up = if axial_engaged { 0.0 } else { model.a0 - model.a0_radial };
        let dr = take_up + delta;
        q[0] = dr * load[0] / fr;
        q[1] = dr * load[1] / fr;
    }
    let m = load[3].hypot(load[4]);
    if m > 0.0 {
        let r = model.r_groove;
        let a = thrust_contact_angle(model, 4.0 * m / r)?;
        let theta = model.a0_radial * a.tan() / r;
        q[3] = theta * load[3] / m;
        q[4] = theta * load[4] / m;
    }
    Ok(hold_tilt(q, opts))
}

/// q with the held tilt of `opts` (unchanged for a free tilt).
pub(crate) fn hold_tilt(mut q: [f64; 5], opts: &SolveOptions) -> [f64; 5] {
    if let Tilt::Fixed {
        theta_x_rad,
        theta_y_rad,
    } = opts.tilt
    {
        q[3] = theta_x_rad;
        q[4] = theta_y_rad;
    }
    q
}

/// Ring evaluation: q -> (reaction, K = -d reaction / dq).
pub(crate) type RingEval<'a> = dyn FnMut(&[f64; 5]) -> Result<([f64; 5], [[f64; 5]; 5])> + 'a;

/// Result of the ring Newton iteration.
#[derive(Debug, Clone)]
pub(crate) struct RingSolution {
    pub q: [f64; 5],
    /// The load balanced at q: the applied load, with the holding moments
    /// in place of Mx, My when the tilt is held.
    pub load: [f64; 5],
    pub k: [[f64; 5]; 5],
    pub iterations: usize,
    pub residual: f64,
}

/// Step length t along the ring displacement direction `dir` (q-space,
/// unscaled) from a position q where no ball touches, to where the balls
/// carry about the load: the first ball reaches |p_j| = A (contact onset of
/// the static model, A-5/A-6: |p_j| is linear in t, so the onset is a root
/// of a quadratic), plus the approach delta = (F / (Z K_n))^(2/3) that
/// carries the load magnitude `force_n` shared by all balls (A-2, A-3; a
/// lower bound of the loaded approach: the iteration continues upwards from
/// it, where every ball that touches has a stiffness). `None` if no ball
/// comes into contact along `dir`.
pub(crate) fn reseat_step(
    model: &BearingModel,
    q: &[f64; 5],
    dir: &[f64; 5],
    u_r: f64,
    offsets: &RacewayOffsets,
    force_n: f64,
) -> Option<f64> {
    let a = model.a0;
    let mut first: Option<(f64, f64)> = None;
    for j in 0..model.ball_count() {
        let p = model.groove_distances(j, q, u_r, offsets);
        let (g1, g2) = model.groove_gradients(j);
        let v = (dot5(&g1, dir), dot5(&g2, dir));
        // |p + t v|^2 = A^2:  vv t^2 + 2 pv t + (pp - A^2) = 0.
        let vv = v.0 * v.0 + v.1 * v.1;
        if vv <= 0.0 || !vv.is_finite() {
            continue;
        }
        let pv = p.0 * v.0 + p.1 * v.1;
        let c = p.0 * p.0 + p.1 * p.1 - a * a;
        let disc = pv * pv - vv * c;
        if disc < 0.0 {
            continue;
        }
        // Larger root: where |p| grows through A along the ray.
        let t = (-pv + disc.sqrt()) / vv;
        if !(t > 0.0 && t.is_finite()) {
            continue;
        }
        // Rate d|p|/dt at the onset (|p| = A there).
        let rate = (pv + t * vv) / a;
        if rate > 0.0 && first.is_none_or(|(tf, _)| t < tf) {
            first = Some((t, rate));
        }
    }
    let (t, rate) = first?;
    let z = model.ball_count() as f64;
    let kn = model.ball_constant(model.bearing.geometry.free_contact_angle_rad);
    let delta = (force_n / (z * kn)).powf(2.0 / 3.0);
    Some(t + delta / rate)
}

fn dot5(a: &[f64; 5], b: &[f64; 5]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Damped Newton iteration on load + reaction(q) = 0 in scaled
/// variables (tilts times R_i, moments over R_i), with a tiny Levenberg
/// regularisation for directions without stiffness and backtracking on the
/// residual norm. `eval` returns (reaction, K = -d reaction / dq).
///
/// `u_r` is the radial growth of the inner raceway used by `eval` (A-10;
/// zero at rest): the no-contact step needs the groove geometry that `eval`
/// sees (see [`reseat_step`]).
pub(crate) fn solve_ring(
    model: &BearingModel,
    load: &[f64; 5],
    q0: [f64; 5],
    u_r: f64,
    opts: &SolveOptions,
    solver: &str,
    eval: &mut RingEval<'_>,
) -> Result<RingSolution> {
    let r = model.r_groove;
    let scale = [1.0, 1.0, 1.0, r, r];
    let held = matches!(opts.tilt, Tilt::Fixed { .. });
    let free = [true, true, true, !held, !held];
    let q0 = hold_tilt(q0, opts);
    let load_ref = (0..5)
        .filter(|i| free[*i])
        .map(|i| (load[i] / scale[i]).abs())
        .fold(1.0, f64::max);
    let norms = |reaction: &[f64; 5]| -> (Vector5<f64>, f64) {
        let g = Vector5::from_fn(|i, _| {
            if free[i] {
                (load[i] + reaction[i]) / scale[i]
            } else {
                0.0
            }
        });
        let n = g.amax() / load_ref;
        (g, n)
    };
    let max_step = 0.25 * model.a0;
    // Stiffness of the bearing with all balls at 1 um approach, used when no
    // ball touches yet.
    let k_ref = model.ball_count() as f64 * 1.5 * model.ball_constant(0.0) * 1e-3;

    let mut q = q0;
    let (mut reaction, mut k) = eval(&q)?;
    let (mut g, mut res) = norms(&reaction);
    for it in 0..=opts.max_iterations {
        if res <= opts.tolerance {
            let balanced = std::array::from_fn(|i| if free[i] { load[i] } else { -reaction[i] });
            return Ok(RingSolution {
                q,
                load: balanced,
                k,
                iterations: it,
                residual: res,
            });
        }
        if it == opts.max_iterations {
            break;
        }
        let ks = Matrix5::from_fn(|i, j| match (free[i], free[j]) {
            (true, true) => k[i][j] / (scale[i] * scale[j]),
            _ if i == j => 1.0,
            _ => 0.0,
        });
        // Contact is judged on the free DOF only: a held tilt has a unit
        // placeholder on its diagonal, not a stiffness.
        let diag_max = (0..5)
            .filter(|i| free[*i])
            .map(|i| ks[(i, i)].abs())
            .fold(0.0, f64::max);
        let no_contact = diag_max <= 0.0;
        let (step, big, mut t) = if no_contact {
            // No ball touches (the offsets or the start opened every gap):
            // the reaction is zero around q, so Newton has nothing to go on
            // and a backtracking line search along the load cannot succeed
            // when the gap is wider than the Hertz approach the load needs.
            // Move along the load to where the balls re-seat instead.
            let dir: [f64; 5] = std::array::from_fn(|i| g[i] / scale[i]);
            match reseat_step(model, &q, &dir, u_r, &opts.offsets, g.norm()) {
                Some(t) => (Vector5::from_fn(|i, _| dir[i] * scale[i]), 0.0, t),
                None => {
                    // Fallback: a step against the stiffness of all balls at
                    // 1 um approach.
                    let step = (ks + Matrix5::identity() * k_ref)
                        .lu()
                        .solve(&g)
                        .filter(|s| s.iter().all(|v| v.is_finite()))
                        .ok_or_else(|| Error::convergence(solver, it, res, opts.tolerance))?;
                    let big = step.amax();
                    (step, big, 1.0)
                }
            }
        } else {
            let mu = 1e-12 * diag_max;
            let step = (ks + Matrix5::identity() * mu)
                .lu()
                .solve(&g)
                .filter(|s| s.iter().all(|v| v.is_finite()))
                .ok_or_else(|| Error::convergence(solver, it, res, opts.tolerance))?;
            let big = step.amax();
            (step, big, 1.0)
        };
        if big > max_step {
            t = max_step / big;
        }
        let mut accepted = false;
        for _ in 0..40 {
            let trial: [f64; 5] = std::array::from_fn(|i| q[i] + t * step[i] / scale[i]);
            let (rt, kt) = eval(&trial)?;
            let (gt, nt) = norms(&rt);
            if nt < res * (1.0 - 1e-4 * t) || no_contact {
                q = trial;
                reaction = rt;
                k = kt;
                g = gt;
                res = nt;
                accepted = true;
                break;
            }
            t *= 0.5;
        }
        if !accepted {
            return Err(Error::convergence(solver, it, res, opts.tolerance));
        }
    }
    Err(Error::convergence(solver, opts.max_iterations, res, opts.tolerance))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearing::Bearing;

    #[test]
    fn static_ring_jacobian_matches_finite_differences() {
        let m = BearingModel::new(&Bearing::preset("6208").unwrap()).unwrap();
        let o = SolveOptions::default();
        let q = [2.1e-5, -0.4e-5, 1.9e-4, 2e-4, 1.5e-3];
        let (_, k) = static_ring(&m, &q, &o);
        for c in 0..5 {
            let h = if c < 3 { 1e-10 } else { 1e-8 };
            let mut qp = q;
            let mut qm = q;
            qp[c] += h;
            qm[c] -= h;
            let (rp, _) = static_ring(&m, &qp, &o);
            let (rm, _) = static_ring(&m, &qm, &o);
            for r in 0..5 {
                let fd = -(rp[r] - rm[r]) / (2.0 * h);
                let tol = 1e-6 * k[r][r].abs().max(k[c][c].abs()).max(1.0);
                assert!((fd - k[r][c]).abs() < tol, "K[{r}][{c}] = {} vs fd {fd}", k[r][c]);
            }
        }
    }

    #[test]
    fn frozen_contact_constants_give_exact_symmetry() {
        // With K independent of the contact angle the static model derives
        // from the potential sum (2/5) K_n delta^2.5: K must be symmetric.
        let mut m = BearingModel::new(&Bearing::preset("7009C").unwrap()).unwrap();
        m.inner.freeze();
        m.outer.freeze();
        let free = SolveOptions {
            tilt: Tilt::Free,
            ..SolveOptions::default()
        };
        let s = solve_static(&m, &[900.0, -300.0, 1500.0, 8.0, -12.0], &free).unwrap();
        let k = s.stiffness_matrix;
        for i in 0..5 {
            for j in 0..5 {
                let scale = (k[i][i] * k[j][j]).sqrt();
                assert!((k[i][j] - k[j][i]).abs() < 1e-11 * scale, "{i} {j}");
            }
        }
    }

    #[test]
    fn thrust_angle_satisfies_a4() {
        let m = BearingModel::new(&Bearing::preset("7009C").unwrap()).unwrap();
        let fa = 1500.0;
        let a = thrust_contact_angle(&m, fa).unwrap();
        let a0 = m.bearing.geometry.free_contact_angle_rad;
        let lhs = fa / (m.ball_count() as f64 * m.ball_constant(a) * m.a0.powf(1.5));
        let rhs = a.sin() * (a0.cos() / a.cos() - 1.0).powf(1.5);
        assert!((lhs / rhs - 1.0).abs() < 1e-12);
        assert!(a > a0);
        assert_eq!(thrust_contact_angle(&m, 0.0).unwrap(), a0);
        assert!(thrust_contact_angle(&m, -1.0).is_err());
    }
}
