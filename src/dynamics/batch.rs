//! Lock-step RK4 of several helical-pair systems ("lanes") at once, and the
//! single-system kernel behind [`HelicalPairSystem`]'s RK4 step.
//!
//! A single trajectory of the 14-state model is latency bound (each RK4
//! stage waits for the mesh force of the previous one). Integrating `L`
//! independent systems (different speeds, bearing cases or sweeps) in
//! lock-step, with the lane index innermost (structure of arrays), gives the
//! CPU `L` independent dependency chains in one vector register.
//!
//! # The kernel
//! One classical RK4 step of docs/concepts/physics.md §7 (A-43 .. A-50) in
//! the reduced coordinates of [`super::gear_model`], arranged for a short
//! dependency chain and few operations (all exact rearrangements of the
//! same RK4 step; they change results only by rounding):
//! - stage positions enter the mesh only through `delta = a . q`, and
//!   `a . (x_q + c h V) = a . x_q + c h (a . V)`: the mesh deflection of a
//!   stage is `D0 + c h dV` with `D0 = a . x_q` once per step and `dV` the
//!   previous stage's mesh velocity (already computed);
//! - the dead zone of the total clearance `2 b` as
//!   `max(0, delta - (e + b)) + min(0, delta - (e - b))` with `e +- b`
//!   tabulated (branch free, no clamp);
//! - contact-dependent mesh damping as a select between two precomputed
//!   products; the structural zeros of the model are skipped (no bearing on
//!   the relative rotation `u`, the torque acts only on `u`);
//! - no division: `k_b / m`, `c_b / m`, `a / m`, `h / 2`, `h / 6` are
//!   precomputed; mesh stiffness, `e +- b` and `de/dt` come from tables on
//!   the half-step grid (one load per stage, no series or interpolation).
//!
//! Every lane performs exactly the same floating-point operations, in the
//! same order, as the one-lane kernel used by
//! [`crate::dynamics::GridOde::rk4_step`] of [`HelicalPairSystem`] (no fused
//! multiply-add, see `src/dynamics/simd.rs`): batch lanes equal scalar runs bitwise,
//! on every instruction set and CPU, whatever lanes a system is grouped with
//! (tested). The instruction set is detected at run time ([`Isa`]).

use super::gear_model::HelicalPairSystem;
use super::poincare::PoincareRecord;
#[cfg(target_arch = "x86_64")]
use super::simd::Avx512;
use super::simd::{Lanes, Portable, Simd};
use crate::{Error, Result};

pub use super::simd::Isa;

/// Most lanes per batch used by the sweeps (one AVX-512 register, two AVX2
/// registers).
pub const LANES: usize = 8;

/// Per-system constants of the RK4 kernel; `T` is `f64` (one system), an
/// array of lanes or a vector register.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Coef<T> {
    /// Mesh-normal projection `a`.
    pub a: [T; 7],
    /// `-k_b / m` of the six bearing coordinates.
    pub nk: [T; 6],
    /// `-c_b / m` of the six bearing coordinates.
    pub nc: [T; 6],
    /// `-a / m`.
    pub na: [T; 7],
    /// `T_p / (R_p m_e)`, the torque term of the `u` row.
    pub g6: T,
    /// Mesh damping `c_m` in contact.
    pub cm: T,
    /// Mesh damping inside the backlash (`c_m` if always acting, else 0).
    pub cg: T,
    /// `h / 2`.
    pub hh: T,
    /// `h`.
    pub h: T,
    /// `h / 6`.
    pub h6: T,
}

impl<T> Coef<T> {
    #[inline(always)]
    fn map<U: Copy>(&self, f: impl Fn(&T) -> U) -> Coef<U> {
        // Plain loops (`array::map` need not inline).
        let z = f(&self.g6);
        let (mut a, mut nk, mut nc, mut na) = ([z; 7], [z; 6], [z; 6], [z; 7]);
        for i in 0..7 {
            a[i] = f(&self.a[i]);
            na[i] = f(&self.na[i]);
        }
        for i in 0..6 {
            nk[i] = f(&self.nk[i]);
            nc[i] = f(&self.nc[i]);
        }
        Coef {
            a,
            nk,
            nc,
            na,
            g6: z,
            cm: f(&self.cm),
            cg: f(&self.cg),
            hh: f(&self.hh),
            h: f(&self.h),
            h6: f(&self.h6),
        }
    }
}

