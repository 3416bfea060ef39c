//! Coupled spindle (seed B): heat balance, transient settling, material and
//! preload trends, compensation preload, runaway detection, determinism.

use thermobear::spindle::*;
use thermobear::Error;

fn spring_spindle(name: &str, force_n: f64) -> Spindle {
    Spindle::preset(name)
        .unwrap()
        .with_preload(Preload::Spring {
            force_n,
            rate_n_per_m: SEED_B_SPRING_RATE_N_PER_M,
        })
        .unwrap()
}

#[test]
fn steady_state_heat_balance() {
    let sp = spring_spindle("seed-ceramic-spindle", 300.0);
    let s = sp.thermal_state(12_000.0).unwrap();
    // Sources = motor + all bearing heat; all of it leaves through the boundaries.
    let bearings: f64 = s.bearing_heat.iter().map(|h| h.heat.total_w()).sum();
    assert!((s.total_heat_w - s.motor_losses_w - bearings).abs() < 1e-9 * s.total_heat_w);
    assert!(
        (s.boundary_flow_w - s.total_heat_w).abs() < 1e-6 * s.total_heat_w,
        "{s:?}"
    );
    assert!(s.temperature_change_k <= sp.config.tolerance_k);
    // Spring balance: every bearing carries F0 + k_s x.
    let f = 300.0 + SEED_B_SPRING_RATE_N_PER_M * s.front.spring_compression_m;
    assert!((s.front.axial_force_n[1] - f).abs() < 1e-6 * f);
}

#[test]
fn transient_settles_to_coupled_steady_state() {
    let sp = spring_spindle("seed-ceramic-spindle", 300.0);
    let s = sp.thermal_state(12_000.0).unwrap();
    // Slowest time constant about 520 s: 8000 s is more than 15 of them.
    let run = sp.transient(12_000.0, 8000.0, 40.0, 50, None, 0.0).unwrap();
    let last = run.temperatures_c.last().unwrap();
    for (a, b) in last.iter().zip(&s.temperatures.temperatures_c) {
        assert!((a - b).abs() < 0.02, "{a} {b}");
    }
    let node = sp.network.front_inner;
    let (t95, _) = settling_times_s(&run, node, s.temperatures.temperatures_c[node], 0.95, 0.5);
    let t95 = t95.unwrap();
    assert!(t95 > 120.0 && t95 < 3600.0, "{t95}");
}

#[test]
fn ceramic_balls_expand_less_than_steel() {
    let h = spring_spindle("seed-ceramic-spindle", 300.0)
        .thermal_state(18_000.0)
        .unwrap();
    let s = spring_spindle("seed-steel-spindle", 300.0)
        .thermal_state(18_000.0)
        .unwrap();
    let a0 = 15f64.to_radians();
    let (dh, ds) = (
        h.front_radial_thermal_displacement_m(a0),
        s.front_radial_thermal_displacement_m(a0),
    );
    assert!(dh > 0.0 && dh < ds, "{dh} {ds}");
}

#[test]
fn temperatures_rise_with_speed_and_preload() {
    let sp = spring_spindle("seed-ceramic-spindle", 300.0);
    let node = sp.network.front_balls;
    let mut last = f64::NEG_INFINITY;
    for n in [6_000.0, 12_000.0, 18_000.0] {
        let t = sp.thermal_state(n).unwrap().temperatures.temperatures_c[node];
        assert!(t > last, "{n}: {t} <= {last}");
        last = t;
    }
    let low = spring_spindle("seed-ceramic-spindle", 200.0)
        .thermal_state(12_000.0)
        .unwrap();
    let high = spring_spindle("seed-ceramic-spindle", 500.0)
        .thermal_state(12_000.0)
        .unwrap();
    assert!(high.temperatures.temperatures_c[node] > low.temperatures.temperatures_c[node]);
    let heat = |s: &SpindleState| s.bearing_heat.iter().map(|h| h.heat.total_w()).sum::<f64>();
    assert!(heat(&high) > heat(&low));
}

