//! A spindle configuration as data: [`SpindleConfig`] to and from JSON
//! (the form Python's spindle description is mapped onto), and the checks
//! of the network and geometry parameters ([`check_params`]) that
//! [`super::Spindle::new`] runs on every configuration, each naming its
//! field.
//!
//! ```
//! use thermobear::spindle::{Spindle, SpindleConfig};
//!
//! let cfg = SpindleConfig::preset("seed-steel-spindle").unwrap();
//! let back = SpindleConfig::from_json(&cfg.to_json().unwrap()).unwrap();
//! assert_eq!(back, cfg); // every float to the last bit
//! assert!(Spindle::new(back).is_ok());
//! ```

use super::coupled::SpindleConfig;
use crate::error::{finite, in_range, non_negative, positive, Error, Result};
use crate::thermal::presets::SpindleParams;

impl SpindleConfig {
    /// The configuration as JSON text (floats round-trip exactly).
    pub fn to_json(&self) -> Result<String> {
        serde_json::to_string(self).map_err(|e| Error::config("spindle_config", "json", e.to_string()))
    }

    /// A configuration from JSON text (the form of [`SpindleConfig::to_json`]).
    /// A syntax error, a missing or unknown-typed field is a
    /// [`Error::Config`] of `spindle_config` whose reason names the field,
    /// the line and the column; the values are checked by
    /// [`super::Spindle::new`].
    pub fn from_json(text: &str) -> Result<Self> {
        serde_json::from_str(text).map_err(|e| {
            Error::config(
                "spindle_config",
                format!("line {} column {}", e.line(), e.column()),
                e.to_string(),
            )
        })
    }
}

/// Check the network and geometry of a spindle: every length, loss, flow
/// and film input by its field name (SI, as stored), and the fits the
/// network needs (rotor core between the pairs, stator bore above the
/// rotor, sleeve around stator and bearings, a sleeve left between the
/// bearing-seat housings).
pub fn check_params(p: &SpindleParams) -> Result<()> {
    for (name, v) in [
        ("front_span_m", p.front_span_m),
        ("rear_span_m", p.rear_span_m),
        ("rotor_diameter_m", p.rotor_diameter_m),
        ("rotor_length_m", p.rotor_length_m),
        ("air_gap_m", p.air_gap_m),
        ("stator_outer_diameter_m", p.stator_outer_diameter_m),
        ("sleeve_outer_diameter_m", p.sleeve_outer_diameter_m),
        ("front_housing_length_m", p.front_housing_length_m),
        ("rear_housing_length_m", p.rear_housing_length_m),
        ("water_flow_l_min", p.water_flow_l_min),
        ("channel_width_m", p.channel_width_m),
        ("channel_height_m", p.channel_height_m),
        ("stator_contact_w_m2k", p.stator_contact_w_m2k),
        ("lubrication_factor_f0", p.lubrication_factor_f0),
        ("loss_reference_rpm", p.loss_reference_rpm),
    ] {
        positive(name, v)?;
    }
    for (name, v) in [
        ("nose_length_m", p.nose_length_m),
        ("stator_copper_w", p.stator_copper_w),
        ("stator_iron_w", p.stator_iron_w),
        ("rotor_copper_w", p.rotor_copper_w),
        ("rotor_mechanical_w", p.rotor_mechanical_w),
    ] {
        non_negative(name, v)?;
    }
    for (name, v) in [
        ("water_temperature_c", p.water_temperature_c),
        ("ambient_temperature_c", p.ambient_temperature_c),
        ("oil_air_temperature_c", p.oil_air_temperature_c),
    ] {
        finite(name, v)?;
    }
    if let Some(h) = p.outer_ring_contact_w_m2k {
        positive("outer_ring_contact_w_m2k", h)?;
    }
    for [length, outer, inner] in p.shaft_segments_m.iter().flatten() {
        positive("shaft_segment_length_m", *length)?;
        positive("shaft_segment_outer_diameter_m", *outer)?;
        in_range("shaft_segment_bore_m", *inner, 0.0, *outer)?;
        if *inner >= *outer {
            return Err(Error::config(
                "shaft_segment_bore_m",
                *inner,
                "must be below the segment's outer diameter",
            ));
        }
    }
    positive("jacket_wetted_fraction", p.jacket_wetted_fraction)?;
    in_range("jacket_wetted_fraction", p.jacket_wetted_fraction, 0.0, 1.0)?;
    check_fits(p)
}

