//! The oil supply as a model input, the oil fraction of the bearing cavity
//! it gives at a speed, and the drag and churning losses that follow from
//! it (docs/concepts/physics.md §9, "Oil supply, cavity oil fraction and
//! drag", eqs. 9.10-9.16).
//!
//! * Jet, oil-air, oil-mist: the oil volume fraction X of the cavity
//!   mixture from the empirical correlation of Parker for jet-lubricated
//!   high-speed ball bearings (R. J. Parker, "Comparison of predicted and
//!   experimental thermal performance of angular-contact ball bearings",
//!   NASA TP-2275, 1984; used by Pinel, Signer & Zaretsky in NASA's
//!   high-speed small-bore bearing reports, 2001, and quoted by Harris &
//!   Kotzalas, *Rolling Bearing Analysis*, 5th ed., vol. 2, fluid drag):
//!   `X = 1e5 W^0.37 / (n dm^1.7)` with the oil flow W through the bearing
//!   in cm^3/min, the shaft speed n in rpm and the pitch diameter dm in mm
//!   ([`parker_cavity_oil_fraction`], eq. 9.10). The fraction grows with
//!   flow (exponent 0.37) and falls with speed (exponent 1) and size
//!   (exponent 1.7). The sources quote X as the share of the cavity held by
//!   oil; we read the number as a volume fraction (0..1): it then gives
//!   1-5 % for jet-lubricated bearings at DN 1-2.5 million, the range of the
//!   fixed fractions it replaces (a reading as a percentage would put less
//!   oil mass in the cavity than its air holds). Oil-air and oil-mist use
//!   the same correlation with their (far smaller) oil flow: an
//!   extrapolation below the jet flows it was fitted on, stated as such.
//! * Ball drag in the mixture ([`ball_drag_in_mixture_w`], eq. 9.12): each
//!   ball moves at v = dm omega_c / 2 through a mixture of density
//!   `rho_e = X rho_oil` and viscosity `mu_e = X mu_oil + (1 - X) mu_air`
//!   (volume-weighted, as Harris & Kotzalas' effective properties); the
//!   drag coefficient of a sphere at the mixture's Reynolds number
//!   `Re = rho_e v D / mu_e` ([`sphere_drag_coefficient`]); power
//!   `Z (1/2) C_D rho_e (pi D^2/4) v^3`. The drag of the air alone is not
//!   counted (zero oil gives zero drag): for the 6208 at 16,000 rpm it would
//!   add about 3 W, the same for every supply.
//! * Oil bath: the SKF catalogue's drag moment `M_drag = V_M K_ball dm^5 n^2`
//!   with `K_ball = i_rw K_z (d + D) / (D - d) 1e-12` (SKF General
//!   Catalogue 6000, 2006, "Drag losses in oil bath lubrication", pp.
//!   98-100; moment in N mm, dm in mm, n in rpm; [`skf_bath_drag_moment_n_m`],
//!   eq. 9.13). The catalogue gives V_M only as a diagram against H/dm,
//!   which we could not read; V_M at the reference level (oil to the middle
//!   of the lowest ball) is fitted on the SKF reference-speed set
//!   ([`SKF_BATH_DRAG_VM_REFERENCE`], fit in validation/), and its change
//!   with the level follows the immersed share of the circle of radius
//!   0.6 dm that SKF's later catalogue uses for the bath drag of rolling
//!   elements (SKF *Rolling bearings* PUB BU/P1 17000 EN, 2018, drag
//!   losses: t = 2 arccos((0.6 dm - H) / (0.6 dm))): `V_M(H) = V_M,ref
//!   s(H) / s(H_ref)`, `s = (t - sin t) / (2 pi)` ([`bath_immersion_share`]).
//! * Grease: the fill fraction of the free volume (default 0.3, SKF's
//!   usual initial fill of 30 % for bearings at speed). After the run-in
//!   the grease is pushed aside into the cage and side spaces (channelling)
//!   and the balls run in a clear track: the steady drag is taken as zero;
//!   no published correlation ties the fill to a steady drag.
//! * Churning of the rings and the cage: we found no published closed form
//!   for a ball bearing's ring and cage churning that we could check, so it
//!   is zero and kept as its own heat term (the split reports it).

