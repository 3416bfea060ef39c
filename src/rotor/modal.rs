//! Natural frequencies against speed (Campbell diagram), whirl direction
//! and critical speeds.
//!
//! The quadratic eigenproblem (M s^2 + (C + Omega G) s + K) v = 0 is solved
//! in first-order (state-space) form, A = [[0, I], [-M^-1 K, -M^-1 (C + Omega G)]]
//! (Friswell et al. 2010, section 3.7), by nalgebra's real Schur
//! decomposition. Eigenvectors of the selected modes come from inverse
//! iteration on the quadratic pencil D(s) = M s^2 + (C + Omega G) s + K at a
//! shift next to each eigenvalue. Whirl direction: the orbit of a node is
//! x + i y = R_f e^{i w t} + R_b e^{-i w t}, R_f = (X + i Y)/2,
//! R_b = conj(X - i Y)/2; a mode whirls forward when the kinetic-energy
//! weighted sum of |R_f|^2 (translations and tilts) exceeds that of |R_b|^2.

use nalgebra::{Complex, DMatrix, DVector};
use rayon::prelude::*;

use super::{Rotor, SystemMatrices, DOF_PER_NODE};
use crate::error::{finite, Error, Result};

/// Whirl direction of a mode relative to the spin.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Whirl {
    /// The orbit turns in the direction of spin.
    Forward,
    /// The orbit turns against the spin.
    Backward,
    /// Planar (no dominant direction), or not classified.
    Undetermined,
}

/// One damped mode at one speed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Mode {
    /// Damped natural frequency Im(s) / 2 pi \[Hz\].
    pub frequency_hz: f64,
    /// Damping ratio -Re(s) / |s| [-] (negative: unstable).
    pub damping_ratio: f64,
    /// Whirl direction; [`Whirl::Undetermined`] for a repeated pair or when
    /// [`CampbellOptions::classify_whirl`] is off.
    pub whirl: Whirl,
}

/// Options of the Campbell analysis.
#[derive(Debug, Clone, PartialEq)]
pub struct CampbellOptions {
    /// Modes kept per speed (lowest frequencies first).
    pub modes: usize,
    /// Pseudo-modal reduction to this many undamped modes (None: full model).
    pub reduced_modes: Option<usize>,
    /// Speed at which the reduction basis is computed \[rpm\].
    pub basis_speed_rpm: f64,
    /// Compute eigenvectors and classify forward/backward whirl.
    pub classify_whirl: bool,
}

impl Default for CampbellOptions {
    fn default() -> Self {
        CampbellOptions {
            modes: 8,
            reduced_modes: None,
            basis_speed_rpm: 0.0,
            classify_whirl: true,
        }
    }
}

/// Modes at one speed.
#[derive(Debug, Clone, PartialEq)]
pub struct CampbellPoint {
    /// Shaft speed \[rpm\].
    pub speed_rpm: f64,
    /// Ascending frequency.
    pub modes: Vec<Mode>,
}

/// A Campbell diagram.
#[derive(Debug, Clone, PartialEq)]
pub struct CampbellDiagram {
    /// One point per requested speed, in input order.
    pub points: Vec<CampbellPoint>,
}

/// A crossing of a whirl branch with an excitation line.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CriticalSpeed {
    /// Critical speed \[rpm\], interpolated between diagram speeds (or refined
    /// by [`refine_critical_speed`]).
    pub speed_rpm: f64,
    /// Frequency at the crossing, harmonic x speed / 60 \[Hz\].
    pub frequency_hz: f64,
    /// Index of the branch (ascending frequency order).
    pub branch: usize,
    /// Excitation order (1 for 1X).
    pub harmonic: f64,
    /// Whirl of the branch at the diagram speed nearest the crossing (at the
    /// final trial speed after refinement).
    pub whirl: Whirl,
    /// Neighbouring diagram speeds that bracket the crossing \[rpm\].
    pub bracket_rpm: [f64; 2],
}

