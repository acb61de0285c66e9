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
mod film_table;
mod lockstep;
#[cfg(feature = "nalgebra")]
mod nalgebra;
mod output;

pub use coupling::NEWTON_ITERATIONS;
pub use equilibrium::Equilibrium;
pub use film_table::{REFRESHES_PER_STEP, SPEED_EXPONENT, TABLE_NODES, TABLE_STEP};
pub use output::{BearingOutput, RollerOutput, StepStatus};

use crate::contact::{ContactLaw, SlicedRoller};
use crate::error::{in_range, Allowed, ParamError};
use crate::film::{ContactInput, FilmModel, FilmSource, Regime, RegimeAxis, ServedLoads};
use crate::lanes::{Wide, WIDE_LANES};
use crate::math::{ln, select, sin_cos};
use crate::params::{reduced_modulus, BearingGeometry, Lubricant, Material, OperatingState};
use core::f32::consts::PI;
use coupling::{finish_roller, prepare_roller, ContactContext, CoupledRoller, RollerMemory};
use film_table::FilmTable;
use output::StiffnessSums;

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

/// Steps [`Bearing::settle`] needs from a cold start (tested over the PHYSICS.md §5.3 domain).
pub const SETTLE_STEPS: usize = 6;

/// Floor of the entrainment speed in the film arithmetic (m/s); see `contact_contexts`.
const MIN_ENTRAINMENT_M_S: f32 = 1.0e-6;

/// ln Q span of the film nodes before any step has loaded a roller: 10 N … 3 kN.
const DEFAULT_LOAD_SPAN: (f32, f32) = (core::f32::consts::LN_10, 8.006_368);

/// The logarithms of a contact's Moes groups that do not change with the speed.
#[derive(Clone, Copy, Debug)]
struct ContactLogs {
    /// ln(E'·R).
    ln_er: f32,
    /// ln G = ln(α·E').
    ln_g: f32,
    /// ln(l·E'·R).
    ln_ler: f32,
}

impl ContactLogs {
    fn of(params: &BearingParams, outer: bool) -> Self {
        let c = params.contact_input(outer, 0.0, 0.0);
        let er = c.reduced_modulus_pa * c.reduced_radius_m;
        Self {
            ln_er: ln(er),
            ln_g: ln(c.pressure_viscosity_pa_inv * c.reduced_modulus_pa),
            ln_ler: ln(c.length_m * er),
        }
    }
}

