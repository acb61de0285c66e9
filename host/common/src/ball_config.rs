//! Ball-bearing configuration files (TOML): a `[ball]` table in place of the roller bearing's
//! `[geometry]`, with the same `[material]`, `[lubricant]`, `[model]` and `[case]` tables, and
//! a run-time ball count over the core's const-generic [`BallBearing`].
//!
//! Keys carry their unit; every refusal names the file, the line and the field, as
//! [`crate::config`] does for roller bearings.

use std::path::Path;

use bearing_core::bearing::ball::{
    BallBearing, BallBearingDesign, BallBearingKind, BallBearingOutput, BallBearingParams,
    BallBearingState, BallFilm, BallLoad, BallOutput, StaticSolveError,
};
use bearing_core::ParamError;
use serde::{Deserialize, Serialize};

use crate::config::{deserialize_config, read_config, ConfigError};
use crate::toml_lines::TomlLines;

/// Whether the configuration `text` describes a ball bearing (it has a `[ball]` table).
pub fn is_ball_config(text: &str) -> bool {
    toml::from_str::<toml::Table>(text).is_ok_and(|t| t.contains_key("ball"))
}

/// A ball-bearing configuration as written in the file.
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct BallBearingConfig {
    /// Name shown in reports.
    pub name: String,
    /// Geometry.
    pub ball: BallConfig,
    /// Rings and balls.
    pub material: BallMaterialConfig,
    /// Oil.
    pub lubricant: BallLubricantConfig,
    /// Model options.
    #[serde(default)]
    pub model: BallModelConfig,
    /// Default operating case of the commands.
    #[serde(default)]
    pub case: BallCaseConfig,
    /// High-speed options.
    #[serde(default)]
    pub high_speed: BallHighSpeedConfig,
}

/// `[high_speed]`.
#[derive(Clone, Debug, Default, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct BallHighSpeedConfig {
    /// The balls' centrifugal force (inner and outer contact angles and loads then differ);
    /// off when absent.
    #[serde(default)]
    pub centrifugal: bool,
}

/// `[ball]`: the geometry.
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct BallConfig {
    /// `"deep_groove"` or `"angular_contact"`.
    pub kind: BallBearingKind,
    /// Number of balls.
    pub ball_count: u16,
    /// Ball diameter D (m).
    pub ball_diameter_m: f32,
    /// Pitch diameter d_m (m).
    pub pitch_diameter_m: f32,
    /// Inner groove radius / D.
    pub inner_groove_ratio: f32,
    /// Outer groove radius / D.
    pub outer_groove_ratio: f32,
    /// Diametral clearance of a deep-groove bearing (m).
    #[serde(default)]
    pub diametral_clearance_m: f32,
    /// Nominal contact angle of an angular-contact bearing (degrees).
    #[serde(default)]
    pub nominal_contact_angle_deg: f32,
}

/// `[material]`.
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct BallMaterialConfig {
    /// Young's modulus (Pa).
    pub elastic_modulus_pa: f32,
    /// Poisson's ratio.
    pub poisson_ratio: f32,
    /// Density of the balls (kg/m³).
    #[serde(default = "steel_density")]
    pub density_kg_m3: f32,
}

fn steel_density() -> f32 {
    bearing_core::bearing::STEEL_DENSITY_KG_M3
}

/// `[lubricant]`.
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct BallLubricantConfig {
    /// η₀ (Pa·s).
    pub viscosity_pa_s: f32,
    /// α (1/Pa).
    pub pressure_viscosity_pa_inv: f32,
    /// Oil density (kg/m³; not used by the ball model yet).
    #[serde(default)]
    pub density_kg_m3: Option<f32>,
}

/// `[model]`.
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct BallModelConfig {
    /// f_damp (s).
    #[serde(default = "default_damping")]
    pub damping_factor_s: f32,
}

fn default_damping() -> f32 {
    1.0e-5
}

impl Default for BallModelConfig {
    fn default() -> Self {
        Self {
            damping_factor_s: default_damping(),
        }
    }
}

/// `[case]`: the commands' default load and speed.
#[derive(Clone, Debug, Default, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct BallCaseConfig {
    /// Radial load (N).
    pub radial_load_n: Option<f32>,
    /// Axial load in +z (N).
    pub axial_load_n: Option<f32>,
    /// Shaft speed (rpm).
    pub speed_rpm: Option<f32>,
}

/// Smallest and largest ball count the host's run-time dispatch builds.
pub const BALL_COUNT_RANGE: (u16, u16) = (3, 40);

impl BallBearingConfig {
    /// Read and validate a ball-bearing configuration file.
    pub fn load(path: &Path) -> Result<(Self, BallBearingParams), ConfigError> {
        Self::parse(&read_config(path)?, path)
    }

