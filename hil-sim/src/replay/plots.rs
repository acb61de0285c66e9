//! Plots of a replay (plotters, PNG): the step-time histogram with the budget, the errors
//! along the trace (stepper and dry model against the reference), and the central film of every
//! roller along the trace.

use super::engine::ReplayRun;
use super::stats::percentile_sorted;
use crate::trace::Trace;
use plotters::prelude::*;
use std::path::Path;

type PlotResult = Result<(), Box<dyn std::error::Error>>;

/// A labelled, coloured line of (x, y) points.
type Series = (&'static str, RGBColor, Vec<(f64, f64)>);

const SIZE: (u32, u32) = (1000, 600);

/// Writes every plot that has data into `dir`; returns the file names written.
pub fn write_all(
    dir: &Path,
    trace: &Trace,
    run: &ReplayRun,
    budget_us: f64,
) -> Result<Vec<String>, String> {
    let mut written = Vec::new();
    let mut attempt = |name: &str, result: PlotResult| match result {
        Ok(()) => {
            written.push(name.to_string());
            Ok(())
        }
        Err(e) => Err(format!("plot {name}: {e}")),
    };
    attempt(
        "step_time_histogram.png",
        step_time_histogram(
            &dir.join("step_time_histogram.png"),
            &run.step_times_ns,
            budget_us,
        ),
    )?;
    if !run.points.is_empty() {
        attempt(
            "error_along_trace.png",
            error_along_trace(&dir.join("error_along_trace.png"), run),
        )?;
    }
    if run.outputs.first().is_some_and(|o| o.rollers > 0) {
        attempt(
            "film_per_roller.png",
            film_per_roller(&dir.join("film_per_roller.png"), trace, run),
        )?;
    }
    Ok(written)
}

/// Histogram of step times in µs over [0, 2·p99.9] (slower steps counted in the caption).
pub fn step_time_histogram(path: &Path, times_ns: &[u64], budget_us: f64) -> PlotResult {
    let mut sorted = times_ns.to_vec();
    sorted.sort_unstable();
    let p999 = percentile_sorted(&sorted, 0.999).unwrap_or(1) as f64 / 1e3;
    let upper = (2.0 * p999).max(budget_us * 1.1).max(1e-3);
    const BINS: usize = 60;
    let width = upper / BINS as f64;
    let mut counts = [0u32; BINS];
    let mut overflow = 0usize;
    for &t in &sorted {
        let us = t as f64 / 1e3;
        match counts.get_mut((us / width) as usize) {
            Some(c) => *c += 1,
            None => overflow += 1,
        }
    }
    let top = counts.iter().copied().max().unwrap_or(1).max(1);
    let root = BitMapBackend::new(path, SIZE).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            format!(
                "Step time ({} steps, {} beyond the axis); red: budget {} µs",
                sorted.len(),
                overflow,
                budget_us
            ),
            ("sans-serif", 22),
        )
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(0.0..upper, 0u32..top + top / 10 + 1)?;
    chart
        .configure_mesh()
        .x_desc("step time (µs)")
        .y_desc("steps")
        .draw()?;
    chart.draw_series(counts.iter().enumerate().map(|(i, &c)| {
        let x0 = i as f64 * width;
        Rectangle::new([(x0, 0), (x0 + width, c)], BLUE.mix(0.6).filled())
    }))?;
    chart.draw_series(LineSeries::new(
        [(budget_us, 0), (budget_us, top + top / 10 + 1)],
        RED.stroke_width(2),
    ))?;
    root.present()?;
    Ok(())
}

/// Relative errors (log scale) at the reference samples along the trace.
pub fn error_along_trace(path: &Path, run: &ReplayRun) -> PlotResult {
    let floor = 1e-7;
    let series: [Series; 3] = [
        (
            "central film (worst loaded contact)",
            BLUE,
            run.points
                .iter()
                .filter_map(|p| p.film_rel_err_max.map(|e| (p.time_s, e.max(floor))))
                .collect(),
        ),
        (
            "bearing force",
            GREEN,
            run.points
                .iter()
                .filter_map(|p| p.force_rel_err.map(|e| (p.time_s, e.max(floor))))
                .collect(),
        ),
        (
            "bearing force, dry model",
            RED,
            run.points
                .iter()
                .filter_map(|p| p.dry_force_rel_err.map(|e| (p.time_s, e.max(floor))))
                .collect(),
        ),
    ];
    let t0 = run.points.first().map_or(0.0, |p| p.time_s);
    let t1 = run.points.last().map_or(1.0, |p| p.time_s).max(t0 + 1e-9);
    let top = series
        .iter()
        .flat_map(|(_, _, v)| v.iter().map(|&(_, e)| e))
        .fold(floor * 10.0, f64::max)
        * 2.0;
    let root = BitMapBackend::new(path, SIZE).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "Relative error against the full numerical solver",
            ("sans-serif", 22),
        )
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(80)
        .build_cartesian_2d(t0..t1, (floor..top).log_scale())?;
    chart
        .configure_mesh()
        .x_desc("time (s)")
        .y_desc("relative error")
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()?;
    for (label, color, points) in series {
        if points.is_empty() {
            continue;
        }
        chart
            .draw_series(LineSeries::new(points, color.stroke_width(2)))?
            .label(label)
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], color.stroke_width(2)));
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    Ok(())
}

/// Central film at the inner contact of every roller along the trace (µm).
pub fn film_per_roller(path: &Path, trace: &Trace, run: &ReplayRun) -> PlotResult {
    let rollers = run
        .outputs
        .first()
        .map_or(0, |o| o.rollers)
        .min(super::MAX_ROLLERS);
    // At most ~4000 points per line keeps the PNG readable and the drawing fast.
    let stride = (run.outputs.len() / 4000).max(1);
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for out in run.outputs.iter().step_by(stride) {
        for &h in out.film_inner_m.iter().take(rollers) {
            let um = f64::from(h) * 1e6;
            if um.is_finite() {
                lo = lo.min(um);
                hi = hi.max(um);
            }
        }
    }
    if !(lo.is_finite() && hi.is_finite()) {
        return Err("no finite film values".into());
    }
    let pad = ((hi - lo) * 0.05).max(1e-6);
    let t0 = trace.samples.first().map_or(0.0, |s| s.time_s);
    let t1 = trace
        .samples
        .last()
        .map_or(1.0, |s| s.time_s)
        .max(t0 + 1e-9);
    let root = BitMapBackend::new(path, SIZE).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            format!("Central film, inner contact, {rollers} rollers"),
            ("sans-serif", 22),
        )
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(80)
        .build_cartesian_2d(t0..t1, (lo - pad)..(hi + pad))?;
    chart
        .configure_mesh()
        .x_desc("time (s)")
        .y_desc("central film (µm)")
        .draw()?;
    for j in 0..rollers {
        let color = Palette99::pick(j).to_rgba();
        let line = trace
            .samples
            .iter()
            .zip(&run.outputs)
            .step_by(stride)
            .filter_map(|(s, o)| {
                o.film_inner_m
                    .get(j)
                    .map(|&h| (s.time_s, f64::from(h) * 1e6))
            });
        chart.draw_series(LineSeries::new(line, color.stroke_width(1)))?;
    }
    root.present()?;
    Ok(())
}
