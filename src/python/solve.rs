//! Bindings for the bearing solvers: one operating point, and stiffness
//! against speed in parallel (GIL released, Ctrl-C between chunks).

use numpy::{IntoPyArray, PyArray2, PyReadonlyArray1};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::bearing::PyBearing;
use super::errors::IntoPy;
use super::parallel::map_interruptible;
use crate::bearing::quasi_static::{static_start_q, WarmStart};
use crate::bearing::state::Tilt;
use crate::bearing::{BearingModel, BearingState, RacewayControl, SolveOptions};
use crate::effects::EffectSet;
use crate::error::{finite, non_negative, Error, Result};

/// Options from Python arguments.
pub fn solve_options(effects: Option<Vec<String>>, raceway_control: &str) -> Result<SolveOptions> {
    let mut o = SolveOptions::default();
    if let Some(names) = effects {
        o.effects = EffectSet::from_names(&names)?;
    }
    o.raceway_control = RacewayControl::from_name(raceway_control)?;
    Ok(o)
}

/// [Fx, Fy, Fz, Mx, My] (N, N m) from the Python load arguments; the radial
/// force acts along x and the tilting moment about y.
pub fn load_vector(axial_n: f64, radial_n: f64, moment_n_m: f64) -> Result<[f64; 5]> {
    finite("axial_n", axial_n)?;
    finite("radial_n", radial_n)?;
    finite("moment_n_m", moment_n_m)?;
    Ok([radial_n, 0.0, axial_n, 0.0, moment_n_m])
}

pub fn check_speed(speed_rpm: f64) -> Result<f64> {
    non_negative("speed_rpm", speed_rpm)
}

pub fn state_dict<'py>(py: Python<'py>, s: &BearingState) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("displacement", s.displacement.to_vec().into_pyarray(py))?;
    d.set_item("applied_load", s.applied_load.to_vec().into_pyarray(py))?;
    let k: Vec<Vec<f64>> = s.stiffness_matrix.iter().map(|r| r.to_vec()).collect();
    d.set_item("stiffness_matrix", PyArray2::from_vec2(py, &k)?)?;
    d.set_item("axial_stiffness_n_per_m", s.axial_stiffness_seed_n_per_m)?;
    d.set_item("radial_stiffness_n_per_m", s.radial_stiffness_seed_n_per_m)?;
    d.set_item("iterations", s.iterations)?;
    d.set_item("residual", s.residual)?;
    d.set_item("speed_rpm", s.speed_rpm)?;
    let b = PyDict::new(py);
    let col = |f: &dyn Fn(&crate::bearing::BallState) -> f64| -> Vec<f64> { s.balls.iter().map(f).collect() };
    let rpm = 30.0 / std::f64::consts::PI;
    b.set_item("ball", (0..s.balls.len() as i64).collect::<Vec<_>>().into_pyarray(py))?;
    b.set_item("azimuth_deg", col(&|x| x.azimuth_rad.to_degrees()).into_pyarray(py))?;
    b.set_item("inner_load_n", col(&|x| x.inner_load_n).into_pyarray(py))?;
    b.set_item("outer_load_n", col(&|x| x.outer_load_n).into_pyarray(py))?;
    b.set_item(
        "inner_contact_angle_deg",
        col(&|x| x.inner_contact_angle_rad.to_degrees()).into_pyarray(py),
    )?;
    b.set_item(
        "outer_contact_angle_deg",
        col(&|x| x.outer_contact_angle_rad.to_degrees()).into_pyarray(py),
    )?;
    b.set_item(
        "inner_deflection_um",
        col(&|x| x.inner_deflection_m * 1e6).into_pyarray(py),
    )?;
    b.set_item(
        "outer_deflection_um",
        col(&|x| x.outer_deflection_m * 1e6).into_pyarray(py),
    )?;
    b.set_item("centrifugal_force_n", col(&|x| x.centrifugal_force_n).into_pyarray(py))?;
    b.set_item(
        "gyroscopic_moment_n_m",
        col(&|x| x.gyroscopic_moment_n_m).into_pyarray(py),
    )?;
    b.set_item("orbit_speed_rpm", col(&|x| x.orbit_speed_rad_s * rpm).into_pyarray(py))?;
    b.set_item("spin_speed_rpm", col(&|x| x.spin_speed_rad_s * rpm).into_pyarray(py))?;
    b.set_item(
        "attitude_angle_deg",
        col(&|x| x.attitude_angle_rad.to_degrees()).into_pyarray(py),
    )?;
    b.set_item("inner_spin_to_roll", col(&|x| x.inner_spin_to_roll).into_pyarray(py))?;
    b.set_item("outer_spin_to_roll", col(&|x| x.outer_spin_to_roll).into_pyarray(py))?;
    b.set_item(
        "inner_semi_major_mm",
        col(&|x| x.inner_semi_major_m * 1e3).into_pyarray(py),
    )?;
    b.set_item(
        "outer_semi_major_mm",
        col(&|x| x.outer_semi_major_m * 1e3).into_pyarray(py),
    )?;
    d.set_item("balls", b)?;
    Ok(d)
}

