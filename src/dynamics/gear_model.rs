//! Gear-pair dynamic models.
//!
//! (a) [`BacklashOscillator`]: the classic single-DOF torsional backlash model
//! in non-dimensional form (Kahraman & Singh 1990, J. Sound Vib. 142(1),
//! 49-75; time-varying stiffness as in Blankenship & Kahraman 1995,
//! J. Sound Vib. 185(5), 743-765):
//! `x'' + 2 zeta x' + k(tau) f(x) = F_m + F_a Omega^2 cos(Omega tau)`,
//! `k(tau) = 1 + alpha cos(Omega tau)`, `f` the dead zone with unit
//! half-backlash (x is measured in units of b, time in 1/omega_n).
//!
//! (b) [`HelicalPair`]: the 8-DOF helical pair of docs/concepts/physics.md §7
//! (A-43 .. A-50), integrated in SI. The rotations enter the mesh only
//! through `R_p theta_p - R_g theta_g` (A-45: the theta terms of delta_x and
//! delta_y combine to `(R_p theta_p - R_g theta_g)(sin^2 phi + cos^2 phi)
//! cos beta`), so, as A-49 does, the two rotations are replaced by the
//! relative coordinate `u = R_p theta_p - R_g theta_g` (m). The rigid-body
//! rotation is removed by assuming the output torque balances the input
//! on average, `T_g = T_p R_g / R_p`, leaving 7 DOF / 14 states:
//! `q = [x_p, y_p, z_p, x_g, y_g, z_g, u]`, state `x = [q, dq/dt]`.
//!
//! Mesh deflection (A-45) `delta_n = a . q` with
//! `a = [s c, C c, S, -s c, -C c, -S, c]`, `s = sin phi`, `C = cos phi`,
//! `c = cos beta`, `S = sin beta`.
//! Equations (A-43, A-44 reduced):
//! `m_i q_i'' + c_bi q_i' + k_bi q_i + a_i F_n = f_i`,
//! with `m_7 = m_e = 1 / (R_p^2/I_p + R_g^2/I_g)`, `k_b7 = c_b7 = 0` and
//! `f_7 = T_p / R_p`. Printed A-50 has `cos phi` and `R_bg^2 / I_p` in the
//! torsional line: both are typos (energy consistency of needs
//! `cos beta` and `R_bp^2 / I_p`); this code uses the consistent form.
//! Mesh force: `F_n = k_m(t) f(delta_n - e(t)) + c_m d/dt(delta_n - e)`,
//! dead zone `f(d) = d - clamp(d, -b, b)` (total backlash 2b).
//! A-46 as printed applies the mesh damping only in contact
//! ([`MeshDamping::InContact`], default); docs/concepts/physics.md §7 writes
//! it always active ([`MeshDamping::Always`]). Both are offered: contact-only damping
//! leaves the separated teeth undamped and makes the force jump at
//! contact, which widens the non-periodic regions markedly.
//! `c_m = 2 zeta_m sqrt(k_mean m_mesh)` with the equivalent mass along the
//! line of action `m_mesh = m_e / cos^2 beta` (torsional mode, rigid bearings).
//!
//! SI instead of A-47's non-dimensionalisation: classical RK4 is invariant
//! under linear rescaling of the state and time, so scaling changes
//! nothing but rounding; the adaptive checks use per-state absolute
//! tolerances scaled with the backlash and velocity scale instead.

use super::batch::HelicalKernel;
use super::ode::{GridOde, OdeSystem, PeriodicTable};
use crate::error::{finite, non_negative, positive};
use crate::{Error, Result};
use nalgebra::{SMatrix, SVector, SymmetricEigen};

/// Fewest RK4 steps accepted per excitation (mesh) period.
pub const MIN_STEPS_PER_PERIOD: usize = 16;
/// Largest accepted `h / T_min` with `T_min` the shortest natural period at
/// the largest mesh stiffness (RK4 phase error ~ (omega h)^4 / 120 stays below
/// 1e-3 per step, well inside the stability bound omega h < 2.83).
pub const MAX_STEP_OVER_SHORTEST_PERIOD: f64 = 0.1;

/// Dead zone `f(d)` of total width `2 b`.
#[inline(always)]
pub fn dead_zone(d: f64, b: f64) -> f64 {
    d - d.clamp(-b, b)
}

// ---------------------------------------------------------------- 1-DOF ----

/// Parameters of the non-dimensional single-DOF backlash oscillator.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BacklashOscillator {
    /// Damping ratio zeta (-).
    pub damping_ratio: f64,
    /// Mean (static) force F_m, in units of k b (-).
    pub mean_force: f64,
    /// Transmission-error excitation amplitude F_a (-), force `F_a Omega^2 cos`.
    pub alternating_force: f64,
    /// Relative stiffness variation alpha in `k = 1 + alpha cos(Omega tau)` (-).
    pub stiffness_variation: f64,
}