/// Eigenvalues of the quadratic pencil of `m` (all of them, 2n).
///
/// The state matrix is built in undamped mass-normalised modal
/// coordinates eta (q = L^-T Q eta, M = L L^T, L^-1 K L^-T = Q Lambda Q^T)
/// with the scaled state [w eta, eta']: S = [[0, W_a], [-W_b, -D~]],
/// W_a = sqrt|Lambda|, W_b = sign(Lambda) sqrt|Lambda|, D~ = Q^T L^-1 (C + Omega G) L^-T Q.
/// det(s I - S) = det(s^2 I + s D~ + Lambda) holds even for zero or negative
/// Lambda, and the entries of S scale with w_max instead of w_max^2, which
/// keeps the Schur eigenvalues accurate next to very stiff high modes.
pub fn eigenvalues(m: &SystemMatrices) -> Result<Vec<Complex<f64>>> {
    let n = m.size();
    let not_pd = || Error::config("mass", "matrix", "not positive definite");
    let l = m.mass_si.clone().cholesky().ok_or_else(not_pd)?.l();
    let (lambda, q) = super::symmetric_modes(&m.mass_si, &m.stiffness_si)?;
    // D~ = Q^T L^-1 D L^-T Q.
    let d = m.damping_and_gyroscopic();
    let y = l.solve_lower_triangular(&d).ok_or_else(not_pd)?;
    let z = l.solve_lower_triangular(&y.transpose()).ok_or_else(not_pd)?.transpose();
    let dt = q.transpose() * z * &q;
    let mut a = DMatrix::zeros(2 * n, 2 * n);
    for i in 0..n {
        let w = lambda[i].abs().sqrt();
        a[(i, n + i)] = w;
        a[(n + i, i)] = -lambda[i].signum() * w;
        for j in 0..n {
            a[(n + i, n + j)] = -dt[(i, j)];
        }
    }
    let max_iter = 10_000;
    let schur = nalgebra::Schur::try_new(a, f64::EPSILON, max_iter)
        .ok_or_else(|| Error::convergence("real Schur (state-space eigenvalues)", max_iter, f64::NAN, f64::EPSILON))?;
    Ok(schur.complex_eigenvalues().iter().copied().collect())
}

/// Dynamic stiffness D(s) = M s^2 + (C + Omega G) s + K, complex.
pub fn dynamic_stiffness(m: &SystemMatrices, s: Complex<f64>) -> DMatrix<Complex<f64>> {
    let d = m.damping_and_gyroscopic();
    DMatrix::from_fn(m.size(), m.size(), |i, j| {
        Complex::new(m.stiffness_si[(i, j)], 0.0) + s * d[(i, j)] + s * s * m.mass_si[(i, j)]
    })
}

/// Right eigenvector of the pencil at eigenvalue `s` by two steps of
/// inverse iteration with a slightly shifted, factorised D.
pub fn eigenvector(m: &SystemMatrices, s: Complex<f64>) -> Result<DVector<Complex<f64>>> {
    let n = m.size();
    let shift = s + s.norm().max(1.0) * Complex::new(1e-9, 1e-9);
    let lu = dynamic_stiffness(m, shift).lu();
    let mut v = DVector::from_fn(n, |i, _| Complex::new(1.0, (i as f64 + 1.0) / n as f64));
    for _ in 0..2 {
        v = lu
            .solve(&v)
            .ok_or_else(|| Error::convergence("inverse iteration (mode shape)", 2, f64::INFINITY, 0.0))?;
        let norm = v.norm();
        if !(norm.is_finite() && norm > 0.0) {
            return Err(Error::convergence("inverse iteration (mode shape)", 2, norm, 0.0));
        }
        v /= Complex::new(norm, 0.0);
    }
    Ok(v)
}

