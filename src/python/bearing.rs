//! Bindings for materials, bearings and system descriptions.

use std::collections::{BTreeMap, HashMap};

use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::errors::IntoPy;
use crate::bearing::{Bearing, BearingGeometry};
use crate::config::SystemConfig;
use crate::effects::Effect;
use crate::error::Error;
use crate::materials::Material;

/// A material (SI inside; constructor and getters carry units in their names).
#[pyclass(name = "Material", module = "thermobear._native", frozen)]
#[derive(Clone)]
pub struct PyMaterial {
    pub inner: Material,
}

#[pymethods]
impl PyMaterial {
    #[new]
    #[pyo3(signature = (name, youngs_modulus_gpa, poisson_ratio, density_kg_m3, thermal_expansion_per_k, conductivity_w_mk, specific_heat_j_kgk))]
    fn new(
        name: String,
        youngs_modulus_gpa: f64,
        poisson_ratio: f64,
        density_kg_m3: f64,
        thermal_expansion_per_k: f64,
        conductivity_w_mk: f64,
        specific_heat_j_kgk: f64,
    ) -> PyResult<Self> {
        let m = Material {
            name,
            youngs_modulus_pa: youngs_modulus_gpa * 1e9,
            poisson_ratio,
            density_kg_m3,
            thermal_expansion_per_k,
            conductivity_w_mk,
            specific_heat_j_kgk,
        };
        m.validate().py_err()?;
        Ok(PyMaterial { inner: m })
    }

    #[staticmethod]
    fn preset(name: &str) -> PyResult<Self> {
        Ok(PyMaterial {
            inner: Material::preset(name).py_err()?,
        })
    }

    #[staticmethod]
    fn preset_names() -> Vec<&'static str> {
        Material::PRESETS.to_vec()
    }

    #[getter]
    fn name(&self) -> &str {
        &self.inner.name
    }
    #[getter]
    fn youngs_modulus_gpa(&self) -> f64 {
        self.inner.youngs_modulus_pa / 1e9
    }
    #[getter]
    fn poisson_ratio(&self) -> f64 {
        self.inner.poisson_ratio
    }
    #[getter]
    fn density_kg_m3(&self) -> f64 {
        self.inner.density_kg_m3
    }
    #[getter]
    fn thermal_expansion_per_k(&self) -> f64 {
        self.inner.thermal_expansion_per_k
    }
    #[getter]
    fn conductivity_w_mk(&self) -> f64 {
        self.inner.conductivity_w_mk
    }
    #[getter]
    fn specific_heat_j_kgk(&self) -> f64 {
        self.inner.specific_heat_j_kgk
    }

    /// Pickle support: the versioned serde envelope (see `_restore`).
    fn __reduce__(&self, py: Python<'_>) -> PyResult<super::persist::Reduced> {
        super::persist::reduce(py, "Material", &self.inner)
    }

    fn __repr__(&self) -> String {
        let m = &self.inner;
        format!(
            "Material(name={:?}, youngs_modulus_gpa={}, poisson_ratio={}, density_kg_m3={}, thermal_expansion_per_k={:e}, conductivity_w_mk={}, specific_heat_j_kgk={})",
            m.name,
            m.youngs_modulus_pa / 1e9,
            m.poisson_ratio,
            m.density_kg_m3,
            m.thermal_expansion_per_k,
            m.conductivity_w_mk,
            m.specific_heat_j_kgk
        )
    }
}

/// A ball bearing.
#[pyclass(name = "Bearing", module = "thermobear._native", frozen)]
#[derive(Clone)]
pub struct PyBearing {
    pub inner: Bearing,
}

fn material_or(m: Option<PyMaterial>, default: Material) -> Material {
    m.map(|m| m.inner).unwrap_or(default)
}