/// The kernel tables of one system: constants and, per half-step grid point,
/// `[k_m, e + b, e - b, de/dt]`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct HelicalKernel {
    pub coef: Coef<f64>,
    pub grid: Vec<[f64; 4]>,
}

impl HelicalKernel {
    /// From the model's divided coefficients. `kbm`, `cbm` must vanish for
    /// `u` and `g` for the bearing coordinates (the model's structure).
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        a: &[f64; 7],
        am: &[f64; 7],
        kbm: &[f64; 7],
        cbm: &[f64; 7],
        g: &[f64; 7],
        b: f64,
        cm: f64,
        always: bool,
        h: f64,
        coef: &[[f64; 3]],
    ) -> Self {
        debug_assert!(kbm[6] == 0.0 && cbm[6] == 0.0 && g[..6].iter().all(|&v| v == 0.0));
        HelicalKernel {
            coef: Coef {
                a: *a,
                nk: std::array::from_fn(|i| -kbm[i]),
                nc: std::array::from_fn(|i| -cbm[i]),
                na: am.map(|v| -v),
                g6: g[6],
                cm,
                cg: if always { cm } else { 0.0 },
                hh: 0.5 * h,
                h,
                h6: h / 6.0,
            },
            grid: coef.iter().map(|&[k, e, de]| [k, e + b, e - b, de]).collect(),
        }
    }

    /// Grid indices of the stages of step `n` (`t_n`, `t_n + h/2`, `t_n + h`).
    #[inline(always)]
    fn stages(&self, n: usize) -> (usize, usize, usize) {
        stage_indices(n, self.grid.len())
    }

    /// One RK4 step of one system.
    #[inline(always)]
    pub fn step(&self, n: usize, x: &mut [f64; 14]) {
        let (j0, j1, j2) = self.stages(n);
        rk4_kernel(&self.coef, &self.grid[j0], &self.grid[j1], &self.grid[j2], x);
    }

    /// One RK4 step of two states of this system in lock-step.
    #[inline(always)]
    pub fn step_pair(&self, n: usize, x: &mut [f64; 14], y: &mut [f64; 14]) {
        self.step_pair_v::<Portable<2>>(n, x, y);
    }

    #[inline(always)]
    fn step_pair_v<V: Lanes<2>>(&self, n: usize, x: &mut [f64; 14], y: &mut [f64; 14]) {
        let (j0, j1, j2) = self.stages(n);
        let c = self.coef.map(|&v| V::splat(v));
        let g = |j: usize| {
            let r = &self.grid[j];
            [V::splat(r[0]), V::splat(r[1]), V::splat(r[2]), V::splat(r[3])]
        };
        let mut v = [V::splat(0.0); 14];
        for i in 0..14 {
            v[i] = V::load(&[x[i], y[i]]);
        }
        rk4_kernel(&c, &g(j0), &g(j1), &g(j2), &mut v);
        for i in 0..14 {
            let mut o = [0.0; 2];
            v[i].store(&mut o);
            x[i] = o[0];
            y[i] = o[1];
        }
    }
}

#[inline(always)]
fn stage_indices(n: usize, grid_len: usize) -> (usize, usize, usize) {
    let j0 = if 2 * n < grid_len { 2 * n } else { (2 * n) % grid_len };
    let j1 = if j0 + 1 == grid_len { 0 } else { j0 + 1 };
    let j2 = if j1 + 1 == grid_len { 0 } else { j1 + 1 };
    (j0, j1, j2)
}

/// `a . x` as a pairwise sum (short dependency chain).
#[inline(always)]
fn dot7<V: Simd>(a: &[V; 7], x: &[V; 7]) -> V {
    let p = |i: usize| a[i].mul(x[i]);
    (p(0).add(p(1)).add(p(2).add(p(3)))).add(p(4).add(p(5)).add(p(6)))
}

