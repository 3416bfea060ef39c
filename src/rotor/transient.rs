//! Time response of M q'' + (C + Omega G) q' + K q = f_u(t) + f_s + f_nl(t, q, q')
//! by the implicit Newmark average-acceleration scheme (beta = 1/4,
//! gamma = 1/2; Newmark, J. Eng. Mech. Div. ASCE 85 (1959) 67-94), which is
//! unconditionally stable and, for linear undamped systems, conserves the
//! energy 1/2 q'^T M q' + 1/2 q^T K q exactly (it is the trapezoidal rule,
//! a Cayley transform of the skew system; gyroscopic forces do no work).
//!
//! Nonlinear forces (e.g. the bearing solver's ball forces) enter through a
//! [`NonlinearForce`] callback and are resolved each step by a modified
//! Newton iteration whose tangent (finite-difference Jacobian of the
//! callback) is kept from step to step and refreshed whenever an iteration
//! contracts the increment by less than a factor 10 ([`SLOW_CONTRACTION`]
//! = 0.1: the next increment above a tenth of the last one).
//!
//! Optionally the model is reduced to the lowest undamped modes
//! (pseudo-modal reduction, q = Phi xi), which removes the very stiff,
//! irrelevant high-frequency shaft modes and makes long runs cheap.

use nalgebra::{DMatrix, DVector};

use super::response::{unbalance_phasor, Unbalance};
use super::{LateralDof, Rotor, SystemMatrices};
use crate::error::{finite, positive, Error, Result};

/// Extra forces on the rotor that depend on its state (bearing ball forces,
/// contact, nonlinear UMP...).
pub trait NonlinearForce: Sync {
    /// Add the forces [N, N m] at time `time_s` and physical state
    /// (q [m, rad], q' [m/s, rad/s]) into `force` (length = rotor DOFs).
    fn add_force(&self, time_s: f64, q: &DVector<f64>, qd: &DVector<f64>, force: &mut DVector<f64>) -> Result<()>;

    /// The physical DOFs the force depends on (for the finite-difference tangent).
    fn dofs(&self) -> Vec<usize>;
}

/// A closure `f(time_s, q, q', force)` (adding into `force`) acting on the
/// listed physical DOFs, as a [`NonlinearForce`].
pub struct ForceFn<F> {
    /// Physical DOF indices the force depends on (the columns of the
    /// finite-difference tangent of the full model).
    pub dofs: Vec<usize>,
    /// The closure `f(time_s, q, q', force)`; it must add into `force`, not
    /// overwrite it.
    pub force: F,
}

impl<F> NonlinearForce for ForceFn<F>
where
    F: Fn(f64, &DVector<f64>, &DVector<f64>, &mut DVector<f64>) -> Result<()> + Sync,
{
    fn add_force(&self, time_s: f64, q: &DVector<f64>, qd: &DVector<f64>, force: &mut DVector<f64>) -> Result<()> {
        (self.force)(time_s, q, qd, force)
    }

    fn dofs(&self) -> Vec<usize> {
        self.dofs.clone()
    }
}

/// Options of a time response.
#[derive(Debug, Clone, PartialEq)]
pub struct TransientOptions {
    /// Shaft speed \[rpm\], constant over the run: sets Omega in the gyroscopic
    /// and bearing matrices and the unbalance force.
    pub speed_rpm: f64,
    /// Simulated time \[s\]; the run takes round(duration_s / time_step_s) steps.
    pub duration_s: f64,
    /// Newmark time step \[s\], at most `duration_s`.
    pub time_step_s: f64,
    /// Node whose motion is recorded \[m\].
    pub probe_position_m: f64,
    /// Pseudo-modal reduction to this many modes (None: full model).
    pub reduced_modes: Option<usize>,
    /// Relative displacement-increment tolerance of the Newton iteration.
    pub tolerance: f64,
    /// Newton iterations per step before giving up.
    pub max_iterations: usize,
    /// Any recorded displacement above this means divergence \[m\].
    pub divergence_limit_m: f64,
}

