//! Integration checks of the coupled thermo-mechanical model (seed A).
use thermobear::bearing::Bearing;
use thermobear::effects::{Effect, EffectSet};
use thermobear::thermal::coupled::{CoupledBearing, CoupledOptions};

/// Seed A: 300 N preload + 2380.9 N axial, 1189.9 N radial at 100 N m.
const FA: f64 = 2680.9;
const FR: f64 = 1189.9;

fn coupled(effects: EffectSet) -> CoupledBearing {
    let b = Bearing::preset("6208").unwrap();
    let mut o = CoupledOptions::default();
    o.solve.effects = effects;
    CoupledBearing::seed_a(&b, o).unwrap()
}

const EXPANSIONS: [Effect; 5] = [
    Effect::ThermalExpansionShaft,
    Effect::ThermalExpansionInnerRing,
    Effect::ThermalExpansionOuterRing,
    Effect::ThermalExpansionBalls,
    Effect::ThermalExpansionHousing,
];

fn only(keep: &[Effect]) -> EffectSet {
    EXPANSIONS
        .iter()
        .filter(|e| !keep.contains(e))
        .fold(EffectSet::all(), |s, e| s.without(*e))
}

#[test]
fn axial_load_heats_more_than_radial_load() {
    // Seed A Fig. 8b, c at 6500 rpm: axial load 0 -> 2380.9 N (radial 1189.9 N)
    // against radial load 0 -> 1189.9 N (axial 2380.9 N), 300 N preload on top.
    let c = coupled(EffectSet::all());
    let tb = |fa: f64, fr: f64| c.solve(6_500.0, fa, fr).unwrap().temperature_c("Tb").unwrap();
    let axial_rise = tb(FA, FR) - tb(300.0, FR);
    let radial_rise = tb(FA, FR) - tb(FA, 0.0);
    assert!(
        axial_rise > 0.0 && axial_rise > radial_rise,
        "{axial_rise} {radial_rise}"
    );
}

#[test]
fn growth_that_closes_the_clearance_stiffens_the_bearing() {
    // Hot balls and a hot inner ring (nothing else growing) raise the
    // interference: the contact loads and the radial stiffness rise against
    // the isothermal state at the same speed and load.
    let iso = coupled(only(&[])).solve(10_000.0, FA, FR).unwrap();
    let hot = coupled(only(&[
        Effect::ThermalExpansionBalls,
        Effect::ThermalExpansionInnerRing,
    ]))
    .solve(10_000.0, FA, FR)
    .unwrap();
    assert_eq!(iso.raceway_offsets.radial_m, 0.0);
    assert!(hot.raceway_offsets.radial_m > 0.0);
    assert!(hot.bearing.radial_stiffness_seed_n_per_m > iso.bearing.radial_stiffness_seed_n_per_m);
    assert!(hot.bearing.max_inner_load_n() > iso.bearing.max_inner_load_n());
    // A hot housing alone (tight fit) opens the clearance instead.
    let housing = coupled(only(&[Effect::ThermalExpansionHousing]))
        .solve(10_000.0, FA, FR)
        .unwrap();
    assert!(housing.raceway_offsets.radial_m < 0.0);
    assert!(housing.bearing.radial_stiffness_seed_n_per_m < iso.bearing.radial_stiffness_seed_n_per_m);
}

#[test]
fn viscosity_at_the_operating_temperature_lowers_the_viscous_heat() {
    // The ball node is hotter than the 28 C oil-air supply, so the oil is
    // thinner there and Mv ~ nu^(2/3) falls.
    let on = coupled(EffectSet::all()).solve(12_000.0, FA, FR).unwrap();
    let off = coupled(EffectSet::all().without(Effect::TemperatureDependentViscosity))
        .solve(12_000.0, FA, FR)
        .unwrap();
    assert!(on.heat.oil_temperature_c > 28.0 && off.heat.oil_temperature_c == 28.0);
    assert!(on.heat.viscosity_cst < off.heat.viscosity_cst);
    let ratio = on.heat.viscous_w / off.heat.viscous_w;
    let expect = (on.heat.viscosity_cst / off.heat.viscosity_cst).powf(2.0 / 3.0);
    assert!((ratio - expect).abs() < 1e-12, "{ratio} {expect}");
}
