//! High-speed quasi-statics: zero-speed limit, Jacobians, speed trends,
#![allow(clippy::needless_range_loop)]
//! centrifugal force, equilibrium, forward map.

use thermobear::bearing::{
    inner_ring_expansion_per_omega2, BearingModel, BearingState, GyroCoupleSign, RacewayControl, SolveOptions,
    WarmStart,
};
use thermobear::units::rpm_to_rad_s;
use thermobear::{Bearing, Effect, EffectSet};

fn model(name: &str) -> BearingModel {
    BearingModel::new(&Bearing::preset(name).unwrap()).unwrap()
}

/// Options with the ring tilt solved from the applied moments (full 5-DOF
/// equilibrium; the default holds the ring level and refuses a moment).
fn free_tilt() -> SolveOptions {
    SolveOptions {
        tilt: thermobear::bearing::Tilt::Free,
        ..SolveOptions::default()
    }
}

fn thrust(fa: f64) -> [f64; 5] {
    [0.0, 0.0, fa, 0.0, 0.0]
}

#[test]
fn zero_speed_limit_equals_static_model() {
    let o = free_tilt();
    for (name, load) in [
        ("6208", [1189.9, 0.0, 2680.9, 0.0, 0.0]),
        ("7009C-hybrid", [400.0, 150.0, 900.0, 2.0, -3.0]),
    ] {
        let m = model(name);
        let st = m.solve_static(&load, &o).unwrap();
        // Start the high-speed model away from the static answer so that it
        // has to find it by itself.
        let start = st.displacement.map(|v| 1.2 * v);
        let qs = m.solve_from(&load, 0.0, &o, start, &mut WarmStart::new()).unwrap();
        for i in 0..5 {
            let d = st.displacement[i];
            assert!((qs.displacement[i] - d).abs() < 1e-9 * d.abs() + 1e-15, "{name} q[{i}]");
        }
        for (a, b) in st.balls.iter().zip(&qs.balls) {
            assert!((a.inner_load_n - b.inner_load_n).abs() < 1e-6 * (1.0 + a.inner_load_n));
            assert!((a.outer_load_n - b.outer_load_n).abs() < 1e-6 * (1.0 + a.outer_load_n));
            if a.inner_load_n > 0.0 {
                assert!((a.inner_contact_angle_rad - b.inner_contact_angle_rad).abs() < 1e-9);
                assert!((a.outer_contact_angle_rad - b.outer_contact_angle_rad).abs() < 1e-9);
                assert!((a.inner_deflection_m - b.inner_deflection_m).abs() < 1e-14);
            }
        }
        for i in 0..5 {
            for j in 0..5 {
                let s = (st.stiffness_matrix[i][i] * st.stiffness_matrix[j][j]).sqrt();
                assert!((st.stiffness_matrix[i][j] - qs.stiffness_matrix[i][j]).abs() < 1e-7 * s);
            }
        }
        assert!((st.axial_stiffness_seed_n_per_m / qs.axial_stiffness_seed_n_per_m - 1.0).abs() < 1e-8);
    }
}

#[test]
fn condensed_stiffness_matches_finite_differences_of_forward_map() {
    for (name, control) in [("6208", RacewayControl::Outer), ("7009C-hybrid", RacewayControl::Inner)] {
        let m = model(name);
        let o = SolveOptions {
            raceway_control: control,
            ..free_tilt()
        };
        let load = [800.0, 200.0, 1500.0, 3.0, -5.0];
        let s = m.solve(&load, 16_000.0, &o).unwrap();
        let q = s.displacement;
        let mut warm = WarmStart::new();
        let f0 = m.ring_forces(&q, 16_000.0, &o, &mut warm).unwrap();
        for c in 0..5 {
            let h = if c < 3 { 1e-10 } else { 3e-9 };
            let mut qp = q;
            let mut qm = q;
            qp[c] += h;
            qm[c] -= h;
            let rp = m.ring_forces(&qp, 16_000.0, &o, &mut warm).unwrap().reaction;
            let rm = m.ring_forces(&qm, 16_000.0, &o, &mut warm).unwrap().reaction;
            for r in 0..5 {
                let fd = -(rp[r] - rm[r]) / (2.0 * h);
                let k = f0.stiffness_matrix[r][c];
                let scale = (f0.stiffness_matrix[r][r] * f0.stiffness_matrix[c][c]).sqrt();
                assert!((fd - k).abs() < 1e-5 * scale, "{name} K[{r}][{c}] = {k} vs fd {fd}");
            }
        }
        // At equilibrium the reaction balances the load.
        for i in 0..5 {
            assert!((f0.reaction[i] + load[i]).abs() < 1e-6 * (1.0 + load[i].abs()));
        }
    }
}

