//! Loads → displacement: the inner-ring displacement that balances an applied load, by Newton's
//! method on the bearing's own stiffness, with a fixed iteration cap.
//!
//! Each unknown of (x, y, z, θ_x, θ_y) is either free (solved for, its applied load given) or
//! held at a given value (its reaction reported). A bearing whose balls all lift off has no
//! stiffness, so the Newton matrix is K + εI (ε = 10⁵ N/m, and ε R_i² for the tilts) and each
//! step is limited to 5 µm (of translation, or of R_i times a tilt): from rest the rings close their clearance in a few
//! steps. A step that does not lower the scaled residual is halved up to eight times.

use super::{BallBearing, BallBearingOutput, BallBearingState};
use crate::error::ParamError;
use crate::math::{max, min};

/// Newton steps allowed before the solve gives up.
pub const MAX_STATIC_ITERATIONS: usize = 200;
/// The residual a solution meets, relative to the applied load's size (forces in N, moments
/// divided by R_i) plus 10⁻³ N.
const RELATIVE_TOLERANCE: f32 = 1.0e-4;

/// An applied load on the inner ring and which displacements are free.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BallLoad {
    /// [F_x, F_y, F_z, M_x, M_y] applied to the inner ring (N, N·m); used on the free
    /// coordinates.
    pub applied: [f32; 5],
    /// Which of (x, y, z, θ_x, θ_y) are solved for.
    pub free: [bool; 5],
    /// The values of the held coordinates (m, rad); the free ones' start.
    pub held: [f32; 5],
    /// Shaft speed (rad/s).
    pub shaft_speed_rad_s: f32,
    /// Cage angle: the azimuth of ball 0 (rad).
    pub cage_angle_rad: f32,
}

impl BallLoad {
    /// Translations free, tilts held at zero (their reaction moments reported).
    pub fn translations(applied_force_n: [f32; 3], shaft_speed_rad_s: f32) -> Self {
        let [fx, fy, fz] = applied_force_n;
        Self {
            applied: [fx, fy, fz, 0.0, 0.0],
            free: [true, true, true, false, false],
            held: [0.0; 5],
            shaft_speed_rad_s,
            cage_angle_rad: 0.0,
        }
    }
}

/// A converged static equilibrium.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StaticSolution<const Z: usize> {
    /// (x, y, z, θ_x, θ_y) (m, rad).
    pub displacement: [f32; 5],
    /// The bearing at that displacement.
    pub output: BallBearingOutput<Z>,
    /// Newton steps taken.
    pub iterations: usize,
}

/// Why a static solve was refused.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StaticSolveError {
    /// A load or speed out of range, named.
    Param(ParamError),
    /// No equilibrium within `MAX_STATIC_ITERATIONS` (200) steps (for instance an
    /// angular-contact bearing pulled in −z, or a load beyond what the balls can carry within
    /// 1 mm): the scaled residual left (N).
    NotConverged {
        /// The largest residual left, forces in N, moments divided by R_i.
        residual_n: f32,
    },
}

impl From<ParamError> for StaticSolveError {
    fn from(e: ParamError) -> Self {
        StaticSolveError::Param(e)
    }
}

impl core::fmt::Display for StaticSolveError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match self {
            StaticSolveError::Param(e) => write!(f, "{e}"),
            StaticSolveError::NotConverged { residual_n } => write!(
                f,
                "no equilibrium found in {MAX_STATIC_ITERATIONS} Newton steps (residual \
                 {residual_n:.3e} N): the bearing cannot carry this load with these \
                 coordinates free"
            ),
        }
    }
}