/// Whirl direction of a physical mode shape (4 DOF per node), weighted by
/// the diagonal of the mass matrix (kinetic energy of each DOF).
pub fn whirl_direction(shape: &DVector<Complex<f64>>, mass_diagonal: &DVector<f64>) -> Whirl {
    let i = Complex::new(0.0, 1.0);
    let (mut fwd, mut bwd) = (0.0, 0.0);
    for node in 0..shape.len() / DOF_PER_NODE {
        let o = node * DOF_PER_NODE;
        let (x, y, tx, ty) = (shape[o], shape[o + 1], shape[o + 2], shape[o + 3]);
        let wt = mass_diagonal[o];
        let wr = mass_diagonal[o + 2];
        // Translation x + i y; tilt of the spin axis n = (ty, -tx).
        fwd += wt * (x + i * y).norm_sqr() + wr * (ty - i * tx).norm_sqr();
        bwd += wt * (x - i * y).norm_sqr() + wr * (ty + i * tx).norm_sqr();
    }
    if (fwd - bwd).abs() <= 1e-3 * (fwd + bwd) {
        Whirl::Undetermined
    } else if fwd > bwd {
        Whirl::Forward
    } else {
        Whirl::Backward
    }
}

/// Modes of `rotor` at one speed, using an optional reduction basis.
pub fn modes_at(
    rotor: &Rotor,
    speed_rpm: f64,
    basis: Option<&DMatrix<f64>>,
    options: &CampbellOptions,
) -> Result<Vec<Mode>> {
    finite("speed_rpm", speed_rpm)?;
    if let Some(phi) = basis {
        if phi.nrows() != rotor.dof_count() || phi.ncols() == 0 {
            return Err(Error::config(
                "basis",
                format!("{}x{}", phi.nrows(), phi.ncols()),
                format!("needs {} rows and at least one column", rotor.dof_count()),
            ));
        }
    }
    let full = rotor.matrices(speed_rpm)?;
    let sys = match basis {
        Some(phi) => full.reduce(phi),
        None => full.clone(),
    };
    let values = eigenvalues(&sys)?;
    let scale = values.iter().map(|v| v.norm()).fold(0.0, f64::max);
    let mut kept: Vec<Complex<f64>> = values
        .into_iter()
        .filter(|v| v.im > 1e-3_f64.max(1e-6 * scale))
        .collect();
    kept.sort_by(|a, b| a.im.total_cmp(&b.im));
    let take = options.modes.min(kept.len());
    let mass_diagonal = full.mass_si.diagonal();
    // A (numerically) repeated pair has no defined whirl direction (any
    // combination of forward and backward is a mode, e.g. at rest).
    let repeated = |k: usize| {
        let near = |j: usize| (kept[j] - kept[k]).norm() <= 1e-6 * kept[k].norm();
        (k > 0 && near(k - 1)) || (k + 1 < kept.len() && near(k + 1))
    };
    let mut modes = kept[..take]
        .iter()
        .enumerate()
        .map(|(k, &s)| {
            if repeated(k) {
                return Ok(Mode {
                    frequency_hz: s.im / (2.0 * std::f64::consts::PI),
                    damping_ratio: -s.re / s.norm(),
                    whirl: Whirl::Undetermined,
                });
            }
            let whirl = if options.classify_whirl {
                let v = eigenvector(&sys, s)?;
                let shape = match basis {
                    Some(phi) => phi.map(|x| Complex::new(x, 0.0)) * v,
                    None => v,
                };
                whirl_direction(&shape, &mass_diagonal)
            } else {
                Whirl::Undetermined
            };
            Ok(Mode {
                frequency_hz: s.im / (2.0 * std::f64::consts::PI),
                damping_ratio: -s.re / s.norm(),
                whirl,
            })
        })
        .collect::<Result<Vec<_>>>()?;
    modes.sort_by(|a, b| a.frequency_hz.total_cmp(&b.frequency_hz));
    Ok(modes)
}

/// Campbell diagram over `speeds_rpm`, in parallel over speeds
/// (deterministic: each speed is computed independently, results in input order).
pub fn campbell(rotor: &Rotor, speeds_rpm: &[f64], options: &CampbellOptions) -> Result<CampbellDiagram> {
    if options.modes == 0 {
        return Err(Error::config("modes", 0, "ask for at least one mode"));
    }
    let basis = match options.reduced_modes {
        Some(r) => Some(rotor.modal_basis(options.basis_speed_rpm, r)?),
        None => None,
    };
    let points = speeds_rpm
        .par_iter()
        .map(|&speed_rpm| {
            Ok(CampbellPoint {
                speed_rpm,
                modes: modes_at(rotor, speed_rpm, basis.as_ref(), options)?,
            })
        })
        .collect::<Result<Vec<_>>>()?;
    Ok(CampbellDiagram { points })
}

