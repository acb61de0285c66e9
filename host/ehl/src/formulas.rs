//! Published film-thickness formulas the solver is checked against (and starts from).
//!
//! Sources and the verification status of their constants:
//! - Moes (1992), line contact, Barus + incompressible, as given in Venner & Lubrecht,
//!   *Multilevel Methods in Lubrication* (Elsevier 2000), eq. for H_c(M, L) with
//!   H = (h/R)(2U)^−½, M = W(2U)^−½, L = G(2U)^¼:
//!   H_c = [(H_RI^{7/3} + H_EI^{7/3})^{3s/7} + (H_RP^{−7/2} + H_EP^{−7/2})^{−2s/7}]^{1/s},
//!   H_RI = 3M⁻¹, H_EI = 2.621M^−⅕, H_RP = 1.287L^⅔, H_EP = 1.311M^−⅛L^¾,
//!   s = 1.5(1 + exp(−1.2 H_EI/H_RI)). The docs/physics.md constants agree with the tribonet.org
//!   line-contact calculator page (which cites Moes) found with the search tool, as far as
//!   that page rendered. Note that the rigid iso-viscous asymptote 3/M is 22 % above Martin's
//!   4.896 U/W (= 2.448/M in these units); the formula is an interpolation meant for the
//!   elastic regimes, and it is only compared with the solver for M ≥ 10.
//! - Pan & Hamrock (1989), *Simple formulas for performance parameters used in
//!   elastohydrodynamically lubricated line contacts*, ASME J. Tribol. 111:246–251, fitted to
//!   Roelands + Dowson–Higginson numerical solutions:
//!   h_min/R = 1.714 W^−0.128 U^0.694 G^0.568, h_c/R = 2.922 W^−0.166 U^0.692 G^0.470
//!   (U on the mean speed, as in Hamrock, *Fundamentals of Fluid Film Lubrication*, 1994,
//!   ch. 21, which reproduces them). Two searches of the stored corpora (last on 2026-11-21,
//!   log in docs/ehl.md) returned the paper only as reference-list entries: not its text, its
//!   fitted W, U, G range, nor its lubricant (η₀, Roelands Z) constants. The constants are those
//!   of docs/physics.md §5.1 cross-checked against Hamrock's book as recalled, so they remain "as
//!   cited"; the agreement test (12 of 16 corners within 10 % for h_c, 15 of 16 for h_min) is
//!   the evidence of how far they match the Roelands + DH model.
//! - Martin (1916), rigid iso-viscous cylinder with the Reynolds exit condition:
//!   w = 4.896 η₀u_mR/h₀, i.e. h₀/R = 4.896 U/W (docs/physics.md §5.1).
//! - Dowson–Toyoda central / Dowson–Higginson minimum (docs/physics.md §5.1), for comparison tables
//!   and as the regression formulas the film network is compared with.
//!
//! The group forms (`W`, `U`, `G` in, `h/R` out) serve the dataset and training pipeline;
//! the `_m` forms take a [`ContactCase`] and return metres.

use super::ContactCase;

/// Moes central film H_c = (h_c/R)(2U)^−½ as a function of M and L.
pub fn moes_central_dimensionless(m: f64, l: f64) -> f64 {
    MoesAsymptotes::new(m, l).central()
}

/// The four Moes asymptotes of the dimensionless central film `H = (h/R)(2U)^−1/2`, as functions
/// of the Moes parameters `M = W(2U)^−1/2`, `L = G(2U)^1/4` (Moes 1992, *Optimum similarity
/// analysis with applications to elastohydrodynamic lubrication*, Wear 159; docs/physics.md §5.1).
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

    /// Moes' interpolation of the four asymptotes (docs/physics.md §5.1):
    /// `H = [(H_RI^{7/3} + H_EI^{7/3})^{3s/7} + (H_RP^{−7/2} + H_EP^{−7/2})^{−2s/7}]^{1/s}`,
    /// `s = 1.5 (1 + exp(−1.2 H_EI/H_RI))`. Without pressure–viscosity (L = 0, so H_RP = 0) the
    /// piezoviscous term is zero.
    pub fn central(&self) -> f64 {
        let s = 1.5 * (1.0 + (-1.2 * self.elastic_isoviscous / self.rigid_isoviscous).exp());
        let iso = (self.rigid_isoviscous.powf(7.0 / 3.0) + self.elastic_isoviscous.powf(7.0 / 3.0))
            .powf(3.0 * s / 7.0);
        let piezo = if self.rigid_piezoviscous > 0.0 {
            (self.rigid_piezoviscous.powf(-3.5) + self.elastic_piezoviscous.powf(-3.5))
                .powf(-2.0 * s / 7.0)
        } else {
            0.0
        };
        (iso + piezo).powf(1.0 / s)
    }
}

