//! The coupled spindle: bearing heat -> thermal network -> thermal offsets
//! and axial growth -> preload -> bearings, to a fixed point (steady) or in
//! time (transient, quasi-steady mechanics).
//!
//! # Model (seed B; every assumption stated)
//!
//! * Front pair: two 7009C (or -hybrid/-ceramic) back-to-back; rear pair:
//!   two 7008C back-to-back; each pair adjacent (centre spacing = bearing
//!   width). Both pairs get the same preload per bearing.
//! * Rigid preload: each pair keeps its assembly interference; the rear set
//!   floats axially in the housing, so the spindle's axial growth between
//!   the sets loads nothing (the effect `preload_change_from_axial_growth`
//!   changes nothing for a rigid preload). Spring preload: one spring pack in
//!   the load path of the bearing system (seed B's constant-pressure
//!   preload); with [`Effect::PreloadChangeFromAxialGrowth`] on, the axial
//!   growth u_axial of the shaft relative to the housing between the two
//!   sets compresses it by x (bearings in series with the spring, x close
//!   to u_axial as the bearings are far stiffer axially), and both pairs
//!   carry the spring force F0 + k_s x. With the effect off the growth does
//!   not reach the spring (an ideal constant-force preload; the spring still
//!   takes the pairs' own axial approach changes from speed and thermal
//!   raceway offsets); the reported `axial_growth_m` is the computed growth
//!   either way.
//! * External radial load at the nose (distance `nose_length_m` in front of
//!   the front pair): rigid shaft on two simple supports (the pairs' moment
//!   stiffness is not used to share the load): front F (1 + a/L), rear
//!   -F a/L, L = front_span + rear_span, along x.
//! * Unbalanced magnetic pull (effect `UnbalancedMagneticPull`, off in the
//!   seed B default as in the rotor model): the static pull k_ump e_static
//!   of the eccentric rotor core acts along y at the core centre (midway
//!   between the pairs for seed B) and is shared by the same lever rule
//!   ([`super::shaft_loads`]); each pair's radial load is then
//!   hypot(F_x, F_y).
//! * Heat per bearing from its quasi-static state (A-20..A-27) by the
//!   single bearing's own code ([`crate::thermal::row_heat`]): M1 with Fa
//!   and Fr of that bearing and the load-weighted mean inner contact angle,
//!   Mv at the pair's ball temperature (with `temperature_dependent_viscosity`,
//!   else at the oil-air supply temperature), spin heat per contact with
//!   E(kappa) at its operating contact angle, spin friction coefficient
//!   `spin_friction_coefficient`; Burton-Staph split; the network lumps a
//!   pair in one inner/balls/outer node triple.
//! * Motor losses as in [`SpindleNetwork::sources_w`] (stator copper +
//!   iron n^1.5, rotor copper + windage n^2).
//! * Thermal offsets per pair from [`thermal_offsets`] with the node rises
//!   above the assembly temperature: inner ring tight on the shaft, outer
//!   ring loose in a steel housing of the sleeve diameter, the free-gap
//!   change (ball growth) projected on the free contact line, and the axial
//!   growth within the pair (half the spacing, shaft vs housing; a DB pair
//!   is unloaded by it, `axial_sign = -1`).
//! * Axial growth between the sets: shaft (front journal, rotor core, rear
//!   journal at their node temperatures) minus housing (front housing,
//!   sleeve, rear housing) over L.

use rayon::prelude::*;

use super::pair::{BearingPair, PairLoad, PairState, PairWarm, Preload};
use super::shaft_loads::CoreMagneticPull;
use crate::bearing::{BearingModel, BearingState, RacewayOffsets, SolveOptions};
use crate::effects::{Effect, EffectSet};
use crate::error::{finite, in_range, non_negative, positive, Error, Result};
use crate::materials::Material;
use crate::thermal::expansion::{thermal_offsets, ComponentRises, Mounting, RingFit, ThermalOffsets};
use crate::thermal::friction::{FrictionSettings, HeatModel, Lubrication, SkfSettings};
use crate::thermal::heat::{BearingHeat, HeatSplit};
use crate::thermal::network::{SteadySolver, Temperatures, Transient, TransientSolver};
use crate::thermal::presets::{BallConduction, SpindleNetwork, SpindleParams};
use crate::thermal::row_heat::{oil_temperature_c, row_friction_heat, OilState};
use crate::units::rpm_to_rad_s;
use crate::Bearing;

/// Assumed spin (traction) coefficient mu_s of A-22: EHL traction of
/// mineral oils at the spin-dominated sliding of angular-contact bearings
/// is typically 0.03-0.07; we take 0.05.
/// The default of both the spindle and the single bearing
/// ([`crate::thermal::coupled::CoupledOptions`]), as in Python.
pub const DEFAULT_SPIN_FRICTION_COEFFICIENT: f64 = 0.05;
/// The default spin friction coefficient under its former name.
#[deprecated(since = "0.2.0", note = "use DEFAULT_SPIN_FRICTION_COEFFICIENT")]
pub const DEFAULT_SPIN_FRICTION: f64 = DEFAULT_SPIN_FRICTION_COEFFICIENT;
/// Spring rate implied by seed B Fig. 17: 6.45 N / 17.92 um = 0.36 N/um.
pub const SEED_B_SPRING_RATE_N_PER_M: f64 = 6.45 / 17.92e-6;

/// The default of the dimensionless scales a stored configuration may omit.
fn unit_scale() -> f64 {
    1.0
}

