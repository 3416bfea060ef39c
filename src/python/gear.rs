//! Bindings for the helical gear pair and its nonlinear dynamics: gear data,
//! the 8-DOF system with a bearing stiffness schedule, speed sweeps
//! (bifurcation diagrams), regime maps and Lyapunov exponents.
//!
//! Long work runs on a worker thread with the GIL released; the calling
//! thread wakes every [`WATCH_MS`] ms, checks for Ctrl-C
//! (`Python::check_signals`) and forwards progress to the Python callback
//! (a callback that returns False stops the work: `thermobear.Interrupted`).
//! The engine's progress hook only reads an atomic "cancel" flag, so it
//! never touches Python; the same flag is the worker's `crate::cancel`
//! flag, which the integration loops look at inside each speed.

use std::collections::BTreeMap;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use numpy::{IntoPyArray, PyReadonlyArray1};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use super::bearing::PyBearing;
use super::errors::IntoPy;
use crate::dynamics::lyapunov::{
    largest_lyapunov_benettin, largest_lyapunov_blocks, largest_lyapunov_variational, DuffingUeda, Lorenz,
    LyapunovBlocks, LyapunovConfig,
};
use crate::dynamics::ode::Gridded;
use crate::dynamics::seed::{
    bearing_schedule, helical_params_from_tables, seed_bearing_loads, BearingCase, GearSystemDefaults, MeshTables,
};
use crate::dynamics::{
    regime_map_partial, sweep_many_partial, sweep_partial, BearingSchedule, HelicalPair, HelicalSweep, ImpactRegime,
    MeshDamping, Motion, PartialRegimeMap, PartialSweep, RegimeCell, SweepConfig, SweepDirection, SweepResult,
};
use crate::error::{finite, positive, Error, Result};
use crate::gear::{
    iso_stiffness, tooth_pair_stiffness, GearPair, GearPairSpec, IsoStiffnessOptions, MeshOptions, MeshStiffness,
    TableGearData, TransmissionError, TypoWarning, WheelSpec,
};

/// Poll interval of the watching (GIL-holding) thread [ms].
pub const WATCH_MS: u64 = 20;

/// Run `work(progress_hook)` on a worker thread with the GIL released,
/// honouring Ctrl-C and forwarding `(done, total)` to `progress`.
fn run_watched<R, W>(py: Python<'_>, progress: Option<&Bound<'_, PyAny>>, work: W) -> PyResult<R>
where
    R: Send,
    W: FnOnce(&(dyn Fn(usize, usize) -> bool + Sync)) -> Result<R> + Send,
{
    // Also the worker's cancel flag (`crate::cancel`): the integration
    // loops inside a speed look at it, so a stop ends a long speed too.
    let cancel = std::sync::Arc::new(AtomicBool::new(false));
    let done = AtomicUsize::new(0);
    let total = AtomicUsize::new(0);
    std::thread::scope(|s| {
        let handle = s.spawn(|| {
            let hook = |d: usize, t: usize| {
                done.store(d, Ordering::Relaxed);
                total.store(t, Ordering::Relaxed);
                !cancel.load(Ordering::Relaxed)
            };
            crate::cancel::with_flag(&cancel, || work(&hook))
        });
        let mut pending: Option<PyErr> = None;
        let mut reported = 0;
        while !handle.is_finished() {
            py.detach(|| std::thread::sleep(std::time::Duration::from_millis(WATCH_MS)));
            if pending.is_some() {
                continue;
            }
            if let Err(e) = py.check_signals() {
                cancel.store(true, Ordering::Relaxed);
                pending = Some(e);
                continue;
            }
            let d = done.load(Ordering::Relaxed);
            if let (Some(cb), true) = (progress, d != reported) {
                reported = d;
                if let Err(e) = super::parallel::report(cb, d, total.load(Ordering::Relaxed)) {
                    cancel.store(true, Ordering::Relaxed);
                    pending = Some(e);
                }
            }
        }
        let out = handle
            .join()
            .map_err(|_| PyRuntimeError::new_err("the gear dynamics worker panicked"))?;
        if let Some(e) = pending {
            return Err(e);
        }
        let out = out.py_err()?;
        let d = done.load(Ordering::Relaxed);
        if let (Some(cb), true) = (progress, d != reported) {
            super::parallel::report(cb, d, total.load(Ordering::Relaxed))?;
        }
        Ok(out)
    })
}

// ------------------------------------------------------------ GearPair ----

/// A helical gear pair (SI inside).
#[pyclass(name = "GearPair", module = "thermobear._native", frozen)]
#[derive(Clone)]
pub struct PyGearPair {
    pub inner: GearPair,
    /// Warnings of the table the pair was built from (as printed).
    pub warnings: Vec<TypoWarning>,
}

fn warning_dicts(py: Python<'_>, ws: &[TypoWarning]) -> PyResult<Py<PyList>> {
    let list = PyList::empty(py);
    for w in ws {
        let d = PyDict::new(py);
        d.set_item("field", &w.field)?;
        d.set_item("given", w.given)?;
        d.set_item("likely_intended", w.likely_intended)?;
        d.set_item("reason", &w.reason)?;
        list.append(d)?;
    }
    Ok(list.unbind())
}

#[pymethods]
impl PyGearPair {
    #[staticmethod]
    fn preset(name: &str) -> PyResult<Self> {
        let inner = GearPair::preset(name).py_err()?;
        let warnings = TableGearData::seed_electric_drive_as_printed().warnings();
        Ok(PyGearPair { inner, warnings })
    }

