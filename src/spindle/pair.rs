//! Two angular-contact bearings back-to-back (DB) on one shaft.
//!
//! # Coordinates
//!
//! The shaft displacement u = [x, y, z, theta_x, theta_y] (m, rad) is taken
//! at the pair centre. Bearing A sits at z_A = -s/2 and bearing B at
//! z_B = +s/2 (s = centre spacing, the bearing width for an adjacent pair).
//! Bearing A uses the global frame; bearing B is mirrored (z -> -z), which
//! flips the axial displacement and, the rotation being an axial vector,
//! both tilts. A shaft rotation theta_y moves the point (0, 0, z_k) by
//! theta x r = (theta_y z_k, -theta_x z_k, 0), so bearing k sees
//!
//! ```text
//! q_k = M_k [x + theta_y z_k, y - theta_x z_k, z, theta_x, theta_y]
//! M_A = I,  M_B = diag(1, 1, -1, -1, -1)
//! ```
//!
//! plus its assembly offset on the local dz. This is a linear map
//! q_k = T_k u + c_k; forces transform with T_k^T (virtual work) and the
//! pair stiffness is exactly sum_k T_k^T K_k T_k.
//!
//! # Preload (back-to-back)
//!
//! A positive local dz loads a bearing; the DB pair is preloaded by pushing
//! the inner rings towards each other by the axial interference c0 per
//! bearing (the offset that gives the preload force at zero speed, cold).
//!
//! * [`Preload::Rigid`]: both offsets stay c0 (fixed axial positions); the
//!   force follows from speed (centrifugal, gyroscopic) and thermal offsets.
//! * [`Preload::Spring`]: the outer ring of B floats against a spring of
//!   rate k_s pre-compressed to F0. An axial thermal growth `u` pushes the
//!   floating ring into the spring; the spring takes an extra compression
//!   `x` and the bearings the rest, so bearing B's local approach is
//!   `-z + c0 + (u - x)` and the spring balance is `-R_Bz = F0 + k_s x`
//!   (R_Bz: axial reaction of the balls on inner ring B, local frame).
//!   k_s -> 0 gives a constant force F0; k_s -> infinity pins x = 0, the
//!   rigid pair with interference c0 + u.

#![allow(clippy::needless_range_loop)] // 5x5 index algebra reads clearer with indices

use crate::bearing::{BearingModel, BearingState, RacewayOffsets, RingForces, SolveOptions, Tilt, WarmStart};
use crate::error::{finite, non_negative, positive, Error, Result};

/// How the pair is preloaded.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub enum Preload {
    /// Fixed axial positions with the interference that gives `force_n`
    /// per bearing at zero speed and uniform assembly temperature.
    Rigid {
        /// Preload force per bearing F0 at assembly \[N\], > 0.
        force_n: f64,
    },
    /// Spring preload: `force_n` at assembly plus `rate_n_per_m` times the
    /// extra spring compression.
    Spring {
        /// Spring force at assembly F0 \[N\], > 0.
        force_n: f64,
        /// Spring rate k_s [N/m], >= 0 (0: constant force F0).
        rate_n_per_m: f64,
    },
}

impl Preload {
    /// Preload force at assembly F0 \[N\].
    pub fn force_n(self) -> f64 {
        match self {
            Preload::Rigid { force_n } | Preload::Spring { force_n, .. } => force_n,
        }
    }

    fn validate(self) -> Result<()> {
        positive("preload_n", self.force_n())?;
        if let Preload::Spring { rate_n_per_m, .. } = self {
            non_negative("spring_rate_n_per_m", rate_n_per_m)?;
        }
        Ok(())
    }
}

/// Everything that loads the pair besides the preload.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PairLoad {
    /// External load on the shaft at the pair centre [Fx, Fy, Fz, Mx, My] (N, N m).
    pub external_load: [f64; 5],
    /// Thermal (or fit) offsets of the groove centres of bearings A and B
    /// (A-38), each in its own frame.
    pub offsets: [RacewayOffsets; 2],
    /// Axial growth that compresses the preload spring \[m\] (spring preload
    /// only; ignored for a rigid pair, whose floating partner takes it).
    pub spring_growth_m: f64,
}

