//! General lumped thermal network (docs/concepts/physics.md §5; seed A Fig. 7,
//! eq. A-28; seed B transient, Fig. 4).
//!
//! Nodes are free (unknown temperature, optional heat capacity m c [J/K])
//! or boundary (fixed temperature). Links carry heat between two nodes:
//! conduction with a constant conductance G [W/K], or convection h(dT,
//! speed) S with h from a [`Convection`] law. The flow from node a to node
//! b is `q_ab = G_ab (T_a - T_b)`.
//!
//! Free node balance: `C_i dT_i/dt = s_i - sum_links q_(i -> j) = r_i(T)`.
//! * Steady state `r(T) = 0`: Newton-Raphson with the analytic Jacobian
//!   (including the dh/dT term of natural convection), backtracking line
//!   search, warm start from the previous solution.
//! * Transient: TR-BDF2 (Bank et al. 1985; Hosea & Shampine 1996), an
//!   L-stable, second-order, one-step implicit method with
//!   gamma = 2 - sqrt(2): a trapezoidal stage to t + gamma h, then a BDF2
//!   stage to t + h, each solved by Newton. Nodes without heat capacity are
//!   algebraic (r_i = 0 at every stage).

use std::sync::Arc;

use nalgebra::{DMatrix, DVector};

use crate::error::{finite, non_negative, positive, Error, Result};

/// Index of a node in its network.
pub type NodeId = usize;

/// Local laminar flat-plate coefficient of Pohlhausen's solution,
/// Nu_x = 0.332 Re_x^(1/2) Pr^(1/3) (Incropera & DeWitt eq. 7.23). Seed A
/// eq. 31 prints 0.332; Harris & Kotzalas print 0.0332 for the same
/// formula: that is ten times below the laminar boundary-layer value, so we
/// take 0.332 and keep the coefficient a parameter.
pub const POHLHAUSEN_LOCAL: f64 = 0.332;

/// Harris & Kotzalas' printed oil-film coefficient (see [`POHLHAUSEN_LOCAL`]).
pub const HARRIS_PRINTED_FILM: f64 = 0.0332;

/// Seed A eq. 31 natural-convection constant read in SI. The seed prints
/// `ha = 2.3e-5 (T1 - T2)^0.25` without units; with Harris' mm-based SI
/// (W/(mm^2 K^1.25)) this is 23 W/(m^2 K^1.25), i.e. h = 41 W/(m^2 K) at a
/// 10 K difference; a plain laminar air correlation (McAdams, horizontal
/// cylinder, h = 1.32 (dT/D)^0.25) gives about 4 W/(m^2 K) for D = 0.1 m, so
/// the seed's value includes radiation and oil splash or is a units slip.
pub const SEED_A_NATURAL_W_M2_K125: f64 = 23.0;

/// A convection law h(dT, speed) [W/(m^2 K)].
#[derive(Debug, Clone, PartialEq)]
pub enum Convection {
    /// Constant h.
    Constant {
        /// Film coefficient h [W/(m^2 K)], >= 0.
        h_w_m2k: f64,
    },
    /// Natural convection `h = C |T_a - T_b|^0.25`.
    Natural {
        /// C [W/(m^2 K^1.25)], >= 0; e.g. [`SEED_A_NATURAL_W_M2_K125`] or
        /// [`Convection::natural_mcadams`].
        coefficient_w_m2_k125: f64,
    },
    /// Forced laminar film (Harris / seed A eq. 31):
    /// `h = c k Pr^(1/3) (u / (nu x))^(1/2)` with the surface speed
    /// `u = velocity_per_speed_m * speed_rad_s` (a radius, m).
    ForcedFilm {
        /// Leading coefficient c [-], >= 0: [`POHLHAUSEN_LOCAL`] (0.332) or
        /// Harris' printed [`HARRIS_PRINTED_FILM`] (0.0332).
        coefficient: f64,
        /// Fluid thermal conductivity k [W/(m K)], > 0.
        fluid_conductivity_w_mk: f64,
        /// Fluid Prandtl number Pr [-], > 0.
        prandtl: f64,
        /// Fluid kinematic viscosity nu [m^2/s], > 0.
        kinematic_viscosity_m2_s: f64,
        /// Characteristic length x along the flow \[m\], > 0.
        length_m: f64,
        /// Surface speed per unit shaft speed \[m\], >= 0 (u = this *
        /// |speed_rad_s|): the radius of a surface turning with the shaft, or
        /// (omega_c / omega) dm / 2 for parts moving at the cage speed.
        velocity_per_speed_m: f64,
    },
    /// Speed-dependent correlation `h = h0 + h1 (omega / omega_ref)^n`
    /// (rotor air gap, shaft ends; seed B Fig. 2 shape).
    SpeedPower {
        /// h0, the coefficient at standstill [W/(m^2 K)], >= 0.
        h0_w_m2k: f64,
        /// h1, the speed-dependent part at the reference speed [W/(m^2 K)], >= 0.
        h1_w_m2k: f64,
        /// omega_ref [rad/s], > 0.
        reference_speed_rad_s: f64,
        /// Exponent n [-], > 0 (the sign of omega does not matter: |omega| is used).
        exponent: f64,
    },
}

impl Convection {
    /// Natural convection with McAdams' laminar horizontal-cylinder law in
    /// air, h = 1.32 (dT / D)^0.25 W/(m^2 K) (Incropera & DeWitt, simplified
    /// air correlations; valid for 1e4 < Ra < 1e9).
    pub fn natural_mcadams(diameter_m: f64) -> Result<Self> {
        let d = positive("diameter_m", diameter_m)?;
        Ok(Convection::Natural {
            coefficient_w_m2_k125: 1.32 / d.powf(0.25),
        })
    }

    fn validate(&self, link: &str) -> Result<()> {
        let f = |n: &str| format!("{link}.{n}");
        match *self {
            Convection::Constant { h_w_m2k } => {
                non_negative(&f("h_w_m2k"), h_w_m2k)?;
            }
            Convection::Natural { coefficient_w_m2_k125 } => {
                non_negative(&f("coefficient_w_m2_k125"), coefficient_w_m2_k125)?;
            }
            Convection::ForcedFilm {
                coefficient,
                fluid_conductivity_w_mk,
                prandtl,
                kinematic_viscosity_m2_s,
                length_m,
                velocity_per_speed_m,
            } => {
                non_negative(&f("coefficient"), coefficient)?;
                positive(&f("fluid_conductivity_w_mk"), fluid_conductivity_w_mk)?;
                positive(&f("prandtl"), prandtl)?;
                positive(&f("kinematic_viscosity_m2_s"), kinematic_viscosity_m2_s)?;
                positive(&f("length_m"), length_m)?;
                non_negative(&f("velocity_per_speed_m"), velocity_per_speed_m)?;
            }
            Convection::SpeedPower {
                h0_w_m2k,
                h1_w_m2k,
                reference_speed_rad_s,
                exponent,
            } => {
                non_negative(&f("h0_w_m2k"), h0_w_m2k)?;
                non_negative(&f("h1_w_m2k"), h1_w_m2k)?;
                positive(&f("reference_speed_rad_s"), reference_speed_rad_s)?;
                positive(&f("exponent"), exponent)?;
            }
        }
        Ok(())
    }

