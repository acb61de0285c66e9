//! The host path of the integer layers ([`super::int::DenseInt`] on x86-64): the same integer
//! arithmetic, bit for bit, carried in f64 lanes because SSE2 (the x86-64 baseline) has packed
//! f64 multiply and add but neither a 64-bit integer multiply nor a sign-extending widen, so the
//! i64 path runs one scalar multiply–add per weight.
//!
//! **Accumulation.** Weights and inputs are i16 and the biases below 2⁴⁰ (the exporter refuses
//! a layer whose bound `Σ|w|·2¹⁵ + |b|` reaches 2⁴⁰, `bearing_train::ann::quant`), so every
//! product `w·x` (|w·x| ≤ 2³⁰) and every partial sum is an integer of magnitude below 2⁴⁰;
//! f64 holds every integer below 2⁵³ exactly, so no addition or multiplication rounds and
//! the f64 sum *is* the i64 sum, in any order. The weights are stored input-major (`[i][o]`,
//! transposed once at compile time by [`ExactF64::new`]) so the loop runs over the inputs
//! outside and the outputs as independent lanes, two per SSE2 register.
//!
//! **Requantisation** `q = ⌊(A·m + 2^(s−1)) / 2^s⌋` saturated to i16 (the core's
//! [`super::int::requantize`], rounding half up), without the 63-bit product `A·m`:
//! 1. `q` is non-decreasing in `A`, so clamping `A` to `[A_lo, A_hi]` — the largest
//!    accumulator still giving −32768 and the smallest already giving 32767, computed exactly
//!    in i128 — leaves every result unchanged and makes the final saturation unnecessary;
//! 2. with `m = m_h·2¹² + m_l` (`0 ≤ m_l < 2¹²`), `u = A·m_h` and `A·m_l` are exact integers
//!    (below 2⁵¹ and 2⁵² for |A| < 2⁴⁰), and for integers `⌊(2¹²u + w)/2^s⌋ =
//!    ⌊(u + ⌊w/2¹²⌋)/2^(s−12)⌋`, so with `z = A·m_l/2¹²`,
//!    `q = ⌊(u + ⌊z⌋ + 2^(k−1)) / 2^k⌋`, `k = s − 12`;
//! 3. a floor becomes a round-to-nearest (adding 1.5·2⁵², exact for values below 2⁵¹): for
//!    `z` with 12 fractional bits, `⌊z⌋ = round(z + 2⁻¹³ − ½)`, the shifted fraction lying
//!    strictly inside (−½, ½) (`z + 2⁻¹³ − ½` needs 13 fractional bits on |z| < 2⁴⁰: exact);
//!    for the outer floor the same shift by `2^(k−1) − ½` (in units of 2^−k) cancels the
//!    rounding half, so `q = round((u + ⌊z⌋ + ½)·2^−k)`. `u − 1.5·2⁵²` is an exact integer in
//!    [−2⁵³, −2⁵²] and adding `1.5·2⁵² + ⌊z⌋` cancels the constant exactly, so every step is
//!    exact; the last sum is `1.5·2⁵² + q` and its low 32 bits are `q` in two's complement.
//!
//! **Direct requantisation** (the common case, 4 operations instead of 9 on the chain every
//! layer waits for): with `c = m·2^−s` (exact: `m < 2²³`), `t = A·c + C` clamped to
//! `[C − 32768, C + 32767]` (`C` = 1.5·2⁵² plus an integer below 2¹⁶) is `C + q`
//! when `s ≤ 38` and `m`'s odd part `m_odd = m/2^(v₂(m))` is at least 2¹⁶:
//! - if `|A·m·2^−s| < 2¹⁵`, the integer `A·m` is below `2^(15+s) ≤ 2⁵³`, so the product `A·c`
//!   is exact; `v = A·c + C` then rounds once to the nearest integer, and `q = ⌊v + ½⌋`
//!   (the i64 formula) equals that rounding unless `v` is a tie. A tie needs
//!   `A·m = (2j+1)·2^(s−1)` with `|2j+1| = |2v| < 2¹⁶`, so `m_odd` would divide `2j+1`:
//!   impossible for `m_odd ≥ 2¹⁶`;
//! - otherwise the rounded product is still at least 2¹⁵ in magnitude (rounding is monotone
//!   and ±2¹⁵ are representable) and `q` saturates either way: the clamp gives the i16 limit.
//!   `|A·c| < 2⁴⁰`, so `A·c + C` stays in [2⁵², 2⁵³) where the spacing is 1.
//!
//! The exporter's multipliers lie in [2²², 2²³), so `m_odd < 2¹⁶` means seven or more
//! trailing zero bits; a layer failing either condition takes the general path above
//! ([`ExactF64::new`] decides once, the layer functions branch once per call).
//!
//! [`ExactF64::new`] checks the conditions (`0 < m < 2²³ ≤ 2^s ≤ 2⁶²` — `m < 2^s` keeps the
//! clamped results inside the i16 range —, every row's bound `B = Σ|w|·2¹⁵ + |b| < 2⁴⁰`, and
//! `B·m + 2^(s−1) < 2⁶³` so the i64 formula it reproduces never wraps) and refuses a layer
//! otherwise, at compile time for the generated
//! statics. The bit identity with the plain i64 formula is tested in `super::int` on the
//! test set, random and extreme inputs.