use super::friction::Lubrication;
use crate::error::{finite, in_range, non_negative, positive, Error, Result};
use crate::units::rpm_to_rad_s;

/// Dynamic viscosity of air at 40-80 C [Pa s] (1.9e-5: 1.91e-5 at 40 C,
/// 2.08e-5 at 80 C; VDI Heat Atlas, properties of dry air), used only in
/// the mixture viscosity of the Reynolds number.
pub const AIR_DYNAMIC_VISCOSITY_PA_S: f64 = 1.9e-5;

/// V_M of the SKF bath drag (catalogue units) at the reference oil level,
/// oil up to the middle of the lowest ball: fitted on the SKF 62-series
/// reference-speed set: 4.28e-6 (validation/bath_drag_fit.md: 24 of 25
/// held-out bearings within 2 sigma, rms z 1.0; the catalogue's
/// diagram could not be read).
pub const SKF_BATH_DRAG_VM_REFERENCE: f64 = 4.28e-6;

/// Default grease fill: 30 % of the free volume (SKF's usual initial fill).
pub const DEFAULT_GREASE_FILL_FRACTION: f64 = 0.3;

/// How the oil reaches the bearing, with what an engineer knows of it.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum OilSupply {
    /// Circulating oil injected between the rings.
    Jet {
        /// Total oil flow into the bearing [cm^3/min].
        oil_flow_cm3_per_min: f64,
        /// Number of jets (>= 1; recorded, the correlation takes the total flow).
        jet_count: u32,
        /// Jet velocity [m/s], when known (recorded; not in the correlation).
        jet_velocity_m_per_s: Option<f64>,
    },
    /// Oil-air: metered oil carried by compressed air.
    OilAir {
        /// Oil volume delivered per hour [cm^3/h].
        oil_volume_cm3_per_h: f64,
        /// Carrier air flow [l/min] (the supplied mixture's fraction).
        air_flow_l_per_min: f64,
    },
    /// Oil mist: oil atomised into the air stream.
    OilMist {
        /// Oil volume delivered per hour [cm^3/h].
        oil_volume_cm3_per_h: f64,
        /// Carrier air flow [l/min].
        air_flow_l_per_min: f64,
    },
    /// Oil bath.
    OilBath {
        /// Static oil level above the lowest point of the lowest ball \[mm\];
        /// None: the middle of the lowest ball (ISO 15312 reference level).
        oil_level_mm: Option<f64>,
    },
    /// Grease packed in the bearing.
    Grease {
        /// Share of the free volume filled with grease (0..1).
        grease_fill_fraction: f64,
    },
}

/// The supply with its two calibratable tunings.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct SupplySettings {
    /// The supply.
    pub supply: OilSupply,
    /// Scale on the oil flow reaching the cavity (1: all of it).
    pub oil_flow_scale: f64,
    /// Exponent of the speed in the cavity fraction (Parker: 1).
    pub cavity_fraction_speed_exponent: f64,
}

impl SupplySettings {
    /// A supply with the published correlation untouched.
    pub fn new(supply: OilSupply) -> Self {
        SupplySettings {
            supply,
            oil_flow_scale: 1.0,
            cavity_fraction_speed_exponent: 1.0,
        }
    }