impl BacklashOscillator {
    /// Validate.
    pub fn new(damping_ratio: f64, mean_force: f64, alternating_force: f64, stiffness_variation: f64) -> Result<Self> {
        non_negative("damping_ratio", damping_ratio)?;
        finite("mean_force", mean_force)?;
        finite("alternating_force", alternating_force)?;
        if !(0.0..1.0).contains(&stiffness_variation.abs()) {
            return Err(Error::config(
                "stiffness_variation",
                stiffness_variation,
                "|alpha| must be below 1 (stiffness stays positive)",
            ));
        }
        Ok(BacklashOscillator {
            damping_ratio,
            mean_force,
            alternating_force,
            stiffness_variation,
        })
    }

    /// System at excitation frequency `omega` (-, in units of omega_n) with
    /// `steps_per_period` RK4 steps per excitation period 2 pi / omega.
    pub fn system(&self, omega: f64, steps_per_period: usize) -> Result<BacklashOscillatorSystem> {
        positive("frequency_ratio", omega)?;
        let period = 2.0 * std::f64::consts::PI / omega;
        let kmax = 1.0 + self.stiffness_variation.abs();
        check_steps(steps_per_period, period, 2.0 * std::f64::consts::PI / kmax.sqrt())?;
        let g = 2 * steps_per_period;
        let phase = |j: usize| 2.0 * std::f64::consts::PI * j as f64 / g as f64;
        let stiffness = (0..g)
            .map(|j| 1.0 + self.stiffness_variation * phase(j).cos())
            .collect();
        let force = (0..g)
            .map(|j| self.mean_force + self.alternating_force * omega * omega * phase(j).cos())
            .collect();
        Ok(BacklashOscillatorSystem {
            p: *self,
            omega,
            step: period / steps_per_period as f64,
            stiffness,
            force,
        })
    }
}

/// [`BacklashOscillator`] tabulated at one frequency. State `[x, x']`.
#[derive(Debug, Clone, PartialEq)]
pub struct BacklashOscillatorSystem {
    p: BacklashOscillator,
    omega: f64,
    step: f64,
    stiffness: Vec<f64>,
    force: Vec<f64>,
}

impl BacklashOscillatorSystem {
    /// Excitation period 2 pi / Omega (-).
    pub fn period(&self) -> f64 {
        self.step * (self.stiffness.len() / 2) as f64
    }
}

impl OdeSystem<2> for BacklashOscillatorSystem {
    fn rhs(&self, t: f64, x: &[f64; 2], dx: &mut [f64; 2]) {
        let c = (self.omega * t).cos();
        let k = 1.0 + self.p.stiffness_variation * c;
        let f = self.p.mean_force + self.p.alternating_force * self.omega * self.omega * c;
        dx[0] = x[1];
        dx[1] = f - 2.0 * self.p.damping_ratio * x[1] - k * dead_zone(x[0], 1.0);
    }
}

impl GridOde<2> for BacklashOscillatorSystem {
    fn step(&self) -> f64 {
        self.step
    }
    fn grid_len(&self) -> usize {
        self.stiffness.len()
    }
    #[inline(always)]
    fn rhs_grid(&self, j: usize, x: &[f64; 2], dx: &mut [f64; 2]) {
        dx[0] = x[1];
        dx[1] = self.force[j] - 2.0 * self.p.damping_ratio * x[1] - self.stiffness[j] * dead_zone(x[0], 1.0);
    }
}

/// Check the fixed step against the excitation period and the shortest
/// natural period; errors name `steps_per_period`.
pub fn check_steps(steps_per_period: usize, period: f64, shortest_natural_period: f64) -> Result<()> {
    if steps_per_period < MIN_STEPS_PER_PERIOD {
        return Err(Error::config(
            "steps_per_period",
            steps_per_period,
            format!("at least {MIN_STEPS_PER_PERIOD} RK4 steps per mesh period are needed"),
        ));
    }
    let h = period / steps_per_period as f64;
    if h > MAX_STEP_OVER_SHORTEST_PERIOD * shortest_natural_period {
        let need = (period / (MAX_STEP_OVER_SHORTEST_PERIOD * shortest_natural_period)).ceil();
        return Err(Error::config(
            "steps_per_period",
            steps_per_period,
            format!(
                "step {h:.3e} exceeds {MAX_STEP_OVER_SHORTEST_PERIOD} x the shortest natural period \
                 {shortest_natural_period:.3e}; use at least {need}"
            ),
        ));
    }
    Ok(())
}

// ---------------------------------------------------------------- 8-DOF ----

/// Bearing support of one gear body in x, y (radial) and z (axial), A-52.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BearingSupport {
    /// Stiffness in x (N/m).
    pub kx_n_per_m: f64,
    /// Stiffness in y (N/m).
    pub ky_n_per_m: f64,
    /// Stiffness in z, axial (N/m).
    pub kz_n_per_m: f64,
    /// Damping in x (N s/m).
    pub cx_n_s_per_m: f64,
    /// Damping in y (N s/m).
    pub cy_n_s_per_m: f64,
    /// Damping in z (N s/m).
    pub cz_n_s_per_m: f64,
}

