//! Motorized spindle (seed B): back-to-back angular-contact bearing pairs on
//! one shaft, rigid or spring preload, coupled with the spindle thermal
//! network.

pub mod pair;

pub use pair::{BearingPair, PairLoad, PairState, Preload};
