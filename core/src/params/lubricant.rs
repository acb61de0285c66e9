//! The lubricant: ambient viscosity, pressure–viscosity coefficient and density.

use crate::error::{in_range, ParamError};

/// A Newtonian, isothermal lubricant (docs/physics.md §5).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lubricant {
    viscosity_pa_s: f32,
    pressure_viscosity_pa_inv: f32,
    density_kg_m3: f32,
}

impl Lubricant {
    /// A lubricant with dynamic viscosity η₀ (`viscosity_pa_s`, 1e-5 … 10 Pa·s),
    /// pressure–viscosity coefficient α (`pressure_viscosity_pa_inv`, 0 … 1e-7 1/Pa) and
    /// density ρ₀ (`density_kg_m3`, 100 … 3000 kg/m³).
    pub fn new(
        viscosity_pa_s: f32,
        pressure_viscosity_pa_inv: f32,
        density_kg_m3: f32,
    ) -> Result<Self, ParamError> {
        Ok(Self {
            viscosity_pa_s: in_range("viscosity_pa_s", viscosity_pa_s, 1.0e-5, 10.0)?,
            pressure_viscosity_pa_inv: in_range(
                "pressure_viscosity_pa_inv",
                pressure_viscosity_pa_inv,
                0.0,
                1.0e-7,
            )?,
            density_kg_m3: in_range("density_kg_m3", density_kg_m3, 100.0, 3000.0)?,
        })
    }

    /// Dynamic viscosity at ambient pressure η₀ (Pa·s).
    pub fn viscosity_pa_s(&self) -> f32 {
        self.viscosity_pa_s
    }

    /// Pressure–viscosity coefficient α (1/Pa).
    pub fn pressure_viscosity_pa_inv(&self) -> f32 {
        self.pressure_viscosity_pa_inv
    }

    /// Density at ambient pressure ρ₀ (kg/m³).
    pub fn density_kg_m3(&self) -> f32 {
        self.density_kg_m3
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn accepts_the_reference_oil_and_names_bad_fields() {
        // docs/physics.md §6.1: α = 2.1e-8 1/Pa, η₀ = 0.08 Pa·s, ρ₀ = 833.8 kg/m³.
        assert!(Lubricant::new(0.08, 2.1e-8, 833.8).is_ok());
        assert_eq!(
            Lubricant::new(0.0, 2.1e-8, 833.8).unwrap_err().field,
            "viscosity_pa_s"
        );
        assert_eq!(
            Lubricant::new(0.08, f32::INFINITY, 833.8)
                .unwrap_err()
                .field,
            "pressure_viscosity_pa_inv"
        );
    }
}
