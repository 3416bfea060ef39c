//! Speed sweeps (bifurcation diagrams) and regime maps.
//!
//! - `Up` / `Down`: continuation, the final state of one speed starts the
//!   next (A, Figs. 14-15: accelerating and decelerating sweeps); sequential.
//! - `Independent`: every speed starts from the model's static state;
//!   speeds run in parallel (rayon).
//!
//! Independent sweeps (stiffness cases x directions) run in parallel with
//! [`sweep_many`]; [`regime_map`] covers torque x speed x transmission-error
//! scale. Every speed's result depends only on its inputs (and, for
//! continuation, on the previous speed in a fixed order), so results do not
//! depend on the number of threads.
//!
//! Progress/cancellation: `progress(done, total)` is called between chunks
//! (after each speed for continuation sweeps, after each chunk of
//! [`CHUNK`] speeds otherwise, and with `done` unchanged before each batch
//! of [`LANES`] parallel speeds, so that a stop is seen quickly); returning
//! `false` stops the work with `Error::Interrupted`. Inside a speed, the
//! integration loops look at the caller's cancel flag (`crate::cancel`,
//! handed to every worker thread) every
//! [`crate::cancel::CHECK_EVERY_STEPS`] steps, so a stop also ends a
//! single long speed within a fraction of a second.
//!
//! Bounds: every sweep refuses more than [`MAX_STEPS_PER_PERIOD`]
//! steps per mesh period and more than [`MAX_PERIODS`] periods in any
//! one count (transient, recorded, Lyapunov, and their caps).
//!
//! Partial results: [`sweep_partial`], [`sweep_many_partial`] and
//! [`regime_map_partial`] keep every finished speed when a speed fails or
//! the work is stopped, and name the failed speeds. A continuation sweep
//! stops at its first failed speed (the next speed would have to start
//! from it); an independent sweep and a regime map run every other speed
//! and report every failure. [`sweep`], [`sweep_many`] and [`regime_map`]
//! return the first failure (in sweep order) instead.

use super::batch::{self, LANES};
use super::classify::{
    chaos_verdict, impact_regime, jumps_and_transitions, section_verdict, zero_one_test, ChaosEvidence, ClassifyConfig,
    ImpactRegime, Motion, Transition, MIN_ZERO_ONE_POINTS,
};
use super::gear_model::{BacklashOscillator, BacklashOscillatorSystem, HelicalPair, HelicalPairSystem};
use super::lyapunov::{largest_lyapunov_blocks, LyapunovBlocks};
use super::ode::GridOde;
use super::poincare::{poincare_sample, PoincareRecord};
use crate::error::positive;
use crate::{Error, Result};
use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

/// Speeds per progress chunk in parallel runs.
pub const CHUNK: usize = 32;

/// Progress hook: `(done, total) -> keep going?`.
pub type Progress<'a> = &'a (dyn Fn(usize, usize) -> bool + Sync);

/// A model that can be tabulated at a "speed" (rpm for the gear pair, the
/// frequency ratio for the 1-DOF oscillator).
pub trait SweepModel<const N: usize>: Sync {
    /// The tabulated system.
    type System: GridOde<N> + Send;
    /// Build the system at `speed`.
    fn system_at(&self, speed: f64, steps_per_period: usize) -> Result<Self::System>;
    /// Relative mesh deflection (dynamic transmission error) at step `n`.
    fn deflection(&self, sys: &Self::System, n: usize, x: &[f64; N]) -> f64;
    /// Half backlash in the unit of [`SweepModel::deflection`].
    fn half_backlash(&self) -> f64;
    /// Static (start) state at `speed`.
    fn initial_state(&self, speed: f64) -> Result<[f64; N]>;

    /// Observed Poincare quantities of a section point `x` (state at step 0),
    /// in the unit of [`SweepModel::deflection`]: the only quantities the
    /// period test compares. Default: the deflection alone.
    fn section_outputs(&self, sys: &Self::System, x: &[f64; N]) -> Vec<f64> {
        vec![self.deflection(sys, 0, x)]
    }

    /// Poincare records of several `(model, speed, start)` runs with the
    /// deflection as observable. The default runs them one by one; models
    /// with a lock-step batch integrator override it (results must equal the
    /// one-by-one runs exactly).
    fn poincare_many(
        models: &[&Self],
        speeds: &[f64],
        starts: &[[f64; N]],
        cfg: &SweepConfig,
    ) -> Result<Vec<PoincareRecord<N>>>
    where
        Self: Sized,
    {
        models
            .iter()
            .zip(speeds)
            .zip(starts)
            .map(|((m, &s), x0)| record_speed(*m, s, x0, cfg))
            .collect()
    }
}

/// Sweep direction.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum SweepDirection {
    /// Continuation with increasing speed.
    Up,
    /// Continuation with decreasing speed.
    Down,
    /// Every speed from the static state.
    Independent,
}

/// Sweep settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SweepConfig {
    /// Mesh periods discarded at each speed.
    pub transient_periods: usize,
    /// Mesh periods sampled at each speed.
    pub recorded_periods: usize,
    /// RK4 steps per mesh period.
    pub steps_per_period: usize,
    /// Periods over which a Lyapunov exponent is measured at non-periodic
    /// speeds (0: none, then the 0-1 test decides).
    pub lyapunov_periods: usize,
    /// Classifier settings.
    pub classify: ClassifyConfig,
    /// Jump threshold relative to the amplitude.
    pub jump_rel: f64,
    /// Jump threshold relative to the median local step.
    pub jump_trend_factor: f64,
    /// Cap on the adaptive transient \[mesh periods\]: while the section
    /// points are still converging the transient is extended by
    /// `recorded_periods` at a time, up to this total; points still
    /// converging at the cap are reported unsettled. A cap at or below
    /// `transient_periods` disables the extension.
    pub max_transient_periods: usize,
    /// Most periods of the Lyapunov estimate \[mesh periods\]: it runs at
    /// least `lyapunov_periods` and is extended block by block while its
    /// sign against the threshold is within its error.
    pub lyapunov_max_periods: usize,
    /// Periods per block of the Lyapunov estimate (the batch-means unit of
    /// its standard error) \[mesh periods\].
    pub lyapunov_block_periods: usize,
    /// Neighbouring steps on each side whose median sets the local trend of
    /// the jump test \[speeds\].
    pub jump_window: usize,
}

impl Default for SweepConfig {
    /// The seed diagram settings: 300 transient + 100 recorded periods, 64
    /// steps per period, transient extended up to 1500 periods while the
    /// section is converging; Lyapunov check of non-periodic speeds over
    /// 100 periods (blocks of 10), extended up to 400 while undecided.
    fn default() -> Self {
        SweepConfig {
            transient_periods: 300,
            recorded_periods: 100,
            steps_per_period: 64,
            lyapunov_periods: 100,
            classify: ClassifyConfig::default(),
            jump_rel: 0.2,
            jump_trend_factor: 5.0,
            max_transient_periods: 1500,
            lyapunov_max_periods: 400,
            lyapunov_block_periods: 10,
            jump_window: 5,
        }
    }
}

