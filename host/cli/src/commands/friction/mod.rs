//! `bearing friction`: the Stribeck curve of a bundled bearing — friction torque, power loss
//! and its split into rolling, viscous and boundary parts against shaft speed, with the film
//! ratio λ of the most loaded contact — beside Palmgren's empirical torque and the torque with
//! the film re-solved for the load the asperities leave it (docs/friction.md, docs/physics.md
//! §8); with `--contact`, the same for one contact ([`contact`]).

use std::path::{Path, PathBuf};

use anyhow::{anyhow, bail, Context};
use bearing_core::{FilmKind, Lubrication};
use clap::Args;
use plotters::prelude::*;
use serde_json::json;

mod contact;

use crate::commands::common::{non_negative, positive, print_json, rad_per_s};
use crate::commands::statics::solve;
use bearing_host_common::config::BearingConfig;
use bearing_host_common::friction::{bearing_friction_at_loads, LoadSharing};
use bearing_host_common::output::write_with;
use bearing_host_common::plot_style::draw_legend;
use bearing_host_common::rolling::boxed;

/// Stribeck curve of a bearing under a radial load: friction torque and power loss against
/// shaft speed, at speeds spaced evenly in log from --min-rpm to --max-rpm; or, with
/// --contact and --roller-load, of one roller–race contact: its friction coefficient and
/// split.
#[derive(Args, Debug)]
pub struct FrictionArgs {
    /// Bearing configuration (TOML); its `[friction]` table sets the friction model.
    #[arg(long)]
    pub config: PathBuf,
    /// Radial load on the inner race (N); default: the config's `[case]`.
    #[arg(long, value_parser = non_negative, conflicts_with = "contact")]
    pub radial_load: Option<f64>,
    /// One contact of a roller instead of the bearing: its friction coefficient against speed.
    #[arg(long, value_enum, requires = "roller_load")]
    pub contact: Option<contact::ContactSide>,
    /// The contact's load Q (N), with --contact.
    #[arg(long, value_parser = positive, requires = "contact")]
    pub roller_load: Option<f64>,
    /// Lowest shaft speed (rpm).
    #[arg(long, default_value_t = 10.0, value_parser = positive)]
    pub min_rpm: f64,
    /// Highest shaft speed (rpm).
    #[arg(long, default_value_t = 15_000.0, value_parser = positive)]
    pub max_rpm: f64,
    /// Speeds of the curve.
    #[arg(long, default_value_t = 13, value_parser = clap::value_parser!(u16).range(2..=200))]
    pub points: u16,
    /// Palmgren's f₀ (speed term; cylindrical roller bearing with cage, oil bath: 2 … 3).
    #[arg(long, default_value_t = 2.0, value_parser = positive)]
    pub palmgren_f0: f64,
    /// Palmgren's f₁ (load term; cylindrical roller bearings: 2·10⁻⁴ … 4·10⁻⁴).
    #[arg(long, default_value_t = 3.0e-4, value_parser = positive)]
    pub palmgren_f1: f64,
    /// Machine-readable output.
    #[arg(long)]
    pub json: bool,
    /// Also draw the curve (SVG).
    #[arg(long, value_name = "FILE.svg")]
    pub plot: Option<PathBuf>,
}

/// One speed of the curve.
struct Point {
    speed_rpm: f64,
    torque_nm: f64,
    power_w: f64,
    split_w: [f64; 3],
    lambda_min: f64,
    palmgren_nm: f64,
    /// Host films at the step's roller loads: [film of the whole load (the core's load
    /// sharing), film re-solved for Q − W_a].
    sharing: [SharingPoint; 2],
}

/// The bearing's friction at one speed with one way of sharing the load.
struct SharingPoint {
    torque_nm: f64,
    power_w: f64,
    asperity_load_n: f64,
    lambda_min: f64,
}

/// Palmgren's empirical friction torque M = M₀ + M₁ (N·m) of a roller bearing (Harris &
/// Kotzalas, Rolling Bearing Analysis, 5th ed., vol. 1 ch. 10 / Palmgren 1959):
/// M₀ = 10⁻⁷·f₀·(ν·n)^{2/3}·d_m³ for ν·n ≥ 2000, else 160·10⁻⁷·f₀·d_m³ (N·mm with ν in
/// mm²/s, n in rpm, d_m in mm), M₁ = f₁·F·d_m (N·mm).
pub fn palmgren_torque_nm(
    f0: f64,
    f1: f64,
    kinematic_viscosity_mm2_s: f64,
    speed_rpm: f64,
    pitch_diameter_mm: f64,
    load_n: f64,
) -> (f64, f64) {
    let vn = kinematic_viscosity_mm2_s * speed_rpm;
    let d3 = pitch_diameter_mm.powi(3);
    let m0 = if vn >= 2000.0 {
        1.0e-7 * f0 * vn.powf(2.0 / 3.0) * d3
    } else {
        160.0e-7 * f0 * d3
    };
    let m1 = f1 * load_n * pitch_diameter_mm;
    (m0 * 1e-3, m1 * 1e-3)
}