/// Stage derivative: from the stage deflection `d = a . q`, the bearing
/// positions `q` and all velocities `v`, the mesh velocity `a . v` and the
/// accelerations.
#[inline(always)]
fn stage<V: Simd>(c: &Coef<V>, g: &[V; 4], d: V, q: &[V; 6], v: &[V; 7]) -> (V, [V; 7]) {
    let dv = dot7(&c.a, v);
    let [km, e_hi, e_lo, edot] = *g;
    let f = d.sub(e_hi).pos_part().add(d.sub(e_lo).neg_part());
    let w = dv.sub(edot);
    let fm = km.mul(f).add(f.select_nonzero(c.cm.mul(w), c.cg.mul(w)));
    let mut acc = [V::splat(0.0); 7];
    for i in 0..6 {
        acc[i] = c.nk[i].mul(q[i]).add(c.nc[i].mul(v[i])).add(c.na[i].mul(fm));
    }
    acc[6] = c.g6.add(c.na[6].mul(fm));
    (dv, acc)
}

/// Stage positions of the bearing coordinates `x_q + s v`.
#[inline(always)]
fn stage_q<V: Simd>(xq: &[V; 7], s: V, v: &[V; 7]) -> [V; 6] {
    let mut q = [s; 6];
    for i in 0..6 {
        q[i] = xq[i].add(s.mul(v[i]));
    }
    q
}

/// Stage velocities `x_v + s k`.
#[inline(always)]
fn stage_v<V: Simd>(xv: &[V; 7], s: V, k: &[V; 7]) -> [V; 7] {
    let mut v = [s; 7];
    for i in 0..7 {
        v[i] = xv[i].add(s.mul(k[i]));
    }
    v
}

/// One classical RK4 step of the helical pair on lanes `V`; `g0, g1, g2` are
/// the grid rows at `t_n`, `t_n + h/2`, `t_n + h`.
#[inline(always)]
pub(crate) fn rk4_kernel<V: Simd>(c: &Coef<V>, g0: &[V; 4], g1: &[V; 4], g2: &[V; 4], x: &mut [V; 14]) {
    // Plain loops and functions throughout (closures and `array::from_fn`
    // need not inline).
    let z = V::splat(0.0);
    let (mut xq, mut xv) = ([z; 7], [z; 7]);
    xq.copy_from_slice(&x[..7]);
    xv.copy_from_slice(&x[7..]);
    let d0 = dot7(&c.a, &xq);
    let mut q1 = [z; 6];
    q1.copy_from_slice(&xq[..6]);
    let (dv1, k1) = stage(c, g0, d0, &q1, &xv);
    let v2 = stage_v(&xv, c.hh, &k1);
    let (dv2, k2) = stage(c, g1, d0.add(c.hh.mul(dv1)), &stage_q(&xq, c.hh, &xv), &v2);
    let v3 = stage_v(&xv, c.hh, &k2);
    let q3 = stage_q(&xq, c.hh, &v2);
    // x += h/6 (k1 + 2 (k2 + k3) + k4), the position slopes being the stage
    // velocities; partial sums formed as soon as their terms exist (fewer
    // live registers).
    let two = V::splat(2.0);
    let mut sq = [z; 7];
    for i in 0..7 {
        sq[i] = xv[i].add(two.mul(v2[i].add(v3[i])));
    }
    let (dv3, k3) = stage(c, g1, d0.add(c.hh.mul(dv2)), &q3, &v3);
    let v4 = stage_v(&xv, c.h, &k3);
    let q4 = stage_q(&xq, c.h, &v3);
    let mut sv = [z; 7];
    for i in 0..7 {
        sv[i] = k1[i].add(two.mul(k2[i].add(k3[i])));
    }
    let (_, k4) = stage(c, g2, d0.add(c.h.mul(dv3)), &q4, &v4);
    for i in 0..7 {
        x[i] = xq[i].add(c.h6.mul(sq[i].add(v4[i])));
        x[7 + i] = xv[i].add(c.h6.mul(sv[i].add(k4[i])));
    }
}

/// One half-step grid point of a batch: `[k_m, e + b, e - b, de/dt]` and the
/// transmission error `e` (the observable), each per lane. Cache-line
/// aligned, so no vector load of a row straddles two lines.
#[derive(Debug, Clone, Copy)]
#[repr(C, align(64))]
struct GridRow<const L: usize> {
    g: [[f64; L]; 4],
    e: [f64; L],
}