    #[staticmethod]
    fn preset_names() -> Vec<&'static str> {
        crate::gear::geometry::PRESETS.to_vec()
    }

    /// Build from a paper-style table (t, mm, s units for material data):
    /// the table is checked for typos first and refused with the likely
    /// intended value named.
    #[staticmethod]
    #[pyo3(signature = (pinion_teeth, gear_teeth, normal_module_mm, normal_pressure_angle_deg, helix_angle_deg, face_width_mm, youngs_modulus_mpa, poisson_ratio, density_t_per_mm3, mass_kg, polar_inertia_t_mm2, input_torque_nm, profile_shift_coeff=(0.0, 0.0), addendum_coeff=1.0, dedendum_coeff=1.25))]
    #[allow(clippy::too_many_arguments)]
    fn from_table(
        pinion_teeth: u32,
        gear_teeth: u32,
        normal_module_mm: f64,
        normal_pressure_angle_deg: f64,
        helix_angle_deg: f64,
        face_width_mm: f64,
        youngs_modulus_mpa: f64,
        poisson_ratio: f64,
        density_t_per_mm3: f64,
        mass_kg: (f64, f64),
        polar_inertia_t_mm2: (f64, f64),
        input_torque_nm: f64,
        profile_shift_coeff: (f64, f64),
        addendum_coeff: f64,
        dedendum_coeff: f64,
    ) -> PyResult<Self> {
        positive("normal_module_mm", normal_module_mm).py_err()?;
        positive("pinion_mass_kg", mass_kg.0).py_err()?;
        positive("gear_mass_kg", mass_kg.1).py_err()?;
        positive("pinion_polar_inertia_t_mm2", polar_inertia_t_mm2.0).py_err()?;
        positive("gear_polar_inertia_t_mm2", polar_inertia_t_mm2.1).py_err()?;
        positive("addendum_coeff", addendum_coeff).py_err()?;
        positive("dedendum_coeff", dedendum_coeff).py_err()?;
        finite("helix_angle_deg", helix_angle_deg).py_err()?;
        let cos_b = helix_angle_deg.to_radians().cos();
        let tip = |z: u32, x: f64| 0.5 * z as f64 * normal_module_mm / cos_b + normal_module_mm * (addendum_coeff + x);
        let table = TableGearData {
            youngs_modulus_mpa,
            density_t_per_mm3,
            mass_kg: [mass_kg.0, mass_kg.1],
            polar_inertia_t_mm2: [polar_inertia_t_mm2.0, polar_inertia_t_mm2.1],
            tip_radius_mm: [
                tip(pinion_teeth, profile_shift_coeff.0),
                tip(gear_teeth, profile_shift_coeff.1),
            ],
        };
        let si = table.into_si().py_err()?;
        let wheel = |z: u32, m: f64, i: f64, x: f64| WheelSpec {
            profile_shift_coeff: x,
            ..WheelSpec::new(z, m, i)
        };
        let spec = GearPairSpec {
            wheels: [
                wheel(
                    pinion_teeth,
                    mass_kg.0,
                    si.polar_inertia_kg_m2[0],
                    profile_shift_coeff.0,
                ),
                wheel(gear_teeth, mass_kg.1, si.polar_inertia_kg_m2[1], profile_shift_coeff.1),
            ],
            normal_module_m: normal_module_mm * 1e-3,
            normal_pressure_angle_rad: normal_pressure_angle_deg.to_radians(),
            helix_angle_rad: helix_angle_deg.to_radians(),
            face_width_m: face_width_mm * 1e-3,
            addendum_coeff,
            dedendum_coeff,
            youngs_modulus_pa: si.youngs_modulus_pa,
            poisson_ratio,
            density_kg_m3: si.density_kg_m3,
            input_torque_n_m: input_torque_nm,
        };
        Ok(PyGearPair {
            inner: GearPair::new(spec).py_err()?,
            warnings: Vec::new(),
        })
    }

    /// Warnings of the data table as printed (the seed's typos for the preset).
    fn typo_warnings(&self, py: Python<'_>) -> PyResult<Py<PyList>> {
        warning_dicts(py, &self.warnings)
    }

    /// Derived geometry (mm, deg, dimensionless ratios).
    fn geometry(&self) -> BTreeMap<&'static str, f64> {
        let g = &self.inner.geometry;
        let s = &self.inner.spec;
        let mm = 1e3;
        let mut d = BTreeMap::new();
        d.insert("pinion_teeth", s.wheels[0].teeth as f64);
        d.insert("gear_teeth", s.wheels[1].teeth as f64);
        d.insert("normal_module_mm", s.normal_module_m * mm);
        d.insert("transverse_module_mm", g.transverse_module_m * mm);
        d.insert("normal_pressure_angle_deg", s.normal_pressure_angle_rad.to_degrees());
        d.insert(
            "transverse_pressure_angle_deg",
            g.transverse_pressure_angle_rad.to_degrees(),
        );
        d.insert(
            "operating_pressure_angle_deg",
            g.operating_pressure_angle_rad.to_degrees(),
        );
        d.insert("helix_angle_deg", s.helix_angle_rad.to_degrees());
        d.insert("base_helix_angle_deg", g.base_helix_angle_rad.to_degrees());
        d.insert("line_of_action_angle_deg", g.line_of_action_angle_rad.to_degrees());
        d.insert("face_width_mm", s.face_width_m * mm);
        d.insert("centre_distance_mm", g.centre_distance_m * mm);
        d.insert("pinion_pitch_radius_mm", g.pitch_radius_m[0] * mm);
        d.insert("gear_pitch_radius_mm", g.pitch_radius_m[1] * mm);
        d.insert("pinion_base_radius_mm", g.base_radius_m[0] * mm);
        d.insert("gear_base_radius_mm", g.base_radius_m[1] * mm);
        d.insert("pinion_tip_radius_mm", g.tip_radius_m[0] * mm);
        d.insert("gear_tip_radius_mm", g.tip_radius_m[1] * mm);
        d.insert("pinion_root_radius_mm", g.root_radius_m[0] * mm);
        d.insert("gear_root_radius_mm", g.root_radius_m[1] * mm);
        d.insert("transverse_base_pitch_mm", g.transverse_base_pitch_m * mm);
        d.insert("path_of_contact_mm", g.path_of_contact_m * mm);
        d.insert("transverse_contact_ratio", g.transverse_contact_ratio);
        d.insert("overlap_ratio", g.overlap_ratio);
        d.insert("total_contact_ratio", g.total_contact_ratio);
        d.insert("gear_ratio", self.inner.gear_ratio());
        d.insert("pinion_mass_kg", s.wheels[0].mass_kg);
        d.insert("gear_mass_kg", s.wheels[1].mass_kg);
        d.insert("pinion_polar_inertia_kg_m2", s.wheels[0].polar_inertia_kg_m2);
        d.insert("gear_polar_inertia_kg_m2", s.wheels[1].polar_inertia_kg_m2);
        d.insert("youngs_modulus_gpa", s.youngs_modulus_pa / 1e9);
        d.insert("density_kg_m3", s.density_kg_m3);
        d.insert("input_torque_nm", s.input_torque_n_m);
        d
    }

    /// ISO 6336-1 Method B stiffness: c', c_gamma_alpha, c_gamma_beta in
    /// N/(mm um) and the totals over the face width in N/m.
    fn iso_stiffness(&self) -> PyResult<BTreeMap<&'static str, f64>> {
        let iso = iso_stiffness(&self.inner, &IsoStiffnessOptions::default()).py_err()?;
        let mut d = BTreeMap::new();
        d.insert("flexibility_q_mm_um_per_n", iso.flexibility_q);
        d.insert("theoretical_single_n_per_mm_um", iso.theoretical_single_n_per_mm_um);
        d.insert("single_n_per_mm_um", iso.single_n_per_mm_um);
        d.insert("mesh_alpha_n_per_mm_um", iso.mesh_alpha_n_per_mm_um);
        d.insert("mesh_beta_n_per_mm_um", iso.mesh_beta_n_per_mm_um);
        d.insert("mesh_alpha_n_per_m", iso.mesh_alpha_n_per_m());
        d.insert("mesh_beta_n_per_m", iso.mesh_beta_n_per_m());
        d.insert("blank_factor", iso.blank_factor);
        d.insert("basic_rack_factor", iso.basic_rack_factor);
        d.insert("load_factor", iso.load_factor);
        Ok(d)
    }

    /// Time-varying mesh stiffness over one mesh period at `points` phases:
    /// transverse (as computed) and normal (what the 8-DOF model uses).
    #[pyo3(signature = (points=64, model="potential-energy"))]
    fn mesh_stiffness<'py>(&self, py: Python<'py>, points: usize, model: &str) -> PyResult<Bound<'py, PyDict>> {
        if points < 8 {
            return Err(Error::config("points", points, "at least 8 samples per mesh period")).py_err();
        }
        let inner = self.inner.clone();
        let model = model.to_string();
        let k = py.detach(move || mesh_model(&inner, &model)).py_err()?;
        let kn = k.normal_direction(&self.inner).py_err()?;
        let d = PyDict::new(py);
        let phase: Vec<f64> = (0..points).map(|i| i as f64 / points as f64).collect();
        d.set_item("mesh_phase", phase.into_pyarray(py))?;
        d.set_item("transverse_stiffness_n_per_m", k.samples(points).into_pyarray(py))?;
        d.set_item("normal_stiffness_n_per_m", kn.samples(points).into_pyarray(py))?;
        Ok(d)
    }

    /// One tooth pair's stiffness over its engagement (approach, pitch
    /// point, recess) at `points` positions: `mesh_cycles` (roll in mesh
    /// periods from entering the path of contact), transverse and normal
    /// stiffness; the mesh stiffness is their sum over the pairs in mesh.
    #[pyo3(signature = (points=256, model="potential-energy"))]
    fn tooth_pair_stiffness<'py>(&self, py: Python<'py>, points: usize, model: &str) -> PyResult<Bound<'py, PyDict>> {
        let inner = self.inner.clone();
        let iso = match model {
            "potential-energy" => None,
            "iso" => Some(iso_stiffness(&inner, &IsoStiffnessOptions::default()).py_err()?),
            other => {
                return Err(Error::config(
                    "mesh_model",
                    other,
                    "must be \"potential-energy\" or \"iso\"",
                ))
                .py_err()
            }
        };
        let rows = py
            .detach(move || tooth_pair_stiffness(&inner, iso.as_ref(), &MeshOptions::default(), points))
            .py_err()?;
        let to_normal = 1.0 / self.inner.spec.helix_angle_rad.cos().powi(2);
        let d = PyDict::new(py);
        d.set_item(
            "mesh_cycles",
            rows.iter().map(|r| r[0]).collect::<Vec<f64>>().into_pyarray(py),
        )?;
        d.set_item(
            "transverse_stiffness_n_per_m",
            rows.iter().map(|r| r[1]).collect::<Vec<f64>>().into_pyarray(py),
        )?;
        d.set_item(
            "normal_stiffness_n_per_m",
            rows.iter()
                .map(|r| r[1] * to_normal)
                .collect::<Vec<f64>>()
                .into_pyarray(py),
        )?;
        Ok(d)
    }

    /// Mesh frequency z_1 n / 60 [Hz].
    fn mesh_frequency_hz(&self, speed_rpm: f64) -> PyResult<f64> {
        self.inner.mesh_frequency_hz(speed_rpm).py_err()
    }

    /// Pickle support: the versioned serde envelope (see `_restore`).
    fn __reduce__(&self, py: Python<'_>) -> PyResult<super::persist::Reduced> {
        super::persist::reduce_gear_pair(py, self)
    }

    fn __repr__(&self) -> String {
        let s = &self.inner.spec;
        format!(
            "GearPair(z={}/{}, m_n={:.3} mm, beta={:.1} deg, b={:.1} mm, eps_alpha={:.3}, eps_beta={:.3})",
            s.wheels[0].teeth,
            s.wheels[1].teeth,
            s.normal_module_m * 1e3,
            s.helix_angle_rad.to_degrees(),
            s.face_width_m * 1e3,
            self.inner.geometry.transverse_contact_ratio,
            self.inner.geometry.overlap_ratio
        )
    }
}

