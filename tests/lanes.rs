//! The lock-step lane kernels against the scalar path on the seed
//! parameters (the seed electric-drive pair, two 6208 per shaft), for every
//! instruction set this CPU has.

use thermobear::dynamics::batch::{poincare_sample_batch_with, HelicalBatch, Isa};
use thermobear::dynamics::integrate::rk4_step_generic;
use thermobear::dynamics::poincare::poincare_sample;
use thermobear::dynamics::*;

fn seed_models() -> Vec<HelicalSweep> {
    let d = GearSystemDefaults::default();
    let pair = HelicalPair::new(seed_a_params(&d).unwrap()).unwrap();
    let bearing = thermobear::Bearing::preset("6208").unwrap();
    let (fa, fr) = seed_bearing_loads(100.0).unwrap();
    let grid = [6000.0, 11_000.0, 17_000.0];
    let mut light = seed_a_params(&d).unwrap();
    // A light-torque variant that loses contact (impacts), so the dead zone
    // and the contact-only damping switch inside the compared runs.
    light.input_torque_n_m = 5.0;
    for e in &mut light.transmission_error_m {
        *e *= 5.0;
    }
    let light = HelicalPair::new(light).unwrap();
    [
        (pair.clone(), BearingCase::Constant),
        (pair, BearingCase::Speed),
        (light, BearingCase::Constant),
    ]
    .into_iter()
    .map(|(p, case)| HelicalSweep {
        pair: p,
        bearings: bearing_schedule(&bearing, case, &grid, fa, fr, 2).unwrap(),
    })
    .collect()
}

#[test]
fn simd_lanes_equal_the_scalar_path_on_every_instruction_set() {
    let models = seed_models();
    let speeds = [6500.0, 8000.0, 9500.0, 11_000.0, 12_500.0, 14_000.0, 15_500.0, 16_500.0];
    let mut systems = Vec::new();
    let mut starts = Vec::new();
    for (l, &s) in speeds.iter().enumerate() {
        let m = &models[l % 3];
        systems.push(m.system_at(s, 64).unwrap());
        starts.push(m.initial_state(s).unwrap());
    }
    let scalar: Vec<_> = (0..8)
        .map(|l| {
            poincare_sample(&systems[l], &starts[l], 10, 4, |n, x| {
                systems[l].relative_deflection_m(n, x)
            })
            .unwrap()
        })
        .collect();
    let isas = Isa::available();
    assert!(isas.contains(&Isa::Portable) && isas.contains(&Isa::detected()));
    for isa in isas {
        let b8 = HelicalBatch::<8>::new(std::array::from_fn(|l| &systems[l])).unwrap();
        let r8 = poincare_sample_batch_with(isa, &b8, &std::array::from_fn(|l| starts[l]), 10, 4).unwrap();
        let b4 = HelicalBatch::<4>::new(std::array::from_fn(|l| &systems[2 * l])).unwrap();
        let r4 = poincare_sample_batch_with(isa, &b4, &std::array::from_fn(|l| starts[2 * l]), 10, 4).unwrap();
        for l in 0..8 {
            // Bitwise: the same operations in the same order in every lane.
            assert_eq!(r8[l], scalar[l], "{isa:?}, 8 lanes, lane {l}");
            if l % 2 == 0 {
                assert_eq!(r4[l / 2], scalar[l], "{isa:?}, 4 lanes, lane {}", l / 2);
            }
            // And so (trivially) within 1e-12 relative.
            let (a, b) = (&r8[l].final_state, &scalar[l].final_state);
            for i in 0..14 {
                assert!((a[i] - b[i]).abs() <= 1e-12 * b[i].abs());
            }
        }
    }
    // The light-torque lanes leave the drive flank (deflection below +b), so
    // the dead zone and the contact switch are exercised.
    for l in [2, 5] {
        let b = systems[l].half_backlash_m();
        println!(
            "lane {l}: DTE {:.3e} .. {:.3e} m, b = {b:.1e} m",
            scalar[l].observable_min, scalar[l].observable_max
        );
        assert!(scalar[l].observable_min < b, "lane {l} stays in contact");
    }
}

#[test]
fn kernel_step_equals_the_reference_rk4_to_round_off_on_seed_parameters() {
    // One step of the rearranged kernel against RK4 from four right-hand
    // side evaluations, from the same state, along 20 mesh periods: agreement
    // to 1e-12 of the state's scale (b for positions, b / h for velocities).
    for m in seed_models() {
        let sys = m.system_at(12_000.0, 64).unwrap();
        let mut x = m.initial_state(12_000.0).unwrap();
        let b = sys.half_backlash_m();
        let mut worst: f64 = 0.0;
        for n in 0..64 * 20 {
            let mut y = x;
            rk4_step_generic(&sys, n % 64, &mut y);
            sys.rk4_step(n % 64, &mut x);
            for i in 0..14 {
                let scale = if i < 7 { b } else { b / sys.step() };
                worst = worst.max((x[i] - y[i]).abs() / scale);
            }
        }
        assert!(worst < 1e-12, "{worst:e}");
    }
}
