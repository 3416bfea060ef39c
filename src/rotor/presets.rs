//! The motorized spindle of seed B (ceramic spindle "170-30/15": 170 mm
//! housing, 30,000 rpm class, 15 kW; front pair 7009C and rear pair 7008C
//! back-to-back, rotor hot-pressed on the shaft, 0.3 mm air gap).
//!
//! Seed B's spindle tables are missing, so every dimension below is an
//! ASSUMPTION chosen to be consistent with that class of spindle, not a
//! value from the paper:
//!
//! * Bearing seats follow the catalogue bores: 7009C d = 45 mm, B = 16 mm;
//!   7008C d = 40 mm, B = 15 mm (ISO 15 dimension series 10).
//! * Shaft (z from the tool nose, m): nose flange 0-0.020 (OD 60, ID 30 mm,
//!   HSK-E40-class taper bore); front bearing seat 0.020-0.075 (OD 45);
//!   spacer 0.075-0.105 (OD 50); rotor seat 0.105-0.235 (OD 50); step
//!   0.235-0.275 (OD 45); rear bearing seat 0.275-0.320 (OD 40); rear end
//!   0.320-0.340 (OD 35, nut/encoder). Drawbar bore 16 mm behind the nose.
//!   Shaft steel (materials::Material::shaft_steel).
//! * Bearings at the width centres of each row: front pair 0.032 and
//!   0.048 m (rows 0.024-0.056), rear pair 0.2925 and 0.3075 m (rows
//!   0.285-0.315). The shift of the load centre by the contact angle is
//!   ignored (it widens a back-to-back pair by a few mm).
//! * Rotor core: 15 kW at 30,000 rpm is 4.8 N m; at a torque per rotor
//!   volume of ~10 kN m/m^3 (water-cooled high-speed induction motors) the
//!   core needs ~4.8e-4 m^3: OD 69.4 mm (70 mm stator bore minus 2 x 0.3 mm
//!   gap), ID 50 mm, length 120 mm (0.110-0.230 m), effective density
//!   7600 kg/m^3 (laminations with stacking factor ~0.95 and the cage), so
//!   ~1.66 kg, lumped as 5 slices at nodes. It adds mass and inertia but
//!   no bending stiffness (shrink-fitted laminations).
//! * Tool holder + tool (HSK-E40 class): 0.45 kg, Ip = 1.2e-4 kg m^2,
//!   Id = 4.0e-4 kg m^2 about the nose node (own Id plus the parallel-axis
//!   term of a ~30 mm overhang), lumped at z = 0; the x-theta coupling of
//!   the overhang is neglected.
//! * Bearings: placeholders until the bearing solver supplies the thermally
//!   coupled 5x5 matrices: radial 1e8 N/m per bearing (the brief's order of
//!   magnitude; seed B quotes up to 2.74e8, docs/concepts/physics.md §8),
//!   axial 2.5e7 N/m, no tilt stiffness per row (the pair's row spacing provides it), no
//!   bearing damping; 2 % modal damping ratio for the whole rotor-bearing
//!   system at rest.
//! * UMP (off by default): R = 34.7 mm, L = 120 mm, g0 = 0.3 mm, assumed
//!   RMS air-gap flux density 0.55 T (fundamental peak ~0.78 T, typical of
//!   induction motors), static eccentricity 10 % of the gap (30 um).

use std::sync::Arc;

use super::{BearingCoefficients, BearingModel, BearingSupport, Disk, RotorSpec, ShaftSection, UnbalancedMagneticPull};
use crate::error::Result;
use crate::materials::Material;

/// Maximum service speed of the 170-30/15 class \[rpm\].
pub const MAX_SPEED_RPM: f64 = 30_000.0;
/// Rated power of the 170-30/15 class \[W\].
pub const RATED_POWER_W: f64 = 15_000.0;
/// Tool nose (probe position for the shaft-end response) \[m\].
pub const NOSE_POSITION_M: f64 = 0.0;
/// Front (7009C) pair load positions \[m\].
pub const FRONT_BEARING_POSITIONS_M: [f64; 2] = [0.032, 0.048];
/// Rear (7008C) pair load positions \[m\].
pub const REAR_BEARING_POSITIONS_M: [f64; 2] = [0.2925, 0.3075];
/// Rotor core span \[m\].
pub const ROTOR_CORE_SPAN_M: (f64, f64) = (0.110, 0.230);
/// Rotor core outer diameter \[m\] (70 mm stator bore - 2 x 0.3 mm air gap).
pub const ROTOR_CORE_OUTER_DIAMETER_M: f64 = 0.0694;
/// Air gap of seed B \[m\].
pub const AIR_GAP_M: f64 = 0.3e-3;

