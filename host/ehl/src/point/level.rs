//! One uniform grid level of the point-contact solver: the discretised Reynolds equation, its
//! semi-system Jacobian in a fixed sparse pattern, its sparse LU, and the Newton correction
//! solved by GMRES with that LU as preconditioner.
//!
//! Discretisation (Venner & Lubrecht, *Multilevel Methods in Lubrication*, 2000, ch. 9, in the
//! scaling X = x/b, Y = y/a, P = p/p_h, H = hR_x/b²):
//!
//!   ∂/∂X(ε ∂P/∂X) + k⁻² ∂/∂Y(ε ∂P/∂Y) − ∂(ρ̄H)/∂X = 0,   ε = ρ̄H³/(η̄λ), λ = 12η₀u_mR_x²/(b³p_h),
//!   H = H₀ + X²/2 + βY²/2 + Σ K P,   β = k²R_x/R_y,
//!
//! with second-order central differences for the Poiseuille terms (ε averaged to the cell
//! faces), the second-order upwind difference (3f_i − 4f_{i−1} + f_{i−2})/(2ΔX) for the wedge
//! term (first order on the first interior column), P = 0 on the boundary and the Reynolds
//! cavitation condition P ≥ 0 as a complementarity: a node with P = 0 whose residual asks for
//! negative pressure is held at zero for the step (primal–dual active set), every other node
//! satisfies the equation.
//!
//! Semi-system Jacobian (Hu & Zhu 2000, *A full numerical solution to the mixed lubrication in
//! point contacts*, ASME J. Tribol. 122:1): the deflection couples every node to every other, so
//! the exact Newton matrix is dense (N⁴ entries on an N² grid). The matrix assembled here keeps
//! the deflection coefficients only within a window of ±2 × ±1 nodes around each node (the
//! whole grid on grids of at most 17² nodes), which is sparse and cheap to factorise. It is the
//! preconditioner of GMRES, which solves the exact Newton system (`linearised`, the far-field
//! coupling by FFT): measured on the 129² level of the docs' circular case, 4–6 GMRES steps per
//! Newton step and 7 Newton steps, 2.5 s for the whole solve, against 8.0 s with a window of
//! ±4 × ±2 (4 GMRES steps, dearer factorisations) and 3.1 s with ±1 × ±1 (10–16 GMRES steps).

use super::deflection::Deflection;
use super::gmres::gmres;
use super::linearised::{Linearisation, ProductBuffers};
use crate::rheology::Rheology;
use crate::EhlError;
use faer::dyn_stack::{MemBuffer, MemStack, StackReq};
use faer::sparse::linalg::lu::{factorize_symbolic_lu, NumericLu, SymbolicLu};
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};
use faer::{Conj, MatMut, Par};

/// The physics of one case in the solver's scaling.
#[derive(Debug, Clone, Copy)]
pub(super) struct Problem {
    /// λ = 12η₀u_mR_x²/(b³p_h).
    pub lambda: f64,
    pub rheology: Rheology,
    /// Coefficient β of Y²/2 in the gap.
    pub transverse_curvature: f64,
    /// k⁻² = (b/a)², the factor of the Y-flow terms.
    pub transverse_flow: f64,
    pub elastic: bool,
}

/// Largest grid (nodes per direction) whose preconditioner is the exact Jacobian (every
/// deflection coefficient in the window: 15² unknowns).
pub(super) const EXACT_JACOBIAN_NODES: usize = 17;

/// Window of the preconditioning Jacobian: column offsets (di, dj) of a row. Grids above
/// [`EXACT_JACOBIAN_NODES`] keep the deflection coupling within ±2 nodes along X and ±1 along Y
/// (the choice measured in the module docs).
fn window(nx: usize, ny: usize) -> Vec<(isize, isize)> {
    let (a, b) = if nx.max(ny) <= EXACT_JACOBIAN_NODES {
        (nx as isize, ny as isize)
    } else {
        (2, 1)
    };
    let mut w = Vec::new();
    for dj in -b..=b {
        for di in -a..=a {
            w.push((di, dj));
        }
    }
    w
}