use super::exact_lut::{LutF64, ROUNDER_OFFSET_CODE};
use super::int::Code;

/// 1.5·2⁵²: adding and subtracting it rounds an f64 below 2⁵¹ in magnitude to an integer
/// (round half to even), and the low 32 bits of the sum are that integer in two's complement.
const ROUNDER: f64 = 6_755_399_441_055_744.0;

/// `2⁻¹³ − ½`: turns round-to-nearest into floor for values with 12 fractional bits.
const FLOOR_12_OFFSET: f64 = 1.0 / 8192.0 - 0.5;

/// Largest accumulator magnitude the exporter produces (`|acc| < 2⁴⁰`).
const ACC_LIMIT: i128 = (1 << 40) - 1;

/// `2^e` as f64 for `−1022 ≤ e ≤ 1023`, built from its bit pattern (usable in `const fn`).
const fn pow2(e: i32) -> f64 {
    f64::from_bits(((1023 + e) as u64) << 52)
}

/// One layer in f64 lanes: weights input-major, biases, and the requantisation constants of the
/// module doc.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExactF64<const I: usize, const O: usize> {
    /// `weights[i][o]` (transposed).
    weights: [[f64; O]; I],
    /// Biases.
    bias: [f64; O],
    /// `A_lo`, `A_hi` of step 1 (limited to ±(2⁴⁰ − 1)).
    acc_min: f64,
    acc_max: f64,
    /// `m_h` and `m_l·2⁻¹²` of step 2.
    multiplier_high: f64,
    multiplier_low_scaled: f64,
    /// `2^−(s−12)`.
    outer_scale: f64,
    /// `m·2^−s`, and whether the direct requantisation applies (module doc).
    scale: f64,
    direct: bool,
}

