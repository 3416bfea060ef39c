//! Unit conversions. The core is SI throughout (m, N, Pa, rad, s, W, K);
//! these helpers sit at the boundaries (configuration files, Python layer).

use std::f64::consts::PI;

/// Millimetres to metres.
pub const MM: f64 = 1e-3;
/// Micrometres to metres.
pub const UM: f64 = 1e-6;
/// Megapascals to pascals.
pub const MPA: f64 = 1e6;
/// Gigapascals to pascals.
pub const GPA: f64 = 1e9;

/// Shaft speed in rpm to angular speed in rad/s.
#[inline]
pub fn rpm_to_rad_s(rpm: f64) -> f64 {
    rpm * PI / 30.0
}

/// Angular speed in rad/s to rpm.
#[inline]
pub fn rad_s_to_rpm(w: f64) -> f64 {
    w * 30.0 / PI
}

/// Degrees to radians.
#[inline]
pub fn deg(d: f64) -> f64 {
    d.to_radians()
}

#[cfg(test)]
mod tests {
    use super::*;
    #[test]
    fn rpm_round_trip() {
        assert!((rpm_to_rad_s(30.0) - PI).abs() < 1e-15);
        assert!((rad_s_to_rpm(rpm_to_rad_s(12_345.0)) - 12_345.0).abs() < 1e-9);
    }
}
