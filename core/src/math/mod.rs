//! Fixed-cost f32 elementary functions.
//!
//! The bearing step must take the same number of instructions for every input
//! (docs/architecture.md), and `libm`'s `logf`/`expf`/`powf` branch on their argument. These
//! versions use only `+ − ×`, bit manipulation and selects (polynomials instead of divisions), so their cost is fixed and
//! their results are bit-identical on the host and on the Cortex-M4F (no fused operations).
//! Accuracy (checked in the tests against f64): a few ulp over the whole positive range.
//!
//! The film network has its own logarithm and exponentials, by series (`series`): they
//! round differently from these, and each family's bits are pinned by its users (see there).

use crate::lanes::{Real, ROUNDER};

#[cfg(test)]
mod lanes_tests;
mod real;

pub mod series;

const SQRT_2: f32 = core::f32::consts::SQRT_2;

// Polynomial coefficients: least-squares fits on Chebyshev nodes (near-minimax), rounded to
// f32 and checked in f32 arithmetic (tests below).
/// log₂(1 + t)/t for t ∈ [√½ − 1, √2 − 1], degree 7: |error of t·P(t)| < 1.5·10⁻⁷.
const LOG2_POLY: [f32; 8] = [
    1.442_694_9,
    -0.721_352_76,
    0.480_924_04,
    -0.360_241_95,
    0.287_075_46,
    -0.248_822_08,
    0.234_211_24,
    -0.146_204_41,
];
/// eʳ for r ∈ [−ln2/2, ln2/2], degree 5: relative error < 2.5·10⁻⁷.
const EXP_POLY: [f32; 6] = [
    1.000_000_1,
    1.0,
    0.499_988_7,
    0.166_664_15,
    0.041_917_54,
    0.008_375_131,
];
/// 2ᶠ for f ∈ [−½, ½], degree 5: relative error < 2.5·10⁻⁷. (The linear coefficient is a fit
/// that happens to round to ln 2, not the constant itself.)
#[allow(clippy::approx_constant)]
const EXP2_POLY: [f32; 6] = [
    1.000_000_1,
    0.693_147_2,
    0.240_221_07,
    0.055_503_27,
    0.009_676_039,
    0.001_340_043_5,
];

/// Horner evaluation of `c[0] + c[1]x + …`; a fixed chain of multiply–adds.
#[inline(always)]
fn horner<T: Real, const N: usize>(c: &[f32; N], x: T) -> T {
    c.iter()
        .rev()
        .fold(T::splat(0.0), |acc, &k| acc * x + T::splat(k))
}

/// `x` rounded to the nearest integer n (|x| < 2²²) without a branch, and 2ⁿ for n in
/// [−126, 127] (the callers clamp their argument so that n is in range; the mask keeps the
/// sign bit clear for any other value). The sum `t = x + 1.5·2²³` lies in [2²³, 2²⁴), where
/// consecutive f32 are 1 apart, so it is rounded to an integer and its bit pattern is
/// `bits(1.5·2²³) + n` (IEEE 754 binary32: the mantissa field counts units of 1 there); then
/// n = t − 1.5·2²³ exactly, and `(bits(t) − bits(1.5·2²³) + 127) << 23` is the pattern of 2ⁿ
/// (biased exponent n + 127, zero mantissa). No float-to-integer conversion: Rust's `as i32`
/// saturates, which costs a compare chain around `cvttss2si` on x86 and keeps SIMD lanes
/// from forming. Shared by [`exp`]/[`exp2`] and the network's (`series`).
#[inline(always)]
pub(crate) fn round_with_pow2(x: f32) -> (f32, f32) {
    let shifted = x + ROUNDER;
    let n = shifted - ROUNDER;
    let biased = shifted
        .to_bits()
        .wrapping_sub(ROUNDER.to_bits())
        .wrapping_add(127);
    (n, f32::from_bits((biased & 0xff) << 23))
}

/// Base-2 logarithm for `x > 0` (finite). Inputs `<= 0`, subnormal or NaN are treated as the
/// smallest normal number; `+∞` as `f32::MAX`. Never returns NaN or ∞.
#[inline]
pub fn log2(x: f32) -> f32 {
    // Clamp into the normal range; NaN becomes the smallest normal number.
    log2_normal(min(max(x, f32::MIN_POSITIVE), f32::MAX))
}

