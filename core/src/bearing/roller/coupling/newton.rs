//! The scalar film–load equation of one roller (or of the rollers in SIMD lanes), solved by
//! safeguarded Newton steps in λ = ln Q: the iteration state, the step, and the solution with
//! its film sum (the parent module explains the equation and why the work is fixed).

use super::PowerLaw;
use crate::bearing::roller::film_table::{FilmSums, StepFilms};
use crate::lanes::Real;
use crate::math::{exp2_in_range, exp_in_range, ln_normal};

/// Bracket of the roller load in the scalar solve (N): 10⁻⁴ N … 10⁷ N.
const LN_LOAD_MIN: f32 = -9.210_34;
const LN_LOAD_MAX: f32 = 16.118_095;

/// Result of a scalar solve (of one roller, or of the rollers in the lanes of `T`): λ = ln Q
/// and the film sum there.
#[derive(Clone, Copy, Debug)]
pub(super) struct Solved<T: Real> {
    /// λ = ln Q.
    pub(super) ln_load: T,
    /// H at λ (m), extrapolated linearly from the last evaluation.
    pub(super) film_m: T,
    /// The last evaluation of the film sum.
    pub(super) last: FilmSums<T>,
    /// dδ/dλ of the elastic approach at the last evaluation (m).
    pub(super) elastic_slope_m: T,
    /// λ of the last evaluation.
    pub(super) last_ln_load: T,
}

/// Solves δ_off + s·e^((λ − λ_ref)/n) = δ_geo + H(λ) for λ = ln Q by safeguarded Newton steps
/// from a start, on the log ratio Φ(λ) = ln D − ln H with D = δ_off − δ_geo +
/// s·e^((λ − λ_ref)/n) the elastic approach still missing. Both sides are close to linear in λ
/// (EHL: ln H ≈ −0.1λ, hydrodynamic: ln H ≈ −λ; ln D ≈ λ/n once loaded), so Newton converges
/// in a few steps from anywhere in the bracket it keeps; Φ' > 0 throughout.
/// The step is taken on 2·sinh(Φ/2), which needs no logarithm ([`Newton::iterate`]). The film
/// sum at the returned λ is the last evaluation continued by its tangent (second-order
/// accurate, and free).
///
/// The iteration state of the rollers in the lanes of `T`: `Newton<f32>` is one roller's
/// (the Cortex-M4 iterates one roller at a time: lanes gain nothing in order). A host builds
/// the states of four or eight rollers at a time (`Newton<F32x4>`, `Newton<F32x8>`), straight from their power laws in
/// lanes (`prepare_sliced`, `super::lockstep`), and iterates them as SIMD lanes. Each lane
/// runs the operations of one roller in the same order
/// (`crate::lanes`), so the results are the same bit for bit. (An iteration is a chain of
/// dependent operations — two exponentials, two roots, three divisions — whose latency a
/// superscalar core cannot hide by overlapping the rollers one after another.)
#[derive(Clone, Copy, Debug)]
pub(crate) struct Newton<T: Real = f32> {
    gap: T,
    inverse_exponent: T,
    /// log₂e/n: the law's exponential taken as a power of two.
    inverse_exponent_log2: T,
    span_m: T,
    ln_load_ref: T,
    lo: T,
    hi: T,
    lam: T,
    /// λ, the film sum and dE/dλ at the last evaluation.
    last: (T, FilmSums<T>, T),
}

impl Default for Newton {
    fn default() -> Self {
        Self::from_one(0.0, 1.0, 0.0, 0.0, 0.0)
    }
}

impl<T: Real> Newton<T> {
    /// The equation on `law` at geometric approach δ_geo (m), from λ = `start` (or the
    /// bracket's lower part if that is outside it).
    #[inline(always)]
    pub(super) fn new(law: &PowerLaw<T>, geometric_approach_m: T, start: T) -> Self {
        let (lo, hi) = (T::splat(LN_LOAD_MIN), T::splat(LN_LOAD_MAX));
        Self::from_one(
            geometric_approach_m - law.offset_m,
            law.exponent,
            law.span_m,
            law.ln_load_ref,
            T::select(
                start.gt(lo) & start.lt(hi),
                start,
                T::splat(LN_LOAD_MIN + 0.5),
            ),
        )
    }

    /// A roller's state before its first step: the gap δ_geo − δ_off (m), the law's exponent
    /// n, span (m) and λ_ref, and the start λ.
    #[inline(always)]
    fn from_one(gap: T, exponent: T, span_m: T, ln_load_ref: T, lam: T) -> Self {
        Self {
            gap,
            inverse_exponent: T::splat(1.0) / exponent,
            inverse_exponent_log2: T::splat(core::f32::consts::LOG2_E) / exponent,
            span_m,
            ln_load_ref,
            lo: T::splat(LN_LOAD_MIN),
            hi: T::splat(LN_LOAD_MAX),
            lam,
            last: (lam, FilmSums::zero(), T::splat(0.0)),
        }
    }