impl TransientOptions {
    /// Defaults: tolerance 1e-10, 30 iterations, divergence at 1 mm.
    pub fn new(speed_rpm: f64, duration_s: f64, time_step_s: f64, probe_position_m: f64) -> Self {
        TransientOptions {
            speed_rpm,
            duration_s,
            time_step_s,
            probe_position_m,
            reduced_modes: None,
            tolerance: 1e-10,
            max_iterations: 30,
            divergence_limit_m: 1e-3,
        }
    }

    fn validate(&self) -> Result<()> {
        finite("speed_rpm", self.speed_rpm)?;
        positive("duration_s", self.duration_s)?;
        positive("time_step_s", self.time_step_s)?;
        if self.time_step_s > self.duration_s {
            return Err(Error::config("time_step_s", self.time_step_s, "exceeds duration_s"));
        }
        positive("tolerance", self.tolerance)?;
        positive("divergence_limit_m", self.divergence_limit_m)?;
        if self.max_iterations == 0 {
            return Err(Error::config("max_iterations", 0, "must be at least 1"));
        }
        Ok(())
    }
}

/// Recorded motion of the probe node and the final state.
#[derive(Debug, Clone, PartialEq)]
pub struct TimeHistory {
    /// Sample times from t = 0, one per time step \[s\].
    pub time_s: Vec<f64>,
    /// Probe displacement x \[m\].
    pub displacement_x_m: Vec<f64>,
    /// Probe displacement y \[m\].
    pub displacement_y_m: Vec<f64>,
    /// Probe velocity in x [m/s].
    pub velocity_x_m_per_s: Vec<f64>,
    /// Probe velocity in y [m/s].
    pub velocity_y_m_per_s: Vec<f64>,
    /// Physical displacement vector at the end [m, rad].
    pub final_displacement_si: DVector<f64>,
    /// Physical velocity vector at the end [m/s, rad/s].
    pub final_velocity_si: DVector<f64>,
    /// Newton iterations used in total.
    pub iterations: usize,
}

impl TimeHistory {
    /// Sample rate of the record \[Hz\].
    pub fn sample_rate_hz(&self) -> f64 {
        if self.time_s.len() < 2 {
            return 0.0;
        }
        1.0 / (self.time_s[1] - self.time_s[0])
    }
}

/// Linear part of the model in the integration coordinates.
struct Linear {
    mass_si: DMatrix<f64>,
    damping_si: DMatrix<f64>,
    stiffness_si: DMatrix<f64>,
    /// Constant force.
    static_force_si: DVector<f64>,
    /// Unbalance force f(t) = cos_part cos(Wt) + sin_part sin(Wt).
    cos_part: DVector<f64>,
    sin_part: DVector<f64>,
    spin_rad_s: f64,
    /// q = basis xi (None: identity).
    basis: Option<DMatrix<f64>>,
}

impl Linear {
    fn to_physical(&self, xi: &DVector<f64>) -> DVector<f64> {
        match &self.basis {
            Some(b) => b * xi,
            None => xi.clone(),
        }
    }

    fn to_generalized(&self, f: &DVector<f64>) -> DVector<f64> {
        match &self.basis {
            Some(b) => b.transpose() * f,
            None => f.clone(),
        }
    }

    fn external(&self, t: f64) -> DVector<f64> {
        let (s, c) = (self.spin_rad_s * t).sin_cos();
        &self.static_force_si + &self.cos_part * c + &self.sin_part * s
    }
}

/// Generalized nonlinear force at (xi, xi').
fn nonlinear_generalized(
    lin: &Linear,
    nl: Option<&dyn NonlinearForce>,
    n_phys: usize,
    t: f64,
    xi: &DVector<f64>,
    xid: &DVector<f64>,
) -> Result<DVector<f64>> {
    match nl {
        None => Ok(DVector::zeros(xi.len())),
        Some(f) => {
            let mut out = DVector::zeros(n_phys);
            f.add_force(t, &lin.to_physical(xi), &lin.to_physical(xid), &mut out)?;
            for v in out.iter() {
                if !v.is_finite() {
                    return Err(Error::config(
                        "nonlinear_force",
                        v,
                        "callback returned a non-finite force",
                    ));
                }
            }
            Ok(lin.to_generalized(&out))
        }
    }
}

