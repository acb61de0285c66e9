//! One time step: the Newmark/HHT-α predictors, the linear response, and Newton on the
//! bearing displacements with the bearings' own stiffness and damping in the tangent (see the
//! parent module for the equations).

use nalgebra::{DMatrix, DVector};

use super::{Integrator, StepError, StepStats, MAX_BEARINGS};
use crate::bearing::BearingState;

/// A vector over the bearing DOFs (x, y of each bearing; the first 2·bearings entries used).
type BearingVector = [f64; 2 * MAX_BEARINGS];
/// A matrix over the bearing DOFs, row-major.
type BearingMatrix = [BearingVector; 2 * MAX_BEARINGS];

/// Solves the small dense system a·x = b in place (partial pivoting); false when singular.
fn solve_small(a: &mut BearingMatrix, b: &mut [f64], n: usize) -> bool {
    for col in 0..n {
        let pivot = (col..n)
            .max_by(|&i, &j| a[i][col].abs().total_cmp(&a[j][col].abs()))
            .unwrap_or(col);
        if a[pivot][col].abs() < 1e-300 || !a[pivot][col].is_finite() {
            return false;
        }
        a.swap(col, pivot);
        b.swap(col, pivot);
        let pivot_row = a[col];
        let pivot_b = b[col];
        for (row, b_row) in a.iter_mut().zip(b.iter_mut()).take(n).skip(col + 1) {
            let f = row[col] / pivot_row[col];
            for (x, p) in row.iter_mut().zip(pivot_row.iter()).take(n).skip(col) {
                *x -= f * p;
            }
            *b_row -= f * pivot_b;
        }
    }
    for col in (0..n).rev() {
        let mut v = b[col];
        for k in col + 1..n {
            v -= a[col][k] * b[k];
        }
        b[col] = v / a[col][col];
    }
    true
}

impl Integrator {
    /// The bearings' reactions at the bearing displacements `u` and velocities `w` (per DOF)
    /// at `time`: trial evaluations, which commit nothing.
    pub(super) fn evaluate_bearings(
        &mut self,
        u: &[f64],
        w: &[f64],
        time: f64,
    ) -> Result<(), StepError> {
        self.react_bearings(u, w, time, false)
    }

    /// As [`Integrator::evaluate_bearings`], but each bearing first converges its memory (warm
    /// start, film table) at the state and commits it (`BearingModel::settle`): the start of a
    /// run, so that the first steps' trials start from a converged warm start, not a cold one.
    pub(super) fn settle_bearings(
        &mut self,
        u: &[f64],
        w: &[f64],
        time: f64,
    ) -> Result<(), StepError> {
        self.react_bearings(u, w, time, true)
    }

    fn react_bearings(
        &mut self,
        u: &[f64],
        w: &[f64],
        time: f64,
        settle: bool,
    ) -> Result<(), StepError> {
        let clock = std::time::Instant::now();
        for (b, model) in self.bearings.iter_mut().enumerate() {
            let state = BearingState {
                displacement: [u[2 * b], u[2 * b + 1]],
                velocity: [w[2 * b], w[2 * b + 1]],
                spin_speed: self.spin_speed,
                time,
            };
            let reaction = if settle {
                model.settle(&state)
            } else {
                model.evaluate(&state)
            };
            self.reactions[b] = reaction.map_err(|source| StepError::Bearing { time, source })?;
        }
        self.stats.bearing_evaluations += 1;
        self.totals.bearing_seconds += clock.elapsed().as_secs_f64();
        let m = 2 * self.bearings.len();
        self.eval_u[..m].copy_from_slice(&u[..m]);
        self.eval_w[..m].copy_from_slice(&w[..m]);
        Ok(())
    }

    /// Adds factor · K*⁻¹ f to q_lin using only the non-zero entries of f.
    fn add_sparse_response(
        q_lin: &mut DVector<f64>,
        k_eff_inv: &DMatrix<f64>,
        f: &DVector<f64>,
        factor: f64,
    ) {
        for (j, &fj) in f.iter().enumerate() {
            if fj != 0.0 {
                q_lin.axpy(factor * fj, &k_eff_inv.column(j), 1.0);
            }
        }
    }

