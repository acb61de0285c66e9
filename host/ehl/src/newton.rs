//! The Newton solver: Reynolds + film + load balance on (P, H₀), with the cavitation
//! complementarity handled by a primal–dual active set.
//!
//! Discretisation (finite volume on the non-uniform grid of [`super::grid`]): for each interior
//! node i the mass balance of its cell is
//!
//!   R_i = ε_{i+½}(P_{i+1}−P_i)/ΔX₊ − ε_{i−½}(P_i−P_{i−1})/ΔX₋ − (Φ_{i+½} − Φ_{i−½}) = 0,
//!
//! with ε = ρ̄H³/(η̄λ̄) averaged arithmetically on faces and the Couette flux Φ = ρ̄H taken
//! second-order upwind (linear extrapolation from the two upstream nodes; first order at the
//! first face). Upwinding is what keeps the scheme stable when ε → 0 in the contact, where
//! the equation degenerates to ρ̄H = const (Venner & Lubrecht, *Multilevel Methods in
//! Lubrication*, 2000, ch. 5); second order keeps the O(ΔX²) accuracy of the Poiseuille term.
//!
//! Cavitation (Reynolds condition) is the complementarity P ≥ 0, R ≤ 0, P·R = 0: where the gap
//! diverges with P = 0 the cell would lose mass (R < 0) and the pressure stays pinned at zero.
//! It is written as the NCP equation φ_i = min(P_i, −σ_i R_i) = 0 with a per-node scale σ_i
//! (see `update_sigma`) and solved by semismooth Newton: each iteration the rows with
//! P_i ≤ −σ_i R_i become ΔP_i = −P_i (the active set), the others the linearised Reynolds
//! equation — the primal–dual active-set method. The exit point moves freely; it moves by about
//! one node per iteration, which is why the driver does that work on a coarse grid first.
//! (A Fischer–Burmeister variant is kept behind `fischer`; it was not better.)
//!
//! Jacobian: R_i depends on P_{i−2..i+1} directly (ε(P), ρ̄(P)) and on H_{i−2..i+1}, and every
//! H_k depends on all P through the deflection matrix, so J = A + B·(−K/π) with banded A, B —
//! dense, assembled in O(4N²) and factorised by LU with partial pivoting (faer). Rows are
//! equilibrated before factorisation. Because the unknown is P itself and η̄ enters only through
//! ε = ρ̄H³·exp(−ln η̄)/λ̄, η̄ spanning 20 decades (or 100 with Barus) just makes ε underflow to 0
//! in the contact; no row is ever multiplied by η̄. A unit test checks J against finite
//! differences.
//!
//! Globalisation: Deuflhard's restricted natural monotonicity test (affine invariant, hence
//! blind to the row scaling): a damping factor α is accepted when the simplified correction
//! Δ̄ = −J⁻¹F(z + αΔ) satisfies ‖Δ̄‖ ≤ (1 − α/4)‖Δ‖, otherwise α shrinks by the fixed factor
//! 0.7 (Deuflhard's predicted μ underestimates across the cavitation kink, see
//! `DAMPING_SHRINK`); trials with H ≤ 0 are rejected. When a full step contracts well
//! (‖Δ̄‖ ≤ ‖Δ‖/4) and the active set stays, the next step is that Δ̄ itself (chord step: the LU
//! is reused, O(N²) instead of O(N³)).
//!
//! All work vectors, the Jacobian and the LU scratch are allocated once per [`NewtonWorkspace`];
//! the iteration loop does not allocate.

use super::grid::{build_nodes, trapezoid_weights, GridSpec};
use super::kernel::{kernel_matrix, kernel_row};
use super::rheology::Rheology;
use faer::dyn_stack::MemBuffer;
use faer::linalg::lu::partial_pivoting::{factor, solve};
use faer::{Mat, Par};
use std::f64::consts::{FRAC_1_PI, FRAC_PI_2};

mod jacobian;

/// Factor by which a rejected damping trial shrinks α (see `run`): 0.5 → 0.7 → 0.8 cut the LU
/// factorisations over the bench's 100 LHS samples from 1820 → 1505 → 1422 (Deuflhard's
/// μ-prediction: 3070); 0.7 keeps the number of trials to reach α = 10⁻⁴ at 26.
const DAMPING_SHRINK: f64 = 0.7;

