//! Zero-speed bearing statics: closed forms, published numbers, equilibrium.
#![allow(clippy::needless_range_loop)]

use thermobear::bearing::{
    contact_stiffness_n_per_m, thrust_contact_angle, BearingGeometry, BearingModel, BearingState, SolveOptions,
};
use thermobear::{Bearing, Error, Material};

fn model(name: &str) -> BearingModel {
    BearingModel::new(&Bearing::preset(name).unwrap()).unwrap()
}

/// Options with the ring tilt solved from the applied moments (the default
/// holds the ring level and refuses a moment).
fn free_tilt() -> SolveOptions {
    SolveOptions {
        tilt: thermobear::bearing::Tilt::Free,
        ..SolveOptions::default()
    }
}

/// Sum of the ball forces on the inner ring, from the per-ball states.
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
fn thrust_only_angle_agrees_with_general_solver() {
    for name in ["6208", "7009C", "7008C-hybrid"] {
        let m = model(name);
        let fa = 1200.0;
        let a = thrust_contact_angle(&m, fa).unwrap();
        let s = m
            .solve_static(&[0.0, 0.0, fa, 0.0, 0.0], &SolveOptions::default())
            .unwrap();
        let z = m.ball_count() as f64;
        for b in &s.balls {
            assert!((b.inner_contact_angle_rad - a).abs() < 1e-10, "{name}");
            // Each ball carries Fa / (Z sin a).
            assert!((b.inner_load_n - fa / (z * a.sin())).abs() < 1e-7 * b.inner_load_n);
        }
        // ISO displacement: dz = A cos(a0) tan(a) (groove centres in one plane at q = 0).
        let g = &m.bearing().geometry;
        let dz = g.curvature_centre_distance_m() * g.free_contact_angle_rad.cos() * a.tan();
        assert!((s.displacement[2] - dz).abs() < 1e-12);
        assert!(s.displacement[0].abs() < 1e-15 && s.displacement[4].abs() < 1e-14);
    }
}

#[test]
fn hertz_stiffness_is_the_derivative_of_the_load_deflection_law() {
    // Pure thrust: Fa = Z K_n(a) delta^1.5 sin a with delta = L - A. The
    // axial stiffness of the 5x5 matrix must equal dFa/d(dz) from two
    // neighbouring solves (central difference of the load-deflection curve).
    let m = model("6208");
    let o = SolveOptions::default();
    let solve = |fa: f64| m.solve_static(&[0.0, 0.0, fa, 0.0, 0.0], &o).unwrap();
    let fa = 2000.0;
    let s = solve(fa);
    let h = 0.5;
    let kfd = 2.0 * h / (solve(fa + h).displacement[2] - solve(fa - h).displacement[2]);
    assert!((s.stiffness_matrix[2][2] / kfd - 1.0).abs() < 1e-6);
    // Contact stiffness 1.5 K^(2/3) Q^(1/3) is dQ/d delta of Q = K delta^1.5.
    let k = m.ball_constant(0.3);
    let delta = 12e-6;
    let q = |d: f64| k * d.powf(1.5);
    let fd = (q(delta + 1e-11) - q(delta - 1e-11)) / 2e-11;
    assert!((contact_stiffness_n_per_m(k, q(delta)) / fd - 1.0).abs() < 1e-6);
}

#[test]
fn stiffness_matrix_is_symmetric_at_zero_speed() {
    // A conservative (Hertz potential) system has a symmetric Hessian. The
    // textbook model keeps the ball force on the line of the groove centres
    // while K depends weakly on the contact angle (gamma = D cos a / dm), which
    // leaves a relative asymmetry of order dK/da / K * (angle change) ~ 1e-5;
    // with K frozen the matrix is symmetric to round-off (unit test
    // `statics::tests::frozen_contact_constants_give_exact_symmetry`).
    let m = model("7009C");
    let s = m
        .solve_static(&[900.0, -300.0, 1500.0, 8.0, -12.0], &free_tilt())
        .unwrap();
    let k = s.stiffness_matrix;
    let r = m.bearing().geometry.inner_groove_centre_radius_m();
    let sc = [1.0, 1.0, 1.0, 1.0 / r, 1.0 / r];
    let kmax = (0..5).map(|i| k[i][i] * sc[i] * sc[i]).fold(0.0, f64::max);
    for i in 0..5 {
        for j in 0..5 {
            let d = (k[i][j] - k[j][i]) * sc[i] * sc[j];
            assert!(d.abs() < 1e-4 * kmax, "K[{i}][{j}] asymmetric");
        }
        assert!(k[i][i] > 0.0);
    }
}

