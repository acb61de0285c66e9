//! Fixed-step implicit time integration of the rotor with nonlinear bearings.
//!
//! Scheme: Newmark (1959) with the Hilber–Hughes–Taylor α modification (Hilber, Hughes & Taylor,
//! *Improved numerical dissipation for time integration algorithms in structural dynamics*,
//! Earthq. Eng. Struct. Dyn. 5 (1977) 283–292; Géradin & Rixen, *Mechanical Vibrations* (2015)
//! §7.3–7.4). With α = 0, β = ¼, γ = ½ it is the average-acceleration (trapezoidal) rule:
//! unconditionally stable, second order, no numerical damping, and it conserves the energy of
//! a linear undamped (also gyroscopic) system exactly. HHT-α (0 < α ≤ ⅓) uses β = (1+α)²/4,
//! γ = ½ + α: still second order, with dissipation of the high modes.
//!
//! Step n → n+1 (h = Δt), with D = C + ΩG and the bearing forces F_b (Newmark relations
//! q₁ = q̃ + βh²a₁, v₁ = ṽ + γh a₁, q̃ = q₀ + hv₀ + (½−β)h²a₀, ṽ = v₀ + (1−γ)h a₀):
//!
//!   M a₁ + (1−α)(D v₁ + K q₁) + α(D v₀ + K q₀) = (1−α)(f₁ + P F_b₁) + α(f₀ + P F_b₀)
//!
//! The linear part gives a constant effective matrix K* = M/(βh²) + (1−α)γ/(βh) D + (1−α)K, so
//! q₁ = K*⁻¹ r + (1−α) Z F_b₁ with Z = K*⁻¹ P (P picks the bearing x, y DOFs). The nonlinear
//! problem shrinks to the bearing displacements u = Pᵀq₁ (2 per bearing):
//!
//!   R(u) = u − u_lin − (1−α) S F_b(u, u̇(u)) = 0,  S = Pᵀ Z,  u̇ = Pᵀṽ + γ/(βh)(u − Pᵀq̃)
//!
//! solved by Newton with the tangent I + (1−α) S (K_b + γ/(βh) C_b) — the bearing's own stiffness
//! and damping matrices. Iterations are bounded; a step that does not converge returns an error
//! naming the time, the iteration count and the residual (it is never silently accepted).
//!
//! Cost per step: the operators K*⁻¹(M/(βh²) + (1−α)γ/(βh) D) and (1−α)K*⁻¹D are formed once,
//! so the linear part is two dense matrix–vector products (four with HHT-α); the constant load
//! (gravity) is pre-solved and the time-varying loads, which act on a few DOFs, are applied
//! through the matching columns of K*⁻¹. Nothing is allocated per step.

use nalgebra::{DMatrix, DVector};

/// Most bearings one rotor may have (the Newton system is solved on the stack).
pub const MAX_BEARINGS: usize = 8;

use super::bearing::{BearingError, BearingModel, BearingReaction, BearingState};

/// Time-integration scheme.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Scheme {
    /// Newmark average acceleration (β = ¼, γ = ½).
    AverageAcceleration,
    /// Hilber–Hughes–Taylor α, 0 < α ≤ ⅓ (positive-α convention).
    Hht {
        /// Dissipation parameter α.
        alpha: f64,
    },
}

impl Scheme {
    /// (α, β, γ).
    pub fn parameters(&self) -> (f64, f64, f64) {
        match *self {
            Scheme::AverageAcceleration => (0.0, 0.25, 0.5),
            Scheme::Hht { alpha } => (alpha, (1.0 + alpha).powi(2) / 4.0, 0.5 + alpha),
        }
    }
}

/// Newton settings for the bearing forces.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NewtonSettings {
    /// Maximum Newton iterations per step.
    pub max_iterations: usize,
    /// Converged when the bearing-displacement correction is below this (m)…
    pub displacement_tolerance: f64,
    /// …or below this fraction of the bearing displacement.
    pub relative_tolerance: f64,
    /// Resolution of the bearing model: a model computed in f32 with a fixed number of inner
    /// iterations (the core) returns forces that scatter slightly between calls, so Newton can
    /// stall just above the tolerance. After 3 iterations a correction below this bound (m)
    /// that no longer halves is accepted as converged to the model's resolution; such steps
    /// are counted in [`StepStats::resolution_limited`] and reported, never hidden.
    pub model_resolution: f64,
}

impl Default for NewtonSettings {
    fn default() -> Self {
        NewtonSettings {
            max_iterations: 20,
            // 10 pm (+10⁻⁶ of the displacement): far below any bearing deflection of interest
            // (an acceleration error of ~0.5 m/s² at h = 8.4 µs), above the scatter of the
            // core's f32 forces mapped through S (≈ 10⁻⁹ m/N × 4·10⁻³ N ≈ 4·10⁻¹² m).
            displacement_tolerance: 1e-11,
            relative_tolerance: 1e-6,
            model_resolution: 1e-9,
        }
    }
}

