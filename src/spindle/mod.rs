//! Motorized spindle (seed B): back-to-back angular-contact bearing pairs on
//! one shaft, rigid or spring preload, coupled with the spindle thermal
//! network.

pub mod pair;

pub use pair::{BearingPair, PairLoad, PairState, PairWarm, Preload};
pub mod coupled;

pub use coupled::{
    compensation_preload, grid_point, optimal_preload, settling_times_s, spindle_grid, BearingHeatReport,
    CompensationPoint, GridPoint, OptimalPreload, Spindle, SpindleConfig, SpindleState, DEFAULT_SPIN_FRICTION,
    SEED_B_SPRING_RATE_N_PER_M,
};
