//! The operating case of one line contact (SI inputs, validated) and its dimensionless groups.
//!
//! Conventions are those of docs/physics.md §1: E' is the reduced modulus 2/[(1−ν₁²)/E₁+(1−ν₂²)/E₂],
//! R the reduced radius, w = Q/l the load per unit length, u_m the entrainment (mean) speed;
//! W = w/(E'R), U = η₀u_m/(E'R), G = αE', Moes M = W(2U)^−½, L = G(2U)^¼,
//! b = √(8wR/(πE')), p_h = √(wE'/(2πR)).

use super::EhlError;
use std::f64::consts::PI;

/// One steady, isothermal, Newtonian line contact (all SI).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct ContactCase {
    /// Load per unit contact length w, N/m.
    pub load_per_length_n_per_m: f64,
    /// Entrainment (mean rolling) speed u_m, m/s.
    pub entrainment_speed_m_s: f64,
    /// Reduced radius R in the rolling direction, m.
    pub reduced_radius_m: f64,
    /// Reduced modulus E', Pa.
    pub reduced_modulus_pa: f64,
    /// Pressure–viscosity coefficient α, 1/Pa.
    pub pressure_viscosity_pa_inv: f64,
    /// Ambient dynamic viscosity η₀, Pa·s.
    pub viscosity_pa_s: f64,
}

/// Reference scales used when a case is given by dimensionless groups only: R = 10 mm,
/// E' = 226 GPa and η₀ = 0.04 Pa·s. Barus + incompressible solutions depend on (M, L) alone; for
/// Roelands η₀ enters through ln η₀ + 9.67, so the reference η₀ is stated here.
pub const REFERENCE_RADIUS_M: f64 = 0.01;
/// Reference reduced modulus for dimensionless cases, Pa.
pub const REFERENCE_MODULUS_PA: f64 = 2.26e11;
/// Reference ambient viscosity for dimensionless cases, Pa·s.
pub const REFERENCE_VISCOSITY_PA_S: f64 = 0.04;
/// Speed parameter used by [`ContactCase::from_moes`] (any value gives the same Barus solution).
pub const REFERENCE_SPEED_PARAMETER: f64 = 1.0e-11;

/// `value` finite and in [lo, hi], else [`EhlError::InvalidInput`] naming `field`.
pub(crate) fn check(field: &'static str, value: f64, lo: f64, hi: f64) -> Result<(), EhlError> {
    if value.is_finite() && value >= lo && value <= hi {
        Ok(())
    } else {
        Err(EhlError::InvalidInput {
            field,
            value,
            allowed: format!("finite, in [{lo:e}, {hi:e}]"),
        })
    }
}

/// The ranges of the solids' reduced modulus E' (Pa), the oil's pressure–viscosity
/// coefficient α (1/Pa) and its ambient viscosity η₀ (Pa·s) every contact case accepts.
pub(crate) fn check_solids_and_oil(
    reduced_modulus_pa: f64,
    pressure_viscosity_pa_inv: f64,
    viscosity_pa_s: f64,
) -> Result<(), EhlError> {
    check("reduced_modulus_pa", reduced_modulus_pa, 1e6, 1e13)?;
    check(
        "pressure_viscosity_pa_inv",
        pressure_viscosity_pa_inv,
        0.0,
        1e-6,
    )?;
    check("viscosity_pa_s", viscosity_pa_s, 1e-5, 1e4)?;
    Ok(())
}

impl ContactCase {
    /// Validating constructor. Ranges are generous physical bounds (far wider than the
    /// docs/physics.md §5.3 domain); NaN, infinities, zero and negative values are refused.
    pub fn new(
        load_per_length_n_per_m: f64,
        entrainment_speed_m_s: f64,
        reduced_radius_m: f64,
        reduced_modulus_pa: f64,
        pressure_viscosity_pa_inv: f64,
        viscosity_pa_s: f64,
    ) -> Result<Self, EhlError> {
        check(
            "load_per_length_n_per_m",
            load_per_length_n_per_m,
            1e-3,
            1e9,
        )?;
        check("entrainment_speed_m_s", entrainment_speed_m_s, 1e-6, 1e3)?;
        check("reduced_radius_m", reduced_radius_m, 1e-6, 10.0)?;
        check_solids_and_oil(
            reduced_modulus_pa,
            pressure_viscosity_pa_inv,
            viscosity_pa_s,
        )?;
        Ok(Self {
            load_per_length_n_per_m,
            entrainment_speed_m_s,
            reduced_radius_m,
            reduced_modulus_pa,
            pressure_viscosity_pa_inv,
            viscosity_pa_s,
        })
    }

