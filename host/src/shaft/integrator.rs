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

use nalgebra::{DMatrix, DVector};

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
}

impl Default for NewtonSettings {
    fn default() -> Self {
        NewtonSettings {
            max_iterations: 20,
            displacement_tolerance: 1e-13,
            relative_tolerance: 1e-10,
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

/// Fixed-step integrator of M q̈ + D q̇ + K q = f(t) + P F_b for one spin speed.
pub struct Integrator {
    alpha: f64,
    beta: f64,
    gamma: f64,
    dt: f64,
    spin_speed: f64,
    mass: DMatrix<f64>,
    damping: DMatrix<f64>,
    stiffness: DMatrix<f64>,
    k_eff_inv: DMatrix<f64>,
    z: DMatrix<f64>,
    s: DMatrix<f64>,
    bearing_dofs: Vec<[usize; 2]>,
    bearings: Vec<Box<dyn BearingModel>>,
    newton: NewtonSettings,
    /// Current state.
    pub state: RotorState,
    f_prev: DVector<f64>,
    fb_prev: DVector<f64>,
    /// Last bearing reactions (one per bearing).
    pub reactions: Vec<BearingReaction>,
    /// Statistics of the last step.
    pub stats: StepStats,
    /// Wall time spent in bearing evaluations since construction (s).
    pub bearing_seconds: f64,
}

impl Integrator {
    /// Sets up the integrator. `damping` is D = C + ΩG (linear part), `bearing_dofs` the x, y
    /// DOF indices of each bearing, `f0` the external load at the initial time. The initial
    /// acceleration is solved from the equation of motion.
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
        f0: DVector<f64>,
    ) -> Result<Integrator, StepError> {
        let (alpha, beta, gamma) = scheme.parameters();
        let n = mass.nrows();
        let k_eff = &mass / (beta * dt * dt)
            + &damping * ((1.0 - alpha) * gamma / (beta * dt))
            + &stiffness * (1.0 - alpha);
        let k_eff_inv = k_eff.try_inverse().ok_or(StepError::SingularSystem)?;
        let nb = bearing_dofs.len();
        let mut z = DMatrix::zeros(n, 2 * nb);
        for (b, dofs) in bearing_dofs.iter().enumerate() {
            for (c, &dof) in dofs.iter().enumerate() {
                z.set_column(2 * b + c, &k_eff_inv.column(dof));
            }
        }
        let mut s = DMatrix::zeros(2 * nb, 2 * nb);
        for (b, dofs) in bearing_dofs.iter().enumerate() {
            for (c, &dof) in dofs.iter().enumerate() {
                for j in 0..2 * nb {
                    s[(2 * b + c, j)] = z[(dof, j)];
                }
            }
        }
        let (time, q, v) = initial;
        let mut me = Integrator {
            alpha,
            beta,
            gamma,
            dt,
            spin_speed,
            mass,
            damping,
            stiffness,
            k_eff_inv,
            z,
            s,
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
            reactions: vec![BearingReaction::default(); nb],
            stats: StepStats::default(),
            bearing_seconds: 0.0,
        };
        let (u, w) = me.bearing_kinematics(&q, &v);
        me.evaluate_bearings(&u, &w, time)?;
        for b in 0..nb {
            me.fb_prev[2 * b] = me.reactions[b].force[0];
            me.fb_prev[2 * b + 1] = me.reactions[b].force[1];
        }
        let mut rhs = f0 - &me.damping * &v - &me.stiffness * &q;
        me.scatter_bearing_forces(&me.fb_prev.clone(), 1.0, &mut rhs);
        let chol = me
            .mass
            .clone()
            .cholesky()
            .ok_or(StepError::SingularSystem)?;
        me.state.a = chol.solve(&rhs);
        Ok(me)
    }

    /// Step size (s).
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// Number of DOFs.
    pub fn n_dof(&self) -> usize {
        self.mass.nrows()
    }

    /// Bearing displacements and velocities stacked [x₀, y₀, x₁, y₁, …].
    fn bearing_kinematics(&self, q: &DVector<f64>, v: &DVector<f64>) -> (Vec<f64>, Vec<f64>) {
        let mut u = Vec::with_capacity(2 * self.bearing_dofs.len());
        let mut w = Vec::with_capacity(2 * self.bearing_dofs.len());
        for dofs in &self.bearing_dofs {
            for &d in dofs {
                u.push(q[d]);
                w.push(v[d]);
            }
        }
        (u, w)
    }

    fn scatter_bearing_forces(&self, fb: &DVector<f64>, factor: f64, f: &mut DVector<f64>) {
        for (b, dofs) in self.bearing_dofs.iter().enumerate() {
            f[dofs[0]] += factor * fb[2 * b];
            f[dofs[1]] += factor * fb[2 * b + 1];
        }
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
        self.bearing_seconds += clock.elapsed().as_secs_f64();
        Ok(())
    }

    /// Advances one step with the external load `f1` at the new time.
    pub fn step(&mut self, f1: &DVector<f64>) -> Result<(), StepError> {
        let (alpha, beta, gamma, h) = (self.alpha, self.beta, self.gamma, self.dt);
        let t1 = self.state.time + h;
        let st = &self.state;
        let q_pred = &st.q + &st.v * h + &st.a * ((0.5 - beta) * h * h);
        let v_pred = &st.v + &st.a * ((1.0 - gamma) * h);
        let c1 = gamma / (beta * h);
        // r = M q̃/(βh²) + (1−α) D (c1 q̃ − ṽ) − α(D v₀ + K q₀) + (1−α) f₁ + α(f₀ + P F_b₀)
        let mut r = &self.mass * &q_pred * (1.0 / (beta * h * h))
            + &self.damping * (&q_pred * ((1.0 - alpha) * c1) - &v_pred * (1.0 - alpha))
            + f1 * (1.0 - alpha);
        if alpha != 0.0 {
            r -= (&self.damping * &st.v + &self.stiffness * &st.q) * alpha;
            r += &self.f_prev * alpha;
            let fb_prev = self.fb_prev.clone();
            self.scatter_bearing_forces(&fb_prev, alpha, &mut r);
        }
        let q_lin = &self.k_eff_inv * r;
        let nb = self.bearing_dofs.len();
        let (u_lin, _) = self.bearing_kinematics(&q_lin, &q_lin);
        let (u_pred, w_pred) = self.bearing_kinematics(&q_pred, &v_pred);
        // Warm start: last step's bearing forces.
        let mut u: Vec<f64> = (0..2 * nb)
            .map(|i| {
                u_lin[i]
                    + (1.0 - alpha)
                        * (0..2 * nb)
                            .map(|j| self.s[(i, j)] * self.fb_prev[j])
                            .sum::<f64>()
            })
            .collect();
        self.stats = StepStats::default();
        let mut converged = nb == 0;
        let mut correction = 0.0;
        while !converged {
            let w: Vec<f64> = (0..2 * nb)
                .map(|i| w_pred[i] + c1 * (u[i] - u_pred[i]))
                .collect();
            self.evaluate_bearings(&u, &w, t1)?;
            if self.stats.iterations >= self.newton.max_iterations {
                return Err(StepError::NotConverged {
                    time: t1,
                    iterations: self.stats.iterations,
                    correction,
                });
            }
            self.stats.iterations += 1;
            // Residual and tangent.
            let mut res = DVector::zeros(2 * nb);
            let mut tangent = DMatrix::identity(2 * nb, 2 * nb);
            for i in 0..2 * nb {
                let mut su = 0.0;
                for j in 0..2 * nb {
                    let (b, c) = (j / 2, j % 2);
                    su += self.s[(i, j)] * self.reactions[b].force[c];
                    // Row i of S·(K_b + c1 C_b), block-diagonal K_b, C_b.
                    for k in 0..2 {
                        let col = 2 * b + k;
                        let kb = self.reactions[b].stiffness[c][k]
                            + c1 * self.reactions[b].damping[c][k];
                        tangent[(i, col)] += (1.0 - alpha) * self.s[(i, j)] * kb;
                    }
                }
                res[i] = u[i] - u_lin[i] - (1.0 - alpha) * su;
            }
            let du = tangent
                .lu()
                .solve(&(-res))
                .ok_or(StepError::SingularTangent { time: t1 })?;
            let mut size = 0.0f64;
            let mut scale = 0.0f64;
            for i in 0..2 * nb {
                u[i] += du[i];
                size = size.max(du[i].abs());
                scale = scale.max(u[i].abs());
            }
            correction = size;
            // f64::max skips NaN: a non-finite iterate must fail the step, never pass the test.
            if !u.iter().chain(du.iter()).all(|x| x.is_finite()) {
                return Err(StepError::NotConverged {
                    time: t1,
                    iterations: self.stats.iterations,
                    correction: f64::NAN,
                });
            }
            converged =
                size <= self.newton.displacement_tolerance + self.newton.relative_tolerance * scale;
        }
        // The forces of the last evaluation are used: they were taken at u − Δu with Δu within
        // the tolerance, so q₁ below is consistent with them to that tolerance.
        let mut fb = DVector::zeros(2 * nb);
        for b in 0..nb {
            fb[2 * b] = self.reactions[b].force[0];
            fb[2 * b + 1] = self.reactions[b].force[1];
        }
        let q1 = q_lin + &self.z * &fb * (1.0 - alpha);
        let a1 = (&q1 - &q_pred) * (1.0 / (beta * h * h));
        let v1 = v_pred + &a1 * (gamma * h);
        let (uc, wc) = self.bearing_kinematics(&q1, &v1);
        for (b, model) in self.bearings.iter_mut().enumerate() {
            let state = BearingState {
                displacement: [uc[2 * b], uc[2 * b + 1]],
                velocity: [wc[2 * b], wc[2 * b + 1]],
                spin_speed: self.spin_speed,
                time: t1,
            };
            model.commit(&state, h);
        }
        self.state = RotorState {
            time: t1,
            q: q1,
            v: v1,
            a: a1,
        };
        self.f_prev.copy_from(f1);
        self.fb_prev = fb;
        Ok(())
    }

    /// Kinetic plus shaft strain energy ½vᵀMv + ½qᵀKq (J); bearing energy is not included.
    pub fn shaft_energy(&self) -> f64 {
        let st = &self.state;
        0.5 * st.v.dot(&(&self.mass * &st.v)) + 0.5 * st.q.dot(&(&self.stiffness * &st.q))
    }
}
