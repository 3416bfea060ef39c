//! Thermal deformation of shaft, rings, balls and housing and the shift it
//! causes between the inner and outer groove curvature centres
//! (docs/concepts/physics.md §5, eqs ).
//!
//! # Convention (what the bearing solver receives)
//!
//! `A2j = B_f D cos(alpha0) + delta_r cos(psi_j) + u_r + u_Tr`, with A2
//! the radial component of the vector from the outer to the inner groove
//! curvature centre. The loaded length of that vector is
//! `(f_i - 0.5) D + delta_i + (f_o - 0.5) D + delta_o`, so a larger A2 means
//! more contact deformation: **positive `u_Tr` = more interference**.
//! Here `u_Tr = u_ic - u_oc`, the outward radial growth of the inner groove
//! centre minus that of the outer groove centre (radii, not diameters).
//!
//! Ball growth does not move the groove centres; it shrinks the free gap
//! between them: with groove radii r_i = f_i D, r_o = f_o D the ball-centre to
//! groove-centre distances at zero load are r_i - D/2 and r_o - D/2, whose
//! sum is the free gap A = (f_i + f_o - 1) D. A ball growing by dD and rings
//! growing their groove radii by dr_i, dr_o change it by
//! `dA = dr_i + dr_o - dD` (reported as `free_gap_change_m`). The exact use
//! in the compatibility equations is to replace (f_i - 0.5) D by
//! (f_i - 0.5) D + dr_i - dD/2 (and likewise outer). A solver that only
//! takes A1, A2 offsets can use the first-order projection on the free
//! contact line, `A2 += -dA cos(alpha0)`, `A1 += -dA sin(alpha0)`
//! ([`ThermalOffsets::radial_with_gap_m`], [`ThermalOffsets::axial_with_gap_m`]).
//!
//! Centrifugal growth is not included here; it is a separate effect
//! of the bearing solver (`ring_centrifugal_expansion`).
//!
//! # Ring fits (our model)
//!
//! A free part heated uniformly grows homogeneously: every radius r becomes
//! r (1 + alpha dT) (plane stress, free ends). A ring on a fit exchanges a
//! fit-pressure change dp with its seat: the free-growth mismatch at the
//! interface is shared by the Lamé compliances of ring and seat (thick
//! cylinders, plane stress), and dp moves the raceway by the Lamé transfer
//! factor. `RingFit::Tight` assumes the fit keeps some interference
//! throughout (linear superposition both ways); `RingFit::Loose` lets the
//! ring float (no transfer). Lamé (internal pressure p on a ring a < r < b):
//! `u(r) = p a^2 / (E (b^2 - a^2)) ((1 - nu) r + (1 + nu) b^2 / r)`.
//!
//! # as printed, sign by sign
//!
//! * A-33 `u = alpha dT d`: free diametral growth; sign right. It is a
//!   *diametral* quantity while A2 in A-38 is radial: fed unhalved into A-38
//!   it doubles the effect (wrong by a factor 2).
//! * A-34 `u_Ts = alpha_s dT_s (1 + nu_s) D_s`, `u_Th = alpha_h dT_h (1 + nu_h) D_h`:
//!   signs right (outward). The (1 + nu) factor is the plane-strain
//!   (axially restrained) cylinder; a shaft or housing free to grow axially
//!   grows alpha dT D. We default to the free form and offer the seed's as
//!   `plane_strain = true`. `u_Tb = alpha_o dT_b D_b` uses the outer-ring
//!   coefficient for the ball: wrong for hybrid bearings (Si3N4 balls expand
//!   about a quarter as much); we use the ball material.
//! * A-35 `u_Tri = u_Ti + (u_Ts - u_Ti') D_i/D_s`: sign right (a shaft
//!   growing more than the ring bore pushes the raceway out), but the
//!   transfer factor D_i/D_s > 1 amplifies the bore displacement across the
//!   ring, whereas Lamé gives a radial transfer 2ab/((1 - nu) a^2 + (1 + nu) b^2) < 1,
//!   and the shaft's own compliance is ignored. Its final form
//!   `alpha_s dT_s (1 + nu_s) D_i` drops the ring's own temperature. The outer
//!   form `u_Tro = u_To + (u_Th - u_To') D_o/D` has the right sign for a tight
//!   outer fit; with a loose fit a growing housing leaves the ring behind.
//! * A-36 `u_Tr = u_Tri - u_Tro - 2 u_Tb`: `+u_Tri` right (inner growth closes
//!   the clearance), `-u_Tro` right (outer growth opens it), `-2 u_Tb` **wrong
//!   sign**: a growing ball closes the clearance and raises interference, so
//!   it enters with `+` (2 dD in diametral clearance terms, dD cos(alpha0) in
//!   A2 terms). The printed right-hand side
//!   `alpha_s dT_s (1+nu_s) D_s + alpha_h dT_h (1+nu_h) D_o - 2 alpha_b dT_b dm`
//!   has a second error: `+alpha_h ...` flips the sign of the outer term
//!   (**wrong**), and `dm` replaces the ball diameter (**wrong**, five times
//!   too large for the 6208).
//! * A-37 `u_Ta = (alpha_h dT_h L_h - alpha_s dT_s L_s) / 2`: the relative axial
//!   growth of housing and shaft from their common axial datum is right in
//!   form; its sign depends on which side of the datum the bearing sits and
//!   which way its contact faces (we expose `axial_sign`); the /2 (not in
//!   docs/concepts/physics.md §5) shares the growth between the two bearings
//!   of a pair; we leave it to the caller.