/// Result at one speed.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct SpeedPoint {
    /// Speed (rpm, or frequency ratio for the 1-DOF model).
    pub speed: f64,
    /// Relative deflection at each Poincare section point (bifurcation diagram ordinates).
    pub poincare_deflection: Vec<f64>,
    /// Minimum relative deflection over the recorded periods.
    pub deflection_min: f64,
    /// Maximum relative deflection over the recorded periods.
    pub deflection_max: f64,
    /// Motion class.
    pub motion: Motion,
    /// Contact regime.
    pub impact: ImpactRegime,
    /// Largest Lyapunov exponent per mesh period, when computed.
    pub lyapunov_per_period: Option<f64>,
    /// Standard error of `lyapunov_per_period` (batch means) \[1/period\].
    pub lyapunov_stderr_per_period: Option<f64>,
    /// 0-1 test K of the section deflection, when computed \[-\].
    pub zero_one_k: Option<f64>,
    /// Transient actually run before the recorded window \[mesh periods\].
    pub transient_periods: usize,
    /// False when the section points were still converging at the
    /// transient cap (the label is then provisional).
    pub settled: bool,
}

impl SpeedPoint {
    /// Peak-to-peak half amplitude of the relative deflection.
    pub fn amplitude(&self) -> f64 {
        0.5 * (self.deflection_max - self.deflection_min)
    }
}

/// A sweep's result, points in ascending speed order.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct SweepResult {
    /// Direction swept.
    pub direction: SweepDirection,
    /// One point per speed, ascending speed.
    pub points: Vec<SpeedPoint>,
    /// Indices i with a jump between points i and i+1 (same non-chaotic
    /// regime family on both sides).
    pub jumps: Vec<usize>,
    /// Changes of regime family between neighbouring points (entries into
    /// and exits from chaos among them), with their size.
    pub transitions: Vec<Transition>,
    /// Indices of the points whose section did not settle within
    /// `max_transient_periods`.
    pub unsettled: Vec<usize>,
}

/// A speed whose run failed.
#[derive(Debug, Clone, PartialEq)]
pub struct SpeedFailure {
    /// Index of the speed in the (ascending) requested speeds.
    pub index: usize,
    /// The speed.
    pub speed: f64,
    /// Why it failed.
    pub error: Error,
}

/// What a sweep finished, and which speeds failed or were never run.
#[derive(Debug, Clone, PartialEq)]
pub struct PartialSweep {
    /// The finished points, ascending speed. A point equals the same speed
    /// of a complete run; `jumps` and `transitions` only join speeds that
    /// are neighbours in the requested speeds.
    pub result: SweepResult,
    /// Failed speeds, in sweep order (at most one for a continuation sweep).
    pub failures: Vec<SpeedFailure>,
    /// Indices (ascending) of the speeds never run: past the failed speed
    /// of a continuation sweep, or left when the work was stopped.
    pub not_run: Vec<usize>,
    /// The progress hook stopped the work before every speed ran.
    pub interrupted: bool,
}

impl PartialSweep {
    /// Every speed finished.
    pub fn is_complete(&self) -> bool {
        self.failures.is_empty() && !self.interrupted
    }

    /// The complete result, or the first failure in sweep order (then
    /// `Error::Interrupted` when stopped).
    pub fn into_result(self) -> Result<SweepResult> {
        if let Some(f) = self.failures.into_iter().next() {
            return Err(f.error);
        }
        if self.interrupted {
            return Err(Error::Interrupted);
        }
        Ok(self.result)
    }
}

/// Most RK4 steps per mesh period a sweep takes. The step rule (a step
/// within 0.1 x the shortest natural period) needs about 270,000 / rpm
/// steps for seed A's pair, so this covers speeds down to a few rpm; past
/// the need, RK4's error falls as the fourth power of the step and more
/// steps only add round-off and time.
pub const MAX_STEPS_PER_PERIOD: usize = 100_000;

/// Most mesh periods in any one count of a sweep (transient, recorded,
/// Lyapunov, and the caps of their adaptive extensions). The default
/// classifier settles within 1,500 periods and decides a Lyapunov
/// exponent within 400; every recorded period is one Poincare sample of
/// the result.
pub const MAX_PERIODS: usize = 100_000;

fn check_config(cfg: &SweepConfig) -> Result<()> {
    if cfg.steps_per_period > MAX_STEPS_PER_PERIOD {
        return Err(Error::config(
            "steps_per_period",
            cfg.steps_per_period,
            format!("must be at most {MAX_STEPS_PER_PERIOD}"),
        ));
    }
    for (name, n) in [
        ("transient_periods", cfg.transient_periods),
        ("recorded_periods", cfg.recorded_periods),
        ("lyapunov_periods", cfg.lyapunov_periods),
        ("max_transient_periods", cfg.max_transient_periods),
        ("lyapunov_max_periods", cfg.lyapunov_max_periods),
    ] {
        if n > MAX_PERIODS {
            return Err(Error::config(name, n, format!("must be at most {MAX_PERIODS}")));
        }
    }
    if cfg.recorded_periods < 2 {
        return Err(Error::config(
            "recorded_periods",
            cfg.recorded_periods,
            "must be at least 2",
        ));
    }
    cfg.classify.check()?;
    positive("jump_rel", cfg.jump_rel)?;
    positive("jump_trend_factor", cfg.jump_trend_factor)?;
    if cfg.lyapunov_block_periods == 0 {
        return Err(Error::config("lyapunov_block_periods", 0, "must be at least 1"));
    }
    Ok(())
}

fn check_speeds(speeds: &[f64]) -> Result<()> {
    if speeds.is_empty() {
        return Err(Error::config("speeds", "[]", "need at least one speed"));
    }
    for &s in speeds {
        positive("speeds", s)?;
    }
    if speeds.windows(2).any(|w| w[1] <= w[0]) {
        return Err(Error::config("speeds", "unsorted", "must be strictly ascending"));
    }
    Ok(())
}

/// Poincare record of one speed from `x0` (scalar RK4).
pub fn record_speed<const N: usize, M: SweepModel<N>>(
    model: &M,
    speed: f64,
    x0: &[f64; N],
    cfg: &SweepConfig,
) -> Result<PoincareRecord<N>> {
    let sys = model.system_at(speed, cfg.steps_per_period)?;
    poincare_sample(&sys, x0, cfg.transient_periods, cfg.recorded_periods, |n, x| {
        model.deflection(&sys, n, x)
    })
}