/// Dot product with eight independent partial sums, so the compiler can vectorise it (a plain
/// sequential sum cannot be reordered); this is the O(N²) deflection product of every trial.
#[inline]
fn dot(a: &[f64], b: &[f64]) -> f64 {
    let mut acc = [0.0f64; 8];
    let chunks = a.len() / 8;
    for c in 0..chunks {
        let (x, y) = (&a[c * 8..c * 8 + 8], &b[c * 8..c * 8 + 8]);
        for l in 0..8 {
            acc[l] += x[l] * y[l];
        }
    }
    let mut tail = 0.0;
    for k in chunks * 8..a.len().min(b.len()) {
        tail += a[k] * b[k];
    }
    acc.iter().sum::<f64>() + tail
}

/// Per-case constants of the dimensionless problem.
#[derive(Debug, Clone, Copy)]
pub struct Problem {
    /// λ̄ of docs/physics.md §5.2.
    pub lambda_bar: f64,
    /// Rheology in the Hertz pressure scale.
    pub rheology: Rheology,
    /// Whether the elastic deflection is included (false only for rigid limit studies).
    pub elastic: bool,
}

/// Convergence limits (docs/physics.md §5.2: ΣΔP/ΣP ≤ 1e−5, load error ≤ 1e−3).
#[derive(Debug, Clone, Copy)]
pub struct Limits {
    pub max_iterations: usize,
    pub pressure_tolerance: f64,
    pub load_tolerance: f64,
}

/// Outcome of one Newton run (converged or not).
#[derive(Debug, Clone, Copy)]
pub struct NewtonReport {
    pub converged: bool,
    pub iterations: usize,
    /// Last relative pressure change Σ|ΔP|/ΣP.
    pub pressure_change: f64,
    /// |∫P dX − π/2| / (π/2).
    pub load_error: f64,
    /// RMS of the scaled Reynolds/complementarity residual.
    pub reynolds_residual: f64,
    pub reason: &'static str,
}

/// Grid, kernel and all work storage for one grid size.
pub struct NewtonWorkspace {
    pub nodes: Vec<f64>,
    /// Unscaled grid, weights, deflection matrix and centre row (domain scale 1).
    base_nodes: Vec<f64>,
    base_weights: Vec<f64>,
    base_kernel: Vec<f64>,
    base_kernel_center: Vec<f64>,
    /// Current domain stretch factor s (nodes = s · base nodes).
    domain_scale: f64,
    weights: Vec<f64>,
    /// Deflection matrix K/π (row-major).
    kernel: Vec<f64>,
    /// Deflection row at X = 0, divided by π.
    kernel_center: Vec<f64>,
    /// Second-order upwind factors (ΔX₊/2)/ΔX₋ per node (0 at node 0).
    beta: Vec<f64>,
    pub p: Vec<f64>,
    pub h: Vec<f64>,
    pub h0: f64,
    p_trial: Vec<f64>,
    h_trial: Vec<f64>,
    h0_trial: f64,
    rho: Vec<f64>,
    drho: Vec<f64>,
    eps: Vec<f64>,
    deps_dp: Vec<f64>,
    deps_dh: Vec<f64>,
    resid: Vec<f64>,
    active: Vec<bool>,
    /// Complementarity scaling σ_i (pressure units per flux imbalance), frozen per iteration.
    sigma: Vec<f64>,
    jt: Mat<f64>,
    rhs: Mat<f64>,
    /// Simplified Newton correction of a trial point (same LU).
    rhs2: Mat<f64>,
    /// Newton step Δ of the current iteration.
    step: Vec<f64>,
    /// Row equilibration factors of the current Jacobian.
    row_scale: Vec<f64>,
    perm: Vec<usize>,
    perm_inv: Vec<usize>,
    stack: MemBuffer,
    /// Residual scale 1/H_ref of the Reynolds rows.
    scale: f64,
    /// Use the Fischer–Burmeister NCP function instead of the min-function active set (kept as
    /// an option: on the LHS population it converged no more often and took ~3× the iterations).
    pub fischer: bool,
}