    /// h at a given |dT| \[K\] and speed [rad/s], and dh/d|dT|.
    fn h_and_slope(&self, abs_dt: f64, speed_rad_s: f64) -> (f64, f64) {
        match *self {
            Convection::Constant { h_w_m2k } => (h_w_m2k, 0.0),
            Convection::Natural {
                coefficient_w_m2_k125: c,
            } => {
                let h = c * abs_dt.powf(0.25);
                // d/d|dT| of C |dT|^0.25, floored at 1e-9 K to stay finite.
                (h, 0.25 * c * abs_dt.max(1e-9).powf(-0.75))
            }
            Convection::ForcedFilm {
                coefficient,
                fluid_conductivity_w_mk: k,
                prandtl,
                kinematic_viscosity_m2_s: nu,
                length_m: x,
                velocity_per_speed_m: r,
            } => {
                let u = r * speed_rad_s.abs();
                (coefficient * k * prandtl.cbrt() * (u / (nu * x)).sqrt(), 0.0)
            }
            Convection::SpeedPower {
                h0_w_m2k,
                h1_w_m2k,
                reference_speed_rad_s,
                exponent,
            } => (
                h0_w_m2k + h1_w_m2k * (speed_rad_s.abs() / reference_speed_rad_s).powf(exponent),
                0.0,
            ),
        }
    }

    /// h [W/(m^2 K)] at a temperature difference and speed.
    pub fn h_w_m2k(&self, delta_t_k: f64, speed_rad_s: f64) -> f64 {
        self.h_and_slope(delta_t_k.abs(), speed_rad_s).0
    }
}

/// A node's role.
#[derive(Debug, Clone, PartialEq)]
pub enum NodeKind {
    /// Unknown temperature; heat capacity m c [J/K] (0 = massless).
    Free {
        /// Heat capacity m c [J/K], >= 0; a massless node is algebraic in a transient.
        heat_capacity_j_per_k: f64,
    },
    /// Fixed temperature \[C\].
    Boundary {
        /// The fixed temperature \[C\].
        temperature_c: f64,
    },
}

/// A named node.
#[derive(Debug, Clone, PartialEq)]
pub struct Node {
    /// Node name, unique among the network's nodes and links.
    pub name: String,
    /// Free (with its heat capacity) or boundary (with its temperature).
    pub kind: NodeKind,
}

/// How a link carries heat.
#[derive(Debug, Clone, PartialEq)]
pub enum LinkKind {
    /// Conduction, `q_ab = G (T_a - T_b)`.
    Conduction {
        /// Constant conductance G [W/K], >= 0 (1 / resistance).
        conductance_w_per_k: f64,
    },
    /// Convection, `q_ab = h(|T_a - T_b|, speed) S (T_a - T_b)`.
    Convection {
        /// Wetted area S [m^2], >= 0.
        area_m2: f64,
        /// The law giving the film coefficient h.
        law: Convection,
    },
}

/// A named link between nodes `a` and `b`.
#[derive(Debug, Clone, PartialEq)]
pub struct Link {
    /// Link name, unique among the network's nodes and links.
    pub name: String,
    /// First node; a positive flow goes from `a` to `b`.
    pub a: NodeId,
    /// Second node (different from `a`).
    pub b: NodeId,
    /// Conduction or convection, with its parameters.
    pub kind: LinkKind,
}

impl Link {
    /// Flow a -> b \[W\] and dq/dT_a (= -dq/dT_b) [W/K].
    #[inline]
    fn flow(&self, ta: f64, tb: f64, speed_rad_s: f64) -> (f64, f64) {
        let dt = ta - tb;
        match &self.kind {
            LinkKind::Conduction { conductance_w_per_k: g } => (g * dt, *g),
            LinkKind::Convection { area_m2, law } => {
                let (h, dh) = law.h_and_slope(dt.abs(), speed_rad_s);
                // q = h(|dT|) S dT, dq/ddT = S (h + |dT| dh/d|dT|).
                (h * area_m2 * dt, area_m2 * (h + dt.abs() * dh))
            }
        }
    }

    /// Conductance at the current state, for the connectivity check and the
    /// Picard start [W/K]. Natural convection counts as connecting.
    fn connects(&self, speed_rad_s: f64) -> bool {
        match &self.kind {
            LinkKind::Conduction { conductance_w_per_k } => *conductance_w_per_k > 0.0,
            LinkKind::Convection { area_m2, law } => {
                *area_m2 > 0.0
                    && match law {
                        Convection::Natural { coefficient_w_m2_k125 } => *coefficient_w_m2_k125 > 0.0,
                        other => other.h_w_m2k(0.0, speed_rad_s) > 0.0,
                    }
            }
        }
    }
}

/// A thermal network: nodes and links.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ThermalNetwork {
    nodes: Vec<Node>,
    links: Vec<Link>,
}

/// Node temperatures of a solution, with their names.
#[derive(Debug, Clone, PartialEq)]
pub struct Temperatures {
    /// Node names, in node order (shared with the solver).
    pub names: Arc<[String]>,
    /// One temperature per node, in node order \[C\].
    pub temperatures_c: Vec<f64>,
}

impl Temperatures {
    /// Temperature of the named node \[C\].
    pub fn get(&self, name: &str) -> Result<f64> {
        self.names
            .iter()
            .position(|n| n == name)
            .map(|i| self.temperatures_c[i])
            .ok_or_else(|| Error::config("node", name, "no node of that name"))
    }
}

impl ThermalNetwork {
    /// An empty network (no nodes, no links).
    pub fn new() -> Self {
        Self::default()
    }

    fn check_name(&self, name: &str) -> Result<()> {
        if name.is_empty() || self.nodes.iter().any(|n| n.name == name) || self.links.iter().any(|l| l.name == name) {
            return Err(Error::config(
                "name",
                name,
                "node and link names must be unique and not empty",
            ));
        }
        Ok(())
    }

    /// Add a free node with heat capacity m c [J/K] (0 for a massless node).
    pub fn add_node(&mut self, name: &str, heat_capacity_j_per_k: f64) -> Result<NodeId> {
        self.check_name(name)?;
        non_negative(&format!("{name}.heat_capacity_j_per_k"), heat_capacity_j_per_k)?;
        self.nodes.push(Node {
            name: name.into(),
            kind: NodeKind::Free { heat_capacity_j_per_k },
        });
        Ok(self.nodes.len() - 1)
    }

    /// Add a fixed-temperature node \[C\].
    pub fn add_boundary(&mut self, name: &str, temperature_c: f64) -> Result<NodeId> {
        self.check_name(name)?;
        finite(&format!("{name}.temperature_c"), temperature_c)?;
        self.nodes.push(Node {
            name: name.into(),
            kind: NodeKind::Boundary { temperature_c },
        });
        Ok(self.nodes.len() - 1)
    }

    fn check_ends(&self, name: &str, a: NodeId, b: NodeId) -> Result<()> {
        if a >= self.nodes.len() || b >= self.nodes.len() || a == b {
            return Err(Error::config(
                name,
                format!("{a}-{b}"),
                "a link joins two different existing nodes",
            ));
        }
        Ok(())
    }

