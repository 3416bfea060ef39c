//! Bindings for the motorized spindle (seed B): coupled steady state,
//! transient, speed x preload x load grids and the compensation preload.
//! Sweeps run through `map_interruptible` (GIL released, Ctrl-C, progress).

use numpy::{IntoPyArray, PyArray2};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::errors::IntoPy;
use super::parallel::{map_interruptible, watched};
use crate::effects::EffectSet;
use crate::error::{finite, non_negative, positive, Error, Result};
use crate::spindle::{
    compensation_preload, grid_point, CompensationPoint, GridPoint, PairState, Preload, Spindle, SpindleConfig,
    SpindleState,
};
use crate::thermal::network::LinkKind;

/// A motorized spindle (native).
#[pyclass(name = "Spindle", module = "thermobear._native", frozen)]
#[derive(Clone)]
pub struct PySpindle {
    pub inner: Spindle,
    pub name: String,
}

fn preload_of(kind: &str, force_n: f64, rate_n_per_um: f64) -> Result<Preload> {
    match kind {
        "rigid" => Ok(Preload::Rigid { force_n }),
        "spring" => Ok(Preload::Spring {
            force_n,
            rate_n_per_m: non_negative("spring_rate_n_per_um", rate_n_per_um)? * 1e6,
        }),
        other => Err(Error::config("preload_kind", other, "must be \"rigid\" or \"spring\"")),
    }
}

fn pair_dict<'py>(py: Python<'py>, p: &PairState) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("displacement", p.displacement.to_vec().into_pyarray(py))?;
    d.set_item("axial_force_n", p.axial_force_n.to_vec())?;
    d.set_item("preload_n", p.preload_n)?;
    d.set_item("spring_compression_m", p.spring_compression_m)?;
    let k: Vec<Vec<f64>> = p.stiffness_matrix.iter().map(|r| r.to_vec()).collect();
    d.set_item("stiffness_matrix", PyArray2::from_vec2(py, &k)?)?;
    let b = &p.bearings[0].balls;
    let col = |f: &dyn Fn(&crate::bearing::BallState) -> f64| -> Vec<f64> { b.iter().map(f).collect() };
    d.set_item(
        "inner_contact_angle_deg",
        col(&|x| x.inner_contact_angle_rad.to_degrees()),
    )?;
    d.set_item(
        "outer_contact_angle_deg",
        col(&|x| x.outer_contact_angle_rad.to_degrees()),
    )?;
    d.set_item("inner_load_n", col(&|x| x.inner_load_n))?;
    d.set_item("outer_load_n", col(&|x| x.outer_load_n))?;
    // Radial load [Fx, Fy] the pair carries: the sum over its two bearings
    // (both frames share x and y, spindle/pair.rs).
    let (la, lb) = (&p.bearings[0].applied_load, &p.bearings[1].applied_load);
    d.set_item("radial_load_n", vec![la[0] + lb[0], la[1] + lb[1]])?;
    Ok(d)
}

