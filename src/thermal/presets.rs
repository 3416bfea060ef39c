//! Ready-made thermal networks for the two seed studies.
//!
//! # Seed A bearing network (Fig. 7, eq. A-28, Table A-2)
//!
//! Free nodes Ts (shaft), Tci (inner ring / shaft contact), Ti (inner
//! raceway), Tb (balls), To (outer raceway), Tco (outer ring / housing
//! contact), Th (housing); boundaries Tog (oil-air, 28 C) and Ta (ambient,
//! 26 C). Resistances (Table A-2 as we read it; the extraction is garbled,
//! our corrections are marked):
//!
//! * R_ci-s = 1/(k_s pi B) + 4 L_s/(k_s pi D_s^2) (spreading into the shaft
//!   plus axial conduction over L_s; the printed third term 1/(h_s pi D_s^2)
//!   is a convection term and belongs to R_s-og, so we drop it here).
//! * R_i-ci = ln(d_i/D_s)/(2 pi k_i B), R_o-co = ln(D/d_o)/(2 pi k_o C)
//!   (A-32; d_i, d_o groove-bottom diameters, D_s bore, D outside diameter).
//! * R_b-i = R_b-o = 1/(Z k_b pi D_b): the printed 1/(k_b pi D_b) is one ball;
//!   the node Tb lumps all Z balls, which conduct in parallel (correction).
//! * R_co-h = ln(D_h/D)/(2 pi k_h C) (conduction through the housing wall;
//!   the printed form mixes h_h into it).
//! * Housing to air: natural convection over the housing's outer cylinder
//!   pi D_h L_h plus both annular end faces (the printed R_h-a is the parallel
//!   combination of a radial and an axial path; same surfaces).
//! * Oil-air films (eq. A-31 with 0.332, see network.rs): shaft end face
//!   pi D_s^2/4 (the printed "Z/(h_s pi D_s^2)" reads as 4/(h pi D_s^2)),
//!   inner ring pi d_i B, balls Z pi D_b^2 (all balls; correction), outer ring
//!   pi d_o C. Surface speed: shaft omega D_s/2 with x = D_s; rings and balls
//!   the cage pitch speed omega_c dm/2 with omega_c = omega (1 - gamma)/2
//!   and x = dm. Oil properties at the oil-air temperature (seed A
//!   assumption 3: the temperature effect on the oil is ignored).
//!
//! Assumed dimensions (seed A gives none): D_s = bearing bore (40 mm); D_h
//! = 1.5 x bearing OD (120 mm, a 20 mm cast wall); L_s = 30 mm (shaft node
//! one bearing width beside the seat); L_h = 40 mm (housing boss length);
//! B = C = bearing width (18 mm); housing cast aluminium (e-drive case);
//! lubricant the e-drive ATF preset.
//!
//! # Seed B motorized spindle
//!
//! Front 7009C pair and rear 7008C pair (back-to-back), rotor on the shaft
//! between them, stator in a water-jacketed steel sleeve. Every dimension
//! and loss is assumed (seed B's tables did not survive extraction) and
//! listed on [`SpindleParams`]. Heat capacities are m c from the volumes and
//! densities of the parts; nothing is tuned to seed B's 21 min.

use std::f64::consts::PI;

use super::heat::{bearing_heat, load_moment_n_m, viscous_moment_n_m, HeatSplit};
use super::lubricant::Lubricant;
use super::network::{Convection, NodeId, ThermalNetwork, POHLHAUSEN_LOCAL, SEED_A_NATURAL_W_M2_K125};
use super::row_heat::oil_temperature_c;
use crate::bearing::{Bearing, BearingModel, SolveOptions};
use crate::effects::EffectSet;
use crate::error::{positive, Result};
use crate::materials::Material;
use crate::units::rpm_to_rad_s;

/// Ratio omega_c / omega of the cage to the inner ring (outer ring fixed,
/// pure rolling): (1 - gamma)/2, gamma = D cos(alpha)/dm.
fn cage_ratio(bearing: &Bearing) -> f64 {
    let g = &bearing.geometry;
    0.5 * (1.0 - g.ball_diameter_m * g.free_contact_angle_rad.cos() / g.pitch_diameter_m)
}

/// Oil-air film law of seed A eq. 31 with the oil at `oil_c`.
fn film(lub: &Lubricant, oil_c: f64, length_m: f64, velocity_per_speed_m: f64) -> Result<Convection> {
    Ok(Convection::ForcedFilm {
        coefficient: POHLHAUSEN_LOCAL,
        fluid_conductivity_w_mk: lub.conductivity_w_mk(oil_c)?,
        prandtl: lub.prandtl(oil_c)?,
        kinematic_viscosity_m2_s: lub.kinematic_viscosity_m2_s(oil_c)?,
        length_m,
        velocity_per_speed_m,
    })
}

/// How heat crosses from the balls into a raceway.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum BallConduction {
    /// Seed A Table A-2: 1/(k_b pi D_b) per ball (bulk conduction of the
    /// ball, no contact constriction), Z balls in parallel.
    SeedA,
    /// Constriction through the Hertz contact spots at contact load
    /// `contact_load_n` per ball: each contact is an isothermal disc of the
    /// same area as the contact ellipse, radius c = sqrt(a b), on two
    /// half-spaces, R = 1/(4 k_ball c) + 1/(4 k_ring c) (Carslaw & Jaeger;
    /// Yovanovich's area-equivalent circle for ellipses), Z in parallel.
    HertzConstriction {
        /// Normal contact load Q of one ball on the raceway \[N\], > 0; the
        /// contact ellipse is taken at the free contact angle.
        contact_load_n: f64,
    },
    /// The same constriction, with each row's own contact under the axial
    /// preload of the spindle ([`SpindleParams::preload_n`]): the row's
    /// static equilibrium under that preload ([`preloaded_contact`], its
    /// own ball count, conformities and free angle) gives the contact load
    /// Q and the operating contact angle of its balls, and the Hertz
    /// ellipse at that load and angle sets the spot size. It follows the
    /// preload (c grows as Q^(1/3)) and differs between the rows. The
    /// network's conductances are built once per preload, so the contact
    /// is the standstill one: speed and temperature change Q by tens of
    /// percent at most, c by a third of that.
    HertzAtPreload,
}