fn mesh_model(pair: &GearPair, model: &str) -> Result<MeshStiffness> {
    match model {
        "potential-energy" => MeshStiffness::potential_energy(pair),
        "iso" => {
            let iso = iso_stiffness(pair, &IsoStiffnessOptions::default())?;
            MeshStiffness::iso_contact_line(pair, &iso, &MeshOptions::default())
        }
        other => Err(Error::config(
            "mesh_model",
            other,
            "must be \"potential-energy\" or \"iso\"",
        )),
    }
}

// ---------------------------------------------------------- GearSystem ----

/// The 8-DOF helical pair (A-43 .. A-52) with a bearing stiffness schedule.
#[pyclass(name = "GearSystem", module = "thermobear._native", frozen)]
pub struct PyGearSystem {
    pub sweep: HelicalSweep,
    pub defaults: GearSystemDefaults,
    pub schedule: Vec<(f64, f64, f64)>,
    pub mesh_model: String,
    /// The gear pair spec the system was built from, with the signed
    /// system torque (pickling).
    pub spec: GearPairSpec,
    /// User mesh tables, if any (pickling).
    pub tables: UserTables,
}

fn mesh_damping_mode(name: &str) -> Result<MeshDamping> {
    match name {
        "in-contact" => Ok(MeshDamping::InContact),
        "always" => Ok(MeshDamping::Always),
        other => Err(Error::config(
            "mesh_damping",
            other,
            "must be \"in-contact\" or \"always\"",
        )),
    }
}

fn support_schedule(speeds: &[f64], kr: &[f64], ka: &[f64]) -> Result<Vec<(f64, f64, f64)>> {
    if speeds.len() != kr.len() || speeds.len() != ka.len() {
        return Err(Error::config(
            "bearing_schedule",
            format!("{}/{}/{}", speeds.len(), kr.len(), ka.len()),
            "speed_rpm, radial and axial stiffness arrays must have the same length",
        ));
    }
    Ok(speeds.iter().zip(kr).zip(ka).map(|((&s, &r), &a)| (s, r, a)).collect())
}

#[pymethods]
impl PyGearSystem {
    /// `speeds_rpm`, `radial_stiffness_n_per_m`, `axial_stiffness_n_per_m`:
    /// the support stiffness of each gear body (all bearings of its shaft
    /// together) against speed. `mesh_stiffness_n_per_m` (normal direction)
    /// and `transmission_error_m`: optional uniform tables over one mesh
    /// period (phases i / len), replacing the computed mesh stiffness
    /// (`mesh_model`) and the first-harmonic TE (`te_amplitude_um`). A
    /// negative `torque_nm` is coast (the pinion driven backwards).
    #[new]
    #[pyo3(signature = (gear, speeds_rpm, radial_stiffness_n_per_m, axial_stiffness_n_per_m, *, half_backlash_um=50.0, mesh_damping_ratio=0.07, mesh_damping="in-contact", bearing_damping_ratio=0.02, te_amplitude_um=None, torque_nm=None, table_points=64, mesh_model=None, mesh_stiffness_n_per_m=None, transmission_error_m=None, mesh_stiffness_scale=1.0))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        py: Python<'_>,
        gear: &PyGearPair,
        speeds_rpm: Vec<f64>,
        radial_stiffness_n_per_m: Vec<f64>,
        axial_stiffness_n_per_m: Vec<f64>,
        half_backlash_um: f64,
        mesh_damping_ratio: f64,
        mesh_damping: &str,
        bearing_damping_ratio: f64,
        te_amplitude_um: Option<f64>,
        torque_nm: Option<f64>,
        table_points: usize,
        mesh_model: Option<String>,
        mesh_stiffness_n_per_m: Option<Vec<f64>>,
        transmission_error_m: Option<Vec<f64>>,
        mesh_stiffness_scale: f64,
    ) -> PyResult<Self> {
        if let (Some(m), Some(_)) = (&mesh_model, &mesh_stiffness_n_per_m) {
            return Err(Error::config(
                "mesh_model",
                m,
                "give either mesh_model or a mesh_stiffness_n_per_m table, not both",
            ))
            .py_err();
        }
        if let (Some(a), Some(_)) = (te_amplitude_um, &transmission_error_m) {
            return Err(Error::config(
                "te_amplitude_um",
                a,
                "give either te_amplitude_um or a transmission_error table, not both",
            ))
            .py_err();
        }
        let defaults = GearSystemDefaults {
            half_backlash_m: half_backlash_um * 1e-6,
            mesh_damping_ratio,
            mesh_damping: mesh_damping_mode(mesh_damping).py_err()?,
            bearing_damping_ratio,
            te_amplitude_m: te_amplitude_um.unwrap_or(2.0) * 1e-6,
            table_points,
            mesh_stiffness_scale,
        };
        let schedule = support_schedule(&speeds_rpm, &radial_stiffness_n_per_m, &axial_stiffness_n_per_m).py_err()?;
        let mut spec = gear.inner.spec.clone();
        if let Some(t) = torque_nm {
            spec.input_torque_n_m = finite("torque_nm", t).py_err()?;
        }
        let mesh_model = match (&mesh_stiffness_n_per_m, mesh_model) {
            (Some(_), _) => TABLE_MODEL.to_string(),
            (None, m) => m.unwrap_or_else(|| "potential-energy".to_string()),
        };
        let tables = UserTables {
            mesh_stiffness_n_per_m,
            transmission_error_m,
        };
        Self::build(py, spec, defaults, schedule, mesh_model, tables)
    }

    /// Pickle support: the versioned serde envelope (see `_restore`).
    fn __reduce__(&self, py: Python<'_>) -> PyResult<super::persist::Reduced> {
        self.reduce_state(py)
    }

    /// Model numbers: mean/min/max normal mesh stiffness, mesh damping, masses,
    /// base radii, angles, backlash, TE amplitude, torque.
    fn params(&self) -> BTreeMap<&'static str, f64> {
        let pair = &self.sweep.pair;
        let p = pair.params();
        let k = &p.mesh_stiffness_n_per_m;
        let mut d = BTreeMap::new();
        d.insert("mesh_stiffness_mean_n_per_m", k.iter().sum::<f64>() / k.len() as f64);
        d.insert("mesh_stiffness_min_n_per_m", k.iter().cloned().fold(f64::MAX, f64::min));
        d.insert("mesh_stiffness_max_n_per_m", k.iter().cloned().fold(f64::MIN, f64::max));
        d.insert("mesh_damping_n_s_per_m", pair.mesh_damping_n_s_per_m());
        d.insert("mesh_damping_ratio", p.mesh_damping_ratio);
        d.insert("mesh_damping_always", f64::from(p.mesh_damping == MeshDamping::Always));
        d.insert("bearing_damping_ratio", self.defaults.bearing_damping_ratio);
        d.insert("half_backlash_um", p.half_backlash_m * 1e6);
        d.insert("te_amplitude_um", self.defaults.te_amplitude_m * 1e6);
        d.insert("mesh_stiffness_scale", self.defaults.mesh_stiffness_scale);
        d.insert("torque_nm", p.input_torque_n_m);
        d.insert("pinion_mass_kg", p.pinion.mass_kg);
        d.insert("gear_mass_kg", p.gear.mass_kg);
        d.insert("pinion_inertia_kg_m2", p.pinion.inertia_kg_m2);
        d.insert("gear_inertia_kg_m2", p.gear.inertia_kg_m2);
        d.insert("pinion_base_radius_m", p.pinion.base_radius_m);
        d.insert("gear_base_radius_m", p.gear.base_radius_m);
        d.insert("helix_angle_deg", p.helix_angle_rad.to_degrees());
        d.insert("line_of_action_angle_deg", p.line_of_action_angle_rad.to_degrees());
        d.insert("pinion_teeth", p.pinion_teeth as f64);
        d
    }

    /// The support stiffness schedule as given: (speed_rpm, kr, ka) arrays.
    fn schedule(&self) -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        (
            self.schedule.iter().map(|s| s.0).collect(),
            self.schedule.iter().map(|s| s.1).collect(),
            self.schedule.iter().map(|s| s.2).collect(),
        )
    }

    /// Support stiffness (kr, ka) [N/m] at a speed (linear in speed).
    fn bearing_stiffness_at(&self, speed_rpm: f64) -> (f64, f64) {
        self.sweep.bearings.at(speed_rpm)
    }

    /// Mesh model used ("potential-energy" or "iso").
    #[getter]
    fn mesh_model(&self) -> &str {
        &self.mesh_model
    }

    /// Diagonal masses of q = [x_p, y_p, z_p, x_g, y_g, z_g, u] [kg].
    fn mass_diagonal_kg(&self, speed_rpm: f64) -> PyResult<Vec<f64>> {
        Ok(self.pair_at(speed_rpm)?.masses_kg().to_vec())
    }

    /// Linear stiffness matrix in contact K = diag(k_b) + k_m a a^T [N/m].
    fn stiffness_matrix(&self, speed_rpm: f64, mesh_stiffness_n_per_m: f64) -> PyResult<Vec<Vec<f64>>> {
        positive("mesh_stiffness_n_per_m", mesh_stiffness_n_per_m).py_err()?;
        let k = self.pair_at(speed_rpm)?.stiffness_matrix(mesh_stiffness_n_per_m);
        Ok((0..7).map(|i| (0..7).map(|j| k[(i, j)]).collect()).collect())
    }

    /// Undamped natural frequencies in contact [Hz], ascending.
    fn natural_frequencies_hz(&self, speed_rpm: f64, mesh_stiffness_n_per_m: f64) -> PyResult<Vec<f64>> {
        positive("mesh_stiffness_n_per_m", mesh_stiffness_n_per_m).py_err()?;
        let (w, _) = self.pair_at(speed_rpm)?.natural_modes(mesh_stiffness_n_per_m);
        Ok(w.iter().map(|w| w / (2.0 * std::f64::consts::PI)).collect())
    }

    /// Mesh-normal projection a of q.
    fn projection(&self) -> Vec<f64> {
        self.sweep.pair.projection().to_vec()
    }

    /// Static state (in contact, mean stiffness and TE) [m].
    fn static_state_m(&self, speed_rpm: f64) -> PyResult<Vec<f64>> {
        Ok(self.pair_at(speed_rpm)?.static_state().py_err()?[..7].to_vec())
    }

    /// Mesh period 60 / (z_p n) [s].
    fn mesh_period_s(&self, speed_rpm: f64) -> PyResult<f64> {
        self.sweep.pair.mesh_period_s(speed_rpm).py_err()
    }

    /// Check that `steps_per_period` RK4 steps resolve the mesh period and
    /// the shortest natural period at `speed_rpm` (ConfigError otherwise).
    fn check_steps(&self, speed_rpm: f64, steps_per_period: usize) -> PyResult<()> {
        self.pair_at(speed_rpm)?.system(speed_rpm, steps_per_period).py_err()?;
        Ok(())
    }

    /// Mesh stiffness (normal) and TE tables the model uses, over one mesh
    /// period: phases i / n, N/m, um and m.
    fn mesh_tables<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let p = self.sweep.pair.params();
        let n = p.mesh_stiffness_n_per_m.len();
        let d = PyDict::new(py);
        let phase: Vec<f64> = (0..n).map(|i| i as f64 / n as f64).collect();
        d.set_item("mesh_phase", phase.into_pyarray(py))?;
        d.set_item(
            "normal_stiffness_n_per_m",
            p.mesh_stiffness_n_per_m.clone().into_pyarray(py),
        )?;
        d.set_item(
            "transmission_error_um",
            p.transmission_error_m
                .iter()
                .map(|e| e * 1e6)
                .collect::<Vec<_>>()
                .into_pyarray(py),
        )?;
        d.set_item("transmission_error_m", p.transmission_error_m.clone().into_pyarray(py))?;
        Ok(d)
    }
}