/// One grid level: geometry, deflection operator, sparse pattern, LU and the state (P, H₀).
pub(super) struct Level {
    pub nx: usize,
    pub ny: usize,
    pub dx: f64,
    pub dy: f64,
    /// Node coordinates X = x/b and Y = y/a.
    pub x: Vec<f64>,
    pub y: Vec<f64>,
    deflection: Deflection,
    window: Vec<(isize, isize)>,
    centre_slot: usize,
    col_ptr: Vec<usize>,
    row_idx: Vec<usize>,
    values: Vec<f64>,
    /// Position in `values` of (row u, window slot s), or usize::MAX outside the grid.
    slot: Vec<usize>,
    symbolic: SymbolicLu<usize>,
    numeric: NumericLu<usize, f64>,
    scratch: MemBuffer,
    /// Pressure P at all nodes (row-major, j·nx + i), zero on the boundary.
    pub p: Vec<f64>,
    /// Film H at all nodes.
    pub h: Vec<f64>,
    /// Rigid-body separation H₀.
    pub h0: f64,
    deflected: Vec<f64>,
    eps: Vec<f64>,
    /// ∂ε/∂P through ρ̄ and η̄ at the node itself.
    deps: Vec<f64>,
    rho: Vec<f64>,
    drho: Vec<f64>,
    /// Reynolds residual at all nodes (zero on the boundary).
    pub residual: Vec<f64>,
    /// Diagonal of the last Jacobian, per unknown.
    diagonal: Vec<f64>,
    /// Newton correction per unknown, then of H₀ (last entry).
    pub correction: Vec<f64>,
    /// Per unknown: held at P = 0 by the active set in the last Jacobian.
    active: Vec<bool>,
    /// Right-hand side of the last Newton system.
    newton_rhs: Vec<f64>,
    /// M⁻¹ c: the windowed Jacobian's solve of the H₀ column.
    h0_direction: Vec<f64>,
    product: ProductBuffers,
}

impl Level {
    /// A level of nx × ny nodes over X ∈ [x_start, x_end], Y ∈ [−y_half, y_half]; `aspect` is
    /// k = a/b (Y lengths in units of b) and `deflection_scale` the film units of the 1/r
    /// integral, 2p_hR_x/(πE'b).
    pub fn new(
        nx: usize,
        ny: usize,
        (x_start, x_end, y_half): (f64, f64, f64),
        aspect: f64,
        deflection_scale: f64,
    ) -> Result<Self, EhlError> {
        let dx = (x_end - x_start) / (nx - 1) as f64;
        let dy = 2.0 * y_half / (ny - 1) as f64;
        let x = (0..nx).map(|i| x_start + dx * i as f64).collect();
        let y = (0..ny).map(|j| -y_half + dy * j as f64).collect();
        let deflection = Deflection::new(nx, ny, dx, dy * aspect, deflection_scale);
        let (ix, iy) = (nx - 2, ny - 2);
        let unknowns = ix * iy;
        // Pattern: (column, row, row·12 + slot), sorted column-major.
        let window = window(nx, ny);
        let centre_slot = window.iter().position(|&o| o == (0, 0)).unwrap_or(0);
        let mut entries = Vec::with_capacity(unknowns * window.len());
        for row in 0..unknowns {
            let (i, j) = ((row % ix) as isize, (row / ix) as isize);
            for (s, &(a, b)) in window.iter().enumerate() {
                let (ci, cj) = (i + a, j + b);
                if ci >= 0 && cj >= 0 && (ci as usize) < ix && (cj as usize) < iy {
                    let col = cj as usize * ix + ci as usize;
                    entries.push((col, row, row * window.len() + s));
                }
            }
        }
        entries.sort_unstable();
        let mut col_ptr = vec![0usize; unknowns + 1];
        let mut row_idx = Vec::with_capacity(entries.len());
        let mut slot = vec![usize::MAX; unknowns * window.len()];
        for (pos, &(col, row, key)) in entries.iter().enumerate() {
            col_ptr[col + 1] += 1;
            row_idx.push(row);
            slot[key] = pos;
        }
        for c in 0..unknowns {
            col_ptr[c + 1] += col_ptr[c];
        }
        let pattern =
            SymbolicSparseColMatRef::new_checked(unknowns, unknowns, &col_ptr, None, &row_idx);
        let symbolic = factorize_symbolic_lu(pattern, Default::default()).map_err(|_| {
            EhlError::InvalidOption {
                field: "nodes",
                message: "sparse LU analysis failed (out of memory)".into(),
            }
        })?;
        let scratch = MemBuffer::new(StackReq::any_of(&[
            symbolic.factorize_numeric_lu_scratch::<f64>(Par::Seq, Default::default()),
            symbolic.solve_in_place_scratch::<f64>(1, Par::Seq),
        ]));
        let n = nx * ny;
        Ok(Self {
            nx,
            ny,
            dx,
            dy,
            x,
            y,
            deflection,
            window,
            centre_slot,
            values: vec![0.0; row_idx.len()],
            col_ptr,
            row_idx,
            slot,
            symbolic,
            numeric: NumericLu::new(),
            scratch,
            p: vec![0.0; n],
            h: vec![0.0; n],
            h0: 0.0,
            deflected: vec![0.0; n],
            eps: vec![0.0; n],
            deps: vec![0.0; n],
            rho: vec![1.0; n],
            drho: vec![0.0; n],
            residual: vec![0.0; n],
            diagonal: vec![1.0; unknowns],
            correction: vec![0.0; unknowns + 1],
            active: vec![false; unknowns],
            newton_rhs: vec![0.0; unknowns + 1],
            h0_direction: vec![0.0; unknowns],
            product: ProductBuffers::new(n),
        })
    }

