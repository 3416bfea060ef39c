//! Coupled thermo-mechanical bearing model (seed A 6208 in its network):
//! one operating point, and a 1001-speed thermal stiffness curve on 2 threads.
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use thermobear::thermal::coupled::{stiffness_curve_mode, CoupledBearing, CoupledOptions, StiffnessMode};
use thermobear::Bearing;

const FA: f64 = 2680.9;
const FR: f64 = 1189.9;

fn coupled() -> CoupledBearing {
    CoupledBearing::seed_a(&Bearing::preset("6208").unwrap(), CoupledOptions::default()).unwrap()
}

fn operating_point(c: &mut Criterion) {
    let m = coupled();
    c.bench_function("coupled_operating_point_12000rpm", |b| {
        b.iter(|| m.solve(black_box(12_000.0), FA, FR).unwrap())
    });
}

fn thermal_curve(c: &mut Criterion) {
    let m = coupled();
    let speeds: Vec<f64> = (0..1001).map(|i| 6_500.0 + 10.0 * i as f64).collect();
    let pool = rayon::ThreadPoolBuilder::new().num_threads(2).build().unwrap();
    let mut g = c.benchmark_group("thermal_stiffness_curve");
    g.sample_size(10);
    g.bench_function("1001_speeds_2_threads", |b| {
        b.iter(|| {
            pool.install(|| stiffness_curve_mode(&m, black_box(&speeds), FA, FR, StiffnessMode::Thermal).unwrap())
        })
    });
    g.finish();
}

criterion_group!(benches, operating_point, thermal_curve);
criterion_main!(benches);
