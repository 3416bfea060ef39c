//! Wiring of the 8-DOF helical pair (A-43 .. A-52) from the computed gear
//! and bearing data instead of placeholders.
//!
//! * Mesh stiffness: the potential-energy time-varying mesh stiffness of
//!   [`crate::gear::MeshStiffness`] acts along the *transverse* line of
//!   action; the dynamics model's `k_m` multiplies the *normal* deflection
//!   `delta_n` of A-45 (`F_n = k_m f(delta_n - e)`, and the static balance is
//!   `F_n cos(beta) = T_p / R_p`). With `delta_n = delta_t cos(beta)` and
//!   `F_t = F_n cos(beta)` the consistent value is `k_n = k_t / cos^2(beta)`,
//!   i.e. [`crate::gear::MeshStiffness::normal_direction`].
//! * Transmission error: `e(t)` along the same normal deflection (m).
//! * Bearings (A-52, `Kb = diag(Kr, Kr, Ka)` per gear body): `Kr`, `Ka` by
//!   the seed's formulas A-39 .. A-42 ([`crate::bearing::BearingState`]) for a
//!   6208 under seed A's loads (section 2.3: Fa = 2380.9 N, Fr = 1189.9 N at
//!   100 N m, preload 300 N), ring held level ([`Tilt::held_level`]). Each
//!   gear shaft runs in [`BEARINGS_PER_SHAFT`] = 2 bearings (seed A Fig. 1:
//!   one each side of the gear); they act in parallel on the gear body, so
//!   the support stiffness is `n Kr`, `n Ka`. Every bearing is solved under
//!   the full seed load, exactly as the seed computes its single-bearing
//!   stiffness (A does not split the load; this is stated, not corrected).
//!   Both shafts use the same bearing and schedule (A-52 has one Kb).
//! * Loads scale with the input torque: `Fa = 2380.9 T/100 + 300`,
//!   `Fr = 1189.9 T/100` N (the gear forces are proportional to T, the
//!   preload is not).
//! * What the seed omits keeps a documented default ([`GearSystemDefaults`]):
//!   half backlash 50 um, mesh damping ratio 0.07 (in contact only, A-46 as
//!   printed), bearing damping ratio 0.02, first-harmonic TE amplitude 2 um.

use super::bifurcation::BearingSchedule;
use super::gear_model::{BearingSupport, GearBody, HelicalPairParams, MeshDamping};
use crate::bearing::{stiffness_curve, Bearing, BearingModel, SolveOptions, Tilt};
use crate::error::{finite, non_negative, positive};
use crate::gear::{GearPair, MeshStiffness, TransmissionError};
use crate::{Error, Result};

/// Bearings on each gear shaft (seed A Fig. 1), acting in parallel.
pub const BEARINGS_PER_SHAFT: usize = 2;
/// Axial gear force on the bearing at the seed torque (A section 2.3) \[N\].
pub const SEED_AXIAL_LOAD_N: f64 = 2380.9;
/// Radial gear force on the bearing at the seed torque (A section 2.3) \[N\].
pub const SEED_RADIAL_LOAD_N: f64 = 1189.9;
/// Axial preload (A section 2.4, Fig. 10) \[N\].
pub const SEED_PRELOAD_N: f64 = 300.0;
/// Input torque at which the seed loads are given [N m].
pub const SEED_TORQUE_N_M: f64 = 100.0;

