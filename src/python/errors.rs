//! The one place where Rust errors become Python exceptions.
//!
//! ThermobearError
//! ├── ConfigError        (also raised for bad arguments; names field and value)
//! ├── ConvergenceError   (solver residual and iterations in the message)
//! │   └── ThermalRunawayError
//! ├── DataError          (measured data that cannot be used)
//! └── Interrupted        (a progress callback returned False)
//! ThreadsWarning (a RuntimeWarning): a `threads` above the cores, capped.
//! `Error::Interrupted` (Ctrl-C seen by the core) becomes KeyboardInterrupt.

use pyo3::create_exception;
use pyo3::exceptions::{PyException, PyKeyboardInterrupt, PyRuntimeWarning};
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
create_exception!(
    thermobear,
    Interrupted,
    ThermobearError,
    "Long work stopped because its progress callback returned False; `done` and `total` say how far it got."
);
create_exception!(
    thermobear,
    ThreadsWarning,
    PyRuntimeWarning,
    "A `threads` argument above the number of available cores, capped to it."
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

/// Split per-speed results into the finished items (with their indices)
/// and the failures `(index, error)`.
pub fn split_results<T>(results: Vec<crate::Result<T>>) -> (Vec<T>, Vec<usize>, Vec<(usize, Error)>) {
    let (mut done, mut index, mut failed) = (Vec::new(), Vec::new(), Vec::new());
    for (i, r) in results.into_iter().enumerate() {
        match r {
            Ok(t) => {
                done.push(t);
                index.push(i);
            }
            Err(e) => failed.push((i, e)),
        }
    }
    (done, index, failed)
}

/// The exception of the first failed speed, carrying the finished rows:
/// `_sweep_partial` (their columns), `_sweep_finished_index` (their
/// indices in `speeds`) and `_sweep_failed` (`(speed, message)` of every
/// failure). The Python layer turns them into `partial` and `failed` frames.
pub fn partial_error(
    py: Python<'_>,
    speeds: &[f64],
    columns: Bound<'_, PyAny>,
    finished: Vec<usize>,
    failed: &[(usize, Error)],
) -> PyErr {
    let err = to_py(failed.first().map_or(Error::Interrupted, |f| f.1.clone()));
    let rows: Vec<(f64, String)> = failed.iter().map(|(i, e)| (speeds[*i], e.to_string())).collect();
    let v = err.value(py);
    let attached = v
        .setattr("_sweep_partial", columns)
        .and_then(|_| v.setattr("_sweep_finished_index", finished))
        .and_then(|_| v.setattr("_sweep_failed", rows));
    match attached {
        Ok(()) => err,
        Err(e) => e,
    }
}

/// The columns of a sweep, or, when some speeds failed, the error of the
/// first failure carrying them ([`partial_error`]).
pub fn finish_sweep<'py>(
    py: Python<'py>,
    speeds: &[f64],
    columns: Bound<'py, pyo3::types::PyDict>,
    finished: Vec<usize>,
    failed: &[(usize, Error)],
) -> PyResult<Bound<'py, pyo3::types::PyDict>> {
    if failed.is_empty() {
        Ok(columns)
    } else {
        Err(partial_error(py, speeds, columns.into_any(), finished, failed))
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
    m.add("Interrupted", py.get_type::<Interrupted>())?;
    m.add("ThreadsWarning", py.get_type::<ThreadsWarning>())?;
    Ok(())
}
