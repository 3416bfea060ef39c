//! Options and results of the ball-bearing solvers.

use super::RacewayOffsets;
use crate::effects::EffectSet;

/// Which raceway controls the ball (no spin there), Jones's hypothesis.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum RacewayControl {
    /// Outer-raceway control, lambda_i = 0, lambda_o = 2 (seed A, Jones).
    #[default]
    Outer,
    /// Inner-raceway control, lambda_i = 2, lambda_o = 0.
    Inner,
}

impl RacewayControl {
    /// The control of a name: "outer" or "inner" (a `ConfigError` naming
    /// `raceway_control` otherwise).
    pub fn from_name(name: &str) -> crate::error::Result<Self> {
        match name {
            "outer" => Ok(RacewayControl::Outer),
            "inner" => Ok(RacewayControl::Inner),
            other => Err(crate::error::Error::config(
                "raceway_control",
                other,
                "must be \"outer\" or \"inner\"",
            )),
        }
    }

    /// (lambda_i, lambda_o) of A-15.
    pub fn lambdas(self) -> (f64, f64) {
        match self {
            RacewayControl::Outer => (0.0, 2.0),
            RacewayControl::Inner => (2.0, 0.0),
        }
    }
}

/// Sign of the raceway friction couple that balances the gyroscopic moment
/// in the ball equilibrium. See [`super::kinematics`] for the
/// derivation.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum GyroCoupleSign {
    /// Derived from the ball's spin and orbit directions: the friction force
    /// at the controlling contact times D/2 cancels the rate of change of the
    /// ball's angular momentum (moment balance about the ball centre).
    #[default]
    Derived,
    /// The opposite sign, as printed in docs/concepts/physics.md §3, (A-15)
    /// (Harris's form `- (Mg/D)(lambda_i cos a_i - lambda_o cos a_o)` in the
    /// axial balance).
    Reversed,
}

impl GyroCoupleSign {
    pub(crate) fn factor(self) -> f64 {
        match self {
            GyroCoupleSign::Derived => 1.0,
            GyroCoupleSign::Reversed => -1.0,
        }
    }
}

/// How the ring tilt (theta_x, theta_y) is treated.
///
/// The default holds the ring level ([`Tilt::held_level`]): in a machine the
/// shaft and the housing align the rings, which is also the Python default
/// (`misalignment_rad=0.0`). [`Tilt::Free`] is the option for a ring whose
/// tilt is solved from the applied moments (Python `misalignment_rad=None`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Tilt {
    /// The tilts are unknowns balanced by the applied moments Mx, My (full
    /// 5-DOF equilibrium; a ring under combined load without moment tilts).
    Free,
    /// The tilts are held at the given values (a ring held by a stiff shaft
    /// and housing, the usual 3-DOF bearing model and the default, level);
    /// the applied moments are ignored and the state reports the moments
    /// needed to hold the tilt.
    Fixed {
        /// Held inner-ring tilt about the x axis \[rad\].
        theta_x_rad: f64,
        /// Held inner-ring tilt about the y axis \[rad\].
        theta_y_rad: f64,
    },
}

impl Tilt {
    /// No tilt, held (seed A's axial/radial model); the default.
    pub fn held_level() -> Self {
        Tilt::Fixed {
            theta_x_rad: 0.0,
            theta_y_rad: 0.0,
        }
    }
}

impl Default for Tilt {
    /// Held level, as a shaft and housing hold the rings of a bearing in a
    /// machine (and as the Python package does by default).
    fn default() -> Self {
        Tilt::held_level()
    }
}

/// Options of the static and quasi-static solvers.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolveOptions {
    /// Effects in the high-speed model (centrifugal_force, gyroscopic_moment,
    /// ring_centrifugal_expansion). Default: all on.
    pub effects: EffectSet,
    /// Raceway control hypothesis. Default: outer.
    pub raceway_control: RacewayControl,
    /// Sign of the gyroscopic friction couple. Default: derived.
    pub gyro_couple_sign: GyroCoupleSign,
    /// Relative tolerance on the ring force balance (residual / max(|load|, 1 N)).
    pub tolerance: f64,
    /// Maximum Newton iterations of the ring equilibrium.
    pub max_iterations: usize,
    /// Thermal or fit offsets of the groove centres. Default zero.
    pub offsets: RacewayOffsets,
    /// Held or free ring tilt. Default: held level ([`Tilt::held_level`],
    /// the applied moments are then ignored and the state reports the
    /// moments that hold the ring); [`Tilt::Free`] solves the tilt from the
    /// applied moments.
    pub tilt: Tilt,
    /// Largest friction coefficient of the ball-raceway contacts available
    /// to hold the gyroscopic moment of a ball without centrifugal force
    /// (dimensionless): the friction couple is at most mu (Q_i + Q_o) D / 2
    /// (Coulomb), beyond which the ball slips gyroscopically (see
    /// `quasi_static::friction_couple`). Default 0.1, the upper end of the
    /// limiting traction coefficients of lubricated steel contacts (Harris &
    /// Kotzalas, Advanced Concepts of Bearing Technology, 5th ed., traction
    /// curves 0.03..0.1), so the full couple is kept wherever a lubricated
    /// contact could hold it. Ignored with the centrifugal force on (Jones's
    /// full couple, seed A).
    pub traction_coefficient: f64,
}