    /// Parse and validate configuration `text`; `path` is only used in errors.
    pub fn parse(text: &str, path: &Path) -> Result<(Self, BallBearingParams), ConfigError> {
        let config: BallBearingConfig = deserialize_config(text, path)?;
        let lines = TomlLines::new(text);
        let located = |table: &str, key: &str, message: String| ConfigError {
            path: path.to_owned(),
            line: lines.line_in_table(table, 0, key),
            field: Some(key.to_owned()),
            message,
        };
        let (lo, hi) = BALL_COUNT_RANGE;
        let count = config.ball.ball_count;
        if !(lo..=hi).contains(&count) {
            return Err(located(
                "ball",
                "ball_count",
                format!("ball_count = {count} is not allowed: it must lie in [{lo}, {hi}]"),
            ));
        }
        let params = config.design().params().map_err(|e| {
            // The core names two fields differently from the file.
            let (table, key) = match e.field {
                "nominal_contact_angle_rad" => ("ball", "nominal_contact_angle_deg"),
                "ball_density_kg_m3" => ("material", "density_kg_m3"),
                "elastic_modulus_pa" | "poisson_ratio" => ("material", e.field),
                "viscosity_pa_s" | "pressure_viscosity_pa_inv" => ("lubricant", e.field),
                "damping_factor_s" => ("model", e.field),
                other => ("ball", other),
            };
            let message = if e.field == "nominal_contact_angle_rad" {
                ParamError {
                    field: "nominal_contact_angle_deg",
                    value: e.value.to_degrees(),
                    allowed: match e.allowed {
                        bearing_core::Allowed::Range { min, max } => bearing_core::Allowed::Range {
                            min: (min.to_degrees() * 1e3).round() / 1e3,
                            max: (max.to_degrees() * 1e3).round() / 1e3,
                        },
                        other => other,
                    },
                }
                .to_string()
            } else {
                e.to_string()
            };
            located(table, key, message)
        })?;
        Ok((config, params))
    }

    /// The file's fields as the core's design.
    pub fn design(&self) -> BallBearingDesign {
        let b = &self.ball;
        BallBearingDesign {
            kind: b.kind,
            ball_count: b.ball_count,
            ball_diameter_m: b.ball_diameter_m,
            pitch_diameter_m: b.pitch_diameter_m,
            inner_groove_ratio: b.inner_groove_ratio,
            outer_groove_ratio: b.outer_groove_ratio,
            diametral_clearance_m: b.diametral_clearance_m,
            nominal_contact_angle_rad: b.nominal_contact_angle_deg.to_radians(),
            elastic_modulus_pa: self.material.elastic_modulus_pa,
            poisson_ratio: self.material.poisson_ratio,
            ball_density_kg_m3: self.material.density_kg_m3,
            viscosity_pa_s: self.lubricant.viscosity_pa_s,
            pressure_viscosity_pa_inv: self.lubricant.pressure_viscosity_pa_inv,
            damping_factor_s: self.model.damping_factor_s,
            centrifugal: self.high_speed.centrifugal,
        }
    }
}

/// A ball bearing's result with its balls in a `Vec`, whatever the ball count.
#[derive(Clone, Debug, PartialEq)]
pub struct BallResult {
    /// (x, y, z, θ_x, θ_y) (m, rad).
    pub displacement: [f32; 5],
    /// Applied load [F_x, F_y, F_z, M_x, M_y] that the displacement balances (N, N·m).
    pub applied_load: [f32; 5],
    /// d applied_load / d displacement (SI).
    pub stiffness: [[f32; 5]; 5],
    /// Damping (SI).
    pub damping: [[f32; 5]; 5],
    /// Cage speed (rad/s).
    pub cage_speed_rad_s: f32,
    /// Newton steps of the static solve (0 for a forward evaluation).
    pub iterations: usize,
    /// Per ball.
    pub balls: Vec<BallOutput>,
}

impl BallResult {
    fn new<const Z: usize>(
        displacement: [f32; 5],
        out: &BallBearingOutput<Z>,
        iterations: usize,
    ) -> Self {
        Self {
            displacement,
            applied_load: out.applied_load(),
            stiffness: out.stiffness,
            damping: out.damping,
            cage_speed_rad_s: out.cage_speed_rad_s,
            iterations,
            balls: out.balls.to_vec(),
        }
    }
}

/// What to compute: the static solve of a load, or the forward map of a state.
#[derive(Clone, Copy, Debug)]
pub enum BallQuery {
    /// Loads → displacement.
    Static(BallLoad),
    /// Displacement → loads.
    Evaluate(BallBearingState),
}