impl<const Z: usize> BallBearing<Z> {
    /// The displacement that balances `load` (module doc).
    ///
    /// ```
    /// use bearing_core::bearing::ball::{BallBearing, BallBearingDesign, BallFilm, BallLoad};
    /// let params = BallBearingDesign::DEEP_GROOVE_6205.params().map_err(|e| format!("{e}"))?;
    /// let bearing = BallBearing::<9>::new(params, BallFilm::Dry).map_err(|e| format!("{e}"))?;
    /// // 1 kN applied downwards (−y) at 6 000 rpm: the ring moves down.
    /// let s = bearing
    ///     .solve_static(&BallLoad::translations([0.0, -1000.0, 0.0], 628.3))
    ///     .map_err(|e| format!("{e}"))?;
    /// assert!(s.displacement[1] < -6e-6);
    /// assert!((s.output.applied_load()[1] + 1000.0).abs() < 0.2);
    /// # Ok::<(), String>(())
    /// ```
    pub fn solve_static(&self, load: &BallLoad) -> Result<StaticSolution<Z>, StaticSolveError> {
        for &v in load.applied.iter() {
            crate::error::in_range("applied_load", v, -1.0e6, 1.0e6)?;
        }
        let lever = self.params.inner_centre_radius_m;
        // Moments and tilts scaled by R_i, so that all five residuals are forces (N).
        let scale = [1.0, 1.0, 1.0, 1.0 / lever, 1.0 / lever];
        let size = load
            .applied
            .iter()
            .zip(scale)
            .fold(0.0_f32, |m, (a, s)| max(m, (a * s).abs()));
        let tolerance = RELATIVE_TOLERANCE * size + 1.0e-3;
        // A film-coupled bearing starts from its dry equilibrium (continuation: the film
        // moves the solution by a fraction of a micrometre, well inside Newton's reach).
        let mut u = load.held;
        if self.film != super::BallFilm::Dry {
            let dry = BallBearing::<Z> {
                film: super::BallFilm::Dry,
                ..*self
            };
            if let Ok(s) = dry.solve_static(load) {
                u = s.displacement;
            }
        }
        let residual_of = |out: &BallBearingOutput<Z>| -> [f32; 5] {
            let model = out.applied_load();
            let mut r = [0.0; 5];
            for ((((r, a), m), free), s) in r
                .iter_mut()
                .zip(load.applied)
                .zip(model)
                .zip(load.free)
                .zip(scale)
            {
                *r = if free { (a - m) * s } else { 0.0 };
            }
            r
        };
        let norm = |r: &[f32; 5]| r.iter().fold(0.0_f32, |m, v| max(m, v.abs()));
        // The line search's merit: the sum of squares, for which a Newton step is a descent
        // direction (the largest component need not fall along it).
        let merit = |r: &[f32; 5]| r.iter().map(|v| v * v).sum::<f32>();
        let state = |u: [f32; 5]| BallBearingState {
            cage_angle_rad: load.cage_angle_rad,
            ..BallBearingState::at(u, load.shaft_speed_rad_s)
        };
        let mut out = self.evaluate(&state(u))?;
        let mut residual = residual_of(&out);
        for iteration in 0..MAX_STATIC_ITERATIONS {
            if norm(&residual) <= tolerance {
                return Ok(StaticSolution {
                    displacement: u,
                    output: out,
                    iterations: iteration,
                });
            }
            let step = newton_step(&out.stiffness, &residual, &load.free, lever);
            let mut fraction = 1.0;
            for attempt in 0..9 {
                let mut trial = u;
                for (t, d) in trial.iter_mut().zip(step) {
                    *t += fraction * d;
                }
                // A trial beyond the state's range (a load the balls cannot carry) is refused
                // like a step that does not help.
                let Ok(trial_out) = self.evaluate(&state(trial)) else {
                    fraction *= 0.5;
                    continue;
                };
                let trial_residual = residual_of(&trial_out);
                // Not worse (with every ball lifted off the residual stays flat while the rings
                // close their clearance), or the last, smallest trial: the iteration cap ends
                // a search that cannot progress.
                if merit(&trial_residual) <= merit(&residual) || attempt == 8 {
                    (u, out, residual) = (trial, trial_out, trial_residual);
                    break;
                }
                fraction *= 0.5;
            }
        }
        Err(StaticSolveError::NotConverged {
            residual_n: norm(&residual),
        })
    }
}

