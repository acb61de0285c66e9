//! `bearing shaft run`: the time response at one speed (or a run-up / run-down ramp), its
//! CSV records, orbit, spectrum and waterfall plots and the cost summary.

use std::path::{Path, PathBuf};

use anyhow::{Context, Result};
use bearing_host_common::output::OutputFiles;
use bearing_shaft::bearing::BearingSpec;
use bearing_shaft::model::RotorModel;
use bearing_shaft::simulate::run as run_time;
use bearing_shaft::spectrum::amplitude_spectrum;
use bearing_shaft::{output, plots};

use super::report::reduction_report;
use super::{check, load, mesh_orders, rpm_to_rad, settings, with_suffix, RunArgs};

pub(super) fn cmd_run(a: RunArgs) -> Result<()> {
    let model = load(&a.model)?;
    let omega = rpm_to_rad(check("speed-rpm", a.speed_rpm, 0.0, 1e6, false)?);
    let end = match a.speed_end_rpm {
        Some(v) => Some(rpm_to_rad(check("speed-end-rpm", v, 0.0, 1e6, false)?)),
        None => None,
    };
    let mut s = settings(&model, &a.time, omega.max(end.unwrap_or(0.0)))?;
    s.spin_speed = omega;
    s.spin_speed_end = end;
    let r = run_time(&model, &s, None)?;
    // Every file of the run or none: staged under temporary names, renamed at the end.
    let mut files = OutputFiles::new();
    let mut stage = |path: &Path| {
        files
            .stage(path)
            .with_context(|| format!("writing {}", path.display()))
    };
    let csv = with_suffix(&a.out, ".csv");
    output::write_run_csv(&stage(&csv)?, &r)
        .with_context(|| format!("writing {}", csv.display()))?;
    let n_b = model.description.bearings.len();
    for b in 0..n_b {
        let p = with_suffix(&a.out, &format!("_b{b}_trace.csv"));
        // hil-sim names bearings by their config file stem and knows the thesis oil, the oil of
        // the bundled bearing files; a linear spring has no lubricant.
        let (id, lubricant) = match &model.description.bearings[b].spec {
            BearingSpec::Roller { config, .. } => (
                config
                    .file_stem()
                    .map_or("roller".into(), |s| s.to_string_lossy().into_owned()),
                "thesis_oil",
            ),
            BearingSpec::Linear(_) => ("linear".to_string(), "none"),
        };
        output::write_kinematics_trace(
            &stage(&p)?,
            &r,
            b,
            (&id, lubricant),
            s.dt * s.record_every as f64,
        )
        .with_context(|| format!("writing {}", p.display()))?;
        // A roller record only for a bearing with rollers (write_roller_csv writes nothing
        // otherwise, and an empty staged file must not be renamed into place).
        if r.samples.first().is_some_and(|x| x.rollers[b].is_some()) {
            let p = with_suffix(&a.out, &format!("_b{b}_rollers.csv"));
            output::write_roller_csv(&stage(&p)?, &r, b)
                .with_context(|| format!("writing {}", p.display()))?;
        }
    }
    // Plots for the first bearing (inner race): orbit and spectrum of y.
    let orbit: Vec<[f64; 2]> = r.samples.iter().map(|s| s.probes[0][0]).collect();
    let orbit_png = with_suffix(&a.out, "_orbit.png");
    plots::orbit(
        &orbit,
        &format!("orbit, node {} at {} rpm", r.probe_nodes[0], a.speed_rpm),
        &stage(&orbit_png)?,
    )
    .map_err(|e| anyhow::anyhow!("writing {}: {e}", orbit_png.display()))?;
    let y: Vec<f64> = orbit.iter().map(|p| p[1]).collect();
    let spec = amplitude_spectrum(&y, s.dt * s.record_every as f64);
    let fs = omega / (2.0 * std::f64::consts::PI);
    let mut markers = vec![("1× speed".to_string(), fs)];
    for m in mesh_orders(&model) {
        markers.push((format!("mesh {m}×"), m * fs));
    }
    for (i, b) in model.description.bearings.iter().enumerate() {
        if let BearingSpec::Roller { config, .. } = &b.spec {
            let f = bearing_shaft::roller_bearing::outer_race_pass_hz(config, omega)?;
            markers.push((format!("outer-race pass, bearing {i}"), f));
        }
    }
    let spec_png = with_suffix(&a.out, "_spectrum.png");
    plots::spectrum(
        &spec,
        &markers,
        &format!("spectrum of y, node {}", r.probe_nodes[0]),
        &stage(&spec_png)?,
    )
    .map_err(|e| anyhow::anyhow!("writing {}: {e}", spec_png.display()))?;
    let mut plotted = vec![
        orbit_png.display().to_string(),
        spec_png.display().to_string(),
    ];
    if end.is_some() {
        // Run-up / run-down: short-time spectra of y over the record, one row per window.
        let sample_dt = s.dt * s.record_every as f64;
        let rows = runup_spectra(&r, &y, sample_dt);
        let top = r.samples.iter().map(|x| x.spin_speed).fold(0.0, f64::max);
        let orders = spectrum_orders(&model, 1.0)?;
        let f_max = 1.3 * orders.iter().map(|o| o.1).fold(1.0, f64::max) * top
            / (2.0 * std::f64::consts::PI);
        let png = with_suffix(&a.out, "_waterfall.png");
        plots::waterfall(
            &rows,
            &orders,
            f_max.min(0.5 / sample_dt),
            &format!("waterfall of y, node {}", r.probe_nodes[0]),
            &stage(&png)?,
        )
        .map_err(|e| anyhow::anyhow!("writing {}: {e}", png.display()))?;
        plotted.push(png.display().to_string());
    }
    let cost = r.cost(s.dt);
    let reduction = match s.reduction_modes {
        None => serde_json::Value::Null,
        Some(k) => reduction_report(&model, &s, k, a.compare_full, &r)?,
    };
    files.commit()?;
    let summary = serde_json::json!({
        "speed_rpm": a.speed_rpm, "speed_end_rpm": a.speed_end_rpm, "dt_s": s.dt, "steps": r.steps, "n_dof": r.n_dof,
        "wall_seconds": r.wall_seconds, "bearing_seconds": r.bearing_seconds,
        "real_time_factor": cost.real_time_factor, "cost": cost,
        "max_newton_iterations": r.max_newton_iterations, "steadiness": r.steadiness,
        "resolution_limited_steps": r.resolution_limited_steps,
        "envelope": r.envelope, "csv": csv, "reduction": reduction,
    });
    if a.model.json {
        println!("{summary}");
    } else {
        println!("{}", serde_json::to_string_pretty(&summary)?);
        println!("{}", cost_line(&cost));
        println!("plots: {}", plotted.join(", "));
    }
    Ok(())
}