/// Moes parameters `(M, L)` from `(W, U, G)`: `M = W(2U)^−1/2`, `L = G(2U)^1/4` (docs/physics.md §1).
pub fn moes_parameters(w: f64, u: f64, g: f64) -> (f64, f64) {
    let two_u = 2.0 * u;
    (w / two_u.sqrt(), g * two_u.powf(0.25))
}

/// Moes central film as `h_c/R = H (2U)^1/2` from the groups `W`, `U`, `G`.
pub fn moes_central(w: f64, u: f64, g: f64) -> f64 {
    let (m, l) = moes_parameters(w, u, g);
    MoesAsymptotes::new(m, l).central() * (2.0 * u).sqrt()
}

/// Dowson–Toyoda central film, `h_c/R = 3.06 G^0.56 U^0.69 W^−0.10` (Dowson & Toyoda 1979, as
/// quoted in Hamrock, *Fundamentals of Fluid Film Lubrication*, ch. 21).
pub fn dowson_toyoda_central(w: f64, u: f64, g: f64) -> f64 {
    3.06 * g.powf(0.56) * u.powf(0.69) * w.powf(-0.10)
}

/// Dowson–Higginson minimum film, `h_min/R = 2.65 G^0.54 U^0.70 W^−0.13` (Dowson & Higginson
/// 1966, *Elastohydrodynamic lubrication*, as in docs/physics.md §5.1).
pub fn dowson_higginson_minimum(w: f64, u: f64, g: f64) -> f64 {
    2.65 * g.powf(0.54) * u.powf(0.70) * w.powf(-0.13)
}

/// Moes central film thickness in m.
pub fn moes_central_film_m(case: &ContactCase) -> f64 {
    let two_u = 2.0 * case.speed_parameter();
    moes_central_dimensionless(case.moes_m(), case.moes_l()) * two_u.sqrt() * case.reduced_radius_m
}

/// Pan–Hamrock central film thickness in m.
pub fn pan_hamrock_central_film_m(case: &ContactCase) -> f64 {
    let (w, u, g) = groups(case);
    2.922 * w.powf(-0.166) * u.powf(0.692) * g.powf(0.470) * case.reduced_radius_m
}

/// Pan–Hamrock minimum film thickness in m.
pub fn pan_hamrock_min_film_m(case: &ContactCase) -> f64 {
    let (w, u, g) = groups(case);
    1.714 * w.powf(-0.128) * u.powf(0.694) * g.powf(0.568) * case.reduced_radius_m
}

/// Dowson–Toyoda central film thickness in m.
pub fn dowson_toyoda_central_film_m(case: &ContactCase) -> f64 {
    let (w, u, g) = groups(case);
    dowson_toyoda_central(w, u, g) * case.reduced_radius_m
}

/// Martin's rigid iso-viscous minimum gap h₀ = 4.896 η₀u_mR/w in m.
pub fn martin_gap_m(case: &ContactCase) -> f64 {
    4.896 * case.speed_parameter() / case.load_parameter() * case.reduced_radius_m
}

fn groups(case: &ContactCase) -> (f64, f64, f64) {
    (
        case.load_parameter(),
        case.speed_parameter(),
        case.material_parameter(),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The blend reduces to its asymptotes (Moes 1992 construction): 3/M at tiny M with L = 0,
    /// 2.621 M^−⅕ at large M with L = 0.
    #[test]
    fn moes_rigid_asymptote() {
        let m = 1e-3;
        assert!((moes_central_dimensionless(m, 0.0) * m / 3.0 - 1.0).abs() < 0.01);
        // Elastic iso-viscous asymptote at large M, L = 0.
        let m: f64 = 1e5;
        let he = 2.621 * m.powf(-0.2);
        assert!((moes_central_dimensionless(m, 0.0) / he - 1.0).abs() < 0.01);
    }

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
