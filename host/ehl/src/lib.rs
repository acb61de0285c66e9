//! Full numerical solution of the isothermal, Newtonian, steady EHL line contact
//! (docs/physics.md §5.2) — the accuracy reference of the project.
//!
//! Unknowns: the pressure at the nodes of a non-uniform grid over X = x/b ∈ [−4.5, 1.5]
//! ([`grid`]) and the rigid-body separation H₀. Equations: Reynolds with Roelands or Barus
//! viscosity and Dowson–Higginson density ([`rheology`]), the film equation with the log-kernel
//! deflection integrated exactly over each piecewise-linear element ([`kernel`]), the load
//! balance ∫P dX = π/2, and the Reynolds cavitation condition as the complementarity P ≥ 0.
//!
//! Method ([`newton`], [`driver`]): full Newton on (P, H₀) with the load row — the approach of
//! Okamura and Houpert & Hamrock (1986), which reached 4.8 GPa — with the cavitation handled by a
//! semismooth (primal–dual active-set) Newton method, dense LU from `faer`, Deuflhard's
//! natural-monotonicity test for the damping (α shrunk by a fixed factor on rejection), chord reuse of the LU once the iteration contracts, grid
//! sequencing (101 → 201 → … → N nodes, each level started from the previous one), a Hertz start
//! with H(0) from Moes' formula, and continuation in the pressure–viscosity coefficient when the
//! direct start fails. Why this rather than multigrid: the line contact has only hundreds of
//! unknowns, Newton converges quadratically independent of load, and the dense LU of that size
//! costs milliseconds, while Gauss–Seidel-type relaxations degrade at high load (docs/physics.md
//! §5.2). Scaling: P itself is the unknown and η̄ enters only through ε ∝ exp(−ln η̄), which
//! underflows harmlessly in the contact; rows are equilibrated before the factorisation, so η̄
//! spanning 20 (Roelands) or 100 (Barus) decades is harmless. Thick films (M ≲ 3) get a
//! stretched domain so the inlet stays fully flooded ([`driver`]). Thin films (Moes' H_c below
//! 4·10⁻³ in Hertz units, i.e. M ≳ 200) use a second grid family with extra nodes at both
//! contact edges, where their inlet meniscus and outlet constriction shrink to a width of order
//! H_c^⅔ ([`grid::GridSpec::thin_film`]); a case that fails on its family is retried on the other. h_c and h_min are reported
//! Richardson-extrapolated from the last two grid levels (raw values kept), and the sequence stops
//! at 401 nodes when the estimated error there is already small.
//!
//! Failure is explicit: [`solve`] returns [`EhlError::NotConverged`] with the residuals unless
//! both docs/physics.md §5.2 criteria (Σ|ΔP|/ΣP ≤ 10⁻⁵ after a full Newton step with an unchanged
//! active set, and |∫P − π/2|/(π/2) ≤ 10⁻³) hold.
//!
//! Accuracy evidence (tests in `tests_reference`, [`convergence`]; tables in docs/ehl.md):
//! grid refinement against Richardson extrapolation, the Hertz limit, Martin's rigid iso-viscous
//! limit, Moes' formula (Barus) and Pan–Hamrock's formulas (Roelands + DH).

pub mod case;
pub mod compare;
pub mod convergence;
pub mod domain;
pub mod driver;
pub mod formulas;
pub mod grid;
pub mod kernel;
pub mod lhs;
pub mod newton;
pub mod point;
pub mod rheology;
pub mod solution;
#[cfg(test)]
mod tests_reference;
pub mod traction;

pub use case::ContactCase;
pub use driver::Solver;
pub use rheology::ViscosityLaw;
pub use solution::{EhlSolution, GridErrorEstimate, Profile};

use grid::GridSpec;

/// Errors of the EHL solver.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum EhlError {
    /// An input is NaN, infinite, zero/negative or outside its physical range.
    #[error("invalid {field} = {value}: allowed {allowed}")]
    InvalidInput {
        field: &'static str,
        value: f64,
        allowed: String,
    },
    /// The case lies outside the domain where the solver's model (Reynolds' thin-film
    /// equation on a parabolic gap, continuum lubricant, fully flooded inlet) holds.
    #[error(
        "{quantity} = {value:.3e} is outside the model's domain: allowed {allowed} ({reason})"
    )]
    OutsideModel {
        quantity: &'static str,
        value: f64,
        allowed: String,
        reason: &'static str,
    },
    /// A solver option is out of range.
    #[error("invalid option {field}: {message}")]
    InvalidOption {
        field: &'static str,
        message: String,
    },
    /// The Newton iteration (with continuation) did not meet the convergence criteria.
    #[error(
        "EHL solve did not converge ({reason}) after {iterations} iterations: \
         pressure change {pressure_change:e}, load error {load_error:e}, \
         Reynolds residual {reynolds_residual:e}"
    )]
    NotConverged {
        reason: &'static str,
        iterations: usize,
        pressure_change: f64,
        load_error: f64,
        reynolds_residual: f64,
    },
    /// The grid does not resolve the film: the estimated relative grid error of the raw h_c or
    /// h_min (fractions; infinite where the solve has a single level) exceeds `limit`.
    #[error(
        "the {nodes_x} × {nodes_y} grid does not resolve the film: estimated grid error h_c \
         {:.1} %, h_min {:.1} % above the {:.1} % bound",
        100.0 * central,
        100.0 * min,
        100.0 * limit
    )]
    GridTooCoarse {
        central: f64,
        min: f64,
        limit: f64,
        nodes_x: usize,
        nodes_y: usize,
    },
}