    /// Check every field (bad values name their field).
    pub fn validate(&self) -> Result<()> {
        in_range("oil_flow_scale", self.oil_flow_scale, 0.0, 100.0)?;
        in_range(
            "cavity_fraction_speed_exponent",
            self.cavity_fraction_speed_exponent,
            0.0,
            3.0,
        )?;
        match self.supply {
            OilSupply::Jet {
                oil_flow_cm3_per_min,
                jet_count,
                jet_velocity_m_per_s,
            } => {
                in_range("oil_flow_cm3_per_min", oil_flow_cm3_per_min, 0.0, 1e6)?;
                if jet_count == 0 {
                    return Err(Error::config("jet_count", 0, "at least one jet"));
                }
                if let Some(v) = jet_velocity_m_per_s {
                    in_range("jet_velocity_m_per_s", v, 0.0, 1000.0)?;
                }
            }
            OilSupply::OilAir {
                oil_volume_cm3_per_h,
                air_flow_l_per_min,
            }
            | OilSupply::OilMist {
                oil_volume_cm3_per_h,
                air_flow_l_per_min,
            } => {
                in_range("oil_volume_cm3_per_h", oil_volume_cm3_per_h, 0.0, 1e5)?;
                in_range("air_flow_l_per_min", air_flow_l_per_min, 0.0, 1e5)?;
            }
            OilSupply::OilBath { oil_level_mm } => {
                if let Some(h) = oil_level_mm {
                    in_range("oil_level_mm", h, 0.0, 1e4)?;
                }
            }
            OilSupply::Grease { grease_fill_fraction } => {
                in_range("grease_fill_fraction", grease_fill_fraction, 0.0, 1.0)?;
            }
        }
        Ok(())
    }

    /// Oil flow into the cavity [cm^3/min] of a jet, oil-air or oil-mist
    /// supply (times the flow scale); None for bath and grease.
    pub fn oil_flow_cm3_per_min(&self) -> Option<f64> {
        let w = match self.supply {
            OilSupply::Jet {
                oil_flow_cm3_per_min, ..
            } => oil_flow_cm3_per_min,
            OilSupply::OilAir {
                oil_volume_cm3_per_h, ..
            }
            | OilSupply::OilMist {
                oil_volume_cm3_per_h, ..
            } => oil_volume_cm3_per_h / 60.0,
            OilSupply::OilBath { .. } | OilSupply::Grease { .. } => return None,
        };
        Some(w * self.oil_flow_scale)
    }

    /// The lubrication method the supply belongs to.
    pub fn method(&self) -> Lubrication {
        match self.supply {
            OilSupply::Jet { .. } => Lubrication::Jet,
            OilSupply::OilAir { .. } => Lubrication::OilAir,
            OilSupply::OilMist { .. } => Lubrication::OilMist,
            OilSupply::OilBath { .. } => Lubrication::OilBath,
            OilSupply::Grease { .. } => Lubrication::Grease,
        }
    }

    /// The supply keywords that [`SupplyInput::resolve`] turns back into
    /// this supply under its [`method`](Self::method): every field of the
    /// supply and both tunings (a model listing its assumptions, or a copy
    /// of a model, passes them on unchanged).
    pub fn input(&self) -> SupplyInput {
        let mut k = SupplyInput {
            oil_flow_scale: Some(self.oil_flow_scale),
            cavity_fraction_speed_exponent: Some(self.cavity_fraction_speed_exponent),
            ..SupplyInput::default()
        };
        match self.supply {
            OilSupply::Jet {
                oil_flow_cm3_per_min,
                jet_count,
                jet_velocity_m_per_s,
            } => {
                k.oil_flow_cm3_per_min = Some(oil_flow_cm3_per_min);
                k.jet_count = Some(jet_count);
                k.jet_velocity_m_per_s = jet_velocity_m_per_s;
            }
            OilSupply::OilAir {
                oil_volume_cm3_per_h,
                air_flow_l_per_min,
            }
            | OilSupply::OilMist {
                oil_volume_cm3_per_h,
                air_flow_l_per_min,
            } => {
                k.oil_volume_cm3_per_h = Some(oil_volume_cm3_per_h);
                k.air_flow_l_per_min = Some(air_flow_l_per_min);
            }
            OilSupply::OilBath { oil_level_mm } => k.oil_level_mm = oil_level_mm,
            OilSupply::Grease { grease_fill_fraction } => k.grease_fill_fraction = Some(grease_fill_fraction),
        }
        k
    }
}