/// A bearing from checked geometry and optional materials (52100 default).
fn finish(
    name: Option<String>,
    default_name: &str,
    g: BearingGeometry,
    ring_material: Option<PyMaterial>,
    ball_material: Option<PyMaterial>,
) -> PyResult<PyBearing> {
    let b = Bearing::new(
        name.unwrap_or_else(|| default_name.into()),
        g,
        material_or(ring_material, Material::steel_52100()),
        material_or(ball_material, Material::steel_52100()),
    )
    .py_err()?;
    Ok(PyBearing { inner: b })
}

#[pymethods]
impl PyBearing {
    /// A built-in bearing: 6208, 7008C, 7009C, each also -hybrid and -ceramic.
    #[staticmethod]
    fn preset(name: &str) -> PyResult<Self> {
        Ok(PyBearing {
            inner: Bearing::preset(name).py_err()?,
        })
    }

    #[staticmethod]
    fn preset_names() -> Vec<&'static str> {
        crate::bearing::presets::PRESETS.to_vec()
    }

    #[staticmethod]
    #[pyo3(signature = (ball_count, ball_diameter_mm, pitch_diameter_mm, inner_conformity, outer_conformity, diametral_clearance_mm, bore_mm, outer_diameter_mm, width_mm, ring_material=None, ball_material=None, name=None))]
    #[allow(clippy::too_many_arguments)]
    fn deep_groove(
        ball_count: i64,
        ball_diameter_mm: f64,
        pitch_diameter_mm: f64,
        inner_conformity: f64,
        outer_conformity: f64,
        diametral_clearance_mm: f64,
        bore_mm: f64,
        outer_diameter_mm: f64,
        width_mm: f64,
        ring_material: Option<PyMaterial>,
        ball_material: Option<PyMaterial>,
        name: Option<String>,
    ) -> PyResult<Self> {
        let z = ball_count_usize(ball_count)?;
        let mm = 1e-3;
        let g = BearingGeometry::deep_groove(
            z,
            ball_diameter_mm * mm,
            pitch_diameter_mm * mm,
            inner_conformity,
            outer_conformity,
            diametral_clearance_mm * mm,
            bore_mm * mm,
            outer_diameter_mm * mm,
            width_mm * mm,
        )
        .py_err()?;
        finish(name, "deep-groove", g, ring_material, ball_material)
    }

    #[staticmethod]
    #[pyo3(signature = (ball_count, ball_diameter_mm, pitch_diameter_mm, inner_conformity, outer_conformity, free_contact_angle_deg, bore_mm, outer_diameter_mm, width_mm, ring_material=None, ball_material=None, name=None))]
    #[allow(clippy::too_many_arguments)]
    fn angular_contact(
        ball_count: i64,
        ball_diameter_mm: f64,
        pitch_diameter_mm: f64,
        inner_conformity: f64,
        outer_conformity: f64,
        free_contact_angle_deg: f64,
        bore_mm: f64,
        outer_diameter_mm: f64,
        width_mm: f64,
        ring_material: Option<PyMaterial>,
        ball_material: Option<PyMaterial>,
        name: Option<String>,
    ) -> PyResult<Self> {
        let z = ball_count_usize(ball_count)?;
        let mm = 1e-3;
        let g = BearingGeometry::angular_contact(
            z,
            ball_diameter_mm * mm,
            pitch_diameter_mm * mm,
            inner_conformity,
            outer_conformity,
            free_contact_angle_deg.to_radians(),
            bore_mm * mm,
            outer_diameter_mm * mm,
            width_mm * mm,
        )
        .py_err()?;
        finish(name, "angular-contact", g, ring_material, ball_material)
    }

    /// The bearing of a system description (TOML text); `catalogue`:
    /// bearings its `[bearing] preset` may name beyond the built-in presets
    /// (name as written -> bearing).
    #[staticmethod]
    #[pyo3(signature = (text, catalogue=None))]
    fn from_toml(text: &str, catalogue: Option<HashMap<String, PyRef<'_, PyBearing>>>) -> PyResult<Self> {
        let sys = with_catalogue(SystemConfig::from_toml(text).py_err()?, catalogue);
        Ok(PyBearing {
            inner: sys.bearing().py_err()?,
        })
    }

    #[getter]
    fn name(&self) -> &str {
        &self.inner.name
    }

    #[getter]
    fn material_class(&self) -> &'static str {
        self.inner.material_class()
    }

    #[getter]
    fn ring_material(&self) -> PyMaterial {
        PyMaterial {
            inner: self.inner.inner_ring.clone(),
        }
    }

    #[getter]
    fn ball_material(&self) -> PyMaterial {
        PyMaterial {
            inner: self.inner.ball.clone(),
        }
    }

    /// Geometry in engineering units (mm, deg).
    fn geometry(&self) -> BTreeMap<&'static str, f64> {
        let g = &self.inner.geometry;
        let mm = 1e3;
        BTreeMap::from([
            ("ball_count", g.ball_count as f64),
            ("ball_diameter_mm", g.ball_diameter_m * mm),
            ("pitch_diameter_mm", g.pitch_diameter_m * mm),
            ("inner_conformity", g.inner_conformity),
            ("outer_conformity", g.outer_conformity),
            ("diametral_clearance_mm", g.diametral_clearance_m * mm),
            ("free_contact_angle_deg", g.free_contact_angle_rad.to_degrees()),
            ("bore_mm", g.bore_m * mm),
            ("outer_diameter_mm", g.outer_diameter_m * mm),
            ("width_mm", g.width_m * mm),
            ("ball_mass_g", self.inner.ball_mass_kg() * 1e3),
        ])
    }

    #[getter]
    fn bearing_type(&self) -> &'static str {
        self.inner.geometry.bearing_type.name()
    }

    /// Hertz contact data of a ball on the "inner" or "outer" raceway at a
    /// contact angle, SI, for a load `load_n`.
    #[pyo3(signature = (raceway, contact_angle_deg, load_n=1000.0, exact=true))]
    fn contact<'py>(
        &self,
        py: Python<'py>,
        raceway: &str,
        contact_angle_deg: f64,
        load_n: f64,
        exact: bool,
    ) -> PyResult<Bound<'py, PyDict>> {
        crate::error::finite("contact_angle_deg", contact_angle_deg).py_err()?;
        crate::error::non_negative("load_n", load_n).py_err()?;
        let a = contact_angle_deg.to_radians();
        let c = match raceway {
            "inner" => self.inner.inner_contact(a),
            "outer" => self.inner.outer_contact(a),
            other => Err(Error::config("raceway", other, "must be \"inner\" or \"outer\"")),
        }
        .py_err()?;
        let c = if exact {
            c
        } else {
            crate::bearing::HertzContact::approximate(c.curvature, c.reduced_modulus_pa)
        };
        let d = PyDict::new(py);
        d.set_item("curvature_sum_per_m", c.curvature.sum)?;
        d.set_item("curvature_difference", c.curvature.difference)?;
        d.set_item("ellipticity", c.ellipse.kappa)?;
        d.set_item("elliptic_k", c.ellipse.k_first)?;
        d.set_item("elliptic_e", c.ellipse.e_second)?;
        d.set_item("reduced_modulus_pa", c.reduced_modulus_pa)?;
        d.set_item("load_deflection_constant_n_per_m1_5", c.k_load_deflection)?;
        d.set_item("deflection_m", c.deflection(load_n))?;
        d.set_item("contact_stiffness_n_per_m", c.stiffness(load_n))?;
        d.set_item("semi_major_m", c.semi_major(load_n))?;
        d.set_item("semi_minor_m", c.semi_minor(load_n))?;
        d.set_item("max_pressure_pa", c.max_pressure(load_n))?;
        Ok(d)
    }

    /// Solve one operating point; see `thermobear.Bearing.solve`.
    #[pyo3(signature = (axial_n, radial_n, moment_n_m, speed_rpm, effects=None, raceway_control="outer", misalignment_rad=Some(0.0)))]
    #[allow(clippy::too_many_arguments)]
    fn solve<'py>(
        &self,
        py: Python<'py>,
        axial_n: f64,
        radial_n: f64,
        moment_n_m: f64,
        speed_rpm: f64,
        effects: Option<Vec<String>>,
        raceway_control: &str,
        misalignment_rad: Option<f64>,
    ) -> PyResult<Bound<'py, PyDict>> {
        super::solve::solve_point(
            py,
            &self.inner,
            axial_n,
            radial_n,
            moment_n_m,
            speed_rpm,
            effects,
            raceway_control,
            misalignment_rad,
        )
    }

    /// Forces of the balls on the inner ring at a prescribed displacement.
    #[pyo3(signature = (displacement, speed_rpm, effects=None, raceway_control="outer"))]
    fn ring_forces<'py>(
        &self,
        py: Python<'py>,
        displacement: [f64; 5],
        speed_rpm: f64,
        effects: Option<Vec<String>>,
        raceway_control: &str,
    ) -> PyResult<Bound<'py, PyDict>> {
        super::solve::ring_forces_point(py, &self.inner, displacement, speed_rpm, effects, raceway_control)
    }

    /// Pickle support: the versioned serde envelope (see `_restore`).
    fn __reduce__(&self, py: Python<'_>) -> PyResult<super::persist::Reduced> {
        super::persist::reduce(py, "Bearing", &self.inner)
    }

    fn __repr__(&self) -> String {
        format!(
            "Bearing({:?}, {}, {})",
            self.inner.name,
            self.bearing_type(),
            self.inner.material_class()
        )
    }
}

