//! Tests of the heat models (src/thermal/friction.rs).

use super::*;
use crate::bearing::Bearing;
use crate::effects::EffectSet;
use crate::thermal::coupled::{CoupledBearing, CoupledOptions};

/// A 6208-size point: d = 40 mm, D = 80 mm (dm = 60 mm), Fr = 3 kN,
/// 3000 rpm, 20 cSt.
fn dg_point(fr: f64, fa: f64, n: f64, nu: f64) -> SkfInputs {
    SkfInputs {
        bore_m: 0.040,
        outer_diameter_m: 0.080,
        static_load_rating_n: 19_000.0,
        radial_n: fr,
        axial_n: fa,
        speed_rpm: n,
        viscosity_cst: nu,
        centrifugal_load: SkfCentrifugalLoad::CatalogueSteelBalls,
    }
}

#[test]
fn skf_deep_groove_moments_match_a_hand_calculation() {
    // 62 series: R1 = 3.9e-7, S1 = 3.23e-3, K_z = 3.1; K_rs = 6e-8 (oil-air),
    // mu_EHL = 0.05. By hand (N mm, mm, rpm, cSt):
    //   G_rr = 3.9e-7 * 60^1.96 * 3000^0.54            = 0.089 91
    //   phi_ish = 1 / (1 + 1.84e-9 (180000)^1.28 20^0.64) = 0.937 5
    //   phi_rs = exp(-6e-8 * 60000 * 120 * sqrt(3.1/80))  = 0.918 4
    //   M_rr = phi_ish phi_rs G_rr (60000)^0.6          = 56.9 N mm
    //   G_sl = 3.23e-3 * 60^-0.26 * 3000^(5/3)           = 696
    //   phi_bl = exp(-2.6e-8 * 60000^1.4 * 60) ~ 5e-4  ->  mu_sl = 0.050 05
    //   M_sl = 34.8 N mm
    let m = skf_moments(
        SkfSeries::DeepGroove62,
        &dg_point(3000.0, 0.0, 3000.0, 20.0),
        0.05,
        6e-8,
    )
    .unwrap();
    let g_rr = 3.9e-7 * 60f64.powf(1.96) * 3000f64.powf(0.54);
    let ish = 1.0 / (1.0 + 1.84e-9 * 180_000f64.powf(1.28) * 20f64.powf(0.64));
    let rs = (-6e-8 * 60_000.0 * 120.0 * (3.1f64 / 80.0).sqrt()).exp();
    let m_rr = ish * rs * g_rr * 60_000f64.powf(0.6) * 1e-3;
    assert!((m.rolling_n_m - m_rr).abs() < 1e-12 * m_rr);
    assert!((m.rolling_n_m * 1e3 - 56.9).abs() < 0.3, "{}", m.rolling_n_m * 1e3);
    assert!((m.phi_ish - 0.9375).abs() < 1e-3 && (m.phi_rs - 0.9184).abs() < 1e-3);
    let bl = (-2.6e-8 * 60_000f64.powf(1.4) * 60.0).exp();
    let g_sl = 3.23e-3 * 60f64.powf(-0.26) * 3000f64.powf(5.0 / 3.0);
    let m_sl = g_sl * (bl * 0.15 + (1.0 - bl) * 0.05) * 1e-3;
    assert!((m.sliding_n_m - m_sl).abs() < 1e-12 * m_sl);
    assert!((m.sliding_n_m * 1e3 - 34.8).abs() < 0.3, "{}", m.sliding_n_m * 1e3);
}