/// Finite-difference tangents (df/dxi, df/dxi') of the nonlinear force.
fn nonlinear_tangent(
    lin: &Linear,
    nl: &dyn NonlinearForce,
    n_phys: usize,
    t: f64,
    xi: &DVector<f64>,
    xid: &DVector<f64>,
) -> Result<(DMatrix<f64>, DMatrix<f64>)> {
    let r = xi.len();
    let columns: Vec<usize> = match lin.basis {
        Some(_) => (0..r).collect(),
        None => nl.dofs().into_iter().filter(|&d| d < r).collect(),
    };
    let f0 = nonlinear_generalized(lin, Some(nl), n_phys, t, xi, xid)?;
    let mut jq = DMatrix::zeros(r, r);
    let mut jv = DMatrix::zeros(r, r);
    let sq = xi.amax().max(1e-12);
    let sv = xid.amax().max(1e-9);
    for &j in &columns {
        let h = 1e-7 * sq;
        let mut p = xi.clone();
        p[j] += h;
        let f = nonlinear_generalized(lin, Some(nl), n_phys, t, &p, xid)?;
        jq.set_column(j, &((f - &f0) / h));
        let h = 1e-7 * sv;
        let mut p = xid.clone();
        p[j] += h;
        let f = nonlinear_generalized(lin, Some(nl), n_phys, t, xi, &p)?;
        jv.set_column(j, &((f - &f0) / h));
    }
    Ok((jq, jv))
}

const BETA: f64 = 0.25;
/// Refresh the tangent when an iteration's increment is above this share of
/// the last one (contraction by less than a factor 10; docs/concepts/spindle-rotor.md).
pub const SLOW_CONTRACTION: f64 = 0.1;
const GAMMA: f64 = 0.5;

fn effective_matrix(
    lin: &Linear,
    dt: f64,
    jq: &DMatrix<f64>,
    jv: &DMatrix<f64>,
) -> Result<nalgebra::LU<f64, nalgebra::Dyn, nalgebra::Dyn>> {
    let s = &lin.stiffness_si - jq
        + (&lin.damping_si - jv) * (GAMMA / (BETA * dt))
        + &lin.mass_si * (1.0 / (BETA * dt * dt));
    let lu = s.lu();
    if !lu.is_invertible() {
        return Err(Error::config(
            "time_step_s",
            dt,
            "Newmark effective stiffness is singular",
        ));
    }
    Ok(lu)
}

