//! Bindings for the spindle rotor dynamics (src/rotor/spindle_vibration.rs):
//! Campbell diagram, critical speeds, vibration velocity against speed and
//! the spectrum at one speed. Sweeps run through `map_interruptible` (GIL
//! released, Ctrl-C, progress); results are dicts of numpy columns.

use numpy::{IntoPyArray, PyReadonlyArray1};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::errors::IntoPy;
use super::parallel::{map_interruptible, watched};
use crate::bearing::RacewayOffsets;
use crate::effects::{Effect, EffectSet};
use crate::error::{finite, Error, Result};
use crate::rotor::modal::Whirl;
use crate::rotor::presets::SpindleRotorGeometry;
use crate::rotor::spindle_bearings::OffsetTable;
use crate::rotor::spindle_vibration::{
    CustomRotor, RowMaterial, SpindleVibration, SpindleVibrationConfig, UnbalanceSpec, VibrationPoint,
};

/// A spindle's own rotor (dict keys as the fields; lengths in m, bearings
/// as the JSON of `Bearing`): replaces the seed rotor and `row_material`.
#[derive(FromPyObject)]
struct RotorArg {
    #[pyo3(item)]
    sections_m: Vec<(f64, f64, f64)>,
    #[pyo3(item)]
    front_rows_m: [f64; 2],
    #[pyo3(item)]
    rear_rows_m: [f64; 2],
    #[pyo3(item)]
    core_span_m: (f64, f64),
    #[pyo3(item)]
    core_outer_diameter_m: f64,
    #[pyo3(item)]
    core_inner_diameter_m: f64,
    #[pyo3(item)]
    air_gap_m: f64,
    #[pyo3(item)]
    front_bearing_json: String,
    #[pyo3(item)]
    rear_bearing_json: String,
}

impl RotorArg {
    fn custom(self) -> Result<CustomRotor> {
        let bearing = |field: &str, text: &str| -> Result<crate::bearing::Bearing> {
            serde_json::from_str(text).map_err(|e| Error::config(field, "json", e.to_string()))
        };
        Ok(CustomRotor {
            front_bearing: bearing("rotor.front_bearing_json", &self.front_bearing_json)?,
            rear_bearing: bearing("rotor.rear_bearing_json", &self.rear_bearing_json)?,
            geometry: SpindleRotorGeometry {
                sections_m: self.sections_m,
                front_rows_m: self.front_rows_m,
                rear_rows_m: self.rear_rows_m,
                core_span_m: self.core_span_m,
                core_outer_diameter_m: self.core_outer_diameter_m,
                core_inner_diameter_m: self.core_inner_diameter_m,
                air_gap_m: self.air_gap_m,
            },
        })
    }
}

fn material(name: &str) -> Result<RowMaterial> {
    match name {
        "hybrid" => Ok(RowMaterial::Hybrid),
        "steel" => Ok(RowMaterial::Steel),
        other => Err(Error::config("row_material", other, "must be \"hybrid\" or \"steel\"")),
    }
}

/// Per-speed thermal offsets of both pairs (all arrays the same length).
struct Offsets {
    speeds_rpm: Vec<f64>,
    front_radial_m: Vec<f64>,
    front_axial_m: Vec<f64>,
    rear_radial_m: Vec<f64>,
    rear_axial_m: Vec<f64>,
}

impl Offsets {
    fn tables(&self) -> Result<(OffsetTable, OffsetTable)> {
        let n = self.speeds_rpm.len();
        for (name, v) in [
            ("front_radial_m", &self.front_radial_m),
            ("front_axial_m", &self.front_axial_m),
            ("rear_radial_m", &self.rear_radial_m),
            ("rear_axial_m", &self.rear_axial_m),
        ] {
            if v.len() != n {
                return Err(Error::config(
                    format!("offsets.{name}"),
                    v.len(),
                    format!("need one value per offset speed ({n})"),
                ));
            }
        }
        let table = |r: &[f64], a: &[f64]| {
            OffsetTable::new(
                self.speeds_rpm.clone(),
                r.iter()
                    .zip(a)
                    .map(|(&radial_m, &axial_m)| RacewayOffsets { axial_m, radial_m })
                    .collect(),
            )
        };
        Ok((
            table(&self.front_radial_m, &self.front_axial_m)?,
            table(&self.rear_radial_m, &self.rear_axial_m)?,
        ))
    }
}

