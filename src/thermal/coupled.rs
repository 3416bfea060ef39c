//! The coupled thermo-mechanical fixed point of one bearing in its thermal
//! network (seed A Fig. 7; docs/concepts/physics.md §1, the coupling chain).
//!
//! One iteration maps node temperatures T to new node temperatures:
//!
//! 1. component rises over the assembly temperature (shaft Ts, inner ring
//!    the mean of Ti and Tci, balls Tb, outer ring the mean of To and Tco,
//!    housing Th) -> [`thermal_offsets`] (A-33..A-37, each part switched by
//!    its `thermal_expansion_*` effect);
//! 2. offsets -> [`RacewayOffsets`]: `radial_m = u_Tr - dA cos(alpha0)`,
//!    `axial_m = u_Ta - dA sin(alpha0)` with dA = dr_i + dr_o - dD the change
//!    of the free groove-centre gap. This is how the ball growth dD enters:
//!    a ball growing by dD shortens the loaded distance between the groove
//!    centres available to the two contacts by dD along the contact line.
//!    The projection on the free contact line instead of the operating one
//!    is second order: dD (1 - cos(alpha - alpha0)), below 0.1 nm here;
//!    the Hertz constants of the grown ball (dD/D ~ 1e-4) are not rebuilt;
//! 3. quasi-static solve (Jones-Harris): the first from the static start,
//!    later ones warm-started from the previous iteration (an unchanged
//!    offset reuses the previous state, so with every expansion switched
//!    off the result is bit-identical to the isothermal solve); every speed
//!    is independent of the others;
//! 4. heat (A-20..A-23): omega M1 (Palmgren, applied loads, load-weighted
//!    mean inner contact angle) + omega Mv (viscosity at the ball node when
//!    `temperature_dependent_viscosity` is on, else at the oil-air supply
//!    temperature, seed A assumption 3) + per-contact spin heat
//!    |omega_s| (3/8) mu_s Q a E (`spin_friction_coefficient`), E by Hamrock-Brewe at
//!    the operating contact angle; optionally the ball drag ("churning") in
//!    the oil-air mixture, Z (pi/64) C_D X rho_oil D^2 dm^3 omega_c^3
//!    ([`super::heat::ball_drag_power_w`], Harris & Kotzalas) at the cage speed of the
//!    solved state and the oil density at the oil temperature of Mv, when
//!    [`CoupledOptions::churning_oil_fraction`] X > 0;
//! 5. Burton-Staph split (A-27) -> steady network (Newton, warm start).
//!
//! Fixed point: Anderson(1) acceleration of the damped Picard iteration
//! `T <- T + lambda (G(T) - T)` ([`anderson_step`]), lambda = 1 to start,
//! halved whenever the temperature change grows; a step whose extrapolation
//! alone would cross the lubricant's temperature limit falls back to G(T). Converged when the
//! largest node change is below `tolerance_k` and the raceway offsets moved
//! less than `tolerance_m`.
//!
//! Thermal runaway is reported as [`Error::ThermalRunaway`] when (a) the
//! bearing held at the lubricant's highest temperature with data (a
//! physical bound: the lubricant fails there) still heats a node beyond it
//! (iterates beyond the bound are pulled back onto it, [`toward_bound`]:
//! the first iterates run on the cold oil's viscous heat and overshoot
//! steady states far below the bound), or (b) heat, the hottest node and the
//! largest contact load all grow while the change between iterates does not
//! shrink, for [`RUNAWAY_STREAK`] iterations in a row (the preload-heat
//! loop diverging). `max_iterations` ends every run with
//! [`Error::convergence`] otherwise.

use rayon::prelude::*;

use super::expansion::{thermal_offsets, ComponentRises, Mounting, RingFit, ThermalOffsets};
use super::friction::{FrictionSettings, HeatBreakdown, HeatModel, Lubrication, SkfMoments, SkfSettings};
use super::heat::{BearingHeat, HeatSplit};
use super::lubricant::Lubricant;
use super::network::SteadySolver;
use super::oil_supply::SupplySettings;
use super::presets::{seed_a_network, BearingNetwork, SeedAParams};
use super::row_heat::{oil_temperature_c, row_friction_heat, OilState};
use crate::bearing::quasi_static::{static_start_q, WarmStart};
use crate::bearing::{Bearing, BearingModel, BearingState, RacewayOffsets, SolveOptions};
use crate::effects::EffectSet;
use crate::error::{finite, in_range, non_negative, positive, Error, Result};
use crate::units::rpm_to_rad_s;

/// Growth streak that declares a runaway (see module docs).
pub const RUNAWAY_STREAK: usize = 4;

/// Settings of the coupled model.
#[derive(Debug, Clone, PartialEq)]
pub struct CoupledOptions {
    /// Bearing solver options; `effects` holds every effect (mechanical,
    /// thermal expansion, viscosity, spin friction); `offsets` is ignored
    /// (the coupled model sets it).
    pub solve: SolveOptions,
    /// Palmgren lubrication factor f0. Default 1.0: Harris' value
    /// for a deep-groove bearing under oil mist (oil-air in seed A).
    pub lubrication_factor_f0: f64,
    /// Spin sliding friction coefficient mu_s. Seed A gives no value;
    /// default 0.05 ([`crate::spindle::DEFAULT_SPIN_FRICTION_COEFFICIENT`],
    /// the spindle's and Python's default): EHL traction at spin-dominated
    /// sliding is 0.03..0.07 (Harris & Kotzalas, traction curves). Assumption.
    pub spin_friction_coefficient: f64,
    /// Assembly (reference) temperature of the clearance and fits \[C\];
    /// `None`: the ambient temperature of the network.
    pub reference_temperature_c: Option<f64>,
    /// Extra heat at the bearing \[W\] beyond the modelled friction (e.g. the
    /// friction of a magnetic pull load the model does not apply, seed B),
    /// split like rolling friction heat (Burton-Staph, A-27: 1/4 inner ring,
    /// 1/2 balls, 1/4 outer ring). Calibration input; default 0.
    pub extra_heat_w: f64,
    /// Oil volume fraction X of the oil-air mixture in the bearing cavity
    /// (0..1, dimensionless) for the ball drag ("churning") loss
    /// Z (pi/64) C_D X rho_oil D^2 dm^3 omega_c^3 (Harris & Kotzalas; C_D =
    /// [`super::heat::SPHERE_DRAG_COEFFICIENT`]). It is dissipated in the lubricant
    /// between the rings like the Palmgren viscous loss Mv, so it is split
    /// like rolling heat (A-27: 1/4 inner ring, 1/2 balls, 1/4 outer ring).
    /// Calibration input; default 0 (off: seed A's heat, A-23).
    pub churning_oil_fraction: f64,
    /// Oil supply (docs/concepts/physics.md §9, oil supply): when set, the
    /// cavity oil fraction, drag and churning follow from the supply and the
    /// speed and `churning_oil_fraction` is not used. Default None.
    pub oil_supply: Option<SupplySettings>,
    /// Heat model (docs/concepts/physics.md §9): Palmgren (default, the
    /// seeds') or the four-term SKF-style model.
    pub heat_model: HeatModel,
    /// Lubrication method: the SKF replenishment constant K_rs when not set
    /// in `skf` (the f0 and X defaults of a method are applied by the
    /// caller through [`Lubrication::defaults`]). Default oil-air (seed A).
    pub lubrication: Lubrication,
    /// Settings of the SKF-style model (series, mu_EHL, K_rs, seal moment).
    pub skf: SkfSettings,
    /// Scale on the housing-to-ambient convection conductance (link R_h-a,
    /// natural convection h = C dT^0.25 scaled through C): a housing that
    /// sheds heat better (fins, air flow, conduction into the machine) or
    /// worse than the bare cylinder assumed. Calibration input; default 1.
    pub housing_conductance_scale: f64,
    /// Largest node temperature change at convergence \[K\].
    pub tolerance_k: f64,
    /// Largest change of the raceway offsets at convergence \[m\].
    pub tolerance_m: f64,
    /// Most fixed-point iterations before [`Error::Convergence`] (>= 1; default 200).
    pub max_iterations: usize,
}