#[test]
fn skf_angular_contact_hand_value_with_centrifugal_terms() {
    // Single row: R = (5.03e-7, 1.97, 1.90e-12), S = (1.30e-2, 0.68, 1.91e-12),
    // K_z = 4.4. Fr = 500 N, Fa = 1000 N, 12,000 rpm, 10 cSt, dm = 60 mm.
    let i = dg_point(500.0, 1000.0, 12_000.0, 10.0);
    let m = skf_moments(SkfSeries::AngularContactSingleRow, &i, 0.05, 3e-8).unwrap();
    let (dm, n, nu) = (60.0f64, 12_000.0f64, 10.0f64);
    let fg_r = 1.90e-12 * dm.powi(4) * n * n;
    let fg_s = 1.91e-12 * dm.powi(4) * n * n;
    let g_rr = 5.03e-7 * dm.powf(1.97) * (500.0 + fg_r + 1.97 * 1000.0).powf(0.54);
    let ish = 1.0 / (1.0 + 1.84e-9 * (n * dm).powf(1.28) * nu.powf(0.64));
    let rs = (-3e-8 * nu * n * 120.0 * (4.4f64 / 80.0).sqrt()).exp();
    let m_rr = ish * rs * g_rr * (nu * n).powf(0.6) * 1e-3;
    assert!((m.rolling_n_m - m_rr).abs() < 1e-12 * m_rr);
    let g_sl = 1.30e-2 * dm.powf(0.26) * ((500.0 + fg_s).powf(4.0 / 3.0) + 0.68 * 1000f64.powf(4.0 / 3.0));
    let bl = (-2.6e-8 * (n * nu).powf(1.4) * dm).exp();
    let m_sl = g_sl * (bl * 0.15 + (1.0 - bl) * 0.05) * 1e-3;
    assert!((m.sliding_n_m - m_sl).abs() < 1e-12 * m_sl);
    // A given centrifugal load replaces both fits.
    let mut j = i;
    j.centrifugal_load = SkfCentrifugalLoad::Given { load_n: 0.0 };
    let z = skf_moments(SkfSeries::AngularContactSingleRow, &j, 0.05, 3e-8).unwrap();
    let g0 = 5.03e-7 * dm.powf(1.97) * (500.0f64 + 1.97 * 1000.0).powf(0.54);
    assert!((z.rolling_n_m - ish * rs * g0 * (nu * n).powf(0.6) * 1e-3).abs() < 1e-12);
    assert!(fg_r > 0.0 && z.rolling_n_m < m.rolling_n_m);
}

#[test]
fn skf_constants_are_the_catalogue_tables() {
    // SKF General Catalogue 6000 (2006), chapter "Friction" (Russian
    // translation 6000 RU). Table 3a, p. 93, deep-groove ball bearings
    // (R1, R2, S1, S2): 60/630 4.1e-7 1.7 3.73e-3 14.6; 62/622 3.9e-7 1.7
    // 3.23e-3 36.5; 63/623 3.7e-7 1.7 2.84e-3 92.8; 64 3.6e-7 1.7 2.43e-3
    // 198. Table 3, p. 92, angular-contact ball bearings, single row (R1,
    // R2, R3, S1, S2, S3): 5.03e-7 1.97 1.90e-12 1.30e-2 0.68 1.91e-12.
    // Table 5, p. 98, K_z: deep-groove 3.1, angular-contact single row 4.4.
    let dg = [
        (SkfSeries::DeepGroove60, [4.1e-7, 1.7, 3.73e-3, 14.6]),
        (SkfSeries::DeepGroove62, [3.9e-7, 1.7, 3.23e-3, 36.5]),
        (SkfSeries::DeepGroove63, [3.7e-7, 1.7, 2.84e-3, 92.8]),
        (SkfSeries::DeepGroove64, [3.6e-7, 1.7, 2.43e-3, 198.0]),
    ];
    for (series, [r1, r2, s1, s2]) in dg {
        let c = series.constants();
        assert_eq!(
            (c.r, c.s, c.kz),
            ([r1, r2, 0.0], [s1, s2, 0.0], 3.1),
            "{}",
            series.name()
        );
        assert_eq!(series.bearing_type(), BearingType::DeepGroove);
    }
    let a = SkfSeries::AngularContactSingleRow.constants();
    assert_eq!(a.r, [5.03e-7, 1.97, 1.90e-12]);
    assert_eq!(a.s, [1.30e-2, 0.68, 1.91e-12]);
    assert_eq!(a.kz, 4.4);
    // The 2006 edition has one row for every single-row angular-contact
    // series: "72B" and "73B" are names of it. "73B" used to hold table 3's
    // double-row row (R1 6.34e-7, R2 1.41, R3 7.83e-13, S1 7.56e-3, S2
    // 1.21, S3 7.83e-13, K_z 3.1); no series has it now.
    for name in ["72B", "73B", "72 b", "73-B", "angular-single-row", "Angular single_row"] {
        assert_eq!(
            SkfSeries::from_name(name).unwrap(),
            SkfSeries::AngularContactSingleRow,
            "{name}"
        );
    }
    let double_row = ([6.34e-7, 1.41, 7.83e-13], [7.56e-3, 1.21, 7.83e-13]);
    assert!(SkfSeries::ALL
        .iter()
        .all(|s| (s.constants().r, s.constants().s) != double_row));
    // Aliases from the series table 3a groups; every name parses back.
    assert_eq!(SkfSeries::from_name("630").unwrap(), SkfSeries::DeepGroove60);
    assert_eq!(SkfSeries::from_name("622").unwrap(), SkfSeries::DeepGroove62);
    assert_eq!(SkfSeries::from_name("623").unwrap(), SkfSeries::DeepGroove63);
    for s in SkfSeries::ALL {
        assert_eq!(SkfSeries::from_name(s.name()).unwrap(), s);
    }
    assert_eq!(
        SkfSeries::default_for(BearingType::AngularContact),
        SkfSeries::AngularContactSingleRow
    );
    match SkfSeries::from_name("33D") {
        Err(Error::Config { field, reason, .. }) => {
            assert_eq!(field, "skf_series");
            assert!(reason.contains("angular-single-row (72B, 73B)"), "{reason}");
        }
        other => panic!("{other:?}"),
    }
    // Saved settings of earlier versions still load.
    for old in ["\"AngularContact72B\"", "\"AngularContact73B\""] {
        let s: SkfSeries = serde_json::from_str(old).unwrap();
        assert_eq!(s, SkfSeries::AngularContactSingleRow);
    }
}

