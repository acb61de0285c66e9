//! The bearing step: from inner-race motion to roller loads, forces, stiffness and damping.
//!
//! [`Bearing`] owns everything a step needs (sliced rollers, roller directions, the warm start)
//! in fixed arrays sized by the const generics `Z` (rollers) and `S` (slices per roller). Its
//! [`Bearing::step`] runs the pipeline of PHYSICS.md §4 with a film model; [`Bearing::step_dry`]
//! is today's multi-body practice (film ≡ 0), for comparison. Both take the same number of
//! operations for every input, and neither can panic: a bad operating state is refused with a
//! flagged, all-zero output.

mod coupling;
mod equilibrium;
mod output;

pub use coupling::INNER_ITERATIONS;
pub use equilibrium::Equilibrium;
pub use output::{BearingOutput, RollerOutput, StepStatus};

use crate::contact::{ContactLaw, SlicedRoller};
use crate::error::{in_range, Allowed, ParamError};
use crate::film::{ContactInput, FilmModel, Regime};
use crate::math::{ln, sin_cos};
use crate::params::{reduced_modulus, BearingGeometry, Lubricant, Material, OperatingState};
use coupling::{solve_roller, ContactContext, StepFilm};
use output::add_roller_stiffness;

/// Everything that defines a lubricated roller bearing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BearingParams {
    geometry: BearingGeometry,
    reduced_modulus_pa: f32,
    lubricant: Lubricant,
    law: ContactLaw,
    damping_factor_s: f32,
}

impl BearingParams {
    /// A bearing from its geometry, the materials of the rings and the rollers, the lubricant,
    /// the slice contact law and the damping factor f_damp (s; 0 … 10⁻³, the thesis used
    /// 0.25·10⁻⁵ … 2.5·10⁻⁵, PHYSICS.md §4).
    pub fn new(
        geometry: BearingGeometry,
        ring_material: Material,
        roller_material: Material,
        lubricant: Lubricant,
        law: ContactLaw,
        damping_factor_s: f32,
    ) -> Result<Self, ParamError> {
        Ok(Self {
            geometry,
            reduced_modulus_pa: reduced_modulus(&ring_material, &roller_material),
            lubricant,
            law,
            damping_factor_s: in_range("damping_factor_s", damping_factor_s, 0.0, 1.0e-3)?,
        })
    }

    /// Geometry.
    pub fn geometry(&self) -> &BearingGeometry {
        &self.geometry
    }
    /// Reduced modulus E' of the roller–race contacts (Pa).
    pub fn reduced_modulus_pa(&self) -> f32 {
        self.reduced_modulus_pa
    }
    /// Lubricant.
    pub fn lubricant(&self) -> &Lubricant {
        &self.lubricant
    }
    /// Slice contact law.
    pub fn law(&self) -> ContactLaw {
        self.law
    }
    /// Damping factor f_damp (s).
    pub fn damping_factor_s(&self) -> f32 {
        self.damping_factor_s
    }

    /// The film-model input of the inner (`outer = false`) or outer contact for roller load
    /// `load_n` (N) at shaft speed ω (rad/s).
    pub fn contact_input(&self, outer: bool, load_n: f32, shaft_speed_rad_s: f32) -> ContactInput {
        let g = &self.geometry;
        ContactInput {
            load_n,
            length_m: g.roller_length_m(),
            entrainment_speed_m_s: g.entrainment_speed_m_s(shaft_speed_rad_s),
            reduced_radius_m: if outer {
                g.outer_reduced_radius_m()
            } else {
                g.inner_reduced_radius_m()
            },
            reduced_modulus_pa: self.reduced_modulus_pa,
            pressure_viscosity_pa_inv: self.lubricant.pressure_viscosity_pa_inv(),
            viscosity_pa_s: self.lubricant.viscosity_pa_s(),
        }
    }
}

/// A bearing of `Z` rollers with `S` slices each, with its warm start.
#[derive(Clone, Debug)]
pub struct Bearing<const Z: usize, const S: usize> {
    params: BearingParams,
    roller: SlicedRoller<S>,
    /// cos and sin of 2πj/Z, the roller positions relative to the cage.
    pitch: [(f32, f32); Z],
    /// 2πj/Z (rad).
    pitch_angle_rad: [f32; Z],
    /// Elastic approach of each roller at the last step: the warm start (m).
    warm_approach_m: [f32; Z],
    output: BearingOutput<Z>,
}