/// Resistance of the Z Hertz contact spots of one raceway at contact load
/// `contact_load_n` and contact angle `contact_angle_rad` (module docs of
/// [`BallConduction::HertzConstriction`]) [K/W].
pub fn hertz_constriction_k_per_w(
    bearing: &Bearing,
    inner: bool,
    contact_load_n: f64,
    contact_angle_rad: f64,
) -> Result<f64> {
    positive("contact_load_n", contact_load_n)?;
    let (contact, ring) = if inner {
        (bearing.inner_contact(contact_angle_rad)?, &bearing.inner_ring)
    } else {
        (bearing.outer_contact(contact_angle_rad)?, &bearing.outer_ring)
    };
    let c = (contact.semi_major(contact_load_n) * contact.semi_minor(contact_load_n)).sqrt();
    let per_contact = 1.0 / (4.0 * bearing.ball.conductivity_w_mk * c) + 1.0 / (4.0 * ring.conductivity_w_mk * c);
    Ok(per_contact / bearing.geometry.ball_count as f64)
}

/// Contact of one row at standstill under the axial load `axial_n`: mean
/// (inner, outer) contact load \[N\] and mean (inner, outer) contact angle
/// \[rad\] of its balls, from the static equilibrium of the ball solver.
pub fn preloaded_contact(bearing: &Bearing, axial_n: f64) -> Result<([f64; 2], [f64; 2])> {
    positive("preload_n", axial_n)?;
    let model = BearingModel::new(bearing)?;
    let state = model.solve(&[0.0, 0.0, axial_n, 0.0, 0.0], 0.0, &SolveOptions::default())?;
    let n = state.balls.len().max(1) as f64;
    let mean = |f: &dyn Fn(&crate::bearing::BallState) -> f64| state.balls.iter().map(f).sum::<f64>() / n;
    Ok((
        [mean(&|b| b.inner_load_n), mean(&|b| b.outer_load_n)],
        [
            mean(&|b| b.inner_contact_angle_rad),
            mean(&|b| b.outer_contact_angle_rad),
        ],
    ))
}

/// Ball-to-raceway resistance of all Z balls of one bearing [K/W];
/// [`BallConduction::HertzAtPreload`] needs the preload: use
/// [`row_ball_raceway_resistance_k_per_w`].
pub fn ball_raceway_resistance_k_per_w(bearing: &Bearing, inner: bool, model: BallConduction) -> Result<f64> {
    let g = &bearing.geometry;
    let z = g.ball_count as f64;
    match model {
        BallConduction::SeedA => Ok(1.0 / (z * bearing.ball.conductivity_w_mk * PI * g.ball_diameter_m)),
        BallConduction::HertzConstriction { contact_load_n } => {
            hertz_constriction_k_per_w(bearing, inner, contact_load_n, g.free_contact_angle_rad)
        }
        BallConduction::HertzAtPreload => Err(crate::error::Error::config(
            "ball_conduction",
            "HertzAtPreload",
            "the contact at the preload needs the preload: use row_ball_raceway_resistance_k_per_w",
        )),
    }
}

/// Ball-to-raceway resistances (inner, outer) of one row under the axial
/// preload `preload_n` [K/W]: [`BallConduction::HertzAtPreload`] from that
/// row's own preloaded contact, the other models as
/// [`ball_raceway_resistance_k_per_w`].
pub fn row_ball_raceway_resistance_k_per_w(
    bearing: &Bearing,
    model: BallConduction,
    preload_n: f64,
) -> Result<(f64, f64)> {
    match model {
        BallConduction::HertzAtPreload => {
            let (q, alpha) = preloaded_contact(bearing, preload_n)?;
            Ok((
                hertz_constriction_k_per_w(bearing, true, q[0], alpha[0])?,
                hertz_constriction_k_per_w(bearing, false, q[1], alpha[1])?,
            ))
        }
        m => Ok((
            ball_raceway_resistance_k_per_w(bearing, true, m)?,
            ball_raceway_resistance_k_per_w(bearing, false, m)?,
        )),
    }
}

/// Parameters of the seed A network (defaults: see module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct SeedAParams {
    /// Shaft diameter D_s at the seat \[m\]; default the bearing bore.
    pub shaft_diameter_m: f64,
    /// Housing outside diameter D_h \[m\]; default 1.5 x the bearing OD.
    pub housing_diameter_m: f64,
    /// Axial conduction length L_s from the seat to the shaft node \[m\];
    /// default 0.030. Also the shaft's axial-growth length of the mounting.
    pub shaft_length_m: f64,
    /// Housing boss length L_h \[m\] (convecting cylinder, and the housing's
    /// axial-growth length of the mounting); default 0.040.
    pub housing_length_m: f64,
    /// Housing material; default cast aluminium.
    pub housing: Material,
    /// Lubricant of the oil-air films and of the viscous moment; default the
    /// e-drive ATF preset.
    pub lubricant: Lubricant,
    /// Oil-air supply temperature, boundary node Tog \[C\]; default 28 (seed A).
    pub oil_air_temperature_c: f64,
    /// Ambient air temperature, boundary node Ta \[C\]; default 26 (seed A).
    /// Also the assembly temperature unless the coupled options give one.
    pub ambient_temperature_c: f64,
    /// Natural convection constant C of h = C dT^0.25 [W/(m^2 K^1.25)].
    pub natural_coefficient_w_m2_k125: f64,
}

impl SeedAParams {
    /// Defaults for a bearing (see module docs for the reasons).
    pub fn for_bearing(bearing: &Bearing) -> Self {
        SeedAParams {
            shaft_diameter_m: bearing.geometry.bore_m,
            housing_diameter_m: 1.5 * bearing.geometry.outer_diameter_m,
            shaft_length_m: 0.030,
            housing_length_m: 0.040,
            housing: Material::aluminium(),
            lubricant: Lubricant::edrive_atf(),
            oil_air_temperature_c: 28.0,
            ambient_temperature_c: 26.0,
            natural_coefficient_w_m2_k125: SEED_A_NATURAL_W_M2_K125,
        }
    }
}

