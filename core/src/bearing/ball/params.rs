//! A ball bearing's design (every field with its unit, as in its configuration file) and the
//! validated parameters the step uses.

use crate::error::{in_range, positive, Allowed, ParamError};
use crate::math::sqrt;

/// How the balls sit in their grooves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
pub enum BallBearingKind {
    /// Deep-groove (radial) ball bearing: both grooves symmetric about the bearing's mid-plane,
    /// a diametral clearance, and a free contact angle that follows the axial displacement's
    /// sign (the ball meets either side of the groove).
    DeepGroove,
    /// Angular-contact ball bearing: the groove-curvature centres offset axially so that at
    /// zero clearance the ball touches both rings at the nominal contact angle; it carries
    /// thrust on the inner ring in +z only.
    AngularContact,
}

/// Everything that defines a ball bearing, as a configuration file gives it.
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
pub struct BallBearingDesign {
    /// Deep-groove or angular-contact.
    pub kind: BallBearingKind,
    /// Number of balls Z (must equal the const generic of [`super::BallBearing`]).
    pub ball_count: u16,
    /// Ball diameter D (m).
    pub ball_diameter_m: f32,
    /// Pitch diameter d_m (m).
    pub pitch_diameter_m: f32,
    /// Inner groove radius over the ball diameter, f_i = r_i/D (0.5 … 0.6).
    pub inner_groove_ratio: f32,
    /// Outer groove radius over the ball diameter, f_o = r_o/D (0.5 … 0.6).
    pub outer_groove_ratio: f32,
    /// Diametral clearance P_d of a deep-groove bearing (m, 0 … 100 µm); 0 for angular contact.
    pub diametral_clearance_m: f32,
    /// Nominal contact angle α₀ of an angular-contact bearing (rad, 5° … 60°); 0 for deep groove.
    pub nominal_contact_angle_rad: f32,
    /// Young's modulus of rings and balls (Pa).
    pub elastic_modulus_pa: f32,
    /// Poisson's ratio of rings and balls.
    pub poisson_ratio: f32,
    /// Density of the balls (kg/m³), for their centrifugal force.
    pub ball_density_kg_m3: f32,
    /// Lubricant viscosity at ambient pressure, η₀ (Pa·s).
    pub viscosity_pa_s: f32,
    /// Pressure–viscosity coefficient, α (1/Pa).
    pub pressure_viscosity_pa_inv: f32,
    /// Damping factor f_damp (s, 0 … 10⁻³): a loaded ball's contact damps with f_damp times
    /// its contact stiffness, as a roller does (docs/physics.md §4).
    pub damping_factor_s: f32,
    /// Include the balls' centrifugal force F_c = ½ m d_m ω_c² (high speed; the inner and outer
    /// contact angles and loads then differ). Off: the outputs are those of the model without it.
    pub centrifugal: bool,
}

impl BallBearingDesign {
    /// The deep-groove bearing 6205 (bore 25 mm, outside 52 mm, width 15 mm): 9 balls of
    /// 7.938 mm on a 39.04 mm pitch diameter, groove radii 0.52 and 0.53 D, 12 µm diametral
    /// clearance; steel (208 GPa, ν 0.3, 7850 kg/m³), oil η₀ = 0.08 Pa·s, α = 2.1·10⁻⁸ 1/Pa
    /// (`configs/deep_groove_6205.toml`).
    pub const DEEP_GROOVE_6205: BallBearingDesign = BallBearingDesign {
        kind: BallBearingKind::DeepGroove,
        ball_count: 9,
        ball_diameter_m: 7.938e-3,
        pitch_diameter_m: 39.04e-3,
        inner_groove_ratio: 0.52,
        outer_groove_ratio: 0.53,
        diametral_clearance_m: 12.0e-6,
        nominal_contact_angle_rad: 0.0,
        elastic_modulus_pa: 208.0e9,
        poisson_ratio: 0.3,
        ball_density_kg_m3: 7850.0,
        viscosity_pa_s: 0.08,
        pressure_viscosity_pa_inv: 2.1e-8,
        damping_factor_s: 1.0e-5,
        centrifugal: false,
    };