/// Values seed A does not give (docs/concepts/physics.md §8), with their defaults.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GearSystemDefaults {
    /// Half backlash b \[m\] (total clearance 2b). Default 50 um.
    pub half_backlash_m: f64,
    /// Mesh damping ratio zeta_m [-]. Default 0.07 (0.03..0.17 is the usual
    /// range of measured gear-mesh damping ratios, Kahraman & Singh 1990).
    pub mesh_damping_ratio: f64,
    /// Where mesh damping acts. Default in contact only (A-46 as printed).
    pub mesh_damping: MeshDamping,
    /// Bearing damping ratio on the body mass [-]. Default 0.02.
    pub bearing_damping_ratio: f64,
    /// Amplitude of the first mesh harmonic of the static TE \[m\]. Default 2 um.
    pub te_amplitude_m: f64,
    /// Samples of k_m and e per mesh period passed to the model. Default 64.
    pub table_points: usize,
    /// Factor on the whole mesh stiffness table k_m(t) [-]. Default 1 (the
    /// computed or given table as it is). A calibration input: seed A gives
    /// no mesh stiffness values, so a scale pinned by its transition speeds
    /// stands for the difference between its numerical method and ours.
    pub mesh_stiffness_scale: f64,
}

impl Default for GearSystemDefaults {
    fn default() -> Self {
        GearSystemDefaults {
            half_backlash_m: 50e-6,
            mesh_damping_ratio: 0.07,
            mesh_damping: MeshDamping::InContact,
            bearing_damping_ratio: 0.02,
            te_amplitude_m: 2e-6,
            table_points: 64,
            mesh_stiffness_scale: 1.0,
        }
    }
}

impl GearSystemDefaults {
    /// Validate.
    pub fn check(&self) -> Result<()> {
        positive("half_backlash_m", self.half_backlash_m)?;
        non_negative("mesh_damping_ratio", self.mesh_damping_ratio)?;
        non_negative("bearing_damping_ratio", self.bearing_damping_ratio)?;
        non_negative("te_amplitude_m", self.te_amplitude_m)?;
        positive("mesh_stiffness_scale", self.mesh_stiffness_scale)?;
        if self.table_points < 8 {
            return Err(Error::config(
                "table_points",
                self.table_points,
                "at least 8 samples per mesh period",
            ));
        }
        Ok(())
    }
}

/// Bearing stiffness case of seed A Fig. 11 / Figs. 14-15.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum BearingCase {
    /// The zero-speed (static) stiffness at every speed.
    Constant,
    /// Quasi-static stiffness at each speed (centrifugal and gyroscopic
    /// effects, ring expansion), no thermal offsets.
    Speed,
}

/// Bearing loads `(axial_n, radial_n)` at an input torque: the seed's gear
/// forces scaled by `T / 100 N m`, plus the preload axially.
pub fn seed_bearing_loads(input_torque_n_m: f64) -> Result<(f64, f64)> {
    finite("input_torque_n_m", input_torque_n_m)?;
    let s = input_torque_n_m.abs() / SEED_TORQUE_N_M;
    Ok((SEED_AXIAL_LOAD_N * s + SEED_PRELOAD_N, SEED_RADIAL_LOAD_N * s))
}

fn check_count(bearings_per_shaft: usize) -> Result<f64> {
    if bearings_per_shaft == 0 {
        return Err(Error::config("bearings_per_shaft", 0, "at least one bearing per shaft"));
    }
    Ok(bearings_per_shaft as f64)
}

/// Support stiffness schedule `(speed, n Kr, n Ka)` of one gear shaft from
/// `bearings_per_shaft` identical bearings in parallel, each under
/// `(axial_n, radial_n)`, ring held level. `Constant`: one zero-speed solve;
/// `Speed`: a quasi-static solve at each of `speeds_rpm` (ascending).
pub fn bearing_schedule(
    bearing: &Bearing,
    case: BearingCase,
    speeds_rpm: &[f64],
    axial_n: f64,
    radial_n: f64,
    bearings_per_shaft: usize,
) -> Result<BearingSchedule> {
    let n = check_count(bearings_per_shaft)?;
    let model = BearingModel::new(bearing)?;
    let opts = SolveOptions {
        tilt: Tilt::held_level(),
        ..SolveOptions::default()
    };
    match case {
        BearingCase::Constant => {
            let s = model.solve_static(&[radial_n, 0.0, axial_n, 0.0, 0.0], &opts)?;
            BearingSchedule::constant(n * s.radial_stiffness_seed_n_per_m, n * s.axial_stiffness_seed_n_per_m)
        }
        BearingCase::Speed => {
            if speeds_rpm.is_empty() {
                return Err(Error::config("speeds_rpm", "[]", "need at least one speed"));
            }
            for &s in speeds_rpm {
                positive("speeds_rpm", s)?;
            }
            let pts = stiffness_curve(&model, speeds_rpm, axial_n, radial_n, &opts)?;
            BearingSchedule::new(
                pts.iter()
                    .map(|p| {
                        (
                            p.speed_rpm,
                            n * p.radial_stiffness_seed_n_per_m,
                            n * p.axial_stiffness_seed_n_per_m,
                        )
                    })
                    .collect(),
            )
        }
    }
}