impl<const I: usize, const O: usize> ExactF64<I, O> {
    /// The host form of a layer (transposes, converts — exactly — and derives the constants).
    ///
    /// # Panics
    /// At compile time for a layer static, if the module doc's exactness conditions fail.
    #[allow(clippy::indexing_slicing)] // const fn: index loops bounded by I and O.
    pub const fn new(
        weights: &[[i16; I]; O],
        bias: &[i64; O],
        multiplier: i32,
        shift: u32,
    ) -> Self {
        assert!(
            shift >= 23 && shift <= 62 && multiplier > 0 && multiplier < 1 << 23,
            "exact f64 requantisation needs 23 <= shift <= 62 and 0 < multiplier < 2^23"
        );
        let mut w = [[0.0; O]; I];
        let mut b = [0.0; O];
        let mut o = 0;
        while o < O {
            b[o] = bias[o] as f64;
            let mut bound = bias[o].unsigned_abs() as u128;
            let mut i = 0;
            while i < I {
                w[i][o] = weights[o][i] as f64;
                bound += weights[o][i].unsigned_abs() as u128 * 32768;
                i += 1;
            }
            assert!(bound < 1 << 40, "accumulator bound reaches 2^40");
            assert!(
                bound * multiplier as u128 + (1 << (shift - 1)) < 1 << 63,
                "the i64 requantisation of this layer could overflow"
            );
            o += 1;
        }
        let m = multiplier as i128;
        let one = 1i128 << shift;
        let half = 1i128 << (shift - 1);
        // Smallest A with A·m + half ≥ 32767·2^s, largest with A·m + half < −32767·2^s.
        let hi_num = 32767 * one - half;
        let mut acc_max = -((-hi_num).div_euclid(m));
        let mut acc_min = (-32767 * one - half - 1).div_euclid(m);
        if acc_max > ACC_LIMIT {
            acc_max = ACC_LIMIT;
        }
        if acc_min < -ACC_LIMIT {
            acc_min = -ACC_LIMIT;
        }
        Self {
            weights: w,
            bias: b,
            acc_min: acc_min as f64,
            acc_max: acc_max as f64,
            multiplier_high: (multiplier >> 12) as f64,
            multiplier_low_scaled: (multiplier & 0xfff) as f64 * pow2(-12),
            outer_scale: pow2(-(shift as i32 - 12)),
            scale: multiplier as f64 * pow2(-(shift as i32)),
            direct: super::int::direct_requantisation(multiplier, shift),
        }
    }

    /// The exact accumulators `b + Σ w·x`, the outputs as lanes, summed as a pairwise tree:
    /// all products at once, then `⌈log₂ I⌉` levels of independent additions (the bias joins
    /// the last product, which waits least in the tree). The network is latency-bound — each
    /// layer waits for the previous one — and a tree is the shortest chain of dependent
    /// additions; every partial sum is a sum of some of the terms, below the row bound 2⁴⁰, so
    /// it is exact and the order does not change the result (module doc).
    ///
    /// The inputs are the i16 codes, or the same integers already in f64 (the activations
    /// [`super::exact_lut`] hands on).
    #[inline(always)]
    pub fn accumulate<T: Code>(&self, x: &[T; I]) -> [f64; O] {
        let mut terms = [[0.0; O]; I];
        for ((term, v), col) in terms.iter_mut().zip(x).zip(&self.weights) {
            let v = T::load(v);
            for (p, w) in term.iter_mut().zip(col) {
                *p = w * v;
            }
        }
        let Some(last) = terms.last_mut() else {
            return self.bias;
        };
        for (p, b) in last.iter_mut().zip(&self.bias) {
            *p += b;
        }
        let mut stride = 1;
        while stride < I {
            let mut i = 0;
            while i + stride < I {
                if let Some((head, tail)) = terms.split_at_mut_checked(i + stride) {
                    if let (Some(a), Some(b)) = (head.get_mut(i), tail.first()) {
                        for (a, b) in a.iter_mut().zip(b) {
                            *a += b;
                        }
                    }
                }
                i += 2 * stride;
            }
            stride *= 2;
        }
        terms.first().copied().unwrap_or(self.bias)
    }

