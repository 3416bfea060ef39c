//! Classification of a steady motion from its Poincare section.
//!
//! Rule (in this order), on the *observed* section quantities only (for the
//! gear pair the dynamic transmission error and its rate, so a slowly
//! decaying mode that does not enter the DTE cannot change the label):
//! 1. Period-n (n = 1..max_period): the smallest n with
//!    `|y_{k+n,i} - y_{k,i}| <= rel_tol * s` for every recorded section point
//!    k and observed quantity i, where `s` is the orbit's size (peak-to-peak
//!    of the observed deflection over the window), see [`section_verdict`].
//!    A window whose period-m mismatch is still shrinking is "converging":
//!    the sweeps extend the transient (up to a cap) before labelling, and
//!    report the points that did not settle.
//! 2. Otherwise chaotic or quasi-periodic by [`chaos_verdict`]: chaos needs
//!    the largest Lyapunov exponent (per excitation period) above
//!    `lyapunov_threshold_per_period` by `lyapunov_sigmas` standard errors
//!    and, when there are at least [`MIN_ZERO_ONE_POINTS`] section points,
//!    the 0-1 test for chaos (Gottwald & Melbourne 2004, Proc. R. Soc. A 460,
//!    603-611; correlation form of Gottwald & Melbourne 2009, SIAM J. Appl.
//!    Dyn. Syst. 8, 129-145) with K > `zero_one_threshold`. Without an
//!    exponent the 0-1 test alone decides; with neither the motion is
//!    reported quasi-periodic.
//!
//! Along a sweep, [`jumps_and_transitions`] reports jumps only between
//! neighbouring speeds of the same non-chaotic regime family and every change
//! of family (entries into and exits from chaos among them) as a transition.
//!
//! Impact regime from the extremes of the relative deflection d against the
//! half backlash b: always in contact on one flank (`d > b` or `d < -b`
//! throughout) -> [`ImpactRegime::NoImpact`]; separation but never reaching the
//! other flank -> [`ImpactRegime::SingleSided`]; both flanks touched ->
//! [`ImpactRegime::DoubleSided`]; never in contact -> [`ImpactRegime::NoContact`].

use crate::error::positive;
use crate::{Error, Result};

/// Kind of steady motion.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum Motion {
    /// Period-n motion (n excitation periods).
    Periodic(usize),
    /// Non-periodic with non-positive largest exponent / regular 0-1 test.
    QuasiPeriodic,
    /// Positive largest Lyapunov exponent / 0-1 test K near 1.
    Chaotic,
}

/// Tooth contact regime.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum ImpactRegime {
    /// Teeth stay in contact on one flank.
    NoImpact,
    /// Teeth separate (drive-side impacts only).
    SingleSided,
    /// Back-side contact occurs as well.
    DoubleSided,
    /// Teeth never touch in the recorded window.
    NoContact,
}

/// Classifier settings (all dimensionless).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClassifyConfig {
    /// Relative tolerance of the period test: section points of the observed
    /// quantities match when they differ by at most `rel_tol` times the
    /// orbit's size (peak-to-peak of the observed deflection) \[-\].
    pub rel_tol: f64,
    /// Largest period tested \[excitation periods\].
    pub max_period: usize,
    /// A period-m mismatch `|y_{k+m} - y_k|` whose largest values over the
    /// four quarters of the window decrease, the last below
    /// `converging_ratio` times the first, is still converging: the
    /// transient is extended (up to the sweep's cap) instead of labelling
    /// \[-\].
    pub converging_ratio: f64,
    /// Chaos needs the largest Lyapunov exponent above
    /// `lyapunov_threshold_per_period` by this many standard errors \[-\].
    pub lyapunov_sigmas: f64,
    /// Floor of the Lyapunov exponent per excitation period below which a
    /// (significant) exponent still counts as zero \[1/period\].
    pub lyapunov_threshold_per_period: f64,
    /// 0-1 test threshold on K \[-\].
    pub zero_one_threshold: f64,
}

impl Default for ClassifyConfig {
    /// rel_tol 1e-4 of the orbit size; max period 32; a mismatch shrinking
    /// steadily to below 0.9 of its first-quarter value is converging; chaos when the
    /// exponent exceeds 1e-3 per period by 3 standard errors (and the 0-1
    /// test, when it has enough points, gives K > 0.5).
    fn default() -> Self {
        ClassifyConfig {
            rel_tol: 1e-4,
            max_period: 32,
            converging_ratio: 0.9,
            lyapunov_sigmas: 3.0,
            lyapunov_threshold_per_period: 1e-3,
            zero_one_threshold: 0.5,
        }
    }
}

