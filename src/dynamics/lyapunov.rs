//! Largest Lyapunov exponent.
//!
//! - [`largest_lyapunov_benettin`]: two nearby trajectories integrated with the
//!   same fixed-step RK4, the separation renormalised to `d0` every
//!   `renorm_steps` steps; `lambda = sum ln(d / d0) / total time`
//!   (Benettin, Galgani, Giorgilli & Strelcyn 1980, Meccanica 15, 9-20;
//!   Wolf, Swift, Swinney & Vastano 1985, Physica D 16, 285-317). Works for any
//!   [`GridOde`], including the non-smooth gear model.
//! - [`largest_lyapunov_variational`]: integrates the tangent equation
//!   `v' = J(t, x) v` alongside the trajectory for systems that provide
//!   [`OdeSystem::jacobian_vector`].
//!
//! Distances use a weighted Euclidean norm `sqrt(sum ((x_i - y_i) / s_i)^2)`;
//! the weights make mixed-unit states (m and m/s) comparable and do not change
//! the exponent.

use super::integrate::{rk4_step, rk4_step_grid};
use super::ode::{GridOde, OdeSystem};
use crate::error::positive;
use crate::{Error, Result};

/// Settings of a Lyapunov run (all counts in RK4 steps).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LyapunovConfig {
    /// Steps discarded before measuring (let the trajectory reach the attractor).
    pub transient_steps: usize,
    /// Steps over which the exponent is averaged.
    pub measure_steps: usize,
    /// Renormalise every this many steps.
    pub renorm_steps: usize,
    /// Initial (and renormalised) separation in the weighted norm (-).
    pub separation: f64,
}

impl LyapunovConfig {
    fn check(&self) -> Result<()> {
        if self.measure_steps == 0 {
            return Err(Error::config("measure_steps", 0, "must be at least 1"));
        }
        if self.renorm_steps == 0 {
            return Err(Error::config("renorm_steps", 0, "must be at least 1"));
        }
        positive("separation", self.separation)?;
        Ok(())
    }
}

fn weighted_distance<const N: usize>(x: &[f64; N], y: &[f64; N], scale: &[f64; N]) -> f64 {
    let mut s = 0.0;
    for i in 0..N {
        let d = (x[i] - y[i]) / scale[i];
        s += d * d;
    }
    s.sqrt()
}

/// Largest Lyapunov exponent (per unit of the system's time) by two-trajectory
/// renormalisation, starting at state `x0` at grid step `n0`. `scale` weights
/// each state in the distance (all must be > 0). Returns the exponent and the
/// reference trajectory's final state.
pub fn largest_lyapunov_benettin<const N: usize, S: GridOde<N>>(
    sys: &S,
    x0: &[f64; N],
    n0: usize,
    scale: &[f64; N],
    cfg: &LyapunovConfig,
) -> Result<(f64, [f64; N])> {
    cfg.check()?;
    for &s in scale {
        positive("scale", s)?;
    }
    let per = (sys.grid_len() / 2).max(1);
    let mut n = n0 % per;
    let mut x = *x0;
    for k in 0..cfg.transient_steps {
        if k % crate::cancel::CHECK_EVERY_STEPS == 0 {
            crate::cancel::check()?;
        }
        rk4_step_grid(sys, n, &mut x);
        n = (n + 1) % per;
    }
    // Deterministic initial perturbation along the weighted diagonal.
    let mut y = x;
    let w = cfg.separation / (N as f64).sqrt();
    for i in 0..N {
        y[i] += w * scale[i];
    }
    let mut sum_log = 0.0;
    let mut done = 0;
    while done < cfg.measure_steps {
        let chunk = cfg.renorm_steps.min(cfg.measure_steps - done);
        for k in 0..chunk {
            if k % crate::cancel::CHECK_EVERY_STEPS == 0 {
                crate::cancel::check()?;
            }
            sys.rk4_step_pair(n, &mut x, &mut y);
            n = (n + 1) % per;
        }
        done += chunk;
        let d = weighted_distance(&x, &y, scale);
        if !d.is_finite() || d == 0.0 {
            return Err(Error::convergence(
                "lyapunov (separation lost)",
                done,
                d,
                cfg.separation,
            ));
        }
        sum_log += (d / cfg.separation).ln();
        let r = cfg.separation / d;
        for i in 0..N {
            y[i] = x[i] + (y[i] - x[i]) * r;
        }
    }
    Ok((sum_log / (cfg.measure_steps as f64 * sys.step()), x))
}