impl Default for CoupledOptions {
    fn default() -> Self {
        CoupledOptions {
            solve: SolveOptions::default(),
            lubrication_factor_f0: 1.0,
            spin_friction_coefficient: crate::spindle::DEFAULT_SPIN_FRICTION_COEFFICIENT,
            reference_temperature_c: None,
            extra_heat_w: 0.0,
            churning_oil_fraction: 0.0,
            oil_supply: None,
            heat_model: HeatModel::Palmgren,
            lubrication: Lubrication::OilAir,
            skf: SkfSettings::default(),
            housing_conductance_scale: 1.0,
            tolerance_k: 1e-6,
            tolerance_m: 1e-12,
            max_iterations: 200,
        }
    }
}

impl CoupledOptions {
    /// Check every field (bad values name their field).
    pub fn validate(&self) -> Result<()> {
        positive("lubrication_factor_f0", self.lubrication_factor_f0)?;
        non_negative("spin_friction_coefficient", self.spin_friction_coefficient)?;
        if let Some(t) = self.reference_temperature_c {
            in_range("reference_temperature_c", t, -60.0, 200.0)?;
        }
        // Bounds: up to 10 kW at one bearing (far above any bearing loss:
        // seed A's highest is ~1 kW); conductance scale 0.01..100 (two
        // decades either way of the bare natural-convection cylinder).
        in_range("extra_heat_w", self.extra_heat_w, 0.0, 1e4)?;
        // A volume fraction: 0 (dry air) .. 1 (flooded cavity).
        in_range("churning_oil_fraction", self.churning_oil_fraction, 0.0, 1.0)?;
        if let Some(s) = &self.oil_supply {
            s.validate()?;
        }
        self.skf.validate()?;
        positive("housing_conductance_scale", self.housing_conductance_scale)?;
        in_range("housing_conductance_scale", self.housing_conductance_scale, 0.01, 100.0)?;
        positive("tolerance_k", self.tolerance_k)?;
        positive("tolerance_m", self.tolerance_m)?;
        if self.max_iterations == 0 {
            return Err(Error::config("max_iterations", 0, "must be at least 1"));
        }
        Ok(())
    }
}

/// Mounting of the seed A bearing matching its network: housing of the
/// network's material and diameter, shaft and housing lengths of the
/// network, both rings on tight fits (A-35 assumes both), free (plane
/// stress) growth, shaft growth loading the bearing (`axial_sign = +1`).
pub fn seed_a_mounting(params: &SeedAParams) -> Mounting {
    Mounting {
        housing: params.housing.clone(),
        housing_outer_diameter_m: params.housing_diameter_m,
        shaft_length_m: params.shaft_length_m,
        housing_length_m: params.housing_length_m,
        inner_fit: RingFit::Tight,
        outer_fit: RingFit::Tight,
        plane_strain: false,
        axial_sign: 1.0,
    }
}

/// Heat of one operating point, by mechanism.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HeatReport {
    /// Palmgren load moment M1, or the SKF rolling moment M_rr [N m].
    pub load_moment_n_m: f64,
    /// Palmgren viscous moment Mv, or the SKF sliding moment M_sl [N m].
    pub viscous_moment_n_m: f64,
    /// SKF seal moment (0 with Palmgren) [N m].
    pub seal_moment_n_m: f64,
    /// Load friction heat omega M1 (SKF: omega M_rr) \[W\].
    pub load_w: f64,
    /// Viscous friction heat omega Mv (SKF: omega M_sl) \[W\].
    pub viscous_w: f64,
    /// Seal friction heat omega M_seal \[W\].
    pub seal_w: f64,
    /// The SKF reduction factors and sliding coefficient (SKF model only).
    pub skf: Option<SkfMoments>,
    /// Oil temperature used in Mv and in the oil density \[C\]: the ball node
    /// with `temperature_dependent_viscosity` on, else the oil-air supply.
    pub oil_temperature_c: f64,
    /// Kinematic viscosity of the lubricant at `oil_temperature_c` used in Mv \[cSt\].
    pub viscosity_cst: f64,
    /// Extra heat of [`CoupledOptions::extra_heat_w`] \[W\].
    pub extra_w: f64,
    /// Ball drag ("churning") heat at [`CoupledOptions::churning_oil_fraction`] \[W\].
    pub churning_w: f64,
    /// Cage speed used by the drag heat: the mean orbit speed of the balls
    /// of the solved state [rad/s].
    pub cage_speed_rad_s: f64,
    /// Oil density at the oil temperature [kg/m^3].
    pub oil_density_kg_m3: f64,
    /// All mechanisms (rolling = load + viscous + extra + churning, inner
    /// and outer spin) \[W\].
    pub heat: BearingHeat,
    /// Burton-Staph split \[W\].
    pub split: HeatSplit,
    /// Heat split into rolling, sliding, spin, drag, churning, seal and
    /// extra; sums to `heat.total_w()` \[W\].
    pub breakdown: HeatBreakdown,
    /// Cavity oil volume fraction X of the drag [-].
    pub cavity_oil_fraction: f64,
}

pub use super::row_heat::{cage_speed_rad_s, mean_inner_contact_angle_rad, spin_contacts};

/// The friction settings of `options` (heat model, f0, mu_s, X, SKF).
pub fn friction_settings(options: &CoupledOptions) -> FrictionSettings {
    FrictionSettings {
        heat_model: options.heat_model,
        lubrication: options.lubrication,
        lubrication_factor_f0: options.lubrication_factor_f0,
        spin_friction_coefficient: options.spin_friction_coefficient,
        load_friction_scale: 1.0,
        oil_volume_fraction: options.churning_oil_fraction,
        skf: options.skf,
        oil_supply: options.oil_supply,
    }
}