    /// A case with the given load W, speed U and material G parameters, built on the
    /// reference R, E', η₀ above.
    pub fn from_dimensionless(w: f64, u: f64, g: f64) -> Result<Self, EhlError> {
        check("W", w, 1e-9, 1e-1)?;
        check("U", u, 1e-16, 1e-4)?;
        check("G", g, 0.0, 1e5)?;
        let er = REFERENCE_MODULUS_PA * REFERENCE_RADIUS_M;
        Self::new(
            w * er,
            u * er / REFERENCE_VISCOSITY_PA_S,
            REFERENCE_RADIUS_M,
            REFERENCE_MODULUS_PA,
            g / REFERENCE_MODULUS_PA,
            REFERENCE_VISCOSITY_PA_S,
        )
    }

    /// A case with Moes parameters M and L at U = [`REFERENCE_SPEED_PARAMETER`].
    pub fn from_moes(m: f64, l: f64) -> Result<Self, EhlError> {
        check("M", m, 1e-3, 1e5)?;
        check("L", l, 0.0, 100.0)?;
        let u = REFERENCE_SPEED_PARAMETER;
        let two_u = 2.0 * u;
        Self::from_dimensionless(m * two_u.sqrt(), u, l / two_u.powf(0.25))
    }

    /// Load parameter W = w/(E'R).
    pub fn load_parameter(&self) -> f64 {
        self.load_per_length_n_per_m / (self.reduced_modulus_pa * self.reduced_radius_m)
    }
    /// Speed parameter U = η₀u_m/(E'R).
    pub fn speed_parameter(&self) -> f64 {
        self.viscosity_pa_s * self.entrainment_speed_m_s
            / (self.reduced_modulus_pa * self.reduced_radius_m)
    }
    /// Material parameter G = αE'.
    pub fn material_parameter(&self) -> f64 {
        self.pressure_viscosity_pa_inv * self.reduced_modulus_pa
    }
    /// Moes load parameter M = W(2U)^−½.
    pub fn moes_m(&self) -> f64 {
        self.load_parameter() / (2.0 * self.speed_parameter()).sqrt()
    }
    /// Moes material parameter L = G(2U)^¼.
    pub fn moes_l(&self) -> f64 {
        self.material_parameter() * (2.0 * self.speed_parameter()).powf(0.25)
    }
    /// Hertz half-width b = √(8wR/(πE')), m.
    pub fn hertz_half_width_m(&self) -> f64 {
        (8.0 * self.load_per_length_n_per_m * self.reduced_radius_m
            / (PI * self.reduced_modulus_pa))
            .sqrt()
    }
    /// Maximum Hertz pressure p_h = √(wE'/(2πR)), Pa.
    pub fn hertz_pressure_pa(&self) -> f64 {
        (self.load_per_length_n_per_m * self.reduced_modulus_pa
            / (2.0 * PI * self.reduced_radius_m))
            .sqrt()
    }
    /// Reynolds coefficient λ̄ = 12η₀u_mR²/(b³p_h) of docs/physics.md §5.2.
    pub fn lambda_bar(&self) -> f64 {
        let b = self.hertz_half_width_m();
        12.0 * self.viscosity_pa_s * self.entrainment_speed_m_s * self.reduced_radius_m.powi(2)
            / (b.powi(3) * self.hertz_pressure_pa())
    }
    /// Film scale b²/R (m): h = H·b²/R.
    pub fn film_scale_m(&self) -> f64 {
        self.hertz_half_width_m().powi(2) / self.reduced_radius_m
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// p_h = 2w/(πb) (docs/physics.md §1 identity) and the groups round-trip through
    /// `from_dimensionless` / `from_moes`.
    #[test]
    fn groups_round_trip() {
        let c = ContactCase::from_moes(100.0, 10.0).unwrap();
        assert!((c.moes_m() / 100.0 - 1.0).abs() < 1e-12);
        assert!((c.moes_l() / 10.0 - 1.0).abs() < 1e-12);
        let ph = 2.0 * c.load_per_length_n_per_m / (PI * c.hertz_half_width_m());
        assert!((ph / c.hertz_pressure_pa() - 1.0).abs() < 1e-12);
    }

    /// NaN, infinity, zero and negative inputs are refused, naming the field.
    #[test]
    fn hostile_inputs_refused() {
        for bad in [f64::NAN, f64::INFINITY, 0.0, -1.0] {
            let e = ContactCase::new(bad, 1.0, 0.01, 2.2e11, 2e-8, 0.04).unwrap_err();
            assert!(e.to_string().contains("load_per_length_n_per_m"), "{e}");
            let e = ContactCase::new(1e5, 1.0, 0.01, 2.2e11, 2e-8, bad).unwrap_err();
            assert!(e.to_string().contains("viscosity_pa_s"), "{e}");
        }
        assert!(ContactCase::new(1e5, 1.0, 0.01, 2.2e11, f64::NAN, 0.04).is_err());
        assert!(ContactCase::from_moes(f64::NAN, 10.0).is_err());
    }
}
