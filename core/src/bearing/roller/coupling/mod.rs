//! The film-coupled roller load: a scalar fixed point solved in a fixed amount of work.
//!
//! The film adds to the approach (docs/physics.md §4): δ_j = δ_geo + H(Q_j) with H = h_in + h_out,
//! and Q_j = Q(δ_j) from the slices. H falls with Q (EHL: ∝ Q^−0.1; hydrodynamic: ∝ 1/Q), so
//! the equation has exactly one root for any geometric approach, positive or negative.
//!
//! **Continuity at separation.** The film sum is written H = √(H_e² + H_RI²), with Martin's
//! rigid iso-viscous film H_RI = 6η₀u_m(R_in + R_out)l/Q exact and H_e the rest of the film
//! model's (complete) film, interpolated in the bearing's film table (`film_table`). At high load
//! H_RI vanishes and the film model rules; as the rollers separate, Q → 0 and Martin's
//! hydrodynamic load takes over smoothly. Roller forces are therefore continuous — and
//! differentiable — in the displacement across the transition.
//!
//! **Fixed work.** One pass over the slices per roller and step, at the approach the last
//! step's film predicts (its value there, continued by its sensitivity dH/dδ_geo to the new
//! geometric approach). The whole-roller power law Q = L·(δ − δ_off)^n fitted to the slices
//! there (matched in load, dQ/dδ and d²Q/dδ²; exact for a straight untilted roller under the
//! Palmgren law) carries the scalar equation δ_off + (Q/L)^(1/n) = δ_geo + H(Q), solved in
//! λ = ln Q by [`NEWTON_ITERATIONS`] safeguarded Newton steps with the film from the bearing's
//! film table (`film_table`); load and moment follow that law.
//!
//! From a converged warm start at most 0.25 µm of geometric approach away this meets
//! |Δh|/h ≤ 10⁻³ (tested against a converged f64 iteration over the docs/physics.md §5.3 domain);
//! larger jumps cost accuracy at the lightest loads for one step (see the test).

mod newton;

use super::film_table::StepFilms;
use crate::contact::{RollerLoad, RollerLoads, SlicedRoller};
use crate::film::{ContactInput, Regime, RegimeAxis};
use crate::lanes::Real;
use crate::math::{exp_in_range, ln_normal};
pub(crate) use newton::Newton;

/// Safeguarded Newton steps of the scalar film–load equation per roller and step. Two suffice
/// with the step of `Newton::iterate`: the warm start's accuracy test passes, and the shaft
/// integrator's Newton converges on the forces (`bearing shaft sweep --film int`); the step on
/// ln(D/H) it replaced needed three.
pub const NEWTON_ITERATIONS: usize = 2;
/// ln Q above the dry load where a roller's first solve starts.
const COLD_START_OFFSET: f32 = 0.1;

/// Smallest load at which the slices' (Q, K) are trusted for the power-law fit (N).
const FIT_MIN_N: f32 = 1.0e-3;

/// Per-step data of one contact (inner or outer), shared by all rollers.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ContactContext {
    /// Contact input with the load left to fill in.
    pub template: ContactInput,
    /// Martin coefficient B with h_RI = B/Q: B = 6·η₀·u_m·R·l (m·N).
    pub martin: f32,
    /// ln(l·E'·R) + ½·ln(2U): ln M = ln Q − this.
    pub ln_m_offset: f32,
    /// ln L (Moes) of this contact.
    pub ln_l: f32,
}

/// Result of the coupled solve for one roller.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct CoupledRoller {
    pub load: RollerLoad,
    /// Elastic approach at the roller middle (m).
    pub approach_m: f32,
    /// λ = ln Q at the solution.
    pub ln_load: f32,
    /// (central, minimum) film of the inner and outer contact (m).
    pub films: [(f32, f32); 2],
    /// 1/(1 − K·dH/dQ) ≥ 1, with dH/dQ of the film sum at the solution (≤ 0): the factor by
    /// which the film softens the roller's stiffness.
    pub softening: f32,
    /// The film coupling factor of the stiffness, dH/dQ/(1 − K·dH/dQ) (m/N, ≤ 0; see
    /// `StiffnessSums`).
    pub film_coupling_m_per_n: f32,
    pub regimes: [Regime; 2],
}

