//! Vibration of the seed B spindle (src/rotor/presets.rs) on real bearing
//! supports (src/rotor/spindle_bearings.rs): Campbell diagram and critical
//! speeds, steady unbalance response, time response with nonlinear ball
//! forces, shaft-end vibration velocity (RMS, peak, 1X/2X/3X) and spectra,
//! uncoupled (zero raceway offsets) or thermally coupled (per-speed
//! offsets from the thermal model).
//!
//! The velocity is the x component at the tool nose (z = 0), the probe
//! position of a shaft-end vibration measurement. Velocity amplitudes of
//! the spectrum and of 1X/2X/3X are single-sided peak amplitudes [mm/s];
//! RMS is the RMS of the whole signal.

use std::sync::Arc;

use nalgebra::DVector;

use super::modal::{campbell, CampbellDiagram, CampbellOptions, CriticalSpeed};
use super::presets::{SpindleParameters, SpindleRotorGeometry, MAX_SPEED_RPM, NOSE_POSITION_M};
use super::response::{harmonic_solution, static_deflection, unbalance_phasor, Unbalance};
use super::spectrum::{amplitude_spectrum, order_amplitudes, peak, rms};
use super::spindle_bearings::{NonlinearBearingForces, OffsetTable, PreloadedRow, SpindleRow};
use super::support::BearingModel as SupportModel;
use super::transient::{time_response, NonlinearForce, TimeHistory, TransientOptions};
use super::{LateralDof, Rotor};
use crate::bearing::{Bearing, SolveOptions};
use crate::effects::{Effect, EffectSet};
use crate::error::{finite, positive, Error, Result};

/// Ball material of the seed spindle's rows.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RowMaterial {
    /// 52100 balls and rings (7009C / 7008C).
    Steel,
    /// Si3N4 balls on steel rings (7009C-hybrid / 7008C-hybrid).
    Hybrid,
}

/// Inputs of a spindle vibration model.
#[derive(Debug, Clone, PartialEq)]
pub struct SpindleVibrationConfig {
    /// Steel or hybrid rows: the 7009C / 7008C presets or their `-hybrid`
    /// variants.
    pub material: RowMaterial,
    /// Constant-force axial preload of each pair \[N\] (400 N: seed B's test).
    pub preload_n: f64,
    /// Shaft, disks, modal damping, UMP data (the constant bearing
    /// stiffness fields of it are not used: the rows come from the solver).
    pub parameters: SpindleParameters,
    /// Effects: the bearing ones go to the ball solver,
    /// `unbalanced_magnetic_pull` switches the UMP.
    pub effects: EffectSet,
    /// Thermal raceway offsets of the front (7009C) pair against speed (None: uncoupled).
    pub front_offsets: Option<OffsetTable>,
    /// Thermal raceway offsets of the rear (7008C) pair against speed (None: uncoupled).
    pub rear_offsets: Option<OffsetTable>,
    /// A spindle's own rotor and bearings (None: the seed B rotor on the
    /// `material` rows).
    pub rotor: Option<CustomRotor>,
}

/// A spindle rotor laid out from the spindle's own description, on its own
/// bearings (the B row of each pair mirrored: back-to-back pairs).
#[derive(Debug, Clone, PartialEq)]
pub struct CustomRotor {
    /// Shaft, rows and rotor core.
    pub geometry: SpindleRotorGeometry,
    /// The bearing of each front row.
    pub front_bearing: Bearing,
    /// The bearing of each rear row.
    pub rear_bearing: Bearing,
}

impl SpindleVibrationConfig {
    /// Uncoupled seed B spindle, 400 N preload, every bearing effect on, UMP off.
    pub fn seed(material: RowMaterial) -> Self {
        SpindleVibrationConfig {
            material,
            preload_n: 400.0,
            parameters: SpindleParameters::default(),
            effects: EffectSet::all().without(Effect::UnbalancedMagneticPull),
            front_offsets: None,
            rear_offsets: None,
            rotor: None,
        }
    }
}