#[test]
fn compensation_preload_is_spring_rate_times_growth() {
    let sp = Spindle::preset("seed-ceramic-spindle").unwrap();
    let ks = SEED_B_SPRING_RATE_N_PER_M;
    let pts = compensation_preload(&sp, &[12_000.0], ks).unwrap();
    let p = pts[0];
    assert!(p.axial_growth_m > 0.0);
    assert!((p.compensation_preload_n - ks * p.axial_growth_m).abs() < 1e-12 * p.compensation_preload_n);
    assert!(p.solved_preload_change_n > 0.0);
}

#[test]
fn spring_growth_raises_force_by_rate_times_growth_in_series_with_bearings() {
    // A spring of rate k_s compressed by u in series with the pair's own
    // axial compliance: dF = k_s u k_b / (k_b + k_s), k_b >> k_s, so dF is
    // just below k_s u (seed B's compensation preload takes dF = k_s u).
    let sp = Spindle::preset("seed-ceramic-spindle").unwrap();
    let ks = SEED_B_SPRING_RATE_N_PER_M;
    let pair = sp
        .front
        .with_preload(Preload::Spring {
            force_n: 300.0,
            rate_n_per_m: ks,
        })
        .unwrap();
    let u = 30e-6;
    let s0 = pair.solve(12_000.0, &PairLoad::default()).unwrap();
    let s1 = pair
        .solve(
            12_000.0,
            &PairLoad {
                spring_growth_m: u,
                ..Default::default()
            },
        )
        .unwrap();
    let df = s1.preload_n - s0.preload_n;
    // Bearings A and B in series along the axis (mean of both states).
    let kz = |s: &PairState| {
        let (a, b) = (
            s.bearings[0].stiffness_matrix[2][2],
            s.bearings[1].stiffness_matrix[2][2],
        );
        a * b / (a + b)
    };
    let kb = 0.5 * (kz(&s0) + kz(&s1));
    let expect = ks * u * kb / (kb + ks);
    assert!(df < ks * u && (df - expect).abs() < 2e-3 * expect, "{df} vs {expect}");
}

#[test]
fn rigid_steel_preload_runs_away_at_18000_rpm() {
    // Rigid (fixed-position) preload: the inner ring runs hotter than the
    // outer, the interference and with it the preload and heat grow.
    let sp = Spindle::preset("seed-steel-spindle")
        .unwrap()
        .with_preload(Preload::Rigid { force_n: 300.0 })
        .unwrap();
    match sp.thermal_state(18_000.0) {
        Err(Error::ThermalRunaway(msg)) => assert!(msg.contains("preload grew"), "{msg}"),
        other => panic!("expected runaway, got {other:?}"),
    }
    // The same spindle with a spring preload settles.
    assert!(spring_spindle("seed-steel-spindle", 300.0)
        .thermal_state(18_000.0)
        .is_ok());
}

#[test]
fn grid_is_independent_of_thread_count() {
    let sp = spring_spindle("seed-ceramic-spindle", 300.0);
    let run = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| spindle_grid(&sp, &[9_000.0], &[250.0, 400.0], &[300.0]))
    };
    let a = run(1);
    let b = run(2);
    for (x, y) in a.iter().zip(&b) {
        assert_eq!(x.as_ref().unwrap(), y.as_ref().unwrap());
    }
}

#[test]
fn bad_input_is_rejected() {
    let sp = spring_spindle("seed-ceramic-spindle", 300.0);
    assert!(matches!(sp.thermal_state(-5.0), Err(Error::Config { .. })));
    assert!(matches!(Spindle::preset("gold"), Err(Error::Config { .. })));
    assert!(matches!(
        sp.with_preload(Preload::Spring {
            force_n: 300.0,
            rate_n_per_m: -1.0
        }),
        Err(Error::Config { .. })
    ));
    assert!(optimal_preload(&sp, &[12_000.0], &[]).is_err());
}

#[test]
fn optimal_preload_trades_stiffness_against_heat() {
    let sp = spring_spindle("seed-ceramic-spindle", 300.0)
        .with_radial_load(500.0)
        .unwrap();
    let best = optimal_preload(&sp, &[12_000.0], &[200.0, 400.0, 600.0]).unwrap();
    let b = &best[0];
    // More preload: stiffer pair (less mechanical displacement under the
    // working load) but more heat (more thermal displacement).
    for w in b.scan.windows(2) {
        assert!(w[1].mechanical_radial_displacement_m < w[0].mechanical_radial_displacement_m);
        assert!(w[1].thermal_radial_displacement_m > w[0].thermal_radial_displacement_m);
        assert!(w[1].bearing_heat_w > w[0].bearing_heat_w);
    }
    let min = b
        .scan
        .iter()
        .map(|g| g.total_radial_displacement_m())
        .fold(f64::INFINITY, f64::min);
    assert_eq!(b.min_radial_displacement_m, min);
    assert!(b
        .scan
        .iter()
        .any(|g| g.preload_n == b.optimal_preload_n && g.total_radial_displacement_m() == min));
}