#[test]
fn skf_deep_groove_with_thrust_matches_a_hand_calculation() {
    // Table 2a (p. 91) deep-groove branch with Fa > 0, 62 series, a
    // 6208-size point (d = 40, D = 80, dm = 60 mm, C0 = 19 kN), Fr = 2 kN,
    // Fa = 1 kN, 3000 rpm, 20 mm^2/s, K_rs = 6e-8, mu_EHL = 0.05. By hand:
    //   a_F = 24.6 (1000/19000)^0.24 = 12.135 deg, sin a_F = 0.210 21
    //   G_rr = 3.9e-7 60^1.96 (2000 + 1.7/0.210 21 * 1000)^0.54 = 0.173 09
    //   G_sl = 3.23e-3 60^-0.145 (2000^5 + 36.5 60^1.5 1000^4 / 0.210 21)^(1/3)
    //        = 861.7
    //   phi_ish = 0.937 46, phi_rs = 0.918 48 (as in the Fa = 0 case)
    //   M_rr = 0.937 46 * 0.918 48 * 0.173 09 * 60000^0.6 = 109.7 N mm
    //   phi_bl = 4.9e-4 -> mu_sl = 0.050 05, M_sl = 43.1 N mm
    let m = skf_moments(
        SkfSeries::DeepGroove62,
        &dg_point(2000.0, 1000.0, 3000.0, 20.0),
        0.05,
        6e-8,
    )
    .unwrap();
    assert!((m.phi_ish - 0.93746).abs() < 1e-5 && (m.phi_rs - 0.91848).abs() < 1e-5);
    assert!((m.rolling_n_m * 1e3 - 109.7).abs() < 0.05, "{}", m.rolling_n_m * 1e3);
    assert!((m.sliding_n_m * 1e3 - 43.1).abs() < 0.05, "{}", m.sliding_n_m * 1e3);
    // The thrust raises both moments over the Fa = 0 point.
    let z = skf_moments(
        SkfSeries::DeepGroove62,
        &dg_point(2000.0, 0.0, 3000.0, 20.0),
        0.05,
        6e-8,
    )
    .unwrap();
    assert!(m.rolling_n_m > z.rolling_n_m && m.sliding_n_m > z.sliding_n_m);
}