/// The supply keywords as given (Python keywords, TOML keys), each
/// optional; [`SupplyInput::resolve`] turns them into the supply of a
/// lubrication method.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SupplyInput {
    /// Jet: total oil flow into the bearing [cm^3/min].
    pub oil_flow_cm3_per_min: Option<f64>,
    /// Jet: number of jets (default 1).
    pub jet_count: Option<u32>,
    /// Jet: jet velocity [m/s].
    pub jet_velocity_m_per_s: Option<f64>,
    /// Oil-air, oil-mist: oil volume per hour [cm^3/h].
    pub oil_volume_cm3_per_h: Option<f64>,
    /// Oil-air, oil-mist: carrier air flow [l/min] (default 0: not given).
    pub air_flow_l_per_min: Option<f64>,
    /// Oil bath: static oil level above the lowest point of the lowest ball \[mm\].
    pub oil_level_mm: Option<f64>,
    /// Grease: fill fraction of the free volume (default 0.3).
    pub grease_fill_fraction: Option<f64>,
    /// Scale on the oil flow reaching the cavity (default 1).
    pub oil_flow_scale: Option<f64>,
    /// Speed exponent of the cavity fraction (default 1, Parker's).
    pub cavity_fraction_speed_exponent: Option<f64>,
}

impl SupplyInput {
    fn given(&self) -> Vec<&'static str> {
        let keys = [
            ("oil_flow_cm3_per_min", self.oil_flow_cm3_per_min.is_some()),
            ("jet_count", self.jet_count.is_some()),
            ("jet_velocity_m_per_s", self.jet_velocity_m_per_s.is_some()),
            ("oil_volume_cm3_per_h", self.oil_volume_cm3_per_h.is_some()),
            ("air_flow_l_per_min", self.air_flow_l_per_min.is_some()),
            ("oil_level_mm", self.oil_level_mm.is_some()),
            ("grease_fill_fraction", self.grease_fill_fraction.is_some()),
            ("oil_flow_scale", self.oil_flow_scale.is_some()),
            (
                "cavity_fraction_speed_exponent",
                self.cavity_fraction_speed_exponent.is_some(),
            ),
        ];
        keys.iter().filter(|(_, g)| *g).map(|(k, _)| *k).collect()
    }

    /// The supply of `method` (module docs): None when no keyword is
    /// given (the method's fixed fraction), except for an oil bath named
    /// in `method_given` without a fixed fraction, which takes the SKF bath
    /// drag at the reference level. A keyword of another method, a jet
    /// without its flow, an oil-air/mist supply without its oil volume, or
    /// a supply keyword with `fixed_fraction_given` is refused, naming it.
    pub fn resolve(
        &self,
        method: Lubrication,
        method_given: bool,
        fixed_fraction_given: bool,
    ) -> Result<Option<SupplySettings>> {
        let given = self.given();
        if given.is_empty() {
            let bath = method_given && method == Lubrication::OilBath && !fixed_fraction_given;
            return Ok(bath.then(|| SupplySettings::new(OilSupply::OilBath { oil_level_mm: None })));
        }
        if fixed_fraction_given {
            return Err(Error::config(
                "churning_oil_fraction",
                "given",
                format!(
                    "a fixed cavity oil fraction overrides the oil supply ({}); give one or the other",
                    given.join(", ")
                ),
            ));
        }
        let own: &[&str] = match method {
            Lubrication::Jet => &["oil_flow_cm3_per_min", "jet_count", "jet_velocity_m_per_s"],
            Lubrication::OilAir | Lubrication::OilMist => &["oil_volume_cm3_per_h", "air_flow_l_per_min"],
            Lubrication::OilBath => &["oil_level_mm"],
            Lubrication::Grease => &["grease_fill_fraction"],
        };
        let tunings = ["oil_flow_scale", "cavity_fraction_speed_exponent"];
        if let Some(k) = given.iter().find(|k| !own.contains(k) && !tunings.contains(k)) {
            return Err(Error::config(
                *k,
                "given",
                format!(
                    "not a supply keyword of lubrication '{}' (it takes {})",
                    method.name(),
                    own.join(", ")
                ),
            ));
        }
        let required = |field: &str, v: Option<f64>| {
            v.ok_or_else(|| Error::config(field, "missing", format!("required by lubrication '{}'", method.name())))
        };
        let supply = match method {
            Lubrication::Jet => OilSupply::Jet {
                oil_flow_cm3_per_min: required("oil_flow_cm3_per_min", self.oil_flow_cm3_per_min)?,
                jet_count: self.jet_count.unwrap_or(1),
                jet_velocity_m_per_s: self.jet_velocity_m_per_s,
            },
            Lubrication::OilAir | Lubrication::OilMist => {
                let oil_volume_cm3_per_h = required("oil_volume_cm3_per_h", self.oil_volume_cm3_per_h)?;
                let air_flow_l_per_min = self.air_flow_l_per_min.unwrap_or(0.0);
                if method == Lubrication::OilAir {
                    OilSupply::OilAir {
                        oil_volume_cm3_per_h,
                        air_flow_l_per_min,
                    }
                } else {
                    OilSupply::OilMist {
                        oil_volume_cm3_per_h,
                        air_flow_l_per_min,
                    }
                }
            }
            Lubrication::OilBath => OilSupply::OilBath {
                oil_level_mm: self.oil_level_mm,
            },
            Lubrication::Grease => OilSupply::Grease {
                grease_fill_fraction: self.grease_fill_fraction.unwrap_or(DEFAULT_GREASE_FILL_FRACTION),
            },
        };
        let s = SupplySettings {
            supply,
            oil_flow_scale: self.oil_flow_scale.unwrap_or(1.0),
            cavity_fraction_speed_exponent: self.cavity_fraction_speed_exponent.unwrap_or(1.0),
        };
        s.validate()?;
        Ok(Some(s))
    }
}