/// Tunable inputs of the seed B spindle model.
#[derive(Debug, Clone, PartialEq)]
pub struct SpindleParameters {
    /// Radial stiffness of each front row [N/m].
    pub front_radial_stiffness_n_per_m: f64,
    /// Radial stiffness of each rear row [N/m].
    pub rear_radial_stiffness_n_per_m: f64,
    /// Axial stiffness of each row [N/m] (not used by the lateral model).
    pub axial_stiffness_n_per_m: f64,
    /// Radial damping of each row [N s/m].
    pub bearing_damping_n_s_per_m: f64,
    /// Modal damping ratio of the rotor-bearing modes at rest [-]. Default
    /// 0.02 (assumed; seed B gives none).
    pub modal_damping_ratio: f64,
    /// Longest shaft finite element \[m\]. Default 0.02.
    pub max_element_length_m: f64,
    /// Include the unbalanced magnetic pull.
    pub magnetic_pull_enabled: bool,
    /// RMS air-gap flux density \[T\].
    pub flux_density_t: f64,
    /// Static eccentricity of the rotor core \[m\].
    pub static_eccentricity_m: f64,
}

impl Default for SpindleParameters {
    fn default() -> Self {
        SpindleParameters {
            front_radial_stiffness_n_per_m: 1e8,
            rear_radial_stiffness_n_per_m: 1e8,
            axial_stiffness_n_per_m: 2.5e7,
            bearing_damping_n_s_per_m: 0.0,
            modal_damping_ratio: 0.02,
            max_element_length_m: 0.02,
            magnetic_pull_enabled: false,
            flux_density_t: 0.55,
            static_eccentricity_m: 0.1 * AIR_GAP_M,
        }
    }
}

/// The layout of a motorized spindle rotor: shaft steps, bearing rows,
/// rotor core; the tool holder and the core density are those of the seed
/// B spindle (module doc). Lengths from the tool nose (z = 0) \[m\].
#[derive(Debug, Clone, PartialEq)]
pub struct SpindleRotorGeometry {
    /// Shaft steps (length, outer diameter, inner diameter) \[m\] from the nose.
    pub sections_m: Vec<(f64, f64, f64)>,
    /// Load positions of the two front rows \[m\].
    pub front_rows_m: [f64; 2],
    /// Load positions of the two rear rows \[m\].
    pub rear_rows_m: [f64; 2],
    /// Axial span of the motor rotor core \[m\].
    pub core_span_m: (f64, f64),
    /// Outer diameter of the rotor core \[m\].
    pub core_outer_diameter_m: f64,
    /// Inner diameter of the rotor core (its seat on the shaft) \[m\].
    pub core_inner_diameter_m: f64,
    /// Radial air gap of the motor \[m\].
    pub air_gap_m: f64,
}

impl SpindleRotorGeometry {
    /// The assumed seed B spindle (module doc).
    pub fn seed_b() -> Self {
        let bore = 0.016;
        SpindleRotorGeometry {
            sections_m: vec![
                (0.020, 0.060, 0.030),
                (0.055, 0.045, bore),
                (0.030, 0.050, bore),
                (0.130, 0.050, bore),
                (0.040, 0.045, bore),
                (0.045, 0.040, bore),
                (0.020, 0.035, bore),
            ],
            front_rows_m: FRONT_BEARING_POSITIONS_M,
            rear_rows_m: REAR_BEARING_POSITIONS_M,
            core_span_m: ROTOR_CORE_SPAN_M,
            core_outer_diameter_m: ROTOR_CORE_OUTER_DIAMETER_M,
            core_inner_diameter_m: 0.050,
            air_gap_m: AIR_GAP_M,
        }
    }