/// Integrate the rotor's equations of motion from rest (or from `initial`
/// physical (q, q')) under the unbalances, the static UMP force and an
/// optional nonlinear force.
pub fn time_response(
    rotor: &Rotor,
    unbalances: &[Unbalance],
    nonlinear: Option<&dyn NonlinearForce>,
    initial: Option<(&DVector<f64>, &DVector<f64>)>,
    options: &TransientOptions,
) -> Result<TimeHistory> {
    options.validate()?;
    let n_phys = rotor.dof_count();
    let sys: SystemMatrices = rotor.matrices(options.speed_rpm)?;
    let w = sys.spin_speed_rad_s;
    let unit = unbalance_phasor(rotor, unbalances)?;
    // f(t) = Re(W^2 F e^{iWt}) = W^2 (Re F cos - Im F sin).
    let cos_phys = unit.map(|c| c.re * w * w);
    let sin_phys = unit.map(|c| -c.im * w * w);
    let basis = match options.reduced_modes {
        Some(r) => Some(rotor.modal_basis(options.speed_rpm, r)?),
        None => None,
    };
    let reduced = match &basis {
        Some(b) => sys.reduce(b),
        None => sys.clone(),
    };
    let lin = Linear {
        damping_si: reduced.damping_and_gyroscopic(),
        mass_si: reduced.mass_si,
        stiffness_si: reduced.stiffness_si,
        static_force_si: reduced.static_force_si,
        cos_part: DVector::zeros(0),
        sin_part: DVector::zeros(0),
        spin_rad_s: w,
        basis,
    };
    let lin = Linear {
        cos_part: lin.to_generalized(&cos_phys),
        sin_part: lin.to_generalized(&sin_phys),
        ..lin
    };
    let r = lin.mass_si.nrows();

    // Initial state in integration coordinates (mass-orthogonal projection
    // for the reduced model: xi = Phi^T M q).
    let (mut xi, mut v) = match initial {
        None => (DVector::zeros(r), DVector::zeros(r)),
        Some((q0, v0)) => {
            if q0.len() != n_phys || v0.len() != n_phys {
                return Err(Error::config(
                    "initial_state",
                    q0.len(),
                    format!("must have {n_phys} entries"),
                ));
            }
            match &lin.basis {
                Some(b) => (b.transpose() * (&sys.mass_si * q0), b.transpose() * (&sys.mass_si * v0)),
                None => (q0.clone(), v0.clone()),
            }
        }
    };
    let mass_chol = lin
        .mass_si
        .clone()
        .cholesky()
        .ok_or_else(|| Error::config("mass", "matrix", "not positive definite"))?;
    let f0 = lin.external(0.0) + nonlinear_generalized(&lin, nonlinear, n_phys, 0.0, &xi, &v)?
        - &lin.damping_si * &v
        - &lin.stiffness_si * &xi;
    let mut a = mass_chol.solve(&f0);

    let dt = options.time_step_s;
    let steps = crate::cancel::step_count(options.duration_s, dt, "time_step_s", f64::round)?;
    let probe = rotor.node_at(options.probe_position_m)?;
    let (px, py) = (rotor.dof(probe, LateralDof::X), rotor.dof(probe, LateralDof::Y));
    let probe_rows: (DVector<f64>, DVector<f64>) = match &lin.basis {
        Some(b) => (b.row(px).transpose(), b.row(py).transpose()),
        None => {
            let mut ex = DVector::zeros(r);
            let mut ey = DVector::zeros(r);
            ex[px] = 1.0;
            ey[py] = 1.0;
            (ex, ey)
        }
    };
    let mut hist = TimeHistory {
        time_s: Vec::with_capacity(steps + 1),
        displacement_x_m: Vec::with_capacity(steps + 1),
        displacement_y_m: Vec::with_capacity(steps + 1),
        velocity_x_m_per_s: Vec::with_capacity(steps + 1),
        velocity_y_m_per_s: Vec::with_capacity(steps + 1),
        final_displacement_si: DVector::zeros(0),
        final_velocity_si: DVector::zeros(0),
        iterations: 0,
    };
    let record = |h: &mut TimeHistory, t: f64, xi: &DVector<f64>, v: &DVector<f64>| {
        h.time_s.push(t);
        h.displacement_x_m.push(probe_rows.0.dot(xi));
        h.displacement_y_m.push(probe_rows.1.dot(xi));
        h.velocity_x_m_per_s.push(probe_rows.0.dot(v));
        h.velocity_y_m_per_s.push(probe_rows.1.dot(v));
    };
    record(&mut hist, 0.0, &xi, &v);

    let zero = DMatrix::zeros(r, r);
    let (mut jq, mut jv) = match nonlinear {
        Some(f) => nonlinear_tangent(&lin, f, n_phys, 0.0, &xi, &v)?,
        None => (zero.clone(), zero.clone()),
    };
    let mut lu = effective_matrix(&lin, dt, &jq, &jv)?;
    let c1 = 1.0 / (BETA * dt * dt);
    let c2 = 1.0 / (BETA * dt);
    let c3 = 1.0 / (2.0 * BETA) - 1.0;

    for step in 1..=steps {
        crate::cancel::check()?;
        crate::cancel::advance();
        let t1 = step as f64 * dt;
        let f_ext = lin.external(t1);
        let mut x1 = &xi + &v * dt + &a * (0.5 * dt * dt);
        let mut iter = 0;
        let mut previous_change = f64::INFINITY;
        loop {
            iter += 1;
            let a1 = (&x1 - &xi) * c1 - &v * c2 - &a * c3;
            let v1 = &v + (&a * (1.0 - GAMMA) + &a1 * GAMMA) * dt;
            let fnl = nonlinear_generalized(&lin, nonlinear, n_phys, t1, &x1, &v1)?;
            let res = &f_ext + fnl - &lin.mass_si * &a1 - &lin.damping_si * &v1 - &lin.stiffness_si * &x1;
            let dx = lu
                .solve(&res)
                .ok_or_else(|| Error::convergence("Newmark step", step, f64::NAN, 0.0))?;
            x1 += &dx;
            let size = x1.amax().max((&x1 - &xi).amax());
            let change = dx.amax();
            if !change.is_finite() {
                return Err(Error::convergence(
                    "Newmark modified Newton",
                    step,
                    change,
                    options.tolerance,
                ));
            }
            if nonlinear.is_none() || change <= options.tolerance * size || size == 0.0 {
                break;
            }
            if iter >= options.max_iterations {
                return Err(Error::convergence(
                    "Newmark modified Newton",
                    iter,
                    change / size,
                    options.tolerance,
                ));
            }
            // Slow (or no) contraction of the modified Newton iteration:
            // refresh the tangent at the current iterate (full Newton step).
            if change > SLOW_CONTRACTION * previous_change {
                if let Some(f) = nonlinear {
                    let a1 = (&x1 - &xi) * c1 - &v * c2 - &a * c3;
                    let v1 = &v + (&a * (1.0 - GAMMA) + &a1 * GAMMA) * dt;
                    (jq, jv) = nonlinear_tangent(&lin, f, n_phys, t1, &x1, &v1)?;
                    lu = effective_matrix(&lin, dt, &jq, &jv)?;
                }
            }
            previous_change = change;
        }
        hist.iterations += iter;
        let a1 = (&x1 - &xi) * c1 - &v * c2 - &a * c3;
        let v1 = &v + (&a * (1.0 - GAMMA) + &a1 * GAMMA) * dt;
        xi = x1;
        v = v1;
        a = a1;
        record(&mut hist, t1, &xi, &v);
        let (x, y) = (hist.displacement_x_m[step], hist.displacement_y_m[step]);
        let amp = x.hypot(y);
        if !amp.is_finite() || amp > options.divergence_limit_m {
            return Err(Error::convergence(
                format!("time response (diverged at t = {t1:.6} s: probe displacement [m] vs divergence_limit_m)"),
                step,
                amp,
                options.divergence_limit_m,
            ));
        }
    }
    hist.final_displacement_si = lin.to_physical(&xi);
    hist.final_velocity_si = lin.to_physical(&v);
    Ok(hist)
}