/// Solve one operating point (static at speed 0, quasi-static above).
#[allow(clippy::too_many_arguments)]
pub fn solve_point<'py>(
    py: Python<'py>,
    bearing: &crate::bearing::Bearing,
    axial_n: f64,
    radial_n: f64,
    moment_n_m: f64,
    speed_rpm: f64,
    effects: Option<Vec<String>>,
    raceway_control: &str,
    misalignment_rad: Option<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    let load = load_vector(axial_n, radial_n, moment_n_m).py_err()?;
    let speed = check_speed(speed_rpm).py_err()?;
    let mut opts = solve_options(effects, raceway_control).py_err()?;
    opts.tilt = tilt_option(misalignment_rad, moment_n_m).py_err()?;
    solve_with(py, bearing, &load, speed, &opts)
}

/// The state dict of `bearing` under `load` at `speed` [rpm] (static at 0,
/// quasi-static above), solved with the GIL released.
pub fn solve_with<'py>(
    py: Python<'py>,
    bearing: &crate::bearing::Bearing,
    load: &[f64; 5],
    speed: f64,
    opts: &SolveOptions,
) -> PyResult<Bound<'py, PyDict>> {
    let s = py
        .detach(|| -> Result<BearingState> {
            let m = BearingModel::new(bearing)?;
            if speed == 0.0 {
                m.solve_static(load, opts)
            } else {
                m.solve(load, speed, opts)
            }
        })
        .py_err()?;
    state_dict(py, &s)
}

/// Tilt handling: held at `misalignment_rad` (ISO/TS 16281 practice, moment
/// is a reaction), or free (None) so the ring carries the moment (`moment_n_m`).
pub fn tilt_option(misalignment_rad: Option<f64>, moment_n_m: f64) -> Result<Tilt> {
    match misalignment_rad {
        None => Ok(Tilt::Free),
        Some(t) => {
            finite("misalignment_rad", t)?;
            if moment_n_m != 0.0 {
                return Err(Error::config(
                    "moment_n_m",
                    moment_n_m,
                    "a moment needs a free tilt: pass misalignment_rad=None (the tilt is then solved)",
                ));
            }
            Ok(Tilt::Fixed {
                theta_x_rad: 0.0,
                theta_y_rad: t,
            })
        }
    }
}

/// The forward map: forces of the balls on the inner ring for a prescribed
/// displacement [dx, dy, dz (m), theta_x, theta_y (rad)] at a speed.
pub fn ring_forces_point<'py>(
    py: Python<'py>,
    bearing: &crate::bearing::Bearing,
    displacement: [f64; 5],
    speed_rpm: f64,
    effects: Option<Vec<String>>,
    raceway_control: &str,
) -> PyResult<Bound<'py, PyDict>> {
    for (i, v) in displacement.iter().enumerate() {
        finite(&format!("displacement[{i}]"), *v).py_err()?;
    }
    let speed = check_speed(speed_rpm).py_err()?;
    let opts = solve_options(effects, raceway_control).py_err()?;
    let f = py
        .detach(|| -> Result<_> {
            let m = BearingModel::new(bearing)?;
            m.ring_forces(&displacement, speed, &opts, &mut WarmStart::new())
        })
        .py_err()?;
    let d = PyDict::new(py);
    d.set_item("reaction", f.reaction.to_vec().into_pyarray(py))?;
    let k: Vec<Vec<f64>> = f.stiffness_matrix.iter().map(|r| r.to_vec()).collect();
    d.set_item("stiffness_matrix", PyArray2::from_vec2(py, &k)?)?;
    Ok(d)
}