/// [`log2`] of a positive normal finite `x`, without the clamp (a caller whose argument is
/// bounded by construction saves its two compares; other inputs give finite nonsense).
/// Of one number or of lanes ([`Real`]: the host's power-law fit takes four rollers' at once).
#[inline(always)]
pub(crate) fn log2_normal<T: Real>(x: T) -> T {
    let (m, e) = x.split_normal();
    let t = m - T::splat(1.0);
    e + t * horner(&LOG2_POLY, t)
}

/// A positive normal finite `x` as m·2ᵉ with m in [√½, √2) (so that the polynomial argument
/// of [`log2_normal`] stays small): (m, e), e as a float. Read from the bit pattern.
#[inline(always)]
pub(crate) fn split_normal(x: f32) -> (f32, f32) {
    let bits = x.to_bits();
    let exponent = ((bits >> 23) & 0xff) as i32 - 127;
    // Mantissa in [1, 2), re-centred to [√½, √2).
    let mantissa = f32::from_bits((bits & 0x007f_ffff) | 0x3f80_0000);
    let high = mantissa > SQRT_2;
    let m = if high { mantissa * 0.5 } else { mantissa };
    (m, (exponent + i32::from(high)) as f32)
}

/// Natural logarithm with the behaviour of [`log2`].
#[inline]
pub fn ln(x: f32) -> f32 {
    log2(x) * core::f32::consts::LN_2
}

/// [`ln`] of a positive normal finite `x`, without the clamp (see [`log2_normal`]).
#[inline(always)]
pub(crate) fn ln_normal<T: Real>(x: T) -> T {
    log2_normal(x) * T::splat(core::f32::consts::LN_2)
}

/// 2ʸ. Arguments are clamped to `[-126, 127]`; NaN is treated as `-126`. Never returns NaN
/// or ∞.
#[inline]
pub fn exp2(y: f32) -> f32 {
    exp2_in_range(min(max(y, -126.0), 127.0))
}

/// [`exp2`] of a `y` known to lie in [−126, 127], without the clamp (see [`exp_in_range`]).
#[inline(always)]
pub(crate) fn exp2_in_range<T: Real>(y: T) -> T {
    let (n, pow2) = y.round_with_pow2();
    horner(&EXP2_POLY, y - n) * pow2
}

/// Exponential. Arguments are clamped to `[-87, 88]` (result between ≈1.6e-38 and ≈1.7e38);
/// NaN is treated as `-87`. Never returns NaN or ∞.
#[inline]
pub fn exp(x: f32) -> f32 {
    exp_in_range(min(max(x, -87.0), 88.0))
}

/// [`exp`] of an `x` known to lie in [−87, 88], without the clamp: the scalar film–load solve
/// calls it a few times per roller with ln Q bracketed, and the clamp's two compares are a
/// sixth of its cost. Arguments outside give finite nonsense, or ∞ beyond |x| ≈ 10⁴.
#[inline(always)]
pub(crate) fn exp_in_range<T: Real>(x: T) -> T {
    // x = n·ln2 + r, |r| ≤ ln2/2; the Cody–Waite split of ln 2 keeps r accurate for large n.
    let (n, pow2) = (x * T::splat(core::f32::consts::LOG2_E)).round_with_pow2();
    const LN_2_HI: f32 = 0.693_145_75;
    const LN_2_LO: f32 = 1.428_606_8e-6;
    let r = (x - n * T::splat(LN_2_HI)) - n * T::splat(LN_2_LO);
    horner(&EXP_POLY, r) * pow2
}

/// `x^y` for `x > 0`; `x <= 0` (or NaN) gives `0`. Never returns NaN or ∞.
#[inline]
pub fn pow(x: f32, y: f32) -> f32 {
    select(x > 0.0, exp2(y * log2(x)), 0.0)
}

/// `x^(10/9)` for `0 < x ≤ 1` (the Palmgren slice law), at about a third of [`pow`]'s cost:
/// x·x^(1/9), the ninth root from a bit-level first guess (the biased bit pattern divided by 9,
/// with an additive constant tuned for the smallest worst-case error: 3.3 %) refined by three
/// Newton steps on y⁹ = x (the relative error e becomes ≈ 4e²: 3.3 % → 4·10⁻³ → 7·10⁻⁵ →
/// 3·10⁻⁸). Inputs ≤ 0 or NaN give 0; the caller keeps x ≤ 1.
#[inline]
pub fn pow_10_9(x: f32) -> f32 {
    let positive = x > 0.0;
    let x = if positive { min(x, 1.0) } else { 1.0 };
    // Masked by a multiplication: the root stays in the data flow (see `select`).
    pow_10_9_in_range(x) * if positive { 1.0 } else { 0.0 }
}

