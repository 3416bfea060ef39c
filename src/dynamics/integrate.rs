//! Time integrators.
//!
//! - Fixed-step classical Runge-Kutta 4 on the half-step grid of a
//!   [`GridOde`]: the hot loop of the bifurcation sweeps. No allocation, stack
//!   arrays, coefficients read from precomputed tables.
//! - Adaptive Dormand-Prince 5(4) (Dormand & Prince 1980, J. Comput. Appl.
//!   Math. 6, 19-26; step-size control as in Hairer, Norsett & Wanner,
//!   *Solving ODEs I*, 2nd ed., section II.4); the 8th-order DOP853 is in
//!   [`super::dop853`]. The two are cross-checked on the impacting gear case.
//!
//! - [`rk4_located`]: RK4 whose steps are split at located switching events
//!   (contact changes), for accuracy checks.
//!
//! Backlash makes the right-hand side continuous with a jump in its
//! derivative (or, with contact-only mesh damping, a jump in the force itself).
//! RK4 then loses its fourth order at the switching steps; the tests in
//! `tests/dynamics.rs` measure the observed order against DOPRI5 (impacting
//! case, 10 mesh periods): plain RK4 with always-on damping 3.0e-7 m at 64
//! steps per period, 3.9e-11 m at 1024 (irregular, about 2nd order at coarse
//! steps); with located switches 8.9e-9 m at 64 and 1.4e-11 m at 512
//! (order ~3); contact-only damping 1.2e-6 m at 64, 3.8e-8 m at 1024.

use super::ode::{GridOde, OdeSystem};
use crate::{Error, Result};

/// Grid indices of the RK4 stages of step `n` (counted from the start of a
/// period): `(t_n, t_n + h/2, t_n + h)` on the half-step grid. No division in
/// the common case `n < steps_per_period`.
#[inline(always)]
fn stage_indices(n: usize, grid_len: usize) -> (usize, usize, usize) {
    let j0 = if 2 * n < grid_len { 2 * n } else { (2 * n) % grid_len };
    let j1 = if j0 + 1 == grid_len { 0 } else { j0 + 1 };
    let j2 = if j1 + 1 == grid_len { 0 } else { j1 + 1 };
    (j0, j1, j2)
}

/// One classical RK4 step of a [`GridOde`] from grid step `n` (the step's start
/// time is `n h`; only `n mod steps_per_period` matters): the system's
/// [`GridOde::rk4_step`] (a specialised kernel where the system has one).
#[inline(always)]
pub fn rk4_step_grid<const N: usize, S: GridOde<N>>(sys: &S, n: usize, x: &mut [f64; N]) {
    sys.rk4_step(n, x);
}

/// One classical RK4 step from four [`GridOde::rhs_grid`] evaluations (the
/// reference form of every RK4 step in this crate).
#[inline(always)]
pub fn rk4_step_generic<const N: usize, S: GridOde<N>>(sys: &S, n: usize, x: &mut [f64; N]) {
    let h = sys.step();
    let (j0, j1, j2) = stage_indices(n, sys.grid_len());
    let mut k1 = [0.0; N];
    let mut k2 = [0.0; N];
    let mut k3 = [0.0; N];
    let mut k4 = [0.0; N];
    let mut y = [0.0; N];
    sys.rhs_grid(j0, x, &mut k1);
    for i in 0..N {
        y[i] = x[i] + 0.5 * h * k1[i];
    }
    sys.rhs_grid(j1, &y, &mut k2);
    for i in 0..N {
        y[i] = x[i] + 0.5 * h * k2[i];
    }
    sys.rhs_grid(j1, &y, &mut k3);
    for i in 0..N {
        y[i] = x[i] + h * k3[i];
    }
    sys.rhs_grid(j2, &y, &mut k4);
    let h6 = h / 6.0;
    for i in 0..N {
        x[i] += h6 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
    }
}

