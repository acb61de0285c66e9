//! The regression films the network falls back to outside its domain, and which its
//! [`TargetForm::LogRatio`](super::TargetForm::LogRatio) output corrects inside it — written in
//! logarithms so they cost a few multiply-adds on the logarithms the guard already has:
//!
//! - Dowson–Toyoda central: `ln(h_c/R) = ln 3.06 + 0.56 ln G + 0.69 ln U − 0.10 ln W`;
//! - Dowson–Higginson minimum: `ln(h_min/R) = ln 2.65 + 0.54 ln G + 0.70 ln U − 0.13 ln W`
//!
//! (docs/physics.md §5.1). The lead's `film::regression` module was not on `main` when this was
//! written; this private copy is meant to be replaced by it.

/// `ln(h_c/R)` by Dowson–Toyoda.
#[inline]
pub fn ln_central_over_r(ln_w: f32, ln_u: f32, ln_g: f32) -> f32 {
    1.118_415 + 0.56 * ln_g + 0.69 * ln_u - 0.10 * ln_w // ln 3.06 = 1.1184149
}

/// `ln(h_min/R)` by Dowson–Higginson.
#[inline]
pub fn ln_minimum_over_r(ln_w: f32, ln_u: f32, ln_g: f32) -> f32 {
    0.974_559_9 + 0.54 * ln_g + 0.70 * ln_u - 0.13 * ln_w // ln 2.65 = 0.9745596
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Against the power form evaluated with libm::powf (an independent evaluation):
    /// G = 4847, U = 1.1e-10, W = 4e-5 (a §6.1-like contact).
    #[test]
    fn matches_power_form() {
        let (w, u, g) = (4e-5f32, 1.1e-10f32, 4847.0f32);
        let dt = 3.06 * libm::powf(g, 0.56) * libm::powf(u, 0.69) * libm::powf(w, -0.10);
        let dh = 2.65 * libm::powf(g, 0.54) * libm::powf(u, 0.70) * libm::powf(w, -0.13);
        let (lw, lu, lg) = (libm::logf(w), libm::logf(u), libm::logf(g));
        assert!((libm::expf(ln_central_over_r(lw, lu, lg)) / dt - 1.0).abs() < 1e-5);
        assert!((libm::expf(ln_minimum_over_r(lw, lu, lg)) / dh - 1.0).abs() < 1e-5);
    }
}
