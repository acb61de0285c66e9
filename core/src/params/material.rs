//! Elastic solids and the reduced modulus E'.

use crate::error::{in_range, ParamError};

/// Isotropic elastic solid (a ring or a roller).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    elastic_modulus_pa: f32,
    poisson_ratio: f32,
}

impl Material {
    /// Bearing steel as used in all reference cases (E = 210 GPa, ν = 0.3).
    pub const STEEL: Material = Material {
        elastic_modulus_pa: 210.0e9,
        poisson_ratio: 0.3,
    };

    /// A solid with Young's modulus `elastic_modulus_pa` (Pa, 1 GPa … 1000 GPa) and Poisson's
    /// ratio `poisson_ratio` (0 … 0.5).
    pub fn new(elastic_modulus_pa: f32, poisson_ratio: f32) -> Result<Self, ParamError> {
        Ok(Self {
            elastic_modulus_pa: in_range("elastic_modulus_pa", elastic_modulus_pa, 1.0e9, 1.0e12)?,
            poisson_ratio: in_range("poisson_ratio", poisson_ratio, 0.0, 0.5)?,
        })
    }

    /// Young's modulus E (Pa).
    pub fn elastic_modulus_pa(&self) -> f32 {
        self.elastic_modulus_pa
    }

    /// Poisson's ratio ν (–).
    pub fn poisson_ratio(&self) -> f32 {
        self.poisson_ratio
    }

    /// (1 − ν²)/E (1/Pa), the compliance that adds up across a contact.
    fn compliance(&self) -> f32 {
        (1.0 - self.poisson_ratio * self.poisson_ratio) / self.elastic_modulus_pa
    }
}

/// Reduced modulus E' = 2 / [(1−ν₁²)/E₁ + (1−ν₂²)/E₂] (Pa), docs/physics.md §1 (Hamrock, Dowson,
/// Venner, Moes; Johnson's E* is E'/2). Steel on steel gives 230.8 GPa.
pub fn reduced_modulus(a: &Material, b: &Material) -> f32 {
    2.0 / (a.compliance() + b.compliance())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steel_on_steel_reduced_modulus_is_230_8_gpa() {
        // docs/physics.md §1: E = 210 GPa, ν = 0.3 → E' = 210/(1 − 0.09) = 230.77 GPa.
        let e = reduced_modulus(&Material::STEEL, &Material::STEEL);
        assert!((e / 230.769e9 - 1.0).abs() < 1e-5, "{e}");
    }

    #[test]
    fn refuses_nan_and_out_of_range() {
        assert_eq!(
            Material::new(f32::NAN, 0.3).unwrap_err().field,
            "elastic_modulus_pa"
        );
        assert_eq!(
            Material::new(210e9, 0.6).unwrap_err().field,
            "poisson_ratio"
        );
        assert_eq!(
            Material::new(-1.0, 0.3).unwrap_err().field,
            "elastic_modulus_pa"
        );
    }
}
