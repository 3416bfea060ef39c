//! The switchable effect `preload_change_from_axial_growth` in the coupled
//! seed B spindle: whether the axial thermal growth between the bearing sets
//! reaches the preload spring (spring law F = F0 + k_s x), and that a rigid
//! preload (floating rear set) is not affected by it.

use thermobear::bearing::RacewayOffsets;
use thermobear::spindle::*;
use thermobear::{Effect, EffectSet};

const SPEED_RPM: f64 = 15_000.0;
const F0_N: f64 = 400.0;

fn seed_b_with(effects: EffectSet, preload: Preload) -> Spindle {
    let mut cfg = SpindleConfig::preset("seed-ceramic-spindle").unwrap();
    cfg.effects = effects;
    cfg.preload = preload;
    Spindle::new(cfg).unwrap()
}

fn spring() -> Preload {
    Preload::Spring {
        force_n: F0_N,
        rate_n_per_m: SEED_B_SPRING_RATE_N_PER_M,
    }
}

/// The spindle's default effects (the magnetic pull is off by default; it
/// would add a radial load the direct pair solves below leave out).
fn base() -> EffectSet {
    EffectSet::all().without(Effect::UnbalancedMagneticPull)
}

fn off() -> EffectSet {
    base().without(Effect::PreloadChangeFromAxialGrowth)
}

/// The front pair re-solved directly at the state's own thermal offsets
/// with `spring_growth_m` of axial growth reaching the spring.
fn front_pair_at(sp: &Spindle, s: &SpindleState, spring_growth_m: f64) -> PairState {
    let a0 = sp.config.params.front_bearing.geometry.free_contact_angle_rad;
    let o = RacewayOffsets {
        axial_m: s.front_offsets.axial_with_gap_m(a0),
        radial_m: s.front_offsets.radial_with_gap_m(a0),
    };
    sp.front
        .solve(
            SPEED_RPM,
            &PairLoad {
                offsets: [o, o],
                spring_growth_m,
                ..Default::default()
            },
        )
        .unwrap()
}

#[test]
fn growth_reaches_the_spring_only_with_the_effect_on() {
    let ks = SEED_B_SPRING_RATE_N_PER_M;
    let sp_on = seed_b_with(base(), spring());
    let sp_off = seed_b_with(off(), spring());
    let on = sp_on.thermal_state(SPEED_RPM).unwrap();
    let off = sp_off.thermal_state(SPEED_RPM).unwrap();
    for s in [&on, &off] {
        // The growth is computed and reported either way.
        assert!(s.axial_growth_m > 10e-6, "{}", s.axial_growth_m);
        // Spring law, every bearing of both pairs: F = F0 + k_s x.
        for p in [&s.front, &s.rear] {
            let f = F0_N + ks * p.spring_compression_m;
            for a in p.axial_force_n {
                assert!((a - f).abs() < 1e-6 * f, "{a} vs {f}");
            }
        }
    }
    // Off: the coupled solve is the pair at its thermal offsets with no
    // growth at the spring (x only from the pair's own axial approach
    // change); on: with all of it. Two independent solves agree.
    let direct_off = front_pair_at(&sp_off, &off, 0.0);
    let direct_on = front_pair_at(&sp_on, &on, on.axial_growth_m);
    assert!((direct_off.preload_n - off.front.preload_n).abs() < 1e-6 * F0_N);
    assert!((direct_on.preload_n - on.front.preload_n).abs() < 1e-6 * F0_N);
    // At the off state's temperatures, letting its growth reach the spring
    // raises the force by k_s u in series with the pair's axial stiffness
    // k_b >> k_s: dF = k_s u k_b / (k_b + k_s), just below k_s u.
    let u = off.axial_growth_m;
    let with_growth = front_pair_at(&sp_off, &off, u);
    let df = with_growth.preload_n - off.front.preload_n;
    assert!(df < ks * u && df > 0.98 * ks * u, "{df} vs k_s u = {}", ks * u);
    // Coupled states: switching the effect on adds k_s u to the preload of
    // both pairs (within 3 %: series compliance, and the extra preload
    // heats the bearings, which changes u and the offsets a little).
    for (p_on, p_off) in [(&on.front, &off.front), (&on.rear, &off.rear)] {
        let d = p_on.preload_n - p_off.preload_n;
        let expect = ks * on.axial_growth_m;
        assert!((d - expect).abs() < 0.03 * expect, "{d} vs {expect}");
    }
    // Off, the spring is not compressed by the growth: its compression is
    // well below u (bearing approach changes only).
    assert!(
        off.front.spring_compression_m < 0.5 * u,
        "{}",
        off.front.spring_compression_m
    );
}

#[test]
fn compensation_preload_follows_the_effect() {
    let ks = SEED_B_SPRING_RATE_N_PER_M;
    let on = compensation_preload(&seed_b_with(base(), spring()), &[SPEED_RPM], ks).unwrap()[0];
    let off = compensation_preload(&seed_b_with(off(), spring()), &[SPEED_RPM], ks).unwrap()[0];
    assert!(on.axial_growth_m > 10e-6 && off.axial_growth_m > 10e-6);
    assert!((on.compensation_preload_n - ks * on.axial_growth_m).abs() < 1e-12 * on.compensation_preload_n);
    assert_eq!(off.compensation_preload_n, 0.0);
    // Solved change on vs off: the growth's share is about k_s u.
    let d = on.solved_preload_change_n - off.solved_preload_change_n;
    assert!((d - on.compensation_preload_n).abs() < 0.03 * on.compensation_preload_n);
}

#[test]
fn rigid_preload_is_unaffected_by_the_effect() {
    // The rear set floats in the housing: the growth between the sets
    // loads nothing, so the switch changes no number.
    let rigid = Preload::Rigid { force_n: F0_N };
    let on = seed_b_with(base(), rigid).thermal_state(SPEED_RPM).unwrap();
    let off = seed_b_with(off(), rigid).thermal_state(SPEED_RPM).unwrap();
    assert!(on.axial_growth_m > 10e-6);
    assert_eq!(on.axial_growth_m, off.axial_growth_m);
    assert_eq!(on.temperatures.temperatures_c, off.temperatures.temperatures_c);
    assert_eq!(on.front.preload_n, off.front.preload_n);
    assert_eq!(on.rear.preload_n, off.rear.preload_n);
    assert_eq!(on.front.spring_compression_m, 0.0);
}
