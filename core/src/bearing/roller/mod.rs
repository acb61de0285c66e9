//! The cylindrical roller bearing: from inner-race motion to roller loads, forces, stiffness
//! and damping.
//!
//! [`Bearing`] owns everything a step needs (sliced rollers, roller directions, the film model
//! chosen at construction, the cage angle, the warm start and the film table) in fixed arrays
//! sized by the const generics `Z` (rollers) and `S` (slices per roller). Two calls run the
//! pipeline of docs/physics.md §4:
//!
//! - [`Bearing::advance`], the real-time step: it moves time on by `dt`, integrating the cage
//!   angle, and carries the warm start and one film-table node to the next step;
//! - [`Bearing::evaluate`], a trial for implicit integrators: the same computation from the
//!   committed state, which it leaves as it was, so its result depends on the committed state
//!   and the trial input alone, however many trials came before.
//!
//! Both take the same number of operations for every input, and neither can panic: a bad
//! operating state or time step is refused with an `Err` naming the field, and nothing is
//! committed. The roller bearing's parts: its design and validated parameters (`design`,
//! `params`), the slice–film coupling of one roller (`coupling`), the film table (`film_table`),
//! the placement of the rollers and the sums over them (`parts`), the host's lockstep lanes
//! (`lockstep`), the friction pass (`friction`) and the static solve (`equilibrium`).

mod coupling;
mod design;
mod dry;
mod equilibrium;
mod film_table;
mod friction;
mod lockstep;
#[cfg(feature = "nalgebra")]
mod nalgebra;
mod output;
mod params;
mod parts;

pub use design::BearingDesign;
pub use equilibrium::Equilibrium;
pub use output::{BearingOutput, OutputView, RollerOutput, RollerTotals};
pub use params::{BearingParams, STEEL_DENSITY_KG_M3};
use parts::{Parts, Place, LOCKSTEP};

use super::cage::wrap_turns;
use super::FilmKind;
use crate::contact::SlicedRoller;
use crate::error::{in_range, Allowed, ParamError};
use crate::film::ann::{AnnF32, AnnInt};
use crate::film::{
    ContactInput, FilmModel, FilmSource, Regime, RegimeAxis, Regression, ServedLoads,
};
use crate::math::ln;
use crate::params::{OperatingState, MAX_CAGE_ANGLE_RAD, MAX_TIME_STEP_S};
use coupling::NEWTON_ITERATIONS;
use coupling::{finish_roller, prepare_roller, ContactContext, CoupledRoller, RollerMemory};
use film_table::FilmTable;

/// Steps [`Bearing::settle`] needs from a cold start (tested over the docs/physics.md §5.3 domain).
pub const SETTLE_STEPS: usize = 6;

/// What a pass of the step does to the committed state.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Pass {
    /// A trial ([`Bearing::evaluate`]): nothing committed changes. (On a film table not yet
    /// filled, the trial fills all of it at its own speed, as every trial until the first
    /// commit does, so the result is still a function of the trial input.)
    Trial,
    /// A real-time step ([`Bearing::advance`]): cage angle, warm start and the next node of
    /// the film table (all of it when not yet filled) are committed.
    Advance,
    /// As `Advance`, renewing every node of the film table ([`Bearing::settle`]'s first step).
    RenewAll,
}

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

