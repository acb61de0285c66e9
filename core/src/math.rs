//! Fixed-cost f32 elementary functions.
//!
//! The bearing step must take the same number of instructions for every input
//! (ARCHITECTURE.md), and `libm`'s `logf`/`expf`/`powf` branch on their argument. These
//! versions use only `+ − × ÷`, bit manipulation and selects, so their cost is fixed and
//! their results are bit-identical on the host and on the Cortex-M4F (no fused operations).
//! Accuracy (checked in the tests against f64): a few ulp over the whole positive range.

const LN_2: f32 = core::f32::consts::LN_2;
const SQRT_2: f32 = core::f32::consts::SQRT_2;

/// Natural logarithm for `x > 0` (finite). Inputs `<= 0`, subnormal or NaN are treated as the
/// smallest normal number; `+∞` as `f32::MAX`. Never returns NaN or ∞.
#[inline]
pub fn ln(x: f32) -> f32 {
    // Clamp into the normal range; `max`/`min` return the non-NaN operand (`clamp` would
    // propagate NaN), so NaN becomes the smallest normal number.
    #[allow(clippy::manual_clamp)]
    let x = x.max(f32::MIN_POSITIVE).min(f32::MAX);
    let bits = x.to_bits();
    let exponent = ((bits >> 23) & 0xff) as i32 - 127;
    // Mantissa in [1, 2).
    let mantissa = f32::from_bits((bits & 0x007f_ffff) | 0x3f80_0000);
    // Re-centre to [√½, √2) so the series argument stays small.
    let high = mantissa > SQRT_2;
    let m = if high { mantissa * 0.5 } else { mantissa };
    let e = (exponent + i32::from(high)) as f32;
    // ln m = 2·atanh(t), t = (m − 1)/(m + 1), |t| ≤ 0.1716: odd series to t¹¹.
    let t = (m - 1.0) / (m + 1.0);
    let t2 = t * t;
    let series = 1.0
        + t2 * (1.0 / 3.0
            + t2 * (1.0 / 5.0 + t2 * (1.0 / 7.0 + t2 * (1.0 / 9.0 + t2 * (1.0 / 11.0)))));
    e * LN_2 + 2.0 * t * series
}

/// Exponential. Arguments are clamped to `[-87, 88]` (result between ≈1.6e-38 and ≈1.7e38);
/// NaN is treated as `-87`. Never returns NaN or ∞.
#[inline]
pub fn exp(x: f32) -> f32 {
    // `max` returns the non-NaN operand, so NaN becomes −87 (`clamp` would keep NaN).
    #[allow(clippy::manual_clamp)]
    let x = x.max(-87.0).min(88.0);
    // x = n·ln2 + r, |r| ≤ ln2/2; round to nearest without a branch.
    let v = x * core::f32::consts::LOG2_E;
    let n = (v + if v >= 0.0 { 0.5 } else { -0.5 }) as i32;
    let nf = n as f32;
    // Cody–Waite split of ln 2 keeps r accurate for large n.
    const LN_2_HI: f32 = 0.693_145_75;
    const LN_2_LO: f32 = 1.428_606_8e-6;
    let r = (x - nf * LN_2_HI) - nf * LN_2_LO;
    // Taylor series to r⁷: truncation < 2e-8 relative for |r| ≤ 0.347.
    let p = 1.0
        + r * (1.0
            + r * (0.5
                + r * (1.0 / 6.0
                    + r * (1.0 / 24.0
                        + r * (1.0 / 120.0 + r * (1.0 / 720.0 + r * (1.0 / 5040.0)))))));
    // 2ⁿ for n in [-126, 127] built from its bits.
    let scale = f32::from_bits(((n + 127).clamp(1, 254) as u32) << 23);
    p * scale
}

/// `x^y` for `x > 0`; `x <= 0` (or NaN) gives `0`. Never returns NaN or ∞.
#[inline]
pub fn pow(x: f32, y: f32) -> f32 {
    let value = exp(y * ln(x));
    if x > 0.0 {
        value
    } else {
        0.0
    }
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
    match k & 3 {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

/// Square root of a non-negative number; negative or NaN inputs give 0.
#[inline]
pub fn sqrt(x: f32) -> f32 {
    // libm's sqrtf is correctly rounded (IEEE), hence identical on every target.
    libm::sqrtf(if x > 0.0 { x.min(f32::MAX) } else { 0.0 })
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
    use super::*;

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
