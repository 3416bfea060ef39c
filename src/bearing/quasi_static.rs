//! High-speed quasi-statics of a ball bearing (Jones 1960; Harris &
//! Kotzalas, Advanced Concepts, ch. 3; seed A section 2.2, A-8..A-19).
//!
//! The inner ring turns at the given speed, the outer ring is fixed. Per
//! ball j the unknowns are the axial and radial distances X1j, X2j from the
//! outer groove curvature centre to the ball centre; the approaches follow
//! from the compatibility relations A-13 solved for them,
//!
//! ```text
//! delta_oj = sqrt(X1^2 + X2^2) - (f_o - 0.5) D
//! delta_ij = sqrt((A1 - X1)^2 + (A2 - X2)^2) - (f_i - 0.5) D
//! ```
//!
//! with the contact angles from the same triangles (A-12):
//! sin a_o = X1 / (X1^2 + X2^2)^(1/2), sin a_i = (A1 - X1) / (...)^(1/2).
//! Eliminating delta_i, delta_o exactly this way leaves two ball-equilibrium
//! equations (A-15, with the friction-couple sign derived in
//! [`super::kinematics`]) in two unknowns per ball:
//!
//! ```text
//! Q_i sin a_i - Q_o sin a_o + s_g (Mg/D)(lambda_i cos a_i - lambda_o cos a_o) = 0
//! Q_i cos a_i - Q_o cos a_o - s_g (Mg/D)(lambda_i sin a_i - lambda_o sin a_o) + Fc = 0
//! ```
//!
//! Q = K(a) delta^1.5 (zero for delta <= 0), Fc = m dm omega_c^2 / 2 (A-16),
//! Mg = J omega_b omega_c sin(beta) (A-17), with omega_c, omega_b, beta from
//! the raceway-control kinematics evaluated at the current contact angles
//! (their dependence on the angles is part of the Jacobian). The ring
//! equilibrium A-8 over the five ring DOF is solved by Newton's method on q
//! (nested: each ring evaluation solves every ball by a damped 2x2 Newton
//! iteration, warm-started from the previous one with a first-order
//! predictor); the ring Jacobian is the exact condensed stiffness
//! dF/dq = sum_j B_j^T (df/dp - df/dx (dR/dx)^(-1) dR/dp) B_j
//! (implicit-function theorem). All derivatives are exact (dual numbers).
//!
//! A ball whose inner contact opens rides on the outer raceway under its
//! centrifugal force; at zero speed (or without centrifugal force) a ball
//! with an open gap is free and carries nothing. Without centrifugal force
//! the friction couple against the gyroscopic moment is bounded by Coulomb
//! friction (`friction_couple`, `SolveOptions::traction_coefficient`): a
//! ball that just touches slides, bent by a_i - a_o = 2 atan(mu), and its
//! loads grow from zero from the groove-centre distance
//! `SpeedContext::onset_distance` on. With inner-raceway control
//! the gyroscopic friction couple at the inner contact is kept whatever the
//! inner load (Jones's hypothesis assumes enough friction); its moment
//! about the groove centre (f_i Mg per ball) enters the ring moments.

use super::dual::Dual;
use super::kinematics::{ball_kinematics, kinematics};
use super::model::BearingModel;
use super::state::{BallState, BearingState, RacewayControl, SolveOptions};
use super::statics::{
    check_moment_with_tilt, check_options, initial_guess, solve_ring, solve_static, static_displacement,
};
use super::stiffness::seed_stiffness;
use super::Bearing;
use crate::effects::Effect;
use crate::error::{Error, Result};
use crate::units::rpm_to_rad_s;

type D4 = Dual<4>;

/// Speed-dependent constants of one solve.
#[derive(Debug, Clone, Copy)]
pub(crate) struct SpeedContext {
    omega_i: f64,
    u_r: f64,
    centrifugal: bool,
    gyroscopic: bool,
    control: RacewayControl,
    sign: f64,
    lam_i: f64,
    lam_o: f64,
    gamma: f64,
    fc_coef: f64,
    inertia: f64,
    d: f64,
    traction: f64,
}

/// Shaft speed below which the speed effects are dropped [rad/s] (about
/// 1e-8 rpm: a ball's centrifugal force there is below 1e-20 N).
const NEGLIGIBLE_SPEED_RAD_S: f64 = 1e-9;

impl SpeedContext {
    /// Contact angle difference a_i - a_o of a ball that slides against its
    /// gyroscopic moment (couple = mu (Q_i + Q_o) D / 2): the force balance
    /// Q_i n_i - Q_o n_o + mu (Q_i + Q_o) t = 0 with t normal to the
    /// controlling contact's normal gives Q_o = Q_i cos(Da) and
    /// sin(Da) = mu (1 + cos(Da)), i.e. tan(Da / 2) = mu [rad, magnitude].
    fn slip_bend_rad(&self) -> f64 {
        if self.gyroscopic && !self.centrifugal {
            2.0 * self.traction.atan()
        } else {
            0.0
        }
    }

    /// Groove-centre distance |p| at which a ball without centrifugal force
    /// first carries load: the two unloaded groove radii (f - 0.5) D meet at
    /// the slip bend (law of cosines; A = B_f D without gyroscopic moment) [m].
    pub(crate) fn onset_distance(&self, m: &BearingModel) -> f64 {
        let c = self.slip_bend_rad().cos();
        (m.ri_off * m.ri_off + m.ro_off * m.ro_off + 2.0 * c * m.ri_off * m.ro_off).sqrt()
    }

