//! Fixed-cost f32 elementary functions of the film network, by series: the same instruction
//! sequence for every argument (no data-dependent branches, no library calls whose cost varies — `libm::tanhf`
//! varies by ±25 %, docs/embedded.md), accurate to a few f32 ulps over the range the network uses.
//!
//! They round differently from the least-squares polynomials of the parent module (`super::ln`,
//! `super::exp`), which the bearing step uses: the network's outputs, and with them the
//! committed weights' regression tests and the recorded traces, depend on these bits, the step's
//! results on those; so both families stay, named by their method.
//!
//! - `ln_atanh`: exponent/mantissa split with the mantissa folded into [√½, √2) by integer arithmetic
//!   (the reduction of musl's `logf`), then `ln m = 2 atanh(s)`, `s = (m−1)/(m+1)`, as an odd
//!   series to s⁹ (|s| ≤ 0.172, truncation < 1e-9). Returns a finite value for *every* bit pattern
//!   (zero, negative, ∞, NaN give meaningless but finite numbers); callers guard validity.
//! - `exp_taylor`: argument clamped to ±87, Cody–Waite reduction `x = k ln 2 + r` with the
//!   nearest integer k (by the 1.5·2²³ rounding constant) and |r| ≤ ½ ln 2; `e^r` by its Taylor
//!   polynomial of degree 7 (truncation < 1e-8; Estrin's scheme, a short dependent chain), `2^k`
//!   assembled in the exponent bits.
//! - `2^k` is built from the bits of the rounding sum `y + 1.5·2²³` itself, whose mantissa holds
//!   k as an integer (`super::round_with_pow2`, shared with the step's `exp`), not by
//!   a float→int conversion: Rust's `as i32`
//!   saturates, which on x86-64 costs a compare-and-select around `cvttss2si` and keeps LLVM from
//!   vectorising a layer's activations; integer adds and a shift vectorise with SSE2 and are
//!   single instructions on the M4. The result is bit-identical to the conversion's.
//! - `tanh x = (e^{2x} − 1)/(e^{2x} + 1)` on x clamped to ±9 (tanh 9 = 1 − 3·10⁻⁸);
//!   `logistic x = 1/(1 + e^{−x})` on x clamped to ±30. Both inline into the caller's loop so a
//!   layer's neurons are evaluated lane-wise (`film::ann::float::DenseF32::forward`).

use super::round_with_pow2;

/// Branch-free clamp (`f32::clamp` panics on bad bounds and `max`/`min` may become libcalls
/// without an FPU `vmaxnm`).
#[inline(always)]
pub fn clamp(x: f32, lo: f32, hi: f32) -> f32 {
    let x = if x < lo { lo } else { x };
    if x > hi {
        hi
    } else {
        x
    }
}

/// Natural logarithm (see the module doc); finite for every input.
#[inline]
pub fn ln_atanh(x: f32) -> f32 {
    let ix = x.to_bits().wrapping_add(0x3f80_0000 - 0x3f35_04f3);
    let k = ((ix >> 23) as i32).wrapping_sub(0x7f);
    let m = f32::from_bits((ix & 0x007f_ffff).wrapping_add(0x3f35_04f3));
    let f = m - 1.0;
    let s = f / (2.0 + f);
    let s2 = s * s;
    let series =
        s * (2.0 + s2 * (2.0 / 3.0 + s2 * (2.0 / 5.0 + s2 * (2.0 / 7.0 + s2 * (2.0 / 9.0)))));
    k as f32 * core::f32::consts::LN_2 + series
}

/// e^t for |t| ≤ ½ ln 2 + ε: Taylor polynomial of degree 7 (truncation < 1e-8), evaluated by
/// Estrin's scheme (Knuth, *TAOCP* vol. 2, §4.6.4): pairs `cᵢ + cᵢ₊₁t`, combined with t² and
/// t⁴. One multiplication more than Horner's rule, but a dependent chain of 6 operations
/// instead of 14 — the activations of a layer wait on this chain, and the network on them.
#[inline(always)]
fn exp_reduced(t: f32) -> f32 {
    let t2 = t * t;
    let t4 = t2 * t2;
    let low = (1.0 + t) + t2 * (1.0 / 2.0 + t * (1.0 / 6.0));
    let high = (1.0 / 24.0 + t * (1.0 / 120.0)) + t2 * (1.0 / 720.0 + t * (1.0 / 5040.0));
    low + t4 * high
}

