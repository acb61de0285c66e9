//! PNG plot of an EHL solution: pressure against X with the Hertz ellipse, and the film.

use anyhow::{anyhow, Result};
use bearing_ehl::EhlSolution;
use bearing_host_common::plot_style::draw_legend;
use plotters::prelude::*;
use std::path::Path;

/// Two stacked panels: p/p_h with the Hertz ellipse √(1−X²) (top), h in µm (bottom).
pub fn plot(s: &EhlSolution, path: &Path) -> Result<()> {
    let root = BitMapBackend::new(path, (1000, 800)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| anyhow!("{e}"))?;
    let (top, bottom) = root.split_vertically(420);
    let x = &s.profile.x;
    let (x0, x1) = (x[0], x[x.len() - 1]);
    let pmax = s.profile.pressure.iter().cloned().fold(1.0, f64::max) * 1.1;
    let mut chart = ChartBuilder::on(&top)
        .caption(
            format!(
                "EHL pressure: p_h = {:.3} GPa, M = {:.2}, L = {:.2}",
                s.hertz_pressure_pa / 1e9,
                s.case.moes_m(),
                s.case.moes_l()
            ),
            ("sans-serif", 22),
        )
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(x0..x1, 0.0..pmax)
        .map_err(|e| anyhow!("{e}"))?;
    chart
        .configure_mesh()
        .x_desc("x / b")
        .y_desc("p / p_h")
        .draw()
        .map_err(|e| anyhow!("{e}"))?;
    chart
        .draw_series(LineSeries::new(
            x.iter().cloned().zip(s.profile.pressure.iter().cloned()),
            BLUE.stroke_width(2),
        ))
        .map_err(|e| anyhow!("{e}"))?
        .label("EHL pressure")
        .legend(|(a, b)| PathElement::new(vec![(a, b), (a + 20, b)], BLUE.stroke_width(2)));
    let hertz: Vec<(f64, f64)> = (0..=400)
        .map(|k| {
            let xx = -1.0 + 2.0 * k as f64 / 400.0;
            (xx, (1.0 - xx * xx).max(0.0).sqrt())
        })
        .collect();
    chart
        .draw_series(LineSeries::new(hertz, RED.stroke_width(1)))
        .map_err(|e| anyhow!("{e}"))?
        .label("Hertz")
        .legend(|(a, b)| PathElement::new(vec![(a, b), (a + 20, b)], RED));
    draw_legend(&mut chart, SeriesLabelPosition::UpperLeft).map_err(|e| anyhow!("{e}"))?;

    let scale = s.case.film_scale_m() * 1e6;
    let film: Vec<(f64, f64)> = x
        .iter()
        .zip(&s.profile.film)
        .map(|(x, h)| (*x, h * scale))
        .collect();
    let hc = s.central_film_m * 1e6;
    let hmax = (hc * 3.0).max(s.min_film_m * 1e6 * 3.0);
    let mut chart = ChartBuilder::on(&bottom)
        .caption(
            format!(
                "film: h_c = {:.4} µm, h_min = {:.4} µm",
                hc,
                s.min_film_m * 1e6
            ),
            ("sans-serif", 22),
        )
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(60)
        .build_cartesian_2d(x0..x1, 0.0..hmax)
        .map_err(|e| anyhow!("{e}"))?;
    chart
        .configure_mesh()
        .x_desc("x / b")
        .y_desc("h [µm]")
        .draw()
        .map_err(|e| anyhow!("{e}"))?;
    chart
        .draw_series(LineSeries::new(
            film.into_iter().filter(|(_, h)| *h <= hmax),
            BLACK.stroke_width(2),
        ))
        .map_err(|e| anyhow!("{e}"))?;
    root.present().map_err(|e| anyhow!("{e}"))?;
    Ok(())
}
