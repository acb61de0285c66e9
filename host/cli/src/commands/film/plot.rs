//! `bearing film --plot`: central film of every film model against load or entrainment speed,
//! with each model's error against the numerical solution, as a PNG.

use super::numerical_solution;
use anyhow::{anyhow, Result};
use bearing_core::film::ann::{AnnF32, AnnInt};
use bearing_core::{ContactInput, FilmModel, FilmSource, Regression};
use bearing_host_common::plot_style::draw_legend;
use plotters::prelude::*;
use std::path::Path;

/// What the horizontal axis of the plot varies.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum PlotOver {
    /// Roller load Q (N).
    Load,
    /// Entrainment speed u_m (m/s).
    Speed,
}

/// One point of the sweep: the varied value and each model's central film (m), `None` where
/// the numerical solver did not converge; the network entries carry whether they fell back.
struct Point {
    x: f64,
    numerical: Option<f64>,
    ann_f32: (f64, bool),
    ann_int: (f64, bool),
    regression: f64,
}

/// The contact with its load or speed set to `value`.
fn varied(contact: &ContactInput, over: PlotOver, value: f64) -> ContactInput {
    match over {
        PlotOver::Load => ContactInput {
            load_n: value as f32,
            ..*contact
        },
        PlotOver::Speed => ContactInput {
            entrainment_speed_m_s: value as f32,
            ..*contact
        },
    }
}

/// Sweep `points` values spaced evenly in log from value/`span` to value·`span` around the
/// contact's own load or speed.
fn sweep(contact: &ContactInput, over: PlotOver, points: usize, span: f64) -> Vec<Point> {
    let centre = f64::from(match over {
        PlotOver::Load => contact.load_n,
        PlotOver::Speed => contact.entrainment_speed_m_s,
    });
    let n = points.max(2);
    (0..n)
        .map(|k| {
            let x = centre * span.powf(-1.0 + 2.0 * k as f64 / (n - 1) as f64);
            let c = varied(contact, over, x);
            let numerical = numerical_solution(&c).ok().map(|s| s.central_film_m);
            let net =
                |f: bearing_core::Film| (f64::from(f.central_m), f.source == FilmSource::Fallback);
            Point {
                x,
                numerical,
                ann_f32: net(AnnF32.film(&c)),
                ann_int: net(AnnInt.film(&c)),
                regression: f64::from(Regression.film(&c).central_m),
            }
        })
        .collect()
}

/// Draw the film of every model against load or speed (top, log–log, µm; network points that
/// fell back to the regression drawn hollow) and each model's relative error against the
/// numerical solution (bottom, %), into a PNG at `path`.
pub fn plot(
    contact: &ContactInput,
    over: PlotOver,
    points: usize,
    span: f64,
    title: &str,
    path: &Path,
) -> Result<()> {
    let data = sweep(contact, over, points, span);
    let e = |err: plotters::drawing::DrawingAreaErrorKind<_>| anyhow!("{err}");
    let root = BitMapBackend::new(path, (1000, 850)).into_drawing_area();
    root.fill(&WHITE).map_err(e)?;
    let (top, bottom) = root.split_vertically(480);
    let x_range = data.first().map_or(1.0, |p| p.x)..data.last().map_or(10.0, |p| p.x);
    let films: Vec<f64> = data
        .iter()
        .flat_map(|p| {
            [
                p.numerical.unwrap_or(p.regression),
                p.regression,
                p.ann_f32.0,
            ]
        })
        .map(|h| h * 1e6)
        .collect();
    let lo = films.iter().cloned().fold(f64::MAX, f64::min) * 0.8;
    let hi = films.iter().cloned().fold(f64::MIN, f64::max) * 1.25;
    let x_desc = match over {
        PlotOver::Load => "roller load Q (N)",
        PlotOver::Speed => "entrainment speed u_m (m/s)",
    };
    let mut chart = ChartBuilder::on(&top)
        .caption(format!("central film: {title}"), ("sans-serif", 22))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(x_range.clone().log_scale(), (lo..hi).log_scale())
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc("h_c (µm)")
        .draw()
        .map_err(e)?;
    type Series<'a> = (
        &'a str,
        RGBColor,
        Box<dyn Fn(&Point) -> Option<(f64, bool)>>,
    );
    let series: [Series; 4] = [
        (
            "numerical",
            BLACK,
            Box::new(|p| p.numerical.map(|h| (h, false))),
        ),
        ("ann_f32", BLUE, Box::new(|p| Some(p.ann_f32))),
        ("ann_int", GREEN, Box::new(|p| Some(p.ann_int))),
        ("regression", RED, Box::new(|p| Some((p.regression, false)))),
    ];
    for (name, colour, value) in &series {
        let line: Vec<(f64, f64)> = data
            .iter()
            .filter_map(|p| value(p).map(|(h, _)| (p.x, h * 1e6)))
            .collect();
        let colour = *colour;
        chart
            .draw_series(LineSeries::new(line, colour.stroke_width(2)))
            .map_err(e)?
            .label(*name)
            .legend(move |(a, b)| PathElement::new(vec![(a, b), (a + 20, b)], colour));
        chart
            .draw_series(data.iter().filter_map(|p| {
                value(p).map(|(h, fell_back)| {
                    let style = if fell_back {
                        colour.stroke_width(1)
                    } else {
                        colour.filled()
                    };
                    Circle::new((p.x, h * 1e6), 3, style)
                })
            }))
            .map_err(e)?;
    }
    draw_legend(&mut chart, SeriesLabelPosition::UpperRight).map_err(e)?;

    // Relative errors against the numerical solution, where it converged.
    let errors: Vec<(usize, f64, f64)> = data
        .iter()
        .filter_map(|p| p.numerical.map(|n| (p, n)))
        .flat_map(|(p, n)| {
            [
                (1, p.x, 100.0 * (p.ann_f32.0 / n - 1.0)),
                (2, p.x, 100.0 * (p.ann_int.0 / n - 1.0)),
                (3, p.x, 100.0 * (p.regression / n - 1.0)),
            ]
        })
        .collect();
    let bound = errors
        .iter()
        .map(|(_, _, v)| v.abs())
        .fold(1.0, f64::max)
        .min(100.0)
        * 1.1;
    let mut chart = ChartBuilder::on(&bottom)
        .caption(
            "error against the numerical solution (hollow: network fell back to the regression)",
            ("sans-serif", 18),
        )
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(x_range.log_scale(), -bound..bound)
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .y_desc("h_c error (%)")
        .draw()
        .map_err(e)?;
    for (index, (_, colour, _)) in series.iter().enumerate().skip(1) {
        let line: Vec<(f64, f64)> = errors
            .iter()
            .filter(|(k, _, _)| *k == index)
            .map(|(_, x, v)| (*x, v.clamp(-bound, bound)))
            .collect();
        chart
            .draw_series(LineSeries::new(line, colour.stroke_width(2)))
            .map_err(e)?;
    }
    root.present().map_err(e)?;
    Ok(())
}
