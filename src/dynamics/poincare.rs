//! Stroboscopic Poincare sampling once per excitation (mesh) period.

use super::integrate::rk4_step_grid;
use super::ode::GridOde;
use crate::{Error, Result};

/// What a Poincare run records.
#[derive(Debug, Clone, PartialEq)]
pub struct PoincareRecord<const N: usize> {
    /// State at the start of each recorded period (the Poincare section).
    pub points: Vec<[f64; N]>,
    /// Observable at each section point.
    pub observable: Vec<f64>,
    /// Smallest observable over every step of the recorded periods.
    pub observable_min: f64,
    /// Largest observable over every step of the recorded periods.
    pub observable_max: f64,
    /// Per-state range (max - min) over the first recorded period: the
    /// amplitude scale used to compare section points.
    pub state_range: [f64; N],
    /// Final state (at the start of a period, step index 0).
    pub final_state: [f64; N],
}

/// Integrate `transient_periods` periods from `x0` (at period start), then
/// `recorded_periods` more, sampling the state once per period and the
/// observable `obs(n, x)` (n = step index within the period) after every step.
/// A non-finite state returns `Error::Convergence` naming the RK4 run; a
/// stop (`crate::cancel`, looked at every
/// [`crate::cancel::CHECK_EVERY_STEPS`] steps and at each period start)
/// returns `Error::Interrupted`.
pub fn poincare_sample<const N: usize, S: GridOde<N>, F: Fn(usize, &[f64; N]) -> f64>(
    sys: &S,
    x0: &[f64; N],
    transient_periods: usize,
    recorded_periods: usize,
    obs: F,
) -> Result<PoincareRecord<N>> {
    if recorded_periods == 0 {
        return Err(Error::config("recorded_periods", 0, "must be at least 1"));
    }
    let per = (sys.grid_len() / 2).max(1);
    let mut x = *x0;
    let every = crate::cancel::CHECK_EVERY_STEPS;
    for p in 0..transient_periods {
        for n in 0..per {
            if n % every == 0 {
                crate::cancel::check()?;
            }
            rk4_step_grid(sys, n, &mut x);
        }
        if !x.iter().all(|v| v.is_finite()) {
            return Err(Error::convergence(
                "rk4 (state diverged in transient)",
                p * per,
                f64::INFINITY,
                0.0,
            ));
        }
    }
    let mut points = Vec::with_capacity(recorded_periods);
    let mut observable = Vec::with_capacity(recorded_periods);
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    let mut smin = x;
    let mut smax = x;
    for p in 0..recorded_periods {
        points.push(x);
        observable.push(obs(0, &x));
        for n in 0..per {
            if n % every == 0 {
                crate::cancel::check()?;
            }
            rk4_step_grid(sys, n, &mut x);
            let next = if n + 1 == per { 0 } else { n + 1 };
            let o = obs(next, &x);
            lo = lo.min(o);
            hi = hi.max(o);
            if p == 0 {
                for i in 0..N {
                    smin[i] = smin[i].min(x[i]);
                    smax[i] = smax[i].max(x[i]);
                }
            }
        }
        if !x.iter().all(|v| v.is_finite()) {
            return Err(Error::convergence("rk4 (state diverged)", p * per, f64::INFINITY, 0.0));
        }
    }
    let mut state_range = [0.0; N];
    for i in 0..N {
        state_range[i] = smax[i] - smin[i];
    }
    Ok(PoincareRecord {
        points,
        observable,
        observable_min: lo,
        observable_max: hi,
        state_range,
        final_state: x,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::ode::{Gridded, OdeSystem};

    #[test]
    fn forced_linear_oscillator_section_is_a_fixed_point() {
        // x'' + 0.4 x' + x = cos(2 t): after the transient the stroboscopic map
        // has one fixed point equal to the steady-state solution
        // x = A cos(2t - psi), A = 1/sqrt((1-4)^2 + 0.8^2).
        struct F;
        impl OdeSystem<2> for F {
            fn rhs(&self, t: f64, x: &[f64; 2], dx: &mut [f64; 2]) {
                dx[0] = x[1];
                dx[1] = (2.0 * t).cos() - 0.4 * x[1] - x[0];
            }
        }
        let g = Gridded::new(F, std::f64::consts::PI, 200);
        let r = poincare_sample(&g, &[0.0, 0.0], 60, 5, |_, x| x[0]).unwrap();
        let amp = 1.0 / (9.0f64 + 0.64).sqrt();
        let psi = (0.8f64).atan2(-3.0);
        for p in &r.points {
            assert!((p[0] - amp * psi.cos()).abs() < 1e-7, "{p:?}");
        }
        assert!((r.observable_max - amp).abs() < 1e-4);
        assert!((r.observable_min + amp).abs() < 1e-4);
    }

    /// x' = -x that raises the cancel flag after `after` right-hand sides.
    struct Raises {
        calls: std::sync::atomic::AtomicUsize,
        after: usize,
        flag: std::sync::Arc<std::sync::atomic::AtomicBool>,
    }

    impl OdeSystem<1> for Raises {
        fn rhs(&self, _t: f64, x: &[f64; 1], dx: &mut [f64; 1]) {
            use std::sync::atomic::Ordering;
            if self.calls.fetch_add(1, Ordering::Relaxed) + 1 == self.after {
                self.flag.store(true, Ordering::Relaxed);
            }
            dx[0] = -x[0];
        }
    }

    #[test]
    fn a_stop_ends_the_run_inside_one_long_period() {
        use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
        use std::sync::Arc;
        // One period of a million steps; the flag rises after ~10,000 steps
        // (4 right-hand sides a step), in the transient and in the record.
        let every = crate::cancel::CHECK_EVERY_STEPS;
        for (transient, recorded) in [(3, 2), (0, 3)] {
            let flag = Arc::new(AtomicBool::new(false));
            let sys = Raises {
                calls: AtomicUsize::new(0),
                after: 40_000,
                flag: Arc::clone(&flag),
            };
            let g = Gridded::new(sys, 1.0, 1_000_000);
            let r = crate::cancel::with_flag(&flag, || poincare_sample(&g, &[1.0], transient, recorded, |_, x| x[0]));
            assert!(matches!(r, Err(Error::Interrupted)), "{r:?}");
            let steps = g.system.calls.load(Ordering::Relaxed) / 4;
            // Stopped at the next look at the flag: within one check interval.
            assert!((10_000..=10_000 + every).contains(&steps), "{steps} steps");
        }
        // Without a flag the same run completes.
        let sys = Raises {
            calls: AtomicUsize::new(0),
            after: 40,
            flag: Arc::new(AtomicBool::new(false)),
        };
        let g = Gridded::new(sys, 1.0, 10_000);
        assert!(poincare_sample(&g, &[1.0], 0, 2, |_, x| x[0]).is_ok());
    }
}
