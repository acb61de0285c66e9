//! PNG plots (plotters, bitmap backend): Campbell diagram, orbit, spectrum, sweep envelopes and
//! the sweep's power loss.

use std::path::Path;

use plotters::prelude::*;

use bearing_host_common::plot_style::draw_legend;

use crate::analysis::operating::CampbellPoint;
use crate::analysis::sweep::SweepPoint;

type PlotResult = Result<(), Box<dyn std::error::Error>>;

fn range_of(values: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), v| {
            (a.min(v), b.max(v))
        });
    if !lo.is_finite() {
        return (0.0, 1.0);
    }
    let pad = 0.05 * (hi - lo).max(hi.abs() * 1e-3).max(1e-30);
    (lo - pad, hi + pad)
}

/// Campbell diagram: natural frequencies (Hz) against speed (rpm), forward whirl solid red,
/// backward blue, with the 1× and `orders` excitation lines.
pub fn campbell(points: &[CampbellPoint], orders: &[f64], path: &Path) -> PlotResult {
    let root = BitMapBackend::new(path, (1000, 700)).into_drawing_area();
    root.fill(&WHITE)?;
    let max_rpm = points
        .iter()
        .map(|p| p.speed_rpm)
        .fold(0.0, f64::max)
        .max(1.0);
    let to_hz = 1.0 / (2.0 * std::f64::consts::PI);
    let max_hz = points
        .iter()
        .flat_map(|p| p.frequencies_rad_s.iter().map(move |w| w * to_hz))
        .fold(0.0, f64::max)
        * 1.1;
    let mut chart = ChartBuilder::on(&root)
        .caption("Campbell diagram", ("sans-serif", 26))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(0.0..max_rpm, 0.0..max_hz.max(1.0))?;
    chart
        .configure_mesh()
        .x_desc("speed (rpm)")
        .y_desc("natural frequency (Hz)")
        .draw()?;
    let n_modes = points
        .iter()
        .map(|p| p.frequencies_rad_s.len())
        .max()
        .unwrap_or(0);
    for m in 0..n_modes {
        let pts: Vec<(f64, f64, crate::analysis::modes::Whirl)> = points
            .iter()
            .filter_map(|p| {
                p.frequencies_rad_s
                    .get(m)
                    .map(|w| (p.speed_rpm, w * to_hz, p.whirl[m]))
            })
            .collect();
        chart.draw_series(pts.iter().map(|&(x, y, wh)| {
            let color = match wh {
                crate::analysis::modes::Whirl::Forward => RED,
                crate::analysis::modes::Whirl::Backward => BLUE,
                crate::analysis::modes::Whirl::Planar => BLACK,
            };
            Circle::new((x, y), 3, color.filled())
        }))?;
    }
    for (i, &order) in std::iter::once(&1.0).chain(orders).enumerate() {
        let color = Palette99::pick(i + 3).to_rgba();
        chart
            .draw_series(LineSeries::new(
                [(0.0, 0.0), (max_rpm, order * max_rpm / 60.0)],
                color.stroke_width(2),
            ))?
            .label(format!("{order}× speed"))
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], color));
    }
    draw_legend(&mut chart, SeriesLabelPosition::MiddleRight)?;
    root.present()?;
    Ok(())
}

/// Orbit y against x (µm) of one node.
pub fn orbit(xy: &[[f64; 2]], title: &str, path: &Path) -> PlotResult {
    let root = BitMapBackend::new(path, (800, 800)).into_drawing_area();
    root.fill(&WHITE)?;
    let um: Vec<(f64, f64)> = xy.iter().map(|p| (p[0] * 1e6, p[1] * 1e6)).collect();
    let (x0, x1) = range_of(um.iter().map(|p| p.0));
    let (y0, y1) = range_of(um.iter().map(|p| p.1));
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 24))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(x0..x1, y0..y1)?;
    chart
        .configure_mesh()
        .x_desc("x (µm)")
        .y_desc("y (µm)")
        .draw()?;
    chart.draw_series(LineSeries::new(um, BLUE))?;
    root.present()?;
    Ok(())
}