fn state_dict<'py>(py: Python<'py>, sp: &Spindle, s: &SpindleState) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("speed_rpm", s.speed_rpm)?;
    d.set_item("node_names", s.temperatures.names.to_vec())?;
    d.set_item("temperatures_c", s.temperatures.temperatures_c.clone())?;
    d.set_item("front", pair_dict(py, &s.front)?)?;
    d.set_item("rear", pair_dict(py, &s.rear)?)?;
    let heat: Vec<f64> = s.bearing_heat.iter().map(|h| h.heat.total_w()).collect();
    d.set_item("bearing_heat_w", heat)?;
    // The heat split per bearing (rolling, sliding, spin, drag, churning,
    // seal, extra), [front A, front B, rear A, rear B].
    let zero = crate::thermal::friction::HeatBreakdown::default();
    for (j, (key, _)) in super::thermal::breakdown_columns(&zero).iter().enumerate() {
        let v: Vec<f64> = s
            .bearing_heat
            .iter()
            .map(|h| super::thermal::breakdown_columns(&h.breakdown)[j].1)
            .collect();
        d.set_item(*key, v)?;
    }
    let x: Vec<f64> = s.bearing_heat.iter().map(|h| h.cavity_oil_fraction).collect();
    d.set_item("cavity_oil_fraction", x)?;
    d.set_item("motor_losses_w", s.motor_losses_w)?;
    d.set_item("magnetic_pull_n", sp.magnetic_pull_n())?;
    d.set_item("total_heat_w", s.total_heat_w)?;
    d.set_item("boundary_flow_w", s.boundary_flow_w)?;
    d.set_item("axial_growth_m", s.axial_growth_m)?;
    let a0 = sp.config.params.front_bearing.geometry.free_contact_angle_rad;
    d.set_item(
        "front_radial_thermal_displacement_m",
        s.front_radial_thermal_displacement_m(a0),
    )?;
    d.set_item("front_ball_growth_m", s.front_offsets.ball_diameter_growth_m)?;
    d.set_item("rear_ball_growth_m", s.rear_offsets.ball_diameter_growth_m)?;
    // Outward growth of the inner and outer groove curvature centres of each
    // row, [u_ic, u_oc] in m (seed B Fig. 8a: inner ring, outer ring, ball).
    for (key, o) in [
        ("front_groove_centres_m", &s.front_offsets),
        ("rear_groove_centres_m", &s.rear_offsets),
    ] {
        d.set_item(
            key,
            vec![o.inner_groove_centre_radial_m, o.outer_groove_centre_radial_m],
        )?;
    }
    // The groove-centre offsets the coupled solve applied to each row,
    // [radial, axial] in m: the seam to the rotor model (thermobear.rotor).
    let rear_a0 = sp.config.params.rear_bearing.geometry.free_contact_angle_rad;
    d.set_item(
        "front_raceway_offsets_m",
        vec![
            s.front_offsets.radial_with_gap_m(a0),
            s.front_offsets.axial_with_gap_m(a0),
        ],
    )?;
    d.set_item(
        "rear_raceway_offsets_m",
        vec![
            s.rear_offsets.radial_with_gap_m(rear_a0),
            s.rear_offsets.axial_with_gap_m(rear_a0),
        ],
    )?;
    d.set_item("iterations", s.iterations)?;
    d.set_item("temperature_change_k", s.temperature_change_k)?;
    Ok(d)
}

#[pymethods]
impl PySpindle {
    /// A preset spindle by name (see `preset_names`).
    #[staticmethod]
    fn preset(name: &str) -> PyResult<Self> {
        let inner = Spindle::preset(name).py_err()?;
        Ok(PySpindle {
            inner,
            name: name.to_ascii_lowercase(),
        })
    }