/// Speed about which a speed exponent other than Parker's tilts the cavity
/// fraction \[rpm\] (eq. 9.10): the fraction there is Parker's whatever the
/// exponent, so the exponent changes how fast the oil leaves the cavity
/// with speed, not how much oil there is (the flow scale's job). Our
/// choice: a round speed inside the range the correlation is used at
/// (DN 1-3 million for pitch diameters of 50-150 mm is 7,000-60,000 rpm).
pub const CAVITY_FRACTION_PIVOT_RPM: f64 = 10_000.0;

/// Parker's cavity oil fraction (eq. 9.10, module docs): `X = 1e5 W^0.37 /
/// (n_p dm^1.7) (n / n_p)^-e`, W in cm^3/min, n in rpm, dm in mm, e the
/// speed exponent (Parker: 1, which gives his `1e5 W^0.37 / (n dm^1.7)`),
/// n_p = [`CAVITY_FRACTION_PIVOT_RPM`]; at most 1 (a flooded cavity), 0
/// without flow.
pub fn parker_cavity_oil_fraction(
    oil_flow_cm3_per_min: f64,
    speed_rpm: f64,
    pitch_diameter_mm: f64,
    speed_exponent: f64,
) -> Result<f64> {
    let w = non_negative("oil_flow_cm3_per_min", oil_flow_cm3_per_min)?;
    let n = non_negative("speed_rpm", speed_rpm.abs())?;
    let dm = positive("pitch_diameter_mm", pitch_diameter_mm)?;
    finite("cavity_fraction_speed_exponent", speed_exponent)?;
    if w == 0.0 {
        return Ok(0.0);
    }
    if n == 0.0 {
        return Ok(1.0);
    }
    let np = CAVITY_FRACTION_PIVOT_RPM;
    Ok((1e5 * w.powf(0.37) / (np * dm.powf(1.7)) * (n / np).powf(-speed_exponent)).min(1.0))
}

