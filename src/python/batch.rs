//! Batch entry points: many operating points in one call, rayon inside,
//! the GIL released, Ctrl-C and the progress callback checked every 20 ms
//! while the threads work (see `parallel.rs`), one row per point.
//!
//! A point that fails (bad input, no convergence, thermal runaway) does not
//! raise: its row carries `ok = False`, the Python exception name in
//! `error_kind` and the message in `error`; its numeric outputs are NaN and
//! the Python side turns them into nulls (never a silent NaN).

use numpy::{IntoPyArray, PyReadonlyArray1};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::bearing::PyBearing;
use super::errors::IntoPy;
use super::parallel::map_interruptible;
use super::solve::{load_vector, solve_options, tilt_option};
use crate::bearing::batch::{solve_point, OperatingPoint, PointSummary};
use crate::bearing::BearingModel;
use crate::error::{Error, Result};
use crate::thermal::coupled::{CoupledBearing, ThermalState};

/// The Python exception class a core error becomes (see `errors.rs`).
pub fn error_kind(e: &Error) -> &'static str {
    match e {
        Error::Config { .. } | Error::Parse(_) => "ConfigError",
        Error::Convergence { .. } => "ConvergenceError",
        Error::ThermalRunaway(_) => "ThermalRunawayError",
        Error::Data(_) => "DataError",
        Error::Interrupted => "KeyboardInterrupt",
    }
}

