//! Bindings for the coupled thermo-mechanical bearing model (seed A):
//! one operating point and a thermal stiffness curve (GIL released,
//! Ctrl-C between chunks).

use numpy::{IntoPyArray, PyReadonlyArray1};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::bearing::{PyBearing, PyMaterial};
use super::errors::IntoPy;
use super::oil_supply::PySupplyInput;
use super::parallel::map_interruptible;
use super::solve::{curve_columns, solve_options, state_dict, tilt_option};
use crate::bearing::BearingType;
use crate::bearing::{Bearing, BearingState};
use crate::error::{finite, Result};
use crate::thermal::coupled::{seed_a_mounting, CoupledBearing, CoupledOptions, HeatReport, ThermalState};
use crate::thermal::friction::{resolve_lubrication, HeatBreakdown, HeatModel, Lubrication, SkfSeries, SkfSettings};
use crate::thermal::oil_supply::SupplyInput;
use crate::thermal::presets::SeedAParams;
use crate::thermal::Lubricant;

/// Model settings of the coupled bearing, shared by every entry point: one
/// dict with every key, built by `thermobear.thermal.state._model_kwargs`
/// (the keyword arguments of `thermobear.thermal_state`).
#[derive(FromPyObject)]
#[pyo3(from_item_all)]
pub struct Settings {
    lubricant: String,
    lubrication_factor_f0: Option<f64>,
    spin_friction: f64,
    oil_air_temperature_c: f64,
    ambient_temperature_c: f64,
    housing_material: Option<PyMaterial>,
    raceway_control: String,
    misalignment_rad: Option<f64>,
    extra_heat_w: f64,
    housing_conductance_scale: f64,
    churning_oil_fraction: Option<f64>,
    heat_model: String,
    lubrication: Option<String>,
    skf_series: Option<String>,
    sliding_friction_ehl: Option<f64>,
    replenishment_krs: Option<f64>,
    seal_moment_n_m: f64,
    oil_supply: PySupplyInput,
}

impl Settings {
    /// Parsed heat model and SKF settings (docs/concepts/physics.md §9).
    fn heat(&self) -> Result<(HeatModel, SkfSettings)> {
        let skf = SkfSettings {
            series: self.skf_series.as_deref().map(SkfSeries::from_name).transpose()?,
            mu_ehl: self.sliding_friction_ehl,
            replenishment_krs: self.replenishment_krs,
            seal_moment_n_m: self.seal_moment_n_m,
        };
        skf.validate()?;
        Ok((HeatModel::from_name(&self.heat_model)?, skf))
    }

    fn build(self, bearing: &Bearing, effects: Option<Vec<String>>) -> Result<CoupledBearing> {
        let (heat_model, skf) = self.heat()?;
        let mut solve = solve_options(effects, &self.raceway_control)?;
        solve.tilt = tilt_option(self.misalignment_rad, 0.0)?;
        let p = seed_a_params(
            bearing,
            &self.lubricant,
            self.oil_air_temperature_c,
            self.ambient_temperature_c,
            self.housing_material,
        )?;
        let mounting = seed_a_mounting(&p);
        let (lubrication, f0, x) = resolve_lubrication(
            self.lubrication.as_deref(),
            bearing.geometry.bearing_type,
            self.lubrication_factor_f0,
            self.churning_oil_fraction,
        )?;
        let oil_supply = SupplyInput::from(self.oil_supply).resolve(
            lubrication,
            self.lubrication.is_some(),
            self.churning_oil_fraction.is_some(),
        )?;
        let options = CoupledOptions {
            heat_model,
            lubrication,
            skf,
            oil_supply,
            lubrication_factor_f0: f0,
            churning_oil_fraction: x,
            solve,
            spin_friction_coefficient: self.spin_friction,
            extra_heat_w: self.extra_heat_w,
            housing_conductance_scale: self.housing_conductance_scale,
            ..CoupledOptions::default()
        };
        CoupledBearing::new(bearing, p, mounting, options)
    }
}

