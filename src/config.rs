//! The system description file (TOML). Engineering units with the unit in
//! every key (`ball_diameter_mm`, `speed_rpm`); unknown keys are rejected
//! with their name. Later sections (thermal, gear, spindle) extend
//! [`SystemConfig`].
//!
//! ```toml
//! [[material]]              # optional user materials, by name
//! name = "soft-steel"
//! base = "52100"            # start from a preset, override any property
//! youngs_modulus_gpa = 200.0
//!
//! [bearing]
//! preset = "6208"           # or give the geometry below (overrides the preset)
//! ring_material = "52100"
//! ball_material = "Si3N4"
//!
//! [operating]
//! speed_rpm = 16000.0
//! axial_n = 2680.9
//! radial_n = 1189.9
//!
//! [sweep]
//! speed_start_rpm = 6500.0
//! speed_stop_rpm = 16500.0
//! speed_count = 101
//!
//! [model]
//! effects = ["centrifugal_force", "gyroscopic_moment", "ring_centrifugal_expansion"]
//! extra_heat_w = 0.0               # optional coupled-thermal calibration inputs
//! housing_conductance_scale = 1.0
//! churning_oil_fraction = 0.0      # oil volume fraction of the cavity mixture (0..1)
//! heat_model = "palmgren"          # or "skf" (docs/concepts/physics.md §9)
//! # lubrication = "jet"            # grease, oil-air, oil-mist, jet, oil-bath
//! # lubrication_factor_f0 = 1.0    # Palmgren f0 (default: the method's)
//! # [model.oil_supply]             # the supply of the method (physics.md §9)
//! # oil_flow_cm3_per_min = 500.0   # jet; oil-air: oil_volume_cm3_per_h, air_flow_l_per_min
//! ```

use serde::Deserialize;

use crate::bearing::{Bearing, BearingGeometry};
use crate::effects::EffectSet;
use crate::error::{Error, Result};
use crate::materials::Material;

/// A whole system description.
#[derive(Debug, Clone, Default, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct SystemConfig {
    /// Optional title.
    pub name: Option<String>,
    /// User materials, the `[[material]]` tables (empty when none); looked
    /// up by name before the presets in [`SystemConfig::material`].
    #[serde(default, rename = "material")]
    pub materials: Vec<MaterialConfig>,
    /// The `[bearing]` section; required by [`SystemConfig::bearing`].
    pub bearing: Option<BearingConfig>,
    /// The `[operating]` section: one speed and load case.
    pub operating: Option<OperatingConfig>,
    /// The `[sweep]` section: the speeds of [`SystemConfig::speeds_rpm`].
    pub sweep: Option<SweepConfig>,
    /// The `[model]` section: effect switches and coupled-thermal inputs.
    pub model: Option<ModelConfig>,
    /// Bearings a `[bearing] preset` may name beyond the built-in presets,
    /// by the name written there (not part of the file: the caller adds
    /// them with [`SystemConfig::with_catalogue`], e.g. the Python
    /// package's bearings by catalogue designation).
    #[serde(skip)]
    pub catalogue: std::collections::HashMap<String, Bearing>,
}

/// A user material: a preset `base` with any property overridden.
#[derive(Debug, Clone, Default, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct MaterialConfig {
    /// Name the other sections use to refer to this material (required).
    pub name: String,
    /// Preset to start from (a [`Material::PRESETS`] name or alias); default "52100".
    pub base: Option<String>,
    /// Young's modulus E \[GPa\] (converted to Pa); overrides the base.
    pub youngs_modulus_gpa: Option<f64>,
    /// Poisson's ratio nu [-], 0 to 0.4999; overrides the base.
    pub poisson_ratio: Option<f64>,
    /// Density rho [kg/m^3]; overrides the base.
    pub density_kg_m3: Option<f64>,
    /// Linear thermal expansion coefficient alpha [1/K], 0 to 1e-3; overrides the base.
    pub thermal_expansion_per_k: Option<f64>,
    /// Thermal conductivity k [W/(m K)]; overrides the base.
    pub conductivity_w_mk: Option<f64>,
    /// Specific heat capacity c [J/(kg K)]; overrides the base.
    pub specific_heat_j_kgk: Option<f64>,
}