/// Heat of a solved bearing (A-20..A-23, A-27, or the SKF-style model,
/// docs/concepts/physics.md §9) with oil at `oil_c`.
#[allow(clippy::too_many_arguments)]
pub fn operating_heat(
    bearing: &Bearing,
    state: &BearingState,
    axial_n: f64,
    radial_n: f64,
    lubricant: &Lubricant,
    oil_c: f64,
    options: &CoupledOptions,
) -> Result<HeatReport> {
    let omega = rpm_to_rad_s(state.speed_rpm);
    let oil = OilState::at(lubricant, oil_c)?;
    let settings = friction_settings(options);
    let f = row_friction_heat(
        bearing,
        state,
        axial_n,
        radial_n,
        &oil,
        lubricant,
        &settings,
        options.solve.effects,
    )?;
    let mut heat = f.heat;
    // The extra heat is split like rolling friction heat; the ball
    // drag heat is already in the rolling part.
    heat.rolling_w += options.extra_heat_w;
    Ok(HeatReport {
        load_moment_n_m: f.load_moment_n_m,
        viscous_moment_n_m: f.viscous_moment_n_m,
        seal_moment_n_m: f.seal_moment_n_m,
        load_w: omega * f.load_moment_n_m,
        viscous_w: omega * f.viscous_moment_n_m,
        seal_w: omega * f.seal_moment_n_m,
        skf: f.skf,
        extra_w: options.extra_heat_w,
        churning_w: f.drag_w,
        cage_speed_rad_s: cage_speed_rad_s(state),
        oil_density_kg_m3: oil.density_kg_m3,
        oil_temperature_c: oil.temperature_c,
        viscosity_cst: oil.viscosity_cst,
        heat,
        split: heat.split(),
        breakdown: HeatBreakdown {
            extra_w: options.extra_heat_w,
            ..f.breakdown
        },
        cavity_oil_fraction: f.cavity_oil_fraction,
    })
}

/// Result of the coupled fixed point.
#[derive(Debug, Clone, PartialEq)]
pub struct ThermalState {
    /// Shaft speed of the operating point \[rpm\].
    pub speed_rpm: f64,
    /// Node names of the network, in node order (boundaries included).
    pub node_names: Vec<String>,
    /// Steady node temperatures, one per entry of `node_names` \[C\].
    pub temperatures_c: Vec<f64>,
    /// Heat flowing out through each boundary node \[W\].
    pub boundary_flows_w: Vec<(String, f64)>,
    /// Heat by mechanism at the converged state (the last iteration's heat).
    pub heat: HeatReport,
    /// Component rises over the reference temperature \[K\].
    pub rises: ComponentRises,
    /// Thermal displacements of every part (switched effects give zero).
    pub offsets: ThermalOffsets,
    /// What the bearing solver received (A-38, ball growth projected).
    pub raceway_offsets: RacewayOffsets,
    /// The bearing at the converged temperatures.
    pub bearing: BearingState,
    /// Fixed-point iterations used.
    pub iterations: usize,
    /// Last largest node temperature change \[K\].
    pub residual_k: f64,
    /// Last change of the raceway offsets \[m\].
    pub offset_change_m: f64,
}

impl ThermalState {
    /// Temperature of a named node \[C\].
    pub fn temperature_c(&self, node: &str) -> Result<f64> {
        self.node_names
            .iter()
            .position(|n| n == node)
            .map(|i| self.temperatures_c[i])
            .ok_or_else(|| {
                Error::config(
                    "node",
                    node,
                    format!("no such node; known: {}", self.node_names.join(", ")),
                )
            })
    }
}

/// One bearing in the seed A network, ready to solve many operating points.
#[derive(Debug, Clone)]
pub struct CoupledBearing {
    model: BearingModel,
    network: BearingNetwork,
    mounting: Mounting,
    params: SeedAParams,
    options: CoupledOptions,
}

/// Data of one iteration used by the runaway rule.
#[derive(Debug, Clone, Copy)]
struct Trend {
    heat_w: f64,
    hottest_c: f64,
    max_load_n: f64,
    change_k: f64,
}

impl Trend {
    fn all_grow(&self, prev: &Trend) -> bool {
        self.heat_w > prev.heat_w
            && self.hottest_c > prev.hottest_c
            && self.max_load_n > prev.max_load_n
            && self.change_k >= prev.change_k
    }
}

impl CoupledBearing {
    /// Build the model, the seed A network and the mounting.
    pub fn new(bearing: &Bearing, params: SeedAParams, mounting: Mounting, options: CoupledOptions) -> Result<Self> {
        options.validate()?;
        mounting.validate(bearing)?;
        params.lubricant.check_temperature(params.oil_air_temperature_c)?;
        // The housing link's conductance is linear in C (h = C dT^0.25), so
        // scaling C scales the link exactly.
        let scaled = SeedAParams {
            natural_coefficient_w_m2_k125: params.natural_coefficient_w_m2_k125 * options.housing_conductance_scale,
            ..params.clone()
        };
        let network = seed_a_network(bearing, &scaled)?;
        Ok(CoupledBearing {
            model: BearingModel::new(bearing)?,
            network,
            mounting,
            params,
            options,
        })
    }

    /// Seed A defaults ([`SeedAParams::for_bearing`], [`seed_a_mounting`]).
    pub fn seed_a(bearing: &Bearing, options: CoupledOptions) -> Result<Self> {
        let params = SeedAParams::for_bearing(bearing);
        let mounting = seed_a_mounting(&params);
        Self::new(bearing, params, mounting, options)
    }

    /// The bearing model (geometry, Hertz constants) solved at each iteration.
    pub fn model(&self) -> &BearingModel {
        &self.model
    }
    /// The coupled options this bearing was built with.
    pub fn options(&self) -> &CoupledOptions {
        &self.options
    }
    /// The seed A network parameters as given (before
    /// [`CoupledOptions::housing_conductance_scale`] is applied).
    pub fn params(&self) -> &SeedAParams {
        &self.params
    }

    fn reference_c(&self) -> f64 {
        self.options
            .reference_temperature_c
            .unwrap_or(self.params.ambient_temperature_c)
    }

    /// Component rises from node temperatures.
    pub fn rises(&self, t: &[f64]) -> ComponentRises {
        let n = &self.network;
        let r = self.reference_c();
        ComponentRises {
            shaft_k: t[n.shaft] - r,
            inner_ring_k: 0.5 * (t[n.inner] + t[n.inner_contact]) - r,
            balls_k: t[n.balls] - r,
            outer_ring_k: 0.5 * (t[n.outer] + t[n.outer_contact]) - r,
            housing_k: t[n.housing] - r,
        }
    }