/// Drag coefficient of a smooth sphere at Reynolds number `re` (eq. 9.11):
/// Schiller & Naumann's `24/Re (1 + 0.15 Re^0.687)` (1933; Clift, Grace &
/// Weber, *Bubbles, Drops, and Particles*, 1978, table 5.2) up to where it
/// meets the subcritical plateau 0.47 (about Re = 700), the plateau above
/// ([`super::heat::SPHERE_DRAG_COEFFICIENT`]).
pub fn sphere_drag_coefficient(re: f64) -> f64 {
    if re <= 0.0 {
        return f64::INFINITY;
    }
    (24.0 / re * (1.0 + 0.15 * re.powf(0.687))).max(super::heat::SPHERE_DRAG_COEFFICIENT)
}

/// Ball drag power in the oil-air mixture \[W\] (eq. 9.12, module docs):
/// `Z (1/2) C_D(Re) rho_e (pi D^2 / 4) v^3`, v = dm |omega_c| / 2,
/// rho_e = X rho_oil, Re with mu_e = X mu_oil + (1 - X) mu_air.
pub fn ball_drag_in_mixture_w(
    ball_count: usize,
    ball_diameter_m: f64,
    pitch_diameter_m: f64,
    cage_speed_rad_s: f64,
    oil_volume_fraction: f64,
    oil_density_kg_m3: f64,
    oil_dynamic_viscosity_pa_s: f64,
) -> Result<f64> {
    let d = positive("ball_diameter_m", ball_diameter_m)?;
    positive("pitch_diameter_m", pitch_diameter_m)?;
    finite("cage_speed_rad_s", cage_speed_rad_s)?;
    let x = in_range("cavity_oil_fraction", oil_volume_fraction, 0.0, 1.0)?;
    positive("oil_density_kg_m3", oil_density_kg_m3)?;
    positive("oil_dynamic_viscosity_pa_s", oil_dynamic_viscosity_pa_s)?;
    let v = 0.5 * pitch_diameter_m * cage_speed_rad_s.abs();
    if x == 0.0 || v == 0.0 {
        return Ok(0.0);
    }
    let rho_e = x * oil_density_kg_m3;
    let mu_e = x * oil_dynamic_viscosity_pa_s + (1.0 - x) * AIR_DYNAMIC_VISCOSITY_PA_S;
    let cd = sphere_drag_coefficient(rho_e * v * d / mu_e);
    let area = 0.25 * std::f64::consts::PI * d * d;
    Ok(ball_count as f64 * 0.5 * cd * rho_e * area * v.powi(3))
}

/// Immersed share `s = (t - sin t) / (2 pi)` of the circle of radius
/// 0.6 dm at oil level H above its lowest point, t = 2 arccos((0.6 dm - H)
/// / (0.6 dm)), t = 2 pi from H = 1.2 dm (eq. 9.14; module docs).
pub fn bath_immersion_share(oil_level_m: f64, pitch_diameter_m: f64) -> Result<f64> {
    let h = non_negative("oil_level_mm", oil_level_m * 1e3)? * 1e-3;
    let r = 0.6 * positive("pitch_diameter_m", pitch_diameter_m)?;
    let t = if h >= 2.0 * r {
        2.0 * std::f64::consts::PI
    } else {
        2.0 * ((r - h) / r).acos()
    };
    Ok((t - t.sin()) / (2.0 * std::f64::consts::PI))
}

/// Bath geometry of one bearing for [`skf_bath_drag_moment_n_m`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BathBearing {
    /// Bore d \[m\].
    pub bore_m: f64,
    /// Outside diameter D \[m\].
    pub outer_diameter_m: f64,
    /// Pitch diameter dm \[m\].
    pub pitch_diameter_m: f64,
    /// Ball diameter \[m\] (the reference level is half of it).
    pub ball_diameter_m: f64,
    /// SKF geometric constant K_z (3.1 deep-groove, 4.4 angular-contact).
    pub kz: f64,
    /// Rows of balls i_rw.
    pub rows: u32,
}

