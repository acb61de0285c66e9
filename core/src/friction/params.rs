//! The validated parameters of the friction model (docs/physics.md §8).

use crate::error::{in_range, ParamError};

/// Roughness, boundary-film, rheology and thermal parameters of the friction model, and the
/// slide-to-roll ratio of the roller contacts. Built only through [`FrictionDesign::params`]
/// (or [`FrictionParams::DEFAULT`]), which checks every field.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrictionParams {
    pub(crate) composite_roughness_m: f32,
    pub(crate) asperity_density_m2: f32,
    pub(crate) summit_radius_m: f32,
    pub(crate) boundary_shear_strength_pa: f32,
    pub(crate) boundary_friction_coefficient: f32,
    pub(crate) eyring_stress_pa: f32,
    pub(crate) viscosity_temperature_coefficient_k_inv: f32,
    pub(crate) fluid_conductivity_w_mk: f32,
    pub(crate) solid_conductivity_w_mk: f32,
    pub(crate) solid_density_kg_m3: f32,
    pub(crate) solid_heat_capacity_j_kgk: f32,
    pub(crate) slide_to_roll_ratio: f32,
}

/// The fields of [`FrictionParams`] by name and unit, as in a bearing file's `[friction]`
/// table; [`FrictionDesign::params`] validates them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrictionDesign {
    /// Composite RMS roughness σ = √(σ₁² + σ₂²) of race and roller (m, 1 nm … 10 µm).
    pub composite_roughness_m: f32,
    /// Areal density of asperity summits η_s (1/m², 10⁶ … 10¹⁶).
    pub asperity_density_m2: f32,
    /// Mean radius of the asperity summits β (m, 10 nm … 10 mm).
    pub summit_radius_m: f32,
    /// Shear strength of the boundary film on the asperities τ_b (Pa, 0 … 1 GPa).
    pub boundary_shear_strength_pa: f32,
    /// Pressure coefficient of the boundary shear strength ζ (0 … 1).
    pub boundary_friction_coefficient: f32,
    /// Eyring stress of the lubricant τ₀ (Pa, 10 kPa … 1 GPa).
    pub eyring_stress_pa: f32,
    /// Temperature–viscosity coefficient β_T of the lubricant, η ∝ e^(−β_T·ΔT) (1/K, 10⁻⁴ … 1).
    pub viscosity_temperature_coefficient_k_inv: f32,
    /// Thermal conductivity of the lubricant K (W/(m·K), 0.01 … 10).
    pub fluid_conductivity_w_mk: f32,
    /// Thermal conductivity of the solids K′ (W/(m·K), 1 … 1000).
    pub solid_conductivity_w_mk: f32,
    /// Density of the solids ρ′ (kg/m³, 1000 … 30 000).
    pub solid_density_kg_m3: f32,
    /// Specific heat capacity of the solids c′ (J/(kg·K), 100 … 5000).
    pub solid_heat_capacity_j_kgk: f32,
    /// Slide-to-roll ratio s = u_s/u_m of every roller contact (0 … 2).
    pub slide_to_roll_ratio: f32,
}

impl FrictionDesign {
    /// The defaults (docs/physics.md §8.5 gives the source of each):
    /// σ = 0.15 µm (ground raceway Rq ≈ 0.12 µm with a roller Rq ≈ 0.09 µm); summit radius
    /// β = 20 µm and density from η_s·β·σ = 0.04 (Greenwood & Williamson's 0.03 … 0.05);
    /// τ_b = 2 MPa, ζ = 0.1 (boundary friction of additive mineral oils on steel, 0.08 …
    /// 0.13); τ₀ = 5 MPa (mineral oils, 2 … 10 MPa, Evans & Johnson 1986); β_T = 0.034 1/K
    /// (an ISO VG 68 oil, the film corrections' default; mineral oils 0.02 … 0.05 1/K); K = 0.14 W/(m·K) (mineral oils 0.12 … 0.15 at ambient
    /// pressure); bearing steel K′ = 46.6 W/(m·K), ρ′ = 7830 kg/m³, c′ = 475 J/(kg·K);
    /// s = 1 % (an assumed roller slip; see docs/physics.md §8.4).
    pub const DEFAULT: FrictionDesign = FrictionDesign {
        composite_roughness_m: 0.15e-6,
        asperity_density_m2: 0.04 / (20.0e-6 * 0.15e-6),
        summit_radius_m: 20.0e-6,
        boundary_shear_strength_pa: 2.0e6,
        boundary_friction_coefficient: 0.1,
        eyring_stress_pa: 5.0e6,
        viscosity_temperature_coefficient_k_inv:
            crate::film::corrections::VG68_TEMPERATURE_VISCOSITY_PER_K,
        fluid_conductivity_w_mk: 0.14,
        solid_conductivity_w_mk: 46.6,
        solid_density_kg_m3: 7830.0,
        solid_heat_capacity_j_kgk: 475.0,
        slide_to_roll_ratio: 0.01,
    };

