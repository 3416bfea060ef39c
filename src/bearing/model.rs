//! A ball bearing prepared for the load solvers: geometry numbers, masses,
//! and the Hertz contact constants tabulated over the contact angle.
//!
//! # Coordinates (ISO/TS 16281 convention)
//!
//! z is the bearing axis, the radial load acts along x, ball j sits at
//! azimuth psi_j = 2 pi j / Z measured from x. The inner-ring displacement
//! relative to the outer ring is q = [dx, dy, dz, theta_x, theta_y] (m, rad),
//! measured from the concentric position with both groove curvature centres
//! of every ball in one radial plane, so taking up the clearance is part of
//! the displacement. At ball j the inner-to-outer groove-centre distance has
//! the components (docs/concepts/physics.md §3, A-5, A-11, A-38)
//!
//! ```text
//! A1j = dz + R_i (theta_x sin psi_j - theta_y cos psi_j) + u_Ta          (axial)
//! A2j = A cos alpha0 + dx cos psi_j + dy sin psi_j + u_r + u_Tr           (radial)
//! ```
//!
//! with A = B_f D and A cos alpha0 = A - Pd/2. Seed A (A-11) measures the
//! axial displacement from the position where the clearance is just taken up
//! axially (A1 = A sin alpha0 + delta_a), so `dz_ISO = dz_seed + A sin alpha0`.
//! The tilt terms follow from the small rotation theta x p of the groove
//! centre p = R_i (cos psi, sin psi, 0); a positive moment M_y tilts the
//! ring by a positive theta_y.
//!
//! # Contact constants
//!
//! The exact Hertz constants (`Bearing::inner_contact`, `outer_contact`)
//! depend on the contact angle through gamma = D cos(alpha) / dm. They are
//! tabulated once per bearing as Chebyshev series of ln K in c = cos(alpha)
//! over cos(85 deg) <= c <= 1 (10 nodes; the interpolation error is below
//! 1e-10, checked in the tests) and evaluated at the actual contact angle of
//! each contact, in both the static and the high-speed model, so the two
//! agree at zero speed. The semi-major-axis coefficient a / Q^(1/3) is
//! tabulated the same way.

use std::f64::consts::PI;

use super::dual::Dual;
use super::geometry::BearingType;
use super::Bearing;
use crate::error::{Error, Result};

/// Number of Chebyshev nodes per tabulated contact constant.
const CHEB_NODES: usize = 10;
/// Largest contact angle covered by the tables [deg]; beyond it the constants
/// are held at the end value.
const CHEB_MAX_ANGLE_DEG: f64 = 85.0;

/// A Chebyshev series of a smooth function of c = cos(alpha) on [c_lo, 1].
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ChebSeries {
    c_lo: f64,
    coef: [f64; CHEB_NODES],
}

impl ChebSeries {
    /// Interpolate `f` at the Chebyshev nodes of the first kind.
    fn fit(c_lo: f64, f: impl Fn(f64) -> Result<f64>) -> Result<Self> {
        let n = CHEB_NODES;
        let mut vals = [0.0; CHEB_NODES];
        for (k, v) in vals.iter_mut().enumerate() {
            let t = (PI * (k as f64 + 0.5) / n as f64).cos();
            let c = 0.5 * (1.0 + c_lo) + 0.5 * (1.0 - c_lo) * t;
            *v = f(c)?;
        }
        let mut coef = [0.0; CHEB_NODES];
        for (j, cj) in coef.iter_mut().enumerate() {
            let mut s = 0.0;
            for (k, v) in vals.iter().enumerate() {
                s += v * (PI * j as f64 * (k as f64 + 0.5) / n as f64).cos();
            }
            *cj = 2.0 * s / n as f64;
        }
        coef[0] *= 0.5;
        Ok(ChebSeries { c_lo, coef })
    }