/// A bearing: a preset and/or explicit geometry (explicit keys win).
#[derive(Debug, Clone, Default, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct BearingConfig {
    /// Bearing preset to start from (a [`Bearing::preset`] name, e.g. "6208", "7009C").
    pub preset: Option<String>,
    /// Display name; default the preset's name, else "custom".
    pub name: Option<String>,
    /// "deep-groove" or "angular-contact". Default: the preset's type; without
    /// a preset, angular-contact if `free_contact_angle_deg` is given.
    #[serde(rename = "type")]
    pub bearing_type: Option<String>,
    /// Number of balls Z.
    pub ball_count: Option<usize>,
    /// Ball diameter D \[mm\].
    pub ball_diameter_mm: Option<f64>,
    /// Pitch diameter dm \[mm\].
    pub pitch_diameter_mm: Option<f64>,
    /// Inner groove conformity f_i = r_i / D [-] (> 0.5).
    pub inner_conformity: Option<f64>,
    /// Outer groove conformity f_o = r_o / D [-] (> 0.5).
    pub outer_conformity: Option<f64>,
    /// Diametral clearance Pd \[mm\]; read for a deep-groove bearing only
    /// (its free contact angle follows from it).
    pub diametral_clearance_mm: Option<f64>,
    /// Free (unloaded) contact angle alpha0 \[deg\]; read for an
    /// angular-contact bearing only (its clearance follows from it).
    pub free_contact_angle_deg: Option<f64>,
    /// Bore d \[mm\].
    pub bore_mm: Option<f64>,
    /// Outside diameter D_o \[mm\].
    pub outer_diameter_mm: Option<f64>,
    /// Width B \[mm\].
    pub width_mm: Option<f64>,
    /// Material of both rings (user material or preset name); default the
    /// preset's, else 52100.
    pub ring_material: Option<String>,
    /// Ball material (user material or preset name); default the preset's, else 52100.
    pub ball_material: Option<String>,
    /// Shaft material under the inner ring; default shaft steel.
    pub shaft_material: Option<String>,
    /// Shaft bore diameter \[mm\]; 0 (default) for a solid shaft, must be
    /// smaller than the bearing bore.
    pub shaft_bore_mm: Option<f64>,
}

/// One operating point.
#[derive(Debug, Clone, Default, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct OperatingConfig {
    /// Shaft (inner-ring) speed \[rpm\]; default 0 (static solve).
    #[serde(default)]
    pub speed_rpm: f64,
    /// Axial load Fz on the inner ring \[N\]; default 0.
    #[serde(default)]
    pub axial_n: f64,
    /// Radial load Fx on the inner ring \[N\]; default 0.
    #[serde(default)]
    pub radial_n: f64,
    /// Tilting moment My on the inner ring \[N m\]; default 0.
    #[serde(default)]
    pub moment_n_m: f64,
    /// The same moment in N mm: the older key, read for one release
    /// (`moment_n_m` is used when both are given).
    #[serde(default)]
    pub moment_nmm: f64,
}

/// An evenly spaced speed range, or an explicit list.
#[derive(Debug, Clone, Default, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct SweepConfig {
    /// First speed of the evenly spaced range \[rpm\] (>= 0).
    pub speed_start_rpm: Option<f64>,
    /// Last speed of the range, inclusive \[rpm\] (>= 0).
    pub speed_stop_rpm: Option<f64>,
    /// Number of speeds in the range (>= 1).
    pub speed_count: Option<usize>,
    /// Explicit speeds \[rpm\] (each >= 0); when given, the range keys are ignored.
    pub speeds_rpm: Option<Vec<f64>>,
}

