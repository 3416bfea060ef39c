//! Named, switchable physical effects. Every term that a model can include
//! or leave out is an [`Effect`]; an [`EffectSet`] says which are on. Names
//! are the public, stable identifiers (Python `effects=[...]`, TOML, the
//! discrepancy workflow).

use crate::error::{Error, Result};

/// A physical effect a model may include.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
#[repr(u8)]
pub enum Effect {
    /// Ball centrifugal force Fc = m dm omega_c^2 / 2.
    CentrifugalForce = 0,
    /// Ball gyroscopic moment Mg = J omega_b omega_c sin(beta).
    GyroscopicMoment = 1,
    /// Centrifugal expansion of the rotating inner ring and shaft.
    RingCentrifugalExpansion = 2,
    /// Thermal radial (and axial) growth of the shaft.
    ThermalExpansionShaft = 3,
    /// Thermal growth of the inner ring.
    ThermalExpansionInnerRing = 4,
    /// Thermal growth of the outer ring.
    ThermalExpansionOuterRing = 5,
    /// Thermal growth of the balls.
    ThermalExpansionBalls = 6,
    /// Thermal radial (and axial) growth of the housing.
    ThermalExpansionHousing = 7,
    /// Lubricant viscosity evaluated at the operating temperature (ASTM D341).
    TemperatureDependentViscosity = 8,
    /// Unbalanced magnetic pull of the eccentric motor rotor: negative
    /// radial stiffness and static pull (src/rotor/magnetic_pull.rs).
    UnbalancedMagneticPull = 9,
    /// Spin friction heat at the ball-raceway contacts.
    SpinFriction = 10,
    /// Axial thermal growth of the shaft relative to the housing between
    /// the bearing sets compressing a spring preload pack (src/spindle).
    PreloadChangeFromAxialGrowth = 11,
}

impl Effect {
    /// Every effect, in registry order.
    pub const ALL: [Effect; 12] = [
        Effect::CentrifugalForce,
        Effect::GyroscopicMoment,
        Effect::RingCentrifugalExpansion,
        Effect::ThermalExpansionShaft,
        Effect::ThermalExpansionInnerRing,
        Effect::ThermalExpansionOuterRing,
        Effect::ThermalExpansionBalls,
        Effect::ThermalExpansionHousing,
        Effect::TemperatureDependentViscosity,
        Effect::UnbalancedMagneticPull,
        Effect::SpinFriction,
        Effect::PreloadChangeFromAxialGrowth,
    ];

    /// The models an effect can act in: `"bearing"` (single-bearing
    /// quasi-statics, src/bearing, and the coupled single-bearing thermal
    /// model, src/thermal), `"spindle"` (the coupled spindle, src/spindle)
    /// and `"rotor"` (the rotor dynamics on solver rows, src/rotor).
    pub const MODELS: [&'static str; 3] = ["bearing", "spindle", "rotor"];

    /// The public name.
    pub fn name(self) -> &'static str {
        match self {
            Effect::CentrifugalForce => "centrifugal_force",
            Effect::GyroscopicMoment => "gyroscopic_moment",
            Effect::RingCentrifugalExpansion => "ring_centrifugal_expansion",
            Effect::ThermalExpansionShaft => "thermal_expansion_shaft",
            Effect::ThermalExpansionInnerRing => "thermal_expansion_inner_ring",
            Effect::ThermalExpansionOuterRing => "thermal_expansion_outer_ring",
            Effect::ThermalExpansionBalls => "thermal_expansion_balls",
            Effect::ThermalExpansionHousing => "thermal_expansion_housing",
            Effect::TemperatureDependentViscosity => "temperature_dependent_viscosity",
            Effect::UnbalancedMagneticPull => "unbalanced_magnetic_pull",
            Effect::SpinFriction => "spin_friction",
            Effect::PreloadChangeFromAxialGrowth => "preload_change_from_axial_growth",
        }
    }