    /// The angular-contact bearing 7205 with a 40° contact angle (bore 25 mm, outside 52 mm,
    /// width 15 mm): 14 balls of 7.938 mm on a 38.5 mm pitch diameter, groove radii 0.52 and
    /// 0.53 D; materials and oil as [`Self::DEEP_GROOVE_6205`] (`configs/angular_7205.toml`).
    pub const ANGULAR_7205: BallBearingDesign = BallBearingDesign {
        kind: BallBearingKind::AngularContact,
        ball_count: 14,
        pitch_diameter_m: 38.5e-3,
        diametral_clearance_m: 0.0,
        nominal_contact_angle_rad: 40.0 * core::f32::consts::PI / 180.0,
        ..Self::DEEP_GROOVE_6205
    };

    /// Validate the design; each refusal names the field and its allowed range.
    pub fn params(&self) -> Result<BallBearingParams, ParamError> {
        let d = in_range("ball_diameter_m", self.ball_diameter_m, 1.0e-4, 0.2)?;
        let dm = positive("pitch_diameter_m", self.pitch_diameter_m)?;
        if dm <= 1.5 * d {
            return Err(ParamError {
                field: "pitch_diameter_m",
                value: dm,
                allowed: Allowed::Range {
                    min: 1.5 * d,
                    max: f32::MAX,
                },
            });
        }
        let fi = in_range("inner_groove_ratio", self.inner_groove_ratio, 0.505, 0.6)?;
        let fo = in_range("outer_groove_ratio", self.outer_groove_ratio, 0.505, 0.6)?;
        let modulus = in_range("elastic_modulus_pa", self.elastic_modulus_pa, 1.0e9, 1.0e12)?;
        let nu = in_range("poisson_ratio", self.poisson_ratio, 0.0, 0.5)?;
        let density = in_range(
            "ball_density_kg_m3",
            self.ball_density_kg_m3,
            100.0,
            20_000.0,
        )?;
        let eta = in_range("viscosity_pa_s", self.viscosity_pa_s, 1.0e-4, 10.0)?;
        let alpha = in_range(
            "pressure_viscosity_pa_inv",
            self.pressure_viscosity_pa_inv,
            0.0,
            1.0e-7,
        )?;
        let damping = in_range("damping_factor_s", self.damping_factor_s, 0.0, 1.0e-3)?;
        // A₀ = (f_i + f_o − 1) D, the distance of the groove-curvature centres when both
        // contacts just touch (Harris & Kotzalas 2007, vol. 1, §2.3).
        let centre_distance = (fi + fo - 1.0) * d;
        let (radial_offset, axial_offset, contact_angle) = match self.kind {
            BallBearingKind::DeepGroove => {
                in_range(
                    "nominal_contact_angle_rad",
                    self.nominal_contact_angle_rad,
                    0.0,
                    0.0,
                )?;
                let pd = in_range(
                    "diametral_clearance_m",
                    self.diametral_clearance_m,
                    0.0,
                    1.0e-4,
                )?;
                // Free contact angle cos α_f = 1 − P_d/(2A₀) (Harris & Kotzalas, vol. 1, eq. 2.10).
                let cos_free = 1.0 - pd / (2.0 * centre_distance);
                let angle = crate::math::atan2(sqrt(1.0 - cos_free * cos_free), cos_free);
                (centre_distance - 0.5 * pd, 0.0, angle)
            }
            BallBearingKind::AngularContact => {
                in_range(
                    "diametral_clearance_m",
                    self.diametral_clearance_m,
                    0.0,
                    0.0,
                )?;
                let a0 = in_range(
                    "nominal_contact_angle_rad",
                    self.nominal_contact_angle_rad,
                    5.0 * core::f32::consts::PI / 180.0,
                    60.0 * core::f32::consts::PI / 180.0,
                )?;
                let (s, c) = crate::math::sin_cos(a0);
                (centre_distance * c, centre_distance * s, a0)
            }
        };
        let (_, cos_nominal) = crate::math::sin_cos(contact_angle);
        let ball_volume = core::f32::consts::PI / 6.0 * d * d * d;
        Ok(BallBearingParams {
            kind: self.kind,
            ball_count: self.ball_count,
            ball_diameter_m: d,
            pitch_diameter_m: dm,
            inner_groove_ratio: fi,
            outer_groove_ratio: fo,
            centre_distance_m: centre_distance,
            unloaded_offset_m: [radial_offset, axial_offset],
            nominal_contact_angle_rad: contact_angle,
            inner_centre_radius_m: 0.5 * dm + (fi - 0.5) * d * cos_nominal,
            reduced_modulus_pa: modulus / (1.0 - nu * nu),
            ball_mass_kg: density * ball_volume,
            viscosity_pa_s: eta,
            pressure_viscosity_pa_inv: alpha,
            damping_factor_s: damping,
            centrifugal: self.centrifugal,
        })
    }
}