impl NewtonWorkspace {
    /// Builds grid, deflection matrix and storage for `spec`.
    pub fn new(spec: &GridSpec) -> Self {
        let nodes = build_nodes(spec);
        let n = nodes.len();
        let mut kernel = kernel_matrix(&nodes);
        kernel.iter_mut().for_each(|k| *k *= FRAC_1_PI);
        let mut kernel_center = vec![0.0; n];
        kernel_row(&nodes, 0.0, &mut kernel_center);
        kernel_center.iter_mut().for_each(|k| *k *= FRAC_1_PI);
        let mut beta = vec![0.0; n];
        for i in 1..n - 1 {
            beta[i] = 0.5 * (nodes[i + 1] - nodes[i]) / (nodes[i] - nodes[i - 1]);
        }
        let unknowns = n - 1;
        let req = factor::lu_in_place_scratch::<usize, f64>(
            unknowns,
            unknowns,
            Par::Seq,
            Default::default(),
        )
        .or(solve::solve_transpose_in_place_scratch::<usize, f64>(
            unknowns,
            1,
            Par::Seq,
        ));
        let weights = trapezoid_weights(&nodes);
        Self {
            base_nodes: nodes.clone(),
            base_weights: weights.clone(),
            base_kernel: kernel.clone(),
            base_kernel_center: kernel_center.clone(),
            domain_scale: 1.0,
            weights,
            kernel,
            kernel_center,
            beta,
            p: vec![0.0; n],
            h: vec![0.0; n],
            h0: 0.0,
            p_trial: vec![0.0; n],
            h_trial: vec![0.0; n],
            h0_trial: 0.0,
            rho: vec![1.0; n],
            drho: vec![0.0; n],
            eps: vec![0.0; n],
            deps_dp: vec![0.0; n],
            deps_dh: vec![0.0; n],
            resid: vec![0.0; n],
            active: vec![false; n],
            sigma: vec![0.0; n],
            jt: Mat::zeros(unknowns, unknowns),
            rhs: Mat::zeros(unknowns, 1),
            rhs2: Mat::zeros(unknowns, 1),
            step: vec![0.0; unknowns],
            row_scale: vec![1.0; unknowns],
            perm: vec![0; unknowns],
            perm_inv: vec![0; unknowns],
            stack: MemBuffer::new(req),
            scale: 1.0,
            fischer: false,
            nodes,
        }
    }

    /// Stretches the domain by `s` ≥ 1 (X_i = s·X_i,base). The log kernel scales exactly:
    /// ∫φ_j(X'/s) ln|sX − X'| dX' = s·K_ij + s ln s ∫φ_j, so the stretched deflection matrix is
    /// an O(N²) update of the stored one — no re-integration.
    pub fn set_domain_scale(&mut self, s: f64) {
        if s == self.domain_scale {
            return;
        }
        let n = self.base_nodes.len();
        let shift = s * s.ln() * FRAC_1_PI;
        for (x, b) in self.nodes.iter_mut().zip(&self.base_nodes) {
            *x = s * b;
        }
        for (w, b) in self.weights.iter_mut().zip(&self.base_weights) {
            *w = s * b;
        }
        for (row, base) in self.kernel.chunks_mut(n).zip(self.base_kernel.chunks(n)) {
            for j in 0..n {
                row[j] = s * base[j] + shift * self.base_weights[j];
            }
        }
        for j in 0..n {
            self.kernel_center[j] = s * self.base_kernel_center[j] + shift * self.base_weights[j];
        }
        self.domain_scale = s;
    }

    /// Number of grid nodes.
    pub fn len(&self) -> usize {
        self.nodes.len()
    }

    /// Always false (a grid has at least two nodes); for clippy's `len_without_is_empty`.
    pub fn is_empty(&self) -> bool {
        self.nodes.is_empty()
    }

    /// Film H at every node for pressure `p` and separation `h0`.
    fn film_into(&self, elastic: bool, p: &[f64], h0: f64, out: &mut [f64]) {
        let n = self.nodes.len();
        for (i, o) in out.iter_mut().enumerate() {
            let x = self.nodes[i];
            let mut defl = 0.0;
            if elastic {
                let row = &self.kernel[i * n..(i + 1) * n];
                defl = dot(row, p);
            }
            *o = h0 + 0.5 * x * x - defl;
        }
    }

