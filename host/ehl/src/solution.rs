//! A converged EHL solution: the film and pressure figures everybody uses, the profiles and
//! how the solve went.

use super::newton::{NewtonReport, NewtonWorkspace};
use super::{ContactCase, SolverOptions};
use std::io::Write;

/// Dimensionless profiles on the grid: X = x/b, P = p/p_h, H = hR/b².
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Profile {
    pub x: Vec<f64>,
    pub pressure: Vec<f64>,
    pub film: Vec<f64>,
}

/// Estimated relative grid error of the raw films on the result grid: |f − f′|/(3f) from the
/// solution f′ on the grid with every spacing doubled, the formal order 2 of the scheme
/// (Roache 1998 §5.4; the refinement study of [`super::convergence`] measures p ≈ 1.8–2.1).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct GridErrorEstimate {
    /// Of h_c.
    pub central_film: f64,
    /// Of h_min.
    pub min_film: f64,
    /// Node count of the other grid the estimate comes from.
    pub other_nodes: usize,
}

impl GridErrorEstimate {
    /// From the films (h_c, h_min) on the result grid and on the half-resolution grid.
    pub fn from_half_grid(fine: (f64, f64), half: (f64, f64), half_nodes: usize) -> Self {
        let relative = |f: f64, g: f64| ((f - g) / f).abs() / 3.0;
        Self {
            central_film: relative(fine.0, half.0),
            min_film: relative(fine.1, half.1),
            other_nodes: half_nodes,
        }
    }

    /// From the films (h_c, h_min) on the result grid and on the grid with every spacing
    /// halved: with f − f* ≈ C h², f − f_fine ≈ ¾ C h², so f's error is ⁴⁄₃ |f − f_fine|.
    pub fn from_double_grid(result: (f64, f64), fine: (f64, f64), fine_nodes: usize) -> Self {
        let relative = |f: f64, g: f64| 4.0 * ((f - g) / f).abs() / 3.0;
        Self {
            central_film: relative(result.0, fine.0),
            min_film: relative(result.1, fine.1),
            other_nodes: fine_nodes,
        }
    }

    /// The larger of the two.
    pub fn largest(&self) -> f64 {
        self.central_film.max(self.min_film)
    }
}

/// Result of a converged solve (SI unless stated).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct EhlSolution {
    /// The case solved.
    pub case: ContactCase,
    /// Film at X = 0 (h_c), m. Richardson-extrapolated from this grid and the half-resolution
    /// level of the grid sequence when `richardson` is true (else the raw value).
    pub central_film_m: f64,
    /// Minimum film h_min, m (parabolic refinement around the smallest nodal film; extrapolated
    /// like `central_film_m`).
    pub min_film_m: f64,
    /// h_c on the result grid itself, m.
    pub central_film_raw_m: f64,
    /// h_min on the result grid itself, m.
    pub min_film_raw_m: f64,
    /// Whether h_c and h_min are Richardson-extrapolated (f + (f − f_½)/3, formal order 2).
    pub richardson: bool,
    /// Grid error of the raw films when the grid sequence reached the result grid from the
    /// half-resolution level (None otherwise: the result is the coarsest level, or that level
    /// was solved afresh; [`super::convergence::grid_error_estimate`] then solves the 2N−1
    /// grid for it).
    pub grid_error_estimate: Option<GridErrorEstimate>,
    /// Where h_min sits, in units of b (X = x/b).
    pub min_film_x: f64,
    /// Maximum pressure (the outlet spike at high load), Pa.
    pub max_pressure_pa: f64,
    /// Where the maximum pressure sits, X = x/b.
    pub max_pressure_x: f64,
    /// Maximum Hertz pressure p_h, Pa.
    pub hertz_pressure_pa: f64,
    /// Hertz half-width b, m.
    pub hertz_half_width_m: f64,
    /// Film exit (cavitation) point: first node downstream of the pressure maximum with P = 0.
    pub exit_x: f64,
    /// Rigid-body separation H₀ (dimensionless).
    pub separation_dimensionless: f64,
    /// Newton iterations in total (including continuation).
    pub iterations: usize,
    /// Last Σ|ΔP|/ΣP.
    pub pressure_change: f64,
    /// |∫P dX − π/2|/(π/2).
    pub load_error: f64,
    /// RMS scaled Reynolds residual.
    pub reynolds_residual: f64,
    /// Wall time of the solve, s.
    pub wall_time_s: f64,
    /// Number of grid nodes.
    pub nodes: usize,
    /// Profiles (dimensionless).
    pub profile: Profile,
}