/// A bearing of `Z` rollers with `S` slices each, with its warm start.
#[derive(Clone, Debug)]
pub struct Bearing<const Z: usize, const S: usize> {
    params: BearingParams,
    roller: SlicedRoller<S>,
    /// cos and sin of 2πj/Z, the roller positions relative to the cage, and 2πj/Z (rad).
    pitch: [(f32, f32, f32); Z],
    /// Speed-independent logarithms of the inner and outer contact.
    contact_logs: [ContactLogs; 2],
    /// What each roller carries to the next step: the warm start.
    memory: [RollerMemory; Z],
    /// ln Q of the lightest and heaviest loaded roller at the last step: where the next step
    /// renews the film table first.
    load_span: (f32, f32),
    /// The film of both contact kinds against the load (`film_table`).
    table: FilmTable,
    /// The table has not been filled since `new` or `reset`: the next step fills all of it.
    table_stale: bool,
    /// The loads the film model serves at each contact kind (inner, outer), as last renewed.
    served: [ServedLoads; 2],
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
        let mut pitch = [(1.0, 0.0, 0.0); Z];
        for (j, p) in pitch.iter_mut().enumerate() {
            let a = 2.0 * core::f32::consts::PI * j as f32 / Z as f32;
            *p = (libm::cosf(a), libm::sinf(a), a);
        }
        let roller = SlicedRoller::new(&params.geometry, params.reduced_modulus_pa, params.law);
        Ok(Self {
            roller,
            contact_logs: [
                ContactLogs::of(&params, false),
                ContactLogs::of(&params, true),
            ],
            params,
            pitch,
            memory: [RollerMemory::cold(&roller); Z],
            load_span: DEFAULT_LOAD_SPAN,
            table: FilmTable::default(),
            table_stale: true,
            served: [ServedLoads::everywhere(FilmSource::None); 2],
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
        self.memory = [RollerMemory::cold(&self.roller); Z];
        self.load_span = DEFAULT_LOAD_SPAN;
        self.table_stale = true;
    }

    /// Per-step data of the two contacts (inner, outer).
    fn contact_contexts(&self, shaft_speed_rad_s: f32) -> [ContactContext; 2] {
        let p = &self.params;
        let context = |(outer, logs): (bool, &ContactLogs)| {
            let mut template = p.contact_input(outer, 0.0, shaft_speed_rad_s);
            // Computed with a floor of 1 µm/s on the entrainment speed, so a shaft at standstill
            // runs the same arithmetic, on normal (not subnormal) numbers, as a turning one:
            // exact zeros and subnormals took a different number of instructions on the
            // emulated M4. At the floor the films are ≈10⁻¹⁰ m and a roller 1 µm clear of its
            // races still carries ≈0.03 N of hydrodynamic load; the step reports zero films,
            // dry regimes and no film source at standstill.
            template.entrainment_speed_m_s =
                crate::math::max(template.entrainment_speed_m_s, MIN_ENTRAINMENT_M_S);
            let speed = template.viscosity_pa_s * template.entrainment_speed_m_s;
            let ln_2u = core::f32::consts::LN_2 + ln(speed) - logs.ln_er;
            ContactContext {
                template,
                martin: 6.0 * speed * template.reduced_radius_m * template.length_m,
                ln_m_offset: logs.ln_ler + 0.5 * ln_2u,
                ln_l: logs.ln_g + 0.25 * ln_2u,
            }
        };
        [
            context((false, &self.contact_logs[0])),
            context((true, &self.contact_logs[1])),
        ]
    }

    /// One lubricated step: roller films from `film`, film-coupled loads, forces, stiffness.
    ///
    /// The film model is called at [`REFRESHES_PER_STEP`] node(s) of the bearing's film table
    /// (`film_table`: by turns the next node of the loaded range or of the whole table, for
    /// one contact kind), so every step costs the same; the first step after [`Bearing::new`]
    /// or [`Bearing::reset`] fills the whole table. [`Bearing::settle`] (the whole table at its
    /// first step) converges the warm start before a real-time loop, and is the call for
    /// quasi-static use (equilibrium iterations), where the force must be one function of the
    /// state.
    ///
    /// A refused `state` leaves the warm start as it was and returns a zero output whose
    /// status names the bad field.
    pub fn step<F: FilmModel + ?Sized>(
        &mut self,
        film: &F,
        state: &OperatingState,
    ) -> &BearingOutput<Z> {
        let renew_all = self.table_stale;
        self.step_renewing(film, state, renew_all)
    }

    /// [`Bearing::step`], renewing every node of the film table (`renew_all`) or the next.
    fn step_renewing<F: FilmModel + ?Sized>(
        &mut self,
        film: &F,
        state: &OperatingState,
        renew_all: bool,
    ) -> &BearingOutput<Z> {
        if let Err(e) = state.check() {
            return self.reject(e);
        }
        let [inner, outer] = self.contact_contexts(state.shaft_speed_rad_s);
        let lubricated = self
            .params
            .geometry
            .entrainment_speed_m_s(state.shaft_speed_rad_s)
            > 0.0;
        let film_shown = if lubricated { 1.0 } else { 0.0 };
        let templates = [inner.template, outer.template];
        // At standstill every contact reports no film source: an interval covering every load
        // with source `None`, chosen field by field so that no roller takes a branch.
        let standstill = |s: ServedLoads| ServedLoads {
            ln_load_min: crate::math::select(lubricated, s.ln_load_min, f32::MIN),
            ln_load_max: crate::math::select(lubricated, s.ln_load_max, f32::MAX),
            source: [FilmSource::None, s.source]
                .get(usize::from(lubricated))
                .copied()
                .unwrap_or(FilmSource::None),
        };
        // The loads the film model serves follow the speed. They are renewed with the table,
        // for one contact per step (the one whose node this step renews; both when the whole
        // table is), so a contact's interval is at most a step old.
        // One code path whichever contact it is (an index, not a branch per contact: with
        // the regression's trivial interval, the two branches differed by an instruction).
        let renewed = self.table.next_contact();
        if renew_all {
            self.served = templates.map(|t| film.served_loads(&t));
        } else if let (Some(slot), Some(template)) =
            (self.served.get_mut(renewed), templates.get(renewed))
        {
            *slot = film.served_loads(template);
        }
        let served = self.served.map(standstill);
        let martin = [inner.martin, outer.martin];
        let films = self
            .table
            .step(film, templates, martin, self.load_span, renew_all);
        self.table_stale = false;
        let regime_axes = [inner, outer].map(|c| RegimeAxis::new(c.ln_m_offset, c.ln_l));
        let mut span = (f32::MAX, f32::MIN);
        let parts = Parts {
            params: &self.params,
            roller: &self.roller,
            pitch: &self.pitch,
        };
        let places = parts.places(state);
        // Each roller: its slice pass and power law (`prepare_roller`), NEWTON_ITERATIONS
        // Newton steps, its outputs (`finish_roller`). A superscalar host runs all of that
        // for eight rollers at a time in SIMD lanes (AVX2; four without it), several groups
        // in flight (`lockstep`): each stage is a chain of dependent operations whose latency
        // the core cannot hide one roller after another. The in-order M4 gains nothing from
        // lanes and would pay ≈ 4 k instructions of loads and stores for the staged state, so
        // it runs the rollers one after another. The operations of each roller are the same either way, so are
        // the results, bit for bit (tests in `lanes`, `coupling`, `slicing` and `lockstep`;
        // `hil-sim qemu` compares whole traces).
        let mut coupled = [CoupledRoller::default(); Z];
        if LOCKSTEP {
            lockstep::Lockstep {
                roller: &self.roller,
                films: &films,
                regime_axes: &regime_axes,
            }
            .solve(&places, &mut self.memory, &mut coupled);
        }
        parts.assemble(
            &mut self.memory,
            &mut self.output,
            state,
            &places,
            |roller, memory, j, geometric, tilt| {
                let r = if LOCKSTEP {
                    coupled.get(j).copied().unwrap_or_default()
                } else {
                    let mut p = prepare_roller(roller, geometric, tilt, memory);
                    // A local copy, which the compiler keeps in registers.
                    let mut newton = p.newton;
                    for _ in 0..NEWTON_ITERATIONS {
                        newton.iterate(&films);
                    }
                    p.newton = newton;
                    finish_roller(&p, &films, &regime_axes, memory)
                };
                let loaded = r.load.load_n >= 1.0;
                span = (
                    crate::math::min(span.0, crate::math::select(loaded, r.ln_load, f32::MAX)),
                    crate::math::max(span.1, crate::math::select(loaded, r.ln_load, f32::MIN)),
                );
                let [(central_in, min_in), (central_out, min_out)] = r.films;
                // Films are finite: hidden at standstill by a factor 0 or 1.
                let shown = |h: f32| h * film_shown;
                // A table, not an `if`: the work must not depend on the speed.
                let shown_regime = |r: Regime| {
                    [Regime::Dry, r]
                        .get(usize::from(lubricated))
                        .copied()
                        .unwrap_or(Regime::Dry)
                };
                let roller = RollerOutput {
                    approach_m: r.approach_m,
                    central_film_in_m: shown(central_in),
                    central_film_out_m: shown(central_out),
                    min_film_in_m: shown(min_in),
                    min_film_out_m: shown(min_out),
                    roller_stiffness_n_per_m: r.load.stiffness_n_per_m * r.softening,
                    regime_in: shown_regime(r.regimes[0]),
                    regime_out: shown_regime(r.regimes[1]),
                    film_source_in: served[0].source_at(r.ln_load),
                    film_source_out: served[1].source_at(r.ln_load),
                    ..RollerOutput::ZERO
                };
                (r.load, roller, r.film_coupling_m_per_n)
            },
        );
        // The loads the next step renews the table at first; unchanged when nothing is loaded.
        if span.0 <= span.1 {
            self.load_span = span;
        }
        &self.output
    }

    /// Run [`Bearing::step`] `steps ≥ 1` times at the same state, the first renewing the whole
    /// film table, so the warm start converges before a real-time loop begins
    /// ([`SETTLE_STEPS`] reach |Δh|/h ≤ 10⁻³ from a cold start; a crowned roller just touching
    /// needs four: its first step has no power law of its own).
    pub fn settle<F: FilmModel + ?Sized>(
        &mut self,
        film: &F,
        state: &OperatingState,
        steps: usize,
    ) -> &BearingOutput<Z> {
        // The table depends on the speed alone: filled once, it is the model's at this state.
        self.step_renewing(film, state, true);
        for _ in 1..steps {
            self.step_renewing(film, state, false);
        }
        &self.output
    }

    /// One dry step (film ≡ 0): today's multi-body practice, for comparison.
    pub fn step_dry(&mut self, state: &OperatingState) -> &BearingOutput<Z> {
        if let Err(e) = state.check() {
            return self.reject(e);
        }
        let parts = Parts {
            params: &self.params,
            roller: &self.roller,
            pitch: &self.pitch,
        };
        let places = parts.places(state);
        // The host runs the slice pass of eight rollers at a time in SIMD lanes (four without
        // AVX2), as the lubricated step does; the M4 one roller after another. Same operations,
        // same results bit for bit (`slicing`'s lane test).
        let mut loads = [crate::contact::RollerLoad::default(); Z];
        if LOCKSTEP {
            for (group, group_places) in loads.chunks_mut(WIDE_LANES).zip(places.chunks(WIDE_LANES))
            {
                let mut approach = [0.0; WIDE_LANES];
                let mut tilt = [0.0; WIDE_LANES];
                for ((a, t), place) in approach.iter_mut().zip(tilt.iter_mut()).zip(group_places) {
                    *a = place.geometric_m;
                    *t = place.tilt_rad;
                }
                let group_loads = self
                    .roller
                    .evaluate_lanes::<Wide, { WIDE_LANES }>(approach, tilt);
                for (i, load) in group.iter_mut().enumerate() {
                    *load = group_loads.lane(i);
                }
            }
        }
        parts.assemble(
            &mut self.memory,
            &mut self.output,
            state,
            &places,
            |roller, _, j, geometric, tilt| {
                let load = if LOCKSTEP {
                    loads.get(j).copied().unwrap_or_default()
                } else {
                    roller.evaluate(geometric, tilt)
                };
                let roller = RollerOutput {
                    approach_m: geometric,
                    roller_stiffness_n_per_m: load.stiffness_n_per_m,
                    regime_in: Regime::Dry,
                    regime_out: Regime::Dry,
                    ..RollerOutput::ZERO
                };
                (load, roller, 0.0)
            },
        );
        &self.output
    }

    fn reject(&mut self, error: ParamError) -> &BearingOutput<Z> {
        self.output = BearingOutput::ZERO;
        self.output.status = StepStatus::Rejected(error);
        &self.output
    }
}

/// Whether the lubricated step solves the rollers in SIMD lanes, four at a time (hosts:
/// `lockstep`), or each roller in turn (bare-metal ARM: the in-order Cortex-M).
const LOCKSTEP: bool = !cfg!(all(target_arch = "arm", target_os = "none"));

/// A roller's direction (cos, sin of θ_j), geometric approach (m) and tilt (rad) at a step.
#[derive(Clone, Copy, Debug, Default)]
struct Place {
    cos: f32,
    sin: f32,
    geometric_m: f32,
    tilt_rad: f32,
}

/// The parts of a bearing the roller loop reads, borrowed apart from the warm start and the
/// output it writes (and from the film table the lubricated step's closure reads).
struct Parts<'a, const Z: usize, const S: usize> {
    params: &'a BearingParams,
    roller: &'a SlicedRoller<S>,
    pitch: &'a [(f32, f32, f32); Z],
}