    pub(crate) fn new(model: &BearingModel, speed_rpm: f64, opts: &SolveOptions) -> Result<Self> {
        crate::error::finite("speed_rpm", speed_rpm)?;
        // Below NEGLIGIBLE_SPEED_RAD_S the speed effects (centrifugal force
        // and gyroscopic moment, both ~ omega^2) are far below the resolution
        // of the contact forces, and their products underflow: the state is
        // the zero-speed one.
        let omega_i = match rpm_to_rad_s(speed_rpm) {
            w if w.abs() < NEGLIGIBLE_SPEED_RAD_S => 0.0,
            w => w,
        };
        let (lam_i, lam_o) = opts.raceway_control.lambdas();
        let u_r = if opts.effects.has(Effect::RingCentrifugalExpansion) {
            model.ring_expansion_m(omega_i)
        } else {
            0.0
        };
        Ok(SpeedContext {
            omega_i,
            u_r,
            centrifugal: opts.effects.has(Effect::CentrifugalForce) && omega_i != 0.0,
            gyroscopic: opts.effects.has(Effect::GyroscopicMoment) && omega_i != 0.0,
            control: opts.raceway_control,
            sign: opts.gyro_couple_sign.factor(),
            lam_i,
            lam_o,
            gamma: model.d / model.dm,
            fc_coef: 0.5 * model.ball_mass_kg * model.dm,
            inertia: model.ball_inertia_kg_m2,
            d: model.d,
            traction: opts.traction_coefficient,
        })
    }
}

/// Everything one ball contributes, as functions of (X1, X2, A1, A2).
#[derive(Debug, Clone, Copy)]
pub(crate) struct BallTerms {
    r_ax: D4,
    r_rad: D4,
    /// Generalised reaction on the inner ring along A1 and A2 [N].
    f1: D4,
    f2: D4,
    /// Friction moment on the inner ring about e_psi [N m].
    mt: D4,
    qi: f64,
    qo: f64,
    dli: f64,
    dlo: f64,
    fc: f64,
    mg: f64,
}

/// Friction couple on a ball against its gyroscopic moment `mg` [N m],
/// given the Coulomb capacity `cap` = mu (Q_i + Q_o) D / 2 [N m] of its two
/// contacts: the full couple Mg of Jones's raceway control where friction
/// can hold it, else the sliding friction couple `cap` (the ball slips
/// gyroscopically).
///
/// Applied to balls without centrifugal force. There the loads of a ball
/// vanish when its gap closes, and with the full couple the ball would have
/// to bend its contact line by tan(a_i - a_o) ~ 2 Mg / (D Q) -> infinity: the
/// ring reaction jumped from zero to a finite load (about 110 N for the
/// 7008C at 18,000 rpm) as the gap closed, and lighter loads had no
/// equilibrium. With the bound a sliding ball bends by the fixed angle
/// a_i - a_o = 2 atan(mu) (see [`SpeedContext::onset_distance`]) and its
/// loads grow continuously from zero. With the centrifugal force on, the
/// outer contact carries at least Fc and the full couple is kept as before
/// (seed A); the balls of the presets need mu ~ 0.01..0.02 there under
/// outer-raceway control.
#[inline]
pub(crate) fn friction_couple(mg: D4, cap: D4) -> D4 {
    if cap.v < mg.v.abs() {
        cap * mg.v.signum()
    } else {
        mg
    }
}

/// Residuals and ring reactions of one ball (see module docs).
#[inline]
pub(crate) fn ball_terms(m: &BearingModel, ctx: &SpeedContext, x: [f64; 2], p: (f64, f64)) -> BallTerms {
    let (x1, x2) = (D4::var(x[0], 0), D4::var(x[1], 1));
    let (a1, a2) = (D4::var(p.0, 2), D4::var(p.1, 3));
    let lo = (x1 * x1 + x2 * x2).sqrt();
    let (so, co) = (x1 / lo, x2 / lo);
    let (y1, y2) = (a1 - x1, a2 - x2);
    let li = (y1 * y1 + y2 * y2).sqrt();
    let (si, ci) = (y1 / li, y2 / li);
    let dli = li - m.ri_off;
    let dlo = lo - m.ro_off;
    let qi = m.inner.k(ci) * dli.pow1_5_pos();
    let qo = m.outer.k(co) * dlo.pow1_5_pos();
    let zero = D4::cst(0.0);
    let (fc, mg) = if ctx.centrifugal || ctx.gyroscopic {
        let kin = kinematics(ctx.control, ctx.omega_i, ctx.gamma, (si, ci), (so, co));
        let fc = if ctx.centrifugal {
            kin.orbit * kin.orbit * ctx.fc_coef
        } else {
            zero
        };
        let mg = if ctx.gyroscopic {
            kin.orbit * kin.wr * ctx.inertia
        } else {
            zero
        };
        (fc, mg)
    } else {
        (zero, zero)
    };
    // Friction couple that holds the ball against Mg: Jones's full couple,
    // bounded by Coulomb friction for a ball without centrifugal force (see
    // [`friction_couple`]).
    let couple = if !ctx.gyroscopic {
        zero
    } else if ctx.centrifugal {
        mg
    } else {
        friction_couple(mg, (qi + qo) * (0.5 * ctx.traction * ctx.d))
    };
    let h = couple * (ctx.sign / ctx.d);
    let r_ax = qi * si - qo * so + h * (ci * ctx.lam_i - co * ctx.lam_o);
    let r_rad = qi * ci - qo * co - h * (si * ctx.lam_i - so * ctx.lam_o) + fc;
    let f1 = -(qi * si + h * ci * ctx.lam_i);
    let f2 = -(qi * ci - h * si * ctx.lam_i);
    let mt = -(couple * (ctx.sign * ctx.lam_i * m.fi));
    BallTerms {
        r_ax,
        r_rad,
        f1,
        f2,
        mt,
        qi: qi.v,
        qo: qo.v,
        dli: dli.v,
        dlo: dlo.v,
        fc: fc.v,
        mg: mg.v,
    }
}

/// Solution of one ball, kept between calls for warm starts.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub(crate) struct BallSolution {
    x: [f64; 2],
    p: (f64, f64),
    dxdp: [[f64; 2]; 2],
    valid: bool,
}

/// Per-ball solutions carried from one call of
/// [`BearingModel::ring_forces`] to the next (warm start of the fast path).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct WarmStart {
    balls: Vec<BallSolution>,
}

impl WarmStart {
    /// An empty warm start (first call starts each ball from the static solution).
    pub fn new() -> Self {
        Self::default()
    }
}

/// A condensed ball: reaction values and their total derivatives w.r.t. (A1, A2).
struct Condensed {
    f: [f64; 3],
    dfdp: [[f64; 2]; 3],
}

