//! `bearing shaft static`, `modes` and `campbell`: the analyses that need no time integration
//! (equilibrium, and the eigenproblem with the bearings linearised there).

use std::path::PathBuf;

use anyhow::Result;
use bearing_host_common::output::write_with;
use bearing_shaft::operating::{campbell, operating_modes};
use bearing_shaft::plots;

use super::{
    check, check_count, load, mesh_orders, rpm_to_rad, CampbellArgs, ModesArgs, StaticArgs,
};

pub(super) fn cmd_static(a: StaticArgs) -> Result<()> {
    let model = load(&a.model)?;
    let omega = rpm_to_rad(check("speed-rpm", a.speed_rpm, 0.0, 1e6, false)?);
    let mut bearings = bearing_shaft::operating::build_bearings(&model)?;
    let eq = bearing_shaft::statics::equilibrium(&model, omega, &mut bearings)?;
    let nodes: Vec<_> = (0..model.n_nodes())
        .map(|i| {
            // Node DOFs [x, y, θx, θy] (`bearing_shaft::element`): rotations about x and y (rad).
            serde_json::json!({"node": i, "z_m": model.description.node_positions[i],
                "x_m": eq.q[4 * i], "y_m": eq.q[4 * i + 1],
                "theta_x_rad": eq.q[4 * i + 2], "theta_y_rad": eq.q[4 * i + 3]})
        })
        .collect();
    let reactions: Vec<_> = model
        .description
        .bearings
        .iter()
        .zip(&eq.reactions)
        .map(|(b, r)| serde_json::json!({"node": b.node, "force_n": r.force, "stiffness_n_per_m": r.stiffness}))
        .collect();
    if a.model.json {
        println!(
            "{}",
            serde_json::json!({"iterations": eq.iterations, "nodes": nodes, "bearings": reactions})
        );
        return Ok(());
    }
    println!("static equilibrium ({} Newton iterations)", eq.iterations);
    println!(
        "{:>5} {:>9} {:>13} {:>13}",
        "node", "z (mm)", "x (µm)", "y (µm)"
    );
    for i in 0..model.n_nodes() {
        println!(
            "{i:>5} {:>9.2} {:>13.4} {:>13.4}",
            model.description.node_positions[i] * 1e3,
            eq.q[4 * i] * 1e6,
            eq.q[4 * i + 1] * 1e6
        );
    }
    for (b, r) in model.description.bearings.iter().zip(&eq.reactions) {
        println!(
            "bearing at node {}: force ({:.2}, {:.2}) N, stiffness kxx {:.4e} kyy {:.4e} N/m",
            b.node, r.force[0], r.force[1], r.stiffness[0][0], r.stiffness[1][1]
        );
    }
    Ok(())
}

pub(super) fn cmd_modes(a: ModesArgs) -> Result<()> {
    let model = load(&a.model)?;
    let omega = rpm_to_rad(check("speed-rpm", a.speed_rpm, 0.0, 1e6, false)?);
    let n = check_count("modes", a.modes, 1, 200)?;
    let (_, modes) = operating_modes(&model, omega, n, true)?;
    if let Some(p) = &a.plot {
        write_with(p, |temp| {
            plots::mode_shapes(&model.description.node_positions, &modes, temp)
                .map_err(|e| std::io::Error::other(e.to_string()))
        })
        .map_err(|e| anyhow::anyhow!("writing {}: {e}", p.display()))?;
    }
    if a.model.json {
        let f: Vec<f64> = modes.iter().map(|m| m.frequency).collect();
        let per_mode: Vec<_> = modes
            .iter()
            .map(|m| {
                serde_json::json!({"frequency_rad_s": m.frequency,
                    "frequency_hz": m.frequency / (2.0 * std::f64::consts::PI),
                    "damping_ratio": m.damping_ratio, "whirl": m.whirl})
            })
            .collect();
        println!(
            "{}",
            serde_json::json!({"speed_rpm": a.speed_rpm, "frequencies_rad_s": f, "modes": per_mode})
        );
        return Ok(());
    }
    println!("modes at {} rpm ({} DOF)", a.speed_rpm, model.n_dof());
    println!(
        "{:>4} {:>14} {:>12} {:>10} {:>9}",
        "#", "ω (rad/s)", "f (Hz)", "ζ", "whirl"
    );
    for (i, m) in modes.iter().enumerate() {
        println!(
            "{:>4} {:>14.3} {:>12.3} {:>10.2e} {:>9?}",
            i + 1,
            m.frequency,
            m.frequency / (2.0 * std::f64::consts::PI),
            m.damping_ratio,
            m.whirl
        );
    }
    Ok(())
}

pub(super) fn cmd_campbell(a: CampbellArgs) -> Result<()> {
    let model = load(&a.model)?;
    let max = check("max-rpm", a.max_rpm, 0.0, 1e6, true)?;
    let steps = check_count("steps", a.steps, 1, 1000)?;
    let n = check_count("modes", a.modes, 1, 200)?;
    let speeds: Vec<f64> = (0..=steps).map(|k| max * k as f64 / steps as f64).collect();
    let points = campbell(&model, &speeds, n)?;
    // The table (or JSON) is the answer; the plot is written when asked, and by default only
    // with the table.
    let plot = match &a.plot {
        Some(p) => Some(p.clone()),
        None if a.model.json => None,
        None => Some(PathBuf::from("campbell.png")),
    };
    if let Some(p) = &plot {
        write_with(p, |temp| {
            plots::campbell(&points, &mesh_orders(&model), temp)
                .map_err(|e| std::io::Error::other(e.to_string()))
        })
        .map_err(|e| anyhow::anyhow!("writing {}: {e}", p.display()))?;
    }
    if a.model.json {
        println!("{}", serde_json::to_string(&points)?);
    } else {
        for p in &points {
            let f: Vec<String> = p
                .frequencies_rad_s
                .iter()
                .map(|w| format!("{w:9.2}"))
                .collect();
            println!("{:>8.0} rpm: {} rad/s", p.speed_rpm, f.join(" "));
        }
        if let Some(p) = &plot {
            println!("plot: {}", p.display());
        }
    }
    Ok(())
}