#[test]
fn skf_angular_contact_catalogue_fit_and_hybrid_factor() {
    // Table 2a (p. 91) angular-contact branch with the table 3 (p. 92)
    // single-row constants and the fitted Fg, a 7208 B-size point (d = 40,
    // D = 80, dm = 60 mm), Fr = 1 kN, Fa = 2 kN, 6000 rpm, 15 mm^2/s, K_rs =
    // 3e-8 (oil jet), K_z = 4.4, mu_EHL = 0.05. By hand:
    //   Fg = 1.90e-12 60^4 6000^2 = 886.5 N (rolling), 891.1 N (sliding)
    //   G_rr = 5.03e-7 60^1.97 (1000 + 886.5 + 1.97 * 2000)^0.54 = 0.172 92
    //   G_sl = 1.30e-2 60^0.26 (1891.1^(4/3) + 0.68 * 2000^(4/3)) = 1527.4
    //   phi_ish = 0.881 24, phi_rs = exp(-3e-8 15 6000 120 sqrt(4.4/80)) = 0.926 83
    //   M_rr = 0.881 24 * 0.926 83 * 0.172 92 * 90000^0.6 = 132.6 N mm
    //   mu_sl = 0.05 (phi_bl = 1.4e-6), M_sl = 76.4 N mm
    // Si3N4 balls, p. 102: 0.41 R3 and 0.41 S3, Fg = 363.5 / 365.4 N:
    //   G_rr = 0.164 36, M_rr = 126.0 N mm; G_sl = 1216.8, M_sl = 60.8 N mm
    let mut i = dg_point(1000.0, 2000.0, 6000.0, 15.0);
    let steel = skf_moments(SkfSeries::AngularContactSingleRow, &i, 0.05, 3e-8).unwrap();
    assert!((steel.phi_ish - 0.88124).abs() < 1e-5 && (steel.phi_rs - 0.92683).abs() < 1e-5);
    assert!(
        (steel.rolling_n_m * 1e3 - 132.6).abs() < 0.05,
        "{}",
        steel.rolling_n_m * 1e3
    );
    assert!(
        (steel.sliding_n_m * 1e3 - 76.4).abs() < 0.05,
        "{}",
        steel.sliding_n_m * 1e3
    );
    i.centrifugal_load = SkfCentrifugalLoad::CatalogueSi3n4Balls;
    let hybrid = skf_moments(SkfSeries::AngularContactSingleRow, &i, 0.05, 3e-8).unwrap();
    assert!(
        (hybrid.rolling_n_m * 1e3 - 126.0).abs() < 0.05,
        "{}",
        hybrid.rolling_n_m * 1e3
    );
    assert!(
        (hybrid.sliding_n_m * 1e3 - 60.8).abs() < 0.05,
        "{}",
        hybrid.sliding_n_m * 1e3
    );
    // The hybrid fit equals a given load of 0.41 times the steel fit.
    let fg = 0.41 * 1.90e-12 * 60f64.powi(4) * 6000f64.powi(2);
    i.centrifugal_load = SkfCentrifugalLoad::Given { load_n: fg };
    let given = skf_moments(SkfSeries::AngularContactSingleRow, &i, 0.05, 3e-8).unwrap();
    assert!((given.rolling_n_m - hybrid.rolling_n_m).abs() < 1e-12 * hybrid.rolling_n_m);
    // At standstill the fit vanishes: steel and hybrid agree.
    let mut s0 = dg_point(1000.0, 2000.0, 0.0, 15.0);
    let a = skf_moments(SkfSeries::AngularContactSingleRow, &s0, 0.05, 3e-8).unwrap();
    s0.centrifugal_load = SkfCentrifugalLoad::CatalogueSi3n4Balls;
    let b = skf_moments(SkfSeries::AngularContactSingleRow, &s0, 0.05, 3e-8).unwrap();
    assert_eq!(a, b);
    // A negative given load names its field.
    i.centrifugal_load = SkfCentrifugalLoad::Given { load_n: -1.0 };
    match skf_moments(SkfSeries::AngularContactSingleRow, &i, 0.05, 3e-8) {
        Err(Error::Config { field, .. }) => assert_eq!(field, "centrifugal_load_n"),
        other => panic!("{other:?}"),
    }
}