fn mesh_model_of(pair: &GearPair, model: &str) -> Result<MeshStiffness> {
    mesh_model(pair, model)
}

/// `mesh_model` of a system built from a user mesh-stiffness table.
const TABLE_MODEL: &str = "table";

/// Mesh stiffness (normal direction, N/m) and TE (m) tables given by the
/// user: uniform samples over one mesh period, used as they are.
#[derive(Debug, Clone, Default)]
pub struct UserTables {
    /// Mesh stiffness samples along the normal deflection \[N/m\].
    pub mesh_stiffness_n_per_m: Option<Vec<f64>>,
    /// Static transmission error samples \[m\].
    pub transmission_error_m: Option<Vec<f64>>,
}

impl PyGearSystem {
    /// The serialised state of the system (pickling).
    fn reduce_state(&self, py: Python<'_>) -> PyResult<super::persist::Reduced> {
        let d = &self.defaults;
        let state = super::persist::GearSystemState {
            spec: self.spec.clone(),
            half_backlash_m: d.half_backlash_m,
            mesh_damping_ratio: d.mesh_damping_ratio,
            mesh_damping: match d.mesh_damping {
                MeshDamping::Always => "always".to_string(),
                _ => "in-contact".to_string(),
            },
            bearing_damping_ratio: d.bearing_damping_ratio,
            te_amplitude_m: d.te_amplitude_m,
            table_points: d.table_points,
            mesh_stiffness_scale: d.mesh_stiffness_scale,
            schedule: self.schedule.clone(),
            mesh_model: self.mesh_model.clone(),
            mesh_stiffness_n_per_m: self.tables.mesh_stiffness_n_per_m.clone(),
            transmission_error_m: self.tables.transmission_error_m.clone(),
        };
        super::persist::reduce(py, "GearSystem", &state)
    }

    /// Rebuild a system from its serialised state (SI, as `new` stores it).
    pub(super) fn restore(py: Python<'_>, s: super::persist::GearSystemState) -> PyResult<Self> {
        let defaults = GearSystemDefaults {
            half_backlash_m: s.half_backlash_m,
            mesh_damping_ratio: s.mesh_damping_ratio,
            mesh_damping: mesh_damping_mode(&s.mesh_damping).py_err()?,
            bearing_damping_ratio: s.bearing_damping_ratio,
            te_amplitude_m: s.te_amplitude_m,
            table_points: s.table_points,
            mesh_stiffness_scale: s.mesh_stiffness_scale,
        };
        let tables = UserTables {
            mesh_stiffness_n_per_m: s.mesh_stiffness_n_per_m,
            transmission_error_m: s.transmission_error_m,
        };
        Self::build(py, s.spec, defaults, s.schedule, s.mesh_model, tables)
    }

    /// The system from SI inputs: the one build path of `new` and `restore`
    /// (mesh stiffness tabulated with the GIL released unless given; the
    /// helical pair at the first schedule speed's support stiffness).
    ///
    /// Coast (negative torque): the gear pair's geometry and mesh stiffness
    /// do not depend on the torque's sign, so the pair is built with |T| and
    /// the model gets the signed torque; the static state then sits on the
    /// back flank (docs/concepts/physics.md §7: the dead zone is odd, so
    /// `(q, T, e) -> (-q, -T, -e)` maps solutions onto solutions).
    fn build(
        py: Python<'_>,
        spec: GearPairSpec,
        mut defaults: GearSystemDefaults,
        schedule: Vec<(f64, f64, f64)>,
        mesh_model: String,
        tables: UserTables,
    ) -> PyResult<Self> {
        defaults.check().py_err()?;
        let bearings = BearingSchedule::new(schedule.clone()).py_err()?;
        let torque = finite("torque_nm", spec.input_torque_n_m).py_err()?;
        let mut drive_spec = spec.clone();
        drive_spec.input_torque_n_m = torque.abs();
        let pair = GearPair::new(drive_spec).py_err()?;
        let kn = match &tables.mesh_stiffness_n_per_m {
            Some(k) => k.clone(),
            None => {
                let (p, m) = (pair.clone(), mesh_model.clone());
                let mesh = py.detach(move || mesh_model_of(&p, &m)).py_err()?;
                mesh.normal_direction(&pair).py_err()?.samples(defaults.table_points)
            }
        };
        let te = match &tables.transmission_error_m {
            Some(e) => {
                let (lo, hi) = e.iter().fold((f64::MAX, f64::MIN), |(l, h), &v| (l.min(v), h.max(v)));
                defaults.te_amplitude_m = if e.is_empty() { 0.0 } else { 0.5 * (hi - lo) };
                e.clone()
            }
            None => TransmissionError::harmonics(vec![(defaults.te_amplitude_m, 0.0)])
                .py_err()?
                .samples(defaults.table_points),
        };
        let mesh_tables = MeshTables {
            normal_stiffness_n_per_m: kn,
            transmission_error_m: te,
        };
        let (kr, ka) = bearings.at(schedule[0].0);
        let mut params = helical_params_from_tables(&pair, mesh_tables, kr, ka, &defaults).py_err()?;
        params.input_torque_n_m = torque;
        Ok(PyGearSystem {
            sweep: HelicalSweep {
                pair: HelicalPair::new(params).py_err()?,
                bearings,
            },
            defaults,
            spec,
            schedule,
            mesh_model,
            tables,
        })
    }
}

