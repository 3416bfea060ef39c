//! Gear dynamics on the seed parameters (the seed electric-drive pair with
//! computed mesh stiffness, two 6208 per shaft at the seed loads,
//! src/dynamics/seed.rs): RK4 steps (one trajectory and lock-step lanes on
//! the detected instruction set), one continuation sweep of 51 speeds, the
//! six seed sweeps over 51 speeds on 2 threads, and a Lyapunov estimate.
//! The full diagram set (1001 speeds) is timed by
//! `cargo run --release --example seed_diagrams`.
//!
//! Compare against the saved baseline with `scripts/bench_compare.sh`.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use std::hint::black_box;
use thermobear::dynamics::batch::{advance_batch, pack, HelicalBatch};
use thermobear::dynamics::integrate::{rk4_advance, rk4_step_generic};
use thermobear::dynamics::lyapunov::{largest_lyapunov_blocks, LyapunovBlocks};
use thermobear::dynamics::*;

/// 10 mesh periods at 64 steps.
const STEPS: usize = 640;
const SPEED_RPM: f64 = 10_000.0;

/// The seed pair with the constant and speed-dependent 6208 cases.
fn seed_models() -> Vec<HelicalSweep> {
    let pair = HelicalPair::new(seed_a_params(&GearSystemDefaults::default()).unwrap()).unwrap();
    let bearing = thermobear::Bearing::preset("6208").unwrap();
    let (fa, fr) = seed_bearing_loads(100.0).unwrap();
    let grid: Vec<f64> = (0..=44).map(|i| 6000.0 + 250.0 * i as f64).collect();
    [BearingCase::Constant, BearingCase::Speed]
        .into_iter()
        .map(|case| HelicalSweep {
            pair: pair.clone(),
            bearings: bearing_schedule(&bearing, case, &grid, fa, fr, 2).unwrap(),
        })
        .collect()
}

fn lanes<const L: usize>(g: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>, m: &HelicalSweep) {
    let systems: Vec<_> = (0..L)
        .map(|l| m.system_at(SPEED_RPM + 500.0 * l as f64, 64).unwrap())
        .collect();
    let batch = HelicalBatch::<L>::new(std::array::from_fn(|l| &systems[l])).unwrap();
    let x0 = pack(&[m.initial_state(SPEED_RPM).unwrap(); L]);
    g.throughput(Throughput::Elements((STEPS * L) as u64));
    g.bench_function(format!("lockstep_{L}_lanes"), |b| {
        b.iter(|| {
            let mut x = x0;
            advance_batch(&batch, &mut x, black_box(STEPS));
            x
        })
    });
}

fn rk4_steps(c: &mut Criterion) {
    let models = seed_models();
    let m = &models[0];
    let sys = m.system_at(SPEED_RPM, 64).unwrap();
    let x0 = m.initial_state(SPEED_RPM).unwrap();
    let mut g = c.benchmark_group("seed_rk4");
    g.throughput(Throughput::Elements(STEPS as u64));
    g.bench_function("scalar_kernel", |b| {
        b.iter(|| {
            let mut x = x0;
            rk4_advance(&sys, &mut x, 0, black_box(STEPS));
            x
        })
    });
    g.bench_function("scalar_reference_4_rhs", |b| {
        b.iter(|| {
            let mut x = x0;
            for n in 0..black_box(STEPS) {
                rk4_step_generic(&sys, n % 64, &mut x);
            }
            x
        })
    });
    lanes::<4>(&mut g, m);
    lanes::<8>(&mut g, m);
    g.finish();
}

fn sweeps(c: &mut Criterion) {
    let models = seed_models();
    let speeds: Vec<f64> = (0..51).map(|i| 6500.0 + 200.0 * i as f64).collect();
    let cfg = SweepConfig::default();
    let mut g = c.benchmark_group("seed_sweep");
    g.sample_size(10);
    g.bench_function("up_51_speeds", |b| {
        b.iter(|| sweep(&models[1], black_box(&speeds), SweepDirection::Up, &cfg, &|_, _| true).unwrap())
    });
    // Six sweeps as the seed set: three stiffness cases x up/down (the
    // constant case twice stands in for the thermal schedule, which needs the
    // coupled thermal solve).
    let jobs: Vec<_> = [&models[0], &models[1], &models[0]]
        .into_iter()
        .flat_map(|m| [(m, SweepDirection::Up), (m, SweepDirection::Down)])
        .collect();
    let pool = rayon::ThreadPoolBuilder::new().num_threads(2).build().unwrap();
    g.bench_function("six_sweeps_51_speeds_2_threads", |b| {
        b.iter(|| pool.install(|| sweep_many(&jobs, black_box(&speeds), &cfg, &|_, _| true).unwrap()))
    });
    g.finish();
}

fn lyapunov(c: &mut Criterion) {
    let models = seed_models();
    let m = &models[1];
    let sys = m.system_at(SPEED_RPM, 64).unwrap();
    let x0 = m.initial_state(SPEED_RPM).unwrap();
    // 10 blocks of 10 mesh periods (renormalised every period), as a sweep's
    // non-periodic point: 100 periods of two trajectories.
    let cfg = LyapunovBlocks {
        renorm_steps: 64,
        renorms_per_block: 10,
        min_blocks: 10,
        max_blocks: 10,
        separation: 1e-6,
        sigmas: 2.0,
        threshold: 0.0,
    };
    let scale = [1e-6; 14];
    let mut g = c.benchmark_group("seed_lyapunov");
    g.throughput(Throughput::Elements((64 * 100) as u64));
    g.bench_function("benettin_100_periods", |b| {
        b.iter(|| largest_lyapunov_blocks(&sys, black_box(&x0), 0, &scale, &cfg, |_| {}).unwrap())
    });
    g.finish();
}

criterion_group!(benches, rk4_steps, sweeps, lyapunov);
criterion_main!(benches);