/// What a roller carries from one step to the next: the warm start. Of one roller, or of the
/// rollers in the lanes of `T` (the host's lockstep stages).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct RollerMemory<T: Real = f32> {
    /// ln Q at the last step.
    pub ln_load: T,
    /// Film sum H at the last step (m); 0 before the first.
    pub film_m: T,
    /// Geometric approach at the last step (m).
    pub geometric_approach_m: T,
    /// dH/dδ_geo at the last step: how the film followed the geometric approach (−1 … 0).
    pub film_sensitivity: T,
    /// The power law fitted to the slices at the last step; before the first step, a straight
    /// untilted roller's law from its first touching slice (`PowerLaw::untouched`).
    pub law: PowerLaw<T>,
    /// Added to ln Q at the start of the solve: [`COLD_START_OFFSET`] before the first step
    /// (no film predicted, so the slices' load is the dry one, where the missing approach is
    /// zero), then 0.
    pub start_offset: T,
}

impl<T: Real> RollerMemory<T> {
    /// The memories of a group of rollers in lanes (see [`Real::gather`]).
    #[inline(always)]
    pub(crate) fn gather(group: &[RollerMemory]) -> Self {
        Self {
            ln_load: T::gather(group, |m| m.ln_load),
            film_m: T::gather(group, |m| m.film_m),
            geometric_approach_m: T::gather(group, |m| m.geometric_approach_m),
            film_sensitivity: T::gather(group, |m| m.film_sensitivity),
            law: PowerLaw {
                offset_m: T::gather(group, |m| m.law.offset_m),
                ln_load_ref: T::gather(group, |m| m.law.ln_load_ref),
                span_m: T::gather(group, |m| m.law.span_m),
                exponent: T::gather(group, |m| m.law.exponent),
            },
            start_offset: T::gather(group, |m| m.start_offset),
        }
    }

    /// The memories of the rollers in the first `out.len()` lanes into `out`: each field's
    /// register taken apart once, then read lane by lane (the host's lockstep stages; idle
    /// lanes beyond `out` are not read).
    #[inline(always)]
    pub(crate) fn store_lanes(&self, out: &mut [RollerMemory]) {
        let ln_load = self.ln_load.to_per_lane();
        let film_m = self.film_m.to_per_lane();
        let geometric_approach_m = self.geometric_approach_m.to_per_lane();
        let film_sensitivity = self.film_sensitivity.to_per_lane();
        let offset_m = self.law.offset_m.to_per_lane();
        let ln_load_ref = self.law.ln_load_ref.to_per_lane();
        let span_m = self.law.span_m.to_per_lane();
        let exponent = self.law.exponent.to_per_lane();
        let start_offset = self.start_offset.to_per_lane();
        for (i, o) in out.iter_mut().enumerate() {
            *o = RollerMemory {
                ln_load: T::item(&ln_load, i),
                film_m: T::item(&film_m, i),
                geometric_approach_m: T::item(&geometric_approach_m, i),
                film_sensitivity: T::item(&film_sensitivity, i),
                law: PowerLaw {
                    offset_m: T::item(&offset_m, i),
                    ln_load_ref: T::item(&ln_load_ref, i),
                    span_m: T::item(&span_m, i),
                    exponent: T::item(&exponent, i),
                },
                start_offset: T::item(&start_offset, i),
            };
        }
    }
}

impl RollerMemory {
    /// The memory of a roller before its first step (after `Bearing::new` or `reset`).
    pub(crate) fn cold<const S: usize>(roller: &SlicedRoller<S>) -> Self {
        Self {
            law: PowerLaw::untouched(roller),
            start_offset: COLD_START_OFFSET,
            ..Self::default()
        }
    }
}

/// Whole-roller power law Q = L·(δ − δ_off)^n summarising the slices near one approach, kept
/// as the approach it passes through: Q = Q_ref·((δ − δ_off)/s)^n, so that the elastic
/// approach at λ = ln Q is s·e^((λ − λ_ref)/n) — one exponential, and no logarithm beyond the
/// fit's ln Q_ref. Of one roller, or of the rollers in the lanes of `T` (the host fits four or eight
/// at once).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct PowerLaw<T: Real = f32> {
    /// δ_off (m).
    offset_m: T,
    /// λ_ref = ln Q_ref of the point the law passes through.
    ln_load_ref: T,
    /// s = δ_ref − δ_off at that point (m).
    span_m: T,
    /// n.
    exponent: T,
}