/// Static (zero-speed) position of the ball centre: on the line of the
/// groove centres, the approaches split by the contact constants.
fn static_start(m: &BearingModel, ctx: &SpeedContext, p: (f64, f64)) -> [f64; 2] {
    let l = p.0.hypot(p.1);
    let (s, c) = (p.0 / l, p.1 / l);
    let delta = l - m.a0;
    let cd = Dual::<1>::cst(c);
    let (ki, ko) = (m.inner.k(cd).v, m.outer.k(cd).v);
    if delta > 0.0 {
        let kn = super::contact::series_constant(ki, ko);
        let q = kn * delta.powf(1.5);
        let lo = m.ro_off + (q / ko).powf(2.0 / 3.0);
        [lo * s, lo * c]
    } else if ctx.centrifugal {
        seated_start(m, ctx, s)
    } else if ctx.gyroscopic {
        bent_start(m, ctx, p)
    } else {
        [m.ro_off * s, m.ro_off * c]
    }
}

/// Position of a ball seated on the outer raceway under its centrifugal
/// force at the kinematic orbit speed of a = 0, near the raceway bottom
/// (|sin a_o| <= 0.05, on the side of the groove-centre direction whose
/// sine is `s`): the start of a ball whose inner gap is open, and of a
/// pinched ball that carries far less than its centrifugal force (see
/// [`cold_ball_newton`]).
fn seated_start(m: &BearingModel, ctx: &SpeedContext, s: f64) -> [f64; 2] {
    let oc = 0.5 * ctx.omega_i * (1.0 - ctx.gamma);
    let fc = ctx.fc_coef * oc * oc;
    let lo = m.ro_off + (fc / m.outer.k(Dual::<1>::cst(1.0)).v).powf(2.0 / 3.0);
    [
        lo * s.clamp(-0.05, 0.05),
        lo * (1.0 - s.clamp(-0.05, 0.05).powi(2)).sqrt(),
    ]
}

/// Start of a ball without centrifugal force whose groove centres are
/// closer than A: equal approaches at both contacts and the contact line
/// bent by the slip angle of [`SpeedContext::slip_bend_rad`], on the side
/// the friction couple pushes it (a_i - a_o has the sign of
/// (lambda_o - lambda_i) h). Falls back to the straight position if the
/// groove centres are too close for contact.
fn bent_start(m: &BearingModel, ctx: &SpeedContext, p: (f64, f64)) -> [f64; 2] {
    let big = p.0.hypot(p.1);
    let phi = p.0.atan2(p.1);
    let straight = [m.ro_off * phi.sin(), m.ro_off * phi.cos()];
    let onset = ctx.onset_distance(m);
    let bend = ctx.slip_bend_rad();
    if big <= onset || bend == 0.0 {
        return straight;
    }
    // Sense of the bend from the couple's sign at the straight position.
    let t = ball_terms(m, ctx, straight, p);
    let h = t.mg * ctx.sign;
    let sense = (h * (ctx.lam_o - ctx.lam_i)).signum();
    // (ri + d)^2 + (ro + d)^2 + 2 cos(bend) (ri + d)(ro + d) = |p|^2.
    let sum = m.ri_off + m.ro_off;
    let delta = 0.5 * (-sum + (sum * sum + 2.0 * (big * big - onset * onset) / (1.0 + bend.cos())).sqrt());
    let (li, lo) = (m.ri_off + delta, m.ro_off + delta);
    let beta_o = ((lo * lo + big * big - li * li) / (2.0 * lo * big))
        .clamp(-1.0, 1.0)
        .acos();
    let ao = phi - sense * beta_o;
    [lo * ao.sin(), lo * ao.cos()]
}

/// Coordinates of the ball centre in which [`newton_in`] steps.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Coords {
    /// x = (X1, X2) themselves.
    Cartesian,
    /// u = (L, a_o) about the outer groove centre, x = L (sin a_o, cos a_o).
    Polar,
}

impl Coords {
    fn coordinates(self, x: [f64; 2]) -> [f64; 2] {
        match self {
            Coords::Cartesian => x,
            Coords::Polar => [x[0].hypot(x[1]), x[0].atan2(x[1])],
        }
    }

    fn point(self, u: [f64; 2]) -> [f64; 2] {
        match self {
            Coords::Cartesian => u,
            Coords::Polar => [u[0] * u[1].sin(), u[0] * u[1].cos()],
        }
    }

    /// dx/du (columns per u component).
    fn dx_du(self, u: [f64; 2]) -> [[f64; 2]; 2] {
        match self {
            Coords::Cartesian => [[1.0, 0.0], [0.0, 1.0]],
            Coords::Polar => {
                let (s, c) = u[1].sin_cos();
                [[s, u[0] * c], [c, -u[0] * s]]
            }
        }
    }

    /// Length of a step du [m].
    fn step_m(self, u: [f64; 2], du: [f64; 2]) -> f64 {
        match self {
            Coords::Cartesian => du[0].abs().max(du[1].abs()),
            Coords::Polar => du[0].abs().max((u[0] * du[1]).abs()),
        }
    }
}

/// Damped Newton iteration of one ball's equilibrium (A-15) from `x0`.
///
/// A ball that rides on the outer raceway under a small force (its
/// centrifugal force at low speed) has a radial contact stiffness many
/// orders above its tangential one (1.5 Q / delta vs Q / L): a Cartesian
/// step along the tangent leaves the raceway by L (1 - cos(da)) >> delta_o
/// and backtracking shrinks it to nothing (the 6208 at 1..100 rpm under
/// 0.25 N axial + 6 N radial stalled at 3 % of its load). Polar
/// coordinates about the outer groove centre follow that raceway; a ball
/// pinched between both raceways is better served by Cartesian steps. Start
/// with polar coordinates when the inner contact is open at `x0`, with
/// Cartesian ones otherwise, and try the other on failure.
fn ball_newton(m: &BearingModel, ctx: &SpeedContext, p: (f64, f64), x0: [f64; 2]) -> Result<([f64; 2], BallTerms)> {
    // The terms at the start serve both the choice and the first iterate.
    let t0 = ball_terms(m, ctx, x0, p);
    let (first, second) = if t0.qi == 0.0 {
        (Coords::Polar, Coords::Cartesian)
    } else {
        (Coords::Cartesian, Coords::Polar)
    };
    newton_in(m, ctx, p, x0, t0, first, false)
        .or_else(|_| newton_in(m, ctx, p, x0, t0, second, false))
        .or_else(|_| newton_in(m, ctx, p, x0, t0, first, true))
}