impl ClassifyConfig {
    /// Validate; errors name the field and its value.
    pub fn check(&self) -> Result<()> {
        positive("rel_tol", self.rel_tol)?;
        if self.max_period == 0 {
            return Err(Error::config("max_period", 0, "must be at least 1"));
        }
        crate::error::in_range("converging_ratio", self.converging_ratio, 0.0, 1.0)?;
        crate::error::non_negative("lyapunov_sigmas", self.lyapunov_sigmas)?;
        crate::error::finite("lyapunov_threshold_per_period", self.lyapunov_threshold_per_period)?;
        crate::error::in_range("zero_one_threshold", self.zero_one_threshold, 0.0, 1.0)?;
        Ok(())
    }
}

/// Smallest period n <= `max_period` of a sequence of section points (each
/// of length `scale.len()`), or None: every pair `(k, k + n)` must agree to
/// `rel_tol * scale[i]` in every component i with a positive scale. A period
/// n is tested only with at least `2 n` points (every phase of the orbit
/// compared at least once).
pub fn detect_period<P: AsRef<[f64]>>(points: &[P], scale: &[f64], rel_tol: f64, max_period: usize) -> Option<usize> {
    let active: Vec<usize> = (0..scale.len())
        .filter(|&i| scale[i] > 0.0 && scale[i].is_finite())
        .collect();
    if active.is_empty() {
        return if points.len() >= 2 { Some(1) } else { None };
    }
    (1..=max_period).find(|&n| {
        points.len() >= 2 * n
            && (0..points.len() - n).all(|k| {
                let (a, b) = (points[k].as_ref(), points[k + n].as_ref());
                active.iter().all(|&i| (a[i] - b[i]).abs() <= rel_tol * scale[i])
            })
    })
}

/// Largest relative period-m mismatch `max_i |y_{k+m,i} - y_{k,i}| / s_i`
/// over each quarter of the pairs k, or None with fewer than 16 pairs.
fn mismatch_quarters<P: AsRef<[f64]>>(points: &[P], scale: &[f64], m: usize) -> Option<[f64; 4]> {
    if points.len() < m + 16 {
        return None;
    }
    let pairs = points.len() - m;
    let e = |k: usize| {
        let (a, b) = (points[k].as_ref(), points[k + m].as_ref());
        (0..scale.len())
            .filter(|&i| scale[i] > 0.0 && scale[i].is_finite())
            .map(|i| (a[i] - b[i]).abs() / scale[i])
            .fold(0.0, f64::max)
    };
    Some(std::array::from_fn(|q| {
        (q * pairs / 4..(q + 1) * pairs / 4).map(e).fold(0.0, f64::max)
    }))
}

/// A mismatch still shrinking: quarter maxima strictly decreasing, the last
/// below `ratio` times the first, the first above the tolerance.
fn shrinking(q: &[f64; 4], rel_tol: f64, ratio: f64) -> bool {
    q[0] > rel_tol && q[1] < q[0] && q[2] < q[1] && q[3] < q[2] && q[3] < ratio * q[0]
}

/// Relative round-off floor of the period test: section points differing
/// by less than this fraction of their largest magnitude always match.
pub const ROUNDOFF_FLOOR: f64 = 1e-12;

/// What one window of section points says.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct SectionVerdict {
    /// Smallest period found by [`detect_period`], if any.
    pub period: Option<usize>,
    /// Still shrinking through the window: some period-m mismatch with m
    /// below the period found, or, without a period, the best candidate
    /// m <= `max_period`. The points have not settled.
    pub converging: bool,
}

