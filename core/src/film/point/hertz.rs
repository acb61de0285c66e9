//! Hertz theory of the elliptical point contact in f32 at a fixed cost: the ellipticity
//! k = a/b and the complete elliptic integral of the second kind E from the radius ratio
//! R_y/R_x, as the host's solver and the point-contact dataset define them
//! (`bearing_ehl::point::hertz`).
//!
//! With e² = m = 1 − 1/k² and the complete elliptic integrals K(m), E(m), k solves (Johnson,
//! *Contact Mechanics*, 1985, eq. 4.39)
//!
//!   R_y/R_x = (k²E − K)/(K − E).
//!
//! K and E come from the arithmetic–geometric mean (Abramowitz & Stegun 17.6.1–17.6.4):
//! a₀ = 1, g₀ = √(1 − m) = 1/k, c₀² = m; aₙ₊₁ = ½(aₙ + gₙ), gₙ₊₁ = √(aₙgₙ),
//! cₙ₊₁ = cₙ²/(4aₙ₊₁); K = π/(2a_N), E = K(1 − S), S = ½m + Σₙ≥₁ 2ⁿ⁻¹cₙ². The sum is carried
//! as S/m with c₁²/m = (k − 1)/(4(k + 1)), so nothing cancels as k → 1, and then
//!
//!   R_y/R_x = k²(1 − S/m)/(S/m),   E = K(1 − m·S/m).
//!
//! k is found from Hamrock & Brewe's approximation k ≈ 1.0339 (R_y/R_x)^0.636 (Hamrock &
//! Brewe 1983, *Simplified solution for stresses and deformations*, ASME J. Lubr. Technol.
//! 105:171), within 3.4 % of the exact value, by a fixed number of steps
//! ln k ← ln k + s(ln r)·(ln r − ln ratio(k)), r = R_y/R_x, whose step factor s is the local
//! slope d ln k / d ln r of the exact relation (2/3 at r = 1, 0.59 at r = 100), a quadratic in
//! ln r least-squares fitted to the slope over r ∈ [1, 100]: each step shrinks the error
//! ≈ 100-fold. The test `ellipticity_matches_the_host` in `tests/tests/film_point.rs`
//! measures the result against the host's bisection on the exact relation.

use crate::math::series::{exp_taylor, ln_atanh};

/// Arithmetic–geometric-mean steps after the first: with g₀ = 1/k ≥ 0.05 (R_y/R_x ≤ 100) the
/// mean converges to f32 precision in four (A&S 17.6: the cₙ fall quadratically).
const AGM_STEPS: usize = 4;
/// Correction steps of ln k after Hamrock–Brewe's start (module doc).
const ELLIPTICITY_STEPS: usize = 3;
/// Step factor of the correction, s = s₀ + s₁ ln r + s₂ (ln r)² (module doc).
const ELLIPTICITY_GAIN: [f32; 3] = [0.671_143_3, -0.014_898_26, -0.001_013_27];
/// Largest R_y/R_x the ellipticity is solved for (k ≈ 17); larger ratios are taken as this
/// one. Hamrock–Dowson's ellipticity factors are within 10⁻⁵ of 1 there.
pub const MAX_RADIUS_RATIO: f32 = 100.0;
/// ln 1.0339 (Hamrock–Brewe's constant).
const LN_1_0339: f32 = 0.033_338_06;

/// The Hertz ellipse's shape: ellipticity and the second elliptic integral.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EllipseShape {
    /// Ellipticity k = a/b ≥ 1.
    pub ellipticity: f32,
    /// ln k.
    pub ln_ellipticity: f32,
    /// Complete elliptic integral of the second kind, E(1 − 1/k²).
    pub second_integral: f32,
    /// Complete elliptic integral of the first kind, K(1 − 1/k²), which sets the Hertz
    /// approach (Hamrock 1994, ch. 3: δ = K [(9/(2E R))(w/(πkE'))²]^⅓).
    pub first_integral: f32,
}