/// Run `bearing friction`.
pub fn run(args: FrictionArgs) -> anyhow::Result<()> {
    let (config, params) = BearingConfig::load(&args.config)?;
    if args.min_rpm >= args.max_rpm {
        bail!(
            "--min-rpm = {} must be below --max-rpm = {}",
            args.min_rpm,
            args.max_rpm
        );
    }
    if let (Some(side), Some(load)) = (args.contact, args.roller_load) {
        return contact::run(&args, &config, &params, side, load);
    }
    let load = crate::commands::statics::radial_load_n(args.radial_load, &config)?;
    let load_source = crate::commands::statics::value_source(
        args.radial_load.is_some(),
        "--radial-load",
        &args.config,
        "radial_load_n",
    );
    crate::commands::statics::check_case(
        &params,
        (load, &load_source),
        (args.max_rpm, "--max-rpm"),
    )?;
    let nu_mm2_s = f64::from(params.lubricant().viscosity_pa_s())
        / f64::from(params.lubricant().density_kg_m3())
        * 1e6;
    let dm_mm = f64::from(params.geometry().pitch_diameter_m()) * 1e3;
    let n = usize::from(args.points);
    let mut bearing = boxed(params, FilmKind::Regression)
        .map_err(|e| anyhow!("{}: {e}", args.config.display()))?;
    let mut points = Vec::with_capacity(n);
    for k in 0..n {
        let rpm = args.min_rpm * (args.max_rpm / args.min_rpm).powf(k as f64 / (n - 1) as f64);
        let s = solve(bearing.as_mut(), load as f32, rad_per_s(rpm))
            .with_context(|| format!("at {rpm:.1} rpm"))?;
        let step = &s.step;
        let [lambda_in, lambda_out] = step
            .rollers
            .iter()
            .zip(&step.lambda)
            .max_by(|a, b| a.0.load_n.total_cmp(&b.0.load_n))
            .map(|(_, l)| *l)
            .context("a bearing without rollers")?;
        let (m0, m1) = palmgren_torque_nm(
            args.palmgren_f0,
            args.palmgren_f1,
            nu_mm2_s,
            rpm,
            dm_mm,
            load,
        );
        let loads: Vec<f32> = step.rollers.iter().map(|r| r.load_n).collect();
        let sharing = [LoadSharing::WholeLoadFilm, LoadSharing::Resolved].map(|sharing| {
            let f = bearing_friction_at_loads(
                &params,
                &loads,
                step.centrifugal_force_n,
                rad_per_s(rpm),
                sharing,
            );
            let [l_in, l_out] = f.lambda_of_most_loaded().unwrap_or([0.0; 2]);
            SharingPoint {
                torque_nm: f64::from(f.bearing.torque_nm),
                power_w: f64::from(f.bearing.power_loss_w),
                asperity_load_n: f64::from(f.asperity_load_n()),
                lambda_min: f64::from(l_in.min(l_out)),
            }
        });
        points.push(Point {
            speed_rpm: rpm,
            torque_nm: f64::from(step.friction_torque_nm),
            power_w: f64::from(step.power_loss_w),
            split_w: step.power_loss_split_w.map(f64::from),
            lambda_min: f64::from(lambda_in.min(lambda_out)),
            palmgren_nm: m0 + m1,
            sharing,
        });
    }
    if let Some(path) = &args.plot {
        write_with(path, |temp| plot(&points, &config.name, load, temp))
            .with_context(|| format!("drawing {}", path.display()))?;
    }
    if args.json {
        let value = json!({
            "bearing": config.name,
            "radial_load_n": load,
            "slide_to_roll_ratio": params.friction().slide_to_roll_ratio(),
            "palmgren": {"f0": args.palmgren_f0, "f1": args.palmgren_f1,
                         "kinematic_viscosity_mm2_s": nu_mm2_s, "pitch_diameter_mm": dm_mm},
            "points": points.iter().map(|p| json!({
                "speed_rpm": p.speed_rpm,
                "friction_torque_nm": p.torque_nm,
                "power_loss_w": p.power_w,
                "power_loss_split_w": {"rolling": p.split_w[0], "viscous": p.split_w[1], "boundary": p.split_w[2]},
                "lambda_min": p.lambda_min,
                "lubrication": Lubrication::of(p.lambda_min as f32).name(),
                "palmgren_torque_nm": p.palmgren_nm,
                "load_sharing": {
                    "whole_load_film": sharing_json(&p.sharing[0]),
                    "resolved_film": sharing_json(&p.sharing[1]),
                    "torque_change": p.sharing[1].torque_nm / p.sharing[0].torque_nm - 1.0,
                },
            })).collect::<Vec<_>>(),
        });
        return print_json(&value);
    }
    print_table(
        &args,
        &config.name,
        load,
        params.friction().slide_to_roll_ratio(),
        &points,
    );
    Ok(())
}

