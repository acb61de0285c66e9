//! The solve driver: grid sequencing (nested iteration), Hertz start and continuation.
//!
//! Why grid sequencing: the Newton iteration is quadratic once close, but from the Hertz start it
//! needs tens of damped iterations to build the inlet, the outlet spike and — above all — to move
//! the cavitation boundary, which the active set shifts by about one node per iteration. Doing
//! that work on a coarse grid (≥ 101 nodes, LU cost 1/64 of the 4× finer grid) and interpolating
//! the converged pressure and H₀ to the next grid (intervals doubled, same grid family) leaves the
//! fine grids only a few quadratic iterations — the classical nested iteration (Venner &
//! Lubrecht 2000, ch. 3 "FMG"). A level that does not converge from the interpolated start is
//! re-solved directly from the Hertz start with continuation, so sequencing never costs
//! robustness.

use super::newton::{Limits, NewtonReport, NewtonWorkspace, Problem};
use super::rheology::Rheology;
use super::{formulas, ContactCase, EhlError, EhlSolution, SolverOptions};
use std::time::Instant;

/// Coarsest grid of the sequence (nodes).
const COARSEST_NODES: usize = 101;
/// Smallest grid a result may come from when `adaptive` stops early.
const MIN_RESULT_NODES: usize = 401;
/// Moes central film (Hertz units H = hR/b²) below which the thin-film grid family is used.
const THIN_FILM: f64 = 4e-3;
/// Adaptive stop: estimated raw relative error of h_c (h_min: twice this) on the result level.
const ADAPTIVE_TOLERANCE: f64 = 0.01;

/// Reusable solver: grids, deflection matrices and all work storage are built once for the
/// options and reused by every [`Solver::solve`] (dataset generation, HIL re-solves).
pub struct Solver {
    opts: SolverOptions,
    /// Grid levels of the family in use, coarsest first; the last one has `opts.nodes` nodes.
    levels: Vec<NewtonWorkspace>,
    /// The same levels in the other grid family (standard / thin-film, see
    /// [`Solver::select_family`]); swapped with `levels` when a case needs the other one.
    other_levels: Vec<NewtonWorkspace>,
    /// Whether `levels` is the thin-film family.
    thin_film: bool,
    /// Saved pressure for continuation restarts (allocated once).
    saved_p: Vec<f64>,
}

impl Solver {
    /// Builds all grid levels (O(N²) kernels, N² Jacobian storage).
    pub fn new(opts: SolverOptions) -> Result<Self, EhlError> {
        opts.validate()?;
        let mut counts = vec![opts.nodes];
        loop {
            let intervals = counts[counts.len() - 1] - 1;
            if intervals % 2 != 0 || intervals / 2 + 1 < COARSEST_NODES {
                break;
            }
            counts.push(intervals / 2 + 1);
        }
        counts.reverse();
        let family = |thin| -> Vec<NewtonWorkspace> {
            counts
                .iter()
                .map(|&n| NewtonWorkspace::new(&opts.grid_spec(n, thin)))
                .collect()
        };
        Ok(Self {
            saved_p: vec![0.0; opts.nodes],
            levels: family(false),
            other_levels: family(true),
            thin_film: false,
            opts,
        })
    }

    /// The options this solver was built with.
    pub fn options(&self) -> &SolverOptions {
        &self.opts
    }

    /// Grid node coordinates X = x/b of the finest (result) grid of the family in use (that of
    /// the last solve; the standard family before any).
    pub fn nodes(&self) -> &[f64] {
        &self.finest().nodes
    }

    fn finest(&self) -> &NewtonWorkspace {
        &self.levels[self.levels.len() - 1]
    }

