use super::*;
use crate::error::Error;

fn jet(w: f64) -> SupplySettings {
    SupplySettings::new(OilSupply::Jet {
        oil_flow_cm3_per_min: w,
        jet_count: 1,
        jet_velocity_m_per_s: None,
    })
}

fn bath_6208(scale: f64) -> BathBearing {
    BathBearing {
        bore_m: 0.040 * scale,
        outer_diameter_m: 0.080 * scale,
        pitch_diameter_m: 0.060 * scale,
        ball_diameter_m: 0.0119 * scale,
        kz: 3.1,
        rows: 1,
    }
}

fn point(b: BathBearing, n: f64) -> DragPoint {
    DragPoint {
        bearing: b,
        ball_count: 9,
        speed_rpm: n,
        cage_speed_rad_s: 0.4 * rpm_to_rad_s(n),
        oil_density_kg_m3: 850.0,
        viscosity_cst: 10.0,
    }
}

#[test]
fn zero_flow_gives_no_cavity_oil_and_no_drag() {
    let p = point(bath_6208(1.0), 16000.0);
    let d = supply_drag(&jet(0.0), &p).unwrap();
    assert_eq!((d.cavity_oil_fraction, d.drag_w, d.churning_w), (0.0, 0.0, 0.0));
    let air = SupplySettings::new(OilSupply::OilAir {
        oil_volume_cm3_per_h: 0.0,
        air_flow_l_per_min: 40.0,
    });
    assert_eq!(supply_drag(&air, &p).unwrap().drag_w, 0.0);
    // With flow the drag is there.
    assert!(supply_drag(&jet(500.0), &p).unwrap().drag_w > 1.0);
}

#[test]
fn parker_fraction_has_the_published_exponents() {
    let x = |w: f64, n: f64, dm: f64| parker_cavity_oil_fraction(w, n, dm, 1.0).unwrap();
    // Falls with speed as n^-1 at a fixed flow.
    let (a, b) = (x(1000.0, 10000.0, 150.0), x(1000.0, 25000.0, 150.0));
    assert!(b < a && ((a / b) - 2.5).abs() < 1e-12);
    // Rises with flow as W^0.37 at a fixed speed.
    let (a, b) = (x(500.0, 20000.0, 150.0), x(2000.0, 20000.0, 150.0));
    assert!(b > a && ((b / a) - 4f64.powf(0.37)).abs() < 1e-12);
    // Falls with the pitch diameter as dm^-1.7.
    let (a, b) = (x(500.0, 20000.0, 50.0), x(500.0, 20000.0, 100.0));
    assert!(((a / b) - 2f64.powf(1.7)).abs() < 1e-12);
    // The correlation's own number: 1e5 * 1000^0.37 / (12000 * 150^1.7).
    let expect = 1e5 * 1000f64.powf(0.37) / (12000.0 * 150f64.powf(1.7));
    assert!((x(1000.0, 12000.0, 150.0) - expect).abs() < 1e-15);
    assert!(expect > 0.005 && expect < 0.05, "jet DN 1.4 million: {expect}");
    // A flooded cavity at most; standstill floods it.
    assert_eq!(x(1e6, 1.0, 10.0), 1.0);
    assert_eq!(x(10.0, 0.0, 60.0), 1.0);
    // The speed exponent is the one given.
    let e = parker_cavity_oil_fraction(1000.0, 20000.0, 100.0, 1.3).unwrap()
        / parker_cavity_oil_fraction(1000.0, 10000.0, 100.0, 1.3).unwrap();
    assert!((e - 2f64.powf(-1.3)).abs() < 1e-12);
    // It tilts the fraction about the pivot speed: there it is Parker's.
    let pivot = CAVITY_FRACTION_PIVOT_RPM;
    for e in [0.5, 1.5] {
        let tilted = parker_cavity_oil_fraction(1000.0, pivot, 100.0, e).unwrap();
        assert!((tilted / x(1000.0, pivot, 100.0) - 1.0).abs() < 1e-12);
    }
}

#[test]
fn ball_drag_in_mixture_is_quadratic_drag_at_high_reynolds() {
    // At a high Reynolds number C_D = 0.47 and the power is the closed form
    // Z (pi/64) C_D X rho D^2 dm^3 omega_c^3 of the fixed-fraction model.
    let (z, d, dm, w, x, rho) = (9usize, 0.0119, 0.060, 700.0, 0.03, 850.0);
    let p = ball_drag_in_mixture_w(z, d, dm, w, x, rho, 0.01).unwrap();
    let closed = crate::thermal::heat::ball_drag_power_w(z, d, dm, w, rho, x, 0.47).unwrap();
    assert!((p - closed).abs() < 1e-12 * closed, "{p} vs {closed}");
    // Power grows as the cube of the cage speed there.
    let p2 = ball_drag_in_mixture_w(z, d, dm, 2.0 * w, x, rho, 0.01).unwrap();
    assert!((p2 / p - 8.0).abs() < 1e-9);
    // A thick, slow mixture: the Stokes-side coefficient is larger.
    assert!(sphere_drag_coefficient(10.0) > 2.0);
    assert!(ball_drag_in_mixture_w(z, d, dm, 0.0, x, rho, 0.01).unwrap() == 0.0);
}