/// Everything that defines a spindle besides the network parameters.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct SpindleConfig {
    /// Network and geometry (front/rear bearings inside).
    pub params: SpindleParams,
    /// Preload per bearing (both pairs).
    pub preload: Preload,
    /// Working radial load at the spindle nose \[N\].
    pub radial_load_n: f64,
    /// Spin friction coefficient mu_s (dimensionless; default
    /// [`DEFAULT_SPIN_FRICTION_COEFFICIENT`]). Stored files that name it
    /// `spin_friction` still load.
    #[serde(alias = "spin_friction")]
    pub spin_friction_coefficient: f64,
    /// Factor on Palmgren's load-friction factor f1 of every bearing
    /// (dimensionless, >= 0; default 1, Harris' constants; the Palmgren
    /// heat model only). Stored files without it load with 1.
    #[serde(default = "unit_scale")]
    pub load_friction_scale: f64,
    /// An extra heat at the front bearing set \[W\] (>= 0; default 0):
    /// half on each front bearing, added to its rolling heat and so split
    /// like it (Burton-Staph, A-27). A known heat the friction model leaves
    /// out. Stored files without it load with 0.
    #[serde(default)]
    pub extra_heat_w: f64,
    /// The speed law of an unknown heat source at the front set, added to
    /// `extra_heat_w`: `max(0, a x + b x^2)`, `x = n / n_ref`, `a` this
    /// \[W\] (default 0; a diagnosis' unknown heat source).
    #[serde(default)]
    pub unknown_heat_linear_w: f64,
    /// `b` of the unknown heat source's law \[W\] (default 0).
    #[serde(default)]
    pub unknown_heat_quadratic_w: f64,
    /// `n_ref` of the unknown heat source's law \[rpm\] (> 0 when a
    /// coefficient is not 0; default 0).
    #[serde(default)]
    pub unknown_heat_reference_rpm: f64,
    /// Temperature at which the spindle was assembled (zero thermal offsets) \[C\].
    pub assembly_temperature_c: f64,
    /// Effects (high-speed bearing terms, thermal expansion by part,
    /// viscosity, unbalanced magnetic pull on the shaft).
    pub effects: EffectSet,
    /// Static unbalanced magnetic pull of the motor rotor on the shaft; it
    /// loads the pairs when `effects` has `UnbalancedMagneticPull`
    /// ([`super::shaft_loads`]). None: no air-gap data (the effect is then
    /// refused).
    pub magnetic_pull: Option<CoreMagneticPull>,
    /// Heat model of the bearings (docs/concepts/physics.md §9; default Palmgren).
    #[serde(default)]
    pub heat_model: HeatModel,
    /// Lubrication method (SKF K_rs default; default oil-air, seed B's).
    #[serde(default = "default_lubrication")]
    pub lubrication: Lubrication,
    /// Oil volume fraction X of the ball drag in the bearing cavities
    /// (0..1; default 0, off).
    #[serde(default)]
    pub churning_oil_fraction: f64,
    /// Oil supply of the bearings (docs/concepts/physics.md §9): when set,
    /// the cavity oil fraction, drag and churning follow from the supply and
    /// the speed, and `churning_oil_fraction` is not used. Default None.
    #[serde(default)]
    pub oil_supply: Option<crate::thermal::oil_supply::SupplySettings>,
    /// Settings of the SKF-style model.
    #[serde(default)]
    pub skf: SkfSettings,
    /// Largest fixed-point iterations of the coupled steady state.
    pub max_iterations: usize,
    /// Converged when no node temperature moves more than this \[K\].
    pub tolerance_k: f64,
}

/// Spindle presets by name (the names of Python's `tb.Spindle.preset`) and
/// the bearing variant of each: seed B's spindle with hybrid (Si3N4 balls,
/// steel rings), all-steel or all-ceramic 7009C/7008C bearings.
pub const SPINDLE_PRESETS: [(&str, &str); 3] = [
    ("seed-ceramic-spindle", "hybrid"),
    ("seed-steel-spindle", "steel"),
    ("seed-full-ceramic-spindle", "ceramic"),
];

impl SpindleConfig {
    /// The extra heat at the front set at `speed_rpm` \[W\]:
    /// `extra_heat_w` plus the unknown heat source's law, `max(0, a x +
    /// b x^2)` with `x = n / n_ref` (none without a reference speed).
    pub fn extra_heat_at_w(&self, speed_rpm: f64) -> f64 {
        let r = self.unknown_heat_reference_rpm;
        let law = if r > 0.0 {
            let x = speed_rpm / r;
            (self.unknown_heat_linear_w * x + self.unknown_heat_quadratic_w * x * x).max(0.0)
        } else {
            0.0
        };
        self.extra_heat_w + law
    }

    /// The unknown heat source's law: finite coefficients within
    /// +-[`MAX_EXTRA_HEAT_W`], and a reference speed > 0 when one is not 0.
    fn check_unknown_heat(&self) -> Result<()> {
        in_range(
            "unknown_heat_linear_w",
            self.unknown_heat_linear_w,
            -MAX_EXTRA_HEAT_W,
            MAX_EXTRA_HEAT_W,
        )?;
        in_range(
            "unknown_heat_quadratic_w",
            self.unknown_heat_quadratic_w,
            -MAX_EXTRA_HEAT_W,
            MAX_EXTRA_HEAT_W,
        )?;
        non_negative("unknown_heat_reference_rpm", self.unknown_heat_reference_rpm)?;
        let law = self.unknown_heat_linear_w != 0.0 || self.unknown_heat_quadratic_w != 0.0;
        if law && self.unknown_heat_reference_rpm <= 0.0 {
            return Err(Error::config(
                "unknown_heat_reference_rpm",
                self.unknown_heat_reference_rpm,
                "a speed > 0 [rpm]: the law's coefficients are its heat at x = n / n_ref",
            ));
        }
        Ok(())
    }

    /// The preset spindle `name` (case-insensitive; the names of
    /// [`SPINDLE_PRESETS`], as Python's `tb.Spindle.preset`).
    pub fn preset(name: &str) -> Result<Self> {
        let variant = SPINDLE_PRESETS
            .iter()
            .find(|(n, _)| n.eq_ignore_ascii_case(name))
            .map(|(_, v)| *v)
            .ok_or_else(|| {
                Error::config(
                    "spindle",
                    name,
                    format!("unknown spindle preset; known: {}", Self::preset_names().join(", ")),
                )
            })?;
        Self::seed_b_variant(variant)
    }

    /// The names [`SpindleConfig::preset`] accepts.
    pub fn preset_names() -> Vec<&'static str> {
        SPINDLE_PRESETS.iter().map(|p| p.0).collect()
    }

    /// Seed B spindle with `variant` bearings ("steel", "hybrid", "ceramic").
    #[deprecated(
        since = "0.2.0",
        note = "use SpindleConfig::preset with a preset name (\"seed-ceramic-spindle\" for the hybrid variant, \"seed-steel-spindle\", \"seed-full-ceramic-spindle\")"
    )]
    pub fn seed_b(variant: &str) -> Result<Self> {
        Self::seed_b_variant(variant)
    }

    /// Seed B spindle with `variant` bearings ("steel", "hybrid", "ceramic"),
    /// 400 N spring preload, no radial load (see the module docs and
    /// [`SpindleParams::seed_b`]); every effect on except the unbalanced
    /// magnetic pull, which is off by default as in the rotor model
    /// (`SpindleVibrationConfig::seed`); its data are the rotor preset's
    /// ([`CoreMagneticPull::seed_b`]).
    fn seed_b_variant(variant: &str) -> Result<Self> {
        let suffix = match variant.to_ascii_lowercase().as_str() {
            "steel" => "",
            "hybrid" => "-hybrid",
            "ceramic" => "-ceramic",
            _ => {
                return Err(Error::config(
                    "variant",
                    variant,
                    "use steel, hybrid (Si3N4 balls) or ceramic (all Si3N4)",
                ))
            }
        };
        let mut params = SpindleParams::seed_b()?;
        params.front_bearing = Bearing::preset(&format!("7009C{suffix}"))?;
        params.rear_bearing = Bearing::preset(&format!("7008C{suffix}"))?;
        let ambient = params.ambient_temperature_c;
        let magnetic_pull = CoreMagneticPull::seed_b(params.front_span_m + params.rear_span_m)?;
        Ok(SpindleConfig {
            params,
            // Seed B's test rig: 400 N preload by a spring pack whose rate
            // follows from its Fig. 17 (6.45 N for 17.92 um).
            preload: Preload::Spring {
                force_n: 400.0,
                rate_n_per_m: SEED_B_SPRING_RATE_N_PER_M,
            },
            radial_load_n: 0.0,
            spin_friction_coefficient: DEFAULT_SPIN_FRICTION_COEFFICIENT,
            load_friction_scale: 1.0,
            extra_heat_w: 0.0,
            unknown_heat_linear_w: 0.0,
            unknown_heat_quadratic_w: 0.0,
            unknown_heat_reference_rpm: 0.0,
            assembly_temperature_c: ambient,
            effects: EffectSet::all().without(Effect::UnbalancedMagneticPull),
            magnetic_pull: Some(magnetic_pull),
            heat_model: HeatModel::Palmgren,
            lubrication: Lubrication::OilAir,
            churning_oil_fraction: 0.0,
            oil_supply: None,
            skf: SkfSettings::default(),
            max_iterations: 60,
            tolerance_k: 1e-4,
        })
    }
}