    fn problem(&self, case: &ContactCase) -> Problem {
        Problem {
            lambda_bar: case.lambda_bar(),
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

    /// Hertz start on level `k` with H(0) from Moes' formula (Martin's gap when rigid).
    fn start_hertz(&mut self, k: usize, case: &ContactCase) {
        let guess = if self.opts.elastic {
            formulas::moes_central_film_m(case)
        } else {
            formulas::martin_gap_m(case)
        };
        let elastic = self.opts.elastic;
        self.levels[k].start_hertz(elastic, guess / case.film_scale_m());
    }

    /// Domain stretch for a case: the fully flooded inlet must reach about 10·√H_c (in units
    /// of b; there the rigid-inlet pressure of Martin's solution has decayed to ~0.3 % of its
    /// peak, since it falls as (x/√(2Rh))⁻³), which exceeds 4.5 b when the film is thick
    /// compared with the elastic deflection (M ≲ 3). Below that the configured domain is used
    /// unchanged; above, the whole grid is stretched by s (docs/physics.md §5.2 fixes [−4.5, 1.5]
    /// for the elastic regime only).
    fn domain_scale(&self, case: &ContactCase) -> f64 {
        let h_c = if self.opts.elastic {
            formulas::moes_central_film_m(case)
        } else {
            formulas::martin_gap_m(case)
        } / case.film_scale_m();
        (10.0 * h_c.sqrt() / -self.opts.x_start).clamp(1.0, 20.0)
    }

    /// Picks the grid family for a case: the thin-film family (extra nodes at the contact
    /// edges, [`super::grid::GridSpec::thin_film`]) when Moes' central film is below
    /// [`THIN_FILM`] in Hertz units, else the standard one. Swaps storage, no allocation.
    fn select_family(&mut self, case: &ContactCase) {
        let thin = self.opts.elastic
            && formulas::moes_central_film_m(case) / case.film_scale_m() < THIN_FILM;
        if thin != self.thin_film {
            std::mem::swap(&mut self.levels, &mut self.other_levels);
            self.thin_film = thin;
        }
    }

    /// Solves one case. Unconverged ⇒ [`EhlError::NotConverged`], never a result.
    ///
    /// The grid family is chosen by `Solver::select_family`; if the solve fails on it, it is
    /// repeated on the other family (a thin film that the edge-refined grid cannot start from
    /// the Hertz pressure may still converge on the standard grid, and vice versa).
    pub fn solve(&mut self, case: &ContactCase) -> Result<EhlSolution, EhlError> {
        let t0 = Instant::now();
        self.select_family(case);
        let first = self.solve_on_family(case, t0);
        if first.is_ok() {
            return first;
        }
        std::mem::swap(&mut self.levels, &mut self.other_levels);
        self.thin_film = !self.thin_film;
        self.solve_on_family(case, t0).or(first)
    }

    /// Grid sequence on the family in `levels`.
    fn solve_on_family(
        &mut self,
        case: &ContactCase,
        t0: Instant,
    ) -> Result<EhlSolution, EhlError> {
        let scale = self.domain_scale(case);
        self.levels
            .iter_mut()
            .for_each(|l| l.set_domain_scale(scale));
        let mut iterations = 0;
        let mut report = self.solve_from_hertz(0, case, &mut iterations);
        // h_c, h_min of the level below the result level, when reached by sequencing.
        let mut coarse = None;
        let last = self.levels.len() - 1;
        let mut result_level = last;
        for k in 1..=last {
            if !report.converged {
                // The coarser grid could not represent this case (thin film at high M): start
                // afresh on this level.
                coarse = None;
                report = self.solve_from_hertz(k, case, &mut iterations);
                continue;
            }
            let (lo, hi) = self.levels.split_at_mut(k);
            let prev = &lo[k - 1];
            let (_, hmin) = super::solution::min_film(&prev.nodes, &prev.h);
            coarse = Some((prev.central_film(self.opts.elastic), hmin));
            hi[0].start_from(&prev.nodes, &prev.p, prev.h0);
            let (prob, limits) = (self.problem(case), self.limits());
            report = self.levels[k].run(&prob, &limits);
            iterations += report.iterations;
            if !report.converged {
                coarse = None;
                report = self.solve_from_hertz(k, case, &mut iterations);
                continue;
            }
            // Adaptive stop: the raw error of this level, estimated as |f_k − f_{k−1}|/3
            // (order 2), is within the target, so the extrapolated value is well inside it.
            if let (true, Some((hc_half, hmin_half))) = (self.opts.adaptive, coarse) {
                let ws = &self.levels[k];
                let hc = ws.central_film(self.opts.elastic);
                let (_, hm) = super::solution::min_film(&ws.nodes, &ws.h);
                let est_c = ((hc - hc_half) / hc).abs() / 3.0;
                let est_m = ((hm - hmin_half) / hm).abs() / 3.0;
                if ws.len() >= MIN_RESULT_NODES
                    && est_c <= ADAPTIVE_TOLERANCE
                    && est_m <= 2.0 * ADAPTIVE_TOLERANCE
                {
                    result_level = k;
                    break;
                }
            }
        }
        if !report.converged {
            coarse = None;
        }
        self.finish(case, report, iterations, t0, coarse, result_level)
    }

    /// Solves `case` on the finest grid warm-started from a previous solution (of this or a
    /// nearby case, any grid), falling back to [`Solver::solve`] if that does not converge.
    pub fn solve_from(
        &mut self,
        case: &ContactCase,
        previous: &EhlSolution,
    ) -> Result<EhlSolution, EhlError> {
        let t0 = Instant::now();
        self.select_family(case);
        let scale = self.domain_scale(case);
        self.levels
            .iter_mut()
            .for_each(|l| l.set_domain_scale(scale));
        let k = self.levels.len() - 1;
        self.levels[k].start_from(
            &previous.profile.x,
            &previous.profile.pressure,
            previous.separation_dimensionless,
        );
        let (prob, limits) = (self.problem(case), self.limits());
        let report = self.levels[k].run(&prob, &limits);
        if !report.converged {
            return self.solve(case);
        }
        self.finish(case, report, report.iterations, t0, None, k)
    }

    fn finish(
        &self,
        case: &ContactCase,
        report: NewtonReport,
        iterations: usize,
        t0: Instant,
        coarse: Option<(f64, f64)>,
        level: usize,
    ) -> Result<EhlSolution, EhlError> {
        if !report.converged {
            return Err(EhlError::NotConverged {
                reason: report.reason,
                iterations,
                pressure_change: report.pressure_change,
                load_error: report.load_error,
                reynolds_residual: report.reynolds_residual,
            });
        }
        Ok(EhlSolution::from_state(
            case,
            &self.opts,
            &self.levels[level],
            iterations,
            &report,
            t0.elapsed().as_secs_f64(),
            coarse,
        ))
    }

    /// Direct solve on level `k` from the Hertz start, with continuation in α on failure.
    fn solve_from_hertz(
        &mut self,
        k: usize,
        case: &ContactCase,
        iterations: &mut usize,
    ) -> NewtonReport {
        self.start_hertz(k, case);
        let prob = self.problem(case);
        let limits = self.limits();
        let direct = self.levels[k].run(&prob, &limits);
        *iterations += direct.iterations;
        if direct.converged || !self.opts.continuation {
            return direct;
        }
        self.continue_in_alpha(k, case, iterations)
    }

    /// Continuation in the pressure–viscosity coefficient on level `k`: solve a mildly
    /// piezoviscous case (α scaled so that α p_h = 4) from the Hertz start, then raise α to its
    /// value in geometric steps, each warm-started from the last; a failed step is retried with
    /// half the step. (Continuation in speed was tried first: it moves L = G(2U)^¼ the wrong
    /// way.)
    fn continue_in_alpha(
        &mut self,
        k: usize,
        case: &ContactCase,
        iterations: &mut usize,
    ) -> NewtonReport {
        let limits = self.limits();
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
            return last;
        }
        let with_alpha = |factor: f64| {
            let mut c = *case;
            c.pressure_viscosity_pa_inv *= factor;
            c
        };
        let mut level = (4.0 / target).ln();
        let c0 = with_alpha(level.exp());
        self.start_hertz(k, &c0);
        let prob = self.problem(&c0);
        let r = self.levels[k].run(&prob, &limits);
        *iterations += r.iterations;
        if !r.converged {
            return r;
        }
        let n = self.levels[k].len();
        let mut step = 0.6f64;
        self.saved_p[..n].copy_from_slice(&self.levels[k].p);
        let mut saved_h0 = self.levels[k].h0;
        while level < 0.0 {
            let next = (level + step).min(0.0);
            let prob = self.problem(&with_alpha(next.exp()));
            let r = self.levels[k].run(&prob, &limits);
            *iterations += r.iterations;
            if r.converged {
                level = next;
                self.saved_p[..n].copy_from_slice(&self.levels[k].p);
                saved_h0 = self.levels[k].h0;
                step = (step * 1.5).min(1.2);
                if level == 0.0 {
                    return r;
                }
            } else {
                self.levels[k].p.copy_from_slice(&self.saved_p[..n]);
                self.levels[k].h0 = saved_h0;
                step *= 0.5;
                last = r;
                if step < 0.02 {
                    break;
                }
            }
        }
        last
    }
}
