//! Ball-bearing internal geometry (docs/concepts/physics.md §3; Harris & Kotzalas
//! ch. 2). Lengths in metres, angles in radians.

use crate::error::{in_range, non_negative, positive, Error, Result};

/// Deep-groove (radial) or angular-contact ball bearing.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, serde::Deserialize)]
pub enum BearingType {
    /// Deep-groove (radial) bearing, e.g. 6208: the free contact angle
    /// follows from the diametral clearance ([`BearingGeometry::deep_groove`]).
    DeepGroove,
    /// Angular-contact bearing, e.g. 7009C: given free contact angle, the
    /// clearance that produces it is derived ([`BearingGeometry::angular_contact`]).
    AngularContact,
}

impl BearingType {
    /// Lower-case name for reports and configuration output:
    /// `"deep-groove"` or `"angular-contact"`.
    pub fn name(self) -> &'static str {
        match self {
            BearingType::DeepGroove => "deep-groove",
            BearingType::AngularContact => "angular-contact",
        }
    }
}

/// Internal geometry of one ball bearing.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct BearingGeometry {
    /// Deep-groove or angular-contact; set by the constructor used.
    pub bearing_type: BearingType,
    /// Number of balls Z.
    pub ball_count: usize,
    /// Ball diameter D \[m\].
    pub ball_diameter_m: f64,
    /// Pitch diameter dm \[m\].
    pub pitch_diameter_m: f64,
    /// Inner groove conformity f_i = r_i / D (> 0.5).
    pub inner_conformity: f64,
    /// Outer groove conformity f_o = r_o / D (> 0.5).
    pub outer_conformity: f64,
    /// Diametral clearance Pd \[m\]; for an angular-contact bearing the
    /// clearance that produces its free contact angle.
    pub diametral_clearance_m: f64,
    /// Free (unloaded) contact angle alpha0 \[rad\], from cos alpha0 = 1 - Pd / (2 A).
    pub free_contact_angle_rad: f64,
    /// Bore d \[m\].
    pub bore_m: f64,
    /// Outside diameter D_o \[m\].
    pub outer_diameter_m: f64,
    /// Width B \[m\].
    pub width_m: f64,
}

impl BearingGeometry {
    /// Deep-groove bearing from ball count, ball and pitch diameters,
    /// conformities and diametral clearance (free contact angle derived).
    #[allow(clippy::too_many_arguments)]
    pub fn deep_groove(
        ball_count: usize,
        ball_diameter_m: f64,
        pitch_diameter_m: f64,
        inner_conformity: f64,
        outer_conformity: f64,
        diametral_clearance_m: f64,
        bore_m: f64,
        outer_diameter_m: f64,
        width_m: f64,
    ) -> Result<Self> {
        non_negative("diametral_clearance_mm", diametral_clearance_m * 1e3)?;
        let mut g = BearingGeometry {
            bearing_type: BearingType::DeepGroove,
            ball_count,
            ball_diameter_m,
            pitch_diameter_m,
            inner_conformity,
            outer_conformity,
            diametral_clearance_m,
            free_contact_angle_rad: 0.0,
            bore_m,
            outer_diameter_m,
            width_m,
        };
        g.validate_common()?;
        let a = g.curvature_centre_distance_m();
        if diametral_clearance_m >= 2.0 * a {
            return Err(Error::config(
                "diametral_clearance_mm",
                diametral_clearance_m * 1e3,
                format!("must be below 2 (f_i + f_o - 1) D = {:.4} mm", 2.0 * a * 1e3),
            ));
        }
        g.free_contact_angle_rad = (1.0 - diametral_clearance_m / (2.0 * a)).acos();
        Ok(g)
    }