fn default_lubrication() -> Lubrication {
    Lubrication::OilAir
}

/// A spindle ready to solve.
#[derive(Debug, Clone)]
pub struct Spindle {
    /// The configuration as built: `params.preload_n` and
    /// `params.ball_conduction` follow the preload. Change it through
    /// [`Spindle::with_preload`] / [`Spindle::with_radial_load`], which
    /// rebuild what depends on it.
    pub config: SpindleConfig,
    /// Front pair (two front bearings back-to-back, spacing = bearing width).
    pub front: BearingPair,
    /// Rear pair (two rear bearings back-to-back, spacing = bearing width).
    pub rear: BearingPair,
    /// The spindle thermal network built from `config.params`.
    pub network: SpindleNetwork,
    housing: Material,
}

/// Heat and mechanics of one bearing in a solved state.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BearingHeatReport {
    /// Heat by mechanism: rolling omega (M1 + Mv), inner and outer spin \[W\].
    pub heat: BearingHeat,
    /// Burton-Staph split to inner ring, balls, outer ring \[W\].
    pub split: HeatSplit,
    /// Palmgren load moment M1, or the SKF rolling moment M_rr [N m].
    pub load_moment_n_m: f64,
    /// Palmgren viscous moment Mv, or the SKF sliding moment M_sl [N m].
    pub viscous_moment_n_m: f64,
    /// Drag heat (ball drag in the mixture, or the bath drag) \[W\].
    pub drag_w: f64,
    /// Cavity oil volume fraction X of the drag [-].
    pub cavity_oil_fraction: f64,
    /// Heat split into rolling, sliding, spin, drag, churning, seal \[W\].
    pub breakdown: crate::thermal::friction::HeatBreakdown,
}

/// A solved spindle operating point.
#[derive(Debug, Clone)]
pub struct SpindleState {
    /// Shaft speed \[rpm\].
    pub speed_rpm: f64,
    /// Steady temperatures of every node of the spindle network \[C\].
    pub temperatures: Temperatures,
    /// Front pair at the converged temperatures.
    pub front: PairState,
    /// Rear pair at the converged temperatures.
    pub rear: PairState,
    /// Heat of bearings [front A, front B, rear A, rear B].
    pub bearing_heat: [BearingHeatReport; 4],
    /// Motor losses \[W\].
    pub motor_losses_w: f64,
    /// Sum of all heat sources \[W\].
    pub total_heat_w: f64,
    /// Heat leaving through the boundaries \[W\] (equals total_heat_w at steady state).
    pub boundary_flow_w: f64,
    /// Thermal offsets of the front pair (one bearing; both share them).
    pub front_offsets: ThermalOffsets,
    /// Thermal offsets of the rear pair (one bearing; both share them).
    pub rear_offsets: ThermalOffsets,
    /// Axial growth of the shaft relative to the housing between the sets \[m\].
    pub axial_growth_m: f64,
    /// Fixed-point iterations used.
    pub iterations: usize,
    /// Largest node temperature change of the last iteration \[K\].
    pub temperature_change_k: f64,
    /// (front preload N, bearing heat W, change K) per fixed-point
    /// iteration; the first entry is the cold start (change infinite).
    pub history: Vec<(f64, f64, f64)>,
}

impl SpindleState {
    /// Radial thermal displacement of the front bearing: the radial
    /// groove-centre interference u_Tr plus the projected free-gap change
    /// (ball growth), [`ThermalOffsets::radial_with_gap_m`] \[m\].
    pub fn front_radial_thermal_displacement_m(&self, free_contact_angle_rad: f64) -> f64 {
        self.front_offsets.radial_with_gap_m(free_contact_angle_rad)
    }

    /// Temperature of a node by name \[C\].
    pub fn temperature_c(&self, node: &str) -> Result<f64> {
        self.temperatures.get(node)
    }
}

/// The largest extra heat of [`SpindleConfig::extra_heat_w`] \[W\]: ten
/// times the heat of the seed spindle's four bearings at 18,000 rpm.
pub const MAX_EXTRA_HEAT_W: f64 = 1e4;

/// `report` with `extra_w` added to its rolling heat (so to its total) and
/// split again like it.
fn with_extra_heat(report: &mut BearingHeatReport, extra_w: f64) {
    if extra_w > 0.0 {
        report.heat.rolling_w += extra_w;
        report.split = report.heat.split();
    }
}

/// Working state carried between evaluations (warm starts).
#[derive(Debug, Clone, Default)]
struct Warm {
    front: PairWarm,
    rear: PairWarm,
}

/// Mechanics and heat at given temperatures.
struct Evaluation {
    front: PairState,
    rear: PairState,
    heat: [BearingHeatReport; 4],
    sources_w: Vec<f64>,
    motor_w: f64,
    front_offsets: ThermalOffsets,
    rear_offsets: ThermalOffsets,
    axial_growth_m: f64,
}

