//! Lubricant properties against temperature (docs/concepts/physics.md §4:
//! the viscous moment needs the kinematic viscosity at the operating
//! temperature; §5: the oil-air film coefficient needs k, Pr, nu).
//!
//! * Kinematic viscosity: ASTM D341 (Walther) chart relation
//!   `log10(log10(nu + 0.7)) = A - B log10(T_K)`, nu in cSt (mm^2/s), fitted
//!   through two (temperature, viscosity) points, usually the 40 C and 100 C
//!   data of a product sheet. The simple 0.7 form is valid for nu >= 2 cSt
//!   (ASTM D341 scope); we refuse fit points below 2 cSt.
//! * Density: linear thermal expansion from the 15 C value,
//!   `rho(T) = rho15 (1 - beta (T - 15))`, beta = 6.4e-4 1/K (typical of
//!   mineral oils, ASTM D1250 / API petroleum measurement tables order of
//!   magnitude).
//! * Thermal conductivity and specific heat: Cragoe's correlations for
//!   petroleum oils (C. S. Cragoe, "Thermal properties of petroleum
//!   products", US Bureau of Standards Misc. Publ. 97, 1929), in SI:
//!   `k = (0.1172 / s) (1 - 5.4e-4 T_C)` W/(m K) and
//!   `c_p = (1684.8 + 3.39 T_C) / sqrt(s)` J/(kg K), with s the specific
//!   gravity at 15 C.
//! * Prandtl number Pr = nu rho c_p / k.

use crate::error::{finite, positive, Error, Result};

/// Absolute zero offset \[K\].
const KELVIN: f64 = 273.15;
/// Constant of the ASTM D341 relation \[cSt\].
const WALTHER_OFFSET_CST: f64 = 0.7;
/// Water density at 15 C used for the specific gravity [kg/m^3].
const WATER_15C_KG_M3: f64 = 999.1;

/// A lubricating oil with temperature-dependent properties.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Lubricant {
    /// Oil name (e.g. "ISO VG 32").
    pub name: String,
    /// Walther constant A of `log10(log10(nu + 0.7)) = A - B log10(T_K)` [-].
    pub walther_a: f64,
    /// Walther constant B [-].
    pub walther_b: f64,
    /// Density at 15 C [kg/m^3].
    pub density_15c_kg_m3: f64,
    /// Volumetric thermal expansion coefficient of the density law [1/K].
    pub density_expansion_per_k: f64,
    /// Lowest temperature at which the data apply (pour point) \[C\].
    pub min_temperature_c: f64,
    /// Highest temperature at which the data apply \[C\].
    pub max_temperature_c: f64,
}

fn walther(nu_cst: f64) -> f64 {
    (nu_cst + WALTHER_OFFSET_CST).log10().log10()
}

impl Lubricant {
    /// Fit the Walther constants through two (temperature C, viscosity cSt)
    /// points. The hotter point must be the thinner oil.
    pub fn from_two_points(
        name: impl Into<String>,
        point_1_c_cst: (f64, f64),
        point_2_c_cst: (f64, f64),
        density_15c_kg_m3: f64,
        min_temperature_c: f64,
        max_temperature_c: f64,
    ) -> Result<Self> {
        let (t1, nu1) = point_1_c_cst;
        let (t2, nu2) = point_2_c_cst;
        for (field, nu) in [("viscosity_1_cst", nu1), ("viscosity_2_cst", nu2)] {
            positive(field, nu)?;
            if nu < 2.0 {
                return Err(Error::config(
                    field,
                    nu,
                    "ASTM D341 (simple Walther form) is valid for viscosities of 2 cSt and above",
                ));
            }
        }
        finite("temperature_1_c", t1)?;
        finite("temperature_2_c", t2)?;
        if t1 <= -KELVIN || t2 <= -KELVIN {
            return Err(Error::config("temperature_c", t1.min(t2), "below absolute zero"));
        }
        if (t1 - t2).abs() < 1.0 {
            return Err(Error::config(
                "temperature_2_c",
                t2,
                "the two fit temperatures must differ by at least 1 K",
            ));
        }
        if (nu1 - nu2) * (t1 - t2) >= 0.0 {
            return Err(Error::config(
                "viscosity_2_cst",
                nu2,
                "viscosity must fall as temperature rises",
            ));
        }
        positive("density_15c_kg_m3", density_15c_kg_m3)?;
        finite("min_temperature_c", min_temperature_c)?;
        finite("max_temperature_c", max_temperature_c)?;
        if max_temperature_c <= min_temperature_c {
            return Err(Error::config(
                "max_temperature_c",
                max_temperature_c,
                format!("must exceed min_temperature_c = {min_temperature_c}"),
            ));
        }
        let (l1, l2) = ((t1 + KELVIN).log10(), (t2 + KELVIN).log10());
        let b = (walther(nu1) - walther(nu2)) / (l2 - l1);
        let a = walther(nu1) + b * l1;
        Ok(Lubricant {
            name: name.into(),
            walther_a: a,
            walther_b: b,
            density_15c_kg_m3,
            density_expansion_per_k: 6.4e-4,
            min_temperature_c,
            max_temperature_c,
        })
    }