    /// Angular-contact bearing from its free contact angle (the clearance
    /// that produces it is derived: Pd = 2 A (1 - cos alpha0)).
    #[allow(clippy::too_many_arguments)]
    pub fn angular_contact(
        ball_count: usize,
        ball_diameter_m: f64,
        pitch_diameter_m: f64,
        inner_conformity: f64,
        outer_conformity: f64,
        free_contact_angle_rad: f64,
        bore_m: f64,
        outer_diameter_m: f64,
        width_m: f64,
    ) -> Result<Self> {
        in_range("free_contact_angle_deg", free_contact_angle_rad.to_degrees(), 1.0, 45.0)?;
        let mut g = BearingGeometry {
            bearing_type: BearingType::AngularContact,
            ball_count,
            ball_diameter_m,
            pitch_diameter_m,
            inner_conformity,
            outer_conformity,
            diametral_clearance_m: 0.0,
            free_contact_angle_rad,
            bore_m,
            outer_diameter_m,
            width_m,
        };
        g.validate_common()?;
        g.diametral_clearance_m = 2.0 * g.curvature_centre_distance_m() * (1.0 - free_contact_angle_rad.cos());
        Ok(g)
    }

    fn validate_common(&self) -> Result<()> {
        if self.ball_count < 3 || self.ball_count > 200 {
            return Err(Error::config("ball_count", self.ball_count, "must lie in [3, 200]"));
        }
        let d = positive("ball_diameter_mm", self.ball_diameter_m * 1e3)? * 1e-3;
        let dm = positive("pitch_diameter_mm", self.pitch_diameter_m * 1e3)? * 1e-3;
        let bore = positive("bore_mm", self.bore_m * 1e3)? * 1e-3;
        let od = positive("outer_diameter_mm", self.outer_diameter_m * 1e3)? * 1e-3;
        positive("width_mm", self.width_m * 1e3)?;
        for (name, f) in [
            ("inner_conformity", self.inner_conformity),
            ("outer_conformity", self.outer_conformity),
        ] {
            if !f.is_finite() || f <= 0.5 {
                return Err(Error::config(
                    name,
                    f,
                    "groove conformity must exceed 0.5 (groove radius larger than the ball radius)",
                ));
            }
            if f > 1.0 {
                return Err(Error::config(
                    name,
                    f,
                    "groove conformity above 1.0 is not a ball-bearing groove",
                ));
            }
        }
        if od <= bore {
            return Err(Error::config(
                "outer_diameter_mm",
                od * 1e3,
                format!("must exceed the bore {} mm", bore * 1e3),
            ));
        }
        if dm <= bore || dm >= od {
            return Err(Error::config(
                "pitch_diameter_mm",
                dm * 1e3,
                format!(
                    "must lie between bore {} mm and outside diameter {} mm",
                    bore * 1e3,
                    od * 1e3
                ),
            ));
        }
        let section = 0.5 * (od - bore);
        if d >= section {
            return Err(Error::config(
                "ball_diameter_mm",
                d * 1e3,
                format!(
                    "ball does not fit the ring section (outside diameter - bore)/2 = {} mm",
                    section * 1e3
                ),
            ));
        }
        if dm - d <= bore || dm + d >= od {
            return Err(Error::config(
                "ball_diameter_mm",
                d * 1e3,
                "ball breaks through a ring: need pitch - ball > bore and pitch + ball < outside diameter",
            ));
        }
        // Balls must not overlap on the pitch circle: Z D < pi dm.
        if self.ball_count as f64 * d >= std::f64::consts::PI * dm {
            return Err(Error::config(
                "ball_count",
                self.ball_count,
                format!(
                    "{} balls of {} mm do not fit on a {} mm pitch circle",
                    self.ball_count,
                    d * 1e3,
                    dm * 1e3
                ),
            ));
        }
        Ok(())
    }

    /// Distance between the groove curvature centres at zero load,
    /// A = (f_i + f_o - 1) D = B_f D \[m\].
    #[inline]
    pub fn curvature_centre_distance_m(&self) -> f64 {
        (self.inner_conformity + self.outer_conformity - 1.0) * self.ball_diameter_m
    }

    /// Total conformity B_f = f_i + f_o - 1.
    #[inline]
    pub fn total_conformity(&self) -> f64 {
        self.inner_conformity + self.outer_conformity - 1.0
    }

