//! Materials of rings, balls, shafts and housings. One struct per material;
//! all properties SI. Presets carry typical handbook values (sources beside
//! each); any property can be overridden field by field.

use crate::error::{in_range, positive, Result};

/// An isotropic, linear-elastic solid with the thermal properties the
/// bearing and thermal models need.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Material {
    /// Material name (preset name, e.g. "52100", or a user material's name).
    pub name: String,
    /// Young's modulus E \[Pa\].
    pub youngs_modulus_pa: f64,
    /// Poisson's ratio nu [-].
    pub poisson_ratio: f64,
    /// Density rho [kg/m^3].
    pub density_kg_m3: f64,
    /// Linear thermal expansion coefficient alpha [1/K].
    pub thermal_expansion_per_k: f64,
    /// Thermal conductivity k [W/(m K)].
    pub conductivity_w_mk: f64,
    /// Specific heat capacity c [J/(kg K)].
    pub specific_heat_j_kgk: f64,
}

impl Material {
    /// AISI 52100 through-hardened bearing steel.
    /// E = 208 GPa, nu = 0.30, rho = 7830 kg/m^3 (Harris & Kotzalas, Rolling
    /// Bearing Analysis 5th ed., vol. 1, table of bearing steels);
    /// alpha = 12.5e-6 1/K, k = 42.7 W/(m K), c = 458 J/(kg K) (ASM Handbook
    /// vol. 1, 52100 at room temperature). Seed A Table 1 prints 1.36e-7 1/K
    /// for the expansion coefficient, a typo for about 1.2e-5 (docs/concepts/physics.md §8).
    pub fn steel_52100() -> Self {
        Material {
            name: "52100".into(),
            youngs_modulus_pa: 208e9,
            poisson_ratio: 0.30,
            density_kg_m3: 7830.0,
            thermal_expansion_per_k: 12.5e-6,
            conductivity_w_mk: 42.7,
            specific_heat_j_kgk: 458.0,
        }
    }

    /// Hot-isostatically-pressed silicon nitride, bearing grade (ASTM F2094
    /// class I typical values): E = 310 GPa, nu = 0.26, rho = 3200 kg/m^3,
    /// alpha = 3.2e-6 1/K, k = 30 W/(m K), c = 690 J/(kg K).
    pub fn silicon_nitride() -> Self {
        Material {
            name: "Si3N4".into(),
            youngs_modulus_pa: 310e9,
            poisson_ratio: 0.26,
            density_kg_m3: 3200.0,
            thermal_expansion_per_k: 3.2e-6,
            conductivity_w_mk: 30.0,
            specific_heat_j_kgk: 690.0,
        }
    }

    /// Structural steel for shafts and gears (seed A Table 3 corrected:
    /// E = 206 GPa, nu = 0.25 as printed for the gears; rho = 7800 kg/m^3);
    /// alpha = 11.5e-6 1/K, k = 45 W/(m K), c = 460 J/(kg K) (typical carbon
    /// and low-alloy steel values, ASM Handbook vol. 1).
    pub fn shaft_steel() -> Self {
        Material {
            name: "shaft-steel".into(),
            youngs_modulus_pa: 206e9,
            poisson_ratio: 0.25,
            density_kg_m3: 7800.0,
            thermal_expansion_per_k: 11.5e-6,
            conductivity_w_mk: 45.0,
            specific_heat_j_kgk: 460.0,
        }
    }

    /// Grey cast iron housing (EN-GJL-250 typical): E = 110 GPa, nu = 0.26,
    /// rho = 7200 kg/m^3, alpha = 10.5e-6 1/K, k = 48 W/(m K), c = 500 J/(kg K).
    pub fn cast_iron() -> Self {
        Material {
            name: "cast-iron".into(),
            youngs_modulus_pa: 110e9,
            poisson_ratio: 0.26,
            density_kg_m3: 7200.0,
            thermal_expansion_per_k: 10.5e-6,
            conductivity_w_mk: 48.0,
            specific_heat_j_kgk: 500.0,
        }
    }

