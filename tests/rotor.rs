//! Physical checks of the rotor-dynamics core (src/rotor).

use std::f64::consts::PI;
use std::sync::Arc;

use nalgebra::{Complex, DVector};
use thermobear::materials::Material;
use thermobear::rotor::beam::shear_coefficient_hollow;
use thermobear::rotor::modal::{campbell, modes_at, CampbellOptions};
use thermobear::rotor::presets::{seed_b_spindle, SpindleParameters, NOSE_POSITION_M, REAR_BEARING_POSITIONS_M};
use thermobear::rotor::response::{static_deflection, unbalance_response, Unbalance};
use thermobear::rotor::transient::{
    mechanical_energy_j, time_response, vibration_summary, NonlinearForce, TransientOptions,
};
use thermobear::rotor::{BearingCoefficients, BearingSupport, LateralDof, Rotor, RotorSpec, ShaftSection};
use thermobear::{Error, Result};

/// Uniform solid shaft pinned (translational springs 1e6 x the beam's
/// 48 EI / L^3, free rotations) at both ends.
fn pinned_shaft(length_m: f64, diameter_m: f64, elements: usize) -> Rotor {
    let s = ShaftSection::new(length_m, diameter_m, 0.0, Material::shaft_steel()).unwrap();
    let k_pin = 1e6 * 48.0 * s.material.youngs_modulus_pa * s.second_moment_m4() / length_m.powi(3);
    let pin = Arc::new(BearingCoefficients::diagonal(k_pin, 0.0, 0.0, 0.0).unwrap());
    Rotor::new(RotorSpec {
        sections: vec![ShaftSection::new(length_m, diameter_m, 0.0, Material::shaft_steel()).unwrap()],
        disks: vec![],
        bearings: vec![
            BearingSupport::new("left", 0.0, pin.clone()),
            BearingSupport::new("right", length_m, pin),
        ],
        magnetic_pull: None,
        modal_damping_ratio: 0.0,
        max_element_length_m: length_m / elements as f64 * (1.0 + 1e-9),
    })
    .unwrap()
}

/// Distinct frequencies [Hz] of the undamped modes (each appears in both planes).
fn plane_frequencies_hz(r: &Rotor, count: usize) -> Vec<f64> {
    let (w, _) = r.undamped_modes(0.0).unwrap();
    w.iter().step_by(2).take(count).map(|w| w / (2.0 * PI)).collect()
}

#[test]
fn simply_supported_slender_beam_converges_to_euler_bernoulli() {
    // w_n = (n pi)^2 sqrt(EI / (rho A L^4)) (Blevins, table 8-1, pinned-pinned).
    let (l, d) = (1.0, 0.01);
    let s = ShaftSection::new(l, d, 0.0, Material::shaft_steel()).unwrap();
    let c = (s.material.youngs_modulus_pa * s.second_moment_m4() / (s.material.density_kg_m3 * s.area_m2())).sqrt();
    let exact: Vec<f64> = (1..=3)
        .map(|n| (n as f64 * PI).powi(2) * c / (l * l) / (2.0 * PI))
        .collect();
    let mut previous = f64::INFINITY;
    for elements in [3, 6, 12] {
        let f = plane_frequencies_hz(&pinned_shaft(l, d, elements), 3);
        let err = f
            .iter()
            .zip(&exact)
            .map(|(a, b)| ((a - b) / b).abs())
            .fold(0.0, f64::max);
        assert!(err < previous, "{elements} elements: error {err} did not decrease");
        previous = err;
    }
    assert!(previous < 1e-3, "12 elements: {previous}");
}

