//! The crate's default solver options hold the ring level, as the Python
//! package does (`misalignment_rad=0.0`): a bearing in a machine has its
//! rings aligned by the shaft and the housing. A free tilt is the named
//! option `Tilt::Free`. The Python side of this check is
//! `tests/test_rust_python_defaults.py`.

use thermobear::bearing::{BearingLoad, BearingModel, RacewayControl, SolveOptions, Tilt};
use thermobear::{Bearing, EffectSet, Error};

/// Seed A's loads of the 100 N m case: axial (with the 300 N preload), radial, no moment.
const AXIAL_N: f64 = 2680.9;
const RADIAL_N: f64 = 1189.9;

fn free_tilt() -> SolveOptions {
    SolveOptions {
        tilt: Tilt::Free,
        ..SolveOptions::default()
    }
}

#[test]
fn default_options_are_the_python_defaults() {
    let o = SolveOptions::default();
    // Python: misalignment_rad=0.0, effects=None (all), raceway_control="outer".
    assert_eq!(o.tilt, Tilt::held_level());
    assert_eq!(Tilt::default(), Tilt::held_level());
    assert_eq!(o.effects, EffectSet::all());
    assert_eq!(o.raceway_control, RacewayControl::Outer);
}

#[test]
fn default_holds_the_ring_level_under_combined_load() {
    for name in ["6208", "7009C"] {
        let b = Bearing::preset(name).unwrap();
        let m = BearingModel::new(&b).unwrap();
        let load = [RADIAL_N, 0.0, AXIAL_N, 0.0, 0.0];
        for speed_rpm in [0.0, 16_000.0] {
            let held = if speed_rpm == 0.0 {
                m.solve_static(&load, &SolveOptions::default()).unwrap()
            } else {
                m.solve(&load, speed_rpm, &SolveOptions::default()).unwrap()
            };
            let free = if speed_rpm == 0.0 {
                m.solve_static(&load, &free_tilt()).unwrap()
            } else {
                m.solve(&load, speed_rpm, &free_tilt()).unwrap()
            };
            eprintln!(
                "{name} {speed_rpm} rpm: held radial {:.4} um axial {:.4} um; free radial {:.4} um axial {:.4} um tilt {:.3e} rad",
                held.radial_displacement_um(),
                held.axial_displacement_um(),
                free.radial_displacement_um(),
                free.axial_displacement_um(),
                free.tilt_rad()
            );
            // Held level: no tilt at all, and the moment that holds the ring
            // is a reaction. The radial load presses the balls near psi = 0,
            // whose axial forces then tilt the ring about y: the holding
            // moment is negative about y and nonzero.
            assert_eq!(held.tilt_rad(), 0.0, "{name} {speed_rpm}");
            assert!(held.applied_load[4] < 0.0, "{name} {speed_rpm}");
            assert!(
                held.applied_load[3].abs() < 1e-9 * held.applied_load[4].abs(),
                "{name} {speed_rpm}"
            );
            // A free ring under the same load without moment tilts and, no
            // longer held by its balls on the far side, moves radially more.
            assert!(free.tilt_rad() > 1e-4, "{name} {speed_rpm}");
            assert!(free.applied_load[4].abs() < 1e-6, "{name} {speed_rpm}");
            assert!(
                free.radial_displacement_um() > 2.0 * held.radial_displacement_um(),
                "{name} {speed_rpm}"
            );
            // The explicit held option is the default, bit for bit.
            let explicit = SolveOptions {
                tilt: Tilt::held_level(),
                ..SolveOptions::default()
            };
            let again = if speed_rpm == 0.0 {
                m.solve_static(&load, &explicit).unwrap()
            } else {
                m.solve(&load, speed_rpm, &explicit).unwrap()
            };
            assert_eq!(again.displacement, held.displacement);
            // Bearing::solve with a BearingLoad takes the same path.
            let via_load = b
                .solve(
                    BearingLoad::new(AXIAL_N, RADIAL_N, 0.0),
                    speed_rpm,
                    &SolveOptions::default(),
                )
                .unwrap();
            assert_eq!(via_load.displacement, held.displacement);
        }
    }
}

#[test]
fn a_moment_needs_the_free_tilt_option() {
    let b = Bearing::preset("7009C").unwrap();
    let m = BearingModel::new(&b).unwrap();
    let load = [RADIAL_N, 0.0, AXIAL_N, 0.0, 5.0];
    // Held level (the default): the moment would be ignored, so it is
    // refused and the message names the field and the way out.
    for speed_rpm in [0.0, 12_000.0] {
        let err = if speed_rpm == 0.0 {
            m.solve_static(&load, &SolveOptions::default())
        } else {
            m.solve(&load, speed_rpm, &SolveOptions::default())
        }
        .unwrap_err();
        assert!(matches!(err, Error::Config { .. }), "{err}");
        let msg = err.to_string();
        assert!(msg.contains("moment_y_n_m") && msg.contains("Tilt::Free"), "{msg}");
    }
    // The free tilt carries it: the ring tilts, and the balls balance it.
    let s = m.solve(&load, 12_000.0, &free_tilt()).unwrap();
    assert!(s.tilt_rad() > 0.0);
    assert!((s.applied_load[4] - 5.0).abs() < 1e-12);
}