impl CampbellDiagram {
    /// Speeds where branch k (k-th lowest frequency, a continuous function
    /// of speed) crosses the line f = harmonic * speed / 60, by linear
    /// interpolation between neighbouring speeds.
    pub fn critical_speeds(&self, harmonic: f64) -> Vec<CriticalSpeed> {
        let mut out = Vec::new();
        let branches = self.points.iter().map(|p| p.modes.len()).min().unwrap_or(0);
        for k in 0..branches {
            for w in self.points.windows(2) {
                let (a, b) = (&w[0], &w[1]);
                let fa = a.modes[k].frequency_hz - harmonic * a.speed_rpm / 60.0;
                let fb = b.modes[k].frequency_hz - harmonic * b.speed_rpm / 60.0;
                if fa == 0.0 || fa * fb < 0.0 {
                    let t = fa / (fa - fb);
                    let speed_rpm = a.speed_rpm + t * (b.speed_rpm - a.speed_rpm);
                    let nearest = if t < 0.5 { a } else { b };
                    out.push(CriticalSpeed {
                        speed_rpm,
                        frequency_hz: harmonic * speed_rpm / 60.0,
                        branch: k,
                        harmonic,
                        whirl: nearest.modes[k].whirl,
                        bracket_rpm: [a.speed_rpm, b.speed_rpm],
                    });
                }
            }
        }
        out.sort_by(|x, y| x.speed_rpm.total_cmp(&y.speed_rpm));
        out
    }

    /// Frequencies of branch `k` over the speeds \[Hz\] (NaN where absent).
    pub fn branch_hz(&self, k: usize) -> Vec<f64> {
        self.points
            .iter()
            .map(|p| p.modes.get(k).map_or(f64::NAN, |m| m.frequency_hz))
            .collect()
    }
}