#[test]
fn spin_friction_switch_removes_only_the_spin_heat() {
    use thermobear::effects::Effect;
    let on = Spindle::preset("seed-ceramic-spindle").unwrap();
    let mut cfg = on.config.clone();
    cfg.effects = cfg.effects.without(Effect::SpinFriction);
    let off = Spindle::new(cfg).unwrap();
    let (a, b) = (
        on.thermal_state(15_000.0).unwrap(),
        off.thermal_state(15_000.0).unwrap(),
    );
    let spin = |s: &SpindleState| -> Vec<f64> {
        s.bearing_heat
            .iter()
            .map(|h| h.heat.inner_spin_w + h.heat.outer_spin_w)
            .collect()
    };
    assert!(spin(&b).iter().all(|w| *w == 0.0), "{:?}", spin(&b));
    assert!(spin(&a).iter().all(|w| *w > 0.0), "{:?}", spin(&a));
    // the rest of the heat is the same physics: less heat, a cooler spindle
    let total = |s: &SpindleState| s.bearing_heat.iter().map(|h| h.heat.total_w()).sum::<f64>();
    assert!(total(&b) < total(&a));
    // Spin heat is delivered mostly to the inner rings and balls, so
    // those run cooler without it (the outer rings may run warmer: cooler
    // oil is more viscous and the viscous heat grows, A-21).
    for node in ["front_inner", "front_balls", "rear_inner", "rear_balls"] {
        let (x, y) = (b.temperatures.get(node).unwrap(), a.temperatures.get(node).unwrap());
        assert!(x < y - 0.5, "{node}: {x} vs {y}");
    }
}

/// The seed B spindle with the unbalanced magnetic pull switched on or off.
fn with_ump(sp: &Spindle, on: bool) -> Spindle {
    use thermobear::effects::Effect;
    let mut cfg = sp.config.clone();
    cfg.effects = if on {
        cfg.effects.with(Effect::UnbalancedMagneticPull)
    } else {
        cfg.effects.without(Effect::UnbalancedMagneticPull)
    };
    Spindle::new(cfg).unwrap()
}

/// Sum of the radial loads [Fx, Fy] the two bearings of a pair carry (both
/// frames share x and y, pair.rs) [N].
fn pair_radial_n(p: &PairState) -> [f64; 2] {
    let (a, b) = (&p.bearings[0].applied_load, &p.bearings[1].applied_load);
    [a[0] + b[0], a[1] + b[1]]
}

#[test]
fn magnetic_pull_loads_the_pairs_in_static_equilibrium_and_heats_the_front_pair() {
    let nose_n = 200.0;
    let base = Spindle::preset("seed-ceramic-spindle")
        .unwrap()
        .with_radial_load(nose_n)
        .unwrap();
    let (on, off) = (with_ump(&base, true), with_ump(&base, false));
    let f = on.magnetic_pull_n();
    assert!(f > 0.0 && off.magnetic_pull_n() == 0.0);
    let (a, b) = (
        on.thermal_state(12_000.0).unwrap(),
        off.thermal_state(12_000.0).unwrap(),
    );
    // Statics of the rigid shaft from the solved ball loads: the pairs carry
    // the pull (y) and the nose load (x) between them ...
    let (fr, rr) = (pair_radial_n(&a.front), pair_radial_n(&a.rear));
    let tol = 1e-6 * base.front.preload.force_n();
    assert!((fr[1] + rr[1] - f).abs() < tol, "{fr:?} {rr:?} {f}");
    assert!((fr[0] + rr[0] - nose_n).abs() < tol, "{fr:?} {rr:?}");
    // ... and the moments about the front pair centre balance: the pull at
    // the core (c behind the front pair), the nose load a in front of it.
    let p = &on.config.params;
    let l = p.front_span_m + p.rear_span_m;
    let c = on.config.magnetic_pull.as_ref().unwrap().core_from_front_pair_m;
    assert!((rr[1] * l - f * c).abs() < tol * l, "{} vs {}", rr[1] * l, f * c);
    assert!((rr[0] * l + nose_n * p.nose_length_m).abs() < tol * l);
    // The extra radial load raises the front pair's friction heat and
    // its temperatures.
    let front_w = |s: &SpindleState| s.bearing_heat[..2].iter().map(|h| h.heat.total_w()).sum::<f64>();
    assert!(front_w(&a) > front_w(&b), "{} vs {}", front_w(&a), front_w(&b));
    for node in ["front_inner", "front_balls", "front_outer"] {
        let (x, y) = (a.temperatures.get(node).unwrap(), b.temperatures.get(node).unwrap());
        assert!(x > y, "{node}: {x} vs {y}");
    }
    // Still a steady state: all heat leaves through the boundaries.
    assert!((a.boundary_flow_w - a.total_heat_w).abs() < 1e-6 * a.total_heat_w);
}