impl PowerLaw {
    /// A straight roller's law from its first touching slice, untilted: offset the approach at
    /// which that slice touches, Palmgren's whole-roller coefficient (Q_ref = L at s = 1 m).
    /// Only the first step after a reset uses it (it is the cold memory's law; later steps
    /// fall back on the last step's), so its tilt is left out: finding the first slice to
    /// touch at a tilt costs a scan over the slices.
    fn untouched<const S: usize>(roller: &SlicedRoller<S>) -> Self {
        Self {
            offset_m: roller.touch_approach_m(),
            ln_load_ref: roller.ln_nominal_coefficient(),
            span_m: 1.0,
            exponent: 10.0 / 9.0,
        }
    }
}

impl<T: Real> PowerLaw<T> {
    /// `self` if `condition`, else `other`, field by field without a branch.
    #[inline(always)]
    fn select(&self, condition: T::Mask, other: &Self) -> Self {
        Self {
            offset_m: T::select(condition, self.offset_m, other.offset_m),
            ln_load_ref: T::select(condition, self.ln_load_ref, other.ln_load_ref),
            span_m: T::select(condition, self.span_m, other.span_m),
            exponent: T::select(condition, self.exponent, other.exponent),
        }
    }

    /// The law through the slices' (Q, K, K') at `approach_m`: K/Q = n/s and
    /// K'/K = (n − 1)/s give s = 1/(K/Q − K'/K), n = s·K/Q. Straight rollers under the
    /// Palmgren law give n = 10/9 exactly; crowned or tilted ones, whose loaded length grows
    /// with the approach, a larger n. An unloaded roller takes `untouched`.
    /// Of one roller, or of the rollers in the lanes of `T`, with the loads `loads`.
    #[inline(always)]
    fn fit(loads: &RollerLoads<T>, approach_m: T, untouched: &Self) -> Self {
        // Both branches are computed and selected (see `math::select`): fixed work.
        let q = loads.load_n;
        let k = loads.stiffness_n_per_m;
        let k2 = loads.stiffness_derivative_n_per_m2;
        let c = T::splat;
        let fit = q.gt(c(FIT_MIN_N)) & k.gt(c(0.0));
        // Finite whatever the slices gave; where `fit` fails the fallback replaces the result.
        let rho1 = k / q.max(c(FIT_MIN_N));
        let rho2 = k2 / k.max(c(1.0e-30));
        let curvature_fit = (rho1 - rho2).gt(c(0.0));
        let span_m = T::select(
            curvature_fit,
            c(1.0) / (rho1 - rho2).max(c(1.0e-30)),
            c(10.0 / 9.0) / rho1,
        );
        let fitted = Self {
            offset_m: approach_m - span_m,
            ln_load_ref: ln_normal(q.max(c(FIT_MIN_N))),
            span_m,
            exponent: T::select(
                curvature_fit,
                (span_m * rho1).max(c(1.0)).min(c(4.0)),
                c(10.0 / 9.0),
            ),
        };
        fitted.select(fit, untouched)
    }
}

/// Newton steps of the dry roller's centrifugal split ([`dry_centrifugal`]).
const DRY_CENTRIFUGAL_STEPS: usize = 4;