    /// Raceway offsets for the solver (module docs, step 2).
    pub fn raceway_offsets(&self, u: &ThermalOffsets) -> RacewayOffsets {
        let a0 = self.model.bearing().geometry.free_contact_angle_rad;
        RacewayOffsets {
            axial_m: u.axial_with_gap_m(a0),
            radial_m: u.radial_with_gap_m(a0),
        }
    }

    fn check_bound(&self, t: &[f64], speed_rpm: f64) -> Result<()> {
        let lub = &self.params.lubricant;
        for (i, node) in self.network.network.nodes().iter().enumerate() {
            if t[i].is_nan() || t[i] > lub.max_temperature_c {
                return Err(Error::ThermalRunaway(format!(
                    "at {speed_rpm} rpm node {} reached {:.1} C, above the highest temperature of lubricant '{}' ({} C); \
                     lower the speed or the load, or use a lubricant rated hotter",
                    node.name, t[i], lub.name, lub.max_temperature_c
                )));
            }
        }
        Ok(())
    }

    /// Heat of the bearing at one operating point with the oil held at
    /// `oil_c` (its viscosity and density taken there) and no thermal
    /// deformation: the friction model of [`operating_heat`] on the
    /// isothermal bearing state, without the thermal network. For conditions
    /// that fix the bearing temperature, such as the ISO 15312 reference
    /// conditions (docs/concepts/physics.md §9, "Reference speed").
    pub fn isothermal_heat(
        &self,
        speed_rpm: f64,
        axial_n: f64,
        radial_n: f64,
        oil_c: f64,
    ) -> Result<(BearingState, HeatReport)> {
        positive("speed_rpm", speed_rpm)?;
        finite("axial_n", axial_n)?;
        finite("radial_n", radial_n)?;
        self.params.lubricant.check_temperature(oil_c)?;
        let load = [radial_n, 0.0, axial_n, 0.0, 0.0];
        let mut opts = self.options.solve;
        opts.offsets = RacewayOffsets::default();
        let start = static_start_q(&self.model, &load, &opts)?;
        let state = self
            .model
            .solve_from(&load, speed_rpm, &opts, start, &mut WarmStart::new())?;
        let bearing = self.model.bearing();
        let heat = operating_heat(
            bearing,
            &state,
            axial_n,
            radial_n,
            &self.params.lubricant,
            oil_c,
            &self.options,
        )?;
        Ok((state, heat))
    }

    /// The coupled steady state at `speed_rpm` under an axial and a radial
    /// load (N; the applied load of the bearing, preload included).
    pub fn solve(&self, speed_rpm: f64, axial_n: f64, radial_n: f64) -> Result<ThermalState> {
        positive("speed_rpm", speed_rpm)?;
        let load = [radial_n, 0.0, axial_n, 0.0, 0.0];
        let effects: EffectSet = self.options.solve.effects;
        let mut opts = self.options.solve;
        opts.offsets = RacewayOffsets::default();
        let start = static_start_q(&self.model, &load, &opts)?;
        let bearing = self.model.bearing();
        let lub = &self.params.lubricant;
        let omega = rpm_to_rad_s(speed_rpm);
        let mut solver = SteadySolver::new(self.network.network.clone());
        let oil_node = self.network.balls;
        let mut t = self.network.network.initial_temperatures(self.reference_c());
        let mut lambda: f64 = 1.0;
        let mut prev: Option<Trend> = None;
        let mut streak = 0;
        let mut last_off = RacewayOffsets::default();
        let mut last_state: Option<BearingState> = None;
        let mut warm = WarmStart::new();
        let mut history: Option<(Vec<f64>, Vec<f64>)> = None;
        let (mut change_k, mut change_m) = (f64::INFINITY, f64::INFINITY);
        for it in 1..=self.options.max_iterations {
            self.check_bound(&t, speed_rpm)?;
            let rises = self.rises(&t);
            let u = thermal_offsets(bearing, &self.mounting, &rises, effects)?;
            let off = self.raceway_offsets(&u);
            // Same offsets as the last solve (always so with every expansion
            // switched off): the bearing state is unchanged. Otherwise warm
            // start from the last solution (the offsets move by microns).
            let state = match &last_state {
                Some(s) if it > 1 && off == last_off => s.clone(),
                _ => {
                    opts.offsets = off;
                    let q0 = last_state.as_ref().map_or(start, |s| s.displacement);
                    match self.model.solve_from(&load, speed_rpm, &opts, q0, &mut warm) {
                        Ok(s) => s,
                        // A warm start can fail where balls lose contact:
                        // retry from the static start.
                        Err(_) if last_state.is_some() => {
                            warm = WarmStart::new();
                            self.model.solve_from(&load, speed_rpm, &opts, start, &mut warm)?
                        }
                        Err(e) => return Err(e),
                    }
                }
            };
            let oil_c = oil_temperature_c(effects, self.params.oil_air_temperature_c, Some(t[oil_node]));
            let heat = operating_heat(bearing, &state, axial_n, radial_n, lub, oil_c, &self.options)?;
            let g = solver
                .solve(&self.network.sources_w(&heat.split), omega)?
                .temperatures_c;
            change_k = g.iter().zip(&t).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max);
            change_m = if it == 1 {
                f64::INFINITY
            } else {
                (off.radial_m - last_off.radial_m)
                    .abs()
                    .max((off.axial_m - last_off.axial_m).abs())
            };
            last_off = off;
            if change_k <= self.options.tolerance_k && change_m <= self.options.tolerance_m {
                self.check_bound(&g, speed_rpm)?;
                let flows = self.network.network.boundary_flows_w(&g, omega);
                return Ok(ThermalState {
                    speed_rpm,
                    node_names: self.network.network.names().iter().cloned().collect(),
                    temperatures_c: g,
                    boundary_flows_w: flows,
                    heat,
                    rises,
                    offsets: u,
                    raceway_offsets: off,
                    bearing: state,
                    iterations: it,
                    residual_k: change_k,
                    offset_change_m: change_m,
                });
            }
            let trend = Trend {
                heat_w: heat.heat.total_w(),
                hottest_c: g.iter().copied().fold(f64::NEG_INFINITY, f64::max),
                max_load_n: state.max_inner_load_n(),
                change_k,
            };
            if let Some(p) = prev {
                if trend.all_grow(&p) {
                    streak += 1;
                    if streak >= RUNAWAY_STREAK {
                        return Err(Error::ThermalRunaway(format!(
                            "at {speed_rpm} rpm heat ({:.1} W), the hottest node ({:.1} C) and the largest \
                             contact load ({:.0} N) grew together for {streak} fixed-point iterations \
                             without settling (last temperature change {:.3e} K)",
                            trend.heat_w, trend.hottest_c, trend.max_load_n, change_k
                        )));
                    }
                } else {
                    streak = 0;
                }
                if change_k > p.change_k {
                    lambda = (0.5 * lambda).max(1.0 / 64.0);
                }
            }
            prev = Some(trend);
            last_state = Some(state);
            let next = anderson_step(&t, &g, history.as_ref(), lambda);
            // Never let the extrapolation alone cross the lubricant bound.
            let next = if next.iter().any(|x| *x > lub.max_temperature_c) {
                g.clone()
            } else {
                next
            };
            // An iterate beyond the bound is not yet a runaway: the first
            // iterates run on the cold (thick) oil's viscous heat and can
            // overshoot a steady state far below the bound. Step towards it
            // only as far as the bound; a runaway is a bearing that, held at
            // the bound, still heats a node beyond it.
            let next = match toward_bound(&t, &next, lub.max_temperature_c) {
                Some(n) => n,
                None => {
                    let (i, hot) =
                        g.iter()
                            .copied()
                            .enumerate()
                            .fold((0, f64::NEG_INFINITY), |b, (i, x)| if x > b.1 { (i, x) } else { b });
                    return Err(Error::ThermalRunaway(format!(
                        "at {speed_rpm} rpm node {} reached {hot:.1} C, above the highest temperature of \
                         lubricant '{}' ({} C), from a state already at that limit; lower the speed or the \
                         load, or use a lubricant rated hotter",
                        self.network.network.nodes()[i].name,
                        lub.name,
                        lub.max_temperature_c
                    )));
                }
            };
            let f: Vec<f64> = g.iter().zip(&t).map(|(a, b)| a - b).collect();
            history = Some((t, f));
            t = next;
        }
        // Report the criterion that failed, each in its own measure.
        Err(if change_k > self.options.tolerance_k {
            Error::convergence(
                "coupled thermo-mechanical fixed point (largest node temperature change, K)",
                self.options.max_iterations,
                change_k,
                self.options.tolerance_k,
            )
        } else {
            Error::convergence(
                "coupled thermo-mechanical fixed point (raceway offset change, m)",
                self.options.max_iterations,
                change_m,
                self.options.tolerance_m,
            )
        })
    }
}