/// Sum of inner-contact forces on the inner ring from the ball states
/// (outer-raceway control: no friction at the inner contact).
fn ball_force_sum(m: &BearingModel, s: &BearingState) -> [f64; 5] {
    let r = m.bearing().geometry.inner_groove_centre_radius_m();
    let mut f = [0.0; 5];
    for b in &s.balls {
        let (sp, cp) = b.azimuth_rad.sin_cos();
        let fz = b.inner_load_n * b.inner_contact_angle_rad.sin();
        let fr = b.inner_load_n * b.inner_contact_angle_rad.cos();
        f[0] += fr * cp;
        f[1] += fr * sp;
        f[2] += fz;
        f[3] += fz * r * sp;
        f[4] -= fz * r * cp;
    }
    f
}

#[test]
fn high_speed_state_is_in_equilibrium() {
    let m = model("6208");
    let load = [1189.9, 0.0, 2680.9, 0.0, 10.0];
    let s = m.solve(&load, 16_000.0, &free_tilt()).unwrap();
    let f = ball_force_sum(&m, &s);
    for i in 0..5 {
        assert!(
            (f[i] - load[i]).abs() < 1e-6 * (1.0 + load[i].abs()),
            "{i}: {} vs {}",
            f[i],
            load[i]
        );
    }
    // Each ball: the outer load exceeds the inner one by about the centrifugal force.
    for b in &s.balls {
        assert!(b.outer_load_n > b.inner_load_n);
    }
}

#[test]
fn centrifugal_force_is_half_m_dm_omega_c_squared() {
    let b = Bearing::preset("7009C").unwrap();
    let m = BearingModel::new(&b).unwrap();
    let s = m.solve(&thrust(300.0), 18_000.0, &SolveOptions::default()).unwrap();
    let mass = b.ball.density_kg_m3 * std::f64::consts::PI * b.geometry.ball_diameter_m.powi(3) / 6.0;
    for ball in &s.balls {
        let fc = 0.5 * mass * b.geometry.pitch_diameter_m * ball.orbit_speed_rad_s.powi(2);
        assert!((ball.centrifugal_force_n / fc - 1.0).abs() < 1e-12);
        // Orbit speed below half the shaft speed (epicyclic, Harris).
        assert!(ball.orbit_speed_rad_s < 0.5 * rpm_to_rad_s(18_000.0));
    }
    // A-16 with the seed's form Fc = pi rho D^3 dm omega_c^2 / 12.
    let ball = s.balls[0];
    let seed = std::f64::consts::PI
        * b.ball.density_kg_m3
        * b.geometry.ball_diameter_m.powi(3)
        * b.geometry.pitch_diameter_m
        * ball.orbit_speed_rad_s.powi(2)
        / 12.0;
    assert!((ball.centrifugal_force_n / seed - 1.0).abs() < 1e-12);
}

#[test]
fn speed_raises_outer_load_and_splits_the_contact_angles() {
    // Harris & Kotzalas (Advanced Concepts, ch. 3, thrust-loaded angular
    // contact bearing at speed): centrifugal force raises the outer contact
    // load, lowers the outer contact angle and raises the inner one. Seed B
    // (Fig. 13a) reports the opposite trend for 7009C; it contradicts the
    // ball equilibrium and is not reproduced.
    for name in ["7009C", "7009C-hybrid", "6208"] {
        let m = model(name);
        let o = SolveOptions::default();
        let mut last: Option<thermobear::bearing::BallState> = None;
        for n in [0.0, 6_000.0, 12_000.0, 18_000.0] {
            let b = m.solve(&thrust(300.0), n, &o).unwrap().balls[0];
            if let Some(p) = last {
                assert!(b.outer_load_n > p.outer_load_n, "{name} {n}");
                assert!(b.outer_contact_angle_rad < p.outer_contact_angle_rad, "{name} {n}");
                assert!(b.inner_contact_angle_rad > p.inner_contact_angle_rad, "{name} {n}");
            }
            last = Some(b);
        }
    }
}