    #[staticmethod]
    fn preset_names() -> Vec<&'static str> {
        Spindle::preset_names()
    }

    /// A spindle from a full configuration: `config_json` as `config_json`
    /// returns it (every field checked, by name), with the bearings of the
    /// front and rear pairs replaced when given, the lubricant by preset
    /// name when given, and the heat-model settings `heat` applied last (as
    /// `with_options`).
    #[staticmethod]
    #[pyo3(signature = (config_json, name, front_bearing=None, rear_bearing=None, lubricant=None, heat=None))]
    fn from_config(
        py: Python<'_>,
        config_json: &str,
        name: &str,
        front_bearing: Option<PyRef<'_, super::bearing::PyBearing>>,
        rear_bearing: Option<PyRef<'_, super::bearing::PyBearing>>,
        lubricant: Option<&str>,
        heat: Option<SpindleHeatArgs>,
    ) -> PyResult<Self> {
        let mut cfg = SpindleConfig::from_json(config_json).py_err()?;
        if let Some(b) = front_bearing {
            cfg.params.front_bearing = b.inner.clone();
        }
        if let Some(b) = rear_bearing {
            cfg.params.rear_bearing = b.inner.clone();
        }
        if let Some(l) = lubricant {
            cfg.params.lubricant = crate::thermal::lubricant::Lubricant::preset(l).py_err()?;
        }
        if let Some(h) = heat {
            h.apply(&mut cfg).py_err()?;
        }
        let inner = py.detach(|| Spindle::new(cfg)).py_err()?;
        Ok(PySpindle {
            inner,
            name: name.to_string(),
        })
    }

    /// The full configuration as JSON (floats round-trip exactly).
    fn config_json(&self) -> PyResult<String> {
        self.inner.config.to_json().py_err()
    }

    /// A copy with other settings (None keeps the current value).
    #[pyo3(signature = (preload_n=None, preload_kind=None, spring_rate_n_per_um=None, radial_load_n=None, effects=None, spin_friction=None, heat=None))]
    #[allow(clippy::too_many_arguments)]
    fn with_options(
        &self,
        py: Python<'_>,
        preload_n: Option<f64>,
        preload_kind: Option<String>,
        spring_rate_n_per_um: Option<f64>,
        radial_load_n: Option<f64>,
        effects: Option<Vec<String>>,
        spin_friction: Option<f64>,
        heat: Option<SpindleHeatArgs>,
    ) -> PyResult<Self> {
        let c = &self.inner.config;
        let (kind0, rate0) = match c.preload {
            Preload::Rigid { .. } => ("rigid", crate::spindle::SEED_B_SPRING_RATE_N_PER_M * 1e-6),
            Preload::Spring { rate_n_per_m, .. } => ("spring", rate_n_per_m * 1e-6),
        };
        let kind = preload_kind.unwrap_or_else(|| kind0.to_string());
        let force = preload_n.unwrap_or(c.preload.force_n());
        let mut preload = preload_of(&kind, force, spring_rate_n_per_um.unwrap_or(rate0)).py_err()?;
        // No new rate given: keep the stored one to the last bit (the
        // N/um round trip above is not exact).
        if let (Preload::Spring { rate_n_per_m, .. }, Preload::Spring { rate_n_per_m: r0, .. }, None) =
            (&mut preload, &c.preload, spring_rate_n_per_um)
        {
            *rate_n_per_m = *r0;
        }
        let mut cfg: SpindleConfig = c.clone();
        cfg.preload = preload;
        if let Some(f) = radial_load_n {
            cfg.radial_load_n = finite("radial_load_n", f).py_err()?;
        }
        if let Some(names) = effects {
            cfg.effects = EffectSet::from_names(&names).py_err()?;
        }
        if let Some(mu) = spin_friction {
            cfg.spin_friction_coefficient = non_negative("spin_friction_coefficient", mu).py_err()?;
        }
        if let Some(h) = heat {
            h.apply(&mut cfg).py_err()?;
        }
        let inner = py.detach(|| Spindle::new(cfg)).py_err()?;
        Ok(PySpindle {
            inner,
            name: self.name.clone(),
        })
    }

    /// Pickle support: the versioned serde envelope (see `_restore`).
    fn __reduce__(&self, py: Python<'_>) -> PyResult<super::persist::Reduced> {
        super::persist::reduce_spindle(py, self)
    }

    #[getter]
    fn name(&self) -> &str {
        &self.name
    }

    #[getter]
    fn preload_n(&self) -> f64 {
        self.inner.config.preload.force_n()
    }

    #[getter]
    fn preload_kind(&self) -> &'static str {
        match self.inner.config.preload {
            Preload::Rigid { .. } => "rigid",
            Preload::Spring { .. } => "spring",
        }
    }

    /// Spring rate [N/um] (None for a rigid preload).
    #[getter]
    fn spring_rate_n_per_um(&self) -> Option<f64> {
        match self.inner.config.preload {
            Preload::Rigid { .. } => None,
            Preload::Spring { rate_n_per_m, .. } => Some(rate_n_per_m * 1e-6),
        }
    }

    #[getter]
    fn radial_load_n(&self) -> f64 {
        self.inner.config.radial_load_n
    }

    #[getter]
    fn node_names(&self) -> Vec<String> {
        self.inner.network.network.names().to_vec()
    }

    #[getter]
    fn effects(&self) -> Vec<&'static str> {
        self.inner.config.effects.names()
    }

    /// The assumed data (numbers in SI or as named; strings for choices).
    fn assumptions<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let c = &self.inner.config;
        let p = &c.params;
        let d = PyDict::new(py);
        d.set_item("front_bearing", p.front_bearing.name.clone())?;
        d.set_item("rear_bearing", p.rear_bearing.name.clone())?;
        d.set_item("ball_material", p.front_bearing.ball.name.clone())?;
        d.set_item("pair_arrangement", "back-to-back, adjacent (spacing = bearing width)")?;
        d.set_item("front_span_mm", p.front_span_m * 1e3)?;
        d.set_item("rear_span_mm", p.rear_span_m * 1e3)?;
        d.set_item("nose_length_mm", p.nose_length_m * 1e3)?;
        d.set_item("rotor_diameter_mm", p.rotor_diameter_m * 1e3)?;
        d.set_item("rotor_length_mm", p.rotor_length_m * 1e3)?;
        d.set_item("sleeve_outer_diameter_mm", p.sleeve_outer_diameter_m * 1e3)?;
        d.set_item("water_flow_l_min", p.water_flow_l_min)?;
        d.set_item("water_temperature_c", p.water_temperature_c)?;
        d.set_item("ambient_temperature_c", p.ambient_temperature_c)?;
        d.set_item("oil_air_temperature_c", p.oil_air_temperature_c)?;
        d.set_item("assembly_temperature_c", c.assembly_temperature_c)?;
        d.set_item("lubricant", p.lubricant.name.clone())?;
        d.set_item("lubrication_factor_f0", p.lubrication_factor_f0)?;
        d.set_item("spin_friction", c.spin_friction_coefficient)?;
        d.set_item("load_friction_scale", c.load_friction_scale)?;
        d.set_item("extra_heat_w", c.extra_heat_w)?;
        d.set_item("unknown_heat_linear_w", c.unknown_heat_linear_w)?;
        d.set_item("unknown_heat_quadratic_w", c.unknown_heat_quadratic_w)?;
        d.set_item("unknown_heat_reference_rpm", c.unknown_heat_reference_rpm)?;
        d.set_item("heat_model", c.heat_model.name())?;
        d.set_item("lubrication", c.lubrication.name())?;
        d.set_item("churning_oil_fraction", c.churning_oil_fraction)?;
        if let Some(s) = &c.oil_supply {
            // the supply keywords that give this supply back (the drag
            // follows them, not churning_oil_fraction)
            let k = s.input();
            let numbers = [
                ("oil_flow_cm3_per_min", k.oil_flow_cm3_per_min),
                ("jet_velocity_m_per_s", k.jet_velocity_m_per_s),
                ("oil_volume_cm3_per_h", k.oil_volume_cm3_per_h),
                ("air_flow_l_per_min", k.air_flow_l_per_min),
                ("oil_level_mm", k.oil_level_mm),
                ("grease_fill_fraction", k.grease_fill_fraction),
                ("oil_flow_scale", k.oil_flow_scale),
                ("cavity_fraction_speed_exponent", k.cavity_fraction_speed_exponent),
            ];
            for (name, v) in numbers.into_iter().filter_map(|(n, v)| v.map(|v| (n, v))) {
                d.set_item(name, v)?;
            }
            if let Some(j) = k.jet_count {
                d.set_item("jet_count", j)?;
            }
        }
        d.set_item(
            "motor_losses_at_reference_w",
            p.stator_copper_w + p.stator_iron_w + p.rotor_copper_w + p.rotor_mechanical_w,
        )?;
        d.set_item("loss_reference_rpm", p.loss_reference_rpm)?;
        d.set_item("preload_kind", self.preload_kind())?;
        d.set_item("preload_n", c.preload.force_n())?;
        d.set_item("spring_rate_n_per_um", self.spring_rate_n_per_um())?;
        d.set_item("radial_load_at_nose_n", c.radial_load_n)?;
        d.set_item(
            "fits",
            "inner ring tight on the shaft, outer ring loose in a steel housing",
        )?;
        d.set_item(
            "rigid_preload",
            "fixed interference per pair; the rear set floats, the growth between the sets loads nothing",
        )?;
        d.set_item(
            "spring_preload",
            "one spring pack in the load path of all bearings; the axial growth between the sets compresses it",
        )?;
        if let Some(m) = &c.magnetic_pull {
            d.set_item("magnetic_pull_static_n", m.static_force_n())?;
            d.set_item("magnetic_pull_core_from_front_pair_mm", m.core_from_front_pair_m * 1e3)?;
            d.set_item("magnetic_pull_flux_density_t", m.pull.flux_density_t)?;
            d.set_item(
                "magnetic_pull_static_eccentricity_um",
                m.pull.static_eccentricity_m * 1e6,
            )?;
            d.set_item(
                "magnetic_pull_direction",
                "+y, perpendicular to the nose load (+x); acts with the unbalanced_magnetic_pull effect on",
            )?;
        }
        Ok(d)
    }

    /// Coupled steady state at one speed (GIL released).
    fn steady_state<'py>(&self, py: Python<'py>, speed_rpm: f64) -> PyResult<Bound<'py, PyDict>> {
        let s = py.detach(|| self.inner.thermal_state(speed_rpm)).py_err()?;
        state_dict(py, &self.inner, &s)
    }

    /// Film coefficient h [W/(m^2 K)] of every convection link of the
    /// thermal network at each speed: link names and an array (rows: speeds).
    /// The temperature difference across a link is taken from `temperatures_c`
    /// (one row of node temperatures per speed, node order) when given, else
    /// `temperature_difference_k` (only natural convection depends on it).
    #[pyo3(signature = (speeds_rpm, temperature_difference_k=10.0, temperatures_c=None))]
    fn convection_coefficients<'py>(
        &self,
        py: Python<'py>,
        speeds_rpm: Vec<f64>,
        temperature_difference_k: f64,
        temperatures_c: Option<Vec<Vec<f64>>>,
    ) -> PyResult<(Vec<String>, Bound<'py, PyArray2<f64>>)> {
        non_negative("temperature_difference_k", temperature_difference_k).py_err()?;
        let net = &self.inner.network.network;
        let n_nodes = net.nodes().len();
        if let Some(t) = &temperatures_c {
            if t.len() != speeds_rpm.len() || t.iter().any(|r| r.len() != n_nodes) {
                return Err(Error::config(
                    "temperatures_c",
                    format!("{} rows", t.len()),
                    "needs one row of node temperatures per speed",
                ))
                .py_err();
            }
        }
        let links: Vec<_> = net
            .links()
            .iter()
            .filter_map(|l| match &l.kind {
                LinkKind::Convection { law, .. } => Some((l, law)),
                LinkKind::Conduction { .. } => None,
            })
            .collect();
        let mut rows = Vec::with_capacity(speeds_rpm.len());
        for (i, &n) in speeds_rpm.iter().enumerate() {
            finite("speeds_rpm", n).py_err()?;
            let w = crate::units::rpm_to_rad_s(n);
            rows.push(
                links
                    .iter()
                    .map(|(l, law)| {
                        let dt = temperatures_c
                            .as_ref()
                            .map_or(temperature_difference_k, |t| t[i][l.a] - t[i][l.b]);
                        law.h_w_m2k(dt, w)
                    })
                    .collect::<Vec<f64>>(),
            );
        }
        let names = links.iter().map(|(l, _)| l.name.clone()).collect();
        Ok((names, PyArray2::from_vec2(py, &rows)?))
    }

    /// Bearing pairs at speed without thermal effects (front, rear).
    fn isothermal<'py>(&self, py: Python<'py>, speed_rpm: f64) -> PyResult<(Bound<'py, PyDict>, Bound<'py, PyDict>)> {
        let (f, r) = py.detach(|| self.inner.isothermal(speed_rpm)).py_err()?;
        Ok((pair_dict(py, &f)?, pair_dict(py, &r)?))
    }

    /// Transient from uniform `initial_c` (default ambient): times [s],
    /// node names and temperatures (rows: times) [C] (GIL released; Ctrl-C
    /// or `progress(steps_done, steps)` returning False stops it within a
    /// step; at most `crate::cancel::MAX_TIME_STEPS` steps).
    #[pyo3(signature = (speed_rpm, duration_s, dt_s=5.0, record_every=1, initial_c=None, mechanics_update_k=0.05, progress=None))]
    #[allow(clippy::too_many_arguments)]
    fn transient<'py>(
        &self,
        py: Python<'py>,
        speed_rpm: f64,
        duration_s: f64,
        dt_s: f64,
        record_every: usize,
        initial_c: Option<f64>,
        mechanics_update_k: f64,
        progress: Option<Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        non_negative("mechanics_update_k", mechanics_update_k).py_err()?;
        positive("duration_s", duration_s).py_err()?;
        positive("dt_s", dt_s).py_err()?;
        let steps = crate::cancel::step_count(duration_s, dt_s, "dt_s", f64::ceil).py_err()?;
        let run = watched(py, steps, progress.as_ref(), |_, _| {
            self.inner
                .transient(speed_rpm, duration_s, dt_s, record_every, initial_c, mechanics_update_k)
        })?
        .py_err()?;
        let d = PyDict::new(py);
        d.set_item("time_s", run.times_s.clone().into_pyarray(py))?;
        d.set_item("node_names", run.names.to_vec())?;
        d.set_item("temperatures_c", PyArray2::from_vec2(py, &run.temperatures_c)?)?;
        Ok(d)
    }

    /// Speed x preload x load grid (speed outermost), columns as arrays.
    #[pyo3(signature = (speeds_rpm, preloads_n, radial_loads_n, progress=None))]
    fn grid<'py>(
        &self,
        py: Python<'py>,
        speeds_rpm: Vec<f64>,
        preloads_n: Vec<f64>,
        radial_loads_n: Vec<f64>,
        progress: Option<Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let mut items = Vec::new();
        for &n in &speeds_rpm {
            positive("speeds_rpm", n).py_err()?;
            for &p in &preloads_n {
                positive("preloads_n", p).py_err()?;
                for &f in &radial_loads_n {
                    finite("radial_loads_n", f).py_err()?;
                    items.push((n, p, f));
                }
            }
        }
        let sp = &self.inner;
        let res = map_interruptible(py, &items, None, progress.as_ref(), |&(n, p, f)| {
            grid_point(sp, n, p, f)
        })?;
        let pts: Vec<GridPoint> = res.into_iter().collect::<Result<_>>().py_err()?;
        let d = PyDict::new(py);
        let col = |f: &dyn Fn(&GridPoint) -> f64| -> Vec<f64> { pts.iter().map(f).collect() };
        d.set_item("speed_rpm", col(&|g| g.speed_rpm))?;
        d.set_item("preload_n", col(&|g| g.preload_n))?;
        d.set_item("radial_load_n", col(&|g| g.radial_load_n))?;
        d.set_item("front_balls_c", col(&|g| g.front_balls_c))?;
        d.set_item("front_inner_c", col(&|g| g.front_inner_c))?;
        d.set_item("front_outer_c", col(&|g| g.front_outer_c))?;
        d.set_item("operating_preload_n", col(&|g| g.operating_preload_n))?;
        d.set_item("bearing_heat_w", col(&|g| g.bearing_heat_w))?;
        d.set_item(
            "mechanical_radial_displacement_um",
            col(&|g| g.mechanical_radial_displacement_m * 1e6),
        )?;
        d.set_item(
            "thermal_radial_displacement_um",
            col(&|g| g.thermal_radial_displacement_m * 1e6),
        )?;
        d.set_item(
            "total_radial_displacement_um",
            col(&|g| g.total_radial_displacement_m() * 1e6),
        )?;
        d.set_item("radial_stiffness_n_per_m", col(&|g| g.front_radial_stiffness_n_per_m))?;
        d.set_item(
            "radial_stiffness_isothermal_n_per_m",
            col(&|g| g.front_radial_stiffness_isothermal_n_per_m),
        )?;
        d.set_item("axial_growth_um", col(&|g| g.axial_growth_m * 1e6))?;
        Ok(d)
    }

    /// Compensation preload (seed B Fig. 17) at each speed for a spring of
    /// `spring_rate_n_per_um` (the preload force is kept).
    #[pyo3(signature = (speeds_rpm, spring_rate_n_per_um, progress=None))]
    fn compensation<'py>(
        &self,
        py: Python<'py>,
        speeds_rpm: Vec<f64>,
        spring_rate_n_per_um: f64,
        progress: Option<Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let ks = non_negative("spring_rate_n_per_um", spring_rate_n_per_um).py_err()? * 1e6;
        let sp = &self.inner;
        let res = map_interruptible(py, &speeds_rpm, None, progress.as_ref(), |&n| {
            compensation_preload(sp, &[n], ks).map(|v| v[0])
        })?;
        let pts: Vec<CompensationPoint> = res.into_iter().collect::<Result<_>>().py_err()?;
        let d = PyDict::new(py);
        let col = |f: &dyn Fn(&CompensationPoint) -> f64| -> Vec<f64> { pts.iter().map(f).collect() };
        d.set_item("speed_rpm", col(&|p| p.speed_rpm))?;
        d.set_item("axial_growth_um", col(&|p| p.axial_growth_m * 1e6))?;
        d.set_item("compensation_preload_n", col(&|p| p.compensation_preload_n))?;
        d.set_item("solved_preload_change_n", col(&|p| p.solved_preload_change_n))?;
        Ok(d)
    }
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<PySpindle>()?;
    Ok(())
}