    /// ISO VG 32 mineral spindle/hydraulic oil: 32 cSt at 40 C (ISO 3448
    /// grade midpoint), 5.4 cSt at 100 C (viscosity index about 100, ASTM
    /// D2270; e.g. Shell Tellus S2 M 32 data sheet: 32 / 5.4 cSt, VI 99,
    /// 872 kg/m^3 at 15 C, pour point -30 C). Upper limit 200 C (beyond,
    /// oxidation and flash point; no data).
    pub fn iso_vg32() -> Self {
        Self::from_two_points("ISO VG 32", (40.0, 32.0), (100.0, 5.4), 872.0, -30.0, 200.0)
            .expect("preset data are valid")
    }

    /// ISO VG 68 mineral gear/circulating oil: 68 cSt at 40 C (ISO 3448),
    /// 8.7 cSt at 100 C (VI about 100; e.g. Shell Tellus S2 M 68: 68 / 8.7
    /// cSt, 886 kg/m^3, pour point -24 C).
    pub fn iso_vg68() -> Self {
        Self::from_two_points("ISO VG 68", (40.0, 68.0), (100.0, 8.7), 886.0, -24.0, 200.0)
            .expect("preset data are valid")
    }

    /// Low-viscosity e-drive / automatic-transmission fluid of the
    /// Dexron-VI class: about 29.5 cSt at 40 C and 6.0 cSt at 100 C, 845
    /// kg/m^3 at 15 C, pour point about -45 C (typical published product
    /// data for Dexron-VI-licensed ATFs).
    pub fn edrive_atf() -> Self {
        Self::from_two_points("e-drive ATF", (40.0, 29.5), (100.0, 6.0), 845.0, -45.0, 200.0)
            .expect("preset data are valid")
    }