/// Solved pair.
#[derive(Debug, Clone, PartialEq)]
pub struct PairState {
    /// Shaft displacement at the pair centre [x, y, z, theta_x, theta_y] (m, rad).
    pub displacement: [f64; 5],
    /// Bearing states A and B (each in its own frame).
    pub bearings: [BearingState; 2],
    /// Axial force of bearing A and B on their inner rings (local, loading positive) \[N\].
    pub axial_force_n: [f64; 2],
    /// Preload: the mean axial force of the two bearings \[N\].
    pub preload_n: f64,
    /// Extra spring compression x \[m\] (0 for a rigid pair).
    pub spring_compression_m: f64,
    /// Pair stiffness at the pair centre, sum_k T_k^T K_k T_k (SI blocks).
    pub stiffness_matrix: [[f64; 5]; 5],
    /// Newton iterations of the shaft equilibrium.
    pub iterations: usize,
}

/// A back-to-back pair prepared for solving.
#[derive(Debug, Clone)]
pub struct BearingPair {
    /// Bearing A at z = -s/2, in the global frame.
    pub model_a: BearingModel,
    /// Bearing B at z = +s/2, mirrored (its outer ring floats on a spring preload).
    pub model_b: BearingModel,
    /// Centre spacing s of the two bearings \[m\].
    pub spacing_m: f64,
    /// The preload; change it with [`BearingPair::with_preload`], which
    /// recomputes `interference_m`.
    pub preload: Preload,
    /// Axial interference per bearing c0 \[m\] (local dz of each bearing at
    /// assembly under the preload force, zero speed).
    pub interference_m: f64,
    /// Solve options of both bearings (effects, ...); `tolerance` and
    /// `max_iterations` also drive the pair's Newton iteration (tolerance
    /// relative to the larger of the preload and the largest external load);
    /// `offsets` is replaced by [`PairLoad::offsets`].
    pub options: SolveOptions,
}

/// Residual, Jacobian, pair stiffness, axial forces and ring forces at one point.
struct Residual {
    r: [f64; 6],
    jac: [[f64; 6]; 6],
    kpair: [[f64; 5]; 5],
    axial: [f64; 2],
    forces: Vec<RingForces>,
}

/// Warm start of a pair solve: shaft displacement, spring compression and
/// the per-ball solutions of both bearings.
#[derive(Debug, Clone, Default)]
pub struct PairWarm {
    /// Shaft displacement at the pair centre [x, y, z, theta_x, theta_y] (m, rad).
    pub displacement: [f64; 5],
    /// Extra spring compression x \[m\] (0 for a rigid pair).
    pub spring_compression_m: f64,
    balls: [WarmStart; 2],
}

/// Local coordinates of bearing k (0 = A, 1 = B) as the rows of T_k.
fn transfer(k: usize, z_k: f64) -> [[f64; 5]; 5] {
    let m = if k == 0 { 1.0 } else { -1.0 };
    [
        [1.0, 0.0, 0.0, 0.0, z_k],
        [0.0, 1.0, 0.0, -z_k, 0.0],
        [0.0, 0.0, m, 0.0, 0.0],
        [0.0, 0.0, 0.0, m, 0.0],
        [0.0, 0.0, 0.0, 0.0, m],
    ]
}

fn mat_vec(t: &[[f64; 5]; 5], u: &[f64; 5]) -> [f64; 5] {
    let mut out = [0.0; 5];
    for (o, row) in out.iter_mut().zip(t) {
        *o = row.iter().zip(u).map(|(a, b)| a * b).sum();
    }
    out
}

impl BearingPair {
    /// Pair of `a` and `b` (usually equal) at `spacing_m` with a preload.
    pub fn new(
        a: BearingModel,
        b: BearingModel,
        spacing_m: f64,
        preload: Preload,
        options: SolveOptions,
    ) -> Result<Self> {
        non_negative("spacing_m", spacing_m)?;
        preload.validate()?;
        let cold = SolveOptions {
            offsets: RacewayOffsets::default(),
            tilt: Tilt::held_level(),
            ..options
        };
        let f0 = preload.force_n();
        let ca = a.solve_static(&[0.0, 0.0, f0, 0.0, 0.0], &cold)?.displacement[2];
        let cb = b.solve_static(&[0.0, 0.0, f0, 0.0, 0.0], &cold)?.displacement[2];
        if (ca - cb).abs() > 1e-6 * ca.abs().max(1e-12) {
            return Err(Error::config(
                "bearing_b",
                b.bearing().name.clone(),
                "the two bearings of a preloaded pair need the same axial offset at the preload (use equal bearings)",
            ));
        }
        Ok(BearingPair {
            model_a: a,
            model_b: b,
            spacing_m,
            preload,
            interference_m: ca,
            options,
        })
    }