impl PyGearSystem {
    fn pair_at(&self, speed_rpm: f64) -> PyResult<HelicalPair> {
        positive("speed_rpm", speed_rpm).py_err()?;
        let (kr, ka) = self.sweep.bearings.at(speed_rpm);
        self.sweep.pair.with_bearing_stiffness(kr, ka).py_err()
    }
}

// -------------------------------------------------------------- sweeps ----

fn direction_of(name: &str) -> Result<SweepDirection> {
    match name {
        "up" => Ok(SweepDirection::Up),
        "down" => Ok(SweepDirection::Down),
        "independent" => Ok(SweepDirection::Independent),
        other => Err(Error::config(
            "direction",
            other,
            "must be \"up\", \"down\" or \"independent\"",
        )),
    }
}

/// Names of the classifier/sweep settings accepted in `settings`.
pub const SETTING_NAMES: [&str; 12] = [
    "max_transient_periods",
    "max_period",
    "period_rel_tol",
    "converging_ratio",
    "lyapunov_block_periods",
    "lyapunov_max_periods",
    "lyapunov_sigmas",
    "lyapunov_threshold_per_mesh_period",
    "zero_one_threshold",
    "jump_rel_amplitude",
    "jump_trend_factor",
    "jump_window_speeds",
];

fn count_setting(name: &str, v: &Bound<'_, PyAny>, min: usize) -> PyResult<usize> {
    let n: i64 = v
        .extract()
        .map_err(|_| Error::config(name, v.to_string(), "must be a whole number"))
        .py_err()?;
    if n < min as i64 {
        return Err(Error::config(name, n, format!("must be at least {min}"))).py_err();
    }
    Ok(n as usize)
}

fn real_setting(name: &str, v: &Bound<'_, PyAny>) -> PyResult<f64> {
    let x: f64 = v
        .extract()
        .map_err(|_| Error::config(name, v.to_string(), "must be a number"))
        .py_err()?;
    finite(name, x).py_err()
}

fn open_unit(name: &str, x: f64) -> Result<f64> {
    if x > 0.0 && x < 1.0 {
        Ok(x)
    } else {
        Err(Error::config(name, x, "must lie strictly between 0 and 1"))
    }
}

/// Sweep settings: the four counts plus the optional `settings` (names of
/// the Python API, [`SETTING_NAMES`]; errors name the setting and value).
/// Without `max_transient_periods` the adaptive transient may grow to
/// `max(1500, 5 x transient_periods)`; without `lyapunov_max_periods` the
/// Lyapunov estimate to `max(400, 4 x lyapunov_periods)`.
fn sweep_config(
    transient_periods: usize,
    record_periods: usize,
    steps_per_period: usize,
    lyapunov_periods: usize,
    settings: Option<&Bound<'_, PyDict>>,
) -> PyResult<SweepConfig> {
    if record_periods < 2 {
        return Err(Error::config("record_periods", record_periods, "must be at least 2")).py_err();
    }
    let mut cfg = SweepConfig {
        transient_periods,
        recorded_periods: record_periods,
        steps_per_period,
        lyapunov_periods,
        // The default caps stay within the sweeps' bound on periods (the
        // counts themselves are checked against it by the sweep).
        max_transient_periods: 1500
            .max(transient_periods.saturating_mul(5))
            .min(crate::dynamics::bifurcation::MAX_PERIODS)
            .max(transient_periods),
        lyapunov_max_periods: 400
            .max(lyapunov_periods.saturating_mul(4))
            .min(crate::dynamics::bifurcation::MAX_PERIODS)
            .max(lyapunov_periods),
        ..SweepConfig::default()
    };
    let Some(settings) = settings else {
        return Ok(cfg);
    };
    for (k, v) in settings.iter() {
        let key: String = k.extract()?;
        if v.is_none() {
            continue;
        }
        let name = key.as_str();
        match name {
            "max_transient_periods" => {
                cfg.max_transient_periods = count_setting(name, &v, transient_periods)?;
            }
            "max_period" => {
                let n = count_setting(name, &v, 1)?;
                if 2 * n > record_periods {
                    return Err(Error::config(
                        name,
                        n,
                        format!(
                            "a period n needs 2 n recorded periods; record_periods = {record_periods} \
                             allows at most {}",
                            record_periods / 2
                        ),
                    ))
                    .py_err();
                }
                cfg.classify.max_period = n;
            }
            "period_rel_tol" => cfg.classify.rel_tol = open_unit(name, real_setting(name, &v)?).py_err()?,
            "converging_ratio" => cfg.classify.converging_ratio = open_unit(name, real_setting(name, &v)?).py_err()?,
            "lyapunov_block_periods" => cfg.lyapunov_block_periods = count_setting(name, &v, 1)?,
            "lyapunov_max_periods" => cfg.lyapunov_max_periods = count_setting(name, &v, lyapunov_periods)?,
            "lyapunov_sigmas" => {
                cfg.classify.lyapunov_sigmas = crate::error::non_negative(name, real_setting(name, &v)?).py_err()?;
            }
            "lyapunov_threshold_per_mesh_period" => {
                cfg.classify.lyapunov_threshold_per_period = real_setting(name, &v)?;
            }
            "zero_one_threshold" => {
                cfg.classify.zero_one_threshold = open_unit(name, real_setting(name, &v)?).py_err()?;
            }
            "jump_rel_amplitude" => cfg.jump_rel = positive(name, real_setting(name, &v)?).py_err()?,
            "jump_trend_factor" => cfg.jump_trend_factor = positive(name, real_setting(name, &v)?).py_err()?,
            "jump_window_speeds" => cfg.jump_window = count_setting(name, &v, 1)?,
            other => {
                return Err(Error::config(
                    "settings",
                    other,
                    format!("unknown setting; known: {}", SETTING_NAMES.join(", ")),
                ))
                .py_err();
            }
        }
    }
    Ok(cfg)
}

/// Motion label: "period-n", "quasi-periodic", "chaotic"; and the period (0 if none).
fn motion_label(m: Motion) -> (String, usize) {
    match m {
        Motion::Periodic(n) => (format!("period-{n}"), n),
        Motion::QuasiPeriodic => ("quasi-periodic".into(), 0),
        Motion::Chaotic => ("chaotic".into(), 0),
    }
}

fn impact_label(i: ImpactRegime) -> &'static str {
    match i {
        ImpactRegime::NoImpact => "no-impact",
        ImpactRegime::SingleSided => "single-sided",
        ImpactRegime::DoubleSided => "double-sided",
        ImpactRegime::NoContact => "no-contact",
    }
}

/// Kind of a regime-family transition, seen in sweep order.
fn transition_kind(from: Motion, to: Motion) -> &'static str {
    match (from, to) {
        (_, Motion::Chaotic) => "enters-chaos",
        (Motion::Chaotic, _) => "exits-chaos",
        (_, Motion::QuasiPeriodic) => "enters-quasi-periodic",
        _ => "exits-quasi-periodic",
    }
}

/// Mesh period `60 / (z_p n)` \[s\].
fn mesh_period(pinion_teeth: u32, speed_rpm: f64) -> f64 {
    60.0 / (pinion_teeth as f64 * speed_rpm)
}