    /// The validated parameters; the error names the first refused field and its range.
    pub fn params(&self) -> Result<FrictionParams, ParamError> {
        Ok(FrictionParams {
            composite_roughness_m: in_range(
                "composite_roughness_m",
                self.composite_roughness_m,
                1.0e-9,
                1.0e-5,
            )?,
            asperity_density_m2: in_range(
                "asperity_density_m2",
                self.asperity_density_m2,
                1.0e6,
                1.0e16,
            )?,
            summit_radius_m: in_range("summit_radius_m", self.summit_radius_m, 1.0e-8, 1.0e-2)?,
            boundary_shear_strength_pa: in_range(
                "boundary_shear_strength_pa",
                self.boundary_shear_strength_pa,
                0.0,
                1.0e9,
            )?,
            boundary_friction_coefficient: in_range(
                "boundary_friction_coefficient",
                self.boundary_friction_coefficient,
                0.0,
                1.0,
            )?,
            eyring_stress_pa: in_range("eyring_stress_pa", self.eyring_stress_pa, 1.0e4, 1.0e9)?,
            viscosity_temperature_coefficient_k_inv: in_range(
                "viscosity_temperature_coefficient_k_inv",
                self.viscosity_temperature_coefficient_k_inv,
                1.0e-4,
                1.0,
            )?,
            fluid_conductivity_w_mk: in_range(
                "fluid_conductivity_w_mk",
                self.fluid_conductivity_w_mk,
                0.01,
                10.0,
            )?,
            solid_conductivity_w_mk: in_range(
                "solid_conductivity_w_mk",
                self.solid_conductivity_w_mk,
                1.0,
                1000.0,
            )?,
            solid_density_kg_m3: in_range(
                "solid_density_kg_m3",
                self.solid_density_kg_m3,
                1000.0,
                30_000.0,
            )?,
            solid_heat_capacity_j_kgk: in_range(
                "solid_heat_capacity_j_kgk",
                self.solid_heat_capacity_j_kgk,
                100.0,
                5000.0,
            )?,
            slide_to_roll_ratio: in_range(
                "slide_to_roll_ratio",
                self.slide_to_roll_ratio,
                0.0,
                2.0,
            )?,
        })
    }
}

impl Default for FrictionDesign {
    fn default() -> Self {
        Self::DEFAULT
    }
}

impl FrictionParams {
    /// [`FrictionDesign::DEFAULT`], validated.
    pub const DEFAULT: FrictionParams = FrictionParams {
        composite_roughness_m: FrictionDesign::DEFAULT.composite_roughness_m,
        asperity_density_m2: FrictionDesign::DEFAULT.asperity_density_m2,
        summit_radius_m: FrictionDesign::DEFAULT.summit_radius_m,
        boundary_shear_strength_pa: FrictionDesign::DEFAULT.boundary_shear_strength_pa,
        boundary_friction_coefficient: FrictionDesign::DEFAULT.boundary_friction_coefficient,
        eyring_stress_pa: FrictionDesign::DEFAULT.eyring_stress_pa,
        viscosity_temperature_coefficient_k_inv: FrictionDesign::DEFAULT
            .viscosity_temperature_coefficient_k_inv,
        fluid_conductivity_w_mk: FrictionDesign::DEFAULT.fluid_conductivity_w_mk,
        solid_conductivity_w_mk: FrictionDesign::DEFAULT.solid_conductivity_w_mk,
        solid_density_kg_m3: FrictionDesign::DEFAULT.solid_density_kg_m3,
        solid_heat_capacity_j_kgk: FrictionDesign::DEFAULT.solid_heat_capacity_j_kgk,
        slide_to_roll_ratio: FrictionDesign::DEFAULT.slide_to_roll_ratio,
    };

    /// The fields by name, as given to [`FrictionDesign::params`].
    pub fn design(&self) -> FrictionDesign {
        FrictionDesign {
            composite_roughness_m: self.composite_roughness_m,
            asperity_density_m2: self.asperity_density_m2,
            summit_radius_m: self.summit_radius_m,
            boundary_shear_strength_pa: self.boundary_shear_strength_pa,
            boundary_friction_coefficient: self.boundary_friction_coefficient,
            eyring_stress_pa: self.eyring_stress_pa,
            viscosity_temperature_coefficient_k_inv: self.viscosity_temperature_coefficient_k_inv,
            fluid_conductivity_w_mk: self.fluid_conductivity_w_mk,
            solid_conductivity_w_mk: self.solid_conductivity_w_mk,
            solid_density_kg_m3: self.solid_density_kg_m3,
            solid_heat_capacity_j_kgk: self.solid_heat_capacity_j_kgk,
            slide_to_roll_ratio: self.slide_to_roll_ratio,
        }
    }

    /// Composite RMS roughness σ (m).
    pub fn composite_roughness_m(&self) -> f32 {
        self.composite_roughness_m
    }

    /// Slide-to-roll ratio s.
    pub fn slide_to_roll_ratio(&self) -> f32 {
        self.slide_to_roll_ratio
    }
}

impl Default for FrictionParams {
    fn default() -> Self {
        Self::DEFAULT
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn defaults_are_valid_and_bad_fields_are_named() {
        assert_eq!(
            FrictionDesign::DEFAULT.params(),
            Ok(FrictionParams::DEFAULT)
        );
        // The conductivity a mixed-EHL source tabulates for the oil, 1600 W/(m·K), is a
        // metal's order; it is refused.
        let bad = FrictionDesign {
            fluid_conductivity_w_mk: 1600.0,
            ..FrictionDesign::DEFAULT
        };
        assert_eq!(bad.params().unwrap_err().field, "fluid_conductivity_w_mk");
        let bad = FrictionDesign {
            composite_roughness_m: f32::NAN,
            ..FrictionDesign::DEFAULT
        };
        assert_eq!(bad.params().unwrap_err().field, "composite_roughness_m");
        let bad = FrictionDesign {
            slide_to_roll_ratio: -0.1,
            ..FrictionDesign::DEFAULT
        };
        assert_eq!(bad.params().unwrap_err().field, "slide_to_roll_ratio");
    }
}