    /// The same pair with another preload (recomputes the interference).
    pub fn with_preload(&self, preload: Preload) -> Result<Self> {
        BearingPair::new(
            self.model_a.clone(),
            self.model_b.clone(),
            self.spacing_m,
            preload,
            self.options,
        )
    }

    fn z_of(&self, k: usize) -> f64 {
        if k == 0 {
            -0.5 * self.spacing_m
        } else {
            0.5 * self.spacing_m
        }
    }

    fn spring_rate(&self) -> Option<f64> {
        match self.preload {
            Preload::Rigid { .. } => None,
            Preload::Spring { rate_n_per_m, .. } => Some(rate_n_per_m),
        }
    }

    /// Local displacements of both bearings for shaft displacement u and
    /// spring compression x.
    fn local_q(&self, u: &[f64; 5], x: f64, load: &PairLoad) -> [[f64; 5]; 2] {
        let mut q = [
            mat_vec(&transfer(0, self.z_of(0)), u),
            mat_vec(&transfer(1, self.z_of(1)), u),
        ];
        q[0][2] += self.interference_m;
        q[1][2] += self.interference_m;
        if self.spring_rate().is_some() {
            q[1][2] += load.spring_growth_m - x;
        }
        q
    }

    /// Residuals (shaft balance: load + sum T^T R; spring balance) and the
    /// Jacobian, with the ring forces of both bearings.
    #[allow(clippy::type_complexity)]
    fn residual(
        &self,
        u: &[f64; 5],
        x: f64,
        speed_rpm: f64,
        load: &PairLoad,
        warm: &mut [WarmStart; 2],
    ) -> Result<Residual> {
        let q = self.local_q(u, x, load);
        let mut r = [0.0; 6];
        let mut jac = [[0.0; 6]; 6];
        let mut kpair = [[0.0; 5]; 5];
        let mut axial = [0.0; 2];
        let mut forces = Vec::with_capacity(2);
        r[..5].copy_from_slice(&load.external_load);
        for k in 0..2 {
            let model = if k == 0 { &self.model_a } else { &self.model_b };
            let opts = SolveOptions {
                offsets: load.offsets[k],
                ..self.options
            };
            let f = model.ring_forces(&q[k], speed_rpm, &opts, &mut warm[k])?;
            let t = transfer(k, self.z_of(k));
            axial[k] = -f.reaction[2];
            // r += T^T R ; d r / d u = -T^T K T ; K = -dR/dq.
            for i in 0..5 {
                for a in 0..5 {
                    r[i] += t[a][i] * f.reaction[a];
                }
                for j in 0..5 {
                    let mut s = 0.0;
                    for a in 0..5 {
                        for b in 0..5 {
                            s += t[a][i] * f.stiffness_matrix[a][b] * t[b][j];
                        }
                    }
                    kpair[i][j] += s;
                    jac[i][j] -= s;
                }
            }
            if k == 1 && self.spring_rate().is_some() {
                // dq_B/dx = -e_z: d(T^T R)/dx = T^T K e_z (column of K).
                for i in 0..5 {
                    let mut s = 0.0;
                    for a in 0..5 {
                        s += t[a][i] * f.stiffness_matrix[a][2];
                    }
                    jac[i][5] += s;
                }
                // Spring row: g = -R_Bz - F0 - k x.
                let ks = self.spring_rate().unwrap_or(0.0);
                r[5] = -f.reaction[2] - self.preload.force_n() - ks * x;
                for j in 0..5 {
                    let mut s = 0.0;
                    for b in 0..5 {
                        s += f.stiffness_matrix[2][b] * t[b][j];
                    }
                    jac[5][j] = s;
                }
                jac[5][5] = -f.stiffness_matrix[2][2] - ks;
            }
            forces.push(f);
        }
        if self.spring_rate().is_none() {
            jac[5][5] = 1.0;
        }
        Ok(Residual {
            r,
            jac,
            kpair,
            axial,
            forces,
        })
    }