/// How the residual unbalance is given.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum UnbalanceSpec {
    /// ISO 21940-11 balance grade G [mm/s] at the maximum service speed.
    Grade {
        /// Balance grade G = e_per Omega_max [mm/s], e.g. 2.5 for G2.5.
        grade_mm_per_s: f64,
    },
    /// Unbalance mass x radius [g mm].
    MassRadius {
        /// Residual unbalance U = m r [g mm] (1 g mm = 1e-6 kg m), >= 0.
        unbalance_g_mm: f64,
    },
}

/// Shaft-end vibration at one speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VibrationPoint {
    /// Shaft speed \[rpm\].
    pub speed_rpm: f64,
    /// RMS of the nose x velocity [mm/s] (steady response: 1X / sqrt 2).
    pub velocity_rms_mm_s: f64,
    /// Largest |v_x| at the nose [mm/s] (steady response: the 1X amplitude).
    pub velocity_peak_mm_s: f64,
    /// 1X, 2X, 3X velocity amplitudes [mm/s].
    pub harmonics_mm_s: [f64; 3],
}

/// A time response at one speed and what it shows.
#[derive(Debug, Clone, PartialEq)]
pub struct TimeVibration {
    /// RMS, peak and 1X/2X/3X of the nose x velocity over the analysed window.
    pub point: VibrationPoint,
    /// The whole recorded response, the discarded settling part included.
    pub history: TimeHistory,
    /// Start of the analysed window \[s\] (the first part is discarded).
    pub window_start_s: f64,
}

/// The seed B spindle on solver-based rows.
pub struct SpindleVibration {
    config: SpindleVibrationConfig,
    geometry: SpindleRotorGeometry,
    rotor: Rotor,
    rows: Vec<(f64, SpindleRow)>,
}

/// Campbell options used for the spindle: the lowest 8 modes of a 24-mode
/// pseudo-modal basis at rest (the seed spindle's basis-shape check in
/// src/rotor/modal.rs).
pub fn spindle_campbell_options(modes: usize) -> CampbellOptions {
    CampbellOptions {
        modes,
        reduced_modes: Some(24.max(modes + 8)),
        ..CampbellOptions::default()
    }
}

impl SpindleVibration {
    /// Build the rotor with the four rows (seed: front A/B 7009C, rear A/B
    /// 7008C; or the spindle's own rotor and bearings; the B rows mirrored:
    /// back-to-back pairs).
    pub fn new(config: SpindleVibrationConfig) -> Result<Self> {
        let opts = SolveOptions {
            effects: config.effects,
            ..SolveOptions::default()
        };
        let (geometry, front_bearing, rear_bearing) = match &config.rotor {
            Some(c) => (c.geometry.clone(), c.front_bearing.clone(), c.rear_bearing.clone()),
            None => {
                let suffix = match config.material {
                    RowMaterial::Steel => "",
                    RowMaterial::Hybrid => "-hybrid",
                };
                (
                    SpindleRotorGeometry::seed_b(),
                    Bearing::preset(&format!("7009C{suffix}"))?,
                    Bearing::preset(&format!("7008C{suffix}"))?,
                )
            }
        };
        let front = Arc::new(PreloadedRow::new(
            &front_bearing,
            config.preload_n,
            opts,
            config.front_offsets.clone(),
        )?);
        let rear = Arc::new(PreloadedRow::new(
            &rear_bearing,
            config.preload_n,
            opts,
            config.rear_offsets.clone(),
        )?);
        let row = |z: f64, r: &Arc<PreloadedRow>, mirrored: bool| {
            (
                z,
                SpindleRow {
                    row: r.clone(),
                    mirrored,
                },
            )
        };
        let rows = vec![
            row(geometry.front_rows_m[0], &front, false),
            row(geometry.front_rows_m[1], &front, true),
            row(geometry.rear_rows_m[0], &rear, false),
            row(geometry.rear_rows_m[1], &rear, true),
        ];
        let parameters = SpindleParameters {
            magnetic_pull_enabled: config.effects.has(Effect::UnbalancedMagneticPull),
            ..config.parameters.clone()
        };
        // The layout takes one model per pair; replace each support by its own row.
        let placeholder: Arc<dyn SupportModel> = Arc::new(rows[0].1.clone());
        let mut spec = if config.rotor.is_some() {
            geometry.spindle_with_bearings(placeholder.clone(), placeholder, &parameters)?
        } else {
            super::presets::seed_b_spindle_with_bearings(placeholder.clone(), placeholder, &parameters)?
        };
        for (b, (z, r)) in spec.bearings.iter_mut().zip(&rows) {
            b.position_m = *z;
            b.model = Arc::new(r.clone());
        }
        let rotor = Rotor::new(spec)?;
        Ok(SpindleVibration {
            config,
            geometry,
            rotor,
            rows,
        })
    }