/// Period test and settling test of one window of observed section points,
/// all compared against the same orbit size `orbit_size` (in the unit of the
/// points). A constant or empty orbit (size 0) is period-1.
pub fn section_verdict<P: AsRef<[f64]>>(points: &[P], orbit_size: f64, cfg: &ClassifyConfig) -> SectionVerdict {
    let dim = points.first().map_or(0, |p| p.as_ref().len());
    // Round-off floor: differences below 1e-12 of the largest |y| are noise
    // (a fixed point of a map has no orbit size of its own).
    let max_abs = points
        .iter()
        .flat_map(|p| p.as_ref().iter())
        .map(|v| v.abs())
        .filter(|v| v.is_finite())
        .fold(0.0, f64::max);
    let size = if orbit_size.is_finite() { orbit_size } else { 0.0 };
    let s = size.max(ROUNDOFF_FLOOR * max_abs / cfg.rel_tol);
    let scale = vec![s; dim];
    let period = detect_period(points, &scale, cfg.rel_tol, cfg.max_period);
    if s == 0.0 {
        return SectionVerdict {
            period,
            converging: false,
        };
    }
    let converging = match period {
        // A period-n match with a shrinking mismatch at some m < n is a
        // slow transient (e.g. a decaying mode), not yet period n.
        Some(n) => (1..n).any(|m| {
            mismatch_quarters(points, &scale, m).is_some_and(|q| shrinking(&q, cfg.rel_tol, cfg.converging_ratio))
        }),
        // No period: the best candidate (smallest last-quarter mismatch)
        // decides, so that chaotic windows rarely look converging.
        None => (1..=cfg.max_period)
            .filter_map(|m| mismatch_quarters(points, &scale, m))
            .min_by(|a, b| a[3].total_cmp(&b[3]))
            .is_some_and(|q| shrinking(&q, cfg.rel_tol, cfg.converging_ratio)),
    };
    SectionVerdict { period, converging }
}

/// Evidence for chaos at a non-periodic point.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ChaosEvidence {
    /// Largest Lyapunov exponent per excitation period \[1/period\].
    pub lyapunov_per_period: Option<f64>,
    /// Its standard error (batch means) \[1/period\]; None counts as 0.
    pub lyapunov_stderr_per_period: Option<f64>,
    /// 0-1 test K of the section observable (only with at least
    /// [`MIN_ZERO_ONE_POINTS`] points) \[-\].
    pub zero_one_k: Option<f64>,
}

/// Chaotic or quasi-periodic from the evidence: with an exponent, chaos needs
/// `lambda - lyapunov_sigmas * stderr > lyapunov_threshold_per_period` and,
/// when the 0-1 test is available, `K > zero_one_threshold` as well (both
/// must agree); without an exponent the 0-1 test alone decides; with
/// neither the motion is reported quasi-periodic.
pub fn chaos_verdict(ev: &ChaosEvidence, cfg: &ClassifyConfig) -> Motion {
    let k_says = ev.zero_one_k.map(|k| k > cfg.zero_one_threshold);
    match ev.lyapunov_per_period {
        Some(l) => {
            let se = ev.lyapunov_stderr_per_period.unwrap_or(0.0);
            let significant = l.is_finite() && l - cfg.lyapunov_sigmas * se > cfg.lyapunov_threshold_per_period;
            if significant && k_says != Some(false) {
                Motion::Chaotic
            } else {
                Motion::QuasiPeriodic
            }
        }
        None if k_says == Some(true) => Motion::Chaotic,
        None => Motion::QuasiPeriodic,
    }
}

/// The 0-1 test statistic K (median over 100 fixed frequencies c in
/// (pi/5, 4 pi/5)) of a scalar series; near 0 regular, near 1 chaotic.
/// Returns 0 for series shorter than 20 points or without variation.
pub fn zero_one_test(phi: &[f64]) -> f64 {
    let n = phi.len();
    if n < 20 {
        return 0.0;
    }
    let mean = phi.iter().sum::<f64>() / n as f64;
    let var = phi.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / n as f64;
    if var <= 1e-300 * mean.abs().max(1.0) {
        return 0.0;
    }
    let ncut = (n / 10).max(3);
    let nc = 100;
    let mut ks: Vec<f64> = (0..nc)
        .map(|m| {
            // Fixed, irregularly spaced c values avoid resonance with the series.
            let frac = ((m as f64 + 0.5) / nc as f64 + 0.618_033_988_75 * m as f64).fract();
            let c = std::f64::consts::PI * (0.2 + 0.6 * frac);
            zero_one_kc(phi, mean, c, ncut)
        })
        .collect();
    ks.sort_by(f64::total_cmp);
    0.5 * (ks[nc / 2 - 1] + ks[nc / 2])
}

