//! Radial loads of the two bearing pairs from the forces on the spindle
//! shaft: statics of a rigid shaft on two simple supports (the pair
//! centres), as for the nose load of [`crate::spindle::Spindle`].
//!
//! A radial force F at axial position c (measured from the front pair
//! centre towards the rear pair, negative in front of the front pair) on a
//! rigid shaft supported at c = 0 (front) and c = L (rear) loads the pairs
//! with (force balance and moment balance about either support)
//!
//! ```text
//! F_front = F (L - c) / L,   F_rear = F c / L,   F_front + F_rear = F,
//! F_rear L = F c   (moments about the front support).
//! ```
//!
//! The nose load sits at c = -a (front F (1 + a/L), rear -F a/L).
//!
//! # Unbalanced magnetic pull (UMP) on the shaft
//!
//! The rotor core sits statically eccentric in the stator bore, so the
//! air gap pulls it towards the narrow side with the constant force
//! F = k_ump e_static, k_ump = pi R L B0^2 / (mu0 g0) (the linear model of
//! [`crate::rotor::UnbalancedMagneticPull`]). The thermal spindle model
//! applies this static pull at the rotor-core centre and shares it between
//! the pairs by the lever rule above; the negative stiffness k_ump acting
//! on the shaft's own displacement at the core (a few um against the
//! 30 um eccentricity of the seed B preset) is left out.
//!
//! Direction: the static eccentricity's direction is set by the machining
//! and assembly of stator and rotor, unrelated to the working load at the
//! nose. We put the pull along +y, perpendicular to the nose load (+x), so
//! the two add as perpendicular components of each pair's radial load
//! (|F_r| = hypot(F_x, F_y), the radial load of the Palmgren M1, A-20). A
//! pull parallel to the nose load would add to (or subtract from) it
//! instead; the perpendicular choice is the middle case.

use crate::error::{finite, Error, Result};
use crate::rotor::presets::{seed_b_spindle, SpindleParameters, FRONT_BEARING_POSITIONS_M, REAR_BEARING_POSITIONS_M};
use crate::rotor::UnbalancedMagneticPull;

/// Loads carried by the front and rear pairs, at each pair centre, of a
/// radial force `force_n` at `position_from_front_m` on a rigid shaft whose
/// pair centres are `span_m` apart (lever rule, module docs) \[N\].
pub fn lever_rule_n(force_n: f64, position_from_front_m: f64, span_m: f64) -> Result<(f64, f64)> {
    finite("radial_force_n", force_n)?;
    finite("position_from_front_m", position_from_front_m)?;
    if !(span_m.is_finite() && span_m > 0.0) {
        return Err(Error::config("span_m", span_m, "the pair centres must be apart"));
    }
    let rear = force_n * position_from_front_m / span_m;
    Ok((force_n - rear, rear))
}

/// The static unbalanced magnetic pull of the motor rotor as a load on the
/// spindle shaft (module docs).
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct CoreMagneticPull {
    /// Air-gap data of the rotor core, the same struct (and for seed B the
    /// same numbers) as the rotor model's; its `position_m` is the rotor
    /// model's core node (z from the nose) and is not used here. The pull
    /// acts when the spindle's effects include
    /// `Effect::UnbalancedMagneticPull` (and `pull.enabled`).
    pub pull: UnbalancedMagneticPull,
    /// Axial distance from the front pair centre to the rotor-core centre,
    /// towards the rear pair \[m\].
    pub core_from_front_pair_m: f64,
}

/// Centre of a pair from its two row positions \[m\].
fn pair_centre_m(rows_m: [f64; 2]) -> f64 {
    0.5 * (rows_m[0] + rows_m[1])
}