    /// `rounder + requantize(A, m, s)` as an f64, for a `rounder` of 1.5·2⁵² plus an integer
    /// (module doc, step 3: the last sum is never a tie, so it rounds to the nearest integer
    /// whatever integer offset the constant carries, as long as the sum stays in [2⁵², 2⁵³)).
    #[inline(always)]
    pub fn requantize_rounded(&self, acc: f64, rounder: f64) -> f64 {
        // `if` forms compile to minpd/maxpd (no NaN handling needed: A is an integer).
        let a = if acc < self.acc_min {
            self.acc_min
        } else {
            acc
        };
        let a = if a > self.acc_max { self.acc_max } else { a };
        // ROUNDER + ⌊v/2¹²⌋, exactly (see the module doc, step 3).
        let rounded_floor_z = ((a * self.multiplier_low_scaled) + FLOOR_12_OFFSET) + ROUNDER;
        // u − ROUNDER is an exact integer in [−2⁵³, −2⁵²]; adding the rounded value cancels
        // ROUNDER exactly, leaving u + ⌊v/2¹²⌋.
        let sum = (a * self.multiplier_high - ROUNDER) + rounded_floor_z;
        (sum + 0.5) * self.outer_scale + rounder
    }

    /// `rounder + requantize(A, m, s)` by the direct requantisation of the module doc (only
    /// for a layer with `direct` set), for a `rounder` of 1.5·2⁵² plus an integer of magnitude
    /// at most 2¹⁶.
    #[inline(always)]
    fn requantize_direct(&self, acc: f64, rounder: f64) -> f64 {
        let t = acc * self.scale + rounder;
        // `if` forms compile to maxpd/minpd (t is never NaN).
        let t = if t < rounder - 32768.0 {
            rounder - 32768.0
        } else {
            t
        };
        if t > rounder + 32767.0 {
            rounder + 32767.0
        } else {
            t
        }
    }

    /// `rounder + requantize(A, m, s)` for every accumulator of the layer: the direct
    /// requantisation where it applies, the general one otherwise (one branch per layer, each
    /// side a straight vectorisable loop).
    #[inline(always)]
    pub fn requantize_all(&self, acc: [f64; O], rounder: f64) -> [f64; O] {
        let mut out = [0.0; O];
        if self.direct {
            for (q, a) in out.iter_mut().zip(acc) {
                *q = self.requantize_direct(a, rounder);
            }
        } else {
            for (q, a) in out.iter_mut().zip(acc) {
                *q = self.requantize_rounded(a, rounder);
            }
        }
        out
    }

    /// Requantised accumulators, bit for bit those of the i64 path, each in the low 16 bits
    /// of a u64 (the bit pattern of the rounded f64).
    ///
    /// Measured choices (x86-64 baseline, `film_ann` bench): out of line, LLVM's SLP
    /// vectoriser packs the whole layer (it needs the stores of the result as seeds; inlined,
    /// it left the sums scalar — with the carried f64 activations, inlining this output layer
    /// into the network still cost ≈ 8 ns); the codes travel as whole u64 words, which the
    /// caller reloads straight from the vector stores (narrowing them to i16 first cost
    /// ≈ 20 ns: 2-byte reloads of a 16-byte store).
    #[inline(never)]
    pub fn forward_linear_bits<T: Code>(&self, x: &[T; I]) -> [u64; O] {
        self.requantize_all(self.accumulate(x), ROUNDER)
            .map(f64::to_bits)
    }

    /// A hidden layer with a table activation on f64 activations: accumulation,
    /// requantisation to `1.5·2⁵² + 32768 + z`, and the exact look-up of
    /// [`super::exact_lut`], all in f64 lanes. Bit for bit `lut_lookup(requantize(A))`.
    /// Out of line like [`Self::forward_linear_bits`] (all three layers inlined into the
    /// network measured ≈ 3 ns slower).
    #[inline(never)]
    pub fn forward_lut_lanes<T: Code>(&self, x: &[T; I], table: &LutF64) -> [f64; O] {
        self.requantize_all(self.accumulate(x), ROUNDER_OFFSET_CODE)
            .map(|r| table.lookup(r))
    }