fn zero_one_kc(phi: &[f64], mean: f64, c: f64, ncut: usize) -> f64 {
    let n = phi.len();
    let mut p = vec![0.0; n + 1];
    let mut q = vec![0.0; n + 1];
    for j in 0..n {
        let (s, co) = (c * (j + 1) as f64).sin_cos();
        p[j + 1] = p[j] + (phi[j] - mean) * co;
        q[j + 1] = q[j] + (phi[j] - mean) * s;
    }
    // Mean-square displacement (mean removed, so the oscillatory correction
    // term of the modified D(n) vanishes).
    let d: Vec<f64> = (1..=ncut)
        .map(|k| {
            let m = n - k;
            (0..m)
                .map(|j| (p[j + k] - p[j]).powi(2) + (q[j + k] - q[j]).powi(2))
                .sum::<f64>()
                / m as f64
        })
        .collect();
    correlation(&(1..=ncut).map(|k| k as f64).collect::<Vec<_>>(), &d)
}

fn correlation(x: &[f64], y: &[f64]) -> f64 {
    let n = x.len() as f64;
    let (mx, my) = (x.iter().sum::<f64>() / n, y.iter().sum::<f64>() / n);
    let (mut sxy, mut sxx, mut syy) = (0.0, 0.0, 0.0);
    for (a, b) in x.iter().zip(y) {
        sxy += (a - mx) * (b - my);
        sxx += (a - mx).powi(2);
        syy += (b - my).powi(2);
    }
    if sxx <= 0.0 || syy <= 0.0 {
        0.0
    } else {
        sxy / (sxx * syy).sqrt()
    }
}

/// Fewest section points for which the 0-1 test is used; shorter
/// non-periodic records are reported quasi-periodic (undecided).
pub const MIN_ZERO_ONE_POINTS: usize = 200;

/// Classify by the rule in the module docs (without a standard error: the
/// exponent counts as exact). `lyapunov_per_period` is the largest exponent
/// times the excitation period, if known; the 0-1 test on `observable` is
/// used when it has at least [`MIN_ZERO_ONE_POINTS`] points.
pub fn classify_motion<P: AsRef<[f64]>>(
    points: &[P],
    scale: &[f64],
    observable: &[f64],
    lyapunov_per_period: Option<f64>,
    cfg: &ClassifyConfig,
) -> Motion {
    if let Some(n) = detect_period(points, scale, cfg.rel_tol, cfg.max_period) {
        return Motion::Periodic(n);
    }
    let ev = ChaosEvidence {
        lyapunov_per_period,
        lyapunov_stderr_per_period: None,
        zero_one_k: (observable.len() >= MIN_ZERO_ONE_POINTS).then(|| zero_one_test(observable)),
    };
    chaos_verdict(&ev, cfg)
}

/// Impact regime from the extremes of the relative deflection (see module docs).
pub fn impact_regime(deflection_min: f64, deflection_max: f64, half_backlash: f64) -> ImpactRegime {
    let b = half_backlash;
    if deflection_min > b || deflection_max < -b {
        ImpactRegime::NoImpact
    } else if deflection_max > b && deflection_min < -b {
        ImpactRegime::DoubleSided
    } else if deflection_max > b || deflection_min < -b {
        ImpactRegime::SingleSided
    } else {
        ImpactRegime::NoContact
    }
}

/// Jump detection along a sweep: index i flags a jump between entries i and
/// i+1 of `amplitude` when the step `|A_{i+1} - A_i|` exceeds both
/// `rel_jump * max(|A_i|, |A_{i+1}|)` and `trend_factor` times the median
/// step over the `window` neighbouring steps on each side (the local trend).
pub fn detect_jumps(amplitude: &[f64], rel_jump: f64, trend_factor: f64, window: usize) -> Vec<usize> {
    if amplitude.len() < 2 {
        return Vec::new();
    }
    let steps: Vec<f64> = amplitude.windows(2).map(|w| (w[1] - w[0]).abs()).collect();
    (0..steps.len())
        .filter(|&i| {
            let lo = i.saturating_sub(window);
            let hi = (i + window + 1).min(steps.len());
            let mut local: Vec<f64> = (lo..hi).filter(|&k| k != i).map(|k| steps[k]).collect();
            let med = if local.is_empty() {
                0.0
            } else {
                local.sort_by(f64::total_cmp);
                local[local.len() / 2]
            };
            let size = amplitude[i].abs().max(amplitude[i + 1].abs());
            steps[i] > rel_jump * size && steps[i] > trend_factor * med
        })
        .collect()
}

/// Regime family: period-n motions of any n form one family.
fn family(m: Motion) -> u8 {
    match m {
        Motion::Periodic(_) => 0,
        Motion::QuasiPeriodic => 1,
        Motion::Chaotic => 2,
    }
}

