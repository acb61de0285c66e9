//! Craig–Bampton component-mode reduction (Craig & Bampton, *Coupling of substructures for
//! dynamic analyses*, AIAA J. 6 (1968) 1313–1319; Friswell et al. (2010) §5.10 on model
//! reduction of rotors).
//!
//! The DOFs are split into boundary DOFs b (kept physical: bearing and load nodes) and interior
//! DOFs i. The interior motion is the static response to the boundary motion plus a few
//! fixed-interface normal modes:
//!
//!   q = T [q_b; η],  T = [[I, 0], [Ψ, Φ]],  Ψ = −K_ii⁻¹ K_ib,  K_ii Φ = M_ii Φ Ω²
//!
//! (rows of T reordered back to the global DOF order). The reduced matrices are TᵀMT, TᵀKT,
//! TᵀGT, TᵀCT. Statics under boundary loads is exact; the dynamic error is that of the truncated
//! interior modes and is measured against the full model by [`frequency_error`].

use nalgebra::DMatrix;

use crate::analysis::modes::{undamped_modes, ModesError};
use crate::model::RotorModel;

/// A reduced model: transformation and reduced matrices.
#[derive(Debug, Clone)]
pub struct ReducedModel {
    /// T (n_full × n_reduced): q_full = T q_reduced.
    pub transform: DMatrix<f64>,
    /// Global DOF index of each kept boundary DOF; boundary DOF k is reduced coordinate k.
    pub boundary_dofs: Vec<usize>,
    /// Number of fixed-interface modes kept.
    pub n_modes: usize,
    /// Reduced mass matrix.
    pub mass: DMatrix<f64>,
    /// Reduced stiffness matrix (shaft only).
    pub stiffness: DMatrix<f64>,
    /// Reduced gyroscopic matrix (per rad/s).
    pub gyroscopic: DMatrix<f64>,
    /// Reduced material damping matrix.
    pub damping: DMatrix<f64>,
}

impl ReducedModel {
    /// Reduced coordinate index of a global boundary DOF.
    pub fn reduced_index(&self, global_dof: usize) -> Option<usize> {
        self.boundary_dofs.iter().position(|&d| d == global_dof)
    }
}

/// Builds the Craig–Bampton model keeping all 4 DOFs of the given nodes and `n_modes`
/// fixed-interface modes.
pub fn craig_bampton(
    model: &RotorModel,
    boundary_nodes: &[usize],
    n_modes: usize,
) -> Result<ReducedModel, ModesError> {
    let n = model.n_dof();
    let mut nodes: Vec<usize> = boundary_nodes.to_vec();
    nodes.sort_unstable();
    nodes.dedup();
    let boundary: Vec<usize> = nodes.iter().flat_map(|&nd| 4 * nd..4 * nd + 4).collect();
    let interior: Vec<usize> = (0..n).filter(|d| !boundary.contains(d)).collect();
    let (nb, ni) = (boundary.len(), interior.len());
    let sub = |m: &DMatrix<f64>, rows: &[usize], cols: &[usize]| {
        DMatrix::from_fn(rows.len(), cols.len(), |r, c| m[(rows[r], cols[c])])
    };
    let k_ii = sub(&model.stiffness, &interior, &interior);
    let k_ib = sub(&model.stiffness, &interior, &boundary);
    let m_ii = sub(&model.mass, &interior, &interior);
    let n_modes = n_modes.min(ni);
    let mut t = DMatrix::zeros(n, nb + n_modes);
    for (k, &d) in boundary.iter().enumerate() {
        t[(d, k)] = 1.0;
    }
    if ni > 0 {
        // The interior with its boundary clamped is held (boundary includes bearing nodes).
        let lu = k_ii.clone().lu();
        let psi = lu.solve(&(-k_ib)).ok_or(ModesError::SingularInterior)?;
        let (_, phi) = undamped_modes(&m_ii, &k_ii)?;
        for (r, &d) in interior.iter().enumerate() {
            for c in 0..nb {
                t[(d, c)] = psi[(r, c)];
            }
            for c in 0..n_modes {
                t[(d, nb + c)] = phi[(r, c)];
            }
        }
    }
    let tt = t.transpose();
    Ok(ReducedModel {
        mass: &tt * &model.mass * &t,
        stiffness: &tt * &model.stiffness * &t,
        gyroscopic: &tt * &model.gyroscopic * &t,
        damping: &tt * &model.damping * &t,
        transform: t,
        boundary_dofs: boundary,
        n_modes,
    })
}

/// Relative errors of the reduced model's lowest undamped natural frequencies against the full
/// model's (both with the bearings linearised to the given 2×2 stiffnesses), skipping
/// rigid-body zeros: (full frequency (rad/s), relative error) pairs, `count` of them.
pub fn frequency_error(
    model: &RotorModel,
    reduced: &ReducedModel,
    bearing_stiffness: &[[[f64; 2]; 2]],
    count: usize,
) -> Result<Vec<(f64, f64)>, ModesError> {
    let zeros = vec![[[0.0; 2]; 2]; bearing_stiffness.len()];
    let (k_full, _) = model.linearised(0.0, bearing_stiffness, &zeros);
    let mut k_red = reduced.stiffness.clone();
    for (dofs, kb) in model.bearing_dofs().iter().zip(bearing_stiffness) {
        let idx = [
            reduced
                .reduced_index(dofs[0])
                .ok_or(ModesError::NotKept(dofs[0]))?,
            reduced
                .reduced_index(dofs[1])
                .ok_or(ModesError::NotKept(dofs[1]))?,
        ];
        for r in 0..2 {
            for c in 0..2 {
                k_red[(idx[r], idx[c])] += kb[r][c];
            }
        }
    }
    let (wf, _) = undamped_modes(&model.mass, &k_full)?;
    let (wr, _) = undamped_modes(&reduced.mass, &k_red)?;
    let floor = 1e-6 * wf.last().copied().unwrap_or(1.0);
    let wf: Vec<f64> = wf.into_iter().filter(|&w| w > floor).collect();
    let wr: Vec<f64> = wr.into_iter().filter(|&w| w > floor).collect();
    Ok(wf
        .iter()
        .zip(&wr)
        .take(count)
        .map(|(f, r)| (*f, (r - f) / f))
        .collect())
}
