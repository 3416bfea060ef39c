//! Heat of one solved bearing row: the single implementation that the
//! single-bearing model ([`super::coupled`]) and every row of the spindle
//! ([`crate::spindle`]) call (docs/concepts/physics.md §4 and §9, "One
//! implementation for the single bearing and the spindle rows").
//!
//! From a quasi-static state it takes, in one place:
//!
//! * the oil state: the oil temperature by one rule ([`oil_temperature_c`]:
//!   the ball temperature with `temperature_dependent_viscosity` on and a
//!   temperature known, else the oil supply temperature), the kinematic
//!   viscosity and density there ([`OilState`]);
//! * the contact angle of Palmgren's P1: the load-weighted mean inner
//!   contact angle ([`mean_inner_contact_angle_rad`]);
//! * the spin contacts: every ball's load, Hertz semi-major axis and spin
//!   speed, E(kappa) at its operating contact angle ([`spin_contacts`]),
//!   only with the `spin_friction` effect on;
//! * the cage speed of the ball drag: the mean orbit speed of the balls
//!   ([`cage_speed_rad_s`]);
//!
//! and hands them to [`friction_heat`] (moments, drag, spin, split).

use super::friction::{friction_heat, FrictionHeat, FrictionPoint, FrictionSettings};
use super::heat::SpinContact;
use super::lubricant::Lubricant;
use crate::bearing::contact::{curvature, hamrock_brewe};
use crate::bearing::{Bearing, BearingState, Raceway};
use crate::effects::{Effect, EffectSet};
use crate::error::{finite, Result};

/// The oil as the heat model sees it: temperature, kinematic viscosity and
/// density there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OilState {
    /// Oil temperature used by the viscous moment and the drag \[C\].
    pub temperature_c: f64,
    /// Kinematic viscosity at `temperature_c` \[cSt\].
    pub viscosity_cst: f64,
    /// Density at `temperature_c` [kg/m^3].
    pub density_kg_m3: f64,
}

impl OilState {
    /// The oil of `lubricant` at `temperature_c` (inside its data range).
    pub fn at(lubricant: &Lubricant, temperature_c: f64) -> Result<Self> {
        finite("oil_temperature_c", temperature_c)?;
        Ok(OilState {
            temperature_c,
            viscosity_cst: lubricant.kinematic_viscosity_cst(temperature_c)?,
            density_kg_m3: lubricant.density_kg_m3(temperature_c)?,
        })
    }
}

/// The oil temperature of the heat model \[C\] (one rule for the single
/// bearing and the spindle rows): the temperature of the balls (the node
/// the oil film sits on) when `temperature_dependent_viscosity` is on and
/// that temperature is known; otherwise the oil supply temperature (the
/// oil-air supply of seed A's assumption 3 and of seed B's spindle).
pub fn oil_temperature_c(effects: EffectSet, supply_temperature_c: f64, ball_temperature_c: Option<f64>) -> f64 {
    match ball_temperature_c {
        Some(t) if effects.has(Effect::TemperatureDependentViscosity) => t,
        _ => supply_temperature_c,
    }
}

/// Load-weighted mean inner contact angle of the loaded balls; the free
/// angle when no ball carries load \[rad\]. Palmgren's P1 stands for the
/// whole bearing, so each ball's angle counts by the load it carries: an
/// unloaded ball (radial load, or a ball lifted off at speed) transmits
/// nothing through its angle, and a plain mean would let it count.
pub fn mean_inner_contact_angle_rad(bearing: &Bearing, state: &BearingState) -> f64 {
    let (qa, q) = state.balls.iter().fold((0.0, 0.0), |(qa, q), b| {
        (qa + b.inner_load_n * b.inner_contact_angle_rad, q + b.inner_load_n)
    });
    if q > 0.0 {
        qa / q
    } else {
        bearing.geometry.free_contact_angle_rad
    }
}

/// Cage speed of a solved state: the mean orbit speed of its balls
/// [rad/s]. The quasi-static model gives each ball its own orbit speed
/// (equal under a pure axial load); the cage makes them share one.
pub fn cage_speed_rad_s(state: &BearingState) -> f64 {
    let n = state.balls.len().max(1) as f64;
    state.balls.iter().map(|b| b.orbit_speed_rad_s).sum::<f64>() / n
}

/// Complete elliptic integral E of a contact at `alpha` (Hamrock-Brewe).
fn elliptic_e(bearing: &Bearing, raceway: Raceway, alpha: f64) -> f64 {
    let g = &bearing.geometry;
    let f = match raceway {
        Raceway::Inner => g.inner_conformity,
        Raceway::Outer => g.outer_conformity,
    };
    let c = curvature(raceway, g.ball_diameter_m, g.pitch_diameter_m, f, alpha);
    hamrock_brewe(c.ry / c.rx).1
}