impl Spindle {
    /// Build the pairs and the network.
    pub fn new(config: SpindleConfig) -> Result<Self> {
        non_negative("spin_friction_coefficient", config.spin_friction_coefficient)?;
        in_range("load_friction_scale", config.load_friction_scale, 0.0, 100.0)?;
        if config.load_friction_scale != 1.0 && config.heat_model != HeatModel::Palmgren {
            return Err(Error::config(
                "load_friction_scale",
                config.load_friction_scale,
                "scales Palmgren's f1: use it with heat_model \"palmgren\"",
            ));
        }
        in_range("churning_oil_fraction", config.churning_oil_fraction, 0.0, 1.0)?;
        in_range("extra_heat_w", config.extra_heat_w, 0.0, MAX_EXTRA_HEAT_W)?;
        config.check_unknown_heat()?;
        if let Some(s) = &config.oil_supply {
            s.validate()?;
        }
        config.skf.validate()?;
        finite("radial_load_n", config.radial_load_n)?;
        finite("assembly_temperature_c", config.assembly_temperature_c)?;
        positive("tolerance_k", config.tolerance_k)?;
        if config.max_iterations == 0 {
            return Err(Error::config("max_iterations", 0, "need at least one iteration"));
        }
        match &config.magnetic_pull {
            Some(m) => m.validate()?,
            None if config.effects.has(Effect::UnbalancedMagneticPull) => {
                return Err(Error::config(
                    "magnetic_pull",
                    "None",
                    "the unbalanced_magnetic_pull effect needs the rotor's air-gap data",
                ))
            }
            None => {}
        }
        super::config_io::check_params(&config.params)?;
        let mut params = config.params.clone();
        let f0 = config.preload.force_n();
        positive("preload_n", f0)?;
        params.preload_n = f0;
        // The ball conduction follows the preload, row by row: a fixed
        // Hertz contact load (stored configurations) becomes each row's own
        // contact under this preload; the bulk (seed A) form is kept.
        if let BallConduction::HertzConstriction { .. } = params.ball_conduction {
            params.ball_conduction = BallConduction::HertzAtPreload;
        }
        let opts = SolveOptions {
            effects: config.effects,
            ..SolveOptions::default()
        };
        let fm = BearingModel::new(&params.front_bearing)?;
        let rm = BearingModel::new(&params.rear_bearing)?;
        let front = BearingPair::new(
            fm.clone(),
            fm,
            params.front_bearing.geometry.width_m,
            config.preload,
            opts,
        )?;
        let rear = BearingPair::new(
            rm.clone(),
            rm,
            params.rear_bearing.geometry.width_m,
            config.preload,
            opts,
        )?;
        let network = SpindleNetwork::new(params.clone())?;
        let mut config = config;
        config.params = params;
        Ok(Spindle {
            config,
            front,
            rear,
            network,
            housing: Material::shaft_steel(),
        })
    }

    /// The preset spindle `name` ("seed-ceramic-spindle",
    /// "seed-steel-spindle", "seed-full-ceramic-spindle"; see
    /// [`SpindleConfig::preset`]), as Python's `tb.Spindle.preset`.
    pub fn preset(name: &str) -> Result<Self> {
        Spindle::new(SpindleConfig::preset(name)?)
    }