fn offsets_arg(d: Option<&Bound<'_, PyDict>>) -> PyResult<Option<Offsets>> {
    let Some(d) = d else { return Ok(None) };
    let get = |k: &str| -> PyResult<Vec<f64>> {
        match d.get_item(k)? {
            Some(v) => v.extract::<Vec<f64>>(),
            None => Err(super::errors::to_py(Error::config("offsets", k, "missing key"))),
        }
    };
    Ok(Some(Offsets {
        speeds_rpm: get("speed_rpm")?,
        front_radial_m: get("front_radial_m")?,
        front_axial_m: get("front_axial_m")?,
        rear_radial_m: get("rear_radial_m")?,
        rear_axial_m: get("rear_axial_m")?,
    }))
}

fn build(
    row_material: &str,
    preload_n: f64,
    effects: Option<Vec<String>>,
    offsets: Option<Offsets>,
    rotor: Option<RotorArg>,
) -> Result<SpindleVibration> {
    let mut c = match rotor {
        Some(r) => SpindleVibrationConfig {
            rotor: Some(r.custom()?),
            ..SpindleVibrationConfig::seed(RowMaterial::Steel)
        },
        None => SpindleVibrationConfig::seed(material(row_material)?),
    };
    c.preload_n = preload_n;
    if let Some(names) = effects {
        c.effects = EffectSet::from_names(&names)?;
    }
    if let Some(o) = offsets {
        let (f, r) = o.tables()?;
        c.front_offsets = Some(f);
        c.rear_offsets = Some(r);
    }
    SpindleVibration::new(c)
}

fn speeds(a: &PyReadonlyArray1<'_, f64>) -> Result<Vec<f64>> {
    let v = a
        .as_slice()
        .map_err(|_| Error::config("speeds_rpm", "array", "must be contiguous"))?;
    if v.is_empty() {
        return Err(Error::config("speeds_rpm", 0, "need at least one speed"));
    }
    for s in v {
        finite("speeds_rpm", *s)?;
        if *s < 0.0 {
            return Err(Error::config("speeds_rpm", *s, "must be non-negative"));
        }
    }
    Ok(v.to_vec())
}

fn whirl_name(w: Whirl) -> &'static str {
    match w {
        Whirl::Forward => "forward",
        Whirl::Backward => "backward",
        Whirl::Undetermined => "undetermined",
    }
}

/// Campbell diagram: flat columns speed_rpm, mode, frequency_hz, damping_ratio, whirl.
#[pyfunction]
#[pyo3(signature = (row_material, preload_n, speeds_rpm, modes=8, effects=None, offsets=None, progress=None, rotor=None))]
#[allow(clippy::too_many_arguments)]
fn rotor_campbell<'py>(
    py: Python<'py>,
    row_material: &str,
    preload_n: f64,
    speeds_rpm: PyReadonlyArray1<'py, f64>,
    modes: usize,
    effects: Option<Vec<String>>,
    offsets: Option<&Bound<'py, PyDict>>,
    progress: Option<&Bound<'py, PyAny>>,
    rotor: Option<RotorArg>,
) -> PyResult<Bound<'py, PyDict>> {
    let sp = speeds(&speeds_rpm).py_err()?;
    if modes == 0 {
        return Err(Error::config("modes", 0, "ask for at least one mode")).py_err();
    }
    let off = offsets_arg(offsets)?;
    let s = py
        .detach(|| build(row_material, preload_n, effects, off, rotor))
        .py_err()?;
    let pts = map_interruptible(py, &sp, None, progress, |&n| s.campbell(&[n], modes))?;
    let (mut speed, mut mode, mut freq, mut zeta, mut whirl) = (vec![], vec![], vec![], vec![], vec![]);
    for p in pts {
        let p = p.py_err()?;
        for (k, m) in p.points[0].modes.iter().enumerate() {
            speed.push(p.points[0].speed_rpm);
            mode.push(k as i64);
            freq.push(m.frequency_hz);
            zeta.push(m.damping_ratio);
            whirl.push(whirl_name(m.whirl));
        }
    }
    let d = PyDict::new(py);
    d.set_item("speed_rpm", speed.into_pyarray(py))?;
    d.set_item("mode", mode.into_pyarray(py))?;
    d.set_item("frequency_hz", freq.into_pyarray(py))?;
    d.set_item("damping_ratio", zeta.into_pyarray(py))?;
    d.set_item("whirl", whirl)?;
    Ok(d)
}