/// `(ln(R_y/R_x) of k, K, E)` of the contact with ellipticity `k` ≥ 1 (module doc).
#[inline(always)]
fn ratio_and_integrals(k: f32) -> (f32, f32, f32) {
    let inv_k = 1.0 / k;
    let m = 1.0 - inv_k * inv_k;
    let mut a = 0.5 * (1.0 + inv_k);
    let mut g = crate::math::sqrt(inv_k);
    // c₁²/m, and S/m so far.
    let mut c2_over_m = (k - 1.0) / (4.0 * (k + 1.0));
    let mut s_over_m = 0.5 + c2_over_m;
    let mut weight = 1.0;
    for _ in 0..AGM_STEPS {
        let a_next = 0.5 * (a + g);
        g = crate::math::sqrt(a * g);
        // cₙ₊₁²/m = (cₙ²/m)·(cₙ²/m)·m/(16 aₙ₊₁²).
        c2_over_m = c2_over_m * c2_over_m * m / (16.0 * a_next * a_next);
        a = a_next;
        weight *= 2.0;
        s_over_m += weight * c2_over_m;
    }
    let big_k = core::f32::consts::FRAC_PI_2 / a;
    let ln_ratio = 2.0 * ln_atanh(k) + ln_atanh(1.0 - s_over_m) - ln_atanh(s_over_m);
    (ln_ratio, big_k, big_k * (1.0 - m * s_over_m))
}

/// Ellipticity and E of the contact with `ln(R_y/R_x)` = `ln_radius_ratio`, clamped to
/// [0, ln [`MAX_RADIUS_RATIO`]] (NaN gives the circular contact). Fixed cost.
#[inline]
pub fn ellipse_shape(ln_radius_ratio: f32) -> EllipseShape {
    let ln_r = crate::math::series::clamp(
        crate::math::finite_or(ln_radius_ratio, 0.0),
        0.0,
        4.605_170_2, // ln 100
    );
    let mut ln_k = LN_1_0339 + 0.636 * ln_r;
    let [s0, s1, s2] = ELLIPTICITY_GAIN;
    let gain = s0 + ln_r * (s1 + ln_r * s2);
    let mut second_integral = core::f32::consts::FRAC_PI_2;
    let mut first_integral = core::f32::consts::FRAC_PI_2;
    for _ in 0..ELLIPTICITY_STEPS {
        let (ln_ratio_k, big_k, e) = ratio_and_integrals(exp_taylor(ln_k));
        second_integral = e;
        first_integral = big_k;
        // k ≥ 1: near R_y/R_x = 1 the first step from Hamrock–Brewe's k ≥ 1.0339 overshoots
        // below 1; the next steps continue from k = 1.
        ln_k = crate::math::max(ln_k + gain * (ln_r - ln_ratio_k), 0.0);
    }
    EllipseShape {
        ellipticity: exp_taylor(ln_k),
        ln_ellipticity: ln_k,
        second_integral,
        first_integral,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The circular contact: k = 1 and E = π/2 (Johnson §4.2), to f32 rounding.
    #[test]
    fn circular_contact() {
        let s = ellipse_shape(0.0);
        assert!((s.ellipticity - 1.0).abs() < 2e-6, "{s:?}");
        assert!(
            (s.second_integral - core::f32::consts::FRAC_PI_2).abs() < 1e-5,
            "{s:?}"
        );
    }

    /// E(0.5) = 1.350643881 and K(0.5) = 1.854074677 (Abramowitz & Stegun table 17.1): k = √2 gives m = ½; and the
    /// ratio it returns solves back to k = √2.
    #[test]
    fn second_integral_matches_the_table() {
        let k = core::f32::consts::SQRT_2;
        let (ln_ratio, big_k, e) = ratio_and_integrals(k);
        assert!((e - 1.350_643_9).abs() < 3e-6, "{e}");
        // K(0.5) = 1.854074677 (A&S table 17.1).
        assert!((big_k - 1.854_074_7).abs() < 3e-6, "{big_k}");
        let s = ellipse_shape(ln_ratio);
        assert!((s.ellipticity / k - 1.0).abs() < 3e-6, "{s:?}");
    }

    /// Hostile ratios stay finite and inside [1, k(100)].
    #[test]
    fn hostile_ratios_are_clamped() {
        let top = ellipse_shape(4.605_170_2).ellipticity;
        for v in [f32::NAN, f32::INFINITY, f32::NEG_INFINITY, -3.0, 1e30] {
            let s = ellipse_shape(v);
            assert!(s.ellipticity >= 1.0 && s.ellipticity <= top, "{v}: {s:?}");
            assert!(s.second_integral.is_finite(), "{v}: {s:?}");
        }
    }
}