impl<const Z: usize, const S: usize> Bearing<Z, S> {
    /// A bearing whose geometry has exactly `Z` rollers, sliced `S ≥ 1` times.
    pub fn new(params: BearingParams) -> Result<Self, ParamError> {
        let count = params.geometry.roller_count();
        if usize::from(count) != Z {
            return Err(ParamError {
                field: "roller_count",
                value: f32::from(count),
                allowed: Allowed::Range {
                    min: Z as f32,
                    max: Z as f32,
                },
            });
        }
        if S == 0 || S > 1000 {
            return Err(ParamError {
                field: "slice_count",
                value: S as f32,
                allowed: Allowed::Range {
                    min: 1.0,
                    max: 1000.0,
                },
            });
        }
        let mut pitch = [(0.0, 1.0); Z];
        let mut pitch_angle_rad = [0.0; Z];
        for (j, (p, a)) in pitch.iter_mut().zip(pitch_angle_rad.iter_mut()).enumerate() {
            *a = 2.0 * core::f32::consts::PI * j as f32 / Z as f32;
            *p = (libm::cosf(*a), libm::sinf(*a));
        }
        Ok(Self {
            roller: SlicedRoller::new(&params.geometry, params.reduced_modulus_pa, params.law),
            params,
            pitch,
            pitch_angle_rad,
            warm_approach_m: [0.0; Z],
            output: BearingOutput::ZERO,
        })
    }

    /// Parameters.
    pub fn params(&self) -> &BearingParams {
        &self.params
    }

    /// The sliced roller.
    pub fn roller(&self) -> &SlicedRoller<S> {
        &self.roller
    }

    /// The last output.
    pub fn output(&self) -> &BearingOutput<Z> {
        &self.output
    }

    /// Forget the warm start (the next step starts from unloaded rollers).
    pub fn reset(&mut self) {
        self.warm_approach_m = [0.0; Z];
    }

    /// Per-step film context of the two contacts.
    fn step_film(&self, shaft_speed_rad_s: f32) -> StepFilm {
        let p = &self.params;
        let context = |outer: bool| {
            let template = p.contact_input(outer, 0.0, shaft_speed_rad_s);
            let er = template.reduced_modulus_pa * template.reduced_radius_m;
            let speed = template.viscosity_pa_s * template.entrainment_speed_m_s;
            let ln_2u = core::f32::consts::LN_2 + ln(speed) - ln(er);
            let ln_g = ln(template.pressure_viscosity_pa_inv * template.reduced_modulus_pa);
            ContactContext {
                template,
                martin: 6.0 * speed * template.reduced_radius_m * template.length_m,
                ln_m_offset: ln(template.length_m * er) + 0.5 * ln_2u,
                ln_l: ln_g + 0.25 * ln_2u,
            }
        };
        let contacts = [context(false), context(true)];
        StepFilm {
            lubricated: contacts[0].template.entrainment_speed_m_s > 0.0,
            contacts,
        }
    }

    /// One lubricated step: roller films from `film`, film-coupled loads, forces, stiffness.
    ///
    /// A refused `state` leaves the warm start as it was and returns a zero output whose
    /// status names the bad field.
    pub fn step<F: FilmModel + ?Sized>(
        &mut self,
        film: &F,
        state: &OperatingState,
    ) -> &BearingOutput<Z> {
        if let Err(e) = state.check() {
            return self.reject(e);
        }
        let step_film = self.step_film(state.shaft_speed_rad_s);
        self.assemble(state, |bearing, j, geometric, tilt| {
            let warm = bearing.warm_approach_m.get(j).copied().unwrap_or(0.0);
            let r = solve_roller(&bearing.roller, film, &step_film, geometric, tilt, warm);
            if let Some(w) = bearing.warm_approach_m.get_mut(j) {
                *w = r.approach_m;
            }
            let [fin, fout] = r.films;
            let s0 = r.load.stiffness_n_per_m;
            let coupling = r.film_slope_m_per_n / (1.0 - s0 * r.film_slope_m_per_n);
            let roller = RollerOutput {
                approach_m: r.approach_m,
                central_film_in_m: fin.central_m,
                central_film_out_m: fout.central_m,
                min_film_in_m: fin.minimum_m,
                min_film_out_m: fout.minimum_m,
                roller_stiffness_n_per_m: s0 / (1.0 - s0 * r.film_slope_m_per_n),
                regime_in: r.regimes[0],
                regime_out: r.regimes[1],
                film_source_in: fin.source,
                film_source_out: fout.source,
                ..RollerOutput::ZERO
            };
            (r.load, roller, coupling)
        })
    }

    /// Run [`Bearing::step`] `steps` times at the same state, so the warm start converges
    /// before a real-time loop begins (three steps reach |Δh|/h ≤ 10⁻³ from a cold start).
    pub fn settle<F: FilmModel + ?Sized>(
        &mut self,
        film: &F,
        state: &OperatingState,
        steps: usize,
    ) -> &BearingOutput<Z> {
        for _ in 0..steps.saturating_sub(1) {
            self.step(film, state);
        }
        self.step(film, state)
    }

