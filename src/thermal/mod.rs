//! Thermal building blocks (docs/concepts/physics.md §4 and §5): lubricant
//! properties, bearing friction heat, a general thermal resistance network
//! with steady and transient solvers, thermal expansion of shaft, rings,
//! balls and housing, and ready-made networks for the two seed studies.
//!
//! The coupled fixed point (heat <-> temperatures <-> geometry <-> loads)
//! is meant to be a thin loop over these pieces: per-contact data in
//! [`heat::bearing_heat`], [`network::SteadySolver::solve`] with a warm
//! start, [`expansion::thermal_offsets`] back to the groove-centre geometry.
//! [`coupled`] is that loop for one bearing in the seed A network.

pub mod coupled;
pub mod expansion;
pub mod friction;
pub mod heat;
pub mod lubricant;
pub mod network;
pub mod oil_supply;
pub mod presets;
pub mod row_heat;

pub use heat::{bearing_heat, BearingHeat, HeatSplit, SpinContact};
pub use lubricant::Lubricant;
pub use network::{Convection, SteadySolver, Temperatures, ThermalNetwork, Transient, TransientSolver};