/// Settings of a block-averaged Benettin run (counts in RK4 steps).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LyapunovBlocks {
    /// Renormalise every this many steps.
    pub renorm_steps: usize,
    /// Renormalisations per block (the batch-means unit of the standard error).
    pub renorms_per_block: usize,
    /// Blocks always measured (at least 2).
    pub min_blocks: usize,
    /// Most blocks measured while the sign is undecided.
    pub max_blocks: usize,
    /// Initial (and renormalised) separation in the weighted norm \[-\].
    pub separation: f64,
    /// Standard errors that decide the sign (stop early once
    /// `|lambda - threshold| > sigmas * stderr`) \[-\].
    pub sigmas: f64,
    /// Threshold the exponent is compared with \[1/time unit of the system\].
    pub threshold: f64,
}

impl LyapunovBlocks {
    fn check(&self) -> Result<()> {
        if self.renorm_steps == 0 {
            return Err(Error::config("renorm_steps", 0, "must be at least 1"));
        }
        if self.renorms_per_block == 0 {
            return Err(Error::config("renorms_per_block", 0, "must be at least 1"));
        }
        if self.min_blocks < 2 {
            return Err(Error::config("min_blocks", self.min_blocks, "must be at least 2"));
        }
        positive("separation", self.separation)?;
        crate::error::non_negative("sigmas", self.sigmas)?;
        crate::error::finite("threshold", self.threshold)?;
        Ok(())
    }
}

/// A largest-exponent estimate with its standard error.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LyapunovEstimate<const N: usize> {
    /// Largest exponent \[1/time unit of the system\].
    pub exponent: f64,
    /// Standard error of the exponent by batch means over the blocks
    /// (`sd(block exponents) / sqrt(blocks)`), same unit.
    pub standard_error: f64,
    /// Blocks measured.
    pub blocks: usize,
    /// Final state of the reference trajectory.
    pub final_state: [f64; N],
}

/// Largest Lyapunov exponent by two-trajectory renormalisation (as
/// [`largest_lyapunov_benettin`], no transient) measured in blocks of
/// `renorms_per_block` renormalisations: at least `min_blocks`, then block
/// by block until the exponent differs from `threshold` by more than
/// `sigmas` standard errors or `max_blocks` are done. `on_renorm` sees the
/// reference state after every renormalisation (for the gear sweeps, the
/// section points). Deterministic: the same inputs give the same blocks.
pub fn largest_lyapunov_blocks<const N: usize, S: GridOde<N>>(
    sys: &S,
    x0: &[f64; N],
    n0: usize,
    scale: &[f64; N],
    cfg: &LyapunovBlocks,
    mut on_renorm: impl FnMut(&[f64; N]),
) -> Result<LyapunovEstimate<N>> {
    cfg.check()?;
    for &s in scale {
        positive("scale", s)?;
    }
    let per = (sys.grid_len() / 2).max(1);
    let mut n = n0 % per;
    let mut x = *x0;
    let mut y = x;
    let w = cfg.separation / (N as f64).sqrt();
    for i in 0..N {
        y[i] += w * scale[i];
    }
    let block_time = (cfg.renorm_steps * cfg.renorms_per_block) as f64 * sys.step();
    let mut blocks: Vec<f64> = Vec::new();
    let stats = |b: &[f64]| {
        let m = b.len() as f64;
        let mean = b.iter().sum::<f64>() / m;
        let var = b.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (m - 1.0).max(1.0);
        (mean, (var / m).sqrt())
    };
    loop {
        let mut sum_log = 0.0;
        for _ in 0..cfg.renorms_per_block {
            for k in 0..cfg.renorm_steps {
                if k % crate::cancel::CHECK_EVERY_STEPS == 0 {
                    crate::cancel::check()?;
                }
                sys.rk4_step_pair(n, &mut x, &mut y);
                n = (n + 1) % per;
            }
            let d = weighted_distance(&x, &y, scale);
            if !d.is_finite() || d == 0.0 {
                return Err(Error::convergence(
                    "lyapunov (separation lost)",
                    blocks.len(),
                    d,
                    cfg.separation,
                ));
            }
            sum_log += (d / cfg.separation).ln();
            let r = cfg.separation / d;
            for i in 0..N {
                y[i] = x[i] + (y[i] - x[i]) * r;
            }
            on_renorm(&x);
        }
        blocks.push(sum_log / block_time);
        if blocks.len() >= cfg.min_blocks {
            let (mean, se) = stats(&blocks);
            if blocks.len() >= cfg.max_blocks || (mean - cfg.threshold).abs() > cfg.sigmas * se {
                return Ok(LyapunovEstimate {
                    exponent: mean,
                    standard_error: se,
                    blocks: blocks.len(),
                    final_state: x,
                });
            }
        }
    }
}

