//! Helical gear pair of seed A (docs/concepts/physics.md §7): geometry and data
//! checks ([`geometry`]), ISO 6336-1 Method B tooth stiffness ([`iso6336`]),
//! time-varying mesh stiffness and static transmission error ([`mesh`]),
//! and the classic 1-DOF torsional backlash scaling ([`torsional`]).
//!
//! What the gear-pair dynamics consume:
//! `GearPair::preset("seed-electric-drive")`, [`GearPair::base_radius_m`],
//! [`GearPair::helix_angle_rad`], [`GearPair::line_of_action_angle_rad`],
//! [`GearPair::mass_kg`], [`GearPair::polar_inertia_kg_m2`],
//! [`GearPair::input_torque_n_m`], [`GearPair::mesh_period_s`],
//! [`MeshStiffness::samples`], [`MeshStiffness::mean_n_per_m`] and
//! [`TransmissionError::samples`].

pub mod geometry;
pub mod iso6336;
pub mod mesh;
pub mod torsional;

pub use geometry::{GearGeometry, GearPair, GearPairSpec, TableGearData, ToothForces, TypoWarning, WheelSpec};
pub use iso6336::{iso_stiffness, GearBlank, IsoStiffness, IsoStiffnessOptions};
pub use mesh::{tooth_pair_stiffness, MeshOptions, MeshStiffness, StiffnessModel, TransmissionError};
pub use torsional::TorsionalMesh;