#[test]
fn ball_centrifugal_load_hybrid_ratio_and_size_against_the_fit() {
    // The coupled models take Fg as the sum of the ball centrifugal forces.
    // At the same cage speed, Si3N4 balls give the density ratio
    // 3200/7830 = 0.409 of the steel load: within 1 % of the catalogue's
    // hybrid factor 0.41 (p. 102).
    let steel = Bearing::preset("7009C").unwrap();
    let hybrid = Bearing::preset("7009C-hybrid").unwrap();
    let n = 12_000.0;
    let g = &steel.geometry;
    // Cage speed of pure rolling at the free contact angle.
    let gamma = g.ball_diameter_m * g.free_contact_angle_rad.cos() / g.pitch_diameter_m;
    let cage = 0.5 * rpm_to_rad_s(n) * (1.0 - gamma);
    let fg = |b: &Bearing| {
        let mut p = point(&b.geometry, n, cage);
        p.ball_mass_kg = b.ball_mass_kg();
        centrifugal_load_n(&p).unwrap()
    };
    let (fs, fh) = (fg(&steel), fg(&hybrid));
    let rho = hybrid.ball.density_kg_m3 / steel.ball.density_kg_m3;
    assert!((fh / fs - rho).abs() < 1e-12, "{} vs {rho}", fh / fs);
    assert!((fh / fs - SKF_HYBRID_CENTRIFUGAL_FACTOR).abs() < 0.01 * SKF_HYBRID_CENTRIFUGAL_FACTOR);
    // Closed form for the steel balls: Z rho pi D^3/6 (dm/2) omega_c^2.
    let m_ball = 7830.0 * std::f64::consts::PI * g.ball_diameter_m.powi(3) / 6.0;
    let closed = 16.0 * m_ball * 0.5 * g.pitch_diameter_m * cage * cage;
    assert!((fs - closed).abs() < 1e-9 * closed);
    // The catalogue fit (table 2a, R3 of table 3, dm = 60 mm) is no force
    // sum: for this bearing it is 9.3 times the sum (docs/concepts/physics.md §9).
    let fit = 1.90e-12 * 60f64.powi(4) * n * n;
    assert!((fit / fs - 9.3).abs() < 0.1, "{}", fit / fs);
}

#[test]
fn skf_total_agrees_with_the_catalogue_constant_friction_estimate() {
    // Published numbers: SKF's constant coefficients of friction for open
    // bearings, M = 0.5 mu P d, mu = 0.0015 deep-groove, 0.0020 single-row
    // angular-contact ball bearings (SKF General Catalogue 6000 EN and
    // Rolling bearings 17000 EN, "Estimating the frictional moment"; valid
    // for P ~ 0.1 C, good lubrication, normal operating conditions). A 6208
    // (C = 32.5 kN) at P = 3 kN, 3000 rpm, 20 cSt: 0.5 * 0.0015 * 3000 * 40
    // = 90 N mm. The four-term model gives 91.7 N mm.
    let m = skf_moments(
        SkfSeries::DeepGroove62,
        &dg_point(3000.0, 0.0, 3000.0, 20.0),
        0.05,
        6e-8,
    )
    .unwrap();
    let total = (m.rolling_n_m + m.sliding_n_m) * 1e3;
    assert!((total - 90.0).abs() < 0.25 * 90.0, "{total}");
    // A 7208 B-size bearing (same d, D) at the same radial load: 120 N mm
    // from mu = 0.0020; the estimate is coarse, we ask for a factor 1.5.
    let a = skf_moments(
        SkfSeries::AngularContactSingleRow,
        &dg_point(3000.0, 0.0, 3000.0, 20.0),
        0.05,
        6e-8,
    )
    .unwrap();
    let total = (a.rolling_n_m + a.sliding_n_m) * 1e3;
    assert!(total > 120.0 / 1.5 && total < 120.0 * 1.5, "{total}");
}