    /// Advances one step with the time-varying load `f1` at the new time (the constant load
    /// given at construction is added internally).
    pub fn step(&mut self, f1: &DVector<f64>) -> Result<(), StepError> {
        let clock = std::time::Instant::now();
        let result = self.step_untimed(f1);
        self.totals.step_seconds += clock.elapsed().as_secs_f64();
        if result.is_ok() {
            self.totals.steps += 1;
            self.totals.bearing_evaluations += self.stats.bearing_evaluations;
        }
        result
    }

    /// Newton system of the bearing DOFs at `u` with bearing forces `forces` (per DOF) and the
    /// reactions' stiffness and damping: the tangent I + (1−α) S (K_b + c1 C_b) (K_b, C_b
    /// block-diagonal) and the update −R(u), R(u) = u − u_lin − (1−α) S F.
    fn newton_system(
        &self,
        forces: &BearingVector,
        u: &BearingVector,
        u_lin: &BearingVector,
        c1: f64,
    ) -> (BearingMatrix, BearingVector) {
        let alpha = self.alpha;
        let m = 2 * self.bearing_dofs.len();
        let mut tangent = [[0.0; 2 * MAX_BEARINGS]; 2 * MAX_BEARINGS];
        let mut du = [0.0; 2 * MAX_BEARINGS];
        for i in 0..m {
            tangent[i][i] = 1.0;
            let mut su = 0.0;
            for (j, &f) in forces.iter().enumerate().take(m) {
                let (b, c) = (j / 2, j % 2);
                let r = &self.reactions[b];
                let sij = self.s[(i, j)];
                su += sij * f;
                for k in 0..2 {
                    let kb = r.stiffness[c][k] + c1 * r.damping[c][k];
                    tangent[i][2 * b + k] += (1.0 - alpha) * sij * kb;
                }
            }
            du[i] = -(u[i] - u_lin[i] - (1.0 - alpha) * su);
        }
        (tangent, du)
    }