    /// Add a conduction link of conductance G [W/K].
    pub fn add_conduction(&mut self, name: &str, a: NodeId, b: NodeId, conductance_w_per_k: f64) -> Result<usize> {
        self.check_name(name)?;
        self.check_ends(name, a, b)?;
        non_negative(&format!("{name}.conductance_w_per_k"), conductance_w_per_k)?;
        self.links.push(Link {
            name: name.into(),
            a,
            b,
            kind: LinkKind::Conduction { conductance_w_per_k },
        });
        Ok(self.links.len() - 1)
    }

    /// Add a conduction link given as a resistance R [K/W].
    pub fn add_resistance(&mut self, name: &str, a: NodeId, b: NodeId, resistance_k_per_w: f64) -> Result<usize> {
        positive(&format!("{name}.resistance_k_per_w"), resistance_k_per_w)?;
        self.add_conduction(name, a, b, 1.0 / resistance_k_per_w)
    }

    /// Add a convection link over area S [m^2].
    pub fn add_convection(&mut self, name: &str, a: NodeId, b: NodeId, area_m2: f64, law: Convection) -> Result<usize> {
        self.check_name(name)?;
        self.check_ends(name, a, b)?;
        non_negative(&format!("{name}.area_m2"), area_m2)?;
        law.validate(name)?;
        self.links.push(Link {
            name: name.into(),
            a,
            b,
            kind: LinkKind::Convection { area_m2, law },
        });
        Ok(self.links.len() - 1)
    }

    /// Change a boundary temperature \[C\].
    pub fn set_boundary_temperature(&mut self, node: NodeId, temperature_c: f64) -> Result<()> {
        finite("temperature_c", temperature_c)?;
        match self.nodes.get_mut(node).map(|n| &mut n.kind) {
            Some(NodeKind::Boundary { temperature_c: t }) => {
                *t = temperature_c;
                Ok(())
            }
            _ => Err(Error::config("node", node, "not a boundary node")),
        }
    }

    /// The nodes, indexed by [`NodeId`] (order of addition).
    pub fn nodes(&self) -> &[Node] {
        &self.nodes
    }
    /// The links, in order of addition (the index the `add_*` methods return).
    pub fn links(&self) -> &[Link] {
        &self.links
    }

    /// Id of the named node.
    pub fn node_id(&self, name: &str) -> Result<NodeId> {
        self.nodes
            .iter()
            .position(|n| n.name == name)
            .ok_or_else(|| Error::config("node", name, "no node of that name"))
    }

    /// Node names (shared).
    pub fn names(&self) -> Arc<[String]> {
        self.nodes.iter().map(|n| n.name.clone()).collect()
    }

    /// Heat capacity of a node [J/K] (0 for boundaries and massless nodes).
    pub fn heat_capacity_j_per_k(&self, node: NodeId) -> f64 {
        match self.nodes[node].kind {
            NodeKind::Free { heat_capacity_j_per_k } => heat_capacity_j_per_k,
            NodeKind::Boundary { .. } => 0.0,
        }
    }

    /// Every free node must reach a boundary node through links that carry
    /// heat at this speed; otherwise its temperature is undetermined.
    pub fn check_connected(&self, speed_rad_s: f64) -> Result<()> {
        let n = self.nodes.len();
        let mut reached: Vec<bool> = self
            .nodes
            .iter()
            .map(|x| matches!(x.kind, NodeKind::Boundary { .. }))
            .collect();
        if !reached.iter().any(|&r| r) {
            return Err(Error::config(
                "network",
                "no boundary node",
                "a thermal network needs at least one fixed-temperature node",
            ));
        }
        let live: Vec<&Link> = self.links.iter().filter(|l| l.connects(speed_rad_s)).collect();
        let mut changed = true;
        while changed {
            changed = false;
            for l in &live {
                if reached[l.a] != reached[l.b] {
                    reached[l.a] = true;
                    reached[l.b] = true;
                    changed = true;
                }
            }
        }
        if let Some(i) = (0..n).find(|&i| !reached[i]) {
            return Err(Error::config(
                "network",
                &self.nodes[i].name,
                format!(
                    "node '{}' has no heat path to a fixed-temperature node at speed {speed_rad_s} rad/s (singular network)",
                    self.nodes[i].name
                ),
            ));
        }
        Ok(())
    }

    /// Full temperature vector with the boundary values filled in.
    pub fn initial_temperatures(&self, free_c: f64) -> Vec<f64> {
        self.nodes
            .iter()
            .map(|n| match n.kind {
                NodeKind::Boundary { temperature_c } => temperature_c,
                NodeKind::Free { .. } => free_c,
            })
            .collect()
    }

    fn check_sources(&self, sources_w: &[f64]) -> Result<()> {
        if sources_w.len() != self.nodes.len() {
            return Err(Error::config(
                "sources_w",
                sources_w.len(),
                format!("need one heat source per node ({} nodes)", self.nodes.len()),
            ));
        }
        for (i, (s, n)) in sources_w.iter().zip(&self.nodes).enumerate() {
            finite(&format!("sources_w[{i}] ({})", n.name), *s)?;
            if matches!(n.kind, NodeKind::Boundary { .. }) && *s != 0.0 {
                return Err(Error::config(
                    format!("sources_w[{i}]"),
                    s,
                    format!("'{}' is a fixed-temperature node; put heat on free nodes", n.name),
                ));
            }
        }
        Ok(())
    }

    /// Net heat into every node r_i = s_i - sum of outflows \[W\], and
    /// optionally the Jacobian dr/dT over all nodes (boundary rows/cols kept;
    /// callers drop them).
    fn residual(&self, t: &[f64], sources_w: &[f64], speed_rad_s: f64, r: &mut [f64], jac: Option<&mut DMatrix<f64>>) {
        r.copy_from_slice(sources_w);
        match jac {
            Some(j) => {
                j.fill(0.0);
                for l in &self.links {
                    let (q, g) = l.flow(t[l.a], t[l.b], speed_rad_s);
                    r[l.a] -= q;
                    r[l.b] += q;
                    j[(l.a, l.a)] -= g;
                    j[(l.a, l.b)] += g;
                    j[(l.b, l.b)] -= g;
                    j[(l.b, l.a)] += g;
                }
            }
            None => {
                for l in &self.links {
                    let (q, _) = l.flow(t[l.a], t[l.b], speed_rad_s);
                    r[l.a] -= q;
                    r[l.b] += q;
                }
            }
        }
    }

    /// Heat leaving the network through each boundary node \[W\] (positive =
    /// out of the network into the boundary), by node.
    pub fn boundary_flows_w(&self, temperatures_c: &[f64], speed_rad_s: f64) -> Vec<(String, f64)> {
        let zero = vec![0.0; self.nodes.len()];
        let mut r = vec![0.0; self.nodes.len()];
        self.residual(temperatures_c, &zero, speed_rad_s, &mut r, None);
        self.nodes
            .iter()
            .zip(r)
            .filter(|(n, _)| matches!(n.kind, NodeKind::Boundary { .. }))
            .map(|(n, q)| (n.name.clone(), q))
            .collect()
    }