/// [`pow_10_9`] for `x` already known to lie in (0, 1] (a slice loop that clamps its approach
/// once for all its uses).
#[inline]
pub fn pow_10_9_in_range(x: f32) -> f32 {
    x * ninth_root_in_range(x)
}

/// `x^(1/9)` for `x` in (0, 1]: a bit-level first guess (the biased bit pattern divided by 9,
/// with an additive constant tuned for the smallest worst-case error: 3.3 %) refined by three
/// Newton steps on y⁹ = x (the relative error e becomes ≈ 4e²: 3.3 % → 4·10⁻³ → 7·10⁻⁵ →
/// 3·10⁻⁸), each y·8/9 + (x/9)/y⁸: three squarings, a division and a multiply–add.
#[inline]
pub fn ninth_root_in_range(x: f32) -> f32 {
    ninth_root_newton::<3>(x)
}

/// [`ninth_root_in_range`] with two Newton steps instead of three: relative error below 10⁻⁴
/// (9.2·10⁻⁵ at worst over 10⁻¹³ … 1, tested), and never below the root (Newton's steps on
/// the convex y⁹ − x reach it from above). The slice pass's root (`contact::slicing`): a
/// slice's load, stiffness and curvature are all proportional to it, so each is that close
/// to Palmgren's law, for five instructions less per slice on the Cortex-M4.
#[inline]
pub(crate) fn ninth_root_two_steps(x: f32) -> f32 {
    ninth_root_newton::<2>(x)
}

/// The ninth root of `x` in (0, 1] by `STEPS` Newton steps from the bit-level first guess.
#[inline(always)]
fn ninth_root_newton<const STEPS: usize>(x: f32) -> f32 {
    const BIAS: i32 = 127 << 23;
    // Found by a scan of the worst relative error over 10⁻¹³ … 1 (fast-inverse-square-root
    // style); without it the first guess is off by up to 6 %.
    const TUNE: i32 = -327_000;
    // BIAS + (bits − BIAS)/9 as an unsigned division (x > 0: the sign bit is clear), which
    // rounds the other way than the signed one below x = 1: a one-ulp difference in the guess.
    const OFFSET: u32 = (BIAS - BIAS / 9 + TUNE) as u32;
    let mut y = f32::from_bits(x.to_bits() / 9 + OFFSET);
    let x_ninth = x * (1.0 / 9.0);
    for _ in 0..STEPS {
        let y2 = y * y;
        let y4 = y2 * y2;
        let y8 = y4 * y4;
        y = y * (8.0 / 9.0) + x_ninth / y8;
    }
    y
}

/// Sine and cosine of `x` (rad) at a fixed cost. Accurate to a few ulp for |x| ≲ 10⁴ (wrap
/// growing angles into [0, 2π) before they get large); non-finite inputs and |x| > 10⁶, where
/// an f32 angle has no meaningful fraction of a turn left, are treated as 0.
#[inline]
pub fn sin_cos(x: f32) -> (f32, f32) {
    let x = if x.is_finite() && x.abs() <= 1.0e6 {
        x
    } else {
        0.0
    };
    // x = k·π/2 + r, |r| ≤ π/4, with a two-part π/2 (Cody–Waite).
    let v = x * core::f32::consts::FRAC_2_PI;
    let k = (v + if v >= 0.0 { 0.5 } else { -0.5 }) as i32;
    let kf = k as f32;
    // π/2 = HI + MID + LO with HI exact in 11 bits, so k·HI is exact for |k| < 2¹³.
    const PIO2_HI: f32 = 1.570_312_5;
    const PIO2_MID: f32 = 4.838_268e-4;
    const PIO2_LO: f32 = 2.563_283e-12;
    let r = ((x - kf * PIO2_HI) - kf * PIO2_MID) - kf * PIO2_LO;
    let r2 = r * r;
    // Taylor series; truncation below 2e-9 for |r| ≤ π/4.
    let s = r
        * (1.0
            + r2 * (-1.0 / 6.0
                + r2 * (1.0 / 120.0 + r2 * (-1.0 / 5040.0 + r2 * (1.0 / 362_880.0)))));
    let c = 1.0
        + r2 * (-0.5
            + r2 * (1.0 / 24.0
                + r2 * (-1.0 / 720.0 + r2 * (1.0 / 40_320.0 + r2 * (-1.0 / 3_628_800.0)))));
    // Quadrant k: (sin, cos) = (s, c), (c, −s), (−s, −c), (−c, s), without a branch: swap on
    // odd k, flip the sign bit of sin when k & 2, of cos when (k + 1) & 2.
    let odd = k & 1 == 1;
    let sin = select(odd, c, s);
    let cos = select(odd, s, c);
    let flip_sin = ((k & 2) as u32) << 30;
    let flip_cos = (((k + 1) & 2) as u32) << 30;
    (
        f32::from_bits(sin.to_bits() ^ flip_sin),
        f32::from_bits(cos.to_bits() ^ flip_cos),
    )
}

