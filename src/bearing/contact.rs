//! Hertz point contact between a ball and a raceway (docs/concepts/physics.md §2;
//! Harris & Kotzalas, Rolling Bearing Analysis, ch. 6; Hamrock & Brewe,
//! J. Lubr. Technol. 105 (1983) for the closed forms).
//!
//! The ellipticity kappa = a/b is found from the exact relation between the
//! curvature difference F(rho) and the complete elliptic integrals; the
//! Hamrock-Brewe closed forms give the starting value.

use std::f64::consts::{FRAC_PI_2, PI};

use crate::error::{Error, Result};

/// Which raceway a ball touches.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Raceway {
    /// Inner-ring raceway: convex in the rolling direction, so its rolling
    /// curvature adds to the ball's.
    Inner,
    /// Outer-ring raceway: concave in the rolling direction, so its rolling
    /// curvature is negative.
    Outer,
}

/// Complete elliptic integrals of the first and second kind, K(m) and E(m),
/// with parameter m = k^2 (0 <= m < 1), by the arithmetic-geometric mean.
/// Exact to machine precision (Abramowitz & Stegun 17.6).
pub fn elliptic_ke(m: f64) -> (f64, f64) {
    debug_assert!((0.0..1.0).contains(&m));
    let mut a = 1.0;
    let mut b = (1.0 - m).sqrt();
    let mut c = m.sqrt();
    let mut sum = 0.5 * c * c; // 2^(n-1) c_n^2 with n = 0
    let mut pow2 = 0.5;
    for _ in 0..40 {
        if c.abs() < 1e-16 * a {
            break;
        }
        let an = 0.5 * (a + b);
        let bn = (a * b).sqrt();
        c = 0.5 * (a - b);
        a = an;
        b = bn;
        pow2 *= 2.0;
        sum += pow2 * c * c;
    }
    let k = PI / (2.0 * a);
    (k, k * (1.0 - sum))
}

/// Curvature sum and difference of a ball on a raceway.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Curvature {
    /// Curvature sum, sum rho [1/m].
    pub sum: f64,
    /// Curvature difference F(rho) [-], 0 <= F < 1.
    pub difference: f64,
    /// Effective radius in the rolling direction Rx \[m\].
    pub rx: f64,
    /// Effective radius across the rolling direction Ry \[m\].
    pub ry: f64,
}

/// Curvature of a ball of diameter `d` on the `raceway` of a bearing with
/// pitch diameter `dm`, groove conformity `f` (groove radius = f d) and
/// contact angle `alpha` (docs/concepts/physics.md §2).
pub fn curvature(raceway: Raceway, d: f64, dm: f64, f: f64, alpha: f64) -> Curvature {
    let gamma = d * alpha.cos() / dm;
    let rho_ball = 2.0 / d;
    let rho_groove = -1.0 / (f * d);
    let rho_roll = match raceway {
        Raceway::Inner => (2.0 / d) * gamma / (1.0 - gamma),
        Raceway::Outer => -(2.0 / d) * gamma / (1.0 + gamma),
    };
    let sum = 2.0 * rho_ball + rho_roll + rho_groove;
    // F(rho) = ((rho_I1 - rho_I2) + (rho_II1 - rho_II2)) / sum rho; the ball's
    // two principal curvatures are equal, so the first bracket vanishes.
    let difference = (rho_roll - rho_groove) / sum;
    Curvature {
        sum,
        difference,
        rx: 1.0 / (rho_ball + rho_roll),
        ry: 1.0 / (rho_ball + rho_groove),
    }
}

/// The exact F(rho) produced by an ellipticity kappa >= 1:
/// F = ((kappa^2 + 1) E - 2 K) / ((kappa^2 - 1) E) with m = 1 - 1/kappa^2.
pub fn curvature_difference_of(kappa: f64) -> f64 {
    if kappa <= 1.0 + 1e-12 {
        return 0.0;
    }
    let k2 = kappa * kappa;
    let (kk, ee) = elliptic_ke(1.0 - 1.0 / k2);
    ((k2 + 1.0) * ee - 2.0 * kk) / ((k2 - 1.0) * ee)
}

/// Hamrock-Brewe closed forms (kappa, E, K) from the radius ratio Ry/Rx >= 1.
pub fn hamrock_brewe(ry_over_rx: f64) -> (f64, f64, f64) {
    let kappa = 1.0339 * ry_over_rx.powf(0.636);
    let e = 1.0003 + 0.5968 / ry_over_rx;
    let k = 1.5277 + 0.6023 * ry_over_rx.ln();
    (kappa, e, k)
}

/// Ellipticity and elliptic integrals of a contact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ellipse {
    /// kappa = a / b >= 1.
    pub kappa: f64,
    /// Complete elliptic integral of the first kind (the seed's Gamma).
    pub k_first: f64,
    /// Complete elliptic integral of the second kind (the seed's Pi).
    pub e_second: f64,
}