    /// The root found so far.
    #[inline(always)]
    pub(super) fn solved(&self) -> Solved<T> {
        let (at, last, elastic_slope_m) = self.last;
        Solved {
            ln_load: self.lam,
            film_m: (last.total_m + last.slope_m * (self.lam - at)).max(T::splat(0.0)),
            last,
            elastic_slope_m,
            last_ln_load: at,
        }
    }

    /// The states of single rollers fresh from `Newton::new`, side by side: their last
    /// evaluation is the start λ with an empty film sum, as `new` leaves it (so it is made
    /// here, not gathered).
    #[cfg(test)]
    #[inline(always)]
    fn start_lanes(rollers: &T::PerLane<Newton>) -> Self {
        let field = |f: fn(&Newton) -> f32| T::from_per_lane(rollers, f);
        let lam = field(|n| n.lam);
        Self {
            gap: field(|n| n.gap),
            inverse_exponent: field(|n| n.inverse_exponent),
            inverse_exponent_log2: field(|n| n.inverse_exponent_log2),
            span_m: field(|n| n.span_m),
            ln_load_ref: field(|n| n.ln_load_ref),
            lo: field(|n| n.lo),
            hi: field(|n| n.hi),
            lam,
            last: (lam, FilmSums::zero(), T::splat(0.0)),
        }
    }

    /// Store what the iterations of lane `i` changed (bracket, λ, last evaluation) into the
    /// state of its roller; the law's constants there are the lane's already.
    #[cfg(test)]
    #[inline(always)]
    fn store_lane(&self, i: usize, roller: &mut Newton) {
        roller.lo = self.lo.lane(i);
        roller.hi = self.hi.lane(i);
        roller.lam = self.lam.lane(i);
        roller.last = (
            self.last.0.lane(i),
            self.last.1.lane(i),
            self.last.2.lane(i),
        );
    }

    /// One safeguarded Newton step on 2·sinh(Φ/2) = √(D/H) − √(H/D), a residual with the root
    /// and the sign of Φ = ln(D/H) but no logarithm: its Newton step is
    /// −2·tanh(Φ/2)/Φ' = 2(H − D)/((D + H)·Φ'), with Φ' = D'/D − H'/H. Near the root it is
    /// Newton's step on Φ (they differ by Φ³/12); far from it the step is at most 2/Φ', so it
    /// never overshoots where the log form's tangent would (the Padé residual, whose step
    /// grows like sinh Φ, did). All in one division.
    #[inline(always)]
    pub(crate) fn iterate(&mut self, films: &StepFilms<'_>) {
        let lam = self.lam;
        // e^((λ − λ_ref)/n) = 2^(log₂e·(λ − λ_ref)/n): λ and λ_ref are bracketed (ln 10⁻⁴ …
        // ln 10⁷ and ≥ ln 10⁻³), n ≥ 1, so the argument is in range.
        let elastic =
            self.span_m * exp2_in_range(self.inverse_exponent_log2 * (lam - self.ln_load_ref));
        let f = films.sum_at(lam);
        let elastic_slope = self.inverse_exponent * elastic;
        self.step(lam, (elastic, elastic_slope), f);
    }

    /// [`Newton::iterate_centrifugal`] where the step's films carry a centrifugal force, else
    /// [`Newton::iterate`] (the host's lanes; the Cortex-M4 takes the branch once per roller).
    #[inline(always)]
    pub(crate) fn iterate_with(&mut self, films: &StepFilms<'_>) {
        if films.centrifugal() {
            self.iterate_centrifugal(films);
        } else {
            self.iterate(films);
        }
    }