impl CoreMagneticPull {
    /// Seed B: the rotor preset's air-gap data (src/rotor/presets.rs:
    /// R = 34.7 mm, L = 120 mm, g0 = 0.3 mm, B0 = 0.55 T RMS, e = 10 % of
    /// the gap) and its core position between the pairs. In the rotor
    /// preset the front pair centre is at z = 0.040 m (rows 0.032, 0.048),
    /// the rear pair centre at z = 0.300 m (rows 0.2925, 0.3075) and the
    /// UMP node at the core centre z = 0.170 m: (0.170 - 0.040) / 0.260 =
    /// 0.5 of the span, midway. The thermal model's pair centres are
    /// `span_m` apart (front + rear span); the core keeps the same fraction
    /// of it, so both models share the pull between the pairs alike.
    pub fn seed_b(span_m: f64) -> Result<Self> {
        let spec = seed_b_spindle(&SpindleParameters {
            magnetic_pull_enabled: true,
            ..SpindleParameters::default()
        })?;
        let pull = spec
            .magnetic_pull
            .ok_or_else(|| Error::config("magnetic_pull", "None", "the seed B rotor preset has no UMP data"))?;
        let (front, rear) = (
            pair_centre_m(FRONT_BEARING_POSITIONS_M),
            pair_centre_m(REAR_BEARING_POSITIONS_M),
        );
        let fraction = (pull.position_m - front) / (rear - front);
        let out = CoreMagneticPull {
            pull,
            core_from_front_pair_m: fraction * span_m,
        };
        out.validate()?;
        Ok(out)
    }

    /// Check the air-gap data and the position.
    pub fn validate(&self) -> Result<()> {
        self.pull.validate()?;
        finite("core_from_front_pair_m", self.core_from_front_pair_m)?;
        Ok(())
    }

    /// Static pull F = k_ump e_static along +y \[N\] (0 when `pull.enabled` is false).
    pub fn static_force_n(&self) -> f64 {
        self.pull.static_force_n()
    }

    /// The pull's share of the front and rear pairs (along +y) for pair
    /// centres `span_m` apart \[N\].
    pub fn pair_loads_n(&self, span_m: f64) -> Result<(f64, f64)> {
        lever_rule_n(self.static_force_n(), self.core_from_front_pair_m, span_m)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rotor::magnetic_pull::MU0_H_PER_M;
    use crate::rotor::presets::{AIR_GAP_M, ROTOR_CORE_OUTER_DIAMETER_M, ROTOR_CORE_SPAN_M};

    #[test]
    fn lever_rule_balances_forces_and_moments() {
        let (f, c, l) = (250.0, -0.06, 0.24);
        let (a, b) = lever_rule_n(f, c, l).unwrap();
        assert!((a + b - f).abs() < 1e-12 * f);
        // Moments about the front support: rear reaction x L = F x c.
        assert!((b * l - f * c).abs() < 1e-12 * f);
        // The nose-load closed form of the spindle: front F (1 + a/L), rear -F a/L.
        assert!((a - f * (1.0 + 0.06 / l)).abs() < 1e-12 * f);
        // A force at a support goes entirely into it.
        assert_eq!(lever_rule_n(f, 0.0, l).unwrap(), (f, 0.0));
        assert!(lever_rule_n(f, 0.1, 0.0).is_err());
        assert!(lever_rule_n(f64::NAN, 0.1, 0.2).is_err());
    }

    #[test]
    fn seed_b_pull_is_the_rotor_presets_closed_form_at_mid_span() {
        let u = CoreMagneticPull::seed_b(0.24).unwrap();
        // k = pi R L B0^2 / (mu0 g0) with R = 34.7 mm, L = 120 mm, B0 = 0.55 T,
        // g0 = 0.3 mm; e = 30 um.
        let (z0, z1) = ROTOR_CORE_SPAN_M;
        let k = std::f64::consts::PI * 0.5 * ROTOR_CORE_OUTER_DIAMETER_M * (z1 - z0) * 0.55 * 0.55
            / (MU0_H_PER_M * AIR_GAP_M);
        let f = k * 0.1 * AIR_GAP_M;
        assert!(
            (u.static_force_n() - f).abs() < 1e-9 * f,
            "{} vs {f}",
            u.static_force_n()
        );
        assert!(u.static_force_n() > 300.0 && u.static_force_n() < 330.0);
        // Core midway between the pairs: equal shares.
        assert!((u.core_from_front_pair_m - 0.12).abs() < 1e-12);
        let (a, b) = u.pair_loads_n(0.24).unwrap();
        assert!((a - b).abs() < 1e-9 * f && (a + b - f).abs() < 1e-9 * f);
    }
}
