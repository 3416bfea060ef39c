//! Spindle benchmarks: a 10-minute transient of the seed B spindle network
//! with sources coupled to the bearing states (target < 50 ms), and one
//! coupled spindle steady operating point.

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use thermobear::spindle::{Preload, Spindle, SEED_B_SPRING_RATE_N_PER_M};

fn spindle() -> Spindle {
    Spindle::preset("seed-ceramic-spindle")
        .unwrap()
        .with_preload(Preload::Spring {
            force_n: 300.0,
            rate_n_per_m: SEED_B_SPRING_RATE_N_PER_M,
        })
        .unwrap()
}

fn bench(c: &mut Criterion) {
    let sp = spindle();
    c.bench_function("spindle transient 10 min, dt 5 s, coupled sources", |b| {
        b.iter(|| black_box(sp.transient(12_000.0, 600.0, 5.0, 12, None, 0.05).unwrap()))
    });
    c.bench_function("spindle coupled steady state 12000 rpm", |b| {
        b.iter(|| black_box(sp.thermal_state(12_000.0).unwrap()))
    });
}

criterion_group!(benches, bench);
criterion_main!(benches);