/// [`ball_newton`] in the given coordinates from `x0` (with its terms
/// `t0`): step capped at half the
/// ball-to-groove-centre distance, backtracking until the residual falls.
///
/// `anticipate`: a contact at its edge (|delta| below the approach
/// delta* = (|r| / K)^(2/3) that would carry the residual force) has
/// dQ/d(delta) = 0, so Newton steps run into it blindly and backtracking
/// stalls there (a ball rolling down the outer raceway onto the inner
/// raceway's flank). With `anticipate` the step is computed with that
/// contact's stiffness at delta*, 1.5 K delta*^(1/2) along its normal
/// (the residual and the converged state stay exact).
fn newton_in(
    m: &BearingModel,
    ctx: &SpeedContext,
    p: (f64, f64),
    x0: [f64; 2],
    t0: BallTerms,
    coords: Coords,
    anticipate: bool,
) -> Result<([f64; 2], BallTerms)> {
    let mut u = coords.coordinates(x0);
    let mut x = x0;
    let norm = |t: &BallTerms| t.r_ax.v.abs().max(t.r_rad.v.abs());
    let mut t = t0;
    let mut converged = false;
    let mut it = 0;
    let mut tol = 0.0;
    while it < 60 {
        let scale = (t.qi + t.qo + t.fc).max(1e-12);
        let jx = [[t.r_ax.d[0], t.r_ax.d[1]], [t.r_rad.d[0], t.r_rad.d[1]]];
        let roundoff = roundoff_force(&jx, x[0].hypot(x[1]));
        tol = (1e-11 * scale).max(roundoff);
        let rn = norm(&t);
        if rn <= tol {
            converged = true;
            break;
        }
        let mut jx = jx;
        if anticipate {
            anticipate_contacts(m, p, x, &t, rn, &mut jx);
        }
        // d r / du = d r / dx * d x / du.
        let dxu = coords.dx_du(u);
        let j: [[f64; 2]; 2] =
            std::array::from_fn(|r| std::array::from_fn(|c| jx[r][0] * dxu[0][c] + jx[r][1] * dxu[1][c]));
        let det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
        if det == 0.0 || !det.is_finite() {
            break;
        }
        let du = [
            -(j[1][1] * t.r_ax.v - j[0][1] * t.r_rad.v) / det,
            -(-j[1][0] * t.r_ax.v + j[0][0] * t.r_rad.v) / det,
        ];
        // Keep the step below half the ball-to-groove-centre distance.
        let big = coords.step_m(u, du);
        let mut lam = if big > 0.5 * m.ro_off {
            0.5 * m.ro_off / big
        } else {
            1.0
        };
        let mut accepted = None;
        for _ in 0..40 {
            let ut = [u[0] + lam * du[0], u[1] + lam * du[1]];
            let xt = coords.point(ut);
            let tt = ball_terms(m, ctx, xt, p);
            if norm(&tt) < rn {
                accepted = Some((ut, xt, tt));
                break;
            }
            lam *= 0.5;
        }
        it += 1;
        match accepted {
            Some((ut, xt, tt)) => {
                let step = (lam * big).abs();
                (u, x, t) = (ut, xt, tt);
                if step <= 1e-14 * x[0].abs().max(x[1].abs()) {
                    converged = true;
                    break;
                }
            }
            None => {
                // No decrease possible: accept round-off level residuals.
                converged = rn <= (1e-9 * scale).max(roundoff);
                break;
            }
        }
    }
    if !converged {
        return Err(Error::convergence("ball equilibrium (A-15)", it, norm(&t), tol));
    }
    Ok((x, t))
}

/// Add to d r / dx the stiffness of the contacts at their edge (see
/// [`newton_in`]): the inner contact enters r as +Q_i n_i with
/// d(delta_i)/dx = -n_i, the outer one as -Q_o n_o with d(delta_o)/dx = n_o;
/// both add -k n n^T.
fn anticipate_contacts(m: &BearingModel, p: (f64, f64), x: [f64; 2], t: &BallTerms, rn: f64, jx: &mut [[f64; 2]; 2]) {
    let unit = |v: [f64; 2]| {
        let l = v[0].hypot(v[1]);
        [v[0] / l, v[1] / l]
    };
    let ni = unit([p.0 - x[0], p.1 - x[1]]);
    let no = unit(x);
    let ki = m.inner.k(Dual::<1>::cst(ni[1])).v;
    let ko = m.outer.k(Dual::<1>::cst(no[1])).v;
    for (dl, n, k) in [(t.dli, ni, ki), (t.dlo, no, ko)] {
        let dstar = (rn / k).powf(2.0 / 3.0);
        if dl.abs() < dstar {
            let kv = 1.5 * k * dstar.sqrt();
            for r in 0..2 {
                for c in 0..2 {
                    jx[r][c] -= kv * n[r] * n[c];
                }
            }
        }
    }
}

/// Force residual that a ball position known to round-off produces [N]:
/// the largest contact stiffness |d r / dx| times 64 ulp of the distance L
/// to the outer groove centre. The approach delta = L - (f_o - 0.5) D is a
/// difference of two lengths of size L, so a lightly pressed ball (the
/// centrifugal force at a few rpm: delta ~ 1e-11 m, Q ~ 1e-7 N) has its
/// loads known to about eps L / delta only, far coarser than the relative
/// 1e-11 of its own forces; the ring forces are untouched at that level.
fn roundoff_force(jx: &[[f64; 2]; 2], l: f64) -> f64 {
    let jmax = jx.iter().flatten().fold(0.0f64, |acc, v| acc.max(v.abs()));
    64.0 * f64::EPSILON * l * jmax
}