/// Advance `steps` RK4 steps starting at grid step `n0`; returns the next
/// step index (reduced modulo the period).
pub fn rk4_advance<const N: usize, S: GridOde<N>>(sys: &S, x: &mut [f64; N], n0: usize, steps: usize) -> usize {
    let per = (sys.grid_len() / 2).max(1);
    let mut n = n0 % per;
    for _ in 0..steps {
        rk4_step_grid(sys, n, x);
        n += 1;
        if n == per {
            n = 0;
        }
    }
    n
}

/// As [`rk4_advance`], looking at the cancel flag every
/// [`crate::cancel::CHECK_EVERY_STEPS`] steps: `Err(Error::Interrupted)`
/// after a stop (`x` then holds the state reached).
pub fn rk4_advance_checked<const N: usize, S: GridOde<N>>(
    sys: &S,
    x: &mut [f64; N],
    n0: usize,
    steps: usize,
) -> Result<usize> {
    let mut n = n0;
    let mut left = steps;
    while left > 0 {
        crate::cancel::check()?;
        let chunk = left.min(crate::cancel::CHECK_EVERY_STEPS);
        n = rk4_advance(sys, x, n, chunk);
        left -= chunk;
    }
    Ok(n)
}

/// As [`rk4_advance`], calling `observe(n_after, &x)` after every step.
pub fn rk4_advance_observe<const N: usize, S: GridOde<N>, F: FnMut(usize, &[f64; N])>(
    sys: &S,
    x: &mut [f64; N],
    n0: usize,
    steps: usize,
    mut observe: F,
) -> usize {
    let per = (sys.grid_len() / 2).max(1);
    let mut n = n0 % per;
    for _ in 0..steps {
        rk4_step_grid(sys, n, x);
        n += 1;
        if n == per {
            n = 0;
        }
        observe(n, x);
    }
    n
}

/// One classical RK4 step of an [`OdeSystem`] at arbitrary time `t`.
pub fn rk4_step<const N: usize, S: OdeSystem<N>>(sys: &S, t: f64, h: f64, x: &mut [f64; N]) {
    let mut k1 = [0.0; N];
    let mut k2 = [0.0; N];
    let mut k3 = [0.0; N];
    let mut k4 = [0.0; N];
    let mut y = [0.0; N];
    sys.rhs(t, x, &mut k1);
    for i in 0..N {
        y[i] = x[i] + 0.5 * h * k1[i];
    }
    sys.rhs(t + 0.5 * h, &y, &mut k2);
    for i in 0..N {
        y[i] = x[i] + 0.5 * h * k2[i];
    }
    sys.rhs(t + 0.5 * h, &y, &mut k3);
    for i in 0..N {
        y[i] = x[i] + h * k3[i];
    }
    sys.rhs(t + h, &y, &mut k4);
    for i in 0..N {
        x[i] += h / 6.0 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
    }
}

