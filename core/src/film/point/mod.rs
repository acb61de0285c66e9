//! The ball–race point contact: its input, its dimensionless groups and Hamrock–Dowson's film
//! formulas in f32 ([`HamrockDowson`], the regression model and the point network's fallback).
//! The network is `film::ann::point`.
//!
//! Conventions as the host's point-contact solver (`bearing_ehl::point`, docs/point_contact.md):
//! x is the rolling direction, R_x and R_y the reduced radii of curvature along and across it
//! (R_y ≥ R_x: the contact ellipse is long across the rolling direction, as in a ball
//! bearing's grooves), E' the reduced modulus of docs/physics.md §1, and
//!
//!   W = w/(E'R_x²), U = η₀u_m/(E'R_x), G = αE', M = W(2U)^−¾, L = G(2U)^¼
//!
//! (Moes' point-contact groups, Nijenbanning, Venner & Moes 1994). Hamrock & Dowson (1977,
//! *Isothermal elastohydrodynamic lubrication of point contacts, part III*, ASME J. Lubr.
//! Technol. 99:264; Hamrock 1994, *Fundamentals of Fluid Film Lubrication*, ch. 22):
//!
//!   h_c/R_x = 2.69 U^0.67 G^0.53 W^−0.067 (1 − 0.61 e^−0.73k),
//!   h_min/R_x = 3.63 U^0.68 G^0.49 W^−0.073 (1 − e^−0.68k),
//!
//! with the exact Hertz ellipticity k of [`hertz`]. Every film here is computed in logarithms
//! (`math::series`), at the same cost for every input.

pub mod hertz;

use super::{Film, FilmContact, FilmModel, FilmSource, ServedLoads};
use crate::math::series::{exp_taylor, ln_atanh};

/// Everything the isothermal point-contact film depends on: one ball–race contact. A
/// ball-bearing model knows each contact's load and speed per step, and its radii of curvature
/// from the ball, the groove and the contact angle; the ellipticity follows from the radii
/// ([`hertz::ellipse_shape`]), as it does on the host.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointContactInput {
    /// Contact load, w (N).
    pub load_n: f32,
    /// Entrainment (mean rolling) speed, u_m (m/s).
    pub entrainment_speed_m_s: f32,
    /// Reduced radius of curvature in the rolling direction, R_x (m).
    pub radius_x_m: f32,
    /// Reduced radius of curvature across the rolling direction, R_y ≥ R_x (m).
    pub radius_y_m: f32,
    /// Reduced modulus, E' (Pa).
    pub reduced_modulus_pa: f32,
    /// Pressure–viscosity coefficient, α (1/Pa).
    pub pressure_viscosity_pa_inv: f32,
    /// Dynamic viscosity at ambient pressure, η₀ (Pa·s).
    pub viscosity_pa_s: f32,
}

impl FilmContact for PointContactInput {
    #[inline]
    fn with_load_n(&self, load_n: f32) -> Self {
        Self { load_n, ..*self }
    }
}

impl PointContactInput {
    /// The seven inputs in the order of the point network's domain box (`PointDomainLimits`),
    /// with R_y as the ratio R_y/R_x: w, u_m, R_x, R_y/R_x, E', α, η₀.
    #[inline]
    pub fn box_values(&self) -> [f32; 7] {
        [
            self.load_n,
            self.entrainment_speed_m_s,
            self.radius_x_m,
            self.radius_y_m / self.radius_x_m,
            self.reduced_modulus_pa,
            self.pressure_viscosity_pa_inv,
            self.viscosity_pa_s,
        ]
    }
}

const LN_2: f32 = core::f32::consts::LN_2;
/// ln(3/(2π)).
const LN_3_OVER_2PI: f32 = -0.739_264_8;
/// ln(6/π).
const LN_6_OVER_PI: f32 = 0.647_029_3;
/// ln 2.69, ln 3.63 (Hamrock–Dowson's constants).
const LN_2_69: f32 = 0.989_541_2;
const LN_3_63: f32 = 1.289_232_6;

/// The logarithms of a point contact's groups, its Hertz pressure and its Hamrock–Dowson films
/// (the point network's features, guard and fallback are built from these).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointGroups {
    /// Every input finite and > 0.
    pub valid: bool,
    /// ln R_x (ln m).
    pub ln_radius_x: f32,
    /// Ellipticity and E of the Hertz ellipse.
    pub shape: hertz::EllipseShape,
    /// ln W, ln U, ln G.
    pub ln_w: f32,
    /// ln U.
    pub ln_u: f32,
    /// ln G.
    pub ln_g: f32,
    /// ln η₀ (ln Pa·s).
    pub ln_viscosity: f32,
    /// ln M, ln L (Moes).
    pub ln_moes_m: f32,
    /// ln L.
    pub ln_moes_l: f32,
    /// ln p_h, the maximum Hertz pressure (ln Pa).
    pub ln_hertz_pressure: f32,
    /// ln(h_c,HD/R_x), ln(h_min,HD/R_x).
    pub ln_hamrock_dowson_over_rx: [f32; 2],
}