/// The fits of [`check_params`].
fn check_fits(p: &SpindleParams) -> Result<()> {
    let half_core = 0.5 * p.rotor_length_m;
    if half_core >= p.front_span_m.min(p.rear_span_m) {
        return Err(Error::config(
            "rotor_length_m",
            p.rotor_length_m,
            "the rotor core must end before the bearing pairs (half its length below both spans)",
        ));
    }
    let bore = p.rotor_diameter_m + 2.0 * p.air_gap_m;
    if p.stator_outer_diameter_m <= bore {
        return Err(Error::config(
            "stator_outer_diameter_m",
            p.stator_outer_diameter_m,
            format!("must exceed the stator bore (rotor diameter + 2 air gaps = {bore} m)"),
        ));
    }
    let seats = p
        .front_bearing
        .geometry
        .outer_diameter_m
        .max(p.rear_bearing.geometry.outer_diameter_m);
    let inside = p.stator_outer_diameter_m.max(seats);
    if p.sleeve_outer_diameter_m <= inside {
        return Err(Error::config(
            "sleeve_outer_diameter_m",
            p.sleeve_outer_diameter_m,
            format!("must exceed the stator and the bearings' outside diameters ({inside} m)"),
        ));
    }
    let longest = p.front_housing_length_m.max(p.rear_housing_length_m);
    if longest >= p.front_span_m + p.rear_span_m {
        return Err(Error::config(
            "front_housing_length_m",
            longest,
            "the bearing-seat housings must leave a sleeve between the pairs (shorter than the two spans)",
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spindle::Spindle;

    #[test]
    fn presets_round_trip_through_json_bit_for_bit() {
        for name in SpindleConfig::preset_names() {
            let cfg = SpindleConfig::preset(name).unwrap();
            let back = SpindleConfig::from_json(&cfg.to_json().unwrap()).unwrap();
            assert_eq!(back, cfg, "{name}");
            check_params(&back.params).unwrap();
        }
    }

    #[test]
    fn bad_fields_are_named() {
        let mut cfg = SpindleConfig::preset("seed-steel-spindle").unwrap();
        cfg.params.rotor_length_m = 0.3;
        let e = Spindle::new(cfg.clone()).unwrap_err().to_string();
        assert!(e.contains("rotor_length_m"), "{e}");
        cfg.params.rotor_length_m = 0.15;
        cfg.params.sleeve_outer_diameter_m = 0.1;
        let e = Spindle::new(cfg.clone()).unwrap_err().to_string();
        assert!(e.contains("sleeve_outer_diameter_m"), "{e}");
        cfg.params.sleeve_outer_diameter_m = 0.18;
        cfg.params.jacket_wetted_fraction = 1.5;
        let e = Spindle::new(cfg).unwrap_err().to_string();
        assert!(e.contains("jacket_wetted_fraction"), "{e}");
        let e = SpindleConfig::from_json("{\"params\": 1}").unwrap_err().to_string();
        assert!(e.contains("spindle_config") && e.contains("line 1"), "{e}");
    }
    #[test]
    fn load_friction_scale_defaults_to_one_and_is_checked() {
        // A stored configuration without the field loads with Harris' f1.
        let cfg = SpindleConfig::preset("seed-ceramic-spindle").unwrap();
        let mut v: serde_json::Value = serde_json::from_str(&cfg.to_json().unwrap()).unwrap();
        v.as_object_mut().unwrap().remove("load_friction_scale");
        let back = SpindleConfig::from_json(&v.to_string()).unwrap();
        assert_eq!(back.load_friction_scale, 1.0);
        assert_eq!(back, cfg);
        let mut bad = cfg.clone();
        bad.load_friction_scale = -1.0;
        let e = Spindle::new(bad).unwrap_err().to_string();
        assert!(e.contains("load_friction_scale"), "{e}");
        let mut skf = cfg;
        skf.heat_model = crate::thermal::friction::HeatModel::Skf;
        skf.load_friction_scale = 2.0;
        let e = Spindle::new(skf).unwrap_err().to_string();
        assert!(e.contains("load_friction_scale") && e.contains("palmgren"), "{e}");
    }

    #[test]
    fn shaft_segments_are_optional_and_checked() {
        // Without segments nothing is written (stored files stay as they were).
        let cfg = SpindleConfig::preset("seed-ceramic-spindle").unwrap();
        assert!(!cfg.to_json().unwrap().contains("shaft_segments_m"));
        let mut with = cfg.clone();
        with.params.shaft_segments_m = Some(vec![[0.05, 0.06, 0.02], [0.3, 0.045, 0.018]]);
        let back = SpindleConfig::from_json(&with.to_json().unwrap()).unwrap();
        assert_eq!(back, with);
        assert!(check_params(&with.params).is_ok());
        for (bad, field) in [
            ([0.0, 0.06, 0.02], "shaft_segment_length_m"),
            ([0.05, -0.06, 0.0], "shaft_segment_outer_diameter_m"),
            ([0.05, 0.06, 0.06], "shaft_segment_bore_m"),
        ] {
            let mut p = cfg.params.clone();
            p.shaft_segments_m = Some(vec![bad]);
            let e = check_params(&p).unwrap_err().to_string();
            assert!(e.contains(field), "{e}");
        }
    }

    #[test]
    fn extra_heat_defaults_to_zero() {
        // A stored configuration without the field loads without extra heat.
        let cfg = SpindleConfig::preset("seed-ceramic-spindle").unwrap();
        let mut v: serde_json::Value = serde_json::from_str(&cfg.to_json().unwrap()).unwrap();
        v.as_object_mut().unwrap().remove("extra_heat_w");
        let back = SpindleConfig::from_json(&v.to_string()).unwrap();
        assert_eq!((back.extra_heat_w, back), (0.0, cfg));
    }
}