/// Amplitude spectrum (log amplitude) with vertical markers at the given frequencies (Hz).
///
/// The band is 1.5 × the highest marker, widened to at least one frequency bin and at most the
/// spectrum's last bin; the amplitude axis spans 6 decades below the largest amplitude shown, or
/// 10⁻³⁰ … 2·10⁻³⁰ m when nothing in the band is above zero (a model without loads, a record
/// too short for a line): both bounds are always finite and positive, which the log axis needs
/// to place its ticks.
pub fn spectrum(
    spec: &[(f64, f64)],
    markers: &[(String, f64)],
    title: &str,
    path: &Path,
) -> PlotResult {
    let root = BitMapBackend::new(path, (1000, 600)).into_drawing_area();
    root.fill(&WHITE)?;
    let pts: Vec<(f64, f64)> = spec.iter().skip(1).copied().filter(|p| p.1 > 0.0).collect();
    let last_bin_hz = pts.last().map_or(1.0, |p| p.0);
    let first_bin_hz = pts.first().map_or(1.0, |p| p.0);
    let f_max = markers.iter().map(|m| m.1).fold(0.0, f64::max) * 1.5;
    let f_max = if f_max.is_finite() && f_max > 0.0 {
        f_max.max(first_bin_hz).min(last_bin_hz)
    } else {
        last_bin_hz
    };
    let shown: Vec<(f64, f64)> = pts.iter().copied().filter(|p| p.0 <= f_max).collect();
    let a_max = shown
        .iter()
        .map(|p| p.1)
        .filter(|a| a.is_finite())
        .fold(1e-30, f64::max);
    let a_min = (a_max * 1e-6)
        .max(shown.iter().map(|p| p.1).fold(f64::INFINITY, f64::min))
        .min(a_max);
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 24))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(80)
        .build_cartesian_2d(0.0..f_max, (a_min..a_max * 2.0).log_scale())?;
    chart
        .configure_mesh()
        .x_desc("frequency (Hz)")
        .y_desc("amplitude (m)")
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()?;
    chart.draw_series(LineSeries::new(
        shown.iter().map(|p| (p.0, p.1.max(a_min))),
        BLUE,
    ))?;
    for (i, (name, f)) in markers.iter().enumerate() {
        let color = Palette99::pick(i + 1).to_rgba();
        chart
            .draw_series(LineSeries::new(
                [(*f, a_min), (*f, a_max * 2.0)],
                color.stroke_width(1),
            ))?
            .label(name.clone())
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], color));
    }
    draw_legend(&mut chart, SeriesLabelPosition::MiddleRight)?;
    root.present()?;
    Ok(())
}

/// Sweep envelopes against speed, lubricated (solid) and dry (dashed-colour), one panel each
/// for bearing stiffness, displacement and acceleration (and contact force / film when known).
pub fn envelopes(points: &[SweepPoint], path: &Path) -> PlotResult {
    type Get = fn(&crate::analysis::simulate::Envelope) -> Option<f64>;
    let panels: [(&str, Get); 6] = [
        ("max bearing stiffness (N/m)", |e| {
            Some(e.max_bearing_stiffness_n_per_m)
        }),
        ("max inner-race displacement (m)", |e| {
            Some(e.max_displacement_m)
        }),
        ("max acceleration (m/s²)", |e| {
            Some(e.max_acceleration_m_s2)
        }),
        ("max bearing force (N)", |e| Some(e.max_bearing_force_n)),
        ("max contact force (N)", |e| e.max_contact_force_n),
        ("max central film (m)", |e| e.max_central_film_m),
    ];
    let root = BitMapBackend::new(path, (1400, 900)).into_drawing_area();
    root.fill(&WHITE)?;
    let areas = root.split_evenly((2, 3));
    let (r0, r1) = range_of(points.iter().map(|p| p.speed_rpm));
    for ((title, get), area) in panels.iter().zip(areas.iter()) {
        let lub: Vec<(f64, f64)> = points
            .iter()
            .filter_map(|p| get(&p.lubricated).map(|v| (p.speed_rpm, v)))
            .collect();
        let dry: Vec<(f64, f64)> = points
            .iter()
            .filter_map(|p| get(&p.dry).map(|v| (p.speed_rpm, v)))
            .collect();
        let (v0, v1) = range_of(lub.iter().chain(&dry).map(|p| p.1));
        let mut chart = ChartBuilder::on(area)
            .caption(*title, ("sans-serif", 18))
            .margin(10)
            .x_label_area_size(35)
            .y_label_area_size(75)
            .build_cartesian_2d(r0..r1, v0..v1)?;
        chart
            .configure_mesh()
            .x_desc("speed (rpm)")
            .y_label_formatter(&|v| format!("{v:.3e}"))
            .draw()?;
        if lub.is_empty() && dry.is_empty() {
            continue;
        }
        chart
            .draw_series(LineSeries::new(lub.clone(), BLUE.stroke_width(2)))?
            .label("lubricated")
            .legend(|(x, y)| PathElement::new([(x, y), (x + 20, y)], BLUE));
        chart.draw_series(lub.iter().map(|&p| Circle::new(p, 3, BLUE.filled())))?;
        chart
            .draw_series(LineSeries::new(dry.clone(), RED.stroke_width(1)))?
            .label("dry")
            .legend(|(x, y)| PathElement::new([(x, y), (x + 20, y)], RED));
        chart.draw_series(dry.iter().map(|&p| Cross::new(p, 4, RED)))?;
        draw_legend(&mut chart, SeriesLabelPosition::MiddleRight)?;
    }
    root.present()?;
    Ok(())
}

