//! Load–approach laws of a steel roller between two raceways.
//!
//! The laws give the load per unit length `w` (N/m) that a roller carries for a total approach
//! `δ` (m) of both raceway contacts in series. Written per unit length, a slice of length
//! `l/n_s` carries `q = (l/n_s)·w(δ)`, so a uniformly loaded roller gives the same total load for
//! any slice count — the trap of the per-slice constant that docs/physics.md §3 warns about.
//!
//! * [`ContactLaw::Palmgren`] (default): Palmgren's empirical steel law per contact,
//!   δ = 3.84·10⁻⁵ Q^0.9 / l^0.8 (mm, N) (Palmgren, *Ball and Roller Bearing Engineering*, 1959;
//!   Harris & Kotzalas, *Essential Concepts of Bearing Technology*, eq. 6.47). Made
//!   dimensionally homogeneous as δ = k·(w/E')^0.9·l^0.1, its constant k follows from the steel
//!   value (E' = 230.8 GPa): k = [`PALMGREN_K`]. Explicit, so a slice costs one power; the
//!   default for the real-time step. It is within 4 % of ISO/TS 16281's
//!   c_L = 35948·l^(8/9) N/mm^(10/9) for the two contacts together (tested).
//! * [`ContactLaw::Lundberg`]: the logarithmic law δ = (2w/(πE'))·[ln(2πE'R/w) − 1] per contact
//!   (Hamrock, *Fundamentals of Fluid Film Lubrication*, 1994, ch. 17), valid for any E' and
//!   sensitive to the raceway radii; implicit in w, solved by a fixed number of Newton steps.

use crate::math::{exp, ln, min, pow, pow_10_9_in_range};

/// Dimensionless constant of the homogeneous Palmgren law δ = k·(w/E')^0.9·l^0.1, per contact.
///
/// From 3.84·10⁻⁵ mm·N^−0.9·mm^0.8 at E' = 230.77 GPa: in SI, δ = 1.52873·10⁻¹⁰·Q^0.9·l^−0.8,
/// so k = 1.52873·10⁻¹⁰ · (2.3077·10¹¹)^0.9 = 2.5775 (checked in the tests).
pub const PALMGREN_K: f32 = 2.5775;

/// Largest approach the laws are evaluated at (m).
pub(crate) const MAX_APPROACH_M: f32 = 1.0e-2; // also keeps `pow_10_9` in its range

/// Newton steps used to invert the Lundberg law (from a Palmgren start; converged to f32).
const LUNDBERG_NEWTON_STEPS: usize = 4;

/// A slice's approach `δ` (m) made safe for a law, and the mask its results are multiplied
/// by: (min(δ, 1 cm), 1) for δ > 0, else (10⁻¹², 0). Approaches beyond 1 cm are not elastic
/// contact any more; the clamp keeps ∞ finite. Cheap operands: a conditional move; the mask
/// (a multiplication by 0 or 1) keeps the law's results in the data flow, so no branch can
/// skip the power and the work does not depend on δ.
#[inline(always)]
pub(crate) fn clamped_approach(approach_m: f32) -> (f32, f32) {
    let positive = approach_m > 0.0;
    let d = if positive {
        min(approach_m, MAX_APPROACH_M)
    } else {
        1.0e-12
    };
    (d, if positive { 1.0 } else { 0.0 })
}

/// Which load–approach law the slices follow.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum ContactLaw {
    /// Palmgren's steel power law w ∝ δ^(10/9), generalised to any E' (default).
    #[default]
    Palmgren,
    /// Lundberg / Hamrock logarithmic law, both contacts in series (implicit, costlier).
    Lundberg,
}

/// A contact law bound to one roller's contacts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct BoundLaw {
    law: ContactLaw,
    /// Palmgren: w = c_w · δ^(10/9), c_w = E'·(2k·l^0.1)^(−10/9) (N/m^(19/9)).
    palmgren_coefficient: f32,
    /// Lundberg: 4/(πE') (m²/N).
    lundberg_compliance: f32,
    /// Lundberg: ln(2πE'√(R_in R_out)) (ln of N/m).
    lundberg_ln_a: f32,
}

impl BoundLaw {
    /// Bind `law` to a roller of effective length `l` (m) with reduced modulus `E'` (Pa) and the
    /// reduced radii of its inner and outer contacts (m).
    pub(crate) fn new(
        law: ContactLaw,
        roller_length_m: f32,
        reduced_modulus_pa: f32,
        inner_radius_m: f32,
        outer_radius_m: f32,
    ) -> Self {
        let two_k = 2.0 * PALMGREN_K * pow(roller_length_m, 0.1);
        let pi = core::f32::consts::PI;
        Self {
            law,
            palmgren_coefficient: reduced_modulus_pa * pow(two_k, -10.0 / 9.0),
            lundberg_compliance: 4.0 / (pi * reduced_modulus_pa),
            lundberg_ln_a: ln(2.0
                * pi
                * reduced_modulus_pa
                * crate::math::sqrt(inner_radius_m * outer_radius_m)),
        }
    }

    /// The law.
    pub(crate) fn kind(&self) -> ContactLaw {
        self.law
    }

    /// Palmgren coefficient c_w of w = c_w·δ^(10/9) (also a good start for Lundberg).
    pub(crate) fn palmgren_coefficient(&self) -> f32 {
        self.palmgren_coefficient
    }