/// Per-speed columns in sweep order (ascending speed for "up" and
/// "independent", descending for "down"); `jump_after`/`transition_*`
/// refer to the step from a row's speed to the next row's speed.
fn sweep_dict<'py>(py: Python<'py>, r: &SweepResult, pinion_teeth: u32) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let n = r.points.len();
    let down = r.direction == SweepDirection::Down;
    let order: Vec<usize> = if down { (0..n).rev().collect() } else { (0..n).collect() };
    let pts: Vec<&crate::dynamics::SpeedPoint> = order.iter().map(|&i| &r.points[i]).collect();
    // Row after which the ascending step (i, i + 1) lies in sweep order.
    let row_of = |i: usize| if down { n - 2 - i } else { i };
    let um = 1e6;
    let col = |f: &dyn Fn(&crate::dynamics::SpeedPoint) -> f64| -> Vec<f64> { pts.iter().map(|p| f(p)).collect() };
    let opt = |f: &dyn Fn(&crate::dynamics::SpeedPoint) -> Option<f64>| -> Vec<Option<f64>> {
        pts.iter().map(|p| f(p)).collect()
    };
    d.set_item("speed_rpm", col(&|p| p.speed).into_pyarray(py))?;
    let labels: Vec<(String, usize)> = pts.iter().map(|p| motion_label(p.motion)).collect();
    d.set_item("regime", labels.iter().map(|l| l.0.clone()).collect::<Vec<_>>())?;
    d.set_item(
        "period",
        labels.iter().map(|l| l.1 as i64).collect::<Vec<_>>().into_pyarray(py),
    )?;
    d.set_item("impact", pts.iter().map(|p| impact_label(p.impact)).collect::<Vec<_>>())?;
    d.set_item("lyapunov_per_mesh_period", opt(&|p| p.lyapunov_per_period))?;
    d.set_item(
        "lyapunov_stderr_per_mesh_period",
        opt(&|p| p.lyapunov_stderr_per_period),
    )?;
    let per_s = |v: Option<f64>, speed: f64| v.map(|l| l / mesh_period(pinion_teeth, speed));
    d.set_item("lyapunov_per_s", opt(&|p| per_s(p.lyapunov_per_period, p.speed)))?;
    d.set_item(
        "lyapunov_stderr_per_s",
        opt(&|p| per_s(p.lyapunov_stderr_per_period, p.speed)),
    )?;
    d.set_item("zero_one_k", opt(&|p| p.zero_one_k))?;
    d.set_item(
        "transient_periods",
        pts.iter()
            .map(|p| p.transient_periods as i64)
            .collect::<Vec<_>>()
            .into_pyarray(py),
    )?;
    d.set_item("settled", pts.iter().map(|p| p.settled).collect::<Vec<_>>())?;
    d.set_item("dte_min_um", col(&|p| p.deflection_min * um).into_pyarray(py))?;
    d.set_item("dte_max_um", col(&|p| p.deflection_max * um).into_pyarray(py))?;
    let mut jump = vec![false; n];
    for &j in &r.jumps {
        if j + 1 < n {
            jump[row_of(j)] = true;
        }
    }
    d.set_item("jump_after", jump)?;
    let mut kind: Vec<Option<&'static str>> = vec![None; n];
    let mut dmin: Vec<Option<f64>> = vec![None; n];
    let mut dmax: Vec<Option<f64>> = vec![None; n];
    for t in r.transitions.iter().filter(|t| t.index + 1 < n) {
        let row = row_of(t.index);
        let (from, to, s) = if down {
            (t.to, t.from, -1.0)
        } else {
            (t.from, t.to, 1.0)
        };
        kind[row] = Some(transition_kind(from, to));
        dmin[row] = Some(s * t.min_change * um);
        dmax[row] = Some(s * t.max_change * um);
    }
    d.set_item("transition_after", kind)?;
    d.set_item("transition_dte_min_change_um", dmin)?;
    d.set_item("transition_dte_max_change_um", dmax)?;
    d.set_item(
        "poincare_count",
        pts.iter()
            .map(|p| p.poincare_deflection.len() as i64)
            .collect::<Vec<_>>()
            .into_pyarray(py),
    )?;
    d.set_item(
        "poincare_dte_um",
        pts.iter()
            .flat_map(|p| p.poincare_deflection.iter().map(|v| v * um))
            .collect::<Vec<_>>()
            .into_pyarray(py),
    )?;
    Ok(d)
}

/// Run `work` like [`run_watched`] but keep its (partial) outcome: returns
/// the outcome and the stop (Ctrl-C or the callback), if any.
fn run_keeping<P, W>(py: Python<'_>, progress: Option<&Bound<'_, PyAny>>, work: W) -> PyResult<(P, Option<PyErr>)>
where
    P: Send,
    W: FnOnce(&(dyn Fn(usize, usize) -> bool + Sync)) -> Result<P> + Send,
{
    let slot = std::sync::Mutex::new(None);
    let run = run_watched(py, progress, |hook| {
        let p = work(hook)?;
        if let Ok(mut s) = slot.lock() {
            *s = Some(p);
        }
        Ok(())
    });
    match (run, slot.into_inner().ok().flatten()) {
        (Err(e), None) => Err(e),
        (Ok(()), None) => Err(PyRuntimeError::new_err("the gear dynamics worker returned no result")),
        (run, Some(p)) => Ok((p, run.err())),
    }
}

/// The complete sweeps, or the error to raise -- the stop, else the first
/// failed speed (as its own exception class) -- carrying what finished:
/// `_sweep_partial` (one sweep dict per job), `_sweep_failed`
/// (`(job, speed_rpm, message)`) and `_sweep_not_run` (`(job, speed_rpm)`).
/// The Python layer turns them into the `partial`, `failed` and `not_run`
/// frames.
fn sweep_results(
    py: Python<'_>,
    parts: Vec<PartialSweep>,
    stop: Option<PyErr>,
    speeds: &[f64],
    teeth: &[u32],
) -> PyResult<Vec<SweepResult>> {
    if stop.is_none() && parts.iter().all(PartialSweep::is_complete) {
        return Ok(parts.into_iter().map(|p| p.result).collect());
    }
    let err = stop.unwrap_or_else(|| {
        let first = parts.iter().find_map(|p| p.failures.first());
        super::errors::to_py(first.map_or(Error::Interrupted, |f| f.error.clone()))
    });
    let dicts = parts
        .iter()
        .zip(teeth)
        .map(|(p, &z)| sweep_dict(py, &p.result, z))
        .collect::<PyResult<Vec<_>>>()?;
    let failed: Vec<(usize, f64, String)> = parts
        .iter()
        .enumerate()
        .flat_map(|(j, p)| p.failures.iter().map(move |f| (j, f.speed, f.error.to_string())))
        .collect();
    let not_run: Vec<(usize, f64)> = parts
        .iter()
        .enumerate()
        .flat_map(|(j, p)| p.not_run.iter().map(move |&i| (j, speeds[i])))
        .collect();
    let v = err.value(py);
    v.setattr("_sweep_partial", dicts)?;
    v.setattr("_sweep_failed", failed)?;
    v.setattr("_sweep_not_run", not_run)?;
    Err(err)
}

/// One speed sweep of a gear system: per-speed columns plus the flat
/// Poincare samples (`poincare_count` per speed).
#[pyfunction]
#[pyo3(signature = (system, speeds_rpm, direction="up", transient_periods=300, record_periods=100, steps_per_period=64, lyapunov_periods=100, progress=None, settings=None))]
#[allow(clippy::too_many_arguments)]
pub fn bifurcation<'py>(
    py: Python<'py>,
    system: &PyGearSystem,
    speeds_rpm: PyReadonlyArray1<'py, f64>,
    direction: &str,
    transient_periods: usize,
    record_periods: usize,
    steps_per_period: usize,
    lyapunov_periods: usize,
    progress: Option<Bound<'py, PyAny>>,
    settings: Option<Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let speeds = speeds_rpm.as_slice()?.to_vec();
    let dir = direction_of(direction).py_err()?;
    let cfg = sweep_config(
        transient_periods,
        record_periods,
        steps_per_period,
        lyapunov_periods,
        settings.as_ref(),
    )?;
    let model = &system.sweep;
    let teeth = model.pair.params().pinion_teeth;
    let (parts, stop) = run_keeping(py, progress.as_ref(), |hook| {
        Ok(vec![sweep_partial(model, &speeds, dir, &cfg, hook)?])
    })?;
    let r = sweep_results(py, parts, stop, &speeds, &[teeth])?;
    sweep_dict(py, &r[0], teeth)
}

