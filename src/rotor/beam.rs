//! Timoshenko beam finite element of a rotating, hollow circular shaft and
//! the assembly of a stepped shaft into global mass, gyroscopic and
//! stiffness matrices.
//!
//! Element: Nelson & McVaugh (1976, J. Eng. Ind. 98, 593-600) in the closed
//! form of Friswell, Penny, Garvey & Lees, *Dynamics of Rotating Machines*
//! (CUP 2010), section 5.4: cubic shape functions that include shear,
//! shear parameter Phi = 12 E I / (kappa G A L^2), consistent translational
//! mass, rotary inertia and the gyroscopic matrix (twice the rotary inertia
//! matrix, coupling the two bending planes).
//!
//! Degrees of freedom per node, in this order: x, y \[m\], theta_x, theta_y
//! \[rad\], with z the spin axis. Sign convention (right-handed small
//! rotations): theta_y = +du_x/dz and theta_x = -du_y/dz for a slender beam,
//! so a disk spinning at +Omega obeys
//! `Id theta_x'' + Ip Omega theta_y' = M_x`, `Id theta_y'' - Ip Omega theta_x' = M_y`.
//! Equations of motion: `M q'' + (C + Omega G) q' + K q = f`.

use nalgebra::{DMatrix, Matrix4, SMatrix};

use crate::error::{positive, Error, Result};
use crate::materials::Material;

/// Degrees of freedom per node (x, y, theta_x, theta_y).
pub const DOF_PER_NODE: usize = 4;

/// An 8x8 element matrix, node ordering [x1, y1, tx1, ty1, x2, y2, tx2, ty2].
pub type ElementMatrix = SMatrix<f64, 8, 8>;

/// One cylindrical step of a stepped shaft.
#[derive(Debug, Clone, PartialEq)]
pub struct ShaftSection {
    /// Axial length of the step \[m\].
    pub length_m: f64,
    /// Outer diameter \[m\].
    pub outer_diameter_m: f64,
    /// Inner (bore) diameter \[m\]; 0 for a solid section.
    pub inner_diameter_m: f64,
    /// Shaft material: E, density and nu (nu gives G and the shear coefficient).
    pub material: Material,
}

impl ShaftSection {
    /// A section, validated.
    pub fn new(length_m: f64, outer_diameter_m: f64, inner_diameter_m: f64, material: Material) -> Result<Self> {
        let s = ShaftSection {
            length_m,
            outer_diameter_m,
            inner_diameter_m,
            material,
        };
        s.validate()?;
        Ok(s)
    }

    /// Check lengths and diameters.
    pub fn validate(&self) -> Result<()> {
        positive("length_m", self.length_m)?;
        positive("outer_diameter_m", self.outer_diameter_m)?;
        crate::error::non_negative("inner_diameter_m", self.inner_diameter_m)?;
        if self.inner_diameter_m >= self.outer_diameter_m {
            return Err(Error::config(
                "inner_diameter_m",
                self.inner_diameter_m,
                format!("must be smaller than outer_diameter_m = {}", self.outer_diameter_m),
            ));
        }
        self.material.validate()
    }

    /// Cross-section area A = pi (do^2 - di^2) / 4 [m^2].
    pub fn area_m2(&self) -> f64 {
        std::f64::consts::PI * (self.outer_diameter_m.powi(2) - self.inner_diameter_m.powi(2)) / 4.0
    }

    /// Diametral second moment of area I = pi (do^4 - di^4) / 64 [m^4].
    pub fn second_moment_m4(&self) -> f64 {
        std::f64::consts::PI * (self.outer_diameter_m.powi(4) - self.inner_diameter_m.powi(4)) / 64.0
    }

    /// Mass of the step \[kg\].
    pub fn mass_kg(&self) -> f64 {
        self.material.density_kg_m3 * self.area_m2() * self.length_m
    }
}