/// Heat-model settings of a spindle (docs/concepts/physics.md §9), from a
/// Python dict: `heat_model` ("palmgren" | "skf"), `lubrication` (method;
/// its defaults fill `lubrication_factor_f0` and `churning_oil_fraction`
/// when not given), `load_friction_scale` (Palmgren's f1 times this),
/// `extra_heat_w` (an extra heat at the front bearing set, W) and the
/// speed law of an unknown heat source there (`unknown_heat_linear_w`,
/// `unknown_heat_quadratic_w`, `unknown_heat_reference_rpm`),
/// `skf_series`, `sliding_friction_ehl`,
/// `replenishment_krs`, `seal_moment_n_m`.
#[derive(FromPyObject)]
#[pyo3(from_item_all)]
pub struct SpindleHeatArgs {
    heat_model: Option<String>,
    lubrication: Option<String>,
    lubrication_factor_f0: Option<f64>,
    load_friction_scale: Option<f64>,
    #[pyo3(default)]
    extra_heat_w: Option<f64>,
    #[pyo3(default)]
    unknown_heat_linear_w: Option<f64>,
    #[pyo3(default)]
    unknown_heat_quadratic_w: Option<f64>,
    #[pyo3(default)]
    unknown_heat_reference_rpm: Option<f64>,
    churning_oil_fraction: Option<f64>,
    skf_series: Option<String>,
    sliding_friction_ehl: Option<f64>,
    replenishment_krs: Option<f64>,
    seal_moment_n_m: Option<f64>,
    oil_supply: super::oil_supply::PySupplyInput,
}

