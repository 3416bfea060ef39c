//! Solve the seed A bearing statically and at speed from Rust.
//!
//! cargo run --release --example bearing_solve

use thermobear::bearing::state::Tilt;
use thermobear::bearing::{BearingModel, SolveOptions};
use thermobear::Bearing;

fn main() -> thermobear::Result<()> {
    let b = Bearing::preset("6208")?;
    let model = BearingModel::new(&b)?;
    let load = [1189.9, 0.0, 2680.9, 0.0, 0.0];
    // Rings held level (ISO/TS 16281 practice, seed A's axial/radial model).
    let opts = SolveOptions {
        tilt: Tilt::held_level(),
        ..Default::default()
    };
    for speed in [0.0, 8000.0, 16000.0] {
        let s = if speed == 0.0 {
            model.solve_static(&load, &opts)?
        } else {
            model.solve(&load, speed, &opts)?
        };
        println!(
            "{speed:7.0} rpm: dz {:7.2} um, kr {:6.1} N/um, ka {:6.1} N/um, max Qi {:7.1} N",
            s.displacement[2] * 1e6,
            s.radial_stiffness_seed_n_per_m / 1e6,
            s.axial_stiffness_seed_n_per_m / 1e6,
            s.max_inner_load_n()
        );
    }
    Ok(())
}