/// Model parameters from the gear data: geometry, masses and inertias of
/// `pair`, the normal-direction mesh stiffness from `transverse_mesh`
/// (transverse line of action, as [`MeshStiffness::potential_energy`]
/// returns it), the static TE `te` (normal deflection, m), bearing support
/// `diag(kr, kr, ka)` on both bodies and the omitted values from `d`.
pub fn helical_params(
    pair: &GearPair,
    transverse_mesh: &MeshStiffness,
    te: &TransmissionError,
    kr_n_per_m: f64,
    ka_n_per_m: f64,
    d: &GearSystemDefaults,
) -> Result<HelicalPairParams> {
    d.check()?;
    let kn = transverse_mesh.normal_direction(pair)?;
    let tables = MeshTables {
        normal_stiffness_n_per_m: kn.samples(d.table_points),
        transmission_error_m: te.samples(d.table_points),
    };
    helical_params_from_tables(pair, tables, kr_n_per_m, ka_n_per_m, d)
}

/// Mesh stiffness and static transmission error over one mesh period,
/// sampled at the uniform phases `i / len` (each table its own length, at
/// least 2 samples); the model interpolates them periodically
/// (Catmull-Rom, [`crate::dynamics::ode::PeriodicTable`]).
#[derive(Debug, Clone, PartialEq)]
pub struct MeshTables {
    /// Mesh stiffness along the normal deflection delta_n of A-45 \[N/m\].
    pub normal_stiffness_n_per_m: Vec<f64>,
    /// Static transmission error along delta_n \[m\].
    pub transmission_error_m: Vec<f64>,
}

/// As [`helical_params`], with the mesh stiffness (normal direction) and
/// the TE given as uniform tables over one mesh period. The input torque is
/// `pair`'s; it may be overridden afterwards (negative for coast).
pub fn helical_params_from_tables(
    pair: &GearPair,
    tables: MeshTables,
    kr_n_per_m: f64,
    ka_n_per_m: f64,
    d: &GearSystemDefaults,
) -> Result<HelicalPairParams> {
    d.check()?;
    positive("kr_n_per_m", kr_n_per_m)?;
    positive("ka_n_per_m", ka_n_per_m)?;
    for (field, t) in [
        ("mesh_stiffness_n_per_m", &tables.normal_stiffness_n_per_m),
        ("transmission_error_m", &tables.transmission_error_m),
    ] {
        if t.len() < 2 {
            return Err(Error::config(
                field,
                t.len(),
                "needs at least 2 samples per mesh period",
            ));
        }
    }
    for &k in &tables.normal_stiffness_n_per_m {
        positive("mesh_stiffness_n_per_m", k)?;
    }
    for &e in &tables.transmission_error_m {
        finite("transmission_error_m", e)?;
    }
    let rb = pair.base_radius_m();
    let m = pair.mass_kg();
    let inertia = pair.polar_inertia_kg_m2();
    let body = |i: usize| GearBody {
        mass_kg: m[i],
        inertia_kg_m2: inertia[i],
        base_radius_m: rb[i],
        bearing: BearingSupport::radial_axial(kr_n_per_m, ka_n_per_m, d.bearing_damping_ratio, m[i]),
    };
    Ok(HelicalPairParams {
        pinion: body(0),
        gear: body(1),
        pinion_teeth: pair.spec.wheels[0].teeth,
        helix_angle_rad: pair.helix_angle_rad(),
        line_of_action_angle_rad: pair.line_of_action_angle_rad(),
        half_backlash_m: d.half_backlash_m,
        mesh_damping_ratio: d.mesh_damping_ratio,
        mesh_damping: d.mesh_damping,
        input_torque_n_m: pair.input_torque_n_m(),
        mesh_stiffness_n_per_m: scaled(tables.normal_stiffness_n_per_m, d.mesh_stiffness_scale),
        transmission_error_m: tables.transmission_error_m,
    })
}

