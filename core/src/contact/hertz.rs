//! Hertz line contact (docs/physics.md §1).

use crate::math::sqrt;

/// Half-width and maximum pressure of a dry line contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct HertzLineContact {
    /// Contact half-width b = √(8wR/(πE')) (m).
    pub half_width_m: f32,
    /// Maximum pressure p_h = √(wE'/(2πR)) = 2w/(πb) (Pa).
    pub max_pressure_pa: f32,
}

impl HertzLineContact {
    /// Hertz figures for load per unit length `w` (N/m), reduced radius `R` (m) and reduced
    /// modulus `E'` (Pa). Non-positive or non-finite inputs give zero.
    pub fn new(
        load_per_length_n_per_m: f32,
        reduced_radius_m: f32,
        reduced_modulus_pa: f32,
    ) -> Self {
        let w = load_per_length_n_per_m;
        let r = reduced_radius_m;
        let e = reduced_modulus_pa;
        if !(w > 0.0 && r > 0.0 && e > 0.0 && w.is_finite() && r.is_finite() && e.is_finite()) {
            return Self {
                half_width_m: 0.0,
                max_pressure_pa: 0.0,
            };
        }
        let pi = core::f32::consts::PI;
        Self {
            half_width_m: sqrt(8.0 * w * r / (pi * e)),
            max_pressure_pa: sqrt(w * e / (2.0 * pi * r)),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_width_and_pressure_satisfy_the_load_balance() {
        // Independent check: the Hertz ellipse p = p_h √(1 − (x/b)²) integrates to w = π b p_h/2.
        let w = 1.2e5f32;
        let c = HertzLineContact::new(w, 3.0e-3, 230.8e9);
        let integral = core::f32::consts::PI * c.half_width_m * c.max_pressure_pa / 2.0;
        assert!((integral / w - 1.0).abs() < 1e-5);
    }

    #[test]
    fn known_value() {
        // w = 100 kN/m, R = 5 mm, E' = 230.8 GPa: b = √(8·1e5·5e-3/(π·2.308e11)) = 74.27 µm,
        // p_h = √(1e5·2.308e11/(2π·5e-3)) = 857.1 MPa (computed by hand from §1).
        let c = HertzLineContact::new(1.0e5, 5.0e-3, 2.308e11);
        assert!(
            (c.half_width_m / 74.27e-6 - 1.0).abs() < 1e-3,
            "{}",
            c.half_width_m
        );
        assert!(
            (c.max_pressure_pa / 857.1e6 - 1.0).abs() < 1e-3,
            "{}",
            c.max_pressure_pa
        );
    }

    #[test]
    fn hostile_inputs_give_zero() {
        let c = HertzLineContact::new(f32::NAN, 1e-3, 2e11);
        assert_eq!(c.half_width_m, 0.0);
        let c = HertzLineContact::new(1e5, -1.0, 2e11);
        assert_eq!(c.max_pressure_pa, 0.0);
    }
}
