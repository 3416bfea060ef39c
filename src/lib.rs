//! # thermobear
//!
//! Thermally coupled rolling-bearing mechanics, bearing stiffness and the
//! nonlinear dynamics of the machines they carry.
//!
//! The core is SI throughout (m, N, Pa, rad, s, W, K; temperatures in deg C
//! where absolute values matter). Public names carry their unit. Equation
//! numbers (A-n, B-n) refer to `../shared/PHYSICS.md` and the two seed
//! studies it restates.
//!
//! The optional `python` feature adds the PyO3 bindings in [`python`]; the
//! rest of the crate never touches Python.

pub mod bearing;
pub mod config;
pub mod dynamics;
pub mod effects;
pub mod error;
pub mod gear;
pub mod materials;
pub mod rotor;
pub mod thermal;
pub mod units;

#[cfg(feature = "python")]
pub mod python;

pub use bearing::{Bearing, BearingGeometry, BearingType};
pub use effects::{Effect, EffectSet};
pub use error::{Error, Result};
pub use materials::Material;