impl SpindleHeatArgs {
    /// Set the heat model of `cfg`; values not given keep the current ones
    /// (with a lubrication method given: its f0 and X defaults).
    fn apply(self, cfg: &mut SpindleConfig) -> crate::error::Result<()> {
        use crate::thermal::friction::{resolve_lubrication, HeatModel, SkfSeries};
        if let Some(m) = &self.heat_model {
            cfg.heat_model = HeatModel::from_name(m)?;
        }
        let bt = cfg.params.front_bearing.geometry.bearing_type;
        if self.lubrication.is_some() {
            let (l, f0, x) = resolve_lubrication(
                self.lubrication.as_deref(),
                bt,
                self.lubrication_factor_f0,
                self.churning_oil_fraction,
            )?;
            cfg.lubrication = l;
            cfg.params.lubrication_factor_f0 = f0;
            cfg.churning_oil_fraction = x;
        } else {
            let f0 = self.lubrication_factor_f0.unwrap_or(cfg.params.lubrication_factor_f0);
            let x = self.churning_oil_fraction.unwrap_or(cfg.churning_oil_fraction);
            let (_, f0, x) = resolve_lubrication(None, bt, Some(f0), Some(x))?;
            cfg.params.lubrication_factor_f0 = f0;
            cfg.churning_oil_fraction = x;
        }
        let supply = crate::thermal::oil_supply::SupplyInput::from(self.oil_supply).resolve(
            cfg.lubrication,
            self.lubrication.is_some(),
            self.churning_oil_fraction.is_some(),
        )?;
        if supply.is_some() || self.lubrication.is_some() || self.churning_oil_fraction.is_some() {
            cfg.oil_supply = supply;
        }
        if let Some(s) = self.load_friction_scale {
            cfg.load_friction_scale = crate::error::in_range("load_friction_scale", s, 0.0, 100.0)?;
        }
        if let Some(e) = self.extra_heat_w {
            cfg.extra_heat_w = e;
        }
        if let Some(a) = self.unknown_heat_linear_w {
            cfg.unknown_heat_linear_w = a;
        }
        if let Some(b) = self.unknown_heat_quadratic_w {
            cfg.unknown_heat_quadratic_w = b;
        }
        if let Some(r) = self.unknown_heat_reference_rpm {
            cfg.unknown_heat_reference_rpm = r;
        }
        if let Some(s) = &self.skf_series {
            cfg.skf.series = Some(SkfSeries::from_name(s)?);
        }
        if self.sliding_friction_ehl.is_some() {
            cfg.skf.mu_ehl = self.sliding_friction_ehl;
        }
        if self.replenishment_krs.is_some() {
            cfg.skf.replenishment_krs = self.replenishment_krs;
        }
        if let Some(m) = self.seal_moment_n_m {
            cfg.skf.seal_moment_n_m = m;
        }
        cfg.skf.validate()
    }
}