/// SKF oil-bath drag moment \[N m\] (eq. 9.13): `V_M(H) K_ball dm^5 n^2`
/// N mm with `K_ball = i_rw K_z (d + D) / (D - d) 1e-12`, V_M(H) eq. 9.14;
/// `oil_level_m` None: the middle of the lowest ball.
pub fn skf_bath_drag_moment_n_m(b: &BathBearing, oil_level_m: Option<f64>, speed_rpm: f64) -> Result<f64> {
    let d = positive("bore_mm", b.bore_m * 1e3)?;
    let big_d = positive("outer_diameter_mm", b.outer_diameter_m * 1e3)?;
    if big_d <= d {
        return Err(Error::config("outer_diameter_mm", big_d, "must exceed the bore"));
    }
    let dm = positive("pitch_diameter_mm", b.pitch_diameter_m * 1e3)?;
    let n = finite("speed_rpm", speed_rpm)?.abs();
    let h_ref = 0.5 * positive("ball_diameter_m", b.ball_diameter_m)?;
    let vm = SKF_BATH_DRAG_VM_REFERENCE * bath_immersion_share(oil_level_m.unwrap_or(h_ref), b.pitch_diameter_m)?
        / bath_immersion_share(h_ref, b.pitch_diameter_m)?;
    let k_ball = b.rows as f64 * positive("skf_kz", b.kz)? * (d + big_d) / (big_d - d) * 1e-12;
    Ok(vm * k_ball * dm.powi(5) * n * n * 1e-3)
}

/// One point as the supply drag sees it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DragPoint {
    /// Bath geometry of the bearing (also dm and D of the balls).
    pub bearing: BathBearing,
    /// Ball count Z.
    pub ball_count: usize,
    /// Shaft speed \[rpm\].
    pub speed_rpm: f64,
    /// Cage speed [rad/s].
    pub cage_speed_rad_s: f64,
    /// Oil density [kg/m^3].
    pub oil_density_kg_m3: f64,
    /// Oil kinematic viscosity \[cSt\].
    pub viscosity_cst: f64,
}

/// Drag and churning of one bearing from its supply.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SupplyDrag {
    /// Cavity oil volume fraction X (0 for bath and grease) [-].
    pub cavity_oil_fraction: f64,
    /// Drag heat: ball drag in the mixture, or the SKF bath drag \[W\].
    pub drag_w: f64,
    /// Churning heat of rings and cage \[W\] (module docs: zero).
    pub churning_w: f64,
}

/// Drag and churning of a point under a supply (module docs).
pub fn supply_drag(s: &SupplySettings, p: &DragPoint) -> Result<SupplyDrag> {
    s.validate()?;
    let b = &p.bearing;
    match s.supply {
        OilSupply::OilBath { oil_level_mm } => {
            let m = skf_bath_drag_moment_n_m(b, oil_level_mm.map(|h| h * 1e-3), p.speed_rpm)?;
            Ok(SupplyDrag {
                cavity_oil_fraction: 0.0,
                drag_w: m * rpm_to_rad_s(p.speed_rpm).abs(),
                churning_w: 0.0,
            })
        }
        OilSupply::Grease { .. } => Ok(SupplyDrag::default()),
        _ => {
            let w = s.oil_flow_cm3_per_min().unwrap_or(0.0);
            let dm_mm = b.pitch_diameter_m * 1e3;
            let x = parker_cavity_oil_fraction(w, p.speed_rpm, dm_mm, s.cavity_fraction_speed_exponent)?;
            let mu = positive("kinematic_viscosity_cst", p.viscosity_cst)? * 1e-6 * p.oil_density_kg_m3;
            let drag_w = ball_drag_in_mixture_w(
                p.ball_count,
                b.ball_diameter_m,
                b.pitch_diameter_m,
                p.cage_speed_rad_s,
                x,
                p.oil_density_kg_m3,
                mu,
            )?;
            Ok(SupplyDrag {
                cavity_oil_fraction: x,
                drag_w,
                churning_w: 0.0,
            })
        }
    }
}

#[cfg(test)]
#[path = "oil_supply_tests.rs"]
mod tests;