/// Largest Lyapunov exponent from the variational equation `v' = J v`,
/// integrated with RK4 of step `h` from time `t0`. Errors if the system has no
/// Jacobian-vector hook.
pub fn largest_lyapunov_variational<const N: usize, S: OdeSystem<N>>(
    sys: &S,
    x0: &[f64; N],
    t0: f64,
    h: f64,
    cfg: &LyapunovConfig,
) -> Result<f64> {
    cfg.check()?;
    positive("step", h)?;
    let mut x = *x0;
    let mut t = t0;
    for k in 0..cfg.transient_steps {
        if k % crate::cancel::CHECK_EVERY_STEPS == 0 {
            crate::cancel::check()?;
        }
        rk4_step(sys, t, h, &mut x);
        t += h;
    }
    let mut v = [1.0 / (N as f64).sqrt(); N];
    let mut probe = [0.0; N];
    if !sys.jacobian_vector(t, &x, &v, &mut probe) {
        return Err(Error::config(
            "system",
            "no jacobian",
            "variational method needs jacobian_vector",
        ));
    }
    let mut sum_log = 0.0;
    let mut done = 0;
    while done < cfg.measure_steps {
        let chunk = cfg.renorm_steps.min(cfg.measure_steps - done);
        for k in 0..chunk {
            if k % crate::cancel::CHECK_EVERY_STEPS == 0 {
                crate::cancel::check()?;
            }
            tangent_rk4_step(sys, t, h, &mut x, &mut v);
            t += h;
        }
        done += chunk;
        let norm = v.iter().map(|a| a * a).sum::<f64>().sqrt();
        if !norm.is_finite() || norm == 0.0 {
            return Err(Error::convergence("lyapunov (tangent vector lost)", done, norm, 1.0));
        }
        sum_log += norm.ln();
        for a in &mut v {
            *a /= norm;
        }
    }
    Ok(sum_log / (cfg.measure_steps as f64 * h))
}

/// RK4 on the pair (x, v) with `x' = f(t, x)`, `v' = J(t, x) v`.
fn tangent_rk4_step<const N: usize, S: OdeSystem<N>>(sys: &S, t: f64, h: f64, x: &mut [f64; N], v: &mut [f64; N]) {
    let stage = |tt: f64, xs: &[f64; N], vs: &[f64; N], kx: &mut [f64; N], kv: &mut [f64; N]| {
        sys.rhs(tt, xs, kx);
        sys.jacobian_vector(tt, xs, vs, kv);
    };
    let (mut k1, mut k2, mut k3, mut k4) = ([0.0; N], [0.0; N], [0.0; N], [0.0; N]);
    let (mut l1, mut l2, mut l3, mut l4) = ([0.0; N], [0.0; N], [0.0; N], [0.0; N]);
    let (mut xs, mut vs) = ([0.0; N], [0.0; N]);
    stage(t, x, v, &mut k1, &mut l1);
    for i in 0..N {
        xs[i] = x[i] + 0.5 * h * k1[i];
        vs[i] = v[i] + 0.5 * h * l1[i];
    }
    stage(t + 0.5 * h, &xs, &vs, &mut k2, &mut l2);
    for i in 0..N {
        xs[i] = x[i] + 0.5 * h * k2[i];
        vs[i] = v[i] + 0.5 * h * l2[i];
    }
    stage(t + 0.5 * h, &xs, &vs, &mut k3, &mut l3);
    for i in 0..N {
        xs[i] = x[i] + h * k3[i];
        vs[i] = v[i] + h * l3[i];
    }
    stage(t + h, &xs, &vs, &mut k4, &mut l4);
    for i in 0..N {
        x[i] += h / 6.0 * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i]);
        v[i] += h / 6.0 * (l1[i] + 2.0 * (l2[i] + l3[i]) + l4[i]);
    }
}