#[test]
fn solved_state_is_in_equilibrium() {
    for (name, load) in [
        ("6208", [1189.9, 0.0, 2380.9, 0.0, 0.0]),
        ("6208", [500.0, 200.0, 0.0, 3.0, 5.0]),
        ("7008C", [300.0, 0.0, 800.0, 0.0, 4.0]),
    ] {
        let m = model(name);
        let s = m.solve_static(&load, &free_tilt()).unwrap();
        let f = ball_force_sum(&m, &s);
        for i in 0..5 {
            assert!(
                (f[i] - load[i]).abs() < 1e-6 * (1.0 + load[i].abs()),
                "{name} {i}: {} vs {}",
                f[i],
                load[i]
            );
        }
    }
}

#[test]
fn pure_radial_load_with_clearance_unloads_part_of_the_ring() {
    let m = model("6208");
    let s = m
        .solve_static(&[1000.0, 0.0, 0.0, 0.0, 0.0], &SolveOptions::default())
        .unwrap();
    // Harris & Kotzalas (Essential Concepts, ch. 7): positive clearance gives a
    // loaded zone of less than 180 deg.
    assert!(s.loaded_zone_rad() < std::f64::consts::PI);
    assert!(s.balls.iter().any(|b| b.inner_load_n == 0.0));
    // Symmetry about the load line.
    let z = s.balls.len();
    for j in 1..z {
        assert!((s.balls[j].inner_load_n - s.balls[z - j].inner_load_n).abs() < 1e-8 * s.max_inner_load_n());
    }
    // Open gaps are negative approaches.
    for b in s.balls.iter().filter(|b| b.inner_load_n == 0.0) {
        assert!(b.inner_deflection_m <= 0.0);
    }
}

#[test]
fn stribeck_load_distribution_for_zero_clearance() {
    // Zero clearance, pure radial load: delta_j = delta_r cos psi_j exactly, so
    // Q_max = Fr / sum(cos^2.5 psi_j) over the loaded half. Stribeck (1901),
    // Harris & Kotzalas, Essential Concepts (5th ed.), eq. 7.27: Q_max ~ 4.37 Fr / Z.
    let g = BearingGeometry::deep_groove(12, 12e-3, 60e-3, 0.52, 0.53, 0.0, 40e-3, 80e-3, 18e-3).unwrap();
    let b = Bearing::new("zero-clearance", g, Material::steel_52100(), Material::steel_52100()).unwrap();
    let m = BearingModel::new(&b).unwrap();
    let fr = 2000.0;
    let s = m
        .solve_static(&[fr, 0.0, 0.0, 0.0, 0.0], &SolveOptions::default())
        .unwrap();
    let z = m.ball_count();
    let sum: f64 = (0..z)
        .map(|j| (2.0 * std::f64::consts::PI * j as f64 / z as f64).cos())
        .filter(|c| *c > 0.0)
        .map(|c| c.powf(2.5))
        .sum();
    let qmax = s.max_inner_load_n();
    assert!((qmax - fr / sum).abs() < 1e-6 * qmax, "{qmax} vs {}", fr / sum);
    let factor = qmax * z as f64 / fr;
    assert!((factor / 4.37 - 1.0).abs() < 0.01, "Stribeck factor {factor}");
}