/// One line: real-time factor, step, DOFs and where the time per step went.
fn cost_line(c: &bearing_shaft::simulate::CostBreakdown) -> String {
    format!(
        "real-time factor {:.3} (dt {:.3} µs, {} DOF, {} steps, {:.2} bearing evaluations/step); \
         per step: bearings {:.2} µs ({:.2} µs per evaluation of all bearings), shaft linear \
         algebra {:.2} µs, rest (loads, recording, a ramp's operator rebuilds) {:.2} µs",
        c.real_time_factor,
        c.dt_s * 1e6,
        c.n_dof,
        c.steps,
        c.bearing_evaluations_per_step,
        c.bearing_us_per_step,
        c.bearing_us_per_evaluation,
        c.linear_algebra_us_per_step,
        c.rest_us_per_step
    )
}

/// Excitation orders for waterfall lines: 1×, each gear mesh and each roller bearing's
/// outer-race pass (f_bpo / f_s, from its geometry at spin speed `omega` — it is a fixed order).
pub(super) fn spectrum_orders(model: &RotorModel, omega: f64) -> Result<Vec<(String, f64)>> {
    let fs = omega / (2.0 * std::f64::consts::PI);
    let mut orders = vec![("1×".to_string(), 1.0)];
    for m in mesh_orders(model) {
        orders.push((format!("mesh {m}×"), m));
    }
    let mut seen: Vec<PathBuf> = Vec::new();
    for b in &model.description.bearings {
        if let BearingSpec::Roller { config, .. } = &b.spec {
            if seen.contains(config) {
                continue;
            }
            seen.push(config.clone());
            let f = bearing_shaft::roller_bearing::outer_race_pass_hz(config, omega)?;
            let stem = config
                .file_stem()
                .map_or("".into(), |s| s.to_string_lossy());
            orders.push((format!("outer-race pass {stem} {:.2}×", f / fs), f / fs));
        }
    }
    Ok(orders)
}

/// Short-time spectra of a run-up record: windows of about 1/8 of the record (a power of two,
/// ≥ 64 samples) advancing by a quarter window, each labelled with its mean speed (rpm).
fn runup_spectra(
    r: &bearing_shaft::simulate::RunResult,
    y: &[f64],
    sample_dt: f64,
) -> Vec<plots::WaterfallRow> {
    let mut window = 64usize;
    while window * 2 <= y.len() / 8 {
        window *= 2;
    }
    let mut rows = Vec::new();
    let mut start = 0;
    while start + window <= y.len() {
        let speed = r.samples[start..start + window]
            .iter()
            .map(|s| s.spin_speed)
            .sum::<f64>()
            / window as f64;
        rows.push((
            speed * 30.0 / std::f64::consts::PI,
            amplitude_spectrum(&y[start..start + window], sample_dt),
        ));
        start += window / 4;
    }
    rows
}