    /// Film at X = 0 for the current state.
    pub fn central_film(&self, elastic: bool) -> f64 {
        let defl = if elastic {
            self.kernel_center
                .iter()
                .zip(&self.p)
                .map(|(k, p)| k * p)
                .sum()
        } else {
            0.0
        };
        self.h0 - defl
    }

    /// ∫P dX (trapezoid, exact for the piecewise-linear pressure).
    pub fn load_integral(&self, p: &[f64]) -> f64 {
        self.weights.iter().zip(p).map(|(w, p)| w * p).sum()
    }

    /// Sets the start: Hertz pressure √(1−X²) and H₀ such that H(0) = `central_guess`.
    pub fn start_hertz(&mut self, elastic: bool, central_guess: f64) {
        for (p, x) in self.p.iter_mut().zip(&self.nodes) {
            *p = (1.0 - x * x).max(0.0).sqrt();
        }
        let n = self.p.len();
        self.p[0] = 0.0;
        self.p[n - 1] = 0.0;
        // Normalise the discrete load so the start satisfies the load row.
        let ratio = FRAC_PI_2 / self.load_integral(&self.p);
        self.p.iter_mut().for_each(|p| *p *= ratio);
        self.h0 = 0.0;
        let c0 = self.central_film(elastic);
        self.h0 = central_guess - c0;
    }

    /// Sets the start by linear interpolation of a previous solution (`x`, `p`) and its H₀.
    pub fn start_from(&mut self, x: &[f64], p: &[f64], h0: f64) {
        let mut k = 0;
        for (pi, xi) in self.p.iter_mut().zip(&self.nodes) {
            while k + 2 < x.len() && x[k + 1] < *xi {
                k += 1;
            }
            let t = ((xi - x[k]) / (x[k + 1] - x[k])).clamp(0.0, 1.0);
            *pi = (p[k] + t * (p[k + 1] - p[k])).max(0.0);
        }
        let n = self.p.len();
        self.p[0] = 0.0;
        self.p[n - 1] = 0.0;
        self.h0 = h0;
    }

    /// Node properties (ρ̄, ε and derivatives) for pressure `p` and film `h`.
    fn properties(&mut self, prob: &Problem, use_trial: bool) {
        let (p, h) = if use_trial {
            (&self.p_trial, &self.h_trial)
        } else {
            (&self.p, &self.h)
        };
        for k in 0..p.len() {
            let (ln_eta, dln_eta) = prob.rheology.ln_viscosity(p[k]);
            let (rho, drho) = prob.rheology.density(p[k]);
            let hk = h[k].max(1e-300);
            let eps = rho * hk * hk * hk * (-ln_eta).exp() / prob.lambda_bar;
            self.rho[k] = rho;
            self.drho[k] = drho;
            self.eps[k] = eps;
            self.deps_dp[k] = eps * (drho / rho - dln_eta);
            self.deps_dh[k] = 3.0 * eps / hk;
        }
    }

    /// Reynolds residual R_i at interior nodes (uses current properties).
    fn residuals(&mut self, use_trial: bool) {
        let (p, h) = if use_trial {
            (&self.p_trial, &self.h_trial)
        } else {
            (&self.p, &self.h)
        };
        let x = &self.nodes;
        let n = x.len();
        let face_flux = |k: usize| -> f64 {
            let qk = self.rho[k] * h[k];
            if k == 0 {
                qk
            } else {
                qk + self.beta[k] * (qk - self.rho[k - 1] * h[k - 1])
            }
        };
        let mut phi_left = face_flux(0);
        for i in 1..n - 1 {
            let dp = x[i + 1] - x[i];
            let dm = x[i] - x[i - 1];
            let er = 0.5 * (self.eps[i] + self.eps[i + 1]);
            let el = 0.5 * (self.eps[i - 1] + self.eps[i]);
            let pois = er * (p[i + 1] - p[i]) / dp - el * (p[i] - p[i - 1]) / dm;
            let phi_right = face_flux(i);
            self.resid[i] = pois - (phi_right - phi_left);
            phi_left = phi_right;
        }
    }

