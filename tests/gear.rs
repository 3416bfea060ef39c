//! Integration checks of the gear-pair API as the 8-DOF dynamics use it.

use std::f64::consts::PI;
use thermobear::gear::{iso_stiffness, GearPair, IsoStiffnessOptions, MeshOptions, MeshStiffness, TransmissionError};

fn quick() -> MeshOptions {
    MeshOptions {
        table_points: 128,
        path_points: 41,
        quadrature_intervals: 32,
    }
}

#[test]
fn seed_pair_feeds_the_dynamics() {
    let p = GearPair::preset("seed-electric-drive").unwrap();
    let rb = p.base_radius_m();
    // Base radii: r_b = z m_n cos(alpha_t) / (2 cos(beta)); their ratio is the gear ratio.
    assert!((rb[1] / rb[0] - 78.0 / 29.0).abs() < 1e-12);
    assert!(p.line_of_action_angle_rad() > 0.0 && p.line_of_action_angle_rad() < PI / 4.0);
    // Torque balance at the pitch point: T1 / r_b1 = T2 / r_b2 (same base-circle force).
    assert!((p.input_torque_n_m() / rb[0] - p.output_torque_n_m() / rb[1]).abs() < 1e-9);
    // One mesh period at 6500 rpm: 60 / (29 * 6500) s.
    let t = p.mesh_period_s(6500.0).unwrap();
    assert!((t - 60.0 / (29.0 * 6500.0)).abs() < 1e-15);

    let k = MeshStiffness::potential_energy_with(&p, &quick()).unwrap();
    let s = k.samples(64);
    assert_eq!(s.len(), 64);
    assert!(s.iter().all(|v| v.is_finite() && *v > 0.0));
    // Both sample sets cover the same single period: every other of 128 is one of 64.
    let s2 = k.samples(128);
    for i in 0..64 {
        assert!((s2[2 * i] - s[i]).abs() <= 1e-9 * s[i]);
    }
    // Normal-direction stiffness for delta_n of A-45: k_t / cos^2(beta).
    let kn = k.normal_direction(&p).unwrap();
    let c2 = p.helix_angle_rad().cos().powi(2);
    assert!((kn.mean_n_per_m() * c2 - k.mean_n_per_m()).abs() < 1e-6 * k.mean_n_per_m());
    // Mean stiffness of the order of ISO's c_gamma_alpha b.
    let iso = iso_stiffness(&p, &IsoStiffnessOptions::default()).unwrap();
    let r = k.mean_n_per_m() / iso.mesh_alpha_n_per_m();
    assert!(r > 0.75 && r < 1.35, "{r}");

    let te = TransmissionError::harmonics(vec![(10e-6, 0.0)]).unwrap();
    let e = te.samples(64);
    assert!((e.iter().cloned().fold(f64::MIN, f64::max) - 10e-6).abs() < 1e-12);
}

#[test]
fn mesh_stiffness_is_deterministic() {
    let p = GearPair::preset("seed-electric-drive").unwrap();
    let a = MeshStiffness::potential_energy_with(&p, &quick()).unwrap();
    let b = MeshStiffness::potential_energy_with(&p, &quick()).unwrap();
    assert_eq!(a, b);
}

#[test]
fn bad_mesh_options_are_refused() {
    let p = GearPair::preset("seed-electric-drive").unwrap();
    let bad = MeshOptions {
        table_points: 2,
        ..quick()
    };
    assert!(MeshStiffness::potential_energy_with(&p, &bad).is_err());
    assert!(MeshStiffness::from_samples(vec![1e8, -1.0]).is_err());
    assert!(MeshStiffness::from_samples(vec![1e8, f64::NAN]).is_err());
}