impl Default for SolveOptions {
    fn default() -> Self {
        SolveOptions {
            effects: EffectSet::all(),
            raceway_control: RacewayControl::Outer,
            gyro_couple_sign: GyroCoupleSign::Derived,
            tolerance: 1e-9,
            max_iterations: 100,
            offsets: RacewayOffsets::default(),
            tilt: Tilt::held_level(),
            traction_coefficient: 0.1,
        }
    }
}

/// External load on the inner ring in the usual three numbers.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BearingLoad {
    /// Axial load Fz \[N\] (positive loads the balls at positive contact angle).
    pub axial_n: f64,
    /// Radial load Fx \[N\].
    pub radial_n: f64,
    /// Tilting moment M_y about the y axis (in the plane of the radial load) [N m].
    pub moment_n_m: f64,
}

impl BearingLoad {
    /// Load from the axial force Fz \[N\], the radial force Fx \[N\] and the
    /// tilting moment M_y [N m] (note the argument order: axial first).
    pub fn new(axial_n: f64, radial_n: f64, moment_n_m: f64) -> Self {
        BearingLoad {
            axial_n,
            radial_n,
            moment_n_m,
        }
    }

    /// As [Fx, Fy, Fz, Mx, My] (N, N m).
    pub fn to_vector(self) -> [f64; 5] {
        [self.radial_n, 0.0, self.axial_n, 0.0, self.moment_n_m]
    }
}

/// State of one ball at the solved equilibrium.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BallState {
    /// Azimuth psi_j from the x axis \[rad\].
    pub azimuth_rad: f64,
    /// Normal load on the inner raceway Q_i \[N\].
    pub inner_load_n: f64,
    /// Normal load on the outer raceway Q_o \[N\].
    pub outer_load_n: f64,
    /// Inner contact angle alpha_i \[rad\].
    pub inner_contact_angle_rad: f64,
    /// Outer contact angle alpha_o \[rad\].
    pub outer_contact_angle_rad: f64,
    /// Hertz approach at the inner contact delta_i \[m\] (negative: gap).
    pub inner_deflection_m: f64,
    /// Hertz approach at the outer contact delta_o \[m\] (negative: gap).
    pub outer_deflection_m: f64,
    /// Ball centrifugal force Fc \[N\].
    pub centrifugal_force_n: f64,
    /// Gyroscopic moment Mg [N m].
    pub gyroscopic_moment_n_m: f64,
    /// Orbit (cage) speed omega_c [rad/s].
    pub orbit_speed_rad_s: f64,
    /// Ball speed about its own axis relative to the cage omega_b [rad/s].
    pub spin_speed_rad_s: f64,
    /// Attitude angle beta of the ball axis \[rad\].
    pub attitude_angle_rad: f64,
    /// Spin of the ball relative to the inner raceway about the contact normal [rad/s].
    pub inner_spin_rad_s: f64,
    /// Spin of the ball relative to the outer raceway about the contact normal [rad/s].
    pub outer_spin_rad_s: f64,
    /// Spin-to-roll ratio at the inner contact [-].
    pub inner_spin_to_roll: f64,
    /// Spin-to-roll ratio at the outer contact [-].
    pub outer_spin_to_roll: f64,
    /// Semi-major axis of the inner contact ellipse a_i \[m\].
    pub inner_semi_major_m: f64,
    /// Semi-major axis of the outer contact ellipse a_o \[m\].
    pub outer_semi_major_m: f64,
}

/// A solved bearing.
///
/// The vectors and the matrix are SI, the crate's convention, and carry the
/// names of their Python twins (`BearingSolution.displacement`,
/// `.applied_load`, and `.stiffness` for `stiffness_matrix`).
#[derive(Debug, Clone, PartialEq)]
pub struct BearingState {
    /// Inner-ring displacement [dx, dy, dz, theta_x, theta_y] in SI (m, rad),
    /// ISO convention (see [`super::model`]).
    pub displacement: [f64; 5],
    /// Applied load [Fx, Fy, Fz, Mx, My] in SI (N, N m); with a held tilt
    /// ([`Tilt::Fixed`], the default) Mx, My are the moments that hold it.
    pub applied_load: [f64; 5],
    /// Per-ball states, ball j at psi_j = 2 pi j / Z.
    pub balls: Vec<BallState>,
    /// Tangent stiffness K = -d(reaction)/dq, rows/columns ordered as q, in
    /// SI like everything in the crate: N/m, N/rad, N m/m, N m/rad by block.
    pub stiffness_matrix: [[f64; 5]; 5],
    /// Axial stiffness by the seed's formula (A-39, A-40) [N/m].
    pub axial_stiffness_seed_n_per_m: f64,
    /// Radial stiffness by the seed's formula (A-41, A-42) [N/m].
    pub radial_stiffness_seed_n_per_m: f64,
    /// Ring Newton iterations used.
    pub iterations: usize,
    /// Final relative force residual.
    pub residual: f64,
    /// Inner-ring speed \[rpm\].
    pub speed_rpm: f64,
}

