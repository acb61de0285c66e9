//! Published film-thickness formulas the solver is checked against (and starts from).
//!
//! Sources and the verification status of their constants:
//! - Moes (1992), line contact, Barus + incompressible, as given in Venner & Lubrecht,
//!   *Multilevel Methods in Lubrication* (Elsevier 2000), eq. for H_c(M, L) with
//!   H = (h/R)(2U)^−½, M = W(2U)^−½, L = G(2U)^¼:
//!   H_c = [(H_RI^{7/3} + H_EI^{7/3})^{3s/7} + (H_RP^{−7/2} + H_EP^{−7/2})^{−2s/7}]^{1/s},
//!   H_RI = 3M⁻¹, H_EI = 2.621M^−⅕, H_RP = 1.287L^⅔, H_EP = 1.311M^−⅛L^¾,
//!   s = 1.5(1 + exp(−1.2 H_EI/H_RI)). The PHYSICS.md constants agree with the tribonet.org
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
//!   of PHYSICS.md §5.1 cross-checked against Hamrock's book as recalled, so they remain "as
//!   cited"; the agreement test (12 of 16 corners within 10 % for h_c, 15 of 16 for h_min) is
//!   the evidence of how far they match the Roelands + DH model.
//! - Martin (1916), rigid iso-viscous cylinder with the Reynolds exit condition:
//!   w = 4.896 η₀u_mR/h₀, i.e. h₀/R = 4.896 U/W (PHYSICS.md §5.1).
//! - Dowson–Toyoda central / Dowson–Higginson minimum (PHYSICS.md §5.1), for comparison tables.

use super::ContactCase;

/// Moes central film H_c = (h_c/R)(2U)^−½ as a function of M and L.
pub fn moes_central_dimensionless(m: f64, l: f64) -> f64 {
    let h_ri = 3.0 / m;
    let h_ei = 2.621 * m.powf(-0.2);
    let h_rp = 1.287 * l.powf(2.0 / 3.0);
    let h_ep = 1.311 * m.powf(-0.125) * l.powf(0.75);
    let s = 1.5 * (1.0 + (-1.2 * h_ei / h_ri).exp());
    let iso = (h_ri.powf(7.0 / 3.0) + h_ei.powf(7.0 / 3.0)).powf(3.0 * s / 7.0);
    let piezo = if l > 0.0 {
        (h_rp.powf(-3.5) + h_ep.powf(-3.5)).powf(-2.0 * s / 7.0)
    } else {
        0.0
    };
    (iso + piezo).powf(1.0 / s)
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
    3.06 * g.powf(0.56) * u.powf(0.69) * w.powf(-0.10) * case.reduced_radius_m
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
}
