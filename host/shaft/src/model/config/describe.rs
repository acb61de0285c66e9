//! Turning the parsed shaft file into a checked [`RotorDescription`]: every value range-checked,
//! every node reference resolved, sections covering each element exactly once.

use std::path::Path;

use super::locator::Locator;
use super::{ConfigError, ShaftFile};
use crate::bearing::{BearingSpec, LinearBearing};
use crate::model::damping::ProportionalDamping;
use crate::model::disk::RigidDisk;
use crate::model::element::Material;
use crate::model::loads::{GearMesh, Load, LoadSet};
use crate::model::motor::Pmsm;
use crate::model::{BearingSite, RotorDescription};

/// Largest Young's modulus accepted (Pa): diamond's, ≈ 1.2 TPa, the stiffest bulk solid.
const MAX_YOUNGS_MODULUS_PA: f64 = 1.2e12;
/// Largest shear modulus accepted (Pa): diamond's is ≈ 0.5 TPa.
const MAX_SHEAR_MODULUS_PA: f64 = 6.0e11;
/// Largest density accepted (kg/m³): osmium, the densest element, 22 590 kg/m³.
const MAX_DENSITY_KG_M3: f64 = 2.3e4;
/// Largest section diameter accepted (m): turbo-generator rotors, the largest shafts built,
/// are about 2 m across. Beyond such bounds the element matrices (∝ d⁴ E, d² ρ) lose every
/// significant digit or overflow, and the failure surfaced later as a singular stiffness or an
/// eigen-solver that did not converge, without the file or the field.
const MAX_SECTION_DIAMETER_M: f64 = 10.0;
/// Largest ratio of the longest to the shortest element. A short element's stiffness grows as
/// 1/L (shear) to 1/L³ (bending) while its mass shrinks as L, so the eigenproblem spans more
/// decades as the ratio grows; the state-space Schur solve of [`crate::analysis::modes`] then loses the
/// low modes. Measured on configs/friswell_5_9_1.toml with its last element split (5th mode
/// at 4000 rpm, published 600.18 rad/s): ratio 100 → 0.003 % off, 250 → 0.03 %, 1000 → 0.6 %,
/// 2500 → 7 %, 2.5·10⁵ (a 1 µm element) → the first mode at 1267 rad/s instead of 85.4.
pub const MAX_ELEMENT_LENGTH_RATIO: f64 = 100.0;

pub(super) fn describe(loc: &Locator<'_>, f: ShaftFile) -> Result<RotorDescription, ConfigError> {
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
    let lengths: Vec<f64> = f.nodes_m.windows(2).map(|w| w[1] - w[0]).collect();
    let longest = lengths.iter().copied().fold(0.0, f64::max);
    if let Some((e, length)) = lengths
        .iter()
        .enumerate()
        .find(|(_, l)| **l * MAX_ELEMENT_LENGTH_RATIO < longest)
    {
        return Err(loc.err(
            "",
            0,
            "nodes_m",
            format!(
                "element {e}–{} is {length:.3e} m long, shorter than 1/{MAX_ELEMENT_LENGTH_RATIO} of the longest element ({longest:.3e} m): element lengths must stay within a factor {MAX_ELEMENT_LENGTH_RATIO} of each other (merge node {} into a neighbour, or refine the long elements)",
                e + 1,
                e + 1
            ),
        ));
    }
    let m = &f.material;
    let material = Material {
        youngs_modulus: loc.range(
            "material",
            0,
            "youngs_modulus_pa",
            m.youngs_modulus_pa,
            0.0,
            MAX_YOUNGS_MODULUS_PA,
            true,
            "Pa",
        )?,
        shear_modulus: loc.range(
            "material",
            0,
            "shear_modulus_pa",
            m.shear_modulus_pa,
            0.0,
            MAX_SHEAR_MODULUS_PA,
            true,
            "Pa",
        )?,
        density: loc.range(
            "material",
            0,
            "density_kg_m3",
            m.density_kg_m3,
            0.0,
            MAX_DENSITY_KG_M3,
            true,
            "kg/m³",
        )?,
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
        let outer = loc.range(
            "section",
            i,
            "outer_diameter_m",
            s.outer_diameter_m,
            0.0,
            MAX_SECTION_DIAMETER_M,
            true,
            "m",
        )?;
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
        .map(|(e, d)| {
            d.ok_or_else(|| {
                // Blame the section next to the gap: the one ending where it starts, else the
                // first one starting after it.
                let (i, key) = f
                    .section
                    .iter()
                    .position(|s| s.to_node == e)
                    .map(|i| (i, "to_node"))
                    .or_else(|| {
                        (0..f.section.len())
                            .filter(|&i| f.section[i].from_node > e)
                            .min_by_key(|&i| f.section[i].from_node)
                            .map(|i| (i, "from_node"))
                    })
                    .unwrap_or((0, "from_node"));
                loc.err(
                    "section",
                    i,
                    key,
                    format!(
                        "element between nodes {e} and {} has no section: sections must cover 0 … {}",
                        e + 1,
                        n_nodes - 1
                    ),
                )
            })
        })
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

    if bearings.len() > crate::analysis::integrator::MAX_BEARINGS {
        return Err(loc.err(
            "bearing",
            crate::analysis::integrator::MAX_BEARINGS,
            "node",
            format!(
                "{} bearings: at most {} are supported",
                bearings.len(),
                crate::analysis::integrator::MAX_BEARINGS
            ),
        ));
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
    // Torque ripple defaults to the mesh order (docs/physics.md §6.2: sinusoids at mesh frequency).
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