#[test]
fn skf_limits_and_scaling() {
    let m = |n: f64, nu: f64, krs: f64| {
        skf_moments(SkfSeries::DeepGroove62, &dg_point(2000.0, 0.0, n, nu), 0.05, krs).unwrap()
    };
    // Without starvation and with phi_ish divided out, M_rr ~ (nu n)^0.6.
    let (a, b) = (m(1000.0, 20.0, 0.0), m(2000.0, 20.0, 0.0));
    let ratio = (b.rolling_n_m / b.phi_ish) / (a.rolling_n_m / a.phi_ish);
    assert!((ratio - 2f64.powf(0.6)).abs() < 1e-12, "{ratio}");
    // Reduction factors: 1 at standstill, falling with speed, both in (0, 1].
    let z = m(0.0, 20.0, 6e-8);
    assert_eq!((z.phi_ish, z.phi_rs, z.rolling_n_m), (1.0, 1.0, 0.0));
    let (lo, hi) = (m(1000.0, 20.0, 6e-8), m(20_000.0, 20.0, 6e-8));
    assert!(hi.phi_ish < lo.phi_ish && hi.phi_rs < lo.phi_rs && hi.phi_rs > 0.0);
    // Sliding coefficient: boundary 0.15 at standstill, full film mu_EHL fast.
    assert!((z.mu_sliding - 0.15).abs() < 1e-12 && (hi.mu_sliding - 0.05).abs() < 1e-9);
    // Oil jet / bath replenish better than oil-air: K_rs 3e-8 < 6e-8.
    let jet = Lubrication::Jet.defaults(BearingType::DeepGroove).replenishment_krs;
    assert!(m(20_000.0, 20.0, jet).phi_rs > hi.phi_rs);
    // Unloaded deep-groove bearing: no load-dependent moment.
    let u = skf_moments(SkfSeries::DeepGroove62, &dg_point(0.0, 0.0, 5000.0, 20.0), 0.05, 6e-8).unwrap();
    assert_eq!(u.rolling_n_m + u.sliding_n_m, 0.0);
    // Bad input names its field.
    match skf_moments(SkfSeries::DeepGroove62, &dg_point(1.0, 0.0, 1.0, 20.0), 0.5, 6e-8) {
        Err(Error::Config { field, .. }) => assert_eq!(field, "sliding_friction_ehl"),
        other => panic!("{other:?}"),
    }
}

#[test]
fn seal_moment_formula() {
    // K_S1 d_s^beta + K_S2 with d_s = 52 mm: 0.028 * 52^2.25 + 2 = 194.7 N mm.
    let m = seal_moment_n_m(0.028, 2.25, 2.0, 0.052).unwrap();
    assert!((m * 1e3 - (0.028 * 52f64.powf(2.25) + 2.0)).abs() < 1e-9);
    assert!(seal_moment_n_m(0.028, 2.25, 2.0, 0.0).is_err());
}