    /// [`Newton::iterate`] of a roller pressed on the outer race by its centrifugal force F_c
    /// (`films.centrifugal_n()`, docs/physics.md §4.1): λ = ln Q_in, the outer contact carries
    /// Q_out = Q_in + F_c. Each contact follows half the whole-roller law at its own load, so
    /// the elastic approach is δ_off + ½·s·[e^((λ − λ_ref)/n) + e^((λ_out − λ_ref)/n)] with
    /// λ_out = λ + ln(1 + F_c/Q_in), and the film sum is h_in(Q_in) + h_out(Q_out)
    /// (`StepFilms::sum_split`). One exponential and one logarithm more than `iterate`.
    #[inline(always)]
    pub(crate) fn iterate_centrifugal(&mut self, films: &StepFilms<'_>) {
        let lam = self.lam;
        let c = T::splat;
        // λ is bracketed: 1/Q ≤ 10⁴, and 1 ≤ Q_out/Q_in stays normal and finite.
        let inv_load = exp_in_range(-lam);
        let load_ratio = c(1.0) + c(films.centrifugal_n()) * inv_load;
        let ln_ratio = ln_normal(load_ratio);
        let exponent = self.inverse_exponent_log2 * (lam - self.ln_load_ref);
        let inner = self.span_m * exp2_in_range(exponent);
        let outer = self.span_m * exp2_in_range(exponent + self.inverse_exponent_log2 * ln_ratio);
        let elastic = c(0.5) * (inner + outer);
        // dλ_out/dλ = Q_in/Q_out.
        let elastic_slope = self.inverse_exponent * c(0.5) * (inner + outer / load_ratio);
        let f = films.sum_split(lam, (lam + ln_ratio, load_ratio), inv_load);
        self.step(lam, (elastic, elastic_slope), f);
    }

    /// The safeguarded step of [`Newton::iterate`] from the evaluation at λ = `lam`: the
    /// elastic approach beyond the law's offset and its dδ/dλ (m), and the film sum `f`.
    #[inline(always)]
    fn step(&mut self, lam: T, (elastic, elastic_slope): (T, T), f: FilmSums<T>) {
        let (h, dh) = (f.total_m.max(T::splat(1.0e-30)), f.slope_m);
        self.last = (lam, f, elastic_slope);
        let missing = elastic - self.gap;
        let defined = missing.gt(T::splat(0.0));
        // The floor by a bit-mask select, not `max`: with `max` LLVM emitted a branch to a copy
        // of the loop body specialised for a floored `missing` (a roller whose approach stays
        // short of the law's offset), and such steps cost more on the M4.
        let tiny = T::splat(1.0e-30);
        let d = T::select(missing.gt(tiny), missing, tiny);
        // 2(H − D)/((D + H)·(D'/D − H'/H)), multiplied through by D·H (> 0; D' > 0, H' ≤ 0).
        let newton =
            lam + T::splat(2.0) * (h - d) * d * h / ((d + h) * (elastic_slope * h - dh * d));
        let above = missing.gt(h);
        // Plain values on both sides: a conditional move, no branch.
        self.hi = T::choose(above, lam, self.hi);
        self.lo = T::choose(above, self.lo, lam);
        self.lam = T::select(
            defined & newton.ge(self.lo) & newton.le(self.hi),
            newton,
            T::splat(0.5) * (self.lo + self.hi),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bearing::roller::film_table::tests::{contacts_with, martin, MODULUS_PA};
    use crate::bearing::roller::film_table::FilmTable;
    use crate::film::Regression;
    use crate::lanes::F32x4;

    /// The host's lanes iterate each roller exactly as the M4 iterates it alone: four rollers
    /// side by side against four one-roller solves, bit for bit in λ, the bracket and the last
    /// evaluation, over loaded, light and separated rollers (gaps from −5 µm to 40 µm, laws
    /// with n from 1 to 4), three iterations each.
    #[test]
    fn lanes_iterate_each_roller_bit_for_bit() {
        let contacts = contacts_with(9.0, MODULUS_PA);
        let mut table = FilmTable::default();
        let films = table.step(&Regression, contacts, martin(&contacts), (2.0, 9.0), true);
        let bits = |n: &Newton| {
            let (at, last, slope) = n.last;
            [n.lam, n.lo, n.hi, at, slope, last.total_m, last.slope_m].map(f32::to_bits)
        };
        let mut rollers = [Newton::default(); 16];
        for (k, roller) in rollers.iter_mut().enumerate() {
            let k = k as f32;
            let law = PowerLaw {
                offset_m: 1.0e-6 * (k - 6.0),
                ln_load_ref: 2.0 + 0.5 * k,
                span_m: 2.0e-6 * (1.0 + 0.3 * k),
                exponent: 1.0 + 0.2 * k,
            };
            *roller = Newton::new(&law, 3.0e-6 * (k - 4.0), 1.0 + 0.7 * k);
        }
        for group in rollers.chunks_exact(4) {
            let group: [Newton; 4] = core::array::from_fn(|i| group[i]);
            let mut lanes = Newton::<F32x4>::start_lanes(&group);
            let mut alone = group;
            for _ in 0..3 {
                lanes.iterate(&films);
                for n in alone.iter_mut() {
                    n.iterate(&films);
                }
            }
            for (i, one) in alone.iter().enumerate() {
                let mut from_lanes = group[i];
                lanes.store_lane(i, &mut from_lanes);
                assert_eq!(bits(&from_lanes), bits(one), "roller {i}");
                assert!(one.lam.is_finite());
            }
        }
    }
}