use crate::bearing::Bearing;
use crate::effects::{Effect, EffectSet};
use crate::error::{finite, non_negative, positive, Error, Result};
use crate::materials::Material;

/// How a ring sits on its seat.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RingFit {
    /// Clearance or light fit: the ring grows freely with its own temperature.
    Loose,
    /// Interference fit kept throughout: ring and seat share the mismatch.
    Tight,
}

/// Shaft, housing and fits around one bearing.
#[derive(Debug, Clone, PartialEq)]
pub struct Mounting {
    /// Housing material (its expansion, and its Lamé compliance for a tight outer fit).
    pub housing: Material,
    /// Outside diameter of the housing wall around the bearing seat \[m\].
    pub housing_outer_diameter_m: f64,
    /// Axial distance from the shaft's axial datum (locating point) to the
    /// bearing, L_s \[m\].
    pub shaft_length_m: f64,
    /// Axial distance from the housing's axial datum to the bearing, L_h \[m\].
    pub housing_length_m: f64,
    /// Fit of the inner ring on the shaft.
    pub inner_fit: RingFit,
    /// Fit of the outer ring in the housing.
    pub outer_fit: RingFit,
    /// Use the seed's plane-strain factor (1 + nu) for shaft and housing.
    pub plane_strain: bool,
    /// +1 when the shaft growing axially more than the housing raises the
    /// contact load of this bearing (A1 grows), -1 when it unloads it.
    pub axial_sign: f64,
}

impl Mounting {
    /// Check every field.
    pub fn validate(&self, bearing: &Bearing) -> Result<()> {
        self.housing.validate()?;
        let od = bearing.geometry.outer_diameter_m;
        positive("housing_outer_diameter_m", self.housing_outer_diameter_m)?;
        if self.housing_outer_diameter_m <= od {
            return Err(Error::config(
                "housing_outer_diameter_m",
                self.housing_outer_diameter_m,
                format!("must exceed the bearing outside diameter {od} m"),
            ));
        }
        non_negative("shaft_length_m", self.shaft_length_m)?;
        non_negative("housing_length_m", self.housing_length_m)?;
        if self.axial_sign != 1.0 && self.axial_sign != -1.0 {
            return Err(Error::config("axial_sign", self.axial_sign, "must be +1 or -1"));
        }
        Ok(())
    }
}

/// Temperature rises above the assembly (reference) temperature \[K\].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ComponentRises {
    /// Shaft rise dT_s \[K\].
    pub shaft_k: f64,
    /// Inner ring rise dT_i \[K\].
    pub inner_ring_k: f64,
    /// Ball rise dT_b \[K\] (all balls alike).
    pub balls_k: f64,
    /// Outer ring rise dT_o \[K\].
    pub outer_ring_k: f64,
    /// Housing rise dT_h \[K\].
    pub housing_k: f64,
}

