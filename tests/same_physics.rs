//! One implementation of each effect: the same bearing solved as a single
//! bearing and as a row of the spindle gives the same heat, contact angles
//! and stiffness; the spindle's ball conduction follows the preload row by
//! row; the rotor rows' operating-point cache stays bounded.

use thermobear::bearing::{Bearing, SolveOptions};
use thermobear::rotor::spindle_bearings::{PreloadedRow, ROW_CACHE_CAPACITY};
use thermobear::spindle::{Preload, Spindle, SpindleConfig, SEED_B_SPRING_RATE_N_PER_M};
use thermobear::thermal::coupled::{seed_a_mounting, CoupledBearing, CoupledOptions};
use thermobear::thermal::presets::{preloaded_contact, row_ball_raceway_resistance_k_per_w, SeedAParams};
use thermobear::thermal::row_heat::oil_temperature_c;

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / a.abs().max(b.abs()).max(1e-300)
}

/// Steel seed B spindle with a spring preload `force_n` and no nose load.
fn spindle(force_n: f64) -> Spindle {
    let mut c = SpindleConfig::preset("seed-steel-spindle").unwrap();
    c.preload = Preload::Spring {
        force_n,
        rate_n_per_m: SEED_B_SPRING_RATE_N_PER_M,
    };
    Spindle::new(c).unwrap()
}

/// The single-bearing model of the spindle's front bearing with the
/// spindle's lubricant, f0, mu_s and effects.
fn single(sp: &Spindle) -> CoupledBearing {
    let c = &sp.config;
    let b = &c.params.front_bearing;
    let mut params = SeedAParams::for_bearing(b);
    params.lubricant = c.params.lubricant.clone();
    let options = CoupledOptions {
        solve: SolveOptions {
            effects: c.effects,
            ..SolveOptions::default()
        },
        lubrication_factor_f0: c.params.lubrication_factor_f0,
        spin_friction_coefficient: c.spin_friction_coefficient,
        churning_oil_fraction: 0.02,
        ..CoupledOptions::default()
    };
    CoupledBearing::new(b, params.clone(), seed_a_mounting(&params), options).unwrap()
}

#[test]
fn single_bearing_and_spindle_row_agree_to_1e9() {
    let mut c = spindle(400.0).config.clone();
    c.churning_oil_fraction = 0.02;
    let sp = Spindle::new(c).unwrap();
    let one = single(&sp);
    let b = sp.config.params.front_bearing.clone();
    assert_eq!(b.name, "7009C");
    let (speed, oil_c) = (15_000.0, 45.0);
    let (front, _) = sp.isothermal(speed).unwrap();
    for row in &front.bearings {
        // The row carries the spring force alone (400 N plus the spring's
        // share of the speed's axial approach): the single bearing gets it.
        let fa = row.applied_load[2];
        assert!(fa > 400.0 && row.applied_load[0].hypot(row.applied_load[1]) < 1e-9 * fa);
        let (state, heat) = one.isothermal_heat(speed, fa, 0.0, oil_c).unwrap();
        let h = sp.row_heat(row, &b, oil_c).unwrap();
        let (s1, s2) = (heat.split, h.split);
        for (a, b) in [
            (s1.inner_ring_w, s2.inner_ring_w),
            (s1.balls_w, s2.balls_w),
            (s1.outer_ring_w, s2.outer_ring_w),
        ] {
            assert!(rel(a, b) < 1e-9, "heat split {s1:?} vs {s2:?}");
        }
        assert!(heat.heat.inner_spin_w > 0.0 && heat.churning_w > 0.0);
        for (p, q) in state.balls.iter().zip(&row.balls) {
            assert!(rel(p.inner_contact_angle_rad, q.inner_contact_angle_rad) < 1e-9);
            assert!(rel(p.outer_contact_angle_rad, q.outer_contact_angle_rad) < 1e-9);
        }
        // Every entry against the geometric mean of its diagonal pair
        // (the blocks carry N/m, N/rad and N m/rad).
        let (k1, k2) = (state.stiffness_matrix, row.stiffness_matrix);
        for i in 0..5 {
            for j in 0..5 {
                let s = (k1[i][i] * k1[j][j]).abs().sqrt();
                assert!(
                    (k1[i][j] - k2[i][j]).abs() <= 1e-9 * s,
                    "K[{i}][{j}] {} vs {}",
                    k1[i][j],
                    k2[i][j]
                );
            }
        }
    }
}

#[test]
fn oil_temperature_rule_is_the_supply_without_temperature_dependent_viscosity() {
    use thermobear::effects::Effect;
    let mut c = spindle(300.0).config.clone();
    c.effects = c.effects.without(Effect::TemperatureDependentViscosity);
    let sp = Spindle::new(c).unwrap();
    let s = sp.thermal_state(12_000.0).unwrap();
    let supply = sp.config.params.oil_air_temperature_c;
    assert_eq!(oil_temperature_c(sp.config.effects, supply, Some(80.0)), supply);
    let b = &sp.config.params.front_bearing;
    let h = sp.row_heat(&s.front.bearings[0], b, supply).unwrap();
    assert_eq!(h.heat, s.bearing_heat[0].heat);
    // With the effect on, the ball temperature is the oil's.
    assert_eq!(
        oil_temperature_c(thermobear::effects::EffectSet::all(), supply, Some(80.0)),
        80.0
    );
    assert_eq!(
        oil_temperature_c(thermobear::effects::EffectSet::all(), supply, None),
        supply
    );
}