/// Model switches.
#[derive(Debug, Clone, Default, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ModelConfig {
    /// Effects that are on; absent means all.
    pub effects: Option<Vec<String>>,
    /// "outer" (default) or "inner" raceway control.
    pub raceway_control: Option<String>,
    /// Extra heat at the bearing \[W\] (coupled thermal model; see
    /// [`crate::thermal::coupled::CoupledOptions::extra_heat_w`]).
    pub extra_heat_w: Option<f64>,
    /// Housing-to-ambient conductance scale (coupled thermal model; see
    /// [`crate::thermal::coupled::CoupledOptions::housing_conductance_scale`]).
    pub housing_conductance_scale: Option<f64>,
    /// Oil volume fraction of the oil-air mixture in the bearing cavity
    /// (0..1, dimensionless) for the ball drag heat (coupled thermal model;
    /// see [`crate::thermal::coupled::CoupledOptions::churning_oil_fraction`]).
    pub churning_oil_fraction: Option<f64>,
    /// Palmgren's lubrication factor f0 (dimensionless, > 0); given, it
    /// overrides the `lubrication` method's default (e.g. a source that
    /// states both its supply and its f0).
    pub lubrication_factor_f0: Option<f64>,
    /// Heat model: "palmgren" (default) or "skf" (docs/concepts/physics.md §9).
    pub heat_model: Option<String>,
    /// Lubrication method ("grease", "oil-air", "oil-mist", "jet",
    /// "oil-bath"); its defaults fill f0 and the drag oil fraction when the
    /// `[bearing]` section is there and `churning_oil_fraction` is not given
    /// ([`crate::thermal::friction::Lubrication::defaults`]).
    pub lubrication: Option<String>,
    /// Oil supply, `[model.oil_supply]` (docs/concepts/physics.md §9, oil
    /// supply): the keys of the lubrication method (`oil_flow_cm3_per_min`,
    /// `jet_count`, `jet_velocity_m_per_s`; `oil_volume_cm3_per_h`,
    /// `air_flow_l_per_min`; `oil_level_mm`; `grease_fill_fraction`) and the
    /// tunings `oil_flow_scale`, `cavity_fraction_speed_exponent`
    /// ([`crate::thermal::oil_supply::SupplyInput::resolve`]).
    pub oil_supply: Option<crate::thermal::oil_supply::SupplyInput>,
}

impl SystemConfig {
    /// Parse TOML text. Unknown keys, wrong types and syntax errors come
    /// back as [`Error::Parse`] with the key and line.
    pub fn from_toml(text: &str) -> Result<Self> {
        toml::from_str(text).map_err(|e| Error::Parse(e.to_string().trim().replace('\n', " ")))
    }

    /// The same description with `bearings` (name as written -> bearing)
    /// resolvable as `[bearing] preset` names after the built-in presets.
    pub fn with_catalogue(mut self, bearings: std::collections::HashMap<String, Bearing>) -> Self {
        self.catalogue = bearings;
        self
    }

    /// The bearing a `[bearing] preset` name stands for: a built-in preset,
    /// else a catalogue bearing of that name (the preset's error otherwise).
    pub fn preset_bearing(&self, name: &str) -> Result<Bearing> {
        Bearing::preset(name).or_else(|e| self.catalogue.get(name).cloned().ok_or(e))
    }

    /// Read and parse a file.
    pub fn from_file(path: &std::path::Path) -> Result<Self> {
        let text = std::fs::read_to_string(path)
            .map_err(|e| Error::config("path", path.display(), format!("cannot read: {e}")))?;
        Self::from_toml(&text)
    }

    /// Resolve a material name: user materials first, then presets.
    pub fn material(&self, name: &str) -> Result<Material> {
        if let Some(m) = self.materials.iter().find(|m| m.name == name) {
            return m.build();
        }
        Material::preset(name)
    }

    /// Build the bearing of the `[bearing]` section.
    pub fn bearing(&self) -> Result<Bearing> {
        let bc = self
            .bearing
            .as_ref()
            .ok_or_else(|| Error::config("bearing", "missing", "the description has no [bearing] section"))?;
        bc.build(self)
    }