#[test]
fn effects_switch_off_to_the_static_model() {
    // With every effect off the speed only sets the kinematics.
    let m = model("6208");
    let load = [1189.9, 0.0, 2680.9, 0.0, 0.0];
    let none = SolveOptions {
        effects: EffectSet::none(),
        ..Default::default()
    };
    let st = m.solve_static(&load, &none).unwrap();
    let s = m.solve(&load, 16_000.0, &none).unwrap();
    for i in 0..5 {
        assert!((s.displacement[i] - st.displacement[i]).abs() < 1e-7 * st.displacement[i].abs() + 1e-15);
    }
    assert!(s.balls[0].orbit_speed_rad_s > 0.0 && s.balls[0].centrifugal_force_n == 0.0);
}

#[test]
fn ring_expansion_equals_a_radial_offset() {
    // The centrifugal growth of the inner ring enters the geometry
    // exactly like a radial raceway offset u_r.
    let b = Bearing::preset("6208").unwrap();
    let m = BearingModel::new(&b).unwrap();
    let n = 16_000.0;
    let w = rpm_to_rad_s(n);
    let u = inner_ring_expansion_per_omega2(&b) * w * w;
    assert!(u > 0.5e-6 && u < 3e-6, "u_r = {u}");
    let load = [1189.9, 0.0, 300.0, 0.0, 0.0];
    let with = m.solve(&load, n, &SolveOptions::default()).unwrap();
    let mut o = SolveOptions {
        effects: EffectSet::all().without(Effect::RingCentrifugalExpansion),
        ..Default::default()
    };
    o.offsets.radial_m = u;
    let offset = m.solve(&load, n, &o).unwrap();
    for (a, c) in with.balls.iter().zip(&offset.balls) {
        assert!((a.inner_load_n - c.inner_load_n).abs() < 1e-6 * (1.0 + a.inner_load_n));
    }
    // Expansion closes the clearance: more of the ring is loaded or the peak falls.
    let o0 = SolveOptions {
        effects: EffectSet::all().without(Effect::RingCentrifugalExpansion),
        ..Default::default()
    };
    let without = m.solve(&load, n, &o0).unwrap();
    assert!(with.max_inner_load_n() < without.max_inner_load_n());
}

#[test]
fn gyroscopic_couple_sign_option_changes_the_angles() {
    let m = model("6208");
    let s_d = m.solve(&thrust(300.0), 18_000.0, &SolveOptions::default()).unwrap();
    let o = SolveOptions {
        gyro_couple_sign: GyroCoupleSign::Reversed,
        ..Default::default()
    };
    let s_r = m.solve(&thrust(300.0), 18_000.0, &o).unwrap();
    let (d, r) = (s_d.balls[0], s_r.balls[0]);
    // The derived couple adds to the centrifugal splitting of the angles
    // under outer-raceway control; the reversed one works against it.
    let split = |b: &thermobear::bearing::BallState| b.inner_contact_angle_rad - b.outer_contact_angle_rad;
    assert!(split(&d) > split(&r));
    // Without the gyroscopic moment the sign is irrelevant.
    let no_gyro = EffectSet::all().without(Effect::GyroscopicMoment);
    let a = m
        .solve(
            &thrust(300.0),
            18_000.0,
            &SolveOptions {
                effects: no_gyro,
                ..Default::default()
            },
        )
        .unwrap();
    let b = m
        .solve(&thrust(300.0), 18_000.0, &SolveOptions { effects: no_gyro, ..o })
        .unwrap();
    assert_eq!(a.displacement, b.displacement);
    assert!(split(&a.balls[0]) < split(&d) && split(&a.balls[0]) > split(&r));
}