impl BearingState {
    /// The tangent stiffness under its former name (SI); use the field
    /// [`BearingState::stiffness_matrix`].
    #[deprecated(
        since = "0.2.0",
        note = "use the field `stiffness_matrix` (SI, as everything in the crate)"
    )]
    pub fn stiffness_matrix_si(&self) -> [[f64; 5]; 5] {
        self.stiffness_matrix
    }

    /// The inner-ring displacement under its former name; use the field
    /// [`BearingState::displacement`].
    #[deprecated(since = "0.2.0", note = "use the field `displacement` (m, rad)")]
    pub fn displacement_m_rad(&self) -> [f64; 5] {
        self.displacement
    }

    /// The seed formula's axial stiffness under its former name \[N/m\].
    #[deprecated(since = "0.2.0", note = "use the field `axial_stiffness_seed_n_per_m`")]
    pub fn axial_stiffness_n_per_m(&self) -> f64 {
        self.axial_stiffness_seed_n_per_m
    }

    /// The seed formula's radial stiffness under its former name \[N/m\].
    #[deprecated(since = "0.2.0", note = "use the field `radial_stiffness_seed_n_per_m`")]
    pub fn radial_stiffness_n_per_m(&self) -> f64 {
        self.radial_stiffness_seed_n_per_m
    }

    /// Radial displacement of the inner ring, sqrt(dx^2 + dy^2) \[um\], as
    /// Python's `BearingSolution.radial_displacement_um`.
    pub fn radial_displacement_um(&self) -> f64 {
        self.displacement[0].hypot(self.displacement[1]) * 1e6
    }

    /// Axial displacement of the inner ring dz \[um\], as Python's
    /// `BearingSolution.axial_displacement_um`.
    pub fn axial_displacement_um(&self) -> f64 {
        self.displacement[2] * 1e6
    }

    /// Ring tilt sqrt(theta_x^2 + theta_y^2) \[rad\], as Python's
    /// `BearingSolution.tilt_rad`.
    pub fn tilt_rad(&self) -> f64 {
        self.displacement[3].hypot(self.displacement[4])
    }

    /// The state if every number in it is finite, else a convergence error
    /// naming `solver` (never a silent NaN; e.g. the quasi-static model is
    /// ill-posed for balls out of contact at a vanishing speed).
    pub fn checked(self, solver: &str) -> crate::error::Result<Self> {
        let ball_ok = |b: &BallState| {
            [
                b.inner_load_n,
                b.outer_load_n,
                b.inner_contact_angle_rad,
                b.outer_contact_angle_rad,
                b.inner_deflection_m,
                b.outer_deflection_m,
                b.centrifugal_force_n,
                b.gyroscopic_moment_n_m,
                b.orbit_speed_rad_s,
                b.spin_speed_rad_s,
                b.attitude_angle_rad,
                b.inner_spin_rad_s,
                b.outer_spin_rad_s,
                b.inner_spin_to_roll,
                b.outer_spin_to_roll,
                b.inner_semi_major_m,
                b.outer_semi_major_m,
            ]
            .iter()
            .all(|v| v.is_finite())
        };
        let finite = self.displacement.iter().all(|v| v.is_finite())
            && self.stiffness_matrix.iter().flatten().all(|v| v.is_finite())
            && self.axial_stiffness_seed_n_per_m.is_finite()
            && self.radial_stiffness_seed_n_per_m.is_finite()
            && self.balls.iter().all(ball_ok);
        if finite {
            Ok(self)
        } else {
            Err(crate::error::Error::convergence(
                format!("{solver} (non-finite state: balls out of contact make the model ill-posed here)"),
                self.iterations,
                f64::INFINITY,
                0.0,
            ))
        }
    }

    /// Largest inner contact load \[N\].
    pub fn max_inner_load_n(&self) -> f64 {
        self.balls.iter().map(|b| b.inner_load_n).fold(0.0, f64::max)
    }

    /// Angular extent of the loaded zone: 2 pi times the fraction of balls
    /// whose inner contact carries load \[rad\].
    pub fn loaded_zone_rad(&self) -> f64 {
        let n = self.balls.iter().filter(|b| b.inner_load_n > 0.0).count();
        2.0 * std::f64::consts::PI * n as f64 / self.balls.len() as f64
    }
}
