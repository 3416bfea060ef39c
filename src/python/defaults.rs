//! The core's default solver options, seen from Python: what
//! `SolveOptions::default()` holds, and a solve made with exactly those
//! options. The Python package's defaults are checked against them, so the
//! crate and the package cannot drift apart.

use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::bearing::PyBearing;
use super::errors::IntoPy;
use super::solve::{check_speed, load_vector, solve_with};
use crate::bearing::state::{GyroCoupleSign, RacewayControl, Tilt};
use crate::bearing::SolveOptions;

/// `SolveOptions::default()` of the Rust core as a dict: `effects` (names),
/// `raceway_control`, `gyro_couple_sign`, `tilt` ("held" or "free") with the
/// held `theta_x_rad`/`theta_y_rad`, `tolerance`, `max_iterations`,
/// `traction_coefficient`, and the raceway offsets in m.
#[pyfunction]
pub fn default_solve_options(py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    let o = SolveOptions::default();
    let d = PyDict::new(py);
    d.set_item("effects", o.effects.names())?;
    d.set_item(
        "raceway_control",
        match o.raceway_control {
            RacewayControl::Outer => "outer",
            RacewayControl::Inner => "inner",
        },
    )?;
    d.set_item(
        "gyro_couple_sign",
        match o.gyro_couple_sign {
            GyroCoupleSign::Derived => "derived",
            GyroCoupleSign::Reversed => "reversed",
        },
    )?;
    match o.tilt {
        Tilt::Free => {
            d.set_item("tilt", "free")?;
            d.set_item("theta_x_rad", py.None())?;
            d.set_item("theta_y_rad", py.None())?;
        }
        Tilt::Fixed {
            theta_x_rad,
            theta_y_rad,
        } => {
            d.set_item("tilt", "held")?;
            d.set_item("theta_x_rad", theta_x_rad)?;
            d.set_item("theta_y_rad", theta_y_rad)?;
        }
    }
    d.set_item("tolerance", o.tolerance)?;
    d.set_item("max_iterations", o.max_iterations)?;
    d.set_item("traction_coefficient", o.traction_coefficient)?;
    d.set_item("raceway_offset_axial_m", o.offsets.axial_m)?;
    d.set_item("raceway_offset_radial_m", o.offsets.radial_m)?;
    Ok(d)
}

/// One operating point solved with `SolveOptions::default()` untouched (no
/// Python argument maps onto the options): the state dict of
/// `Bearing.solve`. The moment is in N m and acts about y, the radial force
/// along x.
#[pyfunction]
#[pyo3(signature = (bearing, axial_n, radial_n, moment_n_m, speed_rpm))]
pub fn solve_with_default_options<'py>(
    py: Python<'py>,
    bearing: &PyBearing,
    axial_n: f64,
    radial_n: f64,
    moment_n_m: f64,
    speed_rpm: f64,
) -> PyResult<Bound<'py, PyDict>> {
    let load = load_vector(axial_n, radial_n, moment_n_m).py_err()?;
    let speed = check_speed(speed_rpm).py_err()?;
    solve_with(py, &bearing.inner, &load, speed, &SolveOptions::default())
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(default_solve_options, m)?)?;
    m.add_function(wrap_pyfunction!(solve_with_default_options, m)?)?;
    Ok(())
}