/// Stiffness and displacements against speed (see thermobear.stiffness_curve).
#[pyfunction]
#[pyo3(signature = (bearing, speeds_rpm, axial_n, radial_n, moment_n_m, effects=None, raceway_control="outer", misalignment_rad=Some(0.0), progress=None))]
#[allow(clippy::too_many_arguments)]
pub fn stiffness_curve<'py>(
    py: Python<'py>,
    bearing: &PyBearing,
    speeds_rpm: PyReadonlyArray1<'py, f64>,
    axial_n: f64,
    radial_n: f64,
    moment_n_m: f64,
    effects: Option<Vec<String>>,
    raceway_control: &str,
    misalignment_rad: Option<f64>,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let speeds = speeds_rpm.as_slice()?.to_vec();
    for &s in &speeds {
        check_speed(s).py_err()?;
    }
    let load = load_vector(axial_n, radial_n, moment_n_m).py_err()?;
    let mut opts = solve_options(effects, raceway_control).py_err()?;
    opts.tilt = tilt_option(misalignment_rad, moment_n_m).py_err()?;
    let model = BearingModel::new(&bearing.inner).py_err()?;
    let start = py.detach(|| static_start_q(&model, &load, &opts)).py_err()?;
    let static_state = py.detach(|| model.solve_static(&load, &opts)).py_err()?;
    let results = map_interruptible(py, &speeds, None, progress.as_ref(), |&n| {
        if n == 0.0 {
            Ok(static_state.clone())
        } else {
            model.solve_from(&load, n, &opts, start, &mut WarmStart::new())
        }
    })?;
    let (states, finished, failed) = super::errors::split_results(results);
    let d = curve_columns(py, &states)?;
    super::errors::finish_sweep(py, &speeds, d, finished, &failed)
}

/// Columns of a stiffness curve (one entry per state).
pub fn curve_columns<'py>(py: Python<'py>, states: &[BearingState]) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    let col = |f: &dyn Fn(&BearingState) -> f64| -> Vec<f64> { states.iter().map(f).collect() };
    d.set_item(
        "axial_stiffness_n_per_m",
        col(&|s| s.axial_stiffness_seed_n_per_m).into_pyarray(py),
    )?;
    d.set_item(
        "radial_stiffness_n_per_m",
        col(&|s| s.radial_stiffness_seed_n_per_m).into_pyarray(py),
    )?;
    let names = ["x", "y", "z", "rx", "ry"];
    let units = ["n_per_m", "n_per_m", "n_per_m", "nm_per_rad", "nm_per_rad"];
    for i in 0..5 {
        let key = format!("k_{}{}_{}", names[i], names[i], units[i]);
        d.set_item(key, col(&|s| s.stiffness_matrix[i][i]).into_pyarray(py))?;
    }
    d.set_item("k_xz_n_per_m", col(&|s| s.stiffness_matrix[0][2]).into_pyarray(py))?;
    d.set_item("k_xry_n_per_rad", col(&|s| s.stiffness_matrix[0][4]).into_pyarray(py))?;
    d.set_item(
        "radial_displacement_mm",
        col(&|s| s.displacement[0].hypot(s.displacement[1]) * 1e3).into_pyarray(py),
    )?;
    d.set_item(
        "axial_displacement_mm",
        col(&|s| s.displacement[2] * 1e3).into_pyarray(py),
    )?;
    d.set_item(
        "tilt_rad",
        col(&|s| s.displacement[3].hypot(s.displacement[4])).into_pyarray(py),
    )?;
    let fold = |f: &dyn Fn(&crate::bearing::BallState) -> f64, max: bool| -> Vec<f64> {
        states
            .iter()
            .map(|s| {
                s.balls
                    .iter()
                    .map(f)
                    .fold(if max { f64::NEG_INFINITY } else { f64::INFINITY }, |a, b| {
                        if max {
                            a.max(b)
                        } else {
                            a.min(b)
                        }
                    })
            })
            .collect()
    };
    d.set_item(
        "inner_contact_angle_max_deg",
        fold(&|b| b.inner_contact_angle_rad.to_degrees(), true).into_pyarray(py),
    )?;
    d.set_item(
        "inner_contact_angle_min_deg",
        fold(&|b| b.inner_contact_angle_rad.to_degrees(), false).into_pyarray(py),
    )?;
    d.set_item(
        "outer_contact_angle_max_deg",
        fold(&|b| b.outer_contact_angle_rad.to_degrees(), true).into_pyarray(py),
    )?;
    d.set_item(
        "outer_contact_angle_min_deg",
        fold(&|b| b.outer_contact_angle_rad.to_degrees(), false).into_pyarray(py),
    )?;
    d.set_item("inner_load_max_n", fold(&|b| b.inner_load_n, true).into_pyarray(py))?;
    d.set_item("outer_load_max_n", fold(&|b| b.outer_load_n, true).into_pyarray(py))?;
    d.set_item(
        "centrifugal_force_n",
        fold(&|b| b.centrifugal_force_n, true).into_pyarray(py),
    )?;
    d.set_item(
        "iterations",
        states
            .iter()
            .map(|s| s.iterations as f64)
            .collect::<Vec<_>>()
            .into_pyarray(py),
    )?;
    Ok(d)
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(stiffness_curve, m)?)?;
    Ok(())
}