#[test]
fn thick_simply_supported_beam_matches_timoshenko_frequency_equation() {
    // Timoshenko beam, pinned-pinned, w = W sin(kz), psi = P cos(kz), k = n pi / L:
    // (kGA k^2 - rho A w^2)(EI k^2 + kGA - rho I w^2) = (kGA k)^2, lower root
    // (Timoshenko 1921; e.g. Han, Benaroya & Wei, J. Sound Vib. 225 (1999) 935, eq. 57).
    let (l, d) = (0.3, 0.1);
    let s = ShaftSection::new(l, d, 0.0, Material::shaft_steel()).unwrap();
    let m = &s.material;
    let (e, g) = (
        m.youngs_modulus_pa,
        m.youngs_modulus_pa / (2.0 * (1.0 + m.poisson_ratio)),
    );
    let kga = shear_coefficient_hollow(m.poisson_ratio, 0.0) * g * s.area_m2();
    let (ra, ri, ei) = (
        m.density_kg_m3 * s.area_m2(),
        m.density_kg_m3 * s.second_moment_m4(),
        e * s.second_moment_m4(),
    );
    let coarse = plane_frequencies_hz(&pinned_shaft(l, d, 15), 3);
    let fine = plane_frequencies_hz(&pinned_shaft(l, d, 45), 3);
    for n in 0..3 {
        let k = (n + 1) as f64 * PI / l;
        // a w^4 + b w^2 + c = 0.
        let a = ra * ri;
        let b = -(ra * (ei * k * k + kga) + ri * kga * k * k);
        let cc = kga * k * k * (ei * k * k + kga) - (kga * k).powi(2);
        let w2 = (-b - (b * b - 4.0 * a * cc).sqrt()) / (2.0 * a);
        let exact = w2.sqrt() / (2.0 * PI);
        let eb = (k * k) * (ei / ra).sqrt() / (2.0 * PI);
        let (e_coarse, e_fine) = ((coarse[n] - exact) / exact, (fine[n] - exact) / exact);
        // Converges from above (consistent mass: Rayleigh-Ritz upper bound).
        assert!(
            e_fine > 0.0 && e_fine < 0.5 * e_coarse,
            "mode {}: {e_coarse} -> {e_fine}",
            n + 1
        );
        assert!(e_fine < 1e-3, "mode {}: {} vs {exact}", n + 1, fine[n]);
        // Shear and rotary inertia matter here: Euler-Bernoulli is far off.
        assert!(eb > 1.05 * exact);
    }
}

#[test]
fn state_space_and_symmetric_eigen_agree_at_rest() {
    // Two independent eigen-solvers on the undamped, non-rotating spindle.
    let p = SpindleParameters {
        modal_damping_ratio: 0.0,
        max_element_length_m: 0.04,
        ..SpindleParameters::default()
    };
    let r = Rotor::new(seed_b_spindle(&p).unwrap()).unwrap();
    let sym = plane_frequencies_hz(&r, 3);
    let ss = modes_at(&r, 0.0, None, &CampbellOptions::default()).unwrap();
    for (k, f) in sym.iter().enumerate() {
        assert!(
            (ss[2 * k].frequency_hz - f).abs() < 1e-6 * f,
            "{} vs {f}",
            ss[2 * k].frequency_hz
        );
    }
}

#[test]
fn reduced_campbell_matches_full_model() {
    let p = SpindleParameters {
        max_element_length_m: 0.04,
        ..SpindleParameters::default()
    };
    let r = Rotor::new(seed_b_spindle(&p).unwrap()).unwrap();
    let speeds = [0.0, 30_000.0];
    let full_opts = CampbellOptions {
        modes: 6,
        ..CampbellOptions::default()
    };
    let full = campbell(&r, &speeds, &full_opts).unwrap();
    let red = campbell(
        &r,
        &speeds,
        &CampbellOptions {
            reduced_modes: Some(20),
            ..full_opts
        },
    )
    .unwrap();
    for (a, b) in full.points.iter().zip(&red.points) {
        for (ma, mb) in a.modes.iter().zip(&b.modes).take(6) {
            assert!((ma.frequency_hz - mb.frequency_hz).abs() < 2e-3 * ma.frequency_hz);
            assert_eq!(ma.whirl, mb.whirl);
        }
    }
}

#[test]
fn campbell_is_identical_on_one_and_two_threads() {
    let p = SpindleParameters {
        max_element_length_m: 0.04,
        ..SpindleParameters::default()
    };
    let r = Rotor::new(seed_b_spindle(&p).unwrap()).unwrap();
    let speeds: Vec<f64> = (0..8).map(|i| 4_000.0 * i as f64).collect();
    let opts = CampbellOptions {
        reduced_modes: Some(16),
        ..CampbellOptions::default()
    };
    let run = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| campbell(&r, &speeds, &opts).unwrap())
    };
    assert_eq!(run(1), run(2));
}

