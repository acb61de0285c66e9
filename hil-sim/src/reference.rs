//! The accuracy reference: the bearing state of a sample recomputed with the full numerical
//! EHL solver (`bearing_ehl`) in every loaded contact, the film–load coupling converged,
//! in f64.
//!
//! For each roller the fixed point of docs/physics.md §4 is solved exactly as the core defines it —
//! δ = δ_geo + h_in(Q) + h_out(Q), Q = Σ_k q_k(δ + x_k ψ − 2P(x_k)) with the same slices, crown
//! and Palmgren law — but with the films from the numerical solver (Roelands viscosity,
//! Dowson–Higginson density, `SolverOptions::default()`: its grid sequence, adaptive stop and
//! Richardson extrapolation) instead of the core's film model, and solved until the load agrees
//! with the slices to 10⁻⁴ relative (the film then to 10⁻⁵). The reference force adds the same
//! viscous damping as the core (f_damp·K·δ̇ with the slices' K).
//!
//! Cost. Every film is a cold solve (5–15 ms each at the hub motor's contacts), so the
//! reference of a sample is a function of the sample alone, whatever was solved before; a
//! warm start from the last solution (`Solver::solve_from`) re-solved on the finest grid and
//! took 25 ms–1 s. The root search starts at the core's load, whose film is within about 1 %
//! of the solver's, so about five residuals (ten solves) settle a roller; the rollers of a
//! sample are solved on all cores, each thread with its own [`Solver`].
//!
//! Scope: the numerical solver is an EHL solver. Rollers whose Hertz pressure at the core's load
//! is below [`MIN_HERTZ_PRESSURE_PA`] (hydrodynamic or barely loaded) are outside it: their load
//! enters the reference force as the core computed it, and they are reported with a NaN load so
//! the film comparison skips them.

use crate::kernel;
use crate::outputs::StepOutputs;
use crate::replay::{AccuracyReference, ReferenceOutputs, StepFault};
use crate::trace::{Sample, TraceMeta};
use bearing_core::contact::{HertzLineContact, PALMGREN_K};
use bearing_core::film::corrections::corrected_film_m;
use bearing_core::film::martin_film_m;
use bearing_core::{BearingParams, ContactLaw, Crown};
use bearing_ehl::{ContactCase, Solver, SolverOptions};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::Mutex;

/// Slices per roller, as in the kernel.
const SLICES: usize = kernel::SLICES;
/// Contacts below this Hertz pressure are outside the EHL reference (Pa).
pub const MIN_HERTZ_PRESSURE_PA: f64 = 0.2e9;
/// |ln Q − ln Q_slices| at which the coupling counts as converged.
const LOAD_TOLERANCE: f64 = 1.0e-4;
/// False-position iterations allowed per roller.
const MAX_ITERATIONS: usize = 30;
/// Half-width of the first bracket around the core's ln Q: the core's film is within about
/// 1 % of the solver's, which moves the root by less than this.
const FIRST_BRACKET: f64 = 0.02;

/// The numerical reference for one bearing.
pub struct NumericalReference {
    params: BearingParams,
    /// The roller law of `params`, built once.
    slices: Slices,
    /// One solver per worker thread (a solver owns its grids and work storage).
    solvers: Vec<Solver>,
}

/// One roller of a sample: where it is and what the core found.
#[derive(Clone, Copy)]
struct RollerCase {
    /// Geometric approach δ_geo (m) and tilt ψ (rad) of the roller.
    geometric_m: f64,
    tilt_rad: f64,
    /// The core's roller load (N), where the root search starts.
    core_load_n: f64,
}

/// The reference solution of one loaded roller.
#[derive(Clone, Copy)]
struct RollerSolution {
    load_n: f64,
    film_inner_m: f64,
    film_outer_m: f64,
    /// Contact stiffness K = dQ/dδ of the slices at the solution (N/m).
    stiffness_n_per_m: f64,
}

/// The roller law in f64: slice positions, crown offsets, Palmgren coefficient.
struct Slices {
    positions_m: [f64; SLICES],
    crown_offsets_m: [f64; SLICES],
    /// q_k = slice_coefficient · δ_k^(10/9) (N/m^(10/9)).
    slice_coefficient: f64,
}

