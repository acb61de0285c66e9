//! Bearing configuration files (TOML): geometry, material, lubricant, model options and a
//! default operating case.
//!
//! Keys carry their SI unit (`pitch_diameter_m`). Every error names the file, the line and the
//! field: syntax and type errors come from the TOML parser with its location; values that the
//! core refuses (NaN, ≤ 0, D ≥ d_m, …) are traced back to the line of their key.

use std::fmt;
use std::path::{Path, PathBuf};

use bearing_core::film::corrections::{
    FilmCorrections, Starvation, ThermalCorrection, OIL_THERMAL_CONDUCTIVITY_W_PER_M_K,
    VG68_TEMPERATURE_VISCOSITY_PER_K,
};
use bearing_core::{BearingDesign, BearingParams, ContactLaw, FrictionDesign, ParamError};
use serde::{Deserialize, Serialize};

use crate::rolling::{MAX_ROLLERS, MIN_ROLLERS};
use crate::toml_lines::{self, TomlLines};

/// A bearing configuration as written in the file.
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct BearingConfig {
    /// Human-readable name.
    pub name: String,
    /// Geometry.
    pub geometry: GeometryConfig,
    /// Material of rings and rollers (both the same).
    pub material: MaterialConfig,
    /// Lubricant.
    pub lubricant: LubricantConfig,
    /// Model options.
    #[serde(default)]
    pub model: ModelConfig,
    /// Default operating case for the CLI.
    #[serde(default)]
    pub case: CaseConfig,
    /// High-speed film corrections (docs/physics.md §5.4); off unless switched on.
    #[serde(default)]
    pub film_corrections: FilmCorrectionsConfig,
    /// Friction model (docs/physics.md §8); every field optional, the core's defaults when
    /// absent.
    #[serde(default)]
    pub friction: FrictionConfig,
}

/// `[film_corrections]`: the thermal and starvation factors applied after the film model.
#[derive(Clone, Debug, Default, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct FilmCorrectionsConfig {
    /// Inlet shear heating (Gupta et al. 1992).
    #[serde(default)]
    pub thermal: bool,
    /// β (1/K): set in `[lubricant]`; here only if it equals that value.
    pub temperature_viscosity_per_k: Option<f32>,
    /// K (W/(m·K)): set in `[lubricant]`; here only if it equals that value.
    pub thermal_conductivity_w_per_m_k: Option<f32>,
    /// Limited inlet supply (Chevalier et al. 1998).
    #[serde(default)]
    pub starvation: bool,
    /// Inlet oil layer thickness h_oil (m); required with `starvation = true`.
    pub oil_layer_m: Option<f32>,
    /// The starvation model's transition exponent γ; required with `starvation = true`.
    pub starvation_exponent: Option<f32>,
}

/// An ISO VG 68 mineral oil's 0.034 1/K (docs/physics.md §5.4).
fn default_temperature_viscosity() -> f32 {
    VG68_TEMPERATURE_VISCOSITY_PER_K
}
/// 0.14 W/(m·K), a mineral oil's (docs/physics.md §5.4, §8.3).
fn default_conductivity() -> f32 {
    OIL_THERMAL_CONDUCTIVITY_W_PER_M_K
}

impl FilmCorrectionsConfig {
    /// The core's corrections with the oil's thermal properties of `lubricant`; the error names
    /// the first refused (or missing: value NaN) field.
    pub fn corrections(&self, lubricant: &LubricantConfig) -> Result<FilmCorrections, ParamError> {
        let thermal = if self.thermal {
            Some(ThermalCorrection::new(
                lubricant.temperature_viscosity_per_k,
                lubricant.thermal_conductivity_w_per_m_k,
            )?)
        } else {
            None
        };
        let starvation = if self.starvation {
            Some(Starvation::new(
                self.oil_layer_m.unwrap_or(f32::NAN),
                self.starvation_exponent.unwrap_or(f32::NAN),
            )?)
        } else {
            None
        };
        Ok(FilmCorrections {
            thermal,
            starvation,
        })
    }
}

/// `[geometry]`.
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct GeometryConfig {
    /// d_m (m).
    pub pitch_diameter_m: f32,
    /// D (m).
    pub roller_diameter_m: f32,
    /// Effective contact length l (m).
    pub roller_length_m: f32,
    /// Z.
    pub roller_count: u16,
    /// Radial clearance g_r per roller (m; negative = interference).
    pub radial_clearance_m: f32,
    /// Multiplier on the ISO/TS 16281 logarithmic crown (0 = straight roller).
    #[serde(default)]
    pub crown_scale: f32,
}

/// `[material]`.
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct MaterialConfig {
    /// E (Pa).
    pub elastic_modulus_pa: f32,
    /// ν (–).
    pub poisson_ratio: f32,
}

