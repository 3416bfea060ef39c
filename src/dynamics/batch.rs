//! Lock-step RK4 of several helical-pair systems ("lanes") at once.
//!
//! A single trajectory of the 14-state model is latency bound (each RK4
//! stage waits for the mesh force of the previous one). Integrating `L`
//! independent systems (different speeds, bearing cases or sweeps) in
//! lock-step, with the lane index innermost, gives the CPU `L` independent
//! dependency chains and lets the compiler use SIMD. Every lane performs
//! exactly the floating-point operations of the scalar
//! [`HelicalPairSystem`] in the same order, so results are bitwise identical
//! to the scalar path (tested), whatever lanes a system is grouped with.

use super::gear_model::HelicalPairSystem;
use super::ode::GridOde;
use super::poincare::PoincareRecord;
use crate::{Error, Result};

/// Lanes used by the sweeps.
pub const LANES: usize = 4;

/// `L` helical-pair systems with the same number of steps per mesh period.
#[derive(Debug, Clone)]
pub struct HelicalBatch<const L: usize> {
    a: [[f64; L]; 7],
    am: [[f64; L]; 7],
    kbm: [[f64; L]; 7],
    cbm: [[f64; L]; 7],
    g: [[f64; L]; 7],
    b: [f64; L],
    cm: [f64; L],
    /// Mesh damping inside the backlash: `c_m` if it always acts, else 0.
    cm_gap: [f64; L],
    h: [f64; L],
    /// `[k_m, e, de/dt]` per grid point and lane.
    coef: Vec<[[f64; L]; 3]>,
}

/// Batch state: `x[state][lane]`.
pub type BatchState<const L: usize> = [[f64; L]; 14];

impl<const L: usize> HelicalBatch<L> {
    /// Gather `L` systems; all must have the same grid length.
    pub fn new(systems: [&HelicalPairSystem; L]) -> Result<Self> {
        let g = systems[0].grid_len();
        if systems.iter().any(|s| s.grid_len() != g) {
            return Err(Error::config(
                "steps_per_period",
                "mixed",
                "lanes must share steps_per_period",
            ));
        }
        let z = [[0.0; L]; 7];
        let mut out = HelicalBatch {
            a: z,
            am: z,
            kbm: z,
            cbm: z,
            g: z,
            b: [0.0; L],
            cm: [0.0; L],
            cm_gap: [0.0; L],
            h: [0.0; L],
            coef: vec![[[0.0; L]; 3]; g],
        };
        for (l, s) in systems.iter().enumerate() {
            for i in 0..7 {
                out.a[i][l] = s.a[i];
                out.am[i][l] = s.am[i];
                out.kbm[i][l] = s.kbm[i];
                out.cbm[i][l] = s.cbm[i];
                out.g[i][l] = s.g[i];
            }
            out.b[l] = s.b;
            out.cm[l] = s.cm;
            out.cm_gap[l] = if s.always { s.cm } else { 0.0 };
            out.h[l] = s.step();
            for j in 0..g {
                for c in 0..3 {
                    out.coef[j][c][l] = s.coef[j][c];
                }
            }
        }
        Ok(out)
    }

    /// Grid length (2 x steps per period).
    pub fn grid_len(&self) -> usize {
        self.coef.len()
    }

    #[inline(always)]
    fn rhs(&self, j: usize, x: &BatchState<L>, dx: &mut BatchState<L>) {
        let c3 = &self.coef[j];
        let a = &self.a;
        let mut fmesh = [0.0; L];
        for l in 0..L {
            let d = ((a[0][l] * x[0][l] + a[1][l] * x[1][l]) + (a[2][l] * x[2][l] + a[3][l] * x[3][l]))
                + ((a[4][l] * x[4][l] + a[5][l] * x[5][l]) + a[6][l] * x[6][l]);
            let dv = ((a[0][l] * x[7][l] + a[1][l] * x[8][l]) + (a[2][l] * x[9][l] + a[3][l] * x[10][l]))
                + ((a[4][l] * x[11][l] + a[5][l] * x[12][l]) + a[6][l] * x[13][l]);
            let s = d - c3[1][l];
            // f64::clamp spelled out as selects (same values, vectorisable).
            let (lo, hi) = (-self.b[l], self.b[l]);
            let cl = if s < lo { lo } else { s };
            let cl = if cl > hi { hi } else { cl };
            let f = s - cl;
            let c = if f != 0.0 { self.cm[l] } else { self.cm_gap[l] };
            fmesh[l] = c3[0][l] * f + c * (dv - c3[2][l]);
        }
        for i in 0..7 {
            for l in 0..L {
                dx[i][l] = x[7 + i][l];
                dx[7 + i][l] =
                    self.g[i][l] - self.kbm[i][l] * x[i][l] - self.cbm[i][l] * x[7 + i][l] - self.am[i][l] * fmesh[l];
            }
        }
    }