    /// Value and derivative d/dc at c (clamped to the table range: zero
    /// slope outside), by the three-term recurrences of T_k and T_k'.
    #[inline]
    pub(crate) fn value_slope(&self, c: f64) -> (f64, f64) {
        if c > 1.0 || c < self.c_lo {
            return (self.value_slope(c.clamp(self.c_lo, 1.0)).0, 0.0);
        }
        let dt_dc = 2.0 / (1.0 - self.c_lo);
        let t = (c - 0.5 * (1.0 + self.c_lo)) * dt_dc;
        let (mut t0, mut t1) = (1.0, t);
        let (mut d0, mut d1) = (0.0, 1.0);
        let mut f = self.coef[0] + self.coef[1] * t;
        let mut df = self.coef[1];
        for &a in &self.coef[2..] {
            let t2 = 2.0 * t * t1 - t0;
            let d2 = 2.0 * t1 + 2.0 * t * d1 - d0;
            f += a * t2;
            df += a * d2;
            (t0, t1, d0, d1) = (t1, t2, d1, d2);
        }
        (f, df * dt_dc)
    }

    #[inline]
    pub(crate) fn eval_f64(&self, c: f64) -> f64 {
        self.value_slope(c).0
    }
}

/// Hertz constants of one raceway over the contact angle.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct ContactTable {
    /// ln K(c), K in Q = K delta^1.5 [N/m^1.5].
    ln_k: ChebSeries,
    /// ln(a / Q^(1/3)), semi-major axis coefficient [m/N^(1/3)].
    ln_a: ChebSeries,
}

impl ContactTable {
    fn new(contact: impl Fn(f64) -> Result<super::HertzContact>) -> Result<Self> {
        let c_lo = CHEB_MAX_ANGLE_DEG.to_radians().cos();
        let ln_k = ChebSeries::fit(c_lo, |c| Ok(contact(c.clamp(-1.0, 1.0).acos())?.k_load_deflection.ln()))?;
        let ln_a = ChebSeries::fit(c_lo, |c| Ok(contact(c.clamp(-1.0, 1.0).acos())?.semi_major(1.0).ln()))?;
        Ok(ContactTable { ln_k, ln_a })
    }

    /// Load-deflection constant K at cos(alpha) = c [N/m^1.5].
    #[inline]
    pub(crate) fn k<const N: usize>(&self, c: Dual<N>) -> Dual<N> {
        let (l, dl) = self.ln_k.value_slope(c.v);
        let k = l.exp();
        c.map(k, k * dl)
    }

    /// Hold K at its value for alpha = 0 (tests of the angle dependence).
    #[cfg(test)]
    pub(crate) fn freeze(&mut self) {
        let k0 = self.ln_k.eval_f64(1.0);
        self.ln_k.coef = [0.0; CHEB_NODES];
        self.ln_k.coef[0] = k0;
    }

    /// Semi-major axis of the contact ellipse under load q at cos(alpha) = c [m].
    pub(crate) fn semi_major_m(&self, c: f64, q: f64) -> f64 {
        if q <= 0.0 {
            return 0.0;
        }
        self.ln_a.eval_f64(c).exp() * q.cbrt()
    }
}

/// A bearing prepared for the solvers (build once, solve many times).
#[derive(Debug, Clone, PartialEq)]
pub struct BearingModel {
    pub(crate) bearing: Bearing,
    pub(crate) bearing_type: BearingType,
    /// (cos psi_j, sin psi_j) per ball.
    pub(crate) azimuth: Vec<(f64, f64)>,
    /// Ball diameter D [m].
    pub(crate) d: f64,
    /// Pitch diameter dm [m].
    pub(crate) dm: f64,
    /// (f_i - 0.5) D and (f_o - 0.5) D [m].
    pub(crate) ri_off: f64,
    pub(crate) ro_off: f64,
    /// Inner groove conformity f_i.
    pub(crate) fi: f64,
    /// A = B_f D [m].
    pub(crate) a0: f64,
    /// A cos alpha0 = A - Pd/2 [m].
    pub(crate) a0_radial: f64,
    /// R_i, radius of the locus of inner groove curvature centres [m].
    pub(crate) r_groove: f64,
    /// Ball mass [kg] and polar moment of inertia [kg m^2].
    pub(crate) ball_mass_kg: f64,
    pub(crate) ball_inertia_kg_m2: f64,
    /// Inner-raceway radial growth per omega^2 [m s^2] (A-10).
    pub(crate) expansion_m_s2: f64,
    pub(crate) inner: ContactTable,
    pub(crate) outer: ContactTable,
}

