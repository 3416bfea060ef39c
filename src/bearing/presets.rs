//! Built-in bearings.
//!
//! * `6208` — seed A Table 1 (Liu et al., Sensors 2021, 21, 309): 9 balls of
//!   12 mm on a 60 mm pitch circle, f_i = 0.52, f_o = 0.53 (groove radii 6.24 /
//!   6.36 mm), diametral clearance 0.04 mm, bore 40 mm, outside 80 mm; width
//!   18 mm from the ISO 15 boundary dimensions of a 6208.
//! * `7008C`, `7009C` — seed B's spindle bearings. Boundary dimensions from
//!   ISO 15 (7008: 40 x 68 x 15 mm; 7009: 45 x 75 x 16 mm), C = 15 deg free
//!   contact angle. The internal geometry is not published by the seed or
//!   catalogues; we assume (and state): pitch diameter (bore + OD)/2; ball
//!   diameter the standard inch ball nearest 0.3 (OD - bore) (Harris &
//!   Kotzalas vol. 1 ch. 1 design proportion, 0.265-0.345 of the section):
//!   5/16 in = 7.938 mm for 7008C, 11/32 in = 8.731 mm for 7009C;
//!   16 balls each (about 75 % of the maximum that fits, typical of spindle
//!   bearings with a machined cage); f_i = 0.52, f_o = 0.53 as in seed A.
//!
//! Each comes in a steel variant and `-hybrid` (Si3N4 balls, steel rings);
//! `-ceramic` is full Si3N4.

use super::{Bearing, BearingGeometry};
use crate::error::{Error, Result};
use crate::materials::Material;

/// Names accepted by [`Bearing::preset`].
pub const PRESETS: [&str; 9] = [
    "6208",
    "6208-hybrid",
    "6208-ceramic",
    "7008C",
    "7008C-hybrid",
    "7008C-ceramic",
    "7009C",
    "7009C-hybrid",
    "7009C-ceramic",
];

fn geometry(base: &str) -> Result<BearingGeometry> {
    let mm = 1e-3;
    match base {
        "6208" => BearingGeometry::deep_groove(
            9,
            12.0 * mm,
            60.0 * mm,
            0.52,
            0.53,
            0.04 * mm,
            40.0 * mm,
            80.0 * mm,
            18.0 * mm,
        ),
        "7008C" => BearingGeometry::angular_contact(
            16,
            7.938 * mm,
            54.0 * mm,
            0.52,
            0.53,
            15f64.to_radians(),
            40.0 * mm,
            68.0 * mm,
            15.0 * mm,
        ),
        "7009C" => BearingGeometry::angular_contact(
            16,
            8.731 * mm,
            60.0 * mm,
            0.52,
            0.53,
            15f64.to_radians(),
            45.0 * mm,
            75.0 * mm,
            16.0 * mm,
        ),
        _ => Err(Error::config(
            "bearing",
            base,
            format!("unknown bearing preset; known: {}", PRESETS.join(", ")),
        )),
    }
}

impl Bearing {
    /// A built-in bearing by name (see module docs); case-insensitive suffix.
    pub fn preset(name: &str) -> Result<Bearing> {
        let (base, variant) = match name.split_once('-') {
            Some((b, v)) => (b, v.to_ascii_lowercase()),
            None => (name, "steel".to_string()),
        };
        let base_upper = base.to_ascii_uppercase();
        let g = geometry(&base_upper).map_err(|_| {
            Error::config(
                "bearing",
                name,
                format!("unknown bearing preset; known: {}", PRESETS.join(", ")),
            )
        })?;
        let steel = Material::steel_52100();
        let si3n4 = Material::silicon_nitride();
        let (rings, ball) = match variant.as_str() {
            "steel" => (steel.clone(), steel),
            "hybrid" => (steel, si3n4),
            "ceramic" => (si3n4.clone(), si3n4),
            _ => {
                return Err(Error::config(
                    "bearing",
                    name,
                    "unknown variant; use -hybrid (Si3N4 balls) or -ceramic (all Si3N4)",
                ))
            }
        };
        let canonical = if variant == "steel" {
            base_upper.clone()
        } else {
            format!("{base_upper}-{variant}")
        };
        Bearing::new(canonical, g, rings, ball)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn all_presets_build() {
        for p in PRESETS {
            let b = Bearing::preset(p).unwrap();
            assert_eq!(b.name, p);
        }
        assert!(Bearing::preset("6209").is_err());
        assert!(Bearing::preset("7009C-gold").is_err());
        assert_eq!(Bearing::preset("7009c").unwrap().name, "7009C");
    }
}