/// Classify a recorded speed (see [`settle_and_finish`]).
pub fn finish_point<const N: usize, M: SweepModel<N>>(
    model: &M,
    speed: f64,
    rec: PoincareRecord<N>,
    cfg: &SweepConfig,
) -> Result<SpeedPoint> {
    Ok(settle_and_finish(model, speed, rec, cfg)?.0)
}

/// Settle and classify a recorded speed; returns the point and the final
/// state (the start of the next speed in a continuation sweep).
///
/// 1. Period test and settling test on the observed section quantities
///    ([`SweepModel::section_outputs`]) against the orbit size (peak-to-peak
///    deflection of the window). While the points are still converging and
///    the cap `max_transient_periods` allows, the window becomes transient
///    and a new window of `recorded_periods` is run (scalar RK4, bitwise
///    equal to the lock-step batches).
/// 2. Non-periodic points: the largest Lyapunov exponent from the final
///    state with its standard error (blocks of `lyapunov_block_periods`,
///    at least `lyapunov_periods`, extended up to `lyapunov_max_periods`
///    while undecided), and the 0-1 test on the section deflection of the
///    window and the Lyapunov run; [`chaos_verdict`] decides.
pub fn settle_and_finish<const N: usize, M: SweepModel<N>>(
    model: &M,
    speed: f64,
    rec: PoincareRecord<N>,
    cfg: &SweepConfig,
) -> Result<(SpeedPoint, [f64; N])> {
    let sys = model.system_at(speed, cfg.steps_per_period)?;
    let mut rec = rec;
    let mut transient = cfg.transient_periods;
    let (verdict, settled) = loop {
        let outs: Vec<Vec<f64>> = rec.points.iter().map(|x| model.section_outputs(&sys, x)).collect();
        let v = section_verdict(&outs, rec.observable_max - rec.observable_min, &cfg.classify);
        if !v.converging {
            break (v, true);
        }
        if transient + cfg.recorded_periods > cfg.max_transient_periods {
            break (v, false);
        }
        transient += cfg.recorded_periods;
        rec = poincare_sample(&sys, &rec.final_state, 0, cfg.recorded_periods, |n, x| {
            model.deflection(&sys, n, x)
        })?;
    };
    let mut ev = ChaosEvidence::default();
    let motion = match verdict.period {
        Some(n) => Motion::Periodic(n),
        None => {
            let mut series = rec.observable.clone();
            if cfg.lyapunov_periods > 0 {
                let period = sys.step() * cfg.steps_per_period as f64;
                let block = cfg.lyapunov_block_periods.min((cfg.lyapunov_periods / 2).max(1));
                let min_blocks = (cfg.lyapunov_periods / block).max(2);
                let lcfg = LyapunovBlocks {
                    renorm_steps: cfg.steps_per_period,
                    renorms_per_block: block,
                    min_blocks,
                    max_blocks: (cfg.lyapunov_max_periods / block).max(min_blocks),
                    separation: 1e-6,
                    sigmas: cfg.classify.lyapunov_sigmas,
                    threshold: cfg.classify.lyapunov_threshold_per_period / period,
                };
                let scale = rec.state_range.map(|s| if s > 0.0 { s } else { 1.0 });
                let est = largest_lyapunov_blocks(&sys, &rec.final_state, 0, &scale, &lcfg, |x| {
                    series.push(model.deflection(&sys, 0, x))
                })?;
                ev.lyapunov_per_period = Some(est.exponent * period);
                ev.lyapunov_stderr_per_period = Some(est.standard_error * period);
            }
            if series.len() >= MIN_ZERO_ONE_POINTS {
                ev.zero_one_k = Some(zero_one_test(&series));
            }
            chaos_verdict(&ev, &cfg.classify)
        }
    };
    let xf = rec.final_state;
    Ok((
        SpeedPoint {
            speed,
            impact: impact_regime(rec.observable_min, rec.observable_max, model.half_backlash()),
            poincare_deflection: rec.observable,
            deflection_min: rec.observable_min,
            deflection_max: rec.observable_max,
            motion,
            lyapunov_per_period: ev.lyapunov_per_period,
            lyapunov_stderr_per_period: ev.lyapunov_stderr_per_period,
            zero_one_k: ev.zero_one_k,
            transient_periods: transient,
            settled,
        },
        xf,
    ))
}

/// Simulate one speed from `x0`; returns the point and the final state.
pub fn run_speed<const N: usize, M: SweepModel<N>>(
    model: &M,
    speed: f64,
    x0: &[f64; N],
    cfg: &SweepConfig,
) -> Result<(SpeedPoint, [f64; N])> {
    let rec = record_speed(model, speed, x0, cfg)?;
    settle_and_finish(model, speed, rec, cfg)
}

fn finish(direction: SweepDirection, points: Vec<SpeedPoint>, cfg: &SweepConfig) -> SweepResult {
    let motions: Vec<Motion> = points.iter().map(|p| p.motion).collect();
    let lo: Vec<f64> = points.iter().map(|p| p.deflection_min).collect();
    let hi: Vec<f64> = points.iter().map(|p| p.deflection_max).collect();
    let (jumps, transitions) =
        jumps_and_transitions(&motions, &lo, &hi, cfg.jump_rel, cfg.jump_trend_factor, cfg.jump_window);
    let unsettled = (0..points.len()).filter(|&i| !points[i].settled).collect();
    SweepResult {
        direction,
        points,
        jumps,
        transitions,
        unsettled,
    }
}

/// Assemble a [`PartialSweep`] from per-speed slots (`None`: not finished).
fn finish_slots(
    direction: SweepDirection,
    slots: Vec<Option<SpeedPoint>>,
    mut failures: Vec<SpeedFailure>,
    interrupted: bool,
    cfg: &SweepConfig,
) -> PartialSweep {
    let failed: Vec<usize> = failures.iter().map(|f| f.index).collect();
    let not_run: Vec<usize> = (0..slots.len())
        .filter(|&i| slots[i].is_none() && !failed.contains(&i))
        .collect();
    let index: Vec<usize> = (0..slots.len()).filter(|&i| slots[i].is_some()).collect();
    let mut result = finish(direction, slots.into_iter().flatten().collect(), cfg);
    if index.len() < index.last().map_or(0, |&l| l + 1) {
        let adjacent = |k: usize| index[k + 1] == index[k] + 1;
        result.jumps.retain(|&k| adjacent(k));
        result.transitions.retain(|t| adjacent(t.index));
    }
    if direction == SweepDirection::Down {
        failures.sort_by_key(|f| std::cmp::Reverse(f.index));
    } else {
        failures.sort_by_key(|f| f.index);
    }
    PartialSweep {
        result,
        failures,
        interrupted: interrupted && !not_run.is_empty(),
        not_run,
    }
}