/// `L` helical-pair systems with the same number of steps per mesh period.
#[derive(Debug, Clone)]
pub struct HelicalBatch<const L: usize> {
    coef: Coef<[f64; L]>,
    grid: Vec<GridRow<L>>,
}

/// Batch state: `x[state][lane]`.
pub type BatchState<const L: usize> = [[f64; L]; 14];

impl<const L: usize> HelicalBatch<L> {
    /// Gather `L` systems; all must have the same grid length.
    pub fn new(systems: [&HelicalPairSystem; L]) -> Result<Self> {
        let g = systems[0].kernel.grid.len();
        if systems.iter().any(|s| s.kernel.grid.len() != g) {
            return Err(Error::config(
                "steps_per_period",
                "mixed",
                "lanes must share steps_per_period",
            ));
        }
        let lanes = |f: &dyn Fn(&HelicalPairSystem) -> f64| -> [f64; L] { std::array::from_fn(|l| f(systems[l])) };
        let c = |f: &dyn Fn(&Coef<f64>) -> f64| lanes(&|s| f(&s.kernel.coef));
        let coef = Coef {
            a: std::array::from_fn(|i| c(&|k| k.a[i])),
            nk: std::array::from_fn(|i| c(&|k| k.nk[i])),
            nc: std::array::from_fn(|i| c(&|k| k.nc[i])),
            na: std::array::from_fn(|i| c(&|k| k.na[i])),
            g6: c(&|k| k.g6),
            cm: c(&|k| k.cm),
            cg: c(&|k| k.cg),
            hh: c(&|k| k.hh),
            h: c(&|k| k.h),
            h6: c(&|k| k.h6),
        };
        let grid = (0..g)
            .map(|j| GridRow {
                g: std::array::from_fn(|r| lanes(&|s| s.kernel.grid[j][r])),
                e: lanes(&|s| s.coef[j][1]),
            })
            .collect();
        Ok(HelicalBatch { coef, grid })
    }

    /// Grid length (2 x steps per period).
    pub fn grid_len(&self) -> usize {
        self.grid.len()
    }

    /// One RK4 step of every lane from step `n` (< steps per period), with
    /// the portable kernel (the sweeps use the detected instruction set).
    pub fn step(&self, n: usize, x: &mut BatchState<L>) {
        let c = self.coef.map(Portable::<L>::load);
        let mut v = load_state::<L, Portable<L>>(x);
        self.step_v(&c, n, &mut v);
        store_state(&v, x);
    }

    #[inline(always)]
    fn step_v<V: Lanes<L>>(&self, c: &Coef<V>, n: usize, x: &mut [V; 14]) {
        let (j0, j1, j2) = stage_indices(n, self.grid.len());
        let row = |j: usize| -> [V; 4] {
            let g = &self.grid[j].g;
            [V::load(&g[0]), V::load(&g[1]), V::load(&g[2]), V::load(&g[3])]
        };
        rk4_kernel(c, &row(j0), &row(j1), &row(j2), x);
    }

    /// Relative deflection `delta_n - e` of every lane at grid point `j`
    /// (the summation order of `HelicalPairSystem::relative_deflection_m`).
    #[inline(always)]
    fn deflection_v<V: Lanes<L>>(&self, c: &Coef<V>, j: usize, x: &[V; 14]) -> V {
        let mut s = c.a[0].mul(x[0]);
        for (ai, xi) in c.a.iter().zip(x).skip(1) {
            s = s.add(ai.mul(*xi));
        }
        s.sub(V::load(&self.grid[j].e))
    }
}

#[inline(always)]
fn load_state<const L: usize, V: Lanes<L>>(x: &BatchState<L>) -> [V; 14] {
    let mut v = [V::splat(0.0); 14];
    for (vi, xi) in v.iter_mut().zip(x) {
        *vi = V::load(xi);
    }
    v
}

#[inline(always)]
fn store_state<const L: usize, V: Lanes<L>>(v: &[V; 14], x: &mut BatchState<L>) {
    for (vi, xi) in v.iter().zip(x.iter_mut()) {
        vi.store(xi);
    }
}

