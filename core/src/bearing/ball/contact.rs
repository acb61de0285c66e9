//! One ball–race contact at a given contact angle: its radii of curvature and its Hertz
//! ellipse, approach and pressure, at a fixed cost.
//!
//! Radii (Harris & Kotzalas 2007, *Rolling Bearing Analysis*, 5th ed., vol. 1, §2.4), with
//! γ = D cos α / d_m:
//!
//!   inner: 1/R_x = 2/D + 2γ/(D(1 − γ)),   outer: 1/R_x = 2/D − 2γ/(D(1 + γ)),
//!   both:  1/R_y = 2/D − 1/(f D)          (f = f_i or f_o; the groove is concave),
//!
//! x along the rolling direction; R_y > R_x in a groove, as the point film's convention asks.
//! With 1/R = 1/R_x + 1/R_y, the ellipticity k, K = K(m) and E = E(m), m = 1 − 1/k², from
//! [`crate::film::point::hertz::ellipse_shape`] (exact to f32 rounding, tested against the
//! host's bisection), Hertz gives for a load Q (Hamrock 1994, *Fundamentals of Fluid Film
//! Lubrication*, ch. 3; Johnson 1985, §4.2):
//!
//!   a = (6k²E Q R/(πE'))^⅓,  b = (6E Q R/(πkE'))^⅓,  p_max = 3Q/(2πab),
//!   δ = K [ (9/(2E R)) (Q/(πkE'))² ]^⅓ = c Q^⅔.
//!
//! So the ball's two contacts in series take δ_i + δ_o = (c_i + c_o) Q^⅔ for one load Q.

use crate::film::point::hertz::ellipse_shape;
use crate::film::PointContactInput;
use crate::math::{ln, pow};

use super::params::BallBearingParams;

/// The Hertz constants of one contact at one contact angle, for any load.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct RaceContact {
    /// Reduced radius of curvature along the rolling direction, R_x (m).
    pub radius_x_m: f32,
    /// Reduced radius across it, R_y (m).
    pub radius_y_m: f32,
    /// c in δ = c Q^⅔ (m/N^⅔).
    pub compliance: f32,
    /// a / Q^⅓ and b / Q^⅓ (m/N^⅓): semi-axes across and along the rolling direction.
    pub semi_axis_per_cbrt_load: [f32; 2],
}

impl RaceContact {
    /// The contact of the inner (`inner` true) or outer race at cos α = `cos_alpha`.
    #[inline]
    pub fn new(p: &BallBearingParams, cos_alpha: f32, inner: bool) -> Self {
        let d = p.ball_diameter_m;
        let gamma = d * cos_alpha / p.pitch_diameter_m;
        let race = if inner {
            2.0 * gamma / (d * (1.0 - gamma))
        } else {
            -2.0 * gamma / (d * (1.0 + gamma))
        };
        let groove = if inner {
            p.inner_groove_ratio
        } else {
            p.outer_groove_ratio
        };
        let curvature_x = 2.0 / d + race;
        let curvature_y = 2.0 / d - 1.0 / (groove * d);
        let (radius_x, radius_y) = (1.0 / curvature_x, 1.0 / curvature_y);
        let r = 1.0 / (curvature_x + curvature_y);
        let shape = ellipse_shape(ln(radius_y / radius_x));
        let (k, e, big_k) = (
            shape.ellipticity,
            shape.second_integral,
            shape.first_integral,
        );
        let modulus = p.reduced_modulus_pa;
        let pi = core::f32::consts::PI;
        let third = 1.0 / 3.0;
        let pi_k_e = pi * k * modulus;
        RaceContact {
            radius_x_m: radius_x,
            radius_y_m: radius_y,
            compliance: big_k * pow(9.0 / (2.0 * e * r) / (pi_k_e * pi_k_e), third),
            semi_axis_per_cbrt_load: [
                pow(6.0 * k * k * e * r / (pi * modulus), third),
                pow(6.0 * e * r / (pi * k * modulus), third),
            ],
        }
    }

    /// The point-contact film input of this contact at load `load_n`.
    #[inline]
    pub fn film_input(
        &self,
        p: &BallBearingParams,
        load_n: f32,
        entrainment_m_s: f32,
    ) -> PointContactInput {
        PointContactInput {
            load_n,
            entrainment_speed_m_s: entrainment_m_s,
            radius_x_m: self.radius_x_m,
            radius_y_m: self.radius_y_m,
            reduced_modulus_pa: p.reduced_modulus_pa,
            pressure_viscosity_pa_inv: p.pressure_viscosity_pa_inv,
            viscosity_pa_s: p.viscosity_pa_s,
        }
    }

    /// Semi-axes [a, b] (m) and maximum pressure (Pa) at load `load_n` ≥ 0.
    #[inline]
    pub fn ellipse(&self, load_n: f32) -> ([f32; 2], f32) {
        let cbrt = pow(load_n, 1.0 / 3.0);
        let a = self.semi_axis_per_cbrt_load[0] * cbrt;
        let b = self.semi_axis_per_cbrt_load[1] * cbrt;
        let area = core::f32::consts::PI * a * b;
        let pressure = crate::math::select(area > 0.0, 1.5 * load_n / area, 0.0);
        ([a, b], pressure)
    }
}