    /// Merit ‖φ‖² of the state whose residuals were just computed, with the NCP function
    /// φ_i = min(P_i, −σ_i R_i) (zero iff P_i ≥ 0, R_i ≤ 0, P_i R_i = 0) and the load row.
    fn merit(&self, p: &[f64], load_error: f64) -> f64 {
        let n = p.len();
        let mut m = 0.0;
        for (i, &pi) in p.iter().enumerate().take(n - 1).skip(1) {
            let phi = self.ncp(pi, i);
            m += phi * phi;
        }
        m + load_error * load_error
    }

    /// NCP value of node i: min(a, b) or Fischer–Burmeister a + b − √(a² + b²), with a = P_i and
    /// b = −σ_i R_i.
    #[inline]
    fn ncp(&self, p: f64, i: usize) -> f64 {
        let a = p;
        let b = -self.sigma[i] * self.resid[i];
        if self.fischer {
            a + b - a.hypot(b)
        } else {
            a.min(b)
        }
    }

    /// σ_i = 1/(ε_{i+½}/ΔX₊ + ε_{i−½}/ΔX₋ + ρ̄_i H_i): turns a cell's flux imbalance into a
    /// pressure-like quantity (the Jacobi-predicted pressure change where Poiseuille flow
    /// dominates, the relative mass imbalance where Couette flow dominates), so the min-function
    /// compares like with like and can never pin a loaded contact node.
    fn update_sigma(&mut self) {
        let x = &self.nodes;
        for i in 1..x.len() - 1 {
            let er = 0.5 * (self.eps[i] + self.eps[i + 1]);
            let el = 0.5 * (self.eps[i - 1] + self.eps[i]);
            let d = er / (x[i + 1] - x[i]) + el / (x[i] - x[i - 1]) + self.rho[i] * self.h[i];
            self.sigma[i] = 1.0 / d;
        }
    }

    /// Evaluates film, properties and residuals of the trial state; returns its merit or None
    /// when the trial film is not positive everywhere.
    fn evaluate_trial(&mut self, prob: &Problem) -> Option<f64> {
        let mut h = std::mem::take(&mut self.h_trial);
        self.film_into(prob.elastic, &self.p_trial, self.h0_trial, &mut h);
        self.h_trial = h;
        if self.h_trial.iter().any(|&v| v <= 0.0 || !v.is_finite()) {
            return None;
        }
        self.properties(prob, true);
        self.residuals(true);
        let load = self.load_integral(&self.p_trial) - FRAC_PI_2;
        let m = self.merit(&self.p_trial, load / FRAC_PI_2);
        m.is_finite().then_some(m)
    }
}