/// Thermal displacements of one bearing (radial quantities are radii) \[m\].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ThermalOffsets {
    /// Outward growth of the shaft surface at the seat (after the fit).
    pub shaft_surface_radial_m: f64,
    /// Outward growth of the housing bore at the seat (after the fit).
    pub housing_bore_radial_m: f64,
    /// Outward growth of the inner groove curvature centre, u_ic.
    pub inner_groove_centre_radial_m: f64,
    /// Outward growth of the outer groove curvature centre, u_oc.
    pub outer_groove_centre_radial_m: f64,
    /// Ball diameter growth dD.
    pub ball_diameter_growth_m: f64,
    /// Inner groove radius growth dr_i.
    pub inner_groove_radius_growth_m: f64,
    /// Outer groove radius growth dr_o.
    pub outer_groove_radius_growth_m: f64,
    /// Change of the free groove-centre gap dA = dr_i + dr_o - dD.
    pub free_gap_change_m: f64,
    /// Change of the inner-ring/shaft fit pressure (positive = tighter) \[Pa\];
    /// 0 for a loose fit.
    pub inner_fit_pressure_change_pa: f64,
    /// Change of the outer-ring/housing fit pressure (positive = tighter) \[Pa\];
    /// 0 for a loose fit.
    pub outer_fit_pressure_change_pa: f64,
    /// u_Tr = u_ic - u_oc, added to A2 (positive = more interference).
    pub radial_m: f64,
    /// u_Ta, added to A1 (positive = more interference).
    pub axial_m: f64,
}

impl ThermalOffsets {
    /// u_Tr plus the first-order projection of the free-gap change on the
    /// free contact line: `u_Tr - dA cos(alpha0)`.
    pub fn radial_with_gap_m(&self, free_contact_angle_rad: f64) -> f64 {
        self.radial_m - self.free_gap_change_m * free_contact_angle_rad.cos()
    }

    /// u_Ta plus `- dA sin(alpha0)`.
    pub fn axial_with_gap_m(&self, free_contact_angle_rad: f64) -> f64 {
        self.axial_m - self.free_gap_change_m * free_contact_angle_rad.sin()
    }
}

/// Radial displacement at the bore a per unit internal pressure of a ring
/// a < r < b, and at its outside b [m/Pa] (Lamé, plane stress).
pub fn lame_internal(bore_radius_m: f64, outer_radius_m: f64, m: &Material) -> (f64, f64) {
    let (a, b) = (bore_radius_m, outer_radius_m);
    let (e, nu) = (m.youngs_modulus_pa, m.poisson_ratio);
    let d = b * b - a * a;
    (a / e * ((b * b + a * a) / d + nu), a * a / (e * d) * 2.0 * b)
}

/// Inward radial displacement at the outside c per unit external pressure
/// of a ring a < r < c, and at its bore a [m/Pa] (Lamé, plane stress); a = 0
/// is a solid cylinder.
pub fn lame_external(bore_radius_m: f64, outer_radius_m: f64, m: &Material) -> (f64, f64) {
    let (a, c) = (bore_radius_m, outer_radius_m);
    let (e, nu) = (m.youngs_modulus_pa, m.poisson_ratio);
    let d = c * c - a * a;
    (c / e * ((c * c + a * a) / d - nu), c * c / (e * d) * 2.0 * a)
}