/// The seed A network and its node ids.
#[derive(Debug, Clone)]
pub struct BearingNetwork {
    /// The network: 7 free massless nodes, 2 boundaries (steady state only).
    pub network: ThermalNetwork,
    /// Ts, the shaft.
    pub shaft: NodeId,
    /// Tci, the inner ring / shaft contact (inner ring bore).
    pub inner_contact: NodeId,
    /// Ti, the inner raceway; receives the inner-ring heat.
    pub inner: NodeId,
    /// Tb, all balls lumped; receives the ball heat.
    pub balls: NodeId,
    /// To, the outer raceway; receives the outer-ring heat.
    pub outer: NodeId,
    /// Tco, the outer ring / housing contact (outer ring OD).
    pub outer_contact: NodeId,
    /// Th, the housing.
    pub housing: NodeId,
    /// Tog, the oil-air supply (boundary).
    pub oil_air: NodeId,
    /// Ta, the ambient air (boundary).
    pub ambient: NodeId,
}

impl BearingNetwork {
    /// Source vector for a Burton-Staph split: inner-ring heat at Ti,
    /// ball heat at Tb, outer-ring heat at To \[W\]. (Eq. A-28 as extracted
    /// shows 0.5 factors in front of H_i, H_o; with A-27 already splitting
    /// the heat, we put each part's share on its node once.)
    pub fn sources_w(&self, split: &HeatSplit) -> Vec<f64> {
        let mut s = vec![0.0; self.network.nodes().len()];
        s[self.inner] = split.inner_ring_w;
        s[self.balls] = split.balls_w;
        s[self.outer] = split.outer_ring_w;
        s
    }
}

/// Build the seed A network (Fig. 7, Table A-2) around `bearing`.
pub fn seed_a_network(bearing: &Bearing, p: &SeedAParams) -> Result<BearingNetwork> {
    let g = &bearing.geometry;
    positive("shaft_diameter_m", p.shaft_diameter_m)?;
    positive("housing_diameter_m", p.housing_diameter_m)?;
    positive("shaft_length_m", p.shaft_length_m)?;
    positive("housing_length_m", p.housing_length_m)?;
    p.housing.validate()?;
    let (b, c) = (g.width_m, g.width_m);
    let (ds, dh, od) = (p.shaft_diameter_m, p.housing_diameter_m, g.outer_diameter_m);
    let (di, d_o) = (g.inner_raceway_diameter_m(), g.outer_raceway_diameter_m());
    let (z, db, dm) = (g.ball_count as f64, g.ball_diameter_m, g.pitch_diameter_m);
    let (ks, ki, ko, kh) = (
        bearing.shaft.conductivity_w_mk,
        bearing.inner_ring.conductivity_w_mk,
        bearing.outer_ring.conductivity_w_mk,
        p.housing.conductivity_w_mk,
    );
    let mut n = ThermalNetwork::new();
    let ts = n.add_node("Ts", 0.0)?;
    let tci = n.add_node("Tci", 0.0)?;
    let ti = n.add_node("Ti", 0.0)?;
    let tb = n.add_node("Tb", 0.0)?;
    let to = n.add_node("To", 0.0)?;
    let tco = n.add_node("Tco", 0.0)?;
    let th = n.add_node("Th", 0.0)?;
    let tog = n.add_boundary("Tog", p.oil_air_temperature_c)?;
    let ta = n.add_boundary("Ta", p.ambient_temperature_c)?;
    n.add_resistance(
        "R_ci-s",
        tci,
        ts,
        1.0 / (ks * PI * b) + 4.0 * p.shaft_length_m / (ks * PI * ds * ds),
    )?;
    n.add_resistance("R_i-ci", ti, tci, (di / ds).ln() / (2.0 * PI * ki * b))?;
    n.add_resistance(
        "R_b-i",
        tb,
        ti,
        ball_raceway_resistance_k_per_w(bearing, true, BallConduction::SeedA)?,
    )?;
    n.add_resistance(
        "R_b-o",
        tb,
        to,
        ball_raceway_resistance_k_per_w(bearing, false, BallConduction::SeedA)?,
    )?;
    n.add_resistance("R_o-co", to, tco, (od / d_o).ln() / (2.0 * PI * ko * c))?;
    n.add_resistance("R_co-h", tco, th, (dh / od).ln() / (2.0 * PI * kh * c))?;
    let housing_area = PI * dh * p.housing_length_m + 2.0 * 0.25 * PI * (dh * dh - od * od);
    n.add_convection(
        "R_h-a",
        th,
        ta,
        housing_area,
        Convection::Natural {
            coefficient_w_m2_k125: p.natural_coefficient_w_m2_k125,
        },
    )?;
    let oil = p.oil_air_temperature_c;
    let cage = cage_ratio(bearing) * 0.5 * dm;
    n.add_convection(
        "R_s-og",
        ts,
        tog,
        0.25 * PI * ds * ds,
        film(&p.lubricant, oil, ds, 0.5 * ds)?,
    )?;
    n.add_convection("R_i-og", ti, tog, PI * di * b, film(&p.lubricant, oil, dm, cage)?)?;
    n.add_convection("R_b-og", tb, tog, z * PI * db * db, film(&p.lubricant, oil, dm, cage)?)?;
    n.add_convection("R_o-og", to, tog, PI * d_o * c, film(&p.lubricant, oil, dm, cage)?)?;
    Ok(BearingNetwork {
        network: n,
        shaft: ts,
        inner_contact: tci,
        inner: ti,
        balls: tb,
        outer: to,
        outer_contact: tco,
        housing: th,
        oil_air: tog,
        ambient: ta,
    })
}