    /// The names [`Spindle::preset`] accepts.
    pub fn preset_names() -> Vec<&'static str> {
        SpindleConfig::preset_names()
    }

    /// Seed B spindle with `variant` bearings ("steel", "hybrid", "ceramic").
    #[deprecated(
        since = "0.2.0",
        note = "use Spindle::preset with a preset name (\"seed-ceramic-spindle\" for the hybrid variant, \"seed-steel-spindle\", \"seed-full-ceramic-spindle\")"
    )]
    pub fn seed_b(variant: &str) -> Result<Self> {
        Spindle::new(SpindleConfig::seed_b_variant(variant)?)
    }

    /// The same spindle with another preload.
    pub fn with_preload(&self, preload: Preload) -> Result<Self> {
        Spindle::new(SpindleConfig {
            preload,
            ..self.config.clone()
        })
    }

    /// The same spindle with another working radial load.
    pub fn with_radial_load(&self, radial_load_n: f64) -> Result<Self> {
        finite("radial_load_n", radial_load_n)?;
        let mut s = self.clone();
        s.config.radial_load_n = radial_load_n;
        Ok(s)
    }

    /// Radial loads on the front and rear pairs from the nose load, along x
    /// (lever rule with the load at c = -a in front of the front pair,
    /// [`super::shaft_loads::lever_rule_n`]: front F (1 + a/L), rear -F a/L) \[N\].
    pub fn pair_radial_loads_n(&self) -> Result<(f64, f64)> {
        let p = &self.config.params;
        super::shaft_loads::lever_rule_n(
            self.config.radial_load_n,
            -p.nose_length_m,
            p.front_span_m + p.rear_span_m,
        )
    }

    /// Static unbalanced magnetic pull on the shaft, along +y \[N\]: the
    /// configured pull with the `UnbalancedMagneticPull` effect on, else 0.
    pub fn magnetic_pull_n(&self) -> f64 {
        match &self.config.magnetic_pull {
            Some(m) if self.config.effects.has(Effect::UnbalancedMagneticPull) => m.static_force_n(),
            _ => 0.0,
        }
    }

    /// Shares of the front and rear pairs of the magnetic pull, along +y
    /// (lever rule on the rigid shaft, [`super::shaft_loads`]) \[N\].
    pub fn pair_magnetic_pull_n(&self) -> Result<(f64, f64)> {
        let p = &self.config.params;
        let at = self
            .config
            .magnetic_pull
            .as_ref()
            .map_or(0.0, |m| m.core_from_front_pair_m);
        super::shaft_loads::lever_rule_n(self.magnetic_pull_n(), at, p.front_span_m + p.rear_span_m)
    }

    /// The pair loads under their former name; see [`Spindle::pair_loads`].
    #[deprecated(since = "0.2.0", note = "use Spindle::pair_loads (SI: N, N m)")]
    pub fn pair_loads_n_nm(&self) -> Result<([f64; 5], [f64; 5])> {
        self.pair_loads()
    }

    /// External loads [Fx, Fy, Fz, Mx, My] on the front and rear pair
    /// centres: the nose load along x ([`Self::pair_radial_loads_n`]) and
    /// the magnetic pull along y ([`Self::pair_magnetic_pull_n`]) (N, N m).
    pub fn pair_loads(&self) -> Result<([f64; 5], [f64; 5])> {
        let (xf, xr) = self.pair_radial_loads_n()?;
        let (yf, yr) = self.pair_magnetic_pull_n()?;
        Ok(([xf, yf, 0.0, 0.0, 0.0], [xr, yr, 0.0, 0.0, 0.0]))
    }

    fn mounting(&self, bearing: &Bearing) -> Mounting {
        let half = 0.5 * bearing.geometry.width_m;
        Mounting {
            housing: self.housing.clone(),
            housing_outer_diameter_m: self.config.params.sleeve_outer_diameter_m,
            shaft_length_m: half,
            housing_length_m: half,
            inner_fit: RingFit::Tight,
            outer_fit: RingFit::Loose,
            plane_strain: false,
            axial_sign: -1.0,
        }
    }

    /// Thermal offsets of the front and rear pairs at node temperatures `t`.
    pub fn thermal_offsets(&self, t: &[f64]) -> Result<(ThermalOffsets, ThermalOffsets)> {
        let n = &self.network;
        let t0 = self.config.assembly_temperature_c;
        let p = &self.config.params;
        let rises = |s: usize, i: usize, b: usize, o: usize, h: usize| ComponentRises {
            shaft_k: t[s] - t0,
            inner_ring_k: t[i] - t0,
            balls_k: t[b] - t0,
            outer_ring_k: t[o] - t0,
            housing_k: t[h] - t0,
        };
        let f = thermal_offsets(
            &p.front_bearing,
            &self.mounting(&p.front_bearing),
            &rises(
                n.shaft_front,
                n.front_inner,
                n.front_balls,
                n.front_outer,
                n.housing_front,
            ),
            self.config.effects,
        )?;
        let r = thermal_offsets(
            &p.rear_bearing,
            &self.mounting(&p.rear_bearing),
            &rises(n.shaft_rear, n.rear_inner, n.rear_balls, n.rear_outer, n.housing_rear),
            self.config.effects,
        )?;
        Ok((f, r))
    }

    /// Axial growth of the shaft relative to the housing between the front
    /// and rear pair centres at node temperatures `t` \[m\] (positive: the
    /// shaft grows more).
    pub fn axial_growth_m(&self, t: &[f64]) -> f64 {
        let n = &self.network;
        let p = &self.config.params;
        let e = self.config.effects;
        let t0 = self.config.assembly_temperature_c;
        let l = p.front_span_m + p.rear_span_m;
        let shaft = Material::shaft_steel();
        let (ls_f, ls_r) = (
            (p.front_span_m - 0.5 * p.rotor_length_m).max(0.0),
            (p.rear_span_m - 0.5 * p.rotor_length_m).max(0.0),
        );
        let ls_rotor = l - ls_f - ls_r;
        let shaft_growth = if e.has(Effect::ThermalExpansionShaft) {
            shaft.thermal_expansion_per_k
                * ((t[n.shaft_front] - t0) * ls_f + (t[n.rotor] - t0) * ls_rotor + (t[n.shaft_rear] - t0) * ls_r)
        } else {
            0.0
        };
        let (lh_f, lh_r) = (0.5 * p.front_housing_length_m, 0.5 * p.rear_housing_length_m);
        let lh_s = (l - lh_f - lh_r).max(0.0);
        let housing_growth = if e.has(Effect::ThermalExpansionHousing) {
            self.housing.thermal_expansion_per_k
                * ((t[n.housing_front] - t0) * lh_f + (t[n.sleeve] - t0) * lh_s + (t[n.housing_rear] - t0) * lh_r)
        } else {
            0.0
        };
        shaft_growth - housing_growth
    }

    /// The part of the axial growth between the sets `growth_m` that
    /// reaches the preload spring \[m\]: all of it with
    /// [`Effect::PreloadChangeFromAxialGrowth`] on, none with it off (ideal
    /// constant-force preload). A rigid pair ignores it (its rear set floats).
    pub fn spring_growth_m(&self, growth_m: f64) -> f64 {
        if self.config.effects.has(Effect::PreloadChangeFromAxialGrowth) {
            growth_m
        } else {
            0.0
        }
    }

    /// Motor losses per node \[W\] at `speed_rpm` (same law as the network preset).
    fn motor_sources(&self, speed_rpm: f64, s: &mut [f64]) -> f64 {
        let p = &self.config.params;
        let r = speed_rpm / p.loss_reference_rpm;
        let stator = p.stator_copper_w + p.stator_iron_w * r.powf(1.5);
        let rotor = p.rotor_copper_w + p.rotor_mechanical_w * r * r;
        s[self.network.stator] += stator;
        s[self.network.rotor] += rotor;
        stator + rotor
    }

    /// The friction settings of the spindle's bearings (heat model, f0,
    /// mu_s, oil fraction X, SKF), as the single bearing's
    /// [`crate::thermal::coupled::friction_settings`].
    pub fn friction_settings(&self) -> FrictionSettings {
        let c = &self.config;
        FrictionSettings {
            heat_model: c.heat_model,
            lubrication: c.lubrication,
            lubrication_factor_f0: c.params.lubrication_factor_f0,
            spin_friction_coefficient: c.spin_friction_coefficient,
            load_friction_scale: c.load_friction_scale,
            oil_volume_fraction: c.churning_oil_fraction,
            skf: c.skf,
            oil_supply: c.oil_supply,
        }
    }

    /// Heat of one solved bearing row of this spindle (`bearing` its
    /// geometry, `state` from a pair solve) with the oil at `oil_c`: the
    /// single implementation of the single bearing
    /// ([`crate::thermal::row_heat::row_friction_heat`]) under the row's own
    /// axial and radial load.
    pub fn row_heat(&self, state: &BearingState, bearing: &Bearing, oil_c: f64) -> Result<BearingHeatReport> {
        let l = &state.applied_load;
        let lub = &self.config.params.lubricant;
        let oil = OilState::at(lub, oil_c)?;
        let f = row_friction_heat(
            bearing,
            state,
            l[2].max(0.0),
            l[0].hypot(l[1]),
            &oil,
            lub,
            &self.friction_settings(),
            self.config.effects,
        )?;
        Ok(BearingHeatReport {
            heat: f.heat,
            split: f.heat.split(),
            load_moment_n_m: f.load_moment_n_m,
            viscous_moment_n_m: f.viscous_moment_n_m,
            drag_w: f.drag_w,
            cavity_oil_fraction: f.cavity_oil_fraction,
            breakdown: f.breakdown,
        })
    }

    /// Mechanics and heat at node temperatures `t` (None: cold, no offsets).
    fn evaluate(&self, speed_rpm: f64, t: Option<&[f64]>, warm: &mut Warm) -> Result<Evaluation> {
        let zero = ThermalOffsets {
            shaft_surface_radial_m: 0.0,
            housing_bore_radial_m: 0.0,
            inner_groove_centre_radial_m: 0.0,
            outer_groove_centre_radial_m: 0.0,
            ball_diameter_growth_m: 0.0,
            inner_groove_radius_growth_m: 0.0,
            outer_groove_radius_growth_m: 0.0,
            free_gap_change_m: 0.0,
            inner_fit_pressure_change_pa: 0.0,
            outer_fit_pressure_change_pa: 0.0,
            radial_m: 0.0,
            axial_m: 0.0,
        };
        let (fo, ro, growth) = match t {
            Some(t) => {
                let (f, r) = self.thermal_offsets(t)?;
                (f, r, self.axial_growth_m(t))
            }
            None => (zero, zero, 0.0),
        };
        let spring_growth_m = self.spring_growth_m(growth);
        let to_raceway = |o: &ThermalOffsets, b: &Bearing| {
            let a0 = b.geometry.free_contact_angle_rad;
            RacewayOffsets {
                axial_m: o.axial_with_gap_m(a0),
                radial_m: o.radial_with_gap_m(a0),
            }
        };
        let p = &self.config.params;
        let (load_front, load_rear) = self.pair_loads()?;
        let f_off = to_raceway(&fo, &p.front_bearing);
        let r_off = to_raceway(&ro, &p.rear_bearing);
        let front = self.front.solve_warm(
            speed_rpm,
            &PairLoad {
                external_load: load_front,
                offsets: [f_off, f_off],
                spring_growth_m,
            },
            &mut warm.front,
        )?;
        let rear = self.rear.solve_warm(
            speed_rpm,
            &PairLoad {
                external_load: load_rear,
                offsets: [r_off, r_off],
                spring_growth_m,
            },
            &mut warm.rear,
        )?;
        let (heat, sources_w, motor_w) = self.heat_sources(speed_rpm, t, &front, &rear)?;
        Ok(Evaluation {
            front,
            rear,
            heat,
            sources_w,
            motor_w,
            front_offsets: fo,
            rear_offsets: ro,
            axial_growth_m: growth,
        })
    }

    /// Bearing heat (from solved pairs, oil at the pair's ball temperature)
    /// and motor losses as a source vector.
    fn heat_sources(
        &self,
        speed_rpm: f64,
        t: Option<&[f64]>,
        front: &PairState,
        rear: &PairState,
    ) -> Result<([BearingHeatReport; 4], Vec<f64>, f64)> {
        let n = &self.network;
        let p = &self.config.params;
        let oil = |node: usize| oil_temperature_c(self.config.effects, p.oil_air_temperature_c, t.map(|t| t[node]));
        let (of, or) = (oil(n.front_balls), oil(n.rear_balls));
        let mut heat = [
            self.row_heat(&front.bearings[0], &p.front_bearing, of)?,
            self.row_heat(&front.bearings[1], &p.front_bearing, of)?,
            self.row_heat(&rear.bearings[0], &p.rear_bearing, or)?,
            self.row_heat(&rear.bearings[1], &p.rear_bearing, or)?,
        ];
        let extra_w = self.config.extra_heat_at_w(speed_rpm);
        for h in heat.iter_mut().take(2) {
            with_extra_heat(h, 0.5 * extra_w);
        }
        let mut s = vec![0.0; n.network.nodes().len()];
        let motor_w = self.motor_sources(speed_rpm, &mut s);
        for (k, h) in heat.iter().enumerate() {
            let (i, b, o) = if k < 2 {
                (n.front_inner, n.front_balls, n.front_outer)
            } else {
                (n.rear_inner, n.rear_balls, n.rear_outer)
            };
            s[i] += h.split.inner_ring_w;
            s[b] += h.split.balls_w;
            s[o] += h.split.outer_ring_w;
        }
        Ok((heat, s, motor_w))
    }

    fn check_speed(speed_rpm: f64) -> Result<f64> {
        positive("speed_rpm", speed_rpm)
    }

    /// Bearings at `speed_rpm` without thermal effects (cold geometry, no
    /// axial growth): (front pair, rear pair).
    pub fn isothermal(&self, speed_rpm: f64) -> Result<(PairState, PairState)> {
        Self::check_speed(speed_rpm)?;
        let e = self.evaluate(speed_rpm, None, &mut Warm::default())?;
        Ok((e.front, e.rear))
    }

    /// The coupled steady state under its former name; see
    /// [`Spindle::thermal_state`].
    #[deprecated(
        since = "0.2.0",
        note = "use Spindle::thermal_state (the name of the Python function)"
    )]
    pub fn steady_state(&self, speed_rpm: f64) -> Result<SpindleState> {
        self.thermal_state(speed_rpm)
    }

    /// Coupled steady state at `speed_rpm` (fixed point, see module docs).
    /// Thermal runaway (preload and bearing heat growing together while the
    /// temperature change does not shrink, or the oil leaving its data range
    /// on the way) is reported as [`Error::ThermalRunaway`]. Python's
    /// `tb.thermal_state(spindle, speed_rpm=...)`.
    pub fn thermal_state(&self, speed_rpm: f64) -> Result<SpindleState> {
        Self::check_speed(speed_rpm)?;
        let speed = rpm_to_rad_s(speed_rpm);
        let mut solver = SteadySolver::new(self.network.network.clone());
        let mut warm = Warm::default();
        let mut ev = self.evaluate(speed_rpm, None, &mut warm)?;
        let mut temps = solver.solve(&ev.sources_w, speed)?;
        let mut history: Vec<(f64, f64, f64)> = Vec::new();
        let bearing_heat_w = |e: &Evaluation| e.heat.iter().map(|h| h.heat.total_w()).sum::<f64>();
        history.push((ev.front.preload_n, bearing_heat_w(&ev), f64::INFINITY));
        let mut growing = 0usize;
        // Fixed point x -> G(x) (G: mechanics, heat, network solve) with
        // Aitken / Irons-Tuck dynamic relaxation x <- x + w (G(x) - x): the
        // plain iteration oscillates (hot oil -> thin film -> less viscous
        // heat -> cooler) with a ratio near -0.6.
        let mut x = temps.temperatures_c.clone();
        let mut omega = 1.0_f64;
        let mut r_prev: Option<Vec<f64>> = None;
        for it in 1..=self.config.max_iterations {
            let next_ev = match self.evaluate(speed_rpm, Some(&x), &mut warm) {
                Ok(e) => e,
                Err(err) => return Err(self.runaway_or(err, &history, speed_rpm)),
            };
            let next = solver.solve(&next_ev.sources_w, speed)?;
            let r: Vec<f64> = next.temperatures_c.iter().zip(&x).map(|(a, b)| a - b).collect();
            let change = r.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
            if let Some(rp) = &r_prev {
                let (mut num, mut den) = (0.0, 0.0);
                for (a, b) in r.iter().zip(rp) {
                    num += b * (a - b);
                    den += (a - b) * (a - b);
                }
                if den > 0.0 {
                    omega = (-omega * num / den).clamp(0.05, 1.5);
                }
            }
            for (xi, ri) in x.iter_mut().zip(&r) {
                *xi += omega * ri;
            }
            r_prev = Some(r);
            let entry = (next_ev.front.preload_n, bearing_heat_w(&next_ev), change);
            let last = history[history.len() - 1];
            if entry.0 > last.0 && entry.1 > last.1 && change >= last.2 * 0.999 {
                growing += 1;
            } else {
                growing = 0;
            }
            history.push(entry);
            ev = next_ev;
            temps = next;
            if change <= self.config.tolerance_k {
                let boundary: f64 = self
                    .network
                    .network
                    .boundary_flows_w(&temps.temperatures_c, speed)
                    .iter()
                    .map(|x| x.1)
                    .sum();
                return Ok(SpindleState {
                    speed_rpm,
                    front: ev.front,
                    rear: ev.rear,
                    bearing_heat: ev.heat,
                    motor_losses_w: ev.motor_w,
                    total_heat_w: ev.sources_w.iter().sum(),
                    boundary_flow_w: boundary,
                    front_offsets: ev.front_offsets,
                    rear_offsets: ev.rear_offsets,
                    axial_growth_m: ev.axial_growth_m,
                    iterations: it,
                    temperature_change_k: change,
                    history,
                    temperatures: temps,
                });
            }
            if growing >= 3 {
                return Err(runaway_error(
                    &history,
                    speed_rpm,
                    "temperature change no longer shrinks",
                ));
            }
        }
        let last = history[history.len() - 1];
        Err(Error::convergence(
            "coupled spindle steady state",
            self.config.max_iterations,
            last.2,
            self.config.tolerance_k,
        ))
    }

    fn runaway_or(&self, err: Error, history: &[(f64, f64, f64)], speed_rpm: f64) -> Error {
        let n = history.len();
        let rising = n >= 2 && history[n - 1].0 > history[n - 2].0 && history[n - 1].1 > history[n - 2].1;
        match err {
            Error::Config { ref field, .. } if rising && field == "oil_temperature_c" => {
                runaway_error(history, speed_rpm, "the oil left its data range while heating up")
            }
            Error::Convergence { .. } if rising => runaway_error(history, speed_rpm, "the bearings lost equilibrium"),
            e => e,
        }
    }

    /// Transient from uniform `initial_c` (free nodes; water and oil-air at
    /// their fixed values) at constant `speed_rpm`, TR-BDF2 steps of `dt_s`,
    /// recording every `record_every` steps. The bearing heat follows the
    /// temperatures through quasi-steady mechanics, re-solved at the start
    /// of a step (explicit in the coupling, as the network integrator)
    /// whenever a node temperature has moved more than `mechanics_update_k`
    /// since the last mechanics solve (0: every step); the heat itself (oil
    /// viscosity at the current temperature) is updated every step. Stops
    /// with `Error::Interrupted` at a step after a cancel (`crate::cancel`).
    pub fn transient(
        &self,
        speed_rpm: f64,
        duration_s: f64,
        dt_s: f64,
        record_every: usize,
        initial_c: Option<f64>,
        mechanics_update_k: f64,
    ) -> Result<Transient> {
        Self::check_speed(speed_rpm)?;
        let init = initial_c.unwrap_or(self.config.params.ambient_temperature_c);
        finite("initial_c", init)?;
        let mut tr = TransientSolver::new(self.network.network.clone());
        let t0 = self.network.network.initial_temperatures(init);
        let mut warm = Warm::default();
        let mut cache: Option<(Vec<f64>, Vec<f64>)> = None;
        let mut mech: Option<(Vec<f64>, PairState, PairState)> = None;
        let threshold = positive("mechanics_update_k", mechanics_update_k.max(0.0) + f64::MIN_POSITIVE)?;
        tr.integrate(
            &t0,
            duration_s,
            dt_s,
            rpm_to_rad_s(speed_rpm),
            record_every,
            |_, temps, out| {
                crate::cancel::check()?;
                if let Some((tc, sc)) = &cache {
                    if tc.as_slice() == temps {
                        out.copy_from_slice(sc);
                        return Ok(());
                    }
                }
                let moved = match &mech {
                    Some((tm, _, _)) => tm.iter().zip(temps).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max),
                    None => f64::INFINITY,
                };
                if moved > threshold {
                    let ev = self.evaluate(speed_rpm, Some(temps), &mut warm)?;
                    mech = Some((temps.to_vec(), ev.front, ev.rear));
                }
                let (_, front, rear) = mech
                    .as_ref()
                    .ok_or_else(|| Error::convergence("spindle transient", 0, f64::NAN, 0.0))?;
                let (_, s, _) = self.heat_sources(speed_rpm, Some(temps), front, rear)?;
                out.copy_from_slice(&s);
                cache = Some((temps.to_vec(), s));
                Ok(())
            },
        )
    }
}