/// Spin contacts of every ball from a solved state, E(kappa) at each
/// contact's operating angle.
pub fn spin_contacts(bearing: &Bearing, state: &BearingState) -> (Vec<SpinContact>, Vec<SpinContact>) {
    let inner = state
        .balls
        .iter()
        .map(|b| SpinContact {
            load_n: b.inner_load_n.max(0.0),
            semi_major_m: b.inner_semi_major_m.max(0.0),
            elliptic_e: elliptic_e(bearing, Raceway::Inner, b.inner_contact_angle_rad),
            spin_speed_rad_s: b.inner_spin_rad_s,
        })
        .collect();
    let outer = state
        .balls
        .iter()
        .map(|b| SpinContact {
            load_n: b.outer_load_n.max(0.0),
            semi_major_m: b.outer_semi_major_m.max(0.0),
            elliptic_e: elliptic_e(bearing, Raceway::Outer, b.outer_contact_angle_rad),
            spin_speed_rad_s: b.outer_spin_rad_s,
        })
        .collect();
    (inner, outer)
}

/// Heat of one solved row (single bearing or spindle row) under the
/// applied `axial_n` and `radial_n` (magnitudes are taken), with `oil`
/// and `settings`; spin heat only with [`Effect::SpinFriction`] in `effects`.
#[allow(clippy::too_many_arguments)]
pub fn row_friction_heat(
    bearing: &Bearing,
    state: &BearingState,
    axial_n: f64,
    radial_n: f64,
    oil: &OilState,
    lubricant: &Lubricant,
    settings: &FrictionSettings,
    effects: EffectSet,
) -> Result<FrictionHeat> {
    let (ci, co) = if effects.has(Effect::SpinFriction) {
        spin_contacts(bearing, state)
    } else {
        (Vec::new(), Vec::new())
    };
    let point = FrictionPoint {
        geometry: &bearing.geometry,
        axial_n: axial_n.abs(),
        radial_n: radial_n.abs(),
        contact_angle_rad: mean_inner_contact_angle_rad(bearing, state),
        speed_rpm: state.speed_rpm,
        viscosity_cst: oil.viscosity_cst,
        oil_density_kg_m3: oil.density_kg_m3,
        cage_speed_rad_s: cage_speed_rad_s(state),
        ball_mass_kg: bearing.ball_mass_kg(),
        lubricant_name: &lubricant.name,
        inner_contacts: &ci,
        outer_contacts: &co,
    };
    friction_heat(settings, &point)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearing::{BearingModel, SolveOptions};
    use crate::thermal::friction::{HeatModel, Lubrication, SkfSettings};
    use crate::thermal::heat::load_moment_n_m;

    /// A deep-groove bearing under equal thrust and radial load at speed:
    /// the balls carry different loads at different angles. M1 takes the load-weighted mean inner
    /// angle (the one rule of every row), which differs from the plain mean.
    #[test]
    fn palmgren_m1_uses_the_load_weighted_contact_angle() {
        let b = Bearing::preset("6208").unwrap();
        let model = BearingModel::new(&b).unwrap();
        let (fa, fr) = (1500.0, 1500.0);
        let state = model
            .solve(&[fr, 0.0, fa, 0.0, 0.0], 6000.0, &SolveOptions::default())
            .unwrap();
        let lub = Lubricant::iso_vg32();
        let oil = OilState::at(&lub, 50.0).unwrap();
        let settings = FrictionSettings {
            heat_model: HeatModel::Palmgren,
            lubrication: Lubrication::OilAir,
            lubrication_factor_f0: 1.0,
            spin_friction_coefficient: 0.05,
            load_friction_scale: 1.0,
            oil_volume_fraction: 0.0,
            oil_supply: None,
            skf: SkfSettings::default(),
        };
        let f = row_friction_heat(&b, &state, fa, fr, &oil, &lub, &settings, EffectSet::all()).unwrap();
        let weighted = mean_inner_contact_angle_rad(&b, &state);
        let n = state.balls.len() as f64;
        let plain = state.balls.iter().map(|x| x.inner_contact_angle_rad).sum::<f64>() / n;
        let m_weighted = load_moment_n_m(&b.geometry, fa, fr, weighted).unwrap();
        let m_plain = load_moment_n_m(&b.geometry, fa, fr, plain).unwrap();
        assert_eq!(f.load_moment_n_m, m_weighted);
        assert!(
            (m_plain - m_weighted).abs() > 1e-3 * m_weighted,
            "{m_plain} {m_weighted}"
        );
        // The oil state is the lubricant's at the given temperature.
        assert_eq!(oil.viscosity_cst, lub.kinematic_viscosity_cst(50.0).unwrap());
    }
}