/// Shear coefficient of a hollow circular section, Cowper (1966,
/// J. Appl. Mech. 33, 335-340, table 1):
/// kappa = 6 (1+nu) (1+m^2)^2 / ((7+6nu)(1+m^2)^2 + (20+12nu) m^2), m = di/do.
/// Solid section (m = 0): 6 (1+nu) / (7 + 6 nu).
pub fn shear_coefficient_hollow(poisson_ratio: f64, diameter_ratio: f64) -> f64 {
    let m2 = diameter_ratio * diameter_ratio;
    let a = (1.0 + m2).powi(2);
    6.0 * (1.0 + poisson_ratio) * a / ((7.0 + 6.0 * poisson_ratio) * a + (20.0 + 12.0 * poisson_ratio) * m2)
}

/// One Timoshenko beam element between two nodes.
#[derive(Debug, Clone, PartialEq)]
pub struct BeamElement {
    /// Element length L \[m\].
    pub length_m: f64,
    /// Outer diameter \[m\], from the section.
    pub outer_diameter_m: f64,
    /// Inner (bore) diameter \[m\]; 0 for a solid section.
    pub inner_diameter_m: f64,
    /// Young's modulus E \[Pa\].
    pub youngs_modulus_pa: f64,
    /// Shear modulus G = E / (2 (1 + nu)) \[Pa\].
    pub shear_modulus_pa: f64,
    /// Density rho [kg/m^3].
    pub density_kg_m3: f64,
    /// Shear coefficient kappa [-].
    pub shear_coefficient: f64,
}

impl BeamElement {
    /// The element of length `length_m` cut from `section`.
    pub fn from_section(section: &ShaftSection, length_m: f64) -> Result<Self> {
        if !(length_m.is_finite() && length_m > 0.0) {
            return Err(Error::config(
                "element_length_m",
                length_m,
                "beam element length must be positive",
            ));
        }
        let m = &section.material;
        Ok(BeamElement {
            length_m,
            outer_diameter_m: section.outer_diameter_m,
            inner_diameter_m: section.inner_diameter_m,
            youngs_modulus_pa: m.youngs_modulus_pa,
            shear_modulus_pa: m.youngs_modulus_pa / (2.0 * (1.0 + m.poisson_ratio)),
            density_kg_m3: m.density_kg_m3,
            shear_coefficient: shear_coefficient_hollow(
                m.poisson_ratio,
                section.inner_diameter_m / section.outer_diameter_m,
            ),
        })
    }

    fn area_m2(&self) -> f64 {
        std::f64::consts::PI * (self.outer_diameter_m.powi(2) - self.inner_diameter_m.powi(2)) / 4.0
    }

    fn second_moment_m4(&self) -> f64 {
        std::f64::consts::PI * (self.outer_diameter_m.powi(4) - self.inner_diameter_m.powi(4)) / 64.0
    }

    /// Shear-deformation parameter Phi = 12 E I / (kappa G A L^2) (Friswell eq. 5.96).
    pub fn shear_parameter(&self) -> f64 {
        12.0 * self.youngs_modulus_pa * self.second_moment_m4()
            / (self.shear_coefficient * self.shear_modulus_pa * self.area_m2() * self.length_m.powi(2))
    }

    /// Bending stiffness of one plane, DOFs [w1, b1, w2, b2] with b = dw/dz
    /// orientation (Friswell eq. 5.97).
    fn plane_stiffness(&self) -> Matrix4<f64> {
        let l = self.length_m;
        let p = self.shear_parameter();
        let f = self.youngs_modulus_pa * self.second_moment_m4() / ((1.0 + p) * l.powi(3));
        let l2 = l * l;
        f * Matrix4::new(
            12.0,
            6.0 * l,
            -12.0,
            6.0 * l,
            6.0 * l,
            (4.0 + p) * l2,
            -6.0 * l,
            (2.0 - p) * l2,
            -12.0,
            -6.0 * l,
            12.0,
            -6.0 * l,
            6.0 * l,
            (2.0 - p) * l2,
            -6.0 * l,
            (4.0 + p) * l2,
        )
    }