fn runaway_error(history: &[(f64, f64, f64)], speed_rpm: f64, why: &str) -> Error {
    let first = history[0];
    let last = history[history.len() - 1];
    Error::ThermalRunaway(format!(
        "at {speed_rpm} rpm the preload grew from {:.1} N to {:.1} N and the bearing heat from {:.1} W to {:.1} W over {} iterations ({why})",
        first.0,
        last.0,
        first.1,
        last.1,
        history.len() - 1
    ))
}

/// Time at which `node` of a transient first comes within `fraction` of its
/// rise to `steady_c` and stays there, and the time it first stays within
/// `band_k` of it \[s\] (None if never).
pub fn settling_times_s(
    run: &Transient,
    node: usize,
    steady_c: f64,
    fraction: f64,
    band_k: f64,
) -> (Option<f64>, Option<f64>) {
    let start = run.temperatures_c[0][node];
    let rise = steady_c - start;
    let mut t_frac = None;
    let mut t_band = None;
    for (t, temps) in run.times_s.iter().zip(&run.temperatures_c) {
        let v = temps[node];
        let ok_frac = (v - start) * rise.signum() >= fraction * rise.abs();
        let ok_band = (v - steady_c).abs() <= band_k;
        t_frac = if ok_frac { t_frac.or(Some(*t)) } else { None };
        t_band = if ok_band { t_band.or(Some(*t)) } else { None };
    }
    (t_frac, t_band)
}