    /// Cast aluminium housing (AlSi9Cu3 typical, e-drive gearbox cases):
    /// E = 75 GPa, nu = 0.33, rho = 2700 kg/m^3, alpha = 21e-6 1/K,
    /// k = 110 W/(m K), c = 900 J/(kg K).
    pub fn aluminium() -> Self {
        Material {
            name: "aluminium".into(),
            youngs_modulus_pa: 75e9,
            poisson_ratio: 0.33,
            density_kg_m3: 2700.0,
            thermal_expansion_per_k: 21e-6,
            conductivity_w_mk: 110.0,
            specific_heat_j_kgk: 900.0,
        }
    }

    /// Names accepted by [`Material::preset`].
    pub const PRESETS: [&'static str; 5] = ["52100", "Si3N4", "shaft-steel", "cast-iron", "aluminium"];

    /// A preset by name (case-insensitive; "steel" is an alias of "52100",
    /// "ceramic" of "Si3N4").
    pub fn preset(name: &str) -> Result<Self> {
        match name.to_ascii_lowercase().as_str() {
            "52100" | "steel" | "bearing-steel" => Ok(Self::steel_52100()),
            "si3n4" | "ceramic" | "silicon-nitride" => Ok(Self::silicon_nitride()),
            "shaft-steel" => Ok(Self::shaft_steel()),
            "cast-iron" => Ok(Self::cast_iron()),
            "aluminium" | "aluminum" => Ok(Self::aluminium()),
            _ => Err(crate::Error::config(
                "material",
                name,
                format!("unknown material preset; known: {}", Self::PRESETS.join(", ")),
            )),
        }
    }

    /// Check every property is physical.
    pub fn validate(&self) -> Result<()> {
        positive("youngs_modulus_gpa", self.youngs_modulus_pa / 1e9)?;
        in_range("poisson_ratio", self.poisson_ratio, 0.0, 0.4999)?;
        positive("density_kg_m3", self.density_kg_m3)?;
        in_range("thermal_expansion_per_k", self.thermal_expansion_per_k, 0.0, 1e-3)?;
        positive("conductivity_w_mk", self.conductivity_w_mk)?;
        positive("specific_heat_j_kgk", self.specific_heat_j_kgk)?;
        Ok(())
    }

    /// (1 - nu^2) / E, the compliance term of the Hertz reduced modulus [1/Pa].
    #[inline]
    pub fn hertz_compliance(&self) -> f64 {
        (1.0 - self.poisson_ratio * self.poisson_ratio) / self.youngs_modulus_pa
    }
}

/// Hertz reduced modulus E' = 2 / ((1-nu1^2)/E1 + (1-nu2^2)/E2) \[Pa\]
/// (docs/concepts/physics.md §2; Harris & Kotzalas eq. 6.40 uses the same E').
pub fn reduced_modulus(a: &Material, b: &Material) -> f64 {
    2.0 / (a.hertz_compliance() + b.hertz_compliance())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn presets_are_valid() {
        for n in Material::PRESETS {
            Material::preset(n).unwrap().validate().unwrap();
        }
        assert!(Material::preset("unobtainium").is_err());
    }

    #[test]
    fn reduced_modulus_steel_on_steel() {
        let s = Material::steel_52100();
        // Same material: E' = E / (1 - nu^2).
        let e = reduced_modulus(&s, &s);
        assert!((e - 208e9 / (1.0 - 0.09)).abs() / e < 1e-12);
        // Hybrid pair is stiffer than all-steel and softer than all-ceramic.
        let c = Material::silicon_nitride();
        let h = reduced_modulus(&s, &c);
        assert!(h > e && h < reduced_modulus(&c, &c));
    }

    #[test]
    fn silicon_nitride_expands_about_a_quarter_of_steel() {
        let r = Material::silicon_nitride().thermal_expansion_per_k / Material::steel_52100().thermal_expansion_per_k;
        assert!(r > 0.2 && r < 0.3, "{r}");
    }
}