/// Refine a critical speed from [`CampbellDiagram::critical_speeds`] by
/// the Illinois variant of regula falsi on g(n) = f_branch(n) - harmonic n / 60
/// inside its bracket, with fresh eigen-solutions at each trial speed (same
/// options, and the same reduction basis, as the diagram).
pub fn refine_critical_speed(rotor: &Rotor, c: &CriticalSpeed, options: &CampbellOptions) -> Result<CriticalSpeed> {
    let basis = match options.reduced_modes {
        Some(r) => Some(rotor.modal_basis(options.basis_speed_rpm, r)?),
        None => None,
    };
    let opts = CampbellOptions {
        modes: options.modes.max(c.branch + 1),
        ..options.clone()
    };
    let g = |n: f64| -> Result<(f64, Whirl)> {
        let modes = modes_at(rotor, n, basis.as_ref(), &opts)?;
        let m = modes
            .get(c.branch)
            .ok_or_else(|| Error::config("branch", c.branch, "branch absent at this speed"))?;
        Ok((m.frequency_hz - c.harmonic * n / 60.0, m.whirl))
    };
    let [mut a, mut b] = c.bracket_rpm;
    let (mut ga, _) = g(a)?;
    let (mut gb, _) = g(b)?;
    if ga * gb > 0.0 {
        return Err(Error::config(
            "bracket_rpm",
            format!("{a}..{b}"),
            "does not bracket a crossing",
        ));
    }
    let tol = 1e-9 * b.abs().max(1.0);
    let max_iter = 60;
    for _ in 0..max_iter {
        let n = (a * gb - b * ga) / (gb - ga);
        let (gn, whirl) = g(n)?;
        if gn == 0.0 || (b - a).abs() < tol || gn.abs() < 1e-12 * c.frequency_hz.max(1.0) {
            return Ok(CriticalSpeed {
                speed_rpm: n,
                frequency_hz: c.harmonic * n / 60.0,
                whirl,
                ..*c
            });
        }
        if gn * gb < 0.0 {
            // Root between b and n: b becomes the far end.
            (a, ga) = (b, gb);
        } else {
            // Same side as b twice: halve the stale end (Illinois).
            ga *= 0.5;
        }
        (b, gb) = (n, gn);
    }
    Err(Error::convergence(
        "critical speed (Illinois)",
        max_iter,
        (b - a).abs(),
        tol,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::materials::Material;
    use crate::rotor::test_support::free_shaft;
    use crate::rotor::{BearingCoefficients, BearingSupport, Disk, RotorSpec, ShaftSection};
    use std::f64::consts::PI;
    use std::sync::Arc;

    #[test]
    fn free_free_slender_beam_matches_euler_bernoulli() {
        // Free-free beam: beta_n L = 4.730041, 7.853205, 10.995608
        // (Blevins, Formulas for Natural Frequency and Mode Shape, table 8-1).
        let (l, d) = (1.0, 0.01);
        let r = free_shaft(l, d, 12);
        let s = ShaftSection::new(l, d, 0.0, Material::shaft_steel()).unwrap();
        let ei = s.material.youngs_modulus_pa * s.second_moment_m4();
        let ra = s.material.density_kg_m3 * s.area_m2();
        let m = modes_at(&r, 0.0, None, &CampbellOptions::default()).unwrap();
        // Two planes: each frequency appears twice.
        for (n, bl) in [4.730041_f64, 7.853205, 10.995608].iter().enumerate() {
            let exact = bl * bl / (l * l) * (ei / ra).sqrt() / (2.0 * PI);
            for f in [m[2 * n].frequency_hz, m[2 * n + 1].frequency_hz] {
                assert!((f - exact).abs() / exact < 2e-3, "mode {n}: {f} vs {exact}");
            }
        }
    }

    /// Short thick steel shaft (bending stiffness ~1900 x the springs, so
    /// effectively rigid) with a disk at its centre, on two equal isotropic
    /// springs k at the ends (+-a from the centre). Returns the rotor and
    /// its rigid-body totals (k, a, m, Ip, Id about the centre).
    fn disk_on_springs() -> (Rotor, [f64; 5]) {
        let (k, a, d) = (2e5, 0.1, 0.05);
        let steel = Material::shaft_steel();
        let disk = Disk {
            name: "disk".into(),
            position_m: a,
            mass_kg: 10.0,
            polar_inertia_kg_m2: 0.2,
            diametral_inertia_kg_m2: 0.12,
        };
        let spring = Arc::new(BearingCoefficients::diagonal(k, 0.0, 0.0, 0.0).unwrap());
        let r = Rotor::new(RotorSpec {
            sections: vec![ShaftSection::new(2.0 * a, d, 0.0, steel.clone()).unwrap()],
            disks: vec![disk.clone()],
            bearings: vec![
                BearingSupport::new("left", 0.0, spring.clone()),
                BearingSupport::new("right", 2.0 * a, spring),
            ],
            magnetic_pull: None,
            modal_damping_ratio: 0.0,
            max_element_length_m: 0.05,
        })
        .unwrap();
        let ms = steel.density_kg_m3 * PI * d * d / 4.0 * 2.0 * a;
        let m = disk.mass_kg + ms;
        let ip = disk.polar_inertia_kg_m2 + ms * d * d / 8.0;
        let id = disk.diametral_inertia_kg_m2 + ms * (d * d / 16.0 + (2.0 * a).powi(2) / 12.0);
        (r, [k, a, m, ip, id])
    }

    #[test]
    fn rigid_disk_on_springs_gyroscopic_splitting() {
        // Translation decouples: w_t = sqrt(2k/m). Tilt: Id w^2 -+ Ip Omega w - 2 k a^2 = 0,
        // w_f,b = (+-Ip W + sqrt(Ip^2 W^2 + 8 Id k a^2)) / (2 Id)
        // (Friswell et al. 2010, section 3.5, rigid rotor).
        let (r, [k, a, m, ip, id]) = disk_on_springs();
        let speed_rpm = 20_000.0;
        let w = crate::units::rpm_to_rad_s(speed_rpm);
        let root = (ip * ip * w * w + 8.0 * id * k * a * a).sqrt();
        let wf = (ip * w + root) / (2.0 * id) / (2.0 * PI);
        let wb = (-ip * w + root) / (2.0 * id) / (2.0 * PI);
        let wt = (2.0 * k / m).sqrt() / (2.0 * PI);
        let modes = modes_at(&r, speed_rpm, None, &CampbellOptions::default()).unwrap();
        let find = |f: f64| modes.iter().find(|m| (m.frequency_hz - f).abs() < 2e-3 * f).copied();
        let b = find(wb).unwrap_or_else(|| panic!("backward {wb} not in {modes:?}"));
        let f = find(wf).unwrap_or_else(|| panic!("forward {wf} not in {modes:?}"));
        assert_eq!(b.whirl, Whirl::Backward);
        assert_eq!(f.whirl, Whirl::Forward);
        let t: Vec<_> = modes
            .iter()
            .filter(|m| (m.frequency_hz - wt).abs() < 2e-3 * wt)
            .collect();
        assert_eq!(t.len(), 2, "translation {wt} (forward + backward) not in {modes:?}");
    }

    #[test]
    fn rigid_disk_critical_speeds_match_closed_form() {
        // 1X crossings (w = Omega): translation at sqrt(2k/m); backward tilt
        // at sqrt(2 k a^2 / (Id + Ip)); a disk-like rotor (Ip > Id) has no
        // forward tilt critical. Coarse diagram + regula-falsi refinement.
        let (r, [k, a, m, ip, id]) = disk_on_springs();
        assert!(ip > id);
        let to_rpm = 30.0 / PI;
        let n_t = (2.0 * k / m).sqrt() * to_rpm;
        let n_b = (2.0 * k * a * a / (id + ip)).sqrt() * to_rpm;
        let speeds: Vec<f64> = (0..=12).map(|i| 250.0 * i as f64).collect();
        let opts = CampbellOptions::default();
        let d = campbell(&r, &speeds, &opts).unwrap();
        let crit = d.critical_speeds(1.0);
        assert_eq!(crit.len(), 3, "{crit:?}");
        let refined: Vec<CriticalSpeed> = crit
            .iter()
            .map(|c| refine_critical_speed(&r, c, &opts).unwrap())
            .collect();
        assert!((refined[0].speed_rpm - n_b).abs() < 2e-3 * n_b, "{refined:?} vs {n_b}");
        assert_eq!(refined[0].whirl, Whirl::Backward);
        for c in &refined[1..] {
            assert!((c.speed_rpm - n_t).abs() < 2e-3 * n_t, "{c:?} vs {n_t}");
        }
        // The refined speed solves f_branch(n) = n / 60 of the model itself.
        let c = &refined[0];
        let f = modes_at(&r, c.speed_rpm, None, &opts).unwrap()[c.branch].frequency_hz;
        assert!(
            (f - c.speed_rpm / 60.0).abs() < 1e-8 * f,
            "{f} vs {}",
            c.speed_rpm / 60.0
        );
    }

    #[test]
    fn critical_speed_of_rigid_translation_mode_is_its_frequency() {
        // Translation mode of the disk above does not depend on speed, so
        // its 1X critical speed is 60 * f.
        let p = |s: f64, f: f64| CampbellPoint {
            speed_rpm: s,
            modes: vec![Mode {
                frequency_hz: f,
                damping_ratio: 0.0,
                whirl: Whirl::Forward,
            }],
        };
        let d = CampbellDiagram {
            points: vec![p(0.0, 100.0), p(10_000.0, 100.0)],
        };
        let c = d.critical_speeds(1.0);
        assert_eq!(c.len(), 1);
        assert!((c[0].speed_rpm - 6_000.0).abs() < 1e-9);
        assert!((d.critical_speeds(2.0)[0].speed_rpm - 3_000.0).abs() < 1e-9);
    }
}