impl EhlSolution {
    pub(crate) fn from_state(
        case: &ContactCase,
        opts: &SolverOptions,
        ws: &NewtonWorkspace,
        iterations: usize,
        report: &NewtonReport,
        wall_time_s: f64,
        coarse: Option<(f64, f64)>,
    ) -> Self {
        let x = &ws.nodes;
        let (p, h) = (&ws.p, &ws.h);
        let scale = case.film_scale_m();
        let b = case.hertz_half_width_m();
        let ph = case.hertz_pressure_pa();
        let hc = ws.central_film(opts.elastic);
        let (mut xmin, mut hmin) = min_film(x, h);
        // X = 0 need not be a node: the exact centre value bounds the continuous minimum.
        if hc < hmin {
            (xmin, hmin) = (0.0, hc);
        }
        let grid_error_estimate = coarse
            .map(|half| GridErrorEstimate::from_half_grid((hc, hmin), half, (x.len() - 1) / 2 + 1));
        // Richardson with the formal order 2 of the scheme (the refinement study measures
        // p ≈ 1.8–2.1), only when the two grids agree to 30 % (asymptotic range).
        let extrapolated = coarse
            .filter(|_| opts.richardson)
            .and_then(|(hc_half, hmin_half)| {
                let ok = |f: f64, g: f64| g > 0.0 && ((f - g) / f).abs() < 0.3;
                (ok(hc, hc_half) && ok(hmin, hmin_half))
                    .then(|| (hc + (hc - hc_half) / 3.0, hmin + (hmin - hmin_half) / 3.0))
            });
        let (hc_out, hmin_out) = extrapolated.unwrap_or((hc, hmin));
        let (mut imax, mut pmax) = (0, f64::NEG_INFINITY);
        for (i, &v) in p.iter().enumerate() {
            if v > pmax {
                pmax = v;
                imax = i;
            }
        }
        let exit = (imax..p.len())
            .find(|&i| p[i] <= 0.0)
            .unwrap_or(p.len() - 1);
        Self {
            case: *case,
            central_film_m: hc_out * scale,
            min_film_m: hmin_out * scale,
            central_film_raw_m: hc * scale,
            min_film_raw_m: hmin * scale,
            richardson: extrapolated.is_some(),
            grid_error_estimate,
            min_film_x: xmin,
            max_pressure_pa: pmax * ph,
            max_pressure_x: x[imax],
            hertz_pressure_pa: ph,
            hertz_half_width_m: b,
            exit_x: x[exit],
            separation_dimensionless: ws.h0,
            iterations,
            pressure_change: report.pressure_change,
            load_error: report.load_error,
            reynolds_residual: report.reynolds_residual,
            wall_time_s,
            nodes: x.len(),
            profile: Profile {
                x: x.clone(),
                pressure: p.clone(),
                film: h.clone(),
            },
        }
    }

    /// Writes the profile as CSV: x_m, x_over_b, pressure_pa, p_over_ph, hertz_pa, film_m.
    pub fn write_profile_csv<W: Write>(&self, mut out: W) -> std::io::Result<()> {
        writeln!(
            out,
            "x_m,x_over_b,pressure_pa,p_over_ph,hertz_pressure_pa,film_m"
        )?;
        let scale = self.case.film_scale_m();
        for i in 0..self.profile.x.len() {
            let x = self.profile.x[i];
            let hz = (1.0 - x * x).max(0.0).sqrt();
            writeln!(
                out,
                "{:.9e},{:.6},{:.9e},{:.6e},{:.9e},{:.9e}",
                x * self.hertz_half_width_m,
                x,
                self.profile.pressure[i] * self.hertz_pressure_pa,
                self.profile.pressure[i],
                hz * self.hertz_pressure_pa,
                self.profile.film[i] * scale
            )?;
        }
        Ok(())
    }
}

/// Minimum film (dimensionless) and its position: smallest nodal value refined by a parabola.
pub(crate) fn min_film(x: &[f64], h: &[f64]) -> (f64, f64) {
    let (mut imin, mut hmin) = (0, f64::INFINITY);
    for (i, &v) in h.iter().enumerate() {
        if v < hmin {
            hmin = v;
            imin = i;
        }
    }
    parabola_min(x, h, imin)
}

/// Vertex of the parabola through nodes i−1, i, i+1 (non-uniform), clamped to that bracket.
fn parabola_min(x: &[f64], y: &[f64], i: usize) -> (f64, f64) {
    if i == 0 || i + 1 >= x.len() {
        return (x[i], y[i]);
    }
    let (x0, x1, x2) = (x[i - 1], x[i], x[i + 1]);
    let (y0, y1, y2) = (y[i - 1], y[i], y[i + 1]);
    let d01 = (y1 - y0) / (x1 - x0);
    let d12 = (y2 - y1) / (x2 - x1);
    let a = (d12 - d01) / (x2 - x0);
    if a <= 0.0 {
        return (x1, y1);
    }
    let bcoef = d01 - a * (x0 + x1);
    let xv = (-bcoef / (2.0 * a)).clamp(x0, x2);
    let yv = y1 + d01 * (xv - x1) + a * (xv - x0) * (xv - x1);
    (xv, yv.min(y1))
}
