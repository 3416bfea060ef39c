use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use thermobear::bearing::{stiffness_curve, BearingModel, SolveOptions, WarmStart};
use thermobear::Bearing;

fn hertz(c: &mut Criterion) {
    let b = Bearing::preset("6208").unwrap();
    c.bench_function("hertz_exact_inner_contact", |bch| {
        bch.iter(|| b.inner_contact(black_box(0.26)).unwrap())
    });
}

/// Seed A's 100 N m load case: Fa = 2380.9 N, Fr = 1189.9 N.
const FA: f64 = 2380.9;
const FR: f64 = 1189.9;
/// Seed A's 300 N axial preload, added to Fa.
const PRELOAD: f64 = 300.0;

fn solves(c: &mut Criterion) {
    let b = Bearing::preset("6208").unwrap();
    let m = BearingModel::new(&b).unwrap();
    let o = SolveOptions::default();
    c.bench_function("bearing_model_build_6208", |bch| {
        bch.iter(|| BearingModel::new(black_box(&b)).unwrap())
    });
    let load = [FR, 0.0, FA, 0.0, 0.0];
    c.bench_function("static_solve_6208_seedA", |bch| {
        bch.iter(|| m.solve_static(black_box(&load), &o).unwrap())
    });
    let load_p = [FR, 0.0, FA + PRELOAD, 0.0, 0.0];
    c.bench_function("high_speed_solve_6208_16000rpm", |bch| {
        bch.iter(|| m.solve(black_box(&load_p), 16_000.0, &o).unwrap())
    });
    let start = m.solve_static(&load_p, &o).unwrap().displacement;
    c.bench_function("high_speed_solve_from_static_6208_16000rpm", |bch| {
        bch.iter(|| {
            m.solve_from(black_box(&load_p), 16_000.0, &o, start, &mut WarmStart::new())
                .unwrap()
        })
    });
    let q = m.solve(&load_p, 16_000.0, &o).unwrap().displacement;
    let mut warm = WarmStart::new();
    m.ring_forces(&q, 16_000.0, &o, &mut warm).unwrap();
    c.bench_function("ring_forces_warm_6208_16000rpm", |bch| {
        bch.iter(|| m.ring_forces(black_box(&q), 16_000.0, &o, &mut warm).unwrap())
    });
}

fn curves(c: &mut Criterion) {
    let m = BearingModel::new(&Bearing::preset("6208").unwrap()).unwrap();
    let o = SolveOptions::default();
    let speeds: Vec<f64> = (0..1001).map(|k| 6_500.0 + 10.0 * k as f64).collect();
    let mut g = c.benchmark_group("stiffness_curve_1001_speeds");
    g.sample_size(10);
    for threads in [1, 2] {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        g.bench_function(format!("{threads}_threads"), |bch| {
            bch.iter(|| pool.install(|| stiffness_curve(&m, black_box(&speeds), FA + PRELOAD, FR, &o).unwrap()))
        });
    }
    g.finish();
}

criterion_group!(benches, hertz, solves, curves);
criterion_main!(benches);
