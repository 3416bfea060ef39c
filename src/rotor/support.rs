//! Bearings as seen by the rotor: linearised 5x5 stiffness and damping at a
//! node, possibly speed dependent (a constant, a speed table, or any
//! closure, e.g. the thermally coupled bearing solver).
//!
//! The 5x5 order is the bearing solver's ring-displacement order
//! (docs/concepts/physics.md §6): [delta_x, delta_y, delta_z, theta_x,
//! theta_y]. The rotor model is lateral (4 DOF per node) and uses rows/columns [0, 1, 3, 4];
//! the axial entry is carried for completeness and for the axial model of
//! the spindle, not used by the lateral matrices.
//!
//! Rotation signs (they matter for the force-tilt coupling terms): right-hand
//! rule about the axes, so theta_y turns +z towards +x (theta_y = +du_x/dz)
//! and theta_x turns +z towards -y (theta_x = -du_y/dz); the moment row of
//! theta_x is M_x, of theta_y is M_y. A bearing model with another
//! convention must flip the signs of its coupling terms before use.

use std::fmt;
use std::sync::Arc;

use nalgebra::{Matrix4, Matrix5};

use crate::error::{finite, non_negative, Error, Result};

/// Linearised bearing coefficients at one operating point. SI blocks:
/// force/translation [N/m], force/rotation [N/rad], moment/rotation
/// [N m/rad]; damping the same per unit velocity [.. s].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BearingCoefficients {
    /// Stiffness, order [x, y, z, theta_x, theta_y], SI blocks.
    pub stiffness_si: Matrix5<f64>,
    /// Damping, same order, SI blocks (N s/m, N s, N m s/rad).
    pub damping_si: Matrix5<f64>,
}

/// Rows/columns of the 5x5 matrices that are lateral rotor DOFs [x, y, tx, ty].
pub const LATERAL_OF_FIVE: [usize; 4] = [0, 1, 3, 4];

impl BearingCoefficients {
    /// Isotropic diagonal coefficients: radial stiffness in x and y, axial
    /// stiffness, tilt stiffness about x and y, and a radial damping.
    pub fn diagonal(
        radial_stiffness_n_per_m: f64,
        axial_stiffness_n_per_m: f64,
        tilt_stiffness_n_m_per_rad: f64,
        radial_damping_n_s_per_m: f64,
    ) -> Result<Self> {
        non_negative("radial_stiffness_n_per_m", radial_stiffness_n_per_m)?;
        non_negative("axial_stiffness_n_per_m", axial_stiffness_n_per_m)?;
        non_negative("tilt_stiffness_n_m_per_rad", tilt_stiffness_n_m_per_rad)?;
        non_negative("radial_damping_n_s_per_m", radial_damping_n_s_per_m)?;
        let k = Matrix5::from_diagonal(&nalgebra::Vector5::new(
            radial_stiffness_n_per_m,
            radial_stiffness_n_per_m,
            axial_stiffness_n_per_m,
            tilt_stiffness_n_m_per_rad,
            tilt_stiffness_n_m_per_rad,
        ));
        let c = Matrix5::from_diagonal(&nalgebra::Vector5::new(
            radial_damping_n_s_per_m,
            radial_damping_n_s_per_m,
            0.0,
            0.0,
            0.0,
        ));
        Ok(BearingCoefficients {
            stiffness_si: k,
            damping_si: c,
        })
    }

    /// The lateral 4x4 stiffness in rotor order [x, y, theta_x, theta_y].
    pub fn lateral_stiffness(&self) -> Matrix4<f64> {
        lateral(&self.stiffness_si)
    }

    /// The lateral 4x4 damping in rotor order.
    pub fn lateral_damping(&self) -> Matrix4<f64> {
        lateral(&self.damping_si)
    }

    /// Every entry finite?
    pub fn validate(&self, name: &str) -> Result<()> {
        for v in self.stiffness_si.iter() {
            finite(&format!("bearings[{name}].stiffness_si"), *v)?;
        }
        for v in self.damping_si.iter() {
            finite(&format!("bearings[{name}].damping_si"), *v)?;
        }
        Ok(())
    }
}

fn lateral(m: &Matrix5<f64>) -> Matrix4<f64> {
    Matrix4::from_fn(|i, j| m[(LATERAL_OF_FIVE[i], LATERAL_OF_FIVE[j])])
}

/// A source of bearing coefficients as a function of shaft speed.
pub trait BearingModel: Send + Sync {
    /// Coefficients at shaft speed `speed_rpm`.
    fn coefficients(&self, speed_rpm: f64) -> Result<BearingCoefficients>;
}

impl BearingModel for BearingCoefficients {
    fn coefficients(&self, _speed_rpm: f64) -> Result<BearingCoefficients> {
        Ok(*self)
    }
}