    /// Heat flow through a named link from its node a to node b \[W\].
    pub fn link_flow_w(&self, link: &str, temperatures_c: &[f64], speed_rad_s: f64) -> Result<f64> {
        let l = self
            .links
            .iter()
            .find(|l| l.name == link)
            .ok_or_else(|| Error::config("link", link, "no link of that name"))?;
        Ok(l.flow(temperatures_c[l.a], temperatures_c[l.b], speed_rad_s).0)
    }

    fn free_indices(&self) -> Vec<usize> {
        (0..self.nodes.len())
            .filter(|&i| matches!(self.nodes[i].kind, NodeKind::Free { .. }))
            .collect()
    }

    /// Time constants of the network linearised at `temperatures_c` \[s\],
    /// largest first: tau = 1 / lambda for the generalised eigenvalues of
    /// `-J v = lambda C v` over the nodes with heat capacity (massless nodes
    /// eliminated by a Schur complement). Uses the symmetric part of J
    /// (exact: every link's Jacobian block is symmetric).
    pub fn time_constants_s(&self, temperatures_c: &[f64], speed_rad_s: f64) -> Result<Vec<f64>> {
        self.check_connected(speed_rad_s)?;
        let n = self.nodes.len();
        let mut jac = DMatrix::zeros(n, n);
        let mut r = vec![0.0; n];
        let zero = vec![0.0; n];
        self.residual(temperatures_c, &zero, speed_rad_s, &mut r, Some(&mut jac));
        let free = self.free_indices();
        let (m, a): (Vec<usize>, Vec<usize>) = free.iter().partition(|&&i| self.heat_capacity_j_per_k(i) > 0.0);
        if m.is_empty() {
            return Ok(vec![]);
        }
        let k =
            |rows: &[usize], cols: &[usize]| DMatrix::from_fn(rows.len(), cols.len(), |i, j| -jac[(rows[i], cols[j])]);
        let mut kmm = k(&m, &m);
        if !a.is_empty() {
            let kaa = k(&a, &a);
            let kam = k(&a, &m);
            let sol = kaa
                .lu()
                .solve(&kam)
                .ok_or_else(|| Error::convergence("thermal time constants (massless block)", 0, f64::INFINITY, 0.0))?;
            kmm -= k(&m, &a) * sol;
        }
        let s: Vec<f64> = m.iter().map(|&i| 1.0 / self.heat_capacity_j_per_k(i).sqrt()).collect();
        let sym = DMatrix::from_fn(m.len(), m.len(), |i, j| 0.5 * (kmm[(i, j)] + kmm[(j, i)]) * s[i] * s[j]);
        let eig = sym.symmetric_eigen();
        let mut tau: Vec<f64> = eig.eigenvalues.iter().map(|&l| 1.0 / l.max(1e-300)).collect();
        tau.sort_by(|x, y| y.partial_cmp(x).unwrap_or(std::cmp::Ordering::Equal));
        Ok(tau)
    }
}

/// Settings of the Newton iterations.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NewtonOptions {
    /// Largest number of Newton iterations.
    pub max_iterations: usize,
    /// Converged when max |r_i| <= relative_tolerance * heat scale \[W\], the
    /// scale being the larger of the total |sources| and the largest link
    /// flow (and at least 1e-9 W).
    pub relative_tolerance: f64,
}

impl Default for NewtonOptions {
    fn default() -> Self {
        NewtonOptions {
            max_iterations: 60,
            relative_tolerance: 1e-12,
        }
    }
}

/// Reusable workspace for the Newton solves of one network.
#[derive(Debug, Clone)]
struct Work {
    free: Vec<usize>,
    /// Position in `free` of each node (usize::MAX for boundaries).
    slot: Vec<usize>,
    jac: DMatrix<f64>,
    r: Vec<f64>,
    trial: Vec<f64>,
}

impl Work {
    fn new(net: &ThermalNetwork) -> Self {
        let n = net.nodes.len();
        let free = net.free_indices();
        let mut slot = vec![usize::MAX; n];
        for (k, &i) in free.iter().enumerate() {
            slot[i] = k;
        }
        Work {
            free,
            slot,
            jac: DMatrix::zeros(n, n),
            r: vec![0.0; n],
            trial: vec![0.0; n],
        }
    }
}

/// The residual of an implicit stage: F_i(T) = w_i r_i(T) - c_i (T_i - b_i)
/// for each free node (w, c, b per node). Steady state: w = 1, c = 0.
struct Stage<'a> {
    weight: &'a [f64],
    capacity: &'a [f64],
    base: &'a [f64],
}

fn scale_of(net: &ThermalNetwork, t: &[f64], sources_w: &[f64], speed: f64) -> f64 {
    let s: f64 = sources_w.iter().map(|x| x.abs()).sum();
    let q = net
        .links
        .iter()
        .map(|l| l.flow(t[l.a], t[l.b], speed).0.abs())
        .fold(0.0, f64::max);
    s.max(q).max(1e-9)
}

/// Newton solve of a stage in place on `t` (boundary entries untouched).
#[allow(clippy::too_many_arguments)]
fn newton(
    net: &ThermalNetwork,
    w: &mut Work,
    t: &mut [f64],
    sources_w: &[f64],
    speed: f64,
    stage: &Stage,
    opts: &NewtonOptions,
    solver: &str,
) -> Result<usize> {
    let nf = w.free.len();
    let eval = |net: &ThermalNetwork, w: &mut Work, t: &[f64], jac: bool| -> f64 {
        if jac {
            net.residual(t, sources_w, speed, &mut w.r, Some(&mut w.jac));
        } else {
            net.residual(t, sources_w, speed, &mut w.r, None);
        }
        let mut m: f64 = 0.0;
        for &i in &w.free {
            let f = stage.weight[i] * w.r[i] - stage.capacity[i] * (t[i] - stage.base[i]);
            w.r[i] = f;
            m = m.max(f.abs());
        }
        m
    };
    let mut res = eval(net, w, t, true);
    for it in 0..=opts.max_iterations {
        // Heat scale, and the roundoff level of the capacity terms C (T - b).
        let cap = w
            .free
            .iter()
            .map(|&i| stage.capacity[i] * t[i].abs())
            .fold(0.0, f64::max);
        let tol = opts.relative_tolerance * scale_of(net, t, sources_w, speed).max(1e-4 * cap);
        if res <= tol {
            return Ok(it);
        }
        if it == opts.max_iterations {
            return Err(Error::convergence(solver, it, res, tol));
        }
        // dF/dT on free nodes: w_i J_ij - c_i delta_ij.
        let a = DMatrix::from_fn(nf, nf, |p, q| {
            let (i, j) = (w.free[p], w.free[q]);
            stage.weight[i] * w.jac[(i, j)] - if p == q { stage.capacity[i] } else { 0.0 }
        });
        let rhs = DVector::from_fn(nf, |p, _| -w.r[w.free[p]]);
        let dx = a
            .lu()
            .solve(&rhs)
            .ok_or_else(|| Error::convergence(format!("{solver} (singular Jacobian)"), it, res, tol))?;
        if dx.iter().any(|v| !v.is_finite()) {
            return Err(Error::convergence(format!("{solver} (non-finite step)"), it, res, tol));
        }
        // Backtracking line search on max |F|.
        let mut lambda = 1.0;
        let mut accepted = false;
        for _ in 0..30 {
            w.trial.copy_from_slice(t);
            for (p, &i) in w.free.iter().enumerate() {
                w.trial[i] = t[i] + lambda * dx[p];
            }
            let trial = std::mem::take(&mut w.trial);
            let rt = eval(net, w, &trial, false);
            w.trial = trial;
            if rt < res || rt <= tol {
                accepted = true;
                break;
            }
            lambda *= 0.5;
        }
        if !accepted {
            return Err(Error::convergence(format!("{solver} (line search)"), it, res, tol));
        }
        t.copy_from_slice(&w.trial);
        res = eval(net, w, t, true);
    }
    Err(Error::convergence(solver, opts.max_iterations, res, 0.0))
}