    /// Shaft steps of shaft steel.
    pub fn shaft(&self) -> Result<Vec<ShaftSection>> {
        let s = Material::shaft_steel();
        self.sections_m
            .iter()
            .map(|&(l, d, di)| ShaftSection::new(l, d, di, s.clone()))
            .collect()
    }

    /// The tool holder at the nose and the rotor core as 5 slices.
    pub fn disks(&self) -> Result<Vec<Disk>> {
        let (z0, z1) = self.core_span_m;
        crate::error::positive("core_length_m", z1 - z0)?;
        let slices = 5;
        let width = (z1 - z0) / slices as f64;
        let mut disks = Vec::with_capacity(slices + 1);
        disks.push(Disk {
            name: "tool_holder".into(),
            position_m: NOSE_POSITION_M,
            mass_kg: 0.45,
            polar_inertia_kg_m2: 1.2e-4,
            diametral_inertia_kg_m2: 4.0e-4,
        });
        for i in 0..slices {
            disks.push(Disk::hollow_cylinder(
                format!("rotor_core_{i}"),
                z0 + width * (i as f64 + 0.5),
                self.core_outer_diameter_m,
                self.core_inner_diameter_m,
                width,
                7600.0,
            )?);
        }
        Ok(disks)
    }

    /// Centre of the rotor core \[m\] (a mesh node: the middle slice).
    pub fn core_centre_m(&self) -> f64 {
        0.5 * (self.core_span_m.0 + self.core_span_m.1)
    }

    /// The rotor on one bearing model per pair (row names `front_A` ...).
    pub fn spindle_with_bearings(
        &self,
        front: Arc<dyn BearingModel>,
        rear: Arc<dyn BearingModel>,
        p: &SpindleParameters,
    ) -> Result<RotorSpec> {
        self.rotor_spec(["front_A", "front_B", "rear_A", "rear_B"], front, rear, p)
    }

    fn rotor_spec(
        &self,
        names: [&str; 4],
        front: Arc<dyn BearingModel>,
        rear: Arc<dyn BearingModel>,
        p: &SpindleParameters,
    ) -> Result<RotorSpec> {
        crate::error::positive("air_gap_m", self.air_gap_m)?;
        let (z0, z1) = self.core_span_m;
        let bearings = vec![
            BearingSupport::new(names[0], self.front_rows_m[0], front.clone()),
            BearingSupport::new(names[1], self.front_rows_m[1], front),
            BearingSupport::new(names[2], self.rear_rows_m[0], rear.clone()),
            BearingSupport::new(names[3], self.rear_rows_m[1], rear),
        ];
        Ok(RotorSpec {
            sections: self.shaft()?,
            disks: self.disks()?,
            bearings,
            magnetic_pull: Some(UnbalancedMagneticPull {
                enabled: p.magnetic_pull_enabled,
                position_m: self.core_centre_m(),
                rotor_radius_m: self.core_outer_diameter_m / 2.0,
                core_length_m: z1 - z0,
                air_gap_m: self.air_gap_m,
                flux_density_t: p.flux_density_t,
                static_eccentricity_m: p.static_eccentricity_m,
                reduction_factor: 1.0,
            }),
            modal_damping_ratio: p.modal_damping_ratio,
            max_element_length_m: p.max_element_length_m,
        })
    }
}

/// Shaft steps of the assumed seed B spindle shaft (module doc).
pub fn seed_b_shaft() -> Result<Vec<ShaftSection>> {
    SpindleRotorGeometry::seed_b().shaft()
}

/// Rotor core slices and the tool holder (module doc).
pub fn seed_b_disks() -> Result<Vec<Disk>> {
    SpindleRotorGeometry::seed_b().disks()
}

/// The seed B spindle with constant placeholder bearings.
pub fn seed_b_spindle(p: &SpindleParameters) -> Result<RotorSpec> {
    let front: Arc<dyn BearingModel> = Arc::new(BearingCoefficients::diagonal(
        p.front_radial_stiffness_n_per_m,
        p.axial_stiffness_n_per_m,
        0.0,
        p.bearing_damping_n_s_per_m,
    )?);
    let rear: Arc<dyn BearingModel> = Arc::new(BearingCoefficients::diagonal(
        p.rear_radial_stiffness_n_per_m,
        p.axial_stiffness_n_per_m,
        0.0,
        p.bearing_damping_n_s_per_m,
    )?);
    seed_b_spindle_with_bearings(front, rear, p)
}