impl<const Z: usize, const S: usize> Parts<'_, Z, S> {
    /// Where each roller is: its direction θ_j = θ_c + 2πj/Z (by the angle-sum identities),
    /// geometric approach and tilt relative to the raceway.
    fn places(&self, state: &OperatingState) -> [Place; Z] {
        let [x, y] = state.displacement_m;
        let [tilt_x, tilt_y] = state.tilt_rad;
        let clearance = self.params.geometry.radial_clearance_m();
        let (sin_c, cos_c) = sin_cos(state.cage_angle_rad);
        let mut places = [Place::default(); Z];
        for (place, &(cp, sp, _)) in places.iter_mut().zip(self.pitch.iter()) {
            let c = cos_c * cp - sin_c * sp;
            let s = sin_c * cp + cos_c * sp;
            *place = Place {
                cos: c,
                sin: s,
                geometric_m: x * c + y * s - clearance,
                tilt_rad: tilt_y * c - tilt_x * s,
            };
        }
        places
    }

    /// Run `roller_step` for every roller and sum forces, moments, stiffness and damping.
    /// `roller_step(roller, its warm start, j, geometric approach, tilt)` returns the slice
    /// load, the roller's film fields and the film coupling factor of the stiffness (see
    /// `StiffnessSums`).
    fn assemble(
        &self,
        memory: &mut [RollerMemory; Z],
        out: &mut BearingOutput<Z>,
        state: &OperatingState,
        places: &[Place; Z],
        mut roller_step: impl FnMut(
            &SlicedRoller<S>,
            &mut RollerMemory,
            usize,
            f32,
            f32,
        ) -> (crate::contact::RollerLoad, RollerOutput, f32),
    ) {
        let [vx, vy] = state.velocity_m_s;
        let damping = self.params.damping_factor_s;
        // Every roller entry is written below; the sums start from zero (in place: the output
        // is a kilobyte and a half, and a copy of it costs as much as a roller).
        out.force_n = [0.0; 2];
        out.moment_nm = [0.0; 2];
        out.status = StepStatus::Ok;
        let mut stiffness = StiffnessSums::default();
        let cage_angle = wrap_angle(state.cage_angle_rad);
        for (j, ((&(_, _, pitch_angle), place), (slot, roller_memory))) in self
            .pitch
            .iter()
            .zip(places.iter())
            .zip(out.rollers.iter_mut().zip(memory.iter_mut()))
            .enumerate()
        {
            let (c, s, geometric) = (place.cos, place.sin, place.geometric_m);
            let (load, mut roller, coupling) =
                roller_step(self.roller, roller_memory, j, geometric, place.tilt_rad);
            let approach_rate = vx * c + vy * s;
            let damping_force = damping * load.stiffness_n_per_m * approach_rate;
            // A roller pushes, it cannot pull: the total roller force is clamped at zero.
            let roller_force = crate::math::max(load.load_n + damping_force, 0.0);
            out.force_n[0] -= roller_force * c;
            out.force_n[1] -= roller_force * s;
            out.moment_nm[0] += load.moment_nm * s;
            out.moment_nm[1] -= load.moment_nm * c;
            stiffness.add(
                (c, s),
                [
                    load.stiffness_n_per_m,
                    load.stiffness_moment_n,
                    load.stiffness_tilt_nm,
                ],
                coupling,
            );
            // θ_c ∈ [−π, π] plus 2πj/Z ∈ [0, 2π): one turn back at most.
            let angle = cage_angle + pitch_angle;
            roller.angle_rad = angle - select(angle > PI, 2.0 * PI, 0.0);
            roller.geometric_approach_m = geometric;
            roller.load_n = load.load_n;
            roller.damping_force_n = damping_force;
            roller.moment_nm = load.moment_nm;
            roller.contact_stiffness_n_per_m = load.stiffness_n_per_m;
            *slot = roller;
        }
        out.stiffness = stiffness.matrix();
        out.damping_n_s_per_m = stiffness.damping(damping);
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
