//! The shaft model file (TOML): nodes, shaft sections with stepped diameters, material, damping,
//! disks, bearings, motor and loads. Parsed with serde; every semantic check names the file, the
//! line and the field, and says what is allowed.
//!
//! ```toml
//! nodes_m = [0.0, 0.25, 0.5]                       # axial node positions, increasing
//! [material]
//! youngs_modulus_pa = 211e9
//! shear_modulus_pa = 81.2e9
//! density_kg_m3 = 7810.0
//! [damping]                                         # optional Rayleigh damping C = aM + bK
//! mass_proportional_per_s = 0.0
//! stiffness_proportional_s = 1e-5
//! [[section]]                                       # elements from_node..to_node
//! from_node = 0
//! to_node = 2
//! outer_diameter_m = 0.05
//! inner_diameter_m = 0.0                            # optional
//! [[disk]]                                          # annulus (or mass_kg + inertias)
//! node = 1
//! outer_diameter_m = 0.28
//! inner_diameter_m = 0.05
//! thickness_m = 0.07
//! [[bearing]]
//! node = 0
//! kind = "linear"                                   # or "roller": config = "x.toml", film = "int"
//! stiffness_n_per_m = 1e6
//! [motor]                                           # needed by gear_mesh loads
//! peak_torque_nm = 68.0
//! max_power_w = 54000.0
//! max_speed_rpm = 21000.0
//! [[load]]
//! kind = "gear_mesh"                                # static | gravity | unbalance | gear_mesh
//! node = 1
//! teeth = 17
//! module_m = 0.004
//! pressure_angle_deg = 20.0
//! ```

use std::path::{Path, PathBuf};

use bearing_host_common::toml_lines::{line_at, TomlLines};
use serde::Deserialize;

use crate::bearing::FilmKind;
use crate::model::RotorModel;

mod describe;
mod locator;

use describe::describe;
pub use describe::MAX_ELEMENT_LENGTH_RATIO;
use locator::Locator;

/// A configuration error with its location.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{}{}: {field}: {message}", file.display(), line.map(|l| format!(":{l}")).unwrap_or_default())]
pub struct ConfigError {
    /// The file.
    pub file: PathBuf,
    /// 1-based line, when known.
    pub line: Option<usize>,
    /// The field (TOML key path).
    pub field: String,
    /// What is wrong and what is allowed.
    pub message: String,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileMaterial {
    pub(super) youngs_modulus_pa: f64,
    pub(super) shear_modulus_pa: f64,
    pub(super) density_kg_m3: f64,
}

#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub(super) struct FileDamping {
    #[serde(default)]
    pub(super) mass_proportional_per_s: f64,
    #[serde(default)]
    pub(super) stiffness_proportional_s: f64,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileSection {
    pub(super) from_node: usize,
    pub(super) to_node: usize,
    pub(super) outer_diameter_m: f64,
    #[serde(default)]
    pub(super) inner_diameter_m: f64,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileDisk {
    pub(super) node: usize,
    pub(super) outer_diameter_m: Option<f64>,
    #[serde(default)]
    pub(super) inner_diameter_m: f64,
    pub(super) thickness_m: Option<f64>,
    pub(super) density_kg_m3: Option<f64>,
    pub(super) mass_kg: Option<f64>,
    pub(super) polar_inertia_kg_m2: Option<f64>,
    pub(super) diametral_inertia_kg_m2: Option<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileBearing {
    pub(super) node: usize,
    pub(super) kind: String,
    pub(super) stiffness_n_per_m: Option<f64>,
    pub(super) damping_n_s_per_m: Option<f64>,
    pub(super) kxx_n_per_m: Option<f64>,
    pub(super) kyy_n_per_m: Option<f64>,
    pub(super) kxy_n_per_m: Option<f64>,
    pub(super) kyx_n_per_m: Option<f64>,
    pub(super) cxx_n_s_per_m: Option<f64>,
    pub(super) cyy_n_s_per_m: Option<f64>,
    pub(super) config: Option<String>,
    pub(super) film: Option<FilmKind>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileMotor {
    pub(super) peak_torque_nm: f64,
    pub(super) max_power_w: f64,
    pub(super) max_speed_rpm: f64,
    #[serde(default = "one")]
    pub(super) load_fraction: f64,
    #[serde(default)]
    pub(super) ripple_fraction: f64,
    pub(super) ripple_order: Option<f64>,
}

fn one() -> f64 {
    1.0
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct FileLoad {
    pub(super) kind: String,
    pub(super) node: Option<usize>,
    pub(super) fx_n: Option<f64>,
    pub(super) fy_n: Option<f64>,
    pub(super) acceleration_m_s2: Option<f64>,
    pub(super) mass_eccentricity_kg_m: Option<f64>,
    pub(super) phase_deg: Option<f64>,
    pub(super) teeth: Option<u32>,
    pub(super) module_m: Option<f64>,
    pub(super) pressure_angle_deg: Option<f64>,
    pub(super) face_width_m: Option<f64>,
    pub(super) mesh_angle_deg: Option<f64>,
    pub(super) force_fluctuation: Option<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct ShaftFile {
    #[serde(default)]
    pub(super) description: String,
    pub(super) nodes_m: Vec<f64>,
    pub(super) material: FileMaterial,
    #[serde(default)]
    pub(super) damping: FileDamping,
    #[serde(default)]
    pub(super) section: Vec<FileSection>,
    #[serde(default)]
    pub(super) disk: Vec<FileDisk>,
    #[serde(default)]
    pub(super) bearing: Vec<FileBearing>,
    pub(super) motor: Option<FileMotor>,
    #[serde(default)]
    pub(super) load: Vec<FileLoad>,
}

/// Reads and checks a shaft file and assembles the model.
pub fn load_model(path: &Path) -> Result<RotorModel, ConfigError> {
    let text = std::fs::read_to_string(path).map_err(|e| ConfigError {
        file: path.to_path_buf(),
        line: None,
        field: "(file)".into(),
        message: format!("cannot read: {e}"),
    })?;
    parse_model(path, &text)
}

/// Parses shaft-file text (`path` names it in errors and resolves relative bearing configs).
pub fn parse_model(path: &Path, text: &str) -> Result<RotorModel, ConfigError> {
    let file: ShaftFile = toml::from_str(text).map_err(|e| {
        let line = e.span().map(|s| line_at(text, s.start));
        // The key on that line, for the message.
        let field = line
            .and_then(|l| text.lines().nth(l - 1))
            .and_then(|l| l.split('=').next())
            .map(|k| k.trim().to_string())
            .unwrap_or_else(|| "(syntax)".into());
        ConfigError {
            file: path.to_path_buf(),
            line,
            field,
            message: e.message().to_string(),
        }
    })?;
    let loc = Locator {
        file: path,
        lines: TomlLines::new(text),
    };
    describe(&loc, file).map(RotorModel::assemble)
}
