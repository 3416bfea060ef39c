//! ODE system traits shared by the integrators, the Lyapunov estimators and the
//! bifurcation sweeps.
//!
//! Two views of the same right-hand side:
//! - [`OdeSystem`]: `dx/dt = f(t, x)` at any time `t` (used by the adaptive
//!   integrator, the reference systems and the variational equations);
//! - [`GridOde`]: the same `f` evaluated only on the fixed grid of half steps
//!   of a fixed-step RK4 run (`t_j = j h / 2`). With `h = T / steps` the stage
//!   times of classical RK4 (`t_n`, `t_n + h/2`, `t_n + h`) fall on a grid of
//!   `2 * steps` points per period `T`, so periodic coefficients (mesh stiffness,
//!   transmission error, harmonic forcing) are tabulated once and the hot loop
//!   does no trigonometry or interpolation.

/// A first-order system `dx/dt = f(t, x)` with `N` states held on the stack.
pub trait OdeSystem<const N: usize> {
    /// Evaluate `dx = f(t, x)`.
    fn rhs(&self, t: f64, x: &[f64; N], dx: &mut [f64; N]);

    /// Optional variational hook: the Jacobian-vector product
    /// `jv = (df/dx)(t, x) v`. Return `false` (the default) if the system does
    /// not provide it; the Lyapunov code then falls back to two-trajectory
    /// (Benettin) renormalisation.
    fn jacobian_vector(&self, _t: f64, _x: &[f64; N], _v: &[f64; N], _jv: &mut [f64; N]) -> bool {
        false
    }
}

/// A system whose right-hand side is sampled on the RK4 half-step grid.
///
/// Grid index `j` stands for time `t_j = j * step_s / 2`; the system is
/// periodic in `j` with period [`GridOde::grid_len`] (= `2 * steps_per_period`).
/// For autonomous systems any `grid_len >= 2` works.
pub trait GridOde<const N: usize> {
    /// Fixed RK4 step `h` (in the system's time unit).
    fn step(&self) -> f64;
    /// Number of half-step grid points per period (`2 * steps_per_period`).
    fn grid_len(&self) -> usize;
    /// Evaluate `dx = f(t_j, x)` at half-step grid point `j` (`0 <= j < grid_len`).
    fn rhs_grid(&self, j: usize, x: &[f64; N], dx: &mut [f64; N]);

    /// One classical RK4 step from grid step `n` (`n mod steps_per_period`
    /// counts). The default evaluates [`GridOde::rhs_grid`] four times
    /// ([`crate::dynamics::integrate::rk4_step_generic`]); systems with a
    /// specialised kernel override it (same method, equal up to round-off).
    #[inline(always)]
    fn rk4_step(&self, n: usize, x: &mut [f64; N])
    where
        Self: Sized,
    {
        crate::dynamics::integrate::rk4_step_generic(self, n, x);
    }

    /// One RK4 step of two states of the same system (the two trajectories
    /// of a Lyapunov estimate); kernels with lanes run them in lock-step.
    /// Each result equals [`GridOde::rk4_step`] of that state exactly.
    #[inline(always)]
    fn rk4_step_pair(&self, n: usize, x: &mut [f64; N], y: &mut [f64; N])
    where
        Self: Sized,
    {
        self.rk4_step(n, x);
        self.rk4_step(n, y);
    }
}

/// Adapter that evaluates an [`OdeSystem`] on an RK4 grid: `t_j = j h / 2`
/// with `h = period / steps_per_period`. Used for the reference systems
/// (Lorenz, Duffing-Ueda) whose right-hand sides are cheap enough to evaluate
/// directly.
#[derive(Debug, Clone)]
pub struct Gridded<S> {
    /// The wrapped system.
    pub system: S,
    step: f64,
    grid_len: usize,
}

impl<S> Gridded<S> {
    /// Wrap `system` with `steps_per_period` RK4 steps per `period`.
    /// Callers validate `period > 0` and `steps_per_period >= 1`.
    pub fn new(system: S, period: f64, steps_per_period: usize) -> Self {
        let steps = steps_per_period.max(1);
        Gridded {
            system,
            step: period / steps as f64,
            grid_len: 2 * steps,
        }
    }
}

impl<const N: usize, S: OdeSystem<N>> GridOde<N> for Gridded<S> {
    fn step(&self) -> f64 {
        self.step
    }
    fn grid_len(&self) -> usize {
        self.grid_len
    }
    fn rhs_grid(&self, j: usize, x: &[f64; N], dx: &mut [f64; N]) {
        self.system.rhs(j as f64 * 0.5 * self.step, x, dx);
    }
}

/// A periodic table sampled uniformly over one period (phase in [0, 1)),
/// interpolated by a periodic cubic Hermite spline whose node slopes are
/// central differences (Catmull-Rom). Value and derivative are continuous, so
/// `d/dt e(t)` of a tabulated transmission error is well defined.
#[derive(Debug, Clone, PartialEq)]
pub struct PeriodicTable {
    samples: Vec<f64>,
}

