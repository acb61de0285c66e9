//! Hertz theory of the elliptical point contact: ellipticity, semi-axes and maximum pressure.
//!
//! Two bodies with reduced radii R_x (rolling direction x) and R_y (transverse, R_y ≥ R_x)
//! touch on an ellipse with semi-axes b along x and a along y, ellipticity k = a/b ≥ 1. With
//! e² = 1 − 1/k² and the complete elliptic integrals K(e), E(e) of the first and second kind,
//! k solves (Johnson, *Contact Mechanics*, 1985, eq. 4.39)
//!
//!   R_y/R_x = (k² E − K)/(K − E),
//!
//! and with 1/R = 1/R_x + 1/R_y and the reduced modulus E' of docs/physics.md §1
//! (Hamrock & Brewe 1983, *Simplified solution for stresses and deformations*, ASME J. Lubr.
//! Technol. 105:171, who write the same closed forms)
//!
//!   a = (6k²E w R/(πE'))^⅓, b = (6E w R/(πkE'))^⅓, p_h = 3w/(2πab).
//!
//! The solver evaluates K and E by the arithmetic–geometric mean (Abramowitz & Stegun 17.6)
//! and k by bisection, so the circular contact (k = 1, E = π/2) is exact. Hamrock–Brewe's
//! approximations k ≈ 1.0339 (R_y/R_x)^0.6360, E ≈ 1.0003 + 0.5968 R_x/R_y are kept for
//! comparison (they are within a few per cent, see the tests) and to invert a given ellipticity.

use std::f64::consts::PI;

/// Complete elliptic integrals (K(m), E(m)) of parameter m = e² ∈ [0, 1) by the
/// arithmetic–geometric mean (Abramowitz & Stegun 17.6.1–17.6.4).
pub fn elliptic_integrals(m: f64) -> (f64, f64) {
    let mut a = 1.0;
    let mut g = (1.0 - m).sqrt();
    let mut c = m.sqrt();
    let mut sum = 0.5 * c * c;
    let mut pow2 = 0.5;
    for _ in 0..40 {
        if c.abs() < 1e-16 {
            break;
        }
        let an = 0.5 * (a + g);
        c = 0.5 * (a - g);
        g = (a * g).sqrt();
        a = an;
        pow2 *= 2.0;
        sum += pow2 * c * c;
    }
    let k = PI / (2.0 * a);
    (k, k * (1.0 - sum))
}

/// R_y/R_x of the contact with ellipticity k = a/b ≥ 1 (Johnson eq. 4.39).
pub fn radius_ratio_of_ellipticity(k: f64) -> f64 {
    if k <= 1.0 + 1e-9 {
        return 1.0;
    }
    let m = 1.0 - 1.0 / (k * k);
    let (kk, ee) = elliptic_integrals(m);
    (k * k * ee - kk) / (kk - ee)
}