    /// Names accepted by [`Lubricant::preset`].
    pub const PRESETS: [&'static str; 3] = ["ISO VG 32", "ISO VG 68", "e-drive ATF"];

    /// A preset by name (case-insensitive; "vg32", "vg68", "atf" accepted).
    pub fn preset(name: &str) -> Result<Self> {
        let key: String = name
            .chars()
            .filter(|c| c.is_ascii_alphanumeric())
            .collect::<String>()
            .to_ascii_lowercase();
        match key.as_str() {
            "isovg32" | "vg32" => Ok(Self::iso_vg32()),
            "isovg68" | "vg68" => Ok(Self::iso_vg68()),
            "edriveatf" | "atf" => Ok(Self::edrive_atf()),
            _ => Err(Error::config(
                "lubricant",
                name,
                format!("unknown lubricant preset; known: {}", Self::PRESETS.join(", ")),
            )),
        }
    }

    /// Check a temperature lies in the data range; the error names it.
    pub fn check_temperature(&self, temperature_c: f64) -> Result<f64> {
        finite("oil_temperature_c", temperature_c)?;
        if temperature_c < self.min_temperature_c {
            return Err(Error::config(
                "oil_temperature_c",
                temperature_c,
                format!(
                    "below the lowest usable temperature of {} ({} C, pour point)",
                    self.name, self.min_temperature_c
                ),
            ));
        }
        if temperature_c > self.max_temperature_c {
            return Err(Error::config(
                "oil_temperature_c",
                temperature_c,
                format!(
                    "above the highest temperature with data for {} ({} C)",
                    self.name, self.max_temperature_c
                ),
            ));
        }
        Ok(temperature_c)
    }

    /// Kinematic viscosity [cSt = mm^2/s] at `temperature_c` (ASTM D341).
    pub fn kinematic_viscosity_cst(&self, temperature_c: f64) -> Result<f64> {
        let t = self.check_temperature(temperature_c)?;
        let w = self.walther_a - self.walther_b * (t + KELVIN).log10();
        Ok(10f64.powf(10f64.powf(w)) - WALTHER_OFFSET_CST)
    }

    /// Kinematic viscosity [m^2/s].
    pub fn kinematic_viscosity_m2_s(&self, temperature_c: f64) -> Result<f64> {
        Ok(self.kinematic_viscosity_cst(temperature_c)? * 1e-6)
    }

    /// Density [kg/m^3].
    pub fn density_kg_m3(&self, temperature_c: f64) -> Result<f64> {
        let t = self.check_temperature(temperature_c)?;
        Ok(self.density_15c_kg_m3 * (1.0 - self.density_expansion_per_k * (t - 15.0)))
    }

    /// Dynamic viscosity [Pa s].
    pub fn dynamic_viscosity_pa_s(&self, temperature_c: f64) -> Result<f64> {
        Ok(self.kinematic_viscosity_m2_s(temperature_c)? * self.density_kg_m3(temperature_c)?)
    }

    fn specific_gravity(&self) -> f64 {
        self.density_15c_kg_m3 / WATER_15C_KG_M3
    }

    /// Thermal conductivity [W/(m K)] (Cragoe).
    pub fn conductivity_w_mk(&self, temperature_c: f64) -> Result<f64> {
        let t = self.check_temperature(temperature_c)?;
        Ok(0.1172 / self.specific_gravity() * (1.0 - 5.4e-4 * t))
    }

    /// Specific heat [J/(kg K)] (Cragoe).
    pub fn specific_heat_j_kgk(&self, temperature_c: f64) -> Result<f64> {
        let t = self.check_temperature(temperature_c)?;
        Ok((1684.8 + 3.39 * t) / self.specific_gravity().sqrt())
    }

    /// Prandtl number nu rho c_p / k [-].
    pub fn prandtl(&self, temperature_c: f64) -> Result<f64> {
        Ok(
            self.dynamic_viscosity_pa_s(temperature_c)? * self.specific_heat_j_kgk(temperature_c)?
                / self.conductivity_w_mk(temperature_c)?,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fit_reproduces_its_points() {
        for (l, p) in [
            (Lubricant::iso_vg32(), [(40.0, 32.0), (100.0, 5.4)]),
            (Lubricant::iso_vg68(), [(40.0, 68.0), (100.0, 8.7)]),
            (Lubricant::edrive_atf(), [(40.0, 29.5), (100.0, 6.0)]),
        ] {
            for (t, nu) in p {
                let v = l.kinematic_viscosity_cst(t).unwrap();
                assert!((v - nu).abs() < 1e-9 * nu, "{} at {t}: {v}", l.name);
            }
        }
        // ISO 3448: VG 32 is 32 cSt at 40 C (grade midpoint, 28.8-35.2).
        let v = Lubricant::preset("vg32")
            .unwrap()
            .kinematic_viscosity_cst(40.0)
            .unwrap();
        assert!((28.8..=35.2).contains(&v));
    }

    #[test]
    fn viscosity_falls_monotonically() {
        let l = Lubricant::iso_vg68();
        let mut prev = f64::INFINITY;
        let mut t = l.min_temperature_c;
        while t <= l.max_temperature_c {
            let v = l.kinematic_viscosity_cst(t).unwrap();
            assert!(v < prev && v > 0.0, "{t}: {v}");
            prev = v;
            t += 2.5;
        }
    }

    #[test]
    fn walther_extrapolation_matches_data_sheet() {
        // Shell Tellus S2 M 32 data sheet lists 338 mm^2/s at 0 C besides
        // 32 / 5.4 at 40 / 100 C; the D341 line through the latter two must
        // land near the independent 0 C value (chart accuracy ~ 10 %).
        let v0 = Lubricant::iso_vg32().kinematic_viscosity_cst(0.0).unwrap();
        assert!((v0 - 338.0).abs() / 338.0 < 0.12, "{v0}");
    }

    #[test]
    fn out_of_range_temperature_is_named() {
        let l = Lubricant::iso_vg32();
        let e = l.kinematic_viscosity_cst(-40.0).unwrap_err().to_string();
        assert!(
            e.contains("oil_temperature_c") && e.contains("-40") && e.contains("pour"),
            "{e}"
        );
        let e = l.prandtl(250.0).unwrap_err().to_string();
        assert!(e.contains("250"), "{e}");
        assert!(Lubricant::from_two_points("x", (40.0, 5.0), (100.0, 30.0), 870.0, -20.0, 150.0).is_err());
        assert!(Lubricant::preset("whale oil").is_err());
    }

    #[test]
    fn property_magnitudes() {
        // Mineral oil at 40 C: k ~ 0.13 W/(m K), c_p ~ 1.9-2.0 kJ/(kg K),
        // Pr of VG 32 = nu rho c_p / k of a few hundred.
        let l = Lubricant::iso_vg32();
        let k = l.conductivity_w_mk(40.0).unwrap();
        let c = l.specific_heat_j_kgk(40.0).unwrap();
        assert!((0.12..0.14).contains(&k) && (1850.0..2050.0).contains(&c), "{k} {c}");
        let pr = l.prandtl(40.0).unwrap();
        let manual = 32e-6 * l.density_kg_m3(40.0).unwrap() * c / k;
        assert!(
            (pr - manual).abs() / manual < 1e-9 && (300.0..500.0).contains(&pr),
            "{pr}"
        );
    }
}
