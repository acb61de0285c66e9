//! Regression ("analytical") film formulas for line contacts (docs/physics.md §5.1).
//!
//! * Dowson–Toyoda central film: h_c/R = 3.06·G^0.56·U^0.69·W^−0.10
//!   (Dowson & Toyoda 1979; Hamrock, *Fundamentals of Fluid Film Lubrication*, eq. 21.59).
//! * Dowson–Higginson minimum film: h_min/R = 2.65·G^0.54·U^0.70·W^−0.13
//!   (Dowson & Higginson 1966; Hamrock eq. 21.58).
//! * Moes' combined formula for the central film over all four regimes (Barus, incompressible).
//!
//! They are evaluated in logarithms of the dimensionless groups, at a fixed cost.
//!
//! **The [`Regression`] film model** is the complete film of a contact, as every film model's
//! is (see `FilmModel`): the EHL formulas above hold only where the contact is elastic and
//! piezoviscous, so each is blended root-sum-square with Martin's rigid iso-viscous film
//! (`hydrodynamic`), h = √(h_DT² + h_RI²) and h_min = √(h_DH² + h_0,RI²). At the loads of an
//! EHL contact (M ≳ 10) the blend changes h_DT by < 0.5 %; as the load vanishes it tends to
//! Martin's film, so a separating roller keeps a finite film and a continuous load.

use super::groups::LnGroups;
use super::hydrodynamic::martin_film_m;
use super::{ContactInput, Film, FilmModel, FilmSource, ServedLoads};
use crate::math::{exp, pow, select, sqrt};

/// Exponent of W in the Dowson–Toyoda central film: h_c ∝ Q^−0.10.
pub const CENTRAL_LOAD_EXPONENT: f32 = -0.10;
/// Exponent of W in the Dowson–Higginson minimum film: h_min ∝ Q^−0.13.
pub const MINIMUM_LOAD_EXPONENT: f32 = -0.13;

/// ln 3.06 and ln 2.65, the formulas' constants.
const LN_3_06: f32 = 1.118_414_9;
const LN_2_65: f32 = 0.974_559_6;

/// Dowson–Toyoda central film h_c (m) from the groups and R (m).
pub fn dowson_toyoda_central_m(g: &LnGroups, reduced_radius_m: f32) -> f32 {
    reduced_radius_m * exp(LN_3_06 + 0.56 * g.ln_g + 0.69 * g.ln_u + CENTRAL_LOAD_EXPONENT * g.ln_w)
}

/// Dowson–Higginson minimum film h_min (m) from the groups and R (m).
pub fn dowson_higginson_minimum_m(g: &LnGroups, reduced_radius_m: f32) -> f32 {
    reduced_radius_m * exp(LN_2_65 + 0.54 * g.ln_g + 0.70 * g.ln_u + MINIMUM_LOAD_EXPONENT * g.ln_w)
}

/// Moes' central film H_c = (h_c/R)(2U)^−1/2 for Moes parameters M, L (Barus, incompressible),
/// docs/physics.md §5.1 (Moes 1992; Venner & Lubrecht, *Multilevel Methods in Lubrication*, 2000,
/// eq. 8.2): H_c = [(H_RI^(7/3) + H_EI^(7/3))^(3s/7) + (H_RP^(−7/2) + H_EP^(−7/2))^(−2s/7)]^(1/s).
pub fn moes_central(m: f32, l: f32) -> f32 {
    let h_ri = 3.0 / m;
    let h_ei = 2.621 * pow(m, -0.2);
    let h_rp = 1.287 * pow(l, 2.0 / 3.0);
    let h_ep = 1.311 * pow(m, -0.125) * pow(l, 0.75);
    let s = 1.5 * (1.0 + exp(-1.2 * h_ei / h_ri));
    let iso = pow(pow(h_ri, 7.0 / 3.0) + pow(h_ei, 7.0 / 3.0), 3.0 * s / 7.0);
    let piezo = pow(pow(h_rp, -3.5) + pow(h_ep, -3.5), -2.0 * s / 7.0);
    pow(iso + piezo, 1.0 / s)
}

/// The regression film model: Dowson–Toyoda central, Dowson–Higginson minimum.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Regression;