/// Any closure `Fn(speed_rpm) -> Result<BearingCoefficients>` is a bearing model.
impl<F> BearingModel for F
where
    F: Fn(f64) -> Result<BearingCoefficients> + Send + Sync,
{
    fn coefficients(&self, speed_rpm: f64) -> Result<BearingCoefficients> {
        self(speed_rpm)
    }
}

/// Coefficients tabulated against speed, linearly interpolated and held
/// constant outside the table.
#[derive(Debug, Clone, PartialEq)]
pub struct SpeedTable {
    speeds_rpm: Vec<f64>,
    values: Vec<BearingCoefficients>,
}

impl SpeedTable {
    /// A table; speeds must be finite and strictly increasing.
    pub fn new(speeds_rpm: Vec<f64>, values: Vec<BearingCoefficients>) -> Result<Self> {
        if speeds_rpm.is_empty() || speeds_rpm.len() != values.len() {
            return Err(Error::config(
                "speeds_rpm",
                speeds_rpm.len(),
                format!("need one speed per coefficient set ({} given)", values.len()),
            ));
        }
        for w in speeds_rpm.windows(2) {
            if w[1].partial_cmp(&w[0]) != Some(std::cmp::Ordering::Greater) {
                return Err(Error::config("speeds_rpm", w[1], "must be strictly increasing"));
            }
        }
        for s in &speeds_rpm {
            finite("speeds_rpm", *s)?;
        }
        Ok(SpeedTable { speeds_rpm, values })
    }
}

impl BearingModel for SpeedTable {
    fn coefficients(&self, speed_rpm: f64) -> Result<BearingCoefficients> {
        finite("speed_rpm", speed_rpm)?;
        let s = &self.speeds_rpm;
        let n = s.len();
        if speed_rpm <= s[0] {
            return Ok(self.values[0]);
        }
        if speed_rpm >= s[n - 1] {
            return Ok(self.values[n - 1]);
        }
        let i = s.partition_point(|&x| x <= speed_rpm) - 1;
        let t = (speed_rpm - s[i]) / (s[i + 1] - s[i]);
        let (a, b) = (&self.values[i], &self.values[i + 1]);
        Ok(BearingCoefficients {
            stiffness_si: a.stiffness_si * (1.0 - t) + b.stiffness_si * t,
            damping_si: a.damping_si * (1.0 - t) + b.damping_si * t,
        })
    }
}

/// A bearing placed on the shaft.
#[derive(Clone)]
pub struct BearingSupport {
    /// Label used in error messages (e.g. `7009C_front_A`).
    pub name: String,
    /// Axial position of the bearing centre (load centre) from the shaft's left end \[m\].
    pub position_m: f64,
    /// Source of the linearised coefficients as a function of shaft speed.
    pub model: Arc<dyn BearingModel>,
}

impl fmt::Debug for BearingSupport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("BearingSupport")
            .field("name", &self.name)
            .field("position_m", &self.position_m)
            .finish_non_exhaustive()
    }
}

impl BearingSupport {
    /// A bearing at `position_m` with the given model.
    pub fn new(name: impl Into<String>, position_m: f64, model: Arc<dyn BearingModel>) -> Self {
        BearingSupport {
            name: name.into(),
            position_m,
            model,
        }
    }

    /// Coefficients at `speed_rpm`, checked finite.
    pub fn coefficients(&self, speed_rpm: f64) -> Result<BearingCoefficients> {
        let c = self.model.coefficients(speed_rpm)?;
        c.validate(&self.name)?;
        Ok(c)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_interpolates_linearly_and_clamps() {
        let a = BearingCoefficients::diagonal(1e8, 2e7, 0.0, 100.0).unwrap();
        let b = BearingCoefficients::diagonal(2e8, 4e7, 0.0, 300.0).unwrap();
        let t = SpeedTable::new(vec![0.0, 10_000.0], vec![a, b]).unwrap();
        let mid = t.coefficients(2_500.0).unwrap();
        assert!((mid.stiffness_si[(0, 0)] - 1.25e8).abs() < 1.0);
        assert!((mid.lateral_damping()[(1, 1)] - 150.0).abs() < 1e-9);
        assert_eq!(t.coefficients(50_000.0).unwrap(), b);
        assert!(SpeedTable::new(vec![1.0, 1.0], vec![a, b]).is_err());
        assert!(BearingCoefficients::diagonal(-1.0, 0.0, 0.0, 0.0).is_err());
    }

    #[test]
    fn lateral_block_skips_axial() {
        let mut k = Matrix5::zeros();
        for i in 0..5 {
            k[(i, i)] = (i + 1) as f64;
        }
        let c = BearingCoefficients {
            stiffness_si: k,
            damping_si: Matrix5::zeros(),
        };
        let l = c.lateral_stiffness();
        assert_eq!([l[(0, 0)], l[(1, 1)], l[(2, 2)], l[(3, 3)]], [1.0, 2.0, 4.0, 5.0]);
    }
}
