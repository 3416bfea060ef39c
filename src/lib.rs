//! # thermobear
//!
//! How does the heat in a rolling bearing change its stiffness, and with it
//! the vibration of the machine it carries? This crate answers it from the
//! equations: ball-bearing mechanics at high speed, friction heat, a thermal
//! resistance network, thermal expansion fed back into the raceway geometry,
//! the resulting stiffness, and the nonlinear dynamics of a helical gear pair
//! and of a motorized spindle rotor.
//!
//! The crate builds and tests without Python. The optional `python` feature
//! adds the PyO3 bindings used by the `thermobear` Python package; nothing
//! else in the crate depends on it.
//!
//! ## Units and conventions
//!
//! Everything inside is SI (m, N, Pa, rad, s, W, K; absolute temperatures in
//! deg C where the name says `_c`), and every public name that carries a
//! dimension says its unit: `speed_rpm`, `axial_n`, `radial_stiffness_seed_n_per_m`.
//! The bearing axis is z, the radial load acts along x, ball j sits at azimuth
//! 2 pi j / Z from x, and ring displacements are measured from the concentric
//! position with the groove curvature centres in one plane (ISO/TS 16281).
//! Physical effects (centrifugal force, gyroscopic moment, spin friction,
//! thermal expansion of each part ...) are named and switchable
//! ([`effects::Effect`], [`effects::EffectSet`]).
//!
//! Equation labels (A-n) are the equation numbers of Liu, Liu & Hu, *Influence
//! of the Bearing Thermal Deformation on Nonlinear Dynamic Characteristics of
//! an Electric Drive Helical Gear System*, Sensors 2021, 21, 309 ("seed A");
//! "seed B" is the study *Dynamic and thermal coupling model of a ceramic
//! motorized spindle* (7009C/7008C hybrid angular-contact bearings). The
//! physics with every equation and its source is written out in the
//! repository's documentation, `docs/concepts/physics.md` (sections §1-§8
//! cited throughout the code).
//!
//! ## Module map
//!
//! | module | physical object |
//! | --- | --- |
//! | [`materials`] | elastic and thermal properties (steel, Si3N4, ...) |
//! | [`bearing`] | geometry, Hertz contact, statics, high-speed quasi-statics, 5x5 stiffness, speed sweeps |
//! | [`thermal`] | lubricant, friction heat, thermal network (steady, transient), expansion, the coupled fixed point |
//! | [`spindle`] | back-to-back angular-contact pairs with rigid or spring preload, the coupled spindle |
//! | [`rotor`] | Timoshenko-beam spindle rotor, Campbell diagram, unbalance response, spectra |
//! | [`gear`] | helical gear geometry, ISO 6336-1 stiffness, time-varying mesh stiffness |
//! | [`dynamics`] | integrators, the 8-DOF helical pair with backlash, Poincare sections, regimes, bifurcation sweeps |
//! | [`effects`], [`config`], [`error`], [`units`] | switchable effects, TOML system files, the error type, unit conversions |
//!
//! ## A bearing at speed
//!
//! The seed A deep-groove bearing under its quoted loads, statically and at
//! 16,000 rpm: the centrifugal force pushes the balls onto the outer raceway,
//! so the outer contacts carry more than the inner ones and the bearing
//! softens axially.
//!
//! ```
//! use thermobear::bearing::{BearingLoad, SolveOptions};
//! use thermobear::Bearing;
//!
//! let b = Bearing::preset("6208")?;
//! let load = BearingLoad::new(2680.9, 1189.9, 0.0); // axial N, radial N, moment N m
//! let opts = SolveOptions::default();
//! let slow = b.solve(load, 0.0, &opts)?;
//! let fast = b.solve(load, 16_000.0, &opts)?;
//! assert!(fast.balls.iter().all(|ball| ball.outer_load_n > ball.inner_load_n));
//! assert!(fast.axial_stiffness_seed_n_per_m < slow.axial_stiffness_seed_n_per_m);
//! // The full 5x5 stiffness d[Fx, Fy, Fz, Mx, My] / d[x, y, z, theta_x, theta_y]
//! // is symmetric at a static equilibrium, to the accuracy of a contact
//! // constant that varies slightly with the contact angle.
//! let k = &slow.stiffness_matrix;
//! assert!((k[0][2] - k[2][0]).abs() < 1e-4 * (k[0][0] * k[2][2]).sqrt());
//! # Ok::<(), thermobear::Error>(())
//! ```
//!
//! ## Heat, temperatures and thermal expansion
//!
//! [`thermal::coupled::CoupledBearing`] iterates friction heat -> network
//! temperatures -> thermal expansion -> bearing geometry to a fixed point
//! (seed A's network). At steady state the heat generated leaves through
//! the boundary nodes.
//!
//! ```
//! use thermobear::thermal::coupled::{CoupledBearing, CoupledOptions};
//! use thermobear::Bearing;
//!
//! let b = Bearing::preset("6208")?;
//! let model = CoupledBearing::seed_a(&b, CoupledOptions::default())?;
//! let st = model.solve(10_000.0, 2680.9, 1189.9)?;
//! let h = &st.heat.heat;
//! let generated = h.rolling_w + h.inner_spin_w + h.outer_spin_w;
//! let out: f64 = st.boundary_flows_w.iter().map(|(_, w)| w).sum();
//! assert!((out - generated).abs() < 1e-3 * generated);
//! // The balls run hottest, the housing coolest (seed A Fig. 8).
//! assert!(st.temperature_c("Tb")? > st.temperature_c("Th")?);
//! # Ok::<(), thermobear::Error>(())
//! ```
//!
//! ## A motorized spindle
//!
//! ```
//! use thermobear::spindle::Spindle;
//!
//! let sp = Spindle::preset("seed-ceramic-spindle")?;
//! let s = sp.thermal_state(12_000.0)?;
//! // Motor and bearing heat leave through water, air and oil-air.
//! assert!((s.boundary_flow_w - s.total_heat_w).abs() < 1e-6 * s.total_heat_w);
//! assert!(s.axial_growth_m > 0.0);
//! # Ok::<(), thermobear::Error>(())
//! ```
//!
//! ## Gear-pair dynamics
//!
//! The 8-DOF helical pair with backlash and time-varying mesh stiffness,
//! swept in speed with the state carried from one speed to the next; each
//! speed is classified (period-n, quasi-periodic, chaotic, impacts).
//!
//! ```
//! use thermobear::dynamics::*;
//! use thermobear::Bearing;
//!
//! let pair = HelicalPair::new(seed_a_params(&GearSystemDefaults::default())?)?;
//! let (fa, fr) = seed_bearing_loads(100.0)?;
//! let grid = [6_000.0, 9_000.0, 12_000.0];
//! let bearings = bearing_schedule(&Bearing::preset("6208")?, BearingCase::Constant, &grid, fa, fr, 2)?;
//! let model = HelicalSweep { pair, bearings };
//! let cfg = SweepConfig { transient_periods: 50, recorded_periods: 20, lyapunov_periods: 0, ..Default::default() };
//! let r = sweep(&model, &[7_000.0, 8_000.0], SweepDirection::Up, &cfg, &|_, _| true)?;
//! assert_eq!(r.points.len(), 2);
//! # Ok::<(), thermobear::Error>(())
//! ```
//!
//! ## Errors
//!
//! Every fallible call returns [`Result`]; [`Error`] names the field and the
//! value of bad input, and a solver that does not converge reports the
//! residual it reached. Nothing panics on bad input and no NaN is returned
//! silently.
//!
//! ## Threads
//!
//! Sweeps run across rayon threads (`RAYON_NUM_THREADS`, or your own
//! `rayon::ThreadPool` with `install`); results do not depend on the number
//! of threads. Long sweeps take a progress callback `(done, total) -> bool`
//! that stops the work when it returns `false`.

#![warn(missing_docs)]

pub mod bearing;
pub mod cancel;
pub mod config;
pub mod dynamics;
pub mod effects;
pub mod error;
pub mod gear;
pub mod materials;
pub mod persist;
pub mod rotor;
pub mod spindle;
pub mod thermal;
pub mod units;

#[cfg(feature = "python")]
mod python;

pub use bearing::{Bearing, BearingGeometry, BearingType};
pub use effects::{Effect, EffectSet};
pub use error::{Error, Result};
pub use materials::Material;

/// The examples of the docs page "Using the Rust crate" (`docs/rust.md`),
/// compiled and run as doctests, so that the page cannot drift from the
/// crate. Only the doctest build sees this item.
#[cfg(doctest)]
#[doc = include_str!("../docs/rust.md")]
pub struct RustPageExamples;
