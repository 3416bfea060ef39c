//! Rotor dynamics of a spindle (seed B): Timoshenko finite-element shaft,
//! lumped disks, linearised bearings, unbalanced magnetic pull, Campbell
//! diagram and critical speeds, unbalance response (frequency and time
//! domain), vibration velocity and spectra.
//!
//! [`spindle_bearings`] builds the supports from the bearing solver
//! (preloaded angular-contact rows, linearised or as nonlinear ball forces,
//! with the thermal raceway-offset seam); [`spindle_vibration`] applies them
//! to the seed B spindle.
//!
//! Equations of motion (Friswell et al. 2010, eq. 5.125 form):
//! `M q'' + (C + Omega G) q' + K(Omega) q = f(t)`, q = [x, y, theta_x, theta_y]
//! per node (see [`beam`] for the sign convention).

pub mod beam;
pub mod magnetic_pull;
pub mod modal;
pub mod presets;
pub mod response;
pub mod spectrum;
pub mod spindle_bearings;
pub mod spindle_vibration;
pub mod support;
pub mod transient;

use nalgebra::{DMatrix, DVector};

use crate::error::{in_range, non_negative, Error, Result};
use crate::units::rpm_to_rad_s;
pub use beam::{BeamElement, ShaftMesh, ShaftSection, DOF_PER_NODE};
pub use magnetic_pull::UnbalancedMagneticPull;
pub use support::{BearingCoefficients, BearingModel, BearingSupport, SpeedTable};

/// A rigid disk lumped at a node (rotor core, tool holder, nut...).
#[derive(Debug, Clone, PartialEq)]
pub struct Disk {
    /// Label used in error messages (e.g. `tool_holder`, `rotor_core_0`).
    pub name: String,
    /// Axial position of the disk's centre of mass \[m\].
    pub position_m: f64,
    /// Mass \[kg\], added to both translations of its node.
    pub mass_kg: f64,
    /// Polar moment of inertia Ip about the spin axis [kg m^2].
    pub polar_inertia_kg_m2: f64,
    /// Diametral moment of inertia Id about a transverse axis through the centre [kg m^2].
    pub diametral_inertia_kg_m2: f64,
}

impl Disk {
    /// A uniform hollow cylinder of density `density_kg_m3`:
    /// m = rho pi (do^2 - di^2) l / 4, Ip = m (do^2 + di^2) / 8,
    /// Id = Ip / 2 + m l^2 / 12.
    pub fn hollow_cylinder(
        name: impl Into<String>,
        position_m: f64,
        outer_diameter_m: f64,
        inner_diameter_m: f64,
        length_m: f64,
        density_kg_m3: f64,
    ) -> Result<Self> {
        crate::error::positive("outer_diameter_m", outer_diameter_m)?;
        non_negative("inner_diameter_m", inner_diameter_m)?;
        non_negative("length_m", length_m)?;
        crate::error::positive("density_kg_m3", density_kg_m3)?;
        if inner_diameter_m >= outer_diameter_m {
            return Err(Error::config(
                "inner_diameter_m",
                inner_diameter_m,
                "must be smaller than outer_diameter_m",
            ));
        }
        let m = density_kg_m3 * std::f64::consts::PI * (outer_diameter_m.powi(2) - inner_diameter_m.powi(2)) * length_m
            / 4.0;
        let ip = m * (outer_diameter_m.powi(2) + inner_diameter_m.powi(2)) / 8.0;
        Ok(Disk {
            name: name.into(),
            position_m,
            mass_kg: m,
            polar_inertia_kg_m2: ip,
            diametral_inertia_kg_m2: ip / 2.0 + m * length_m.powi(2) / 12.0,
        })
    }

    fn validate(&self) -> Result<()> {
        let f = |s: &str| format!("disks[{}].{s}", self.name);
        non_negative(&f("mass_kg"), self.mass_kg)?;
        non_negative(&f("polar_inertia_kg_m2"), self.polar_inertia_kg_m2)?;
        non_negative(&f("diametral_inertia_kg_m2"), self.diametral_inertia_kg_m2)?;
        Ok(())
    }
}

