//! `bearing friction --contact inner|outer --roller-load Q`: the Stribeck curve of one
//! roller–race contact of a bearing — its film ratio, regime, friction (traction) coefficient
//! μ = (F_v + F_b)/Q split into its viscous and boundary parts, and the rolling-resistance
//! coefficient F_R/Q, against shaft speed — with the film of the whole load (as the core) and
//! re-solved for the load the asperities leave it (docs/physics.md §8, docs/friction.md).

use std::path::Path;

use anyhow::anyhow;
use bearing_core::friction::Prepared;
use bearing_core::BearingParams;
use clap::ValueEnum;
use plotters::prelude::*;
use serde_json::json;

use super::FrictionArgs;
use crate::commands::common::{print_json, rad_per_s};
use bearing_host_common::config::BearingConfig;
use bearing_host_common::friction::{contact_friction, LoadSharing, SharedContact};
use bearing_host_common::output::write_with;
use bearing_host_common::plot_style::draw_legend;

/// The contact of a roller.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ContactSide {
    /// Roller on the inner raceway.
    Inner,
    /// Roller on the outer raceway.
    Outer,
}

impl ContactSide {
    fn name(self) -> &'static str {
        match self {
            ContactSide::Inner => "inner",
            ContactSide::Outer => "outer",
        }
    }
}

/// One speed of the contact's curve: [film of the whole load, re-solved film].
struct Point {
    speed_rpm: f64,
    entrainment_m_s: f64,
    contacts: [SharedContact; 2],
}

/// The coefficients of a contact: [μ, μ_viscous, μ_boundary, F_R/Q].
fn coefficients(c: &SharedContact, load_n: f64) -> [f64; 4] {
    let f = &c.friction;
    let per_load = |force: f32| f64::from(force) / load_n;
    [
        f64::from(f.friction_coefficient()),
        per_load(f.viscous_n),
        per_load(f.boundary_n),
        per_load(f.rolling_n),
    ]
}

fn contact_json(c: &SharedContact, load_n: f64) -> serde_json::Value {
    let [mu, viscous, boundary, rolling] = coefficients(c, load_n);
    json!({
        "central_film_m": c.central_film_m,
        "lambda": c.friction.lambda,
        "lubrication": c.friction.lubrication().name(),
        "asperity_load_n": c.friction.asperity_load_n,
        "friction_coefficient": mu,
        "friction_coefficient_split": {"viscous": viscous, "boundary": boundary},
        "rolling_resistance_coefficient": rolling,
        "forces_n": {"rolling": c.friction.rolling_n, "viscous": c.friction.viscous_n,
                     "boundary": c.friction.boundary_n},
        "iterations": c.iterations,
    })
}

/// Run `bearing friction --contact`.
pub fn run(
    args: &FrictionArgs,
    config: &BearingConfig,
    params: &BearingParams,
    side: ContactSide,
    load_n: f64,
) -> anyhow::Result<()> {
    let outer = side == ContactSide::Outer;
    let load = load_n as f32;
    crate::commands::film::check_hertz("--roller-load", &params.contact_input(outer, load, 0.0))?;
    // The speed as `bearing static` checks it (the contact's load is checked above, not the
    // bearing's radial load).
    crate::commands::statics::check_case(
        params,
        (0.0, "--radial-load"),
        (args.max_rpm, "--max-rpm"),
    )?;
    let n = usize::from(args.points);
    let points: Vec<Point> = (0..n)
        .map(|k| {
            let rpm = args.min_rpm * (args.max_rpm / args.min_rpm).powf(k as f64 / (n - 1) as f64);
            let input = params.contact_input(outer, load, rad_per_s(rpm));
            let prepared = Prepared::new(params.friction(), &input);
            let contacts = [LoadSharing::WholeLoadFilm, LoadSharing::Resolved]
                .map(|sharing| contact_friction(params, &prepared, &input, sharing));
            Point {
                speed_rpm: rpm,
                entrainment_m_s: f64::from(input.entrainment_speed_m_s),
                contacts,
            }
        })
        .collect();
    let title = format!("{}, {} contact, {load_n:.0} N", config.name, side.name());
    if let Some(path) = &args.plot {
        write_with(path, |temp| plot(&points, &title, load_n, temp))
            .map_err(|e| anyhow!("drawing {}: {e}", path.display()))?;
    }
    if args.json {
        return print_json(&json!({
            "bearing": config.name,
            "contact": side.name(),
            "roller_load_n": load_n,
            "slide_to_roll_ratio": params.friction().slide_to_roll_ratio(),
            "composite_roughness_m": params.friction().composite_roughness_m(),
            "points": points.iter().map(|p| json!({
                "speed_rpm": p.speed_rpm,
                "entrainment_speed_m_s": p.entrainment_m_s,
                "whole_load_film": contact_json(&p.contacts[0], load_n),
                "resolved_film": contact_json(&p.contacts[1], load_n),
            })).collect::<Vec<_>>(),
        }));
    }
    println!(
        "{title}, slide/roll {} (docs/physics.md §8; film of the whole load Q, as the core)",
        params.friction().slide_to_roll_ratio()
    );
    println!(
        "{:>9} {:>8} {:>9} {:>7} {:>10} {:>7} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9}",
        "rpm",
        "u_m m/s",
        "h_c nm",
        "λ",
        "regime",
        "W_a/Q %",
        "μ",
        "μ_visc",
        "μ_bound",
        "F_R/Q",
        "λ re-solv",
        "μ re-solv"
    );
    for p in &points {
        let [whole, resolved] = &p.contacts;
        let [mu, viscous, boundary, rolling] = coefficients(whole, load_n);
        println!(
            "{:>9.0} {:>8.3} {:>9.1} {:>7.2} {:>10} {:>7.1} {:>9.5} {:>9.5} {:>9.5} {:>9.5} {:>9.2} {:>9.5}",
            p.speed_rpm,
            p.entrainment_m_s,
            whole.central_film_m * 1e9,
            whole.friction.lambda,
            whole.friction.lubrication().name(),
            100.0 * f64::from(whole.friction.asperity_load_n) / load_n,
            mu,
            viscous,
            boundary,
            rolling,
            resolved.friction.lambda,
            coefficients(resolved, load_n)[0]
        );
    }
    if let Some(path) = &args.plot {
        println!("plot: {}", path.display());
    }
    Ok(())
}