impl BearingSupport {
    /// A-52 form `diag(Kr, Kr, Ka)` with damping from a damping ratio on the
    /// body mass, `c = 2 zeta sqrt(k m)`.
    pub fn radial_axial(kr_n_per_m: f64, ka_n_per_m: f64, damping_ratio: f64, mass_kg: f64) -> Self {
        let c = |k: f64| 2.0 * damping_ratio * (k * mass_kg).max(0.0).sqrt();
        BearingSupport {
            kx_n_per_m: kr_n_per_m,
            ky_n_per_m: kr_n_per_m,
            kz_n_per_m: ka_n_per_m,
            cx_n_s_per_m: c(kr_n_per_m),
            cy_n_s_per_m: c(kr_n_per_m),
            cz_n_s_per_m: c(ka_n_per_m),
        }
    }
}

/// One gear body (pinion or wheel).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GearBody {
    /// Mass (kg).
    pub mass_kg: f64,
    /// Polar moment of inertia (kg m^2).
    pub inertia_kg_m2: f64,
    /// Base-circle radius (m).
    pub base_radius_m: f64,
    /// Bearing support.
    pub bearing: BearingSupport,
}

/// Where the mesh damping acts (see module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MeshDamping {
    /// Only while the teeth are in contact (A-46 as printed).
    InContact,
    /// Always, also inside the backlash (docs/concepts/physics.md §7 form).
    Always,
}

/// Plain-number description of the helical pair.
#[derive(Debug, Clone, PartialEq)]
pub struct HelicalPairParams {
    /// Driving gear.
    pub pinion: GearBody,
    /// Driven gear.
    pub gear: GearBody,
    /// Pinion tooth count (sets the mesh frequency `z_p n / 60`).
    pub pinion_teeth: u32,
    /// Helix angle beta (rad).
    pub helix_angle_rad: f64,
    /// Angle phi between the plane of action and the vertical (rad).
    pub line_of_action_angle_rad: f64,
    /// Half backlash b (m); total clearance 2b.
    pub half_backlash_m: f64,
    /// Mesh damping ratio zeta_m (-).
    pub mesh_damping_ratio: f64,
    /// Where mesh damping acts.
    pub mesh_damping: MeshDamping,
    /// Input torque on the pinion (N m).
    pub input_torque_n_m: f64,
    /// Mesh stiffness samples over one mesh period (N/m).
    pub mesh_stiffness_n_per_m: Vec<f64>,
    /// Static transmission error samples over one mesh period (m).
    pub transmission_error_m: Vec<f64>,
}

/// Mean mesh stiffness of the fixture [`HelicalPairParams::seed_a`] [N/m]:
/// 6.0e8 N/m, a round value between the two models of `crate::gear` for the
/// seed pair along the transverse line of action: ISO 6336-1 method B
/// c_gamma_alpha b = 16.6 N/(mm um) x 33 mm = 5.5e8 N/m and the
/// potential-energy mean 6.6e8 N/m (tested). The Python preset
/// `seed-electric-drive` does not use it: it computes the potential-energy
/// table (9.0e8 N/m in the normal direction of A-45).
pub const SEED_A_FIXTURE_MESH_STIFFNESS_N_PER_M: f64 = 6.0e8;

impl HelicalPairParams {
    /// Seed A, Table 3 (first gear pair): z = 29/78, m_n = 1.537 mm,
    /// alpha_n = 16.5 deg, beta = 31.2 deg, masses 1.201/3.1 kg, inertias
    /// 0.1152/1.6 t mm^2 = 1.152e-4/1.6e-3 kg m^2 (docs/concepts/physics.md §8).
    /// Base radii from r_b = z m_n / (2 cos beta) cos alpha_t,
    /// tan alpha_t = tan alpha_n / cos beta; phi = alpha_t (centres on a
    /// horizontal line). A gives no backlash, damping, TE or stiffness values;
    /// documented defaults (docs/concepts/physics.md §8): b = 50 um, zeta_m = 0.07,
    /// bearing zeta = 0.02, mean mesh stiffness
    /// [`SEED_A_FIXTURE_MESH_STIFFNESS_N_PER_M`] with a +-10 % harmonic
    /// variation, TE amplitude 2 um, Kr = 2e8 N/m, Ka = 5e7 N/m, 100 N m.
    pub fn seed_a() -> Self {
        let beta = 31.2f64.to_radians();
        let alpha_n = 16.5f64.to_radians();
        let alpha_t = (alpha_n.tan() / beta.cos()).atan();
        let mn = 1.537e-3;
        let rb = |z: f64| z * mn / (2.0 * beta.cos()) * alpha_t.cos();
        let body = |m: f64, i: f64, r: f64| GearBody {
            mass_kg: m,
            inertia_kg_m2: i,
            base_radius_m: r,
            bearing: BearingSupport::radial_axial(2.0e8, 5.0e7, 0.02, m),
        };
        let n = 64;
        let ph = |k: usize| 2.0 * std::f64::consts::PI * k as f64 / n as f64;
        HelicalPairParams {
            pinion: body(1.201, 1.152e-4, rb(29.0)),
            gear: body(3.1, 1.6e-3, rb(78.0)),
            pinion_teeth: 29,
            helix_angle_rad: beta,
            line_of_action_angle_rad: alpha_t,
            half_backlash_m: 50e-6,
            mesh_damping_ratio: 0.07,
            mesh_damping: MeshDamping::InContact,
            input_torque_n_m: 100.0,
            mesh_stiffness_n_per_m: (0..n)
                .map(|k| SEED_A_FIXTURE_MESH_STIFFNESS_N_PER_M * (1.0 + 0.1 * ph(k).cos()))
                .collect(),
            transmission_error_m: (0..n).map(|k| 2.0e-6 * ph(k).sin()).collect(),
        }
    }
}