    /// The effects of `[model]` (all when absent).
    pub fn effects(&self) -> Result<EffectSet> {
        match self.model.as_ref().and_then(|m| m.effects.as_ref()) {
            Some(names) => EffectSet::from_names(names),
            None => Ok(EffectSet::all()),
        }
    }

    /// The raceway control of `[model]` ("outer" when absent; another name
    /// is a `ConfigError` naming `raceway_control`).
    pub fn raceway_control(&self) -> Result<crate::bearing::RacewayControl> {
        match self.model.as_ref().and_then(|m| m.raceway_control.as_deref()) {
            Some(name) => crate::bearing::RacewayControl::from_name(name),
            None => Ok(crate::bearing::RacewayControl::default()),
        }
    }

    /// The options of a bearing solve from `[model]`: its effects and its
    /// raceway control (the other options at their defaults).
    pub fn solve_options(&self) -> Result<crate::bearing::SolveOptions> {
        Ok(crate::bearing::SolveOptions {
            effects: self.effects()?,
            raceway_control: self.raceway_control()?,
            ..Default::default()
        })
    }

    /// The coupled thermal options with the `[model]` calibration inputs
    /// applied to `base` (validated: bad values name their key), its raceway
    /// control included.
    pub fn coupled_options(
        &self,
        base: crate::thermal::coupled::CoupledOptions,
    ) -> Result<crate::thermal::coupled::CoupledOptions> {
        let mut o = base;
        if let Some(m) = &self.model {
            if m.raceway_control.is_some() {
                o.solve.raceway_control = self.raceway_control()?;
            }
            if let Some(e) = m.extra_heat_w {
                o.extra_heat_w = e;
            }
            if let Some(k) = m.housing_conductance_scale {
                o.housing_conductance_scale = k;
            }
            if let Some(x) = m.churning_oil_fraction {
                o.churning_oil_fraction = x;
            }
            if let Some(h) = &m.heat_model {
                o.heat_model = crate::thermal::friction::HeatModel::from_name(h)?;
            }
            if let Some(l) = &m.lubrication {
                let kind = match &self.bearing {
                    Some(_) => self.bearing()?.geometry.bearing_type,
                    None => crate::bearing::BearingType::AngularContact,
                };
                let (lub, f0, x) = crate::thermal::friction::resolve_lubrication(
                    Some(l),
                    kind,
                    m.lubrication_factor_f0,
                    m.churning_oil_fraction,
                )?;
                o.lubrication = lub;
                o.lubrication_factor_f0 = f0;
                o.churning_oil_fraction = x;
            } else if let Some(f0) = m.lubrication_factor_f0 {
                o.lubrication_factor_f0 = f0;
            }
            o.oil_supply = m.oil_supply.unwrap_or_default().resolve(
                o.lubrication,
                m.lubrication.is_some(),
                m.churning_oil_fraction.is_some(),
            )?;
        }
        o.validate()?;
        Ok(o)
    }

    /// The speeds of `[sweep]`.
    pub fn speeds_rpm(&self) -> Result<Vec<f64>> {
        let s = self
            .sweep
            .as_ref()
            .ok_or_else(|| Error::config("sweep", "missing", "the description has no [sweep] section"))?;
        if let Some(v) = &s.speeds_rpm {
            for &x in v {
                crate::error::non_negative("speeds_rpm", x)?;
            }
            return Ok(v.clone());
        }
        match (s.speed_start_rpm, s.speed_stop_rpm, s.speed_count) {
            (Some(a), Some(b), Some(n)) => {
                crate::error::non_negative("speed_start_rpm", a)?;
                crate::error::non_negative("speed_stop_rpm", b)?;
                if n < 1 {
                    return Err(Error::config("speed_count", n, "must be at least 1"));
                }
                Ok(linspace(a, b, n))
            }
            _ => Err(Error::config(
                "sweep",
                "incomplete",
                "give speeds_rpm, or speed_start_rpm + speed_stop_rpm + speed_count",
            )),
        }
    }
}

