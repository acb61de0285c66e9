//! Greenwood–Tripp asperity contact: the Gaussian statistical integrals F₂ and F₅/₂, the
//! asperity load and the real contact area (docs/physics.md §8.2).
//!
//! For two rough surfaces with a Gaussian distribution of summit heights of composite standard
//! deviation σ, the asperity pressure and the real-area fraction at a separation h are
//! (Greenwood & Tripp, Proc. IMechE 185 (1970–71) 625–633; in the form of Gelinck & Schipper,
//! Tribol. Int. 33 (2000) 175–181)
//!
//! p_a = (8√2/15)·π·(η_s β σ)²·√(σ/β)·E′·F₅/₂(λ),  A_a/A_n = π²·(η_s β σ)²·F₂(λ),
//!
//! with λ = h/σ, E′ the reduced modulus of docs/physics.md §1 (twice Johnson's E*, hence 8√2
//! rather than Greenwood & Tripp's 16√2), η_s the summit density, β the summit radius and
//! F_n(λ) = ∫_λ^∞ (s − λ)ⁿ φ(s) ds for the standard normal density φ.

use crate::math::{exp, min, select};

/// ln F₂(λ) as a quartic in λ, least-squares fit to numerical quadrature of the Gaussian on
/// λ ∈ [0, 6] (601 points): |F_fit/F − 1| < 0.21 % there (test `gt_integrals_match_quadrature`).
const LN_F2: [f32; 5] = [
    -0.695_192_7,
    -1.585_754_8,
    -0.284_017_15,
    -0.021_066_184,
    0.000_953_746_5,
];
/// ln F₅/₂(λ), as [`LN_F2`]: |F_fit/F − 1| < 0.17 % on [0, 6].
const LN_F52: [f32; 5] = [
    -0.485_065,
    -1.735_834_1,
    -0.277_553_64,
    -0.020_625_53,
    0.000_899_317_6,
];

/// Largest λ of the fits: beyond it F₂, F₅/₂ < 5·10⁻¹¹ (of their 0.5, 0.62 at λ = 0) and the
/// functions return 0 (no asperity contact).
pub const LAMBDA_MAX: f32 = 6.0;

/// The fit `c` of ln F at λ (clamped to [0, [`LAMBDA_MAX`]]), 0 beyond it.
#[inline(always)]
fn integral(c: &[f32; 5], lambda: f32) -> f32 {
    let x = min(crate::math::max(lambda, 0.0), LAMBDA_MAX);
    let ln_f = c.iter().rev().fold(0.0, |acc, &k| acc * x + k);
    select(lambda < LAMBDA_MAX, exp(ln_f), 0.0)
}

/// F₂(λ), the Gaussian integral of the real contact area.
pub fn f2(lambda: f32) -> f32 {
    integral(&LN_F2, lambda)
}

/// F₅/₂(λ), the Gaussian integral of the asperity load.
pub fn f5_2(lambda: f32) -> f32 {
    integral(&LN_F52, lambda)
}

/// The roughness constants of a contact pair that do not depend on the film.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Roughness {
    /// (8√2/15)·π·(η_s β σ)²·√(σ/β): asperity pressure per E′·F₅/₂.
    pub load_factor: f32,
    /// π²·(η_s β σ)²: real-area fraction per F₂.
    pub area_factor: f32,
}

impl Roughness {
    /// From σ (m), summit density η_s (1/m²) and summit radius β (m).
    pub(crate) fn new(sigma_m: f32, density_m2: f32, summit_radius_m: f32) -> Self {
        let nbs = density_m2 * summit_radius_m * sigma_m;
        let nbs2 = nbs * nbs;
        let pi = core::f32::consts::PI;
        Self {
            load_factor: (8.0 * core::f32::consts::SQRT_2 / 15.0)
                * pi
                * nbs2
                * crate::math::sqrt(sigma_m / summit_radius_m),
            area_factor: pi * pi * nbs2,
        }
    }

    /// Asperity load W_a (N) and real contact area A_a (m²) over the nominal (Hertz) area
    /// `nominal_area_m2` at film ratio λ, reduced modulus E′; A_a is at most the nominal area.
    pub(crate) fn contact(&self, lambda: f32, modulus_pa: f32, nominal_area_m2: f32) -> (f32, f32) {
        let load = self.load_factor * modulus_pa * nominal_area_m2 * f5_2(lambda);
        let area = min(self.area_factor * f2(lambda), 1.0) * nominal_area_m2;
        (load, area)
    }
}
