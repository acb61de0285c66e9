//! The Craig–Bampton error report of `bearing shaft run --reduce`.

use anyhow::{Context, Result};
use bearing_shaft::model::RotorModel;
use bearing_shaft::simulate::{run as run_time, RunResult, RunSettings};

/// Error of the Craig–Bampton model against the full one: the lowest natural frequencies with
/// the bearings linearised at the equilibrium and, with `compare_full`, the run envelopes.
pub(super) fn reduction_report(
    model: &RotorModel,
    s: &RunSettings,
    modes: usize,
    compare_full: bool,
    reduced_run: &RunResult,
) -> Result<serde_json::Value> {
    use bearing_shaft::operating::{build_bearings, linearise};
    let mut bearings = build_bearings(model)?;
    let eq = bearing_shaft::statics::equilibrium(model, s.spin_speed, &mut bearings)?;
    let kb: Vec<_> = linearise(model, &mut bearings, &eq.q, s.spin_speed)?
        .iter()
        .map(|r| r.stiffness)
        .collect();
    let system = bearing_shaft::system::TimeSystem::new(model, Some(modes))?;
    let reduced = system.reduced.as_ref().context("reduced model")?;
    let errors = bearing_shaft::reduction::frequency_error(model, reduced, &kb, 6)?;
    let freq: Vec<_> = errors
        .iter()
        .map(|(w, e)| serde_json::json!({"full_rad_s": w, "relative_error": e}))
        .collect();
    let envelope = if compare_full {
        let full = run_time(
            model,
            &RunSettings {
                reduction_modes: None,
                ..s.clone()
            },
            None,
        )?;
        let rel = |a: f64, b: f64| (a - b) / b;
        serde_json::json!({
            "max_displacement_relative_error": rel(reduced_run.envelope.max_displacement_m, full.envelope.max_displacement_m),
            "max_acceleration_relative_error": rel(reduced_run.envelope.max_acceleration_m_s2, full.envelope.max_acceleration_m_s2),
            "max_bearing_force_relative_error": rel(reduced_run.envelope.max_bearing_force_n, full.envelope.max_bearing_force_n),
            "full_wall_seconds": full.wall_seconds,
        })
    } else {
        serde_json::Value::Null
    };
    Ok(
        serde_json::json!({"modes_kept": modes, "n_dof_full": model.n_dof(),
        "frequencies": freq, "envelope_vs_full": envelope}),
    )
}