/// The heat entries of a result dict (rows by mechanism, split to the
/// parts, moments, oil state), shared by the coupled and isothermal calls.
fn heat_items(py: Python<'_>, d: &Bound<'_, PyDict>, h: &HeatReport) -> PyResult<()> {
    let sources = if h.skf.is_some() {
        vec!["rolling", "sliding", "seal", "extra", "churning"]
    } else {
        vec!["load", "viscous", "inner_spin", "outer_spin", "extra", "churning"]
    };
    let heats = if h.skf.is_some() {
        vec![h.load_w, h.viscous_w, h.seal_w, h.extra_w, h.churning_w]
    } else {
        vec![
            h.load_w,
            h.viscous_w,
            h.heat.inner_spin_w,
            h.heat.outer_spin_w,
            h.extra_w,
            h.churning_w,
        ]
    };
    d.set_item("source", sources)?;
    d.set_item("heat_w", heats.into_pyarray(py))?;
    d.set_item("heat_model", if h.skf.is_some() { "skf" } else { "palmgren" })?;
    if let Some(k) = &h.skf {
        d.set_item("skf_phi_ish", k.phi_ish)?;
        d.set_item("skf_phi_rs", k.phi_rs)?;
        d.set_item("skf_mu_sliding", k.mu_sliding)?;
    }
    d.set_item("part", vec!["inner_ring", "balls", "outer_ring"])?;
    d.set_item(
        "part_heat_w",
        vec![h.split.inner_ring_w, h.split.balls_w, h.split.outer_ring_w].into_pyarray(py),
    )?;
    d.set_item("oil_temperature_c", h.oil_temperature_c)?;
    d.set_item("viscosity_cst", h.viscosity_cst)?;
    d.set_item("load_moment_n_m", h.load_moment_n_m)?;
    d.set_item("viscous_moment_n_m", h.viscous_moment_n_m)?;
    d.set_item("total_heat_w", h.heat.total_w())?;
    d.set_item("churning_w", h.churning_w)?;
    breakdown_items(d, &h.breakdown)?;
    d.set_item("cavity_oil_fraction", h.cavity_oil_fraction)?;
    d.set_item("cage_speed_rad_s", h.cage_speed_rad_s)?;
    d.set_item("oil_density_kg_m3", h.oil_density_kg_m3)?;
    Ok(())
}

/// The heat split keys (W): rolling, sliding, spin, drag, churning, seal,
/// extra (docs/concepts/physics.md §9, heat split); they sum to the total.
pub fn breakdown_items(d: &Bound<'_, PyDict>, b: &HeatBreakdown) -> PyResult<()> {
    for (k, v) in breakdown_columns(b) {
        d.set_item(k, v)?;
    }
    Ok(())
}

