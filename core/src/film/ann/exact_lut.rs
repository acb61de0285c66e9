//! The activation table look-up of the host path in exact f64 lanes: [`super::int::lut_lookup`]
//! bit for bit, taking the requantised code as the f64 the requantisation leaves
//! (`super::exact_f64`) and handing the activation to the next layer's accumulation as an f64,
//! so the codes never leave the vector registers for integer index arithmetic and never make
//! an i16 round trip between layers. Only the table address goes through a general register.
//!
//! **Definition** ([`super::int::lut_lookup`], 1025 points `T[0..=1024]`, 64 codes per
//! segment): for a code `z`, `u = z + 32768 ∈ [0, 65535]`, `k = ⌊u/64⌋`, `j = u mod 64`,
//! `d = T[k+1] − T[k]`, and the result is `T[k] + ⌊(d·j + 32)/64⌋`.
//!
//! **Exact steps.**
//! 1. The requantisation ends by adding a rounding constant `C` to a value that is never a
//!    half-integer (module doc of `exact_f64`, step 3: the value is `(2n+1)/2^(k+1)`, `k ≥ 11`).
//!    With `C = 1.5·2⁵² + 32768` instead of `1.5·2⁵²` the sum lies in `[2⁵², 2⁵³)`, where the
//!    f64 spacing is 1, so it rounds to `C + z` exactly as before (a non-tie rounds to the
//!    nearest integer whatever integer is added first), and the low 16 bits of its mantissa
//!    are `u` (`C` has zero low 17 bits, and `0 ≤ u < 2¹⁶`).
//! 2. `k = (bits >> 6) & 1023` and `j = bits & 63` are integer operations on that bit pattern.
//!    `j/64` is made exact without a conversion: the f64 with the exponent of `2⁴⁶` and `j` as
//!    its low mantissa bits is `2⁴⁶ + j·2⁻⁶` (the spacing at `2⁴⁶` is `2⁻⁶`), and subtracting
//!    `2⁴⁶` is exact (Sterbenz).
//! 3. The table holds, per segment, `P = 1.5·2⁵² + T[k]` and `d` (both integers below 2⁵³:
//!    exact). `y = d·(j/64) + 2⁻⁷`: `|d·j| < 2¹⁶·2⁶`, so `d·j/64` has at most 22 significant
//!    bits and `y` (magnitude below 2¹⁶, 7 fractional bits) at most 23: both exact.
//! 4. `P + y` lies in `[2⁵², 2⁵³)` and rounds to the nearest integer. `y`'s fraction in units of
//!    2⁻⁷ is odd, so it is never a half-integer and the result is `1.5·2⁵² + T[k] + ⌊y + ½⌋`.
//!    With `n = d·j + 32`: `y + ½ = n/64 + 2⁻⁷`, and adding `2⁻⁷ < 2⁻⁶` to a multiple of `2⁻⁶`
//!    crosses no integer, so `⌊y + ½⌋ = ⌊n/64⌋`, the definition's step (the `2⁻⁷` only breaks
//!    the ties that round-half-to-even would send the other way).
//! 5. Subtracting `1.5·2⁵²` leaves the integer `T[k] + ⌊n/64⌋` (between `T[k]` and `T[k+1]`,
//!    so inside i16): exact.
//!
//! The tests compare every one of the 65 536 codes with [`super::int::lut_lookup`] on the
//! model's table and on tables built to reach the extremes (`|d| = 65535`, alternating signs).

use super::int::{Lut, LUT_LEN};

/// 1.5·2⁵² (as in `exact_f64`): adding it rounds an f64 below 2⁵¹ to an integer.
const ROUNDER: f64 = 6_755_399_441_055_744.0;

/// `1.5·2⁵² + 32768`: the rounding constant that leaves `u = z + 32768` in the low mantissa
/// bits (module doc, step 1).
pub const ROUNDER_OFFSET_CODE: f64 = ROUNDER + 32768.0;

/// `2⁴⁶`, whose f64 spacing is `2⁻⁶` (module doc, step 2).
const TWO_POW_46: f64 = 70_368_744_177_664.0;

/// `2⁻⁷`, the tie breaker of step 3.
const TIE_BREAK: f64 = 1.0 / 128.0;

/// Segments of the table.
const SEGMENTS: usize = LUT_LEN - 1;

/// Code bits below the segment index (64 codes per segment).
const FRACTION_BITS: u32 = 6;

/// An activation table in exact f64 pairs: `[1.5·2⁵² + T[k], T[k+1] − T[k]]` per segment, so a
/// look-up is one 16-byte load.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LutF64 {
    segments: [[f64; 2]; SEGMENTS],
}

