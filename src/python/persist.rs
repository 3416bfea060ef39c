//! Pickling of the native classes through the versioned serde envelope of
//! [`crate::persist`].
//!
//! `__reduce__` of each class returns `(_restore, (state,))`, `state` a dict
//! `{"format": "thermobear", "version": 1, "kind": <class>, "data": <serde
//! JSON text>}`. `_restore` checks format, version and kind (ConfigError
//! naming the field and value) and rebuilds the object through its validated
//! constructor, so results are bit-identical.

use pyo3::prelude::*;
use pyo3::types::PyDict;
use serde::{Deserialize, Serialize};

use super::bearing::{PyBearing, PyMaterial};
use super::errors::IntoPy;
use super::gear::{PyGearPair, PyGearSystem};
use super::spindle::PySpindle;
use crate::bearing::Bearing;
use crate::error::Error;
use crate::gear::{GearPair, GearPairSpec, TypoWarning};
use crate::materials::Material;
use crate::persist::Envelope;
use crate::spindle::{Spindle, SpindleConfig};

/// What `__reduce__` returns: the restoring function and its argument.
pub type Reduced = (Py<PyAny>, (Py<PyDict>,));

/// Serialised data of a gear pair: its spec and the table warnings.
#[derive(Serialize, Deserialize)]
struct GearPairState {
    spec: GearPairSpec,
    warnings: Vec<TypoWarning>,
}

/// Serialised data of a spindle: its name and configuration.
#[derive(Serialize, Deserialize)]
struct SpindleState {
    name: String,
    config: SpindleConfig,
}

/// Serialised data of a gear system: what its constructor consumed (SI).
#[derive(Serialize, Deserialize)]
pub struct GearSystemState {
    /// Gear pair spec with the system torque.
    pub spec: GearPairSpec,
    /// Half backlash \[m\].
    pub half_backlash_m: f64,
    /// Mesh damping ratio.
    pub mesh_damping_ratio: f64,
    /// "in-contact" or "always".
    pub mesh_damping: String,
    /// Bearing damping ratio.
    pub bearing_damping_ratio: f64,
    /// Transmission error amplitude \[m\].
    pub te_amplitude_m: f64,
    /// Mesh stiffness table points.
    pub table_points: usize,
    /// Factor on the mesh stiffness table (1 in states saved before it existed).
    #[serde(default = "unit_scale")]
    pub mesh_stiffness_scale: f64,
    /// (speed_rpm, kr, ka) support schedule.
    pub schedule: Vec<(f64, f64, f64)>,
    /// "potential-energy", "iso" or "table".
    pub mesh_model: String,
    /// User mesh stiffness table (normal direction) \[N/m\], if given.
    #[serde(default)]
    pub mesh_stiffness_n_per_m: Option<Vec<f64>>,
    /// User transmission error table \[m\], if given.
    #[serde(default)]
    pub transmission_error_m: Option<Vec<f64>>,
}

fn unit_scale() -> f64 {
    1.0
}

fn to_dict<'py>(py: Python<'py>, env: &Envelope) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("format", &env.format)?;
    d.set_item("version", env.version)?;
    d.set_item("kind", &env.kind)?;
    d.set_item("data", &env.data)?;
    Ok(d)
}

fn field<'py, T: FromPyObjectOwned<'py>>(d: &Bound<'py, PyDict>, name: &str) -> PyResult<T> {
    let v = d
        .get_item(name)?
        .ok_or_else(|| Error::config(name, "missing", "serialised state has no such field"))
        .py_err()?;
    v.extract::<T>()
        .map_err(|_| Error::config(name, v.repr().map(|r| r.to_string()).unwrap_or_default(), "wrong type"))
        .py_err()
}

fn from_dict(state: &Bound<'_, PyAny>) -> PyResult<Envelope> {
    let d = state
        .cast::<PyDict>()
        .map_err(|_| Error::config("state", state.get_type().to_string(), "must be a dict"))
        .py_err()?;
    let format: String = field(d, "format")?;
    let version: i64 = field(d, "version")?;
    let env = Envelope {
        format,
        version: u32::try_from(version)
            .map_err(|_| Error::config("version", version, "unsupported serialisation version"))
            .py_err()?,
        kind: field(d, "kind")?,
        data: field(d, "data")?,
    };
    env.check().py_err()?;
    Ok(env)
}

/// `(_restore, (envelope,))` of `value` serialised as `kind`.
pub fn reduce<T: Serialize>(py: Python<'_>, kind: &str, value: &T) -> PyResult<Reduced> {
    let env = Envelope::wrap(kind, value).py_err()?;
    let restore = py.import("thermobear._native")?.getattr("_restore")?.unbind();
    Ok((restore, (to_dict(py, &env)?.unbind(),)))
}

/// `__reduce__` of a gear pair.
pub fn reduce_gear_pair(py: Python<'_>, g: &PyGearPair) -> PyResult<Reduced> {
    let s = GearPairState {
        spec: g.inner.spec.clone(),
        warnings: g.warnings.clone(),
    };
    reduce(py, "GearPair", &s)
}

/// `__reduce__` of a spindle.
pub fn reduce_spindle(py: Python<'_>, s: &PySpindle) -> PyResult<Reduced> {
    let st = SpindleState {
        name: s.name.clone(),
        config: s.inner.config.clone(),
    };
    reduce(py, "Spindle", &st)
}

/// Rebuild a native object from its serialised state (the dict of
/// `__reduce__`). Unknown format, version or kind: ConfigError.
#[pyfunction]
fn _restore(py: Python<'_>, state: &Bound<'_, PyAny>) -> PyResult<Py<PyAny>> {
    let env = from_dict(state)?;
    let obj: Py<PyAny> = match env.kind.as_str() {
        "Material" => {
            let m: Material = env.open("Material").py_err()?;
            m.validate().py_err()?;
            Py::new(py, PyMaterial { inner: m })?.into_any()
        }
        "Bearing" => {
            let b: Bearing = env.open("Bearing").py_err()?;
            b.validate().py_err()?;
            Py::new(py, PyBearing { inner: b })?.into_any()
        }
        "GearPair" => {
            let s: GearPairState = env.open("GearPair").py_err()?;
            let inner = GearPair::new(s.spec).py_err()?;
            Py::new(
                py,
                PyGearPair {
                    inner,
                    warnings: s.warnings,
                },
            )?
            .into_any()
        }
        "Spindle" => {
            let s: SpindleState = env.open("Spindle").py_err()?;
            let inner = py.detach(|| Spindle::new(s.config)).py_err()?;
            Py::new(py, PySpindle { inner, name: s.name })?.into_any()
        }
        "GearSystem" => {
            let s: GearSystemState = env.open("GearSystem").py_err()?;
            Py::new(py, PyGearSystem::restore(py, s)?)?.into_any()
        }
        other => {
            return Err(Error::config(
                "kind",
                other,
                "unknown kind; known: Material, Bearing, GearPair, Spindle, GearSystem",
            ))
            .py_err()
        }
    };
    Ok(obj)
}

/// Register `_restore` (under the module name pickle imports).
pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(_restore, m)?)?;
    m.getattr("_restore")?.setattr("__module__", "thermobear._native")?;
    Ok(())
}
