//! Rotor-dynamics benchmarks on the seed B spindle (src/rotor/presets.rs):
//! a 200-speed Campbell diagram and a 1 s time response with a nonlinear
//! (Hertzian stand-in) bearing-force callback. Run on 2 rayon threads.

use std::hint::black_box;
use std::time::Duration;

use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::DVector;
use thermobear::rotor::modal::{campbell, CampbellOptions};
use thermobear::rotor::presets::{
    seed_b_spindle, SpindleParameters, FRONT_BEARING_POSITIONS_M, MAX_SPEED_RPM, NOSE_POSITION_M,
    REAR_BEARING_POSITIONS_M,
};
use thermobear::rotor::response::Unbalance;
use thermobear::rotor::spindle_vibration::{RowMaterial, SpindleVibration, SpindleVibrationConfig, UnbalanceSpec};
use thermobear::rotor::transient::{time_response, NonlinearForce, TransientOptions};
use thermobear::rotor::{LateralDof, Rotor};
use thermobear::Result;

/// Stand-in for the bearing solver's ball forces: each row is two opposed
/// preloaded Hertzian contacts per direction, f(u) = K [(d0 - u)+^1.5 - (d0 + u)+^1.5],
/// with K chosen so the tangent at u = 0 is the linear bearing stiffness k
/// (k = 3 K sqrt(d0)). The rotor model keeps the linear k (for its modal
/// basis and damping), so the callback returns f(u) + k u, the nonlinear part.
struct HertzianStandIn {
    dofs: Vec<usize>,
    hertz_constant_n_per_m1_5: f64,
    preload_deflection_m: f64,
    linear_n_per_m: f64,
}

impl NonlinearForce for HertzianStandIn {
    fn add_force(&self, _t: f64, q: &DVector<f64>, _qd: &DVector<f64>, f: &mut DVector<f64>) -> Result<()> {
        let (k, d0) = (self.hertz_constant_n_per_m1_5, self.preload_deflection_m);
        for &i in &self.dofs {
            let u = q[i];
            let hertz = k * ((d0 - u).max(0.0).powf(1.5) - (d0 + u).max(0.0).powf(1.5));
            f[i] += hertz + self.linear_n_per_m * u;
        }
        Ok(())
    }
    fn dofs(&self) -> Vec<usize> {
        self.dofs.clone()
    }
}

fn rotor_benches(c: &mut Criterion) {
    let _ = rayon::ThreadPoolBuilder::new().num_threads(2).build_global();
    let p = SpindleParameters::default();
    let rotor = Rotor::new(seed_b_spindle(&p).unwrap()).unwrap();
    let speeds: Vec<f64> = (0..200).map(|i| MAX_SPEED_RPM * i as f64 / 199.0).collect();
    let opts = CampbellOptions {
        reduced_modes: Some(24),
        ..CampbellOptions::default()
    };
    let mut g = c.benchmark_group("rotor");
    g.sample_size(10).measurement_time(Duration::from_secs(10));
    g.bench_function("campbell_seed_b_200_speeds_reduced24", |b| {
        b.iter(|| campbell(black_box(&rotor), &speeds, &opts).unwrap())
    });

    let d0: f64 = 5e-6;
    let k = p.front_radial_stiffness_n_per_m;
    let mut dofs = Vec::new();
    for z in FRONT_BEARING_POSITIONS_M.iter().chain(&REAR_BEARING_POSITIONS_M) {
        let n = rotor.node_at(*z).unwrap();
        dofs.extend([rotor.dof(n, LateralDof::X), rotor.dof(n, LateralDof::Y)]);
    }
    let nl = HertzianStandIn {
        dofs,
        hertz_constant_n_per_m1_5: k / (3.0 * d0.sqrt()),
        preload_deflection_m: d0,
        linear_n_per_m: k,
    };
    let unbalance = [Unbalance::from_balance_grade(0.17, 2.5, rotor.mass_kg(), MAX_SPEED_RPM, 0.0).unwrap()];
    let mut t_opts = TransientOptions::new(18_000.0, 1.0, 5e-5, NOSE_POSITION_M);
    t_opts.reduced_modes = Some(24);
    t_opts.tolerance = 1e-8;
    g.bench_function("time_response_1s_hertzian_callback_reduced24", |b| {
        b.iter(|| time_response(black_box(&rotor), &unbalance, Some(&nl), None, &t_opts).unwrap())
    });
    let full_opts = TransientOptions {
        reduced_modes: None,
        ..t_opts.clone()
    };
    g.bench_function("time_response_1s_hertzian_callback_full100dof", |b| {
        b.iter(|| time_response(black_box(&rotor), &unbalance, Some(&nl), None, &full_opts).unwrap())
    });

    // The seed spindle on bearing-solver rows (src/rotor/spindle_vibration.rs):
    // a fresh model per iteration, so the 400 row solves (2 row types x 200
    // speeds) are timed together with the eigenproblems.
    let cfg = SpindleVibrationConfig::seed(RowMaterial::Hybrid);
    g.bench_function("campbell_seed_b_200_speeds_solver_rows", |b| {
        b.iter(|| {
            let s = SpindleVibration::new(black_box(cfg.clone())).unwrap();
            s.campbell(&speeds, 8).unwrap()
        })
    });
    let s = SpindleVibration::new(cfg.clone()).unwrap();
    let u = s.unbalance(UnbalanceSpec::Grade { grade_mm_per_s: 2.5 }).unwrap();
    g.bench_function("time_response_1s_nonlinear_ball_forces_18000rpm", |b| {
        b.iter(|| s.time_vibration(18_000.0, 1.0, 0.0, black_box(&u), true).unwrap())
    });
    g.finish();
}

criterion_group!(benches, rotor_benches);
criterion_main!(benches);