/// Ellipticity k = a/b of the contact with R_y/R_x = `ratio` ≥ 1, by bisection on
/// [`radius_ratio_of_ellipticity`] (monotone in k).
pub fn ellipticity_of_radius_ratio(ratio: f64) -> f64 {
    if ratio <= 1.0 {
        return 1.0;
    }
    let (mut lo, mut hi) = (1.0_f64, 2.0_f64);
    while radius_ratio_of_ellipticity(hi) < ratio {
        hi *= 2.0;
    }
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if radius_ratio_of_ellipticity(mid) < ratio {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// Hamrock–Brewe (1983) approximation of the ellipticity, k ≈ 1.0339 (R_y/R_x)^0.6360.
pub fn hamrock_brewe_ellipticity(ratio: f64) -> f64 {
    1.0339 * ratio.powf(0.6360)
}

/// Hamrock–Brewe (1983) approximation of E, E ≈ 1.0003 + 0.5968 R_x/R_y.
pub fn hamrock_brewe_second_integral(ratio: f64) -> f64 {
    1.0003 + 0.5968 / ratio
}

/// The Hertz contact of one point-contact case.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct HertzEllipse {
    /// Ellipticity k = a/b.
    pub ellipticity: f64,
    /// Semi-axis along the rolling direction, b, m.
    pub semi_axis_rolling_m: f64,
    /// Semi-axis across the rolling direction, a, m.
    pub semi_axis_transverse_m: f64,
    /// Maximum Hertz pressure p_h, Pa.
    pub max_pressure_pa: f64,
}

impl HertzEllipse {
    /// The contact of load w (N) between bodies of reduced radii R_x ≤ R_y (m) and reduced
    /// modulus E' (Pa).
    pub fn new(load_n: f64, radius_x_m: f64, radius_y_m: f64, modulus_pa: f64) -> Self {
        let ratio = radius_y_m / radius_x_m;
        let k = ellipticity_of_radius_ratio(ratio);
        let (_, e) = elliptic_integrals(1.0 - 1.0 / (k * k));
        let r = 1.0 / (1.0 / radius_x_m + 1.0 / radius_y_m);
        let base = 6.0 * e * load_n * r / (PI * modulus_pa);
        let a = (base * k * k).cbrt();
        let b = (base / k).cbrt();
        Self {
            ellipticity: k,
            semi_axis_rolling_m: b,
            semi_axis_transverse_m: a,
            max_pressure_pa: 3.0 * load_n / (2.0 * PI * a * b),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// K(0) = E(0) = π/2; K(0.5) = 1.854074677, E(0.5) = 1.350643881 (Abramowitz & Stegun
    /// table 17.1, m = 0.5).
    #[test]
    fn elliptic_integrals_match_tables() {
        let (k0, e0) = elliptic_integrals(0.0);
        assert!((k0 - PI / 2.0).abs() < 1e-15 && (e0 - PI / 2.0).abs() < 1e-15);
        let (k, e) = elliptic_integrals(0.5);
        assert!((k - 1.854_074_677).abs() < 1e-8, "{k}");
        assert!((e - 1.350_643_881).abs() < 1e-8, "{e}");
    }

    /// Circular contact: a = b = (3wR_x/(2E'))^⅓ and p_h = 3w/(2πa²) (Johnson eq. 4.22 with
    /// E* = E'/2, R = R_x/2 for a sphere of reduced radius R_x).
    #[test]
    fn circular_contact_is_exact() {
        let h = HertzEllipse::new(100.0, 0.01, 0.01, 2.2e11);
        let a = (3.0f64 * 100.0 * 0.01 / (2.0 * 2.2e11)).cbrt();
        assert!((h.ellipticity - 1.0).abs() < 1e-12);
        assert!((h.semi_axis_rolling_m / a - 1.0).abs() < 1e-12);
        assert!((h.semi_axis_transverse_m / a - 1.0).abs() < 1e-12);
        assert!((h.max_pressure_pa / (3.0 * 100.0 / (2.0 * PI * a * a)) - 1.0).abs() < 1e-12);
    }

    /// Hamrock–Brewe's approximations of k and E stay within 3 % and 2 % of the exact values for
    /// R_y/R_x from 2 to 40, the accepted range (3.1 % for k at 50; at R_y/R_x = 1 their k is
    /// 1.0339 against the exact 1), and the bisection inverts the ratio.
    #[test]
    fn hamrock_brewe_approximations_agree() {
        for ratio in [2.0, 5.0, 10.0, 25.0, 40.0] {
            let k = ellipticity_of_radius_ratio(ratio);
            assert!((radius_ratio_of_ellipticity(k) / ratio - 1.0).abs() < 1e-9);
            let kb = hamrock_brewe_ellipticity(ratio);
            assert!((kb / k - 1.0).abs() < 0.03, "ratio {ratio}: k {k} vs {kb}");
            let (_, e) = elliptic_integrals(1.0 - 1.0 / (k * k));
            let eb = hamrock_brewe_second_integral(ratio);
            assert!((eb / e - 1.0).abs() < 0.02, "ratio {ratio}: E {e} vs {eb}");
        }
    }
}