#[test]
fn magnetic_pull_agrees_with_the_rotor_model_and_vanishes_without_flux() {
    use thermobear::effects::Effect;
    use thermobear::rotor::spindle_vibration::{RowMaterial, SpindleVibration, SpindleVibrationConfig};
    let sp = Spindle::preset("seed-ceramic-spindle").unwrap();
    // Default: UMP off in both models.
    let mut vc = SpindleVibrationConfig::seed(RowMaterial::Hybrid);
    assert_eq!(sp.config.effects, vc.effects);
    assert!(!sp.config.effects.has(Effect::UnbalancedMagneticPull));
    // With the effect on, the rotor model's static pull is the thermal one.
    vc.effects = vc.effects.with(Effect::UnbalancedMagneticPull);
    let rotor = SpindleVibration::new(vc).unwrap();
    let spec = rotor.rotor().spec();
    let rotor_pull = spec.magnetic_pull.as_ref().unwrap();
    let on = with_ump(&sp, true);
    assert!((on.magnetic_pull_n() - rotor_pull.static_force_n()).abs() < 1e-9 * rotor_pull.static_force_n());
    // Same place between the pair centres (fraction of the span) in both models.
    let z: Vec<f64> = spec.bearings.iter().map(|b| b.position_m).collect();
    let (front, rear) = (0.5 * (z[0] + z[1]), 0.5 * (z[2] + z[3]));
    let p = &on.config.params;
    let c = on.config.magnetic_pull.as_ref().unwrap().core_from_front_pair_m;
    let frac = (rotor_pull.position_m - front) / (rear - front);
    assert!((c / (p.front_span_m + p.rear_span_m) - frac).abs() < 1e-12, "{frac}");
    // No flux, no pull: identical to the effect off.
    let mut cfg = on.config.clone();
    cfg.magnetic_pull.as_mut().unwrap().pull.flux_density_t = 0.0;
    let zero = Spindle::new(cfg).unwrap();
    assert_eq!(zero.magnetic_pull_n(), 0.0);
    let (a, b) = (
        zero.thermal_state(12_000.0).unwrap(),
        with_ump(&sp, false).thermal_state(12_000.0).unwrap(),
    );
    assert_eq!(a.temperatures.temperatures_c, b.temperatures.temperatures_c);
    assert_eq!(a.front, b.front);
    // The effect without air-gap data is refused.
    let mut cfg = on.config.clone();
    cfg.magnetic_pull = None;
    assert!(matches!(Spindle::new(cfg), Err(Error::Config { .. })));
}