/// Steady-state solver, reusable with warm starts (the coupled fixed point
/// calls [`SteadySolver::solve`] once per outer iteration).
#[derive(Debug, Clone)]
pub struct SteadySolver {
    network: ThermalNetwork,
    names: Arc<[String]>,
    /// Newton settings (default: 60 iterations, relative tolerance 1e-12).
    pub options: NewtonOptions,
    work: Work,
    last: Option<Vec<f64>>,
    /// Newton iterations used by the last solve.
    pub last_iterations: usize,
}

impl SteadySolver {
    /// A solver for `network` with default [`NewtonOptions`] and no warm
    /// start (the first solve starts from a linearised network).
    pub fn new(network: ThermalNetwork) -> Self {
        let work = Work::new(&network);
        SteadySolver {
            names: network.names(),
            network,
            options: NewtonOptions::default(),
            work,
            last: None,
            last_iterations: 0,
        }
    }

    /// The network being solved.
    pub fn network(&self) -> &ThermalNetwork {
        &self.network
    }

    /// Change a boundary temperature (keeps the warm start).
    pub fn set_boundary_temperature(&mut self, node: NodeId, temperature_c: f64) -> Result<()> {
        self.network.set_boundary_temperature(node, temperature_c)?;
        if let Some(t) = self.last.as_mut() {
            t[node] = temperature_c;
        }
        Ok(())
    }

    /// Forget the warm start.
    pub fn reset(&mut self) {
        self.last = None;
    }

    /// Linear start: every link at its conductance for |dT| = 10 K.
    fn linear_start(&self, sources_w: &[f64], speed: f64) -> Result<Vec<f64>> {
        let net = &self.network;
        let mut t = net.initial_temperatures(0.0);
        let free = &self.work.free;
        let nf = free.len();
        let slot = &self.work.slot;
        let mut a = DMatrix::zeros(nf, nf);
        let mut b = DVector::from_fn(nf, |p, _| sources_w[free[p]]);
        for l in &net.links {
            let g = match &l.kind {
                LinkKind::Conduction { conductance_w_per_k } => *conductance_w_per_k,
                LinkKind::Convection { area_m2, law } => area_m2 * law.h_w_m2k(10.0, speed),
            };
            for (x, y) in [(l.a, l.b), (l.b, l.a)] {
                if slot[x] != usize::MAX {
                    a[(slot[x], slot[x])] += g;
                    if slot[y] != usize::MAX {
                        a[(slot[x], slot[y])] -= g;
                    } else {
                        b[slot[x]] += g * t[y];
                    }
                }
            }
        }
        let x = a
            .lu()
            .solve(&b)
            .ok_or_else(|| Error::convergence("thermal steady state (linear start)", 0, f64::INFINITY, 0.0))?;
        for (p, &i) in free.iter().enumerate() {
            t[i] = x[p];
        }
        Ok(t)
    }

    /// Steady temperatures for heat sources [W per node] at a speed [rad/s].
    pub fn solve(&mut self, sources_w: &[f64], speed_rad_s: f64) -> Result<Temperatures> {
        let net = &self.network;
        net.check_sources(sources_w)?;
        finite("speed_rad_s", speed_rad_s)?;
        net.check_connected(speed_rad_s)?;
        let mut t = match self.last.take() {
            Some(t) => t,
            None => self.linear_start(sources_w, speed_rad_s)?,
        };
        let n = net.nodes.len();
        let ones = vec![1.0; n];
        let zeros = vec![0.0; n];
        let stage = Stage {
            weight: &ones,
            capacity: &zeros,
            base: &zeros,
        };
        let it = newton(
            net,
            &mut self.work,
            &mut t,
            sources_w,
            speed_rad_s,
            &stage,
            &self.options,
            "thermal steady state",
        )?;
        self.last_iterations = it;
        self.last = Some(t.clone());
        Ok(Temperatures {
            names: self.names.clone(),
            temperatures_c: t,
        })
    }

    /// Steady state with sources that depend on the temperatures (e.g. the
    /// viscous moment through the oil viscosity): fixed-point iteration
    /// `s <- sources(T)`, `T <- solve(s)` until the temperatures move less
    /// than `tolerance_k`.
    pub fn solve_with<F>(
        &mut self,
        speed_rad_s: f64,
        mut sources: F,
        tolerance_k: f64,
        max_iterations: usize,
    ) -> Result<Temperatures>
    where
        F: FnMut(&Temperatures) -> Result<Vec<f64>>,
    {
        positive("tolerance_k", tolerance_k)?;
        let mut temps = Temperatures {
            names: self.names.clone(),
            temperatures_c: self
                .last
                .clone()
                .unwrap_or_else(|| self.network.initial_temperatures(self.mean_boundary())),
        };
        let mut change = f64::INFINITY;
        for _ in 0..max_iterations {
            let s = sources(&temps)?;
            let next = self.solve(&s, speed_rad_s)?;
            change = next
                .temperatures_c
                .iter()
                .zip(&temps.temperatures_c)
                .map(|(a, b)| (a - b).abs())
                .fold(0.0, f64::max);
            temps = next;
            if change <= tolerance_k {
                return Ok(temps);
            }
        }
        Err(Error::convergence(
            "thermal steady state with temperature-dependent sources",
            max_iterations,
            change,
            tolerance_k,
        ))
    }

    fn mean_boundary(&self) -> f64 {
        let b: Vec<f64> = self
            .network
            .nodes
            .iter()
            .filter_map(|n| match n.kind {
                NodeKind::Boundary { temperature_c } => Some(temperature_c),
                _ => None,
            })
            .collect();
        b.iter().sum::<f64>() / b.len().max(1) as f64
    }
}

/// A recorded transient.
#[derive(Debug, Clone, PartialEq)]
pub struct Transient {
    /// Node names, in node order.
    pub names: Arc<[String]>,
    /// Times of the records \[s\].
    pub times_s: Vec<f64>,
    /// Temperatures at each record, one vector per time \[C\].
    pub temperatures_c: Vec<Vec<f64>>,
}

/// TR-BDF2 transient integrator with a fixed step.
#[derive(Debug, Clone)]
pub struct TransientSolver {
    network: ThermalNetwork,
    /// Newton settings of each implicit stage (default: 30 iterations,
    /// relative tolerance 1e-10).
    pub options: NewtonOptions,
    work: Work,
    capacity: Vec<f64>,
    gamma_stage: Vec<f64>,
    bdf_stage: Vec<f64>,
    /// Newton iterations of the last step (both stages).
    pub last_iterations: usize,
}

