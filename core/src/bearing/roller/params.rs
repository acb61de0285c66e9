//! The validated parameters of a bearing.

use crate::contact::ContactLaw;
use crate::error::{in_range, ParamError};
use crate::film::corrections::FilmCorrections;
use crate::film::ContactInput;
use crate::friction::FrictionParams;
use crate::params::{reduced_modulus, BearingGeometry, Lubricant, Material};

/// Density of bearing steel (kg/m³), the usual roller density.
pub const STEEL_DENSITY_KG_M3: f32 = 7850.0;

/// Everything that defines a lubricated roller bearing.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BearingParams {
    pub(super) geometry: BearingGeometry,
    pub(super) reduced_modulus_pa: f32,
    pub(super) lubricant: Lubricant,
    pub(super) law: ContactLaw,
    pub(super) damping_factor_s: f32,
    pub(super) film_corrections: FilmCorrections,
    /// Density of the rollers (kg/m³) when the bearing includes their centrifugal force.
    pub(super) centrifugal_density_kg_m3: Option<f32>,
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
            film_corrections: FilmCorrections::OFF,
            centrifugal_density_kg_m3: None,
            friction: FrictionParams::DEFAULT,
        })
    }

    /// The same bearing with the rollers' centrifugal force on the outer race (docs/physics.md
    /// §4.1), rollers of density ρ (`roller_density_kg_m3`, 1000 … 20 000 kg/m³; bearing steel
    /// [`STEEL_DENSITY_KG_M3`]). A bearing is built without it.
    pub fn with_centrifugal_force(self, roller_density_kg_m3: f32) -> Result<Self, ParamError> {
        Ok(Self {
            centrifugal_density_kg_m3: Some(in_range(
                "roller_density_kg_m3",
                roller_density_kg_m3,
                1000.0,
                20_000.0,
            )?),
            ..self
        })
    }

    /// The roller mass m = ρ·(π/4)·D²·l (kg) of the centrifugal force, with l the effective
    /// length (the edge radii's share of the roller is left out); `None` without it.
    pub fn roller_mass_kg(&self) -> Option<f32> {
        let g = &self.geometry;
        let d = g.roller_diameter_m();
        self.centrifugal_density_kg_m3
            .map(|rho| rho * (0.25 * core::f32::consts::PI) * d * d * g.roller_length_m())
    }

    /// A roller's centrifugal force F_c = m·ω_c²·d_m/2 (N) at shaft speed ω (rad/s), ω_c the
    /// cage speed (docs/physics.md §2); `None` when the bearing leaves it out.
    pub fn centrifugal_force_n(&self, shaft_speed_rad_s: f32) -> Option<f32> {
        let g = &self.geometry;
        let cage = g.cage_speed_rad_s(shaft_speed_rad_s);
        self.roller_mass_kg()
            .map(|m| m * cage * cage * (0.5 * g.pitch_diameter_m()))
    }

    /// The same bearing with the high-speed film corrections `corrections` (docs/physics.md
    /// §5.4); a bearing is built with none ([`FilmCorrections::OFF`]).
    pub fn with_film_corrections(self, corrections: FilmCorrections) -> Self {
        Self {
            film_corrections: corrections,
            ..self
        }
    }

    /// The high-speed film corrections applied after the film model.
    pub fn film_corrections(&self) -> &FilmCorrections {
        &self.film_corrections
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
