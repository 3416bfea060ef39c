//! Nonlinear gear dynamics: ODE traits, RK4 / Dormand-Prince integrators,
//! the 1-DOF backlash oscillator and the 8-DOF (reduced to 7-DOF) helical
//! pair of docs/concepts/physics.md §7 (A-43 .. A-50), Lyapunov exponents,
//! Poincare sections, motion classification and speed sweeps (A, section 3.3,
//! Figs. 14-15).

pub mod batch;
pub mod bifurcation;
pub mod classify;
pub mod dop853;
pub mod gear_model;
pub mod integrate;
pub mod lyapunov;
pub mod ode;
pub mod poincare;
pub mod seed;
pub(crate) mod simd;

pub use bifurcation::{
    regime_map, regime_map_partial, sweep, sweep_many, sweep_many_partial, sweep_partial, BearingSchedule, CellFailure,
    HelicalSweep, PartialRegimeMap, PartialSweep, RegimeCell, SpeedFailure, SpeedPoint, SweepConfig, SweepDirection,
    SweepModel, SweepResult,
};
pub use classify::{ChaosEvidence, ClassifyConfig, ImpactRegime, Motion, SectionVerdict, Transition};
pub use gear_model::{
    BacklashOscillator, BearingSupport, GearBody, HelicalPair, HelicalPairParams, HelicalPairSystem, MeshDamping,
};
pub use ode::{GridOde, OdeSystem, PeriodicTable};
pub use seed::{
    bearing_schedule, helical_params, helical_params_from_tables, seed_a_params, seed_bearing_loads, BearingCase,
    GearSystemDefaults, MeshTables,
};