    /// One RK4 step of every lane from step `n` (< steps per period).
    #[inline(always)]
    pub fn step(&self, n: usize, x: &mut BatchState<L>) {
        let gl = self.grid_len();
        let j0 = (2 * n) % gl;
        let j1 = j0 + 1;
        let j2 = if j1 + 1 == gl { 0 } else { j1 + 1 };
        let z = [[0.0; L]; 14];
        let (mut k1, mut k2, mut k3, mut k4, mut y) = (z, z, z, z, z);
        self.rhs(j0, x, &mut k1);
        for i in 0..14 {
            for l in 0..L {
                y[i][l] = x[i][l] + 0.5 * self.h[l] * k1[i][l];
            }
        }
        self.rhs(j1, &y, &mut k2);
        for i in 0..14 {
            for l in 0..L {
                y[i][l] = x[i][l] + 0.5 * self.h[l] * k2[i][l];
            }
        }
        self.rhs(j1, &y, &mut k3);
        for i in 0..14 {
            for l in 0..L {
                y[i][l] = x[i][l] + self.h[l] * k3[i][l];
            }
        }
        self.rhs(j2, &y, &mut k4);
        for i in 0..14 {
            for l in 0..L {
                let h6 = self.h[l] / 6.0;
                x[i][l] += h6 * (k1[i][l] + 2.0 * (k2[i][l] + k3[i][l]) + k4[i][l]);
            }
        }
    }

    /// Relative deflection `delta_n - e` of every lane at step `n`.
    #[inline(always)]
    fn deflection(&self, n: usize, x: &BatchState<L>) -> [f64; L] {
        let j = (2 * n) % self.grid_len();
        let mut out = [0.0; L];
        for (l, o) in out.iter_mut().enumerate() {
            // Same summation order as HelicalPairSystem::relative_deflection_m.
            let mut s = 0.0;
            for (ai, xi) in self.a.iter().zip(x.iter()) {
                s += ai[l] * xi[l];
            }
            *o = s - self.coef[j][1][l];
        }
        out
    }
}

/// Pack lane states.
pub fn pack<const L: usize>(states: &[[f64; 14]; L]) -> BatchState<L> {
    let mut x = [[0.0; L]; 14];
    for (l, s) in states.iter().enumerate() {
        for i in 0..14 {
            x[i][l] = s[i];
        }
    }
    x
}

/// State of one lane.
pub fn lane<const L: usize>(x: &BatchState<L>, l: usize) -> [f64; 14] {
    std::array::from_fn(|i| x[i][l])
}

/// Lock-step version of [`super::poincare::poincare_sample`] with the
/// relative deflection as observable; one record per lane, identical to the
/// scalar records. On x86-64 CPUs with AVX2 (detected at run time) the same
/// code is compiled with 256-bit vectors; no FMA contraction is used, so the
/// results do not depend on the CPU.
pub fn poincare_sample_batch<const L: usize>(
    batch: &HelicalBatch<L>,
    starts: &[[f64; 14]; L],
    transient_periods: usize,
    recorded_periods: usize,
) -> Result<[PoincareRecord<14>; L]> {
    #[cfg(target_arch = "x86_64")]
    {
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: the CPU supports AVX2 (checked just above), the only
            // requirement of a `target_feature(enable = "avx2")` function.
            return unsafe { poincare_avx2(batch, starts, transient_periods, recorded_periods) };
        }
    }
    poincare_impl(batch, starts, transient_periods, recorded_periods)
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn poincare_avx2<const L: usize>(
    batch: &HelicalBatch<L>,
    starts: &[[f64; 14]; L],
    transient_periods: usize,
    recorded_periods: usize,
) -> Result<[PoincareRecord<14>; L]> {
    poincare_impl(batch, starts, transient_periods, recorded_periods)
}

/// Advance `steps` lock-step RK4 steps from step 0 (AVX2 when available);
/// used by the timing example.
pub fn advance_batch<const L: usize>(batch: &HelicalBatch<L>, x: &mut BatchState<L>, steps: usize) {
    #[cfg(target_arch = "x86_64")]
    {
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: AVX2 support checked just above.
            unsafe { advance_avx2(batch, x, steps) };
            return;
        }
    }
    advance_impl(batch, x, steps);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn advance_avx2<const L: usize>(batch: &HelicalBatch<L>, x: &mut BatchState<L>, steps: usize) {
    advance_impl(batch, x, steps);
}

