//! The point-contact solve: Hertz start, Newton steps on the pressures and H₀ (the load
//! balance) on each grid level, and grid sequencing (each level started from the interpolated
//! solution of the level below).

use super::level::{Level, Problem};
use super::{formulas, PointContactCase, PointSolution};
use crate::rheology::{Rheology, ViscosityLaw};
use crate::EhlError;
use std::f64::consts::PI;
use std::time::Instant;

/// Dimensionless load ∫∫P dXdY of the Hertz pressure √(1 − X² − Y²): 2π/3.
pub const HERTZ_LOAD: f64 = 2.0 * PI / 3.0;

/// Relative residual to which GMRES solves each Newton system (inexact Newton: the outer
/// iteration still converges to the pressure tolerance in the measured 7–8 steps per level).
const KRYLOV_TOLERANCE: f64 = 1e-3;

/// Smallest relaxation of a Newton step.
const MIN_RELAXATION: f64 = 0.125;

/// Coarsest grid of the sequence (nodes across the rolling direction).
const COARSEST_NODES: usize = 33;

/// Most grid levels of the sequence.
const MAX_LEVELS: usize = 3;

/// Solver options. `Default` is the accuracy setting: Roelands, Dowson–Higginson, elastic,
/// 129 × 129 nodes at the finest level, X ∈ [−4.5, 1.5], Y ∈ [−3, 3].
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct PointSolverOptions {
    /// Pressure–viscosity law.
    pub viscosity: ViscosityLaw,
    /// Dowson–Higginson density (true) or incompressible.
    pub compressible: bool,
    /// Nodes per direction on the finest level (2ⁿ + 1, 17 ..= 513); across the rolling
    /// direction (Y) always, along it (X) unless `rolling_nodes` is set.
    pub nodes: usize,
    /// Nodes along the rolling direction X on the finest level (2ⁿ + 1, from `nodes` to
    /// 4·(nodes − 1) + 1 and at most 1025), None for `nodes`. A film that varies faster along X
    /// than across it — high M, and elliptical contacts, whose transverse flow is scaled by
    /// k⁻² — is resolved by a finer X spacing at less cost than a finer square grid
    /// (docs/point_contact.md).
    #[serde(default)]
    pub rolling_nodes: Option<usize>,
    /// Elastic deflection on (false: rigid surfaces, for limit studies).
    pub elastic: bool,
    /// Inlet end of the domain, X = x/b.
    pub x_start: f64,
    /// Outlet end of the domain, X = x/b.
    pub x_end: f64,
    /// Half-width of the domain across the rolling direction, Y = y/a.
    pub y_half: f64,
    /// Iteration limit per grid level.
    pub max_iterations: usize,
    /// Tolerance of the full Newton correction Σ|δP|/ΣP.
    pub pressure_tolerance: f64,
    /// Relative load-balance tolerance.
    pub load_tolerance: f64,
    /// Report h_c and h_min Richardson-extrapolated from the two finest levels.
    pub richardson: bool,
    /// Choose the finest grid from the case ([`grid_for_case`]) instead of `nodes` and
    /// `rolling_nodes` (which are then not used).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub grid_from_case: bool,
    /// Refuse ([`EhlError::GridTooCoarse`]) a solution whose estimated grid error of the raw
    /// h_c or h_min exceeds this fraction, or that has no estimate; None accepts every grid.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub max_grid_error: Option<f64>,
}

/// Default nodes per direction (the coarsest grid [`grid_for_case`] chooses).
pub const DEFAULT_POINT_NODES: usize = 129;

/// Default bound on the estimated grid error of the raw films (fraction): the Richardson value
/// reported is then within it of the grid-converged film (docs/point_contact.md).
pub const DEFAULT_MAX_GRID_ERROR: f64 = 0.02;

/// Estimated grid error of the raw films on the 129² grid per unit M/k, %: measured over the
/// table of docs/point_contact.md (h_c 0.031–0.040 % per unit M/k at k = 1–8, M = 20–2000; h_min
/// up to 1.3 times h_c at k ≤ 3 and 1.2 times at k = 8), the larger of the two.
const ERROR_PER_M_OVER_K_129: f64 = 0.045;

/// Predicted grid error (%) the grid of [`grid_for_case`] must meet: 1.5 %, a quarter below the
/// default bound for the scatter of the prediction (L = 4–15 moves it by ±20 % at k = 8).
const PREDICTED_ERROR_TARGET: f64 = 1.5;

/// Ellipticity from which 129 nodes across resolve the film (docs/point_contact.md: at k = 5.8
/// and 8 the 257² films equal the 257 × 129 ones; below, h_min's side lobes need Y nodes too).
const FINE_ACROSS_ELLIPTICITY: f64 = 5.8;