/// n evenly spaced values from a to b inclusive.
pub fn linspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    if n == 1 {
        return vec![a];
    }
    (0..n).map(|i| a + (b - a) * i as f64 / (n - 1) as f64).collect()
}

impl MaterialConfig {
    /// Build the material: preset `base` (default 52100) with overrides.
    pub fn build(&self) -> Result<Material> {
        let mut m = Material::preset(self.base.as_deref().unwrap_or("52100"))?;
        m.name = self.name.clone();
        if let Some(v) = self.youngs_modulus_gpa {
            m.youngs_modulus_pa = v * 1e9;
        }
        if let Some(v) = self.poisson_ratio {
            m.poisson_ratio = v;
        }
        if let Some(v) = self.density_kg_m3 {
            m.density_kg_m3 = v;
        }
        if let Some(v) = self.thermal_expansion_per_k {
            m.thermal_expansion_per_k = v;
        }
        if let Some(v) = self.conductivity_w_mk {
            m.conductivity_w_mk = v;
        }
        if let Some(v) = self.specific_heat_j_kgk {
            m.specific_heat_j_kgk = v;
        }
        m.validate()?;
        Ok(m)
    }
}

impl BearingConfig {
    /// Build the bearing: start from the preset (if any), override geometry
    /// and materials with the explicit keys.
    pub fn build(&self, sys: &SystemConfig) -> Result<Bearing> {
        let mm = 1e-3;
        let base = match &self.preset {
            Some(p) => Some(sys.preset_bearing(p)?),
            None => None,
        };
        let bg = base.as_ref().map(|b| &b.geometry);
        let need = |field: &str, v: Option<f64>, from_base: Option<f64>| -> Result<f64> {
            v.or(from_base)
                .ok_or_else(|| Error::config(field, "missing", "give it or a `preset` to start from"))
        };
        let kind = match (&self.bearing_type, bg) {
            (Some(t), _) => t.to_ascii_lowercase(),
            (None, Some(g)) => g.bearing_type.name().to_string(),
            (None, None) => {
                if self.free_contact_angle_deg.is_some() {
                    "angular-contact".into()
                } else {
                    "deep-groove".into()
                }
            }
        };
        let z = self
            .ball_count
            .or(bg.map(|g| g.ball_count))
            .ok_or_else(|| Error::config("ball_count", "missing", "give it or a `preset` to start from"))?;
        let d = need(
            "ball_diameter_mm",
            self.ball_diameter_mm,
            bg.map(|g| g.ball_diameter_m / mm),
        )? * mm;
        let dm = need(
            "pitch_diameter_mm",
            self.pitch_diameter_mm,
            bg.map(|g| g.pitch_diameter_m / mm),
        )? * mm;
        let fi = need(
            "inner_conformity",
            self.inner_conformity,
            bg.map(|g| g.inner_conformity),
        )?;
        let fo = need(
            "outer_conformity",
            self.outer_conformity,
            bg.map(|g| g.outer_conformity),
        )?;
        let bore = need("bore_mm", self.bore_mm, bg.map(|g| g.bore_m / mm))? * mm;
        let od = need(
            "outer_diameter_mm",
            self.outer_diameter_mm,
            bg.map(|g| g.outer_diameter_m / mm),
        )? * mm;
        let w = need("width_mm", self.width_mm, bg.map(|g| g.width_m / mm))? * mm;
        let geometry = match kind.as_str() {
            "deep-groove" => {
                let pd = need(
                    "diametral_clearance_mm",
                    self.diametral_clearance_mm,
                    bg.map(|g| g.diametral_clearance_m / mm),
                )? * mm;
                BearingGeometry::deep_groove(z, d, dm, fi, fo, pd, bore, od, w)?
            }
            "angular-contact" => {
                let a0 = need(
                    "free_contact_angle_deg",
                    self.free_contact_angle_deg,
                    bg.map(|g| g.free_contact_angle_rad.to_degrees()),
                )?;
                BearingGeometry::angular_contact(z, d, dm, fi, fo, a0.to_radians(), bore, od, w)?
            }
            other => {
                return Err(Error::config(
                    "type",
                    other,
                    "must be \"deep-groove\" or \"angular-contact\"",
                ));
            }
        };
        let rings = match &self.ring_material {
            Some(n) => sys.material(n)?,
            None => base
                .as_ref()
                .map(|b| b.inner_ring.clone())
                .unwrap_or_else(Material::steel_52100),
        };
        let ball = match &self.ball_material {
            Some(n) => sys.material(n)?,
            None => base
                .as_ref()
                .map(|b| b.ball.clone())
                .unwrap_or_else(Material::steel_52100),
        };
        let name = self
            .name
            .clone()
            .or_else(|| base.as_ref().map(|b| b.name.clone()))
            .unwrap_or_else(|| "custom".into());
        let mut b = Bearing::new(name, geometry, rings, ball)?;
        if let Some(s) = &self.shaft_material {
            b.shaft = sys.material(s)?;
        }
        if let Some(s) = self.shaft_bore_mm {
            b.shaft_bore_m = s * mm;
        }
        b.validate()?;
        Ok(b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn preset_with_overrides_and_user_material() {
        let sys = SystemConfig::from_toml(
            r#"
            [[material]]
            name = "soft"
            base = "52100"
            youngs_modulus_gpa = 190.0

            [bearing]
            preset = "6208"
            diametral_clearance_mm = 0.02
            ball_material = "soft"
            "#,
        )
        .unwrap();
        let b = sys.bearing().unwrap();
        assert!((b.geometry.diametral_clearance_m - 0.02e-3).abs() < 1e-15);
        assert_eq!(b.geometry.ball_count, 9);
        assert!((b.ball.youngs_modulus_pa - 190e9).abs() < 1.0);
        assert!(sys.effects().unwrap() == EffectSet::all());
    }

    #[test]
    fn unknown_key_is_named() {
        let e = SystemConfig::from_toml("[bearing]\npreset = \"6208\"\nball_diameter = 12.0\n").unwrap_err();
        assert!(e.to_string().contains("ball_diameter"), "{e}");
        let e = SystemConfig::from_toml("[bearnig]\n").unwrap_err();
        assert!(e.to_string().contains("bearnig"), "{e}");
    }

    #[test]
    fn catalogue_bearings_resolve_after_the_presets() {
        let text = "[bearing]\npreset = \"7014C\"\nfree_contact_angle_deg = 25.0\n";
        let plain = SystemConfig::from_toml(text).unwrap();
        assert!(plain.bearing().is_err(), "not a built-in preset");
        let mut b = Bearing::preset("7009C").unwrap();
        b.name = "7014C".into();
        let mut cat = std::collections::HashMap::new();
        cat.insert("7014C".to_string(), b.clone());
        let got = plain.with_catalogue(cat.clone()).bearing().unwrap();
        // the catalogue bearing is the base; explicit keys still win
        assert_eq!(got.geometry.ball_count, b.geometry.ball_count);
        assert!((got.geometry.free_contact_angle_rad - 25f64.to_radians()).abs() < 1e-12);
        // a built-in preset is never shadowed by the catalogue
        cat.insert("6208".to_string(), b);
        let sys = SystemConfig::from_toml("[bearing]\npreset = \"6208\"\n").unwrap();
        assert_eq!(
            sys.with_catalogue(cat).bearing().unwrap(),
            Bearing::preset("6208").unwrap()
        );
    }

    #[test]
    fn explicit_geometry_matches_preset() {
        let sys = SystemConfig::from_toml(
            r#"
            [bearing]
            type = "deep-groove"
            ball_count = 9
            ball_diameter_mm = 12.0
            pitch_diameter_mm = 60.0
            inner_conformity = 0.52
            outer_conformity = 0.53
            diametral_clearance_mm = 0.04
            bore_mm = 40.0
            outer_diameter_mm = 80.0
            width_mm = 18.0
            [sweep]
            speed_start_rpm = 0.0
            speed_stop_rpm = 100.0
            speed_count = 3
            [model]
            effects = ["centrifugal_force"]
            "#,
        )
        .unwrap();
        assert_eq!(
            sys.bearing().unwrap().geometry,
            Bearing::preset("6208").unwrap().geometry
        );
        assert_eq!(sys.speeds_rpm().unwrap(), vec![0.0, 50.0, 100.0]);
        assert_eq!(sys.effects().unwrap().names(), vec!["centrifugal_force"]);
        let bad = SystemConfig::from_toml("[bearing]\npreset=\"6208\"\ninner_conformity = 0.5\n").unwrap();
        assert!(bad.bearing().unwrap_err().to_string().contains("inner_conformity"));
        let bad = SystemConfig::from_toml("[model]\neffects = [\"warp_drive\"]\n").unwrap();
        assert!(bad.effects().unwrap_err().to_string().contains("warp_drive"));
    }

    #[test]
    fn model_raceway_control_reaches_the_solve_and_the_thermal_model() {
        use crate::bearing::RacewayControl;
        use crate::thermal::coupled::CoupledOptions;
        let with = |body: &str| SystemConfig::from_toml(&format!("[model]\n{body}\n")).unwrap();
        let inner = with("raceway_control = \"inner\"");
        assert_eq!(inner.solve_options().unwrap().raceway_control, RacewayControl::Inner);
        let o = inner.coupled_options(CoupledOptions::default()).unwrap();
        assert_eq!(o.solve.raceway_control, RacewayControl::Inner);
        // Absent: outer control, the default of both.
        assert_eq!(with("").solve_options().unwrap().raceway_control, RacewayControl::Outer);
        for bad in [with("raceway_control = \"middle\"")] {
            for e in [
                bad.solve_options().unwrap_err(),
                bad.coupled_options(CoupledOptions::default()).unwrap_err(),
            ] {
                match e {
                    Error::Config { field, value, .. } => {
                        assert_eq!((field.as_str(), value.as_str()), ("raceway_control", "middle"))
                    }
                    other => panic!("{other}"),
                }
            }
        }
    }

    #[test]
    fn model_thermal_calibration_inputs_parse_and_validate() {
        use crate::thermal::coupled::CoupledOptions;
        let with = |body: &str| SystemConfig::from_toml(&format!("[model]\n{body}\n")).unwrap();
        let o = with("extra_heat_w = 12.5\nhousing_conductance_scale = 2.0")
            .coupled_options(CoupledOptions::default())
            .unwrap();
        assert_eq!((o.extra_heat_w, o.housing_conductance_scale), (12.5, 2.0));
        // Absent keys keep the baseline.
        let d = with("").coupled_options(CoupledOptions::default()).unwrap();
        assert_eq!(d, CoupledOptions::default());
        match with("extra_heat_w = -3.0").coupled_options(CoupledOptions::default()) {
            Err(Error::Config { field, .. }) => assert_eq!(field, "extra_heat_w"),
            other => panic!("{other:?}"),
        }
        assert!(SystemConfig::from_toml("[model]\nextra_heat = 1.0\n").is_err());
    }

    #[test]
    fn model_churning_oil_fraction_parses_and_is_a_volume_fraction() {
        use crate::thermal::coupled::CoupledOptions;
        let with = |body: &str| SystemConfig::from_toml(&format!("[model]\n{body}\n")).unwrap();
        let o = with("churning_oil_fraction = 0.02")
            .coupled_options(CoupledOptions::default())
            .unwrap();
        assert_eq!(o.churning_oil_fraction, 0.02);
        assert_eq!(
            CoupledOptions {
                churning_oil_fraction: 0.0,
                ..o
            },
            CoupledOptions::default()
        );
        // A fraction outside [0, 1] names its key.
        for bad in ["-0.1", "1.2"] {
            match with(&format!("churning_oil_fraction = {bad}")).coupled_options(CoupledOptions::default()) {
                Err(Error::Config { field, .. }) => assert_eq!(field, "churning_oil_fraction"),
                other => panic!("{bad}: {other:?}"),
            }
        }
    }

    #[test]
    fn model_heat_model_and_lubrication_parse() {
        use crate::thermal::coupled::CoupledOptions;
        use crate::thermal::friction::{HeatModel, Lubrication};
        let with = |body: &str| SystemConfig::from_toml(&format!("[model]\n{body}\n")).unwrap();
        let o = with("heat_model = \"skf\"\nlubrication = \"jet\"")
            .coupled_options(CoupledOptions::default())
            .unwrap();
        assert_eq!((o.heat_model, o.lubrication), (HeatModel::Skf, Lubrication::Jet));
        // No [bearing]: the angular-contact jet defaults (f0 6.6, X 3 %).
        assert_eq!((o.lubrication_factor_f0, o.churning_oil_fraction), (6.6, 0.03));
        match with("heat_model = \"harris\"").coupled_options(CoupledOptions::default()) {
            Err(Error::Config { field, .. }) => assert_eq!(field, "heat_model"),
            other => panic!("{other:?}"),
        }
        match with("lubrication = \"water\"").coupled_options(CoupledOptions::default()) {
            Err(Error::Config { field, .. }) => assert_eq!(field, "lubrication"),
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn model_oil_supply_parses_into_the_supply_of_the_method() {
        use crate::thermal::coupled::CoupledOptions;
        use crate::thermal::friction::Lubrication;
        use crate::thermal::oil_supply::OilSupply;
        let text = "[model]\nlubrication = \"jet\"\n[model.oil_supply]\noil_flow_cm3_per_min = 500.0\njet_count = 2\n";
        let o = SystemConfig::from_toml(text)
            .unwrap()
            .coupled_options(CoupledOptions::default())
            .unwrap();
        let s = o.oil_supply.unwrap();
        assert_eq!(
            s.supply,
            OilSupply::Jet {
                oil_flow_cm3_per_min: 500.0,
                jet_count: 2,
                jet_velocity_m_per_s: None
            }
        );
        // A stated f0 overrides the method's (a deep-groove jet: 4), with or
        // without a method; zero names its key.
        let f0 = |m: &str| {
            SystemConfig::from_toml(&format!("[bearing]\npreset = \"6208\"\n[model]\n{m}"))
                .unwrap()
                .coupled_options(CoupledOptions::default())
        };
        assert_eq!(f0("lubrication = \"jet\"\n").unwrap().lubrication_factor_f0, 4.0);
        let given = f0("lubrication = \"jet\"\nlubrication_factor_f0 = 1.0\n").unwrap();
        assert_eq!(
            (given.lubrication, given.lubrication_factor_f0),
            (Lubrication::Jet, 1.0)
        );
        assert_eq!(f0("lubrication_factor_f0 = 1.5\n").unwrap().lubrication_factor_f0, 1.5);
        match f0("lubrication = \"jet\"\nlubrication_factor_f0 = 0.0\n") {
            Err(Error::Config { field, .. }) => assert_eq!(field, "lubrication_factor_f0"),
            other => panic!("{other:?}"),
        }
        // A key of another method names itself; an unknown key is a parse error.
        let bad = "[model]\nlubrication = \"jet\"\n[model.oil_supply]\noil_level_mm = 5.0\n";
        match SystemConfig::from_toml(bad)
            .unwrap()
            .coupled_options(CoupledOptions::default())
        {
            Err(Error::Config { field, .. }) => assert_eq!(field, "oil_level_mm"),
            other => panic!("{other:?}"),
        }
        assert!(SystemConfig::from_toml("[model.oil_supply]\nflow = 1.0\n").is_err());
    }
}