/// Why a step failed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StepError {
    /// Newton did not converge within the iteration bound.
    #[error("Newton on the bearing forces did not converge at t = {time:.6e} s: {iterations} iterations, last correction {correction:.3e} m")]
    NotConverged {
        /// Time of the failed step (s).
        time: f64,
        /// Iterations done.
        iterations: usize,
        /// Size of the last correction (m).
        correction: f64,
    },
    /// A bearing model failed.
    #[error("at t = {time:.6e} s: {source}")]
    Bearing {
        /// Time (s).
        time: f64,
        /// The bearing error.
        source: BearingError,
    },
    /// The Newton tangent is singular.
    #[error("singular Newton tangent at t = {time:.6e} s")]
    SingularTangent {
        /// Time (s).
        time: f64,
    },
    /// The loads cannot be evaluated (e.g. a speed outside the motor range).
    #[error("load: {0}")]
    Load(String),
    /// More bearings than [`MAX_BEARINGS`].
    #[error("{0} bearings: at most {MAX_BEARINGS} are supported")]
    TooManyBearings(usize),
    /// The effective matrix K* or M is singular.
    #[error("singular effective system matrix (check mass and step size)")]
    SingularSystem,
}

/// Statistics of the last step.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StepStats {
    /// Newton iterations of the last step.
    pub iterations: usize,
    /// Bearing evaluations of the last step.
    pub bearing_evaluations: usize,
    /// The last step converged to the bearing model's resolution, not to the tolerance.
    pub resolution_limited: bool,
}

/// Totals since the integrator was built: what a run's cost breakdown is made of.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct StepTotals {
    /// Steps taken.
    pub steps: usize,
    /// Bearing evaluations (each evaluates every bearing once).
    pub bearing_evaluations: usize,
    /// Wall time inside [`Integrator::step`] (s).
    pub step_seconds: f64,
    /// Part of it in bearing evaluations (s); the rest of `step_seconds` is the shaft's linear
    /// algebra (predictors, the two matrix–vector products, Newton on the bearing DOFs).
    pub bearing_seconds: f64,
}

impl StepTotals {
    /// Mean bearing evaluations per step.
    pub fn evaluations_per_step(&self) -> f64 {
        self.bearing_evaluations as f64 / self.steps.max(1) as f64
    }
}

/// The state of the rotor: displacements, velocities, accelerations at time `time`.
#[derive(Debug, Clone, PartialEq)]
pub struct RotorState {
    /// Time (s).
    pub time: f64,
    /// Displacements q (m, rad).
    pub q: DVector<f64>,
    /// Velocities (m/s, rad/s).
    pub v: DVector<f64>,
    /// Accelerations (m/s², rad/s²).
    pub a: DVector<f64>,
}

/// Fixed-step integrator of M q̈ + D q̇ + K q = f_const + f(t) + P F_b for one spin speed.
pub struct Integrator {
    alpha: f64,
    beta: f64,
    gamma: f64,
    dt: f64,
    spin_speed: f64,
    mass: DMatrix<f64>,
    stiffness: DMatrix<f64>,
    /// K*⁻¹ (M/(βh²) + (1−α)γ/(βh) D).
    op_q: DMatrix<f64>,
    /// −(1−α) K*⁻¹ D.
    op_v: DMatrix<f64>,
    /// HHT terms −α K*⁻¹ K and −α K*⁻¹ D (None for α = 0).
    op_hht: Option<(DMatrix<f64>, DMatrix<f64>)>,
    k_eff_inv: DMatrix<f64>,
    /// K*⁻¹ f_const.
    const_response: DVector<f64>,
    /// f_const (kept to rebuild `const_response` after a speed change).
    constant_load: DVector<f64>,
    z: DMatrix<f64>,
    s: DMatrix<f64>,
    bearing_dofs: Vec<[usize; 2]>,
    bearings: Vec<Box<dyn BearingModel>>,
    newton: NewtonSettings,
    /// Current state.
    pub state: RotorState,
    f_prev: DVector<f64>,
    fb_prev: DVector<f64>,
    q_pred: DVector<f64>,
    v_pred: DVector<f64>,
    q_lin: DVector<f64>,
    /// Last bearing reactions (one per bearing).
    pub reactions: Vec<BearingReaction>,
    /// Statistics of the last step.
    pub stats: StepStats,
    /// Totals since construction (the initial evaluation is not counted).
    pub totals: StepTotals,
    /// Bearing displacements and velocities of the last evaluation (where `reactions` hold).
    eval_u: [f64; 2 * MAX_BEARINGS],
    eval_w: [f64; 2 * MAX_BEARINGS],
}