/// The angle of the point (x, y) from +x towards +y (rad, in [−π, π]) at a fixed cost, for
/// finite inputs not both zero (which give 0). The octant is reduced without a branch to
/// t = min(|x|, |y|)/max(|x|, |y|) ∈ [0, 1], where Abramowitz & Stegun's polynomial 4.4.49
/// gives atan t within 2·10⁻⁸; the error in f32 is a few ulp of π.
#[inline]
pub fn atan2(y: f32, x: f32) -> f32 {
    // A&S 4.4.49: atan t = t(1 + a₂t² + a₄t⁴ + … + a₁₆t¹⁶), 0 ≤ t ≤ 1.
    const A: [f32; 8] = [
        -0.333_331_45,
        0.199_935_51,
        -0.142_089,
        0.106_562_64,
        -0.075_289_64,
        0.042_909_614,
        -0.016_165_737,
        0.002_866_225_7,
    ];
    let (ax, ay) = (x.abs(), y.abs());
    let steep = ay > ax;
    let big = select(steep, ay, ax);
    let small = select(steep, ax, ay);
    let t = small / select(big > 0.0, big, 1.0);
    let t2 = t * t;
    let mut poly = A[7];
    for a in A[..7].iter().rev() {
        poly = poly * t2 + a;
    }
    let first = t + t * t2 * poly;
    // Undo the reductions: past the diagonal, then into the left half-plane, then below.
    let octant = select(steep, core::f32::consts::FRAC_PI_2 - first, first);
    let half = select(x < 0.0, core::f32::consts::PI - octant, octant);
    let angle = select(y < 0.0, -half, half);
    finite_or(angle, 0.0)
}

/// Square root of a sum of squares or another value known to be finite and ≥ 0 (no clamp:
/// the film table's blends √(e² + h_RI²) take a dozen of these per roller and step).
#[inline(always)]
pub(crate) fn sqrt_non_negative(x: f32) -> f32 {
    sqrt_raw(x)
}

/// Square root of a non-negative number; negative or NaN inputs give 0, +∞ gives `f32::MAX`'s
/// root.
#[inline]
pub fn sqrt(x: f32) -> f32 {
    // A bit-mask select: with a plain `if` the compiler skips the root when it knows x = 0.
    sqrt_raw(select(x > 0.0, min(x, f32::MAX), 0.0))
}

// IEEE square root on a Cortex-M4F: one `vsqrt.f32` in a leaf function. (Rust has no stable
// FPU target feature for this target, so an inline `asm!` with float registers is refused;
// `global_asm!` with an `.fpu` directive is not.) The hard-float ABI passes and returns the
// f32 in s0.
#[cfg(all(target_arch = "arm", target_abi = "eabihf"))]
core::arch::global_asm!(
    ".section .text.bearing_core_vsqrtf,\"ax\",%progbits",
    ".global bearing_core_vsqrtf",
    ".type bearing_core_vsqrtf,%function",
    ".thumb_func",
    ".fpu fpv4-sp-d16",
    "bearing_core_vsqrtf:",
    "vsqrt.f32 s0, s0",
    "bx lr",
);

#[cfg(all(target_arch = "arm", target_abi = "eabihf"))]
extern "C" {
    fn bearing_core_vsqrtf(x: f32) -> f32;
}

/// IEEE square root of a finite non-negative `x` on a Cortex-M4F.
#[cfg(all(target_arch = "arm", target_abi = "eabihf"))]
#[inline]
fn sqrt_raw(x: f32) -> f32 {
    // SAFETY: `bearing_core_vsqrtf` (above) executes `vsqrt.f32 s0, s0; bx lr`: it reads and
    // writes only s0 (a caller-saved register under the AAPCS-VFP ABI that `extern "C"` uses
    // on eabihf targets), touches no memory and no stack, and always returns. The eabihf
    // targets always have the FPU that executes it.
    unsafe { bearing_core_vsqrtf(x) }
}