/// Thermal offsets of `bearing` in `mounting` for the given rises.
/// Each part's growth is switched by its effect in `effects`
/// (`thermal_expansion_shaft`, `_inner_ring`, `_outer_ring`, `_balls`,
/// `_housing`): a part switched off keeps its cold size.
pub fn thermal_offsets(
    bearing: &Bearing,
    mounting: &Mounting,
    rises: &ComponentRises,
    effects: EffectSet,
) -> Result<ThermalOffsets> {
    mounting.validate(bearing)?;
    let on = |e: Effect, field: &str, v: f64| -> Result<f64> {
        finite(field, v)?;
        Ok(if effects.has(e) { v } else { 0.0 })
    };
    let dts = on(Effect::ThermalExpansionShaft, "shaft_rise_k", rises.shaft_k)?;
    let dti = on(
        Effect::ThermalExpansionInnerRing,
        "inner_ring_rise_k",
        rises.inner_ring_k,
    )?;
    let dtb = on(Effect::ThermalExpansionBalls, "balls_rise_k", rises.balls_k)?;
    let dto = on(
        Effect::ThermalExpansionOuterRing,
        "outer_ring_rise_k",
        rises.outer_ring_k,
    )?;
    let dth = on(Effect::ThermalExpansionHousing, "housing_rise_k", rises.housing_k)?;

    let g = &bearing.geometry;
    let (si, sr, sb, so, sh) = (
        &bearing.shaft,
        &bearing.inner_ring,
        &bearing.ball,
        &bearing.outer_ring,
        &mounting.housing,
    );
    let strain = |m: &Material| {
        if mounting.plane_strain {
            1.0 + m.poisson_ratio
        } else {
            1.0
        }
    };

    // Radii: shaft bore c_s, seat a_i (bearing bore), inner groove bottom b_i,
    // outer groove bottom a_o, seat c_o (bearing OD), housing outside R_h.
    let c_s = 0.5 * bearing.shaft_bore_m;
    let a_i = 0.5 * g.bore_m;
    let b_i = 0.5 * g.inner_raceway_diameter_m();
    let a_o = 0.5 * g.outer_raceway_diameter_m();
    let c_o = 0.5 * g.outer_diameter_m;
    let r_h = 0.5 * mounting.housing_outer_diameter_m;
    let r_i = g.inner_conformity * g.ball_diameter_m;
    let r_o = g.outer_conformity * g.ball_diameter_m;

    // Free growths.
    let shaft_free = si.thermal_expansion_per_k * dts * strain(si) * a_i;
    let ring_i = sr.thermal_expansion_per_k * dti;
    let ring_o = so.thermal_expansion_per_k * dto;
    let housing_free = sh.thermal_expansion_per_k * dth * strain(sh) * c_o;

    // Inner fit: mismatch = shaft surface - ring bore (free), positive tightens.
    let (mut dp_i, mut inner_shift, mut shaft_surface) = (0.0, 0.0, shaft_free);
    if mounting.inner_fit == RingFit::Tight {
        let (ring_bore, ring_transfer) = lame_internal(a_i, b_i, sr);
        let (shaft_c, _) = lame_external(c_s, a_i, si);
        dp_i = (shaft_free - ring_i * a_i) / (ring_bore + shaft_c);
        inner_shift = dp_i * ring_transfer;
        shaft_surface = shaft_free - dp_i * shaft_c;
    }
    // Outer fit: mismatch = ring OD (free) - housing bore (free), positive tightens.
    let (mut dp_o, mut outer_shift, mut housing_bore) = (0.0, 0.0, housing_free);
    if mounting.outer_fit == RingFit::Tight {
        let (ring_od, ring_transfer) = lame_external(a_o, c_o, so);
        let (housing_c, _) = lame_internal(c_o, r_h, sh);
        dp_o = (ring_o * c_o - housing_free) / (ring_od + housing_c);
        outer_shift = -dp_o * ring_transfer;
        housing_bore = housing_free + dp_o * housing_c;
    }

    // Groove centres: homogeneous growth of the ring about its axis plus the
    // fit shift of the groove bottom.
    let u_ic = ring_i * (b_i + r_i) + inner_shift;
    let u_oc = ring_o * (a_o - r_o) + outer_shift;
    let dd = sb.thermal_expansion_per_k * dtb * g.ball_diameter_m;
    let dri = ring_i * r_i;
    let dro = ring_o * r_o;
    let axial = mounting.axial_sign
        * (si.thermal_expansion_per_k * dts * mounting.shaft_length_m
            - sh.thermal_expansion_per_k * dth * mounting.housing_length_m);
    Ok(ThermalOffsets {
        shaft_surface_radial_m: shaft_surface,
        housing_bore_radial_m: housing_bore,
        inner_groove_centre_radial_m: u_ic,
        outer_groove_centre_radial_m: u_oc,
        ball_diameter_growth_m: dd,
        inner_groove_radius_growth_m: dri,
        outer_groove_radius_growth_m: dro,
        free_gap_change_m: dri + dro - dd,
        inner_fit_pressure_change_pa: dp_i,
        outer_fit_pressure_change_pa: dp_o,
        radial_m: u_ic - u_oc,
        axial_m: axial,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mounting(inner: RingFit, outer: RingFit) -> Mounting {
        Mounting {
            housing: Material::cast_iron(),
            housing_outer_diameter_m: 0.12,
            shaft_length_m: 0.1,
            housing_length_m: 0.1,
            inner_fit: inner,
            outer_fit: outer,
            plane_strain: false,
            axial_sign: 1.0,
        }
    }

    fn rises(s: f64, i: f64, b: f64, o: f64, h: f64) -> ComponentRises {
        ComponentRises {
            shaft_k: s,
            inner_ring_k: i,
            balls_k: b,
            outer_ring_k: o,
            housing_k: h,
        }
    }

    #[test]
    fn zero_rise_gives_zero_offsets() {
        let b = Bearing::preset("6208").unwrap();
        let u = thermal_offsets(
            &b,
            &mounting(RingFit::Tight, RingFit::Tight),
            &ComponentRises::default(),
            EffectSet::all(),
        )
        .unwrap();
        for v in [
            u.radial_m,
            u.axial_m,
            u.free_gap_change_m,
            u.inner_fit_pressure_change_pa,
            u.shaft_surface_radial_m,
        ] {
            assert_eq!(v, 0.0);
        }
    }

    #[test]
    fn hand_calculation_with_loose_fits() {
        // 6208 (seed A): d_i = 60 - 12 - 0.02 = 47.98 mm, f_i D = 6.24 mm; inner
        // groove centre radius 23.99 + 6.24 = 30.23 mm. 52100: alpha = 12.5e-6.
        // dT_i = 20 K: u_ic = 12.5e-6 * 20 * 30.23 mm = 7.5575 um.
        let b = Bearing::preset("6208").unwrap();
        let m = mounting(RingFit::Loose, RingFit::Loose);
        let u = thermal_offsets(&b, &m, &rises(0.0, 20.0, 0.0, 0.0, 0.0), EffectSet::all()).unwrap();
        assert!(
            (u.inner_groove_centre_radial_m - 7.5575e-6).abs() < 1e-12,
            "{}",
            u.inner_groove_centre_radial_m
        );
        assert!((u.radial_m - u.inner_groove_centre_radial_m).abs() < 1e-18);
        // Outer: d_o/2 = 36.01 mm, minus r_o = 6.36 -> 29.65 mm; dT_o = 10 K.
        let u = thermal_offsets(&b, &m, &rises(0.0, 0.0, 0.0, 10.0, 0.0), EffectSet::all()).unwrap();
        assert!((u.outer_groove_centre_radial_m - 12.5e-6 * 10.0 * 29.65e-3).abs() < 1e-12);
        // Ball 30 K: dD = 12.5e-6 * 30 * 12 mm = 4.5 um, gap shrinks by 4.5 um.
        let u = thermal_offsets(&b, &m, &rises(0.0, 0.0, 30.0, 0.0, 0.0), EffectSet::all()).unwrap();
        assert!((u.ball_diameter_growth_m - 4.5e-6).abs() < 1e-15 && (u.free_gap_change_m + 4.5e-6).abs() < 1e-15);
        // Axial: (11.5e-6 * 15 - 10.5e-6 * 5) * 0.1 m.
        let u = thermal_offsets(&b, &m, &rises(15.0, 0.0, 0.0, 0.0, 5.0), EffectSet::all()).unwrap();
        assert!((u.axial_m - (11.5e-6 * 15.0 - 10.5e-6 * 5.0) * 0.1).abs() < 1e-15);
    }

    #[test]
    fn signs_follow_the_geometry() {
        let b = Bearing::preset("7009C").unwrap();
        let m = mounting(RingFit::Tight, RingFit::Tight);
        let a0 = b.geometry.free_contact_angle_rad;
        let r = |x: ComponentRises| thermal_offsets(&b, &m, &x, EffectSet::all()).unwrap();
        // Hot inner ring or shaft: more interference.
        assert!(r(rises(0.0, 10.0, 0.0, 0.0, 0.0)).radial_m > 0.0);
        assert!(r(rises(10.0, 0.0, 0.0, 0.0, 0.0)).radial_m > 0.0);
        // Hot outer ring or housing: less.
        assert!(r(rises(0.0, 0.0, 0.0, 10.0, 0.0)).radial_m < 0.0);
        assert!(r(rises(0.0, 0.0, 0.0, 0.0, 10.0)).radial_m < 0.0);
        // Hot ball: no groove-centre motion but more interference through the gap.
        let u = r(rises(0.0, 0.0, 10.0, 0.0, 0.0));
        assert_eq!(u.radial_m, 0.0);
        assert!(u.radial_with_gap_m(a0) > 0.0 && u.axial_with_gap_m(a0) > 0.0);
        // Uniform heating of an all-steel bearing with equal alphas everywhere
        // is a homogeneous dilatation: the gap scales, no fit pressure change.
        let mut bb = b.clone();
        bb.shaft = bb.inner_ring.clone();
        let mut mm = m.clone();
        mm.housing = bb.outer_ring.clone();
        let u = thermal_offsets(&bb, &mm, &rises(20.0, 20.0, 20.0, 20.0, 20.0), EffectSet::all()).unwrap();
        assert!(u.inner_fit_pressure_change_pa.abs() < 1e-3 && u.outer_fit_pressure_change_pa.abs() < 1e-3);
        let g = &bb.geometry;
        let expect = 12.5e-6 * 20.0 * g.total_conformity() * g.ball_diameter_m;
        assert!((u.free_gap_change_m - expect).abs() < 1e-15);
        // Effects switch parts off by name.
        let u = thermal_offsets(
            &b,
            &m,
            &rises(10.0, 10.0, 10.0, 10.0, 10.0),
            EffectSet::none().with(Effect::ThermalExpansionBalls),
        )
        .unwrap();
        assert_eq!(u.radial_m, 0.0);
        assert!(u.ball_diameter_growth_m > 0.0);
    }

    #[test]
    fn fit_interfaces_stay_in_contact() {
        // Tight fits: ring bore and shaft surface end at the same radius,
        // ring OD and housing bore likewise (two independent Lamé routes).
        let b = Bearing::preset("7009C").unwrap();
        let m = mounting(RingFit::Tight, RingFit::Tight);
        let x = rises(25.0, 10.0, 30.0, 8.0, 3.0);
        let u = thermal_offsets(&b, &m, &x, EffectSet::all()).unwrap();
        let g = &b.geometry;
        let (a, bi) = (0.5 * g.bore_m, 0.5 * g.inner_raceway_diameter_m());
        let bore = 12.5e-6 * 10.0 * a + u.inner_fit_pressure_change_pa * lame_internal(a, bi, &b.inner_ring).0;
        assert!(
            (bore - u.shaft_surface_radial_m).abs() < 1e-14,
            "{bore} {}",
            u.shaft_surface_radial_m
        );
        assert!(u.inner_fit_pressure_change_pa > 0.0);
        let (ao, c) = (0.5 * g.outer_raceway_diameter_m(), 0.5 * g.outer_diameter_m);
        let od = 12.5e-6 * 8.0 * c - u.outer_fit_pressure_change_pa * lame_external(ao, c, &b.outer_ring).0;
        assert!((od - u.housing_bore_radial_m).abs() < 1e-14);
        // Lamé transfer across the inner ring is below 1 (radial), unlike A-35's D_i/D_s.
        let (cb, tr) = lame_internal(a, bi, &b.inner_ring);
        assert!(tr < cb && tr / cb > 0.5);
    }

    #[test]
    fn silicon_nitride_balls_grow_a_quarter() {
        // Seed B: ceramic 7009 radial thermal displacement 8.2 um vs steel
        // 16.68 um; the ball alone scales by alpha: 3.2/12.5 = 0.256.
        let m = mounting(RingFit::Loose, RingFit::Loose);
        let x = rises(0.0, 0.0, 40.0, 0.0, 0.0);
        let s = thermal_offsets(&Bearing::preset("7009C").unwrap(), &m, &x, EffectSet::all()).unwrap();
        let c = thermal_offsets(&Bearing::preset("7009C-hybrid").unwrap(), &m, &x, EffectSet::all()).unwrap();
        let ratio = c.ball_diameter_growth_m / s.ball_diameter_growth_m;
        assert!((ratio - 3.2 / 12.5).abs() < 1e-12);
    }
}