/// The finest grid (nodes along X, across) for a case of Moes' `m` and ellipticity `k`: the
/// fewest nodes along X of 129, 257, 513 whose predicted raw grid error
/// ERROR_PER_M_OVER_K_129 · (M/k) · (128/(n_x − 1))² % (second order) is within 1.5 %; as many
/// across below k = 5.8 (at most 257: 513² needs 2.2 GB), 129 across from it. So M/k ≤ 33 gives
/// 129², M/k ≤ 133 gives 257² (257 × 129 from k = 5.8), above it 513 × 257 (513 × 129).
pub fn grid_for_case(m: f64, k: f64) -> (usize, usize) {
    let predicted_129 = ERROR_PER_M_OVER_K_129 * m / k;
    let mut nx = DEFAULT_POINT_NODES;
    let mut predicted = predicted_129;
    while predicted > PREDICTED_ERROR_TARGET && nx < 513 {
        nx = 2 * (nx - 1) + 1;
        predicted /= 4.0;
    }
    let ny = if k >= FINE_ACROSS_ELLIPTICITY {
        DEFAULT_POINT_NODES
    } else {
        nx.min(257)
    };
    (nx, ny)
}

impl Default for PointSolverOptions {
    fn default() -> Self {
        Self {
            viscosity: ViscosityLaw::Roelands,
            compressible: true,
            nodes: DEFAULT_POINT_NODES,
            rolling_nodes: None,
            elastic: true,
            x_start: -4.5,
            x_end: 1.5,
            y_half: 3.0,
            max_iterations: 200,
            pressure_tolerance: 1e-4,
            load_tolerance: 1e-4,
            richardson: true,
            grid_from_case: true,
            max_grid_error: Some(DEFAULT_MAX_GRID_ERROR),
        }
    }
}

impl PointSolverOptions {
    fn validate(&self) -> Result<(), EhlError> {
        let bad = |field, message: &str| {
            Err(EhlError::InvalidOption {
                field,
                message: message.to_string(),
            })
        };
        let intervals = self.nodes.wrapping_sub(1);
        if !(17..=513).contains(&self.nodes) || !intervals.is_power_of_two() {
            return bad("nodes", "must be 2^n + 1 in 17..=513");
        }
        if let Some(nx) = self.rolling_nodes {
            let fits = nx >= self.nodes && nx <= 1025 && (nx - 1) <= 4 * intervals;
            if !(fits && (nx - 1).is_power_of_two()) {
                return bad(
                    "rolling_nodes",
                    "must be 2^n + 1, from nodes to 4 (nodes - 1) + 1, at most 1025",
                );
            }
        }
        // X = 0 and Y = 0 must be nodes on every level of the sequence.
        let on_grid = |start: f64, end: f64| {
            let f = -start / (end - start) * 16.0;
            (f - f.round()).abs() < 1e-9
        };
        if !(self.x_start.is_finite()
            && self.x_end.is_finite()
            && (-20.0..=-1.5).contains(&self.x_start)
            && (1.2..=10.0).contains(&self.x_end)
            && on_grid(self.x_start, self.x_end))
        {
            return bad(
                "x_start",
                "x_start in [-20, -1.5], x_end in [1.2, 10], with -x_start/(x_end - x_start) a multiple of 1/16",
            );
        }
        if !(self.y_half.is_finite() && (1.5..=20.0).contains(&self.y_half)) {
            return bad("y_half", "must be finite, in [1.5, 20]");
        }
        if let Some(e) = self.max_grid_error {
            if !(e.is_finite() && e > 0.0 && e < 1.0) {
                return bad("max_grid_error", "must be finite, in (0, 1)");
            }
        }
        crate::check_iteration(
            self.max_iterations,
            self.pressure_tolerance,
            self.load_tolerance,
        )
    }
}

/// Result of one level's iteration.
#[derive(Debug, Clone, Copy)]
pub(super) struct LevelReport {
    pub iterations: usize,
    pub pressure_change: f64,
    pub load_error: f64,
}