fn light_spindle(damping: f64) -> Rotor {
    let p = SpindleParameters {
        modal_damping_ratio: damping,
        max_element_length_m: 0.04,
        ..SpindleParameters::default()
    };
    Rotor::new(seed_b_spindle(&p).unwrap()).unwrap()
}

/// Complex amplitude of the `w` [rad/s] component over whole periods at the end of a record.
fn tail_phasor(t: &[f64], x: &[f64], w: f64, periods: f64) -> Complex<f64> {
    let dt = t[1] - t[0];
    let n = (periods * 2.0 * PI / w / dt).round() as usize;
    let start = t.len() - n;
    let mut acc = Complex::new(0.0, 0.0);
    for i in start..t.len() {
        acc += x[i] * Complex::from_polar(1.0, -w * t[i]);
    }
    acc * (2.0 / n as f64)
}

#[test]
fn steady_unbalance_response_matches_time_integration() {
    let r = light_spindle(0.02);
    let speed_rpm = 12_000.0;
    let w = speed_rpm * PI / 30.0;
    let u = [Unbalance::from_balance_grade(0.17, 2.5, r.mass_kg(), 30_000.0, 0.4).unwrap()];
    let steady = unbalance_response(&r, &u, &[speed_rpm], NOSE_POSITION_M).unwrap()[0];
    // 100 steps per revolution, 0.1 s (~11 decay times of the first mode).
    let opts = TransientOptions::new(speed_rpm, 0.1, 2.0 * PI / w / 100.0, NOSE_POSITION_M);
    let h = time_response(&r, &u, None, None, &opts).unwrap();
    let x = tail_phasor(&h.time_s, &h.displacement_x_m, w, 5.0);
    let y = tail_phasor(&h.time_s, &h.displacement_y_m, w, 5.0);
    let scale = steady.displacement_x_m.norm();
    assert!(
        (x - steady.displacement_x_m).norm() < 1e-2 * scale,
        "{x} vs {}",
        steady.displacement_x_m
    );
    assert!(
        (y - steady.displacement_y_m).norm() < 1e-2 * scale,
        "{y} vs {}",
        steady.displacement_y_m
    );
    // Velocity RMS of the steady state: W |X| / sqrt 2; 1X carries it.
    let v = vibration_summary(&h, speed_rpm, 0.08).unwrap();
    assert!((v.velocity_rms_m_per_s - steady.velocity_rms_x_m_per_s).abs() < 2e-2 * steady.velocity_rms_x_m_per_s);
    assert!(
        (v.velocity_orders_m_per_s[0] - steady.velocity_peak_x_m_per_s).abs() < 2e-2 * steady.velocity_peak_x_m_per_s
    );
    assert!(v.velocity_orders_m_per_s[1] < 1e-2 * v.velocity_orders_m_per_s[0]);
}

#[test]
fn undamped_gyroscopic_free_vibration_conserves_energy() {
    // No damping, spinning at 30,000 rpm: gyroscopic forces do no work, so
    // 1/2 v'Mv + 1/2 q'Kq stays constant (Newmark average acceleration
    // conserves it for linear systems).
    let r = light_spindle(0.0);
    let sys = r.matrices(30_000.0).unwrap();
    let mut q0 = DVector::zeros(r.dof_count());
    let nose = r.node_at(NOSE_POSITION_M).unwrap();
    q0[r.dof(nose, LateralDof::X)] = 2e-6;
    q0[r.dof(nose, LateralDof::ThetaY)] = 1e-5;
    let v0 = DVector::zeros(r.dof_count());
    let e0 = mechanical_energy_j(&sys, &q0, &v0);
    let opts = TransientOptions::new(30_000.0, 0.01, 2e-5, NOSE_POSITION_M);
    let h = time_response(&r, &[], None, Some((&q0, &v0)), &opts).unwrap();
    let e1 = mechanical_energy_j(&sys, &h.final_displacement_si, &h.final_velocity_si);
    assert!((e1 - e0).abs() < 1e-8 * e0, "{e0} -> {e1}");
    // Energy moved between x and y planes (gyroscopic coupling is active).
    assert!(h.displacement_y_m.iter().any(|y| y.abs() > 1e-9));
}