    /// Node index of unknown u.
    #[inline]
    pub fn node_of(&self, u: usize) -> usize {
        let ix = self.nx - 2;
        (u / ix + 1) * self.nx + u % ix + 1
    }

    /// Deflection coefficient between nodes (offset in nodes).
    #[inline]
    fn kernel(&self, di: isize, dj: isize) -> f64 {
        self.deflection.coefficient(di, dj)
    }

    /// ∫∫ P dX dY (P vanishes on the boundary, so the cell sum is the trapezoidal rule).
    pub fn load(&self) -> f64 {
        self.p.iter().sum::<f64>() * self.dx * self.dy
    }

    /// Film, ε, ρ̄ and the Reynolds residual for the current P and H₀.
    pub fn evaluate(&mut self, prob: &Problem) {
        let (nx, ny) = (self.nx, self.ny);
        if prob.elastic {
            self.deflection.apply(&self.p, &mut self.deflected);
        } else {
            self.deflected.iter_mut().for_each(|d| *d = 0.0);
        }
        for j in 0..ny {
            let yy = 0.5 * prob.transverse_curvature * self.y[j] * self.y[j];
            for i in 0..nx {
                let m = j * nx + i;
                let h = self.h0 + 0.5 * self.x[i] * self.x[i] + yy + self.deflected[m];
                let (ln_eta, dln_eta) = prob.rheology.ln_viscosity(self.p[m]);
                let (rho, drho) = prob.rheology.density(self.p[m]);
                let eps = rho * h.max(0.0).powi(3) * (-ln_eta).exp() / prob.lambda;
                self.h[m] = h;
                self.eps[m] = eps;
                self.deps[m] = eps * (drho / rho - dln_eta);
                self.rho[m] = rho;
                self.drho[m] = drho;
            }
        }
        let wx = 1.0 / (self.dx * self.dx);
        let wy = prob.transverse_flow / (self.dy * self.dy);
        for j in 1..ny - 1 {
            for i in 1..nx - 1 {
                let m = j * nx + i;
                let (e, w, n, s) = (m + 1, m - 1, m + nx, m - nx);
                let face = |q: usize| 0.5 * (self.eps[m] + self.eps[q]);
                let p = &self.p;
                let flow = wx * (face(e) * (p[e] - p[m]) - face(w) * (p[m] - p[w]))
                    + wy * (face(n) * (p[n] - p[m]) - face(s) * (p[m] - p[s]));
                let rh = |q: usize| self.rho[q] * self.h[q];
                let wedge = if i >= 2 {
                    (3.0 * rh(m) - 4.0 * rh(w) + rh(w - 1)) / (2.0 * self.dx)
                } else {
                    (rh(m) - rh(w)) / self.dx
                };
                self.residual[m] = flow - wedge;
            }
        }
    }