/// The point of the segment from `t` to `next` where it leaves the
/// temperatures at or below `bound` \[C\] (all of `next` when it stays
/// below); `None` when `t` already sits at the bound and `next` goes beyond
/// it (no step towards the bound is left).
pub fn toward_bound(t: &[f64], next: &[f64], bound: f64) -> Option<Vec<f64>> {
    let mut s: f64 = 1.0;
    for (a, b) in t.iter().zip(next) {
        if *b > bound {
            s = s.min(((bound - a) / (b - a)).max(0.0));
        }
    }
    if s <= 1e-12 {
        return None;
    }
    Some(
        t.iter()
            .zip(next)
            .map(|(a, b)| (a + s * (b - a)).min(bound.max(*a)))
            .collect(),
    )
}

/// One Anderson(1) mixing step (Walker & Ni, SIAM J. Numer. Anal. 49 (2011),
/// m = 1): with f = G(x) - x and the previous pair (x', f'),
/// `x+ = x + beta f - theta ((x - x') + beta (f - f'))`,
/// `theta = f.(f - f') / |f - f'|^2`; a plain damped step `x + beta f`
/// without history or when f = f'.
pub fn anderson_step(x: &[f64], g: &[f64], previous: Option<&(Vec<f64>, Vec<f64>)>, beta: f64) -> Vec<f64> {
    let f: Vec<f64> = g.iter().zip(x).map(|(a, b)| a - b).collect();
    let plain = || x.iter().zip(&f).map(|(xi, fi)| xi + beta * fi).collect();
    let Some((xp, fp)) = previous else {
        return plain();
    };
    let df: Vec<f64> = f.iter().zip(fp).map(|(a, b)| a - b).collect();
    let dd: f64 = df.iter().map(|d| d * d).sum();
    if !(dd > 0.0 && dd.is_finite()) {
        return plain();
    }
    let theta = f.iter().zip(&df).map(|(a, b)| a * b).sum::<f64>() / dd;
    (0..x.len())
        .map(|i| x[i] + beta * f[i] - theta * ((x[i] - xp[i]) + beta * df[i]))
        .collect()
}

/// Which stiffness a curve shows (seed A Fig. 11's three cases).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StiffnessMode {
    /// Zero-speed (static) stiffness at every speed.
    Constant,
    /// Quasi-static stiffness, isothermal.
    Speed,
    /// Quasi-static stiffness at the coupled thermal steady state.
    Thermal,
}

impl StiffnessMode {
    /// The mode named "constant", "speed" or "thermal" (exact, lower case).
    pub fn from_name(name: &str) -> Result<Self> {
        match name {
            "constant" => Ok(StiffnessMode::Constant),
            "speed" => Ok(StiffnessMode::Speed),
            "thermal" => Ok(StiffnessMode::Thermal),
            other => Err(Error::config(
                "mode",
                other,
                "must be \"constant\", \"speed\" or \"thermal\"",
            )),
        }
    }
}