/// Cubic stand-in bearing: f = -k1 u - k3 u^3 on x and y of the given nodes.
struct CubicBearings {
    dofs: Vec<usize>,
    linear_n_per_m: f64,
    cubic_n_per_m3: f64,
}

impl NonlinearForce for CubicBearings {
    fn add_force(&self, _t: f64, q: &DVector<f64>, _qd: &DVector<f64>, f: &mut DVector<f64>) -> Result<()> {
        for &d in &self.dofs {
            f[d] -= self.linear_n_per_m * q[d] + self.cubic_n_per_m3 * q[d].powi(3);
        }
        Ok(())
    }
    fn dofs(&self) -> Vec<usize> {
        self.dofs.clone()
    }
}

#[test]
fn nonlinear_callback_with_linear_law_reproduces_linear_bearings() {
    let speed_rpm = 18_000.0;
    let u = [Unbalance {
        position_m: 0.17,
        unbalance_kg_m: 5e-6,
        phase_rad: 0.0,
    }];
    let opts = TransientOptions::new(speed_rpm, 0.005, 2e-5, NOSE_POSITION_M);
    // Same spindle with the rear bearings moved into the callback.
    let p = SpindleParameters {
        max_element_length_m: 0.04,
        ..SpindleParameters::default()
    };
    let mut spec = seed_b_spindle(&p).unwrap();
    let rear = Arc::new(BearingCoefficients::diagonal(0.0, 0.0, 0.0, 0.0).unwrap());
    for b in spec.bearings.iter_mut().filter(|b| b.name.starts_with("7008C")) {
        b.model = rear.clone();
    }
    // Modal damping is built from the supported rotor at rest, which differs
    // once the rear bearings move into the callback: compare undamped models.
    spec.modal_damping_ratio = 0.0;
    let r = Rotor::new(spec).unwrap();
    let mut dofs = Vec::new();
    for z in REAR_BEARING_POSITIONS_M {
        let n = r.node_at(z).unwrap();
        dofs.extend([r.dof(n, LateralDof::X), r.dof(n, LateralDof::Y)]);
    }
    let cb = CubicBearings {
        dofs,
        linear_n_per_m: 1e8,
        cubic_n_per_m3: 0.0,
    };
    let undamped_linear = time_response(&light_spindle(0.0), &u, None, None, &opts).unwrap();
    let nl = time_response(&r, &u, Some(&cb), None, &opts).unwrap();
    let scale = undamped_linear
        .displacement_x_m
        .iter()
        .fold(0.0_f64, |m, x| m.max(x.abs()));
    for (a, b) in undamped_linear.displacement_x_m.iter().zip(&nl.displacement_x_m) {
        assert!((a - b).abs() < 1e-6 * scale);
    }
    // A hardening cubic term (k3 u^2 / k1 ~ 1e-2 at u ~ 1e-7 m) converges and
    // changes the motion by a small, non-zero amount.
    let hard = thermobear::rotor::transient::ForceFn {
        dofs: cb.dofs.clone(),
        force: |_t: f64, q: &DVector<f64>, _v: &DVector<f64>, f: &mut DVector<f64>| -> Result<()> {
            for &d in &cb.dofs {
                f[d] -= 1e8 * q[d] + 1e20 * q[d].powi(3);
            }
            Ok(())
        },
    };
    let h = time_response(&r, &u, Some(&hard), None, &opts).unwrap();
    let diff = h
        .displacement_x_m
        .iter()
        .zip(&nl.displacement_x_m)
        .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
    assert!(diff > 1e-5 * scale && diff < 0.2 * scale, "{diff} vs {scale}");
    assert!(h.iterations > nl.iterations);
}