/// ln 2 split for Cody & Waite's reduction (Cody & Waite 1980, *Software Manual for the
/// Elementary Functions*): the high part has trailing zero bits so `k·LN2_HI` is exact.
const LN2_HI: f32 = 0.693_145_75;
const LN2_LO: f32 = 1.428_606_8e-6;

/// e^x with Cody–Waite reduction `r = x − k ln 2`, `k = round(x/ln 2)`, for |x| ≤ 87 (the
/// callers clamp).
#[inline(always)]
fn exp_in_range(x: f32) -> f32 {
    let (k, scale) = round_with_pow2(x * core::f32::consts::LOG2_E);
    let r = (x - k * LN2_HI) - k * LN2_LO;
    exp_reduced(r) * scale
}

/// e^x (see `exp_in_range`); x clamped to ±87.
#[inline]
pub fn exp_taylor(x: f32) -> f32 {
    exp_in_range(clamp(x, -87.0, 87.0))
}

/// Hyperbolic tangent. |2x| ≤ 18 needs no second clamp inside `exp`.
#[inline(always)]
pub fn tanh(x: f32) -> f32 {
    let e = exp_in_range(2.0 * clamp(x, -9.0, 9.0));
    (e - 1.0) / (e + 1.0)
}

/// Logistic sigmoid.
#[inline(always)]
pub fn logistic(x: f32) -> f32 {
    1.0 / (1.0 + exp_in_range(-clamp(x, -30.0, 30.0)))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Reference: libm (correctly rounded to ~1 ulp). Relative error over 40 decades.
    #[test]
    fn ln_matches_libm() {
        let mut x = 1e-20f32;
        while x < 1e20 {
            let (got, want) = (ln_atanh(x), libm::logf(x));
            assert!(
                (got - want).abs() <= 2e-7 * want.abs().max(1.0),
                "ln({x}) = {got}, libm {want}"
            );
            x *= 1.37;
        }
    }

    /// Reference: libm `expf`; relative error ≤ 4 ulp over the clamped range.
    #[test]
    fn exp_matches_libm() {
        let mut x = -86.0f32;
        while x < 86.0 {
            let (got, want) = (exp_taylor(x), libm::expf(x));
            assert!(
                (got / want - 1.0).abs() < 5e-7,
                "exp({x}) = {got}, libm {want}"
            );
            x += 0.173;
        }
    }

    /// Reference: libm tanhf and 1/(1+expf(−x)); absolute error ≤ 3e-7 (activations live in
    /// [−1, 1]).
    #[test]
    fn activations_match_libm() {
        let mut x = -40.0f32;
        while x < 40.0 {
            assert!((tanh(x) - libm::tanhf(x)).abs() < 3e-7, "tanh({x})");
            assert!(
                (logistic(x) - 1.0 / (1.0 + libm::expf(-x))).abs() < 3e-7,
                "logistic({x})"
            );
            x += 0.0371;
        }
    }

    /// Reference: libm tanhf, densely over the range the network's pre-activations reach
    /// (|x| ≤ 10, step 2⁻¹³ ≈ 1.2e-4, 163 841 points) and near zero, where (e − 1)/(e + 1)
    /// cancels: absolute error ≤ 3e-7 and the sign of x kept.
    #[test]
    fn tanh_dense_against_libm() {
        let mut worst = 0.0f32;
        for n in -81_920i32..=81_920 {
            let x = n as f32 / 8192.0;
            let (got, want) = (tanh(x), libm::tanhf(x));
            worst = worst.max((got - want).abs());
            assert!(got * x >= 0.0 && got.abs() <= 1.0, "tanh({x}) = {got}");
        }
        assert!(worst < 3e-7, "max |tanh − tanhf| = {worst}");
        let mut x = 1e-30f32;
        while x < 1e-2 {
            assert!(
                (tanh(x) - x).abs() < 3e-7 && (tanh(-x) + x).abs() < 3e-7,
                "tanh(±{x})"
            );
            x *= 3.7;
        }
    }

    /// Hostile bit patterns give finite logarithms (the guard relies on it).
    #[test]
    fn ln_is_finite_for_every_pattern() {
        for x in [
            0.0,
            -0.0,
            -1.0,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
            f32::MIN_POSITIVE / 4.0,
            f32::MAX,
        ] {
            assert!(ln_atanh(x).is_finite(), "ln({x})");
        }
    }
}
