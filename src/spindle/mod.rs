//! Motorized spindle (seed B): back-to-back angular-contact bearing pairs on
//! one shaft, rigid or spring preload, coupled with the spindle thermal
//! network ([`crate::thermal::presets::SpindleNetwork`]).
//!
//! * [`pair`]: [`BearingPair`], the shaft equilibrium of two mirrored
//!   bearings with a rigid or spring [`Preload`], its 5x5 stiffness.
//! * [`coupled`]: [`Spindle`], the coupled steady state (fixed point with
//!   runaway detection), the transient with quasi-steady mechanics, the
//!   compensation preload (B Fig. 17), the optimal preload (B Figs. 15-16)
//!   and speed x preload x load grids across threads.
//! * [`config_io`]: [`SpindleConfig`] to and from JSON, and the named
//!   checks of its network and geometry ([`check_params`]).
//! * [`shaft_loads`]: the pairs' radial loads from the forces on the rigid
//!   shaft (nose load, static unbalanced magnetic pull [`CoreMagneticPull`]).
//!
//! ```
//! use thermobear::spindle::{Preload, Spindle, SEED_B_SPRING_RATE_N_PER_M};
//!
//! let sp = Spindle::preset("seed-ceramic-spindle")
//!     .unwrap()
//!     .with_preload(Preload::Spring { force_n: 300.0, rate_n_per_m: SEED_B_SPRING_RATE_N_PER_M })
//!     .unwrap();
//! let s = sp.thermal_state(12_000.0).unwrap();
//! // All heat (motor + bearings) leaves through water, air and oil-air.
//! assert!((s.boundary_flow_w - s.total_heat_w).abs() < 1e-6 * s.total_heat_w);
//! // The spring took up the axial growth: the preload rose.
//! assert!(s.axial_growth_m > 0.0 && s.front.preload_n > 300.0);
//! ```

pub mod pair;

pub use pair::{BearingPair, PairLoad, PairState, PairWarm, Preload};
pub mod config_io;
pub mod coupled;
pub mod shaft_loads;

pub use config_io::check_params;
#[allow(deprecated)]
pub use coupled::DEFAULT_SPIN_FRICTION;
pub use coupled::{
    compensation_preload, grid_point, optimal_preload, settling_times_s, spindle_grid, BearingHeatReport,
    CompensationPoint, GridPoint, OptimalPreload, Spindle, SpindleConfig, SpindleState,
    DEFAULT_SPIN_FRICTION_COEFFICIENT, SEED_B_SPRING_RATE_N_PER_M, SPINDLE_PRESETS,
};
pub use shaft_loads::{lever_rule_n, CoreMagneticPull};