/// Pack lane states.
pub fn pack<const L: usize>(states: &[[f64; 14]; L]) -> BatchState<L> {
    std::array::from_fn(|i| std::array::from_fn(|l| states[l][i]))
}

/// State of one lane.
pub fn lane<const L: usize>(x: &BatchState<L>, l: usize) -> [f64; 14] {
    std::array::from_fn(|i| x[i][l])
}

// ------------------------------------------------------------ dispatch ----

/// Work generic over the lane vector type.
trait Job<const L: usize> {
    type Out;
    fn run<V: Lanes<L>>(self) -> Self::Out;
}

fn check_isa(isa: Isa) -> Result<()> {
    if isa.is_available() {
        Ok(())
    } else {
        Err(Error::config("isa", isa.name(), "not supported by this CPU"))
    }
}

/// Run `job` for `L` lanes with `isa` (available): lane arrays compiled for
/// that instruction set, one lane as plain `f64`.
fn dispatch<const L: usize, J: Job<L>>(isa: Isa, job: J) -> J::Out {
    #[cfg(target_arch = "x86_64")]
    {
        if L == 8 && isa == Isa::Avx512 {
            // SAFETY: `isa` is available (checked by every caller), so the
            // CPU has AVX-512F and AVX2.
            return unsafe { run_avx512(job) };
        }
        if L >= 4 && isa >= Isa::Avx2 {
            // SAFETY: as above, the CPU has AVX2.
            return unsafe { run_avx2(job) };
        }
    }
    let _ = isa;
    if L == 1 {
        return job.run::<f64>();
    }
    job.run::<Portable<L>>()
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
unsafe fn run_avx2<const L: usize, J: Job<L>>(job: J) -> J::Out {
    job.run::<Portable<L>>()
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,avx512f")]
unsafe fn run_avx512<const L: usize, J: Job<L>>(job: J) -> J::Out {
    job.run::<Avx512>()
}

// ----------------------------------------------------------- advancing ----

struct Advance<'a, const L: usize> {
    batch: &'a HelicalBatch<L>,
    x: &'a mut BatchState<L>,
    steps: usize,
}

impl<const L: usize> Job<L> for Advance<'_, L> {
    type Out = ();
    #[inline(always)]
    fn run<V: Lanes<L>>(self) {
        let b = self.batch;
        let c = b.coef.map(|v| V::load(v));
        let mut x = load_state::<L, V>(self.x);
        let per = b.grid_len() / 2;
        let mut n = 0;
        for _ in 0..self.steps {
            b.step_v(&c, n, &mut x);
            n += 1;
            if n == per {
                n = 0;
            }
        }
        store_state(&x, self.x);
    }
}

/// Advance `steps` lock-step RK4 steps from step 0 with the detected
/// instruction set; used by the timing example and the benches.
pub fn advance_batch<const L: usize>(batch: &HelicalBatch<L>, x: &mut BatchState<L>, steps: usize) {
    dispatch(Isa::detected(), Advance { batch, x, steps });
}

/// As [`advance_batch`] with a given instruction set (error if this CPU
/// lacks it).
pub fn advance_batch_with<const L: usize>(
    isa: Isa,
    batch: &HelicalBatch<L>,
    x: &mut BatchState<L>,
    steps: usize,
) -> Result<()> {
    check_isa(isa)?;
    dispatch(isa, Advance { batch, x, steps });
    Ok(())
}

// ------------------------------------------------------------ sampling ----

/// What the recorded periods observe after every step: the relative
/// deflection's extremes and (first period) the state's extremes.
struct Observe<const L: usize> {
    lo: [f64; L],
    hi: [f64; L],
    smin: BatchState<L>,
    smax: BatchState<L>,
    track_state: bool,
}

/// Steps `from..to` of one mesh period (at most a period); the
/// target-feature entry points stay this small (the per-period
/// bookkeeping and the looks at the cancel flag are outside), which keeps
/// the compiler inlining every lane operation into them.
struct Periods<'a, const L: usize> {
    batch: &'a HelicalBatch<L>,
    x: &'a mut BatchState<L>,
    from: usize,
    to: usize,
    observe: Option<&'a mut Observe<L>>,
}