    /// Solve the shaft equilibrium at `speed_rpm`.
    pub fn solve(&self, speed_rpm: f64, load: &PairLoad) -> Result<PairState> {
        self.solve_from(speed_rpm, load, [0.0; 5], 0.0)
    }

    /// Solve from a start displacement and spring compression.
    pub fn solve_from(&self, speed_rpm: f64, load: &PairLoad, start_u: [f64; 5], start_x: f64) -> Result<PairState> {
        let mut w = PairWarm {
            displacement: start_u,
            spring_compression_m: start_x,
            ..Default::default()
        };
        self.solve_warm(speed_rpm, load, &mut w)
    }

    /// Solve starting from (and updating) a warm start. A warm start the
    /// damped Newton iteration cannot leave (no step along its direction
    /// lowers the residual, as a start on the far side of a contact loss
    /// can do) is retried once from the cold start, the unloaded position.
    pub fn solve_warm(&self, speed_rpm: f64, load: &PairLoad, pw: &mut PairWarm) -> Result<PairState> {
        let cold = pw.displacement == [0.0; 5]
            && pw.spring_compression_m == 0.0
            && pw.balls.iter().all(|b| *b == WarmStart::default());
        match self.solve_warm_once(speed_rpm, load, pw) {
            Err(Error::Convergence { .. }) if !cold => {
                *pw = PairWarm::default();
                self.solve_warm_once(speed_rpm, load, pw)
            }
            r => r,
        }
    }

    fn solve_warm_once(&self, speed_rpm: f64, load: &PairLoad, pw: &mut PairWarm) -> Result<PairState> {
        let (start_u, start_x) = (pw.displacement, pw.spring_compression_m);
        non_negative("speed_rpm", speed_rpm)?;
        for (i, v) in load.external_load.iter().enumerate() {
            finite(
                ["radial_x_n", "radial_y_n", "axial_n", "moment_x_n_m", "moment_y_n_m"][i],
                *v,
            )?;
        }
        finite("spring_growth_m", load.spring_growth_m)?;
        let warm = &mut pw.balls;
        let (mut u, mut x) = (start_u, start_x);
        let scale = self
            .preload
            .force_n()
            .max(load.external_load.iter().fold(1.0, |a, v| a.max(v.abs())));
        let tol = self.options.tolerance.max(1e-10) * scale;
        let norm = |r: &[f64; 6]| {
            let m = r[3].abs().max(r[4].abs()) / self.spacing_m.max(0.01);
            r[0].abs().max(r[1].abs()).max(r[2].abs()).max(r[5].abs()).max(m)
        };
        let mut res = self.residual(&u, x, speed_rpm, load, warm)?;
        let mut rn = norm(&res.r);
        let max_it = self.options.max_iterations;
        for it in 0..max_it {
            if rn <= tol {
                let st = self.finish(u, x, speed_rpm, load, warm, res, it)?;
                pw.displacement = u;
                pw.spring_compression_m = x;
                return Ok(st);
            }
            let jm = nalgebra::SMatrix::<f64, 6, 6>::from_fn(|i, j| res.jac[i][j]);
            let rv = nalgebra::SVector::<f64, 6>::from_fn(|i, _| -res.r[i]);
            let dx = jm
                .lu()
                .solve(&rv)
                .ok_or_else(|| Error::convergence("bearing pair equilibrium (singular)", it, rn, tol))?;
            // Damped step: at most 5 um / 1 mrad per iteration, halving on growth.
            let big = (0..3).map(|i| dx[i].abs()).fold(dx[5].abs(), f64::max) / 5e-6;
            let bigt = dx[3].abs().max(dx[4].abs()) / 1e-3;
            let mut lam = 1.0 / big.max(bigt).max(1.0);
            let mut accepted = false;
            for _ in 0..30 {
                let mut ut = u;
                for i in 0..5 {
                    ut[i] += lam * dx[i];
                }
                let xt = if self.spring_rate().is_some() {
                    x + lam * dx[5]
                } else {
                    0.0
                };
                if let Ok(rt) = self.residual(&ut, xt, speed_rpm, load, warm) {
                    let rtn = norm(&rt.r);
                    if rtn < rn || rtn <= tol {
                        (u, x, res, rn) = (ut, xt, rt, rtn);
                        accepted = true;
                        break;
                    }
                }
                lam *= 0.5;
            }
            if !accepted {
                return Err(Error::convergence("bearing pair equilibrium", it, rn, tol));
            }
        }
        if rn <= tol {
            let st = self.finish(u, x, speed_rpm, load, warm, res, max_it)?;
            pw.displacement = u;
            pw.spring_compression_m = x;
            return Ok(st);
        }
        Err(Error::convergence("bearing pair equilibrium", max_it, rn, tol))
    }

