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
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct FilmCorrectionsConfig {
    /// Inlet shear heating (Gupta et al. 1992).
    #[serde(default)]
    pub thermal: bool,
    /// β of η = η₀·e^(−β(T − T₀)) (1/K).
    #[serde(default = "default_temperature_viscosity")]
    pub temperature_viscosity_per_k: f32,
    /// Oil thermal conductivity K (W/(m·K)).
    #[serde(default = "default_conductivity")]
    pub thermal_conductivity_w_per_m_k: f32,
    /// Limited inlet supply (Chevalier et al. 1998).
    #[serde(default)]
    pub starvation: bool,
    /// Inlet oil layer thickness h_oil (m); required with `starvation = true`.
    pub oil_layer_m: Option<f32>,
    /// The starvation model's transition exponent γ; required with `starvation = true`.
    pub starvation_exponent: Option<f32>,
}

fn default_temperature_viscosity() -> f32 {
    VG68_TEMPERATURE_VISCOSITY_PER_K
}
fn default_conductivity() -> f32 {
    OIL_THERMAL_CONDUCTIVITY_W_PER_M_K
}

impl Default for FilmCorrectionsConfig {
    fn default() -> Self {
        Self {
            thermal: false,
            temperature_viscosity_per_k: default_temperature_viscosity(),
            thermal_conductivity_w_per_m_k: default_conductivity(),
            starvation: false,
            oil_layer_m: None,
            starvation_exponent: None,
        }
    }
}