/// Power loss of the roller bearings against speed at each speed's static equilibrium,
/// lubricated (solid, circles) and dry (thin, crosses): the total on the left, its rolling,
/// viscous and boundary parts on the right (docs/shaft.md).
pub fn power_loss(points: &[SweepPoint], path: &Path) -> PlotResult {
    let root = BitMapBackend::new(path, (1400, 600)).into_drawing_area();
    root.fill(&WHITE)?;
    let areas = root.split_evenly((1, 2));
    let (r0, r1) = range_of(points.iter().map(|p| p.speed_rpm));
    type Get = fn(&crate::bearing::BearingFriction) -> f64;
    type Series<'a> = (&'a str, RGBColor, Get);
    let total: [Series; 1] = [("total", BLACK, |f| f.power_loss_w)];
    let parts: [Series; 3] = [
        ("rolling", BLUE, |f| f.power_loss_split_w[0]),
        ("viscous", GREEN, |f| f.power_loss_split_w[1]),
        ("boundary", RED, |f| f.power_loss_split_w[2]),
    ];
    let panels: [(&str, &[Series]); 2] = [
        ("roller bearings: power loss (W)", &total),
        ("power loss by part (W)", &parts),
    ];
    for ((title, series), area) in panels.iter().zip(areas.iter()) {
        let curve = |side: usize, get: Get| -> Vec<(f64, f64)> {
            points
                .iter()
                .filter_map(|p| p.friction[side].map(|f| (p.speed_rpm, get(&f))))
                .collect()
        };
        let all = series
            .iter()
            .flat_map(|(_, _, get)| [curve(0, *get), curve(1, *get)])
            .flatten()
            .map(|p| p.1);
        let (v0, v1) = range_of(all);
        let mut chart = ChartBuilder::on(area)
            .caption(*title, ("sans-serif", 18))
            .margin(10)
            .x_label_area_size(35)
            .y_label_area_size(75)
            .build_cartesian_2d(r0..r1, v0.min(0.0)..v1)?;
        chart
            .configure_mesh()
            .x_desc("speed (rpm)")
            .y_label_formatter(&|v| format!("{v:.3e}"))
            .draw()?;
        for &(name, colour, get) in series.iter() {
            let (lub, dry) = (curve(0, get), curve(1, get));
            chart
                .draw_series(LineSeries::new(lub.clone(), colour.stroke_width(2)))?
                .label(format!("{name}, lubricated"))
                .legend(move |(x, y)| {
                    PathElement::new([(x, y), (x + 20, y)], colour.stroke_width(2))
                });
            chart.draw_series(lub.iter().map(|&p| Circle::new(p, 3, colour.filled())))?;
            chart
                .draw_series(LineSeries::new(dry.clone(), colour.stroke_width(1)))?
                .label(format!("{name}, dry loads"))
                .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], colour));
            chart.draw_series(dry.iter().map(|&p| Cross::new(p, 4, colour)))?;
        }
        draw_legend(&mut chart, SeriesLabelPosition::UpperLeft)?;
    }
    root.present()?;
    Ok(())
}

/// Mode shapes: orbit size √(|X|² + |Y|²) of each node (normalised) against the axial position,
/// one line per mode, labelled with frequency and whirl.
pub fn mode_shapes(
    positions: &[f64],
    modes: &[crate::analysis::modes::Mode],
    path: &Path,
) -> PlotResult {
    let root = BitMapBackend::new(path, (1000, 600)).into_drawing_area();
    root.fill(&WHITE)?;
    let (z0, z1) = range_of(positions.iter().map(|z| z * 1e3));
    let mut chart = ChartBuilder::on(&root)
        .caption("Mode shapes (orbit size)", ("sans-serif", 24))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .build_cartesian_2d(z0..z1, 0.0..1.05)?;
    chart
        .configure_mesh()
        .x_desc("axial position (mm)")
        .y_desc("relative amplitude")
        .draw()?;
    for (i, m) in modes.iter().enumerate() {
        let size: Vec<f64> = m
            .shape
            .chunks(4)
            .map(|n| (n[0].norm_sqr() + n[1].norm_sqr()).sqrt())
            .collect();
        let big = size.iter().copied().fold(1e-300, f64::max);
        let color = Palette99::pick(i).to_rgba();
        chart
            .draw_series(LineSeries::new(
                positions.iter().zip(&size).map(|(z, a)| (z * 1e3, a / big)),
                color.stroke_width(2),
            ))?
            .label(format!(
                "{:.1} Hz {:?}",
                m.frequency / (2.0 * std::f64::consts::PI),
                m.whirl
            ))
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], color));
    }
    draw_legend(&mut chart, SeriesLabelPosition::MiddleRight)?;
    root.present()?;
    Ok(())
}