/// The groups of `c`, at a fixed cost (module doc). p_h = 3w/(2πab) with
/// ab = (6EwR/(πE'))^⅔ k^⅓, 1/R = 1/R_x + 1/R_y (`hertz` module doc).
#[inline]
pub fn groups(c: &PointContactInput) -> PointGroups {
    let raw = [
        c.load_n,
        c.entrainment_speed_m_s,
        c.radius_x_m,
        c.radius_y_m,
        c.reduced_modulus_pa,
        c.pressure_viscosity_pa_inv,
        c.viscosity_pa_s,
    ];
    let mut valid = true;
    for v in raw {
        valid &= (v > 0.0) & (v <= f32::MAX);
    }
    let [ln_q, ln_u_m, ln_rx, ln_ry, ln_e, ln_alpha, ln_eta] = raw.map(ln_atanh);
    let ln_ratio = ln_ry - ln_rx;
    let shape = hertz::ellipse_shape(ln_ratio);
    let ln_w = ln_q - ln_e - 2.0 * ln_rx;
    let ln_u = ln_eta + ln_u_m - ln_e - ln_rx;
    let ln_g = ln_alpha + ln_e;
    let ln_moes_m = ln_w - 0.75 * (LN_2 + ln_u);
    let ln_moes_l = ln_g + 0.25 * (LN_2 + ln_u);
    // ln R = ln R_x − ln(1 + R_x/R_y).
    let ln_r = ln_rx - ln_atanh(1.0 + exp_taylor(-crate::math::max(ln_ratio, -80.0)));
    let ln_base = LN_6_OVER_PI + ln_atanh(shape.second_integral) + ln_q + ln_r - ln_e;
    let ln_hertz_pressure =
        LN_3_OVER_2PI + ln_q - (2.0 / 3.0) * ln_base - (1.0 / 3.0) * shape.ln_ellipticity;
    let k = shape.ellipticity;
    let central_shape = ln_atanh(1.0 - 0.61 * exp_taylor(-0.73 * k));
    let minimum_shape = ln_atanh(1.0 - exp_taylor(-0.68 * k));
    PointGroups {
        valid,
        ln_radius_x: ln_rx,
        shape,
        ln_w,
        ln_u,
        ln_g,
        ln_viscosity: ln_eta,
        ln_moes_m,
        ln_moes_l,
        ln_hertz_pressure,
        ln_hamrock_dowson_over_rx: [
            LN_2_69 + 0.67 * ln_u + 0.53 * ln_g - 0.067 * ln_w + central_shape,
            LN_3_63 + 0.68 * ln_u + 0.49 * ln_g - 0.073 * ln_w + minimum_shape,
        ],
    }
}

/// `exp(ln_h)` if the input was valid and the value is finite and ≥ 0, else 0.
#[inline(always)]
pub(crate) fn film_or_zero(valid: bool, ln_h: f32) -> f32 {
    let h = exp_taylor(ln_h);
    if valid & (0.0..=f32::MAX).contains(&h) {
        h
    } else {
        0.0
    }
}

/// Hamrock–Dowson's central and minimum films of a point contact (module doc); zero films for
/// non-physical input (NaN, ∞, zero or negative fields), reported as [`FilmSource::Fallback`]
/// as the line contact's networks do.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct HamrockDowson;

impl HamrockDowson {
    /// The films of prepared groups (`source` for valid input).
    #[inline]
    pub fn film_of(g: &PointGroups, source: FilmSource) -> Film {
        let [c, m] = g.ln_hamrock_dowson_over_rx;
        Film {
            central_m: film_or_zero(g.valid, g.ln_radius_x + c),
            minimum_m: film_or_zero(g.valid, g.ln_radius_x + m),
            source: if g.valid {
                source
            } else {
                FilmSource::Fallback
            },
        }
    }
}

impl FilmModel<PointContactInput> for HamrockDowson {
    fn name(&self) -> &'static str {
        "hamrock_dowson"
    }

    fn film(&self, contact: &PointContactInput) -> Film {
        Self::film_of(&groups(contact), FilmSource::Regression)
    }

    fn served_loads(&self, _template: &PointContactInput) -> ServedLoads {
        ServedLoads::everywhere(FilmSource::Regression)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn contact() -> PointContactInput {
        PointContactInput {
            load_n: 40.0,
            entrainment_speed_m_s: 10.0,
            radius_x_m: 6e-3,
            radius_y_m: 6e-3,
            reduced_modulus_pa: 2.26e11,
            pressure_viscosity_pa_inv: 2e-8,
            viscosity_pa_s: 0.02,
        }
    }

    /// docs/point_contact.md's circular case: Hamrock–Dowson gives h_c = 0.579 µm, and its
    /// Hertz pressure is 1.40 GPa (Moes M = 69, L = 18.7), as the host's solver reports.
    #[test]
    fn documented_circular_case() {
        let c = contact();
        let f = HamrockDowson.film(&c);
        assert_eq!(f.source, FilmSource::Regression);
        assert!((f.central_m * 1e6 - 0.579).abs() < 0.0006, "{f:?}");
        let g = groups(&c);
        let ph = libm::expf(g.ln_hertz_pressure);
        assert!((ph / 1.40e9 - 1.0).abs() < 0.005, "{ph}");
        assert!((libm::expf(g.ln_moes_m) - 69.0).abs() < 0.5);
        assert!((libm::expf(g.ln_moes_l) - 18.7).abs() < 0.05);
    }

    /// Non-physical fields give zero films flagged `Fallback`, never NaN.
    #[test]
    fn hostile_fields_give_zero() {
        for bad in [0.0, -1.0, f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
            for field in 0..7 {
                let mut c = contact();
                let f = [
                    &mut c.load_n,
                    &mut c.entrainment_speed_m_s,
                    &mut c.radius_x_m,
                    &mut c.radius_y_m,
                    &mut c.reduced_modulus_pa,
                    &mut c.pressure_viscosity_pa_inv,
                    &mut c.viscosity_pa_s,
                ];
                if let Some(v) = f.into_iter().nth(field) {
                    *v = bad;
                }
                let film = HamrockDowson.film(&c);
                assert_eq!((film.central_m, film.minimum_m), (0.0, 0.0), "{c:?}");
                assert_eq!(film.source, FilmSource::Fallback);
            }
        }
    }
}