impl BearingModel {
    /// Prepare `bearing` (about 60 exact Hertz evaluations).
    pub fn new(bearing: &Bearing) -> Result<Self> {
        bearing.validate()?;
        let g = &bearing.geometry;
        let z = g.ball_count;
        let azimuth = (0..z)
            .map(|j| {
                let p = g.azimuth(j);
                (p.cos(), p.sin())
            })
            .collect();
        let a0 = g.curvature_centre_distance_m();
        let inner = ContactTable::new(|a| bearing.inner_contact(a))?;
        let outer = ContactTable::new(|a| bearing.outer_contact(a))?;
        Ok(BearingModel {
            bearing: bearing.clone(),
            bearing_type: g.bearing_type,
            azimuth,
            d: g.ball_diameter_m,
            dm: g.pitch_diameter_m,
            ri_off: (g.inner_conformity - 0.5) * g.ball_diameter_m,
            ro_off: (g.outer_conformity - 0.5) * g.ball_diameter_m,
            fi: g.inner_conformity,
            a0,
            a0_radial: a0 * g.free_contact_angle_rad.cos(),
            r_groove: g.inner_groove_centre_radius_m(),
            ball_mass_kg: bearing.ball_mass_kg(),
            ball_inertia_kg_m2: bearing.ball_inertia_kg_m2(),
            expansion_m_s2: inner_ring_expansion_per_omega2(bearing),
            inner,
            outer,
        })
    }

    /// The bearing this model was built from.
    pub fn bearing(&self) -> &Bearing {
        &self.bearing
    }

    /// Number of balls Z.
    pub fn ball_count(&self) -> usize {
        self.azimuth.len()
    }

    /// Series constant K_n of one ball loaded at the same angle on both
    /// raceways, from the tables (A-3) [N/m^1.5].
    pub fn ball_constant(&self, alpha_rad: f64) -> f64 {
        let c = Dual::<1>::cst(alpha_rad.cos());
        super::contact::series_constant(self.inner.k(c).v, self.outer.k(c).v)
    }

    /// K_n(c) of A-3 with its derivative, c = cos(alpha) (both contacts at alpha).
    #[inline]
    pub(crate) fn kn<const N: usize>(&self, c: Dual<N>) -> Dual<N> {
        let (li, dli) = self.inner.ln_k.value_slope(c.v);
        let (lo, dlo) = self.outer.ln_k.value_slope(c.v);
        let (ei, eo) = ((-2.0 / 3.0 * li).exp(), (-2.0 / 3.0 * lo).exp());
        let a = ei + eo;
        let da = -2.0 / 3.0 * (ei * dli + eo * dlo);
        let kn = a.powf(-1.5);
        c.map(kn, -1.5 * kn / a * da)
    }

    /// Radial growth of the inner raceway of the ring rotating at
    /// `speed_rad_s` (A-10) \[m\]. See [`inner_ring_expansion_per_omega2`].
    pub fn ring_expansion_m(&self, speed_rad_s: f64) -> f64 {
        self.expansion_m_s2 * speed_rad_s * speed_rad_s
    }

    /// Groove-centre distances (A1, A2) of ball j at displacement q plus the
    /// radial growth `u_r` and the thermal offsets (A-11, A-38) [m].
    #[inline]
    pub(crate) fn groove_distances(&self, j: usize, q: &[f64; 5], u_r: f64, off: &RacewayOffsets) -> (f64, f64) {
        let (c, s) = self.azimuth[j];
        let a1 = q[2] + self.r_groove * (q[3] * s - q[4] * c) + off.axial_m;
        let a2 = self.a0_radial + q[0] * c + q[1] * s + u_r + off.radial_m;
        (a1, a2)
    }

    /// d(A1)/dq and d(A2)/dq of ball j.
    #[inline]
    pub(crate) fn groove_gradients(&self, j: usize) -> ([f64; 5], [f64; 5]) {
        let (c, s) = self.azimuth[j];
        (
            [0.0, 0.0, 1.0, self.r_groove * s, -self.r_groove * c],
            [c, s, 0.0, 0.0, 0.0],
        )
    }

