//! The validated parameters of a bearing.

use crate::contact::ContactLaw;
use crate::error::{in_range, ParamError};
use crate::film::ContactInput;
use crate::friction::FrictionParams;
use crate::params::{reduced_modulus, BearingGeometry, Lubricant, Material};

/// Everything that defines a lubricated roller bearing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BearingParams {
    pub(super) geometry: BearingGeometry,
    pub(super) reduced_modulus_pa: f32,
    pub(super) lubricant: Lubricant,
    pub(super) law: ContactLaw,
    pub(super) damping_factor_s: f32,
    pub(super) friction: FrictionParams,
}

impl BearingParams {
    /// A bearing from its geometry, the materials of the rings and the rollers, the lubricant,
    /// the slice contact law and the damping factor f_damp (s; 0 … 10⁻³, the thesis used
    /// 0.25·10⁻⁵ … 2.5·10⁻⁵, docs/physics.md §4).
    pub fn new(
        geometry: BearingGeometry,
        ring_material: Material,
        roller_material: Material,
        lubricant: Lubricant,
        law: ContactLaw,
        damping_factor_s: f32,
    ) -> Result<Self, ParamError> {
        Ok(Self {
            geometry,
            reduced_modulus_pa: reduced_modulus(&ring_material, &roller_material),
            lubricant,
            law,
            damping_factor_s: in_range("damping_factor_s", damping_factor_s, 0.0, 1.0e-3)?,
            friction: FrictionParams::DEFAULT,
        })
    }

    /// The same bearing with the friction model's parameters `friction` (the constructor
    /// gives [`FrictionParams::DEFAULT`]).
    pub fn with_friction(self, friction: FrictionParams) -> Self {
        Self { friction, ..self }
    }

    /// The friction model's parameters.
    pub fn friction(&self) -> &FrictionParams {
        &self.friction
    }

    /// Geometry.
    pub fn geometry(&self) -> &BearingGeometry {
        &self.geometry
    }
    /// Reduced modulus E' of the roller–race contacts (Pa).
    pub fn reduced_modulus_pa(&self) -> f32 {
        self.reduced_modulus_pa
    }
    /// Lubricant.
    pub fn lubricant(&self) -> &Lubricant {
        &self.lubricant
    }
    /// Slice contact law.
    pub fn law(&self) -> ContactLaw {
        self.law
    }
    /// Damping factor f_damp (s).
    pub fn damping_factor_s(&self) -> f32 {
        self.damping_factor_s
    }

    /// The film-model input of the inner (`outer = false`) or outer contact for roller load
    /// `load_n` (N) at shaft speed ω (rad/s).
    pub fn contact_input(&self, outer: bool, load_n: f32, shaft_speed_rad_s: f32) -> ContactInput {
        let g = &self.geometry;
        ContactInput {
            load_n,
            length_m: g.roller_length_m(),
            entrainment_speed_m_s: g.entrainment_speed_m_s(shaft_speed_rad_s),
            reduced_radius_m: if outer {
                g.outer_reduced_radius_m()
            } else {
                g.inner_reduced_radius_m()
            },
            reduced_modulus_pa: self.reduced_modulus_pa,
            pressure_viscosity_pa_inv: self.lubricant.pressure_viscosity_pa_inv(),
            viscosity_pa_s: self.lubricant.viscosity_pa_s(),
        }
    }
}