    /// One dry step (film ≡ 0): today's multi-body practice, for comparison.
    pub fn step_dry(&mut self, state: &OperatingState) -> &BearingOutput<Z> {
        if let Err(e) = state.check() {
            return self.reject(e);
        }
        self.assemble(state, |bearing, _, geometric, tilt| {
            let load = bearing.roller.evaluate(geometric, tilt);
            let roller = RollerOutput {
                approach_m: geometric,
                roller_stiffness_n_per_m: load.stiffness_n_per_m,
                regime_in: Regime::Dry,
                regime_out: Regime::Dry,
                ..RollerOutput::ZERO
            };
            (load, roller, 0.0)
        })
    }

    fn reject(&mut self, error: ParamError) -> &BearingOutput<Z> {
        self.output = BearingOutput::ZERO;
        self.output.status = StepStatus::Rejected(error);
        &self.output
    }

    /// Run `roller_step` for every roller and sum forces, moments, stiffness and damping.
    /// `roller_step(self, j, geometric approach, tilt)` returns the slice load, the roller's
    /// film fields and the film coupling factor of the stiffness (see `add_roller_stiffness`).
    fn assemble(
        &mut self,
        state: &OperatingState,
        mut roller_step: impl FnMut(
            &mut Self,
            usize,
            f32,
            f32,
        ) -> (crate::contact::RollerLoad, RollerOutput, f32),
    ) -> &BearingOutput<Z> {
        let [x, y] = state.displacement_m;
        let [vx, vy] = state.velocity_m_s;
        let [tilt_x, tilt_y] = state.tilt_rad;
        let clearance = self.params.geometry.radial_clearance_m();
        let damping = self.params.damping_factor_s;
        let (sin_c, cos_c) = sin_cos(state.cage_angle_rad);
        let mut out = BearingOutput::<Z>::ZERO;
        for j in 0..Z {
            let (cp, sp) = self.pitch.get(j).copied().unwrap_or((1.0, 0.0));
            // Roller direction θ_j = θ_c + 2πj/Z by the angle-sum identities.
            let c = cos_c * cp - sin_c * sp;
            let s = sin_c * cp + cos_c * sp;
            let geometric = x * c + y * s - clearance;
            let tilt = tilt_y * c - tilt_x * s;
            let (load, mut roller, coupling) = roller_step(self, j, geometric, tilt);
            let approach_rate = vx * c + vy * s;
            let damping_force = damping * load.stiffness_n_per_m * approach_rate;
            // A roller pushes, it cannot pull: the total roller force is clamped at zero.
            let roller_force = (load.load_n + damping_force).max(0.0);
            out.force_n[0] -= roller_force * c;
            out.force_n[1] -= roller_force * s;
            out.moment_nm[0] += load.moment_nm * s;
            out.moment_nm[1] -= load.moment_nm * c;
            add_roller_stiffness(
                &mut out.stiffness,
                (c, s),
                [
                    load.stiffness_n_per_m,
                    load.stiffness_moment_n,
                    load.stiffness_tilt_nm,
                ],
                coupling,
            );
            let cd = damping * load.stiffness_n_per_m;
            out.damping_n_s_per_m[0][0] += cd * c * c;
            out.damping_n_s_per_m[0][1] += cd * c * s;
            out.damping_n_s_per_m[1][0] += cd * c * s;
            out.damping_n_s_per_m[1][1] += cd * s * s;
            roller.angle_rad = wrap_angle(
                state.cage_angle_rad + self.pitch_angle_rad.get(j).copied().unwrap_or(0.0),
            );
            roller.geometric_approach_m = geometric;
            roller.load_n = load.load_n;
            roller.damping_force_n = damping_force;
            roller.moment_nm = load.moment_nm;
            roller.contact_stiffness_n_per_m = load.stiffness_n_per_m;
            if let Some(slot) = out.rollers.get_mut(j) {
                *slot = roller;
            }
        }
        self.output = out;
        &self.output
    }
}

/// Wrap an angle into [−π, π] at a fixed cost.
fn wrap_angle(angle_rad: f32) -> f32 {
    let turns = angle_rad * (0.5 * core::f32::consts::FRAC_1_PI);
    let whole = (turns + if turns >= 0.0 { 0.5 } else { -0.5 }) as i32;
    angle_rad - whole as f32 * (2.0 * core::f32::consts::PI)
}

#[cfg(test)]
mod tests;