/// `[lubricant]`.
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct LubricantConfig {
    /// η₀ (Pa·s).
    pub viscosity_pa_s: f32,
    /// α (1/Pa).
    pub pressure_viscosity_pa_inv: f32,
    /// ρ₀ (kg/m³).
    pub density_kg_m3: f32,
    /// β of η = η₀·e^(−β(T − T₀)) (1/K): the film's thermal correction (docs/physics.md §5.4)
    /// and the friction's thermal traction and rolling resistance (§8.3) both use it.
    #[serde(default = "default_temperature_viscosity")]
    pub temperature_viscosity_per_k: f32,
    /// The oil's thermal conductivity K (W/(m·K)), for the same two.
    #[serde(default = "default_conductivity")]
    pub thermal_conductivity_w_per_m_k: f32,
}

/// `[model]`.
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ModelConfig {
    /// `"palmgren"` (default) or `"lundberg"`.
    #[serde(default = "default_law")]
    pub contact_law: String,
    /// f_damp (s).
    #[serde(default = "default_damping")]
    pub damping_factor_s: f32,
    /// The rollers' centrifugal force on the outer race (docs/physics.md §4.1).
    #[serde(default)]
    pub centrifugal: bool,
    /// Roller density ρ (kg/m³) of the centrifugal force.
    #[serde(default = "default_roller_density")]
    pub roller_density_kg_m3: f32,
}

fn default_law() -> String {
    "palmgren".into()
}
fn default_damping() -> f32 {
    1.0e-5
}
fn default_roller_density() -> f32 {
    bearing_core::bearing::STEEL_DENSITY_KG_M3
}

impl Default for ModelConfig {
    fn default() -> Self {
        Self {
            contact_law: default_law(),
            damping_factor_s: default_damping(),
            centrifugal: false,
            roller_density_kg_m3: default_roller_density(),
        }
    }
}

/// `[case]`: defaults for the CLI.
#[derive(Clone, Debug, Default, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct CaseConfig {
    /// Radial load on the inner race (N).
    pub radial_load_n: Option<f32>,
    /// Shaft speed (rpm).
    pub speed_rpm: Option<f32>,
}

/// `[friction]`: the fields of the core's [`FrictionDesign`], each defaulting to
/// [`FrictionDesign::DEFAULT`].
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
#[serde(default, deny_unknown_fields)]
pub struct FrictionConfig {
    /// σ (m).
    pub composite_roughness_m: f32,
    /// η_s (1/m²).
    pub asperity_density_m2: f32,
    /// β (m).
    pub summit_radius_m: f32,
    /// τ_b (Pa).
    pub boundary_shear_strength_pa: f32,
    /// ζ (–).
    pub boundary_friction_coefficient: f32,
    /// τ₀ (Pa).
    pub eyring_stress_pa: f32,
    /// β_T (1/K): set in `[lubricant]` (`temperature_viscosity_per_k`); here only if it equals
    /// that value.
    pub viscosity_temperature_coefficient_k_inv: Option<f32>,
    /// K (W/(m·K)): set in `[lubricant]` (`thermal_conductivity_w_per_m_k`); here only if it
    /// equals that value.
    pub fluid_conductivity_w_mk: Option<f32>,
    /// K′ (W/(m·K)).
    pub solid_conductivity_w_mk: f32,
    /// ρ′ (kg/m³).
    pub solid_density_kg_m3: f32,
    /// c′ (J/(kg·K)).
    pub solid_heat_capacity_j_kgk: f32,
    /// s (–).
    pub slide_to_roll_ratio: f32,
}

impl Default for FrictionConfig {
    fn default() -> Self {
        let d = FrictionDesign::DEFAULT;
        Self {
            composite_roughness_m: d.composite_roughness_m,
            asperity_density_m2: d.asperity_density_m2,
            summit_radius_m: d.summit_radius_m,
            boundary_shear_strength_pa: d.boundary_shear_strength_pa,
            boundary_friction_coefficient: d.boundary_friction_coefficient,
            eyring_stress_pa: d.eyring_stress_pa,
            viscosity_temperature_coefficient_k_inv: None,
            fluid_conductivity_w_mk: None,
            solid_conductivity_w_mk: d.solid_conductivity_w_mk,
            solid_density_kg_m3: d.solid_density_kg_m3,
            solid_heat_capacity_j_kgk: d.solid_heat_capacity_j_kgk,
            slide_to_roll_ratio: d.slide_to_roll_ratio,
        }
    }
}