#[test]
fn extra_heat_enters_the_front_bearings_and_the_heat_balance() {
    use thermobear::thermal::row_heat::oil_temperature_c;
    let base = spring_spindle("seed-ceramic-spindle", 400.0);
    let extra_w = 80.0;
    let sp = Spindle::new(SpindleConfig {
        extra_heat_w: extra_w,
        ..base.config.clone()
    })
    .unwrap();
    let (s0, s) = (
        base.thermal_state(12_000.0).unwrap(),
        sp.thermal_state(12_000.0).unwrap(),
    );
    // Each front bearing reports its friction heat at the solved state plus
    // half the extra heat, split like rolling heat (1/4, 1/2, 1/4); the
    // friction heat is recomputed at the converged temperatures, which the
    // fixed point leaves within its tolerance (1e-4 K): 1e-3 W.
    let p = &sp.config.params;
    let ball_c = s.temperatures.get("front_balls").unwrap();
    let oil_c = oil_temperature_c(sp.config.effects, p.oil_air_temperature_c, Some(ball_c));
    for k in 0..2 {
        let friction = sp.row_heat(&s.front.bearings[k], &p.front_bearing, oil_c).unwrap();
        let h = &s.bearing_heat[k];
        let added = h.heat.total_w() - friction.heat.total_w();
        assert!((added - 0.5 * extra_w).abs() < 1e-3, "{added}");
        let ring = h.split.outer_ring_w - friction.split.outer_ring_w;
        let balls = h.split.balls_w - friction.split.balls_w;
        assert!((ring - 0.125 * extra_w).abs() < 1e-3 && (balls - 0.25 * extra_w).abs() < 1e-3);
    }
    // Sources = motor + bearings (extra included); all of it leaves.
    let bearings: f64 = s.bearing_heat.iter().map(|h| h.heat.total_w()).sum();
    assert!((s.total_heat_w - s.motor_losses_w - bearings).abs() < 1e-9 * s.total_heat_w);
    assert!((s.boundary_flow_w - s.total_heat_w).abs() < 1e-6 * s.total_heat_w);
    // The heat warms the front set more than the rear.
    let rise = |n: &str| s.temperatures.get(n).unwrap() - s0.temperatures.get(n).unwrap();
    assert!(rise("front_outer") > rise("rear_outer") && rise("front_outer") > 0.5);
    // Zero is the spindle as it was; a negative heat is refused by name.
    let zero = Spindle::new(SpindleConfig {
        extra_heat_w: 0.0,
        ..base.config.clone()
    })
    .unwrap();
    assert_eq!(zero.thermal_state(12_000.0).unwrap().total_heat_w, s0.total_heat_w);
    match Spindle::new(SpindleConfig {
        extra_heat_w: -1.0,
        ..base.config.clone()
    }) {
        Err(Error::Config { field, .. }) => assert_eq!(field, "extra_heat_w"),
        other => panic!("{other:?}"),
    }
}

#[test]
fn unknown_heat_law_is_the_extra_heat_of_its_speed() {
    // The law max(0, a x + b x^2), x = n / n_ref, at 12,000 rpm of a 10,000
    // rpm reference: 30 * 1.2 + 20 * 1.44 = 64.8 W, the same state as a
    // constant extra heat of 64.8 W; a law clipped at zero adds nothing.
    let base = spring_spindle("seed-ceramic-spindle", 400.0);
    let with = |e: f64, a: f64, b: f64, r: f64| {
        Spindle::new(SpindleConfig {
            extra_heat_w: e,
            unknown_heat_linear_w: a,
            unknown_heat_quadratic_w: b,
            unknown_heat_reference_rpm: r,
            ..base.config.clone()
        })
    };
    let law = with(0.0, 30.0, 20.0, 10_000.0).unwrap();
    assert!((law.config.extra_heat_at_w(12_000.0) - 64.8).abs() < 1e-12);
    let (s, c) = (
        law.thermal_state(12_000.0).unwrap(),
        with(64.8, 0.0, 0.0, 0.0).unwrap().thermal_state(12_000.0).unwrap(),
    );
    assert!((s.total_heat_w - c.total_heat_w).abs() < 1e-9 * c.total_heat_w);
    let negative = with(0.0, -30.0, 0.0, 10_000.0).unwrap();
    assert_eq!(negative.config.extra_heat_at_w(12_000.0), 0.0);
    let t0 = base.thermal_state(12_000.0).unwrap().total_heat_w;
    assert_eq!(negative.thermal_state(12_000.0).unwrap().total_heat_w, t0);
    // A law without its reference speed is refused by name.
    match with(0.0, 30.0, 0.0, 0.0) {
        Err(Error::Config { field, .. }) => assert_eq!(field, "unknown_heat_reference_rpm"),
        other => panic!("{other:?}"),
    }
}
