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

use serde::Deserialize;

use super::bearing::{BearingSpec, FilmChoice, LinearBearing};
use super::damping::ProportionalDamping;
use super::disk::RigidDisk;
use super::element::Material;
use super::loads::{GearMesh, Load, LoadSet};
use super::model::{BearingSite, RotorDescription, RotorModel};
use super::motor::Pmsm;

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
struct FileMaterial {
    youngs_modulus_pa: f64,
    shear_modulus_pa: f64,
    density_kg_m3: f64,
}

#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
struct FileDamping {
    #[serde(default)]
    mass_proportional_per_s: f64,
    #[serde(default)]
    stiffness_proportional_s: f64,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct FileSection {
    from_node: usize,
    to_node: usize,
    outer_diameter_m: f64,
    #[serde(default)]
    inner_diameter_m: f64,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct FileDisk {
    node: usize,
    outer_diameter_m: Option<f64>,
    #[serde(default)]
    inner_diameter_m: f64,
    thickness_m: Option<f64>,
    density_kg_m3: Option<f64>,
    mass_kg: Option<f64>,
    polar_inertia_kg_m2: Option<f64>,
    diametral_inertia_kg_m2: Option<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct FileBearing {
    node: usize,
    kind: String,
    stiffness_n_per_m: Option<f64>,
    damping_n_s_per_m: Option<f64>,
    kxx_n_per_m: Option<f64>,
    kyy_n_per_m: Option<f64>,
    kxy_n_per_m: Option<f64>,
    kyx_n_per_m: Option<f64>,
    cxx_n_s_per_m: Option<f64>,
    cyy_n_s_per_m: Option<f64>,
    config: Option<String>,
    film: Option<FilmChoice>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct FileMotor {
    peak_torque_nm: f64,
    max_power_w: f64,
    max_speed_rpm: f64,
    #[serde(default = "one")]
    load_fraction: f64,
    #[serde(default)]
    ripple_fraction: f64,
    ripple_order: Option<f64>,
}

fn one() -> f64 {
    1.0
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct FileLoad {
    kind: String,
    node: Option<usize>,
    fx_n: Option<f64>,
    fy_n: Option<f64>,
    acceleration_m_s2: Option<f64>,
    mass_eccentricity_kg_m: Option<f64>,
    phase_deg: Option<f64>,
    teeth: Option<u32>,
    module_m: Option<f64>,
    pressure_angle_deg: Option<f64>,
    face_width_m: Option<f64>,
    mesh_angle_deg: Option<f64>,
    force_fluctuation: Option<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct ShaftFile {
    #[serde(default)]
    description: String,
    nodes_m: Vec<f64>,
    material: FileMaterial,
    #[serde(default)]
    damping: FileDamping,
    #[serde(default)]
    section: Vec<FileSection>,
    #[serde(default)]
    disk: Vec<FileDisk>,
    #[serde(default)]
    bearing: Vec<FileBearing>,
    motor: Option<FileMotor>,
    #[serde(default)]
    load: Vec<FileLoad>,
}

/// Source text plus path, to turn (table, index, key) into a line number.
struct Locator<'a> {
    file: &'a Path,
    text: &'a str,
}

impl Locator<'_> {
    /// Line of `key` inside the `index`-th `[[table]]` (or `[table]`, or the top level when
    /// `table` is empty).
    fn line(&self, table: &str, index: usize, key: &str) -> Option<usize> {
        let lines: Vec<&str> = self.text.lines().collect();
        let mut start = 0usize;
        if !table.is_empty() {
            let headers = [format!("[[{table}]]"), format!("[{table}]")];
            let mut seen = 0usize;
            let mut found = None;
            for (i, l) in lines.iter().enumerate() {
                let t = l.trim();
                if headers.iter().any(|h| t.starts_with(h.as_str())) {
                    if seen == index {
                        found = Some(i);
                        break;
                    }
                    seen += 1;
                }
            }
            start = found?;
        }
        for (i, l) in lines.iter().enumerate().skip(start) {
            let t = l.trim_start();
            if i > start && t.starts_with('[') {
                break;
            }
            if let Some(rest) = t.strip_prefix(key) {
                if rest.trim_start().starts_with('=') {
                    return Some(i + 1);
                }
            }
        }
        if table.is_empty() {
            None
        } else {
            Some(start + 1)
        }
    }

    fn err(&self, table: &str, index: usize, key: &str, message: String) -> ConfigError {
        let field = match table {
            "" => key.to_string(),
            "material" | "damping" | "motor" => format!("{table}.{key}"),
            _ => format!("{table}[{index}].{key}"),
        };
        ConfigError {
            file: self.file.to_path_buf(),
            line: self.line(table, index, key),
            field,
            message,
        }
    }

    /// A finite value in [lo, hi] (inclusive unless `open_lo`).
    #[allow(clippy::too_many_arguments)]
    fn range(
        &self,
        table: &str,
        index: usize,
        key: &str,
        value: f64,
        lo: f64,
        hi: f64,
        open_lo: bool,
        unit: &str,
    ) -> Result<f64, ConfigError> {
        let ok = value.is_finite() && value <= hi && if open_lo { value > lo } else { value >= lo };
        if ok {
            Ok(value)
        } else {
            let bracket = if open_lo { "(" } else { "[" };
            Err(self.err(
                table,
                index,
                key,
                format!(
                    "{value} is not allowed: must be finite and in {bracket}{lo}, {hi}] {unit}"
                ),
            ))
        }
    }

    fn positive(&self, t: &str, i: usize, k: &str, v: f64, unit: &str) -> Result<f64, ConfigError> {
        self.range(t, i, k, v, 0.0, f64::MAX, true, unit)
    }

    fn non_negative(
        &self,
        t: &str,
        i: usize,
        k: &str,
        v: f64,
        unit: &str,
    ) -> Result<f64, ConfigError> {
        self.range(t, i, k, v, 0.0, f64::MAX, false, unit)
    }

    fn finite(&self, t: &str, i: usize, k: &str, v: f64, unit: &str) -> Result<f64, ConfigError> {
        self.range(t, i, k, v, -f64::MAX, f64::MAX, false, unit)
    }

    fn node(&self, t: &str, i: usize, node: usize, n_nodes: usize) -> Result<usize, ConfigError> {
        if node < n_nodes {
            Ok(node)
        } else {
            Err(self.err(
                t,
                i,
                "node",
                format!("node {node} does not exist: allowed 0 … {}", n_nodes - 1),
            ))
        }
    }

    fn required<T: Copy>(
        &self,
        t: &str,
        i: usize,
        k: &str,
        v: Option<T>,
        why: &str,
    ) -> Result<T, ConfigError> {
        v.ok_or_else(|| self.err(t, i, k, format!("missing: required {why}")))
    }
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
        let line = e
            .span()
            .map(|s| text[..s.start.min(text.len())].matches('\n').count() + 1);
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
    let loc = Locator { file: path, text };
    describe(&loc, file).map(RotorModel::assemble)
}

fn describe(loc: &Locator<'_>, f: ShaftFile) -> Result<RotorDescription, ConfigError> {
    let _ = f.description;
    let n_nodes = f.nodes_m.len();
    if n_nodes < 2 {
        return Err(loc.err(
            "",
            0,
            "nodes_m",
            format!("{n_nodes} nodes given: at least 2 needed"),
        ));
    }
    for (i, z) in f.nodes_m.iter().enumerate() {
        loc.finite("", 0, "nodes_m", *z, "m")?;
        if i > 0 && *z <= f.nodes_m[i - 1] {
            return Err(loc.err(
                "",
                0,
                "nodes_m",
                format!(
                    "positions must increase strictly: node {i} at {z} m follows {} m",
                    f.nodes_m[i - 1]
                ),
            ));
        }
    }
    let m = &f.material;
    let material = Material {
        youngs_modulus: loc.positive(
            "material",
            0,
            "youngs_modulus_pa",
            m.youngs_modulus_pa,
            "Pa",
        )?,
        shear_modulus: loc.positive("material", 0, "shear_modulus_pa", m.shear_modulus_pa, "Pa")?,
        density: loc.positive("material", 0, "density_kg_m3", m.density_kg_m3, "kg/m³")?,
    };
    let nu = material.poisson_ratio();
    if !(-1.0..0.5).contains(&nu) {
        return Err(loc.err(
            "material",
            0,
            "shear_modulus_pa",
            format!("E/(2G) − 1 = ν = {nu:.3} is not a Poisson ratio in (−1, 0.5)"),
        ));
    }
    let damping = ProportionalDamping {
        mass_coefficient: loc.non_negative(
            "damping",
            0,
            "mass_proportional_per_s",
            f.damping.mass_proportional_per_s,
            "1/s",
        )?,
        stiffness_coefficient: loc.non_negative(
            "damping",
            0,
            "stiffness_proportional_s",
            f.damping.stiffness_proportional_s,
            "s",
        )?,
    };
    let mut element_diameters: Vec<Option<(f64, f64)>> = vec![None; n_nodes - 1];
    for (i, s) in f.section.iter().enumerate() {
        loc.node("section", i, s.from_node, n_nodes)
            .map_err(|e| ConfigError {
                field: format!("section[{i}].from_node"),
                ..e
            })?;
        if s.to_node <= s.from_node || s.to_node >= n_nodes {
            return Err(loc.err(
                "section",
                i,
                "to_node",
                format!(
                    "{} must be in {} … {}",
                    s.to_node,
                    s.from_node + 1,
                    n_nodes - 1
                ),
            ));
        }
        let outer = loc.positive("section", i, "outer_diameter_m", s.outer_diameter_m, "m")?;
        let inner = loc.range(
            "section",
            i,
            "inner_diameter_m",
            s.inner_diameter_m,
            0.0,
            outer,
            false,
            "m (below the outer diameter)",
        )?;
        if inner >= outer {
            return Err(loc.err(
                "section",
                i,
                "inner_diameter_m",
                format!("{inner} m must be below the outer diameter {outer} m"),
            ));
        }
        for (e, slot) in element_diameters
            .iter_mut()
            .enumerate()
            .take(s.to_node)
            .skip(s.from_node)
        {
            if slot.is_some() {
                return Err(loc.err(
                    "section",
                    i,
                    "from_node",
                    format!(
                        "element {e}–{} is already covered by another section",
                        e + 1
                    ),
                ));
            }
            *slot = Some((outer, inner));
        }
    }
    let element_diameters = element_diameters
        .into_iter()
        .enumerate()
        .map(|(e, d)| d.ok_or_else(|| loc.err("section", 0, "from_node", format!("element between nodes {e} and {} has no section: sections must cover 0 … {}", e + 1, n_nodes - 1))))
        .collect::<Result<Vec<_>, _>>()?;

    let mut disks = Vec::new();
    for (i, d) in f.disk.iter().enumerate() {
        let node = loc.node("disk", i, d.node, n_nodes)?;
        let disk = if let Some(mass) = d.mass_kg {
            RigidDisk {
                node,
                mass: loc.positive("disk", i, "mass_kg", mass, "kg")?,
                polar_inertia: loc.non_negative(
                    "disk",
                    i,
                    "polar_inertia_kg_m2",
                    loc.required(
                        "disk",
                        i,
                        "polar_inertia_kg_m2",
                        d.polar_inertia_kg_m2,
                        "with mass_kg",
                    )?,
                    "kg·m²",
                )?,
                diametral_inertia: loc.non_negative(
                    "disk",
                    i,
                    "diametral_inertia_kg_m2",
                    loc.required(
                        "disk",
                        i,
                        "diametral_inertia_kg_m2",
                        d.diametral_inertia_kg_m2,
                        "with mass_kg",
                    )?,
                    "kg·m²",
                )?,
            }
        } else {
            let outer = loc.positive(
                "disk",
                i,
                "outer_diameter_m",
                loc.required(
                    "disk",
                    i,
                    "outer_diameter_m",
                    d.outer_diameter_m,
                    "(or mass_kg and inertias)",
                )?,
                "m",
            )?;
            let inner = loc.range(
                "disk",
                i,
                "inner_diameter_m",
                d.inner_diameter_m,
                0.0,
                outer,
                false,
                "m",
            )?;
            let thickness = loc.positive(
                "disk",
                i,
                "thickness_m",
                loc.required(
                    "disk",
                    i,
                    "thickness_m",
                    d.thickness_m,
                    "for a disk given by its geometry",
                )?,
                "m",
            )?;
            let density = loc.positive(
                "disk",
                i,
                "density_kg_m3",
                d.density_kg_m3.unwrap_or(material.density),
                "kg/m³",
            )?;
            RigidDisk::annulus(node, density, outer, inner, thickness)
        };
        disks.push(disk);
    }

    let mut bearings = Vec::new();
    for (i, b) in f.bearing.iter().enumerate() {
        let node = loc.node("bearing", i, b.node, n_nodes)?;
        let spec = match b.kind.as_str() {
            "linear" => {
                let k_iso = b.stiffness_n_per_m;
                let c_iso = b.damping_n_s_per_m.unwrap_or(0.0);
                let kxx = b.kxx_n_per_m.or(k_iso);
                let kyy = b.kyy_n_per_m.or(k_iso);
                let kxx = loc.positive(
                    "bearing",
                    i,
                    "kxx_n_per_m",
                    loc.required(
                        "bearing",
                        i,
                        "stiffness_n_per_m",
                        kxx,
                        "for kind = \"linear\" (or kxx_n_per_m and kyy_n_per_m)",
                    )?,
                    "N/m",
                )?;
                let kyy = loc.positive(
                    "bearing",
                    i,
                    "kyy_n_per_m",
                    loc.required(
                        "bearing",
                        i,
                        "stiffness_n_per_m",
                        kyy,
                        "for kind = \"linear\" (or kxx_n_per_m and kyy_n_per_m)",
                    )?,
                    "N/m",
                )?;
                let kxy = loc.finite(
                    "bearing",
                    i,
                    "kxy_n_per_m",
                    b.kxy_n_per_m.unwrap_or(0.0),
                    "N/m",
                )?;
                let kyx = loc.finite(
                    "bearing",
                    i,
                    "kyx_n_per_m",
                    b.kyx_n_per_m.unwrap_or(0.0),
                    "N/m",
                )?;
                let c_iso = loc.non_negative("bearing", i, "damping_n_s_per_m", c_iso, "N·s/m")?;
                let cxx = loc.non_negative(
                    "bearing",
                    i,
                    "cxx_n_s_per_m",
                    b.cxx_n_s_per_m.unwrap_or(c_iso),
                    "N·s/m",
                )?;
                let cyy = loc.non_negative(
                    "bearing",
                    i,
                    "cyy_n_s_per_m",
                    b.cyy_n_s_per_m.unwrap_or(c_iso),
                    "N·s/m",
                )?;
                BearingSpec::Linear(LinearBearing {
                    stiffness: [[kxx, kxy], [kyx, kyy]],
                    damping: [[cxx, 0.0], [0.0, cyy]],
                })
            }
            "roller" => {
                let rel = b.config.as_ref().ok_or_else(|| {
                    loc.err(
                        "bearing",
                        i,
                        "config",
                        "missing: kind = \"roller\" needs config = \"<bearing file>.toml\"".into(),
                    )
                })?;
                let base = loc.file.parent().unwrap_or(Path::new("."));
                BearingSpec::Roller {
                    config: base.join(rel),
                    film: b.film.ok_or_else(|| {
                        loc.err(
                            "bearing",
                            i,
                            "film",
                            "missing: one of \"int\", \"f32\", \"regression\", \"dry\"".into(),
                        )
                    })?,
                }
            }
            other => {
                return Err(loc.err(
                    "bearing",
                    i,
                    "kind",
                    format!("\"{other}\" is unknown: allowed \"linear\", \"roller\""),
                ))
            }
        };
        bearings.push(BearingSite { node, spec });
    }

    let motor = match &f.motor {
        None => None,
        Some(m) => Some(Pmsm {
            peak_torque: loc.positive("motor", 0, "peak_torque_nm", m.peak_torque_nm, "N·m")?,
            max_power: loc.positive("motor", 0, "max_power_w", m.max_power_w, "W")?,
            max_speed: loc.positive("motor", 0, "max_speed_rpm", m.max_speed_rpm, "rpm")?
                * std::f64::consts::PI
                / 30.0,
            load_fraction: loc.range(
                "motor",
                0,
                "load_fraction",
                m.load_fraction,
                0.0,
                1.0,
                false,
                "",
            )?,
            ripple_fraction: loc.range(
                "motor",
                0,
                "ripple_fraction",
                m.ripple_fraction,
                0.0,
                1.0,
                false,
                "",
            )?,
            ripple_order: 0.0,
        }),
    };
    let ripple_order = match &f.motor {
        Some(m) => match m.ripple_order {
            Some(o) => Some(loc.positive("motor", 0, "ripple_order", o, "per revolution")?),
            None => None,
        },
        None => None,
    };

    let mut loads = Vec::new();
    let mut mesh_teeth = None;
    for (i, l) in f.load.iter().enumerate() {
        let load = match l.kind.as_str() {
            "static" => Load::Static {
                node: loc.node("load", i, loc.required("load", i, "node", l.node, "for kind = \"static\"")?, n_nodes)?,
                force: [
                    loc.finite("load", i, "fx_n", l.fx_n.unwrap_or(0.0), "N")?,
                    loc.finite("load", i, "fy_n", l.fy_n.unwrap_or(0.0), "N")?,
                ],
            },
            "gravity" => Load::Gravity {
                acceleration: loc.non_negative("load", i, "acceleration_m_s2", l.acceleration_m_s2.unwrap_or(9.81), "m/s²")?,
            },
            "unbalance" => Load::Unbalance {
                node: loc.node("load", i, loc.required("load", i, "node", l.node, "for kind = \"unbalance\"")?, n_nodes)?,
                mass_eccentricity: loc.non_negative("load", i, "mass_eccentricity_kg_m", loc.required("load", i, "mass_eccentricity_kg_m", l.mass_eccentricity_kg_m, "for kind = \"unbalance\"")?, "kg·m")?,
                phase: loc.finite("load", i, "phase_deg", l.phase_deg.unwrap_or(0.0), "deg")?.to_radians(),
            },
            "gear_mesh" => {
                if f.motor.is_none() {
                    return Err(loc.err("load", i, "kind", "gear_mesh needs a [motor] table (the transmitted torque)".into()));
                }
                let teeth = loc.required("load", i, "teeth", l.teeth, "for kind = \"gear_mesh\"")?;
                if teeth < 5 {
                    return Err(loc.err("load", i, "teeth", format!("{teeth} teeth: at least 5")));
                }
                if let Some(w) = l.face_width_m {
                    loc.positive("load", i, "face_width_m", w, "m")?;
                }
                mesh_teeth.get_or_insert(teeth);
                Load::GearMesh(GearMesh {
                    node: loc.node("load", i, loc.required("load", i, "node", l.node, "for kind = \"gear_mesh\"")?, n_nodes)?,
                    teeth,
                    module: loc.positive("load", i, "module_m", loc.required("load", i, "module_m", l.module_m, "for kind = \"gear_mesh\"")?, "m")?,
                    pressure_angle: loc.range("load", i, "pressure_angle_deg", l.pressure_angle_deg.unwrap_or(20.0), 0.0, 45.0, true, "deg")?.to_radians(),
                    mesh_angle: loc.finite("load", i, "mesh_angle_deg", l.mesh_angle_deg.unwrap_or(0.0), "deg")?.to_radians(),
                    force_fluctuation: loc.range("load", i, "force_fluctuation", l.force_fluctuation.unwrap_or(0.0), 0.0, 1.0, false, "")?,
                })
            }
            other => return Err(loc.err("load", i, "kind", format!("\"{other}\" is unknown: allowed \"static\", \"gravity\", \"unbalance\", \"gear_mesh\""))),
        };
        loads.push(load);
    }
    // Torque ripple defaults to the mesh order (PHYSICS.md §6.2: sinusoids at mesh frequency).
    let motor = motor.map(|m| Pmsm {
        ripple_order: ripple_order.or(mesh_teeth.map(f64::from)).unwrap_or(1.0),
        ..m
    });
    Ok(RotorDescription {
        node_positions: f.nodes_m,
        element_diameters,
        material,
        disks,
        bearings,
        damping,
        loads: LoadSet { loads, motor },
    })
}
