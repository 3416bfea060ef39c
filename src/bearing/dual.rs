//! Forward-mode dual numbers: a value with its N partial derivatives.
//!
//! The bearing solvers write each residual once, over [`Dual`], and get the
//! exact analytic Jacobian by the chain rule (no finite differences, no
//! truncation error). Tests compare every Jacobian against central finite
//! differences.

use std::ops::{Add, Div, Mul, Neg, Sub};

/// A value `v` and its gradient `d` with respect to N independent variables.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Dual<const N: usize> {
    /// Function value.
    pub v: f64,
    /// Partial derivatives dv/dx_i with respect to the N independent variables.
    pub d: [f64; N],
}

impl<const N: usize> Dual<N> {
    /// A constant (zero gradient).
    #[inline]
    pub fn cst(v: f64) -> Self {
        Dual { v, d: [0.0; N] }
    }

    /// The independent variable number `i` with value `v`.
    #[inline]
    pub fn var(v: f64, i: usize) -> Self {
        let mut d = [0.0; N];
        d[i] = 1.0;
        Dual { v, d }
    }

    /// Apply a scalar function with value `f` and derivative `df` at `self.v`.
    #[inline]
    pub fn map(self, f: f64, df: f64) -> Self {
        self.chain(f, df)
    }

    #[inline]
    fn chain(self, f: f64, df: f64) -> Self {
        let mut d = self.d;
        for x in d.iter_mut() {
            *x *= df;
        }
        Dual { v: f, d }
    }

    /// Square root, derivative 1 / (2 sqrt v); the gradient is set to zero
    /// where sqrt v is not positive (no infinite slope at v = 0).
    #[inline]
    pub fn sqrt(self) -> Self {
        let s = self.v.sqrt();
        self.chain(s, if s > 0.0 { 0.5 / s } else { 0.0 })
    }

    /// x^1.5 for x > 0, 0 otherwise (Hertz law; C1 at 0).
    #[inline]
    pub fn pow1_5_pos(self) -> Self {
        if self.v > 0.0 {
            let s = self.v.sqrt();
            self.chain(self.v * s, 1.5 * s)
        } else {
            Dual::cst(0.0)
        }
    }

    /// Natural logarithm, derivative 1 / v (v > 0).
    #[inline]
    pub fn ln(self) -> Self {
        self.chain(self.v.ln(), 1.0 / self.v)
    }

    /// Real power v^p, derivative p v^(p - 1).
    #[inline]
    pub fn powf(self, p: f64) -> Self {
        let f = self.v.powf(p);
        self.chain(f, p * self.v.powf(p - 1.0))
    }

    /// Exponential e^v, derivative e^v.
    #[inline]
    pub fn exp(self) -> Self {
        let e = self.v.exp();
        self.chain(e, e)
    }

    /// Reciprocal 1 / v, derivative -1 / v^2.
    #[inline]
    pub fn recip(self) -> Self {
        let r = 1.0 / self.v;
        self.chain(r, -r * r)
    }

    /// Integer power v^n, derivative n v^(n - 1).
    #[inline]
    pub fn powi(self, n: i32) -> Self {
        let p = self.v.powi(n);
        self.chain(p, n as f64 * self.v.powi(n - 1))
    }
}

impl<const N: usize> Add for Dual<N> {
    type Output = Self;
    #[inline]
    fn add(mut self, o: Self) -> Self {
        self.v += o.v;
        for i in 0..N {
            self.d[i] += o.d[i];
        }
        self
    }
}

impl<const N: usize> Sub for Dual<N> {
    type Output = Self;
    #[inline]
    fn sub(mut self, o: Self) -> Self {
        self.v -= o.v;
        for i in 0..N {
            self.d[i] -= o.d[i];
        }
        self
    }
}

impl<const N: usize> Mul for Dual<N> {
    type Output = Self;
    #[inline]
    fn mul(self, o: Self) -> Self {
        let mut d = [0.0; N];
        for (i, x) in d.iter_mut().enumerate() {
            *x = self.d[i] * o.v + self.v * o.d[i];
        }
        Dual { v: self.v * o.v, d }
    }
}

impl<const N: usize> Div for Dual<N> {
    type Output = Self;
    #[inline]
    fn div(self, o: Self) -> Self {
        let inv = 1.0 / o.v;
        let q = self.v * inv;
        let mut d = [0.0; N];
        for (i, x) in d.iter_mut().enumerate() {
            *x = (self.d[i] - q * o.d[i]) * inv;
        }
        Dual { v: q, d }
    }
}

impl<const N: usize> Neg for Dual<N> {
    type Output = Self;
    #[inline]
    fn neg(mut self) -> Self {
        self.v = -self.v;
        for x in self.d.iter_mut() {
            *x = -*x;
        }
        self
    }
}

impl<const N: usize> Add<f64> for Dual<N> {
    type Output = Self;
    #[inline]
    fn add(mut self, o: f64) -> Self {
        self.v += o;
        self
    }
}

impl<const N: usize> Sub<f64> for Dual<N> {
    type Output = Self;
    #[inline]
    fn sub(mut self, o: f64) -> Self {
        self.v -= o;
        self
    }
}

impl<const N: usize> Mul<f64> for Dual<N> {
    type Output = Self;
    #[inline]
    fn mul(mut self, o: f64) -> Self {
        self.v *= o;
        for x in self.d.iter_mut() {
            *x *= o;
        }
        self
    }
}

impl<const N: usize> Div<f64> for Dual<N> {
    type Output = Self;
    #[inline]
    fn div(self, o: f64) -> Self {
        self * (1.0 / o)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn derivatives_match_finite_differences() {
        // f(x, y) = sqrt(x^2 + y^2)^1.5 / (1 + x y) + exp(-y) x^3
        let f = |x: Dual<2>, y: Dual<2>| (x * x + y * y).sqrt().pow1_5_pos() / (x * y + 1.0) + (-y).exp() * x.powi(3);
        let (x0, y0) = (0.7, 1.3);
        let r = f(Dual::var(x0, 0), Dual::var(y0, 1));
        let h = 1e-6;
        let g = |x: f64, y: f64| f(Dual::cst(x), Dual::cst(y)).v;
        let fx = (g(x0 + h, y0) - g(x0 - h, y0)) / (2.0 * h);
        let fy = (g(x0, y0 + h) - g(x0, y0 - h)) / (2.0 * h);
        assert!((r.d[0] - fx).abs() < 1e-8 && (r.d[1] - fy).abs() < 1e-8);
        // Hertz power is zero with zero slope for negative approach.
        let z = Dual::<1>::var(-1e-6, 0).pow1_5_pos();
        assert_eq!((z.v, z.d[0]), (0.0, 0.0));
        assert!((Dual::<1>::var(4.0, 0).recip().d[0] + 1.0 / 16.0).abs() < 1e-15);
    }
}