impl FilmModel for Regression {
    fn name(&self) -> &'static str {
        "regression"
    }

    fn served_loads(&self, _template: &ContactInput) -> ServedLoads {
        // The formula serves every load; `film` returns zero for an invalid contact.
        ServedLoads::everywhere(FilmSource::Regression)
    }

    fn film(&self, contact: &ContactInput) -> Film {
        let g = LnGroups::new(contact);
        let r = contact.reduced_radius_m;
        let (central, minimum) = (
            dowson_toyoda_central_m(&g, r),
            dowson_higginson_minimum_m(&g, r),
        );
        let martin = martin_film_m(contact);
        let film = Film {
            central_m: sqrt(central * central + martin * martin),
            minimum_m: sqrt(minimum * minimum + martin * martin),
            source: FilmSource::Regression,
        };
        let ok = contact.is_valid() & film.central_m.is_finite() & film.minimum_m.is_finite();
        Film {
            central_m: select(ok, film.central_m, 0.0),
            minimum_m: select(ok, film.minimum_m, 0.0),
            source: if ok {
                FilmSource::Regression
            } else {
                FilmSource::None
            },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn contact() -> ContactInput {
        ContactInput {
            load_n: 1500.0,
            length_m: 0.015,
            entrainment_speed_m_s: 10.0,
            reduced_radius_m: 3.5e-3,
            reduced_modulus_pa: 230.77e9,
            pressure_viscosity_pa_inv: 2.1e-8,
            viscosity_pa_s: 0.08,
        }
    }

    #[test]
    fn regression_matches_the_formulas_in_f64() {
        let c = contact();
        let (w, u, g) = (
            c.load_n as f64
                / (c.length_m as f64 * c.reduced_modulus_pa as f64 * c.reduced_radius_m as f64),
            c.viscosity_pa_s as f64 * c.entrainment_speed_m_s as f64
                / (c.reduced_modulus_pa as f64 * c.reduced_radius_m as f64),
            c.pressure_viscosity_pa_inv as f64 * c.reduced_modulus_pa as f64,
        );
        let r = c.reduced_radius_m as f64;
        let dt = 3.06 * g.powf(0.56) * u.powf(0.69) * w.powf(-0.10) * r;
        let dh = 2.65 * g.powf(0.54) * u.powf(0.70) * w.powf(-0.13) * r;
        // Blended with Martin's h₀/R = 4.896U/W, the central and minimum gap alike.
        let hc = dt.hypot(4.896 * u / w * r);
        let hm = dh.hypot(4.896 * u / w * r);
        // At this load (M ≈ 18) the blend is a small correction.
        assert!(hc / dt - 1.0 < 0.01 && hm / dh - 1.0 < 0.01);
        let f = Regression.film(&c);
        assert!(
            (f.central_m as f64 / hc - 1.0).abs() < 1e-5,
            "{} vs {hc}",
            f.central_m
        );
        assert!((f.minimum_m as f64 / hm - 1.0).abs() < 1e-5);
        assert_eq!(f.source, FilmSource::Regression);
        // A sanity figure: sub-micron film, minimum below central.
        assert!(f.central_m > 1e-7 && f.central_m < 2e-6 && f.minimum_m < f.central_m);
    }

    #[test]
    fn moes_reaches_its_asymptotes() {
        // Rigid iso-viscous (small M, L → 0): H → 3/M; elastic piezo-viscous (large M, L):
        // H → 1.311 M^−1/8 L^3/4.
        let m = 0.01f32;
        assert!((moes_central(m, 1e-3) / (3.0 / m) - 1.0).abs() < 0.01);
        let (m, l) = (5000.0f32, 20.0f32);
        let ep = 1.311 * m.powf(-0.125) * l.powf(0.75);
        assert!(
            (moes_central(m, l) / ep - 1.0).abs() < 0.05,
            "{} vs {ep}",
            moes_central(m, l)
        );
    }

    #[test]
    fn regression_tends_to_martin_as_the_load_vanishes() {
        let mut c = contact();
        c.load_n = 0.05;
        let (u, w) = (
            c.viscosity_pa_s as f64 * c.entrainment_speed_m_s as f64
                / (c.reduced_modulus_pa as f64 * c.reduced_radius_m as f64),
            c.load_n as f64
                / (c.length_m as f64 * c.reduced_modulus_pa as f64 * c.reduced_radius_m as f64),
        );
        let martin = 4.896 * u / w * c.reduced_radius_m as f64;
        let f = Regression.film(&c);
        assert!(
            (f.central_m as f64 / martin - 1.0).abs() < 1e-3,
            "{} vs {martin}",
            f.central_m
        );
        assert!((f.minimum_m as f64 / martin - 1.0).abs() < 1e-3);
    }

    #[test]
    fn hostile_contacts_give_zero_film() {
        let mut c = contact();
        c.load_n = f32::NAN;
        assert_eq!(Regression.film(&c), Film::ZERO);
        let mut c = contact();
        c.entrainment_speed_m_s = -1.0;
        assert_eq!(Regression.film(&c), Film::ZERO);
    }
}