/// Solves `case` (see the module docs of [`super`]).
pub fn solve_point(
    case: &PointContactCase,
    opts: &PointSolverOptions,
) -> Result<PointSolution, EhlError> {
    opts.validate()?;
    let start = Instant::now();
    let hertz = case.hertz();
    let (b, k) = (hertz.semi_axis_rolling_m, hertz.ellipticity);
    let ph = hertz.max_pressure_pa;
    let rx = case.radius_x_m;
    let problem = Problem {
        lambda: 12.0 * case.viscosity_pa_s * case.entrainment_speed_m_s * rx * rx
            / (b.powi(3) * ph),
        rheology: Rheology::new(
            opts.viscosity,
            opts.compressible,
            ph,
            case.pressure_viscosity_pa_inv,
            case.viscosity_pa_s,
        ),
        transverse_curvature: k * k * rx / case.radius_y_m,
        transverse_flow: 1.0 / (k * k),
        elastic: opts.elastic,
    };
    let film_scale = b * b / rx;
    let deflection_scale = 2.0 * ph * rx / (PI * case.reduced_modulus_pa * b);
    let (nx, ny) = if opts.grid_from_case {
        grid_for_case(case.moes_m(), k)
    } else {
        (opts.rolling_nodes.unwrap_or(opts.nodes), opts.nodes)
    };
    let counts = level_sizes(nx, ny);
    let domain = (opts.x_start, opts.x_end, opts.y_half);
    let mut previous: Option<Level> = None;
    let mut films: Vec<(f64, f64)> = Vec::new();
    let mut iterations = 0;
    let mut report = None;
    for &(nx, ny) in &counts {
        let mut level = Level::new(nx, ny, domain, k, deflection_scale)?;
        match &previous {
            Some(coarse) => interpolate(coarse, &mut level),
            None => start_hertz(&mut level, &problem, case, opts, film_scale),
        }
        let r = iterate(&mut level, &problem, opts)?;
        iterations += r.iterations;
        films.push(central_and_min(&level));
        report = Some(r);
        previous = Some(level);
    }
    let (level, report) = match (previous, report) {
        (Some(l), Some(r)) => (l, r),
        _ => unreachable!("at least one level"),
    };
    let solution = PointSolution::new(
        case,
        opts,
        &level,
        &films,
        iterations,
        report,
        film_scale,
        start.elapsed().as_secs_f64(),
    );
    if let Some(limit) = opts.max_grid_error {
        let (central, min) = solution
            .grid_error_estimate
            .unwrap_or((f64::INFINITY, f64::INFINITY));
        if !(central <= limit && min <= limit) {
            return Err(EhlError::GridTooCoarse {
                central,
                min,
                limit,
                nodes_x: level.nx,
                nodes_y: level.ny,
            });
        }
    }
    Ok(solution)
}

/// Grid sizes (nodes along X, across), coarsest first: the finest (nx, ny) and the grids
/// below it, each with half the X intervals while nx > ny and half of both once the grid is
/// square, down to [`COARSEST_NODES`] across or [`MAX_LEVELS`] levels, whichever comes
/// first. Either way the two finest levels differ by a halving (of ΔX alone on a grid finer
/// along X), so the Richardson factor 4 of the second-order scheme holds for the refined
/// direction; halving ΔY too on a rectangular grid would put a grid too coarse across on the
/// level below (measured at k = 8, M = 2000: h_min on 129 × 65 nodes is 7 % off the 257 × 129
/// value, which spoils its extrapolation, docs/point_contact.md). The level limit keeps the
/// coarsest spacing within 4× of the finest, so that a large domain whose film the finest grid
/// resolves is not started on a grid too coarse to carry the load with a positive film
/// (measured: a rigid iso-viscous case on X ∈ [−18, 6] at 257² fails to converge from 33²).
fn level_sizes(nx: usize, ny: usize) -> Vec<(usize, usize)> {
    let mut counts = vec![(nx, ny)];
    while counts.len() < MAX_LEVELS && counts[counts.len() - 1].1 > COARSEST_NODES {
        let (x, y) = counts[counts.len() - 1];
        let half = |n: usize| (n - 1) / 2 + 1;
        counts.push(if x > y {
            (half(x), y)
        } else {
            (half(x), half(y))
        });
    }
    counts.reverse();
    counts
}

/// Hertz pressure and H₀ such that the centre film is the Nijenbanning–Venner–Moes estimate
/// (elastic), or zero pressure and the Brewe–Hamrock–Taylor gap (rigid).
fn start_hertz(
    level: &mut Level,
    problem: &Problem,
    case: &PointContactCase,
    opts: &PointSolverOptions,
    film_scale: f64,
) {
    let nx = level.nx;
    for j in 1..level.ny - 1 {
        for i in 1..nx - 1 {
            let r2 = level.x[i] * level.x[i] + level.y[j] * level.y[j];
            level.p[j * nx + i] = if opts.elastic {
                (1.0 - r2).max(0.0).sqrt()
            } else {
                0.0
            };
        }
    }
    let guess = if opts.elastic {
        formulas::nijenbanning_central_film_m(case)
    } else {
        formulas::brewe_hamrock_taylor_min_film_m(case)
    } / film_scale;
    level.h0 = 0.0;
    level.evaluate(problem);
    let centre = centre_index(level);
    level.h0 = guess - level.h[centre];
}

