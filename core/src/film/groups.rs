//! Dimensionless groups of a line contact (docs/physics.md §1), in logarithms.
//!
//! The film models work with ln W, ln U, ln G (and Moes' ln M, ln L), which turns every
//! power-law formula into a sum and keeps the cost fixed.

use super::ContactInput;
use crate::math::ln;

/// Logarithms of the dimensionless groups of one contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LnGroups {
    /// ln W, W = w/(E'R) = Q/(l E' R).
    pub ln_w: f32,
    /// ln U, U = η₀ u_m/(E' R).
    pub ln_u: f32,
    /// ln G, G = α E'.
    pub ln_g: f32,
}

impl LnGroups {
    /// Groups of `contact`. Inputs must be positive and finite (see [`ContactInput::is_valid`]);
    /// others give finite but meaningless values.
    pub fn new(contact: &ContactInput) -> Self {
        let er = contact.reduced_modulus_pa * contact.reduced_radius_m;
        Self {
            ln_w: ln(contact.load_n) - ln(contact.length_m * er),
            ln_u: ln(contact.viscosity_pa_s * contact.entrainment_speed_m_s) - ln(er),
            ln_g: ln(contact.pressure_viscosity_pa_inv * contact.reduced_modulus_pa),
        }
    }

    /// ln M, M = W·(2U)^(−1/2) (Moes).
    pub fn ln_m(&self) -> f32 {
        self.ln_w - 0.5 * (core::f32::consts::LN_2 + self.ln_u)
    }

    /// ln L, L = G·(2U)^(1/4) (Moes).
    pub fn ln_l(&self) -> f32 {
        self.ln_g + 0.25 * (core::f32::consts::LN_2 + self.ln_u)
    }
}

impl ContactInput {
    /// True when every field is finite and strictly positive (α may be zero: iso-viscous).
    pub fn is_valid(&self) -> bool {
        // `&`, not `&&`: every field is checked, so the work does not depend on the data.
        let positive = |v: f32| v.is_finite() & (v > 0.0);
        positive(self.load_n)
            & positive(self.length_m)
            & positive(self.entrainment_speed_m_s)
            & positive(self.reduced_radius_m)
            & positive(self.reduced_modulus_pa)
            & positive(self.viscosity_pa_s)
            & self.pressure_viscosity_pa_inv.is_finite()
            & (self.pressure_viscosity_pa_inv >= 0.0)
    }

    /// Load per unit length w = Q/l (N/m).
    pub fn load_per_length_n_per_m(&self) -> f32 {
        self.load_n / self.length_m
    }
}