#[test]
fn magnetic_pull_softens_and_can_destabilise() {
    let base = SpindleParameters {
        max_element_length_m: 0.04,
        ..SpindleParameters::default()
    };
    let off = Rotor::new(seed_b_spindle(&base).unwrap()).unwrap();
    let on_p = SpindleParameters {
        magnetic_pull_enabled: true,
        ..base.clone()
    };
    let on = Rotor::new(seed_b_spindle(&on_p).unwrap()).unwrap();
    let f_off = plane_frequencies_hz(&off, 1)[0];
    let f_on = plane_frequencies_hz(&on, 1)[0];
    assert!(f_on < f_off, "{f_on} !< {f_off}");
    // The static eccentricity (+x) pulls the core further towards +x.
    let sys = on.matrices(0.0).unwrap();
    let q = static_deflection(&sys).unwrap();
    let core = on.node_at(0.17).unwrap();
    assert!(q[on.dof(core, LateralDof::X)] > 0.0);
    // An absurd flux density makes the negative stiffness win: the time
    // response must report divergence, not return garbage.
    let wild = SpindleParameters {
        magnetic_pull_enabled: true,
        flux_density_t: 10.0,
        ..base
    };
    let r = Rotor::new(seed_b_spindle(&wild).unwrap()).unwrap();
    let opts = TransientOptions::new(0.0, 0.2, 2e-5, NOSE_POSITION_M);
    match time_response(&r, &[], None, None, &opts) {
        Err(Error::Convergence { .. }) => {}
        other => panic!("expected divergence, got {other:?}"),
    }
}

#[test]
fn undamped_nonlinear_free_vibration_conserves_total_energy() {
    // Conservative hardening springs f = -k3 u^3 at the rear bearings add the
    // potential k3 u^4 / 4; with no damping the total energy is constant up
    // to the O(dt^2) error of the trapezoidal rule on a nonlinear system.
    let r = light_spindle(0.0);
    let sys = r.matrices(30_000.0).unwrap();
    let mut dofs = Vec::new();
    for z in REAR_BEARING_POSITIONS_M {
        let n = r.node_at(z).unwrap();
        dofs.extend([r.dof(n, LateralDof::X), r.dof(n, LateralDof::Y)]);
    }
    let cb = CubicBearings {
        dofs: dofs.clone(),
        linear_n_per_m: 0.0,
        cubic_n_per_m3: 1e20,
    };
    let energy = |q: &DVector<f64>, v: &DVector<f64>| {
        mechanical_energy_j(&sys, q, v) + dofs.iter().map(|&d| 1e20 * q[d].powi(4) / 4.0).sum::<f64>()
    };
    // Smooth start (mostly low modes): static deflection under a lateral
    // force at the rear row, scaled to 2 um there.
    let tail = r.dof(r.node_at(REAR_BEARING_POSITIONS_M[1]).unwrap(), LateralDof::X);
    let mut f = DVector::zeros(r.dof_count());
    f[tail] = 1.0;
    let shape = sys.stiffness_si.clone().lu().solve(&f).unwrap();
    let q0 = &shape * (2e-6 / shape[tail]);
    let v0 = DVector::zeros(r.dof_count());
    let e0 = energy(&q0, &v0);
    let nonlinear_share = dofs.iter().map(|&d| 1e20 * q0[d].powi(4) / 4.0).sum::<f64>() / e0;
    assert!(nonlinear_share > 0.01, "{nonlinear_share}");
    let drift = |dt: f64| {
        let mut opts = TransientOptions::new(30_000.0, 0.0025, dt, NOSE_POSITION_M);
        opts.tolerance = 1e-8;
        let h = time_response(&r, &[], Some(&cb), Some((&q0, &v0)), &opts).unwrap();
        ((energy(&h.final_displacement_si, &h.final_velocity_si) - e0) / e0).abs()
    };
    // Second-order scheme: the drift shrinks with dt (it oscillates in time,
    // bounded by O(dt^2); measured 1.1e-2 -> 2.1e-4 at this end time).
    let (coarse, fine) = (drift(1e-5), drift(5e-6));
    assert!(fine < 0.4 * coarse, "{coarse} -> {fine}");
    assert!(fine < 1e-2, "{fine}");
}