/// Solver options. `Default` is the accuracy-reference setting: Roelands, Dowson–Higginson,
/// elastic, default grid, docs/physics.md §5.2 tolerances, continuation allowed.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct SolverOptions {
    /// Pressure–viscosity law.
    pub viscosity: ViscosityLaw,
    /// Dowson–Higginson density (true) or incompressible.
    pub compressible: bool,
    /// Number of grid nodes (≥ 41).
    pub nodes: usize,
    /// Elastic deflection on (false: rigid surfaces, for limit studies).
    pub elastic: bool,
    /// Inlet end of the domain in units of b.
    pub x_start: f64,
    /// Outlet end of the domain in units of b.
    pub x_end: f64,
    /// Newton iteration limit per attempt.
    pub max_iterations: usize,
    /// Σ|ΔP|/ΣP tolerance (docs/physics.md §5.2: 10⁻⁵).
    pub pressure_tolerance: f64,
    /// Relative load-balance tolerance (docs/physics.md §5.2: 10⁻³).
    pub load_tolerance: f64,
    /// Allow continuation in α when the direct Hertz start fails.
    pub continuation: bool,
    /// Report h_c and h_min Richardson-extrapolated from the result grid and the
    /// half-resolution level of the grid sequence (raw values are kept in the solution).
    pub richardson: bool,
    /// Stop the grid sequence at the first level of ≥ 401 nodes whose estimated raw error
    /// |f_k − f_{k−1}|/3 is ≤ 1 % for h_c and ≤ 2 % for h_min (the result then has fewer than
    /// `nodes` nodes; `EhlSolution::nodes` says how many).
    pub adaptive: bool,
}

/// Default number of grid nodes (see the grid-refinement test for its accuracy).
pub const DEFAULT_NODES: usize = 801;

/// Node cap of [`SolverOptions::fast`] (no 801-node level: high-M cases lose accuracy and
/// robustness, see docs/ehl.md).
pub const FAST_NODES: usize = 401;

impl Default for SolverOptions {
    fn default() -> Self {
        Self {
            viscosity: ViscosityLaw::Roelands,
            compressible: true,
            nodes: DEFAULT_NODES,
            elastic: true,
            x_start: -4.5,
            x_end: 1.5,
            max_iterations: 60,
            pressure_tolerance: 1e-5,
            load_tolerance: 1e-3,
            continuation: true,
            richardson: true,
            adaptive: true,
        }
    }
}

/// The iteration limits every solver's options accept: at most 10 000 iterations, pressure
/// and load tolerances in (0, 0.1).
pub(crate) fn check_iteration(
    max_iterations: usize,
    pressure_tolerance: f64,
    load_tolerance: f64,
) -> Result<(), EhlError> {
    let bad = |field, message: &str| {
        Err(EhlError::InvalidOption {
            field,
            message: message.to_string(),
        })
    };
    if max_iterations == 0 || max_iterations > 10_000 {
        return bad("max_iterations", "must be in 1..=10000");
    }
    if !(pressure_tolerance > 0.0 && pressure_tolerance < 0.1) {
        return bad("pressure_tolerance", "must be in (0, 0.1)");
    }
    if !(load_tolerance > 0.0 && load_tolerance < 0.1) {
        return bad("load_tolerance", "must be in (0, 0.1)");
    }
    Ok(())
}

impl SolverOptions {
    /// The default physics with the grid sequence capped at 401 nodes (same median cost as the
    /// default on the bench's LHS samples, p95 about 3× lower; less accurate at high M, see
    /// docs/ehl.md).
    pub fn fast() -> Self {
        Self {
            nodes: FAST_NODES,
            ..Default::default()
        }
    }

    pub(crate) fn validate(&self) -> Result<(), EhlError> {
        let bad = |field, message: &str| {
            Err(EhlError::InvalidOption {
                field,
                message: message.to_string(),
            })
        };
        if !(41..=8193).contains(&self.nodes) {
            return bad("nodes", "must be in 41..=8193");
        }
        if !(self.x_start.is_finite() && self.x_start <= -1.5 && self.x_start >= -50.0) {
            return bad("x_start", "must be finite, in [-50, -1.5]");
        }
        if !(self.x_end.is_finite() && self.x_end >= 1.2 && self.x_end <= 10.0) {
            return bad("x_end", "must be finite, in [1.2, 10]");
        }
        check_iteration(
            self.max_iterations,
            self.pressure_tolerance,
            self.load_tolerance,
        )
    }

    fn grid_spec(&self, nodes: usize, thin_film: bool) -> GridSpec {
        let mut spec = if thin_film {
            GridSpec::thin_film(nodes - 1)
        } else {
            GridSpec::with_intervals(nodes - 1)
        };
        spec.x_start = self.x_start;
        spec.x_end = self.x_end;
        spec
    }
}

/// One-shot solve (builds a [`Solver`]; use the solver directly for many cases).
pub fn solve(case: &ContactCase, opts: &SolverOptions) -> Result<EhlSolution, EhlError> {
    Solver::new(*opts)?.solve(case)
}