/// The limited Newton step (m, rad) for the scaled `residual` (module doc).
fn newton_step(
    stiffness: &[[f32; 5]; 5],
    residual: &[f32; 5],
    free: &[bool; 5],
    lever: f32,
) -> [f32; 5] {
    const REGULARISATION_N_PER_M: f32 = 1.0e5;
    // Unknowns v = (x, y, z, θ_x R_i, θ_y R_i), equations the scaled residuals: the matrix is
    // S K S with S = diag(1, 1, 1, 1/R_i, 1/R_i).
    let scale = [1.0, 1.0, 1.0, 1.0 / lever, 1.0 / lever];
    let mut a = [[0.0_f32; 6]; 5];
    for (i, row) in a.iter_mut().enumerate() {
        let (k_row, fi, si) = (
            stiffness.get(i).copied().unwrap_or([0.0; 5]),
            free.get(i).copied().unwrap_or(false),
            scale.get(i).copied().unwrap_or(1.0),
        );
        for (j, cell) in row.iter_mut().take(5).enumerate() {
            let fj = free.get(j).copied().unwrap_or(false);
            let sj = scale.get(j).copied().unwrap_or(1.0);
            let diagonal = if i == j { REGULARISATION_N_PER_M } else { 0.0 };
            *cell = if fi && fj {
                si * k_row.get(j).copied().unwrap_or(0.0) * sj + diagonal
            } else if i == j {
                1.0
            } else {
                0.0
            };
        }
        if let Some(rhs) = row.get_mut(5) {
            *rhs = if fi {
                residual.get(i).copied().unwrap_or(0.0)
            } else {
                0.0
            };
        }
    }
    let v = solve_5x5(a);
    let mut step = [0.0_f32; 5];
    for ((d, v), s) in step.iter_mut().zip(v).zip(scale) {
        *d = v * s;
    }
    // Limit to 5 µm / 10⁻³ rad (in v: 5 µm for every coordinate at R_i ≈ 5 mm and more).
    let largest = v.iter().fold(0.0_f32, |m, x| max(m, x.abs()));
    let limit = min(1.0, 5.0e-6 / max(largest, 1.0e-30));
    for d in step.iter_mut() {
        *d *= limit;
    }
    step
}

/// Solve the 5 × 5 system whose augmented rows are `a` by Gaussian elimination with partial
/// pivoting (a singular pivot gives a zero component). Hand-written: five unknowns and no
/// allocation, where a linear-algebra crate would add a dependency to the `no_std` core.
fn solve_5x5(mut a: [[f32; 6]; 5]) -> [f32; 5] {
    for col in 0..5 {
        // Pivot: the largest |a[r][col]| for r ≥ col.
        let mut pivot = col;
        let mut best = 0.0_f32;
        for (r, row) in a.iter().enumerate().skip(col) {
            let v = row.get(col).copied().unwrap_or(0.0).abs();
            if v > best {
                (best, pivot) = (v, r);
            }
        }
        a.swap(col, pivot);
        let Some(&pivot_row) = a.get(col) else {
            continue;
        };
        let p = pivot_row.get(col).copied().unwrap_or(0.0);
        if p == 0.0 {
            continue;
        }
        for row in a.iter_mut().skip(col + 1) {
            let factor = row.get(col).copied().unwrap_or(0.0) / p;
            for (x, pv) in row.iter_mut().zip(pivot_row.iter()) {
                *x -= factor * pv;
            }
        }
    }
    let mut x = [0.0_f32; 5];
    for col in (0..5).rev() {
        let Some(row) = a.get(col) else { continue };
        let mut sum = row.get(5).copied().unwrap_or(0.0);
        for (c, xv) in x.iter().enumerate().skip(col + 1) {
            sum -= row.get(c).copied().unwrap_or(0.0) * xv;
        }
        let p = row.get(col).copied().unwrap_or(0.0);
        if let Some(xc) = x.get_mut(col) {
            *xc = if p != 0.0 { sum / p } else { 0.0 };
        }
    }
    x
}