/// A ball query refused: bad parameters or state, or no equilibrium.
pub type BallError = StaticSolveError;

fn answer<const Z: usize>(
    params: BallBearingParams,
    film: BallFilm,
    query: &BallQuery,
) -> Result<BallResult, BallError> {
    let bearing = BallBearing::<Z>::new(params, film)?;
    match query {
        BallQuery::Static(load) => {
            let s = bearing.solve_static(load)?;
            Ok(BallResult::new(s.displacement, &s.output, s.iterations))
        }
        BallQuery::Evaluate(state) => {
            let out = bearing.evaluate(state)?;
            Ok(BallResult::new(state.displacement, &out, 0))
        }
    }
}

macro_rules! dispatch {
    ($count:expr, $params:expr, $film:expr, $query:expr; $($z:literal)*) => {
        match $count {
            $($z => answer::<$z>($params, $film, $query),)*
            other => Err(StaticSolveError::Param(ParamError {
                field: "ball_count",
                value: f32::from(other),
                allowed: bearing_core::Allowed::Range {
                    min: f32::from(BALL_COUNT_RANGE.0),
                    max: f32::from(BALL_COUNT_RANGE.1),
                },
            })),
        }
    };
}

/// Answer `query` for the bearing `params` with `film`, at its run-time ball count.
pub fn ball_query(
    params: BallBearingParams,
    film: BallFilm,
    query: &BallQuery,
) -> Result<BallResult, BallError> {
    dispatch!(params.ball_count(), params, film, query;
        3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29 30
        31 32 33 34 35 36 37 38 39 40)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bundled(name: &str) -> std::path::PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../configs")
            .join(name)
    }

    /// The bundled configs give the core's presets exactly.
    #[test]
    fn bundled_configs_are_the_presets() {
        for (file, preset) in [
            ("deep_groove_6205.toml", BallBearingDesign::DEEP_GROOVE_6205),
            ("angular_7205.toml", BallBearingDesign::ANGULAR_7205),
        ] {
            let path = bundled(file);
            let text = std::fs::read_to_string(&path).unwrap();
            assert!(is_ball_config(&text), "{file}");
            let (config, params) = BallBearingConfig::load(&path).unwrap();
            let design = config.design();
            // Degrees in the file, radians in the preset: equal to f32 rounding.
            let angle = design.nominal_contact_angle_rad;
            assert!((angle - preset.nominal_contact_angle_rad).abs() < 1e-6);
            let preset = BallBearingDesign {
                nominal_contact_angle_rad: angle,
                ..preset
            };
            assert_eq!(design, preset, "{file}");
            assert_eq!(params, preset.params().unwrap());
        }
        let roller = std::fs::read_to_string(bundled("hub_motor.toml")).unwrap();
        assert!(!is_ball_config(&roller));
    }

    /// A refused value names the file, its line and the field in the file's own terms.
    #[test]
    fn refusals_name_line_and_field() {
        let text = std::fs::read_to_string(bundled("angular_7205.toml"))
            .unwrap()
            .replace(
                "nominal_contact_angle_deg = 40.0",
                "nominal_contact_angle_deg = 75.0",
            );
        let e = BallBearingConfig::parse(&text, Path::new("a.toml")).unwrap_err();
        assert_eq!(e.field.as_deref(), Some("nominal_contact_angle_deg"));
        let line = text
            .lines()
            .position(|l| l.starts_with("nominal_contact_angle_deg"))
            .unwrap()
            + 1;
        assert_eq!(e.line, Some(line));
        assert!(e.message.contains("[5, 60]"), "{}", e.message);
        let text = std::fs::read_to_string(bundled("deep_groove_6205.toml"))
            .unwrap()
            .replace("ball_count = 9", "ball_count = 90");
        let e = BallBearingConfig::parse(&text, Path::new("b.toml")).unwrap_err();
        assert_eq!(e.field.as_deref(), Some("ball_count"));
    }

    /// The run-time dispatch answers as the const-generic bearing does.
    #[test]
    fn dispatch_matches_the_generic_bearing() {
        let params = BallBearingDesign::DEEP_GROOVE_6205.params().unwrap();
        let state = BallBearingState::at([1e-6, -15e-6, 2e-6, 0.0, 0.0], 1000.0);
        let dynamic =
            ball_query(params, BallFilm::NetworkInt, &BallQuery::Evaluate(state)).unwrap();
        let generic = BallBearing::<9>::new(params, BallFilm::NetworkInt)
            .unwrap()
            .evaluate(&state)
            .unwrap();
        assert_eq!(dynamic.applied_load, generic.applied_load());
        assert_eq!(dynamic.balls, generic.balls.to_vec());
    }
}