fn centre_index(level: &Level) -> usize {
    let i = level
        .x
        .iter()
        .position(|x| x.abs() < 1e-9)
        .unwrap_or(level.nx / 2);
    (level.ny / 2) * level.nx + i
}

/// Bilinear interpolation of P (and H₀) from the level below, which has half the intervals
/// along X and half or the same number across.
fn interpolate(coarse: &Level, fine: &mut Level) {
    let (cn, fnx) = (coarse.nx, fine.nx);
    let across = (fine.ny - 1) / (coarse.ny - 1);
    for j in 0..fine.ny {
        let (cj, rj) = (j / across, j % across);
        for i in 0..fnx {
            let (ci, ri) = (i / 2, i % 2);
            let at = |a: usize, b: usize| coarse.p[(cj + b) * cn + ci + a];
            fine.p[j * fnx + i] = match (ri, rj) {
                (0, 0) => at(0, 0),
                (1, 0) => 0.5 * (at(0, 0) + at(1, 0)),
                (0, _) => 0.5 * (at(0, 0) + at(0, 1)),
                _ => 0.25 * (at(0, 0) + at(1, 0) + at(0, 1) + at(1, 1)),
            };
        }
    }
    fine.h0 = coarse.h0;
}

/// Newton steps on P and H₀ (relaxed only where the correction grows) until both tolerances
/// hold.
fn iterate(
    level: &mut Level,
    problem: &Problem,
    opts: &PointSolverOptions,
) -> Result<LevelReport, EhlError> {
    let mut p_old = vec![0.0; level.p.len()];
    let (mut pressure_change, mut load_error) = (f64::INFINITY, f64::INFINITY);
    let mut omega = 1.0;
    for it in 1..=opts.max_iterations {
        level.evaluate(problem);
        level.newton_correction(problem, HERTZ_LOAD, KRYLOV_TOLERANCE)?;
        p_old.copy_from_slice(&level.p);
        let unknowns = level.correction.len() - 1;
        for u in 0..unknowns {
            let m = level.node_of(u);
            level.p[m] = (p_old[m] + omega * level.correction[u]).max(0.0);
        }
        level.h0 += omega * level.correction[unknowns];
        let total: f64 = level.p.iter().sum();
        let change: f64 = level.p.iter().zip(&p_old).map(|(a, b)| (a - b).abs()).sum();
        // The size of the full correction, whatever the relaxation.
        let previous_change = pressure_change;
        pressure_change = if total > 0.0 {
            change / (total * omega)
        } else {
            1.0
        };
        // Halve the relaxation where the correction grows (the active set flipping between
        // two states near the cavitation boundary), grow it back otherwise.
        omega = if pressure_change > previous_change {
            (0.5 * omega).max(MIN_RELAXATION)
        } else {
            (2.0 * omega).min(1.0)
        };
        load_error = level.load() / HERTZ_LOAD - 1.0;
        if pressure_change <= opts.pressure_tolerance && load_error.abs() <= opts.load_tolerance {
            level.evaluate(problem);
            return Ok(LevelReport {
                iterations: it,
                pressure_change,
                load_error: load_error.abs(),
            });
        }
        if !(pressure_change.is_finite() && level.h0.is_finite()) {
            break;
        }
    }
    Err(EhlError::NotConverged {
        reason: "point contact: iteration limit on a grid level",
        iterations: opts.max_iterations,
        pressure_change,
        load_error,
        reynolds_residual: level.residual_norm(),
    })
}

/// Centre film H(0, 0) and the minimum film (smallest nodal H refined by a parabola along X
/// and along Y), dimensionless.
pub(super) fn central_and_min(level: &Level) -> (f64, f64) {
    let centre = level.h[centre_index(level)];
    let nx = level.nx;
    let (mut imin, mut hmin) = (0, f64::INFINITY);
    for j in 1..level.ny - 1 {
        for i in 1..nx - 1 {
            let v = level.h[j * nx + i];
            if v < hmin {
                hmin = v;
                imin = j * nx + i;
            }
        }
    }
    let drop = |a: f64, b: f64| {
        let curvature = a - 2.0 * hmin + b;
        if curvature > 0.0 {
            (b - a) * (b - a) / (8.0 * curvature)
        } else {
            0.0
        }
    };
    let h = &level.h;
    let refined = hmin - drop(h[imin - 1], h[imin + 1]) - drop(h[imin - nx], h[imin + nx]);
    (centre, refined.min(centre))
}