    /// Inner raceway groove-bottom diameter d_i = dm - D - Pd/2 \[m\].
    pub fn inner_raceway_diameter_m(&self) -> f64 {
        self.pitch_diameter_m - self.ball_diameter_m - 0.5 * self.diametral_clearance_m
    }

    /// Outer raceway groove-bottom diameter d_o = dm + D + Pd/2 \[m\].
    pub fn outer_raceway_diameter_m(&self) -> f64 {
        self.pitch_diameter_m + self.ball_diameter_m + 0.5 * self.diametral_clearance_m
    }

    /// Radius of the locus of inner-groove curvature centres,
    /// R_i = dm/2 + (f_i - 0.5) D cos alpha0 (used with tilt, A-11) \[m\].
    pub fn inner_groove_centre_radius_m(&self) -> f64 {
        0.5 * self.pitch_diameter_m
            + (self.inner_conformity - 0.5) * self.ball_diameter_m * self.free_contact_angle_rad.cos()
    }

    /// Azimuth of ball j (0-based): psi_j = 2 pi j / Z.
    #[inline]
    pub fn azimuth(&self, j: usize) -> f64 {
        2.0 * std::f64::consts::PI * j as f64 / self.ball_count as f64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn seed_6208() -> BearingGeometry {
        BearingGeometry::deep_groove(9, 12e-3, 60e-3, 0.52, 0.53, 0.04e-3, 40e-3, 80e-3, 18e-3).unwrap()
    }

    #[test]
    fn seed_a_free_contact_angle() {
        // Seed A Table 1: Pd = 0.04 mm gives 14.8351 deg.
        let g = seed_6208();
        assert!(
            (g.free_contact_angle_rad.to_degrees() - 14.8351).abs() < 1e-3,
            "{}",
            g.free_contact_angle_rad.to_degrees()
        );
        // Table 1 groove radii 6.24 / 6.36 mm.
        assert!((g.inner_conformity * 12.0 - 6.24).abs() < 1e-12 && (g.outer_conformity * 12.0 - 6.36).abs() < 1e-12);
    }

    #[test]
    fn angular_contact_clearance_round_trip() {
        let g =
            BearingGeometry::angular_contact(16, 8.731e-3, 60e-3, 0.52, 0.53, 15f64.to_radians(), 45e-3, 75e-3, 16e-3)
                .unwrap();
        let dg = BearingGeometry::deep_groove(
            16,
            8.731e-3,
            60e-3,
            0.52,
            0.53,
            g.diametral_clearance_m,
            45e-3,
            75e-3,
            16e-3,
        )
        .unwrap();
        assert!((dg.free_contact_angle_rad - g.free_contact_angle_rad).abs() < 1e-12);
    }

    #[test]
    fn bad_geometry_names_the_field() {
        let e = BearingGeometry::deep_groove(9, 12e-3, 60e-3, 0.5, 0.53, 0.04e-3, 40e-3, 80e-3, 18e-3).unwrap_err();
        assert!(e.to_string().contains("inner_conformity"));
        let e = BearingGeometry::deep_groove(9, 25e-3, 60e-3, 0.52, 0.53, 0.04e-3, 40e-3, 80e-3, 18e-3).unwrap_err();
        assert!(e.to_string().contains("ball_diameter_mm"), "{e}");
        let e = BearingGeometry::deep_groove(9, 12e-3, 60e-3, 0.52, 0.53, -0.01e-3, 40e-3, 80e-3, 18e-3).unwrap_err();
        assert!(e.to_string().contains("diametral_clearance_mm"));
        let e = BearingGeometry::deep_groove(9, f64::NAN, 60e-3, 0.52, 0.53, 0.01e-3, 40e-3, 80e-3, 18e-3).unwrap_err();
        assert!(e.to_string().contains("ball_diameter_mm"));
        let e = BearingGeometry::deep_groove(30, 12e-3, 60e-3, 0.52, 0.53, 0.01e-3, 40e-3, 80e-3, 18e-3).unwrap_err();
        assert!(e.to_string().contains("ball_count"));
    }
}