/// A dry roller pressed on the outer race by its centrifugal force F_c = `centrifugal_n` (N,
/// docs/physics.md §4.1). The slices' `loads` at the geometric approach `approach_m` (m) are
/// those of two contacts at equal loads Q_s; with each contact on half the power law through
/// them (e(Q) = s·(Q/Q_s)^(1/n) beyond its offset), the inner load solves
/// ½·[e(Q_in) + e(Q_in + F_c)] = s, by [`DRY_CENTRIFUGAL_STEPS`] Newton steps from
/// Q_s − F_c/2: the root for n = 1, and left of it for n > 1, where the concave law's Newton
/// steps rise monotonically to it. Where F_c alone takes the outer contact past the approach,
/// the roller leaves the inner race (Q_in = 0). Load and stiffness (the two contacts in
/// series, dQ_in/dδ) follow the law; moment and tilt terms stay the slices'.
pub(crate) fn dry_centrifugal<const S: usize>(
    roller: &SlicedRoller<S>,
    loads: RollerLoad,
    approach_m: f32,
    centrifugal_n: f32,
) -> RollerLoad {
    use crate::math::{max, pow, select};
    let law = PowerLaw::fit(
        &RollerLoads::<f32>::from_lanes(&loads),
        approach_m,
        &PowerLaw::untouched(roller),
    );
    let q_s = max(loads.load_n, FIT_MIN_N);
    let inverse_n = 1.0 / law.exponent;
    // e(Q)/s and its derivative in Q.
    let relative = |q: f32| pow(q / q_s, inverse_n);
    let mut q = max(q_s - 0.5 * centrifugal_n, 1.0e-6 * q_s);
    for _ in 0..DRY_CENTRIFUGAL_STEPS {
        let (inner, outer) = (relative(q), relative(q + centrifugal_n));
        let residual = 0.5 * (inner + outer) - 1.0;
        let slope = 0.5 * inverse_n * (inner / q + outer / (q + centrifugal_n));
        q = max(q - residual / max(slope, 1.0e-30), 1.0e-6 * q_s);
    }
    let carried = (loads.load_n > FIT_MIN_N) & (relative(centrifugal_n) < 2.0);
    let load_n = select(carried, q, 0.0);
    // dδ/dQ_in = ½·(s/n)·[(Q_in/Q_s)^(1/n)/Q_in + (Q_out/Q_s)^(1/n)/Q_out].
    let compliance = 0.5
        * law.span_m
        * inverse_n
        * (relative(q) / q + relative(q + centrifugal_n) / (q + centrifugal_n));
    RollerLoad {
        load_n,
        stiffness_n_per_m: select(carried, 1.0 / max(compliance, 1.0e-30), 0.0),
        ..loads
    }
}

/// What a roller's step has before its Newton iterations (of one roller, or of the rollers
/// in the lanes of `T`): the slices at the predicted approach and the power law fitted there.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Prepared<T: Real = f32> {
    geometric_approach_m: T,
    approach1: T,
    r1: RollerLoads<T>,
    law: PowerLaw<T>,
    /// The film–load equation on `law`, to be iterated [`NEWTON_ITERATIONS`] times.
    pub newton: Newton<T>,
}

/// The approach at which a roller's one slice pass runs: the geometric approach `δ_geo` (m)
/// plus the film the roller's memory predicts there. The film changes little from step to
/// step (EHL: ∝ Q^−0.1), and what it does change moves the approach by a fraction of the
/// film; the change is predicted to first order from its sensitivity at the last step.
/// Of one roller, or of the rollers in the lanes of `T`.
#[inline(always)]
pub(crate) fn predicted_approach<T: Real>(geometric_approach_m: T, memory: &RollerMemory<T>) -> T {
    let predicted_film = (memory.film_m
        + memory.film_sensitivity * (geometric_approach_m - memory.geometric_approach_m))
        .max(T::splat(0.0));
    geometric_approach_m + predicted_film
}

/// Prepare one roller at geometric approach `δ_geo` (m) and tilt `ψ` (rad) from its memory of
/// the last step: the slice pass at [`predicted_approach`] and the power law
/// ([`prepare_sliced`]); the caller then iterates `newton` [`NEWTON_ITERATIONS`] times and
/// calls [`finish_roller`].
#[inline(always)]
pub(crate) fn prepare_roller<const S: usize>(
    roller: &SlicedRoller<S>,
    geometric_approach_m: f32,
    tilt_rad: f32,
    memory: &RollerMemory,
) -> Prepared {
    let approach1 = predicted_approach(geometric_approach_m, memory);
    prepare_sliced::<f32>(
        RollerLoads::from_lanes(&roller.evaluate(approach1, tilt_rad)),
        approach1,
        geometric_approach_m,
        memory,
    )
}