    #[allow(clippy::too_many_arguments)]
    fn finish(
        &self,
        u: [f64; 5],
        x: f64,
        speed_rpm: f64,
        load: &PairLoad,
        warm: &mut [WarmStart; 2],
        res: Residual,
        iterations: usize,
    ) -> Result<PairState> {
        // The last residual evaluation was at (u, x): `warm` holds its balls.
        let q = self.local_q(&u, x, load);
        let mut states = Vec::with_capacity(2);
        for (k, f) in res.forces.iter().enumerate() {
            let model = if k == 0 { &self.model_a } else { &self.model_b };
            let opts = SolveOptions {
                offsets: load.offsets[k],
                ..self.options
            };
            let balls = model.ball_states(&q[k], speed_rpm, &opts, &warm[k])?;
            let (ka, kr) = crate::bearing::seed_stiffness(model, &balls);
            states.push(BearingState {
                displacement: q[k],
                applied_load: f.reaction.map(|v| -v),
                balls,
                stiffness_matrix: f.stiffness_matrix,
                axial_stiffness_seed_n_per_m: ka,
                radial_stiffness_seed_n_per_m: kr,
                iterations,
                residual: 0.0,
                speed_rpm,
            });
        }
        let b = states
            .pop()
            .ok_or_else(|| Error::convergence("bearing pair", 0, f64::NAN, 0.0))?;
        let a = states
            .pop()
            .ok_or_else(|| Error::convergence("bearing pair", 0, f64::NAN, 0.0))?;
        Ok(PairState {
            displacement: u,
            axial_force_n: res.axial,
            preload_n: 0.5 * (res.axial[0] + res.axial[1]),
            spring_compression_m: x,
            stiffness_matrix: res.kpair,
            bearings: [a, b],
            iterations,
        })
    }