#[test]
fn degenerate_and_bad_loads() {
    let m = model("6208");
    let o = SolveOptions::default();
    // Zero load: the concentric, unloaded state.
    let s = m.solve_static(&[0.0; 5], &o).unwrap();
    assert_eq!(s.displacement, [0.0; 5]);
    assert!(s.balls.iter().all(|b| b.inner_load_n == 0.0));
    let e = m.solve_static(&[f64::NAN, 0.0, 0.0, 0.0, 0.0], &o).unwrap_err();
    assert!(matches!(e, Error::Config { .. }));
    let ac = model("7009C");
    let e = ac.solve_static(&[0.0, 0.0, -100.0, 0.0, 0.0], &o).unwrap_err();
    assert!(e.to_string().contains("axial_n"), "{e}");
    // A deep-groove bearing takes thrust both ways, mirror-symmetric.
    let p = m.solve_static(&[0.0, 0.0, 700.0, 0.0, 0.0], &o).unwrap();
    let n = m.solve_static(&[0.0, 0.0, -700.0, 0.0, 0.0], &o).unwrap();
    assert!((p.displacement[2] + n.displacement[2]).abs() < 1e-15);
    // Too few iterations: a convergence error carrying its residual.
    let tight = SolveOptions {
        max_iterations: 1,
        ..free_tilt()
    };
    match m.solve_static(&[1189.9, 0.0, 2380.9, 0.0, 30.0], &tight) {
        Err(Error::Convergence { residual, .. }) => assert!(residual > 0.0 && residual.is_finite()),
        other => panic!("expected a convergence error, got {other:?}"),
    }
    let bad = SolveOptions { tolerance: 0.0, ..o };
    assert!(m.solve_static(&[100.0, 0.0, 0.0, 0.0, 0.0], &bad).is_err());
}

#[test]
fn raceway_offset_is_a_shift_of_the_displacement() {
    // An axial offset u_Ta of the groove centres is equivalent to
    // moving the ring by the same amount: dz(offset) = dz(0) - u_Ta.
    let m = model("6208");
    let load = [800.0, 0.0, 1500.0, 0.0, 0.0];
    let s0 = m.solve_static(&load, &SolveOptions::default()).unwrap();
    let mut o = SolveOptions::default();
    o.offsets.axial_m = 5e-6;
    let s1 = m.solve_static(&load, &o).unwrap();
    assert!((s1.displacement[2] - (s0.displacement[2] - 5e-6)).abs() < 1e-13);
    assert!((s1.balls[0].inner_load_n - s0.balls[0].inner_load_n).abs() < 1e-7 * s0.balls[0].inner_load_n);
    // A radial offset u_Tr closes the clearance: same as a bearing with
    // Pd' = Pd - 2 u_Tr.
    let mut o = SolveOptions::default();
    o.offsets.radial_m = 4e-6;
    let s2 = m.solve_static(&load, &o).unwrap();
    let g0 = &m.bearing().geometry;
    let g = BearingGeometry::deep_groove(
        g0.ball_count,
        g0.ball_diameter_m,
        g0.pitch_diameter_m,
        g0.inner_conformity,
        g0.outer_conformity,
        g0.diametral_clearance_m - 8e-6,
        g0.bore_m,
        g0.outer_diameter_m,
        g0.width_m,
    )
    .unwrap();
    let b = Bearing::new("tighter", g, Material::steel_52100(), Material::steel_52100()).unwrap();
    let s3 = BearingModel::new(&b)
        .unwrap()
        .solve_static(&load, &SolveOptions::default())
        .unwrap();
    for (a, b) in s2.balls.iter().zip(&s3.balls) {
        assert!((a.inner_load_n - b.inner_load_n).abs() < 1e-7 * (1.0 + b.inner_load_n));
    }
    assert!(s2.balls[0].inner_load_n != s0.balls[0].inner_load_n);
}