    /// Load per unit length `w` (N/m) and its first and second derivatives `dw/dδ` (N/m²),
    /// `d²w/dδ²` (N/m³) for total approach `δ` (m). Zero for δ ≤ 0. The work done does not
    /// depend on δ.
    #[inline]
    pub(crate) fn load_per_length(&self, approach_m: f32) -> (f32, f32, f32) {
        let (d, mask) = clamped_approach(approach_m);
        let (w, dw, d2w) = match self.law {
            ContactLaw::Palmgren => {
                let w = self.palmgren_coefficient * pow_10_9_in_range(d);
                let w_per_d = w / d;
                (w, (10.0 / 9.0) * w_per_d, (10.0 / 81.0) * w_per_d / d)
            }
            ContactLaw::Lundberg => self.lundberg(d),
        };
        (w * mask, dw * mask, d2w * mask)
    }

    /// Invert δ = (4w/(πE'))·[ln(A/w) − 1], A = 2πE'√(R_in R_out), for w by Newton in v = ln w.
    fn lundberg(&self, approach_m: f32) -> (f32, f32, f32) {
        let c = self.lundberg_compliance;
        let ln_a = self.lundberg_ln_a;
        // The law is monotone only while ln(A/w) > 2; stay inside.
        let v_max = ln_a - 2.5;
        let mut v = min(
            ln(self.palmgren_coefficient * pow(approach_m, 10.0 / 9.0)),
            v_max,
        );
        for _ in 0..LUNDBERG_NEWTON_STEPS {
            let w = exp(v);
            let f = c * w * (ln_a - v - 1.0) - approach_m;
            let df = c * w * (ln_a - v - 2.0);
            v = min(v - f / df, v_max);
        }
        let w = exp(v);
        // dδ/dw = g = c·(ln A − v − 2); dw/dδ = 1/g; d²w/dδ² = c/(g³·w).
        let g = c * (ln_a - v - 2.0);
        (w, 1.0 / g, c / (g * g * g * w))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn palmgren_constant_reproduces_the_published_steel_law() {
        // 3.84e-5 mm/N^0.9·mm^0.8 converted to SI, then k = that·E'^0.9 (E' = 210/0.91 GPa).
        let si = 3.84e-5f64 * 1e-3 * 1000f64.powf(-0.8);
        let k = si * (210e9f64 / 0.91).powf(0.9);
        assert!((k / PALMGREN_K as f64 - 1.0).abs() < 1e-4, "k = {k}");
    }

    #[test]
    fn steel_law_is_within_5_percent_of_iso_ts_16281() {
        // ISO/TS 16281: whole roller, both contacts: Q = 35948·l^(8/9)·δ^(10/9) (N, mm).
        for &l_mm in &[5.0f64, 9.0, 15.0, 30.0] {
            let law = BoundLaw::new(
                ContactLaw::Palmgren,
                (l_mm * 1e-3) as f32,
                230.77e9,
                3e-3,
                5e-3,
            );
            for &delta_um in &[2.0f64, 10.0, 30.0] {
                let (w, _, _) = law.load_per_length((delta_um * 1e-6) as f32);
                let q = w as f64 * l_mm * 1e-3;
                let iso = 35948.0 * l_mm.powf(8.0 / 9.0) * (delta_um * 1e-3).powf(10.0 / 9.0);
                assert!(
                    (q / iso - 1.0).abs() < 0.05,
                    "l={l_mm} δ={delta_um}: {q} vs ISO {iso}"
                );
            }
        }
    }

    #[test]
    fn lundberg_inverse_satisfies_the_forward_law_and_is_close_to_palmgren() {
        // Forward law in f64 (Hamrock's form, two contacts in series).
        let (e, ri, ro, l) = (230.77e9f64, 3.5e-3, 5.2e-3, 0.015);
        let law = BoundLaw::new(
            ContactLaw::Lundberg,
            l as f32,
            e as f32,
            ri as f32,
            ro as f32,
        );
        let palm = BoundLaw::new(
            ContactLaw::Palmgren,
            l as f32,
            e as f32,
            ri as f32,
            ro as f32,
        );
        for &delta in &[1e-6f64, 5e-6, 2e-5] {
            let (w, dw, _) = law.load_per_length(delta as f32);
            let w = w as f64;
            let pi = core::f64::consts::PI;
            let forward = 2.0 * w / (pi * e) * ((2.0 * pi * e * ri / w).ln() - 1.0)
                + 2.0 * w / (pi * e) * ((2.0 * pi * e * ro / w).ln() - 1.0);
            assert!((forward / delta - 1.0).abs() < 1e-4, "δ {delta}: {forward}");
            // Derivative against a central difference of the forward solve.
            let h = delta * 1e-3;
            let (wp, _, _) = law.load_per_length((delta + h) as f32);
            let (wm, _, _) = law.load_per_length((delta - h) as f32);
            let fd = (wp as f64 - wm as f64) / (2.0 * h);
            assert!((dw as f64 / fd - 1.0).abs() < 0.02, "dw {dw} vs {fd}");
            // The two laws agree within ~20 % over the working range.
            let (wpal, _, _) = palm.load_per_length(delta as f32);
            assert!(
                (w / wpal as f64 - 1.0).abs() < 0.25,
                "Lundberg {w} vs Palmgren {wpal}"
            );
        }
    }

    #[test]
    fn no_load_without_approach() {
        let law = BoundLaw::new(ContactLaw::Palmgren, 0.01, 2.3e11, 3e-3, 5e-3);
        assert_eq!(law.load_per_length(-1e-6), (0.0, 0.0, 0.0));
        assert_eq!(law.load_per_length(f32::NAN), (0.0, 0.0, 0.0));
    }
}
