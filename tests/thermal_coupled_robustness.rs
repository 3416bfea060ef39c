//! Regression: the coupled single-bearing solve of the 7009C-hybrid under
//! 400 N axial preload used to stop with a ball-equilibrium error at
//! scattered speeds once the viscous heat was raised (f0 >= 1.5): the
//! thermal offsets open the inner gap of the lightly loaded balls and the
//! per-ball Newton iteration, started from the tangent predictor of the
//! loaded state, stalled on the edge of the inner contact.

use thermobear::bearing::Bearing;
use thermobear::thermal::coupled::{CoupledBearing, CoupledOptions};

#[test]
fn hybrid_7009c_light_preload_solves_where_it_used_to_fail() {
    let b = Bearing::preset("7009C-hybrid").unwrap();
    // (f0, speed) pairs that failed before the cold-start fallback.
    for (f0, n) in [(1.5, 10_750.0), (2.0, 8_000.0), (3.0, 6_000.0), (4.0, 4_750.0)] {
        let o = CoupledOptions {
            lubrication_factor_f0: f0,
            ..CoupledOptions::default()
        };
        let c = CoupledBearing::seed_a(&b, o).unwrap();
        let s = c
            .solve(n, 400.0, 0.0)
            .unwrap_or_else(|e| panic!("f0 {f0} at {n} rpm: {e:?}"));
        // Steady state: all bearing heat leaves through the boundaries.
        let out: f64 = s.boundary_flows_w.iter().map(|(_, q)| q).sum();
        let h = s.heat.heat.total_w();
        assert!((out - h).abs() < 1e-6 * h, "f0 {f0} at {n} rpm: {out} vs {h}");
        // The ring is in equilibrium with the applied 400 N axial load.
        assert_eq!(s.bearing.applied_load[2], 400.0);
        assert!(s.bearing.residual <= c.options().solve.tolerance);
        // More viscous heat -> a hotter bearing than f0 = 1.
        let cold = CoupledBearing::seed_a(&b, CoupledOptions::default())
            .unwrap()
            .solve(n, 400.0, 0.0)
            .unwrap();
        assert!(s.temperature_c("Tb").unwrap() > cold.temperature_c("Tb").unwrap());
    }
}