/// The text form of `bearing friction`: one row per speed.
fn print_table(
    args: &FrictionArgs,
    name: &str,
    load: f64,
    slide_to_roll_ratio: f32,
    points: &[Point],
) {
    let share = |p: &Point, i: usize| {
        if p.power_w > 0.0 {
            p.split_w[i] / p.power_w
        } else {
            0.0
        }
    };
    println!(
        "{} — {load:.0} N radial, slide/roll {} (friction model: docs/physics.md §8)",
        name, slide_to_roll_ratio
    );
    println!(
        "{:>9} {:>11} {:>10} {:>8} {:>8} {:>8} {:>7} {:>10} {:>12} {:>11}",
        "rpm",
        "torque N·m",
        "power W",
        "roll %",
        "visc %",
        "bound %",
        "λ_min",
        "regime",
        "Palmgren N·m",
        "re-solved %"
    );
    for p in points {
        println!(
            "{:>9.0} {:>11.5} {:>10.3} {:>8.1} {:>8.1} {:>8.1} {:>7.2} {:>10} {:>12.5} {:>+11.2}",
            p.speed_rpm,
            p.torque_nm,
            p.power_w,
            100.0 * share(p, 0),
            100.0 * share(p, 1),
            100.0 * share(p, 2),
            p.lambda_min,
            Lubrication::of(p.lambda_min as f32).name(),
            p.palmgren_nm,
            100.0 * (p.sharing[1].torque_nm / p.sharing[0].torque_nm - 1.0)
        );
    }
    println!(
        "re-solved %: torque with the film re-solved for Q − W_a against the film of the whole \
         load Q, both with the regression film at the step's roller loads (docs/friction.md)"
    );
    if let Some(path) = &args.plot {
        println!("plot: {}", path.display());
    }
}

fn sharing_json(s: &SharingPoint) -> serde_json::Value {
    json!({
        "friction_torque_nm": s.torque_nm,
        "power_loss_w": s.power_w,
        "asperity_load_n": s.asperity_load_n,
        "lambda_min": s.lambda_min,
    })
}

/// Torque (model and Palmgren, log) against speed (log) on top, the power-loss shares
/// (rolling, viscous, boundary, %) below, into an SVG at `path`.
fn plot(points: &[Point], name: &str, load: f64, path: &Path) -> anyhow::Result<()> {
    let e = |err: plotters::drawing::DrawingAreaErrorKind<_>| anyhow!("{err}");
    let root = SVGBackend::new(path, (900, 800)).into_drawing_area();
    root.fill(&WHITE).map_err(e)?;
    let (top, bottom) = root.split_vertically(430);
    let x =
        points.first().map_or(1.0, |p| p.speed_rpm)..points.last().map_or(10.0, |p| p.speed_rpm);
    let torques = points.iter().flat_map(|p| [p.torque_nm, p.palmgren_nm]);
    let (lo, hi) = torques.fold((f64::MAX, f64::MIN), |(a, b), t| (a.min(t), b.max(t)));
    let y = (lo.max(1e-9) * 0.5)..(hi.max(1e-8) * 2.0);
    let mut chart = ChartBuilder::on(&top)
        .caption(
            format!("{name}, {load:.0} N: friction torque"),
            ("sans-serif", 20),
        )
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(x.clone().log_scale(), y.log_scale())
        .map_err(e)?;
    chart
        .configure_mesh()
        .x_desc("shaft speed (rpm)")
        .y_desc("torque (N·m)")
        .draw()
        .map_err(e)?;
    let series = [
        ("model (rolling + viscous + boundary)", BLUE, 0usize),
        ("Palmgren M₀ + M₁", RED, 1),
    ];
    for (label, colour, which) in series {
        let data = points.iter().map(move |p| {
            (
                p.speed_rpm,
                if which == 0 {
                    p.torque_nm
                } else {
                    p.palmgren_nm
                },
            )
        });
        chart
            .draw_series(LineSeries::new(data, colour.stroke_width(2)))
            .map_err(e)?
            .label(label)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour));
    }
    draw_legend(&mut chart, SeriesLabelPosition::UpperLeft).map_err(e)?;
    let mut shares = ChartBuilder::on(&bottom)
        .caption("share of the power loss", ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(x.log_scale(), 0.0..100.0)
        .map_err(e)?;
    shares
        .configure_mesh()
        .x_desc("shaft speed (rpm)")
        .y_desc("%")
        .draw()
        .map_err(e)?;
    for (label, colour, i) in [
        ("rolling", BLUE, 0usize),
        ("viscous", GREEN, 1),
        ("boundary", RED, 2),
    ] {
        let data = points.iter().map(move |p| {
            let share = if p.power_w > 0.0 {
                100.0 * p.split_w[i] / p.power_w
            } else {
                0.0
            };
            (p.speed_rpm, share)
        });
        shares
            .draw_series(LineSeries::new(data, colour.stroke_width(2)))
            .map_err(e)?
            .label(label)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour));
    }
    draw_legend(&mut shares, SeriesLabelPosition::UpperLeft).map_err(e)?;
    root.present().map_err(e)?;
    Ok(())
}