/// The validated parameters of a ball bearing, with the geometry the step derives from them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BallBearingParams {
    pub(super) kind: BallBearingKind,
    pub(super) ball_count: u16,
    pub(super) ball_diameter_m: f32,
    pub(super) pitch_diameter_m: f32,
    pub(super) inner_groove_ratio: f32,
    pub(super) outer_groove_ratio: f32,
    /// A₀ = (f_i + f_o − 1)D (m).
    pub(super) centre_distance_m: f32,
    /// Radial and axial distance from the outer to the inner groove-curvature centre of an
    /// unloaded ball with the rings centred (m).
    pub(super) unloaded_offset_m: [f32; 2],
    /// α₀: the free contact angle of a deep-groove bearing, the nominal one of an
    /// angular-contact bearing (rad).
    pub(super) nominal_contact_angle_rad: f32,
    /// R_i = d_m/2 + (f_i − 0.5)D cos α₀, the radius of the inner groove-curvature centres'
    /// locus, the lever arm of the ball loads' moments (m).
    pub(super) inner_centre_radius_m: f32,
    /// E' = E/(1 − ν²) for rings and balls of one material (Pa).
    pub(super) reduced_modulus_pa: f32,
    pub(super) ball_mass_kg: f32,
    pub(super) viscosity_pa_s: f32,
    pub(super) pressure_viscosity_pa_inv: f32,
    pub(super) damping_factor_s: f32,
    /// Whether the balls' centrifugal force is included.
    pub(super) centrifugal: bool,
}

impl BallBearingParams {
    /// Whether the balls' centrifugal force is included.
    pub fn centrifugal(&self) -> bool {
        self.centrifugal
    }
    /// The same bearing with the balls' centrifugal force switched on or off.
    pub fn with_centrifugal(self, centrifugal: bool) -> Self {
        Self {
            centrifugal,
            ..self
        }
    }
    /// Deep-groove or angular-contact.
    pub fn kind(&self) -> BallBearingKind {
        self.kind
    }
    /// Number of balls.
    pub fn ball_count(&self) -> u16 {
        self.ball_count
    }
    /// Ball diameter D (m).
    pub fn ball_diameter_m(&self) -> f32 {
        self.ball_diameter_m
    }
    /// Pitch diameter d_m (m).
    pub fn pitch_diameter_m(&self) -> f32 {
        self.pitch_diameter_m
    }
    /// A₀ = (f_i + f_o − 1)D, the groove-curvature centres' distance at first touch (m).
    pub fn centre_distance_m(&self) -> f32 {
        self.centre_distance_m
    }
    /// The free (deep-groove) or nominal (angular-contact) contact angle α₀ (rad).
    pub fn nominal_contact_angle_rad(&self) -> f32 {
        self.nominal_contact_angle_rad
    }
    /// R_i, the lever arm of the ball loads' moments (m).
    pub fn inner_centre_radius_m(&self) -> f32 {
        self.inner_centre_radius_m
    }
    /// E' (Pa).
    pub fn reduced_modulus_pa(&self) -> f32 {
        self.reduced_modulus_pa
    }
    /// Mass of one ball (kg).
    pub fn ball_mass_kg(&self) -> f32 {
        self.ball_mass_kg
    }
}