/// Critical speeds (crossings of the branches with f = harmonic x speed / 60).
#[pyfunction]
#[pyo3(signature = (row_material, preload_n, speeds_rpm, modes=8, harmonic=1.0, effects=None, offsets=None, rotor=None))]
#[allow(clippy::too_many_arguments)]
fn rotor_critical_speeds<'py>(
    py: Python<'py>,
    row_material: &str,
    preload_n: f64,
    speeds_rpm: PyReadonlyArray1<'py, f64>,
    modes: usize,
    harmonic: f64,
    effects: Option<Vec<String>>,
    offsets: Option<&Bound<'py, PyDict>>,
    rotor: Option<RotorArg>,
) -> PyResult<Bound<'py, PyDict>> {
    let sp = speeds(&speeds_rpm).py_err()?;
    crate::error::positive("harmonic", harmonic).py_err()?;
    if modes == 0 {
        return Err(Error::config("modes", 0, "ask for at least one mode")).py_err();
    }
    let off = offsets_arg(offsets)?;
    let s = py
        .detach(|| build(row_material, preload_n, effects, off, rotor))
        .py_err()?;
    // One speed per item (each independent, as in one Campbell diagram):
    // Ctrl-C skips the speeds not started.
    let pts = map_interruptible(py, &sp, None, None, |&n| s.campbell(&[n], modes))?;
    let mut points = Vec::with_capacity(pts.len());
    for p in pts {
        points.extend(p.py_err()?.points);
    }
    let c = crate::rotor::modal::CampbellDiagram { points }.critical_speeds(harmonic);
    let d = PyDict::new(py);
    d.set_item(
        "speed_rpm",
        c.iter().map(|x| x.speed_rpm).collect::<Vec<_>>().into_pyarray(py),
    )?;
    d.set_item(
        "frequency_hz",
        c.iter().map(|x| x.frequency_hz).collect::<Vec<_>>().into_pyarray(py),
    )?;
    d.set_item(
        "branch",
        c.iter().map(|x| x.branch as i64).collect::<Vec<_>>().into_pyarray(py),
    )?;
    d.set_item("whirl", c.iter().map(|x| whirl_name(x.whirl)).collect::<Vec<_>>())?;
    Ok(d)
}

fn unbalance_spec(grade: Option<f64>, g_mm: Option<f64>) -> Result<UnbalanceSpec> {
    match (grade, g_mm) {
        (Some(_), Some(_)) => Err(Error::config(
            "unbalance_g_mm",
            "both",
            "give either unbalance_grade or unbalance_g_mm, not both",
        )),
        (_, Some(u)) => Ok(UnbalanceSpec::MassRadius { unbalance_g_mm: u }),
        (Some(g), None) => Ok(UnbalanceSpec::Grade { grade_mm_per_s: g }),
        (None, None) => Ok(UnbalanceSpec::Grade { grade_mm_per_s: 2.5 }),
    }
}

/// Nose vibration velocity against speed: method "frequency" (steady
/// unbalance response, linearised rows) or "time" (time response with the
/// nonlinear ball forces, `duration_s` per speed).
#[pyfunction]
#[pyo3(signature = (row_material, preload_n, speeds_rpm, unbalance_grade=None, unbalance_g_mm=None, method="frequency", duration_s=0.1, effects=None, offsets=None, progress=None, rotor=None))]
#[allow(clippy::too_many_arguments)]
fn rotor_vibration<'py>(
    py: Python<'py>,
    row_material: &str,
    preload_n: f64,
    speeds_rpm: PyReadonlyArray1<'py, f64>,
    unbalance_grade: Option<f64>,
    unbalance_g_mm: Option<f64>,
    method: &str,
    duration_s: f64,
    effects: Option<Vec<String>>,
    offsets: Option<&Bound<'py, PyDict>>,
    progress: Option<&Bound<'py, PyAny>>,
    rotor: Option<RotorArg>,
) -> PyResult<Bound<'py, PyDict>> {
    let sp = speeds(&speeds_rpm).py_err()?;
    let time = match method {
        "frequency" => false,
        "time" => true,
        other => return Err(Error::config("method", other, "must be \"frequency\" or \"time\"")).py_err(),
    };
    if time {
        if let Some(s) = sp.iter().find(|s| **s <= 0.0) {
            return Err(Error::config("speeds_rpm", *s, "the time method needs positive speeds")).py_err();
        }
    }
    let spec = unbalance_spec(unbalance_grade, unbalance_g_mm).py_err()?;
    let off = offsets_arg(offsets)?;
    let s = py
        .detach(|| build(row_material, preload_n, effects, off, rotor))
        .py_err()?;
    let u = s.unbalance(spec).py_err()?;
    let pts = map_interruptible(py, &sp, None, progress, |&n| -> Result<VibrationPoint> {
        if time {
            Ok(s.time_vibration(n, duration_s, 0.0, &u, true)?.point)
        } else {
            Ok(s.steady_vibration(&[n], &u)?[0])
        }
    })?;
    let (pts, finished, failed) = super::errors::split_results(pts);
    let col = |f: &dyn Fn(&VibrationPoint) -> f64| pts.iter().map(f).collect::<Vec<_>>();
    let d = PyDict::new(py);
    d.set_item("speed_rpm", col(&|p| p.speed_rpm).into_pyarray(py))?;
    d.set_item("velocity_rms_mm_s", col(&|p| p.velocity_rms_mm_s).into_pyarray(py))?;
    d.set_item("velocity_peak_mm_s", col(&|p| p.velocity_peak_mm_s).into_pyarray(py))?;
    d.set_item("x1_mm_s", col(&|p| p.harmonics_mm_s[0]).into_pyarray(py))?;
    d.set_item("x2_mm_s", col(&|p| p.harmonics_mm_s[1]).into_pyarray(py))?;
    d.set_item("x3_mm_s", col(&|p| p.harmonics_mm_s[2]).into_pyarray(py))?;
    d.set_item("unbalance_g_mm", u.unbalance_kg_m * 1e6)?;
    if !failed.is_empty() {
        return Err(super::errors::partial_error(py, &sp, d.into_any(), finished, &failed));
    }
    Ok(d)
}