/// Solve the exact ellipticity relation for kappa given F(rho), starting
/// from Hamrock-Brewe, by safeguarded Newton on ln(kappa).
pub fn ellipse(c: &Curvature) -> Result<Ellipse> {
    let f = c.difference;
    if !(0.0..1.0).contains(&f) || !f.is_finite() {
        return Err(Error::config("curvature_difference", f, "F(rho) must lie in [0, 1)"));
    }
    if f < 1e-12 {
        return Ok(Ellipse {
            kappa: 1.0,
            k_first: FRAC_PI_2,
            e_second: FRAC_PI_2,
        });
    }
    let ratio = (c.ry / c.rx).max(1.0);
    // Bracket in x = ln(kappa); F(kappa) increases monotonically from 0 to 1.
    let mut lo = 0.0_f64;
    let mut hi = 12.0_f64; // kappa up to e^12, far beyond any bearing contact
    let mut x = hamrock_brewe(ratio).0.max(1.0 + 1e-9).ln().clamp(1e-9, hi);
    for _ in 0..100 {
        let g = curvature_difference_of(x.exp()) - f;
        if g.abs() < 1e-14 {
            break;
        }
        if g > 0.0 {
            hi = x;
        } else {
            lo = x;
        }
        // Newton step with a central-difference slope, kept inside the bracket.
        let h = 1e-6 * x.max(1e-3);
        let slope = (curvature_difference_of((x + h).exp()) - curvature_difference_of((x - h).exp())) / (2.0 * h);
        let mut xn = x - g / slope;
        if !(xn > lo && xn < hi && xn.is_finite()) {
            xn = 0.5 * (lo + hi);
        }
        if (xn - x).abs() < 1e-15 * x.max(1.0) {
            x = xn;
            break;
        }
        x = xn;
    }
    let kappa = x.exp();
    let (kk, ee) = elliptic_ke(1.0 - 1.0 / (kappa * kappa));
    Ok(Ellipse {
        kappa,
        k_first: kk,
        e_second: ee,
    })
}

/// A solved Hertz contact geometry: everything that does not depend on load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzContact {
    /// Curvature sum and difference of the ball-raceway pair.
    pub curvature: Curvature,
    /// Ellipticity kappa and elliptic integrals: exact ([`HertzContact::new`])
    /// or Hamrock-Brewe ([`HertzContact::approximate`]).
    pub ellipse: Ellipse,
    /// Reduced modulus E' = 2 / ((1-nu1^2)/E1 + (1-nu2^2)/E2) \[Pa\].
    pub reduced_modulus_pa: f64,
    /// Load-deflection constant K in Q = K delta^1.5 [N/m^1.5].
    pub k_load_deflection: f64,
}

impl HertzContact {
    /// Build from curvature and reduced modulus with the exact ellipticity.
    pub fn new(curvature: Curvature, reduced_modulus_pa: f64) -> Result<Self> {
        let ellipse = ellipse(&curvature)?;
        Ok(Self::from_parts(curvature, ellipse, reduced_modulus_pa))
    }

    /// Build with the Hamrock-Brewe closed forms instead of the exact solve.
    pub fn approximate(curvature: Curvature, reduced_modulus_pa: f64) -> Self {
        let (kappa, e, k) = hamrock_brewe((curvature.ry / curvature.rx).max(1.0));
        Self::from_parts(
            curvature,
            Ellipse {
                kappa,
                k_first: k,
                e_second: e,
            },
            reduced_modulus_pa,
        )
    }

    fn from_parts(curvature: Curvature, ellipse: Ellipse, ep: f64) -> Self {
        let Ellipse {
            kappa,
            k_first,
            e_second,
        } = ellipse;
        // K = (pi kappa E' / 3) sqrt(2 E / (F^3 sum rho))   (docs/concepts/physics.md §2, A-1)
        let k = PI * kappa * ep / 3.0 * (2.0 * e_second / (k_first.powi(3) * curvature.sum)).sqrt();
        HertzContact {
            curvature,
            ellipse,
            reduced_modulus_pa: ep,
            k_load_deflection: k,
        }
    }

    /// Normal load for an approach delta \[N\]; zero when delta <= 0.
    #[inline]
    pub fn load(&self, delta: f64) -> f64 {
        if delta > 0.0 {
            self.k_load_deflection * delta * delta.sqrt()
        } else {
            0.0
        }
    }

    /// Approach for a load Q \[m\].
    #[inline]
    pub fn deflection(&self, q: f64) -> f64 {
        if q > 0.0 {
            (q / self.k_load_deflection).powf(2.0 / 3.0)
        } else {
            0.0
        }
    }

    /// Tangent contact stiffness dQ/d delta = 1.5 K^(2/3) Q^(1/3) (A-1) [N/m].
    #[inline]
    pub fn stiffness(&self, q: f64) -> f64 {
        if q > 0.0 {
            1.5 * self.k_load_deflection.powf(2.0 / 3.0) * q.cbrt()
        } else {
            0.0
        }
    }

