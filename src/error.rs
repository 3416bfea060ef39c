//! The crate's one error type. `src/python/errors.rs` maps each variant to a
//! Python exception in the `thermobear.ThermobearError` hierarchy.

use thiserror::Error;

/// Result alias used throughout the crate.
pub type Result<T> = std::result::Result<T, Error>;

/// Everything that can go wrong in the crate: bad input, a solver that did
/// not converge, a runaway, unusable data, or an interrupt.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum Error {
    /// A parameter or configuration value that is not physical or not allowed.
    /// `field` names the parameter as the user wrote it (with its unit suffix).
    #[error("invalid {field} = {value}: {reason}")]
    Config {
        /// Parameter name, with its unit suffix (e.g. `ball_diameter_mm`).
        field: String,
        /// The rejected value as text.
        value: String,
        /// Why the value is rejected (e.g. "must be greater than zero").
        reason: String,
    },
    /// A system-description file that cannot be parsed (syntax, unknown key, type).
    #[error("system description: {0}")]
    Parse(String),
    /// An iterative solver stopped before meeting its tolerance.
    #[error(
        "{solver} did not converge after {iterations} iterations: residual {residual:.3e} (tolerance {tolerance:.1e})"
    )]
    Convergence {
        /// Name of the solver that gave up (e.g. "quasi-static").
        solver: String,
        /// Iterations spent.
        iterations: usize,
        /// Residual at the last iterate, in the solver's own measure.
        residual: f64,
        /// The tolerance it had to meet, same measure as `residual`.
        tolerance: f64,
    },
    /// Heat and preload grow together without bound (thermo-mechanical runaway).
    #[error("thermal runaway: {0}")]
    ThermalRunaway(String),
    /// Measured data that cannot be used (unknown quantity, missing column, units).
    #[error("measured data: {0}")]
    Data(String),
    /// The caller asked to stop (Ctrl-C from Python).
    #[error("interrupted")]
    Interrupted,
}

impl Error {
    /// Build a [`Error::Config`] naming the field, its value and why it is rejected.
    pub fn config(field: impl Into<String>, value: impl std::fmt::Display, reason: impl Into<String>) -> Self {
        Error::Config {
            field: field.into(),
            value: short_number(value.to_string()),
            reason: reason.into(),
        }
    }

    /// Build a [`Error::Convergence`].
    pub fn convergence(solver: impl Into<String>, iterations: usize, residual: f64, tolerance: f64) -> Self {
        Error::Convergence {
            solver: solver.into(),
            iterations,
            residual,
            tolerance,
        }
    }
}

/// A long number written in full (`1e300` as 301 digits) in exponent form;
/// any other text unchanged.
fn short_number(text: String) -> String {
    if text.len() > 20 {
        if let Ok(x) = text.parse::<f64>() {
            return format!("{x:e}");
        }
    }
    text
}

/// Check that a value is finite; name the field otherwise.
pub fn finite(field: &str, value: f64) -> Result<f64> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::config(field, value, "must be a finite number"))
    }
}

/// Check that a value is finite and strictly positive.
pub fn positive(field: &str, value: f64) -> Result<f64> {
    finite(field, value)?;
    if value > 0.0 {
        Ok(value)
    } else {
        Err(Error::config(field, value, "must be greater than zero"))
    }
}

/// Check that a value is finite and not negative.
pub fn non_negative(field: &str, value: f64) -> Result<f64> {
    finite(field, value)?;
    if value >= 0.0 {
        Ok(value)
    } else {
        Err(Error::config(field, value, "must not be negative"))
    }
}

/// Check that a value lies in the closed interval [lo, hi].
pub fn in_range(field: &str, value: f64, lo: f64, hi: f64) -> Result<f64> {
    finite(field, value)?;
    if value >= lo && value <= hi {
        Ok(value)
    } else {
        Err(Error::config(field, value, format!("must lie in [{lo}, {hi}]")))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn messages_name_field_and_value() {
        let e = positive("ball_diameter_mm", -1.0).unwrap_err();
        let s = e.to_string();
        assert!(s.contains("ball_diameter_mm") && s.contains("-1"), "{s}");
        let e = finite("speed_rpm", f64::NAN).unwrap_err();
        assert!(e.to_string().contains("NaN"));
        let e = Error::config("axial_n", 1e300, "too large");
        assert_eq!(e.to_string(), "invalid axial_n = 1e300: too large");
        let e = Error::convergence("quasi-static", 50, 1.5e-3, 1e-9);
        assert!(e.to_string().contains("1.500e-3"));
    }
}