/// [`prepare_roller`] after its slice pass: the slices' load `r1` at `approach1` (m), of one
/// roller or of the rollers in the lanes of `T` (the host prepares four or eight at once).
#[inline(always)]
pub(crate) fn prepare_sliced<T: Real>(
    r1: RollerLoads<T>,
    approach1: T,
    geometric_approach_m: T,
    memory: &RollerMemory<T>,
) -> Prepared<T> {
    // A whole-roller power law through the slices there (matching load, stiffness and
    // curvature: its error is third order in the approach's step from `approach1`), and the
    // film–load equation on it. Load and moment follow the law.
    // Where the slices carry nothing at `approach1` (a light roller whose film was
    // over-predicted), the last step's law stands in (before the first step, the cold
    // memory's).
    let law1 = PowerLaw::fit(&r1, approach1, &memory.law);
    // From the slices' load where they carry one, else from the last step's; before the first
    // step a little above it.
    let carried = r1.load_n.gt(T::splat(FIT_MIN_N));
    let start = T::select(carried, law1.ln_load_ref, memory.ln_load) + memory.start_offset;
    Prepared {
        geometric_approach_m,
        approach1,
        r1,
        law: law1,
        newton: Newton::new(&law1, geometric_approach_m, start),
    }
}

/// A roller's solve after its Newton iterations, of one roller or of the rollers in the lanes
/// of `T`: [`CoupledRoller`] but the regimes.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Finished<T: Real> {
    load: RollerLoads<T>,
    approach_m: T,
    ln_load: T,
    films: [(T, T); 2],
    softening: T,
    film_coupling_m_per_n: T,
}

impl<T: Real> Finished<T> {
    /// The result of the roller in lane `i`, with its contacts' regimes on `regime_axes`.
    #[inline(always)]
    pub(crate) fn roller(&self, i: usize, regime_axes: &[RegimeAxis; 2]) -> CoupledRoller {
        let ln_load = self.ln_load.lane(i);
        CoupledRoller {
            load: self.load.lane(i),
            approach_m: self.approach_m.lane(i),
            ln_load,
            films: self.films.map(|(c, m)| (c.lane(i), m.lane(i))),
            softening: self.softening.lane(i),
            film_coupling_m_per_n: self.film_coupling_m_per_n.lane(i),
            regimes: regime_axes.map(|axis| axis.at(ln_load)),
        }
    }

    /// The results of the rollers in the first `out.len()` lanes into `out` ([`Self::roller`]
    /// lane by lane): each field's register taken apart once, then read lane by lane (the
    /// host's lockstep stages; idle lanes beyond `out` are not read).
    #[inline(always)]
    pub(crate) fn store_rollers(&self, regime_axes: &[RegimeAxis; 2], out: &mut [CoupledRoller]) {
        let load_n = self.load.load_n.to_per_lane();
        let moment_nm = self.load.moment_nm.to_per_lane();
        let stiffness_n_per_m = self.load.stiffness_n_per_m.to_per_lane();
        let stiffness_moment_n = self.load.stiffness_moment_n.to_per_lane();
        let stiffness_tilt_nm = self.load.stiffness_tilt_nm.to_per_lane();
        let stiffness_derivative = self.load.stiffness_derivative_n_per_m2.to_per_lane();
        let approach_m = self.approach_m.to_per_lane();
        let ln_load = self.ln_load.to_per_lane();
        let [(central_0, minimum_0), (central_1, minimum_1)] = self.films;
        let films = [
            (central_0.to_per_lane(), minimum_0.to_per_lane()),
            (central_1.to_per_lane(), minimum_1.to_per_lane()),
        ];
        let softening = self.softening.to_per_lane();
        let film_coupling_m_per_n = self.film_coupling_m_per_n.to_per_lane();
        for (i, o) in out.iter_mut().enumerate() {
            let ln_load = T::item(&ln_load, i);
            let [(c0, m0), (c1, m1)] = &films;
            *o = CoupledRoller {
                load: RollerLoad {
                    load_n: T::item(&load_n, i),
                    moment_nm: T::item(&moment_nm, i),
                    stiffness_n_per_m: T::item(&stiffness_n_per_m, i),
                    stiffness_moment_n: T::item(&stiffness_moment_n, i),
                    stiffness_tilt_nm: T::item(&stiffness_tilt_nm, i),
                    stiffness_derivative_n_per_m2: T::item(&stiffness_derivative, i),
                },
                approach_m: T::item(&approach_m, i),
                ln_load,
                films: [
                    (T::item(c0, i), T::item(m0, i)),
                    (T::item(c1, i), T::item(m1, i)),
                ],
                softening: T::item(&softening, i),
                film_coupling_m_per_n: T::item(&film_coupling_m_per_n, i),
                regimes: regime_axes.map(|axis| axis.at(ln_load)),
            };
        }
    }
}