    /// Semi-major axis a of the contact ellipse under load Q \[m\]:
    /// a = (6 kappa^2 E Q / (pi sum rho E'))^(1/3).
    pub fn semi_major(&self, q: f64) -> f64 {
        let Ellipse { kappa, e_second, .. } = self.ellipse;
        (6.0 * kappa * kappa * e_second * q.max(0.0) / (PI * self.curvature.sum * self.reduced_modulus_pa)).cbrt()
    }

    /// Semi-minor axis b = a / kappa \[m\].
    pub fn semi_minor(&self, q: f64) -> f64 {
        self.semi_major(q) / self.ellipse.kappa
    }

    /// Maximum contact pressure p0 = 3 Q / (2 pi a b) \[Pa\].
    pub fn max_pressure(&self, q: f64) -> f64 {
        let a = self.semi_major(q);
        if a <= 0.0 {
            return 0.0;
        }
        1.5 * q / (PI * a * self.semi_minor(q))
    }
}

/// Series load-deflection constant of a ball between two raceways,
/// K_n = (K_i^(-2/3) + K_o^(-2/3))^(-3/2).
pub fn series_constant(k_inner: f64, k_outer: f64) -> f64 {
    (k_inner.powf(-2.0 / 3.0) + k_outer.powf(-2.0 / 3.0)).powf(-1.5)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn elliptic_integrals_known_values() {
        let (k, e) = elliptic_ke(0.0);
        assert!((k - FRAC_PI_2).abs() < 1e-15 && (e - FRAC_PI_2).abs() < 1e-15);
        // A&S table 17.1: m = 0.5 -> K = 1.854074677301372, E = 1.350643881047675
        let (k, e) = elliptic_ke(0.5);
        assert!((k - 1.854_074_677_301_372).abs() < 1e-13, "{k}");
        assert!((e - 1.350_643_881_047_675).abs() < 1e-13, "{e}");
        // m = 0.9: K = 2.578092113348173, E = 1.104774732704073
        let (k, e) = elliptic_ke(0.9);
        assert!((k - 2.578_092_113_348_173).abs() < 1e-12 && (e - 1.104_774_732_704_073).abs() < 1e-12);
    }

    #[test]
    fn exact_ellipticity_inverts_the_relation() {
        for &(f, d, dm, alpha) in &[
            (0.52, 12e-3, 60e-3, 0.0),
            (0.53, 12e-3, 60e-3, 0.3),
            (0.515, 8e-3, 54e-3, 0.26),
        ] {
            for r in [Raceway::Inner, Raceway::Outer] {
                let c = curvature(r, d, dm, f, alpha);
                let el = ellipse(&c).unwrap();
                assert!((curvature_difference_of(el.kappa) - c.difference).abs() < 1e-12);
                // Hamrock-Brewe within their stated few-percent accuracy.
                let (kap, e, k) = hamrock_brewe(c.ry / c.rx);
                assert!((kap / el.kappa - 1.0).abs() < 0.03, "kappa {kap} vs {}", el.kappa);
                assert!((e / el.e_second - 1.0).abs() < 0.03);
                assert!((k / el.k_first - 1.0).abs() < 0.03);
            }
        }
    }

    #[test]
    fn sphere_limit_matches_classical_hertz() {
        // Two equal spheres: F(rho) = 0, kappa = 1, delta = (9 Q^2 sum_rho / (8 E'^2))^(1/3).
        let c = Curvature {
            sum: 4.0 / 0.01,
            difference: 0.0,
            rx: 0.005,
            ry: 0.005,
        };
        let ep = 2.0 * 210e9 / (1.0 - 0.09);
        let h = HertzContact::new(c, ep).unwrap();
        let q = 500.0;
        let delta = (9.0 * q * q * c.sum / (8.0 * ep * ep)).cbrt();
        assert!((h.deflection(q) / delta - 1.0).abs() < 1e-12);
        // a = b = (3 Q R*/(4 E*))^(1/3) with R* = 2/sum_rho, E* = E'/2.
        let a = (3.0 * q * (2.0 / c.sum) / (4.0 * ep / 2.0)).cbrt();
        assert!((h.semi_major(q) / a - 1.0).abs() < 1e-12);
    }

    #[test]
    fn tangent_stiffness_is_derivative_of_load() {
        let c = curvature(Raceway::Inner, 12e-3, 60e-3, 0.52, 0.2);
        let h = HertzContact::new(c, 228e9).unwrap();
        let delta = 8e-6;
        let q = h.load(delta);
        let eps = 1e-11;
        let fd = (h.load(delta + eps) - h.load(delta - eps)) / (2.0 * eps);
        assert!((h.stiffness(q) / fd - 1.0).abs() < 1e-6);
        assert!((h.deflection(q) / delta - 1.0).abs() < 1e-12);
        assert_eq!(h.load(-1e-6), 0.0);
    }

    #[test]
    fn series_constant_equals_sum_of_deflections() {
        let (ki, ko) = (9.0e9, 8.0e9);
        let kn = series_constant(ki, ko);
        let q = 700.0_f64;
        let d = (q / ki).powf(2.0 / 3.0) + (q / ko).powf(2.0 / 3.0);
        assert!((kn * d.powf(1.5) / q - 1.0).abs() < 1e-12);
    }
}
