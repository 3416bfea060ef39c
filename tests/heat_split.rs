//! The heat split (rolling, sliding, spin, drag, churning, seal, extra)
//! sums to the total heat in every heat output: the single bearing's
//! coupled state, and every row of the spindle; with the oil supply the
//! drag follows the supply and the speed.

use thermobear::bearing::Bearing;
use thermobear::spindle::*;
use thermobear::thermal::coupled::{CoupledBearing, CoupledOptions};
use thermobear::thermal::friction::{HeatModel, Lubrication};
use thermobear::thermal::oil_supply::{OilSupply, SupplySettings};

fn jet(w: f64) -> SupplySettings {
    SupplySettings::new(OilSupply::Jet {
        oil_flow_cm3_per_min: w,
        jet_count: 1,
        jet_velocity_m_per_s: None,
    })
}

fn supplies() -> Vec<Option<SupplySettings>> {
    vec![
        None,
        Some(jet(300.0)),
        Some(SupplySettings::new(OilSupply::OilAir {
            oil_volume_cm3_per_h: 0.5,
            air_flow_l_per_min: 40.0,
        })),
        Some(SupplySettings::new(OilSupply::OilBath { oil_level_mm: None })),
        Some(SupplySettings::new(OilSupply::Grease {
            grease_fill_fraction: 0.3,
        })),
    ]
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * b.abs().max(1.0)
}

#[test]
fn single_bearing_split_sums_to_the_total_for_every_supply_and_model() {
    let b = Bearing::preset("6208").unwrap();
    for model in [HeatModel::Palmgren, HeatModel::Skf] {
        for s in supplies() {
            let o = CoupledOptions {
                heat_model: model,
                lubrication: Lubrication::Jet,
                churning_oil_fraction: 0.03,
                extra_heat_w: 5.0,
                oil_supply: s,
                ..CoupledOptions::default()
            };
            let st = CoupledBearing::seed_a(&b, o)
                .unwrap()
                .solve(12_000.0, 2680.9, 1189.9)
                .unwrap();
            let h = &st.heat;
            assert!(
                close(h.breakdown.total_w(), h.heat.total_w()),
                "{model:?} {s:?}: {:?} vs {}",
                h.breakdown,
                h.heat.total_w()
            );
            assert_eq!(h.breakdown.extra_w, 5.0);
            assert_eq!(h.breakdown.drag_w, h.churning_w);
            match model {
                HeatModel::Palmgren => assert_eq!(h.breakdown.sliding_w, 0.0),
                HeatModel::Skf => assert!(h.breakdown.sliding_w > 0.0 && h.breakdown.spin_w == 0.0),
            }
        }
    }
}

#[test]
fn supply_drag_falls_behind_the_fixed_fraction_drag_at_speed() {
    // At a fixed jet flow the cavity fraction falls as 1/n, so the drag grows
    // as n^2 (omega_c^3 / n) instead of the fixed fraction's n^3.
    let b = Bearing::preset("6208").unwrap();
    let drag = |n: f64, s: Option<SupplySettings>| {
        let o = CoupledOptions {
            churning_oil_fraction: 0.03,
            oil_supply: s,
            ..CoupledOptions::default()
        };
        let st = CoupledBearing::seed_a(&b, o).unwrap().solve(n, 2680.9, 1189.9).unwrap();
        (st.heat.breakdown.drag_w, st.heat.cavity_oil_fraction)
    };
    let (lo_s, x_lo) = drag(6_500.0, Some(jet(300.0)));
    let (hi_s, x_hi) = drag(13_000.0, Some(jet(300.0)));
    let (lo_f, _) = drag(6_500.0, None);
    let (hi_f, _) = drag(13_000.0, None);
    assert!((x_lo / x_hi - 2.0).abs() < 1e-12, "{x_lo} {x_hi}");
    let supply_growth = hi_s / lo_s;
    let fixed_growth = hi_f / lo_f;
    assert!(supply_growth > 3.5 && supply_growth < 4.5, "{supply_growth}");
    assert!(fixed_growth > 7.0 && fixed_growth < 9.0, "{fixed_growth}");
    // Zero flow: no drag.
    assert_eq!(drag(13_000.0, Some(jet(0.0))).0, 0.0);
}

#[test]
fn spindle_rows_split_sums_to_the_total() {
    let base = Spindle::preset("seed-ceramic-spindle").unwrap();
    for s in supplies() {
        let mut cfg = base.config.clone();
        cfg.oil_supply = s;
        cfg.churning_oil_fraction = 0.01;
        let sp = Spindle::new(cfg).unwrap();
        let st = sp.thermal_state(12_000.0).unwrap();
        for h in &st.bearing_heat {
            assert!(
                close(h.breakdown.total_w(), h.heat.total_w()),
                "{s:?}: {:?} vs {}",
                h.breakdown,
                h.heat.total_w()
            );
            assert_eq!(h.breakdown.drag_w, h.drag_w);
        }
    }
}