impl Slices {
    fn new(params: &BearingParams) -> Self {
        let g = params.geometry();
        let l = f64::from(g.roller_length_m());
        let d = f64::from(g.roller_diameter_m());
        let scale = match g.crown() {
            Crown::None => 0.0,
            Crown::Logarithmic { scale } => f64::from(scale),
        };
        let mut positions_m = [0.0; SLICES];
        let mut crown_offsets_m = [0.0; SLICES];
        for (k, (x, c)) in positions_m
            .iter_mut()
            .zip(crown_offsets_m.iter_mut())
            .enumerate()
        {
            *x = (k as f64 + 0.5) * l / SLICES as f64 - 0.5 * l;
            // ISO/TS 16281 logarithmic crown (docs/physics.md §3), on both contacts.
            let r = 2.0 * *x / l;
            *c = -2.0 * scale * 0.00035 * d * -(1.0 - r * r).max(1.0e-6).ln();
        }
        // Palmgren, homogeneous form δ = k·(w/E')^0.9·l^0.1 per contact (core::contact::law).
        let e = f64::from(params.reduced_modulus_pa());
        let per_length = e * (2.0 * f64::from(PALMGREN_K) * l.powf(0.1)).powf(-10.0 / 9.0);
        Self {
            positions_m,
            crown_offsets_m,
            slice_coefficient: per_length * l / SLICES as f64,
        }
    }

    /// Roller load Q (N) and contact stiffness K = dQ/dδ (N/m) at approach δ and tilt ψ.
    fn load(&self, approach_m: f64, tilt_rad: f64) -> (f64, f64) {
        self.positions_m
            .iter()
            .zip(self.crown_offsets_m.iter())
            .fold((0.0, 0.0), |(q, k), (&x, &c)| {
                let d = approach_m + x * tilt_rad + c;
                if d > 0.0 {
                    let qk = self.slice_coefficient * d.powf(10.0 / 9.0);
                    (q + qk, k + (10.0 / 9.0) * qk / d)
                } else {
                    (q, k)
                }
            })
    }
}

impl NumericalReference {
    /// The reference for a trace's bearing and lubricant.
    pub fn new(meta: &TraceMeta) -> Result<Self, String> {
        let params = kernel::params(&meta.bearing, &meta.lubricant)
            .map_err(|e| crate::wiring::describe(&e))?;
        if params.law() != ContactLaw::Palmgren {
            return Err("the numerical reference implements the Palmgren slice law only".into());
        }
        let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
        let solvers = (0..threads)
            .map(|_| Solver::new(SolverOptions::default()).map_err(|e| e.to_string()))
            .collect::<Result<_, _>>()?;
        Ok(Self {
            slices: Slices::new(&params),
            params,
            solvers,
        })
    }

    /// Hertz pressure of the inner contact at load `load_n` (Pa), the more loaded one.
    fn hertz_pressure(&self, load_n: f64, speed_rad_s: f32) -> f64 {
        let c = self.params.contact_input(false, load_n as f32, speed_rad_s);
        let hertz = HertzLineContact::new(
            c.load_per_length_n_per_m(),
            c.reduced_radius_m,
            c.reduced_modulus_pa,
        );
        f64::from(hertz.max_pressure_pa)
    }

    /// Solve the loaded rollers `cases` (index, case) on every solver's thread.
    fn solve_rollers(
        &mut self,
        cases: &[(usize, RollerCase)],
        speed_rad_s: f32,
    ) -> Result<Vec<(usize, RollerSolution)>, String> {
        let (params, slices) = (&self.params, &self.slices);
        let next = AtomicUsize::new(0);
        let solved = Mutex::new(Vec::with_capacity(cases.len()));
        let first_error = Mutex::new(None);
        std::thread::scope(|scope| {
            for solver in self.solvers.iter_mut().take(cases.len().max(1)) {
                let (next, solved, first_error) = (&next, &solved, &first_error);
                scope.spawn(move || {
                    while let Some(&(j, case)) = cases.get(next.fetch_add(1, Ordering::Relaxed)) {
                        match couple(solver, params, slices, j, case, speed_rad_s) {
                            Ok(solution) => lock(solved).push((j, solution)),
                            Err(e) => {
                                lock(first_error).get_or_insert(e);
                                return;
                            }
                        }
                    }
                });
            }
        });
        match first_error
            .into_inner()
            .unwrap_or_else(std::sync::PoisonError::into_inner)
        {
            Some(e) => Err(e),
            None => Ok(solved
                .into_inner()
                .unwrap_or_else(std::sync::PoisonError::into_inner)),
        }
    }
}