/// The mesh stiffness table times `scale` (the table itself when 1, bit for bit).
fn scaled(k: Vec<f64>, scale: f64) -> Vec<f64> {
    if scale == 1.0 {
        return k;
    }
    k.into_iter().map(|v| v * scale).collect()
}

/// Seed A's first gear pair with its computed potential-energy mesh
/// stiffness, a first-harmonic TE of `d.te_amplitude_m` and the 6208's
/// zero-speed stiffness (two per shaft) under the seed loads.
pub fn seed_a_params(d: &GearSystemDefaults) -> Result<HelicalPairParams> {
    let pair = GearPair::preset("seed-electric-drive")?;
    let mesh = MeshStiffness::potential_energy(&pair)?;
    let te = TransmissionError::harmonics(vec![(d.te_amplitude_m, 0.0)])?;
    let bearing = Bearing::preset("6208")?;
    let (fa, fr) = seed_bearing_loads(pair.input_torque_n_m())?;
    let sched = bearing_schedule(&bearing, BearingCase::Constant, &[], fa, fr, BEARINGS_PER_SHAFT)?;
    let (kr, ka) = sched.at(0.0);
    helical_params(&pair, &mesh, &te, kr, ka, d)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::gear_model::{dead_zone, HelicalPair};

    #[test]
    fn seed_params_use_normal_mesh_stiffness_and_balance_the_torque() {
        let d = GearSystemDefaults::default();
        let p = seed_a_params(&d).unwrap();
        let pair = GearPair::preset("seed-electric-drive").unwrap();
        let mesh = MeshStiffness::potential_energy(&pair).unwrap();
        let mean_n = p.mesh_stiffness_n_per_m.iter().sum::<f64>() / p.mesh_stiffness_n_per_m.len() as f64;
        let cb = pair.helix_angle_rad().cos();
        // k_n = k_t / cos^2(beta) (the mean of the resampled table equals the
        // table mean up to the interpolation of 64 of its samples).
        assert!((mean_n * cb * cb / mesh.mean_n_per_m() - 1.0).abs() < 0.01);
        // Static balance: the transverse mesh force equals T / r_b, i.e. the
        // transverse deflection times k_t carries the torque.
        let model = HelicalPair::new(p.clone()).unwrap();
        let x = model.static_state().unwrap();
        let a = model.projection();
        let dn: f64 = (0..7).map(|i| a[i] * x[i]).sum();
        let fnorm = mean_n * dead_zone(dn, p.half_backlash_m);
        let ft = fnorm * cb;
        assert!((ft * p.pinion.base_radius_m / 100.0 - 1.0).abs() < 1e-9, "{ft}");
        // Bearing support: two bearings in parallel, stiffer than one.
        let b = Bearing::preset("6208").unwrap();
        let one = bearing_schedule(&b, BearingCase::Constant, &[], 2680.9, 1189.9, 1).unwrap();
        assert!((p.pinion.bearing.kx_n_per_m / one.at(0.0).0 - 2.0).abs() < 1e-12);
        assert!((p.gear.bearing.kz_n_per_m / one.at(0.0).1 - 2.0).abs() < 1e-12);
    }

    #[test]
    fn tables_path_equals_the_computed_path_and_names_bad_tables() {
        let d = GearSystemDefaults::default();
        let p = seed_a_params(&d).unwrap();
        let pair = GearPair::preset("seed-electric-drive").unwrap();
        let (kr, ka) = (p.pinion.bearing.kx_n_per_m, p.pinion.bearing.kz_n_per_m);
        let tables = MeshTables {
            normal_stiffness_n_per_m: p.mesh_stiffness_n_per_m.clone(),
            transmission_error_m: p.transmission_error_m.clone(),
        };
        let q = helical_params_from_tables(&pair, tables.clone(), kr, ka, &d).unwrap();
        assert_eq!(q, p);
        let mut bad = tables.clone();
        bad.normal_stiffness_n_per_m[5] = 0.0;
        let e = helical_params_from_tables(&pair, bad, kr, ka, &d).unwrap_err();
        assert!(e.to_string().contains("mesh_stiffness_n_per_m"), "{e}");
        let short = MeshTables {
            transmission_error_m: vec![0.0],
            ..tables
        };
        let e = helical_params_from_tables(&pair, short, kr, ka, &d).unwrap_err();
        assert!(e.to_string().contains("transmission_error_m"), "{e}");
    }

    #[test]
    fn mesh_stiffness_scale_scales_the_table_and_the_static_deflection() {
        let d = GearSystemDefaults::default();
        let half = GearSystemDefaults {
            mesh_stiffness_scale: 0.5,
            ..d
        };
        let p1 = seed_a_params(&d).unwrap();
        let p2 = seed_a_params(&half).unwrap();
        for (a, b) in p1.mesh_stiffness_n_per_m.iter().zip(&p2.mesh_stiffness_n_per_m) {
            assert_eq!(*b, 0.5 * a);
        }
        // The static mesh force carries the same torque: on half the stiffness
        // the teeth deflect twice as far beyond the backlash (F = k (d - b)).
        let beyond = |p: &HelicalPairParams| {
            let m = HelicalPair::new(p.clone()).unwrap();
            let x = m.static_state().unwrap();
            let a = m.projection();
            (0..7).map(|i| a[i] * x[i]).sum::<f64>() - p.half_backlash_m
        };
        let ratio = beyond(&p2) / beyond(&p1);
        assert!((ratio - 2.0).abs() < 1e-9, "{ratio}");
        let bad = GearSystemDefaults {
            mesh_stiffness_scale: 0.0,
            ..d
        };
        assert!(seed_a_params(&bad)
            .unwrap_err()
            .to_string()
            .contains("mesh_stiffness_scale"));
    }

    #[test]
    fn loads_scale_with_torque_and_bad_input_is_named() {
        let (fa, fr) = seed_bearing_loads(100.0).unwrap();
        assert!((fa - 2680.9).abs() < 1e-9 && (fr - 1189.9).abs() < 1e-9);
        let (fa, fr) = seed_bearing_loads(50.0).unwrap();
        assert!((fa - (1190.45 + 300.0)).abs() < 1e-9 && (fr - 594.95).abs() < 1e-9);
        let b = Bearing::preset("6208").unwrap();
        let e = bearing_schedule(&b, BearingCase::Constant, &[], 2680.9, 1189.9, 0).unwrap_err();
        assert!(e.to_string().contains("bearings_per_shaft"));
        let e = bearing_schedule(&b, BearingCase::Speed, &[], 2680.9, 1189.9, 2).unwrap_err();
        assert!(e.to_string().contains("speeds_rpm"));
        let d = GearSystemDefaults {
            half_backlash_m: 0.0,
            ..GearSystemDefaults::default()
        };
        assert!(seed_a_params(&d).unwrap_err().to_string().contains("half_backlash_m"));
    }
}