#[test]
fn speed_dependent_bearing_closure_equals_constant_bearing_at_that_speed() {
    // k(n) = 1e8 (1 + n / 30,000 rpm): the closure model at 20,000 rpm must
    // give the same modes as a constant bearing with k(20,000 rpm).
    let stiffening = |n: f64| BearingCoefficients::diagonal(1e8 * (1.0 + n / 30_000.0), 2.5e7, 0.0, 0.0);
    let p = SpindleParameters {
        max_element_length_m: 0.04,
        ..SpindleParameters::default()
    };
    let closure = Rotor::new(
        thermobear::rotor::presets::seed_b_spindle_with_bearings(Arc::new(stiffening), Arc::new(stiffening), &p)
            .unwrap(),
    )
    .unwrap();
    let k = stiffening(20_000.0).unwrap().stiffness_si[(0, 0)];
    let constant = Rotor::new(
        seed_b_spindle(&SpindleParameters {
            front_radial_stiffness_n_per_m: k,
            rear_radial_stiffness_n_per_m: k,
            ..p.clone()
        })
        .unwrap(),
    )
    .unwrap();
    let opts = CampbellOptions {
        modes: 4,
        classify_whirl: false,
        ..CampbellOptions::default()
    };
    // Each rotor reduced on its own modes at 20,000 rpm (exact at that speed
    // for the undamped part, so the two must agree closely).
    let basis = |r: &Rotor| r.modal_basis(20_000.0, 16).unwrap();
    let a = modes_at(&closure, 20_000.0, Some(&basis(&closure)), &opts).unwrap();
    let b = modes_at(&constant, 20_000.0, Some(&basis(&constant)), &opts).unwrap();
    for (x, y) in a.iter().zip(&b) {
        // Frequencies agree; damping differs slightly only through the modal
        // damping matrix, which each rotor builds from its bearings at rest.
        assert!((x.frequency_hz - y.frequency_hz).abs() < 1e-3 * y.frequency_hz);
    }
    // And the stiffer bearings raise the first frequency above the 0 rpm value.
    let rest = modes_at(&closure, 0.0, Some(&closure.modal_basis(0.0, 16).unwrap()), &opts).unwrap();
    assert!(a[0].frequency_hz > rest[0].frequency_hz * 1.05);
}

#[test]
fn spinning_pinned_shaft_matches_timoshenko_whirl_frequency_equation() {
    // Spinning Timoshenko beam, pinned-pinned, complex r = x + i y:
    // w = W sin(kz) e^{i w t}, psi = P cos(kz) e^{i w t}, k = pi / L gives
    // (kGA k^2 - rho A w^2)(EI k^2 + kGA - rho I w^2 +- 2 rho I Omega w) = (kGA k)^2,
    // + forward, - backward (gyroscopic moment of the polar inertia 2 rho I per
    // length; Friswell et al. 2010, sec. 5.3-5.4). Without shear (kGA -> inf)
    // it reduces to the Rayleigh beam EI k^4 - (rho A + rho I k^2) w^2 +- 2 rho I Omega k^2 w = 0.
    let (l, d) = (0.5, 0.05);
    let r = pinned_shaft(l, d, 16);
    let s = ShaftSection::new(l, d, 0.0, Material::shaft_steel()).unwrap();
    let m = &s.material;
    let kga = shear_coefficient_hollow(m.poisson_ratio, 0.0) * m.youngs_modulus_pa / (2.0 * (1.0 + m.poisson_ratio))
        * s.area_m2();
    let (ra, ri, ei) = (
        m.density_kg_m3 * s.area_m2(),
        m.density_kg_m3 * s.second_moment_m4(),
        m.youngs_modulus_pa * s.second_moment_m4(),
    );
    let omega = 1e4;
    let k = PI / l;
    let root = |sign: f64| {
        let f = |w: f64| {
            (kga * k * k - ra * w * w) * (ei * k * k + kga - ri * w * w + sign * 2.0 * ri * omega * w)
                - (kga * k).powi(2)
        };
        let (mut lo, mut hi) = (0.0, (kga * k * k / ra).sqrt());
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if f(mid) > 0.0 {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi) / (2.0 * PI)
    };
    let (wf, wb) = (root(1.0), root(-1.0));
    let modes = modes_at(&r, omega * 30.0 / PI, None, &CampbellOptions::default()).unwrap();
    let (b, f) = (modes[0], modes[1]);
    assert_eq!(b.whirl, thermobear::rotor::modal::Whirl::Backward);
    assert_eq!(f.whirl, thermobear::rotor::modal::Whirl::Forward);
    assert!((f.frequency_hz - wf).abs() < 1e-3 * wf, "{} vs {wf}", f.frequency_hz);
    assert!((b.frequency_hz - wb).abs() < 1e-3 * wb, "{} vs {wb}", b.frequency_hz);
    let split = f.frequency_hz - b.frequency_hz;
    assert!((split - (wf - wb)).abs() < 1e-2 * (wf - wb), "{split} vs {}", wf - wb);
}