/// Validated helical pair with derived quantities.
#[derive(Debug, Clone, PartialEq)]
pub struct HelicalPair {
    params: HelicalPairParams,
    stiffness: PeriodicTable,
    error: PeriodicTable,
    /// Projection of q on the mesh normal.
    a: [f64; 7],
    /// Masses `[m_p x3, m_g x3, m_e]` (kg).
    mass: [f64; 7],
    mesh_damping_n_s_per_m: f64,
}

fn check_body(prefix: &str, g: &GearBody) -> Result<()> {
    positive(&format!("{prefix}.mass_kg"), g.mass_kg)?;
    positive(&format!("{prefix}.inertia_kg_m2"), g.inertia_kg_m2)?;
    positive(&format!("{prefix}.base_radius_m"), g.base_radius_m)?;
    let b = &g.bearing;
    positive(&format!("{prefix}.bearing.kx_n_per_m"), b.kx_n_per_m)?;
    positive(&format!("{prefix}.bearing.ky_n_per_m"), b.ky_n_per_m)?;
    positive(&format!("{prefix}.bearing.kz_n_per_m"), b.kz_n_per_m)?;
    non_negative(&format!("{prefix}.bearing.cx_n_s_per_m"), b.cx_n_s_per_m)?;
    non_negative(&format!("{prefix}.bearing.cy_n_s_per_m"), b.cy_n_s_per_m)?;
    non_negative(&format!("{prefix}.bearing.cz_n_s_per_m"), b.cz_n_s_per_m)?;
    Ok(())
}

impl HelicalPair {
    /// Validate and derive.
    pub fn new(params: HelicalPairParams) -> Result<Self> {
        check_body("pinion", &params.pinion)?;
        check_body("gear", &params.gear)?;
        if params.pinion_teeth == 0 {
            return Err(Error::config("pinion_teeth", 0, "must be at least 1"));
        }
        let beta = finite("helix_angle_rad", params.helix_angle_rad)?;
        if beta.abs() >= std::f64::consts::FRAC_PI_2 {
            return Err(Error::config("helix_angle_rad", beta, "must lie in (-pi/2, pi/2)"));
        }
        let phi = finite("line_of_action_angle_rad", params.line_of_action_angle_rad)?;
        non_negative("half_backlash_m", params.half_backlash_m)?;
        non_negative("mesh_damping_ratio", params.mesh_damping_ratio)?;
        finite("input_torque_n_m", params.input_torque_n_m)?;
        let stiffness = PeriodicTable::new("mesh_stiffness_n_per_m", params.mesh_stiffness_n_per_m.clone())?;
        if stiffness.min() <= 0.0 {
            return Err(Error::config(
                "mesh_stiffness_n_per_m",
                stiffness.min(),
                "all samples must be greater than zero",
            ));
        }
        let error = PeriodicTable::new("transmission_error_m", params.transmission_error_m.clone())?;
        let (s, c) = phi.sin_cos();
        let (sb, cb) = beta.sin_cos();
        let a = [s * cb, c * cb, sb, -s * cb, -c * cb, -sb, cb];
        let (p, g) = (&params.pinion, &params.gear);
        let me = 1.0 / (p.base_radius_m.powi(2) / p.inertia_kg_m2 + g.base_radius_m.powi(2) / g.inertia_kg_m2);
        let mass = [p.mass_kg, p.mass_kg, p.mass_kg, g.mass_kg, g.mass_kg, g.mass_kg, me];
        let m_mesh = me / (cb * cb);
        let cm = 2.0 * params.mesh_damping_ratio * (stiffness.mean() * m_mesh).sqrt();
        Ok(HelicalPair {
            params,
            stiffness,
            error,
            a,
            mass,
            mesh_damping_n_s_per_m: cm,
        })
    }

    /// The parameters.
    pub fn params(&self) -> &HelicalPairParams {
        &self.params
    }

    /// Mesh-normal projection vector `a` of `q`.
    pub fn projection(&self) -> [f64; 7] {
        self.a
    }

    /// Diagonal mass vector `[m_p, m_p, m_p, m_g, m_g, m_g, m_e]` (kg).
    pub fn masses_kg(&self) -> [f64; 7] {
        self.mass
    }

    /// Mesh damping coefficient c_m (N s/m).
    pub fn mesh_damping_n_s_per_m(&self) -> f64 {
        self.mesh_damping_n_s_per_m
    }