    /// The configuration the model was built from.
    pub fn config(&self) -> &SpindleVibrationConfig {
        &self.config
    }

    /// The assembled rotor: seed B shaft and disks on the four solver-based rows.
    pub fn rotor(&self) -> &Rotor {
        &self.rotor
    }

    /// The rows (axial position \[m\], row) in support order.
    pub fn rows(&self) -> &[(f64, SpindleRow)] {
        &self.rows
    }

    /// Campbell diagram with the lowest `modes` modes.
    pub fn campbell(&self, speeds_rpm: &[f64], modes: usize) -> Result<CampbellDiagram> {
        campbell(&self.rotor, speeds_rpm, &spindle_campbell_options(modes))
    }

    /// Critical speeds (1X crossings, `harmonic` = 1) from a Campbell diagram over `speeds_rpm`.
    pub fn critical_speeds(&self, speeds_rpm: &[f64], modes: usize, harmonic: f64) -> Result<Vec<CriticalSpeed>> {
        positive("harmonic", harmonic)?;
        Ok(self.campbell(speeds_rpm, modes)?.critical_speeds(harmonic))
    }

    /// The residual unbalance at the middle of the rotor core (phase 0).
    pub fn unbalance(&self, spec: UnbalanceSpec) -> Result<Unbalance> {
        // The centre slice of the core, a mesh node (presets.rs).
        let z = self.geometry.core_centre_m();
        match spec {
            UnbalanceSpec::Grade { grade_mm_per_s } => {
                Unbalance::from_balance_grade(z, grade_mm_per_s, self.rotor.mass_kg(), MAX_SPEED_RPM, 0.0)
            }
            UnbalanceSpec::MassRadius { unbalance_g_mm } => {
                finite("unbalance_g_mm", unbalance_g_mm)?;
                if unbalance_g_mm < 0.0 {
                    return Err(Error::config("unbalance_g_mm", unbalance_g_mm, "must be non-negative"));
                }
                Ok(Unbalance {
                    position_m: z,
                    unbalance_kg_m: unbalance_g_mm * 1e-6,
                    phase_rad: 0.0,
                })
            }
        }
    }

    /// Steady unbalance response (frequency domain) at the nose: only 1X
    /// exists in a linear steady state, so 2X = 3X = 0, peak = 1X and
    /// RMS = 1X / sqrt 2 (x direction).
    pub fn steady_vibration(&self, speeds_rpm: &[f64], unbalance: &Unbalance) -> Result<Vec<VibrationPoint>> {
        let resp = super::response::unbalance_response(&self.rotor, &[*unbalance], speeds_rpm, NOSE_POSITION_M)?;
        Ok(resp
            .iter()
            .map(|r| VibrationPoint {
                speed_rpm: r.speed_rpm,
                velocity_rms_mm_s: r.velocity_rms_x_m_per_s * 1e3,
                velocity_peak_mm_s: r.velocity_peak_x_m_per_s * 1e3,
                harmonics_mm_s: [r.velocity_peak_x_m_per_s * 1e3, 0.0, 0.0],
            })
            .collect())
    }