    fn step_untimed(&mut self, f1: &DVector<f64>) -> Result<(), StepError> {
        let (alpha, beta, gamma, h) = (self.alpha, self.beta, self.gamma, self.dt);
        let t1 = self.state.time + h;
        let c1 = gamma / (beta * h);
        // Predictors q̃, ṽ.
        self.q_pred.copy_from(&self.state.q);
        self.q_pred.axpy(h, &self.state.v, 1.0);
        self.q_pred.axpy((0.5 - beta) * h * h, &self.state.a, 1.0);
        self.v_pred.copy_from(&self.state.v);
        self.v_pred.axpy((1.0 - gamma) * h, &self.state.a, 1.0);
        // Linear response q_lin = K*⁻¹ r (without the new bearing forces).
        self.q_lin.copy_from(&self.const_response);
        self.q_lin.gemv(1.0, &self.op_q, &self.q_pred, 1.0);
        self.q_lin.gemv(1.0, &self.op_v, &self.v_pred, 1.0);
        Self::add_sparse_response(&mut self.q_lin, &self.k_eff_inv, f1, 1.0 - alpha);
        if let Some((op_k, op_d)) = &self.op_hht {
            self.q_lin.gemv(1.0, op_k, &self.state.q, 1.0);
            self.q_lin.gemv(1.0, op_d, &self.state.v, 1.0);
            Self::add_sparse_response(&mut self.q_lin, &self.k_eff_inv, &self.f_prev, alpha);
            self.q_lin.gemv(alpha, &self.z, &self.fb_prev, 1.0);
        }
        let nb = self.bearing_dofs.len();
        let m = 2 * nb;
        let mut u_lin = [0.0; 2 * MAX_BEARINGS];
        let mut u_pred = [0.0; 2 * MAX_BEARINGS];
        let mut w_pred = [0.0; 2 * MAX_BEARINGS];
        for (b, d) in self.bearing_dofs.iter().enumerate() {
            for c in 0..2 {
                u_lin[2 * b + c] = self.q_lin[d[c]];
                u_pred[2 * b + c] = self.q_pred[d[c]];
                w_pred[2 * b + c] = self.v_pred[d[c]];
            }
        }
        // Predictor: one Newton update from the last evaluation point u_e with the reactions
        // stored there, linearised as F ≈ F_e − K_e (u − u_e) − C_e (u̇ − u̇_e) — free of any
        // bearing call, exact for a linear bearing — so the first evaluation of this step is
        // already close to the solution.
        let mut u = [0.0; 2 * MAX_BEARINGS];
        let mut f_at = [0.0; 2 * MAX_BEARINGS];
        for (j, f) in f_at.iter_mut().enumerate().take(m) {
            let (b, c) = (j / 2, j % 2);
            let r = &self.reactions[b];
            // Force at u_e with this step's velocity law u̇(u_e) = ṽ + c1 (u_e − ũ).
            *f = r.force[c];
            for k in 0..2 {
                let jk = 2 * b + k;
                let w_at = w_pred[jk] + c1 * (self.eval_u[jk] - u_pred[jk]);
                *f -= r.damping[c][k] * (w_at - self.eval_w[jk]);
            }
        }
        let (mut tangent, mut du) = self.newton_system(&f_at, &self.eval_u, &u_lin, c1);
        let predicted = solve_small(&mut tangent, &mut du, m);
        for i in 0..m {
            u[i] = if predicted && du[i].is_finite() {
                self.eval_u[i] + du[i]
            } else {
                // Fallback: last step's forces on the linear response.
                u_lin[i]
                    + (1.0 - alpha)
                        * (0..m)
                            .map(|j| self.s[(i, j)] * self.fb_prev[j])
                            .sum::<f64>()
            };
        }
        self.stats = StepStats::default();
        let mut converged = nb == 0;
        let mut correction = 0.0;
        let mut previous = f64::INFINITY;
        let mut w = [0.0; 2 * MAX_BEARINGS];
        while !converged {
            for i in 0..m {
                w[i] = w_pred[i] + c1 * (u[i] - u_pred[i]);
            }
            self.evaluate_bearings(&u, &w, t1)?;
            if self.stats.iterations >= self.newton.max_iterations {
                return Err(StepError::NotConverged {
                    time: t1,
                    iterations: self.stats.iterations,
                    correction,
                });
            }
            self.stats.iterations += 1;
            let mut forces = [0.0; 2 * MAX_BEARINGS];
            for (j, f) in forces.iter_mut().enumerate().take(m) {
                *f = self.reactions[j / 2].force[j % 2];
            }
            let (mut tangent, mut du) = self.newton_system(&forces, &u, &u_lin, c1);
            if !solve_small(&mut tangent, &mut du, m) {
                return Err(StepError::SingularTangent { time: t1 });
            }
            let mut size = 0.0f64;
            let mut scale = 0.0f64;
            for i in 0..m {
                u[i] += du[i];
                size = size.max(du[i].abs());
                scale = scale.max(u[i].abs());
            }
            correction = size;
            // f64::max skips NaN: a non-finite iterate must fail the step, never pass the test.
            if !u[..m].iter().chain(du[..m].iter()).all(|x| x.is_finite()) {
                return Err(StepError::NotConverged {
                    time: t1,
                    iterations: self.stats.iterations,
                    correction: f64::NAN,
                });
            }
            converged =
                size <= self.newton.displacement_tolerance + self.newton.relative_tolerance * scale;
            if !converged
                && self.stats.iterations >= 3
                && size <= self.newton.model_resolution
                && size > 0.5 * previous
            {
                converged = true;
                self.stats.resolution_limited = true;
            }
            previous = size;
        }
        // The forces of the last evaluation are used: they were taken at u − Δu with Δu within
        // the tolerance, so q₁ below is consistent with them to that tolerance.
        for b in 0..nb {
            self.fb_prev[2 * b] = self.reactions[b].force[0];
            self.fb_prev[2 * b + 1] = self.reactions[b].force[1];
        }
        // q₁ = q_lin + (1−α) Z F_b;  a₁ = (q₁ − q̃)/(βh²);  v₁ = ṽ + γh a₁.
        let st = &mut self.state;
        st.q.copy_from(&self.q_lin);
        st.q.gemv(1.0 - alpha, &self.z, &self.fb_prev, 1.0);
        st.a.copy_from(&st.q);
        st.a.axpy(-1.0, &self.q_pred, 1.0);
        st.a *= 1.0 / (beta * h * h);
        st.v.copy_from(&self.v_pred);
        st.v.axpy(gamma * h, &st.a, 1.0);
        st.time = t1;
        for (b, model) in self.bearings.iter_mut().enumerate() {
            let d = self.bearing_dofs[b];
            let state = BearingState {
                displacement: [st.q[d[0]], st.q[d[1]]],
                velocity: [st.v[d[0]], st.v[d[1]]],
                spin_speed: self.spin_speed,
                time: t1,
            };
            model.commit(&state, h);
        }
        self.f_prev.copy_from(f1);
        Ok(())
    }
}