/// The guarded value; a worker that panicked while holding the lock poisoned it, but its data
/// (a list of finished results) is still whole.
fn lock<T>(m: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    m.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// Central film (m) of one contact at roller load `load_n`: a cold solve, so the film is a
/// function of the contact alone.
fn film(
    solver: &mut Solver,
    params: &BearingParams,
    roller: usize,
    outer: bool,
    load_n: f64,
    speed_rad_s: f32,
) -> Result<f64, String> {
    let input = params.contact_input(outer, load_n as f32, speed_rad_s);
    let case = ContactCase::new(
        load_n / f64::from(input.length_m),
        f64::from(input.entrainment_speed_m_s),
        f64::from(input.reduced_radius_m),
        f64::from(input.reduced_modulus_pa),
        f64::from(input.pressure_viscosity_pa_inv),
        f64::from(input.viscosity_pa_s),
    )
    .map_err(|e| e.to_string())?;
    let solution = solver.solve(&case).map_err(|e| {
        format!(
            "roller {roller} {} contact at {load_n:.1} N: {e}",
            if outer { "outer" } else { "inner" }
        )
    })?;
    // The bearing's high-speed corrections (docs/physics.md §5.4), applied to the numerical film
    // as the core applies them to its own.
    let corrections = params.film_corrections();
    if corrections.is_off() {
        return Ok(solution.central_film_m);
    }
    let h = solution.central_film_m as f32;
    let factor = corrections.factors(&input, h).product();
    Ok(f64::from(corrected_film_m(
        h,
        martin_film_m(&input),
        factor,
    )))
}

/// The film–load coupling of one roller: the root of F(ln Q) = ln Q − ln Q_slices(δ_geo +
/// h_in(Q) + h_out(Q)), which rises with ln Q (the films thin as the load grows), by Illinois
/// false position. The bracket starts ±[`FIRST_BRACKET`] around the core's load and doubles
/// outwards until F changes sign. (Plain fixed-point iteration diverges when the film is many
/// times the elastic approach: contraction ≈ 0.11·H/δ_elastic.)
fn couple(
    solver: &mut Solver,
    params: &BearingParams,
    slices: &Slices,
    j: usize,
    case: RollerCase,
    speed_rad_s: f32,
) -> Result<RollerSolution, String> {
    let RollerCase {
        geometric_m,
        tilt_rad,
        core_load_n,
    } = case;
    let mut residual = |ln_q: f64| -> Result<(f64, (f64, f64)), String> {
        let q = ln_q.exp();
        let h_in = film(solver, params, j, false, q, speed_rad_s)?;
        let h_out = film(solver, params, j, true, q, speed_rad_s)?;
        let (q_slices, _) = slices.load(geometric_m + h_in + h_out, tilt_rad);
        Ok((ln_q - q_slices.max(1.0e-9).ln(), (h_in, h_out)))
    };
    let (mut a, mut b) = (
        core_load_n.ln() - FIRST_BRACKET,
        core_load_n.ln() + FIRST_BRACKET,
    );
    let mut fa = residual(a)?.0;
    let mut fb = residual(b)?.0;
    let mut width = FIRST_BRACKET;
    let mut widen = 0;
    while fa > 0.0 && widen < 20 {
        width *= 2.0;
        (b, fb) = (a, fa);
        a -= width;
        fa = residual(a)?.0;
        widen += 1;
    }
    while fb < 0.0 && widen < 40 {
        width *= 2.0;
        (a, fa) = (b, fb);
        b += width;
        fb = residual(b)?.0;
        widen += 1;
    }
    if fa > 0.0 || fb < 0.0 {
        return Err(format!("roller {j}: no bracket for the film–load coupling"));
    }
    let mut side = 0i8;
    for _ in 0..MAX_ITERATIONS {
        let c = (a * fb - b * fa) / (fb - fa);
        let (fc, films_c) = residual(c)?;
        // |ln Q − ln Q_slices| ≤ 10⁻⁴: the film (∝ Q^−0.1) is then within 10⁻⁵ of its fixed
        // point, below the numerical solver's own grid error.
        if fc.abs() <= LOAD_TOLERANCE || (b - a).abs() <= LOAD_TOLERANCE {
            let (_, k) = slices.load(geometric_m + films_c.0 + films_c.1, tilt_rad);
            return Ok(RollerSolution {
                load_n: c.exp(),
                film_inner_m: films_c.0,
                film_outer_m: films_c.1,
                stiffness_n_per_m: k,
            });
        }
        if fc > 0.0 {
            (b, fb) = (c, fc);
            if side == 1 {
                fa *= 0.5;
            }
            side = 1;
        } else {
            (a, fa) = (c, fc);
            if side == -1 {
                fb *= 0.5;
            }
            side = -1;
        }
    }
    Err(format!(
        "roller {j}: film–load coupling not converged in {MAX_ITERATIONS} iterations"
    ))
}

impl AccuracyReference for NumericalReference {
    fn name(&self) -> String {
        "numerical EHL (Roelands + Dowson–Higginson), converged film–load coupling, f64".into()
    }

    fn reference(
        &mut self,
        sample: &Sample,
        stepped: &StepOutputs,
    ) -> Result<ReferenceOutputs, StepFault> {
        let fault = |reason: String| StepFault { reason };
        let z = stepped.rollers;
        let g = self.params.geometry();
        let clearance = f64::from(g.radial_clearance_m());
        let damping = f64::from(self.params.damping_factor_s());
        let [tilt_x, tilt_y] = sample.tilt_rad.unwrap_or([0.0; 2]).map(f64::from);
        let (x, y) = (f64::from(sample.x_m), f64::from(sample.y_m));
        let (vx, vy) = (f64::from(sample.vx_m_s), f64::from(sample.vy_m_s));
        let mut out = ReferenceOutputs {
            force_n: [0.0; 2],
            roller_load_n: vec![f64::NAN; z],
            film_inner_m: vec![f64::NAN; z],
            film_outer_m: vec![f64::NAN; z],
        };
        // Each roller's direction and case; the loaded ones go to the numerical solver.
        let rollers: Vec<((f64, f64), RollerCase)> = (0..z)
            .map(|j| {
                let theta =
                    f64::from(stepped.cage_angle_rad) + std::f64::consts::TAU * j as f64 / z as f64;
                let (s, c) = theta.sin_cos();
                let case = RollerCase {
                    geometric_m: x * c + y * s - clearance,
                    tilt_rad: tilt_y * c - tilt_x * s,
                    core_load_n: f64::from(stepped.roller_load_n.get(j).copied().unwrap_or(0.0)),
                };
                ((s, c), case)
            })
            .collect();
        let loaded: Vec<(usize, RollerCase)> = rollers
            .iter()
            .enumerate()
            .filter(|(_, (_, case))| {
                case.core_load_n > 0.0
                    && self.hertz_pressure(case.core_load_n, sample.speed_rad_s)
                        >= MIN_HERTZ_PRESSURE_PA
            })
            .map(|(j, (_, case))| (j, *case))
            .collect();
        let mut solved: Vec<Option<RollerSolution>> = vec![None; z];
        for (j, solution) in self
            .solve_rollers(&loaded, sample.speed_rad_s)
            .map_err(fault)?
        {
            if let Some(slot) = solved.get_mut(j) {
                *slot = Some(solution);
            }
        }
        let slices = &self.slices;
        for (j, ((s, c), case)) in rollers.iter().enumerate() {
            let (load, stiffness) = match solved.get(j).copied().flatten() {
                Some(r) => {
                    out.roller_load_n[j] = r.load_n;
                    out.film_inner_m[j] = r.film_inner_m;
                    out.film_outer_m[j] = r.film_outer_m;
                    (r.load_n, r.stiffness_n_per_m)
                }
                None => {
                    // Outside the EHL reference: the core's load enters the force unchanged.
                    let approach =
                        f64::from(stepped.roller_approach_m.get(j).copied().unwrap_or(0.0));
                    let (_, k) = slices.load(
                        approach
                            + f64::from(stepped.film_inner_m.get(j).copied().unwrap_or(0.0))
                            + f64::from(stepped.film_outer_m.get(j).copied().unwrap_or(0.0)),
                        case.tilt_rad,
                    );
                    (case.core_load_n, k)
                }
            };
            let roller_force = (load + damping * stiffness * (vx * c + vy * s)).max(0.0);
            out.force_n[0] -= roller_force * c;
            out.force_n[1] -= roller_force * s;
        }
        Ok(out)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::replay::BearingStepper;
    use crate::trace::{Trace, ValidationOptions};
    use bearing_core::FilmKind;

    /// The bundled hub-motor run-up stepped with the integer network: the trace and the
    /// stepper's outputs at each sample index of `at`.
    fn stepped(at: &[usize]) -> (Trace, Vec<StepOutputs>) {
        let path =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("traces/hub_motor_runup.bin");
        let trace = Trace::read(&path, &ValidationOptions::default()).unwrap();
        let mut stepper =
            crate::wiring::primed_stepper(&trace.meta, FilmKind::Int, &trace.samples[0]).unwrap();
        let mut out = StepOutputs::default();
        let mut kept = Vec::new();
        for (i, sample) in trace
            .samples
            .iter()
            .enumerate()
            .take(at.iter().max().unwrap() + 1)
        {
            stepper.step(sample, &mut out).unwrap();
            if at.contains(&i) {
                kept.push(out);
            }
        }
        (trace, kept)
    }

    /// Each loaded roller of the reference satisfies the film–load coupling it claims to solve,
    /// checked with films from separate solver runs at the returned load: the slices carry the
    /// returned load (to the 10⁻⁴ tolerance in ln Q) at δ_geo + h_in + h_out, and the returned
    /// films are the solver's at that load. Two samples: off resonance (t = 0.1 s) and at the
    /// resonance crossing (t = 0.52 s, bearing force ≈ 2 kN on top of ≈ 6 kN of roller loads).
    /// Solved in the opposite order a second time, the reference is bit-identical: it depends
    /// on the sample alone.
    #[test]
    fn reference_rollers_satisfy_the_film_load_coupling_and_depend_on_the_sample_alone() {
        let at = [2000, 10_400];
        let (trace, outputs) = stepped(&at);
        let mut reference = NumericalReference::new(&trace.meta).unwrap();
        let first: Vec<ReferenceOutputs> = at
            .iter()
            .zip(&outputs)
            .map(|(&i, o)| reference.reference(&trace.samples[i], o).unwrap())
            .collect();
        let mut again: Vec<ReferenceOutputs> = at
            .iter()
            .zip(&outputs)
            .rev()
            .map(|(&i, o)| reference.reference(&trace.samples[i], o).unwrap())
            .collect();
        again.reverse();
        // Bit for bit (unloaded rollers are NaN, which `==` would not match).
        let bits = |r: &[ReferenceOutputs]| -> Vec<Vec<u64>> {
            r.iter()
                .map(|o| {
                    o.force_n
                        .iter()
                        .chain(&o.roller_load_n)
                        .chain(&o.film_inner_m)
                        .chain(&o.film_outer_m)
                        .map(|v| v.to_bits())
                        .collect()
                })
                .collect()
        };
        assert_eq!(bits(&first), bits(&again));

        let params = reference.params;
        let slices = Slices::new(&params);
        let clearance = f64::from(params.geometry().radial_clearance_m());
        let mut solver = Solver::new(SolverOptions::default()).unwrap();
        for ((&i, stepped), truth) in at.iter().zip(&outputs).zip(&first) {
            let sample = &trace.samples[i];
            let z = stepped.rollers;
            let mut checked = 0;
            for j in 0..z {
                let q = truth.roller_load_n[j];
                if !q.is_finite() {
                    continue;
                }
                let theta =
                    f64::from(stepped.cage_angle_rad) + std::f64::consts::TAU * j as f64 / z as f64;
                let (s, c) = theta.sin_cos();
                let geometric = f64::from(sample.x_m) * c + f64::from(sample.y_m) * s - clearance;
                let [tilt_x, tilt_y] = sample.tilt_rad.unwrap_or([0.0; 2]).map(f64::from);
                let tilt = tilt_y * c - tilt_x * s;
                let h_in = film(&mut solver, &params, j, false, q, sample.speed_rad_s).unwrap();
                let h_out = film(&mut solver, &params, j, true, q, sample.speed_rad_s).unwrap();
                assert_eq!(
                    (h_in, h_out),
                    (truth.film_inner_m[j], truth.film_outer_m[j])
                );
                let (q_slices, _) = slices.load(geometric + h_in + h_out, tilt);
                assert!(
                    (q.ln() - q_slices.ln()).abs() <= LOAD_TOLERANCE,
                    "sample {i}, roller {j}: Q {q} N, slices {q_slices} N"
                );
                checked += 1;
            }
            assert!(checked >= 10, "sample {i}: {checked} loaded rollers");
        }
    }
}