/// Assumed data of the seed B motorized spindle (all SI). Defaults in
/// [`SpindleParams::seed_b`].
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct SpindleParams {
    /// Bearing of the front (nose-side) pair; default 7009C-ceramic.
    pub front_bearing: Bearing,
    /// Bearing of the rear pair; default 7008C-ceramic.
    pub rear_bearing: Bearing,
    /// Shaft length from the front bearing pair centre to the rotor centre \[m\].
    pub front_span_m: f64,
    /// Shaft length from the rotor centre to the rear pair centre \[m\].
    pub rear_span_m: f64,
    /// Shaft nose length in front of the front pair \[m\].
    pub nose_length_m: f64,
    /// Rotor (laminations + cage) outside diameter \[m\].
    pub rotor_diameter_m: f64,
    /// Rotor length, also the stator core length \[m\].
    pub rotor_length_m: f64,
    /// Radial air gap rotor-stator \[m\] (seed B: 0.3 mm).
    pub air_gap_m: f64,
    /// Stator outside diameter \[m\].
    pub stator_outer_diameter_m: f64,
    /// Sleeve (housing) outside diameter \[m\].
    pub sleeve_outer_diameter_m: f64,
    /// Front bearing-seat housing length \[m\].
    pub front_housing_length_m: f64,
    /// Rear bearing-seat housing length \[m\].
    pub rear_housing_length_m: f64,
    /// Water jacket flow [L/min].
    pub water_flow_l_min: f64,
    /// Width w of the rectangular water-jacket channel \[m\].
    pub channel_width_m: f64,
    /// Height h of the rectangular water-jacket channel \[m\].
    pub channel_height_m: f64,
    /// Wetted fraction of the stator-sleeve interface area (0..1) [-].
    pub jacket_wetted_fraction: f64,
    /// Thermal contact conductance stator / sleeve (shrink fit) [W/(m^2 K)].
    pub stator_contact_w_m2k: f64,
    /// Thermal contact conductance of the outer rings' seats in the housing
    /// [W/(m^2 K)], over the seat area pi D W of each bearing; None: perfect
    /// contact (conduction through ring and housing only). A loose
    /// (clearance) fit with an oil film conducts about 10^3 to 10^4
    /// W/(m^2 K) (Yovanovich's gap and contact conductances); stored
    /// configurations without it load with None.
    #[serde(default)]
    pub outer_ring_contact_w_m2k: Option<f64>,
    /// The shaft of the rotor model as (length, outer diameter, inner
    /// diameter) \[m\] segments from the tool nose, in order; None: the
    /// layout derived from the bearing bores and spans. Only the rotor
    /// (its beam elements) reads it; the thermal network lumps the shaft.
    /// Stored configurations without it load with None.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub shaft_segments_m: Option<Vec<[f64; 3]>>,
    /// Cooling-water temperature, a boundary node \[C\] (seed B: 18).
    pub water_temperature_c: f64,
    /// Ambient air temperature, a boundary node \[C\] (seed B: 25).
    pub ambient_temperature_c: f64,
    /// Oil-air supply temperature \[C\] (compressed air at ambient).
    pub oil_air_temperature_c: f64,
    /// Lubricant of the oil-air films and of the viscous moment; default ISO VG 32.
    pub lubricant: Lubricant,
    /// Palmgren lubrication factor f0 (oil-air: 1-2; we take 1.0).
    pub lubrication_factor_f0: f64,
    /// Axial preload per bearing \[N\].
    pub preload_n: f64,
    /// Ball-raceway conduction model (default: Hertz constriction at each
    /// row's own contact under `preload_n`, [`BallConduction::HertzAtPreload`]).
    pub ball_conduction: BallConduction,
    /// Stator copper loss \[W\], put on the stator node; constant with speed.
    pub stator_copper_w: f64,
    /// Stator iron loss at `loss_reference_rpm` \[W\]; scales with (n/n_ref)^1.5.
    pub stator_iron_w: f64,
    /// Rotor copper loss \[W\], put on the rotor node; constant with speed.
    pub rotor_copper_w: f64,
    /// Rotor mechanical (windage) loss at `loss_reference_rpm` \[W\]; scales
    /// with (n/n_ref)^2.
    pub rotor_mechanical_w: f64,
    /// Speed n_ref at which the iron and windage losses are given, also the
    /// speed of the air-gap coefficient h1 \[rpm\].
    pub loss_reference_rpm: f64,
}

impl SpindleParams {
    /// Assumed seed B spindle: ceramic (Si3N4) 7009C front / 7008C rear
    /// pairs; rotor 79.4 mm x 150 mm, 0.3 mm gap (seed B), stator OD 140 mm,
    /// steel sleeve OD 180 mm; spans 120 / 120 mm; nose 60 mm; water 10
    /// L/min at 18 C (seed B) in a 10 x 5 mm channel wetting half the stator
    /// interface; ambient and oil-air 25 C (seed B); VG 32 oil, f0 = 1;
    /// preload 300 N (seed B's lowest). Motor losses at 12 000 rpm, no load:
    /// stator copper 250 W, iron 200 W, rotor copper 100 W, windage 50 W
    /// (600 W, about 6 % of a 10 kW spindle; the 2/3 stator, 1/3 rotor
    /// split of Bossmanns & Tu, J. Manuf. Sci. Eng. 121 (1999)). Iron loss
    /// scales with n^1.5 and windage with n^2 from the reference; copper is
    /// kept constant (magnetising current). Stator contact 1000 W/(m^2 K)
    /// (shrink fit, typical of 500-3000 in spindle models). Ball-raceway
    /// conduction through the Hertz spots (the seed A bulk form ignores the
    /// constriction and makes balls and rings nearly isothermal).
    pub fn seed_b() -> Result<Self> {
        Ok(SpindleParams {
            front_bearing: Bearing::preset("7009C-ceramic")?,
            rear_bearing: Bearing::preset("7008C-ceramic")?,
            ball_conduction: BallConduction::HertzAtPreload,
            front_span_m: 0.12,
            rear_span_m: 0.12,
            nose_length_m: 0.06,
            rotor_diameter_m: 0.0794,
            rotor_length_m: 0.15,
            air_gap_m: 0.3e-3,
            stator_outer_diameter_m: 0.14,
            sleeve_outer_diameter_m: 0.18,
            front_housing_length_m: 0.06,
            rear_housing_length_m: 0.05,
            water_flow_l_min: 10.0,
            channel_width_m: 0.010,
            channel_height_m: 0.005,
            jacket_wetted_fraction: 0.5,
            stator_contact_w_m2k: 1000.0,
            outer_ring_contact_w_m2k: None,
            shaft_segments_m: None,
            water_temperature_c: 18.0,
            ambient_temperature_c: 25.0,
            oil_air_temperature_c: 25.0,
            lubricant: Lubricant::iso_vg32(),
            lubrication_factor_f0: 1.0,
            preload_n: 300.0,
            stator_copper_w: 250.0,
            stator_iron_w: 200.0,
            rotor_copper_w: 100.0,
            rotor_mechanical_w: 50.0,
            loss_reference_rpm: 12_000.0,
        })
    }
}