/// Ball equilibrium from the static position. Without centrifugal force
/// but with the gyroscopic couple, a lightly loaded ball slides and sits
/// bent by the slip angle, far from the straight static position: if the
/// contacts at the static position cannot hold the couple (Coulomb), start
/// from [`bent_start`] first, the static position second, and the other
/// way round otherwise.
///
/// With the centrifugal force, a pinched ball (|p| > A) that fails from
/// the static position starts again seated on the outer raceway
/// ([`seated_start`]). At the edge of the load zone a ball can carry a few
/// newtons statically against a centrifugal force of 100 N and more (the
/// 6208 under 1.7 kN axial + 3.1 kN radial at 17,844 rpm: 3.6 N against
/// 122 N). Its equilibrium is then that of a ball riding on the outer
/// raceway and rolled up against the inner one, the contact line bent by
/// 10..20 deg, tens of microns across the line of the groove centres from
/// the straight static position. Across that line the straight ball is
/// held only by the stiffness ~ Q / L of its light contacts, and under
/// outer-raceway control its orbit speed (1 - gamma cos a_i) /
/// (1 + cos(a_i - a_o)), hence Fc, grows as the line bends: with Fc of some
/// ten times Q the restoring stiffness across the line changes sign (in
/// the case above 2.5e4 N/m from the contacts, -2.4e3 N/m with the growth
/// of Fc; the derivatives are exact, this is the model's own behaviour).
/// The Newton steps there are millimetres long or point away from the
/// equilibrium, backtracking cuts them to nothing and the iteration stalls
/// with the residual at about Fc. Seated, the ball is held by its outer
/// load ~ Fc instead, as a ball with an open inner gap is (whose
/// equilibrium this one continues across |p| = A). Under inner-raceway
/// control the orbit speed falls as the line bends, and with the
/// gyroscopic moment (on by default) its friction couple enters the
/// balance: neither failed from the static position in random sweeps, so
/// the pocket showed with the centrifugal force alone.
fn cold_ball_newton(m: &BearingModel, ctx: &SpeedContext, p: (f64, f64)) -> Result<([f64; 2], BallTerms)> {
    let straight = static_start(m, ctx, p);
    if !ctx.gyroscopic || ctx.centrifugal {
        let l = p.0.hypot(p.1);
        return ball_newton(m, ctx, p, straight).or_else(|e| {
            if ctx.centrifugal && l > m.a0 {
                ball_newton(m, ctx, p, seated_start(m, ctx, p.0 / l))
            } else {
                Err(e)
            }
        });
    }
    let t = ball_terms(m, ctx, straight, p);
    let slides = 0.5 * ctx.traction * ctx.d * (t.qi + t.qo) < t.mg.abs();
    let bent = bent_start(m, ctx, p);
    let (first, second) = if slides { (bent, straight) } else { (straight, bent) };
    ball_newton(m, ctx, p, first).or_else(|_| ball_newton(m, ctx, p, second))
}

fn solve_ball(m: &BearingModel, ctx: &SpeedContext, p: (f64, f64), prev: &mut BallSolution) -> Result<Condensed> {
    if !ctx.centrifugal && p.0.hypot(p.1) <= ctx.onset_distance(m) {
        // Free ball: no centrifugal force and an open gap.
        *prev = BallSolution {
            x: static_start(m, ctx, p),
            p,
            dxdp: [[0.0; 2]; 2],
            valid: false,
        };
        return Ok(Condensed {
            f: [0.0; 3],
            dfdp: [[0.0; 2]; 3],
        });
    }
    let (x, t) = if prev.valid {
        let (d1, d2) = (p.0 - prev.p.0, p.1 - prev.p.1);
        let predicted = [
            prev.x[0] + prev.dxdp[0][0] * d1 + prev.dxdp[0][1] * d2,
            prev.x[1] + prev.dxdp[1][0] * d1 + prev.dxdp[1][1] * d2,
        ];
        // The predictor is a tangent of the previous contact state. When
        // the groove centres moved across the point where the inner contact
        // opens (|p| = A0), the Newton iteration from it can stall on the
        // inner contact's edge (dli = 0, where dQ/d(delta) = 0) with the
        // outer contact open: only Fc is left, with no direction that lowers
        // the residual. Restart from the cold (static) position then.
        match ball_newton(m, ctx, p, predicted) {
            Ok(sol) => sol,
            Err(_) => cold_ball_newton(m, ctx, p)?,
        }
    } else {
        cold_ball_newton(m, ctx, p)?
    };
    // Implicit-function condensation.
    let jx = [[t.r_ax.d[0], t.r_ax.d[1]], [t.r_rad.d[0], t.r_rad.d[1]]];
    let jp = [[t.r_ax.d[2], t.r_ax.d[3]], [t.r_rad.d[2], t.r_rad.d[3]]];
    let det = jx[0][0] * jx[1][1] - jx[0][1] * jx[1][0];
    let inv = [[jx[1][1] / det, -jx[0][1] / det], [-jx[1][0] / det, jx[0][0] / det]];
    let mut dxdp = [[0.0; 2]; 2];
    for r in 0..2 {
        for c in 0..2 {
            dxdp[r][c] = -(inv[r][0] * jp[0][c] + inv[r][1] * jp[1][c]);
        }
    }
    let total = |f: &D4| -> [f64; 2] {
        [
            f.d[2] + f.d[0] * dxdp[0][0] + f.d[1] * dxdp[1][0],
            f.d[3] + f.d[0] * dxdp[0][1] + f.d[1] * dxdp[1][1],
        ]
    };
    *prev = BallSolution {
        x,
        p,
        dxdp,
        valid: true,
    };
    Ok(Condensed {
        f: [t.f1.v, t.f2.v, t.mt.v],
        dfdp: [total(&t.f1), total(&t.f2), total(&t.mt)],
    })
}

/// Reaction of the balls on the inner ring and K = -d(reaction)/dq at q.
pub(crate) fn qs_ring(
    m: &BearingModel,
    ctx: &SpeedContext,
    q: &[f64; 5],
    opts: &SolveOptions,
    warm: &mut WarmStart,
) -> Result<([f64; 5], [[f64; 5]; 5])> {
    let z = m.ball_count();
    if warm.balls.len() != z {
        warm.balls = vec![BallSolution::default(); z];
    }
    let mut reaction = [0.0; 5];
    let mut k = [[0.0; 5]; 5];
    for j in 0..z {
        let p = m.groove_distances(j, q, ctx.u_r, &opts.offsets);
        let c = solve_ball(m, ctx, p, &mut warm.balls[j])?;
        let (g1, g2) = m.groove_gradients(j);
        super::statics::assemble(
            &mut reaction,
            &mut k,
            (c.f[0], c.f[1]),
            [c.dfdp[0], c.dfdp[1]],
            (&g1, &g2),
        );
        if c.f[2] != 0.0 || c.dfdp[2] != [0.0; 2] {
            let (cp, sp) = m.azimuth[j];
            let tang = [0.0, 0.0, 0.0, -sp, cp];
            let dm: [f64; 5] = std::array::from_fn(|l| c.dfdp[2][0] * g1[l] + c.dfdp[2][1] * g2[l]);
            for r in 3..5 {
                reaction[r] += c.f[2] * tang[r];
                for (l, dml) in dm.iter().enumerate() {
                    k[r][l] -= tang[r] * dml;
                }
            }
        }
    }
    Ok((reaction, k))
}