/// Bearing states against speed for one mode, in parallel (each speed
/// solved independently from the static start: bit-identical for any
/// thread count). Thermal mode also returns the thermal states. Fails with
/// the error of the lowest-index failing speed.
pub fn stiffness_curve_mode(
    coupled: &CoupledBearing,
    speeds_rpm: &[f64],
    axial_n: f64,
    radial_n: f64,
    mode: StiffnessMode,
) -> Result<Vec<(BearingState, Option<ThermalState>)>> {
    let load = [radial_n, 0.0, axial_n, 0.0, 0.0];
    let opts = SolveOptions {
        offsets: RacewayOffsets::default(),
        ..coupled.options.solve
    };
    let m = &coupled.model;
    let points: Vec<Result<(BearingState, Option<ThermalState>)>> = match mode {
        StiffnessMode::Constant => {
            let s = m.solve_static(&load, &opts)?;
            speeds_rpm.iter().map(|_| Ok((s.clone(), None))).collect()
        }
        StiffnessMode::Speed => {
            let start = static_start_q(m, &load, &opts)?;
            speeds_rpm
                .par_iter()
                .map(|&n| Ok((m.solve_from(&load, n, &opts, start, &mut WarmStart::new())?, None)))
                .collect()
        }
        StiffnessMode::Thermal => speeds_rpm
            .par_iter()
            .map(|&n| {
                let s = coupled.solve(n, axial_n, radial_n)?;
                Ok((s.bearing.clone(), Some(s)))
            })
            .collect(),
    };
    points.into_iter().collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::effects::Effect;
    use crate::thermal::heat::bearing_heat;

    /// Seed A: 300 N preload + 2380.9 N axial, 1189.9 N radial (100 N m).
    const FA: f64 = 2680.9;
    const FR: f64 = 1189.9;

    fn seed_a(effects: EffectSet) -> CoupledBearing {
        let b = Bearing::preset("6208").unwrap();
        let mut o = CoupledOptions::default();
        o.solve.effects = effects;
        CoupledBearing::seed_a(&b, o).unwrap()
    }

    fn thermal_off() -> EffectSet {
        let mut e = EffectSet::all();
        for x in [
            Effect::ThermalExpansionShaft,
            Effect::ThermalExpansionInnerRing,
            Effect::ThermalExpansionOuterRing,
            Effect::ThermalExpansionBalls,
            Effect::ThermalExpansionHousing,
        ] {
            e = e.without(x);
        }
        e
    }

    #[test]
    fn zero_heat_limit_equals_isothermal_model() {
        let c = seed_a(thermal_off());
        let s = c.solve(10_000.0, FA, FR).unwrap();
        let iso = c
            .model()
            .solve(&[FR, 0.0, FA, 0.0, 0.0], 10_000.0, &c.options().solve)
            .unwrap();
        assert_eq!(s.bearing.displacement, iso.displacement);
        assert_eq!(s.bearing.stiffness_matrix, iso.stiffness_matrix);
        assert_eq!(s.raceway_offsets, RacewayOffsets::default());
        assert!(s.heat.heat.total_w() > 0.0);
    }

    #[test]
    fn isothermal_heat_is_the_friction_model_at_the_given_oil_temperature() {
        // Palmgren viscous moment by hand: 1e-7 f0 (nu n)^(2/3) dm^3
        // [N mm, dm in mm] with nu of the lubricant at the given temperature.
        let c = seed_a(EffectSet::all());
        let (state, h) = c.isothermal_heat(8_000.0, FA, FR, 70.0).unwrap();
        let lub = &c.params().lubricant;
        let nu = lub.kinematic_viscosity_cst(70.0).unwrap();
        assert_eq!(h.viscosity_cst, nu);
        let dm_mm = c.model().bearing().geometry.pitch_diameter_m * 1e3;
        let f0 = c.options().lubrication_factor_f0;
        let mv = 1e-7 * f0 * (nu * 8_000.0).powf(2.0 / 3.0) * dm_mm.powi(3) * 1e-3;
        assert!((h.viscous_moment_n_m - mv).abs() <= 1e-12 * mv.max(1.0));
        // the isothermal bearing state is the model's own solve
        let iso = c
            .model()
            .solve(&[FR, 0.0, FA, 0.0, 0.0], 8_000.0, &c.options().solve)
            .unwrap();
        for k in 0..5 {
            assert!((state.displacement[k] - iso.displacement[k]).abs() <= 1e-12);
        }
        // a hotter oil is thinner: less viscous loss, same load moment
        let (_, hot) = c.isothermal_heat(8_000.0, FA, FR, 100.0).unwrap();
        assert!(hot.viscous_moment_n_m < h.viscous_moment_n_m);
        assert_eq!(hot.load_moment_n_m, h.load_moment_n_m);
        // and equals the coupled solve's heat when that solve holds the oil
        // at the oil-air temperature (no temperature-dependent viscosity,
        // no expansion)
        let e = thermal_off().without(Effect::TemperatureDependentViscosity);
        let cold = seed_a(e);
        let s = cold.solve(8_000.0, FA, FR).unwrap();
        let (_, same) = cold
            .isothermal_heat(8_000.0, FA, FR, cold.params().oil_air_temperature_c)
            .unwrap();
        assert!((same.heat.total_w() - s.heat.heat.total_w()).abs() <= 1e-9 * s.heat.heat.total_w());
        assert!(c.isothermal_heat(8_000.0, FA, FR, f64::NAN).is_err());
        assert!(c.isothermal_heat(-1.0, FA, FR, 70.0).is_err());
    }

    #[test]
    fn heat_balance_at_convergence() {
        let c = seed_a(EffectSet::all());
        let s = c.solve(12_000.0, FA, FR).unwrap();
        let out: f64 = s.boundary_flows_w.iter().map(|(_, q)| q).sum();
        let h = s.heat.heat.total_w();
        assert!((out - h).abs() < 1e-6 * h, "{out} vs {h}");
        let sp = s.heat.split;
        assert!((sp.inner_ring_w + sp.balls_w + sp.outer_ring_w - h).abs() < 1e-9 * h);
        assert!(s.residual_k <= 1e-6 && s.iterations < 12, "{}", s.iterations);
        // Heat makes every free node hotter than both boundaries.
        for n in ["Ts", "Ti", "Tb", "To", "Th"] {
            assert!(s.temperature_c(n).unwrap() > 26.0, "{n}");
        }
    }

    #[test]
    fn anderson_step_solves_a_linear_map_exactly() {
        // G(x) = a x + b: after one plain step, the Anderson(1) (secant) step
        // lands on the fixed point x* = b / (1 - a).
        let (a, b) = (0.4, 3.0);
        let x0 = [0.0];
        let g0 = [a * x0[0] + b];
        let x1 = anderson_step(&x0, &g0, None, 1.0);
        let f0 = vec![g0[0] - x0[0]];
        let g1 = [a * x1[0] + b];
        let x2 = anderson_step(&x1, &g1, Some(&(x0.to_vec(), f0)), 1.0);
        assert!((x2[0] - b / (1.0 - a)).abs() < 1e-12, "{x2:?}");
    }

    #[test]
    fn runaway_rule_separates_warm_up_from_divergence() {
        // A normal warm-up from the cold start: heat, temperatures and loads
        // rise but each change is smaller than the last (contraction 0.3).
        // A runaway: the same growth with changes that do not shrink.
        let seq = |ratio: f64| -> Vec<Trend> {
            let mut out = Vec::new();
            let (mut t, mut d) = (40.0, 10.0);
            for _ in 0..6 {
                out.push(Trend {
                    heat_w: 100.0 + t,
                    hottest_c: t,
                    max_load_n: 2000.0 + t,
                    change_k: d,
                });
                t += d;
                d *= ratio;
            }
            out
        };
        let grows = |v: &[Trend]| v.windows(2).filter(|w| w[1].all_grow(&w[0])).count();
        assert_eq!(grows(&seq(0.3)), 0);
        assert!(grows(&seq(1.2)) >= RUNAWAY_STREAK);
    }

    #[test]
    fn heat_rises_with_speed_and_preload() {
        // Seed A Fig. 6: heat rises with speed and with axial preload.
        let c = seed_a(EffectSet::all());
        let h = |n: f64, fa: f64| c.solve(n, fa, 0.0).unwrap().heat.heat.total_w();
        assert!(h(12_000.0, 300.0) > h(6_000.0, 300.0));
        assert!(h(10_000.0, 600.0) > h(10_000.0, 300.0));
    }

    #[test]
    fn temperatures_rise_with_speed_and_axial_load() {
        let c = seed_a(EffectSet::all());
        let tb = |n: f64, fa: f64, fr: f64| c.solve(n, fa, fr).unwrap().temperature_c("Tb").unwrap();
        assert!(tb(14_000.0, 300.0, 0.0) > tb(8_000.0, 300.0, 0.0));
        assert!(tb(6_500.0, FA, FR) > tb(6_500.0, 300.0, FR));
    }

    #[test]
    fn hot_bearing_beyond_lubricant_limit_is_a_runaway() {
        let b = Bearing::preset("6208").unwrap();
        let mut p = SeedAParams::for_bearing(&b);
        p.lubricant.max_temperature_c = 30.0;
        let m = seed_a_mounting(&p);
        let c = CoupledBearing::new(&b, p, m, CoupledOptions::default()).unwrap();
        match c.solve(15_000.0, FA, FR) {
            Err(Error::ThermalRunaway(msg)) => assert!(msg.contains("lubricant") && msg.contains("node"), "{msg}"),
            other => panic!("expected a runaway, got {other:?}"),
        }
    }

    #[test]
    fn step_towards_the_lubricant_bound_stops_on_it() {
        // Linear path from t to next: node 1 crosses 200 C at a quarter.
        let t = [50.0, 180.0];
        let next = [90.0, 260.0];
        let s = toward_bound(&t, &next, 200.0).unwrap();
        assert!((s[0] - 60.0).abs() < 1e-12 && (s[1] - 200.0).abs() < 1e-12);
        // Below the bound the step is untouched; at the bound none is left.
        assert_eq!(toward_bound(&t, &[60.0, 190.0], 200.0).unwrap(), vec![60.0, 190.0]);
        assert!(toward_bound(&[50.0, 200.0], &next, 200.0).is_none());
    }

    #[test]
    fn iteration_cap_reports_convergence_error() {
        let b = Bearing::preset("6208").unwrap();
        let o = CoupledOptions {
            max_iterations: 2,
            ..CoupledOptions::default()
        };
        let c = CoupledBearing::seed_a(&b, o).unwrap();
        assert!(matches!(c.solve(12_000.0, FA, FR), Err(Error::Convergence { .. })));
    }

    #[test]
    fn spin_friction_switch_adds_spin_heat_only() {
        let on = seed_a(EffectSet::all()).solve(12_000.0, FA, FR).unwrap();
        let off = seed_a(EffectSet::all().without(Effect::SpinFriction))
            .solve(12_000.0, FA, FR)
            .unwrap();
        assert_eq!(off.heat.heat.inner_spin_w + off.heat.heat.outer_spin_w, 0.0);
        assert!(on.heat.heat.inner_spin_w > 0.0);
        assert!(on.heat.heat.total_w() > off.heat.heat.total_w());
    }

    #[test]
    fn thermal_curve_is_thread_count_independent_and_speed_mode_matches_without_expansion() {
        let c = seed_a(thermal_off());
        let speeds = [7_000.0, 11_000.0, 15_000.0];
        let th = stiffness_curve_mode(&c, &speeds, FA, FR, StiffnessMode::Thermal).unwrap();
        let sp = stiffness_curve_mode(&c, &speeds, FA, FR, StiffnessMode::Speed).unwrap();
        for (a, b) in th.iter().zip(&sp) {
            assert_eq!(a.0.stiffness_matrix, b.0.stiffness_matrix);
        }
        let c = seed_a(EffectSet::all());
        let one = rayon::ThreadPoolBuilder::new().num_threads(1).build().unwrap();
        let a = one.install(|| stiffness_curve_mode(&c, &speeds, FA, FR, StiffnessMode::Thermal).unwrap());
        let b = stiffness_curve_mode(&c, &speeds, FA, FR, StiffnessMode::Thermal).unwrap();
        for (x, y) in a.iter().zip(&b) {
            assert_eq!(x.0.stiffness_matrix, y.0.stiffness_matrix);
        }
        assert!(StiffnessMode::from_name("hot").is_err());
    }

    #[test]
    fn extra_heat_is_split_like_rolling_heat_and_leaves_through_the_boundaries() {
        let base = seed_a(EffectSet::all()).solve(10_000.0, FA, FR).unwrap();
        let b = Bearing::preset("6208").unwrap();
        let e = 40.0;
        let o = CoupledOptions {
            extra_heat_w: e,
            ..CoupledOptions::default()
        };
        let s = CoupledBearing::seed_a(&b, o).unwrap().solve(10_000.0, FA, FR).unwrap();
        assert_eq!(s.heat.extra_w, e);
        // Heat balance with the extra source (A-23 + E).
        let h = s.heat.heat.total_w();
        let out: f64 = s.boundary_flows_w.iter().map(|(_, q)| q).sum();
        assert!((out - h).abs() < 1e-6 * h, "{out} vs {h}");
        // Burton-Staph: friction split + E/4, E/2, E/4.
        let own = bearing_heat(
            rpm_to_rad_s(10_000.0),
            s.heat.load_moment_n_m,
            s.heat.viscous_moment_n_m,
            0.06,
            &[],
            &[],
        )
        .unwrap();
        let spin = BearingHeat {
            rolling_w: 0.0,
            ..s.heat.heat
        };
        let fr = BearingHeat {
            rolling_w: own.rolling_w,
            ..spin
        }
        .split();
        assert!((s.heat.split.inner_ring_w - fr.inner_ring_w - 0.25 * e).abs() < 1e-9 * h);
        assert!((s.heat.split.balls_w - fr.balls_w - 0.5 * e).abs() < 1e-9 * h);
        assert!((s.heat.split.outer_ring_w - fr.outer_ring_w - 0.25 * e).abs() < 1e-9 * h);
        // More heat, hotter bearing.
        for n in ["Ti", "Tb", "To", "Th"] {
            assert!(s.temperature_c(n).unwrap() > base.temperature_c(n).unwrap(), "{n}");
        }
    }

    #[test]
    fn housing_conductance_scale_scales_the_natural_convection_link() {
        let b = Bearing::preset("6208").unwrap();
        let p = SeedAParams::for_bearing(&b);
        let solve = |k: f64| {
            let o = CoupledOptions {
                housing_conductance_scale: k,
                ..CoupledOptions::default()
            };
            CoupledBearing::seed_a(&b, o).unwrap().solve(10_000.0, FA, FR).unwrap()
        };
        let (one, two) = (solve(1.0), solve(2.0));
        // Flow to ambient = k C A (Th - Ta)^1.25 (natural convection over the
        // housing cylinder and both end faces, module docs of presets).
        let od = b.geometry.outer_diameter_m;
        let dh = p.housing_diameter_m;
        let area = std::f64::consts::PI * (dh * p.housing_length_m + 0.5 * (dh * dh - od * od));
        for (k, s) in [(1.0, &one), (2.0, &two)] {
            let dt = s.temperature_c("Th").unwrap() - p.ambient_temperature_c;
            let q = s.boundary_flows_w.iter().find(|(n, _)| n == "Ta").unwrap().1;
            let expect = k * p.natural_coefficient_w_m2_k125 * area * dt.powf(1.25);
            assert!((q - expect).abs() < 1e-6 * expect, "k {k}: {q} vs {expect}");
        }
        // A better-cooled housing runs cooler.
        assert!(two.temperature_c("Th").unwrap() < one.temperature_c("Th").unwrap());
        // Default options are the unscaled model, bit for bit.
        let d = seed_a(EffectSet::all()).solve(10_000.0, FA, FR).unwrap();
        assert_eq!(d.temperatures_c, one.temperatures_c);
    }

    #[test]
    fn new_calibration_inputs_are_validated() {
        let b = Bearing::preset("6208").unwrap();
        for (o, field) in [
            (
                CoupledOptions {
                    extra_heat_w: -1.0,
                    ..CoupledOptions::default()
                },
                "extra_heat_w",
            ),
            (
                CoupledOptions {
                    extra_heat_w: f64::NAN,
                    ..CoupledOptions::default()
                },
                "extra_heat_w",
            ),
            (
                CoupledOptions {
                    churning_oil_fraction: -0.01,
                    ..CoupledOptions::default()
                },
                "churning_oil_fraction",
            ),
            (
                CoupledOptions {
                    churning_oil_fraction: 1.5,
                    ..CoupledOptions::default()
                },
                "churning_oil_fraction",
            ),
            (
                CoupledOptions {
                    churning_oil_fraction: f64::NAN,
                    ..CoupledOptions::default()
                },
                "churning_oil_fraction",
            ),
            (
                CoupledOptions {
                    housing_conductance_scale: 0.0,
                    ..CoupledOptions::default()
                },
                "housing_conductance_scale",
            ),
            (
                CoupledOptions {
                    housing_conductance_scale: 1e3,
                    ..CoupledOptions::default()
                },
                "housing_conductance_scale",
            ),
        ] {
            match CoupledBearing::seed_a(&b, o) {
                Err(Error::Config { field: f, .. }) => assert_eq!(f, field),
                other => panic!("{field}: expected a config error, got {other:?}"),
            }
        }
    }

    fn with_churning(x: f64) -> CoupledBearing {
        let b = Bearing::preset("6208").unwrap();
        let o = CoupledOptions {
            churning_oil_fraction: x,
            ..CoupledOptions::default()
        };
        CoupledBearing::seed_a(&b, o).unwrap()
    }

    /// Ball drag closed form, written out independently of
    /// `ball_drag_power_w`: Z (pi/64) C_D X rho D^2 dm^3 omega_c^3 with the
    /// lubricant's density law rho15 (1 - beta (T - 15)).
    fn drag_by_hand(c: &CoupledBearing, s: &ThermalState, x: f64) -> f64 {
        let g = &c.model().bearing().geometry;
        let lub = &c.params().lubricant;
        let rho = lub.density_15c_kg_m3 * (1.0 - lub.density_expansion_per_k * (s.heat.oil_temperature_c - 15.0));
        let wc = s.bearing.balls.iter().map(|b| b.orbit_speed_rad_s).sum::<f64>() / s.bearing.balls.len() as f64;
        g.ball_count as f64
            * std::f64::consts::PI
            * 0.47
            * x
            * rho
            * g.ball_diameter_m.powi(2)
            * g.pitch_diameter_m.powi(3)
            * wc.powi(3)
            / 64.0
    }

    #[test]
    fn churning_heat_is_ball_drag_at_the_solved_cage_speed_and_leaves_through_the_boundaries() {
        let x = 0.05;
        let base = seed_a(EffectSet::all()).solve(12_000.0, FA, FR).unwrap();
        let c = with_churning(x);
        let s = c.solve(12_000.0, FA, FR).unwrap();
        assert_eq!(base.heat.churning_w, 0.0);
        let p = drag_by_hand(&c, &s, x);
        assert!(
            p > 1.0 && (s.heat.churning_w - p).abs() < 1e-9 * p,
            "{} vs {p}",
            s.heat.churning_w
        );
        // Total heat at the converged state = the baseline mechanisms at
        // that state + the drag power (A-23 + P), and it all leaves
        // through the boundaries.
        let own = s.heat.load_w + s.heat.viscous_w + s.heat.heat.inner_spin_w + s.heat.heat.outer_spin_w;
        let h = s.heat.heat.total_w();
        assert!((h - own - p).abs() < 1e-9 * h, "{h} vs {own} + {p}");
        let out: f64 = s.boundary_flows_w.iter().map(|(_, q)| q).sum();
        assert!((out - h).abs() < 1e-6 * h, "{out} vs {h}");
        // Split like rolling heat: P/4, P/2, P/4 on top of the friction split.
        let fr = BearingHeat {
            rolling_w: s.heat.load_w + s.heat.viscous_w,
            ..s.heat.heat
        }
        .split();
        assert!((s.heat.split.inner_ring_w - fr.inner_ring_w - 0.25 * p).abs() < 1e-9 * h);
        assert!((s.heat.split.balls_w - fr.balls_w - 0.5 * p).abs() < 1e-9 * h);
        assert!((s.heat.split.outer_ring_w - fr.outer_ring_w - 0.25 * p).abs() < 1e-9 * h);
        for n in ["Ti", "Tb", "To", "Th"] {
            assert!(s.temperature_c(n).unwrap() > base.temperature_c(n).unwrap(), "{n}");
        }
    }

    #[test]
    fn churning_grows_with_speed_faster_than_the_viscous_loss() {
        let x = 0.02;
        let c = with_churning(x);
        let (lo, hi) = (c.solve(7_000.0, FA, FR).unwrap(), c.solve(14_000.0, FA, FR).unwrap());
        // Exactly (omega_c ratio)^3 times the density ratio (drag law).
        let ratio = hi.heat.churning_w / lo.heat.churning_w;
        let kin = (hi.heat.cage_speed_rad_s / lo.heat.cage_speed_rad_s).powi(3) * hi.heat.oil_density_kg_m3
            / lo.heat.oil_density_kg_m3;
        assert!((ratio - kin).abs() < 1e-9 * kin, "{ratio} vs {kin}");
        // About 8 for twice the speed (cage speed ~ proportional to shaft
        // speed); Palmgren's omega Mv grows at most like 2^(5/3) = 3.17
        // (less as the oil warms and thins).
        let viscous = hi.heat.viscous_w / lo.heat.viscous_w;
        assert!(
            ratio > 7.0 && viscous < 2f64.powf(5.0 / 3.0) && ratio > 2.0 * viscous,
            "{ratio} {viscous}"
        );
        let share = |s: &ThermalState| s.heat.churning_w / s.heat.heat.total_w();
        assert!(share(&hi) > share(&lo));
    }
}
