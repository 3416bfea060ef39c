//! Stable, versioned serialisation of the model structs (pickling, caches,
//! clusters).
//!
//! A model is stored as an [`Envelope`]: the format name `"thermobear"`, the
//! format [`VERSION`], the kind of object (`"Bearing"`, `"Material"`, ...) and
//! the serde JSON text of its defining data. Floats are written with the
//! shortest representation that parses back to the same bits, so a model
//! restored from an envelope gives bit-identical results. An envelope of
//! another format, version or kind is refused with [`Error::Config`] naming
//! the field and the value.

use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};

/// Format name stored in every envelope.
pub const FORMAT: &str = "thermobear";

/// Version of the envelope layout and of the serialised model data.
pub const VERSION: u32 = 1;

/// A versioned, self-describing serialised model.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct Envelope {
    /// Always [`FORMAT`].
    pub format: String,
    /// [`VERSION`] of the writer.
    pub version: u32,
    /// Kind of object, e.g. `"Bearing"`.
    pub kind: String,
    /// serde JSON text of the object.
    pub data: String,
}

impl Envelope {
    /// Serialise `value` as an envelope of `kind`.
    pub fn wrap<T: Serialize>(kind: &str, value: &T) -> Result<Self> {
        let data = serde_json::to_string(value).map_err(|e| Error::config("data", kind, e.to_string()))?;
        Ok(Envelope {
            format: FORMAT.to_string(),
            version: VERSION,
            kind: kind.to_string(),
            data,
        })
    }

    /// Check format and version (any kind).
    pub fn check(&self) -> Result<()> {
        if self.format != FORMAT {
            return Err(Error::config(
                "format",
                &self.format,
                format!("not a {FORMAT} serialisation"),
            ));
        }
        if self.version != VERSION {
            return Err(Error::config(
                "version",
                self.version,
                format!("unsupported serialisation version (this build reads version {VERSION})"),
            ));
        }
        Ok(())
    }

    /// Deserialise the data of an envelope that must be of `kind`.
    pub fn open<T: DeserializeOwned>(&self, kind: &str) -> Result<T> {
        self.check()?;
        if self.kind != kind {
            return Err(Error::config("kind", &self.kind, format!("expected \"{kind}\"")));
        }
        serde_json::from_str(&self.data).map_err(|e| Error::config("data", kind, e.to_string()))
    }

    /// The whole envelope as JSON text.
    pub fn to_json(&self) -> Result<String> {
        serde_json::to_string(self).map_err(|e| Error::config("envelope", &self.kind, e.to_string()))
    }

    /// An envelope from JSON text (format and version checked).
    pub fn from_json(text: &str) -> Result<Self> {
        let e: Envelope = serde_json::from_str(text).map_err(|e| Error::config("envelope", "json", e.to_string()))?;
        e.check()?;
        Ok(e)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearing::Bearing;
    use crate::gear::{GearPair, GearPairSpec, TableGearData, TypoWarning};
    use crate::materials::Material;
    use crate::spindle::{Preload, Spindle, SpindleConfig};

    fn round<T: Serialize + DeserializeOwned>(kind: &str, v: &T) -> T {
        let env = Envelope::wrap(kind, v).unwrap();
        let text = env.to_json().unwrap();
        Envelope::from_json(&text).unwrap().open(kind).unwrap()
    }

    #[test]
    fn materials_round_trip_exactly() {
        for name in Material::PRESETS {
            let m = Material::preset(name).unwrap();
            assert_eq!(round("Material", &m), m);
        }
        let odd = Material {
            name: "odd".into(),
            youngs_modulus_pa: 0.1 + 0.2,
            poisson_ratio: 1.0 / 3.0,
            density_kg_m3: 7_812.345_678_901_234,
            thermal_expansion_per_k: 1.1e-5 * 1.000_000_000_000_1,
            conductivity_w_mk: f64::MIN_POSITIVE,
            specific_heat_j_kgk: 5e-324,
        };
        let back = round("Material", &odd);
        assert_eq!(back.youngs_modulus_pa.to_bits(), odd.youngs_modulus_pa.to_bits());
        assert_eq!(back.specific_heat_j_kgk.to_bits(), odd.specific_heat_j_kgk.to_bits());
        assert_eq!(back, odd);
    }

    #[test]
    fn bearings_round_trip_exactly() {
        for name in crate::bearing::presets::PRESETS {
            let b = Bearing::preset(name).unwrap();
            let back: Bearing = round("Bearing", &b);
            back.validate().unwrap();
            assert_eq!(back, b);
        }
    }

    #[test]
    fn gear_specs_and_warnings_round_trip() {
        let pair = GearPair::preset("seed-electric-drive").unwrap();
        let spec: GearPairSpec = round("GearPair", &pair.spec);
        assert_eq!(spec, pair.spec);
        assert_eq!(GearPair::new(spec).unwrap(), pair);
        let ws = TableGearData::seed_electric_drive_as_printed().warnings();
        let back: Vec<TypoWarning> = round("warnings", &ws);
        assert_eq!(back, ws);
    }

    #[test]
    fn spindle_config_round_trips_and_rebuilds() {
        let mut cfg = SpindleConfig::preset("seed-ceramic-spindle").unwrap();
        cfg.preload = Preload::Rigid { force_n: 612.5 };
        let back: SpindleConfig = round("Spindle", &cfg);
        assert_eq!(back, cfg);
        let (a, b) = (Spindle::new(cfg).unwrap(), Spindle::new(back).unwrap());
        assert_eq!(a.config, b.config);
        let (fa, _) = a.isothermal(12_000.0).unwrap();
        let (fb, _) = b.isothermal(12_000.0).unwrap();
        assert_eq!(format!("{fa:?}"), format!("{fb:?}"));
    }

    #[test]
    fn wrong_version_format_or_kind_is_refused() {
        let m = Material::preset("steel").unwrap();
        let mut env = Envelope::wrap("Material", &m).unwrap();
        env.version = 99;
        let err = env.open::<Material>("Material").unwrap_err().to_string();
        assert!(err.contains("version") && err.contains("99"), "{err}");
        env.version = VERSION;
        let err = env.open::<Material>("Bearing").unwrap_err().to_string();
        assert!(err.contains("kind") && err.contains("Material"), "{err}");
        env.format = "other".into();
        let err = env.open::<Material>("Material").unwrap_err().to_string();
        assert!(err.contains("format") && err.contains("other"), "{err}");
    }
}
