//! RK4 cost of the 8-DOF (7-DOF reduced) helical pair and a reduced seed
//! diagram set. The full set (1001 speeds) is timed once by
//! `cargo run --release --example seed_diagrams`.

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use std::hint::black_box;
use thermobear::dynamics::batch::{advance_batch, pack, HelicalBatch, LANES};
use thermobear::dynamics::integrate::rk4_advance;
use thermobear::dynamics::*;

const STEPS: usize = 6400; // 100 mesh periods at 64 steps

fn rk4_steps(c: &mut Criterion) {
    let pair = HelicalPair::new(HelicalPairParams::seed_a()).unwrap();
    let sys = pair.system(10_000.0, 64).unwrap();
    let x0 = pair.static_state().unwrap();
    let mut g = c.benchmark_group("rk4_8dof");
    g.throughput(Throughput::Elements(STEPS as u64));
    g.bench_function("scalar_step", |b| {
        b.iter(|| {
            let mut x = x0;
            rk4_advance(&sys, &mut x, 0, black_box(STEPS));
            x
        })
    });
    let systems: Vec<_> = (0..LANES)
        .map(|l| pair.system(8000.0 + 1000.0 * l as f64, 64).unwrap())
        .collect();
    let batch = HelicalBatch::<LANES>::new(std::array::from_fn(|l| &systems[l])).unwrap();
    g.throughput(Throughput::Elements((STEPS * LANES) as u64));
    g.bench_function("lockstep_lane_step", |b| {
        b.iter(|| {
            let mut x = pack(&[x0; LANES]);
            advance_batch(&batch, &mut x, black_box(STEPS));
            x
        })
    });
    g.finish();
}

fn seed_set_reduced(c: &mut Criterion) {
    let pair = HelicalPair::new(HelicalPairParams::seed_a()).unwrap();
    let models: Vec<HelicalSweep> = [
        BearingSchedule::constant(2.0e8, 5.0e7).unwrap(),
        BearingSchedule::new(vec![(6500.0, 2.0e8, 5.0e7), (16500.0, 1.8e8, 4.6e7)]).unwrap(),
        BearingSchedule::new(vec![(6500.0, 1.9e8, 5.6e7), (16500.0, 1.75e8, 5.3e7)]).unwrap(),
    ]
    .into_iter()
    .map(|b| HelicalSweep {
        pair: pair.clone(),
        bearings: b,
    })
    .collect();
    let jobs: Vec<_> = models
        .iter()
        .flat_map(|m| [(m, SweepDirection::Up), (m, SweepDirection::Down)])
        .collect();
    let speeds: Vec<f64> = (0..101).map(|i| 6500.0 + 100.0 * i as f64).collect();
    let cfg = SweepConfig::default();
    let pool = rayon::ThreadPoolBuilder::new().num_threads(2).build().unwrap();
    let mut g = c.benchmark_group("seed_set");
    g.sample_size(10);
    g.bench_function("101_speeds_x3_cases_x2_dirs_2_threads", |b| {
        b.iter(|| pool.install(|| sweep_many(&jobs, &speeds, &cfg, &|_, _| true).unwrap()))
    });
    g.finish();
}

criterion_group!(benches, rk4_steps, seed_set_reduced);
criterion_main!(benches);