/// Water at 18 C: nu [m^2/s], k [W/(m K)], Pr (Incropera table A.6).
const WATER_18C: (f64, f64, f64) = (1.06e-6, 0.598, 7.5);
/// Air at 25-40 C: nu [m^2/s], k [W/(m K)], Pr (Incropera table A.4).
const AIR: (f64, f64, f64) = (1.6e-5, 0.0265, 0.71);

/// Water-jacket film coefficient by Dittus-Boelter, Nu = 0.023 Re^0.8
/// Pr^0.4 (heated wall), for `flow_l_min` through a `w` x `h` rectangular
/// channel (hydraulic diameter 2 w h/(w + h)) [W/(m^2 K)].
pub fn water_jacket_h_w_m2k(flow_l_min: f64, width_m: f64, height_m: f64) -> Result<f64> {
    positive("water_flow_l_min", flow_l_min)?;
    positive("channel_width_m", width_m)?;
    positive("channel_height_m", height_m)?;
    let (nu, k, pr) = WATER_18C;
    let u = flow_l_min / 60_000.0 / (width_m * height_m);
    let dhyd = 2.0 * width_m * height_m / (width_m + height_m);
    let re = u * dhyd / nu;
    Ok(0.023 * re.powf(0.8) * pr.powf(0.4) * k / dhyd)
}

/// Becker & Kaye's Taylor-Couette air-gap Nusselt number (Nu = h 2 delta / k):
/// 2 for Ta < 1700, 0.128 Ta^0.367 for Ta < 1e4, 0.409 Ta^0.241 above;
/// Ta = omega^2 r_m delta^3 / nu^2.
fn air_gap_nusselt(speed_rad_s: f64, mean_radius_m: f64, gap_m: f64) -> f64 {
    let ta = speed_rad_s.powi(2) * mean_radius_m * gap_m.powi(3) / AIR.0.powi(2);
    if ta < 1700.0 {
        2.0
    } else if ta < 1e4 {
        (0.128 * ta.powf(0.367)).max(2.0)
    } else {
        0.409 * ta.powf(0.241)
    }
}

/// The spindle network, its node ids and its heat model.
#[derive(Debug, Clone)]
pub struct SpindleNetwork {
    /// The network: 13 free nodes with heat capacity m c, 3 boundaries.
    pub network: ThermalNetwork,
    /// The parameters it was built from (also used by the heat model).
    pub params: SpindleParams,
    /// Front shaft section (front journal and nose).
    pub shaft_front: NodeId,
    /// Rotor (laminations + cage and the shaft core under it); rotor losses.
    pub rotor: NodeId,
    /// Rear shaft section (rear journal).
    pub shaft_rear: NodeId,
    /// Stator core; stator losses.
    pub stator: NodeId,
    /// Inner rings of the front pair (both bearings lumped).
    pub front_inner: NodeId,
    /// Balls of the front pair (both bearings lumped).
    pub front_balls: NodeId,
    /// Outer rings of the front pair (both bearings lumped).
    pub front_outer: NodeId,
    /// Inner rings of the rear pair (both bearings lumped).
    pub rear_inner: NodeId,
    /// Balls of the rear pair (both bearings lumped).
    pub rear_balls: NodeId,
    /// Outer rings of the rear pair (both bearings lumped).
    pub rear_outer: NodeId,
    /// Front bearing-seat housing.
    pub housing_front: NodeId,
    /// Steel sleeve around the stator, cooled by the water jacket.
    pub sleeve: NodeId,
    /// Rear bearing-seat housing.
    pub housing_rear: NodeId,
    /// Cooling water (boundary).
    pub water: NodeId,
    /// Ambient air (boundary).
    pub ambient: NodeId,
    /// Oil-air supply (boundary).
    pub oil_air: NodeId,
}

/// Ring and ball volumes of one bearing [m^3]: inner ring (bore to groove
/// bottom), balls, outer ring (groove bottom to OD), grooves ignored.
fn bearing_volumes(b: &Bearing) -> (f64, f64, f64) {
    let g = &b.geometry;
    let ring = |d1: f64, d2: f64| 0.25 * PI * (d2 * d2 - d1 * d1) * g.width_m;
    (
        ring(g.bore_m, g.inner_raceway_diameter_m()),
        g.ball_count as f64 * PI * g.ball_diameter_m.powi(3) / 6.0,
        ring(g.outer_raceway_diameter_m(), g.outer_diameter_m),
    )
}

fn annulus_volume(d1: f64, d2: f64, len: f64) -> f64 {
    0.25 * PI * (d2 * d2 - d1 * d1) * len
}