/// A change of regime family (periodic, quasi-periodic, chaotic) between
/// neighbouring sweep points `index` and `index + 1` (ascending speed).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Transition {
    /// Index of the lower-speed point.
    pub index: usize,
    /// Motion at `index`.
    pub from: Motion,
    /// Motion at `index + 1`.
    pub to: Motion,
    /// Change of the smallest deflection, point `index + 1` minus `index`
    /// (unit of the deflection: \[m\] for the gear pair).
    pub min_change: f64,
    /// Change of the largest deflection (same unit).
    pub max_change: f64,
}

impl Transition {
    /// Change of the half peak-to-peak amplitude (unit of the deflection).
    pub fn amplitude_change(&self) -> f64 {
        0.5 * (self.max_change - self.min_change)
    }
    /// Entry into chaos (with increasing speed).
    pub fn enters_chaos(&self) -> bool {
        self.to == Motion::Chaotic && self.from != Motion::Chaotic
    }
    /// Exit from chaos (with increasing speed).
    pub fn exits_chaos(&self) -> bool {
        self.from == Motion::Chaotic && self.to != Motion::Chaotic
    }
}

/// Jumps and regime transitions along a sweep (points in ascending speed;
/// `lo`, `hi` the deflection extremes of each point).
///
/// - A transition is reported wherever the regime family changes
///   (periodic / quasi-periodic / chaotic), with the change of both extremes:
///   entries into and exits from chaos are transitions, never jumps.
/// - A jump at i needs points i and i+1 in the same non-chaotic family and
///   the amplitude step `|A_{i+1} - A_i|` (A = (hi - lo) / 2) above both
///   `rel_jump * max(|A_i|, |A_{i+1}|)` and `trend_factor` times the median
///   of the other eligible steps (same family, not chaotic) within `window`
///   steps on each side. No jump is flagged inside a chaotic band.
pub fn jumps_and_transitions(
    motions: &[Motion],
    lo: &[f64],
    hi: &[f64],
    rel_jump: f64,
    trend_factor: f64,
    window: usize,
) -> (Vec<usize>, Vec<Transition>) {
    let n = motions.len().min(lo.len()).min(hi.len());
    if n < 2 {
        return (Vec::new(), Vec::new());
    }
    let amp: Vec<f64> = (0..n).map(|i| 0.5 * (hi[i] - lo[i])).collect();
    let eligible = |i: usize| family(motions[i]) == family(motions[i + 1]) && motions[i] != Motion::Chaotic;
    let steps: Vec<f64> = (0..n - 1).map(|i| (amp[i + 1] - amp[i]).abs()).collect();
    let mut jumps = Vec::new();
    let mut transitions = Vec::new();
    for i in 0..n - 1 {
        if family(motions[i]) != family(motions[i + 1]) {
            transitions.push(Transition {
                index: i,
                from: motions[i],
                to: motions[i + 1],
                min_change: lo[i + 1] - lo[i],
                max_change: hi[i + 1] - hi[i],
            });
            continue;
        }
        if !eligible(i) || !steps[i].is_finite() {
            continue;
        }
        let a = i.saturating_sub(window);
        let b = (i + window + 1).min(steps.len());
        let mut local: Vec<f64> = (a..b)
            .filter(|&k| k != i && eligible(k) && steps[k].is_finite())
            .map(|k| steps[k])
            .collect();
        let med = if local.is_empty() {
            0.0
        } else {
            local.sort_by(f64::total_cmp);
            local[local.len() / 2]
        };
        let size = amp[i].abs().max(amp[i + 1].abs());
        if steps[i] > rel_jump * size && steps[i] > trend_factor * med {
            jumps.push(i);
        }
    }
    (jumps, transitions)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn impact_regimes_from_extremes() {
        assert_eq!(impact_regime(2.0, 3.0, 1.0), ImpactRegime::NoImpact);
        assert_eq!(impact_regime(-3.0, -2.0, 1.0), ImpactRegime::NoImpact);
        assert_eq!(impact_regime(0.5, 3.0, 1.0), ImpactRegime::SingleSided);
        assert_eq!(impact_regime(-1.5, 3.0, 1.0), ImpactRegime::DoubleSided);
        assert_eq!(impact_regime(-0.5, 0.5, 1.0), ImpactRegime::NoContact);
    }

    #[test]
    fn jumps_found_against_smooth_trend() {
        let mut a: Vec<f64> = (0..50).map(|i| 1.0 + 0.01 * i as f64).collect();
        for v in a.iter_mut().skip(30) {
            *v *= 0.4;
        }
        assert_eq!(detect_jumps(&a, 0.2, 5.0, 5), vec![29]);
        let smooth: Vec<f64> = (0..50).map(|i| (i as f64 * 0.1).sin() + 2.0).collect();
        assert!(detect_jumps(&smooth, 0.2, 5.0, 5).is_empty());
    }

    #[test]
    fn no_jump_inside_a_chaotic_band_and_chaos_edges_are_transitions() {
        // Period-1 branch 0..9 with a fold at 4 -> 5 (amplitude 3 -> 1),
        // chaotic band 10..19 whose envelope widens abruptly at 14 -> 15
        // (as at an interior crisis), then a period-2 window 20..29 entered
        // with a drop.
        let mut m = vec![Motion::Periodic(1); 10];
        m.extend(vec![Motion::Chaotic; 10]);
        m.extend(vec![Motion::Periodic(2); 10]);
        let amp: Vec<f64> = (0..30)
            .map(|i| match i {
                0..=4 => 3.0 + 0.01 * i as f64,
                5..=9 => 1.0 + 0.01 * i as f64,
                10..=19 => [2.0, 2.05, 2.1, 2.15, 2.2, 6.0, 6.05, 6.1, 6.15, 6.2][i - 10],
                _ => 0.8 + 0.01 * i as f64,
            })
            .collect();
        let lo: Vec<f64> = amp.iter().map(|a| 10.0 - a).collect();
        let hi: Vec<f64> = amp.iter().map(|a| 10.0 + a).collect();
        // The amplitude-only detector splits the band.
        assert!(detect_jumps(&amp, 0.2, 5.0, 5).contains(&14));
        let (jumps, tr) = jumps_and_transitions(&m, &lo, &hi, 0.2, 5.0, 5);
        assert_eq!(jumps, vec![4]);
        assert_eq!(tr.len(), 2);
        assert!(tr[0].enters_chaos() && tr[0].index == 9);
        assert!(tr[1].exits_chaos() && tr[1].index == 19 && tr[1].to == Motion::Periodic(2));
        assert!((tr[1].amplitude_change() - (amp[20] - amp[19])).abs() < 1e-12);
        assert!((tr[1].max_change - (hi[20] - hi[19])).abs() < 1e-12);
    }

    #[test]
    fn converging_window_is_not_labelled_and_chaos_needs_significance() {
        let cfg = ClassifyConfig::default();
        // Fixed point approached geometrically (rho = 0.9) with a period-3
        // wobble on top: not period-3 or any other while it shrinks.
        let pts: Vec<[f64; 1]> = (0..60)
            .map(|k| [1.0 + 0.5 * 0.9f64.powi(k) * [1.0, -0.5, 0.2][k as usize % 3]])
            .collect();
        let v = section_verdict(&pts, 1.0, &cfg);
        assert!(v.converging, "{v:?}");
        // Settled period-2.
        let p2: Vec<[f64; 1]> = (0..60).map(|k| [if k % 2 == 0 { 0.0 } else { 1.0 }]).collect();
        assert_eq!(
            section_verdict(&p2, 1.0, &cfg),
            SectionVerdict {
                period: Some(2),
                converging: false
            }
        );
        // A period-8 orbit with a 0.037 um split on a 100 um orbit is period 8.
        let p8: Vec<[f64; 1]> = (0..80)
            .map(|k| [50e-6 + if k % 8 == 0 { 0.037e-6 } else { 0.0 } + 1e-6 * (k % 4) as f64])
            .collect();
        assert_eq!(section_verdict(&p8, 100e-6, &cfg).period, Some(8));
        let ev = |l: f64, se: f64, k: Option<f64>| ChaosEvidence {
            lyapunov_per_period: Some(l),
            lyapunov_stderr_per_period: Some(se),
            zero_one_k: k,
        };
        assert_eq!(chaos_verdict(&ev(0.05, 0.005, Some(0.9)), &cfg), Motion::Chaotic);
        assert_eq!(chaos_verdict(&ev(0.05, 0.02, Some(0.9)), &cfg), Motion::QuasiPeriodic);
        assert_eq!(chaos_verdict(&ev(0.05, 0.005, Some(0.1)), &cfg), Motion::QuasiPeriodic);
        assert_eq!(chaos_verdict(&ev(-0.05, 0.001, None), &cfg), Motion::QuasiPeriodic);
        let bad = ClassifyConfig {
            converging_ratio: 1.5,
            ..cfg
        };
        assert!(bad.check().unwrap_err().to_string().contains("converging_ratio"));
    }
}
