//! Full numerical solution of the isothermal, Newtonian, steady EHL line contact
//! (PHYSICS.md §5.2) — the accuracy reference of the project.
//!
//! Unknowns: the pressure at the nodes of a non-uniform grid over X = x/b ∈ [−4.5, 1.5]
//! ([`grid`]) and the rigid-body separation H₀. Equations: Reynolds with Roelands or Barus
//! viscosity and Dowson–Higginson density ([`rheology`]), the film equation with the log-kernel
//! deflection integrated exactly over each piecewise-linear element ([`kernel`]), the load
//! balance ∫P dX = π/2, and the Reynolds cavitation condition as the complementarity P ≥ 0.
//!
//! Method ([`newton`]): full Newton on (P, H₀) with the load row — the approach of Okamura and
//! Houpert & Hamrock (1986), which reached 4.8 GPa — with the cavitation handled by a primal–dual
//! active set (a semismooth Newton method), dense LU from `faer`, a backtracking line search,
//! a Hertz start, and continuation in the pressure–viscosity coefficient when the direct start
//! fails. Why this rather than
//! multigrid: the line contact has only a few hundred unknowns, a direct Newton converges
//! quadratically in ~5–15 iterations independent of load, and a dense LU of that size costs a few
//! milliseconds — well inside the budget — while Gauss–Seidel-type relaxations degrade at high
//! load (PHYSICS.md §5.2). Scaling: P itself is the unknown and η̄ enters only through
//! ε ∝ exp(−ln η̄), which underflows harmlessly in the contact; rows are equilibrated before the
//! factorisation, so η̄ spanning 20 (Roelands) or 100 (Barus) decades is harmless.
//!
//! Failure is explicit: [`solve`] returns [`EhlError::NotConverged`] with the residuals unless
//! both PHYSICS.md §5.2 criteria (Σ|ΔP|/ΣP ≤ 10⁻⁵ after a full Newton step with an unchanged
//! active set, and |∫P − π/2|/(π/2) ≤ 10⁻³) hold.
//!
//! Accuracy evidence (tests in [`tests_reference`], [`convergence`]; tables in docs/ehl.md):
//! grid refinement against Richardson extrapolation, the Hertz limit, Martin's rigid iso-viscous
//! limit, Moes' formula (Barus) and Pan–Hamrock's formulas (Roelands + DH).

pub mod case;
pub mod convergence;
pub mod formulas;
pub mod grid;
pub mod kernel;
pub mod lhs;
pub mod newton;
pub mod rheology;
pub mod solution;
#[cfg(test)]
mod tests_reference;

pub use case::ContactCase;
pub use rheology::ViscosityLaw;
pub use solution::{EhlSolution, Profile};

use grid::GridSpec;
use newton::{Limits, NewtonReport, NewtonWorkspace, Problem};
use rheology::Rheology;
use std::time::Instant;

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
}

/// Solver options. `Default` is the accuracy-reference setting: Roelands, Dowson–Higginson,
/// elastic, default grid, PHYSICS.md §5.2 tolerances, continuation allowed.
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
    /// Σ|ΔP|/ΣP tolerance (PHYSICS.md §5.2: 10⁻⁵).
    pub pressure_tolerance: f64,
    /// Relative load-balance tolerance (PHYSICS.md §5.2: 10⁻³).
    pub load_tolerance: f64,
    /// Allow continuation in α when the direct Hertz start fails.
    pub continuation: bool,
}

/// Default number of grid nodes (see the grid-refinement test for its accuracy).
pub const DEFAULT_NODES: usize = 801;

/// Node count of [`SolverOptions::fast`] (h_c error up to ~2.6 % at M ≈ 60, see docs/ehl.md).
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
        }
    }
}

impl SolverOptions {
    /// The default physics on the coarser 401-node grid (≈ 8× cheaper per Newton step).
    pub fn fast() -> Self {
        Self {
            nodes: FAST_NODES,
            ..Default::default()
        }
    }

    fn validate(&self) -> Result<(), EhlError> {
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
        if self.max_iterations == 0 || self.max_iterations > 10_000 {
            return bad("max_iterations", "must be in 1..=10000");
        }
        if !(self.pressure_tolerance > 0.0 && self.pressure_tolerance < 0.1) {
            return bad("pressure_tolerance", "must be in (0, 0.1)");
        }
        if !(self.load_tolerance > 0.0 && self.load_tolerance < 0.1) {
            return bad("load_tolerance", "must be in (0, 0.1)");
        }
        Ok(())
    }

    fn grid_spec(&self) -> GridSpec {
        let mut spec = GridSpec::with_intervals(self.nodes - 1);
        spec.x_start = self.x_start;
        spec.x_end = self.x_end;
        spec
    }
}

/// Reusable solver: grid, deflection matrix and all work storage are built once for the
/// options and reused by every [`Solver::solve`] (dataset generation, HIL re-solves).
pub struct Solver {
    opts: SolverOptions,
    ws: NewtonWorkspace,
}

impl Solver {
    /// Builds the workspace (grid, O(N²) kernel, N² Jacobian storage).
    pub fn new(opts: SolverOptions) -> Result<Self, EhlError> {
        opts.validate()?;
        Ok(Self {
            ws: NewtonWorkspace::new(&opts.grid_spec()),
            opts,
        })
    }

    /// The options this solver was built with.
    pub fn options(&self) -> &SolverOptions {
        &self.opts
    }

    /// Grid node coordinates X = x/b.
    pub fn nodes(&self) -> &[f64] {
        &self.ws.nodes
    }