#[test]
fn lubrication_defaults_follow_the_tables() {
    use BearingType::{AngularContact as A, DeepGroove as D};
    // Harris & Kotzalas (Palmgren) f0: deep groove oil mist 1, bath 2,
    // jet 4; angular contact oil mist 1.7, bath 3.3, jet 6.6, grease 2.
    let f0 = |l: Lubrication, t| l.defaults(t).lubrication_factor_f0;
    assert_eq!(
        [
            f0(Lubrication::OilMist, D),
            f0(Lubrication::OilBath, D),
            f0(Lubrication::Jet, D)
        ],
        [1.0, 2.0, 4.0]
    );
    assert_eq!(
        [
            f0(Lubrication::OilMist, A),
            f0(Lubrication::OilBath, A),
            f0(Lubrication::Jet, A),
            f0(Lubrication::Grease, A)
        ],
        [1.7, 3.3, 6.6, 2.0]
    );
    assert_eq!(f0(Lubrication::OilAir, A), f0(Lubrication::OilMist, A));
    // The drag oil fraction grows with the oil kept in the cavity, inside its bounds.
    let xs: Vec<f64> = [
        Lubrication::Grease,
        Lubrication::OilMist,
        Lubrication::OilAir,
        Lubrication::Jet,
        Lubrication::OilBath,
    ]
    .iter()
    .map(|l| {
        let d = l.defaults(D);
        let (lo, hi) = d.oil_fraction_bounds;
        assert!(
            lo <= d.oil_volume_fraction && d.oil_volume_fraction <= hi,
            "{}",
            l.name()
        );
        let (lo, hi) = d.f0_bounds;
        assert!(
            lo <= d.lubrication_factor_f0 && d.lubrication_factor_f0 <= hi,
            "{}",
            l.name()
        );
        d.oil_volume_fraction
    })
    .collect();
    assert!(xs.windows(2).all(|w| w[0] < w[1]), "{xs:?}");
    // SKF K_rs: 3e-8 jet and bath, 6e-8 grease and oil-air.
    assert_eq!(Lubrication::Jet.defaults(A).replenishment_krs, 3e-8);
    assert_eq!(Lubrication::Grease.defaults(A).replenishment_krs, 6e-8);
    for l in Lubrication::ALL {
        assert_eq!(Lubrication::from_name(l.name()).unwrap(), l);
    }
    assert_eq!(Lubrication::from_name("Oil_Air").unwrap(), Lubrication::OilAir);
    match Lubrication::from_name("honey") {
        Err(Error::Config { field, .. }) => assert_eq!(field, "lubrication"),
        other => panic!("{other:?}"),
    }
    assert_eq!(HeatModel::from_name("SKF").unwrap(), HeatModel::Skf);
    assert!(HeatModel::from_name("harris").is_err());
    assert_eq!(skf_mu_ehl_for_lubricant("e-drive ATF"), 0.1);
    assert_eq!(skf_mu_ehl_for_lubricant("ISO VG 32"), 0.05);
}

fn point<'a>(g: &'a BearingGeometry, n: f64, cage: f64) -> FrictionPoint<'a> {
    FrictionPoint {
        geometry: g,
        axial_n: 400.0,
        radial_n: 0.0,
        contact_angle_rad: g.free_contact_angle_rad,
        speed_rpm: n,
        viscosity_cst: 15.0,
        oil_density_kg_m3: 850.0,
        cage_speed_rad_s: cage,
        ball_mass_kg: 0.01,
        lubricant_name: "ISO VG 32",
        inner_contacts: &[],
        outer_contacts: &[],
    }
}

fn settings(model: HeatModel, x: f64) -> FrictionSettings {
    FrictionSettings {
        heat_model: model,
        lubrication: Lubrication::Jet,
        lubrication_factor_f0: 1.7,
        spin_friction_coefficient: 0.05,
        load_friction_scale: 1.0,
        oil_volume_fraction: x,
        skf: SkfSettings::default(),
        oil_supply: None,
    }
}

#[test]
fn friction_heat_dispatch_drag_limits_and_speed_exponents() {
    let g = Bearing::preset("7009C").unwrap().geometry;
    // Palmgren through the dispatcher = the direct moments.
    let p = friction_heat(&settings(HeatModel::Palmgren, 0.0), &point(&g, 12_000.0, 500.0)).unwrap();
    let m1 = load_moment_n_m(&g, 400.0, 0.0, g.free_contact_angle_rad).unwrap();
    let mv = viscous_moment_n_m(1.7, 15.0, 12_000.0, g.pitch_diameter_m).unwrap();
    let w = rpm_to_rad_s(12_000.0);
    assert!((p.heat.total_w() - w * (m1 + mv)).abs() < 1e-12 * p.heat.total_w());
    // Drag -> 0 as X -> 0 (linearly), in both models.
    for model in [HeatModel::Palmgren, HeatModel::Skf] {
        let d = |x: f64| friction_heat(&settings(model, x), &point(&g, 12_000.0, 500.0)).unwrap();
        assert_eq!(d(0.0).drag_w, 0.0);
        assert!((d(1e-6).drag_w / d(1e-3).drag_w - 1e-3).abs() < 1e-9);
        assert!((d(0.03).heat.total_w() - d(0.0).heat.total_w() - d(0.03).drag_w).abs() < 1e-9);
    }
    // Drag ~ n^3 at fixed viscosity (cage speed proportional to shaft speed).
    let d = |n: f64| {
        friction_heat(&settings(HeatModel::Skf, 0.03), &point(&g, n, n * 0.04))
            .unwrap()
            .drag_w
    };
    assert!((d(20_000.0) / d(10_000.0) - 8.0).abs() < 1e-9);
    // SKF heat without drag, no starvation: the rolling part ~ n^1.6 / phi_ish.
    let mut s = settings(HeatModel::Skf, 0.0);
    s.skf.replenishment_krs = Some(0.0);
    let h = |n: f64| friction_heat(&s, &point(&g, n, 0.0)).unwrap();
    let (a, b) = (h(2000.0), h(4000.0));
    let (sa, sb) = (a.skf.unwrap(), b.skf.unwrap());
    let r = (b.load_moment_n_m / sb.phi_ish) / (a.load_moment_n_m / sa.phi_ish);
    assert!((r - 2f64.powf(0.6)).abs() < 1e-9, "{r}");
    // Seal moment adds omega M_seal.
    let without = h(3000.0);
    let mut s2 = s;
    s2.skf.seal_moment_n_m = 0.01;
    let with_seal = friction_heat(&s2, &point(&g, 3000.0, 0.0)).unwrap();
    let dw = with_seal.heat.total_w() - without.heat.total_w();
    assert!((dw - 0.01 * rpm_to_rad_s(3000.0)).abs() < 1e-12);
}