/// TR-BDF2 stage fraction gamma = 2 - sqrt(2).
const GAMMA: f64 = 2.0 - std::f64::consts::SQRT_2;

/// The most rows a transient records (times x node temperatures): a
/// million rows of a spindle network are a few hundred megabytes.
pub const MAX_RECORDED_ROWS: usize = 1_000_000;

impl TransientSolver {
    /// A TR-BDF2 integrator for `network` (heat capacities read once here).
    pub fn new(network: ThermalNetwork) -> Self {
        let work = Work::new(&network);
        let n = network.nodes.len();
        let capacity = (0..n).map(|i| network.heat_capacity_j_per_k(i)).collect();
        TransientSolver {
            network,
            options: NewtonOptions {
                max_iterations: 30,
                relative_tolerance: 1e-10,
            },
            work,
            capacity,
            gamma_stage: vec![0.0; n],
            bdf_stage: vec![0.0; n],
            last_iterations: 0,
        }
    }

    /// The network being integrated.
    pub fn network(&self) -> &ThermalNetwork {
        &self.network
    }

    /// One TR-BDF2 step of length `dt_s` from time `t_s`, in place on
    /// `temperatures_c` (all nodes; boundary entries are reset to their
    /// fixed values). `sources_w` gives the sources at t, t + gamma dt and
    /// t + dt (pass the same slice three times for constant sources).
    pub fn step(
        &mut self,
        temperatures_c: &mut [f64],
        dt_s: f64,
        speed_rad_s: f64,
        sources_w: [&[f64]; 3],
    ) -> Result<()> {
        let net = &self.network;
        let n = net.nodes.len();
        if temperatures_c.len() != n {
            return Err(Error::config(
                "temperatures_c",
                temperatures_c.len(),
                format!("need one temperature per node ({n} nodes)"),
            ));
        }
        for (k, s) in sources_w.iter().enumerate() {
            if s.len() != n {
                return Err(Error::config(
                    "sources_w",
                    s.len(),
                    format!("stage {k}: need one heat source per node ({n} nodes)"),
                ));
            }
        }
        for (i, node) in net.nodes.iter().enumerate() {
            if let NodeKind::Boundary { temperature_c } = node.kind {
                temperatures_c[i] = temperature_c;
            }
        }
        let h = dt_s;
        // Stage 1 (trapezoid to t + gamma h), massive rows:
        //   C (X - T_n) = (gamma h / 2) (r(X) + r(T_n))
        // written as (gamma h / 2) r(X) - C (X - b) = 0 with
        //   b = T_n + (gamma h / 2) r(T_n) / C; massless rows: r(X) = 0.
        let mut r0 = vec![0.0; n];
        net.residual(temperatures_c, sources_w[0], speed_rad_s, &mut r0, None);
        let mut weight = vec![1.0; n];
        let mut base = vec![0.0; n];
        let half = 0.5 * GAMMA * h;
        for i in 0..n {
            if self.capacity[i] > 0.0 {
                weight[i] = half;
                base[i] = temperatures_c[i] + half * r0[i] / self.capacity[i];
            }
        }
        let cap_rows: Vec<f64> = self.capacity.iter().map(|&c| c.max(0.0)).collect();
        self.gamma_stage.copy_from_slice(temperatures_c);
        let it1 = newton(
            net,
            &mut self.work,
            &mut self.gamma_stage,
            sources_w[1],
            speed_rad_s,
            &Stage {
                weight: &weight,
                capacity: &cap_rows,
                base: &base,
            },
            &self.options,
            "thermal transient (TR stage)",
        )?;
        // Stage 2 (BDF2 to t + h):
        //   C (Y - a X + c0 T_n) = w h r(Y), a = 1/(g(2-g)),
        //   c0 = (1-g)^2/(g(2-g)), w = (1-g)/(2-g).
        let ga = 1.0 / (GAMMA * (2.0 - GAMMA));
        let gc = (1.0 - GAMMA).powi(2) / (GAMMA * (2.0 - GAMMA));
        let gw = (1.0 - GAMMA) / (2.0 - GAMMA);
        for i in 0..n {
            if self.capacity[i] > 0.0 {
                weight[i] = gw * h;
                base[i] = ga * self.gamma_stage[i] - gc * temperatures_c[i];
            } else {
                weight[i] = 1.0;
                base[i] = 0.0;
            }
        }
        self.bdf_stage.copy_from_slice(&self.gamma_stage);
        let it2 = newton(
            net,
            &mut self.work,
            &mut self.bdf_stage,
            sources_w[2],
            speed_rad_s,
            &Stage {
                weight: &weight,
                capacity: &cap_rows,
                base: &base,
            },
            &self.options,
            "thermal transient (BDF2 stage)",
        )?;
        self.last_iterations = it1 + it2;
        temperatures_c.copy_from_slice(&self.bdf_stage);
        Ok(())
    }

