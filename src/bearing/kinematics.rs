//! Ball kinematics under raceway control (Jones 1960; Harris & Kotzalas,
//! Advanced Concepts, ch. 3; seed A-19, A-24..A-26), and the direction of
//! the raceway friction couple that balances the gyroscopic moment.
//!
//! # Derivation
//!
//! Work in the cage frame, which turns with the orbit speed omega_c about
//! +z. At ball j use the unit vectors e_r (radially out), e_psi (direction
//! of the orbit, the inner ring turns at omega_i > 0 about +z) and e_z, with
//! e_z x e_r = e_psi. The contact normals point from the ball centre to the
//! contacts: outer n_o = sin(a_o) e_z + cos(a_o) e_r; inner -n_i with
//! n_i = sin(a_i) e_z + cos(a_i) e_r (the load line runs from the inner
//! contact through the ball centre to the outer contact). In this frame the
//! outer ring turns at -omega_c e_z, the inner ring at (omega_i - omega_c) e_z.
//! The ball turns at w = w_z e_z + w_r e_r (no component about e_psi).
//!
//! Rolling without slip at the contact centres (ball and ring surface speeds
//! equal, with w x n = (w_z cos a - w_r sin a) e_psi and gamma' = D / dm):
//!
//! ```text
//! outer:  w_z cos a_o - w_r sin a_o = -omega_c (1/gamma' + cos a_o)
//! inner:  w_z cos a_i - w_r sin a_i = -(omega_i - omega_c) (1/gamma' - cos a_i)
//! ```
//!
//! Outer-raceway control (no spin at the outer contact, (w + omega_c e_z).n_o = 0)
//! gives w_z = -omega_c (1 + cos a_o / gamma'), w_r = omega_c sin a_o / gamma',
//! hence tan(beta) = w_r / (-w_z) = sin a_o / (cos a_o + gamma') (A-19) and
//! omega_c / omega_i = (1 - gamma' cos a_i) / (1 + cos(a_i - a_o)).
//! Inner-raceway control ((w - (omega_i - omega_c) e_z).n_i = 0) gives
//! w_z = (omega_i - omega_c)(1 - cos a_i / gamma'), w_r = (omega_i - omega_c) sin a_i / gamma',
//! tan(beta) = sin a_i / (cos a_i - gamma') and
//! omega_c / omega_i = (cos(a_i - a_o) - gamma' cos a_o) / (1 + cos(a_i - a_o)).
//! Both match Harris & Kotzalas (Advanced Concepts, eqs. 3.37-3.48).
//!
//! The angular momentum of the ball is H = J (w + omega_c e_z); w is fixed
//! in the cage frame, so dH/dt = omega_c e_z x J w = J omega_c w_r e_psi.
//! The contacts must therefore apply the moment M = J omega_c w_r e_psi about
//! the ball centre, of magnitude Mg = J omega_b omega_c sin(beta) (A-17) with
//! omega_b = |w|, and along +e_psi for either sense of rotation (w_r omega_c
//! = omega_c^2 sin a / gamma' >= 0 for a >= 0). A friction force F t at the
//! outer contact (t in the axial plane, perpendicular to n_o) gives the
//! moment (D/2) n_o x F t = (D/2) F (sin a_o t_r - cos a_o t_z) e_psi, so
//! t = -cos(a_o) e_z + sin(a_o) e_r with F = 2 Mg / D (lambda_o = 2). At the
//! inner contact (arm -(D/2) n_i) the same reasoning gives
//! t = cos(a_i) e_z - sin(a_i) e_r. The ball equilibrium (A-15) is then
//!
//! ```text
//! Q_i sin a_i - Q_o sin a_o + (Mg/D)(lambda_i cos a_i - lambda_o cos a_o) = 0
//! Q_i cos a_i - Q_o cos a_o - (Mg/D)(lambda_i sin a_i - lambda_o sin a_o) + Fc = 0
//! ```
//!
//! which is the opposite sign of the friction terms printed in
//! docs/concepts/physics.md §3, (A-15) and in Harris's form;
//! [`super::GyroCoupleSign::Reversed`] selects that printed form. The test `friction_couple_opposes_gyroscopic_moment`
//! checks the moment balance with vectors.