/// The seed B spindle with bearing models supplied by the caller (e.g. the
/// thermally coupled bearing solver), one model per row of each pair.
pub fn seed_b_spindle_with_bearings(
    front: Arc<dyn BearingModel>,
    rear: Arc<dyn BearingModel>,
    p: &SpindleParameters,
) -> Result<RotorSpec> {
    SpindleRotorGeometry::seed_b().rotor_spec(
        ["7009C_front_A", "7009C_front_B", "7008C_rear_A", "7008C_rear_B"],
        front,
        rear,
        p,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rotor::modal::{campbell, CampbellOptions, Whirl};
    use crate::rotor::Rotor;

    #[test]
    fn spindle_mass_and_first_modes_are_plausible() {
        let r = Rotor::new(seed_b_spindle(&SpindleParameters::default()).unwrap()).unwrap();
        // Shaft 5.19e-4 m^3 x 7800 = 4.05 kg + core ~1.66 kg + holder 0.45 kg.
        let m = r.mass_kg();
        assert!((m - 6.16).abs() < 0.02, "{m}");
        // Rigid modes on 4 x 1e8 N/m: translation sqrt(4e8 / m) ~ 1.5 kHz
        // bounds the first mode from above; the flexible shaft lowers it.
        let opts = CampbellOptions {
            reduced_modes: Some(16),
            ..CampbellOptions::default()
        };
        let d = campbell(&r, &[0.0, MAX_SPEED_RPM], &opts).unwrap();
        let f0 = d.points[0].modes[0].frequency_hz;
        let rigid = (4e8 / m).sqrt() / (2.0 * std::f64::consts::PI);
        assert!(f0 > 200.0 && f0 < rigid, "{f0} vs {rigid}");
        // At speed the lowest pair splits into backward below, forward above.
        let at = &d.points[1].modes;
        assert_eq!(at[0].whirl, Whirl::Backward);
        assert!(at.iter().any(|m| m.whirl == Whirl::Forward));
    }

    fn first_mode_hz(g: &SpindleRotorGeometry) -> f64 {
        let k: Arc<dyn BearingModel> = Arc::new(BearingCoefficients::diagonal(1e8, 2.5e7, 0.0, 0.0).unwrap());
        let r = Rotor::new(
            g.spindle_with_bearings(k.clone(), k, &SpindleParameters::default())
                .unwrap(),
        )
        .unwrap();
        let opts = CampbellOptions {
            reduced_modes: Some(16),
            ..CampbellOptions::default()
        };
        campbell(&r, &[0.0], &opts).unwrap().points[0].modes[0].frequency_hz
    }

    #[test]
    fn seed_geometry_gives_the_seed_rotor_bit_for_bit() {
        let p = SpindleParameters::default();
        let k: Arc<dyn BearingModel> = Arc::new(BearingCoefficients::diagonal(1e8, 2.5e7, 0.0, 0.0).unwrap());
        let a = Rotor::new(seed_b_spindle(&p).unwrap()).unwrap();
        let b = Rotor::new(
            SpindleRotorGeometry::seed_b()
                .spindle_with_bearings(k.clone(), k, &p)
                .unwrap(),
        )
        .unwrap();
        assert_eq!(a.matrices(12_000.0).unwrap(), b.matrices(12_000.0).unwrap());
    }

    #[test]
    fn longer_span_and_heavier_core_lower_the_first_mode() {
        let seed = SpindleRotorGeometry::seed_b();
        let f0 = first_mode_hz(&seed);
        // Rear pair and shaft end 40 mm further back: a longer span.
        let mut long = seed.clone();
        long.sections_m[4].0 += 0.040;
        long.rear_rows_m = [seed.rear_rows_m[0] + 0.040, seed.rear_rows_m[1] + 0.040];
        let mut heavy = seed.clone();
        heavy.core_outer_diameter_m = 0.090;
        let (fl, fh) = (first_mode_hz(&long), first_mode_hz(&heavy));
        assert!(fl < f0 && fh < f0, "{f0} {fl} {fh}");
    }
}