/// The friction coefficient and its parts (log) against speed (log) on top, λ below with the
/// regime limits 1 and 3, into an SVG at `path`.
fn plot(points: &[Point], title: &str, load_n: f64, path: &Path) -> anyhow::Result<()> {
    let e = |err: plotters::drawing::DrawingAreaErrorKind<_>| anyhow!("{err}");
    let root = SVGBackend::new(path, (900, 800)).into_drawing_area();
    root.fill(&WHITE).map_err(e)?;
    let (top, bottom) = root.split_vertically(450);
    let x =
        points.first().map_or(1.0, |p| p.speed_rpm)..points.last().map_or(10.0, |p| p.speed_rpm);
    let values = points
        .iter()
        .flat_map(|p| coefficients(&p.contacts[0], load_n))
        .filter(|v| *v > 0.0);
    let (lo, hi) = values.fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(v), b.max(v)));
    // Four decades below the largest: the boundary part's tail below that is not visible.
    let y = (lo.max(hi * 1e-4) * 0.5)..(hi.max(1e-6) * 2.0);
    let mut chart = ChartBuilder::on(&top)
        .caption(format!("{title}: friction coefficient"), ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(x.clone().log_scale(), y.clone().log_scale())
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc("shaft speed (rpm)")
        .y_desc("coefficient (–)")
        .y_label_formatter(&|v| format!("{v:.0e}"))
        .draw()
        .map_err(e)?;
    let series = [
        ("μ = (F_v + F_b)/Q", BLACK, 0usize),
        ("viscous F_v/Q", GREEN, 1),
        ("boundary F_b/Q", RED, 2),
        ("rolling resistance F_R/Q", BLUE, 3),
    ];
    for (label, colour, i) in series {
        let floor = y.start;
        let data = points.iter().map(move |p| {
            let v = coefficients(&p.contacts[0], load_n)[i];
            (p.speed_rpm, v.max(floor))
        });
        chart
            .draw_series(LineSeries::new(data, colour.stroke_width(2)))
            .map_err(e)?
            .label(label)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour));
    }
    draw_legend(&mut chart, SeriesLabelPosition::UpperRight).map_err(e)?;
    let lambdas = points
        .iter()
        .map(|p| f64::from(p.contacts[0].friction.lambda));
    let (l_lo, l_hi) = lambdas.fold((f64::MAX, f64::MIN), |(a, b), v| (a.min(v), b.max(v)));
    let mut film = ChartBuilder::on(&bottom)
        .caption("film ratio λ = h_c/σ", ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(
            x.clone().log_scale(),
            ((l_lo.max(1e-3) * 0.5).min(0.5)..(l_hi * 2.0).max(6.0)).log_scale(),
        )
        .map_err(e)?;
    film.configure_mesh()
        .x_desc("shaft speed (rpm)")
        .y_desc("λ")
        .draw()
        .map_err(e)?;
    film.draw_series(LineSeries::new(
        points
            .iter()
            .map(|p| (p.speed_rpm, f64::from(p.contacts[0].friction.lambda))),
        BLACK.stroke_width(2),
    ))
    .map_err(e)?
    .label("λ")
    .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK));
    for (limit, label) in [(1.0, "boundary | mixed"), (3.0, "mixed | full film")] {
        film.draw_series(LineSeries::new(
            [(x.start, limit), (x.end, limit)],
            RGBColor(150, 150, 150).stroke_width(1),
        ))
        .map_err(e)?
        .label(label)
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], RGBColor(150, 150, 150)));
    }
    draw_legend(&mut film, SeriesLabelPosition::UpperLeft).map_err(e)?;
    root.present().map_err(e)?;
    Ok(())
}