    /// Integrate from `initial_c` (one value per node; boundary entries
    /// are replaced by their fixed values) over `duration_s` with fixed
    /// steps of at most `dt_s`, recording every `record_every` steps (and
    /// the last). `sources(t_s, temperatures_c, out)` fills the heat
    /// sources at time t from the temperatures at the start of the step
    /// (explicit in the coupling, exact for time-only dependence). At most
    /// [`crate::cancel::MAX_TIME_STEPS`] steps and [`MAX_RECORDED_ROWS`]
    /// recorded rows (a `ConfigError` naming `dt_s` and `duration_s`, or
    /// `record_every`); stops with `Error::Interrupted` after a cancel.
    pub fn integrate<F>(
        &mut self,
        initial_c: &[f64],
        duration_s: f64,
        dt_s: f64,
        speed_rad_s: f64,
        record_every: usize,
        mut sources: F,
    ) -> Result<Transient>
    where
        F: FnMut(f64, &[f64], &mut [f64]) -> Result<()>,
    {
        positive("duration_s", duration_s)?;
        positive("dt_s", dt_s)?;
        finite("speed_rad_s", speed_rad_s)?;
        self.network.check_connected(speed_rad_s)?;
        let n = self.network.nodes.len();
        if initial_c.len() != n {
            return Err(Error::config(
                "initial_c",
                initial_c.len(),
                format!("need one temperature per node ({n} nodes)"),
            ));
        }
        for (i, v) in initial_c.iter().enumerate() {
            finite(&format!("initial_c[{i}]"), *v)?;
        }
        let steps = crate::cancel::step_count(duration_s, dt_s, "dt_s", f64::ceil)?;
        let h = duration_s / steps as f64;
        let every = record_every.max(1);
        if steps / every > MAX_RECORDED_ROWS {
            return Err(Error::config(
                "record_every",
                record_every,
                format!(
                    "{steps} steps recorded every {every} are more than {MAX_RECORDED_ROWS} rows; \
                     use record_every >= {}",
                    steps.div_ceil(MAX_RECORDED_ROWS)
                ),
            ));
        }
        let mut t = initial_c.to_vec();
        for (i, node) in self.network.nodes.iter().enumerate() {
            if let NodeKind::Boundary { temperature_c } = node.kind {
                t[i] = temperature_c;
            }
        }
        let mut out = Transient {
            names: self.network.names(),
            times_s: vec![0.0],
            temperatures_c: vec![t.clone()],
        };
        let mut s = [vec![0.0; n], vec![0.0; n], vec![0.0; n]];
        for k in 0..steps {
            crate::cancel::check()?;
            crate::cancel::advance();
            let t0 = k as f64 * h;
            for (j, frac) in [0.0, GAMMA, 1.0].into_iter().enumerate() {
                sources(t0 + frac * h, &t, &mut s[j])?;
                self.network.check_sources(&s[j])?;
            }
            self.step(&mut t, h, speed_rad_s, [&s[0], &s[1], &s[2]])?;
            if (k + 1) % every == 0 || k + 1 == steps {
                out.times_s.push(t0 + h);
                out.temperatures_c.push(t.clone());
            }
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Source node -> R1 -> middle -> R2 -> end -> R3 -> ambient.
    fn chain(p: f64, r: [f64; 3], ta: f64) -> (ThermalNetwork, Vec<f64>) {
        let mut n = ThermalNetwork::new();
        let a = n.add_node("a", 10.0).unwrap();
        let b = n.add_node("b", 0.0).unwrap();
        let c = n.add_node("c", 20.0).unwrap();
        let amb = n.add_boundary("amb", ta).unwrap();
        n.add_resistance("ab", a, b, r[0]).unwrap();
        n.add_resistance("bc", b, c, r[1]).unwrap();
        n.add_resistance("ca", c, amb, r[2]).unwrap();
        (n, vec![p, 0.0, 0.0, 0.0])
    }

    #[test]
    fn transient_step_rejects_sources_of_the_wrong_length() {
        // A source vector that does not match the nodes is a named error,
        // not a panic inside the step.
        let (n, s) = chain(50.0, [0.1, 0.2, 0.3], 20.0);
        let mut solver = TransientSolver::new(n);
        let mut t = vec![20.0; s.len()];
        let short = &s[..2];
        let err = solver.step(&mut t, 1.0, 0.0, [&s, short, &s]).unwrap_err();
        assert!(err.to_string().contains("sources_w"), "{err}");
        assert!(solver.step(&mut t, 1.0, 0.0, [&s, &s, &s]).is_ok());
    }

    #[test]
    fn three_node_chain_is_series_resistance() {
        let (n, s) = chain(50.0, [0.1, 0.2, 0.3], 20.0);
        let mut solver = SteadySolver::new(n);
        let t = solver.solve(&s, 0.0).unwrap();
        assert!((t.get("a").unwrap() - (20.0 + 50.0 * 0.6)).abs() < 1e-10);
        assert!((t.get("b").unwrap() - (20.0 + 50.0 * 0.5)).abs() < 1e-10);
        assert!((t.get("c").unwrap() - (20.0 + 50.0 * 0.3)).abs() < 1e-10);
    }

    #[test]
    fn two_node_network_against_cramer() {
        // Nodes 1, 2 with sources p1, p2; G1 to ambient, G12 between, G2 to ambient:
        // (G1+G12) x1 - G12 x2 = p1 ; -G12 x1 + (G2+G12) x2 = p2 (x = T - Ta).
        let (g1, g2, g12, p1, p2) = (2.0, 5.0, 3.0, 40.0, 10.0);
        let mut n = ThermalNetwork::new();
        let a = n.add_node("1", 0.0).unwrap();
        let b = n.add_node("2", 0.0).unwrap();
        let amb = n.add_boundary("amb", 25.0).unwrap();
        n.add_conduction("g1", a, amb, g1).unwrap();
        n.add_conduction("g2", b, amb, g2).unwrap();
        n.add_conduction("g12", a, b, g12).unwrap();
        let t = SteadySolver::new(n).solve(&[p1, p2, 0.0], 0.0).unwrap();
        let det = (g1 + g12) * (g2 + g12) - g12 * g12;
        let x1 = (p1 * (g2 + g12) + g12 * p2) / det;
        let x2 = ((g1 + g12) * p2 + g12 * p1) / det;
        assert!((t.temperatures_c[0] - 25.0 - x1).abs() < 1e-10);
        assert!((t.temperatures_c[1] - 25.0 - x2).abs() < 1e-10);
    }

    fn convective_net() -> (ThermalNetwork, Vec<f64>) {
        let mut n = ThermalNetwork::new();
        let a = n.add_node("body", 500.0).unwrap();
        let b = n.add_node("shell", 0.0).unwrap();
        let amb = n.add_boundary("air", 26.0).unwrap();
        let oil = n.add_boundary("oil", 28.0).unwrap();
        n.add_conduction("k", a, b, 4.0).unwrap();
        n.add_convection(
            "nat",
            b,
            amb,
            0.05,
            Convection::Natural {
                coefficient_w_m2_k125: SEED_A_NATURAL_W_M2_K125,
            },
        )
        .unwrap();
        n.add_convection(
            "film",
            a,
            oil,
            0.002,
            Convection::ForcedFilm {
                coefficient: POHLHAUSEN_LOCAL,
                fluid_conductivity_w_mk: 0.13,
                prandtl: 400.0,
                kinematic_viscosity_m2_s: 30e-6,
                length_m: 0.06,
                velocity_per_speed_m: 0.03,
            },
        )
        .unwrap();
        (n, vec![60.0, 0.0, 0.0, 0.0])
    }

    #[test]
    fn heat_balance_at_steady_state() {
        let (n, s) = convective_net();
        let mut solver = SteadySolver::new(n.clone());
        let t = solver.solve(&s, 800.0).unwrap();
        let out: f64 = n.boundary_flows_w(&t.temperatures_c, 800.0).iter().map(|x| x.1).sum();
        assert!((out - 60.0).abs() < 1e-9 * 60.0, "{out}");
        // Warm start converges at once and gives the same answer.
        let t2 = solver.solve(&s, 800.0).unwrap();
        assert!(solver.last_iterations <= 1);
        assert!((t2.temperatures_c[0] - t.temperatures_c[0]).abs() < 1e-9);
    }

    #[test]
    fn nonlinear_convection_against_bisection() {
        // Single node: P = G (T - Ta) + C S (T - Ta)^1.25 with G = 0.5 W/K.
        let (p, g, c, s, ta) = (30.0, 0.5, 23.0, 0.04, 26.0);
        let mut n = ThermalNetwork::new();
        let a = n.add_node("x", 0.0).unwrap();
        let amb = n.add_boundary("amb", ta).unwrap();
        n.add_conduction("g", a, amb, g).unwrap();
        n.add_convection(
            "nat",
            a,
            amb,
            s,
            Convection::Natural {
                coefficient_w_m2_k125: c,
            },
        )
        .unwrap();
        let t = SteadySolver::new(n).solve(&[p, 0.0], 0.0).unwrap().temperatures_c[0];
        let f = |x: f64| g * x + c * s * x.powf(1.25) - p;
        let (mut lo, mut hi) = (0.0, 200.0);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if f(mid) > 0.0 {
                hi = mid
            } else {
                lo = mid
            }
        }
        assert!((t - ta - 0.5 * (lo + hi)).abs() < 1e-9, "{t}");
    }

    /// Single RC node: C dT/dt = P - G (T - Ta).
    fn rc(c: f64, g: f64) -> ThermalNetwork {
        let mut n = ThermalNetwork::new();
        let a = n.add_node("m", c).unwrap();
        let amb = n.add_boundary("amb", 20.0).unwrap();
        n.add_conduction("g", a, amb, g).unwrap();
        n
    }

    fn rc_error(dt: f64) -> f64 {
        let (c, g, p) = (100.0, 2.0, 10.0);
        let mut solver = TransientSolver::new(rc(c, g));
        let tr = solver
            .integrate(&[20.0, 20.0], 100.0, dt, 0.0, 1_000_000, |_, _, s| {
                s[0] = p;
                s[1] = 0.0;
                Ok(())
            })
            .unwrap();
        let t_end = *tr.times_s.last().unwrap();
        let exact = 20.0 + p / g * (1.0 - (-t_end * g / c).exp());
        (tr.temperatures_c.last().unwrap()[0] - exact).abs()
    }

    #[test]
    fn rc_transient_is_second_order() {
        let e1 = rc_error(10.0);
        let e2 = rc_error(5.0);
        let e3 = rc_error(2.5);
        let o1 = (e1 / e2).log2();
        let o2 = (e2 / e3).log2();
        assert!((o1 - 2.0).abs() < 0.15 && (o2 - 2.0).abs() < 0.1, "{o1} {o2}");
        assert!(e3 < 1e-3, "{e3}");
    }

    #[test]
    fn transient_settles_to_steady_state() {
        let (n, s) = convective_net();
        let speed = 800.0;
        let steady = SteadySolver::new(n.clone()).solve(&s, speed).unwrap();
        let tau = n.time_constants_s(&steady.temperatures_c, speed).unwrap()[0];
        let mut solver = TransientSolver::new(n);
        let init = solver.network().initial_temperatures(26.0);
        let tr = solver
            .integrate(&init, 30.0 * tau, tau / 10.0, speed, 1000, |_, _, out| {
                out.copy_from_slice(&s);
                Ok(())
            })
            .unwrap();
        let last = tr.temperatures_c.last().unwrap();
        for (a, b) in last.iter().zip(&steady.temperatures_c) {
            assert!((a - b).abs() < 1e-6, "{a} vs {b}");
        }
    }

    #[test]
    fn errors_name_the_culprit() {
        let mut n = ThermalNetwork::new();
        let a = n.add_node("a", 1.0).unwrap();
        let e = n.add_conduction("bad", a, a, 1.0).unwrap_err().to_string();
        assert!(e.contains("bad"));
        let amb = n.add_boundary("amb", 20.0).unwrap();
        let e = n.add_conduction("neg", a, amb, -1.0).unwrap_err().to_string();
        assert!(e.contains("neg.conductance_w_per_k"), "{e}");
        let e = n.add_node("heavy", -5.0).unwrap_err().to_string();
        assert!(e.contains("heavy.heat_capacity_j_per_k"), "{e}");
        n.add_conduction("ok", a, amb, 1.0).unwrap();
        let island = n.add_node("island", 1.0).unwrap();
        let other = n.add_node("other", 1.0).unwrap();
        n.add_conduction("i-o", island, other, 1.0).unwrap();
        let e = SteadySolver::new(n.clone())
            .solve(&[1.0, 0.0, 0.0, 0.0], 0.0)
            .unwrap_err()
            .to_string();
        assert!(e.contains("island") && e.contains("singular"), "{e}");
        // A film coefficient vanishes at zero speed: that link no longer connects.
        let mut m = ThermalNetwork::new();
        let x = m.add_node("ball", 1.0).unwrap();
        let oil = m.add_boundary("oil", 28.0).unwrap();
        m.add_convection(
            "film",
            x,
            oil,
            1e-3,
            Convection::ForcedFilm {
                coefficient: POHLHAUSEN_LOCAL,
                fluid_conductivity_w_mk: 0.13,
                prandtl: 400.0,
                kinematic_viscosity_m2_s: 30e-6,
                length_m: 0.06,
                velocity_per_speed_m: 0.03,
            },
        )
        .unwrap();
        assert!(SteadySolver::new(m.clone())
            .solve(&[1.0, 0.0], 0.0)
            .unwrap_err()
            .to_string()
            .contains("ball"));
        assert!(SteadySolver::new(m).solve(&[1.0, 0.0], 100.0).is_ok());
    }

    #[test]
    fn non_convergence_reports_residual() {
        let (n, s) = convective_net();
        let mut solver = SteadySolver::new(n);
        solver.options.max_iterations = 1;
        solver.options.relative_tolerance = 1e-300;
        match solver.solve(&s, 800.0).unwrap_err() {
            Error::Convergence {
                residual, iterations, ..
            } => assert!(residual.is_finite() && iterations == 1),
            e => panic!("{e}"),
        }
    }

    #[test]
    fn film_coefficient_hand_value() {
        // h = 0.332 k Pr^(1/3) sqrt(u / (nu x)) with k = 0.13, Pr = 400,
        // nu = 30e-6, x = 0.06, u = 0.03 m * 800 rad/s = 24 m/s.
        let law = Convection::ForcedFilm {
            coefficient: POHLHAUSEN_LOCAL,
            fluid_conductivity_w_mk: 0.13,
            prandtl: 400.0,
            kinematic_viscosity_m2_s: 30e-6,
            length_m: 0.06,
            velocity_per_speed_m: 0.03,
        };
        let hand = 0.332 * 0.13 * 400f64.cbrt() * (24.0 / (30e-6 * 0.06f64)).sqrt();
        assert!((law.h_w_m2k(5.0, -800.0) - hand).abs() < 1e-9 * hand);
        // Natural: h = C dT^0.25, symmetric in the sign of dT.
        let nat = Convection::Natural {
            coefficient_w_m2_k125: 23.0,
        };
        assert!((nat.h_w_m2k(-16.0, 0.0) - 46.0).abs() < 1e-12);
    }

    #[test]
    fn massless_node_is_eliminated_in_time_constants() {
        // C -- R1 -- (massless) -- R2 -- ambient: tau = C (R1 + R2).
        let mut n = ThermalNetwork::new();
        let a = n.add_node("a", 40.0).unwrap();
        let b = n.add_node("b", 0.0).unwrap();
        let amb = n.add_boundary("amb", 0.0).unwrap();
        n.add_resistance("r1", a, b, 2.0).unwrap();
        n.add_resistance("r2", b, amb, 3.0).unwrap();
        let tau = n.time_constants_s(&[0.0; 3], 0.0).unwrap();
        assert_eq!(tau.len(), 1);
        assert!((tau[0] - 200.0).abs() < 1e-9);
    }

    #[test]
    fn rc_time_constant_is_c_over_g() {
        let n = rc(300.0, 1.5);
        let tau = n.time_constants_s(&[20.0, 20.0], 0.0).unwrap();
        assert!((tau[0] - 200.0).abs() < 1e-9);
    }
}