/// The heat split as (key, W) pairs, in the documented order.
pub fn breakdown_columns(b: &HeatBreakdown) -> [(&'static str, f64); 7] {
    [
        ("rolling_heat_w", b.rolling_w),
        ("sliding_heat_w", b.sliding_w),
        ("spin_heat_w", b.spin_w),
        ("drag_heat_w", b.drag_w),
        ("ring_cage_churning_heat_w", b.churning_w),
        ("seal_heat_w", b.seal_w),
        ("extra_heat_w", b.extra_w),
    ]
}

fn thermal_dict<'py>(py: Python<'py>, c: &CoupledBearing, s: &ThermalState) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("node", s.node_names.clone())?;
    d.set_item("temperature_c", s.temperatures_c.clone().into_pyarray(py))?;
    heat_items(py, &d, &s.heat)?;
    d.set_item(
        "boundary",
        s.boundary_flows_w.iter().map(|b| b.0.clone()).collect::<Vec<_>>(),
    )?;
    d.set_item(
        "boundary_flow_w",
        s.boundary_flows_w
            .iter()
            .map(|b| b.1)
            .collect::<Vec<_>>()
            .into_pyarray(py),
    )?;
    let u = &s.offsets;
    let def = PyDict::new(py);
    let um = 1e6;
    def.set_item("radial_thermal_offset_um", s.raceway_offsets.radial_m * um)?;
    def.set_item("axial_thermal_offset_um", s.raceway_offsets.axial_m * um)?;
    def.set_item("groove_centre_radial_um", u.radial_m * um)?;
    def.set_item("groove_centre_axial_um", u.axial_m * um)?;
    def.set_item("ball_growth_um", u.ball_diameter_growth_m * um)?;
    def.set_item("free_gap_change_um", u.free_gap_change_m * um)?;
    def.set_item("inner_groove_centre_um", u.inner_groove_centre_radial_m * um)?;
    def.set_item("outer_groove_centre_um", u.outer_groove_centre_radial_m * um)?;
    def.set_item("shaft_surface_um", u.shaft_surface_radial_m * um)?;
    def.set_item("housing_bore_um", u.housing_bore_radial_m * um)?;
    let omega = crate::units::rpm_to_rad_s(s.speed_rpm);
    def.set_item("centrifugal_expansion_um", c.model().ring_expansion_m(omega) * um)?;
    def.set_item(
        "radial_displacement_um",
        s.bearing.displacement[0].hypot(s.bearing.displacement[1]) * um,
    )?;
    def.set_item("axial_displacement_um", s.bearing.displacement[2] * um)?;
    d.set_item("deformations", def)?;
    d.set_item("solution", state_dict(py, &s.bearing)?)?;
    d.set_item("iterations", s.iterations)?;
    d.set_item("residual_k", s.residual_k)?;
    d.set_item("offset_change_m", s.offset_change_m)?;
    Ok(d)
}

/// Coupled thermal steady state of one bearing in the seed A network.
#[pyfunction]
#[pyo3(signature = (bearing, speed_rpm, axial_n, radial_n, effects, settings))]
#[allow(clippy::too_many_arguments)]
pub fn thermal_state<'py>(
    py: Python<'py>,
    bearing: &PyBearing,
    speed_rpm: f64,
    axial_n: f64,
    radial_n: f64,
    effects: Option<Vec<String>>,
    settings: Settings,
) -> PyResult<Bound<'py, PyDict>> {
    let b = &bearing.inner;
    let (c, s) = py
        .detach(|| -> Result<(CoupledBearing, ThermalState)> {
            let c = settings.build(b, effects)?;
            let s = c.solve(speed_rpm, axial_n, radial_n)?;
            Ok((c, s))
        })
        .py_err()?;
    thermal_dict(py, &c, &s)
}

/// Heat of one bearing with the oil held at `oil_temperature_c` and no
/// thermal deformation (the friction model alone, no network).
#[pyfunction]
#[pyo3(signature = (bearing, speed_rpm, axial_n, radial_n, oil_temperature_c, effects, settings))]
#[allow(clippy::too_many_arguments)]
pub fn isothermal_heat<'py>(
    py: Python<'py>,
    bearing: &PyBearing,
    speed_rpm: f64,
    axial_n: f64,
    radial_n: f64,
    oil_temperature_c: f64,
    effects: Option<Vec<String>>,
    settings: Settings,
) -> PyResult<Bound<'py, PyDict>> {
    let b = &bearing.inner;
    let (state, h) = py
        .detach(|| -> Result<(BearingState, HeatReport)> {
            let c = settings.build(b, effects)?;
            c.isothermal_heat(speed_rpm, axial_n, radial_n, oil_temperature_c)
        })
        .py_err()?;
    let d = PyDict::new(py);
    heat_items(py, &d, &h)?;
    d.set_item("speed_rpm", speed_rpm)?;
    d.set_item("solution", state_dict(py, &state)?)?;
    Ok(d)
}