impl FrictionConfig {
    /// The table as the core's [`FrictionDesign`], with the oil's thermal properties of
    /// `lubricant`.
    pub fn design(&self, lubricant: &LubricantConfig) -> FrictionDesign {
        FrictionDesign {
            composite_roughness_m: self.composite_roughness_m,
            asperity_density_m2: self.asperity_density_m2,
            summit_radius_m: self.summit_radius_m,
            boundary_shear_strength_pa: self.boundary_shear_strength_pa,
            boundary_friction_coefficient: self.boundary_friction_coefficient,
            eyring_stress_pa: self.eyring_stress_pa,
            viscosity_temperature_coefficient_k_inv: lubricant.temperature_viscosity_per_k,
            fluid_conductivity_w_mk: lubricant.thermal_conductivity_w_per_m_k,
            solid_conductivity_w_mk: self.solid_conductivity_w_mk,
            solid_density_kg_m3: self.solid_density_kg_m3,
            solid_heat_capacity_j_kgk: self.solid_heat_capacity_j_kgk,
            slide_to_roll_ratio: self.slide_to_roll_ratio,
        }
    }
}

/// The values of `[model] contact_law`.
pub const CONTACT_LAWS: [&str; 2] = ["palmgren", "lundberg"];

/// A configuration that could not be read or was refused.
#[derive(Debug)]
pub struct ConfigError {
    /// The file.
    pub path: PathBuf,
    /// 1-based line, when known.
    pub line: Option<usize>,
    /// The field, when known.
    pub field: Option<String>,
    /// What is wrong.
    pub message: String,
}

impl fmt::Display for ConfigError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.path.display())?;
        if let Some(line) = self.line {
            write!(f, ":{line}")?;
        }
        if let Some(field) = &self.field {
            write!(f, ": field `{field}`")?;
        }
        write!(f, ": {}", self.message)
    }
}

impl std::error::Error for ConfigError {}

/// The text of the configuration file `path`, or an error naming it.
pub(crate) fn read_config(path: &Path) -> Result<String, ConfigError> {
    std::fs::read_to_string(path).map_err(|e| ConfigError {
        path: path.to_owned(),
        line: None,
        field: None,
        message: format!("cannot read: {e}"),
    })
}

/// A configuration table deserialized from `text`; a syntax or type error is located by the
/// line and key the TOML parser points at (`path` is only used in errors).
pub(crate) fn deserialize_config<T: serde::de::DeserializeOwned>(
    text: &str,
    path: &Path,
) -> Result<T, ConfigError> {
    toml::from_str(text).map_err(|e| {
        let line = e.span().map(|s| toml_lines::line_at(text, s.start));
        ConfigError {
            path: path.to_owned(),
            line,
            field: line.and_then(|l| toml_lines::key_on_line(text, l)),
            message: e.message().trim().to_owned(),
        }
    })
}

impl BearingConfig {
    /// Read and validate a configuration file.
    pub fn load(path: &Path) -> Result<(Self, BearingParams), ConfigError> {
        Self::parse(&read_config(path)?, path)
    }

    /// Parse and validate configuration `text`; `path` is only used in errors.
    pub fn parse(text: &str, path: &Path) -> Result<(Self, BearingParams), ConfigError> {
        let config: BearingConfig = deserialize_config(text, path)?;
        let lines = TomlLines::new(text);
        let law = config.model.contact_law.as_str();
        if !CONTACT_LAWS.contains(&law) {
            return Err(ConfigError {
                path: path.to_owned(),
                line: lines.line_in_table("model", 0, "contact_law"),
                field: Some("contact_law".into()),
                message: format!(
                    "contact_law = {law:?} is not allowed: it must be one of {}",
                    CONTACT_LAWS.map(|l| format!("{l:?}")).join(", ")
                ),
            });
        }
        config.check_thermal_properties(&lines, path)?;
        let params = config.params().map_err(|e| {
            // The core's friction names the oil's properties by its own fields; the file sets
            // them in `[lubricant]`.
            let field = match e.field {
                "viscosity_temperature_coefficient_k_inv" => "temperature_viscosity_per_k",
                "fluid_conductivity_w_mk" => "thermal_conductivity_w_per_m_k",
                other => other,
            };
            ConfigError {
                path: path.to_owned(),
                line: lines.line_of_key(field),
                field: Some(field.to_owned()),
                message: e.to_string(),
            }
        })?;
        Ok((config, params))
    }