    /// Whether node m is cavitated: no pressure and a residual that asks for negative
    /// pressure.
    #[inline]
    fn cavitated(&self, m: usize) -> bool {
        self.p[m] <= 0.0 && self.residual[m] < 0.0
    }

    /// Σ |R|/|J_mm| over the nodes that are not cavitated: the size of a Jacobi correction,
    /// in units of P (the diagonal is that of the last assembled Jacobian).
    pub fn residual_norm(&self) -> f64 {
        (0..self.active.len())
            .map(|u| {
                let m = self.node_of(u);
                if self.cavitated(m) {
                    0.0
                } else {
                    (self.residual[m] / self.diagonal[u]).abs()
                }
            })
            .sum()
    }

    /// Assembles the semi-system Jacobian at the state of the last [`Level::evaluate`],
    /// factorises it and solves the full Newton system of the pressures and H₀ (load balance
    /// to `target_load`) by GMRES preconditioned with that factorisation, to the relative
    /// residual `tolerance`. The correction is left in `correction` (H₀'s last); returns the
    /// GMRES iterations.
    pub fn newton_correction(
        &mut self,
        prob: &Problem,
        target_load: f64,
        tolerance: f64,
    ) -> Result<usize, EhlError> {
        let nx = self.nx;
        let ix = nx - 2;
        let wx = 1.0 / (self.dx * self.dx);
        let wy = prob.transverse_flow / (self.dy * self.dy);
        self.values.iter_mut().for_each(|v| *v = 0.0);
        let unknowns = self.active.len();
        for u in 0..unknowns {
            let m = self.node_of(u);
            let (i, j) = ((u % ix + 1) as isize, (u / ix + 1) as isize);
            let base = u * self.window.len();
            let (e, w, n, s) = (m + 1, m - 1, m + nx, m - nx);
            let p = &self.p;
            let face = |q: usize| 0.5 * (self.eps[m] + self.eps[q]);
            // ∂(flow)/∂ε_q for the node and its four neighbours.
            let gains = [
                (
                    m,
                    0.5 * wx * (p[e] - 2.0 * p[m] + p[w]) + 0.5 * wy * (p[n] - 2.0 * p[m] + p[s]),
                ),
                (e, 0.5 * wx * (p[e] - p[m])),
                (w, 0.5 * wx * (p[w] - p[m])),
                (n, 0.5 * wy * (p[n] - p[m])),
                (s, 0.5 * wy * (p[s] - p[m])),
            ];
            let upwind: &[(usize, f64)] = if i >= 2 {
                &[
                    (m, 1.5 / self.dx),
                    (w, -2.0 / self.dx),
                    (w - 1, 0.5 / self.dx),
                ]
            } else {
                &[(m, 1.0 / self.dx), (w, -1.0 / self.dx)]
            };
            let node_ij = |q: usize| ((q % nx) as isize, (q / nx) as isize);
            for slot_index in 0..self.window.len() {
                let (a, b) = self.window[slot_index];
                let pos = self.slot[base + slot_index];
                if pos == usize::MAX {
                    continue;
                }
                let (ki, kj) = (i + a, j + b);
                let k = kj as usize * nx + ki as usize;
                let mut v = match (a, b) {
                    (0, 0) => -(wx * (face(e) + face(w)) + wy * (face(n) + face(s))),
                    (1, 0) => wx * face(e),
                    (-1, 0) => wx * face(w),
                    (0, 1) => wy * face(n),
                    (0, -1) => wy * face(s),
                    _ => 0.0,
                };
                for &(q, gain) in &gains {
                    let (qi, qj) = node_ij(q);
                    let mut d = if q == k { self.deps[q] } else { 0.0 };
                    if prob.elastic && self.h[q] > 0.0 {
                        d += 3.0 * self.eps[q] / self.h[q] * self.kernel(qi - ki, qj - kj);
                    }
                    v += gain * d;
                }
                for &(q, c) in upwind {
                    let (qi, qj) = node_ij(q);
                    let mut d = if q == k {
                        self.drho[q] * self.h[q]
                    } else {
                        0.0
                    };
                    if prob.elastic {
                        d += self.rho[q] * self.kernel(qi - ki, qj - kj);
                    }
                    v -= c * d;
                }
                self.values[pos] = v;
            }
            let diagonal = self.values[self.slot[base + self.centre_slot]];
            self.diagonal[u] = diagonal;
            // Primal–dual active set (Hintermüller, Ito & Kunisch 2002): the node is held at
            // P = 0 when the pressure its equation asks to remove, −R/|J_mm|, exceeds P.
            self.active[u] = -self.residual[m] / diagonal.abs() > self.p[m];
            if self.active[u] {
                for s in 0..self.window.len() {
                    let pos = self.slot[base + s];
                    if pos != usize::MAX {
                        self.values[pos] = 0.0;
                    }
                }
                self.values[self.slot[base + self.centre_slot]] = 1.0;
                self.newton_rhs[u] = -self.p[m];
            } else {
                self.newton_rhs[u] = -self.residual[m];
            }
        }
        self.newton_rhs[unknowns] = target_load - self.load();
        let linearisation = Linearisation {
            nx,
            ny: self.ny,
            dx: self.dx,
            dy: self.dy,
            wx,
            wy,
            elastic: prob.elastic,
            p: &self.p,
            h: &self.h,
            eps: &self.eps,
            deps: &self.deps,
            rho: &self.rho,
            drho: &self.drho,
            active: &self.active,
        };
        let (deflection, buffers) = (&mut self.deflection, &mut self.product);
        // The H₀ column c of the Jacobian: the product with the unit H₀ direction.
        let mut unit = vec![0.0; unknowns + 1];
        unit[unknowns] = 1.0;
        let mut h0_column = vec![0.0; unknowns + 1];
        linearisation.apply(deflection, buffers, &unit, &mut h0_column);
        let pattern = SymbolicSparseColMatRef::new_checked(
            unknowns,
            unknowns,
            &self.col_ptr,
            None,
            &self.row_idx,
        );
        let matrix = SparseColMatRef::new(pattern, &self.values);
        let lu = self
            .symbolic
            .factorize_numeric_lu(
                &mut self.numeric,
                matrix,
                Par::Seq,
                MemStack::new(&mut self.scratch),
                Default::default(),
            )
            .map_err(|_| EhlError::NotConverged {
                reason: "singular semi-system Jacobian",
                iterations: 0,
                pressure_change: f64::NAN,
                load_error: f64::NAN,
                reynolds_residual: f64::NAN,
            })?;
        let scratch = &mut self.scratch;
        let mut solve = |v: &mut [f64]| {
            let rhs = MatMut::from_column_major_slice_mut(v, unknowns, 1);
            lu.solve_in_place_with_conj(Conj::No, rhs, Par::Seq, MemStack::new(scratch));
        };
        // Bordered preconditioner [M c; bᵀ 0] with b = ΔXΔY·1 (the load row), by block
        // elimination: z = M⁻¹r − t M⁻¹c, t = (bᵀM⁻¹r − s)/(bᵀM⁻¹c).
        let w = &mut self.h0_direction;
        w.copy_from_slice(&h0_column[..unknowns]);
        solve(w);
        let cell = self.dx * self.dy;
        let schur = cell * w.iter().sum::<f64>();
        let precondition = |v: &mut [f64]| {
            let s = v[unknowns];
            solve(&mut v[..unknowns]);
            let t = if schur != 0.0 {
                (cell * v[..unknowns].iter().sum::<f64>() - s) / schur
            } else {
                0.0
            };
            v[..unknowns]
                .iter_mut()
                .zip(w.iter())
                .for_each(|(a, b)| *a -= t * b);
            v[unknowns] = t;
        };
        let apply = |v: &[f64], out: &mut [f64]| linearisation.apply(deflection, buffers, v, out);
        let (iterations, _) = gmres(
            &self.newton_rhs,
            &mut self.correction,
            tolerance,
            60,
            apply,
            precondition,
        );
        Ok(iterations)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rheology::ViscosityLaw;

    /// A level of n² nodes in a pressurised, elastic, compressible Roelands state.
    fn pressurised(n: usize) -> (Level, Problem) {
        let mut level = Level::new(
            n,
            n,
            (-4.5, 1.5, 3.0),
            1.0,
            2.0 / (std::f64::consts::PI.powi(2)),
        )
        .unwrap();
        let prob = Problem {
            lambda: 0.5,
            rheology: Rheology::new(ViscosityLaw::Roelands, true, 5e8, 2e-8, 0.04),
            transverse_curvature: 1.0,
            transverse_flow: 1.0,
            elastic: true,
        };
        for j in 1..n - 1 {
            for i in 1..n - 1 {
                let (x, y) = (level.x[i], level.y[j]);
                level.p[j * n + i] = (1.2 - 0.3 * x * x - 0.2 * y * y).max(0.0) + 0.01 * i as f64;
            }
        }
        level.h0 = 0.5;
        level.evaluate(&prob);
        (level, prob)
    }

    /// With the full window the assembled Jacobian equals the finite-difference derivative of
    /// the residual.
    #[test]
    fn jacobian_matches_finite_differences() {
        let n = 9;
        let (mut level, prob) = pressurised(n);
        level.newton_correction(&prob, 1.0, 1e-10).unwrap();
        let r0 = level.residual.clone();
        let ix = n - 2;
        let mut worst: f64 = 0.0;
        for col in [0usize, 5, 20, 24, 40] {
            let k = level.node_of(col);
            let h = 1e-7;
            level.p[k] += h;
            level.evaluate(&prob);
            for row in 0..ix * ix {
                let m = level.node_of(row);
                let fd = (level.residual[m] - r0[m]) / h;
                let (ri, rj) = ((row % ix) as isize, (row / ix) as isize);
                let (ci, cj) = ((col % ix) as isize, (col / ix) as isize);
                let s = level
                    .window
                    .iter()
                    .position(|&o| o == (ci - ri, cj - rj))
                    .unwrap();
                let pos = level.slot[row * level.window.len() + s];
                let jv = level.values[pos];
                if (fd - jv).abs() > 1e-4 * (1.0 + fd.abs()) {
                    println!("row {row} col {col}: fd {fd} J {jv}");
                }
                worst = worst.max((fd - jv).abs() / (1.0 + fd.abs()));
            }
            level.p[k] -= h;
        }
        assert!(worst < 1e-4, "{worst}");
    }

    /// On a grid whose preconditioner keeps only the near window, the GMRES correction of P
    /// and H₀ solves the full linearised equations: a small step t along it changes every free
    /// node's residual by −t·R and the load by t·(target − load), to finite-difference accuracy
    /// (checked against the residual itself, not the matrix-free product it was solved with).
    #[test]
    fn newton_correction_solves_the_linearised_equations() {
        let n = 33;
        let (mut level, prob) = pressurised(n);
        assert!(n > EXACT_JACOBIAN_NODES && level.window.len() < n * n);
        let target = 1.1 * level.load();
        let iterations = level.newton_correction(&prob, target, 1e-10).unwrap();
        let (r0, load0) = (level.residual.clone(), level.load());
        let unknowns = level.active.len();
        let t = 1e-6;
        for u in 0..unknowns {
            let m = level.node_of(u);
            level.p[m] += t * level.correction[u];
        }
        level.h0 += t * level.correction[unknowns];
        level.evaluate(&prob);
        let scale = r0.iter().map(|r| r.abs()).fold(0.0, f64::max);
        let (mut worst, mut free) = (0.0f64, 0);
        for u in (0..unknowns).filter(|&u| !level.active[u]) {
            let m = level.node_of(u);
            let predicted = -t * r0[m];
            worst = worst.max((level.residual[m] - r0[m] - predicted).abs() / (t * scale));
            free += 1;
        }
        let load_change = (level.load() - load0) / (t * (target - load0));
        println!(
            "GMRES {iterations} iterations; {free} free rows, worst {worst:e}; load {load_change}"
        );
        assert!(iterations > 1 && free > unknowns / 2);
        assert!(worst < 1e-4, "{worst}");
        assert!((load_change - 1.0).abs() < 1e-6, "{load_change}");
    }
}