use super::dual::Dual;
use super::RacewayControl;

/// Kinematics of one ball in the cage frame (generic for derivatives).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Kin<const N: usize> {
    /// Orbit (cage) speed omega_c [rad/s].
    pub orbit: Dual<N>,
    /// Ball angular velocity in the cage frame along e_z and e_r [rad/s].
    pub wz: Dual<N>,
    pub wr: Dual<N>,
}

/// Raceway-control kinematics from the contact-angle sines and cosines.
#[inline]
pub(crate) fn kinematics<const N: usize>(
    control: RacewayControl,
    omega_i: f64,
    gamma: f64,
    (si, ci): (Dual<N>, Dual<N>),
    (so, co): (Dual<N>, Dual<N>),
) -> Kin<N> {
    let cos_diff = ci * co + si * so;
    match control {
        RacewayControl::Outer => {
            let orbit = (ci * (-gamma) + 1.0) / (cos_diff + 1.0) * omega_i;
            Kin {
                orbit,
                wz: -(orbit * (co / gamma + 1.0)),
                wr: orbit * so / gamma,
            }
        }
        RacewayControl::Inner => {
            let orbit = (cos_diff - co * gamma) / (cos_diff + 1.0) * omega_i;
            let rel = -orbit + omega_i;
            Kin {
                orbit,
                wz: rel * (-(ci / gamma) + 1.0),
                wr: rel * si / gamma,
            }
        }
    }
}

/// Kinematics of one ball (inner ring turning at `inner_ring_speed_rad_s`,
/// outer ring fixed), in the cage frame.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BallKinematics {
    /// Orbit (cage) speed omega_c [rad/s].
    pub orbit_speed_rad_s: f64,
    /// Ball speed about its own axis relative to the cage, omega_b = |w| [rad/s].
    pub spin_speed_rad_s: f64,
    /// Attitude angle beta of the ball axis from the bearing axis \[rad\] (A-19).
    pub attitude_angle_rad: f64,
    /// Ball angular velocity along the bearing axis, cage frame [rad/s].
    pub spin_axial_rad_s: f64,
    /// Ball angular velocity along e_r (radially out), cage frame [rad/s].
    pub spin_radial_rad_s: f64,
    /// Spin of the ball relative to the inner raceway about the contact
    /// normal n_i [rad/s] (A-24).
    pub inner_spin_rad_s: f64,
    /// Spin of the ball relative to the outer raceway about n_o [rad/s] (A-24).
    pub outer_spin_rad_s: f64,
    /// Rolling speed of the ball relative to the inner raceway [rad/s].
    pub inner_roll_rad_s: f64,
    /// Rolling speed of the ball relative to the outer raceway [rad/s].
    pub outer_roll_rad_s: f64,
}

impl BallKinematics {
    /// Spin-to-roll ratio at the inner contact (0 when not rolling).
    pub fn inner_spin_to_roll(&self) -> f64 {
        ratio(self.inner_spin_rad_s, self.inner_roll_rad_s)
    }
    /// Spin-to-roll ratio at the outer contact (0 when not rolling).
    pub fn outer_spin_to_roll(&self) -> f64 {
        ratio(self.outer_spin_rad_s, self.outer_roll_rad_s)
    }
}

fn ratio(a: f64, b: f64) -> f64 {
    if b.abs() > 0.0 {
        a / b
    } else {
        0.0
    }
}