    /// Mesh period `60 / (z_p n)` (s).
    pub fn mesh_period_s(&self, speed_rpm: f64) -> Result<f64> {
        positive("speed_rpm", speed_rpm)?;
        Ok(60.0 / (self.params.pinion_teeth as f64 * speed_rpm))
    }

    /// Copy with both gears' bearings set to `diag(Kr, Kr, Ka)`,
    /// keeping the damping coefficients.
    pub fn with_bearing_stiffness(&self, kr_n_per_m: f64, ka_n_per_m: f64) -> Result<Self> {
        positive("kr_n_per_m", kr_n_per_m)?;
        positive("ka_n_per_m", ka_n_per_m)?;
        let mut p = self.params.clone();
        for body in [&mut p.pinion, &mut p.gear] {
            body.bearing.kx_n_per_m = kr_n_per_m;
            body.bearing.ky_n_per_m = kr_n_per_m;
            body.bearing.kz_n_per_m = ka_n_per_m;
        }
        HelicalPair::new(p)
    }

    /// Copy with another input torque and transmission-error scale factor.
    pub fn with_torque_and_error_scale(&self, input_torque_n_m: f64, error_scale: f64) -> Result<Self> {
        finite("error_scale", error_scale)?;
        let mut p = self.params.clone();
        p.input_torque_n_m = input_torque_n_m;
        for e in &mut p.transmission_error_m {
            *e *= error_scale;
        }
        HelicalPair::new(p)
    }

    /// Bearing stiffness diagonal of q (N/m); zero for u.
    pub fn bearing_stiffness(&self) -> [f64; 7] {
        let (p, g) = (&self.params.pinion.bearing, &self.params.gear.bearing);
        [
            p.kx_n_per_m,
            p.ky_n_per_m,
            p.kz_n_per_m,
            g.kx_n_per_m,
            g.ky_n_per_m,
            g.kz_n_per_m,
            0.0,
        ]
    }

    /// Bearing damping diagonal of q (N s/m); zero for u.
    pub fn bearing_damping(&self) -> [f64; 7] {
        let (p, g) = (&self.params.pinion.bearing, &self.params.gear.bearing);
        [
            p.cx_n_s_per_m,
            p.cy_n_s_per_m,
            p.cz_n_s_per_m,
            g.cx_n_s_per_m,
            g.cy_n_s_per_m,
            g.cz_n_s_per_m,
            0.0,
        ]
    }

    /// Linear stiffness matrix in contact, `K = diag(k_b) + k_m a a^T` (N/m).
    pub fn stiffness_matrix(&self, mesh_stiffness_n_per_m: f64) -> SMatrix<f64, 7, 7> {
        let a = SVector::<f64, 7>::from(self.a);
        SMatrix::<f64, 7, 7>::from_diagonal(&SVector::from(self.bearing_stiffness()))
            + mesh_stiffness_n_per_m * a * a.transpose()
    }

    /// Undamped natural angular frequencies (rad/s, ascending) in contact at
    /// mesh stiffness `k_m`: square roots of the eigenvalues of
    /// `M^-1/2 K M^-1/2` (symmetric), with the mass-normalised modes.
    pub fn natural_modes(&self, mesh_stiffness_n_per_m: f64) -> (Vec<f64>, SMatrix<f64, 7, 7>) {
        let k = self.stiffness_matrix(mesh_stiffness_n_per_m);
        let mut ms = SMatrix::<f64, 7, 7>::zeros();
        for i in 0..7 {
            ms[(i, i)] = 1.0 / self.mass[i].sqrt();
        }
        let eig = SymmetricEigen::new(ms * k * ms);
        let mut idx: Vec<usize> = (0..7).collect();
        idx.sort_by(|&i, &j| eig.eigenvalues[i].total_cmp(&eig.eigenvalues[j]));
        let w = idx.iter().map(|&i| eig.eigenvalues[i].max(0.0).sqrt()).collect();
        let mut modes = SMatrix::<f64, 7, 7>::zeros();
        for (c, &i) in idx.iter().enumerate() {
            // Physical mode shape q = M^-1/2 v.
            modes.set_column(c, &(ms * eig.eigenvectors.column(i)));
        }
        (w, modes)
    }

    /// Shortest natural period at the largest mesh stiffness sample (s).
    pub fn shortest_natural_period_s(&self) -> f64 {
        let (w, _) = self.natural_modes(self.stiffness.max());
        2.0 * std::f64::consts::PI / w[6]
    }

    /// Static equilibrium state in contact at the mean mesh stiffness and mean
    /// transmission error: `K q = f + a k_m (e + b sign(T))`, zero velocity.
    pub fn static_state(&self) -> Result<[f64; 14]> {
        let km = self.stiffness.mean();
        let k = self.stiffness_matrix(km);
        let shift = self.error.mean() + self.params.half_backlash_m * self.params.input_torque_n_m.signum();
        let mut f = SVector::<f64, 7>::from(self.a) * (km * shift);
        f[6] += self.params.input_torque_n_m / self.params.pinion.base_radius_m;
        let q = k
            .lu()
            .solve(&f)
            .ok_or_else(|| Error::config("bearing stiffness", 0, "static stiffness matrix is singular"))?;
        let mut x = [0.0; 14];
        x[..7].copy_from_slice(q.as_slice());
        Ok(x)
    }