/// Everything that defines a rotor model (user input).
#[derive(Debug, Clone)]
pub struct RotorSpec {
    /// Shaft steps from the left end (z = 0) to the right.
    pub sections: Vec<ShaftSection>,
    /// Rigid disks; each position becomes a mesh node and must lie on the shaft.
    pub disks: Vec<Disk>,
    /// Bearing supports; each position becomes a mesh node and must lie on
    /// the shaft.
    pub bearings: Vec<BearingSupport>,
    /// Optional unbalanced magnetic pull at the rotor core.
    pub magnetic_pull: Option<UnbalancedMagneticPull>,
    /// Modal damping ratio of the rotor-bearing modes at rest [-] (the
    /// structural damping of shaft and fits; bearing damping adds to it).
    pub modal_damping_ratio: f64,
    /// Longest finite element \[m\].
    pub max_element_length_m: f64,
}

/// Lateral DOF of a node.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LateralDof {
    /// Translation x \[m\].
    X = 0,
    /// Translation y \[m\].
    Y = 1,
    /// Rotation about x \[rad\] (theta_x = -du_y/dz, see [`beam`]).
    ThetaX = 2,
    /// Rotation about y \[rad\] (theta_y = +du_x/dz, see [`beam`]).
    ThetaY = 3,
}

/// Global matrices of the rotor at one speed. `_si`: SI blocks per DOF
/// pair (kg, kg m, kg m^2 for mass; N/m, N/rad, N m/rad for stiffness;
/// the same per unit velocity for damping; kg m^2 for the gyroscopic
/// matrix per rad/s of spin; N and N m for forces).
#[derive(Debug, Clone, PartialEq)]
pub struct SystemMatrices {
    /// Spin speed Omega [rad/s].
    pub spin_speed_rad_s: f64,
    /// Mass matrix M: consistent shaft mass and rotary inertia, plus the disk
    /// masses and diametral inertias.
    pub mass_si: DMatrix<f64>,
    /// Gyroscopic matrix per unit spin speed (multiply by Omega), skew.
    pub gyroscopic_si: DMatrix<f64>,
    /// Shaft + bearings (+ UMP negative stiffness).
    pub stiffness_si: DMatrix<f64>,
    /// Modal structural damping + bearing damping.
    pub damping_si: DMatrix<f64>,
    /// Constant forces (UMP from static eccentricity) [N, N m].
    pub static_force_si: DVector<f64>,
}

impl SystemMatrices {
    /// Project on a basis `phi` (n x r): X_r = phi^T X phi.
    pub fn reduce(&self, phi: &DMatrix<f64>) -> SystemMatrices {
        let p = |m: &DMatrix<f64>| phi.transpose() * m * phi;
        SystemMatrices {
            spin_speed_rad_s: self.spin_speed_rad_s,
            mass_si: p(&self.mass_si),
            gyroscopic_si: p(&self.gyroscopic_si),
            stiffness_si: p(&self.stiffness_si),
            damping_si: p(&self.damping_si),
            static_force_si: phi.transpose() * &self.static_force_si,
        }
    }

    /// Number of coordinates.
    pub fn size(&self) -> usize {
        self.mass_si.nrows()
    }

    /// Total viscous matrix C + Omega G.
    pub fn damping_and_gyroscopic(&self) -> DMatrix<f64> {
        &self.damping_si + &self.gyroscopic_si * self.spin_speed_rad_s
    }
}

/// A meshed, assembled rotor.
#[derive(Debug, Clone)]
pub struct Rotor {
    spec: RotorSpec,
    mesh: ShaftMesh,
    mass_si: DMatrix<f64>,
    gyroscopic_si: DMatrix<f64>,
    shaft_stiffness: DMatrix<f64>,
    structural_damping: DMatrix<f64>,
    bearing_nodes: Vec<usize>,
    ump_node: Option<usize>,
}

