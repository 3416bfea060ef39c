use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use thermobear::thermal::heat::{bearing_heat, HeatSplit};
use thermobear::thermal::presets::{seed_a_network, SeedAParams, SpindleNetwork, SpindleParams};
use thermobear::thermal::{SteadySolver, TransientSolver};
use thermobear::units::rpm_to_rad_s;
use thermobear::{Bearing, EffectSet};

fn seed_a_steady(c: &mut Criterion) {
    let b = Bearing::preset("6208").unwrap();
    let net = seed_a_network(&b, &SeedAParams::for_bearing(&b)).unwrap();
    let w = rpm_to_rad_s(10_000.0);
    let split: HeatSplit = bearing_heat(w, 0.003, 0.14, 0.0, &[], &[]).unwrap().split();
    let s = net.sources_w(&split);
    c.bench_function("seed_a_steady_cold_start", |bch| {
        bch.iter(|| {
            let mut solver = SteadySolver::new(net.network.clone());
            solver.solve(black_box(&s), w).unwrap()
        })
    });
    let mut warm = SteadySolver::new(net.network.clone());
    warm.solve(&s, w).unwrap();
    let s2: Vec<f64> = s.iter().map(|x| 1.01 * x).collect();
    let mut flip = false;
    c.bench_function("seed_a_steady_warm_start", |bch| {
        bch.iter(|| {
            flip = !flip;
            warm.solve(black_box(if flip { &s2 } else { &s }), w).unwrap()
        })
    });
}

fn spindle_transient(c: &mut Criterion) {
    let sp = SpindleNetwork::new(SpindleParams::seed_b().unwrap()).unwrap();
    let w = rpm_to_rad_s(12_000.0);
    let init = sp.network.initial_temperatures(25.0);
    let mut group = c.benchmark_group("spindle_transient_10min");
    group.sample_size(20);
    group.bench_function("dt_1s_temperature_dependent_sources", |bch| {
        bch.iter(|| {
            let mut tr = TransientSolver::new(sp.network.clone());
            tr.integrate(&init, 600.0, 1.0, w, 60, |_, t, out| {
                out.copy_from_slice(&sp.sources_w(12_000.0, Some(t), EffectSet::all())?);
                Ok(())
            })
            .unwrap()
        })
    });
    group.finish();
}

criterion_group!(benches, seed_a_steady, spindle_transient);
criterion_main!(benches);