/// Thermal stiffness curve: the coupled state at every speed, in parallel.
#[pyfunction]
#[pyo3(signature = (bearing, speeds_rpm, axial_n, radial_n, effects, settings, progress=None))]
#[allow(clippy::too_many_arguments)]
pub fn thermal_stiffness_curve<'py>(
    py: Python<'py>,
    bearing: &PyBearing,
    speeds_rpm: PyReadonlyArray1<'py, f64>,
    axial_n: f64,
    radial_n: f64,
    effects: Option<Vec<String>>,
    settings: Settings,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let speeds = speeds_rpm.as_slice()?.to_vec();
    let c = settings.build(&bearing.inner, effects).py_err()?;
    let results = map_interruptible(py, &speeds, None, progress.as_ref(), |&n| c.solve(n, axial_n, radial_n))?;
    let (states, finished, failed) = super::errors::split_results(results);
    let bearings: Vec<BearingState> = states.iter().map(|s| s.bearing.clone()).collect();
    let d = curve_columns(py, &bearings)?;
    let col = |f: &dyn Fn(&ThermalState) -> f64| -> Vec<f64> { states.iter().map(f).collect() };
    for (key, name) in [
        ("shaft_temperature_c", "Ts"),
        ("inner_ring_temperature_c", "Ti"),
        ("ball_temperature_c", "Tb"),
        ("outer_ring_temperature_c", "To"),
        ("housing_temperature_c", "Th"),
    ] {
        let t: Vec<f64> = states
            .iter()
            .map(|s| s.temperature_c(name))
            .collect::<Result<_>>()
            .py_err()?;
        d.set_item(key, t.into_pyarray(py))?;
    }
    d.set_item("heat_w", col(&|s| s.heat.heat.total_w()).into_pyarray(py))?;
    d.set_item("load_heat_w", col(&|s| s.heat.load_w).into_pyarray(py))?;
    d.set_item("viscous_heat_w", col(&|s| s.heat.viscous_w).into_pyarray(py))?;
    d.set_item("churning_w", col(&|s| s.heat.churning_w).into_pyarray(py))?;
    for (j, (key, _)) in breakdown_columns(&HeatBreakdown::default()).iter().enumerate() {
        let v = col(&|s| breakdown_columns(&s.heat.breakdown)[j].1);
        d.set_item(*key, v.into_pyarray(py))?;
    }
    d.set_item(
        "cavity_oil_fraction",
        col(&|s| s.heat.cavity_oil_fraction).into_pyarray(py),
    )?;
    d.set_item(
        "radial_thermal_offset_um",
        col(&|s| s.raceway_offsets.radial_m * 1e6).into_pyarray(py),
    )?;
    d.set_item(
        "axial_thermal_offset_um",
        col(&|s| s.raceway_offsets.axial_m * 1e6).into_pyarray(py),
    )?;
    d.set_item(
        "ball_growth_um",
        col(&|s| s.offsets.ball_diameter_growth_m * 1e6).into_pyarray(py),
    )?;
    d.set_item(
        "centrifugal_expansion_um",
        col(&|s| c.model().ring_expansion_m(crate::units::rpm_to_rad_s(s.speed_rpm)) * 1e6).into_pyarray(py),
    )?;
    d.set_item("thermal_iterations", col(&|s| s.iterations as f64).into_pyarray(py))?;
    super::errors::finish_sweep(py, &speeds, d, finished, &failed)
}

/// Coupled thermal states of many operating points (arrays of one length:
/// speed, axial and radial load) under one set of model settings, one row per
/// point with its error if it failed (see `batch.rs`).
#[pyfunction]
#[pyo3(signature = (bearing, speed_rpm, axial_n, radial_n, effects, settings, threads=None, progress=None))]
#[allow(clippy::too_many_arguments)]
pub fn thermal_state_many<'py>(
    py: Python<'py>,
    bearing: &PyBearing,
    speed_rpm: PyReadonlyArray1<'py, f64>,
    axial_n: PyReadonlyArray1<'py, f64>,
    radial_n: PyReadonlyArray1<'py, f64>,
    effects: Option<Vec<String>>,
    settings: Settings,
    threads: Option<usize>,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let c = settings.build(&bearing.inner, effects).py_err()?;
    super::batch::thermal_many(py, &c, [&speed_rpm, &axial_n, &radial_n], threads, progress.as_ref())
}