/// Per-ball states at q after a [`qs_ring`] evaluation (uses the warm start).
pub(crate) fn qs_balls(
    m: &BearingModel,
    ctx: &SpeedContext,
    q: &[f64; 5],
    opts: &SolveOptions,
    warm: &WarmStart,
) -> Vec<BallState> {
    (0..m.ball_count())
        .map(|j| {
            let p = m.groove_distances(j, q, ctx.u_r, &opts.offsets);
            let sol = warm.balls.get(j).copied().unwrap_or_default();
            let x = if sol.valid { sol.x } else { static_start(m, ctx, p) };
            let t = ball_terms(m, ctx, x, p);
            let ai = (p.0 - x[0]).atan2(p.1 - x[1]);
            let ao = x[0].atan2(x[1]);
            let kin = ball_kinematics(ctx.control, ctx.omega_i, ctx.gamma, ai, ao);
            let (qi, qo) = if sol.valid { (t.qi, t.qo) } else { (0.0, 0.0) };
            BallState {
                azimuth_rad: m.bearing.geometry.azimuth(j),
                inner_load_n: qi,
                outer_load_n: qo,
                inner_contact_angle_rad: ai,
                outer_contact_angle_rad: ao,
                inner_deflection_m: t.dli,
                outer_deflection_m: t.dlo,
                centrifugal_force_n: t.fc,
                gyroscopic_moment_n_m: t.mg,
                orbit_speed_rad_s: kin.orbit_speed_rad_s,
                spin_speed_rad_s: kin.spin_speed_rad_s,
                attitude_angle_rad: kin.attitude_angle_rad,
                inner_spin_rad_s: kin.inner_spin_rad_s,
                outer_spin_rad_s: kin.outer_spin_rad_s,
                inner_spin_to_roll: kin.inner_spin_to_roll(),
                outer_spin_to_roll: kin.outer_spin_to_roll(),
                inner_semi_major_m: m.inner.semi_major_m(ai.cos(), qi),
                outer_semi_major_m: m.outer.semi_major_m(ao.cos(), qo),
            }
        })
        .collect()
}

/// Forces of the balls on the inner ring at a prescribed displacement.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RingForces {
    /// Reaction of the balls on the inner ring [Fx, Fy, Fz, Mx, My] (N, N m);
    /// at equilibrium it balances the applied load (load + reaction = 0).
    pub reaction: [f64; 5],
    /// Tangent stiffness K = -d(reaction)/dq (N/m, N/rad, N m/m, N m/rad).
    pub stiffness_matrix: [[f64; 5]; 5],
}

impl BearingModel {
    /// Forward map: ball forces on the inner ring for the displacement
    /// q = [dx, dy, dz, theta_x, theta_y] (m, rad) at `speed_rpm`, each ball
    /// in its own quasi-static equilibrium. `warm` carries the per-ball
    /// solutions between calls (fast path for time integration: start with
    /// [`WarmStart::new`] and pass the same one on every call).
    pub fn ring_forces(
        &self,
        q: &[f64; 5],
        speed_rpm: f64,
        opts: &SolveOptions,
        warm: &mut WarmStart,
    ) -> Result<RingForces> {
        for (i, v) in q.iter().enumerate() {
            crate::error::finite(["dx_m", "dy_m", "dz_m", "theta_x_rad", "theta_y_rad"][i], *v)?;
        }
        check_options(opts)?;
        let ctx = SpeedContext::new(self, speed_rpm, opts)?;
        let (reaction, k) = qs_ring(self, &ctx, q, opts, warm)?;
        Ok(RingForces {
            reaction,
            stiffness_matrix: k,
        })
    }

    /// Per-ball states at q after [`BearingModel::ring_forces`] with the same `warm`.
    pub fn ball_states(
        &self,
        q: &[f64; 5],
        speed_rpm: f64,
        opts: &SolveOptions,
        warm: &WarmStart,
    ) -> Result<Vec<BallState>> {
        let ctx = SpeedContext::new(self, speed_rpm, opts)?;
        Ok(qs_balls(self, &ctx, q, opts, warm))
    }

    /// Zero-speed equilibrium under the load [Fx, Fy, Fz, Mx, My] (N, N m).
    pub fn solve_static(&self, load: &[f64; 5], opts: &SolveOptions) -> Result<BearingState> {
        solve_static(self, load, opts)
    }

    /// Quasi-static equilibrium at `speed_rpm` under [Fx, Fy, Fz, Mx, My]
    /// (N, N m), warm-started from the static solution.
    pub fn solve(&self, load: &[f64; 5], speed_rpm: f64, opts: &SolveOptions) -> Result<BearingState> {
        let start = static_start_q(self, load, opts)?;
        self.solve_from(load, speed_rpm, opts, start, &mut WarmStart::new())
    }

    /// Quasi-static equilibrium from a given start displacement and warm start.
    pub fn solve_from(
        &self,
        load: &[f64; 5],
        speed_rpm: f64,
        opts: &SolveOptions,
        start_m_rad: [f64; 5],
        warm: &mut WarmStart,
    ) -> Result<BearingState> {
        self.check_load(load)?;
        check_moment_with_tilt(load, opts)?;
        check_options(opts)?;
        let ctx = SpeedContext::new(self, speed_rpm, opts)?;
        let sol = solve_ring(
            self,
            load,
            start_m_rad,
            ctx.u_r,
            opts,
            "quasi-static bearing equilibrium",
            &mut |q| qs_ring(self, &ctx, q, opts, warm),
        )?;
        // solve_ring's last evaluation is at sol.q, so `warm` holds its balls.
        let k = sol.k;
        let balls = qs_balls(self, &ctx, &sol.q, opts, warm);
        let (ka, kr) = seed_stiffness(self, &balls);
        BearingState {
            displacement: sol.q,
            applied_load: sol.load,
            balls,
            stiffness_matrix: k,
            axial_stiffness_seed_n_per_m: ka,
            radial_stiffness_seed_n_per_m: kr,
            iterations: sol.iterations,
            residual: sol.residual,
            speed_rpm,
        }
        .checked("quasi-static bearing equilibrium")
    }
}