/// Classical RK4 with located switching events: steps of nominal size `h`
/// from `t0` to `t0 + steps h`; whenever the switching function `g(t, x)`
/// changes sign over a step, the crossing fraction is found by the Illinois
/// variant of regula falsi on `theta -> g(t + theta h, RK4(x, theta h))` and
/// the step is split there, so no RK4 step straddles a kink of the
/// right-hand side (e.g. `g = |delta_n - e| - b` for backlash contact).
/// Returns the number of located crossings. Slower than the grid RK4 (uses
/// [`OdeSystem::rhs`] at arbitrary times); meant for accuracy checks.
pub fn rk4_located<const N: usize, S: OdeSystem<N>, G: Fn(f64, &[f64; N]) -> f64>(
    sys: &S,
    g: G,
    t0: f64,
    h: f64,
    steps: usize,
    x: &mut [f64; N],
) -> usize {
    let mut crossings = 0;
    let t_end = t0 + steps as f64 * h;
    let mut t = t0;
    let mut g0 = g(t, x);
    while t < t_end - 1e-12 * h {
        let dt = h.min(t_end - t);
        let mut y = *x;
        rk4_step(sys, t, dt, &mut y);
        let g1 = g(t + dt, &y);
        if g0 != 0.0 && g0.signum() != g1.signum() {
            // Illinois regula falsi on the step fraction.
            let (mut a, mut fa, mut b, mut fb) = (0.0, g0, 1.0, g1);
            let mut side = 0;
            for _ in 0..60 {
                let c = (a * fb - b * fa) / (fb - fa);
                let mut z = *x;
                rk4_step(sys, t, c * dt, &mut z);
                let fc = g(t + c * dt, &z);
                if fc.signum() == fa.signum() {
                    a = c;
                    fa = fc;
                    if side == -1 {
                        fb *= 0.5;
                    }
                    side = -1;
                } else {
                    b = c;
                    fb = fc;
                    if side == 1 {
                        fa *= 0.5;
                    }
                    side = 1;
                }
                if (b - a) < 1e-13 || fc == 0.0 {
                    break;
                }
            }
            // Step to just past the crossing so the next step starts on the
            // new side of the switching surface.
            let theta = b.max(1e-12);
            rk4_step(sys, t, theta * dt, x);
            t += theta * dt;
            g0 = g(t, x);
            crossings += 1;
        } else {
            *x = y;
            t += dt;
            g0 = g1;
        }
    }
    crossings
}

/// Tolerances of the adaptive integrator: a step is accepted when
/// `sqrt(mean_i (err_i / (atol_i + rtol * max(|x_i|, |x_new_i|)))^2) <= 1`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AdaptiveTolerance<const N: usize> {
    /// Relative tolerance (dimensionless).
    pub rtol: f64,
    /// Absolute tolerance per state, in the state's own unit (choose it from
    /// the state's scale, e.g. a fraction of the backlash for displacements).
    pub atol: [f64; N],
    /// Maximum number of attempted steps before giving up.
    pub max_steps: usize,
}

/// Counters of an adaptive run.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct AdaptiveStats {
    /// Accepted steps.
    pub accepted: usize,
    /// Rejected steps.
    pub rejected: usize,
    /// Right-hand-side evaluations.
    pub evaluations: usize,
}

// Dormand-Prince 5(4) tableau (Dormand & Prince 1980, Table 2).
const C2: f64 = 1.0 / 5.0;
const C3: f64 = 3.0 / 10.0;
const C4: f64 = 4.0 / 5.0;
const C5: f64 = 8.0 / 9.0;
const A21: f64 = 1.0 / 5.0;
const A31: f64 = 3.0 / 40.0;
const A32: f64 = 9.0 / 40.0;
const A41: f64 = 44.0 / 45.0;
const A42: f64 = -56.0 / 15.0;
const A43: f64 = 32.0 / 9.0;
const A51: f64 = 19372.0 / 6561.0;
const A52: f64 = -25360.0 / 2187.0;
const A53: f64 = 64448.0 / 6561.0;
const A54: f64 = -212.0 / 729.0;
const A61: f64 = 9017.0 / 3168.0;
const A62: f64 = -355.0 / 33.0;
const A63: f64 = 46732.0 / 5247.0;
const A64: f64 = 49.0 / 176.0;
const A65: f64 = -5103.0 / 18656.0;
const B1: f64 = 35.0 / 384.0;
const B3: f64 = 500.0 / 1113.0;
const B4: f64 = 125.0 / 192.0;
const B5: f64 = -2187.0 / 6784.0;
const B6: f64 = 11.0 / 84.0;
// Error weights b - b_hat (5th minus embedded 4th order).
const E1: f64 = 71.0 / 57600.0;
const E3: f64 = -71.0 / 16695.0;
const E4: f64 = 71.0 / 1920.0;
const E5: f64 = -17253.0 / 339200.0;
const E6: f64 = 22.0 / 525.0;
const E7: f64 = -1.0 / 40.0;

