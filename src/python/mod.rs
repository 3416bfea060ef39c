//! PyO3 bindings: the `thermobear._native` extension module. All Python
//! glue lives under this directory; the core crate knows nothing of it.

use pyo3::prelude::*;

pub mod batch;
pub mod bearing;
pub mod defaults;
pub mod errors;
pub mod gear;
pub mod oil_supply;
pub mod parallel;
pub mod persist;
pub mod rotor;
pub mod solve;
pub mod spindle;
pub mod thermal;

#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    errors::register(m)?;
    bearing::register(m)?;
    solve::register(m)?;
    defaults::register(m)?;
    batch::register(m)?;
    gear::register(m)?;
    rotor::register(m)?;
    spindle::register(m)?;
    thermal::register(m)?;
    persist::register(m)?;
    parallel::register(m)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