impl LutF64 {
    /// The f64 pairs of an i16 table (exact conversions; a `const fn`, so the model's copy is
    /// built at compile time).
    #[allow(clippy::indexing_slicing)] // const fn: k + 1 ≤ SEGMENTS < LUT_LEN.
    pub const fn new(table: &Lut) -> Self {
        let mut segments = [[0.0; 2]; SEGMENTS];
        let mut k = 0;
        while k < SEGMENTS {
            let a = table[k] as i32;
            let b = table[k + 1] as i32;
            segments[k] = [ROUNDER + a as f64, (b - a) as f64];
            k += 1;
        }
        Self { segments }
    }

    /// `lut_lookup(T, z)` as an exact f64, from `C + z` rounded with `C` =
    /// [`ROUNDER_OFFSET_CODE`] (module doc, steps 2–5).
    #[inline(always)]
    pub fn lookup(&self, rounded_offset_code: f64) -> f64 {
        let bits = rounded_offset_code.to_bits();
        let segment = (bits >> FRACTION_BITS) as usize & (SEGMENTS - 1);
        let fraction =
            f64::from_bits((bits & ((1 << FRACTION_BITS) - 1)) | TWO_POW_46.to_bits()) - TWO_POW_46;
        // The mask keeps the index in range, so the fallback is never taken.
        let [base, step] = self
            .segments
            .get(segment)
            .copied()
            .unwrap_or([ROUNDER, 0.0]);
        (base + (step * fraction + TIE_BREAK)) - ROUNDER
    }
}

#[cfg(test)]
mod tests {
    use super::super::int::lut_lookup;
    use super::super::model_weights as model;
    use super::*;

    /// `C + z` as the requantisation leaves it (module doc, step 1), computed independently
    /// here by integer arithmetic on the bit pattern of `1.5·2⁵²`.
    fn offset_code(z: i16) -> f64 {
        f64::from_bits(ROUNDER.to_bits() + (i64::from(z) + 32768) as u64)
    }

    /// Every code through the table against the integer definition.
    fn check_every_code(table: &Lut) {
        let exact = LutF64::new(table);
        for z in i16::MIN..=i16::MAX {
            let want = lut_lookup(table, z);
            let got = exact.lookup(offset_code(z));
            assert_eq!(got, f64::from(want), "code {z}");
        }
    }

    /// The model's tanh table: all 65 536 codes equal `lut_lookup` (reference: the integer
    /// definition the Cortex-M4 runs).
    #[test]
    fn every_code_of_the_model_table_matches_the_integer_lookup() {
        assert_eq!(offset_code(-32768), ROUNDER);
        assert_eq!(offset_code(5), ROUNDER_OFFSET_CODE + 5.0);
        check_every_code(&model::LUT);
    }

    /// Tables that reach the extremes of the exactness argument — steps of ±65535 alternating
    /// (largest `|d·j|`), a ramp with odd steps (every tie `d·j ≡ 32 mod 64` occurs, where
    /// round-half-to-even without the tie breaker would differ from the definition), and
    /// random points — all 65 536 codes each against `lut_lookup`.
    #[test]
    fn every_code_of_extreme_tables_matches_the_integer_lookup() {
        let alternating: Lut =
            core::array::from_fn(|k| if k % 2 == 0 { i16::MIN } else { i16::MAX });
        let ramp: Lut = core::array::from_fn(|k| (k as i32 * 63 - 32000) as i16);
        let mut state = 0x2545_f491_u32;
        let random: Lut = core::array::from_fn(|_| {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            state as i16
        });
        for table in [alternating, ramp, random] {
            check_every_code(&table);
        }
    }

    /// The tie breaker is needed: without it, round-half-to-even gives a different result for
    /// some code of the ramp table (so the test above can see a wrong offset).
    #[test]
    fn the_tie_breaker_changes_ties() {
        let ramp: Lut = core::array::from_fn(|k| (k as i32 * 63 - 32000) as i16);
        let exact = LutF64::new(&ramp);
        let differing = (i16::MIN..=i16::MAX)
            .filter(|&z| {
                let bits = offset_code(z).to_bits();
                let segment = (bits >> FRACTION_BITS) as usize & (SEGMENTS - 1);
                let fraction = f64::from((bits & 63) as u8) / 64.0;
                let [base, step] = exact.segments[segment];
                let without = (base + step * fraction) - ROUNDER;
                without != f64::from(lut_lookup(&ramp, z))
            })
            .count();
        assert!(differing > 100, "{differing}");
    }
}