    /// Check a load vector [Fx, Fy, Fz, Mx, My] (N, N m).
    pub(crate) fn check_load(&self, load: &[f64; 5]) -> Result<()> {
        const NAMES: [&str; 5] = ["radial_x_n", "radial_y_n", "axial_n", "moment_x_n_m", "moment_y_n_m"];
        for (v, n) in load.iter().zip(NAMES) {
            crate::error::finite(n, *v)?;
        }
        if self.bearing_type == BearingType::AngularContact && load[2] < 0.0 {
            return Err(Error::config(
                "axial_n",
                load[2],
                "an angular-contact bearing carries axial load in one direction only (positive axial load loads the balls at positive contact angle)",
            ));
        }
        Ok(())
    }
}

/// Axial and radial offsets of the inner groove centres relative to the
/// outer ones that do not come from the ring displacement: thermal
/// expansion (A-38: u_Ta, u_Tr), fits, manufacturing offsets. Positive
/// values act like a positive dz and a positive radial approach.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RacewayOffsets {
    /// Axial offset u_Ta \[m\].
    pub axial_m: f64,
    /// Radial offset u_Tr (closes the clearance when positive) \[m\].
    pub radial_m: f64,
}

/// Radial growth of the inner raceway per unit omega^2 [m s^2] (A-10).
///
/// The inner ring is taken as a free rotating annular disc in plane stress,
/// bore radius a = d/2 and outer radius b = raceway groove-bottom radius,
/// Timoshenko & Goodier, Theory of Elasticity, 3rd ed., section 32:
/// sigma_r(b) = 0, sigma_theta(b) = rho omega^2 ((3 + nu) a^2 + (1 - nu) b^2) / 4,
/// so u(b) = b sigma_theta(b) / E. The shaft and the fit pressure are not
/// included: the rotating ring grows faster at its bore than a solid shaft
/// at its surface (u = (1 - nu) rho omega^2 a^3 / (4 E)), so the fit is
/// relieved and the ring expands as if free once the fit pressure has been
/// used up; the interference fit itself (a static offset) can be passed as
/// a [`RacewayOffsets::radial_m`].
pub fn inner_ring_expansion_per_omega2(bearing: &Bearing) -> f64 {
    let m = &bearing.inner_ring;
    let a = 0.5 * bearing.geometry.bore_m;
    let b = 0.5 * bearing.geometry.inner_raceway_diameter_m();
    let nu = m.poisson_ratio;
    b * m.density_kg_m3 * ((3.0 + nu) * a * a + (1.0 - nu) * b * b) / (4.0 * m.youngs_modulus_pa)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tables_reproduce_exact_hertz() {
        for name in ["6208", "7009C-hybrid"] {
            let b = Bearing::preset(name).unwrap();
            let m = BearingModel::new(&b).unwrap();
            for k in 0..=40 {
                let alpha = (k as f64) * 2.0_f64.to_radians();
                let c = Dual::<1>::cst(alpha.cos());
                let ki = b.inner_contact(alpha).unwrap();
                let ko = b.outer_contact(alpha).unwrap();
                assert!((m.inner.k(c).v / ki.k_load_deflection - 1.0).abs() < 1e-10, "{alpha}");
                assert!((m.outer.k(c).v / ko.k_load_deflection - 1.0).abs() < 1e-10);
                let q = 800.0;
                assert!((m.inner.semi_major_m(alpha.cos(), q) / ki.semi_major(q) - 1.0).abs() < 1e-10);
                assert!((m.outer.semi_major_m(alpha.cos(), q) / ko.semi_major(q) - 1.0).abs() < 1e-10);
            }
        }
    }

    #[test]
    fn free_disc_expansion_matches_thin_ring_limit() {
        // For a thin ring (a -> b) u = rho omega^2 b^3 / E (hoop stress rho v^2).
        let mut b = Bearing::preset("6208").unwrap();
        let r = 0.5 * b.geometry.inner_raceway_diameter_m();
        b.geometry.bore_m = 2.0 * r * (1.0 - 1e-9);
        let u = inner_ring_expansion_per_omega2(&b);
        let thin = b.inner_ring.density_kg_m3 * r.powi(3) / b.inner_ring.youngs_modulus_pa;
        assert!((u / thin - 1.0).abs() < 1e-6);
    }
}
