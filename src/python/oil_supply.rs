//! The oil supply keywords from Python (`thermobear.thermal.oil_supply`):
//! every key present, None where not given.

use pyo3::prelude::*;

use crate::thermal::oil_supply::SupplyInput;

/// The supply keywords of a thermal call (a dict with every key).
#[derive(FromPyObject, Default, Clone, Copy)]
#[pyo3(from_item_all)]
pub struct PySupplyInput {
    oil_flow_cm3_per_min: Option<f64>,
    jet_count: Option<u32>,
    jet_velocity_m_per_s: Option<f64>,
    oil_volume_cm3_per_h: Option<f64>,
    air_flow_l_per_min: Option<f64>,
    oil_level_mm: Option<f64>,
    grease_fill_fraction: Option<f64>,
    oil_flow_scale: Option<f64>,
    cavity_fraction_speed_exponent: Option<f64>,
}

impl From<PySupplyInput> for SupplyInput {
    fn from(p: PySupplyInput) -> Self {
        SupplyInput {
            oil_flow_cm3_per_min: p.oil_flow_cm3_per_min,
            jet_count: p.jet_count,
            jet_velocity_m_per_s: p.jet_velocity_m_per_s,
            oil_volume_cm3_per_h: p.oil_volume_cm3_per_h,
            air_flow_l_per_min: p.air_flow_l_per_min,
            oil_level_mm: p.oil_level_mm,
            grease_fill_fraction: p.grease_fill_fraction,
            oil_flow_scale: p.oil_flow_scale,
            cavity_fraction_speed_exponent: p.cavity_fraction_speed_exponent,
        }
    }
}