/// Static solution as the start of the high-speed solve (q = 0 for zero load).
pub(crate) fn static_start_q(model: &BearingModel, load: &[f64; 5], opts: &SolveOptions) -> Result<[f64; 5]> {
    model.check_load(load)?;
    if load.iter().all(|v| *v == 0.0) {
        return initial_guess(model, load, opts);
    }
    // The start need not be converged tightly: the high-speed iteration
    // finishes the job (a loose static tolerance saves iterations).
    let loose = SolveOptions {
        tolerance: opts.tolerance.max(1e-4),
        ..*opts
    };
    Ok(static_displacement(model, load, &loose)?.q)
}

impl Bearing {
    /// Solve for an axial load, a radial load along x and a tilting moment
    /// about y at `speed_rpm`: the static (Hertz) solve at 0 rpm, the
    /// quasi-static one above, as Python's `Bearing.solve` (builds a
    /// [`BearingModel`]; keep the model when solving many times).
    pub fn solve(&self, load: BearingLoad, speed_rpm: f64, opts: &SolveOptions) -> Result<BearingState> {
        let model = BearingModel::new(self)?;
        if speed_rpm == 0.0 {
            model.solve_static(&load.to_vector(), opts)
        } else {
            model.solve(&load.to_vector(), speed_rpm, opts)
        }
    }
}

use super::state::BearingLoad;

