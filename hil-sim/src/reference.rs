//! The accuracy reference: the bearing state of a sample recomputed with the full numerical
//! EHL solver (`bearing_ehl`) in every loaded contact, the film–load coupling converged,
//! in f64.
//!
//! For each roller the fixed point of docs/physics.md §4 is solved exactly as the core defines it —
//! δ = δ_geo + h_in(Q) + h_out(Q), Q = Σ_k q_k(δ + x_k ψ − 2P(x_k)) with the same slices, crown
//! and Palmgren law — but with the films from the numerical solver (Roelands viscosity,
//! Dowson–Higginson density, default grid) instead of the core's film model, and solved until
//! the load agrees with the slices to 10⁻⁴ relative (the film then to 10⁻⁵). The reference force adds the same viscous damping
//! as the core (f_damp·K·δ̇ with the slices' K).
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
use bearing_core::{BearingParams, ContactLaw, Crown};
use bearing_ehl::{ContactCase, EhlSolution, Solver, SolverOptions};

/// Slices per roller, as in the kernel.
const SLICES: usize = kernel::SLICES;
/// Contacts below this Hertz pressure are outside the EHL reference (Pa).
pub const MIN_HERTZ_PRESSURE_PA: f64 = 0.2e9;
/// |ln Q − ln Q_slices| at which the coupling counts as converged.
const LOAD_TOLERANCE: f64 = 1.0e-4;
/// Fixed-point iterations allowed per roller.
const MAX_ITERATIONS: usize = 30;

/// The numerical reference for one bearing.
pub struct NumericalReference {
    params: BearingParams,
    solver: Solver,
    /// Last solution per roller and contact, to warm-start the next sample's solves.
    previous: Vec<[Option<EhlSolution>; 2]>,
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
        let solver = Solver::new(SolverOptions::default()).map_err(|e| e.to_string())?;
        Ok(Self {
            params,
            solver,
            previous: Vec::new(),
        })
    }

    /// Central film (m) of one contact at roller load `load_n`, warm-started when possible.
    fn film(
        &mut self,
        roller: usize,
        outer: bool,
        load_n: f64,
        speed_rad_s: f32,
    ) -> Result<f64, String> {
        let input = self.params.contact_input(outer, load_n as f32, speed_rad_s);
        let case = ContactCase::new(
            load_n / f64::from(input.length_m),
            f64::from(input.entrainment_speed_m_s),
            f64::from(input.reduced_radius_m),
            f64::from(input.reduced_modulus_pa),
            f64::from(input.pressure_viscosity_pa_inv),
            f64::from(input.viscosity_pa_s),
        )
        .map_err(|e| e.to_string())?;
        let slot = self
            .previous
            .get_mut(roller)
            .and_then(|p| p.get_mut(usize::from(outer)))
            .ok_or("roller index out of range")?;
        let solution = match slot.as_ref() {
            Some(previous) => self.solver.solve_from(&case, previous),
            None => self.solver.solve(&case),
        }
        .map_err(|e| {
            format!(
                "roller {roller} {} contact at {load_n:.1} N: {e}",
                if outer { "outer" } else { "inner" }
            )
        })?;
        let h = solution.central_film_m;
        *slot = Some(solution);
        Ok(h)
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
        if self.previous.len() != z {
            self.previous = (0..z).map(|_| [None, None]).collect();
        }
        let slices = Slices::new(&self.params);
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
        for j in 0..z {
            let theta =
                f64::from(stepped.cage_angle_rad) + std::f64::consts::TAU * j as f64 / z as f64;
            let (s, c) = theta.sin_cos();
            let geometric = x * c + y * s - clearance;
            let tilt = tilt_y * c - tilt_x * s;
            let core_load = f64::from(stepped.roller_load_n.get(j).copied().unwrap_or(0.0));
            let loaded = core_load > 0.0
                && self.hertz_pressure(core_load, sample.speed_rad_s) >= MIN_HERTZ_PRESSURE_PA;
            let (load, stiffness) = if loaded {
                // Root of F(Q) = Q − Q_slices(δ_geo + h_in(Q) + h_out(Q)), which rises with Q (the
                // films thin as the load grows): Illinois false position in ln Q, bracketed
                // around the core's load. Plain fixed-point iteration diverges when the film is
                // many times the elastic approach (contraction ≈ 0.11·H/δ_elastic).
                let residual = |q: f64, me: &mut Self| -> Result<(f64, (f64, f64)), String> {
                    let h_in = me.film(j, false, q, sample.speed_rad_s)?;
                    let h_out = me.film(j, true, q, sample.speed_rad_s)?;
                    let (q_slices, _) = slices.load(geometric + h_in + h_out, tilt);
                    Ok((q.ln() - q_slices.max(1.0e-9).ln(), (h_in, h_out)))
                };
                let (mut a, mut b) = (core_load.ln() - 0.5, core_load.ln() + 0.5);
                let (mut fa, mut films) = residual(a.exp(), self).map_err(fault)?;
                let (mut fb, _) = residual(b.exp(), self).map_err(fault)?;
                let mut widen = 0;
                while fa > 0.0 && widen < 20 {
                    a -= 1.0;
                    (fa, films) = residual(a.exp(), self).map_err(fault)?;
                    widen += 1;
                }
                while fb < 0.0 && widen < 40 {
                    b += 1.0;
                    (fb, _) = residual(b.exp(), self).map_err(fault)?;
                    widen += 1;
                }
                if fa > 0.0 || fb < 0.0 {
                    return Err(fault(format!(
                        "roller {j}: no bracket for the film–load coupling"
                    )));
                }
                let mut q = core_load;
                let mut converged = false;
                let mut side = 0i8;
                for _ in 0..MAX_ITERATIONS {
                    let c = (a * fb - b * fa) / (fb - fa);
                    let (fc, films_c) = residual(c.exp(), self).map_err(fault)?;
                    films = films_c;
                    q = c.exp();
                    // |ln Q − ln Q_slices| ≤ 10⁻⁴: the film (∝ Q^−0.1) is then within 10⁻⁵ of its
                    // fixed point, below the numerical solver's own warm/cold-start scatter.
                    if fc.abs() <= LOAD_TOLERANCE || (b - a).abs() <= LOAD_TOLERANCE {
                        converged = true;
                        break;
                    }
                    if fc > 0.0 {
                        b = c;
                        fb = fc;
                        if side == 1 {
                            fa *= 0.5;
                        }
                        side = 1;
                    } else {
                        a = c;
                        fa = fc;
                        if side == -1 {
                            fb *= 0.5;
                        }
                        side = -1;
                    }
                }
                if !converged {
                    return Err(fault(format!("roller {j}: film–load coupling not converged in {MAX_ITERATIONS} iterations")));
                }
                out.roller_load_n[j] = q;
                out.film_inner_m[j] = films.0;
                out.film_outer_m[j] = films.1;
                let (_, k) = slices.load(geometric + films.0 + films.1, tilt);
                (q, k)
            } else {
                // Outside the EHL reference: the core's load enters the force unchanged.
                let approach = f64::from(stepped.roller_approach_m.get(j).copied().unwrap_or(0.0));
                let (_, k) = slices.load(
                    approach
                        + f64::from(stepped.film_inner_m.get(j).copied().unwrap_or(0.0))
                        + f64::from(stepped.film_outer_m.get(j).copied().unwrap_or(0.0)),
                    tilt,
                );
                (core_load, k)
            };
            let roller_force = (load + damping * stiffness * (vx * c + vy * s)).max(0.0);
            out.force_n[0] -= roller_force * c;
            out.force_n[1] -= roller_force * s;
        }
        Ok(out)
    }
}
