//! Classification of a steady motion from its Poincare section.
//!
//! Rule (in this order):
//! 1. Period-n (n = 1..max_period): the smallest n with
//!    `|x_{k+n,i} - x_{k,i}| <= rel_tol * s_i` for every recorded section point
//!    k and state i, where `s_i` is the state's range over one period (an
//!    amplitude scale; states that do not move are skipped).
//! 2. Otherwise chaotic if the largest Lyapunov exponent (per excitation
//!    period) is known and exceeds `lyapunov_threshold_per_period`,
//!    quasi-periodic if it is known and does not.
//! 3. Without an exponent, the 0-1 test for chaos on the section observable
//!    (Gottwald & Melbourne 2004, Proc. R. Soc. A 460, 603-611; correlation
//!    form of Gottwald & Melbourne 2009, SIAM J. Appl. Dyn. Syst. 8, 129-145):
//!    K > `zero_one_threshold` -> chaotic, else quasi-periodic. It needs a few
//!    hundred section points to be reliable: with fewer than
//!    [`MIN_ZERO_ONE_POINTS`] the motion is reported quasi-periodic. The sweeps
//!    therefore compute a Lyapunov exponent for every non-periodic speed by
//!    default.
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

/// Classifier settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ClassifyConfig {
    /// Relative tolerance of the period test (-).
    pub rel_tol: f64,
    /// Largest period tested.
    pub max_period: usize,
    /// Lyapunov exponent per excitation period above which motion is chaotic.
    pub lyapunov_threshold_per_period: f64,
    /// 0-1 test threshold on K.
    pub zero_one_threshold: f64,
}

impl Default for ClassifyConfig {
    /// rel_tol 1e-3; max period 16; lambda T > 0.01 (1 % growth per period,
    /// above the ~1e-3 finite-time noise of a 100-period estimate of a regular
    /// orbit); K > 0.5.
    fn default() -> Self {
        ClassifyConfig {
            rel_tol: 1e-3,
            max_period: 16,
            lyapunov_threshold_per_period: 0.01,
            zero_one_threshold: 0.5,
        }
    }
}

impl ClassifyConfig {
    /// Validate.
    pub fn check(&self) -> Result<()> {
        positive("rel_tol", self.rel_tol)?;
        if self.max_period == 0 {
            return Err(Error::config("max_period", 0, "must be at least 1"));
        }
        crate::error::finite("lyapunov_threshold_per_period", self.lyapunov_threshold_per_period)?;
        crate::error::in_range("zero_one_threshold", self.zero_one_threshold, 0.0, 1.0)?;
        Ok(())
    }
}

/// Smallest period n <= `max_period` of a sequence of section points (each
/// of length `scale.len()`), or None. Needs at least `n + 1` points per tested n.
pub fn detect_period<P: AsRef<[f64]>>(points: &[P], scale: &[f64], rel_tol: f64, max_period: usize) -> Option<usize> {
    let active: Vec<usize> = (0..scale.len())
        .filter(|&i| scale[i] > 0.0 && scale[i].is_finite())
        .collect();
    if active.is_empty() {
        return if points.len() >= 2 { Some(1) } else { None };
    }
    (1..=max_period).find(|&n| {
        points.len() > n
            && (0..points.len() - n).all(|k| {
                let (a, b) = (points[k].as_ref(), points[k + n].as_ref());
                active.iter().all(|&i| (a[i] - b[i]).abs() <= rel_tol * scale[i])
            })
    })
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

/// Classify by the rule in the module docs. `lyapunov_per_period` is the
/// largest exponent times the excitation period, if known.
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
    match lyapunov_per_period {
        Some(l) if l > cfg.lyapunov_threshold_per_period => Motion::Chaotic,
        Some(_) => Motion::QuasiPeriodic,
        None if observable.len() >= MIN_ZERO_ONE_POINTS && zero_one_test(observable) > cfg.zero_one_threshold => {
            Motion::Chaotic
        }
        None => Motion::QuasiPeriodic,
    }
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
}