impl SpindleNetwork {
    /// Build the network (see [`SpindleParams::seed_b`] for every assumption).
    pub fn new(p: SpindleParams) -> Result<Self> {
        let (fb, rb) = (&p.front_bearing, &p.rear_bearing);
        let steel = Material::shaft_steel();
        let mc = |m: &Material, v: f64| m.density_kg_m3 * m.specific_heat_j_kgk * v;
        let mut n = ThermalNetwork::new();
        // Shaft sections: front journal (bore of 7009C) incl. nose, rotor
        // core, rear journal.
        let (dsf, dsr) = (fb.geometry.bore_m, rb.geometry.bore_m);
        let c_sf = mc(
            &steel,
            annulus_volume(0.0, dsf, p.nose_length_m + p.front_span_m - 0.5 * p.rotor_length_m),
        );
        // The rear journal runs from the rotor core to the rear pair centre
        // and on to the pair's back face: a back-to-back pair is two bearings
        // wide, so one rear bearing width beyond its centre (the front
        // journal's counterpart is the nose).
        let c_sr = mc(
            &steel,
            annulus_volume(0.0, dsr, p.rear_span_m - 0.5 * p.rotor_length_m + rb.geometry.width_m),
        );
        let c_rotor = mc(&steel, annulus_volume(0.0, p.rotor_diameter_m, p.rotor_length_m));
        let stator_bore = p.rotor_diameter_m + 2.0 * p.air_gap_m;
        let c_stator = mc(
            &steel,
            annulus_volume(stator_bore, p.stator_outer_diameter_m, p.rotor_length_m),
        );
        let sf = n.add_node("shaft_front", c_sf)?;
        let rt = n.add_node("rotor", c_rotor)?;
        let sr = n.add_node("shaft_rear", c_sr)?;
        let st = n.add_node("stator", c_stator)?;
        // Bearing pairs (two bearings each, lumped).
        let mut bearing_nodes = |b: &Bearing, tag: &str| -> Result<[NodeId; 3]> {
            let (vi, vb, vo) = bearing_volumes(b);
            Ok([
                n.add_node(&format!("{tag}_inner"), 2.0 * mc(&b.inner_ring, vi))?,
                n.add_node(&format!("{tag}_balls"), 2.0 * mc(&b.ball, vb))?,
                n.add_node(&format!("{tag}_outer"), 2.0 * mc(&b.outer_ring, vo))?,
            ])
        };
        let [fi, fbn, fo] = bearing_nodes(fb, "front")?;
        let [ri, rbn, ro] = bearing_nodes(rb, "rear")?;
        let so = p.sleeve_outer_diameter_m;
        let hf = n.add_node(
            "housing_front",
            mc(
                &steel,
                annulus_volume(fb.geometry.outer_diameter_m, so, p.front_housing_length_m),
            ),
        )?;
        let sleeve_len = p.front_span_m + p.rear_span_m - p.front_housing_length_m.max(p.rear_housing_length_m);
        let sl = n.add_node(
            "sleeve",
            mc(&steel, annulus_volume(p.stator_outer_diameter_m, so, sleeve_len)),
        )?;
        let hr = n.add_node(
            "housing_rear",
            mc(
                &steel,
                annulus_volume(rb.geometry.outer_diameter_m, so, p.rear_housing_length_m),
            ),
        )?;
        let water = n.add_boundary("water", p.water_temperature_c)?;
        let amb = n.add_boundary("ambient", p.ambient_temperature_c)?;
        let oil = n.add_boundary("oil_air", p.oil_air_temperature_c)?;

        // Shaft axial conduction k A / L between section centres.
        let ks = steel.conductivity_w_mk;
        n.add_conduction("shaft_front-rotor", sf, rt, ks * 0.25 * PI * dsf * dsf / p.front_span_m)?;
        n.add_conduction("shaft_rear-rotor", sr, rt, ks * 0.25 * PI * dsr * dsr / p.rear_span_m)?;
        // Bearings: as in seed A, two bearings wide (2B), Z balls x 2.
        let lub = &p.lubricant;
        let oil_c = p.oil_air_temperature_c;
        let link_bearing = |n: &mut ThermalNetwork,
                            b: &Bearing,
                            tag: &str,
                            shaft: NodeId,
                            nodes: [NodeId; 3],
                            housing: NodeId|
         -> Result<()> {
            let g = &b.geometry;
            let w2 = 2.0 * g.width_m;
            let (di, d_o) = (g.inner_raceway_diameter_m(), g.outer_raceway_diameter_m());
            let zb = 2.0 * g.ball_count as f64;
            let shaft_r = 1.0 / (ks * PI * w2);
            n.add_resistance(
                &format!("{tag}_inner-shaft"),
                nodes[0],
                shaft,
                shaft_r + (di / g.bore_m).ln() / (2.0 * PI * b.inner_ring.conductivity_w_mk * w2),
            )?;
            // Two bearings in parallel: half the one-bearing resistance.
            let (rbi, rbo) = row_ball_raceway_resistance_k_per_w(b, p.ball_conduction, p.preload_n)?;
            let (rbi, rbo) = (0.5 * rbi, 0.5 * rbo);
            n.add_resistance(&format!("{tag}_balls-inner"), nodes[1], nodes[0], rbi)?;
            n.add_resistance(&format!("{tag}_balls-outer"), nodes[1], nodes[2], rbo)?;
            // Seat contact: 1/(h pi D 2B) for the two bearings' seats.
            let seat_r = p
                .outer_ring_contact_w_m2k
                .map_or(0.0, |h| 1.0 / (h * PI * g.outer_diameter_m * w2));
            n.add_resistance(
                &format!("{tag}_outer-housing"),
                nodes[2],
                housing,
                (g.outer_diameter_m / d_o).ln() / (2.0 * PI * b.outer_ring.conductivity_w_mk * w2)
                    + seat_r
                    + (so / g.outer_diameter_m).ln() / (2.0 * PI * steel.conductivity_w_mk * w2),
            )?;
            let dm = g.pitch_diameter_m;
            let cage = cage_ratio(b) * 0.5 * dm;
            n.add_convection(
                &format!("{tag}_inner-oil"),
                nodes[0],
                oil,
                PI * di * w2,
                film(lub, oil_c, dm, cage)?,
            )?;
            n.add_convection(
                &format!("{tag}_balls-oil"),
                nodes[1],
                oil,
                zb * PI * g.ball_diameter_m.powi(2),
                film(lub, oil_c, dm, cage)?,
            )?;
            n.add_convection(
                &format!("{tag}_outer-oil"),
                nodes[2],
                oil,
                PI * d_o * w2,
                film(lub, oil_c, dm, cage)?,
            )?;
            Ok(())
        };
        link_bearing(&mut n, fb, "front", sf, [fi, fbn, fo], hf)?;
        link_bearing(&mut n, rb, "rear", sr, [ri, rbn, ro], hr)?;
        // Rotor-stator air gap: Becker & Kaye at the loss reference speed,
        // blended with the conduction limit (Nu = 2) as h0 + h1 (w/w_ref)^0.734
        // (0.734 = 2 x 0.367, the Ta exponent in the middle regime).
        let rm = 0.5 * p.rotor_diameter_m + 0.5 * p.air_gap_m;
        let w_ref = rpm_to_rad_s(p.loss_reference_rpm);
        let h_cond = 2.0 * AIR.1 / (2.0 * p.air_gap_m);
        let h_ref = air_gap_nusselt(w_ref, rm, p.air_gap_m) * AIR.1 / (2.0 * p.air_gap_m);
        n.add_convection(
            "rotor-stator_gap",
            rt,
            st,
            PI * p.rotor_diameter_m * p.rotor_length_m,
            Convection::SpeedPower {
                h0_w_m2k: h_cond,
                h1_w_m2k: (h_ref - h_cond).max(0.0),
                reference_speed_rad_s: w_ref,
                exponent: 0.734,
            },
        )?;
        // Stator -> sleeve (shrink-fit contact) and sleeve -> water jacket.
        let stator_area = PI * p.stator_outer_diameter_m * p.rotor_length_m;
        n.add_conduction("stator-sleeve", st, sl, p.stator_contact_w_m2k * stator_area)?;
        let hw = water_jacket_h_w_m2k(p.water_flow_l_min, p.channel_width_m, p.channel_height_m)?;
        n.add_convection(
            "sleeve-water",
            sl,
            water,
            p.jacket_wetted_fraction * stator_area,
            Convection::Constant { h_w_m2k: hw },
        )?;
        // Sleeve axial conduction to the bearing housings.
        let a_sleeve = 0.25 * PI * (so * so - p.stator_outer_diameter_m.powi(2));
        n.add_conduction("sleeve-housing_front", sl, hf, ks * a_sleeve / (0.5 * sleeve_len))?;
        n.add_conduction("sleeve-housing_rear", sl, hr, ks * a_sleeve / (0.5 * sleeve_len))?;
        // Outside surfaces to ambient air (McAdams natural convection).
        let outside = Convection::natural_mcadams(so)?;
        n.add_convection(
            "housing_front-air",
            hf,
            amb,
            PI * so * p.front_housing_length_m + 0.25 * PI * (so * so - dsf * dsf),
            outside.clone(),
        )?;
        n.add_convection(
            "housing_rear-air",
            hr,
            amb,
            PI * so * p.rear_housing_length_m + 0.25 * PI * (so * so - dsr * dsr),
            outside.clone(),
        )?;
        n.add_convection("sleeve-air", sl, amb, PI * so * sleeve_len, outside)?;
        // Rotating shaft nose in air: laminar film with air properties.
        n.add_convection(
            "nose-air",
            sf,
            amb,
            PI * dsf * p.nose_length_m,
            Convection::ForcedFilm {
                coefficient: POHLHAUSEN_LOCAL,
                fluid_conductivity_w_mk: AIR.1,
                prandtl: AIR.2,
                kinematic_viscosity_m2_s: AIR.0,
                length_m: PI * dsf,
                velocity_per_speed_m: 0.5 * dsf,
            },
        )?;
        Ok(SpindleNetwork {
            network: n,
            params: p,
            shaft_front: sf,
            rotor: rt,
            shaft_rear: sr,
            stator: st,
            front_inner: fi,
            front_balls: fbn,
            front_outer: fo,
            rear_inner: ri,
            rear_balls: rbn,
            rear_outer: ro,
            housing_front: hf,
            sleeve: sl,
            housing_rear: hr,
            water,
            ambient: amb,
            oil_air: oil,
        })
    }