    /// One-line physical description.
    pub fn description(self) -> &'static str {
        match self {
            Effect::CentrifugalForce => "ball centrifugal force pressing balls on the outer raceway (A-16)",
            Effect::GyroscopicMoment => {
                "ball gyroscopic moment, resisted by raceway friction under raceway control (A-17..A-19)"
            }
            Effect::RingCentrifugalExpansion => {
                "radial growth of the rotating inner ring and shaft by centrifugal stress (A-10)"
            }
            Effect::ThermalExpansionShaft => {
                "thermal growth of the shaft, pressed into the inner ring through the fit and axially (A-33..A-37)"
            }
            Effect::ThermalExpansionInnerRing => {
                "thermal growth of the inner ring moving the inner groove centre outwards (A-33..A-36)"
            }
            Effect::ThermalExpansionOuterRing => {
                "thermal growth of the outer ring moving the outer groove centre outwards (A-33..A-36)"
            }
            Effect::ThermalExpansionBalls => {
                "thermal growth of the balls shrinking the free groove-centre gap (f_i + f_o - 1) D (A-34, A-36)"
            }
            Effect::ThermalExpansionHousing => {
                "thermal growth of the housing, pulling the outer ring through the fit and axially (A-33..A-37)"
            }
            Effect::TemperatureDependentViscosity => {
                "oil viscosity at the operating temperature in the viscous friction moment (ASTM D341, A-21)"
            }
            Effect::UnbalancedMagneticPull => {
                "unbalanced magnetic pull of the eccentric motor rotor in its air gap (negative stiffness, static pull)"
            }
            Effect::SpinFriction => {
                "spin friction heat (3/8) mu_s Q a E |omega_s| per ball-raceway contact (A-22, A-23)"
            }
            Effect::PreloadChangeFromAxialGrowth => {
                "axial thermal growth of the shaft relative to the housing between the bearing sets compresses \
                 the preload spring pack (spring preload: force change = rate x growth; spindle model only)"
            }
        }
    }

    /// The models (of [`Effect::MODELS`]) that read this effect, as the
    /// code does: the ball solver's terms act wherever bearings are solved
    /// (every model), the thermal ones where a temperature field exists
    /// (bearing, spindle; the rotor takes its thermal raceway offsets as
    /// input). `spin_friction` switches the spin heat of the single-bearing
    /// and the spindle thermal models.
    pub fn models(self) -> &'static [&'static str] {
        const ALL_MODELS: &[&str] = &["bearing", "spindle", "rotor"];
        const THERMAL: &[&str] = &["bearing", "spindle"];
        match self {
            // src/bearing/quasi_static.rs (SpeedContext), used by the
            // spindle pairs and the rotor's preloaded rows alike.
            Effect::CentrifugalForce | Effect::GyroscopicMoment | Effect::RingCentrifugalExpansion => ALL_MODELS,
            // src/thermal/expansion.rs thermal_offsets (bearing thermal
            // model, spindle pairs) and the spindle's axial growth.
            Effect::ThermalExpansionShaft
            | Effect::ThermalExpansionInnerRing
            | Effect::ThermalExpansionOuterRing
            | Effect::ThermalExpansionBalls
            | Effect::ThermalExpansionHousing => THERMAL,
            // src/thermal/coupled.rs and src/spindle/coupled.rs heat sources.
            Effect::TemperatureDependentViscosity => THERMAL,
            // src/rotor/spindle_vibration.rs; its static pull loads the
            // spindle's bearing pairs (src/spindle/shaft_loads.rs).
            Effect::UnbalancedMagneticPull => &["spindle", "rotor"],
            // src/thermal/coupled.rs and src/spindle/coupled.rs heat sources.
            Effect::SpinFriction => THERMAL,
            // src/spindle/coupled.rs evaluate.
            Effect::PreloadChangeFromAxialGrowth => &["spindle"],
        }
    }

    /// Parse a public name.
    pub fn from_name(name: &str) -> Result<Effect> {
        Effect::ALL.iter().copied().find(|e| e.name() == name).ok_or_else(|| {
            let known: Vec<_> = Effect::ALL.iter().map(|e| e.name()).collect();
            Error::config("effects", name, format!("unknown effect; known: {}", known.join(", ")))
        })
    }

    #[inline]
    fn bit(self) -> u64 {
        1u64 << (self as u8)
    }
}