/// Forward map for a bearing (builds the model; see [`BearingModel::ring_forces`]).
pub fn ring_forces(
    bearing: &Bearing,
    q: &[f64; 5],
    speed_rpm: f64,
    opts: &SolveOptions,
) -> Result<([f64; 5], Vec<BallState>)> {
    let model = BearingModel::new(bearing)?;
    let mut warm = WarmStart::new();
    let f = model.ring_forces(q, speed_rpm, opts, &mut warm)?;
    Ok((f.reaction, model.ball_states(q, speed_rpm, opts, &warm)?))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearing::{GyroCoupleSign, RacewayControl};

    fn fixture(name: &str, control: RacewayControl) -> (BearingModel, SpeedContext, SolveOptions) {
        let m = BearingModel::new(&Bearing::preset(name).unwrap()).unwrap();
        let o = SolveOptions {
            raceway_control: control,
            ..Default::default()
        };
        let ctx = SpeedContext::new(&m, 18_000.0, &o).unwrap();
        (m, ctx, o)
    }

    #[test]
    fn ball_jacobian_matches_finite_differences() {
        for control in [RacewayControl::Outer, RacewayControl::Inner] {
            let (m, ctx, _) = fixture("7009C", control);
            let p = (m.a0 * 0.30, m.a0 * 0.97);
            let x = [0.2 * m.ro_off, 1.01 * m.ro_off];
            let t = ball_terms(&m, &ctx, x, p);
            let vars = [x[0], x[1], p.0, p.1];
            for v in 0..4 {
                let h = 1e-10;
                let eval = |dv: f64| {
                    let mut w = vars;
                    w[v] += dv;
                    ball_terms(&m, &ctx, [w[0], w[1]], (w[2], w[3]))
                };
                let (tp, tm) = (eval(h), eval(-h));
                let fd = |a: f64, b: f64| (a - b) / (2.0 * h);
                for (an, num) in [
                    (t.r_ax.d[v], fd(tp.r_ax.v, tm.r_ax.v)),
                    (t.r_rad.d[v], fd(tp.r_rad.v, tm.r_rad.v)),
                    (t.f1.d[v], fd(tp.f1.v, tm.f1.v)),
                    (t.f2.d[v], fd(tp.f2.v, tm.f2.v)),
                    (t.mt.d[v], fd(tp.mt.v, tm.mt.v)),
                ] {
                    assert!(
                        (an - num).abs() <= 1e-5 * an.abs().max(1e3),
                        "{control:?} var {v}: {an} vs {num}"
                    );
                }
            }
        }
    }

    /// Moment balance about the ball centre with vectors in (e_r, e_psi, e_z):
    /// the friction force the model applies at the controlling contact, times
    /// its arm, supplies dH/dt = omega_c e_z x J w (the gyroscopic couple).
    #[test]
    fn friction_couple_opposes_gyroscopic_moment() {
        fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
            [
                a[1] * b[2] - a[2] * b[1],
                a[2] * b[0] - a[0] * b[2],
                a[0] * b[1] - a[1] * b[0],
            ]
        }
        for control in [RacewayControl::Outer, RacewayControl::Inner] {
            let (m, ctx, o) = fixture("6208", control);
            let mut warm = WarmStart::new();
            let load = [0.0, 0.0, 300.0, 0.0, 0.0];
            let s = m
                .solve_from(&load, 18_000.0, &o, static_start_q(&m, &load, &o).unwrap(), &mut warm)
                .unwrap();
            let b = s.balls[0];
            let (ai, ao) = (b.inner_contact_angle_rad, b.outer_contact_angle_rad);
            // Basis (e_r, e_psi, e_z) is right-handed: e_z x e_r = e_psi.
            let n_o = [ao.cos(), 0.0, ao.sin()];
            let n_i = [ai.cos(), 0.0, ai.sin()];
            // Ball angular velocity in the cage frame from the kinematics.
            let kin = ball_kinematics(control, ctx.omega_i, ctx.gamma, ai, ao);
            let w = [kin.spin_radial_rad_s, 0.0, kin.spin_axial_rad_s];
            let dhdt = cross([0.0, 0.0, kin.orbit_speed_rad_s], w).map(|c| c * m.ball_inertia_kg_m2);
            assert!(dhdt[1] > 0.0 && (dhdt[1] - b.gyroscopic_moment_n_m).abs() < 1e-9 * dhdt[1]);
            // The friction forces the ball equilibrium uses: the residual
            // minus its normal-load and centrifugal parts.
            let p = m.groove_distances(0, &s.displacement, ctx.u_r, &o.offsets);
            let x = warm.balls[0].x;
            let t = ball_terms(&m, &ctx, x, p);
            let normal_ax = t.qi * ai.sin() - t.qo * ao.sin();
            let normal_rad = t.qi * ai.cos() - t.qo * ao.cos() + t.fc;
            let fric = [t.r_rad.v - normal_rad, 0.0, t.r_ax.v - normal_ax];
            // Friction sits at the controlling contact: arm (D/2) n_o or -(D/2) n_i.
            let arm = match control {
                RacewayControl::Outer => n_o.map(|c| 0.5 * m.d * c),
                RacewayControl::Inner => n_i.map(|c| -0.5 * m.d * c),
            };
            // The residuals are converged, so the friction force is the
            // negative of the normal + centrifugal part; recompute it from the
            // Mg terms directly instead to keep the check independent.
            let (lam_i, lam_o) = control.lambdas();
            let h = t.mg / m.d;
            let f_model = [
                -h * (lam_i * ai.sin() - lam_o * ao.sin()),
                0.0,
                h * (lam_i * ai.cos() - lam_o * ao.cos()),
            ];
            assert!((f_model[0] - fric[0]).abs() < 1e-6 && (f_model[2] - fric[2]).abs() < 1e-6);
            let couple = cross(arm, f_model);
            assert!(
                (couple[1] - dhdt[1]).abs() < 1e-9 * dhdt[1],
                "{control:?}: friction couple {} vs required {}",
                couple[1],
                dhdt[1]
            );
            // The reversed sign doubles the unbalance instead of cancelling it.
            let o_rev = SolveOptions {
                gyro_couple_sign: GyroCoupleSign::Reversed,
                ..o
            };
            let ctx_rev = SpeedContext::new(&m, 18_000.0, &o_rev).unwrap();
            let tr = ball_terms(&m, &ctx_rev, x, p);
            let fric_rev = [tr.r_rad.v - normal_rad, 0.0, tr.r_ax.v - normal_ax];
            let couple_rev = cross(arm, fric_rev);
            assert!((couple_rev[1] + dhdt[1]).abs() < 1e-9 * dhdt[1]);
        }
    }

    /// A ball without centrifugal force whose groove centres are just past
    /// the contact onset slides against its gyroscopic moment: the friction
    /// force is mu (Q_i + Q_o), so Q_o = Q_i cos(a_i - a_o) and
    /// tan((a_i - a_o) / 2) = mu (closed form of the force balance), with
    /// loads that vanish at the onset distance.
    #[test]
    fn sliding_ball_bends_by_twice_the_friction_angle() {
        let m = BearingModel::new(&Bearing::preset("7008C").unwrap()).unwrap();
        let o = SolveOptions {
            effects: crate::effects::EffectSet::all().without(Effect::CentrifugalForce),
            ..Default::default()
        };
        let ctx = SpeedContext::new(&m, 18_000.0, &o).unwrap();
        let onset = ctx.onset_distance(&m);
        assert!(onset < m.a0);
        let dir = 16f64.to_radians();
        let mut last = 0.0;
        for k in 1..=5 {
            let l = onset + 1e-8 * k as f64;
            let p = (l * dir.sin(), l * dir.cos());
            let mut sol = BallSolution::default();
            solve_ball(&m, &ctx, p, &mut sol).unwrap();
            let t = ball_terms(&m, &ctx, sol.x, p);
            let ai = (p.0 - sol.x[0]).atan2(p.1 - sol.x[1]);
            let ao = sol.x[0].atan2(sol.x[1]);
            assert!(
                0.5 * o.traction_coefficient * m.d * (t.qi + t.qo) < t.mg.abs(),
                "not sliding"
            );
            assert!(
                ((ai - ao) - 2.0 * o.traction_coefficient.atan()).abs() < 1e-9,
                "{}",
                ai - ao
            );
            assert!((t.qo - t.qi * (ai - ao).cos()).abs() < 1e-9 * t.qi);
            assert!(t.qi > last);
            last = t.qi;
        }
        // Closer than the onset the ball is free.
        let p = (0.999 * onset * dir.sin(), 0.999 * onset * dir.cos());
        let c = solve_ball(&m, &ctx, p, &mut BallSolution::default()).unwrap();
        assert_eq!(c.f, [0.0; 3]);
    }

    /// A ball whose groove centres move from a loaded position to one with
    /// the inner gap open (|p| < A0) must reach the same equilibrium from the
    /// warm start (predictor of the loaded state) as from the cold start.
    #[test]
    fn warm_start_across_inner_contact_opening_matches_cold_start() {
        let m = BearingModel::new(&Bearing::preset("7009C-hybrid").unwrap()).unwrap();
        let o = SolveOptions::default();
        let ctx = SpeedContext::new(&m, 8_000.0, &o).unwrap();
        let open: (f64, f64) = (1.381434e-4, 4.133031e-4);
        assert!(open.0.hypot(open.1) < m.a0);
        let mut checked = 0;
        for k in 1..=40 {
            let s = 1.0 + 0.0005 * k as f64;
            let loaded = (open.0 * s, open.1 * s);
            let mut warm = BallSolution::default();
            solve_ball(&m, &ctx, loaded, &mut warm).unwrap();
            assert!(warm.valid);
            let w = solve_ball(&m, &ctx, open, &mut warm).unwrap();
            let xw = warm.x;
            let mut cold = BallSolution::default();
            let c = solve_ball(&m, &ctx, open, &mut cold).unwrap();
            for i in 0..2 {
                assert!(
                    (xw[i] - cold.x[i]).abs() < 1e-9 * m.ro_off,
                    "{k}: {xw:?} vs {:?}",
                    cold.x
                );
                assert!((w.f[i] - c.f[i]).abs() <= 1e-6 * c.f[i].abs().max(1e-3));
            }
            checked += 1;
        }
        assert_eq!(checked, 40);
    }
}