impl Rotor {
    /// Mesh and assemble. Bearings, disks and the UMP position become nodes;
    /// any of them off the shaft is a configuration error naming it.
    pub fn new(spec: RotorSpec) -> Result<Rotor> {
        in_range("modal_damping_ratio", spec.modal_damping_ratio, 0.0, 1.0)?;
        let total: f64 = spec.sections.iter().map(|s| s.length_m).sum();
        let on_shaft = |field: String, z: f64| -> Result<f64> {
            if z.is_finite() && (-beam::NODE_TOLERANCE_M..=total + beam::NODE_TOLERANCE_M).contains(&z) {
                Ok(z)
            } else {
                Err(Error::config(
                    field,
                    z,
                    format!("lies off the shaft, which spans 0..{total} m"),
                ))
            }
        };
        let mut required = Vec::new();
        for b in &spec.bearings {
            required.push(on_shaft(format!("bearings[{}].position_m", b.name), b.position_m)?);
        }
        for d in &spec.disks {
            d.validate()?;
            required.push(on_shaft(format!("disks[{}].position_m", d.name), d.position_m)?);
        }
        if let Some(u) = &spec.magnetic_pull {
            u.validate()?;
            required.push(on_shaft("magnetic_pull.position_m".into(), u.position_m)?);
        }
        let mesh = ShaftMesh::new(&spec.sections, &required, spec.max_element_length_m)?;
        let (mut mass, mut gyroscopic, shaft_stiffness) = mesh.assemble();
        for d in &spec.disks {
            let o = node_of(&mesh, d.position_m)? * DOF_PER_NODE;
            mass[(o, o)] += d.mass_kg;
            mass[(o + 1, o + 1)] += d.mass_kg;
            mass[(o + 2, o + 2)] += d.diametral_inertia_kg_m2;
            mass[(o + 3, o + 3)] += d.diametral_inertia_kg_m2;
            // Id tx'' + Ip W ty' = Mx ; Id ty'' - Ip W tx' = My (beam module doc).
            gyroscopic[(o + 2, o + 3)] += d.polar_inertia_kg_m2;
            gyroscopic[(o + 3, o + 2)] -= d.polar_inertia_kg_m2;
        }
        let bearing_nodes = spec
            .bearings
            .iter()
            .map(|b| node_of(&mesh, b.position_m))
            .collect::<Result<Vec<_>>>()?;
        let ump_node = match &spec.magnetic_pull {
            Some(u) => Some(node_of(&mesh, u.position_m)?),
            None => None,
        };
        let n = mass.nrows();
        let mut rotor = Rotor {
            spec,
            mesh,
            mass_si: mass,
            gyroscopic_si: gyroscopic,
            shaft_stiffness,
            structural_damping: DMatrix::zeros(n, n),
            bearing_nodes,
            ump_node,
        };
        rotor.structural_damping = rotor.modal_damping_matrix()?;
        Ok(rotor)
    }

    /// The input this rotor was built from.
    pub fn spec(&self) -> &RotorSpec {
        &self.spec
    }

    /// The finite-element mesh.
    pub fn mesh(&self) -> &ShaftMesh {
        &self.mesh
    }

    /// Number of generalized coordinates (4 per node).
    pub fn dof_count(&self) -> usize {
        self.mass_si.nrows()
    }

    /// Node at an axial position (must be a mesh node).
    pub fn node_at(&self, position_m: f64) -> Result<usize> {
        node_of(&self.mesh, position_m)
    }

    /// Global index of a DOF of a node.
    pub fn dof(&self, node: usize, dof: LateralDof) -> usize {
        node * DOF_PER_NODE + dof as usize
    }

    /// Nodes carrying the bearings, in `spec.bearings` order.
    pub fn bearing_nodes(&self) -> &[usize] {
        &self.bearing_nodes
    }

    /// Total rotating mass (shaft + disks) \[kg\].
    pub fn mass_kg(&self) -> f64 {
        self.mesh.elements.iter().map(|e| e.mass_kg()).sum::<f64>()
            + self.spec.disks.iter().map(|d| d.mass_kg).sum::<f64>()
    }

    /// Stiffness of shaft + bearings at `speed_rpm` + UMP, and the bearing damping.
    fn stiffness_and_bearing_damping(&self, speed_rpm: f64) -> Result<(DMatrix<f64>, DMatrix<f64>)> {
        let mut k = self.shaft_stiffness.clone();
        let n = k.nrows();
        let mut c = DMatrix::zeros(n, n);
        for (b, &node) in self.spec.bearings.iter().zip(&self.bearing_nodes) {
            let co = b.coefficients(speed_rpm)?;
            let (kb, cb) = (co.lateral_stiffness(), co.lateral_damping());
            let o = node * DOF_PER_NODE;
            for i in 0..4 {
                for j in 0..4 {
                    k[(o + i, o + j)] += kb[(i, j)];
                    c[(o + i, o + j)] += cb[(i, j)];
                }
            }
        }
        if let (Some(u), Some(node)) = (&self.spec.magnetic_pull, self.ump_node) {
            let o = node * DOF_PER_NODE;
            let ku = u.stiffness_n_per_m();
            k[(o, o)] -= ku;
            k[(o + 1, o + 1)] -= ku;
        }
        Ok((k, c))
    }

