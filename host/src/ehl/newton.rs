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
//! Each Newton iteration freezes the active set {i : P_i = 0 and R_i ≤ 0} (their rows become
//! ΔP_i = 0), solves the full Jacobian for the rest, and projects P ≥ 0 — the primal–dual
//! active-set (semismooth Newton with the min-function, c → 0⁺) method. The exit point thus moves
//! freely by any number of nodes per iteration.
//!
//! Jacobian: R_i depends on P_{i−2..i+1} directly (ε(P), ρ̄(P)) and on H_{i−2..i+1}, and every
//! H_k depends on all P through the deflection matrix, so J = A + B·(−K/π) with banded A, B —
//! dense, assembled in O(4N²) and factorised by LU with partial pivoting (faer). Rows are
//! equilibrated before factorisation. Because the unknown is P itself and η̄ enters only through
//! ε = ρ̄H³·exp(−ln η̄)/λ̄, η̄ spanning 20 decades (or 100 with Barus) just makes ε underflow to 0
//! in the contact; no row is ever multiplied by η̄.
//!
//! Globalisation: backtracking on the merit ‖F‖² (scaled Reynolds residual of free nodes, the
//! positive part of R on pinned nodes, and the load row), rejecting any trial with H ≤ 0.
//! Start: Hertz pressure and H₀ from Moes' formula. If the direct start fails, the caller
//! ([`super::Solver`]) continues in speed from a thicker-film case.
//!
//! All work vectors, the Jacobian and the LU scratch are allocated once per [`NewtonWorkspace`];
//! the iteration loop does not allocate.

use super::grid::{build_nodes, trapezoid_weights, GridSpec};
use super::kernel::{kernel_matrix, kernel_row};
use super::rheology::Rheology;
use faer::dyn_stack::{MemBuffer, MemStack};
use faer::linalg::lu::partial_pivoting::{factor, solve};
use faer::{Mat, Par};
use std::f64::consts::{FRAC_1_PI, FRAC_PI_2};

/// Per-case constants of the dimensionless problem.
#[derive(Debug, Clone, Copy)]
pub struct Problem {
    /// λ̄ of PHYSICS.md §5.2.
    pub lambda_bar: f64,
    /// Rheology in the Hertz pressure scale.
    pub rheology: Rheology,
    /// Whether the elastic deflection is included (false only for rigid limit studies).
    pub elastic: bool,
}

