//! Plots of a replay (plotters, PNG): the step-time histogram with the budget, the errors
//! along the trace (stepper and dry model against the reference), and the central film of every
//! roller along the trace.

use super::engine::ReplayRun;
use super::stats::percentile_sorted;
use crate::trace::Trace;
use bearing_host_common::output::OutputFiles;
use bearing_host_common::plot_style::draw_legend;
use plotters::prelude::*;
use std::path::Path;

type PlotResult = Result<(), Box<dyn std::error::Error>>;

/// A labelled, coloured line of (x, y) points.
type Series = (&'static str, RGBColor, Vec<(f64, f64)>);

const SIZE: (u32, u32) = (1000, 600);

/// Draws every plot that has data into `files`, staged for `dir` (they appear there when
/// `files` is committed); returns the file names.
pub fn write_all(
    files: &mut OutputFiles,
    dir: &Path,
    trace: &Trace,
    run: &ReplayRun,
    budget_us: f64,
) -> Result<Vec<String>, String> {
    let mut written = Vec::new();
    let mut attempt = |name: &str, draw: &dyn Fn(&Path) -> PlotResult| {
        let temp = files
            .stage(&dir.join(name))
            .map_err(|e| format!("plot {name}: {e}"))?;
        draw(&temp).map_err(|e| format!("plot {name}: {e}"))?;
        written.push(name.to_string());
        Ok::<(), String>(())
    };
    attempt("step_time_histogram.png", &|p| {
        step_time_histogram(p, &run.step_times_ns, budget_us)
    })?;
    if !run.points.is_empty() {
        attempt("error_along_trace.png", &|p| error_along_trace(p, run))?;
    }
    if run.outputs.first().is_some_and(|o| o.rollers > 0) {
        attempt("film_per_roller.png", &|p| film_per_roller(p, trace, run))?;
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
    draw_legend(&mut chart, SeriesLabelPosition::MiddleRight)?;
    root.present()?;
    Ok(())
}

/// Colour of a value scaled to [0, 1]: dark blue through green to yellow (a viridis-like ramp,
/// readable in grey scale because its lightness rises monotonically).
fn ramp(t: f64) -> RGBColor {
    let t = t.clamp(0.0, 1.0);
    let stops = [
        (68.0, 1.0, 84.0),
        (59.0, 82.0, 139.0),
        (33.0, 145.0, 140.0),
        (94.0, 201.0, 98.0),
        (253.0, 231.0, 37.0),
    ];
    let x = t * (stops.len() - 1) as f64;
    let i = (x as usize).min(stops.len() - 2);
    let f = x - i as f64;
    let (a, b) = (stops[i], stops[i + 1]);
    let mix = |p: f64, q: f64| (p + (q - p) * f).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// Central film at the inner contact of every roller. Top: a map of the first (up to) 400
/// steps — time across, roller index up, colour the film — where each roller's passage through
/// the load zone is a diagonal stripe. Bottom: the film against the roller's angular position
/// over the whole trace (up to 20 000 points), which shows the load zone.
pub fn film_per_roller(path: &Path, trace: &Trace, run: &ReplayRun) -> PlotResult {
    let rollers = run
        .outputs
        .first()
        .map_or(0, |o| o.rollers)
        .min(super::MAX_ROLLERS);
    let steps = run.outputs.len().min(trace.samples.len());
    if rollers == 0 || steps == 0 {
        return Err("no roller outputs".into());
    }
    let film_um = |out: &super::StepOutputs, j: usize| f64::from(out.film_inner_m[j]) * 1e6;
    let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
    for out in run.outputs.iter().take(steps) {
        for j in 0..rollers {
            let v = film_um(out, j);
            if v.is_finite() {
                lo = lo.min(v);
                hi = hi.max(v);
            }
        }
    }
    if !(lo.is_finite() && hi.is_finite()) {
        return Err("no finite film values".into());
    }
    let span = (hi - lo).max(1e-12);
    let root = BitMapBackend::new(path, (1000, 900)).into_drawing_area();
    root.fill(&WHITE)?;
    let (top, bottom) = root.split_vertically(450);

    let window = steps.min(400);
    let t0 = trace.samples.first().map_or(0.0, |s| s.time_s);
    let period = 1.0 / trace.meta.sample_rate_hz;
    let t1 = t0 + window as f64 * period;
    let mut map = ChartBuilder::on(&top)
        .caption(
            format!("Central film, inner contact, first {window} steps: {lo:.3} µm (dark) … {hi:.3} µm (yellow)"),
            ("sans-serif", 20),
        )
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(t0..t1, 0.0..rollers as f64)?;
    map.configure_mesh()
        .disable_mesh()
        .x_desc("time (s)")
        .y_desc("roller")
        .draw()?;
    map.draw_series(
        run.outputs
            .iter()
            .take(window)
            .enumerate()
            .flat_map(|(i, out)| {
                let x0 = t0 + i as f64 * period;
                (0..rollers).map(move |j| {
                    Rectangle::new(
                        [(x0, j as f64), (x0 + period, j as f64 + 1.0)],
                        ramp((film_um(out, j) - lo) / span).filled(),
                    )
                })
            }),
    )?;

    let pad = 0.05 * span;
    let mut scatter = ChartBuilder::on(&bottom)
        .caption(
            "Central film against roller position, whole trace",
            ("sans-serif", 20),
        )
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(0.0..360.0, (lo - pad)..(hi + pad))?;
    scatter
        .configure_mesh()
        .x_desc("roller angle from +x (degrees)")
        .y_desc("central film (µm)")
        .draw()?;
    let stride = (steps * rollers / 20_000).max(1);
    let points = run
        .outputs
        .iter()
        .take(steps)
        .flat_map(|out| {
            (0..rollers).map(move |j| {
                let angle = f64::from(out.cage_angle_rad)
                    + std::f64::consts::TAU * j as f64 / rollers as f64;
                (
                    angle.rem_euclid(std::f64::consts::TAU).to_degrees(),
                    film_um(out, j),
                )
            })
        })
        .step_by(stride);
    scatter.draw_series(points.map(|p| Circle::new(p, 1, BLUE.mix(0.4).filled())))?;
    root.present()?;
    Ok(())
}