    /// Heat of one bearing pair at `speed_rpm` with oil at `oil_c` (two
    /// bearings, thrust preload only; spin heat needs the quasi-static
    /// contact data and is left out here).
    fn pair_heat(&self, b: &Bearing, speed_rpm: f64, oil_c: f64) -> Result<HeatSplit> {
        let p = &self.params;
        let g = &b.geometry;
        let m1 = load_moment_n_m(g, p.preload_n, 0.0, g.free_contact_angle_rad)?;
        let nu = p.lubricant.kinematic_viscosity_cst(oil_c)?;
        let mv = viscous_moment_n_m(p.lubrication_factor_f0, nu, speed_rpm, g.pitch_diameter_m)?;
        let h = bearing_heat(rpm_to_rad_s(speed_rpm), m1, mv, 0.0, &[], &[])?.split();
        Ok(HeatSplit {
            inner_ring_w: 2.0 * h.inner_ring_w,
            balls_w: 2.0 * h.balls_w,
            outer_ring_w: 2.0 * h.outer_ring_w,
        })
    }

    /// Heat sources [W per node] at `speed_rpm`. With
    /// `temperature_dependent_viscosity` on and node temperatures given,
    /// the oil viscosity is taken at each pair's ball temperature, else at
    /// the oil-air supply temperature (the rule of every heat model,
    /// [`super::row_heat::oil_temperature_c`]).
    pub fn sources_w(&self, speed_rpm: f64, temperatures_c: Option<&[f64]>, effects: EffectSet) -> Result<Vec<f64>> {
        let p = &self.params;
        positive("speed_rpm", speed_rpm)?;
        let mut s = vec![0.0; self.network.nodes().len()];
        let r = speed_rpm / p.loss_reference_rpm;
        s[self.stator] = p.stator_copper_w + p.stator_iron_w * r.powf(1.5);
        s[self.rotor] = p.rotor_copper_w + p.rotor_mechanical_w * r * r;
        let oil_at =
            |node: NodeId| oil_temperature_c(effects, p.oil_air_temperature_c, temperatures_c.map(|t| t[node]));
        for (b, [i, bl, o]) in [
            (&p.front_bearing, [self.front_inner, self.front_balls, self.front_outer]),
            (&p.rear_bearing, [self.rear_inner, self.rear_balls, self.rear_outer]),
        ] {
            let h = self.pair_heat(b, speed_rpm, oil_at(bl))?;
            s[i] += h.inner_ring_w;
            s[bl] += h.balls_w;
            s[o] += h.outer_ring_w;
        }
        Ok(s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::thermal::heat::BearingHeat;
    use crate::thermal::network::{SteadySolver, TransientSolver};

    #[test]
    fn seed_a_ordering_and_heat_balance() {
        let b = Bearing::preset("6208").unwrap();
        let net = seed_a_network(&b, &SeedAParams::for_bearing(&b)).unwrap();
        let speed = rpm_to_rad_s(6500.0);
        let split = BearingHeat {
            rolling_w: 80.0,
            inner_spin_w: 2.0,
            outer_spin_w: 10.0,
        }
        .split();
        let s = net.sources_w(&split);
        let t = SteadySolver::new(net.network.clone()).solve(&s, speed).unwrap();
        let v = &t.temperatures_c;
        assert!(
            v[net.balls] > v[net.inner] && v[net.inner] > v[net.outer] && v[net.outer] > v[net.housing],
            "{v:?}"
        );
        assert!(v[net.housing] > 26.0);
        let out: f64 = net.network.boundary_flows_w(v, speed).iter().map(|x| x.1).sum();
        assert!((out - 92.0).abs() < 1e-9 * 92.0, "{out}");
        // Faster: better oil-air cooling at the same heat input.
        let t2 = SteadySolver::new(net.network.clone()).solve(&s, 2.0 * speed).unwrap();
        assert!(t2.temperatures_c[net.balls] < v[net.balls]);
    }

    #[test]
    fn water_jacket_coefficient_magnitude() {
        // 10 L/min through 10 x 5 mm: u = 3.33 m/s, Dh = 6.67 mm, Re = 2.1e4,
        // Nu = 0.023 Re^0.8 Pr^0.4 ~ 150 -> h ~ 1.3e4 W/(m^2 K).
        let h = water_jacket_h_w_m2k(10.0, 0.010, 0.005).unwrap();
        let re: f64 = (10.0 / 60_000.0 / 5e-5) * (2.0 * 0.010 * 0.005 / 0.015) / 1.06e-6;
        let hand = 0.023 * re.powf(0.8) * 7.5f64.powf(0.4) * 0.598 / (2.0 * 0.010 * 0.005 / 0.015);
        assert!((h - hand).abs() < 1e-9 * hand && (1.0e4..1.7e4).contains(&h), "{h}");
    }

    #[test]
    fn spindle_steady_state_balance_and_ordering() {
        let sp = SpindleNetwork::new(SpindleParams::seed_b().unwrap()).unwrap();
        let speed = rpm_to_rad_s(12_000.0);
        let mut solver = SteadySolver::new(sp.network.clone());
        let s0 = sp.sources_w(12_000.0, None, EffectSet::all()).unwrap();
        let t = solver
            .solve_with(
                speed,
                |t| sp.sources_w(12_000.0, Some(&t.temperatures_c), EffectSet::all()),
                1e-9,
                100,
            )
            .unwrap();
        let v = &t.temperatures_c;
        let s = sp.sources_w(12_000.0, Some(v), EffectSet::all()).unwrap();
        let out: f64 = sp.network.boundary_flows_w(v, speed).iter().map(|x| x.1).sum();
        let total: f64 = s.iter().sum();
        assert!((out - total).abs() < 1e-8 * total, "{out} {total}");
        // Fixed point: the sources at T* reproduce T* in a fresh solve, and
        // they differ from the supply-temperature estimate (viscosity really moved).
        let again = SteadySolver::new(sp.network.clone()).solve(&s, speed).unwrap();
        for (a, b) in again.temperatures_c.iter().zip(v) {
            assert!((a - b).abs() < 1e-7, "{a} {b}");
        }
        assert!((total - s0.iter().sum::<f64>()).abs() > 1.0);
        // Seed B: balls hotter than inner rings hotter than outer rings, and
        // the sleeve near the water the coolest free node.
        assert!(
            v[sp.front_balls] > v[sp.front_inner] && v[sp.front_inner] > v[sp.front_outer],
            "{v:?}"
        );
        let coolest = (0..v.len())
            .filter(|&i| i != sp.water && i != sp.ambient && i != sp.oil_air)
            .min_by(|&a, &b| v[a].total_cmp(&v[b]))
            .unwrap();
        assert_eq!(coolest, sp.sleeve);
    }

    #[test]
    fn spindle_transient_time_constant() {
        let sp = SpindleNetwork::new(SpindleParams::seed_b().unwrap()).unwrap();
        let speed = rpm_to_rad_s(12_000.0);
        let s = sp.sources_w(12_000.0, None, EffectSet::all()).unwrap();
        let steady = SteadySolver::new(sp.network.clone()).solve(&s, speed).unwrap();
        let tau = sp.network.time_constants_s(&steady.temperatures_c, speed).unwrap();
        // Computed from masses, not tuned: the slowest mode is minutes long.
        assert!(tau[0] > 60.0 && tau[0] < 3600.0, "{tau:?}");
        // Transient from 25 C (water node fixed at 18 C) approaches the steady
        // state; after 8 tau the rotor is within 0.1 % of its rise.
        let mut tr = TransientSolver::new(sp.network.clone());
        let init = sp.network.initial_temperatures(25.0);
        let run = tr
            .integrate(&init, 8.0 * tau[0], 10.0, speed, 1000, |_, _, out| {
                out.copy_from_slice(&s);
                Ok(())
            })
            .unwrap();
        let last = run.temperatures_c.last().unwrap();
        let rise = steady.temperatures_c[sp.rotor] - 25.0;
        assert!((last[sp.rotor] - steady.temperatures_c[sp.rotor]).abs() < 1e-3 * rise.abs().max(1.0));
    }
}