/// Integrate `x` from `t0` to `t1` (> t0) with adaptive Dormand-Prince 5(4).
/// Returns the counters; `Error::Convergence` if `max_steps` is exhausted or
/// the step size underflows (e.g. a non-finite right-hand side).
pub fn dopri5<const N: usize, S: OdeSystem<N>>(
    sys: &S,
    t0: f64,
    t1: f64,
    x: &mut [f64; N],
    tol: &AdaptiveTolerance<N>,
) -> Result<AdaptiveStats> {
    crate::error::positive("rtol", tol.rtol)?;
    for &a in &tol.atol {
        crate::error::positive("atol", a)?;
    }
    if t1 <= t0 || !t1.is_finite() || !t0.is_finite() {
        return Err(Error::config("t1_s", t1, "must be finite and after t0_s"));
    }
    let mut stats = AdaptiveStats::default();
    let mut t = t0;
    let span = t1 - t0;
    let mut h = initial_step(sys, t0, x, tol, span);
    let mut k1 = [0.0; N];
    sys.rhs(t, x, &mut k1);
    stats.evaluations += 1;
    let (mut k2, mut k3, mut k4, mut k5, mut k6, mut k7) = ([0.0; N], [0.0; N], [0.0; N], [0.0; N], [0.0; N], [0.0; N]);
    let mut y = [0.0; N];
    let mut xn = [0.0; N];
    let mut last_err = f64::INFINITY;
    while t < t1 {
        if stats.accepted + stats.rejected >= tol.max_steps {
            return Err(Error::convergence("dopri5", tol.max_steps, last_err, 1.0));
        }
        let last = t + h >= t1;
        if last {
            h = t1 - t;
        }
        for i in 0..N {
            y[i] = x[i] + h * A21 * k1[i];
        }
        sys.rhs(t + C2 * h, &y, &mut k2);
        for i in 0..N {
            y[i] = x[i] + h * (A31 * k1[i] + A32 * k2[i]);
        }
        sys.rhs(t + C3 * h, &y, &mut k3);
        for i in 0..N {
            y[i] = x[i] + h * (A41 * k1[i] + A42 * k2[i] + A43 * k3[i]);
        }
        sys.rhs(t + C4 * h, &y, &mut k4);
        for i in 0..N {
            y[i] = x[i] + h * (A51 * k1[i] + A52 * k2[i] + A53 * k3[i] + A54 * k4[i]);
        }
        sys.rhs(t + C5 * h, &y, &mut k5);
        for i in 0..N {
            y[i] = x[i] + h * (A61 * k1[i] + A62 * k2[i] + A63 * k3[i] + A64 * k4[i] + A65 * k5[i]);
        }
        sys.rhs(t + h, &y, &mut k6);
        for i in 0..N {
            xn[i] = x[i] + h * (B1 * k1[i] + B3 * k3[i] + B4 * k4[i] + B5 * k5[i] + B6 * k6[i]);
        }
        sys.rhs(t + h, &xn, &mut k7);
        stats.evaluations += 6;
        let mut acc = 0.0;
        for i in 0..N {
            let e = h * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i]);
            let sc = tol.atol[i] + tol.rtol * x[i].abs().max(xn[i].abs());
            acc += (e / sc) * (e / sc);
        }
        let err = (acc / N as f64).sqrt();
        last_err = err;
        if !err.is_finite() {
            return Err(Error::convergence("dopri5", stats.accepted, err, 1.0));
        }
        // Standard controller, safety 0.9, growth limited to [0.2, 5].
        let fac = (0.9 * err.max(1e-300).powf(-0.2)).clamp(0.2, 5.0);
        if err <= 1.0 {
            stats.accepted += 1;
            t = if last { t1 } else { t + h };
            *x = xn;
            k1 = k7; // first same as last
            h *= fac;
        } else {
            stats.rejected += 1;
            h *= fac.min(1.0);
        }
        if h < 1e-14 * span.max(t.abs()) {
            return Err(Error::convergence(
                "dopri5 (step size underflow)",
                stats.accepted,
                err,
                1.0,
            ));
        }
    }
    Ok(stats)
}