/// Several sweeps over the same speeds in parallel (lock-step batches);
/// one dict per (system, direction) job, in order.
#[pyfunction]
#[pyo3(signature = (systems, directions, speeds_rpm, transient_periods=300, record_periods=100, steps_per_period=64, lyapunov_periods=100, progress=None, settings=None))]
#[allow(clippy::too_many_arguments)]
pub fn bifurcation_many<'py>(
    py: Python<'py>,
    systems: Vec<PyRef<'py, PyGearSystem>>,
    directions: Vec<String>,
    speeds_rpm: PyReadonlyArray1<'py, f64>,
    transient_periods: usize,
    record_periods: usize,
    steps_per_period: usize,
    lyapunov_periods: usize,
    progress: Option<Bound<'py, PyAny>>,
    settings: Option<Bound<'py, PyDict>>,
) -> PyResult<Vec<Bound<'py, PyDict>>> {
    if systems.len() != directions.len() || systems.is_empty() {
        return Err(Error::config(
            "directions",
            format!("{} systems / {} directions", systems.len(), directions.len()),
            "give one direction per system (at least one)",
        ))
        .py_err();
    }
    let speeds = speeds_rpm.as_slice()?.to_vec();
    let cfg = sweep_config(
        transient_periods,
        record_periods,
        steps_per_period,
        lyapunov_periods,
        settings.as_ref(),
    )?;
    let jobs: Vec<(&HelicalSweep, SweepDirection)> = systems
        .iter()
        .zip(&directions)
        .map(|(s, d)| Ok((&s.sweep, direction_of(d)?)))
        .collect::<Result<_>>()
        .py_err()?;
    let teeth: Vec<u32> = systems.iter().map(|s| s.sweep.pair.params().pinion_teeth).collect();
    let (parts, stop) = run_keeping(py, progress.as_ref(), |hook| {
        sweep_many_partial(&jobs, &speeds, &cfg, hook)
    })?;
    let rs = sweep_results(py, parts, stop, &speeds, &teeth)?;
    rs.iter()
        .zip(&systems)
        .map(|(r, s)| sweep_dict(py, r, s.sweep.pair.params().pinion_teeth))
        .collect()
}

/// Regime map over TE scale x torque x speed (speed fastest), every cell from
/// its static state.
#[pyfunction]
#[pyo3(signature = (system, torques_nm, te_scales, speeds_rpm, transient_periods=300, record_periods=100, steps_per_period=64, lyapunov_periods=100, progress=None, settings=None))]
#[allow(clippy::too_many_arguments)]
pub fn regime_map<'py>(
    py: Python<'py>,
    system: &PyGearSystem,
    torques_nm: Vec<f64>,
    te_scales: Vec<f64>,
    speeds_rpm: PyReadonlyArray1<'py, f64>,
    transient_periods: usize,
    record_periods: usize,
    steps_per_period: usize,
    lyapunov_periods: usize,
    progress: Option<Bound<'py, PyAny>>,
    settings: Option<Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyDict>> {
    let speeds = speeds_rpm.as_slice()?.to_vec();
    for &t in &torques_nm {
        finite("torques_nm", t).py_err()?;
    }
    for &e in &te_scales {
        finite("te_scales", e).py_err()?;
        crate::error::non_negative("te_scales", e).py_err()?;
    }
    let cfg = sweep_config(
        transient_periods,
        record_periods,
        steps_per_period,
        lyapunov_periods,
        settings.as_ref(),
    )?;
    let model = &system.sweep;
    let z = model.pair.params().pinion_teeth;
    let (map, stop): (PartialRegimeMap, _) = run_keeping(py, progress.as_ref(), |hook| {
        regime_map_partial(model, &torques_nm, &te_scales, &speeds, &cfg, hook)
    })?;
    if stop.is_none() && map.failures.is_empty() && !map.interrupted {
        return regime_dict(py, &map.cells, z);
    }
    // The error to raise (the stop, else the first failed cell) carries the
    // finished cells (`_map_partial`), the failed ones (`_map_failed`:
    // `(torque_nm, te_scale, speed_rpm, message)`) and those never run
    // (`_map_not_run`: `(torque_nm, te_scale, speed_rpm)`).
    let err = stop
        .unwrap_or_else(|| super::errors::to_py(map.failures.first().map_or(Error::Interrupted, |f| f.error.clone())));
    let (nt, ns) = (torques_nm.len(), speeds.len());
    let failed: Vec<(f64, f64, f64, String)> = map
        .failures
        .iter()
        .map(|f| (f.input_torque_n_m, f.error_scale, f.speed_rpm, f.error.to_string()))
        .collect();
    let not_run: Vec<(f64, f64, f64)> = map
        .not_run
        .iter()
        .map(|&c| (torques_nm[(c / ns) % nt], te_scales[c / ns / nt], speeds[c % ns]))
        .collect();
    let v = err.value(py);
    v.setattr("_map_partial", regime_dict(py, &map.cells, z)?)?;
    v.setattr("_map_failed", failed)?;
    v.setattr("_map_not_run", not_run)?;
    Err(err)
}

/// The regime map's columns, one row per cell in map order.
fn regime_dict<'py>(py: Python<'py>, cells: &[RegimeCell], z: u32) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let col = |f: &dyn Fn(&crate::dynamics::RegimeCell) -> f64| -> Vec<f64> { cells.iter().map(f).collect() };
    d.set_item("torque_nm", col(&|c| c.input_torque_n_m).into_pyarray(py))?;
    d.set_item("te_scale", col(&|c| c.error_scale).into_pyarray(py))?;
    d.set_item("speed_rpm", col(&|c| c.speed_rpm).into_pyarray(py))?;
    let labels: Vec<(String, usize)> = cells.iter().map(|c| motion_label(c.motion)).collect();
    d.set_item("regime", labels.iter().map(|l| l.0.clone()).collect::<Vec<_>>())?;
    d.set_item(
        "period",
        labels.iter().map(|l| l.1 as i64).collect::<Vec<_>>().into_pyarray(py),
    )?;
    d.set_item(
        "impact",
        cells.iter().map(|c| impact_label(c.impact)).collect::<Vec<_>>(),
    )?;
    d.set_item("amplitude_um", col(&|c| c.amplitude_m * 1e6).into_pyarray(py))?;
    d.set_item("mean_dte_um", col(&|c| c.mean_deflection_m * 1e6).into_pyarray(py))?;
    let opt =
        |f: &dyn Fn(&crate::dynamics::RegimeCell) -> Option<f64>| -> Vec<Option<f64>> { cells.iter().map(f).collect() };
    d.set_item("lyapunov_per_mesh_period", opt(&|c| c.lyapunov_per_period))?;
    d.set_item(
        "lyapunov_stderr_per_mesh_period",
        opt(&|c| c.lyapunov_stderr_per_period),
    )?;
    d.set_item(
        "lyapunov_per_s",
        opt(&|c| c.lyapunov_per_period.map(|l| l / mesh_period(z, c.speed_rpm))),
    )?;
    d.set_item(
        "lyapunov_stderr_per_s",
        opt(&|c| c.lyapunov_stderr_per_period.map(|l| l / mesh_period(z, c.speed_rpm))),
    )?;
    d.set_item("zero_one_k", opt(&|c| c.zero_one_k))?;
    d.set_item(
        "transient_periods",
        cells
            .iter()
            .map(|c| c.transient_periods as i64)
            .collect::<Vec<_>>()
            .into_pyarray(py),
    )?;
    d.set_item("settled", cells.iter().map(|c| c.settled).collect::<Vec<_>>())?;
    Ok(d)
}

// ------------------------------------------------------------ Lyapunov ----

/// Largest Lyapunov exponent of a reference system ("lorenz": sigma 10,
/// rho 28, beta 8/3; "duffing-ueda": x'' + 0.05 x' + x^3 = 7.5 cos t) per
/// unit time, by "benettin" (two trajectories) or "variational".
#[pyfunction]
#[pyo3(signature = (name, time=None, step=None, transient_time=None, method="benettin"))]
pub fn largest_lyapunov_reference(
    py: Python<'_>,
    name: &str,
    time: Option<f64>,
    step: Option<f64>,
    transient_time: Option<f64>,
    method: &str,
) -> PyResult<f64> {
    let (x0, t_def, h_def): (Vec<f64>, f64, f64) = match name {
        "lorenz" => (vec![1.0, 1.0, 20.0], 2000.0, 0.01),
        "duffing-ueda" => (vec![3.0, 0.0], 20_000.0, 2.0 * std::f64::consts::PI / 120.0),
        other => {
            return Err(Error::config("name", other, "must be \"lorenz\" or \"duffing-ueda\"")).py_err();
        }
    };
    let t = positive("time", time.unwrap_or(t_def)).py_err()?;
    let h = positive("step", step.unwrap_or(h_def)).py_err()?;
    let tt = crate::error::non_negative("transient_time", transient_time.unwrap_or(20.0)).py_err()?;
    if h > t / 100.0 {
        return Err(Error::config("step", h, "at least 100 steps over the averaging time")).py_err();
    }
    let renorm = ((0.1 / h).round() as usize).max(1);
    let cfg = LyapunovConfig {
        transient_steps: (tt / h).round() as usize,
        measure_steps: (t / h).round() as usize,
        renorm_steps: renorm,
        separation: 1e-8,
    };
    let method = method.to_string();
    let name = name.to_string();
    super::parallel::watched(py, 1, None, move |_, _| -> Result<f64> {
        match (name.as_str(), method.as_str()) {
            ("lorenz", "benettin") => {
                let g = Gridded::new(Lorenz::classic(), h, 1);
                let x: [f64; 3] = [x0[0], x0[1], x0[2]];
                Ok(largest_lyapunov_benettin(&g, &x, 0, &[1.0; 3], &cfg)?.0)
            }
            ("lorenz", "variational") => {
                largest_lyapunov_variational(&Lorenz::classic(), &[x0[0], x0[1], x0[2]], 0.0, h, &cfg)
            }
            ("duffing-ueda", "benettin") => {
                // Grid with the forcing period 2 pi so the time table is exact.
                let spp = ((2.0 * std::f64::consts::PI / h).round() as usize).max(1);
                let g = Gridded::new(DuffingUeda::chaotic(), 2.0 * std::f64::consts::PI, spp);
                Ok(largest_lyapunov_benettin(&g, &[x0[0], x0[1]], 0, &[1.0; 2], &cfg)?.0)
            }
            ("duffing-ueda", "variational") => {
                largest_lyapunov_variational(&DuffingUeda::chaotic(), &[x0[0], x0[1]], 0.0, h, &cfg)
            }
            (_, m) => Err(Error::config("method", m, "must be \"benettin\" or \"variational\"")),
        }
    })?
    .py_err()
}