/// Spectrum of the nose velocity from a time response at one speed.
#[pyfunction]
#[pyo3(signature = (row_material, preload_n, speed_rpm, duration_s=0.2, nonlinear=true, unbalance_grade=None, unbalance_g_mm=None, effects=None, offsets=None, rotor=None))]
#[allow(clippy::too_many_arguments)]
fn rotor_spectrum<'py>(
    py: Python<'py>,
    row_material: &str,
    preload_n: f64,
    speed_rpm: f64,
    duration_s: f64,
    nonlinear: bool,
    unbalance_grade: Option<f64>,
    unbalance_g_mm: Option<f64>,
    effects: Option<Vec<String>>,
    offsets: Option<&Bound<'py, PyDict>>,
    rotor: Option<RotorArg>,
) -> PyResult<Bound<'py, PyDict>> {
    let spec = unbalance_spec(unbalance_grade, unbalance_g_mm).py_err()?;
    let off = offsets_arg(offsets)?;
    let (t, f, a, u) = watched(py, 1, None, |_, _| -> Result<_> {
        let s = build(row_material, preload_n, effects, off, rotor)?;
        let u = s.unbalance(spec)?;
        let t = s.time_vibration(speed_rpm, duration_s, 0.0, &u, nonlinear)?;
        let (f, a) = s.spectrum(&t)?;
        Ok((t, f, a, u))
    })?
    .py_err()?;
    let d = PyDict::new(py);
    d.set_item("frequency_hz", f.into_pyarray(py))?;
    d.set_item("velocity_mm_s", a.into_pyarray(py))?;
    d.set_item("time_s", t.history.time_s.into_pyarray(py))?;
    d.set_item(
        "velocity_x_mm_s",
        t.history
            .velocity_x_m_per_s
            .iter()
            .map(|v| v * 1e3)
            .collect::<Vec<_>>()
            .into_pyarray(py),
    )?;
    d.set_item("x1_mm_s", t.point.harmonics_mm_s[0])?;
    d.set_item("x2_mm_s", t.point.harmonics_mm_s[1])?;
    d.set_item("x3_mm_s", t.point.harmonics_mm_s[2])?;
    d.set_item("velocity_rms_mm_s", t.point.velocity_rms_mm_s)?;
    d.set_item("velocity_peak_mm_s", t.point.velocity_peak_mm_s)?;
    d.set_item("unbalance_g_mm", u.unbalance_kg_m * 1e6)?;
    Ok(d)
}

/// Name of the unbalanced-magnetic-pull effect (for the Python defaults).
#[pyfunction]
fn rotor_default_effects() -> Vec<&'static str> {
    EffectSet::all().without(Effect::UnbalancedMagneticPull).names()
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(rotor_campbell, m)?)?;
    m.add_function(wrap_pyfunction!(rotor_critical_speeds, m)?)?;
    m.add_function(wrap_pyfunction!(rotor_vibration, m)?)?;
    m.add_function(wrap_pyfunction!(rotor_spectrum, m)?)?;
    m.add_function(wrap_pyfunction!(rotor_default_effects, m)?)?;
    Ok(())
}