/// Compensation preload (seed B Fig. 17) at one speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CompensationPoint {
    /// Shaft speed \[rpm\].
    pub speed_rpm: f64,
    /// Axial growth of the shaft relative to the housing between the sets \[m\].
    pub axial_growth_m: f64,
    /// k_s u_axial \[N\] (bearings rigid compared with the spring); 0 with
    /// [`Effect::PreloadChangeFromAxialGrowth`] off (the growth does not
    /// reach the spring).
    pub compensation_preload_n: f64,
    /// Preload change of the front pair from the coupled solve, spring in
    /// series with the bearings' own axial compliance \[N\].
    pub solved_preload_change_n: f64,
}

/// Compensation preload at each speed for a spring preload of rate
/// `rate_n_per_m` (the spindle's preload force F0 and effects are kept;
/// with `preload_change_from_axial_growth` off the growth is still
/// reported but neither the closed form nor the solve sees it).
pub fn compensation_preload(
    spindle: &Spindle,
    speeds_rpm: &[f64],
    rate_n_per_m: f64,
) -> Result<Vec<CompensationPoint>> {
    non_negative("spring_rate_n_per_m", rate_n_per_m)?;
    let sp = spindle.with_preload(Preload::Spring {
        force_n: spindle.config.preload.force_n(),
        rate_n_per_m,
    })?;
    speeds_rpm
        .par_iter()
        .map(|&n| {
            let s = sp.thermal_state(n)?;
            Ok(CompensationPoint {
                speed_rpm: n,
                axial_growth_m: s.axial_growth_m,
                compensation_preload_n: rate_n_per_m * sp.spring_growth_m(s.axial_growth_m),
                solved_preload_change_n: s.front.preload_n - sp.config.preload.force_n(),
            })
        })
        .collect()
}