/// Convergence limits (PHYSICS.md §5.2: ΣΔP/ΣP ≤ 1e−5, load error ≤ 1e−3).
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
        Self {
            weights: trapezoid_weights(&nodes),
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
            nodes,
        }
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
                defl = row.iter().zip(p).map(|(k, p)| k * p).sum::<f64>();
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
        for i in 1..n - 1 {
            let phi = p[i].min(-self.sigma[i] * self.resid[i]);
            m += phi * phi;
        }
        m + load_error * load_error
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
        let mut merit = self.merit(&self.p, load_err);
        let mut pressure_change = f64::INFINITY;
        let mut stalls = 0usize;
        for iter in 1..=limits.max_iterations {
            // Active set of the min-function: rows where φ_i = P_i.
            self.update_sigma();
            merit = self.merit(&self.p, load_err);
            let mut set_changed = false;
            for i in 1..n - 1 {
                let a = self.p[i] <= -self.sigma[i] * self.resid[i];
                set_changed |= a != self.active[i];
                self.active[i] = a;
            }
            if !self.assemble_and_solve(prob) {
                return self.report(false, iter, pressure_change, load_err, "singular Jacobian");
            }
            // Damping by Deuflhard's restricted natural monotonicity test (affine invariant, so
            // indifferent to the 20-decade spread of ε): accept α when the simplified correction
            // Δ̄ = −J⁻¹F(z + αΔ) satisfies ‖Δ̄‖ ≤ (1 − α/4)‖Δ‖; otherwise shrink α to the
            // predicted μ = ½α²‖Δ‖/‖Δ̄ − (1−α)Δ‖ (Deuflhard, *Newton Methods for Nonlinear
            // Problems*, 2004, §3.3, NLEQ-ERR).
            for r in 0..unknowns {
                self.step[r] = self.rhs[(r, 0)];
            }
            let step_norm = self.step_norm(|r| self.step[r]);
            let mut alpha: f64 = 1.0;
            let mut accepted = false;
            for _ in 0..20 {
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
                if std::env::var_os("EHL_TRACE2").is_some() {
                    let (mut im, mut vm) = (0, 0.0f64);
                    let (mut jm, mut wm) = (0, 0.0f64);
                    for r in 0..unknowns - 1 {
                        if self.step[r].abs() > vm {
                            vm = self.step[r].abs();
                            im = r;
                        }
                        if self.rhs2[(r, 0)].abs() > wm {
                            wm = self.rhs2[(r, 0)].abs();
                            jm = r;
                        }
                    }
                    eprintln!("  a={alpha:.3e} |d|={step_norm:.3e} |bar|={bar_norm:.3e} maxd {vm:.3e} at X={:.3} (P={:.3}) maxbar {wm:.3e} at X={:.3} dH0={:.3e}", self.nodes[im+1], self.p[im+1], self.nodes[jm+1], self.step[unknowns-1]);
                }
                if bar_norm <= (1.0 - 0.25 * alpha) * step_norm || bar_norm < 1e-12 {
                    accepted = true;
                    break;
                }
                let dev = self.step_norm(|r| self.rhs2[(r, 0)] - (1.0 - alpha) * self.step[r]);
                let mu = 0.5 * alpha * alpha * step_norm / dev.max(1e-300);
                alpha = mu.min(0.5 * alpha).max(0.1 * alpha);
                if alpha < 1e-4 {
                    break;
                }
            }
            if !accepted {
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
            if std::env::var_os("EHL_TRACE").is_some() {
                let nact = self.active.iter().filter(|a| **a).count();
                eprintln!("it {iter} alpha {alpha} merit {merit:.3e} dP {pressure_change:.3e} active {nact} changed {set_changed} h0 {:.5}", self.h0);
            }
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

    /// Assembles, factorises and solves J Δ = −F in place (Δ left in `rhs`). Returns false if
    /// the step is not finite.
    fn assemble_and_solve(&mut self, prob: &Problem) -> bool {
        self.assemble(prob, true);
        let unknowns = self.nodes.len() - 1;
        let mut stack = MemStack::new(&mut self.stack);
        let (_, perm) = factor::lu_in_place(
            self.jt.as_mut(),
            &mut self.perm,
            &mut self.perm_inv,
            Par::Seq,
            &mut stack,
            Default::default(),
        );
        solve::solve_transpose_in_place(
            self.jt.as_ref(),
            self.jt.as_ref(),
            perm,
            self.rhs.as_mut(),
            Par::Seq,
            &mut stack,
        );
        (0..unknowns).all(|r| self.rhs[(r, 0)].is_finite())
    }

    /// Assembles J transposed (column r = row r of J) and −F in `rhs`; with `equilibrate` each
    /// row is divided by its largest entry.
    fn assemble(&mut self, prob: &Problem, equilibrate: bool) {
        let n = self.nodes.len();
        let unknowns = n - 1;
        let last = unknowns - 1;
        for i in 1..n - 1 {
            let r = i - 1;
            let col = self.jt.col_as_slice_mut(r);
            col.iter_mut().for_each(|v| *v = 0.0);
            if self.active[i] {
                col[r] = 1.0;
                self.rhs[(r, 0)] = -self.p[i];
                self.row_scale[r] = 1.0;
                continue;
            }
            let x = &self.nodes;
            let (p, h) = (&self.p, &self.h);
            let dp = x[i + 1] - x[i];
            let dm = x[i] - x[i - 1];
            let gp = (p[i + 1] - p[i]) / dp;
            let gm = (p[i] - p[i - 1]) / dm;
            let er = 0.5 * (self.eps[i] + self.eps[i + 1]);
            let el = 0.5 * (self.eps[i - 1] + self.eps[i]);
            let bi = self.beta[i];
            let bim = self.beta[i - 1];
            // Couette derivative coefficients ∂R/∂q_k for k = i, i−1, i−2.
            let cq = [-(1.0 + bi), bi + 1.0 + bim, -bim];
            // d R / d (direct P) and d R / d H for k = i+1, i, i−1, i−2.
            let mut dpk = [0.0f64; 4];
            let mut dhk = [0.0f64; 4];
            dpk[0] = er / dp + 0.5 * self.deps_dp[i + 1] * gp;
            dhk[0] = 0.5 * self.deps_dh[i + 1] * gp;
            dpk[1] = -er / dp - el / dm + 0.5 * self.deps_dp[i] * (gp - gm);
            dhk[1] = 0.5 * self.deps_dh[i] * (gp - gm);
            dpk[2] = el / dm - 0.5 * self.deps_dp[i - 1] * gm;
            dhk[2] = -0.5 * self.deps_dh[i - 1] * gm;
            for (j, c) in cq.iter().enumerate() {
                if j > i {
                    break;
                }
                let k = i - j;
                dpk[j + 1] += c * self.drho[k] * h[k];
                dhk[j + 1] += c * self.rho[k];
            }
            // Elastic coupling: Σ_k dR/dH_k · (−K_km/π) for all interior m, and ∂/∂H₀.
            let mut dh0 = 0.0;
            for (j, g) in dhk.iter().enumerate() {
                if j > i + 1 || *g == 0.0 {
                    continue;
                }
                let k = i + 1 - j;
                dh0 += g;
                if prob.elastic {
                    let krow = &self.kernel[k * n + 1..k * n + n - 1];
                    for (c, kv) in col[..last].iter_mut().zip(krow) {
                        *c -= g * kv;
                    }
                }
            }
            col[last] = dh0;
            for (j, d) in dpk.iter().enumerate() {
                if j > i + 1 {
                    continue;
                }
                let m = i + 1 - j;
                if m >= 1 && m <= n - 2 {
                    col[m - 1] += d;
                }
            }
            let big = col.iter().fold(0.0f64, |a, v| a.max(v.abs()));
            let s = if big > 0.0 && equilibrate {
                1.0 / big
            } else {
                1.0
            };
            col.iter_mut().for_each(|v| *v *= s);
            self.rhs[(r, 0)] = -self.resid[i] * s;
            self.row_scale[r] = s;
        }
        // Load row.
        {
            let col = self.jt.col_as_slice_mut(last);
            let wmax = if equilibrate {
                self.weights.iter().fold(0.0f64, |a, w| a.max(*w))
            } else {
                1.0
            };
            for m in 1..n - 1 {
                col[m - 1] = self.weights[m] / wmax;
            }
            col[last] = 0.0;
            self.rhs[(last, 0)] = -(self.load_integral(&self.p) - FRAC_PI_2) / wmax;
            self.row_scale[last] = 1.0 / wmax;
        }
    }

    /// Weighted norm of an unknown-space vector (P entries as they are, H₀ relative to the
    /// central film scale).
    fn step_norm(&self, v: impl Fn(usize) -> f64) -> f64 {
        let unknowns = self.nodes.len() - 1;
        let mut acc = 0.0;
        for r in 0..unknowns - 1 {
            acc += v(r) * v(r);
        }
        let h = v(unknowns - 1) * self.scale;
        (acc + h * h).sqrt()
    }

    /// Simplified Newton correction Δ̄ = −J⁻¹F(trial) with the current LU and the same row
    /// types and scales as J (trial residuals must be evaluated); left in `rhs2`.
    fn simplified_correction(&mut self) {
        let n = self.nodes.len();
        let unknowns = n - 1;
        for i in 1..n - 1 {
            let r = i - 1;
            let f = if self.active[i] {
                self.p_trial[i]
            } else {
                self.resid[i] * self.row_scale[r]
            };
            self.rhs2[(r, 0)] = -f;
        }
        self.rhs2[(unknowns - 1, 0)] =
            -(self.load_integral(&self.p_trial) - FRAC_PI_2) * self.row_scale[unknowns - 1];
        let perm = faer::perm::PermRef::new_checked(&self.perm, &self.perm_inv, unknowns);
        let mut stack = MemStack::new(&mut self.stack);
        solve::solve_transpose_in_place(
            self.jt.as_ref(),
            self.jt.as_ref(),
            perm,
            self.rhs2.as_mut(),
            Par::Seq,
            &mut stack,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ehl::rheology::ViscosityLaw;

    /// The analytic Jacobian equals a central finite difference of the residual (Roelands +
    /// DH, elastic) at a perturbed Hertz state — an independent check of every derivative.
    #[test]
    fn jacobian_matches_finite_differences() {
        let mut ws = NewtonWorkspace::new(&GridSpec::with_intervals(60));
        let prob = Problem {
            lambda_bar: 0.05,
            rheology: Rheology::new(ViscosityLaw::Roelands, true, 0.8e9, 2e-8, 0.04),
            elastic: true,
        };
        ws.start_hertz(true, 0.3);
        let n = ws.len();
        for i in 1..n - 1 {
            ws.p[i] += 0.05 * (i as f64 * 0.7).sin().abs();
        }
        let eval = |ws: &mut NewtonWorkspace| -> Vec<f64> {
            let mut h = std::mem::take(&mut ws.h);
            ws.film_into(true, &ws.p, ws.h0, &mut h);
            ws.h = h;
            ws.properties(&prob, false);
            ws.residuals(false);
            let mut f: Vec<f64> = ws.resid[1..n - 1].to_vec();
            f.push(ws.load_integral(&ws.p) - FRAC_PI_2);
            f
        };
        eval(&mut ws);
        ws.active.iter_mut().for_each(|a| *a = false);
        ws.assemble(&prob, false);
        let unknowns = n - 1;
        let mut worst: f64 = 0.0;
        for c in 0..unknowns {
            let step = 1e-6;
            let (f_plus, f_minus);
            if c < unknowns - 1 {
                ws.p[c + 1] += step;
                f_plus = eval(&mut ws);
                ws.p[c + 1] -= 2.0 * step;
                f_minus = eval(&mut ws);
                ws.p[c + 1] += step;
            } else {
                ws.h0 += step;
                f_plus = eval(&mut ws);
                ws.h0 -= 2.0 * step;
                f_minus = eval(&mut ws);
                ws.h0 += step;
            }
            for r in 0..unknowns {
                let fd = (f_plus[r] - f_minus[r]) / (2.0 * step);
                let an = ws.jt[(c, r)];
                let scale = ws
                    .jt
                    .col_as_slice(r)
                    .iter()
                    .fold(0.0f64, |a, v| a.max(v.abs()));
                worst = worst.max((fd - an).abs() / scale);
            }
        }
        assert!(worst < 1e-6, "worst relative Jacobian error {worst}");
    }
}
