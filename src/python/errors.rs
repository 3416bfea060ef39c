//! The one place where Rust errors become Python exceptions.
//!
//! ThermobearError
//! ├── ConfigError        (also raised for bad arguments; names field and value)
//! ├── ConvergenceError   (solver residual and iterations in the message)
//! │   └── ThermalRunawayError
//! └── DataError          (measured data that cannot be used)
//! `Error::Interrupted` becomes KeyboardInterrupt.

use pyo3::create_exception;
use pyo3::exceptions::{PyException, PyKeyboardInterrupt};
use pyo3::prelude::*;

use crate::error::Error;

create_exception!(
    thermobear,
    ThermobearError,
    PyException,
    "Base class of every thermobear error."
);
create_exception!(
    thermobear,
    ConfigError,
    ThermobearError,
    "A parameter, configuration value or file that is not valid; the message names the field and the value."
);
create_exception!(
    thermobear,
    ConvergenceError,
    ThermobearError,
    "An iterative solver stopped before its tolerance; the message gives the residual."
);
create_exception!(
    thermobear,
    ThermalRunawayError,
    ConvergenceError,
    "Heat and preload grow together without bound."
);
create_exception!(
    thermobear,
    DataError,
    ThermobearError,
    "Measured data that cannot be used."
);

/// Convert a core error into the matching Python exception.
pub fn to_py(err: Error) -> PyErr {
    let msg = err.to_string();
    match err {
        Error::Config { .. } | Error::Parse(_) => ConfigError::new_err(msg),
        Error::Convergence { .. } => ConvergenceError::new_err(msg),
        Error::ThermalRunaway(_) => ThermalRunawayError::new_err(msg),
        Error::Data(_) => DataError::new_err(msg),
        Error::Interrupted => PyKeyboardInterrupt::new_err(msg),
    }
}

/// `?`-friendly conversion.
pub trait IntoPy<T> {
    fn py_err(self) -> PyResult<T>;
}

impl<T> IntoPy<T> for crate::Result<T> {
    fn py_err(self) -> PyResult<T> {
        self.map_err(to_py)
    }
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("ThermobearError", py.get_type::<ThermobearError>())?;
    m.add("ConfigError", py.get_type::<ConfigError>())?;
    m.add("ConvergenceError", py.get_type::<ConvergenceError>())?;
    m.add("ThermalRunawayError", py.get_type::<ThermalRunawayError>())?;
    m.add("DataError", py.get_type::<DataError>())?;
    Ok(())
}