    /// Global matrices at shaft speed `speed_rpm`.
    pub fn matrices(&self, speed_rpm: f64) -> Result<SystemMatrices> {
        crate::error::finite("speed_rpm", speed_rpm)?;
        let (stiffness, bearing_damping) = self.stiffness_and_bearing_damping(speed_rpm)?;
        let mut static_force = DVector::zeros(self.dof_count());
        if let (Some(u), Some(node)) = (&self.spec.magnetic_pull, self.ump_node) {
            static_force[node * DOF_PER_NODE] += u.static_force_n();
        }
        Ok(SystemMatrices {
            spin_speed_rad_s: rpm_to_rad_s(speed_rpm),
            mass_si: self.mass_si.clone(),
            gyroscopic_si: self.gyroscopic_si.clone(),
            stiffness_si: stiffness,
            damping_si: &self.structural_damping + bearing_damping,
            static_force_si: static_force,
        })
    }

    /// Undamped non-rotating modes at `speed_rpm` (bearing stiffness at that
    /// speed): natural frequencies [rad/s] ascending and mass-normalised
    /// mode shapes (columns). Negative eigenvalues (UMP exceeding support
    /// stiffness) come out as negative squared frequencies, reported as -sqrt(|l|).
    pub fn undamped_modes(&self, speed_rpm: f64) -> Result<(Vec<f64>, DMatrix<f64>)> {
        let (k, _) = self.stiffness_and_bearing_damping(speed_rpm)?;
        let (values, l_q) = symmetric_modes(&self.mass_si, &k)?;
        // Mode shapes phi = L^-T Q.
        let l = self.mass_si.clone().cholesky().ok_or_else(not_positive_mass)?.l();
        let phi = l
            .transpose()
            .solve_upper_triangular(&l_q)
            .ok_or_else(not_positive_mass)?;
        let w = values.iter().map(|&v| v.signum() * v.abs().sqrt()).collect();
        Ok((w, phi))
    }

    /// The first `modes` mass-normalised undamped modes at `speed_rpm` as a
    /// reduction basis (n x modes), pseudo-modal reduction (Friswell et al.
    /// 2010, section 7.2).
    pub fn modal_basis(&self, speed_rpm: f64, modes: usize) -> Result<DMatrix<f64>> {
        let n = self.dof_count();
        if modes == 0 || modes > n {
            return Err(Error::config("reduced_modes", modes, format!("must lie in 1..={n}")));
        }
        let (_, phi) = self.undamped_modes(speed_rpm)?;
        Ok(phi.columns(0, modes).into_owned())
    }

    /// C = M Phi diag(2 zeta w_i) Phi^T M from the modes at rest (0 rpm).
    fn modal_damping_matrix(&self) -> Result<DMatrix<f64>> {
        let n = self.dof_count();
        let zeta = self.spec.modal_damping_ratio;
        if zeta == 0.0 {
            return Ok(DMatrix::zeros(n, n));
        }
        let (k, _) = self.stiffness_and_bearing_damping(0.0)?;
        let (values, q) = symmetric_modes(&self.mass_si, &k)?;
        let l = self.mass_si.clone().cholesky().ok_or_else(not_positive_mass)?.l();
        // M Phi = L L^T L^-T Q = L Q.
        let lq = &l * &q;
        let mut scaled = lq.clone();
        for (j, v) in values.iter().enumerate() {
            let w = v.max(0.0).sqrt();
            scaled.column_mut(j).scale_mut(2.0 * zeta * w);
        }
        Ok(&scaled * lq.transpose())
    }
}

fn not_positive_mass() -> Error {
    Error::config("mass", "matrix", "rotor mass matrix is not positive definite")
}