/// Mechanical energy 1/2 q'^T M q' + 1/2 q^T K q of a physical state \[J\].
pub fn mechanical_energy_j(sys: &SystemMatrices, q: &DVector<f64>, qd: &DVector<f64>) -> f64 {
    0.5 * qd.dot(&(&sys.mass_si * qd)) + 0.5 * q.dot(&(&sys.stiffness_si * q))
}

/// Velocity RMS, peak and the 1X/2X/3X amplitudes of the probe's x velocity
/// over the record from `settle_s` on.
#[derive(Debug, Clone, PartialEq)]
pub struct VibrationSummary {
    /// RMS of the x velocity after `settle_s` [m/s].
    pub velocity_rms_m_per_s: f64,
    /// Largest |v_x| after `settle_s` [m/s].
    pub velocity_peak_m_per_s: f64,
    /// Amplitudes of 1X, 2X, 3X of the x velocity [m/s].
    pub velocity_orders_m_per_s: Vec<f64>,
}

/// Summarise the x velocity of `history` after `settle_s`.
pub fn vibration_summary(history: &TimeHistory, speed_rpm: f64, settle_s: f64) -> Result<VibrationSummary> {
    let start = history.time_s.partition_point(|&t| t < settle_s);
    let v = &history.velocity_x_m_per_s[start..];
    if v.len() < 16 {
        return Err(Error::config("settle_s", settle_s, "leaves fewer than 16 samples"));
    }
    Ok(VibrationSummary {
        velocity_rms_m_per_s: super::spectrum::rms(v),
        velocity_peak_m_per_s: super::spectrum::peak(v),
        velocity_orders_m_per_s: super::spectrum::order_amplitudes(v, history.sample_rate_hz(), speed_rpm, 3)?,
    })
}