/// Record and classify independent `(model, speed)` runs, each from its
/// static state, as one lock-step batch. When the batch fails, every run
/// is repeated alone (the batch equals the one-by-one runs exactly), so
/// only the runs that fail on their own are reported.
fn independent_points<const N: usize, M: SweepModel<N>>(
    runs: &[(&M, f64)],
    cfg: &SweepConfig,
) -> Vec<Result<SpeedPoint>> {
    let batch = (|| {
        let starts = runs
            .iter()
            .map(|(m, s)| m.initial_state(*s))
            .collect::<Result<Vec<_>>>()?;
        let models: Vec<&M> = runs.iter().map(|r| r.0).collect();
        let speeds: Vec<f64> = runs.iter().map(|r| r.1).collect();
        M::poincare_many(&models, &speeds, &starts, cfg)
    })();
    match batch {
        Ok(recs) => runs
            .iter()
            .zip(recs)
            .map(|(&(m, s), r)| finish_point(m, s, r, cfg))
            .collect(),
        Err(Error::Interrupted) => vec![Err(Error::Interrupted); runs.len()],
        Err(_) => runs
            .iter()
            .map(|&(m, s)| {
                let x0 = m.initial_state(s)?;
                let rec = record_speed(m, s, &x0, cfg)?;
                finish_point(m, s, rec, cfg)
            })
            .collect(),
    }
}

/// Shared progress counter for nested parallel work.
struct Counter<'a> {
    done: AtomicUsize,
    total: usize,
    cancelled: AtomicBool,
    progress: Progress<'a>,
}

impl Counter<'_> {
    /// Ask the progress hook (without new progress) whether to go on:
    /// parallel work calls this before each batch of lanes, so a stop is
    /// seen within one batch instead of one chunk.
    fn keep_going(&self) -> Result<()> {
        if self.cancelled.load(Ordering::Relaxed) || !(self.progress)(self.done.load(Ordering::Relaxed), self.total) {
            self.cancelled.store(true, Ordering::Relaxed);
            return Err(Error::Interrupted);
        }
        Ok(())
    }

    fn tick(&self, n: usize) -> Result<()> {
        if self.cancelled.load(Ordering::Relaxed) {
            return Err(Error::Interrupted);
        }
        let done = self.done.fetch_add(n, Ordering::Relaxed) + n;
        if !(self.progress)(done, self.total) {
            self.cancelled.store(true, Ordering::Relaxed);
            return Err(Error::Interrupted);
        }
        Ok(())
    }
}

fn sweep_counted<const N: usize, M: SweepModel<N>>(
    model: &M,
    speeds: &[f64],
    direction: SweepDirection,
    cfg: &SweepConfig,
    counter: &Counter,
) -> PartialSweep {
    let n = speeds.len();
    let mut slots: Vec<Option<SpeedPoint>> = vec![None; n];
    let mut failures = Vec::new();
    let mut interrupted = false;
    let flag = crate::cancel::current();
    match direction {
        SweepDirection::Independent => {
            let all: Vec<usize> = (0..n).collect();
            for chunk in all.chunks(CHUNK) {
                let part: Vec<Vec<(usize, Result<SpeedPoint>)>> = chunk
                    .par_chunks(LANES)
                    .map(|ii| {
                        if counter.keep_going().is_err() {
                            return Vec::new();
                        }
                        let runs: Vec<(&M, f64)> = ii.iter().map(|&i| (model, speeds[i])).collect();
                        let points = crate::cancel::with_current(flag.as_ref(), || independent_points(&runs, cfg));
                        ii.iter().copied().zip(points).collect()
                    })
                    .collect();
                for (i, r) in part.into_iter().flatten() {
                    match r {
                        Ok(p) => slots[i] = Some(p),
                        Err(Error::Interrupted) => interrupted = true,
                        Err(error) => failures.push(SpeedFailure {
                            index: i,
                            speed: speeds[i],
                            error,
                        }),
                    }
                }
                if interrupted || counter.tick(chunk.len()).is_err() {
                    interrupted = true;
                    break;
                }
            }
        }
        SweepDirection::Up | SweepDirection::Down => {
            let order: Vec<usize> = if direction == SweepDirection::Up {
                (0..n).collect()
            } else {
                (0..n).rev().collect()
            };
            let mut x = model.initial_state(speeds[order[0]]);
            for &i in &order {
                let run = x.and_then(|x0| run_speed(model, speeds[i], &x0, cfg));
                match run {
                    Ok((p, xf)) => {
                        slots[i] = Some(p);
                        x = Ok(xf);
                    }
                    Err(Error::Interrupted) => {
                        interrupted = true;
                        break;
                    }
                    Err(error) => {
                        failures.push(SpeedFailure {
                            index: i,
                            speed: speeds[i],
                            error,
                        });
                        break;
                    }
                }
                if counter.tick(1).is_err() {
                    interrupted = true;
                    break;
                }
            }
        }
    }
    finish_slots(direction, slots, failures, interrupted, cfg)
}

/// Continuation sweeps of several jobs in lock-step (one batch per speed
/// step). A job whose speed fails leaves the batch (its later speeds are
/// not run); when a batch fails, its runs are repeated one by one (bitwise
/// equal) so the other jobs go on.
fn continuation_group<const N: usize, M: SweepModel<N>>(
    jobs: &[(&M, SweepDirection)],
    speeds: &[f64],
    cfg: &SweepConfig,
    counter: &Counter,
) -> Vec<PartialSweep> {
    let ns = speeds.len();
    let index = |d: SweepDirection, i: usize| if d == SweepDirection::Down { ns - 1 - i } else { i };
    let mut slots: Vec<Vec<Option<SpeedPoint>>> = vec![vec![None; ns]; jobs.len()];
    let mut failures: Vec<Vec<SpeedFailure>> = vec![Vec::new(); jobs.len()];
    let mut interrupted = false;
    let mut xs: Vec<Option<[f64; N]>> = Vec::with_capacity(jobs.len());
    for (j, (m, d)) in jobs.iter().enumerate() {
        let k = index(*d, 0);
        match m.initial_state(speeds[k]) {
            Ok(x) => xs.push(Some(x)),
            Err(error) => {
                failures[j].push(SpeedFailure {
                    index: k,
                    speed: speeds[k],
                    error,
                });
                xs.push(None);
            }
        }
    }
    for i in 0..ns {
        let live: Vec<usize> = (0..jobs.len()).filter(|&j| xs[j].is_some()).collect();
        if live.is_empty() {
            break;
        }
        let models: Vec<&M> = live.iter().map(|&j| jobs[j].0).collect();
        let sp: Vec<f64> = live.iter().map(|&j| speeds[index(jobs[j].1, i)]).collect();
        let starts: Vec<[f64; N]> = live.iter().filter_map(|&j| xs[j]).collect();
        let recs: Vec<Result<PoincareRecord<N>>> = match M::poincare_many(&models, &sp, &starts, cfg) {
            Ok(r) => r.into_iter().map(Ok).collect(),
            Err(Error::Interrupted) => vec![Err(Error::Interrupted); live.len()],
            Err(_) => (0..live.len())
                .map(|k| record_speed(models[k], sp[k], &starts[k], cfg))
                .collect(),
        };
        for (k, rec) in recs.into_iter().enumerate() {
            let j = live[k];
            let at = index(jobs[j].1, i);
            match rec.and_then(|r| settle_and_finish(models[k], sp[k], r, cfg)) {
                Ok((p, xf)) => {
                    xs[j] = Some(xf);
                    slots[j][at] = Some(p);
                }
                Err(Error::Interrupted) => {
                    interrupted = true;
                    xs[j] = None;
                }
                Err(error) => {
                    failures[j].push(SpeedFailure {
                        index: at,
                        speed: sp[k],
                        error,
                    });
                    xs[j] = None;
                }
            }
        }
        if interrupted || counter.tick(live.len()).is_err() {
            interrupted = true;
            break;
        }
    }
    jobs.iter()
        .zip(slots)
        .zip(failures)
        .map(|(((_, d), s), f)| finish_slots(*d, s, f, interrupted, cfg))
        .collect()
}