    /// Mechanical energy (J) for the conservative case (constant stiffness,
    /// no damping, no torque): kinetic + bearing springs + mesh spring with
    /// the dead zone, `V_m = k_m f(delta_n - e)^2 / 2`.
    pub fn mechanical_energy_j(&self, x: &[f64; 14]) -> f64 {
        let kb = self.bearing_stiffness();
        let mut e = 0.0;
        let mut d = 0.0;
        for i in 0..7 {
            e += 0.5 * self.mass[i] * x[7 + i] * x[7 + i] + 0.5 * kb[i] * x[i] * x[i];
            d += self.a[i] * x[i];
        }
        let f = dead_zone(d - self.error.mean(), self.params.half_backlash_m);
        e + 0.5 * self.stiffness.mean() * f * f
    }

    /// Tabulate the system at `speed_rpm` with `steps_per_period` RK4 steps per
    /// mesh period. Errors name `steps_per_period` when the step is too
    /// coarse for the mesh period or for the shortest natural period.
    pub fn system(&self, speed_rpm: f64, steps_per_period: usize) -> Result<HelicalPairSystem> {
        let period = self.mesh_period_s(speed_rpm)?;
        check_steps(steps_per_period, period, self.shortest_natural_period_s())?;
        let g = 2 * steps_per_period;
        let (km, _) = self.stiffness.on_grid(g);
        let (e, de) = self.error.on_grid(g);
        let coef: Vec<[f64; 3]> = (0..g).map(|j| [km[j], e[j], de[j] / period]).collect();
        let kb = self.bearing_stiffness();
        let cb = self.bearing_damping();
        let mut kbm = [0.0; 7];
        let mut cbm = [0.0; 7];
        let mut am = [0.0; 7];
        for i in 0..7 {
            kbm[i] = kb[i] / self.mass[i];
            cbm[i] = cb[i] / self.mass[i];
            am[i] = self.a[i] / self.mass[i];
        }
        let mut g7 = [0.0; 7];
        g7[6] = self.params.input_torque_n_m / self.params.pinion.base_radius_m / self.mass[6];
        let b = self.params.half_backlash_m;
        let cm = self.mesh_damping_n_s_per_m;
        let always = self.params.mesh_damping == MeshDamping::Always;
        let step = period / steps_per_period as f64;
        let kernel = HelicalKernel::new(&self.a, &am, &kbm, &cbm, &g7, b, cm, always, step, &coef);
        Ok(HelicalPairSystem {
            a: self.a,
            am,
            kbm,
            cbm,
            g: g7,
            b,
            cm,
            always,
            step,
            period,
            coef,
            kernel,
            stiffness: self.stiffness.clone(),
            error: self.error.clone(),
        })
    }
}

/// The helical pair tabulated at one speed: 14 states
/// `[x_p, y_p, z_p, x_g, y_g, z_g, u, velocities]` (m, m/s).
#[derive(Debug, Clone, PartialEq)]
pub struct HelicalPairSystem {
    pub(crate) a: [f64; 7],
    pub(crate) am: [f64; 7],
    pub(crate) kbm: [f64; 7],
    pub(crate) cbm: [f64; 7],
    pub(crate) g: [f64; 7],
    pub(crate) b: f64,
    pub(crate) cm: f64,
    pub(crate) always: bool,
    pub(crate) step: f64,
    pub(crate) period: f64,
    /// `[k_m, e, de/dt]` on the half-step grid (N/m, m, m/s).
    pub(crate) coef: Vec<[f64; 3]>,
    /// The RK4 kernel's tables (src/dynamics/batch.rs).
    pub(crate) kernel: HelicalKernel,
    pub(crate) stiffness: PeriodicTable,
    pub(crate) error: PeriodicTable,
}

impl HelicalPairSystem {
    /// Mesh period (s).
    pub fn period_s(&self) -> f64 {
        self.period
    }

    /// Half backlash b (m).
    pub fn half_backlash_m(&self) -> f64 {
        self.b
    }

    /// Mesh stiffness (N/m), transmission error (m) and its rate (m/s) at
    /// time `t_s`, from the interpolated tables.
    pub fn mesh_state(&self, t_s: f64) -> (f64, f64, f64) {
        let phase = t_s / self.period;
        let (k, _) = self.stiffness.eval(phase);
        let (e, de) = self.error.eval(phase);
        (k, e, de / self.period)
    }

    /// Mesh damping coefficient c_m (N s/m) and whether it acts inside the backlash.
    pub fn mesh_damping(&self) -> (f64, bool) {
        (self.cm, self.always)
    }

    /// Static transmission error e(t) (m) from the interpolated table.
    pub fn transmission_error_m(&self, t_s: f64) -> f64 {
        self.error.eval(t_s / self.period).0
    }