/// One row of a waterfall: a speed (rpm) and the amplitude spectrum (Hz, m) there.
pub type WaterfallRow = (f64, Vec<(f64, f64)>);

/// Waterfall (colour map): frequency (Hz) across, speed (rpm) up, log₁₀ amplitude as colour
/// over 4 decades below the largest amplitude; each row spans half-way to its neighbours, so
/// unevenly spaced speeds (the §6.2 sweep) and run-up windows both work. `orders` draws the
/// lines f = order × speed / 60 (1×, gear mesh, outer-race pass, …) as labelled dashes.
pub fn waterfall(
    rows: &[WaterfallRow],
    orders: &[(String, f64)],
    f_max: f64,
    title: &str,
    path: &Path,
) -> PlotResult {
    let root = BitMapBackend::new(path, (1100, 700)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut rows: Vec<&WaterfallRow> = rows.iter().filter(|r| !r.1.is_empty()).collect();
    rows.sort_by(|a, b| a.0.total_cmp(&b.0));
    if rows.is_empty() {
        return Err("waterfall: no spectra".into());
    }
    let speeds: Vec<f64> = rows.iter().map(|r| r.0).collect();
    let half = |i: usize| -> (f64, f64) {
        let lo = if i > 0 {
            0.5 * (speeds[i - 1] + speeds[i])
        } else if speeds.len() > 1 {
            speeds[0] - 0.5 * (speeds[1] - speeds[0])
        } else {
            speeds[0] * 0.95
        };
        let hi = if i + 1 < speeds.len() {
            0.5 * (speeds[i] + speeds[i + 1])
        } else if speeds.len() > 1 {
            speeds[i] + 0.5 * (speeds[i] - speeds[i - 1])
        } else {
            speeds[0] * 1.05 + 1.0
        };
        (lo, hi)
    };
    let (s_lo, s_hi) = (half(0).0, half(speeds.len() - 1).1);
    let a_max = rows
        .iter()
        .flat_map(|r| r.1.iter().skip(1).filter(|p| p.0 <= f_max).map(|p| p.1))
        .fold(1e-300, f64::max);
    let decades = 4.0;
    let mut chart = ChartBuilder::on(&root)
        .caption(title, ("sans-serif", 24))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(0.0..f_max, s_lo..s_hi)?;
    chart
        .configure_mesh()
        .disable_mesh()
        .x_desc("frequency (Hz)")
        .y_desc("speed (rpm)")
        .draw()?;
    for (i, row) in rows.iter().enumerate() {
        let (lo, hi) = half(i);
        // Cells one bin wide centred on the bins, or (fine spectra) at most 500 cells across,
        // each showing the largest amplitude of the bins it covers.
        let df = row.1.get(1).map_or(f_max, |p| p.0);
        let width = df.max(f_max / 500.0);
        let columns = (f_max / width).ceil() as usize + 1;
        let mut cells = vec![0.0f64; columns];
        for &(f, a) in row.1.iter().skip(1) {
            if f <= f_max {
                let c = ((f / width).round() as usize).min(columns - 1);
                cells[c] = cells[c].max(a);
            }
        }
        chart.draw_series(
            cells
                .iter()
                .enumerate()
                .filter(|c| *c.1 > 0.0)
                .map(|(c, &a)| {
                    let level = ((a / a_max).log10() / decades + 1.0).clamp(0.0, 1.0);
                    let color = HSLColor(0.66 * (1.0 - level), 0.9, 0.25 + 0.35 * level);
                    let f0 = (c as f64 - 0.5) * width;
                    Rectangle::new(
                        [(f0.max(0.0), lo), ((f0 + width).min(f_max), hi)],
                        color.filled(),
                    )
                }),
        )?;
    }
    for (i, (name, order)) in orders.iter().enumerate() {
        let color = Palette99::pick(i + 1).to_rgba();
        chart
            .draw_series(DashedLineSeries::new(
                // Clipped here at f_max: plotters clamps points outside the chart to its edge,
                // which would bend the line.
                [
                    (order * s_lo / 60.0, s_lo),
                    (
                        (order * s_hi / 60.0).min(f_max),
                        s_hi.min(60.0 * f_max / order),
                    ),
                ],
                6,
                4,
                color.stroke_width(2),
            ))?
            .label(name.clone())
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], color));
    }
    draw_legend(&mut chart, SeriesLabelPosition::MiddleRight)?;
    root.present()?;
    Ok(())
}