    fn problem(&self, case: &ContactCase, speed_factor: f64) -> Problem {
        Problem {
            lambda_bar: case.lambda_bar() * speed_factor,
            rheology: Rheology::new(
                self.opts.viscosity,
                self.opts.compressible,
                case.hertz_pressure_pa(),
                case.pressure_viscosity_pa_inv,
                case.viscosity_pa_s,
            ),
            elastic: self.opts.elastic,
        }
    }

    fn limits(&self) -> Limits {
        Limits {
            max_iterations: self.opts.max_iterations,
            pressure_tolerance: self.opts.pressure_tolerance,
            load_tolerance: self.opts.load_tolerance,
        }
    }

    /// Start from Hertz with H(0) from Moes' formula at the (possibly scaled) speed.
    fn start(&mut self, case: &ContactCase, speed_factor: f64) {
        let mut c = *case;
        c.entrainment_speed_m_s *= speed_factor;
        let guess = if self.opts.elastic {
            formulas::moes_central_film_m(&c)
        } else {
            formulas::martin_gap_m(&c)
        };
        self.ws
            .start_hertz(self.opts.elastic, guess / case.film_scale_m());
    }

    /// Solves one case. Unconverged ⇒ [`EhlError::NotConverged`], never a result.
    pub fn solve(&mut self, case: &ContactCase) -> Result<EhlSolution, EhlError> {
        let t0 = Instant::now();
        let limits = self.limits();
        self.start(case, 1.0);
        let prob = self.problem(case, 1.0);
        let direct = self.ws.run(&prob, &limits);
        let mut iterations = direct.iterations;
        let report = if direct.converged || !self.opts.continuation {
            direct
        } else {
            let (r, it) = self.continue_in_alpha(case, &limits);
            iterations += it;
            r
        };
        if !report.converged {
            return Err(not_converged(&report, iterations));
        }
        Ok(EhlSolution::from_state(
            case,
            &self.opts,
            &self.ws,
            iterations,
            &report,
            t0.elapsed().as_secs_f64(),
        ))
    }

    /// Solves `case` warm-started from a previous solution of the same case (e.g. on a coarser
    /// grid), falling back to [`Solver::solve`] if that does not converge.
    pub fn solve_from(
        &mut self,
        case: &ContactCase,
        previous: &EhlSolution,
    ) -> Result<EhlSolution, EhlError> {
        let t0 = Instant::now();
        self.ws.start_from(
            &previous.profile.x,
            &previous.profile.pressure,
            previous.separation_dimensionless,
        );
        let report = self.ws.run(&self.problem(case, 1.0), &self.limits());
        if !report.converged {
            return self.solve(case);
        }
        Ok(EhlSolution::from_state(
            case,
            &self.opts,
            &self.ws,
            report.iterations,
            &report,
            t0.elapsed().as_secs_f64(),
        ))
    }

    /// Continuation in the pressure–viscosity coefficient: solve a mildly piezoviscous case
    /// (α scaled so that α p_h ≈ 4) from the Hertz start, then raise α to its value in
    /// geometric steps, each warm-started from the last; a failed step is retried with half the
    /// step. (Continuation in speed was tried first: it moves L = G(2U)^¼ the wrong way.)
    fn continue_in_alpha(&mut self, case: &ContactCase, limits: &Limits) -> (NewtonReport, usize) {
        let mut iterations = 0;
        let target = case.pressure_viscosity_pa_inv * case.hertz_pressure_pa();
        let mut last = NewtonReport {
            converged: false,
            iterations: 0,
            pressure_change: f64::NAN,
            load_error: f64::NAN,
            reynolds_residual: f64::NAN,
            reason: "continuation failed",
        };
        if target <= 4.0 {
            return (last, 0);
        }
        let with_alpha = |factor: f64| {
            let mut c = *case;
            c.pressure_viscosity_pa_inv *= factor;
            c
        };
        let mut level = (4.0 / target).ln();
        let c0 = with_alpha(level.exp());
        self.start(&c0, 1.0);
        let r = self.ws.run(&self.problem(&c0, 1.0), limits);
        iterations += r.iterations;
        if !r.converged {
            return (r, iterations);
        }
        let mut step = 0.6f64;
        let mut saved_p = self.ws.p.clone();
        let mut saved_h0 = self.ws.h0;
        while level < 0.0 {
            let next = (level + step).min(0.0);
            let c = with_alpha(next.exp());
            let r = self.ws.run(&self.problem(&c, 1.0), limits);
            iterations += r.iterations;
            if r.converged {
                level = next;
                saved_p.copy_from_slice(&self.ws.p);
                saved_h0 = self.ws.h0;
                step = (step * 1.5).min(1.2);
                if level == 0.0 {
                    return (r, iterations);
                }
            } else {
                self.ws.p.copy_from_slice(&saved_p);
                self.ws.h0 = saved_h0;
                step *= 0.5;
                last = r;
                if step < 0.02 {
                    break;
                }
            }
        }
        (last, iterations)
    }
}

fn not_converged(r: &NewtonReport, iterations: usize) -> EhlError {
    EhlError::NotConverged {
        reason: r.reason,
        iterations,
        pressure_change: r.pressure_change,
        load_error: r.load_error,
        reynolds_residual: r.reynolds_residual,
    }
}

/// One-shot solve (builds a [`Solver`]; use the solver directly for many cases).
pub fn solve(case: &ContactCase, opts: &SolverOptions) -> Result<EhlSolution, EhlError> {
    Solver::new(*opts)?.solve(case)
}
