//! The operating case of one point contact (SI inputs, validated) and its dimensionless groups.
//!
//! Conventions (docs/physics.md §1 for E'): x is the rolling (entrainment) direction with reduced
//! radius R_x, y the transverse direction with R_y ≥ R_x (a ball on its race: the race's
//! conformity makes R_y the larger), w the contact load, u_m the entrainment (mean) speed.
//! Hamrock–Dowson groups: W = w/(E'R_x²), U = η₀u_m/(E'R_x), G = αE'. Moes groups for point
//! contacts (Nijenbanning, Venner & Moes 1994): M = W(2U)^−¾, L = G(2U)^¼, H = (h/R_x)(2U)^−½.

use super::hertz::{radius_ratio_of_ellipticity, HertzEllipse};
use crate::case::{check, check_solids_and_oil};
use crate::EhlError;

/// One steady, isothermal, Newtonian point contact (all SI).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct PointContactCase {
    /// Contact load w, N.
    pub load_n: f64,
    /// Entrainment (mean rolling) speed u_m along x, m/s.
    pub entrainment_speed_m_s: f64,
    /// Reduced radius R_x in the rolling direction, m.
    pub radius_x_m: f64,
    /// Reduced radius R_y across the rolling direction (≥ R_x), m.
    pub radius_y_m: f64,
    /// Reduced modulus E', Pa.
    pub reduced_modulus_pa: f64,
    /// Pressure–viscosity coefficient α, 1/Pa.
    pub pressure_viscosity_pa_inv: f64,
    /// Ambient dynamic viscosity η₀, Pa·s.
    pub viscosity_pa_s: f64,
}

/// Largest R_y/R_x accepted: ellipticity k ≈ 10, beyond the ≈ 8 of deep-groove ball bearings.
pub const MAX_RADIUS_RATIO: f64 = 40.0;

impl PointContactCase {
    /// Validating constructor (generous physical bounds; NaN, infinities, zero and negative
    /// values are refused; R_y/R_x must lie in [1, 40]).
    pub fn new(
        load_n: f64,
        entrainment_speed_m_s: f64,
        radius_x_m: f64,
        radius_y_m: f64,
        reduced_modulus_pa: f64,
        pressure_viscosity_pa_inv: f64,
        viscosity_pa_s: f64,
    ) -> Result<Self, EhlError> {
        check("load_n", load_n, 1e-6, 1e7)?;
        check("entrainment_speed_m_s", entrainment_speed_m_s, 1e-6, 1e3)?;
        check("radius_x_m", radius_x_m, 1e-6, 10.0)?;
        check("radius_y_m", radius_y_m, 1e-6, 400.0)?;
        check(
            "radius_ratio",
            radius_y_m / radius_x_m,
            1.0,
            MAX_RADIUS_RATIO,
        )?;
        check_solids_and_oil(
            reduced_modulus_pa,
            pressure_viscosity_pa_inv,
            viscosity_pa_s,
        )?;
        Ok(Self {
            load_n,
            entrainment_speed_m_s,
            radius_x_m,
            radius_y_m,
            reduced_modulus_pa,
            pressure_viscosity_pa_inv,
            viscosity_pa_s,
        })
    }

    /// A case with Moes parameters M, L and ellipticity k = a/b ≥ 1, built on the line
    /// contact's reference R_x, E', η₀ (crate::case) at U = 10⁻¹¹.
    pub fn from_moes(m: f64, l: f64, ellipticity: f64) -> Result<Self, EhlError> {
        check("M", m, 1e-2, 1e5)?;
        check("L", l, 0.0, 100.0)?;
        check("ellipticity", ellipticity, 1.0, 12.0)?;
        let u = crate::case::REFERENCE_SPEED_PARAMETER;
        let two_u = 2.0 * u;
        let w = m * two_u.powf(0.75);
        let g = l / two_u.powf(0.25);
        let rx = crate::case::REFERENCE_RADIUS_M;
        let e = crate::case::REFERENCE_MODULUS_PA;
        let eta = crate::case::REFERENCE_VISCOSITY_PA_S;
        Self::new(
            w * e * rx * rx,
            u * e * rx / eta,
            rx,
            rx * radius_ratio_of_ellipticity(ellipticity),
            e,
            g / e,
            eta,
        )
    }

    /// Load parameter W = w/(E'R_x²).
    pub fn load_parameter(&self) -> f64 {
        self.load_n / (self.reduced_modulus_pa * self.radius_x_m * self.radius_x_m)
    }
    /// Speed parameter U = η₀u_m/(E'R_x).
    pub fn speed_parameter(&self) -> f64 {
        self.viscosity_pa_s * self.entrainment_speed_m_s
            / (self.reduced_modulus_pa * self.radius_x_m)
    }
    /// Material parameter G = αE'.
    pub fn material_parameter(&self) -> f64 {
        self.pressure_viscosity_pa_inv * self.reduced_modulus_pa
    }
    /// Moes load parameter M = W(2U)^−¾.
    pub fn moes_m(&self) -> f64 {
        self.load_parameter() / (2.0 * self.speed_parameter()).powf(0.75)
    }
    /// Moes material parameter L = G(2U)^¼.
    pub fn moes_l(&self) -> f64 {
        self.material_parameter() * (2.0 * self.speed_parameter()).powf(0.25)
    }
    /// The Hertz contact ellipse.
    pub fn hertz(&self) -> HertzEllipse {
        HertzEllipse::new(
            self.load_n,
            self.radius_x_m,
            self.radius_y_m,
            self.reduced_modulus_pa,
        )
    }
}