/// Lorenz (1963) system `x' = sigma (y - x)`, `y' = x (rho - z) - y`,
/// `z' = x y - beta z`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Lorenz {
    /// sigma (-).
    pub sigma: f64,
    /// rho (-).
    pub rho: f64,
    /// beta (-).
    pub beta: f64,
}

impl Lorenz {
    /// The classic chaotic case sigma = 10, rho = 28, beta = 8/3.
    pub fn classic() -> Self {
        Lorenz {
            sigma: 10.0,
            rho: 28.0,
            beta: 8.0 / 3.0,
        }
    }
}

impl OdeSystem<3> for Lorenz {
    fn rhs(&self, _t: f64, x: &[f64; 3], dx: &mut [f64; 3]) {
        dx[0] = self.sigma * (x[1] - x[0]);
        dx[1] = x[0] * (self.rho - x[2]) - x[1];
        dx[2] = x[0] * x[1] - self.beta * x[2];
    }
    fn jacobian_vector(&self, _t: f64, x: &[f64; 3], v: &[f64; 3], jv: &mut [f64; 3]) -> bool {
        jv[0] = self.sigma * (v[1] - v[0]);
        jv[1] = (self.rho - x[2]) * v[0] - v[1] - x[0] * v[2];
        jv[2] = x[1] * v[0] + x[0] * v[1] - self.beta * v[2];
        true
    }
}

/// Ueda's form of the Duffing oscillator `x'' + k x' + x^3 = B cos t`
/// (Ueda 1979, J. Stat. Phys. 20, 181-196).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DuffingUeda {
    /// Damping k (-).
    pub damping: f64,
    /// Forcing amplitude B (-).
    pub forcing: f64,
}

impl DuffingUeda {
    /// Ueda's chaotic case k = 0.05, B = 7.5.
    pub fn chaotic() -> Self {
        DuffingUeda {
            damping: 0.05,
            forcing: 7.5,
        }
    }
}

impl OdeSystem<2> for DuffingUeda {
    fn rhs(&self, t: f64, x: &[f64; 2], dx: &mut [f64; 2]) {
        dx[0] = x[1];
        dx[1] = self.forcing * t.cos() - self.damping * x[1] - x[0] * x[0] * x[0];
    }
    fn jacobian_vector(&self, _t: f64, x: &[f64; 2], v: &[f64; 2], jv: &mut [f64; 2]) -> bool {
        jv[0] = v[1];
        jv[1] = -3.0 * x[0] * x[0] * v[0] - self.damping * v[1];
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::ode::Gridded;

    #[test]
    fn linear_damped_oscillator_exponent_is_minus_zeta_omega() {
        // x'' + 2 z w x' + w^2 x = 0, underdamped: both exponents equal -z w.
        struct Osc;
        impl OdeSystem<2> for Osc {
            fn rhs(&self, _t: f64, x: &[f64; 2], dx: &mut [f64; 2]) {
                dx[0] = x[1];
                dx[1] = -x[0] - 0.2 * x[1];
            }
        }
        let g = Gridded::new(Osc, 0.05, 1);
        let cfg = LyapunovConfig {
            transient_steps: 0,
            measure_steps: 20_000,
            renorm_steps: 10,
            separation: 1e-8,
        };
        let (l, _) = largest_lyapunov_benettin(&g, &[1.0, 0.0], 0, &[1.0, 1.0], &cfg).unwrap();
        assert!((l + 0.1).abs() < 2e-3, "{l}");
        let bad = LyapunovConfig { renorm_steps: 0, ..cfg };
        assert!(largest_lyapunov_benettin(&g, &[1.0, 0.0], 0, &[1.0, 1.0], &bad).is_err());
    }
}