    /// Dynamic transmission error `delta_n - e` (m) at the start of RK4 step
    /// `n` (grid point 2n).
    pub fn relative_deflection_m(&self, n: usize, x: &[f64; 14]) -> f64 {
        let j = (2 * n) % self.coef.len();
        self.a.iter().zip(x.iter()).map(|(a, q)| a * q).sum::<f64>() - self.coef[j][1]
    }

    /// Rate of the dynamic transmission error `d(delta_n - e)/dt` \[m/s\]
    /// at the start of RK4 step `n` (grid point 2n).
    pub fn relative_deflection_rate_m_per_s(&self, n: usize, x: &[f64; 14]) -> f64 {
        let j = (2 * n) % self.coef.len();
        self.a.iter().zip(x[7..].iter()).map(|(a, v)| a * v).sum::<f64>() - self.coef[j][2]
    }

    #[inline(always)]
    fn accel(&self, km: f64, e: f64, edot: f64, x: &[f64; 14], dx: &mut [f64; 14]) {
        // Pairwise sums (shorter dependency chains than a running sum); the
        // lock-step batch in `batch.rs` repeats this expression order exactly.
        let a = &self.a;
        let d =
            ((a[0] * x[0] + a[1] * x[1]) + (a[2] * x[2] + a[3] * x[3])) + ((a[4] * x[4] + a[5] * x[5]) + a[6] * x[6]);
        let dv = ((a[0] * x[7] + a[1] * x[8]) + (a[2] * x[9] + a[3] * x[10]))
            + ((a[4] * x[11] + a[5] * x[12]) + a[6] * x[13]);
        let f = dead_zone(d - e, self.b);
        let c = if self.always || f != 0.0 { self.cm } else { 0.0 };
        let fmesh = km * f + c * (dv - edot);
        for i in 0..7 {
            dx[i] = x[7 + i];
            dx[7 + i] = self.g[i] - self.kbm[i] * x[i] - self.cbm[i] * x[7 + i] - self.am[i] * fmesh;
        }
    }
}

impl GridOde<14> for HelicalPairSystem {
    fn step(&self) -> f64 {
        self.step
    }
    fn grid_len(&self) -> usize {
        self.coef.len()
    }
    #[inline(always)]
    fn rhs_grid(&self, j: usize, x: &[f64; 14], dx: &mut [f64; 14]) {
        let [km, e, edot] = self.coef[j];
        self.accel(km, e, edot, x, dx);
    }
    /// The lane kernel of src/dynamics/batch.rs with one lane (the same
    /// RK4 step rearranged; equal to four `rhs_grid` stages up to rounding,
    /// and bitwise equal to every lane of the lock-step batches).
    #[inline(always)]
    fn rk4_step(&self, n: usize, x: &mut [f64; 14]) {
        self.kernel.step(n, x);
    }
    /// Both states in one 2-lane register.
    #[inline(always)]
    fn rk4_step_pair(&self, n: usize, x: &mut [f64; 14], y: &mut [f64; 14]) {
        self.kernel.step_pair(n, x, y);
    }
}