/// One point of a speed x preload x load grid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GridPoint {
    /// Shaft speed \[rpm\].
    pub speed_rpm: f64,
    /// Preload force per bearing at assembly F0 \[N\].
    pub preload_n: f64,
    /// Working radial load at the spindle nose \[N\].
    pub radial_load_n: f64,
    /// Temperature of the front pair's ball node \[C\].
    pub front_balls_c: f64,
    /// Temperature of the front pair's inner-ring node \[C\].
    pub front_inner_c: f64,
    /// Temperature of the front pair's outer-ring node \[C\].
    pub front_outer_c: f64,
    /// Operating preload of the front pair \[N\].
    pub operating_preload_n: f64,
    /// Total bearing heat \[W\].
    pub bearing_heat_w: f64,
    /// Radial displacement of the front pair under its radial load at speed,
    /// cold geometry, signed along the pair's external radial load
    /// ([`radial_displacement_along_load_m`]; positive: the shaft moves
    /// with the load) \[m\].
    pub mechanical_radial_displacement_m: f64,
    /// Radial thermal displacement of the front bearing, u_Tr plus the
    /// projected free-gap change ([`ThermalOffsets::radial_with_gap_m`];
    /// positive: the inner groove centre moves outward relative to the
    /// outer one, more interference) \[m\].
    pub thermal_radial_displacement_m: f64,
    /// Radial stiffness K_xx of the front pair, coupled thermal state [N/m].
    pub front_radial_stiffness_n_per_m: f64,
    /// Same, cold geometry at speed [N/m].
    pub front_radial_stiffness_isothermal_n_per_m: f64,
    /// Axial growth between the sets \[m\].
    pub axial_growth_m: f64,
}

impl GridPoint {
    /// Total radial displacement of seed B Figs. 15-16 (its eq. 22,
    /// delta_r + u_Tr) \[m\]: the sum of the two signed displacements of
    /// the loaded side's inner raceway, each positive outward along the
    /// load (the mechanical one with the load, the thermal one towards more
    /// interference); a thermal shrink (negative u_Tr) reduces it.
    pub fn total_radial_displacement_m(&self) -> f64 {
        self.mechanical_radial_displacement_m + self.thermal_radial_displacement_m
    }
}

/// Radial displacement of a pair along its external radial load \[m\]:
/// the shaft displacement (dx, dy) projected on the direction of the load
/// (Fx, Fy), positive with the load; with no radial load (no direction)
/// the size hypot(dx, dy).
pub fn radial_displacement_along_load_m(displacement: &[f64; 5], load: &[f64; 5]) -> f64 {
    let f = load[0].hypot(load[1]);
    if f > 0.0 {
        (displacement[0] * load[0] + displacement[1] * load[1]) / f
    } else {
        displacement[0].hypot(displacement[1])
    }
}

/// Evaluate one grid point: the spindle with this preload (same preload
/// kind; a spring keeps its rate) and radial load, coupled steady state
/// plus the isothermal mechanics.
pub fn grid_point(spindle: &Spindle, speed_rpm: f64, preload_n: f64, radial_load_n: f64) -> Result<GridPoint> {
    let preload = match spindle.config.preload {
        Preload::Rigid { .. } => Preload::Rigid { force_n: preload_n },
        Preload::Spring { rate_n_per_m, .. } => Preload::Spring {
            force_n: preload_n,
            rate_n_per_m,
        },
    };
    let sp = spindle.with_preload(preload)?.with_radial_load(radial_load_n)?;
    let s = sp.thermal_state(speed_rpm)?;
    let (cold, _) = sp.isothermal(speed_rpm)?;
    let n = &sp.network;
    let t = &s.temperatures.temperatures_c;
    let a0 = sp.config.params.front_bearing.geometry.free_contact_angle_rad;
    let (front_load, _) = sp.pair_loads()?;
    Ok(GridPoint {
        speed_rpm,
        preload_n,
        radial_load_n,
        front_balls_c: t[n.front_balls],
        front_inner_c: t[n.front_inner],
        front_outer_c: t[n.front_outer],
        operating_preload_n: s.front.preload_n,
        bearing_heat_w: s.bearing_heat.iter().map(|h| h.heat.total_w()).sum(),
        mechanical_radial_displacement_m: radial_displacement_along_load_m(&cold.displacement, &front_load),
        thermal_radial_displacement_m: s.front_radial_thermal_displacement_m(a0),
        front_radial_stiffness_n_per_m: s.front.stiffness_matrix[0][0],
        front_radial_stiffness_isothermal_n_per_m: cold.stiffness_matrix[0][0],
        axial_growth_m: s.axial_growth_m,
    })
}

/// Speed x preload x load grid across threads (rayon); each point is solved
/// independently, so the result does not depend on the thread count. Order:
/// speed outermost, load innermost.
pub fn spindle_grid(
    spindle: &Spindle,
    speeds_rpm: &[f64],
    preloads_n: &[f64],
    radial_loads_n: &[f64],
) -> Vec<Result<GridPoint>> {
    let mut items = Vec::with_capacity(speeds_rpm.len() * preloads_n.len() * radial_loads_n.len());
    for &n in speeds_rpm {
        for &p in preloads_n {
            for &f in radial_loads_n {
                items.push((n, p, f));
            }
        }
    }
    items
        .par_iter()
        .map(|&(n, p, f)| grid_point(spindle, n, p, f))
        .collect()
}

/// Optimal preload at one speed (seed B Figs. 15-16).
#[derive(Debug, Clone, PartialEq)]
pub struct OptimalPreload {
    /// Shaft speed \[rpm\].
    pub speed_rpm: f64,
    /// The scanned preload with the least total radial displacement \[N\]
    /// (the first one on a tie).
    pub optimal_preload_n: f64,
    /// Its total radial displacement, [`GridPoint::total_radial_displacement_m`] \[m\].
    pub min_radial_displacement_m: f64,
    /// Every scanned point at this speed.
    pub scan: Vec<GridPoint>,
}

/// Scan `preloads_n` at each speed (working radial load of the spindle)
/// and pick the preload with the least total radial displacement.
pub fn optimal_preload(spindle: &Spindle, speeds_rpm: &[f64], preloads_n: &[f64]) -> Result<Vec<OptimalPreload>> {
    if preloads_n.is_empty() {
        return Err(Error::config("preloads_n", "[]", "need at least one preload"));
    }
    let grid = spindle_grid(spindle, speeds_rpm, preloads_n, &[spindle.config.radial_load_n]);
    let mut out = Vec::with_capacity(speeds_rpm.len());
    for (i, &n) in speeds_rpm.iter().enumerate() {
        let scan = grid[i * preloads_n.len()..(i + 1) * preloads_n.len()]
            .iter()
            .cloned()
            .collect::<Result<Vec<_>>>()?;
        let best = scan
            .iter()
            .min_by(|a, b| {
                a.total_radial_displacement_m()
                    .total_cmp(&b.total_radial_displacement_m())
            })
            .copied()
            .ok_or_else(|| Error::config("preloads_n", "[]", "need at least one preload"))?;
        out.push(OptimalPreload {
            speed_rpm: n,
            optimal_preload_n: best.preload_n,
            min_radial_displacement_m: best.total_radial_displacement_m(),
            scan,
        });
    }
    Ok(out)
}