#[inline(always)]
fn advance_impl<const L: usize>(batch: &HelicalBatch<L>, x: &mut BatchState<L>, steps: usize) {
    let per = batch.grid_len() / 2;
    let mut n = 0;
    for _ in 0..steps {
        batch.step(n, x);
        n += 1;
        if n == per {
            n = 0;
        }
    }
}

#[inline(always)]
fn poincare_impl<const L: usize>(
    batch: &HelicalBatch<L>,
    starts: &[[f64; 14]; L],
    transient_periods: usize,
    recorded_periods: usize,
) -> Result<[PoincareRecord<14>; L]> {
    if recorded_periods == 0 {
        return Err(Error::config("recorded_periods", 0, "must be at least 1"));
    }
    let per = batch.grid_len() / 2;
    let mut x = pack(starts);
    let finite = |x: &BatchState<L>| x.iter().all(|r| r.iter().all(|v| v.is_finite()));
    for p in 0..transient_periods {
        for n in 0..per {
            batch.step(n, &mut x);
        }
        if !finite(&x) {
            return Err(Error::convergence(
                "rk4 (state diverged in transient)",
                p * per,
                f64::INFINITY,
                0.0,
            ));
        }
    }
    let mut points = vec![Vec::with_capacity(recorded_periods); L];
    let mut obs = vec![Vec::with_capacity(recorded_periods); L];
    let mut lo = [f64::INFINITY; L];
    let mut hi = [f64::NEG_INFINITY; L];
    let mut smin = x;
    let mut smax = x;
    for p in 0..recorded_periods {
        let o0 = batch.deflection(0, &x);
        for l in 0..L {
            points[l].push(lane(&x, l));
            obs[l].push(o0[l]);
        }
        for n in 0..per {
            batch.step(n, &mut x);
            let next = if n + 1 == per { 0 } else { n + 1 };
            let o = batch.deflection(next, &x);
            for l in 0..L {
                lo[l] = lo[l].min(o[l]);
                hi[l] = hi[l].max(o[l]);
            }
            if p == 0 {
                for i in 0..14 {
                    for l in 0..L {
                        smin[i][l] = smin[i][l].min(x[i][l]);
                        smax[i][l] = smax[i][l].max(x[i][l]);
                    }
                }
            }
        }
        if !finite(&x) {
            return Err(Error::convergence("rk4 (state diverged)", p * per, f64::INFINITY, 0.0));
        }
    }
    let mut points = points.into_iter();
    let mut obs = obs.into_iter();
    Ok(std::array::from_fn(|l| PoincareRecord {
        points: points.next().unwrap_or_default(),
        observable: obs.next().unwrap_or_default(),
        observable_min: lo[l],
        observable_max: hi[l],
        state_range: std::array::from_fn(|i| smax[i][l] - smin[i][l]),
        final_state: lane(&x, l),
    }))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::gear_model::{HelicalPair, HelicalPairParams, MeshDamping};
    use crate::dynamics::poincare::poincare_sample;

    #[test]
    fn batch_lanes_are_bitwise_identical_to_scalar_runs() {
        let mut p = HelicalPairParams::seed_a();
        p.input_torque_n_m = 10.0;
        for e in &mut p.transmission_error_m {
            *e *= 5.0;
        }
        let pair = HelicalPair::new(p.clone()).unwrap();
        p.mesh_damping = MeshDamping::Always;
        let pair2 = HelicalPair::new(p).unwrap().with_bearing_stiffness(1.5e8, 7e7).unwrap();
        let sys = [
            pair.system(7000.0, 48).unwrap(),
            pair2.system(9000.0, 48).unwrap(),
            pair.system(13000.0, 48).unwrap(),
        ];
        let starts = [
            pair.static_state().unwrap(),
            pair2.static_state().unwrap(),
            pair.static_state().unwrap(),
        ];
        let batch = HelicalBatch::new([&sys[0], &sys[1], &sys[2]]).unwrap();
        let recs = poincare_sample_batch(&batch, &starts, 20, 5).unwrap();
        for l in 0..3 {
            let r = poincare_sample(&sys[l], &starts[l], 20, 5, |n, x| sys[l].relative_deflection_m(n, x)).unwrap();
            assert_eq!(recs[l], r, "lane {l}");
        }
        let other = pair.system(7000.0, 64).unwrap();
        assert!(HelicalBatch::new([&sys[0], &other]).is_err());
    }
}