impl OdeSystem<14> for HelicalPairSystem {
    fn rhs(&self, t: f64, x: &[f64; 14], dx: &mut [f64; 14]) {
        let phase = t / self.period;
        let (km, _) = self.stiffness.eval(phase);
        let (e, de) = self.error.eval(phase);
        self.accel(km, e, de / self.period, x, dx);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The number written in the source right after `marker` (first token).
    fn quoted(src: &str, marker: &str) -> f64 {
        let at = src.find(marker).unwrap_or_else(|| panic!("{marker:?} not in the doc")) + marker.len();
        let tok: String = src[at..]
            .trim_start()
            .chars()
            .take_while(|c| c.is_ascii_digit() || *c == '.' || *c == 'e' || *c == '-')
            .collect();
        tok.parse()
            .unwrap_or_else(|_| panic!("no number after {marker:?}: {tok:?}"))
    }

    #[test]
    fn fixture_mesh_stiffness_doc_quotes_the_values_the_code_computes() {
        use crate::gear::{iso_stiffness, GearPair, IsoStiffnessOptions, MeshStiffness};
        let src = include_str!("gear_model.rs");
        let before = &src[..src.find("pub const SEED_A_FIXTURE_MESH_STIFFNESS_N_PER_M").unwrap()];
        let doc = &before[before.rfind("\n\n").unwrap()..];
        let p = HelicalPairParams::seed_a();
        let mean = p.mesh_stiffness_n_per_m.iter().sum::<f64>() / p.mesh_stiffness_n_per_m.len() as f64;
        assert!((mean / SEED_A_FIXTURE_MESH_STIFFNESS_N_PER_M - 1.0).abs() < 1e-12);
        assert_eq!(quoted(doc, "[N/m]:\n///"), SEED_A_FIXTURE_MESH_STIFFNESS_N_PER_M);
        let pair = GearPair::preset("seed-electric-drive").unwrap();
        let iso = iso_stiffness(&pair, &IsoStiffnessOptions::default()).unwrap();
        let pe = MeshStiffness::potential_energy(&pair).unwrap();
        let pe_normal = pe.normal_direction(&pair).unwrap().mean_n_per_m();
        let c = quoted(doc, "c_gamma_alpha b =");
        let width = quoted(doc, "N/(mm um) x");
        let product = quoted(doc, "mm =");
        // Each quoted figure is the code's value to its printed digits.
        let close = |q: f64, v: f64, what: &str| assert!((q / v - 1.0).abs() < 0.01, "{what}: doc {q}, code {v}");
        close(c, iso.mesh_alpha_n_per_mm_um, "c_gamma_alpha");
        close(width, pair.spec.face_width_m * 1e3, "face width");
        close(product, c * width * 1e6, "product");
        close(product, iso.mesh_alpha_n_per_m(), "ISO total");
        close(quoted(doc, "potential-energy mean"), pe.mean_n_per_m(), "PE mean");
        close(quoted(doc, "table ("), pe_normal, "PE normal mean");
        assert!(iso.mesh_alpha_n_per_m() < mean && mean < pe.mean_n_per_m());
    }

    #[test]
    fn backlash_oscillator_validates_and_has_static_contact_solution() {
        assert!(BacklashOscillator::new(-0.1, 0.1, 0.1, 0.0).is_err());
        assert!(BacklashOscillator::new(0.05, 0.1, 0.1, 1.2)
            .unwrap_err()
            .to_string()
            .contains("stiffness_variation"));
        let osc = BacklashOscillator::new(0.05, 0.1, 0.0, 0.0).unwrap();
        assert!(osc.system(0.0, 64).is_err());
        // Unforced: the static contact x = F_m + 1 is an equilibrium.
        let sys = osc.system(1.0, 64).unwrap();
        let mut dx = [1.0; 2];
        sys.rhs(0.3, &[1.1, 0.0], &mut dx);
        assert!(dx[0].abs() < 1e-15 && dx[1].abs() < 1e-12, "{dx:?}");
        assert!((sys.period() - 2.0 * std::f64::consts::PI).abs() < 1e-12);
    }

    #[test]
    fn dead_zone_is_continuous_and_odd() {
        let b = 2.0;
        assert_eq!(dead_zone(1.5, b), 0.0);
        assert_eq!(dead_zone(3.0, b), 1.0);
        assert_eq!(dead_zone(-3.0, b), -1.0);
        assert!(dead_zone(2.0 + 1e-12, b).abs() < 1e-11);
    }

    #[test]
    fn seed_geometry_and_static_force_balance() {
        let pair = HelicalPair::new(HelicalPairParams::seed_a()).unwrap();
        let p = pair.params();
        // Base radius of the 29-tooth pinion: r = 29*1.537/(2 cos 31.2deg) = 26.06 mm,
        // alpha_t = 19.10 deg, r_b = 24.62 mm.
        assert!((p.pinion.base_radius_m - 24.62e-3).abs() < 0.02e-3);
        // Static state: the mesh force F_n cos(beta) equals T_p / R_p.
        let x = pair.static_state().unwrap();
        let a = pair.projection();
        let d: f64 = (0..7).map(|i| a[i] * x[i]).sum();
        let mean_k = p.mesh_stiffness_n_per_m.iter().sum::<f64>() / 64.0;
        let fn_n = mean_k * dead_zone(d, p.half_backlash_m);
        let expect = p.input_torque_n_m / p.pinion.base_radius_m / p.helix_angle_rad.cos();
        assert!((fn_n / expect - 1.0).abs() < 1e-9, "{fn_n} vs {expect}");
        // Pinion bearing carries F_n cos(beta) sin(phi) in x.
        let fx = -p.pinion.bearing.kx_n_per_m * x[0];
        let want = fn_n * a[0];
        assert!((fx / want - 1.0).abs() < 1e-9);
    }

    #[test]
    fn bad_input_names_fields() {
        let mut p = HelicalPairParams::seed_a();
        p.pinion.mass_kg = 0.0;
        let e = HelicalPair::new(p).unwrap_err().to_string();
        assert!(e.contains("pinion.mass_kg"), "{e}");
        let mut p = HelicalPairParams::seed_a();
        p.gear.inertia_kg_m2 = -1.0;
        assert!(HelicalPair::new(p)
            .unwrap_err()
            .to_string()
            .contains("gear.inertia_kg_m2"));
        let mut p = HelicalPairParams::seed_a();
        p.mesh_stiffness_n_per_m[3] = -1.0;
        assert!(HelicalPair::new(p)
            .unwrap_err()
            .to_string()
            .contains("mesh_stiffness_n_per_m"));
        let pair = HelicalPair::new(HelicalPairParams::seed_a()).unwrap();
        let e = pair.system(10_000.0, 8).unwrap_err().to_string();
        assert!(e.contains("steps_per_period"), "{e}");
        // Shortest natural period limit: at very low speed the mesh period is
        // long and 16 steps are too coarse.
        let e = pair.system(50.0, 16).unwrap_err().to_string();
        assert!(e.contains("shortest natural period"), "{e}");
        assert!(pair.system(-1.0, 64).is_err());
    }
}