    /// Translational consistent mass of one plane (Friswell eq. 5.98).
    fn plane_translational_mass(&self) -> Matrix4<f64> {
        let l = self.length_m;
        let p = self.shear_parameter();
        let f = self.density_kg_m3 * self.area_m2() * l / (840.0 * (1.0 + p).powi(2));
        let m1 = 312.0 + 588.0 * p + 280.0 * p * p;
        let m2 = (44.0 + 77.0 * p + 35.0 * p * p) * l;
        let m3 = 108.0 + 252.0 * p + 140.0 * p * p;
        let m4 = (26.0 + 63.0 * p + 35.0 * p * p) * l;
        let m5 = (8.0 + 14.0 * p + 7.0 * p * p) * l * l;
        let m6 = (6.0 + 14.0 * p + 7.0 * p * p) * l * l;
        f * Matrix4::new(m1, m2, m3, -m4, m2, m5, m4, -m6, m3, m4, m1, -m2, -m4, -m6, -m2, m5)
    }

    /// Rotary (diametral) inertia of one plane (Friswell eq. 5.99).
    fn plane_rotary_mass(&self) -> Matrix4<f64> {
        let l = self.length_m;
        let p = self.shear_parameter();
        let f = self.density_kg_m3 * self.second_moment_m4() / (30.0 * (1.0 + p).powi(2) * l);
        let m7 = (3.0 - 15.0 * p) * l;
        let m8 = (4.0 + 5.0 * p + 10.0 * p * p) * l * l;
        let m9 = (-1.0 - 5.0 * p + 5.0 * p * p) * l * l;
        f * Matrix4::new(
            36.0, m7, -36.0, m7, m7, m8, -m7, m9, -36.0, -m7, 36.0, -m7, m7, m9, -m7, m8,
        )
    }

    /// Element mass matrix (translational + rotary inertia), 8x8.
    pub fn mass(&self) -> ElementMatrix {
        let p = self.plane_translational_mass() + self.plane_rotary_mass();
        both_planes(&p)
    }

    /// Element bending stiffness matrix, 8x8.
    pub fn stiffness(&self) -> ElementMatrix {
        both_planes(&self.plane_stiffness())
    }

    /// Element gyroscopic matrix per unit spin speed [kg m^2 per element
    /// scale], skew-symmetric, 8x8: the polar inertia per length is twice
    /// the diametral one, so G couples the planes with 2 x the rotary mass.
    pub fn gyroscopic(&self) -> ElementMatrix {
        let r = 2.0 * self.plane_rotary_mass();
        let mut g = ElementMatrix::zeros();
        for i in 0..4 {
            for j in 0..4 {
                let (ai, si) = XZ_PLANE[i];
                let (bj, sj) = YZ_PLANE[j];
                // Virtual work of the gyroscopic moments: G[a, b] = +R, G[b, a] = -R
                // in the slope orientation of both planes (module doc).
                g[(ai, bj)] += si * sj * r[(i, j)];
                g[(bj, ai)] -= si * sj * r[(i, j)];
            }
        }
        g
    }

    /// Mass of the element \[kg\].
    pub fn mass_kg(&self) -> f64 {
        self.density_kg_m3 * self.area_m2() * self.length_m
    }
}

/// x-z plane: (local index, sign) of [u1, du1/dz, u2, du2/dz] = [x1, ty1, x2, ty2].
const XZ_PLANE: [(usize, f64); 4] = [(0, 1.0), (3, 1.0), (4, 1.0), (7, 1.0)];
/// y-z plane: [v1, dv1/dz, v2, dv2/dz] = [y1, -tx1, y2, -tx2].
const YZ_PLANE: [(usize, f64); 4] = [(1, 1.0), (2, -1.0), (5, 1.0), (6, -1.0)];

/// Place one plane matrix (slope orientation) in both bending planes.
fn both_planes(p: &Matrix4<f64>) -> ElementMatrix {
    let mut m = ElementMatrix::zeros();
    for plane in [&XZ_PLANE, &YZ_PLANE] {
        for i in 0..4 {
            for j in 0..4 {
                let (gi, si) = plane[i];
                let (gj, sj) = plane[j];
                m[(gi, gj)] += si * sj * p[(i, j)];
            }
        }
    }
    m
}