#[test]
fn forward_map_warm_and_cold_agree() {
    let m = model("6208");
    let o = SolveOptions::default();
    let q = [2.0e-5, 1.0e-6, 2.0e-4, 1e-5, 5e-4];
    let mut warm = WarmStart::new();
    let first = m.ring_forces(&q, 12_000.0, &o, &mut warm).unwrap();
    // Move along a path and come back: warm starts must not change the answer.
    for k in 1..5 {
        let qk = q.map(|v| v * (1.0 + 0.01 * k as f64));
        m.ring_forces(&qk, 12_000.0, &o, &mut warm).unwrap();
    }
    let again = m.ring_forces(&q, 12_000.0, &o, &mut warm).unwrap();
    for i in 0..5 {
        assert!((first.reaction[i] - again.reaction[i]).abs() < 1e-9 * (1.0 + first.reaction[i].abs()));
    }
    let (cold, balls) = thermobear::bearing::ring_forces(m.bearing(), &q, 12_000.0, &o).unwrap();
    assert_eq!(balls.len(), 9);
    for i in 0..5 {
        assert!((first.reaction[i] - cold[i]).abs() < 1e-9 * (1.0 + cold[i].abs()));
    }
    assert!(m
        .ring_forces(&[f64::NAN, 0.0, 0.0, 0.0, 0.0], 0.0, &o, &mut warm)
        .is_err());
}

#[test]
fn unloaded_bearing_at_speed_rests_on_the_outer_raceway() {
    let m = model("6208");
    let s = m.solve(&[0.0; 5], 10_000.0, &SolveOptions::default()).unwrap();
    assert_eq!(s.displacement, [0.0; 5]);
    for b in &s.balls {
        assert_eq!(b.inner_load_n, 0.0);
        assert!((b.outer_load_n - b.centrifugal_force_n).abs() < 1e-9 * b.centrifugal_force_n);
    }
}

#[test]
fn load_and_speed_grid_converges_to_equilibrium() {
    // Light, heavy, tilting and mixed loads from standstill to 60,000 rpm:
    // every solve converges and the ball forces balance the load (moments
    // included: the tilt is free).
    let o = free_tilt();
    for name in ["6208", "7009C", "7008C-hybrid", "6208-ceramic"] {
        let m = model(name);
        for load in [
            [1000.0, 0.0, 0.0, 0.0, 0.0],
            [0.0, 0.0, 50.0, 0.0, 0.0],
            [0.0, 0.0, 5000.0, 0.0, 0.0],
            [2000.0, 0.0, 100.0, 0.0, 0.0],
            [0.0, 0.0, 0.0, 0.0, 20.0],
            [100.0, 50.0, 300.0, 1.0, -2.0],
            [5.0, 0.0, 0.0, 0.0, 0.0],
        ] {
            for n in [0.0, 10_000.0, 30_000.0, 60_000.0] {
                let s = m
                    .solve(&load, n, &o)
                    .unwrap_or_else(|e| panic!("{name} {load:?} {n}: {e}"));
                let f = ball_force_sum(&m, &s);
                for i in 0..5 {
                    assert!(
                        (f[i] - load[i]).abs() < 1e-6 * (1.0 + load[i].abs()),
                        "{name} {load:?} {n} [{i}]"
                    );
                }
            }
        }
    }
}

/// Found by hypothesis: at a vanishing speed and a light load most balls are
/// out of contact and the quasi-static model is ill-posed. The solver must
/// say so instead of returning a NaN stiffness.
#[test]
fn vanishing_speed_with_free_balls_is_an_error_not_nan() {
    let b = thermobear::Bearing::preset("6208").unwrap();
    let m = thermobear::bearing::BearingModel::new(&b).unwrap();
    let opts = thermobear::bearing::SolveOptions {
        tilt: thermobear::bearing::state::Tilt::held_level(),
        ..Default::default()
    };
    match m.solve(&[6.0, 0.0, 0.25, 0.0, 0.0], 1e-12, &opts) {
        Ok(s) => {
            assert!(s.stiffness_matrix.iter().flatten().all(|v| v.is_finite()));
            assert!(s.balls.iter().all(|x| x.orbit_speed_rad_s.is_finite()));
        }
        Err(e) => assert!(matches!(e, thermobear::Error::Convergence { .. }), "{e}"),
    }
}
