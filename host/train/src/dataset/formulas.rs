//! Closed-form line-contact film formulas in f64 (PHYSICS.md §5.1): the regression formulas
//! the network is compared with (Dowson–Toyoda central, Dowson–Higginson minimum) and the
//! Moes formula, the documented stand-in target used to test the pipeline before the numerical
//! solver lands.
//!
//! All take the dimensionless groups of PHYSICS.md §1 (`W = w/(E'R)`, `U = η₀u_m/(E'R)`,
//! `G = αE'`) and return `h/R`.

/// Dowson–Toyoda central film, `h_c/R = 3.06 G^0.56 U^0.69 W^−0.10`
/// (Dowson & Toyoda 1979, as quoted in Hamrock, *Fundamentals of Fluid Film Lubrication*, ch. 21).
pub fn dowson_toyoda_central(w: f64, u: f64, g: f64) -> f64 {
    3.06 * g.powf(0.56) * u.powf(0.69) * w.powf(-0.10)
}

/// Dowson–Higginson minimum film, `h_min/R = 2.65 G^0.54 U^0.70 W^−0.13`
/// (Dowson & Higginson 1966, *Elastohydrodynamic lubrication*, as in PHYSICS.md §5.1).
pub fn dowson_higginson_minimum(w: f64, u: f64, g: f64) -> f64 {
    2.65 * g.powf(0.54) * u.powf(0.70) * w.powf(-0.13)
}

/// The four Moes asymptotes of the dimensionless central film `H = (h/R)(2U)^−1/2`, as functions
/// of the Moes parameters `M = W(2U)^−1/2`, `L = G(2U)^1/4` (Moes 1992, *Optimum similarity analysis
/// with applications to elastohydrodynamic lubrication*, Wear 159; PHYSICS.md §5.1).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MoesAsymptotes {
    /// Rigid–isoviscous (Martin): `H_RI = 3/M`.
    pub rigid_isoviscous: f64,
    /// Elastic–isoviscous: `H_EI = 2.621 M^−1/5`.
    pub elastic_isoviscous: f64,
    /// Rigid–piezoviscous: `H_RP = 1.287 L^2/3`.
    pub rigid_piezoviscous: f64,
    /// Elastic–piezoviscous: `H_EP = 1.311 M^−1/8 L^3/4`.
    pub elastic_piezoviscous: f64,
}

impl MoesAsymptotes {
    /// Asymptotes at Moes parameters `M`, `L`.
    pub fn new(m: f64, l: f64) -> Self {
        Self {
            rigid_isoviscous: 3.0 / m,
            elastic_isoviscous: 2.621 * m.powf(-0.2),
            rigid_piezoviscous: 1.287 * l.powf(2.0 / 3.0),
            elastic_piezoviscous: 1.311 * m.powf(-0.125) * l.powf(0.75),
        }
    }

    /// Moes' interpolation of the four asymptotes (PHYSICS.md §5.1):
    /// `H = [(H_RI^{7/3} + H_EI^{7/3})^{3s/7} + (H_RP^{−7/2} + H_EP^{−7/2})^{−2s/7}]^{1/s}`,
    /// `s = 1.5 (1 + exp(−1.2 H_EI/H_RI))`.
    pub fn central(&self) -> f64 {
        let s = 1.5 * (1.0 + (-1.2 * self.elastic_isoviscous / self.rigid_isoviscous).exp());
        let iso = (self.rigid_isoviscous.powf(7.0 / 3.0) + self.elastic_isoviscous.powf(7.0 / 3.0))
            .powf(3.0 * s / 7.0);
        let piezo = (self.rigid_piezoviscous.powf(-3.5) + self.elastic_piezoviscous.powf(-3.5))
            .powf(-2.0 * s / 7.0);
        (iso + piezo).powf(1.0 / s)
    }
}

/// Moes parameters `(M, L)` from `(W, U, G)`: `M = W(2U)^−1/2`, `L = G(2U)^1/4` (PHYSICS.md §1).
pub fn moes_parameters(w: f64, u: f64, g: f64) -> (f64, f64) {
    let two_u = 2.0 * u;
    (w / two_u.sqrt(), g * two_u.powf(0.25))
}

/// Moes central film as `h_c/R = H (2U)^1/2`.
pub fn moes_central(w: f64, u: f64, g: f64) -> f64 {
    let (m, l) = moes_parameters(w, u, g);
    MoesAsymptotes::new(m, l).central() * (2.0 * u).sqrt()
}

/// Minimum film of the Moes stand-in: the Moes central film scaled by the ratio of the
/// Dowson–Higginson minimum to the Dowson–Toyoda central film. Moes gives no minimum-film
/// formula; this keeps the stand-in smooth, positive and different from both regression
/// formulas, which is all a pipeline test needs. It is not a physical claim.
pub fn moes_minimum(w: f64, u: f64, g: f64) -> f64 {
    moes_central(w, u, g) * dowson_higginson_minimum(w, u, g) / dowson_toyoda_central(w, u, g)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Moes' formula must approach each asymptote far inside its regime (the construction
    /// property of Moes 1992): elastic–piezoviscous at large M and L, rigid–isoviscous at small M, L.
    #[test]
    fn moes_tends_to_its_asymptotes() {
        let ep = MoesAsymptotes::new(1.0e4, 20.0);
        assert!((ep.central() / ep.elastic_piezoviscous - 1.0).abs() < 0.02);
        let ri = MoesAsymptotes::new(1.0e-3, 0.01);
        assert!((ri.central() / ri.rigid_isoviscous - 1.0).abs() < 0.01);
    }

    /// Hand-evaluated Dowson–Toyoda value: G = 5000, U = 1e-11, W = 1e-4 gives
    /// 3.06 · 5000^0.56 · 1e-11^0.69 · 1e-4^−0.1 (evaluated with exp/ln by hand here).
    #[test]
    fn dowson_toyoda_matches_hand_value() {
        let expected =
            (3.06f64.ln() + 0.56 * 5000f64.ln() + 0.69 * 1e-11f64.ln() - 0.10 * 1e-4f64.ln()).exp();
        let got = dowson_toyoda_central(1e-4, 1e-11, 5000.0);
        assert!((got / expected - 1.0).abs() < 1e-12);
        // Order of magnitude of a typical roller contact: h/R ~ 1e-4 … 1e-5.
        assert!(got > 1e-6 && got < 1e-3, "{got}");
    }
}