/// One sweep over ascending `speeds`; the first failed speed (in sweep
/// order) is the error. See [`sweep_partial`] to keep the finished speeds.
pub fn sweep<const N: usize, M: SweepModel<N>>(
    model: &M,
    speeds: &[f64],
    direction: SweepDirection,
    cfg: &SweepConfig,
    progress: Progress,
) -> Result<SweepResult> {
    sweep_partial(model, speeds, direction, cfg, progress)?.into_result()
}

/// One sweep over ascending `speeds`, keeping the finished speeds when a
/// speed fails or the progress hook stops the work. A continuation sweep
/// ("up"/"down") stops at its failed speed; an independent sweep runs
/// every other speed. Errors only for settings checked before any work.
pub fn sweep_partial<const N: usize, M: SweepModel<N>>(
    model: &M,
    speeds: &[f64],
    direction: SweepDirection,
    cfg: &SweepConfig,
    progress: Progress,
) -> Result<PartialSweep> {
    check_config(cfg)?;
    check_speeds(speeds)?;
    let counter = Counter {
        done: AtomicUsize::new(0),
        total: speeds.len(),
        cancelled: AtomicBool::new(false),
        progress,
    };
    Ok(sweep_counted(model, speeds, direction, cfg, &counter))
}

/// Several independent sweeps `(model, direction)` over the same speeds, in
/// parallel; results in the order of `jobs`. Continuation sweeps are grouped
/// (at most [`LANES`] per group, as many groups as rayon threads) and each
/// group runs in lock-step; lanes are bitwise independent, so the grouping
/// (and the thread count) does not change any result.
pub fn sweep_many<const N: usize, M: SweepModel<N>>(
    jobs: &[(&M, SweepDirection)],
    speeds: &[f64],
    cfg: &SweepConfig,
    progress: Progress,
) -> Result<Vec<SweepResult>> {
    sweep_many_partial(jobs, speeds, cfg, progress)?
        .into_iter()
        .map(PartialSweep::into_result)
        .collect()
}

/// [`sweep_many`] keeping every job's finished speeds (see
/// [`sweep_partial`]); errors only for settings checked before any work.
pub fn sweep_many_partial<const N: usize, M: SweepModel<N>>(
    jobs: &[(&M, SweepDirection)],
    speeds: &[f64],
    cfg: &SweepConfig,
    progress: Progress,
) -> Result<Vec<PartialSweep>> {
    check_config(cfg)?;
    check_speeds(speeds)?;
    let counter = Counter {
        done: AtomicUsize::new(0),
        total: speeds.len() * jobs.len(),
        cancelled: AtomicBool::new(false),
        progress,
    };
    let cont: Vec<usize> = (0..jobs.len())
        .filter(|&j| jobs[j].1 != SweepDirection::Independent)
        .collect();
    let indep: Vec<usize> = (0..jobs.len())
        .filter(|&j| jobs[j].1 == SweepDirection::Independent)
        .collect();
    let threads = rayon::current_num_threads().max(1);
    let group = cont.len().div_ceil(threads).clamp(1, LANES);
    let groups: Vec<Vec<usize>> = cont.chunks(group).map(|c| c.to_vec()).collect();
    // The caller's cancel flag reaches every part of the work.
    let flag = crate::cancel::current();
    let flag = flag.as_ref();
    let (cont_res, indep_res) = rayon::join(
        || -> Vec<Vec<PartialSweep>> {
            groups
                .par_iter()
                .map(|g| {
                    let js: Vec<(&M, SweepDirection)> = g.iter().map(|&j| jobs[j]).collect();
                    crate::cancel::with_current(flag, || continuation_group(&js, speeds, cfg, &counter))
                })
                .collect()
        },
        || -> Vec<PartialSweep> {
            indep
                .par_iter()
                .map(|&j| {
                    crate::cancel::with_current(flag, || sweep_counted(jobs[j].0, speeds, jobs[j].1, cfg, &counter))
                })
                .collect()
        },
    );
    let mut out: Vec<Option<PartialSweep>> = vec![None; jobs.len()];
    for (g, rs) in groups.iter().zip(cont_res) {
        for (&j, r) in g.iter().zip(rs) {
            out[j] = Some(r);
        }
    }
    for (&j, r) in indep.iter().zip(indep_res) {
        out[j] = Some(r);
    }
    Ok(out.into_iter().flatten().collect())
}

// ------------------------------------------------------------- models ----

/// Bearing stiffness as a function of speed: `(speed_rpm, kr_n_per_m,
/// ka_n_per_m)` samples, linear in speed between them and constant beyond
/// the ends. A single sample is a constant stiffness.
#[derive(Debug, Clone, PartialEq)]
pub struct BearingSchedule {
    points: Vec<(f64, f64, f64)>,
}

impl BearingSchedule {
    /// Validate: at least one sample, ascending speeds, positive stiffness.
    pub fn new(points: Vec<(f64, f64, f64)>) -> Result<Self> {
        if points.is_empty() {
            return Err(Error::config(
                "bearing_schedule",
                "[]",
                "needs at least one (speed_rpm, kr, ka) sample",
            ));
        }
        for &(s, kr, ka) in &points {
            crate::error::non_negative("bearing_schedule.speed_rpm", s)?;
            positive("bearing_schedule.kr_n_per_m", kr)?;
            positive("bearing_schedule.ka_n_per_m", ka)?;
        }
        if points.windows(2).any(|w| w[1].0 <= w[0].0) {
            return Err(Error::config(
                "bearing_schedule.speed_rpm",
                "unsorted",
                "must be strictly ascending",
            ));
        }
        Ok(BearingSchedule { points })
    }