/// IEEE square root elsewhere: libm's `sqrtf` is correctly rounded like `vsqrt`, so both
/// targets give the same bits.
#[cfg(not(all(target_arch = "arm", target_abi = "eabihf")))]
#[inline]
fn sqrt_raw(x: f32) -> f32 {
    libm::sqrtf(x)
}

/// `a` if `condition`, else `b`, by bit masks: both sides are always computed and no branch
/// is taken, so the work does not depend on the data. (A plain `if` on floats lets LLVM turn
/// the select into a branch that skips the costlier side — a division, `exp`, `ln` — and the
/// instruction count of a step would then depend on its input.)
#[inline(always)]
pub fn select(condition: bool, a: f32, b: f32) -> f32 {
    let mask = (condition as u32).wrapping_neg();
    f32::from_bits((a.to_bits() & mask) | (b.to_bits() & !mask))
}

/// The smaller of two indices (`Ord::min` without its generic call).
#[inline(always)]
pub(crate) fn min_index(a: usize, b: usize) -> usize {
    if a < b {
        a
    } else {
        b
    }
}

/// The larger of `a` and `b`; `b` when `a` is NaN. A compare and a select: no library call
/// (ARMv7E-M has no `vmaxnm`, so `f32::max` becomes a call to `fmaxf`).
#[inline(always)]
pub fn max(a: f32, b: f32) -> f32 {
    if a > b {
        a
    } else {
        b
    }
}

/// The smaller of `a` and `b`; `b` when `a` is NaN.
#[inline(always)]
pub fn min(a: f32, b: f32) -> f32 {
    if a < b {
        a
    } else {
        b
    }
}

/// `value` if it is finite, else `fallback`.
#[inline]
pub fn finite_or(value: f32, fallback: f32) -> f32 {
    if value.is_finite() {
        value
    } else {
        fallback
    }
}

#[cfg(test)]
mod tests {
    /// atan2 against std's over every quadrant and both sides of each diagonal.
    #[test]
    fn atan2_matches_std() {
        let mut worst = 0.0_f64;
        for i in 0..4000 {
            let angle = -3.1 + 6.2 * i as f64 / 3999.0;
            let r = 10f64.powi(i % 7 - 3);
            let (y, x) = ((r * angle.sin()) as f32, (r * angle.cos()) as f32);
            let err = (super::atan2(y, x) as f64 - (y as f64).atan2(x as f64)).abs();
            worst = worst.max(err);
        }
        assert!(worst < 1.0e-6, "worst {worst:e} rad");
        assert_eq!(super::atan2(0.0, 0.0), 0.0);
        assert_eq!(super::atan2(f32::NAN, 1.0), 0.0);
    }

    use super::*;

    /// Reference: `libm::ldexpf(1, k)` (exact powers of two) and round-half-even of k + ¼, k ± ½
    /// (the nearest integer the 1.5·2²³ addition must give), for every k the callers reach.
    #[test]
    fn round_with_pow2_is_exact() {
        for k in -126i32..=126 {
            let kf = k as f32;
            assert_eq!(round_with_pow2(kf), (kf, libm::ldexpf(1.0, k)), "k = {k}");
            let (up, _) = round_with_pow2(kf + 0.25);
            assert_eq!(up, kf, "k + ¼, k = {k}");
            // Ties go to the even neighbour (IEEE 754 round-to-nearest-even).
            let (tie, _) = round_with_pow2(kf + 0.5);
            let even = if k % 2 == 0 { kf } else { kf + 1.0 };
            assert_eq!(tie, even, "k + ½, k = {k}");
        }
        let (k, scale) = round_with_pow2(127.0);
        assert_eq!((k, scale), (127.0, libm::ldexpf(1.0, 127)));
    }

    fn rel(a: f32, b: f64) -> f64 {
        ((a as f64 - b) / b).abs()
    }

    #[test]
    fn ln_matches_f64_over_the_positive_range() {
        // Reference: the f64 logarithm of the same f32 value (std).
        let mut worst = 0.0f64;
        let mut x = 1.0e-37f32;
        while x < 1.0e38 {
            let reference = (x as f64).ln();
            let err = (ln(x) as f64 - reference).abs() / reference.abs().max(1.0);
            worst = worst.max(err);
            x *= 1.37;
        }
        assert!(worst < 3.0e-7, "worst ln error {worst}");
    }