impl PeriodicTable {
    /// Build from `samples` (at least one, all finite). `field` names the
    /// input in errors.
    pub fn new(field: &str, samples: Vec<f64>) -> crate::Result<Self> {
        if samples.is_empty() {
            return Err(crate::Error::config(
                field,
                "[]",
                "needs at least one sample per period",
            ));
        }
        for &s in &samples {
            crate::error::finite(field, s)?;
        }
        Ok(PeriodicTable { samples })
    }

    /// Constant table.
    pub fn constant(value: f64) -> Self {
        PeriodicTable { samples: vec![value] }
    }

    /// The raw samples.
    pub fn samples(&self) -> &[f64] {
        &self.samples
    }

    /// Arithmetic mean of the samples.
    pub fn mean(&self) -> f64 {
        self.samples.iter().sum::<f64>() / self.samples.len() as f64
    }

    /// Largest sample.
    pub fn max(&self) -> f64 {
        self.samples.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
    }

    /// Smallest sample.
    pub fn min(&self) -> f64 {
        self.samples.iter().cloned().fold(f64::INFINITY, f64::min)
    }

    /// Value and derivative with respect to phase (per period) at `phase`
    /// (any real number; the table is periodic with period 1).
    pub fn eval(&self, phase: f64) -> (f64, f64) {
        let n = self.samples.len();
        if n == 1 {
            return (self.samples[0], 0.0);
        }
        let s = phase.rem_euclid(1.0) * n as f64;
        let i = (s.floor() as usize).min(n - 1);
        let u = s - i as f64;
        let at = |k: isize| self.samples[k.rem_euclid(n as isize) as usize];
        let ii = i as isize;
        let (p0, p1) = (at(ii), at(ii + 1));
        // Node slopes per sample interval (central differences).
        let m0 = 0.5 * (at(ii + 1) - at(ii - 1));
        let m1 = 0.5 * (at(ii + 2) - at(ii));
        let (u2, u3) = (u * u, u * u * u);
        let h00 = 2.0 * u3 - 3.0 * u2 + 1.0;
        let h10 = u3 - 2.0 * u2 + u;
        let h01 = -2.0 * u3 + 3.0 * u2;
        let h11 = u3 - u2;
        let value = h00 * p0 + h10 * m0 + h01 * p1 + h11 * m1;
        let d00 = 6.0 * u2 - 6.0 * u;
        let d10 = 3.0 * u2 - 4.0 * u + 1.0;
        let d01 = -6.0 * u2 + 6.0 * u;
        let d11 = 3.0 * u2 - 2.0 * u;
        let dvalue_du = d00 * p0 + d10 * m0 + d01 * p1 + d11 * m1;
        (value, dvalue_du * n as f64)
    }

    /// Tabulate value and phase-derivative on `grid_len` uniform phases
    /// `j / grid_len` (the RK4 half-step grid).
    pub fn on_grid(&self, grid_len: usize) -> (Vec<f64>, Vec<f64>) {
        (0..grid_len).map(|j| self.eval(j as f64 / grid_len as f64)).unzip()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn periodic_table_interpolates_nodes_and_smooth_sine() {
        let n = 64;
        let samples: Vec<f64> = (0..n)
            .map(|k| (2.0 * std::f64::consts::PI * k as f64 / n as f64).sin())
            .collect();
        let t = PeriodicTable::new("e_m", samples.clone()).unwrap();
        for (k, s) in samples.iter().enumerate() {
            assert!((t.eval(k as f64 / n as f64).0 - s).abs() < 1e-14);
        }
        // Catmull-Rom is third-order accurate for smooth data; derivative of
        // sin(2 pi p) is 2 pi cos(2 pi p).
        for q in 0..200 {
            let p = q as f64 / 200.0 + 0.0013;
            let (v, d) = t.eval(p);
            let w = 2.0 * std::f64::consts::PI;
            assert!((v - (w * p).sin()).abs() < 2e-4);
            assert!((d - w * (w * p).cos()).abs() < 2e-2 * w);
        }
        assert!(PeriodicTable::new("k_n_per_m", vec![]).is_err());
        assert!(PeriodicTable::new("k_n_per_m", vec![f64::NAN]).is_err());
    }
}

/// Reference systems shared by the integrator tests.
#[cfg(test)]
pub(crate) mod test_systems {
    use super::OdeSystem;

    /// Harmonic oscillator x'' = -w^2 x (exact solution cos(w t)).
    pub(crate) struct Harmonic(pub f64);

    impl OdeSystem<2> for Harmonic {
        fn rhs(&self, _t: f64, x: &[f64; 2], dx: &mut [f64; 2]) {
            dx[0] = x[1];
            dx[1] = -self.0 * self.0 * x[0];
        }
    }
}
