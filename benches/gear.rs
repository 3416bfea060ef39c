use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
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

criterion_group!(benches, tvms);
criterion_main!(benches);