    /// Sample a closure `speed_rpm -> (kr_n_per_m, ka_n_per_m)` at the given
    /// ascending speeds (e.g. the bearing model at each sweep speed).
    pub fn from_fn(speeds_rpm: &[f64], f: impl Fn(f64) -> (f64, f64)) -> Result<Self> {
        Self::new(
            speeds_rpm
                .iter()
                .map(|&s| {
                    let (kr, ka) = f(s);
                    (s, kr, ka)
                })
                .collect(),
        )
    }

    /// Constant stiffness.
    pub fn constant(kr_n_per_m: f64, ka_n_per_m: f64) -> Result<Self> {
        Self::new(vec![(0.0, kr_n_per_m, ka_n_per_m)])
    }

    /// `(kr, ka)` in N/m at `speed_rpm`.
    pub fn at(&self, speed_rpm: f64) -> (f64, f64) {
        let p = &self.points;
        if speed_rpm <= p[0].0 {
            return (p[0].1, p[0].2);
        }
        for w in p.windows(2) {
            if speed_rpm <= w[1].0 {
                let u = (speed_rpm - w[0].0) / (w[1].0 - w[0].0);
                return (w[0].1 + u * (w[1].1 - w[0].1), w[0].2 + u * (w[1].2 - w[0].2));
            }
        }
        let l = p[p.len() - 1];
        (l.1, l.2)
    }
}

/// The helical pair with a speed-dependent bearing stiffness.
#[derive(Debug, Clone, PartialEq)]
pub struct HelicalSweep {
    /// Gear pair (its own bearing stiffness is replaced by the schedule).
    pub pair: HelicalPair,
    /// Bearing stiffness vs speed.
    pub bearings: BearingSchedule,
}

impl HelicalSweep {
    fn pair_at(&self, speed_rpm: f64) -> Result<HelicalPair> {
        let (kr, ka) = self.bearings.at(speed_rpm);
        self.pair.with_bearing_stiffness(kr, ka)
    }
}

impl SweepModel<14> for HelicalSweep {
    type System = HelicalPairSystem;
    fn system_at(&self, speed: f64, steps_per_period: usize) -> Result<HelicalPairSystem> {
        self.pair_at(speed)?.system(speed, steps_per_period)
    }
    fn deflection(&self, sys: &HelicalPairSystem, n: usize, x: &[f64; 14]) -> f64 {
        sys.relative_deflection_m(n, x)
    }
    fn half_backlash(&self) -> f64 {
        self.pair.params().half_backlash_m
    }
    fn initial_state(&self, speed: f64) -> Result<[f64; 14]> {
        self.pair_at(speed)?.static_state()
    }
    /// The dynamic transmission error and its rate times `T / (2 pi)` (T the
    /// mesh period), both \[m\]: the bearing coordinates enter only through
    /// the DTE.
    fn section_outputs(&self, sys: &HelicalPairSystem, x: &[f64; 14]) -> Vec<f64> {
        let w = sys.period_s() / (2.0 * std::f64::consts::PI);
        vec![
            sys.relative_deflection_m(0, x),
            sys.relative_deflection_rate_m_per_s(0, x) * w,
        ]
    }

    /// Lock-step batches of up to [`LANES`] systems on the detected
    /// instruction set ([`super::batch::poincare_many`]).
    fn poincare_many(
        models: &[&Self],
        speeds: &[f64],
        starts: &[[f64; 14]],
        cfg: &SweepConfig,
    ) -> Result<Vec<PoincareRecord<14>>> {
        let systems = models
            .iter()
            .zip(speeds)
            .map(|(m, &s)| m.system_at(s, cfg.steps_per_period))
            .collect::<Result<Vec<_>>>()?;
        batch::poincare_many(&systems, starts, cfg.transient_periods, cfg.recorded_periods)
    }
}

impl SweepModel<2> for BacklashOscillator {
    type System = BacklashOscillatorSystem;
    fn system_at(&self, speed: f64, steps_per_period: usize) -> Result<BacklashOscillatorSystem> {
        self.system(speed, steps_per_period)
    }
    fn deflection(&self, _sys: &BacklashOscillatorSystem, _n: usize, x: &[f64; 2]) -> f64 {
        x[0]
    }
    fn half_backlash(&self) -> f64 {
        1.0
    }
    /// Displacement and velocity times `1 / Omega` (both in units of b).
    fn section_outputs(&self, sys: &BacklashOscillatorSystem, x: &[f64; 2]) -> Vec<f64> {
        vec![x[0], x[1] * sys.period() / (2.0 * std::f64::consts::PI)]
    }
    fn initial_state(&self, _speed: f64) -> Result<[f64; 2]> {
        // Static contact: k f(x) = F_m  ->  x = F_m + sign(F_m).
        Ok([self.mean_force + self.mean_force.signum(), 0.0])
    }
}

/// One cell of a regime map.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct RegimeCell {
    /// Input torque (N m).
    pub input_torque_n_m: f64,
    /// Transmission-error scale factor applied to the pair's TE samples (-).
    pub error_scale: f64,
    /// Speed (rpm).
    pub speed_rpm: f64,
    /// Motion class.
    pub motion: Motion,
    /// Contact regime.
    pub impact: ImpactRegime,
    /// Half peak-to-peak relative deflection (m).
    pub amplitude_m: f64,
    /// Mean of the relative deflection extremes (m).
    pub mean_deflection_m: f64,
    /// Largest Lyapunov exponent per mesh period, when computed \[1/period\].
    pub lyapunov_per_period: Option<f64>,
    /// Its standard error (batch means) \[1/period\].
    pub lyapunov_stderr_per_period: Option<f64>,
    /// 0-1 test K, when computed \[-\].
    pub zero_one_k: Option<f64>,
    /// Transient actually run \[mesh periods\].
    pub transient_periods: usize,
    /// False when the section was still converging at the transient cap.
    pub settled: bool,
}

/// A regime-map cell whose run failed.
#[derive(Debug, Clone, PartialEq)]
pub struct CellFailure {
    /// Index of the cell in map order (error scale x torque x speed, speed fastest).
    pub index: usize,
    /// Input torque (N m).
    pub input_torque_n_m: f64,
    /// Transmission-error scale factor (-).
    pub error_scale: f64,
    /// Speed (rpm).
    pub speed_rpm: f64,
    /// Why it failed.
    pub error: Error,
}

/// What a regime map finished, and which cells failed or were never run.
#[derive(Debug, Clone, PartialEq)]
pub struct PartialRegimeMap {
    /// The finished cells, in map order.
    pub cells: Vec<RegimeCell>,
    /// Failed cells, in map order.
    pub failures: Vec<CellFailure>,
    /// Map-order indices of the cells never run (the work was stopped).
    pub not_run: Vec<usize>,
    /// The progress hook stopped the work before every cell ran.
    pub interrupted: bool,
}