#[test]
fn coupled_state_with_skf_and_jet_drag_balances_heat() {
    let b = Bearing::preset("6208").unwrap();
    let d = Lubrication::Jet.defaults(b.geometry.bearing_type);
    let o = CoupledOptions {
        heat_model: HeatModel::Skf,
        lubrication: Lubrication::Jet,
        lubrication_factor_f0: d.lubrication_factor_f0,
        churning_oil_fraction: d.oil_volume_fraction,
        solve: crate::bearing::SolveOptions {
            effects: EffectSet::all(),
            ..Default::default()
        },
        ..CoupledOptions::default()
    };
    let s = CoupledBearing::seed_a(&b, o)
        .unwrap()
        .solve(8000.0, 500.0, 200.0)
        .unwrap();
    let out: f64 = s.boundary_flows_w.iter().map(|x| x.1).sum();
    let h = s.heat.heat.total_w();
    assert!(h > 1.0 && (out - h).abs() < 1e-6 * h, "{out} vs {h}");
    // The report's parts add up: rolling + sliding + seal + drag.
    let parts = s.heat.load_w + s.heat.viscous_w + s.heat.seal_w + s.heat.churning_w;
    assert!((parts - h).abs() < 1e-9 * h, "{parts} vs {h}");
    assert!(s.heat.skf.is_some() && s.heat.churning_w > 0.0);
    // Split conserves the total.
    let sp = s.heat.split;
    assert!((sp.inner_ring_w + sp.balls_w + sp.outer_ring_w - h).abs() < 1e-9 * h);
}

#[test]
fn load_friction_scale_multiplies_palmgren_m1_only() {
    // The factor scales M1 = f1 P1 dm and nothing else: the heat grows by
    // (s - 1) omega M1 and the split keeps Burton-Staph's halves.
    let g = Bearing::preset("7009C").unwrap().geometry;
    let at = |s: f64| {
        let mut st = settings(HeatModel::Palmgren, 0.0);
        st.load_friction_scale = s;
        friction_heat(&st, &point(&g, 12_000.0, 500.0)).unwrap()
    };
    let (one, three) = (at(1.0), at(3.0));
    let m1 = load_moment_n_m(&g, 400.0, 0.0, g.free_contact_angle_rad).unwrap();
    assert_eq!(three.load_moment_n_m, 3.0 * m1);
    assert_eq!(three.viscous_moment_n_m, one.viscous_moment_n_m);
    let w = rpm_to_rad_s(12_000.0);
    let extra = three.heat.total_w() - one.heat.total_w();
    assert!((extra - 2.0 * w * m1).abs() < 1e-9 * extra, "{extra}");
    // Zero load friction leaves the viscous heat alone.
    let zero = at(0.0);
    assert!((one.heat.total_w() - zero.heat.total_w() - w * m1).abs() < 1e-9 * one.heat.total_w());
}