#[test]
fn iso_ts_16281_reference_displacements() {
    // Reference displacements for a deep-groove bearing (Z = 7, Dw = 11.5 mm,
    // Dpw = 43.5 mm, f_i = 0.52, f_o = 0.53, E = 210 GPa, nu = 0.3) under
    // 1000 N loads, ISO/TS 16281 method, as used to validate the open
    // implementation github.com/minzhun/ISO16281 (Test_BallBearing.py,
    // examples 1-5, values labelled MASTA). ISO/TS 16281 evaluates K at the
    // nominal angle; we use the actual angle, hence the 1e-4 tolerance.
    let mut steel = Material::steel_52100();
    steel.youngs_modulus_pa = 210e9;
    steel.poisson_ratio = 0.3;
    // The reference solves the ring free to tilt (a combined load without
    // moment tilts it); under pure radial or pure axial load the tilt is
    // zero either way.
    let o = free_tilt();
    let cases: [(f64, [f64; 5], usize, f64); 6] = [
        (0.0, [1000.0, 0.0, 0.0, 0.0, 0.0], 0, 15.1101),
        (0.0, [0.0, 0.0, 1000.0, 0.0, 0.0], 2, 133.5381),
        (0.01, [1000.0, 0.0, 0.0, 0.0, 0.0], 0, 21.223),
        (0.01, [0.0, 0.0, 1000.0, 0.0, 0.0], 2, 149.1717),
        (0.01, [1000.0, 0.0, 1000.0, 0.0, 0.0], 0, 19.5923),
        (0.01, [1000.0, 0.0, 1000.0, 0.0, 0.0], 2, 146.4603),
    ];
    for (pd_mm, load, dof, expected_um) in cases {
        let g =
            BearingGeometry::deep_groove(7, 11.5e-3, 43.5e-3, 0.52, 0.53, pd_mm * 1e-3, 30e-3, 62e-3, 16e-3).unwrap();
        let b = Bearing::new("iso-example", g, steel.clone(), steel.clone()).unwrap();
        let s = BearingModel::new(&b).unwrap().solve_static(&load, &o).unwrap();
        let got = s.displacement[dof] * 1e6;
        assert!(
            (got / expected_um - 1.0).abs() < 1e-4,
            "Pd {pd_mm} mm, load {load:?}: {got} um vs {expected_um} um"
        );
    }
}

#[test]
fn held_tilt_reports_the_holding_moment() {
    use thermobear::bearing::Tilt;
    let m = model("6208");
    let load = [1189.9, 0.0, 2380.9, 0.0, 0.0];
    // Free tilt: combined load without moment tilts the ring.
    let free = m.solve_static(&load, &free_tilt()).unwrap();
    assert!(free.displacement[4].abs() > 1e-4);
    // Holding the tilt found by the free solve reproduces it with zero holding moment.
    let at_free = SolveOptions {
        tilt: Tilt::Fixed {
            theta_x_rad: free.displacement[3],
            theta_y_rad: free.displacement[4],
        },
        ..Default::default()
    };
    let same = m.solve_static(&load, &at_free).unwrap();
    for i in 0..3 {
        assert!((same.displacement[i] - free.displacement[i]).abs() < 1e-12);
    }
    assert!(same.applied_load[4].abs() < 1e-6);
    // Level ring (the default): no tilt, and a holding moment equal to the
    // ball moments.
    let level = SolveOptions::default();
    assert_eq!(level.tilt, Tilt::held_level());
    let s = m.solve_static(&load, &level).unwrap();
    assert_eq!((s.displacement[3], s.displacement[4]), (0.0, 0.0));
    let f = ball_force_sum(&m, &s);
    for i in 0..5 {
        assert!((f[i] - s.applied_load[i]).abs() < 1e-6 * (1.0 + f[i].abs()), "{i}");
    }
    // Radial load on the ball at psi = 0 raises its axial force: the
    // moment that keeps the ring level is negative about y.
    assert!(s.applied_load[4] < 0.0);
    let bad = SolveOptions {
        tilt: Tilt::Fixed {
            theta_x_rad: f64::INFINITY,
            theta_y_rad: 0.0,
        },
        ..Default::default()
    };
    assert!(m.solve_static(&load, &bad).is_err());
}