impl NewtonWorkspace {
    /// Runs the damped active-set Newton iteration from the current (P, H₀).
    pub fn run(&mut self, prob: &Problem, limits: &Limits) -> NewtonReport {
        let n = self.nodes.len();
        let unknowns = n - 1;
        // Residual scale: 1/H at X = 0 of the start (rows are flux imbalances ~ ρ̄H).
        self.scale = 1.0 / self.central_film(prob.elastic).abs().max(1e-12);
        let mut h = std::mem::take(&mut self.h);
        self.film_into(prob.elastic, &self.p, self.h0, &mut h);
        self.h = h;
        if self.h.iter().any(|&v| v <= 0.0 || !v.is_finite()) {
            return self.report(false, 0, f64::NAN, f64::NAN, "start film not positive");
        }
        self.properties(prob, false);
        self.residuals(false);
        let mut load_err = (self.load_integral(&self.p) - FRAC_PI_2) / FRAC_PI_2;
        let mut merit;
        let mut pressure_change = f64::INFINITY;
        let mut stalls = 0usize;
        // Chord reuse: when the last step was a full step with good contraction and the active
        // set is unchanged, the simplified correction Δ̄ already computed for the accepted point
        // is the next step (J factorised once, back-substitution only: O(N²) instead of O(N³)).
        let mut reuse = false;
        for iter in 1..=limits.max_iterations {
            // Active set of the min-function: rows where φ_i = P_i.
            self.update_sigma();
            let mut set_changed = false;
            for i in 1..n - 1 {
                let a = !self.fischer && self.p[i] <= -self.sigma[i] * self.resid[i];
                set_changed |= a != self.active[i];
                self.active[i] = a;
            }
            if reuse && !set_changed {
                for r in 0..unknowns {
                    self.rhs[(r, 0)] = self.rhs2[(r, 0)];
                }
            } else if !self.assemble_and_solve(prob) {
                return self.report(false, iter, pressure_change, load_err, "singular Jacobian");
            }
            // Damping by Deuflhard's restricted natural monotonicity test (affine invariant, so
            // indifferent to the 20-decade spread of ε): accept α when the simplified correction
            // Δ̄ = −J⁻¹F(z + αΔ) satisfies ‖Δ̄‖ ≤ (1 − α/4)‖Δ‖ (Deuflhard, *Newton Methods for
            // Nonlinear Problems*, 2004, §3.3, NLEQ-ERR); otherwise shrink α.
            for r in 0..unknowns {
                self.step[r] = self.rhs[(r, 0)];
            }
            let step_norm = self.step_norm(|r| self.step[r]);
            let mut alpha: f64 = 1.0;
            let mut accepted = false;
            for _ in 0..40 {
                for i in 1..n - 1 {
                    self.p_trial[i] = self.p[i] + alpha * self.step[i - 1];
                }
                self.p_trial[0] = 0.0;
                self.p_trial[n - 1] = 0.0;
                self.h0_trial = self.h0 + alpha * self.step[unknowns - 1];
                if self.evaluate_trial(prob).is_none() {
                    alpha *= 0.5;
                    if alpha < 1e-4 {
                        break;
                    }
                    continue;
                }
                self.simplified_correction();
                let bar_norm = self.step_norm(|r| self.rhs2[(r, 0)]);
                if bar_norm <= (1.0 - 0.25 * alpha) * step_norm || bar_norm < 1e-12 {
                    accepted = true;
                    reuse = alpha == 1.0 && bar_norm <= 0.25 * step_norm;
                    break;
                }
                // Rejected: shrink by a fixed factor. (Deuflhard's prediction
                // μ = ½α²‖Δ‖/‖Δ̄ − (1−α)Δ‖ was used before; across the cavitation kink it
                // underestimates badly, so α fell to its 0.1α floor where a much larger step
                // would have passed, and the creeping iterations doubled the number of LU
                // factorisations over the LHS population. Trials cost O(N²), an LU O(N³).)
                alpha *= DAMPING_SHRINK;
                if alpha < 1e-4 {
                    break;
                }
            }
            if !accepted {
                reuse = false;
                stalls += 1;
                if stalls > 3 || self.evaluate_trial(prob).is_none() {
                    return self.report(false, iter, pressure_change, load_err, "damping failed");
                }
            } else {
                stalls = 0;
            }
            let new_merit = self.merit(
                &self.p_trial,
                (self.load_integral(&self.p_trial) - FRAC_PI_2) / FRAC_PI_2,
            );
            let mut dsum = 0.0;
            let mut psum = 0.0;
            for i in 0..n {
                dsum += (self.p_trial[i] - self.p[i]).abs();
                psum += self.p_trial[i];
            }
            pressure_change = dsum / psum.max(1e-300);
            std::mem::swap(&mut self.p, &mut self.p_trial);
            std::mem::swap(&mut self.h, &mut self.h_trial);
            self.h0 = self.h0_trial;
            merit = new_merit;
            load_err = (self.load_integral(&self.p) - FRAC_PI_2) / FRAC_PI_2;
            // Properties/residuals of the accepted state are those of the trial just swapped in;
            // the residual vector was computed for it already.
            if alpha == 1.0
                && !set_changed
                && pressure_change <= limits.pressure_tolerance
                && load_err.abs() <= limits.load_tolerance
            {
                return self.report(true, iter, pressure_change, load_err, "converged");
            }
        }
        let _ = merit;
        self.report(
            false,
            limits.max_iterations,
            pressure_change,
            load_err,
            "iteration limit",
        )
    }

    fn report(
        &self,
        converged: bool,
        iterations: usize,
        pressure_change: f64,
        load_error: f64,
        reason: &'static str,
    ) -> NewtonReport {
        let n = self.nodes.len();
        let m = self.merit(&self.p, 0.0);
        NewtonReport {
            converged,
            iterations,
            pressure_change,
            load_error: load_error.abs(),
            reynolds_residual: (m / (n - 2) as f64).sqrt(),
            reason,
        }
    }
}