/// Largest Lyapunov exponent of the gear system at one speed, by Benettin
/// renormalisation once per mesh period after a transient from the static
/// state, measured in blocks of `block_periods` periods (`periods` rounded
/// down to whole blocks, at least 2): a dict with the exponent and its
/// batch-means standard error per second and per mesh period, the blocks
/// and the mesh period \[s\].
#[pyfunction]
#[pyo3(signature = (system, speed_rpm, periods=200, transient_periods=300, steps_per_period=64, block_periods=10))]
pub fn largest_lyapunov_gear(
    py: Python<'_>,
    system: &PyGearSystem,
    speed_rpm: f64,
    periods: usize,
    transient_periods: usize,
    steps_per_period: usize,
    block_periods: usize,
) -> PyResult<BTreeMap<&'static str, f64>> {
    if block_periods == 0 {
        return Err(Error::config("block_periods", 0, "must be at least 1")).py_err();
    }
    if periods < block_periods.saturating_mul(2) {
        return Err(Error::config(
            "periods",
            periods,
            format!("at least 2 blocks of block_periods = {block_periods} are needed"),
        ))
        .py_err();
    }
    use crate::dynamics::bifurcation::{MAX_PERIODS, MAX_STEPS_PER_PERIOD};
    for (name, n, max) in [
        ("steps_per_period", steps_per_period, MAX_STEPS_PER_PERIOD),
        ("periods", periods, MAX_PERIODS),
        ("transient_periods", transient_periods, MAX_PERIODS),
    ] {
        if n > max {
            return Err(Error::config(name, n, format!("must be at most {max}"))).py_err();
        }
    }
    let pair = system.pair_at(speed_rpm)?;
    let est = super::parallel::watched(py, 1, None, move |_, _| -> Result<(f64, f64, usize, f64)> {
        let sys = pair.system(speed_rpm, steps_per_period)?;
        let mut x0 = pair.static_state()?;
        // Looks at the cancel flag as it goes: Ctrl-C ends a long transient.
        crate::dynamics::integrate::rk4_advance_checked(&sys, &mut x0, 0, transient_periods * steps_per_period)?;
        // Scales: backlash for displacements, backlash x mesh frequency for velocities.
        let b = pair.params().half_backlash_m;
        let v = b / sys.period_s();
        let mut scale = [b; 14];
        for s in scale.iter_mut().skip(7) {
            *s = v;
        }
        let blocks = periods / block_periods;
        let cfg = LyapunovBlocks {
            renorm_steps: steps_per_period,
            renorms_per_block: block_periods,
            min_blocks: blocks,
            max_blocks: blocks,
            separation: 1e-6,
            sigmas: 0.0,
            threshold: 0.0,
        };
        let e = largest_lyapunov_blocks(&sys, &x0, 0, &scale, &cfg, |_| {})?;
        Ok((e.exponent, e.standard_error, e.blocks, sys.period_s()))
    })?
    .py_err()?;
    let t = mesh_period(system.sweep.pair.params().pinion_teeth, speed_rpm);
    let mut d = BTreeMap::new();
    d.insert("lyapunov_per_s", est.0);
    d.insert("lyapunov_stderr_per_s", est.1);
    d.insert("lyapunov_per_mesh_period", est.0 * t);
    d.insert("lyapunov_stderr_per_mesh_period", est.1 * t);
    d.insert("blocks", est.2 as f64);
    d.insert("mesh_period_s", t);
    Ok(d)
}

// ------------------------------------------------------------- bearings ----

/// Support stiffness of one gear shaft from `bearings_per_shaft` bearings in
/// parallel: case "constant" (zero-speed solve) or "speed" (quasi-static at
/// each speed), ring held level. Returns (speed_rpm, kr, ka) arrays; for
/// "constant" the single zero-speed value at speed 0.
#[pyfunction]
#[pyo3(signature = (bearing, case, speeds_rpm, axial_n, radial_n, bearings_per_shaft=2))]
pub fn gear_bearing_schedule(
    py: Python<'_>,
    bearing: &PyBearing,
    case: &str,
    speeds_rpm: Vec<f64>,
    axial_n: f64,
    radial_n: f64,
    bearings_per_shaft: usize,
) -> PyResult<(Vec<f64>, Vec<f64>, Vec<f64>)> {
    let c = match case {
        "constant" => BearingCase::Constant,
        "speed" => BearingCase::Speed,
        other => {
            return Err(Error::config("stiffness", other, "must be \"constant\" or \"speed\"")).py_err();
        }
    };
    let b = bearing.inner.clone();
    let sched = py
        .detach(move || -> Result<Vec<(f64, f64, f64)>> {
            let s = bearing_schedule(&b, c, &speeds_rpm, axial_n, radial_n, bearings_per_shaft)?;
            Ok(match c {
                BearingCase::Constant => {
                    let (kr, ka) = s.at(0.0);
                    vec![(0.0, kr, ka)]
                }
                BearingCase::Speed => speeds_rpm
                    .iter()
                    .map(|&n| {
                        let (kr, ka) = s.at(n);
                        (n, kr, ka)
                    })
                    .collect(),
            })
        })
        .py_err()?;
    Ok((
        sched.iter().map(|s| s.0).collect(),
        sched.iter().map(|s| s.1).collect(),
        sched.iter().map(|s| s.2).collect(),
    ))
}

/// Seed A bearing loads (axial incl. 300 N preload, radial) [N] at a torque.
#[pyfunction]
pub fn seed_gear_bearing_loads(torque_nm: f64) -> PyResult<(f64, f64)> {
    seed_bearing_loads(torque_nm).py_err()
}

/// The documented defaults for what seed A omits.
#[pyfunction]
pub fn gear_defaults() -> BTreeMap<&'static str, f64> {
    let d = GearSystemDefaults::default();
    let mut m = BTreeMap::new();
    m.insert("half_backlash_um", d.half_backlash_m * 1e6);
    m.insert("mesh_damping_ratio", d.mesh_damping_ratio);
    m.insert("bearing_damping_ratio", d.bearing_damping_ratio);
    m.insert("te_amplitude_um", d.te_amplitude_m * 1e6);
    m.insert("mesh_stiffness_scale", d.mesh_stiffness_scale);
    m.insert("table_points", d.table_points as f64);
    m.insert("bearings_per_shaft", crate::dynamics::seed::BEARINGS_PER_SHAFT as f64);
    m
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyGearPair>()?;
    m.add_class::<PyGearSystem>()?;
    m.add_function(wrap_pyfunction!(bifurcation, m)?)?;
    m.add_function(wrap_pyfunction!(bifurcation_many, m)?)?;
    m.add_function(wrap_pyfunction!(regime_map, m)?)?;
    m.add_function(wrap_pyfunction!(largest_lyapunov_reference, m)?)?;
    m.add_function(wrap_pyfunction!(largest_lyapunov_gear, m)?)?;
    m.add_function(wrap_pyfunction!(gear_bearing_schedule, m)?)?;
    m.add_function(wrap_pyfunction!(seed_gear_bearing_loads, m)?)?;
    m.add_function(wrap_pyfunction!(gear_defaults, m)?)?;
    Ok(())
}
