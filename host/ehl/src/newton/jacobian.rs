//! Jacobian of the discrete Reynolds/complementarity/load system, its LU solve, and the
//! simplified Newton corrections used by the damping test (split from [`super`] for size).

use super::{NewtonWorkspace, Problem};
use faer::dyn_stack::MemStack;
use faer::linalg::lu::partial_pivoting::{factor, solve};
use faer::Par;
use std::f64::consts::FRAC_PI_2;

impl NewtonWorkspace {
    /// Assembles, factorises and solves J Δ = −F in place (Δ left in `rhs`). Returns false if
    /// the step is not finite.
    pub(super) fn assemble_and_solve(&mut self, prob: &Problem) -> bool {
        self.assemble(prob, true);
        let unknowns = self.nodes.len() - 1;
        let stack = MemStack::new(&mut self.stack);
        let (_, perm) = factor::lu_in_place(
            self.jt.as_mut(),
            &mut self.perm,
            &mut self.perm_inv,
            Par::Seq,
            stack,
            Default::default(),
        );
        solve::solve_transpose_in_place(
            self.jt.as_ref(),
            self.jt.as_ref(),
            perm,
            self.rhs.as_mut(),
            Par::Seq,
            stack,
        );
        (0..unknowns).all(|r| self.rhs[(r, 0)].is_finite())
    }

    /// Assembles J transposed (column r = row r of J) and −F in `rhs`; with `equilibrate` each
    /// row is divided by its largest entry.
    pub(super) fn assemble(&mut self, prob: &Problem, equilibrate: bool) {
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
            if self.fischer {
                // φ = a + b − r with a = P_i, b = −σR_i: ∂φ = (1 − a/r)e_i + (1 − b/r)(−σ∇R).
                let a = self.p[i];
                let bb = -self.sigma[i] * self.resid[i];
                let rr = a.hypot(bb);
                let (da, db) = if rr > 1e-300 {
                    (1.0 - a / rr, 1.0 - bb / rr)
                } else {
                    (
                        1.0 - std::f64::consts::FRAC_1_SQRT_2,
                        1.0 - std::f64::consts::FRAC_1_SQRT_2,
                    )
                };
                let f = -self.sigma[i] * db;
                col.iter_mut().for_each(|v| *v *= f);
                col[r] += da;
                let big = col.iter().fold(0.0f64, |acc, v| acc.max(v.abs()));
                let s = if big > 0.0 && equilibrate {
                    1.0 / big
                } else {
                    1.0
                };
                col.iter_mut().for_each(|v| *v *= s);
                self.rhs[(r, 0)] = -(a + bb - rr) * s;
                self.row_scale[r] = s;
                continue;
            }
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
    pub(super) fn step_norm(&self, v: impl Fn(usize) -> f64) -> f64 {
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
    pub(super) fn simplified_correction(&mut self) {
        let n = self.nodes.len();
        let unknowns = n - 1;
        for i in 1..n - 1 {
            let r = i - 1;
            let f = if self.fischer {
                self.ncp(self.p_trial[i], i) * self.row_scale[r]
            } else if self.active[i] {
                self.p_trial[i]
            } else {
                self.resid[i] * self.row_scale[r]
            };
            self.rhs2[(r, 0)] = -f;
        }
        self.rhs2[(unknowns - 1, 0)] =
            -(self.load_integral(&self.p_trial) - FRAC_PI_2) * self.row_scale[unknowns - 1];
        let perm = faer::perm::PermRef::new_checked(&self.perm, &self.perm_inv, unknowns);
        let stack = MemStack::new(&mut self.stack);
        solve::solve_transpose_in_place(
            self.jt.as_ref(),
            self.jt.as_ref(),
            perm,
            self.rhs2.as_mut(),
            Par::Seq,
            stack,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::GridSpec;
    use crate::rheology::{Rheology, ViscosityLaw};

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