    /// A hidden ReLU layer on f64 activations: `max(requantize(A), 0)` as an exact f64
    /// (`1.5·2⁵² + q − 1.5·2⁵²` is the integer `q`).
    #[inline(never)]
    pub fn forward_relu_lanes<T: Code>(&self, x: &[T; I]) -> [f64; O] {
        self.requantize_all(self.accumulate(x), ROUNDER).map(|r| {
            let q = r - ROUNDER;
            if q > 0.0 {
                q
            } else {
                0.0
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::super::int::requantize;
    use super::super::model_weights as model;
    use super::*;
    use std::vec;
    use std::vec::Vec;

    /// SplitMix64 (Steele, Lea & Flood 2014): a seeded, dependency-free source of test values.
    fn splitmix(state: &mut u64) -> u64 {
        *state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = *state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    /// Accumulators where the requantisation of `(m, s)` can go wrong: both sides of each
    /// saturation threshold, both sides of the rounding boundary of a spread of codes
    /// (`A·m + 2^(s−1)` a multiple of 2^s, or one below), the accumulator limits ±(2⁴⁰−1),
    /// and random accumulators on a log scale; only those where the i64 formula does not wrap
    /// (`new` refuses layers that can get there).
    fn critical_accumulators(m: i32, s: u32, state: &mut u64) -> Vec<i64> {
        let limit = (1i64 << 40) - 1;
        let mut accs = vec![-limit, limit, 0, 1, -1];
        // Rounding boundaries: the smallest A giving q is ⌈(q·2^s − 2^(s−1))/m⌉.
        for q in (-32768i128..=32767)
            .step_by(997)
            .chain([-32768, -32767, 32766, 32767])
        {
            let a = -((-(q * (1i128 << s) - (1i128 << (s - 1)))).div_euclid(i128::from(m)));
            for d in -2..=2 {
                let a = (a + d).clamp(-i128::from(limit), i128::from(limit));
                accs.push(a as i64);
            }
        }
        for _ in 0..300 {
            let r = splitmix(state);
            let a = (r >> (24 + (r % 40))) as i64 & limit;
            accs.push(if r & 1 == 0 { a } else { -a });
        }
        accs.retain(|a| i128::from(*a).abs() * i128::from(m) + (1i128 << (s - 1)) < 1i128 << 63);
        accs
    }

    /// The model's three (m, s) pairs, edge pairs and random Q23 multipliers with shifts 23–62.
    fn multiplier_shift_pairs() -> Vec<(i32, u32)> {
        let mut pairs = vec![
            (model::INT_LAYER_0.multiplier, model::INT_LAYER_0.shift),
            (model::INT_LAYER_1.multiplier, model::INT_LAYER_1.shift),
            (model::INT_LAYER_2.multiplier, model::INT_LAYER_2.shift),
            ((1 << 22) + 1, 23),
            (1, 23),
            ((1 << 23) - 1, 62),
            ((1 << 23) - 1, 38),
            ((1 << 22) + (1 << 6), 38),
            ((1 << 22) + (1 << 7), 30),
        ];
        let mut state = 7u64;
        for _ in 0..60 {
            let m = (1 << 22) + (splitmix(&mut state) % (1 << 22)) as i32;
            let s = 23 + (splitmix(&mut state) % 40) as u32;
            pairs.push((m, s));
        }
        pairs
    }

    /// Both requantisations (the general one of steps 1–3 for every pair, the direct one for
    /// the pairs `new` selects it for) against the i64 formula (`requantize`, itself checked
    /// against rational arithmetic in `int`) at the critical accumulators, with the plain
    /// rounding constant and with the look-up's offset one.
    #[test]
    fn requantisation_matches_the_i64_formula() {
        let mut state = 3u64;
        let (mut general, mut direct) = (0usize, 0usize);
        for (m, s) in multiplier_shift_pairs() {
            let layer = ExactF64::<1, 1>::new(&[[0]], &[0], m, s);
            assert_eq!(
                layer.direct,
                s <= 38 && (m >> m.trailing_zeros()) >= 1 << 16,
                "m {m}, s {s}"
            );
            for a in critical_accumulators(m, s, &mut state) {
                let want = requantize(a, m, s);
                let got = layer.requantize_rounded(a as f64, ROUNDER).to_bits() as i16;
                assert_eq!(got, want, "general: A {a}, m {m}, s {s}");
                let got = layer.requantize_rounded(a as f64, ROUNDER_OFFSET_CODE) - ROUNDER;
                assert_eq!(got, f64::from(want) + 32768.0, "general offset: A {a}");
                general += 1;
                if layer.direct {
                    let got = layer.requantize_direct(a as f64, ROUNDER).to_bits() as i16;
                    assert_eq!(got, want, "direct: A {a}, m {m}, s {s}");
                    let got = layer.requantize_direct(a as f64, ROUNDER_OFFSET_CODE) - ROUNDER;
                    assert_eq!(got, f64::from(want) + 32768.0, "direct offset: A {a}");
                    direct += 1;
                }
            }
        }
        assert!(general > 20_000 && direct > 10_000, "{general} {direct}");
    }

    /// The direct requantisation's condition on the multiplier's odd part is needed: for
    /// `m = 2²²` (odd part 1) at `s = 23`, `A = 1` gives the tie `v = ½`, which the i64
    /// formula rounds up and round-half-to-even down; `new` does not select the direct path.
    #[test]
    fn direct_requantisation_needs_a_large_odd_part() {
        let layer = ExactF64::<1, 1>::new(&[[0]], &[0], 1 << 22, 23);
        assert!(!layer.direct);
        assert_eq!(requantize(1, 1 << 22, 23), 1);
        assert_eq!(layer.requantize_direct(1.0, ROUNDER).to_bits() as i16, 0);
        assert_eq!(layer.requantize_rounded(1.0, ROUNDER).to_bits() as i16, 1);
    }

    /// The direct requantisation's condition `s ≤ 38` is needed: above it the product `A·c`
    /// can round onto a rounding boundary. The accumulators here were found by solving
    /// `A·m + 2^(s−1) ≡ d (mod 2^s)` for small `d` (A within 2^(s−39)·m⁻¹ of a boundary), and
    /// the direct form gives a code one off the i64 formula for each.
    #[test]
    fn direct_requantisation_needs_a_small_shift() {
        for (m, s, a) in [
            (6_660_753, 40, 4_306_346_383i64),
            (6_660_753, 40, -4_306_346_383),
            (4_571_629, 45, 133_079_602_473),
            (4_389_619, 45, -143_751_455_702),
        ] {
            let mut layer = ExactF64::<1, 1>::new(&[[0]], &[0], m, s);
            assert!(!layer.direct);
            let want = requantize(a, m, s);
            assert_eq!(
                layer.requantize_rounded(a as f64, ROUNDER).to_bits() as i16,
                want
            );
            layer.direct = true;
            let got = layer.requantize_direct(a as f64, ROUNDER).to_bits() as i16;
            assert_eq!(i32::from(got - want).abs(), 1, "A {a}, m {m}, s {s}");
        }
    }

    /// The accumulators are the i64 sums (reference: the plain row-by-row i64 formula written
    /// here) for extreme inputs, where the partial sums are largest.
    #[test]
    fn accumulators_are_exact() {
        let layer = &model::INT_LAYER_1;
        let exact = ExactF64::new(&layer.weights, &layer.bias, layer.multiplier, layer.shift);
        let mut state = 11u64;
        for k in 0..2000 {
            let x: [i16; 10] = core::array::from_fn(|_| {
                let r = splitmix(&mut state);
                if k % 2 == 0 {
                    [i16::MIN, -32767, 0, 32767][(r % 4) as usize]
                } else {
                    r as i16
                }
            });
            let got = exact.accumulate(&x);
            for ((row, b), g) in layer.weights.iter().zip(&layer.bias).zip(got) {
                let mut want = *b;
                for (w, v) in row.iter().zip(&x) {
                    want += i64::from(*w) * i64::from(*v);
                }
                assert_eq!(g, want as f64, "{x:?}");
            }
        }
    }
}
