//! The assembled rotor: shaft elements between consecutive nodes, rigid disks, bearing sites,
//! material damping and loads, with the global mass M, stiffness K, gyroscopic G and damping C
//! matrices (dense; rotors of this project have ≤ a few hundred DOFs).
//!
//! Global DOF of node i: 4i + {0: x, 1: y, 2: θx, 3: θy} (see [`crate::model::element`]). The equation
//! of motion with the spin speed Ω held constant (Friswell et al. (2010) eq. (5.1) form):
//!
//!   M q̈ + (C + Ω G) q̇ + K q = f(t) + Σ_bearings Pᵀ F_b(P q, P q̇)

pub mod config;
pub mod damping;
pub mod disk;
pub mod element;
pub mod loads;
pub mod motor;
pub mod speed_profile;

use nalgebra::{DMatrix, DVector};

use crate::bearing::BearingSpec;
use crate::model::damping::ProportionalDamping;
use crate::model::disk::RigidDisk;
use crate::model::element::{Material, TimoshenkoElement};
use crate::model::loads::LoadSet;

/// DOFs per node.
pub const DOF_PER_NODE: usize = 4;

/// A bearing placed at a node.
#[derive(Debug, Clone, PartialEq)]
pub struct BearingSite {
    /// Node index.
    pub node: usize,
    /// How to build its model.
    pub spec: BearingSpec,
}

/// Geometry and properties of a rotor before assembly.
#[derive(Debug, Clone, PartialEq)]
pub struct RotorDescription {
    /// Axial node positions (m), strictly increasing.
    pub node_positions: Vec<f64>,
    /// Outer and inner diameter (m) of element e (between nodes e and e+1).
    pub element_diameters: Vec<(f64, f64)>,
    /// Shaft material.
    pub material: Material,
    /// Rigid disks.
    pub disks: Vec<RigidDisk>,
    /// Bearings.
    pub bearings: Vec<BearingSite>,
    /// Material damping of the shaft.
    pub damping: ProportionalDamping,
    /// External loads.
    pub loads: LoadSet,
}

/// Assembled rotor model.
#[derive(Debug, Clone)]
pub struct RotorModel {
    /// The description it was built from.
    pub description: RotorDescription,
    /// Shaft elements, element e between nodes e and e+1.
    pub elements: Vec<TimoshenkoElement>,
    /// Mass matrix M.
    pub mass: DMatrix<f64>,
    /// Stiffness matrix K (shaft only; bearings are added by the analyses).
    pub stiffness: DMatrix<f64>,
    /// Gyroscopic matrix G (per rad/s of spin).
    pub gyroscopic: DMatrix<f64>,
    /// Material damping matrix C = aM_shaft + bK_shaft.
    pub damping: DMatrix<f64>,
    /// Gravity load per unit g: M times a unit acceleration field along −y (N per m/s²).
    pub gravity_vector: DVector<f64>,
}

impl RotorModel {
    /// Assembles the global matrices. The description must be valid (the TOML loader checks it).
    pub fn assemble(description: RotorDescription) -> RotorModel {
        let n_nodes = description.node_positions.len();
        let n = n_nodes * DOF_PER_NODE;
        let mut mass = DMatrix::zeros(n, n);
        let mut stiffness = DMatrix::zeros(n, n);
        let mut gyroscopic = DMatrix::zeros(n, n);
        let mut elements = Vec::with_capacity(n_nodes.saturating_sub(1));
        for (e, &(outer, inner)) in description.element_diameters.iter().enumerate() {
            let element = TimoshenkoElement {
                length: description.node_positions[e + 1] - description.node_positions[e],
                outer_diameter: outer,
                inner_diameter: inner,
                material: description.material,
            };
            let m = element.matrices();
            let base = e * DOF_PER_NODE;
            for r in 0..8 {
                for c in 0..8 {
                    mass[(base + r, base + c)] += m.mass[(r, c)];
                    stiffness[(base + r, base + c)] += m.stiffness[(r, c)];
                    gyroscopic[(base + r, base + c)] += m.gyroscopic[(r, c)];
                }
            }
            elements.push(element);
        }
        let damping = &mass * description.damping.mass_coefficient
            + &stiffness * description.damping.stiffness_coefficient;
        for disk in &description.disks {
            let b = disk.node * DOF_PER_NODE;
            mass[(b, b)] += disk.mass;
            mass[(b + 1, b + 1)] += disk.mass;
            mass[(b + 2, b + 2)] += disk.diametral_inertia;
            mass[(b + 3, b + 3)] += disk.diametral_inertia;
            gyroscopic[(b + 2, b + 3)] += disk.polar_inertia;
            gyroscopic[(b + 3, b + 2)] -= disk.polar_inertia;
        }
        let mut unit_down = DVector::zeros(n);
        for i in 0..n_nodes {
            unit_down[i * DOF_PER_NODE + 1] = -1.0;
        }
        let gravity_vector = &mass * unit_down;
        RotorModel {
            description,
            elements,
            mass,
            stiffness,
            gyroscopic,
            damping,
            gravity_vector,
        }
    }

    /// Number of DOFs.
    pub fn n_dof(&self) -> usize {
        self.mass.nrows()
    }

    /// Number of nodes.
    pub fn n_nodes(&self) -> usize {
        self.description.node_positions.len()
    }

    /// Total mass of shaft and disks (kg).
    pub fn total_mass(&self) -> f64 {
        self.elements.iter().map(|e| e.mass()).sum::<f64>()
            + self.description.disks.iter().map(|d| d.mass).sum::<f64>()
    }

    /// Global indices of the x and y DOFs of each bearing, in bearing order.
    pub fn bearing_dofs(&self) -> Vec<[usize; 2]> {
        self.description
            .bearings
            .iter()
            .map(|b| [b.node * DOF_PER_NODE, b.node * DOF_PER_NODE + 1])
            .collect()
    }

    /// Stiffness K + Σ P ᵀK_b P and damping C + Ω G + Σ Pᵀ C_b P with the bearings linearised to
    /// the given 2×2 stiffness and damping matrices (one pair per bearing, in bearing order).
    pub fn linearised(
        &self,
        spin_speed: f64,
        bearing_stiffness: &[[[f64; 2]; 2]],
        bearing_damping: &[[[f64; 2]; 2]],
    ) -> (DMatrix<f64>, DMatrix<f64>) {
        let mut k = self.stiffness.clone();
        let mut d = &self.damping + &self.gyroscopic * spin_speed;
        for ((dofs, kb), cb) in self
            .bearing_dofs()
            .iter()
            .zip(bearing_stiffness)
            .zip(bearing_damping)
        {
            for r in 0..2 {
                for c in 0..2 {
                    k[(dofs[r], dofs[c])] += kb[r][c];
                    d[(dofs[r], dofs[c])] += cb[r][c];
                }
            }
        }
        (k, d)
    }
}