fn seed_a_params(
    bearing: &Bearing,
    lubricant: &str,
    oil_air_temperature_c: f64,
    ambient_temperature_c: f64,
    housing_material: Option<PyMaterial>,
) -> Result<SeedAParams> {
    let mut p = SeedAParams::for_bearing(bearing);
    p.lubricant = Lubricant::preset(lubricant)?;
    p.oil_air_temperature_c = finite("oil_air_temperature_c", oil_air_temperature_c)?;
    p.ambient_temperature_c = finite("ambient_temperature_c", ambient_temperature_c)?;
    if let Some(m) = housing_material {
        p.housing = m.inner;
    }
    Ok(p)
}

/// The seed A network of `bearing` with the Python-side settings.
fn seed_a_net(
    bearing: &Bearing,
    lubricant: &str,
    oil_air_temperature_c: f64,
    ambient_temperature_c: f64,
    housing_material: Option<PyMaterial>,
) -> Result<crate::thermal::presets::BearingNetwork> {
    let p = seed_a_params(
        bearing,
        lubricant,
        oil_air_temperature_c,
        ambient_temperature_c,
        housing_material,
    )?;
    crate::thermal::presets::seed_a_network(bearing, &p)
}

/// The seed A network at `speed_rpm` as plain numbers (for independent
/// solvers): node names, fixed temperatures (boundaries) and per link
/// `(name, a, b, conductance_w_per_k, natural_w_per_k125)`, the flow a -> b
/// being `G dT + N |dT|^0.25 dT`.
#[pyfunction]
#[pyo3(signature = (bearing, speed_rpm, lubricant="e-drive ATF".to_string(), oil_air_temperature_c=28.0, ambient_temperature_c=26.0, housing_material=None))]
pub fn seed_a_network_links<'py>(
    py: Python<'py>,
    bearing: &PyBearing,
    speed_rpm: f64,
    lubricant: String,
    oil_air_temperature_c: f64,
    ambient_temperature_c: f64,
    housing_material: Option<PyMaterial>,
) -> PyResult<Bound<'py, PyDict>> {
    use crate::thermal::network::{Convection, LinkKind, NodeKind};
    let net = seed_a_net(
        &bearing.inner,
        &lubricant,
        oil_air_temperature_c,
        ambient_temperature_c,
        housing_material,
    )
    .py_err()?;
    let w = crate::units::rpm_to_rad_s(crate::error::non_negative("speed_rpm", speed_rpm).py_err()?);
    let d = PyDict::new(py);
    let nodes = net.network.nodes();
    d.set_item("node", nodes.iter().map(|n| n.name.clone()).collect::<Vec<_>>())?;
    let fixed = PyDict::new(py);
    for n in nodes {
        if let NodeKind::Boundary { temperature_c } = n.kind {
            fixed.set_item(n.name.clone(), temperature_c)?;
        }
    }
    d.set_item("boundary_temperature_c", fixed)?;
    let links: Vec<(String, usize, usize, f64, f64)> = net
        .network
        .links()
        .iter()
        .map(|l| match &l.kind {
            LinkKind::Conduction { conductance_w_per_k } => (l.name.clone(), l.a, l.b, *conductance_w_per_k, 0.0),
            LinkKind::Convection { area_m2, law } => match law {
                Convection::Natural { coefficient_w_m2_k125 } => {
                    (l.name.clone(), l.a, l.b, 0.0, coefficient_w_m2_k125 * area_m2)
                }
                other => (l.name.clone(), l.a, l.b, other.h_w_m2k(0.0, w) * area_m2, 0.0),
            },
        })
        .collect();
    d.set_item("links", links)?;
    Ok(d)
}