impl PartialRegimeMap {
    /// The complete map, or the first failure (then `Error::Interrupted`).
    pub fn into_result(self) -> Result<Vec<RegimeCell>> {
        if let Some(f) = self.failures.into_iter().next() {
            return Err(f.error);
        }
        if self.interrupted {
            return Err(Error::Interrupted);
        }
        Ok(self.cells)
    }
}

/// Regime map over error scale x torque x speed (speed fastest), every cell
/// started from its static state (independent), in parallel; the first
/// failed cell is the error (see [`regime_map_partial`]).
pub fn regime_map(
    base: &HelicalSweep,
    torques_n_m: &[f64],
    error_scales: &[f64],
    speeds_rpm: &[f64],
    cfg: &SweepConfig,
    progress: Progress,
) -> Result<Vec<RegimeCell>> {
    regime_map_partial(base, torques_n_m, error_scales, speeds_rpm, cfg, progress)?.into_result()
}

/// [`regime_map`] keeping the finished cells: a failed cell is reported and
/// every other cell still runs; a stop keeps the cells finished so far.
/// Errors only for settings checked before any work.
pub fn regime_map_partial(
    base: &HelicalSweep,
    torques_n_m: &[f64],
    error_scales: &[f64],
    speeds_rpm: &[f64],
    cfg: &SweepConfig,
    progress: Progress,
) -> Result<PartialRegimeMap> {
    check_config(cfg)?;
    check_speeds(speeds_rpm)?;
    if torques_n_m.is_empty() || error_scales.is_empty() {
        return Err(Error::config(
            "torques_n_m",
            "[]",
            "need at least one torque and one error scale",
        ));
    }
    let mut models = Vec::new();
    for &e in error_scales {
        for &t in torques_n_m {
            let pair = base.pair.with_torque_and_error_scale(t, e)?;
            models.push((
                t,
                e,
                HelicalSweep {
                    pair,
                    bearings: base.bearings.clone(),
                },
            ));
        }
    }
    let cells: Vec<(usize, usize)> = (0..models.len())
        .flat_map(|m| (0..speeds_rpm.len()).map(move |s| (m, s)))
        .collect();
    let counter = Counter {
        done: AtomicUsize::new(0),
        total: cells.len(),
        cancelled: AtomicBool::new(false),
        progress,
    };
    let mut slots: Vec<Option<RegimeCell>> = vec![None; cells.len()];
    let mut failures = Vec::new();
    let mut interrupted = false;
    let all: Vec<usize> = (0..cells.len()).collect();
    let flag = crate::cancel::current();
    for chunk in all.chunks(CHUNK) {
        let part: Vec<Vec<(usize, Result<SpeedPoint>)>> = chunk
            .par_chunks(LANES)
            .map(|group| {
                if counter.keep_going().is_err() {
                    return Vec::new();
                }
                let runs: Vec<(&HelicalSweep, f64)> = group
                    .iter()
                    .map(|&c| (&models[cells[c].0].2, speeds_rpm[cells[c].1]))
                    .collect();
                let points = crate::cancel::with_current(flag.as_ref(), || independent_points(&runs, cfg));
                group.iter().copied().zip(points).collect()
            })
            .collect();
        for (c, r) in part.into_iter().flatten() {
            let (t, e, _) = &models[cells[c].0];
            match r {
                Ok(p) => {
                    slots[c] = Some(RegimeCell {
                        input_torque_n_m: *t,
                        error_scale: *e,
                        speed_rpm: p.speed,
                        motion: p.motion,
                        impact: p.impact,
                        amplitude_m: p.amplitude(),
                        mean_deflection_m: 0.5 * (p.deflection_max + p.deflection_min),
                        lyapunov_per_period: p.lyapunov_per_period,
                        lyapunov_stderr_per_period: p.lyapunov_stderr_per_period,
                        zero_one_k: p.zero_one_k,
                        transient_periods: p.transient_periods,
                        settled: p.settled,
                    })
                }
                Err(Error::Interrupted) => interrupted = true,
                Err(error) => failures.push(CellFailure {
                    index: c,
                    input_torque_n_m: *t,
                    error_scale: *e,
                    speed_rpm: speeds_rpm[cells[c].1],
                    error,
                }),
            }
        }
        if interrupted || counter.tick(chunk.len()).is_err() {
            interrupted = true;
            break;
        }
    }
    failures.sort_by_key(|f| f.index);
    let failed: Vec<usize> = failures.iter().map(|f| f.index).collect();
    let not_run: Vec<usize> = (0..cells.len())
        .filter(|&c| slots[c].is_none() && !failed.contains(&c))
        .collect();
    Ok(PartialRegimeMap {
        cells: slots.into_iter().flatten().collect(),
        failures,
        interrupted: interrupted && !not_run.is_empty(),
        not_run,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn schedule_interpolates_linearly_and_clamps() {
        let s = BearingSchedule::new(vec![(1000.0, 2e8, 4e7), (3000.0, 1e8, 6e7)]).unwrap();
        assert_eq!(s.at(500.0), (2e8, 4e7));
        assert_eq!(s.at(2000.0), (1.5e8, 5e7));
        assert_eq!(s.at(9000.0), (1e8, 6e7));
        let f = BearingSchedule::from_fn(&[1000.0, 3000.0], |n| {
            (2e8 - 5e4 * (n - 1000.0), 4e7 + 1e4 * (n - 1000.0))
        })
        .unwrap();
        assert_eq!(f, s);
        assert!(BearingSchedule::new(vec![(2.0, 1e8, 1e8), (1.0, 1e8, 1e8)]).is_err());
        assert!(BearingSchedule::constant(-1.0, 1e8)
            .unwrap_err()
            .to_string()
            .contains("kr_n_per_m"));
    }

    #[test]
    fn sweep_rejects_bad_speeds_and_config() {
        let osc = BacklashOscillator::new(0.05, 0.1, 0.1, 0.0).unwrap();
        let cfg = SweepConfig::default();
        let ok = |_: usize, _: usize| true;
        assert!(sweep(&osc, &[], SweepDirection::Up, &cfg, &ok).is_err());
        assert!(sweep(&osc, &[1.0, 0.5], SweepDirection::Up, &cfg, &ok).is_err());
        let bad = SweepConfig {
            recorded_periods: 1,
            ..cfg
        };
        let e = sweep(&osc, &[1.0], SweepDirection::Up, &bad, &ok).unwrap_err();
        assert!(e.to_string().contains("recorded_periods"));
        let coarse = SweepConfig {
            steps_per_period: 8,
            ..cfg
        };
        let e = sweep(&osc, &[1.0], SweepDirection::Independent, &coarse, &ok).unwrap_err();
        assert!(e.to_string().contains("steps_per_period"));
    }

    #[test]
    fn progress_reports_every_speed_and_total() {
        let osc = BacklashOscillator::new(0.05, 0.1, 0.02, 0.0).unwrap();
        let cfg = SweepConfig {
            transient_periods: 5,
            recorded_periods: 4,
            steps_per_period: 32,
            lyapunov_periods: 0,
            ..SweepConfig::default()
        };
        let seen = std::sync::Mutex::new(Vec::new());
        let speeds = [0.5, 0.6, 0.7];
        sweep(&osc, &speeds, SweepDirection::Down, &cfg, &|d, t| {
            seen.lock().map(|mut v| v.push((d, t))).is_ok()
        })
        .unwrap();
        assert_eq!(seen.into_inner().unwrap(), vec![(1, 3), (2, 3), (3, 3)]);
    }

    #[test]
    fn sweeps_refuse_counts_past_their_bounds() {
        let osc = BacklashOscillator::new(0.05, 0.1, 0.1, 0.0).unwrap();
        let ok = |_: usize, _: usize| true;
        let cfg = SweepConfig::default();
        let fine = SweepConfig {
            steps_per_period: MAX_STEPS_PER_PERIOD + 1,
            ..cfg
        };
        let e = sweep(&osc, &[1.0], SweepDirection::Up, &fine, &ok)
            .unwrap_err()
            .to_string();
        assert!(e.contains("steps_per_period") && e.contains("at most 100000"), "{e}");
        let long = SweepConfig {
            transient_periods: 1_000_000_000,
            ..cfg
        };
        let e = sweep(&osc, &[1.0], SweepDirection::Up, &long, &ok)
            .unwrap_err()
            .to_string();
        assert!(e.contains("transient_periods") && e.contains("at most 100000"), "{e}");
    }

    use std::sync::Arc;

    /// x' = -x that raises `flag` once `calls` reaches `after` right-hand
    /// sides (4 a step), shared by every speed.
    struct RaisingOde {
        calls: Arc<AtomicUsize>,
        after: usize,
        flag: Arc<AtomicBool>,
    }

    impl super::super::ode::OdeSystem<1> for RaisingOde {
        fn rhs(&self, _t: f64, x: &[f64; 1], dx: &mut [f64; 1]) {
            if self.calls.fetch_add(1, Ordering::Relaxed) + 1 == self.after {
                self.flag.store(true, Ordering::Relaxed);
            }
            dx[0] = -x[0];
        }
    }

    struct Raising {
        calls: Arc<AtomicUsize>,
        after: usize,
        flag: Arc<AtomicBool>,
    }

    impl SweepModel<1> for Raising {
        type System = super::super::ode::Gridded<RaisingOde>;
        fn system_at(&self, _speed: f64, steps_per_period: usize) -> Result<Self::System> {
            let ode = RaisingOde {
                calls: Arc::clone(&self.calls),
                after: self.after,
                flag: Arc::clone(&self.flag),
            };
            Ok(super::super::ode::Gridded::new(ode, 1.0, steps_per_period))
        }
        fn deflection(&self, _sys: &Self::System, _n: usize, x: &[f64; 1]) -> f64 {
            x[0]
        }
        fn half_backlash(&self) -> f64 {
            1.0
        }
        fn initial_state(&self, _speed: f64) -> Result<[f64; 1]> {
            Ok([1.0])
        }
    }

    #[test]
    fn the_cancel_flag_stops_a_sweep_inside_one_speed() {
        // Each speed is 50,000 periods of 100,000 steps (5e9 steps); the
        // flag rises after 10,000 steps, long before the first period ends.
        let cfg = SweepConfig {
            transient_periods: 50_000,
            recorded_periods: 2,
            steps_per_period: MAX_STEPS_PER_PERIOD,
            lyapunov_periods: 0,
            ..SweepConfig::default()
        };
        let every = crate::cancel::CHECK_EVERY_STEPS;
        let speeds = [1.0, 2.0];
        for dir in [SweepDirection::Up, SweepDirection::Independent] {
            let model = Raising {
                calls: Arc::new(AtomicUsize::new(0)),
                after: 40_000,
                flag: Arc::new(AtomicBool::new(false)),
            };
            let calls = Arc::clone(&model.calls);
            let flag = Arc::clone(&model.flag);
            let hook_calls = AtomicUsize::new(0);
            let hook = |_: usize, _: usize| {
                hook_calls.fetch_add(1, Ordering::Relaxed);
                true
            };
            // The flag is installed on this thread only; the independent
            // sweep's speeds run on rayon's threads and still see it.
            let p = crate::cancel::with_flag(&flag, || sweep_partial(&model, &speeds, dir, &cfg, &hook)).unwrap();
            assert!(p.interrupted && p.failures.is_empty(), "{dir:?}: {:?}", p.failures);
            assert_eq!(p.not_run, vec![0, 1], "{dir:?}");
            assert!(p.result.points.is_empty());
            assert!(matches!(p.into_result(), Err(Error::Interrupted)));
            // Every speed running stops at its next look at the flag.
            let steps = calls.load(Ordering::Relaxed) / 4;
            assert!(
                steps >= 10_000 && steps <= 10_000 + speeds.len() * every,
                "{dir:?}: {steps} steps"
            );
        }
    }

    #[test]
    fn the_cancel_flag_stops_a_regime_map_cell_of_the_gear_pair() {
        use super::super::gear_model::HelicalPairParams;
        // One cell of 1e9 lock-step steps (minutes); a stop 0.1 s in.
        let base = HelicalSweep {
            pair: HelicalPair::new(HelicalPairParams::seed_a()).unwrap(),
            bearings: BearingSchedule::constant(2.0e8, 5.0e7).unwrap(),
        };
        let cfg = SweepConfig {
            transient_periods: 10_000,
            recorded_periods: 2,
            steps_per_period: MAX_STEPS_PER_PERIOD,
            lyapunov_periods: 0,
            ..SweepConfig::default()
        };
        let flag = Arc::new(AtomicBool::new(false));
        let raise = {
            let flag = Arc::clone(&flag);
            std::thread::spawn(move || {
                std::thread::sleep(std::time::Duration::from_millis(100));
                flag.store(true, Ordering::Relaxed);
                std::time::Instant::now()
            })
        };
        let map = crate::cancel::with_flag(&flag, || {
            regime_map_partial(&base, &[100.0], &[1.0], &[10_000.0], &cfg, &|_, _| true)
        })
        .unwrap();
        let latency = raise.join().unwrap().elapsed();
        eprintln!("regime map cell stopped {latency:?} after the flag");
        assert!(map.interrupted && map.cells.is_empty() && map.failures.is_empty());
        assert_eq!(map.not_run, vec![0]);
    }
}
