//! How far a `bearing ehl solve` result can be trusted: the case must lie in the domain where
//! the solver's model holds (`bearing_ehl::domain`), and the result grid must resolve it — its
//! estimated grid error (`bearing_ehl::convergence::grid_error_estimate`) at most
//! [`GRID_ERROR_LIMIT`], else the result is refused with the `--nodes` that would do.

use anyhow::{anyhow, bail, Result};
use bearing_ehl::{self as ehl, ContactCase, EhlSolution, SolverOptions};

/// Largest estimated relative grid error of h_c or h_min a result is given with.
pub const GRID_ERROR_LIMIT: f64 = 0.1;

/// Solves `case`, refusing it outside the model's domain (naming `flags`, the flags that set
/// the case) or when the grid of `--nodes` is too coarse for it; the solver's own refusals go
/// through `solver_error` (which names the flags). The solution carries its grid-error
/// estimate.
pub fn solve(
    case: &ContactCase,
    opts: &SolverOptions,
    flags: &str,
    solver_error: impl Fn(ehl::EhlError) -> anyhow::Error,
) -> Result<EhlSolution> {
    let domain = |e: ehl::EhlError| anyhow!("{e}; the case is set by {flags}");
    ehl::domain::check_case(case, opts).map_err(domain)?;
    let mut sol = ehl::solve(case, opts).map_err(solver_error)?;
    ehl::domain::check_solution(&sol, opts).map_err(domain)?;
    let estimate = ehl::convergence::grid_error_estimate(&sol, opts)
        .map_err(|e| anyhow!("grid-error estimate on {} nodes: {e}", 2 * sol.nodes - 1))?;
    if estimate.largest() > GRID_ERROR_LIMIT {
        bail!(
            "--nodes {}: the grid is too coarse for this case (M = {:.3}, L = {:.3}): estimated grid error of h_c {:.1} %, h_min {:.1} % (from the {}-node grid), allowed ≤ {:.0} %; use --nodes {} or more (41..=8193)",
            opts.nodes,
            case.moes_m(),
            case.moes_l(),
            100.0 * estimate.central_film,
            100.0 * estimate.min_film,
            estimate.other_nodes,
            100.0 * GRID_ERROR_LIMIT,
            (4 * (sol.nodes - 1) + 1).min(8193)
        );
    }
    sol.grid_error_estimate = Some(estimate);
    Ok(sol)
}
