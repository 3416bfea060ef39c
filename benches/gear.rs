//! The seed electric-drive gear pair: time-varying mesh stiffness (energy
//! method, table lookup) and what a sweep pays per speed before
//! integrating: the 8-DOF model's parameters from the gear pair, and its
//! tabulation at one speed (natural-period check, mesh tables on the RK4
//! grid, kernel coefficients).

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use thermobear::dynamics::{seed_a_params, GearSystemDefaults, HelicalPair};
use thermobear::gear::{GearPair, MeshOptions, MeshStiffness};

fn tvms(c: &mut Criterion) {
    let p = GearPair::preset("seed-electric-drive").unwrap();
    let opts = MeshOptions {
        table_points: 256,
        ..MeshOptions::default()
    };
    c.bench_function("tvms_seed_256_samples_energy_method", |b| {
        b.iter(|| MeshStiffness::potential_energy_with(black_box(&p), &opts).unwrap())
    });
    let k = MeshStiffness::potential_energy_with(&p, &opts).unwrap();
    c.bench_function("tvms_lookup_at_phase", |b| b.iter(|| k.at(black_box(0.377))));
}

fn seed_model(c: &mut Criterion) {
    let d = GearSystemDefaults::default();
    c.bench_function("seed_helical_params_from_gear_pair", |b| {
        b.iter(|| seed_a_params(black_box(&d)).unwrap())
    });
    let pair = HelicalPair::new(seed_a_params(&d).unwrap()).unwrap();
    c.bench_function("seed_system_at_speed_64_steps", |b| {
        b.iter(|| pair.system(black_box(10_000.0), 64).unwrap())
    });
    c.bench_function("seed_pair_with_bearing_stiffness", |b| {
        b.iter(|| pair.with_bearing_stiffness(black_box(1.9e8), 5.1e7).unwrap())
    });
}

criterion_group!(benches, tvms, seed_model);
criterion_main!(benches);
