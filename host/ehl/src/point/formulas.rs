//! Published point-contact film formulas the solver is compared with (and starts from).
//!
//! - Hamrock & Dowson (1977), *Isothermal elastohydrodynamic lubrication of point contacts,
//!   part III — fully flooded results*, ASME J. Lubr. Technol. 99:264, fitted to their
//!   numerical solutions (Barus viscosity, Dowson–Higginson density, k from 1 to 8, moderate
//!   loads; reproduced in Hamrock, *Fundamentals of Fluid Film Lubrication*, 1994, ch. 22):
//!   h_c/R_x = 2.69 U^0.67 G^0.53 W^−0.067 (1 − 0.61 e^−0.73k),
//!   h_min/R_x = 3.63 U^0.68 G^0.49 W^−0.073 (1 − e^−0.68k),
//!   with U, W, G of [`super::PointContactCase`] (U on the mean speed).
//! - Nijenbanning, Venner & Moes (1994), *Film thickness in elastohydrodynamically lubricated
//!   elliptic contacts*, Wear 176:217, central film from four asymptotes fitted to multigrid
//!   solutions (Barus, incompressible), D = R_x/R_y, H = (h_c/R_x)(2U)^−½:
//!   H_RI = 145(1 + 0.796 D^{14/15})^{−15/7} D^−1 M^−2,
//!   H_EI = 3.18(1 + 0.006 ln D + 0.63 D^{4/7})^{−14/25} D^{−1/15} M^{−2/15},
//!   H_RP = 1.29(1 + 0.691 D)^{−2/3} L^{2/3},
//!   H_EP = 1.48(1 + 0.006 ln D + 0.63 D^{4/7})^{−7/20} D^{−1/24} M^{−1/12} L^{3/4},
//!   H = [(H_RI^{3/2} + H_EI^{3/2})^{2s/3} + (H_RP^{−8} + H_EP^{−8})^{−s/8}]^{1/s},
//!   s = 1.5(1 + e^{−1.2 H_EI/H_RI}). The constants are those reproduced in Venner & Lubrecht,
//!   *Multilevel Methods in Lubrication* (2000), and agree with a public implementation found
//!   with the search tool; the paper's own text was not available. The blend is written in
//!   Moes' line-contact form (each bracket raised to the power that makes the sum homogeneous
//!   of degree s, crate::formulas).
//! - Brewe, Hamrock & Taylor (1979), *Effect of geometry on hydrodynamic film thickness*, ASME
//!   J. Lubr. Technol. 101:231: rigid, iso-viscous, Reynolds exit condition,
//!   h_min/R_x = 128 α_r φ² [0.131 atan(α_r/2) + 1.683]² (U/W)², α_r = R_y/R_x,
//!   φ = (1 + 2/(3α_r))^−1 (as reproduced in Hamrock 1994, ch. 15); E′ cancels in U/W. The
//!   solver, rigid and iso-viscous, meets it within ≈ 1 % once its domain's truncation is
//!   extrapolated out (test `rigid_isoviscous_film_meets_brewe_hamrock_taylor`,
//!   docs/point_contact.md).

use super::PointContactCase;

fn groups(case: &PointContactCase) -> (f64, f64, f64, f64) {
    (
        case.load_parameter(),
        case.speed_parameter(),
        case.material_parameter(),
        case.hertz().ellipticity,
    )
}

/// Hamrock–Dowson central film thickness, m.
pub fn hamrock_dowson_central_film_m(case: &PointContactCase) -> f64 {
    let (w, u, g, k) = groups(case);
    2.69 * u.powf(0.67)
        * g.powf(0.53)
        * w.powf(-0.067)
        * (1.0 - 0.61 * (-0.73 * k).exp())
        * case.radius_x_m
}

/// Hamrock–Dowson minimum film thickness, m.
pub fn hamrock_dowson_min_film_m(case: &PointContactCase) -> f64 {
    let (w, u, g, k) = groups(case);
    3.63 * u.powf(0.68)
        * g.powf(0.49)
        * w.powf(-0.073)
        * (1.0 - (-0.68 * k).exp())
        * case.radius_x_m
}

/// Nijenbanning–Venner–Moes central film H = (h_c/R_x)(2U)^−½ from M, L and D = R_x/R_y.
pub fn nijenbanning_central_dimensionless(m: f64, l: f64, d: f64) -> f64 {
    let ln_d = d.ln();
    let shape = 1.0 + 0.006 * ln_d + 0.63 * d.powf(4.0 / 7.0);
    let rigid_iso = 145.0 * (1.0 + 0.796 * d.powf(14.0 / 15.0)).powf(-15.0 / 7.0) / d / (m * m);
    let elastic_iso = 3.18 * shape.powf(-14.0 / 25.0) * d.powf(-1.0 / 15.0) * m.powf(-2.0 / 15.0);
    let rigid_piezo = 1.29 * (1.0 + 0.691 * d).powf(-2.0 / 3.0) * l.powf(2.0 / 3.0);
    let elastic_piezo =
        1.48 * shape.powf(-7.0 / 20.0) * d.powf(-1.0 / 24.0) * m.powf(-1.0 / 12.0) * l.powf(0.75);
    let s = 1.5 * (1.0 + (-1.2 * elastic_iso / rigid_iso).exp());
    let iso = (rigid_iso.powf(1.5) + elastic_iso.powf(1.5)).powf(2.0 * s / 3.0);
    let piezo = if rigid_piezo > 0.0 {
        (rigid_piezo.powf(-8.0) + elastic_piezo.powf(-8.0)).powf(-s / 8.0)
    } else {
        0.0
    };
    (iso + piezo).powf(1.0 / s)
}

/// Nijenbanning–Venner–Moes central film thickness, m.
pub fn nijenbanning_central_film_m(case: &PointContactCase) -> f64 {
    let two_u = 2.0 * case.speed_parameter();
    let d = case.radius_x_m / case.radius_y_m;
    nijenbanning_central_dimensionless(case.moes_m(), case.moes_l(), d)
        * two_u.sqrt()
        * case.radius_x_m
}

/// Brewe–Hamrock–Taylor rigid iso-viscous minimum film, m.
pub fn brewe_hamrock_taylor_min_film_m(case: &PointContactCase) -> f64 {
    let (w, u, _, _) = groups(case);
    let ar = case.radius_y_m / case.radius_x_m;
    let phi = 1.0 / (1.0 + 2.0 / (3.0 * ar));
    let c = 0.131 * (ar / 2.0).atan() + 1.683;
    128.0 * ar * phi * phi * c * c * (u / w).powi(2) * case.radius_x_m
}