/// Resistance of the inner ball-raceway link of a pair: 1 K across it.
fn link_resistance(sp: &Spindle, name: &str) -> f64 {
    let net = &sp.network.network;
    let link = net.links().iter().find(|l| l.name == name).unwrap();
    let mut t = vec![0.0; net.nodes().len()];
    t[link.a] = 1.0;
    1.0 / net.link_flow_w(name, &t, 0.0).unwrap()
}

#[test]
fn ball_conduction_follows_the_preload_on_both_rows() {
    let (lo, hi) = (spindle(200.0), spindle(800.0));
    for (tag, b) in [
        ("front", &lo.config.params.front_bearing),
        ("rear", &lo.config.params.rear_bearing),
    ] {
        let name = format!("{tag}_balls-inner");
        let (r_lo, r_hi) = (link_resistance(&lo, &name), link_resistance(&hi, &name));
        // Each row's own contact: Z Q sin(alpha) carries the preload (statics).
        for f in [200.0, 800.0] {
            let (q, a) = preloaded_contact(b, f).unwrap();
            let z = b.geometry.ball_count as f64;
            assert!(rel(z * q[0] * a[0].sin(), f) < 1e-6, "{tag}: {q:?} {a:?}");
        }
        let expect = |f: f64| {
            0.5 * row_ball_raceway_resistance_k_per_w(b, lo.config.params.ball_conduction, f)
                .unwrap()
                .0
        };
        assert!(rel(r_lo, expect(200.0)) < 1e-9 && rel(r_hi, expect(800.0)) < 1e-9);
        // The spot radius grows as Q^(1/3) (Hertz): four times the preload
        // gives a bit less than 4^(-1/3) of the resistance (the contact angle
        // grows with the load, so Q grows a little less than the preload).
        let ratio = r_hi / r_lo;
        assert!(
            ratio < 1.0 && (ratio - 4f64.powf(-1.0 / 3.0)).abs() < 0.03,
            "{tag}: {ratio}"
        );
    }
    // The rows differ: the 7008C's own (smaller) contact, not the 7009C's.
    let (f, r) = (
        link_resistance(&lo, "front_balls-inner"),
        link_resistance(&lo, "rear_balls-inner"),
    );
    assert!(rel(f, r) > 0.01, "front {f} rear {r}");
}

fn rss_pages() -> usize {
    std::fs::read_to_string("/proc/self/statm")
        .ok()
        .and_then(|s| s.split_whitespace().nth(1).and_then(|v| v.parse().ok()))
        .unwrap_or(0)
}

#[test]
fn row_cache_stays_bounded_over_a_thousand_preload_scan() {
    let b = Bearing::preset("7009C").unwrap();
    // One long-lived row visited at 1,000 operating points (each preload
    // step of a scan asks new speeds), then 1,000 preloads each on a row.
    let row = PreloadedRow::new(&b, 400.0, SolveOptions::default(), None).unwrap();
    for i in 0..1000 {
        row.operating_point(1000.0 + 10.0 * i as f64).unwrap();
        assert!(row.cached_points() <= ROW_CACHE_CAPACITY);
    }
    assert_eq!(row.cached_points(), ROW_CACHE_CAPACITY);
    // The most recent speed is still a hit (same point, no new entry).
    let p = row.operating_point(1000.0 + 10.0 * 999.0).unwrap();
    assert_eq!(row.operating_point(1000.0 + 10.0 * 999.0).unwrap(), p);
    assert_eq!(row.cached_points(), ROW_CACHE_CAPACITY);
    let before = rss_pages();
    let mut peak = before;
    for i in 0..1000 {
        let r = PreloadedRow::new(&b, 100.0 + i as f64, SolveOptions::default(), None).unwrap();
        r.operating_point(12_000.0).unwrap();
        assert_eq!(r.cached_points(), 1);
        peak = peak.max(rss_pages());
    }
    // Resident memory grows by less than 8 MB over the scan (4 kB pages).
    assert!(peak.saturating_sub(before) * 4096 < 8 << 20, "{before} -> {peak} pages");
}

#[test]
fn total_radial_displacement_is_signed_along_the_load() {
    use thermobear::spindle::coupled::radial_displacement_along_load_m;
    use thermobear::spindle::grid_point;
    let d = [3e-6, 4e-6, 0.0, 0.0, 0.0];
    assert!(rel(radial_displacement_along_load_m(&d, &[0.0, 5.0, 0.0, 0.0, 0.0]), 4e-6) < 1e-12);
    assert!(rel(radial_displacement_along_load_m(&d, &[-2.0, 0.0, 0.0, 0.0, 0.0]), -3e-6) < 1e-12);
    assert!(rel(radial_displacement_along_load_m(&d, &[0.0; 5]), 5e-6) < 1e-12);
    // A nose load pushes the shaft with it; the pair is axisymmetric, so the
    // reversed load gives the same signed displacement along it.
    let sp = spindle(300.0);
    let g = grid_point(&sp, 12_000.0, 300.0, 500.0).unwrap();
    let h = grid_point(&sp, 12_000.0, 300.0, -500.0).unwrap();
    assert!(g.mechanical_radial_displacement_m > 0.0, "{g:?}");
    assert!(rel(g.mechanical_radial_displacement_m, h.mechanical_radial_displacement_m) < 1e-6);
    assert_eq!(
        g.total_radial_displacement_m(),
        g.mechanical_radial_displacement_m + g.thermal_radial_displacement_m
    );
}