/// A bearing of `Z` rollers with `S` slices each, stepping with one film model, with its cage
/// angle and warm start.
///
/// ```
/// use bearing_core::{Bearing, BearingDesign, FilmKind, OperatingState};
///
/// let params = BearingDesign::NU205.params()?;
/// let mut bearing = Bearing::<12, 10>::new(params, FilmKind::Regression)?;
/// let state = OperatingState::new([0.0, -4.0e-6], [0.0; 2], [0.0; 2], 1000.0)?;
/// bearing.settle(&state, bearing_core::bearing::SETTLE_STEPS)?;
/// let out = bearing.advance(&state, 1.0e-4)?;
/// assert!(out.force_n[1] > 0.0); // the rollers push the race back up
/// # Ok::<(), bearing_core::ParamError>(())
/// ```
#[derive(Clone, Debug)]
pub struct Bearing<const Z: usize, const S: usize> {
    params: BearingParams,
    /// The film model every step uses and the film table holds.
    film: FilmKind,
    /// Committed cage angle θ_c (rad), wrapped by whole turns into (−2π, 2π): [0, 2π) while
    /// the shaft turns forward.
    cage_angle_rad: f32,
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
    /// A bearing whose geometry has exactly `Z` rollers, sliced `S ≥ 1` times, stepping with
    /// the film model `film`; cage angle 0, cold warm start, film table empty (the first
    /// committing step fills it).
    ///
    /// ```
    /// use bearing_core::{Bearing, BearingDesign, FilmKind};
    /// let params = BearingDesign::HUB_MOTOR.params()?;
    /// assert!(Bearing::<17, 10>::new(params, FilmKind::Int).is_ok());
    /// let wrong = Bearing::<12, 10>::new(params, FilmKind::Int).unwrap_err();
    /// assert_eq!(wrong.field, "roller_count");
    /// # Ok::<(), bearing_core::ParamError>(())
    /// ```
    pub fn new(params: BearingParams, film: FilmKind) -> Result<Self, ParamError> {
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
            film,
            cage_angle_rad: 0.0,
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

    /// The film model, chosen at construction.
    pub fn film(&self) -> FilmKind {
        self.film
    }

    /// The output of the last call that computed ([`Bearing::advance`],
    /// [`Bearing::evaluate`], [`Bearing::settle`]); all zero before the first.
    pub fn output(&self) -> &BearingOutput<Z> {
        &self.output
    }

    /// The committed cage angle θ_c (rad): roller j sits at θ_c + 2πj/Z (docs/physics.md §2).
    /// Kept within (−2π, 2π) by whole turns, in [0, 2π) while the shaft turns forward.
    pub fn cage_angle_rad(&self) -> f32 {
        self.cage_angle_rad
    }

    /// Set the cage angle θ_c (rad, finite, |θ_c| ≤ 10⁴), wrapped by whole turns as
    /// [`Bearing::advance`] wraps it.
    pub fn set_cage_angle(&mut self, cage_angle_rad: f32) -> Result<(), ParamError> {
        let angle = in_range(
            "cage_angle_rad",
            cage_angle_rad,
            -MAX_CAGE_ANGLE_RAD,
            MAX_CAGE_ANGLE_RAD,
        )?;
        self.cage_angle_rad = wrap_turns(angle);
        Ok(())
    }

    /// Forget the warm start and the film table (the next step starts from unloaded rollers
    /// and fills the whole table); the cage angle is kept.
    pub fn reset(&mut self) {
        self.memory = [RollerMemory::cold(&self.roller); Z];
        self.load_span = DEFAULT_LOAD_SPAN;
        self.table_stale = true;
    }

    /// The real-time step: time moves on by `dt_s` (s, 0 … 1) to the inner-race motion
    /// `state`. The cage turns by ω_c·dt at the cage speed ω_c = (ω/2)(1 − D/d_m) of the
    /// state's shaft speed (docs/physics.md §2) and is wrapped by whole turns, so a run may last
    /// any time; the warm start carries to the next step, and the film table renews one node
    /// (the whole table at the first step after [`Bearing::new`] or [`Bearing::reset`]). The
    /// work is the same at every step.
    ///
    /// A refused `state` or `dt_s` returns the error naming the field and commits nothing.
    ///
    /// ```
    /// use bearing_core::{Bearing, BearingDesign, FilmKind, OperatingState};
    /// let mut bearing = Bearing::<17, 10>::new(BearingDesign::HUB_MOTOR.params()?, FilmKind::Dry)?;
    /// let state = OperatingState::new([0.0, -5.0e-6], [0.0; 2], [0.0; 2], 2000.0)?;
    /// bearing.advance(&state, 1.0e-3)?;
    /// // ω_c = 0.5·2000·(1 − 8.8/60) rad/s for 1 ms.
    /// assert!((bearing.cage_angle_rad() - 0.853_333).abs() < 1e-5);
    /// let refused = bearing.advance(&state, f32::NAN).unwrap_err();
    /// assert_eq!(refused.field, "time_step_s");
    /// # Ok::<(), bearing_core::ParamError>(())
    /// ```
    pub fn advance(
        &mut self,
        state: &OperatingState,
        dt_s: f32,
    ) -> Result<&BearingOutput<Z>, ParamError> {
        self.run(state, dt_s, Pass::Advance)
    }

    /// A trial evaluation for implicit integrators: the output at the inner-race motion
    /// `state`, `dt_s` (s, 0 … 1) after the committed state, with the cage turned as
    /// [`Bearing::advance`] would turn it. The committed state (cage angle, warm start, film
    /// table) is left as it was: the result depends on it and on the arguments alone, bit for
    /// bit, however many trials came before. Commit the accepted state with
    /// [`Bearing::advance`].
    ///
    /// ```
    /// use bearing_core::{Bearing, BearingDesign, FilmKind, OperatingState};
    /// let mut bearing = Bearing::<12, 10>::new(BearingDesign::NU205.params()?, FilmKind::Regression)?;
    /// let state = OperatingState::new([0.0, -4.0e-6], [0.0; 2], [0.0; 2], 1500.0)?;
    /// bearing.settle(&state, 3)?;
    /// let first = *bearing.evaluate(&state, 1.0e-4)?;
    /// let trial = OperatingState { displacement_m: [0.0, -5.0e-6], ..state };
    /// bearing.evaluate(&trial, 1.0e-4)?;
    /// assert_eq!(*bearing.evaluate(&state, 1.0e-4)?, first);
    /// # Ok::<(), bearing_core::ParamError>(())
    /// ```
    pub fn evaluate(
        &mut self,
        state: &OperatingState,
        dt_s: f32,
    ) -> Result<&BearingOutput<Z>, ParamError> {
        self.run(state, dt_s, Pass::Trial)
    }

    /// The cage angle `dt_s` after the committed one at shaft speed ω, wrapped by whole turns
    /// (one float-to-integer truncation: its cost does not depend on the angle, unlike
    /// `floorf`'s on the M4): exact into [0, 2π) for the non-negative angles of forward
    /// rotation, within (−2π, 2π) otherwise.
    fn cage_angle_after(&self, shaft_speed_rad_s: f32, dt_s: f32) -> f32 {
        let turned = self.params.geometry.cage_speed_rad_s(shaft_speed_rad_s) * dt_s;
        wrap_turns(self.cage_angle_rad + turned)
    }

    /// Check the inputs, then one pass with the bearing's film model.
    fn run(
        &mut self,
        state: &OperatingState,
        dt_s: f32,
        pass: Pass,
    ) -> Result<&BearingOutput<Z>, ParamError> {
        state.check()?;
        in_range("time_step_s", dt_s, 0.0, MAX_TIME_STEP_S)?;
        let cage_angle_rad = self.cage_angle_after(state.shaft_speed_rad_s, dt_s);
        // The centrifugal force is a compile-time switch of the lubricated pass, in a function
        // of its own: a bearing without it runs the code it ran before.
        if self.params.centrifugal_density_kg_m3.is_some() {
            self.lubricated_centrifugal(state, cage_angle_rad, pass);
        } else {
            match self.film {
                FilmKind::Int => self.lubricated::<_, false>(&AnnInt, state, cage_angle_rad, pass),
                FilmKind::F32 => self.lubricated::<_, false>(&AnnF32, state, cage_angle_rad, pass),
                FilmKind::Regression => {
                    self.lubricated::<_, false>(&Regression, state, cage_angle_rad, pass)
                }
                FilmKind::Dry => self.dry(state, cage_angle_rad),
            }
        }
        if pass != Pass::Trial {
            self.cage_angle_rad = cage_angle_rad;
        }
        Ok(&self.output)
    }

    /// The pass of a bearing with the rollers' centrifugal force (docs/physics.md §4.1), with
    /// the bearing's film model. Not inlined into `run`: six copies of the lubricated pass
    /// there cost the step without it ≈ 300 instructions on the M4.
    #[inline(never)]
    fn lubricated_centrifugal(&mut self, state: &OperatingState, cage_angle_rad: f32, pass: Pass) {
        match self.film {
            FilmKind::Int => self.lubricated::<_, true>(&AnnInt, state, cage_angle_rad, pass),
            FilmKind::F32 => self.lubricated::<_, true>(&AnnF32, state, cage_angle_rad, pass),
            FilmKind::Regression => {
                self.lubricated::<_, true>(&Regression, state, cage_angle_rad, pass)
            }
            FilmKind::Dry => self.dry(state, cage_angle_rad),
        }
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
                martin: crate::film::MARTIN * speed * template.reduced_radius_m * template.length_m,
                ln_m_offset: logs.ln_ler + 0.5 * ln_2u,
                ln_l: logs.ln_g + 0.25 * ln_2u,
            }
        };
        [
            context((false, &self.contact_logs[0])),
            context((true, &self.contact_logs[1])),
        ]
    }

    /// [`Bearing::settle`] with another film model than the bearing's (a test double).
    #[cfg(test)]
    pub(crate) fn settle_with<F: FilmModel>(
        &mut self,
        film: &F,
        state: &OperatingState,
        steps: usize,
    ) -> BearingOutput<Z> {
        let angle = self.cage_angle_rad;
        self.lubricated::<F, false>(film, state, angle, Pass::RenewAll);
        for _ in 1..steps {
            self.lubricated::<F, false>(film, state, angle, Pass::Advance);
        }
        self.output
    }

    /// Renew the loads the film model serves at each contact kind, as a pass renews the film
    /// table (`renew_all`: every node; `renew`: the next one). Inlined into the lubricated
    /// pass, which it was written in: the same instructions.
    #[inline(always)]
    fn renew_served<F: FilmModel>(
        &mut self,
        film: &F,
        templates: &[ContactInput; 2],
        renew_all: bool,
        renew: bool,
    ) {
        // The loads the film model serves follow the speed. They are renewed with the table,
        // for one contact per step (the one whose node this step renews; both when the whole
        // table is), so a contact's interval is at most a step old.
        // One code path whichever contact it is (an index, not a branch per contact: with
        // the regression's trivial interval, the two branches differed by an instruction).
        // A trial renews nothing, except a table never filled: then every trial fills all of
        // it at its own speed (the same bits whatever the trials before), and the first
        // committing pass fills it again.
        let renewed = self.table.next_contact();
        if renew_all {
            self.served = templates.map(|t| film.served_loads(&t));
        } else if let (true, Some(slot), Some(template)) =
            (renew, self.served.get_mut(renewed), templates.get(renewed))
        {
            *slot = film.served_loads(template);
        }
    }

    /// One lubricated pass with the film model `film` (the bearing's own) at cage angle
    /// `cage_angle_rad`; `pass` says what it commits.
    ///
    /// The film model is called at `REFRESHES_PER_STEP` node(s) of the bearing's film table
    /// (`film_table`: by turns the next node of the loaded range or of the whole table, for
    /// one contact kind) by a committing pass, so every step costs the same; a trial reads the
    /// table as committed. Inlined into `run` for every film model: as a call, the integer
    /// network's step cost the M4 ≈ 90 instructions more (28 244 against 28 152 per replayed
    /// hub-motor step).
    #[inline(always)]
    fn lubricated<F: FilmModel, const CENTRIFUGAL: bool>(
        &mut self,
        film: &F,
        state: &OperatingState,
        cage_angle_rad: f32,
        pass: Pass,
    ) {
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
        let renew_all = self.table_stale | (pass == Pass::RenewAll);
        let renew = (pass != Pass::Trial) | self.table_stale;
        self.renew_served(film, &templates, renew_all, renew);
        let served = self.served.map(standstill);
        let martin = [inner.martin, outer.martin];
        let speed_scale = FilmTable::speed_scale(&templates);
        let inv_speed_scale = 1.0 / speed_scale;
        if renew {
            self.table.renew_nodes(
                film,
                (templates, &self.params.film_corrections),
                martin,
                inv_speed_scale,
                self.load_span,
                renew_all,
            );
        }
        // The rollers' centrifugal force on the outer race, if the bearing includes it.
        let centrifugal_n = if CENTRIFUGAL {
            self.params.centrifugal_force_n(state.shaft_speed_rad_s)
        } else {
            None
        };
        let films =
            self.table
                .films_centrifugal(speed_scale, inv_speed_scale, martin, centrifugal_n);
        // A trial works on a copy of the warm start (only a trial pays for the copy).
        let mut trial_memory;
        let memory = if pass == Pass::Trial {
            trial_memory = self.memory;
            &mut trial_memory
        } else {
            self.table_stale = false;
            &mut self.memory
        };
        let regime_axes = [inner, outer].map(|c| RegimeAxis::new(c.ln_m_offset, c.ln_l));
        let mut span = (f32::MAX, f32::MIN);
        let parts = Parts {
            params: &self.params,
            roller: &self.roller,
            pitch: &self.pitch,
        };
        let places = parts.places(state, cage_angle_rad);
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
            .solve(&places, memory, &mut coupled);
        }
        parts.assemble(
            memory,
            &mut self.output,
            state,
            cage_angle_rad,
            &places,
            |roller, memory, j, geometric, tilt| {
                let r = if LOCKSTEP {
                    coupled.get(j).copied().unwrap_or_default()
                } else {
                    let mut p = prepare_roller(roller, geometric, tilt, memory);
                    // A local copy, which the compiler keeps in registers.
                    let mut newton = p.newton;
                    if CENTRIFUGAL {
                        for _ in 0..NEWTON_ITERATIONS {
                            newton.iterate_centrifugal(&films);
                        }
                    } else {
                        for _ in 0..NEWTON_ITERATIONS {
                            newton.iterate(&films);
                        }
                    }
                    p.newton = newton;
                    finish_roller::<CENTRIFUGAL>(&p, &films, &regime_axes, memory)
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
        if CENTRIFUGAL {
            self.output.totals.centrifugal_force_n = centrifugal_n.unwrap_or(0.0);
        }
        // The loads the next step renews the table at first; unchanged when nothing is loaded.
        if (span.0 <= span.1) & (pass != Pass::Trial) {
            self.load_span = span;
        }
    }

    /// Converge the warm start at `state` before a real-time loop, or for quasi-static use
    /// (equilibrium iterations, where the force must be one function of the state):
    /// `steps ≥ 1` committing steps with no time passing (the cage angle stays), the first
    /// renewing the whole film table at this speed. [`SETTLE_STEPS`] reach |Δh|/h ≤ 10⁻³
    /// from a cold start (a crowned roller just touching needs four: its first step has no
    /// power law of its own). The dry model has no warm start: one step. It continues from the
    /// warm start it finds; after a far jump or hostile inputs, [`Bearing::reset`] first makes
    /// the result the fresh bearing's, bit for bit (tested in `core/tests/hostile_sequences.rs`).
    pub fn settle(
        &mut self,
        state: &OperatingState,
        steps: usize,
    ) -> Result<&BearingOutput<Z>, ParamError> {
        self.run(state, 0.0, Pass::RenewAll)?;
        if self.film != FilmKind::Dry {
            for _ in 1..steps {
                self.run(state, 0.0, Pass::Advance)?;
            }
        }
        Ok(&self.output)
    }
}

#[cfg(test)]
mod high_speed_tests;
#[cfg(test)]
mod stepping_tests;
#[cfg(test)]
mod tests;