    /// Reaction of the pair on the shaft [Fx, Fy, Fz, Mx, My] at a
    /// prescribed shaft displacement (spring at compression `x`), i.e. the
    /// forward map whose Jacobian is minus the pair stiffness.
    pub fn shaft_reaction(&self, u: &[f64; 5], x: f64, speed_rpm: f64, load: &PairLoad) -> Result<[f64; 5]> {
        let no_load = PairLoad {
            external_load: [0.0; 5],
            ..*load
        };
        let mut warm = [WarmStart::new(), WarmStart::new()];
        let r = self.residual(u, x, speed_rpm, &no_load, &mut warm)?;
        Ok([r.r[0], r.r[1], r.r[2], r.r[3], r.r[4]])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Bearing;

    fn pair(preload: Preload) -> BearingPair {
        let m = BearingModel::new(&Bearing::preset("7009C").unwrap()).unwrap();
        BearingPair::new(m.clone(), m, 0.016, preload, SolveOptions::default()).unwrap()
    }

    #[test]
    fn symmetric_pair_without_load() {
        let p = pair(Preload::Rigid { force_n: 300.0 });
        for speed in [0.0, 12_000.0] {
            let s = p.solve(speed, &PairLoad::default()).unwrap();
            assert!((s.axial_force_n[0] - s.axial_force_n[1]).abs() < 1e-6 * 300.0, "{s:?}");
            assert!(s.displacement.iter().all(|v| v.abs() < 1e-12), "{:?}", s.displacement);
            if speed == 0.0 {
                assert!((s.preload_n - 300.0).abs() < 1e-3);
            }
        }
    }

    #[test]
    fn pair_stiffness_is_sum_of_mirrored_bearings() {
        let p = pair(Preload::Rigid { force_n: 400.0 });
        let s = p.solve(9000.0, &PairLoad::default()).unwrap();
        let (ka, kb) = (&s.bearings[0].stiffness_matrix, &s.bearings[1].stiffness_matrix);
        let k = &s.stiffness_matrix;
        let close = |a: f64, b: f64| (a - b).abs() <= 1e-9 * a.abs().max(b.abs());
        // Translations add directly; the mirror flips z and both tilts, so
        // their diagonal terms add as well, and the x-z couplings cancel.
        for i in 0..3 {
            assert!(close(k[i][i], ka[i][i] + kb[i][i]), "{i}");
        }
        assert!(k[0][2].abs() <= 1e-6 * k[0][0]);
        // Tilt about y: the shaft tilt moves A by -h theta_y and B (mirrored,
        // local tilt -theta_y) by +h theta_y radially, so each bearing adds
        // K_44 + h^2 K_00 - h (K_04 + K_40).
        let h = 0.5 * p.spacing_m;
        let one = |k: &[[f64; 5]; 5]| k[4][4] + h * h * k[0][0] - h * (k[0][4] + k[4][0]);
        let expect = one(ka) + one(kb);
        assert!((k[4][4] - expect).abs() <= 1e-6 * k[4][4].abs(), "{} {expect}", k[4][4]);
        // Symmetric pair without load: equal stiffness of both bearings.
        assert!(close(ka[2][2], kb[2][2]) && close(ka[0][0], kb[0][0]));
    }

    #[test]
    fn pair_stiffness_is_jacobian_of_pair_force() {
        let p = pair(Preload::Rigid { force_n: 300.0 });
        let load = PairLoad {
            external_load: [400.0, 0.0, 150.0, 0.0, 0.0],
            ..Default::default()
        };
        let s = p.solve(6000.0, &load).unwrap();
        let u0 = s.displacement;
        for j in 0..5 {
            let h = if j < 3 { 1e-9 } else { 1e-7 };
            let mut up = u0;
            let mut um = u0;
            up[j] += h;
            um[j] -= h;
            let fp = p.shaft_reaction(&up, 0.0, 6000.0, &load).unwrap();
            let fm = p.shaft_reaction(&um, 0.0, 6000.0, &load).unwrap();
            for i in 0..5 {
                let fd = -(fp[i] - fm[i]) / (2.0 * h);
                let k = s.stiffness_matrix[i][j];
                let scale = s.stiffness_matrix[i][i]
                    .abs()
                    .max(s.stiffness_matrix[j][j].abs())
                    .max(1.0);
                assert!(
                    (fd - k).abs() < 1e-4 * scale.sqrt() * k.abs().max(scale).sqrt(),
                    "{i} {j} {fd} {k}"
                );
            }
        }
    }

    #[test]
    fn spring_limits() {
        let rigid = pair(Preload::Rigid { force_n: 300.0 });
        let soft = pair(Preload::Spring {
            force_n: 300.0,
            rate_n_per_m: 1e-3,
        });
        let stiff = pair(Preload::Spring {
            force_n: 300.0,
            rate_n_per_m: 1e14,
        });
        // Radial thermal interference raises a rigid preload; a soft spring keeps F0.
        let off = RacewayOffsets {
            axial_m: 0.0,
            radial_m: 3e-6,
        };
        let load = PairLoad {
            offsets: [off, off],
            ..Default::default()
        };
        let r = rigid.solve(12_000.0, &load).unwrap();
        let s0 = soft.solve(12_000.0, &load).unwrap();
        let s1 = stiff.solve(12_000.0, &load).unwrap();
        assert!(r.preload_n > 330.0, "{}", r.preload_n);
        assert!((s0.preload_n - 300.0).abs() < 1e-3, "{}", s0.preload_n);
        assert!(
            (s1.preload_n - r.preload_n).abs() < 1e-3 * r.preload_n,
            "{} {}",
            s1.preload_n,
            r.preload_n
        );
    }
}