impl FilmCorrectionsConfig {
    /// The core's corrections; the error names the first refused (or missing: value NaN) field.
    pub fn corrections(&self) -> Result<FilmCorrections, ParamError> {
        let thermal = if self.thermal {
            Some(ThermalCorrection::new(
                self.temperature_viscosity_per_k,
                self.thermal_conductivity_w_per_m_k,
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
    /// β_T (1/K).
    pub viscosity_temperature_coefficient_k_inv: f32,
    /// K (W/(m·K)).
    pub fluid_conductivity_w_mk: f32,
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
            viscosity_temperature_coefficient_k_inv: d.viscosity_temperature_coefficient_k_inv,
            fluid_conductivity_w_mk: d.fluid_conductivity_w_mk,
            solid_conductivity_w_mk: d.solid_conductivity_w_mk,
            solid_density_kg_m3: d.solid_density_kg_m3,
            solid_heat_capacity_j_kgk: d.solid_heat_capacity_j_kgk,
            slide_to_roll_ratio: d.slide_to_roll_ratio,
        }
    }
}

impl FrictionConfig {
    /// The table as the core's [`FrictionDesign`].
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

impl BearingConfig {
    /// Read and validate a configuration file.
    pub fn load(path: &Path) -> Result<(Self, BearingParams), ConfigError> {
        let text = std::fs::read_to_string(path).map_err(|e| ConfigError {
            path: path.to_owned(),
            line: None,
            field: None,
            message: format!("cannot read: {e}"),
        })?;
        Self::parse(&text, path)
    }

    /// Parse and validate configuration `text`; `path` is only used in errors.
    pub fn parse(text: &str, path: &Path) -> Result<(Self, BearingParams), ConfigError> {
        let config: BearingConfig = toml::from_str(text).map_err(|e| {
            let line = e.span().map(|s| toml_lines::line_at(text, s.start));
            ConfigError {
                path: path.to_owned(),
                line,
                field: line.and_then(|l| toml_lines::key_on_line(text, l)),
                message: e.message().trim().to_owned(),
            }
        })?;
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
        let params = config.params().map_err(|e| ConfigError {
            path: path.to_owned(),
            line: lines.line_of_key(e.field),
            field: Some(e.field.to_owned()),
            message: e.to_string(),
        })?;
        Ok((config, params))
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
            .with_film_corrections(self.film_corrections.corrections()?)
            .with_friction(self.friction.design().params()?);
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
mod tests {
    use super::*;

    fn bundled(name: &str) -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../configs")
            .join(name)
    }

    #[test]
    fn bundled_configs_load() {
        for name in ["hub_motor.toml", "nu205.toml", "static_check.toml"] {
            let (c, p) = BearingConfig::load(&bundled(name)).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(p.geometry().roller_count(), c.geometry.roller_count);
        }
    }

    #[test]
    fn refused_value_names_file_line_and_field() {
        let text = std::fs::read_to_string(bundled("hub_motor.toml")).unwrap();
        let bad = text.replace("roller_diameter_m = 0.0088", "roller_diameter_m = 0.07");
        let e = BearingConfig::parse(&bad, Path::new("bad.toml")).unwrap_err();
        let expected_line = bad
            .lines()
            .position(|l| l.starts_with("roller_diameter_m"))
            .unwrap()
            + 1;
        assert_eq!(e.line, Some(expected_line));
        assert_eq!(e.field.as_deref(), Some("roller_diameter_m"));
        let shown = e.to_string();
        assert!(
            shown.starts_with(&format!(
                "bad.toml:{expected_line}: field `roller_diameter_m`"
            )),
            "{shown}"
        );
        assert!(shown.contains("pitch_diameter_m"), "{shown}");
    }

    #[test]
    fn friction_table_is_optional_and_its_values_are_checked() {
        let text = std::fs::read_to_string(bundled("nu205.toml")).unwrap();
        let (_, params) = BearingConfig::parse(&text, Path::new("nu205.toml")).unwrap();
        assert_eq!(*params.friction(), bearing_core::FrictionParams::DEFAULT);
        let rough = format!("{text}\n[friction]\ncomposite_roughness_m = 0.3e-6\n");
        let (_, params) = BearingConfig::parse(&rough, Path::new("rough.toml")).unwrap();
        assert_eq!(params.friction().composite_roughness_m(), 0.3e-6);
        // An oil's conductivity of 1600 W/(m·K) (a metal's order) is refused at its line.
        let bad = format!("{text}\n[friction]\nfluid_conductivity_w_mk = 1600.0\n");
        let e = BearingConfig::parse(&bad, Path::new("bad.toml")).unwrap_err();
        assert_eq!(e.line, Some(line_of(&bad, "fluid_conductivity_w_mk")));
        assert_eq!(e.field.as_deref(), Some("fluid_conductivity_w_mk"));
        assert!(e.to_string().contains("[0.01, 10]"), "{e}");
    }

    /// The line of `prefix…` in `text` (1-based).
    fn line_of(text: &str, prefix: &str) -> usize {
        text.lines().position(|l| l.starts_with(prefix)).unwrap() + 1
    }

    /// The high-speed switches reach the core's parameters (off in `hub_motor.toml`, on in
    /// `hub_motor_high_speed.toml`), and a refused value names its line and field.
    #[test]
    fn high_speed_switches_reach_the_params_and_bad_values_are_located() {
        let (_, plain) = BearingConfig::load(&bundled("hub_motor.toml")).unwrap();
        assert!(plain.film_corrections().is_off());
        assert_eq!(plain.centrifugal_force_n(2199.0), None);
        let text = std::fs::read_to_string(bundled("hub_motor_high_speed.toml")).unwrap();
        let (_, on) = BearingConfig::parse(&text, Path::new("h.toml")).unwrap();
        let c = on.film_corrections();
        assert!(c.thermal.is_some() && c.starvation.is_some());
        assert!(on.centrifugal_force_n(2199.0).unwrap() > 180.0);
        for (key, bad) in [
            ("oil_layer_m", "oil_layer_m = -1.0"),
            (
                "thermal_conductivity_w_per_m_k",
                "thermal_conductivity_w_per_m_k = 0.0",
            ),
            ("roller_density_kg_m3", "roller_density_kg_m3 = 1.0e9"),
        ] {
            let original = text.lines().find(|l| l.starts_with(key)).unwrap();
            let bad_text = text.replace(original, bad);
            let e = BearingConfig::parse(&bad_text, Path::new("h.toml")).unwrap_err();
            assert_eq!(e.line, Some(line_of(&bad_text, key)), "{e}");
            assert_eq!(e.field.as_deref(), Some(key), "{e}");
        }
    }

    #[test]
    fn an_unknown_contact_law_is_named_with_the_laws_allowed() {
        let text = std::fs::read_to_string(bundled("hub_motor.toml")).unwrap();
        let bad = text.replace("contact_law = \"palmgren\"", "contact_law = \"hertz\"");
        let e = BearingConfig::parse(&bad, Path::new("c.toml")).unwrap_err();
        assert_eq!(e.line, Some(line_of(&bad, "contact_law")));
        let shown = e.to_string();
        assert!(shown.contains("\"hertz\""), "{shown}");
        assert!(shown.contains("\"palmgren\", \"lundberg\""), "{shown}");
        assert!(!shown.contains("NaN"), "{shown}");
    }

    #[test]
    fn a_roller_count_the_host_cannot_step_is_refused_at_load_with_its_line() {
        let text = std::fs::read_to_string(bundled("hub_motor.toml")).unwrap();
        for count in [3, 5] {
            let bad = text.replace("roller_count = 17", &format!("roller_count = {count}"));
            let e = BearingConfig::parse(&bad, Path::new("r.toml")).unwrap_err();
            assert_eq!(e.line, Some(line_of(&bad, "roller_count")), "{e}");
            assert!(e.to_string().contains("[6, 40]"), "{e}");
        }
    }

    #[test]
    fn a_type_error_names_the_field() {
        let text = std::fs::read_to_string(bundled("hub_motor.toml")).unwrap();
        let bad = text.replace("roller_count = 17", "roller_count = \"x\"");
        let e = BearingConfig::parse(&bad, Path::new("t.toml")).unwrap_err();
        assert_eq!(e.line, Some(line_of(&bad, "roller_count")));
        assert_eq!(e.field.as_deref(), Some("roller_count"), "{e}");
    }

    #[test]
    fn syntax_and_unknown_fields_are_located() {
        let e = BearingConfig::parse(
            "name = \"x\"\n[geometry]\npitch_diameter_m = \"a\"\n",
            Path::new("s.toml"),
        )
        .unwrap_err();
        assert_eq!(e.line, Some(3), "{e}");
        let text = std::fs::read_to_string(bundled("nu205.toml")).unwrap();
        let bad = text.replace("roller_count = 12", "roller_count = 12\nroller_colour = 3");
        let e = BearingConfig::parse(&bad, Path::new("u.toml")).unwrap_err();
        assert!(e.to_string().contains("roller_colour"), "{e}");
        // The unknown key starts its line: the error points at that line, not the one before.
        let expected = bad
            .lines()
            .position(|l| l.starts_with("roller_colour"))
            .unwrap()
            + 1;
        assert_eq!(e.line, Some(expected), "{e}");
        let nan = text.replace("viscosity_pa_s = 0.08", "viscosity_pa_s = nan");
        let e = BearingConfig::parse(&nan, Path::new("n.toml")).unwrap_err();
        assert_eq!(e.field.as_deref(), Some("viscosity_pa_s"), "{e}");
    }
}