/// A set of effects (bit set; cheap to copy into hot loops).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct EffectSet(u64);

impl Default for EffectSet {
    /// All effects on.
    fn default() -> Self {
        Self::all()
    }
}

impl EffectSet {
    /// Every effect on.
    pub fn all() -> Self {
        EffectSet(Effect::ALL.iter().fold(0, |m, e| m | e.bit()))
    }
    /// No effect on (the plain static model).
    pub fn none() -> Self {
        EffectSet(0)
    }
    /// Is `e` on?
    #[inline]
    pub fn has(self, e: Effect) -> bool {
        self.0 & e.bit() != 0
    }
    /// With `e` switched on.
    pub fn with(self, e: Effect) -> Self {
        EffectSet(self.0 | e.bit())
    }
    /// With `e` switched off.
    pub fn without(self, e: Effect) -> Self {
        EffectSet(self.0 & !e.bit())
    }
    /// Exactly the named effects.
    pub fn from_names<S: AsRef<str>>(names: &[S]) -> Result<Self> {
        names
            .iter()
            .try_fold(Self::none(), |s, n| Ok(s.with(Effect::from_name(n.as_ref())?)))
    }
    /// Names of the effects that are on, in registry order.
    pub fn names(self) -> Vec<&'static str> {
        Effect::ALL.iter().filter(|e| self.has(**e)).map(|e| e.name()).collect()
    }
}

/// Serialised as the list of effect names (stable across versions of the
/// bit layout).
impl serde::Serialize for EffectSet {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> std::result::Result<S::Ok, S::Error> {
        serializer.collect_seq(self.names())
    }
}

impl<'de> serde::Deserialize<'de> for EffectSet {
    fn deserialize<D: serde::Deserializer<'de>>(deserializer: D) -> std::result::Result<Self, D::Error> {
        let names = <Vec<String> as serde::Deserialize>::deserialize(deserializer)?;
        EffectSet::from_names(&names).map_err(serde::de::Error::custom)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn serde_uses_names_and_round_trips() {
        let s = EffectSet::none().with(Effect::ALL[0]).with(Effect::ALL[2]);
        let text = serde_json::to_string(&s).unwrap();
        assert_eq!(
            text,
            format!("[\"{}\",\"{}\"]", Effect::ALL[0].name(), Effect::ALL[2].name())
        );
        assert_eq!(serde_json::from_str::<EffectSet>(&text).unwrap(), s);
        assert!(serde_json::from_str::<EffectSet>("[\"no_such_effect\"]").is_err());
    }

    #[test]
    fn names_round_trip_and_unknown_rejected() {
        for e in Effect::ALL {
            assert_eq!(Effect::from_name(e.name()).unwrap(), e);
        }
        let err = EffectSet::from_names(&["centrifugal_force", "magic"]).unwrap_err();
        assert!(err.to_string().contains("magic"));
        let s = EffectSet::from_names(&["gyroscopic_moment"]).unwrap();
        assert!(s.has(Effect::GyroscopicMoment) && !s.has(Effect::CentrifugalForce));
        assert_eq!(EffectSet::all().names().len(), Effect::ALL.len());
        assert_eq!(
            EffectSet::all().without(Effect::CentrifugalForce).names().len(),
            Effect::ALL.len() - 1
        );
    }

    #[test]
    fn every_effect_acts_in_a_known_model() {
        for e in Effect::ALL {
            assert!(!e.models().is_empty(), "{} acts nowhere", e.name());
            for m in e.models() {
                assert!(Effect::MODELS.contains(m), "{}: unknown model {m}", e.name());
            }
        }
        // Registry order is the discriminant order (one bit per effect).
        for (i, e) in Effect::ALL.iter().enumerate() {
            assert_eq!(*e as usize, i, "{}", e.name());
        }
        let e = Effect::from_name("preload_change_from_axial_growth").unwrap();
        assert_eq!(e, Effect::PreloadChangeFromAxialGrowth);
        assert_eq!(e.models(), &["spindle"]);
        assert_eq!(Effect::UnbalancedMagneticPull.models(), &["spindle", "rotor"]);
    }
}
