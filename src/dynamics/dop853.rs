//! Adaptive DOP853: explicit Runge-Kutta of order 8 with the 5th/3rd-order
//! combined error estimate of Hairer's DOP853 (Hairer, Norsett & Wanner,
//! *Solving ODEs I*, 2nd ed., section II.10). No dense output. Used as the
//! high-accuracy reference for the fixed-step RK4 runs.

use super::integrate::{AdaptiveStats, AdaptiveTolerance};
use super::ode::OdeSystem;
use crate::{Error, Result};

// Dormand-Prince RK8(7)13M as used in Hairer's DOP853 (Hairer, Norsett &
// Wanner, Solving ODEs I, 2nd ed., section II.10; dop853.f). Numbers are
// the published tableau, printed to f64 precision from the table SciPy
// ships (scipy/integrate/_ivp/dop853_coefficients.py).
const C: [f64; 12] = [
    0.0,
    0.05260015195876773,
    0.0789002279381516,
    0.1183503419072274,
    0.2816496580927726,
    0.3333333333333333,
    0.25,
    0.3076923076923077,
    0.6512820512820513,
    0.6,
    0.8571428571428571,
    1.0,
];
const A: [[f64; 12]; 12] = [
    [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [
        0.05260015195876773,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        0.0197250569845379,
        0.0591751709536137,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        0.02958758547680685,
        0.0,
        0.08876275643042054,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        0.2413651341592667,
        0.0,
        -0.8845494793282861,
        0.924834003261792,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        0.037037037037037035,
        0.0,
        0.0,
        0.17082860872947386,
        0.12546768756682242,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        0.037109375,
        0.0,
        0.0,
        0.17025221101954405,
        0.06021653898045596,
        -0.017578125,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        0.03709200011850479,
        0.0,
        0.0,
        0.17038392571223998,
        0.10726203044637328,
        -0.015319437748624402,
        0.008273789163814023,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        0.6241109587160757,
        0.0,
        0.0,
        -3.3608926294469414,
        -0.868219346841726,
        27.59209969944671,
        20.154067550477894,
        -43.48988418106996,
        0.0,
        0.0,
        0.0,
        0.0,
    ],
    [
        0.47766253643826434,
        0.0,
        0.0,
        -2.4881146199716677,
        -0.590290826836843,
        21.230051448181193,
        15.279233632882423,
        -33.28821096898486,
        -0.020331201708508627,
        0.0,
        0.0,
        0.0,
    ],
    [
        -0.9371424300859873,
        0.0,
        0.0,
        5.186372428844064,
        1.0914373489967295,
        -8.149787010746927,
        -18.52006565999696,
        22.739487099350505,
        2.4936055526796523,
        -3.0467644718982196,
        0.0,
        0.0,
    ],
    [
        2.273310147516538,
        0.0,
        0.0,
        -10.53449546673725,
        -2.0008720582248625,
        -17.9589318631188,
        27.94888452941996,
        -2.8589982771350235,
        -8.87285693353063,
        12.360567175794303,
        0.6433927460157636,
        0.0,
    ],
];
const B: [f64; 12] = [
    0.054293734116568765,
    0.0,
    0.0,
    0.0,
    0.0,
    4.450312892752409,
    1.8915178993145003,
    -5.801203960010585,
    0.3111643669578199,
    -0.1521609496625161,
    0.20136540080403034,
    0.04471061572777259,
];
/// 5th-order error weights over the 12 stages and f(t + h, x_new).
const E5: [f64; 13] = [
    0.01312004499419488,
    0.0,
    0.0,
    0.0,
    0.0,
    -1.2251564463762044,
    -0.4957589496572502,
    1.6643771824549864,
    -0.35032884874997366,
    0.3341791187130175,
    0.08192320648511571,
    -0.022355307863886294,
    0.0,
];
/// 3rd-order error weights (same stages).
const E3: [f64; 13] = [
    -0.18980075407240762,
    0.0,
    0.0,
    0.0,
    0.0,
    4.450312892752409,
    1.8915178993145003,
    -5.801203960010585,
    -0.4226823213237919,
    -0.1521609496625161,
    0.20136540080403034,
    0.02265179219836082,
    0.0,
];

/// Integrate `x` from `t0` to `t1` (> t0) with adaptive DOP853. Error norm
/// (Hairer): `err = h * |e5|^2 / sqrt((|e5|^2 + 0.01 |e3|^2) N)` with the
/// weighted norms of the two embedded estimates; accept if `err <= 1`; step
/// factor `0.9 err^(-1/8)` limited to [0.2, 10]. `Error::Convergence` if
/// `max_steps` is exhausted or the step size underflows.
pub fn dop853<const N: usize, S: OdeSystem<N>>(
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
    let span = t1 - t0;
    let mut stats = AdaptiveStats::default();
    let mut k = [[0.0; N]; 13];
    sys.rhs(t0, x, &mut k[0]);
    stats.evaluations += 1;
    let mut h = super::integrate::initial_step(sys, t0, x, tol, span);
    let mut t = t0;
    let mut y = [0.0; N];
    let mut xn = [0.0; N];
    let mut last_err = f64::INFINITY;
    while t < t1 {
        if stats.accepted + stats.rejected >= tol.max_steps {
            return Err(Error::convergence("dop853", tol.max_steps, last_err, 1.0));
        }
        let last = t + h >= t1;
        if last {
            h = t1 - t;
        }
        for s in 1..12 {
            for i in 0..N {
                let mut acc = 0.0;
                for (r, kr) in k.iter().enumerate().take(s) {
                    acc += A[s][r] * kr[i];
                }
                y[i] = x[i] + h * acc;
            }
            let (_, rest) = k.split_at_mut(s);
            sys.rhs(t + C[s] * h, &y, &mut rest[0]);
        }
        for i in 0..N {
            let mut acc = 0.0;
            for (s, ks) in k.iter().enumerate().take(12) {
                acc += B[s] * ks[i];
            }
            xn[i] = x[i] + h * acc;
        }
        let (_, tail) = k.split_at_mut(12);
        sys.rhs(t + h, &xn, &mut tail[0]);
        stats.evaluations += 12;
        let (mut e5, mut e3) = (0.0, 0.0);
        for i in 0..N {
            let sc = tol.atol[i] + tol.rtol * x[i].abs().max(xn[i].abs());
            let (mut a5, mut a3) = (0.0, 0.0);
            for (s, ks) in k.iter().enumerate() {
                a5 += E5[s] * ks[i];
                a3 += E3[s] * ks[i];
            }
            e5 += (a5 / sc).powi(2);
            e3 += (a3 / sc).powi(2);
        }
        let err = if e5 == 0.0 && e3 == 0.0 {
            0.0
        } else {
            h.abs() * e5 / ((e5 + 0.01 * e3) * N as f64).sqrt()
        };
        last_err = err;
        if !err.is_finite() {
            return Err(Error::convergence("dop853", stats.accepted, err, 1.0));
        }
        let fac = if err == 0.0 {
            10.0
        } else {
            (0.9 * err.powf(-1.0 / 8.0)).clamp(0.2, 10.0)
        };
        if err <= 1.0 {
            stats.accepted += 1;
            t = if last { t1 } else { t + h };
            *x = xn;
            k[0] = k[12];
            h *= fac;
        } else {
            stats.rejected += 1;
            h *= fac.min(1.0);
        }
        if t < t1 && h < 1e-14 * span.max(t.abs()) {
            return Err(Error::convergence(
                "dop853 (step size underflow)",
                stats.accepted,
                err,
                1.0,
            ));
        }
    }
    Ok(stats)
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::dynamics::ode::test_systems::Harmonic;

    #[test]
    fn tableau_is_consistent() {
        // Row sums of A equal C (internal consistency), weights sum to 1,
        // error weights annihilate constants (sum to 0).
        for s in 0..12 {
            let row: f64 = A[s].iter().sum();
            assert!((row - C[s]).abs() < 1e-14, "row {s}: {row} vs {}", C[s]);
        }
        assert!((B.iter().sum::<f64>() - 1.0).abs() < 1e-14);
        // Order conditions sum b_i c_i^(q-1) = 1/q up to q = 8.
        for q in 1..=8 {
            let v: f64 = (0..12).map(|s| B[s] * C[s].powi(q - 1)).sum();
            assert!((v - 1.0 / q as f64).abs() < 1e-13, "q {q}: {v}");
        }
        assert!(E5.iter().sum::<f64>().abs() < 1e-14 && E3.iter().sum::<f64>().abs() < 1e-14);
    }

    #[test]
    fn dop853_reaches_tight_tolerance_with_few_steps() {
        let w = 3.0;
        let tol = AdaptiveTolerance {
            rtol: 1e-12,
            atol: [1e-14; 2],
            max_steps: 100_000,
        };
        let mut x = [1.0, 0.0];
        let st = dop853(&Harmonic(w), 0.0, 10.0, &mut x, &tol).unwrap();
        assert!((x[0] - 30f64.cos()).abs() < 1e-10, "{x:?}");
        assert!((x[1] + w * 30f64.sin()).abs() < 1e-9);
        // Eighth order: far fewer steps than DOPRI5 at the same tolerance.
        let mut y = [1.0, 0.0];
        let st5 = crate::dynamics::integrate::dopri5(&Harmonic(w), 0.0, 10.0, &mut y, &tol).unwrap();
        assert!(
            st.accepted * 3 < st5.accepted,
            "dop853 {} vs dopri5 {}",
            st.accepted,
            st5.accepted
        );
    }
}