impl<const L: usize> Job<L> for Periods<'_, L> {
    type Out = ();
    #[inline(always)]
    fn run<V: Lanes<L>>(self) {
        let b = self.batch;
        let c = b.coef.map(|v| V::load(v));
        let per = b.grid_len() / 2;
        let mut x = load_state::<L, V>(self.x);
        let steps = self.from..self.to.min(per);
        match self.observe {
            None => {
                for n in steps {
                    b.step_v(&c, n, &mut x);
                }
            }
            Some(o) => {
                let (mut lo, mut hi) = (V::load(&o.lo), V::load(&o.hi));
                let (mut smin, mut smax) = (load_state::<L, V>(&o.smin), load_state::<L, V>(&o.smax));
                for n in steps {
                    b.step_v(&c, n, &mut x);
                    let next = if n + 1 == per { 0 } else { n + 1 };
                    let d = b.deflection_v(&c, 2 * next, &x);
                    lo = lo.min(d);
                    hi = hi.max(d);
                    if o.track_state {
                        for i in 0..14 {
                            smin[i] = smin[i].min(x[i]);
                            smax[i] = smax[i].max(x[i]);
                        }
                    }
                }
                lo.store(&mut o.lo);
                hi.store(&mut o.hi);
                store_state(&smin, &mut o.smin);
                store_state(&smax, &mut o.smax);
            }
        }
        store_state(&x, self.x);
    }
}

fn all_finite<const L: usize>(x: &BatchState<L>) -> bool {
    x.iter().all(|r| r.iter().all(|v| v.is_finite()))
}

/// Relative deflection `delta_n - e` of every lane at step 0, in the
/// summation order of `HelicalPairSystem::relative_deflection_m`.
fn section_deflection<const L: usize>(b: &HelicalBatch<L>, x: &BatchState<L>) -> [f64; L] {
    let c = b.coef.map(Portable::<L>::load);
    let mut d = [0.0; L];
    b.deflection_v(&c, 0, &load_state::<L, Portable<L>>(x)).store(&mut d);
    d
}