/// Add an element matrix between nodes `node` and `node + 1` into a global matrix.
pub fn add_element(global: &mut DMatrix<f64>, node: usize, e: &ElementMatrix) {
    let o = node * DOF_PER_NODE;
    for i in 0..8 {
        for j in 0..8 {
            global[(o + i, o + j)] += e[(i, j)];
        }
    }
}

/// A meshed shaft: node positions and the elements between consecutive nodes.
#[derive(Debug, Clone, PartialEq)]
pub struct ShaftMesh {
    /// Axial node positions from the left end (z = 0) \[m\], strictly increasing.
    pub node_positions_m: Vec<f64>,
    /// Elements between consecutive nodes: element i spans nodes i and i + 1.
    pub elements: Vec<BeamElement>,
}

/// Two positions closer than this are one node \[m\].
pub const NODE_TOLERANCE_M: f64 = 1e-9;

impl ShaftMesh {
    /// Mesh a stepped shaft so that every position in `required_m` is a
    /// node, no element is longer than `max_element_length_m`, and section
    /// boundaries are nodes. Positions outside [0, total length] are
    /// rejected by the caller (it knows their names).
    pub fn new(sections: &[ShaftSection], required_m: &[f64], max_element_length_m: f64) -> Result<Self> {
        if sections.is_empty() {
            return Err(Error::config("sections", 0, "a shaft needs at least one section"));
        }
        positive("max_element_length_m", max_element_length_m)?;
        for (i, s) in sections.iter().enumerate() {
            s.validate().map_err(|e| prefix_field(e, &format!("sections[{i}].")))?;
        }
        let mut breaks = vec![0.0];
        let mut z = 0.0;
        for s in sections {
            z += s.length_m;
            breaks.push(z);
        }
        let total = z;
        for &p in required_m {
            if p > NODE_TOLERANCE_M && p < total - NODE_TOLERANCE_M {
                breaks.push(p);
            }
        }
        breaks.sort_by(|a, b| a.total_cmp(b));
        breaks.dedup_by(|a, b| (*a - *b).abs() < NODE_TOLERANCE_M);

        let mut nodes = vec![0.0];
        let mut elements = Vec::new();
        for w in breaks.windows(2) {
            let (a, b) = (w[0], w[1]);
            let mid = 0.5 * (a + b);
            let section = section_at(sections, mid);
            let n = ((b - a) / max_element_length_m).ceil().max(1.0) as usize;
            let le = (b - a) / n as f64;
            for k in 1..=n {
                nodes.push(if k == n { b } else { a + le * k as f64 });
                elements.push(BeamElement::from_section(section, le)?);
            }
        }
        Ok(ShaftMesh {
            node_positions_m: nodes,
            elements,
        })
    }

    /// Number of nodes.
    pub fn node_count(&self) -> usize {
        self.node_positions_m.len()
    }

    /// Total shaft length \[m\].
    pub fn length_m(&self) -> f64 {
        *self.node_positions_m.last().unwrap_or(&0.0)
    }

    /// Index of the node at `position_m` (within [`NODE_TOLERANCE_M`] x 1000).
    pub fn node_at(&self, position_m: f64) -> Option<usize> {
        self.node_positions_m
            .iter()
            .position(|&z| (z - position_m).abs() <= 1e3 * NODE_TOLERANCE_M)
    }

    /// Global (mass, gyroscopic per rad/s, stiffness) of the shaft alone.
    pub fn assemble(&self) -> (DMatrix<f64>, DMatrix<f64>, DMatrix<f64>) {
        let n = self.node_count() * DOF_PER_NODE;
        let mut m = DMatrix::zeros(n, n);
        let mut g = DMatrix::zeros(n, n);
        let mut k = DMatrix::zeros(n, n);
        for (i, e) in self.elements.iter().enumerate() {
            add_element(&mut m, i, &e.mass());
            add_element(&mut g, i, &e.gyroscopic());
            add_element(&mut k, i, &e.stiffness());
        }
        (m, g, k)
    }
}