/// Solves the small dense system a·x = b in place (partial pivoting); false when singular.
fn solve_small(
    a: &mut [[f64; 2 * MAX_BEARINGS]; 2 * MAX_BEARINGS],
    b: &mut [f64],
    n: usize,
) -> bool {
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
    /// Sets up the integrator. `damping` is D = C + ΩG (linear part), `bearing_dofs` the x, y
    /// DOF indices of each bearing, `constant_load` the load present at all times (gravity),
    /// `f0` the time-varying load at the initial time. The initial acceleration is solved from
    /// the equation of motion.
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        scheme: Scheme,
        dt: f64,
        spin_speed: f64,
        mass: DMatrix<f64>,
        damping: DMatrix<f64>,
        stiffness: DMatrix<f64>,
        bearing_dofs: Vec<[usize; 2]>,
        bearings: Vec<Box<dyn BearingModel>>,
        newton: NewtonSettings,
        initial: (f64, DVector<f64>, DVector<f64>),
        constant_load: DVector<f64>,
        f0: DVector<f64>,
    ) -> Result<Integrator, StepError> {
        let nb = bearing_dofs.len();
        if nb > MAX_BEARINGS {
            return Err(StepError::TooManyBearings(nb));
        }
        let (alpha, beta, gamma) = scheme.parameters();
        let n = mass.nrows();
        let empty = || DMatrix::zeros(0, 0);
        let (time, q, v) = initial;
        let mut me = Integrator {
            alpha,
            beta,
            gamma,
            dt,
            spin_speed,
            mass,
            stiffness,
            op_q: empty(),
            op_v: empty(),
            op_hht: None,
            k_eff_inv: empty(),
            const_response: DVector::zeros(n),
            constant_load: constant_load.clone(),
            z: empty(),
            s: empty(),
            bearing_dofs,
            bearings,
            newton,
            state: RotorState {
                time,
                q: q.clone(),
                v: v.clone(),
                a: DVector::zeros(n),
            },
            f_prev: f0.clone(),
            fb_prev: DVector::zeros(2 * nb),
            q_pred: DVector::zeros(n),
            v_pred: DVector::zeros(n),
            q_lin: DVector::zeros(n),
            reactions: vec![BearingReaction::default(); nb],
            stats: StepStats::default(),
            totals: StepTotals::default(),
            eval_u: [0.0; 2 * MAX_BEARINGS],
            eval_w: [0.0; 2 * MAX_BEARINGS],
        };
        me.build_operators(&damping)?;
        let mut u = [0.0; 2 * MAX_BEARINGS];
        let mut w = [0.0; 2 * MAX_BEARINGS];
        for (b, d) in me.bearing_dofs.iter().enumerate() {
            for c in 0..2 {
                u[2 * b + c] = q[d[c]];
                w[2 * b + c] = v[d[c]];
            }
        }
        me.evaluate_bearings(&u, &w, time)?;
        let mut rhs = constant_load + f0 - &damping * &v - &me.stiffness * &q;
        for (b, d) in me.bearing_dofs.iter().enumerate() {
            for c in 0..2 {
                me.fb_prev[2 * b + c] = me.reactions[b].force[c];
                rhs[d[c]] += me.reactions[b].force[c];
            }
        }
        let chol = me
            .mass
            .clone()
            .cholesky()
            .ok_or(StepError::SingularSystem)?;
        me.state.a = chol.solve(&rhs);
        me.totals = StepTotals::default();
        Ok(me)
    }

    /// Forms K* = M/(βh²) + (1−α)γ/(βh) D + (1−α)K, its inverse and the step operators for the
    /// linear damping D (the constructor's, or a new one after a speed change).
    fn build_operators(&mut self, damping: &DMatrix<f64>) -> Result<(), StepError> {
        let (alpha, beta, gamma, dt) = (self.alpha, self.beta, self.gamma, self.dt);
        let (mass, stiffness) = (&self.mass, &self.stiffness);
        let n = mass.nrows();
        let nb = self.bearing_dofs.len();
        let c1 = gamma / (beta * dt);
        let k_eff =
            mass / (beta * dt * dt) + damping * ((1.0 - alpha) * c1) + stiffness * (1.0 - alpha);
        let k_eff_inv = k_eff.try_inverse().ok_or(StepError::SingularSystem)?;
        self.op_q = &k_eff_inv * (mass / (beta * dt * dt) + damping * ((1.0 - alpha) * c1));
        self.op_v = &k_eff_inv * damping * (-(1.0 - alpha));
        self.op_hht = (alpha != 0.0).then(|| {
            (
                &k_eff_inv * stiffness * (-alpha),
                &k_eff_inv * damping * (-alpha),
            )
        });
        self.const_response = &k_eff_inv * &self.constant_load;
        let mut z = DMatrix::zeros(n, 2 * nb);
        for (b, dofs) in self.bearing_dofs.iter().enumerate() {
            for (c, &dof) in dofs.iter().enumerate() {
                z.set_column(2 * b + c, &k_eff_inv.column(dof));
            }
        }
        let mut s = DMatrix::zeros(2 * nb, 2 * nb);
        for (b, dofs) in self.bearing_dofs.iter().enumerate() {
            for (c, &dof) in dofs.iter().enumerate() {
                for j in 0..2 * nb {
                    s[(2 * b + c, j)] = z[(dof, j)];
                }
            }
        }
        self.k_eff_inv = k_eff_inv;
        self.z = z;
        self.s = s;
        Ok(())
    }

    /// Changes the spin speed Ω (rad/s) for the following steps: the bearings see the new
    /// speed and the operators are rebuilt with the new linear damping D = C + ΩG (given by the
    /// caller in the integrated coordinates). For a speed ramp this is called before every
    /// step with the speed at the step's end, so the gyroscopic term of the implicit equation
    /// is taken at t₁ like every other term of the average-acceleration rule. (With HHT-α the
    /// α-weighted D v₀ term then also uses the new D: an O(ΔΩ) difference per step.)
    pub fn set_spin_speed(
        &mut self,
        spin_speed: f64,
        damping: &DMatrix<f64>,
    ) -> Result<(), StepError> {
        if spin_speed == self.spin_speed {
            return Ok(());
        }
        self.spin_speed = spin_speed;
        self.build_operators(damping)
    }

    /// Current spin speed (rad/s).
    pub fn spin_speed(&self) -> f64 {
        self.spin_speed
    }

    /// The bearing models (e.g. for their per-roller states after a step).
    pub fn bearing_models(&self) -> &[Box<dyn BearingModel>] {
        &self.bearings
    }

    /// Step size (s).
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// Number of DOFs.
    pub fn n_dof(&self) -> usize {
        self.mass.nrows()
    }

    fn evaluate_bearings(&mut self, u: &[f64], w: &[f64], time: f64) -> Result<(), StepError> {
        let clock = std::time::Instant::now();
        for (b, model) in self.bearings.iter_mut().enumerate() {
            let state = BearingState {
                displacement: [u[2 * b], u[2 * b + 1]],
                velocity: [w[2 * b], w[2 * b + 1]],
                spin_speed: self.spin_speed,
                time,
            };
            self.reactions[b] = model
                .evaluate(&state)
                .map_err(|source| StepError::Bearing { time, source })?;
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
        let mut tangent = [[0.0; 2 * MAX_BEARINGS]; 2 * MAX_BEARINGS];
        let mut du = [0.0; 2 * MAX_BEARINGS];
        for i in 0..m {
            tangent[i][i] = 1.0;
            let mut su = 0.0;
            for j in 0..m {
                let (b, c) = (j / 2, j % 2);
                let r = &self.reactions[b];
                // Force at u_e with this step's velocity law u̇(u_e) = ṽ + c1 (u_e − ũ).
                let mut f = r.force[c];
                for k in 0..2 {
                    let jk = 2 * b + k;
                    let w_at = w_pred[jk] + c1 * (self.eval_u[jk] - u_pred[jk]);
                    f -= r.damping[c][k] * (w_at - self.eval_w[jk]);
                    tangent[i][jk] +=
                        (1.0 - alpha) * self.s[(i, j)] * (r.stiffness[c][k] + c1 * r.damping[c][k]);
                }
                su += self.s[(i, j)] * f;
            }
            du[i] = -(self.eval_u[i] - u_lin[i] - (1.0 - alpha) * su);
        }
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
            // Residual R(u) and tangent I + (1−α) S (K_b + c1 C_b) (K_b, C_b block-diagonal).
            let mut tangent = [[0.0; 2 * MAX_BEARINGS]; 2 * MAX_BEARINGS];
            let mut du = [0.0; 2 * MAX_BEARINGS];
            for i in 0..m {
                tangent[i][i] = 1.0;
                let mut su = 0.0;
                for j in 0..m {
                    let (b, c) = (j / 2, j % 2);
                    let r = &self.reactions[b];
                    let sij = self.s[(i, j)];
                    su += sij * r.force[c];
                    for k in 0..2 {
                        let kb = r.stiffness[c][k] + c1 * r.damping[c][k];
                        tangent[i][2 * b + k] += (1.0 - alpha) * sij * kb;
                    }
                }
                du[i] = -(u[i] - u_lin[i] - (1.0 - alpha) * su);
            }
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

    /// Kinetic plus shaft strain energy ½vᵀMv + ½qᵀKq (J); bearing energy is not included.
    pub fn shaft_energy(&self) -> f64 {
        let st = &self.state;
        0.5 * st.v.dot(&(&self.mass * &st.v)) + 0.5 * st.q.dot(&(&self.stiffness * &st.q))
    }
}
