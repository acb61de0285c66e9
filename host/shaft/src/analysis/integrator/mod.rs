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

mod operators;
mod step;

use nalgebra::{DMatrix, DVector};

/// Most bearings one rotor may have (the Newton system is solved on the stack).
pub const MAX_BEARINGS: usize = 8;

use crate::bearing::{BearingError, BearingModel, BearingReaction};

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

impl Integrator {
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

    /// Kinetic plus shaft strain energy ½vᵀMv + ½qᵀKq (J); bearing energy is not included.
    pub fn shaft_energy(&self) -> f64 {
        let st = &self.state;
        0.5 * st.v.dot(&(&self.mass * &st.v)) + 0.5 * st.q.dot(&(&self.stiffness * &st.q))
    }
}