    /// Linear steady state (q, q') at t = 0 (unbalance phasor + static UMP deflection).
    pub fn steady_state_at_zero(&self, speed_rpm: f64, unbalance: &Unbalance) -> Result<(DVector<f64>, DVector<f64>)> {
        let m = self.rotor.matrices(speed_rpm)?;
        let f = unbalance_phasor(&self.rotor, &[*unbalance])?;
        let q = harmonic_solution(&m, &f)?;
        let w = m.spin_speed_rad_s;
        let q0 = q.map(|c| c.re) + static_deflection(&m)?;
        let v0 = q.map(|c| -w * c.im);
        Ok((q0, v0))
    }

    /// Time response at `speed_rpm` for `duration_s`, started from the
    /// linear steady state; `nonlinear`: full ball forces with the cage
    /// turning (else the linearised supports). The first `settle_s` are
    /// discarded before the RMS, peak and 1X/2X/3X are taken.
    pub fn time_vibration(
        &self,
        speed_rpm: f64,
        duration_s: f64,
        settle_s: f64,
        unbalance: &Unbalance,
        nonlinear: bool,
    ) -> Result<TimeVibration> {
        positive("speed_rpm", speed_rpm)?;
        positive("duration_s", duration_s)?;
        if !(0.0..duration_s).contains(&settle_s) {
            return Err(Error::config("settle_s", settle_s, "must lie in [0, duration_s)"));
        }
        // 64 samples per revolution resolve 3X with margin (Nyquist 32X) and
        // keep the Newmark period error at 1X below (2 pi / 64)^2 / 12 = 0.08 %.
        let dt = 60.0 / speed_rpm / 64.0;
        let mut opts = TransientOptions::new(speed_rpm, duration_s, dt, NOSE_POSITION_M);
        opts.reduced_modes = Some(24);
        opts.tolerance = 1e-8;
        let (q0, v0) = self.steady_state_at_zero(speed_rpm, unbalance)?;
        let nl = if nonlinear {
            Some(NonlinearBearingForces::new(&self.rotor, &self.rows, speed_rpm)?)
        } else {
            None
        };
        let history = time_response(
            &self.rotor,
            &[*unbalance],
            nl.as_ref().map(|f| f as &dyn NonlinearForce),
            Some((&q0, &v0)),
            &opts,
        )?;
        let start = (settle_s / dt).round() as usize;
        let v = &history.velocity_x_m_per_s[start.min(history.time_s.len() - 2)..];
        let fs = history.sample_rate_hz();
        let h = order_amplitudes(v, fs, speed_rpm, 3)?;
        Ok(TimeVibration {
            point: VibrationPoint {
                speed_rpm,
                velocity_rms_mm_s: rms(v) * 1e3,
                velocity_peak_mm_s: peak(v) * 1e3,
                harmonics_mm_s: [h[0] * 1e3, h[1] * 1e3, h[2] * 1e3],
            },
            history,
            window_start_s: start as f64 * dt,
        })
    }

    /// Amplitude spectrum (Hann window) of the nose velocity in x over the
    /// analysed window of a time response: (frequency \[Hz\], amplitude [mm/s]).
    pub fn spectrum(&self, t: &TimeVibration) -> Result<(Vec<f64>, Vec<f64>)> {
        let dt = 1.0 / t.history.sample_rate_hz();
        let start = (t.window_start_s / dt).round() as usize;
        let (f, a) = amplitude_spectrum(&t.history.velocity_x_m_per_s[start..], t.history.sample_rate_hz())?;
        Ok((f, a.iter().map(|v| v * 1e3).collect()))
    }

    /// Global index of the nose x DOF.
    pub fn nose_x_dof(&self) -> Result<usize> {
        Ok(self.rotor.dof(self.rotor.node_at(NOSE_POSITION_M)?, LateralDof::X))
    }
}