#[test]
fn sphere_drag_coefficient_is_continuous_and_falls_to_the_plateau() {
    let mut last = f64::INFINITY;
    for k in 0..400 {
        let re = 10f64.powf(-1.0 + 7.0 * k as f64 / 400.0);
        let c = sphere_drag_coefficient(re);
        assert!(c <= last + 1e-12 && c >= 0.47);
        last = c;
    }
    // Schiller-Naumann meets 0.47 between Re 500 and 1000.
    assert!(sphere_drag_coefficient(500.0) > 0.47 && sphere_drag_coefficient(1000.0) == 0.47);
    // Stokes limit 24/Re.
    assert!((sphere_drag_coefficient(1e-3) * 1e-3 / 24.0 - 1.0).abs() < 1e-2);
}

#[test]
fn bath_drag_scales_as_dm5_n2() {
    let m = |s: f64, n: f64| skf_bath_drag_moment_n_m(&bath_6208(s), None, n).unwrap();
    // Same bearing, speed doubled: four times the moment.
    assert!((m(1.0, 6000.0) / m(1.0, 3000.0) - 4.0).abs() < 1e-12);
    // Geometry scaled by k (same H/dm, same (d+D)/(D-d)): k^5.
    assert!((m(2.0, 3000.0) / m(1.0, 3000.0) - 32.0).abs() < 1e-9);
    // Catalogue form at the reference level: V_M K_ball dm^5 n^2 (N mm).
    let k_ball = 3.1 * (40.0 + 80.0) / (80.0 - 40.0) * 1e-12;
    let expect = SKF_BATH_DRAG_VM_REFERENCE * k_ball * 60f64.powi(5) * 3000f64.powi(2) * 1e-3;
    assert!((m(1.0, 3000.0) - expect).abs() < 1e-12 * expect);
    // A higher level drags more, no oil none.
    let b = bath_6208(1.0);
    let hi = skf_bath_drag_moment_n_m(&b, Some(0.03), 3000.0).unwrap();
    assert!(hi > m(1.0, 3000.0));
    assert_eq!(skf_bath_drag_moment_n_m(&b, Some(0.0), 3000.0).unwrap(), 0.0);
}

#[test]
fn immersion_share_goes_from_zero_to_one() {
    assert_eq!(bath_immersion_share(0.0, 0.06).unwrap(), 0.0);
    assert!((bath_immersion_share(0.036, 0.06).unwrap() - 0.5).abs() < 1e-12);
    assert_eq!(bath_immersion_share(0.5, 0.06).unwrap(), 1.0);
    let mut last = 0.0;
    for k in 1..=100 {
        let s = bath_immersion_share(0.072 * k as f64 / 100.0, 0.06).unwrap();
        assert!(s > last);
        last = s;
    }
}

#[test]
fn grease_has_no_steady_drag_and_bad_inputs_name_their_field() {
    let p = point(bath_6208(1.0), 16000.0);
    let g = SupplySettings::new(OilSupply::Grease {
        grease_fill_fraction: 0.3,
    });
    assert_eq!(supply_drag(&g, &p).unwrap(), SupplyDrag::default());
    let bad = |s: SupplySettings, field: &str| match supply_drag(&s, &p) {
        Err(Error::Config { field: f, .. }) => assert_eq!(f, field),
        other => panic!("{field}: {other:?}"),
    };
    bad(jet(-1.0), "oil_flow_cm3_per_min");
    bad(
        SupplySettings::new(OilSupply::Jet {
            oil_flow_cm3_per_min: 100.0,
            jet_count: 0,
            jet_velocity_m_per_s: None,
        }),
        "jet_count",
    );
    bad(
        SupplySettings::new(OilSupply::Grease {
            grease_fill_fraction: 1.5,
        }),
        "grease_fill_fraction",
    );
    bad(
        SupplySettings::new(OilSupply::OilBath {
            oil_level_mm: Some(-2.0),
        }),
        "oil_level_mm",
    );
    let mut s = jet(100.0);
    s.oil_flow_scale = f64::NAN;
    bad(s, "oil_flow_scale");
}

#[test]
fn supply_keywords_resolve_back_to_the_same_supply() {
    let tuned = |supply| SupplySettings {
        supply,
        oil_flow_scale: 2.5,
        cavity_fraction_speed_exponent: 0.8,
    };
    let supplies = [
        tuned(OilSupply::Jet {
            oil_flow_cm3_per_min: 500.0,
            jet_count: 2,
            jet_velocity_m_per_s: Some(12.0),
        }),
        jet(100.0),
        tuned(OilSupply::OilAir {
            oil_volume_cm3_per_h: 5.0,
            air_flow_l_per_min: 30.0,
        }),
        tuned(OilSupply::OilMist {
            oil_volume_cm3_per_h: 2.0,
            air_flow_l_per_min: 0.0,
        }),
        tuned(OilSupply::OilBath { oil_level_mm: None }),
        tuned(OilSupply::OilBath {
            oil_level_mm: Some(4.0),
        }),
        tuned(OilSupply::Grease {
            grease_fill_fraction: 0.2,
        }),
    ];
    for s in supplies {
        let back = s.input().resolve(s.method(), false, false).unwrap();
        assert_eq!(back, Some(s), "{s:?}");
    }
}