/// The section containing axial position `z` (the last one beyond the end).
fn section_at(sections: &[ShaftSection], z: f64) -> &ShaftSection {
    let mut end = 0.0;
    for s in sections {
        end += s.length_m;
        if z < end {
            return s;
        }
    }
    &sections[sections.len() - 1]
}

/// Prefix the field of a config error (to say which list item it came from).
pub(crate) fn prefix_field(e: Error, prefix: &str) -> Error {
    match e {
        Error::Config { field, value, reason } => Error::Config {
            field: format!("{prefix}{field}"),
            value,
            reason,
        },
        other => other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn steel_section(length_m: f64, d: f64) -> ShaftSection {
        ShaftSection::new(length_m, d, 0.0, Material::shaft_steel()).unwrap()
    }

    #[test]
    fn element_matrices_symmetric_and_gyroscopic_skew() {
        let e = BeamElement::from_section(&steel_section(0.1, 0.05), 0.05).unwrap();
        let (m, k, g) = (e.mass(), e.stiffness(), e.gyroscopic());
        assert!((m - m.transpose()).abs().max() < 1e-12 * m.abs().max());
        assert!((k - k.transpose()).abs().max() < 1e-12 * k.abs().max());
        assert!((g + g.transpose()).abs().max() < 1e-12 * g.abs().max());
    }

    #[test]
    fn rigid_translation_carries_element_mass_and_no_strain() {
        // Rigid-body translation in x: kinetic energy 1/2 m v^2, no elastic force.
        let e = BeamElement::from_section(
            &ShaftSection::new(1.0, 0.08, 0.03, Material::shaft_steel()).unwrap(),
            0.07,
        )
        .unwrap();
        let mut t = SMatrix::<f64, 8, 1>::zeros();
        t[0] = 1.0;
        t[4] = 1.0;
        let mass = (t.transpose() * e.mass() * t)[0];
        assert!((mass - e.mass_kg()).abs() < 1e-12 * mass, "{mass} vs {}", e.mass_kg());
        assert!((e.stiffness() * t).abs().max() < 1e-6);
        // Rigid rotation about x (theta_x = 1, y = -z): no elastic force either.
        let mut r = SMatrix::<f64, 8, 1>::zeros();
        r[2] = 1.0;
        r[6] = 1.0;
        r[5] = -e.length_m;
        assert!((e.stiffness() * r).abs().max() < 1e-6 * e.stiffness().abs().max());
    }

    #[test]
    fn cowper_solid_section_coefficient() {
        // Cowper (1966): solid circle 6(1+nu)/(7+6nu); nu = 0.3 -> 0.8864.
        assert!((shear_coefficient_hollow(0.3, 0.0) - 7.8 / 8.8).abs() < 1e-12);
        // Thin-walled tube tends to 2(1+nu)/(4+3nu).
        let thin = shear_coefficient_hollow(0.3, 0.9999);
        assert!((thin - 2.6 / 4.9).abs() < 1e-3, "{thin}");
    }

    #[test]
    fn mesh_puts_nodes_at_required_positions_and_rejects_bad_sections() {
        let s = vec![steel_section(0.1, 0.04), steel_section(0.2, 0.05)];
        let mesh = ShaftMesh::new(&s, &[0.037, 0.25], 0.03).unwrap();
        assert!(mesh.node_at(0.037).is_some() && mesh.node_at(0.1).is_some() && mesh.node_at(0.25).is_some());
        assert!(mesh.elements.iter().all(|e| e.length_m <= 0.03 + 1e-12));
        let total: f64 = mesh.elements.iter().map(|e| e.length_m).sum();
        assert!((total - 0.3).abs() < 1e-12);
        let bad = ShaftSection {
            length_m: 0.0,
            ..steel_section(0.1, 0.04)
        };
        let err = ShaftMesh::new(&[bad], &[], 0.01).unwrap_err();
        assert!(err.to_string().contains("sections[0].length_m"), "{err}");
        assert!(BeamElement::from_section(&steel_section(0.1, 0.04), -1.0).is_err());
    }
}