/// Raceway-control kinematics of a ball with inner and outer contact angles
/// `inner_contact_angle_rad`, `outer_contact_angle_rad` in a bearing with
/// ball-to-pitch diameter ratio `ball_to_pitch` (gamma' = D / dm).
pub fn ball_kinematics(
    control: RacewayControl,
    inner_ring_speed_rad_s: f64,
    ball_to_pitch: f64,
    inner_contact_angle_rad: f64,
    outer_contact_angle_rad: f64,
) -> BallKinematics {
    let (si, ci) = inner_contact_angle_rad.sin_cos();
    let (so, co) = outer_contact_angle_rad.sin_cos();
    let k = kinematics::<1>(
        control,
        inner_ring_speed_rad_s,
        ball_to_pitch,
        (Dual::cst(si), Dual::cst(ci)),
        (Dual::cst(so), Dual::cst(co)),
    );
    let (oc, wz, wr) = (k.orbit.v, k.wz.v, k.wr.v);
    let wo_ring = -oc; // outer ring in the cage frame
    let wi_ring = inner_ring_speed_rad_s - oc;
    BallKinematics {
        orbit_speed_rad_s: oc,
        spin_speed_rad_s: wz.hypot(wr),
        attitude_angle_rad: wr.atan2(-wz),
        spin_axial_rad_s: wz,
        spin_radial_rad_s: wr,
        inner_spin_rad_s: (wz - wi_ring) * si + wr * ci,
        outer_spin_rad_s: (wz - wo_ring) * so + wr * co,
        inner_roll_rad_s: (wz - wi_ring) * ci - wr * si,
        outer_roll_rad_s: (wz - wo_ring) * co - wr * so,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rolling_and_control_conditions_hold() {
        let g = 12.0 / 60.0;
        let w = 1000.0;
        for control in [RacewayControl::Outer, RacewayControl::Inner] {
            let (ai, ao) = (0.45_f64, 0.31_f64);
            let k = ball_kinematics(control, w, g, ai, ao);
            // Surface speeds at the contacts (cage frame) equal the ring speeds.
            let (wz, wr) = (k.spin_axial_rad_s, k.spin_radial_rad_s);
            let r = 0.5; // D/2 in units of D; radii in units of D with dm = 1/g
            let ball_o = r * (wz * ao.cos() - wr * ao.sin());
            let ring_o = -k.orbit_speed_rad_s * (0.5 / g + r * ao.cos());
            assert!((ball_o - ring_o).abs() < 1e-9 * w);
            let ball_i = -r * (wz * ai.cos() - wr * ai.sin());
            let ring_i = (w - k.orbit_speed_rad_s) * (0.5 / g - r * ai.cos());
            assert!((ball_i - ring_i).abs() < 1e-9 * w);
            match control {
                RacewayControl::Outer => {
                    assert!(k.outer_spin_rad_s.abs() < 1e-9 * w);
                    assert!((k.attitude_angle_rad.tan() - ao.sin() / (ao.cos() + g)).abs() < 1e-12);
                }
                RacewayControl::Inner => {
                    assert!(k.inner_spin_rad_s.abs() < 1e-9 * w);
                    assert!((k.attitude_angle_rad.tan() - ai.sin() / (ai.cos() - g)).abs() < 1e-12);
                }
            }
        }
    }

    #[test]
    fn zero_contact_angle_gives_classical_cage_speed() {
        // Radial bearing, a = 0: omega_c = omega_i (1 - gamma') / 2 (Harris & Kotzalas
        // Essential Concepts, ch. 8, epicyclic cage speed) and ball speed
        // omega_b = (dm / 2D) omega_i (1 - gamma'^2).
        let g = 0.2;
        let k = ball_kinematics(RacewayControl::Outer, 100.0, g, 0.0, 0.0);
        assert!((k.orbit_speed_rad_s - 100.0 * (1.0 - g) / 2.0).abs() < 1e-12);
        assert!((k.spin_speed_rad_s - 100.0 * (1.0 - g * g) / (2.0 * g)).abs() < 1e-10);
        assert!(k.attitude_angle_rad.abs() < 1e-15);
    }
}