/// Steady temperatures of the seed A network (Newton) for the heat on the
/// inner raceway, balls and outer raceway nodes [W] at `speed_rpm`.
#[pyfunction]
#[pyo3(signature = (bearing, speed_rpm, inner_ring_w, balls_w, outer_ring_w, lubricant="e-drive ATF".to_string(), oil_air_temperature_c=28.0, ambient_temperature_c=26.0, housing_material=None))]
#[allow(clippy::too_many_arguments)]
pub fn seed_a_steady_temperatures<'py>(
    py: Python<'py>,
    bearing: &PyBearing,
    speed_rpm: f64,
    inner_ring_w: f64,
    balls_w: f64,
    outer_ring_w: f64,
    lubricant: String,
    oil_air_temperature_c: f64,
    ambient_temperature_c: f64,
    housing_material: Option<PyMaterial>,
) -> PyResult<Bound<'py, PyDict>> {
    // Built once: solved below and its node names returned with the result.
    let net = seed_a_net(
        &bearing.inner,
        &lubricant,
        oil_air_temperature_c,
        ambient_temperature_c,
        housing_material,
    )
    .py_err()?;
    let t = py
        .detach(|| -> Result<Vec<f64>> {
            let split = crate::thermal::HeatSplit {
                inner_ring_w: finite("inner_ring_w", inner_ring_w)?,
                balls_w: finite("balls_w", balls_w)?,
                outer_ring_w: finite("outer_ring_w", outer_ring_w)?,
            };
            let w = crate::units::rpm_to_rad_s(crate::error::non_negative("speed_rpm", speed_rpm)?);
            let mut solver = crate::thermal::SteadySolver::new(net.network.clone());
            Ok(solver.solve(&net.sources_w(&split), w)?.temperatures_c)
        })
        .py_err()?;
    let d = PyDict::new(py);
    d.set_item("node", net.network.names().iter().cloned().collect::<Vec<_>>())?;
    d.set_item("temperature_c", t.into_pyarray(py))?;
    Ok(d)
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(seed_a_network_links, m)?)?;
    m.add_function(wrap_pyfunction!(seed_a_steady_temperatures, m)?)?;
    m.add_function(wrap_pyfunction!(thermal_state, m)?)?;
    m.add_function(wrap_pyfunction!(isothermal_heat, m)?)?;
    m.add_function(wrap_pyfunction!(thermal_stiffness_curve, m)?)?;
    m.add_function(wrap_pyfunction!(thermal_state_many, m)?)?;
    m.add_function(wrap_pyfunction!(lubrication_defaults, m)?)?;
    m.add_function(wrap_pyfunction!(skf_sliding_friction_ehl, m)?)?;
    Ok(())
}

/// Defaults a lubrication method sets for a bearing type
/// (docs/concepts/physics.md §9): f0 and its bounds, the drag oil fraction
/// X and its bounds, the SKF K_rs.
#[pyfunction]
pub fn lubrication_defaults<'py>(
    py: Python<'py>,
    lubrication: &str,
    bearing_type: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let l = Lubrication::from_name(lubrication).py_err()?;
    let t = match bearing_type {
        "deep_groove" | "deep-groove" => BearingType::DeepGroove,
        "angular_contact" | "angular-contact" => BearingType::AngularContact,
        _ => {
            return Err(crate::error::Error::config(
                "bearing_type",
                bearing_type,
                "deep_groove or angular_contact",
            ))
            .py_err()
        }
    };
    let x = l.defaults(t);
    let d = PyDict::new(py);
    d.set_item("lubrication", l.name())?;
    d.set_item("lubrication_factor_f0", x.lubrication_factor_f0)?;
    d.set_item("f0_bounds", x.f0_bounds)?;
    d.set_item("oil_volume_fraction", x.oil_volume_fraction)?;
    d.set_item("oil_fraction_bounds", x.oil_fraction_bounds)?;
    d.set_item("replenishment_krs", x.replenishment_krs)?;
    Ok(d)
}

/// The SKF full-film sliding coefficient mu_EHL the heat model takes for a
/// lubricant when none is given (docs/concepts/physics.md §9).
#[pyfunction]
pub fn skf_sliding_friction_ehl(lubricant: &str) -> f64 {
    crate::thermal::friction::skf_mu_ehl_for_lubricant(lubricant)
}