/// Initial step guess (Hairer, Norsett & Wanner, section II.4, simplified).
pub(crate) fn initial_step<const N: usize, S: OdeSystem<N>>(
    sys: &S,
    t0: f64,
    x: &[f64; N],
    tol: &AdaptiveTolerance<N>,
    span: f64,
) -> f64 {
    let mut f0 = [0.0; N];
    sys.rhs(t0, x, &mut f0);
    let (mut d0, mut d1) = (0.0, 0.0);
    for i in 0..N {
        let sc = tol.atol[i] + tol.rtol * x[i].abs();
        d0 += (x[i] / sc).powi(2);
        d1 += (f0[i] / sc).powi(2);
    }
    let (d0, d1) = ((d0 / N as f64).sqrt(), (d1 / N as f64).sqrt());
    let h = if d0 < 1e-5 || d1 < 1e-5 {
        1e-6 * span
    } else {
        0.01 * d0 / d1
    };
    h.min(span).max(1e-12 * span)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::ode::Gridded;

    use crate::dynamics::ode::test_systems::Harmonic;

    #[test]
    fn rk4_advance_checked_matches_rk4_advance_and_stops_on_the_flag() {
        let g = Gridded::new(Harmonic(1.0), 1.0, 100);
        let (mut a, mut b) = ([1.0, 0.0], [1.0, 0.0]);
        let steps = 3 * crate::cancel::CHECK_EVERY_STEPS + 7;
        assert_eq!(
            rk4_advance_checked(&g, &mut a, 3, steps).unwrap(),
            rk4_advance(&g, &mut b, 3, steps)
        );
        assert_eq!(a, b);
        let flag = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(true));
        let r = crate::cancel::with_flag(&flag, || rk4_advance_checked(&g, &mut a, 0, steps));
        assert!(matches!(r, Err(Error::Interrupted)));
        // Nothing was integrated past the stop.
        assert_eq!(a, b);
    }

    #[test]
    fn rk4_is_fourth_order_on_harmonic_oscillator() {
        // Exact solution cos(w t); error over one period scales as h^4.
        let w = 2.0 * std::f64::consts::PI;
        let err = |steps: usize| {
            let g = Gridded::new(Harmonic(w), 1.0, steps);
            let mut x = [1.0, 0.0];
            rk4_advance(&g, &mut x, 0, steps);
            ((x[0] - 1.0).powi(2) + (x[1] / w).powi(2)).sqrt()
        };
        let (e1, e2) = (err(32), err(64));
        let order = (e1 / e2).log2();
        assert!((order - 4.0).abs() < 0.15, "order {order}");
    }

    #[test]
    fn dopri5_matches_exact_solution_and_rejects_bad_input() {
        let w = 3.0;
        let tol = AdaptiveTolerance {
            rtol: 1e-11,
            atol: [1e-12; 2],
            max_steps: 100_000,
        };
        let mut x = [1.0, 0.0];
        let st = dopri5(&Harmonic(w), 0.0, 10.0, &mut x, &tol).unwrap();
        assert!((x[0] - (30.0f64).cos()).abs() < 1e-9, "{x:?}");
        assert!((x[1] + w * (30.0f64).sin()).abs() < 1e-8);
        assert!(st.accepted > 10);
        let bad = AdaptiveTolerance { rtol: -1.0, ..tol };
        assert!(dopri5(&Harmonic(w), 0.0, 1.0, &mut x, &bad).is_err());
        let few = AdaptiveTolerance { max_steps: 3, ..tol };
        assert!(matches!(
            dopri5(&Harmonic(w), 0.0, 100.0, &mut x, &few),
            Err(Error::Convergence { .. })
        ));
    }
}