/// Eigenvalues (ascending) and eigenvectors Q of L^-1 K L^-T, M = L L^T.
pub(crate) fn symmetric_modes(mass: &DMatrix<f64>, stiffness: &DMatrix<f64>) -> Result<(Vec<f64>, DMatrix<f64>)> {
    let l = mass.clone().cholesky().ok_or_else(not_positive_mass)?.l();
    let y = l.solve_lower_triangular(stiffness).ok_or_else(not_positive_mass)?;
    let a = l.solve_lower_triangular(&y.transpose()).ok_or_else(not_positive_mass)?;
    let a = (&a + a.transpose()) * 0.5;
    let eig = nalgebra::SymmetricEigen::try_new(a, f64::EPSILON, 10_000)
        .ok_or_else(|| Error::convergence("symmetric eigen (undamped modes)", 10_000, f64::NAN, f64::EPSILON))?;
    let mut order: Vec<usize> = (0..eig.eigenvalues.len()).collect();
    order.sort_by(|&i, &j| eig.eigenvalues[i].total_cmp(&eig.eigenvalues[j]));
    let values = order.iter().map(|&i| eig.eigenvalues[i]).collect();
    let q = DMatrix::from_fn(eig.eigenvectors.nrows(), order.len(), |r, c| {
        eig.eigenvectors[(r, order[c])]
    });
    Ok((values, q))
}

fn node_of(mesh: &ShaftMesh, position_m: f64) -> Result<usize> {
    mesh.node_at(position_m).ok_or_else(|| {
        Error::config(
            "position_m",
            position_m,
            "is not a node of the mesh (list it among the bearings, disks or probes)",
        )
    })
}

#[cfg(test)]
pub(crate) mod test_support {
    use super::*;
    use crate::materials::Material;

    /// Uniform solid steel shaft without supports.
    pub fn free_shaft(length_m: f64, diameter_m: f64, elements: usize) -> Rotor {
        Rotor::new(RotorSpec {
            sections: vec![ShaftSection::new(length_m, diameter_m, 0.0, Material::shaft_steel()).unwrap()],
            disks: vec![],
            bearings: vec![],
            magnetic_pull: None,
            modal_damping_ratio: 0.0,
            max_element_length_m: length_m / elements as f64 * (1.0 + 1e-9),
        })
        .unwrap()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::materials::Material;
    use std::sync::Arc;

    #[test]
    fn bearing_off_the_shaft_is_named() {
        let spec = RotorSpec {
            sections: vec![ShaftSection::new(0.3, 0.04, 0.0, Material::shaft_steel()).unwrap()],
            disks: vec![],
            bearings: vec![BearingSupport::new(
                "rear",
                0.35,
                Arc::new(BearingCoefficients::diagonal(1e8, 0.0, 0.0, 0.0).unwrap()),
            )],
            magnetic_pull: None,
            modal_damping_ratio: 0.02,
            max_element_length_m: 0.05,
        };
        let e = Rotor::new(spec).unwrap_err().to_string();
        assert!(e.contains("bearings[rear].position_m") && e.contains("0.35"), "{e}");
    }

    #[test]
    fn modal_damping_gives_requested_ratio_on_each_mode() {
        // Phi^T C Phi = diag(2 zeta w): check with the undamped modes.
        let mut r = test_support::free_shaft(0.5, 0.03, 6);
        r.spec.modal_damping_ratio = 0.03;
        r.structural_damping = r.modal_damping_matrix().unwrap();
        let (w, phi) = r.undamped_modes(0.0).unwrap();
        let c = phi.transpose() * &r.structural_damping * &phi;
        for j in 4..8 {
            assert!((c[(j, j)] - 2.0 * 0.03 * w[j]).abs() < 1e-6 * w[j], "{j}");
        }
        // Rigid-body modes (4 of them for a free shaft in two planes) are undamped.
        assert!(c[(0, 0)].abs() < 1e-6 * w[4]);
    }

    #[test]
    fn hollow_cylinder_disk_inertia() {
        // Thin disk: Id -> Ip / 2.
        let d = Disk::hollow_cylinder("d", 0.0, 0.2, 0.0, 1e-6, 7800.0).unwrap();
        assert!((d.diametral_inertia_kg_m2 - d.polar_inertia_kg_m2 / 2.0).abs() < 1e-9 * d.polar_inertia_kg_m2);
        assert!((d.polar_inertia_kg_m2 - d.mass_kg * 0.01 / 2.0).abs() < 1e-15);
    }
}