    #[test]
    fn log2_and_exp2_match_f64() {
        let mut worst = 0.0f64;
        let mut x = 1.0e-37f32;
        while x < 1.0e38 {
            let reference = (x as f64).log2();
            worst = worst.max((log2(x) as f64 - reference).abs() / reference.abs().max(1.0));
            x *= 1.37;
        }
        assert!(worst < 3.0e-7, "worst log2 error {worst}");
        let mut worst = 0.0f64;
        let mut y = -120.0f32;
        while y < 120.0 {
            worst = worst.max(rel(exp2(y), (y as f64).exp2()));
            y += 0.0917;
        }
        assert!(worst < 5.0e-7, "worst exp2 error {worst}");
    }

    #[test]
    fn exp_matches_f64() {
        let mut worst = 0.0f64;
        let mut x = -80.0f32;
        while x < 80.0 {
            worst = worst.max(rel(exp(x), (x as f64).exp()));
            x += 0.0731;
        }
        assert!(worst < 5.0e-7, "worst exp error {worst}");
    }

    #[test]
    fn pow_matches_f64_for_the_exponents_in_use() {
        for &y in &[
            10.0 / 9.0,
            0.9,
            0.56,
            0.69,
            -0.1,
            -0.13,
            0.54,
            7.0 / 3.0,
            3.0 / 7.0,
        ] {
            let mut x = 1.0e-12f32;
            while x < 1.0e12 {
                // exp(y·ln x) in f32 cannot beat the rounding of y·ln x itself: allow a
                // few ulp of that product on top of the pure-function error.
                let e = rel(pow(x, y), (x as f64).powf(y as f64));
                let limit = 1.0e-6 + 2.5e-7 * ((y as f64) * (x as f64).ln()).abs();
                assert!(e < limit, "pow({x}, {y}) error {e} (limit {limit})");
                x *= 3.3;
            }
        }
    }

    #[test]
    fn sin_cos_matches_f64() {
        let mut worst = 0.0f64;
        let mut x = -100.0f32;
        while x < 100.0 {
            let (s, c) = sin_cos(x);
            worst = worst.max((s as f64 - (x as f64).sin()).abs());
            worst = worst.max((c as f64 - (x as f64).cos()).abs());
            x += 0.0173;
        }
        assert!(worst < 2.0e-6, "worst sin/cos error {worst}");
    }

    #[test]
    fn pow_10_9_matches_f64_over_the_approaches_in_use() {
        let mut worst = 0.0f64;
        let mut x = 1.0e-13f32;
        while x <= 1.0 {
            worst = worst.max(rel(pow_10_9(x), (x as f64).powf(10.0 / 9.0)));
            x *= 1.013;
        }
        assert!(worst < 1.0e-6, "worst x^(10/9) error {worst}");
        assert_eq!(pow_10_9(0.0), 0.0);
        assert_eq!(pow_10_9(-1.0), 0.0);
        assert_eq!(pow_10_9(f32::NAN), 0.0);
    }

    /// Against f64's ninth root over the slice approaches in use (10⁻¹³ … 1 m): within
    /// 10⁻⁴, and not below it.
    #[test]
    fn two_step_ninth_root_matches_f64_from_above() {
        let mut worst = 0.0f64;
        let mut x = 1.0e-13f32;
        while x <= 1.0 {
            let exact = (x as f64).powf(1.0 / 9.0);
            let root = ninth_root_two_steps(x) as f64;
            assert!(
                root >= exact * (1.0 - 1.0e-7),
                "x = {x}: {root} below {exact}"
            );
            worst = worst.max(rel(ninth_root_two_steps(x), exact));
            x *= 1.0013;
        }
        assert!(worst < 1.0e-4, "worst two-step ninth root error {worst}");
        assert!(
            worst > 1.0e-6,
            "two steps are no more accurate than three: {worst}"
        );
    }

    #[test]
    fn hostile_inputs_stay_finite() {
        for &x in &[
            f32::NAN,
            f32::INFINITY,
            f32::NEG_INFINITY,
            0.0,
            -1.0,
            f32::MAX,
            f32::MIN_POSITIVE,
            1e-45,
        ] {
            assert!(ln(x).is_finite());
            assert!(exp(x).is_finite());
            assert!(pow(x, 1.5).is_finite());
            assert!(pow(2.0, x).is_finite());
            assert!(sqrt(x).is_finite());
        }
    }
}
