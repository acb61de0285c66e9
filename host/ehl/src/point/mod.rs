//! Full numerical solution of the isothermal, Newtonian, steady EHL point contact, circular
//! and elliptical — the accuracy reference for ball-bearing contacts.
//!
//! Unknowns: the pressure at the nodes of a uniform grid over X = x/b ∈ [−4.5, 1.5],
//! Y = y/a ∈ [−3, 3] (b the Hertz semi-axis along the rolling direction, a across it; [`hertz`])
//! and the rigid-body separation H₀. Equations (`level`): Reynolds in 2D with Roelands or
//! Barus viscosity and Dowson–Higginson density (the rheology of the line contact,
//! crate::rheology), the film equation with the exact elastic half-space deflection of
//! piecewise-constant pressure (Love's rectangle coefficients, applied by zero-padded FFT;
//! [`deflection`]), the Reynolds cavitation condition P ≥ 0 and the load balance
//! ∫∫P dXdY = 2π/3.
//!
//! Method ([`solver`], `level`, `linearised`, `gmres`): Newton on the pressures and H₀
//! together (the load balance is the last equation), with the Reynolds cavitation condition by
//! a primal–dual active set, a Hertz start with H₀ set from the Nijenbanning–Venner–Moes film,
//! and grid sequencing 33² → 65² → 129² (at most three levels, each started from the bilinear
//! interpolation of the one below; a grid finer along X, e.g. 257 × 129, is reached by halving
//! ΔX alone, `solver::level_sizes`). Each Newton system is solved by GMRES with the exact Jacobian applied
//! matrix-free (its deflection part by FFT) and preconditioned by the sparse LU (faer) of the
//! semi-system Jacobian, which keeps the deflection coupling within ±2 × ±1 nodes; the step is
//! relaxed only where the correction grows. h_c and h_min are reported Richardson-extrapolated
//! from the two finest levels (raw values kept). At default settings the finest grid is chosen
//! from the case (`solver::grid_for_case`, 129² to 513 × 257 by M/k) and a result whose
//! estimated raw grid error exceeds 2 % is refused (`EhlError::GridTooCoarse`). Cost and
//! accuracy are measured in docs/point_contact.md.
//!
//! Why not Venner–Lubrecht multigrid (yet): the Newton–Krylov route reuses the line contact's
//! faer LU and active-set approach; on fine grids the numeric LU of the preconditioner is most
//! of the time (≈ 60 % of the profile samples of a 513² solve, which peaks at 2.3 GB), so
//! multilevel multi-integration with an FAS line-relaxation solve (Venner & Lubrecht, 2000) is
//! the known way to the fine grids' cost; it is not implemented. Reusing one LU over several
//! Newton steps was measured and rejected (docs/point_contact.md).

pub mod case;
pub mod deflection;
pub mod formulas;
mod gmres;
pub mod hertz;
mod level;
mod linearised;
pub mod solver;
#[cfg(test)]
mod tests;

pub use case::PointContactCase;
pub use hertz::HertzEllipse;
pub use solver::{
    grid_for_case, solve_point, PointSolverOptions, DEFAULT_MAX_GRID_ERROR, DEFAULT_POINT_NODES,
    HERTZ_LOAD,
};

use level::Level;
use solver::LevelReport;

/// Pressure and film maps of a solution (dimensionless: X = x/b, Y = y/a, P = p/p_h,
/// H = hR_x/b²), row-major with X fastest.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct PointMaps {
    pub x: Vec<f64>,
    pub y: Vec<f64>,
    pub pressure: Vec<f64>,
    pub film: Vec<f64>,
}

/// Result of a converged point-contact solve (SI unless stated).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct PointSolution {
    /// The case solved.
    pub case: PointContactCase,
    /// The Hertz contact.
    pub hertz: HertzEllipse,
    /// Film at the contact centre, m (Richardson-extrapolated when `richardson`).
    pub central_film_m: f64,
    /// Minimum film, m (extrapolated like `central_film_m`).
    pub min_film_m: f64,
    /// h_c on the finest grid itself, m.
    pub central_film_raw_m: f64,
    /// h_min on the finest grid itself, m.
    pub min_film_raw_m: f64,
    /// Whether h_c and h_min are extrapolated (f + (f − f_½)/3, formal order 2).
    pub richardson: bool,
    /// Estimated relative error of the raw h_c and h_min, |f − f_½|/(3f), from the level
    /// below (None with a single level); on a grid finer along X than across, the level below
    /// has half the X intervals only, and this is the error of the X spacing.
    pub grid_error_estimate: Option<(f64, f64)>,
    /// Maximum pressure, Pa.
    pub max_pressure_pa: f64,
    /// Maximum Hertz pressure p_h, Pa.
    pub hertz_pressure_pa: f64,
    /// Iterations over all levels.
    pub iterations: usize,
    /// Last Σ|ΔP|/ΣP.
    pub pressure_change: f64,
    /// |∫∫P − 2π/3|/(2π/3).
    pub load_error: f64,
    /// Nodes of the finest grid (along X times across).
    pub nodes: usize,
    /// Wall time, s.
    pub wall_time_s: f64,
    /// The maps on the finest grid.
    pub maps: PointMaps,
}

impl PointSolution {
    #[allow(clippy::too_many_arguments)]
    fn new(
        case: &PointContactCase,
        opts: &PointSolverOptions,
        level: &Level,
        films: &[(f64, f64)],
        iterations: usize,
        report: LevelReport,
        film_scale: f64,
        wall_time_s: f64,
    ) -> Self {
        let hertz = case.hertz();
        let (hc, hmin) = films[films.len() - 1];
        let half = (films.len() >= 2).then(|| films[films.len() - 2]);
        let grid_error_estimate =
            half.map(|(c, m)| (((hc - c) / hc).abs() / 3.0, ((hmin - m) / hmin).abs() / 3.0));
        let extrapolated = half.filter(|_| opts.richardson).and_then(|(c, m)| {
            let ok = |f: f64, g: f64| g > 0.0 && ((f - g) / f).abs() < 0.3;
            (ok(hc, c) && ok(hmin, m)).then(|| (hc + (hc - c) / 3.0, hmin + (hmin - m) / 3.0))
        });
        let (hc_out, hmin_out) = extrapolated.unwrap_or((hc, hmin));
        let pmax = level.p.iter().cloned().fold(0.0, f64::max);
        Self {
            case: *case,
            hertz,
            central_film_m: hc_out * film_scale,
            min_film_m: hmin_out * film_scale,
            central_film_raw_m: hc * film_scale,
            min_film_raw_m: hmin * film_scale,
            richardson: extrapolated.is_some(),
            grid_error_estimate,
            max_pressure_pa: pmax * hertz.max_pressure_pa,
            hertz_pressure_pa: hertz.max_pressure_pa,
            iterations,
            pressure_change: report.pressure_change,
            load_error: report.load_error,
            nodes: level.nx * level.ny,
            wall_time_s,
            maps: PointMaps {
                x: level.x.clone(),
                y: level.y.clone(),
                pressure: level.p.clone(),
                film: level.h.clone(),
            },
        }
    }
}
