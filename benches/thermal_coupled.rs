//! Coupled thermo-mechanical bearing model (seed A 6208 in its network):
//! one operating point, and a 1001-speed thermal stiffness curve on 2 threads,
//! with the default model (no drag) and with seed A's oil jet (500 cm^3/min
//! assumed, f0 = 1: the cavity oil fraction and the ball drag at every speed).
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use thermobear::thermal::coupled::{stiffness_curve_mode, CoupledBearing, CoupledOptions, StiffnessMode};
use thermobear::thermal::friction::Lubrication;
use thermobear::thermal::oil_supply::{OilSupply, SupplySettings};
use thermobear::Bearing;

const FA: f64 = 2680.9;
const FR: f64 = 1189.9;

fn coupled() -> CoupledBearing {
    CoupledBearing::seed_a(&Bearing::preset("6208").unwrap(), CoupledOptions::default()).unwrap()
}

/// Seed A's bearing with its oil jet (the seed A studies' supply).
fn coupled_jet() -> CoupledBearing {
    let options = CoupledOptions {
        lubrication: Lubrication::Jet,
        oil_supply: Some(SupplySettings::new(OilSupply::Jet {
            oil_flow_cm3_per_min: 500.0,
            jet_count: 1,
            jet_velocity_m_per_s: None,
        })),
        ..CoupledOptions::default()
    };
    CoupledBearing::seed_a(&Bearing::preset("6208").unwrap(), options).unwrap()
}

fn operating_point(c: &mut Criterion) {
    let m = coupled();
    c.bench_function("coupled_operating_point_12000rpm", |b| {
        b.iter(|| m.solve(black_box(12_000.0), FA, FR).unwrap())
    });
}

fn thermal_curve(c: &mut Criterion) {
    let speeds: Vec<f64> = (0..1001).map(|i| 6_500.0 + 10.0 * i as f64).collect();
    let pool = rayon::ThreadPoolBuilder::new().num_threads(2).build().unwrap();
    let mut g = c.benchmark_group("thermal_stiffness_curve");
    g.sample_size(10);
    for (name, m) in [
        ("1001_speeds_2_threads", coupled()),
        ("1001_speeds_2_threads_jet_500", coupled_jet()),
    ] {
        g.bench_function(name, |b| {
            b.iter(|| {
                pool.install(|| stiffness_curve_mode(&m, black_box(&speeds), FA, FR, StiffnessMode::Thermal).unwrap())
            })
        });
    }
    g.finish();
}

criterion_group!(benches, operating_point, thermal_curve);
criterion_main!(benches);