fn ball_count_usize(z: i64) -> PyResult<usize> {
    if z < 3 {
        return Err(Error::config("ball_count", z, "must lie in [3, 200]")).py_err();
    }
    Ok(z as usize)
}

/// The effects registry: (name, description, models it acts in) triples.
#[pyfunction]
pub fn effects() -> Vec<(&'static str, &'static str, Vec<&'static str>)> {
    Effect::ALL
        .iter()
        .map(|e| (e.name(), e.description(), e.models().to_vec()))
        .collect()
}

/// `sys` with the caller's catalogue bearings (none: as it is).
fn with_catalogue(sys: SystemConfig, catalogue: Option<HashMap<String, PyRef<'_, PyBearing>>>) -> SystemConfig {
    match catalogue {
        Some(c) => sys.with_catalogue(c.into_iter().map(|(k, b)| (k, b.inner.clone())).collect()),
        None => sys,
    }
}

/// Check a TOML system description; returns the section names present.
/// `catalogue` as for `Bearing.from_toml`.
#[pyfunction]
#[pyo3(signature = (text, catalogue=None))]
pub fn check_config(text: &str, catalogue: Option<HashMap<String, PyRef<'_, PyBearing>>>) -> PyResult<Vec<String>> {
    let sys = with_catalogue(SystemConfig::from_toml(text).py_err()?, catalogue);
    let mut s = Vec::new();
    if sys.bearing.is_some() {
        sys.bearing().py_err()?;
        s.push("bearing".to_string());
    }
    if sys.model.is_some() {
        sys.solve_options().py_err()?;
        s.push("model".into());
    }
    if sys.sweep.is_some() {
        sys.speeds_rpm().py_err()?;
        s.push("sweep".into());
    }
    if sys.operating.is_some() {
        s.push("operating".into());
    }
    Ok(s)
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PyMaterial>()?;
    m.add_class::<PyBearing>()?;
    m.add_function(wrap_pyfunction!(effects, m)?)?;
    m.add_function(wrap_pyfunction!(check_config, m)?)?;
    Ok(())
}