    /// Refuses a copy of the oil's β or K in `[friction]` or `[film_corrections]` that differs
    /// from `[lubricant]`, the one source of both, naming its line and field.
    fn check_thermal_properties(&self, lines: &TomlLines, path: &Path) -> Result<(), ConfigError> {
        let l = &self.lubricant;
        let copies = [
            (
                "friction",
                "viscosity_temperature_coefficient_k_inv",
                self.friction.viscosity_temperature_coefficient_k_inv,
                "temperature_viscosity_per_k",
                l.temperature_viscosity_per_k,
            ),
            (
                "friction",
                "fluid_conductivity_w_mk",
                self.friction.fluid_conductivity_w_mk,
                "thermal_conductivity_w_per_m_k",
                l.thermal_conductivity_w_per_m_k,
            ),
            (
                "film_corrections",
                "temperature_viscosity_per_k",
                self.film_corrections.temperature_viscosity_per_k,
                "temperature_viscosity_per_k",
                l.temperature_viscosity_per_k,
            ),
            (
                "film_corrections",
                "thermal_conductivity_w_per_m_k",
                self.film_corrections.thermal_conductivity_w_per_m_k,
                "thermal_conductivity_w_per_m_k",
                l.thermal_conductivity_w_per_m_k,
            ),
        ];
        for (table, key, copy, source_key, source) in copies {
            if let Some(v) = copy.filter(|&v| v != source) {
                return Err(ConfigError {
                    path: path.to_owned(),
                    line: lines.line_in_table(table, 0, key),
                    field: Some(key.to_owned()),
                    message: format!(
                        "[{table}] {key} = {v} differs from [lubricant] {source_key} = {source}: \
                             the oil's thermal properties are set once, in [lubricant] (remove \
                             this key or give it the same value)"
                    ),
                });
            }
        }
        Ok(())
    }

    /// The file's fields as the core's [`BearingDesign`] (the contact law's name checked; the
    /// values are checked by [`BearingDesign::params`]).
    pub fn design(&self) -> Result<BearingDesign, ParamError> {
        let g = &self.geometry;
        let l = &self.lubricant;
        let contact_law = match self.model.contact_law.as_str() {
            "palmgren" => ContactLaw::Palmgren,
            "lundberg" => ContactLaw::Lundberg,
            _ => {
                return Err(ParamError {
                    field: "contact_law",
                    value: f32::NAN,
                    allowed: bearing_core::Allowed::Finite,
                })
            }
        };
        Ok(BearingDesign {
            pitch_diameter_m: g.pitch_diameter_m,
            roller_diameter_m: g.roller_diameter_m,
            roller_length_m: g.roller_length_m,
            roller_count: g.roller_count,
            radial_clearance_m: g.radial_clearance_m,
            crown_scale: g.crown_scale,
            elastic_modulus_pa: self.material.elastic_modulus_pa,
            poisson_ratio: self.material.poisson_ratio,
            viscosity_pa_s: l.viscosity_pa_s,
            pressure_viscosity_pa_inv: l.pressure_viscosity_pa_inv,
            density_kg_m3: l.density_kg_m3,
            contact_law,
            damping_factor_s: self.model.damping_factor_s,
        })
    }

    /// The core parameters: the file's fields as the core's [`BearingDesign`], validated by
    /// it (the first refused field is named).
    pub fn params(&self) -> Result<BearingParams, ParamError> {
        let params = self
            .design()?
            .params()?
            .with_film_corrections(self.film_corrections.corrections(&self.lubricant)?)
            .with_friction(self.friction.design(&self.lubricant).params()?);
        let params = if self.model.centrifugal {
            params.with_centrifugal_force(self.model.roller_density_kg_m3)?
        } else {
            params
        };
        // The core's geometry takes up to 128 rollers; the host's run-time bearing (`rolling`)
        // is compiled for MIN_ROLLERS ..= MAX_ROLLERS, so a count outside it would be refused
        // later, far from the file.
        let count = self.geometry.roller_count;
        if !(MIN_ROLLERS..=MAX_ROLLERS).contains(&count) {
            return Err(ParamError {
                field: "roller_count",
                value: f32::from(count),
                allowed: bearing_core::Allowed::Range {
                    min: f32::from(MIN_ROLLERS),
                    max: f32::from(MAX_ROLLERS),
                },
            });
        }
        if let Some(v) = self.case.radial_load_n {
            if !(v.is_finite() && v >= 0.0) {
                return Err(ParamError {
                    field: "radial_load_n",
                    value: v,
                    allowed: bearing_core::Allowed::Range {
                        min: 0.0,
                        max: f32::MAX,
                    },
                });
            }
        }
        if let Some(v) = self.case.speed_rpm {
            if !v.is_finite() || v.abs() > 900_000.0 {
                return Err(ParamError {
                    field: "speed_rpm",
                    value: v,
                    allowed: bearing_core::Allowed::Range {
                        min: -900_000.0,
                        max: 900_000.0,
                    },
                });
            }
        }
        Ok(params)
    }
}

#[cfg(test)]
#[path = "config_tests.rs"]
mod tests;