/// One contiguous f64 column per name, read from numpy arrays of one length.
fn columns<const N: usize>(arrays: [(&str, &PyReadonlyArray1<'_, f64>); N]) -> PyResult<[Vec<f64>; N]> {
    let n = arrays[0].1.len()?;
    for (name, a) in &arrays {
        if a.len()? != n {
            return Err(Error::config(
                *name,
                format!("an array of {} values", a.len()?),
                format!("must have the length of {} ({n})", arrays[0].0),
            ))
            .py_err();
        }
    }
    let mut out: [Vec<f64>; N] = std::array::from_fn(|_| Vec::new());
    for (slot, (_, a)) in out.iter_mut().zip(arrays.iter()) {
        *slot = a.as_array().iter().copied().collect();
    }
    Ok(out)
}

/// Set `ok`, `error_kind` and `error` from per-point results.
fn error_columns<T>(d: &Bound<'_, PyDict>, results: &[Result<T>]) -> PyResult<()> {
    let py = d.py();
    d.set_item(
        "ok",
        results.iter().map(|r| r.is_ok()).collect::<Vec<_>>().into_pyarray(py),
    )?;
    d.set_item(
        "error_kind",
        results
            .iter()
            .map(|r| r.as_ref().err().map(error_kind))
            .collect::<Vec<_>>(),
    )?;
    d.set_item(
        "error",
        results
            .iter()
            .map(|r| r.as_ref().err().map(|e| e.to_string()))
            .collect::<Vec<_>>(),
    )?;
    Ok(())
}

/// The [`PointSummary`] columns (units in the names; NaN or 0 where a point failed).
fn summary_columns(d: &Bound<'_, PyDict>, rows: &[Option<&PointSummary>]) -> PyResult<()> {
    let py = d.py();
    let col = |f: &dyn Fn(&PointSummary) -> f64| -> Vec<f64> { rows.iter().map(|r| r.map_or(f64::NAN, f)).collect() };
    let deg = |r: f64| r.to_degrees();
    let set = |key: &str, v: Vec<f64>| d.set_item(key, v.into_pyarray(py));
    set("axial_stiffness_n_per_m", col(&|s| s.axial_stiffness_seed_n_per_m))?;
    set("radial_stiffness_n_per_m", col(&|s| s.radial_stiffness_seed_n_per_m))?;
    set("k_xx_n_per_m", col(&|s| s.stiffness_diagonal[0]))?;
    set("k_zz_n_per_m", col(&|s| s.stiffness_diagonal[2]))?;
    set("k_ryry_nm_per_rad", col(&|s| s.stiffness_diagonal[4]))?;
    set("axial_displacement_um", col(&|s| s.axial_displacement_m * 1e6))?;
    set("radial_displacement_um", col(&|s| s.radial_displacement_m * 1e6))?;
    set("tilt_rad", col(&|s| s.tilt_rad))?;
    set(
        "inner_contact_angle_max_deg",
        col(&|s| deg(s.inner_contact_angle_range_rad.0)),
    )?;
    set(
        "inner_contact_angle_min_deg",
        col(&|s| deg(s.inner_contact_angle_range_rad.1)),
    )?;
    set(
        "outer_contact_angle_max_deg",
        col(&|s| deg(s.outer_contact_angle_range_rad.0)),
    )?;
    set(
        "outer_contact_angle_min_deg",
        col(&|s| deg(s.outer_contact_angle_range_rad.1)),
    )?;
    set("inner_load_max_n", col(&|s| s.inner_load_max_n))?;
    set("outer_load_max_n", col(&|s| s.outer_load_max_n))?;
    set("centrifugal_force_n", col(&|s| s.centrifugal_force_n))?;
    set(
        "cage_speed_rpm",
        col(&|s| s.cage_speed_rad_s * 30.0 / std::f64::consts::PI),
    )?;
    set("residual", col(&|s| s.residual))?;
    d.set_item(
        "iterations",
        rows.iter()
            .map(|r| r.map_or(0, |s| s.iterations as i64))
            .collect::<Vec<_>>()
            .into_pyarray(py),
    )?;
    Ok(())
}

/// Solve many operating points of one bearing (see `Bearing.solve_many`):
/// arrays of one length, options shared; one row per point.
#[pyfunction]
#[pyo3(signature = (bearing, axial_n, radial_n, moment_n_m, speed_rpm, effects=None, raceway_control="outer", misalignment_rad=Some(0.0), threads=None, progress=None))]
#[allow(clippy::too_many_arguments)]
pub fn solve_many<'py>(
    py: Python<'py>,
    bearing: &PyBearing,
    axial_n: PyReadonlyArray1<'py, f64>,
    radial_n: PyReadonlyArray1<'py, f64>,
    moment_n_m: PyReadonlyArray1<'py, f64>,
    speed_rpm: PyReadonlyArray1<'py, f64>,
    effects: Option<Vec<String>>,
    raceway_control: &str,
    misalignment_rad: Option<f64>,
    threads: Option<usize>,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let [fa, fr, m, n] = columns([
        ("axial_n", &axial_n),
        ("radial_n", &radial_n),
        ("moment_n_m", &moment_n_m),
        ("speed_rpm", &speed_rpm),
    ])?;
    let base = solve_options(effects, raceway_control).py_err()?;
    let model = BearingModel::new(&bearing.inner).py_err()?;
    let points: Vec<Result<OperatingPoint>> = (0..fa.len())
        .map(|i| {
            Ok(OperatingPoint {
                load: load_vector(fa[i], fr[i], m[i])?,
                speed_rpm: n[i],
                options: crate::bearing::SolveOptions {
                    tilt: tilt_option(misalignment_rad, m[i])?,
                    ..base
                },
            })
        })
        .collect();
    let results = map_interruptible(py, &points, threads, progress.as_ref(), |p| {
        let p = p.as_ref().map_err(Clone::clone)?;
        solve_point(&model, p).map(|s| PointSummary::from(&s))
    })?;
    let d = PyDict::new(py);
    let rows: Vec<Option<&PointSummary>> = results.iter().map(|r| r.as_ref().ok()).collect();
    summary_columns(&d, &rows)?;
    error_columns(&d, &results)?;
    Ok(d)
}

/// The scalar outputs of a coupled thermal state that a results table keeps.
pub struct ThermalSummary {
    bearing: PointSummary,
    /// Shaft, inner ring, balls, outer ring, housing \[C\].
    temperatures_c: [f64; 5],
    oil_temperature_c: f64,
    viscosity_cst: f64,
    heat_w: f64,
    load_heat_w: f64,
    viscous_heat_w: f64,
    churning_w: f64,
    breakdown: crate::thermal::friction::HeatBreakdown,
    cavity_oil_fraction: f64,
    radial_thermal_offset_m: f64,
    axial_thermal_offset_m: f64,
    ball_growth_m: f64,
    centrifugal_expansion_m: f64,
    iterations: usize,
    residual_k: f64,
}

/// Node names of the seed A network read into `temperatures_c`, in order.
const THERMAL_NODES: [(&str, &str); 5] = [
    ("shaft_temperature_c", "Ts"),
    ("inner_ring_temperature_c", "Ti"),
    ("ball_temperature_c", "Tb"),
    ("outer_ring_temperature_c", "To"),
    ("housing_temperature_c", "Th"),
];

/// Solve one coupled point and keep its summary.
pub fn thermal_point(c: &CoupledBearing, speed_rpm: f64, axial_n: f64, radial_n: f64) -> Result<ThermalSummary> {
    let s: ThermalState = c.solve(speed_rpm, axial_n, radial_n)?;
    let mut t = [0.0; 5];
    for (slot, (_, node)) in t.iter_mut().zip(THERMAL_NODES) {
        *slot = s.temperature_c(node)?;
    }
    let h = &s.heat;
    Ok(ThermalSummary {
        bearing: PointSummary::from(&s.bearing),
        temperatures_c: t,
        oil_temperature_c: h.oil_temperature_c,
        viscosity_cst: h.viscosity_cst,
        heat_w: h.heat.total_w(),
        load_heat_w: h.load_w,
        viscous_heat_w: h.viscous_w,
        churning_w: h.churning_w,
        breakdown: h.breakdown,
        cavity_oil_fraction: h.cavity_oil_fraction,
        radial_thermal_offset_m: s.raceway_offsets.radial_m,
        axial_thermal_offset_m: s.raceway_offsets.axial_m,
        ball_growth_m: s.offsets.ball_diameter_growth_m,
        centrifugal_expansion_m: c.model().ring_expansion_m(crate::units::rpm_to_rad_s(s.speed_rpm)),
        iterations: s.iterations,
        residual_k: s.residual_k,
    })
}

/// Columns of many coupled points (one row per point, errors per row).
pub fn thermal_columns<'py>(py: Python<'py>, results: &[Result<ThermalSummary>]) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let rows: Vec<Option<&ThermalSummary>> = results.iter().map(|r| r.as_ref().ok()).collect();
    let bearing: Vec<Option<&PointSummary>> = rows.iter().map(|r| r.map(|t| &t.bearing)).collect();
    summary_columns(&d, &bearing)?;
    let col = |f: &dyn Fn(&ThermalSummary) -> f64| -> Vec<f64> { rows.iter().map(|r| r.map_or(f64::NAN, f)).collect() };
    let set = |key: &str, v: Vec<f64>| d.set_item(key, v.into_pyarray(py));
    for (i, (key, _)) in THERMAL_NODES.iter().enumerate() {
        set(key, col(&|t| t.temperatures_c[i]))?;
    }
    set("oil_temperature_c", col(&|t| t.oil_temperature_c))?;
    set("viscosity_cst", col(&|t| t.viscosity_cst))?;
    set("heat_w", col(&|t| t.heat_w))?;
    set("load_heat_w", col(&|t| t.load_heat_w))?;
    set("viscous_heat_w", col(&|t| t.viscous_heat_w))?;
    set("churning_w", col(&|t| t.churning_w))?;
    // The heat split (rolling, sliding, spin, drag, churning, seal, extra).
    let zero = crate::thermal::friction::HeatBreakdown::default();
    for (j, (key, _)) in super::thermal::breakdown_columns(&zero).iter().enumerate() {
        set(key, col(&|t| super::thermal::breakdown_columns(&t.breakdown)[j].1))?;
    }
    set("cavity_oil_fraction", col(&|t| t.cavity_oil_fraction))?;
    set("radial_thermal_offset_um", col(&|t| t.radial_thermal_offset_m * 1e6))?;
    set("axial_thermal_offset_um", col(&|t| t.axial_thermal_offset_m * 1e6))?;
    set("ball_growth_um", col(&|t| t.ball_growth_m * 1e6))?;
    set("centrifugal_expansion_um", col(&|t| t.centrifugal_expansion_m * 1e6))?;
    set("thermal_residual_k", col(&|t| t.residual_k))?;
    d.set_item(
        "thermal_iterations",
        rows.iter()
            .map(|r| r.map_or(0, |t| t.iterations as i64))
            .collect::<Vec<_>>()
            .into_pyarray(py),
    )?;
    error_columns(&d, results)?;
    Ok(d)
}

/// Coupled points `(speed_rpm, axial_n, radial_n)` of one coupled bearing,
/// in chunks with the GIL released (the binding of `thermal_state_many`).
pub fn thermal_many<'py>(
    py: Python<'py>,
    c: &CoupledBearing,
    arrays: [&PyReadonlyArray1<'py, f64>; 3],
    threads: Option<usize>,
    progress: Option<&Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let [n, fa, fr] = columns([
        ("speed_rpm", arrays[0]),
        ("axial_n", arrays[1]),
        ("radial_n", arrays[2]),
    ])?;
    let idx: Vec<usize> = (0..n.len()).collect();
    let results = map_interruptible(py, &idx, threads, progress, |&i| thermal_point(c, n[i], fa[i], fr[i]))?;
    thermal_columns(py, &results)
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(solve_many, m)?)?;
    Ok(())
}
