//! Thermal building blocks used together: heat -> network -> expansion, and
//! the energy bookkeeping of the transient integrator.

use thermobear::thermal::expansion::{thermal_offsets, ComponentRises, Mounting, RingFit};
use thermobear::thermal::heat::{bearing_heat, load_moment_n_m, viscous_moment_n_m};
use thermobear::thermal::presets::{seed_a_network, SeedAParams, SpindleNetwork, SpindleParams};
use thermobear::thermal::{SteadySolver, TransientSolver};
use thermobear::units::rpm_to_rad_s;
use thermobear::{Bearing, EffectSet, Material};

/// The coupling loop in miniature: viscosity at the ball temperature ->
/// heat -> seed A network -> temperatures -> expansion offsets.
#[test]
fn seed_a_heat_network_expansion_loop() {
    let b = Bearing::preset("6208").unwrap();
    let p = SeedAParams::for_bearing(&b);
    let net = seed_a_network(&b, &p).unwrap();
    let g = &b.geometry;
    let rpm = 10_000.0;
    let w = rpm_to_rad_s(rpm);
    let m1 = load_moment_n_m(g, 300.0, 0.0, g.free_contact_angle_rad).unwrap();
    let mut solver = SteadySolver::new(net.network.clone());
    let lub = p.lubricant.clone();
    let heat_at = |ball_c: f64| {
        let nu = lub.kinematic_viscosity_cst(ball_c).unwrap();
        let mv = viscous_moment_n_m(1.5, nu, rpm, g.pitch_diameter_m).unwrap();
        bearing_heat(w, m1, mv, 0.0, &[], &[]).unwrap()
    };
    let t = solver
        .solve_with(
            w,
            |t| Ok(net.sources_w(&heat_at(t.temperatures_c[net.balls]).split())),
            1e-10,
            200,
        )
        .unwrap();
    let v = &t.temperatures_c;
    let h = heat_at(v[net.balls]);
    // Heat balance at the coupled fixed point.
    let out: f64 = net.network.boundary_flows_w(v, w).iter().map(|x| x.1).sum();
    assert!((out - h.total_w()).abs() < 1e-8 * h.total_w());
    // Expansion from the node rises over the 26 C assembly temperature:
    // inner side hotter than outer side -> more interference (u_Tr > 0).
    let rises = ComponentRises {
        shaft_k: v[net.shaft] - 26.0,
        inner_ring_k: v[net.inner] - 26.0,
        balls_k: v[net.balls] - 26.0,
        outer_ring_k: v[net.outer] - 26.0,
        housing_k: v[net.housing] - 26.0,
    };
    let m = Mounting {
        housing: Material::aluminium(),
        housing_outer_diameter_m: p.housing_diameter_m,
        shaft_length_m: p.shaft_length_m,
        housing_length_m: p.housing_length_m,
        inner_fit: RingFit::Tight,
        outer_fit: RingFit::Loose,
        plane_strain: false,
        axial_sign: 1.0,
    };
    let tight = thermal_offsets(&b, &m, &rises, EffectSet::all()).unwrap();
    let loose = thermal_offsets(
        &b,
        &Mounting {
            inner_fit: RingFit::Loose,
            ..m.clone()
        },
        &rises,
        EffectSet::all(),
    )
    .unwrap();
    // Free rings: the inner groove centre (hotter, larger radius) moves out
    // more than the outer one -> more interference.
    assert!(v[net.inner] > v[net.outer] && loose.radial_m > 0.0);
    // The shaft runs cooler than the inner ring: through a tight fit it holds
    // the ring back (fit pressure drops), so less interference than free.
    assert!(v[net.shaft] < v[net.inner]);
    assert!(tight.inner_fit_pressure_change_pa < 0.0 && tight.radial_m < loose.radial_m);
    // Micrometres, against a 40 um diametral clearance.
    assert!(
        loose.radial_m.abs() < 20e-6 && tight.radial_m.abs() < 20e-6,
        "{}",
        loose.radial_m
    );
}

/// Energy bookkeeping of the transient: heat stored, sum C dT, equals the
/// time integral of (sources - heat leaving through the boundaries).
#[test]
fn spindle_transient_stores_what_it_does_not_lose() {
    let sp = SpindleNetwork::new(SpindleParams::seed_b().unwrap()).unwrap();
    let w = rpm_to_rad_s(12_000.0);
    let s = sp.sources_w(12_000.0, None, EffectSet::all()).unwrap();
    let mut tr = TransientSolver::new(sp.network.clone());
    let init = sp.network.initial_temperatures(25.0);
    let run = tr
        .integrate(&init, 600.0, 2.0, w, 1, |_, _, out| {
            out.copy_from_slice(&s);
            Ok(())
        })
        .unwrap();
    let p: f64 = s.iter().sum();
    let lost = |t: &[f64]| -> f64 { sp.network.boundary_flows_w(t, w).iter().map(|x| x.1).sum() };
    let mut integral = 0.0;
    for k in 1..run.times_s.len() {
        let dt = run.times_s[k] - run.times_s[k - 1];
        integral += 0.5 * dt * ((p - lost(&run.temperatures_c[k - 1])) + (p - lost(&run.temperatures_c[k])));
    }
    let first = &run.temperatures_c[0];
    let last = run.temperatures_c.last().unwrap();
    let stored: f64 = (0..last.len())
        .map(|i| sp.network.heat_capacity_j_per_k(i) * (last[i] - first[i]))
        .sum();
    assert!((stored - integral).abs() < 2e-3 * stored, "{stored} {integral}");
    // After 10 min the rotor has risen but not yet settled (slowest tau ~ 8-9 min).
    let rotor = last[sp.rotor];
    assert!(rotor > 30.0 && rotor < 54.0, "{rotor}");
}