/// Finish one prepared roller after its Newton iterations: load, films and regimes, and its
/// memory for the next step (updated).
#[inline(always)]
pub(crate) fn finish_roller<const CENTRIFUGAL: bool>(
    prepared: &Prepared,
    films: &StepFilms<'_>,
    regime_axes: &[RegimeAxis; 2],
    memory: &mut RollerMemory,
) -> CoupledRoller {
    finish_lanes::<f32, CENTRIFUGAL>(prepared, films, memory).roller(0, regime_axes)
}

/// [`finish_roller`] but the regimes, of one roller or of the rollers in the lanes of `T`
/// (the host finishes four or eight at once), with their memories `memory` (updated).
#[inline(always)]
pub(crate) fn finish_lanes<T: Real, const CENTRIFUGAL: bool>(
    prepared: &Prepared<T>,
    films: &StepFilms<'_>,
    memory: &mut RollerMemory<T>,
) -> Finished<T> {
    let Prepared {
        geometric_approach_m,
        approach1,
        r1,
        law: law1,
        newton,
    } = *prepared;
    let solved2 = newton.solved();
    let approach_m = geometric_approach_m + solved2.film_m;
    let ln_load = solved2.ln_load;
    let load_n = exp_in_range(ln_load);
    // At the root, Q = e^λ is the law's load at `approach_m`; a roller whose approach stays
    // short of the law's offset (no film, separated) carries nothing.
    let carried = T::select(approach_m.gt(law1.offset_m), load_n, T::splat(0.0));
    let mut load = RollerLoads {
        load_n: carried,
        moment_nm: r1.moment_nm + r1.stiffness_moment_n * (approach_m - approach1),
        ..r1
    };
    // A roller pressed on the outer race by its centrifugal force (docs/physics.md §4.1): its
    // contacts carry Q_in and Q_in + F_c, each with its own film, and its stiffness is the
    // law's dQ_in/dδ = Q_in/(dδ/dλ) of the two contacts in series, not the slices' at equal
    // loads. `CENTRIFUGAL` is the bearing's switch (`films.centrifugal()`), a compile-time
    // constant so that a bearing without it runs the code it ran before.
    let contact_films = if CENTRIFUGAL {
        load.stiffness_n_per_m = T::select(
            approach_m.gt(law1.offset_m),
            load_n / solved2.elastic_slope_m.max(T::splat(1.0e-30)),
            T::splat(0.0),
        );
        let last_ratio = T::splat(1.0) + T::splat(films.centrifugal_n()) * solved2.last.inv_load();
        films.contacts_from_split(
            &solved2.last,
            solved2.film_m,
            (solved2.last_ln_load + ln_normal(last_ratio), last_ratio),
        )
    } else {
        films.contacts_from(&solved2.last, solved2.film_m)
    };
    // At the root, dE/dλ·dλ = dδ_geo + dH/dλ·dλ: dH/dδ_geo = H'/(E' − H').
    let film_slope_m = solved2.last.slope_m;
    let film_sensitivity =
        film_slope_m / (solved2.elastic_slope_m - film_slope_m).max(T::splat(1.0e-30));
    let film_sensitivity = film_sensitivity.max(T::splat(-1.0)).min(T::splat(0.0));
    *memory = RollerMemory {
        ln_load,
        film_m: solved2.film_m,
        geometric_approach_m,
        film_sensitivity,
        law: law1,
        start_offset: T::splat(0.0),
    };

    // dH/dQ, and 1/(1 − K·dH/dQ) ≥ 1 (dH/dQ ≤ 0): film coupling and roller stiffness share
    // it.
    let film_slope_m_per_n = film_slope_m / load_n;
    let softening = T::splat(1.0) / (T::splat(1.0) - load.stiffness_n_per_m * film_slope_m_per_n);
    Finished {
        load,
        approach_m,
        ln_load,
        films: contact_films,
        softening,
        film_coupling_m_per_n: film_slope_m_per_n * softening,
    }
}
