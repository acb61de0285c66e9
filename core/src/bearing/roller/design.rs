//! A bearing described field by field, with the units in the field names, and the reference
//! bearings of `configs/` as presets.

use super::BearingParams;
use crate::contact::ContactLaw;
use crate::error::ParamError;
use crate::params::{BearingGeometry, Crown, Lubricant, Material};

/// Everything that defines a lubricated cylindrical roller bearing, by name and unit: the
/// fields of a bearing configuration file (`configs/*.toml`). [`BearingDesign::params`]
/// validates every field once and names the first refused one.
///
/// ```
/// use bearing_core::{BearingDesign, ContactLaw};
///
/// let wide = BearingDesign {
///     roller_length_m: 0.020,
///     contact_law: ContactLaw::Lundberg,
///     ..BearingDesign::HUB_MOTOR
/// };
/// assert!(wide.params().is_ok());
/// let bad = BearingDesign { roller_count: 1, ..wide };
/// assert_eq!(bad.params().unwrap_err().field, "roller_count");
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BearingDesign {
    /// Pitch diameter d_m (m, 1 mm … 10 m).
    pub pitch_diameter_m: f32,
    /// Roller diameter D (m, below d_m).
    pub roller_diameter_m: f32,
    /// Effective contact length l, roller length minus edge radii (m, 0.1 mm … 1 m).
    pub roller_length_m: f32,
    /// Number of rollers Z (3 … 128, and Z·D < π·d_m).
    pub roller_count: u16,
    /// Radial internal clearance g_r per roller (m, −1 mm … 1 mm; negative: interference).
    pub radial_clearance_m: f32,
    /// Multiplier on the ISO/TS 16281 logarithmic crown (0 … 10; 0 is a straight roller).
    pub crown_scale: f32,
    /// Young's modulus of rings and rollers (Pa, 1 GPa … 1000 GPa).
    pub elastic_modulus_pa: f32,
    /// Poisson's ratio of rings and rollers (0 … 0.5).
    pub poisson_ratio: f32,
    /// Lubricant viscosity at ambient pressure η₀ (Pa·s, 10⁻⁵ … 10).
    pub viscosity_pa_s: f32,
    /// Pressure–viscosity coefficient α (1/Pa, 0 … 10⁻⁷).
    pub pressure_viscosity_pa_inv: f32,
    /// Lubricant density ρ₀ (kg/m³, 100 … 3000).
    pub density_kg_m3: f32,
    /// Load–deflection law of the roller slices.
    pub contact_law: ContactLaw,
    /// Damping factor f_damp (s, 0 … 10⁻³; docs/physics.md §4).
    pub damping_factor_s: f32,
}

impl BearingDesign {
    /// The hub-motor shaft bearing, `configs/hub_motor.toml` (docs/physics.md §6.2): pitch diameter
    /// 60 mm, 17 rollers Ø8.8 mm × 15 mm, 2 µm radial interference, steel, the thesis oil
    /// (η₀ = 0.08 Pa·s, α = 2.1·10⁻⁸ 1/Pa, ρ₀ = 833.8 kg/m³), Palmgren slices,
    /// f_damp = 10⁻⁵ s.
    pub const HUB_MOTOR: BearingDesign = BearingDesign {
        pitch_diameter_m: 0.060,
        roller_diameter_m: 0.0088,
        roller_length_m: 0.015,
        roller_count: 17,
        radial_clearance_m: -2.0e-6,
        crown_scale: 1.0,
        ..THESIS_STEEL_AND_OIL
    };

    /// The test-rig bearing NU 205 ECP, `configs/nu205.toml` (docs/physics.md §6.1): raceways
    /// Ø31.5 / Ø46.5 mm (pitch diameter 39 mm), 12 rollers Ø7.5 mm × 9 mm, zero clearance,
    /// materials, oil and model as [`BearingDesign::HUB_MOTOR`].
    pub const NU205: BearingDesign = BearingDesign {
        pitch_diameter_m: 0.039,
        roller_diameter_m: 0.0075,
        roller_length_m: 0.009,
        roller_count: 12,
        radial_clearance_m: 0.0,
        crown_scale: 1.0,
        ..THESIS_STEEL_AND_OIL
    };

    /// The validated parameters; the error names the first refused field and its range.
    pub fn params(&self) -> Result<BearingParams, ParamError> {
        let crown = if self.crown_scale == 0.0 {
            Crown::None
        } else {
            Crown::Logarithmic {
                scale: self.crown_scale,
            }
        };
        let geometry = BearingGeometry::new(
            self.pitch_diameter_m,
            self.roller_diameter_m,
            self.roller_length_m,
            self.roller_count,
            crown,
            self.radial_clearance_m,
        )?;
        let material = Material::new(self.elastic_modulus_pa, self.poisson_ratio)?;
        let lubricant = Lubricant::new(
            self.viscosity_pa_s,
            self.pressure_viscosity_pa_inv,
            self.density_kg_m3,
        )?;
        BearingParams::new(
            geometry,
            material,
            material,
            lubricant,
            self.contact_law,
            self.damping_factor_s,
        )
    }
}

/// Steel rings and rollers (E = 210 GPa, ν = 0.3), the oil of both reference machines and the
/// `[model]` section of both configuration files (f_damp inside the thesis' 0.25 … 2.5·10⁻⁵ s,
/// docs/physics.md §4); the geometry fields are placeholders that every preset overrides.
const THESIS_STEEL_AND_OIL: BearingDesign = BearingDesign {
    pitch_diameter_m: 0.0,
    roller_diameter_m: 0.0,
    roller_length_m: 0.0,
    roller_count: 0,
    radial_clearance_m: 0.0,
    crown_scale: 1.0,
    elastic_modulus_pa: 210.0e9,
    poisson_ratio: 0.3,
    viscosity_pa_s: 0.08,
    pressure_viscosity_pa_inv: 2.1e-8,
    density_kg_m3: 833.8,
    contact_law: ContactLaw::Palmgren,
    damping_factor_s: 1.0e-5,
};

#[cfg(test)]
mod tests {
    use super::*;

    /// The presets are valid and have the roller counts of their configuration files.
    #[test]
    fn presets_are_valid() {
        assert_eq!(
            BearingDesign::HUB_MOTOR
                .params()
                .unwrap()
                .geometry()
                .roller_count(),
            17
        );
        assert_eq!(
            BearingDesign::NU205
                .params()
                .unwrap()
                .geometry()
                .roller_count(),
            12
        );
    }
}