fn sample<const L: usize>(
    isa: Isa,
    b: &HelicalBatch<L>,
    starts: &[[f64; 14]; L],
    transient_periods: usize,
    recorded_periods: usize,
) -> Result<[PoincareRecord<14>; L]> {
    if recorded_periods == 0 {
        return Err(Error::config("recorded_periods", 0, "must be at least 1"));
    }
    let per = b.grid_len() / 2;
    let mut x = pack(starts);
    let every = crate::cancel::CHECK_EVERY_STEPS;
    for p in 0..transient_periods {
        for from in (0..per).step_by(every) {
            crate::cancel::check()?;
            let job = Periods {
                batch: b,
                x: &mut x,
                from,
                to: from + every,
                observe: None,
            };
            dispatch(isa, job);
        }
        if !all_finite(&x) {
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
    let mut o = Observe {
        lo: [f64::INFINITY; L],
        hi: [f64::NEG_INFINITY; L],
        smin: x,
        smax: x,
        track_state: true,
    };
    for p in 0..recorded_periods {
        let d0 = section_deflection(b, &x);
        for l in 0..L {
            points[l].push(lane(&x, l));
            obs[l].push(d0[l]);
        }
        o.track_state = p == 0;
        for from in (0..per).step_by(every) {
            crate::cancel::check()?;
            let job = Periods {
                batch: b,
                x: &mut x,
                from,
                to: from + every,
                observe: Some(&mut o),
            };
            dispatch(isa, job);
        }
        if !all_finite(&x) {
            return Err(Error::convergence("rk4 (state diverged)", p * per, f64::INFINITY, 0.0));
        }
    }
    let mut points = points.into_iter();
    let mut obs = obs.into_iter();
    Ok(std::array::from_fn(|l| PoincareRecord {
        points: points.next().unwrap_or_default(),
        observable: obs.next().unwrap_or_default(),
        observable_min: o.lo[l],
        observable_max: o.hi[l],
        state_range: std::array::from_fn(|i| o.smax[i][l] - o.smin[i][l]),
        final_state: lane(&x, l),
    }))
}

/// Lock-step version of [`super::poincare::poincare_sample`] with the
/// relative deflection as observable; one record per lane, bitwise equal
/// to the scalar records. Runs with the detected instruction set
/// ([`Isa::detected`]): AVX-512F for 8 lanes, AVX2 for 4 or 8, SSE2 for 2
/// on x86-64; portable code otherwise.
pub fn poincare_sample_batch<const L: usize>(
    batch: &HelicalBatch<L>,
    starts: &[[f64; 14]; L],
    transient_periods: usize,
    recorded_periods: usize,
) -> Result<[PoincareRecord<14>; L]> {
    poincare_sample_batch_with(Isa::detected(), batch, starts, transient_periods, recorded_periods)
}

/// As [`poincare_sample_batch`] with a given instruction set (error if this
/// CPU lacks it).
pub fn poincare_sample_batch_with<const L: usize>(
    isa: Isa,
    batch: &HelicalBatch<L>,
    starts: &[[f64; 14]; L],
    transient_periods: usize,
    recorded_periods: usize,
) -> Result<[PoincareRecord<14>; L]> {
    check_isa(isa)?;
    sample(isa, batch, starts, transient_periods, recorded_periods)
}

fn sample_group<const L: usize>(
    systems: &[HelicalPairSystem],
    starts: &[[f64; 14]],
    transient_periods: usize,
    recorded_periods: usize,
) -> Result<Vec<PoincareRecord<14>>> {
    let pick = |l: usize| if l < systems.len() { l } else { 0 };
    let batch = HelicalBatch::<L>::new(std::array::from_fn(|l| &systems[pick(l)]))?;
    let st: [[f64; 14]; L] = std::array::from_fn(|l| starts[pick(l)]);
    let recs = poincare_sample_batch(&batch, &st, transient_periods, recorded_periods)?;
    Ok(recs.into_iter().take(systems.len()).collect())
}

/// Poincare records of many systems from their starts, in lock-step groups
/// of at most [`Isa::max_lanes`] of the detected instruction set; each
/// group runs on the narrowest batch (1, 2, 4 or 8 lanes) that holds it,
/// padded by repeating its first lane. Records equal
/// the one-by-one scalar runs bitwise.
pub fn poincare_many(
    systems: &[HelicalPairSystem],
    starts: &[[f64; 14]],
    transient_periods: usize,
    recorded_periods: usize,
) -> Result<Vec<PoincareRecord<14>>> {
    if systems.len() != starts.len() {
        return Err(Error::config("starts", starts.len(), "need one start per system"));
    }
    let width = Isa::detected().max_lanes().min(LANES);
    let mut out = Vec::with_capacity(systems.len());
    for (sys, x0) in systems.chunks(width).zip(starts.chunks(width)) {
        let recs = match sys.len() {
            1 => sample_group::<1>(sys, x0, transient_periods, recorded_periods)?,
            2 => sample_group::<2>(sys, x0, transient_periods, recorded_periods)?,
            3 | 4 => sample_group::<4>(sys, x0, transient_periods, recorded_periods)?,
            _ => sample_group::<8>(sys, x0, transient_periods, recorded_periods)?,
        };
        out.extend(recs);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::gear_model::{HelicalPair, HelicalPairParams, MeshDamping};
    use crate::dynamics::integrate::rk4_step_generic;
    use crate::dynamics::poincare::poincare_sample;
    use crate::dynamics::GridOde;

    fn impacting() -> (HelicalPair, HelicalPair) {
        let mut p = HelicalPairParams::seed_a();
        p.input_torque_n_m = 10.0;
        for e in &mut p.transmission_error_m {
            *e *= 5.0;
        }
        let pair = HelicalPair::new(p.clone()).unwrap();
        p.mesh_damping = MeshDamping::Always;
        let pair2 = HelicalPair::new(p).unwrap().with_bearing_stiffness(1.5e8, 7e7).unwrap();
        (pair, pair2)
    }

    #[test]
    fn batch_lanes_are_bitwise_identical_to_scalar_runs_on_every_isa() {
        let (pair, pair2) = impacting();
        let speeds = [7000.0, 9000.0, 13000.0, 8000.0, 11000.0, 12000.0, 15000.0, 16000.0];
        let sys: Vec<HelicalPairSystem> = speeds
            .iter()
            .enumerate()
            .map(|(l, &s)| if l % 2 == 0 { &pair } else { &pair2 }.system(s, 48).unwrap())
            .collect();
        let starts: Vec<[f64; 14]> = (0..8)
            .map(|l| if l % 2 == 0 { &pair } else { &pair2 }.static_state().unwrap())
            .collect();
        let scalar: Vec<_> = (0..8)
            .map(|l| poincare_sample(&sys[l], &starts[l], 20, 5, |n, x| sys[l].relative_deflection_m(n, x)).unwrap())
            .collect();
        for isa in Isa::available() {
            let b8 = HelicalBatch::<8>::new(std::array::from_fn(|l| &sys[l])).unwrap();
            let r8 = poincare_sample_batch_with(isa, &b8, &std::array::from_fn(|l| starts[l]), 20, 5).unwrap();
            let b4 = HelicalBatch::<4>::new(std::array::from_fn(|l| &sys[l + 4])).unwrap();
            let r4 = poincare_sample_batch_with(isa, &b4, &std::array::from_fn(|l| starts[l + 4]), 20, 5).unwrap();
            let b2 = HelicalBatch::<2>::new([&sys[1], &sys[2]]).unwrap();
            let r2 = poincare_sample_batch_with(isa, &b2, &[starts[1], starts[2]], 20, 5).unwrap();
            let b3 = HelicalBatch::<3>::new([&sys[0], &sys[3], &sys[5]]).unwrap();
            let r3 = poincare_sample_batch_with(isa, &b3, &[starts[0], starts[3], starts[5]], 20, 5).unwrap();
            for l in 0..8 {
                assert_eq!(r8[l], scalar[l], "{isa:?} 8 lanes, lane {l}");
            }
            for l in 0..4 {
                assert_eq!(r4[l], scalar[l + 4], "{isa:?} 4 lanes, lane {l}");
            }
            assert_eq!(r2[0], scalar[1], "{isa:?}");
            assert_eq!(r2[1], scalar[2], "{isa:?}");
            assert_eq!(
                [&r3[0], &r3[1], &r3[2]],
                [&scalar[0], &scalar[3], &scalar[5]],
                "{isa:?}"
            );
        }
        // Grouping through poincare_many (7 systems: one 8-lane group padded).
        let many = poincare_many(&sys[..7], &starts[..7], 20, 5).unwrap();
        assert_eq!(many, scalar[..7].to_vec());
        let other = pair.system(7000.0, 64).unwrap();
        assert!(HelicalBatch::new([&sys[0], &other]).is_err());
    }

    #[test]
    fn kernel_step_agrees_with_the_reference_rk4_to_round_off() {
        // The rearranged kernel against RK4 from four right-hand-side
        // evaluations, one step at a time from the same state along 30 mesh
        // periods of impacting orbits: every step agrees to round-off.
        let (pair, pair2) = impacting();
        for (p, speed) in [(&pair, 9000.0), (&pair2, 13000.0)] {
            let sys = p.system(speed, 64).unwrap();
            let mut x = p.static_state().unwrap();
            let mut other = x;
            other[13] += 1e-3;
            let mut worst: f64 = 0.0;
            for n in 0..64 * 30 {
                let mut y = x;
                rk4_step_generic(&sys, n % 64, &mut y);
                let (mut u, mut v) = (x, other);
                sys.rk4_step_pair(n % 64, &mut u, &mut v);
                sys.rk4_step(n % 64, &mut x);
                sys.rk4_step(n % 64, &mut other);
                // Pair steps equal single steps bitwise.
                assert_eq!((u, v), (x, other));
                for i in 0..14 {
                    // Relative to the state's scale (positions ~ b, velocities ~ b / h).
                    let scale = if i < 7 { 50e-6 } else { 50e-6 / sys.step() };
                    worst = worst.max((x[i] - y[i]).abs() / scale);
                }
            }
            assert!(worst < 1e-12, "{worst:e}");
        }
    }
}
