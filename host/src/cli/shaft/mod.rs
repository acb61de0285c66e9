//! `bearing shaft …`: the flexible-shaft simulator's analyses — static equilibrium, modes,
//! Campbell diagram, time response and speed sweep — on a shaft TOML file
//! (see `bearing_host::shaft::config`).

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

use anyhow::{bail, Context, Result};
use bearing_host::shaft::bearing::{BearingSpec, FilmChoice, LinearBearing};
use bearing_host::shaft::config::load_model;
use bearing_host::shaft::integrator::{NewtonSettings, Scheme};
use bearing_host::shaft::loads::Load;
use bearing_host::shaft::model::RotorModel;
use bearing_host::shaft::operating::{campbell, operating_modes};
use bearing_host::shaft::simulate::{run as run_time, RunSettings};
use bearing_host::shaft::spectrum::amplitude_spectrum;
use bearing_host::shaft::sweep::{hub_motor_speeds_rpm, sweep};
use bearing_host::shaft::{output, plots};
use clap::{Args, Subcommand, ValueEnum};

mod report;
use report::reduction_report;

/// Arguments of `bearing shaft`.
#[derive(Args, Debug)]
pub struct ShaftArgs {
    #[command(subcommand)]
    command: ShaftCommand,
}

#[derive(Subcommand, Debug)]
enum ShaftCommand {
    /// Static equilibrium under static loads, gravity and mean gear forces.
    Static(StaticArgs),
    /// Natural frequencies and whirl at one speed, bearings linearised at the equilibrium.
    Modes(ModesArgs),
    /// Campbell diagram: natural frequencies over speed (PNG plot).
    Campbell(CampbellArgs),
    /// Time response at one speed: CSV record, kinematics traces, orbit and spectrum plots.
    Run(RunArgs),
    /// Speed sweep to steady state, lubricated and dry side by side, in parallel.
    Sweep(SweepArgs),
}

#[derive(Args, Debug)]
struct ModelArgs {
    /// Shaft model file (TOML).
    #[arg(long)]
    config: PathBuf,
    /// Replace every bearing by an isotropic linear spring of this stiffness (N/m, > 0), e.g.
    /// while the core's roller bearing is not wired.
    #[arg(long)]
    linear_bearings: Option<f64>,
    /// Damping of the replacement linear bearings (N·s/m, ≥ 0).
    #[arg(long, default_value_t = 0.0)]
    linear_damping: f64,
    /// Film model of every roller bearing (overrides the file; `sweep` runs this film against
    /// dry, so it must not be `dry` there).
    #[arg(long, value_enum)]
    film: Option<FilmArg>,
    /// Print JSON instead of a table.
    #[arg(long)]
    json: bool,
}

#[derive(Args, Debug)]
struct StaticArgs {
    #[command(flatten)]
    model: ModelArgs,
    /// Spin speed (rpm, ≥ 0): sets the mean gear forces.
    #[arg(long, default_value_t = 0.0)]
    speed_rpm: f64,
}

#[derive(Args, Debug)]
struct ModesArgs {
    #[command(flatten)]
    model: ModelArgs,
    /// Spin speed (rpm, ≥ 0).
    #[arg(long, default_value_t = 0.0)]
    speed_rpm: f64,
    /// Number of modes (1 … 200).
    #[arg(long, default_value_t = 8)]
    modes: usize,
    /// Also plot the mode shapes to this PNG.
    #[arg(long)]
    plot: Option<PathBuf>,
}

#[derive(Args, Debug)]
struct CampbellArgs {
    #[command(flatten)]
    model: ModelArgs,
    /// Highest speed (rpm, > 0).
    #[arg(long, default_value_t = 21_000.0)]
    max_rpm: f64,
    /// Number of speed intervals (1 … 1000).
    #[arg(long, default_value_t = 40)]
    steps: usize,
    /// Number of modes (1 … 200).
    #[arg(long, default_value_t = 8)]
    modes: usize,
    /// Output PNG.
    #[arg(long, default_value = "campbell.png")]
    plot: PathBuf,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum SchemeArg {
    /// Newmark average acceleration.
    Newmark,
    /// Hilber–Hughes–Taylor α.
    Hht,
}

#[derive(Args, Debug)]
struct TimeArgs {
    /// Time step (s, > 0); default 1/(20 × mesh frequency), or 1/100 of a revolution.
    #[arg(long)]
    dt: Option<f64>,
    /// Scheme.
    #[arg(long, value_enum, default_value_t = SchemeArg::Newmark)]
    scheme: SchemeArg,
    /// HHT α (0 < α ≤ 1/3).
    #[arg(long, default_value_t = 0.05)]
    alpha: f64,
    /// Craig–Bampton reduction keeping this many fixed-interface modes (0 … 500).
    #[arg(long)]
    reduce: Option<usize>,
    /// Settling time before recording (s, ≥ 0).
    #[arg(long, default_value_t = 0.1)]
    settle: f64,
    /// Recorded time (s, > 0).
    #[arg(long, default_value_t = 0.05)]
    duration: f64,
    /// Keep every n-th step in the outputs (1 … 10⁶): the trace's sample interval is n·dt.
    #[arg(long, default_value_t = 1)]
    record_every: usize,
    /// Newton stall bound (m, in (0, 10⁻⁶]): a correction below it that no longer halves is
    /// accepted as the bearing model's f32 resolution (such steps are counted in
    /// `resolution_limited_steps`). Default 1 nm.
    #[arg(long, default_value_t = NewtonSettings::default().model_resolution)]
    newton_resolution: f64,
}

#[derive(Args, Debug)]
struct RunArgs {
    #[command(flatten)]
    model: ModelArgs,
    #[command(flatten)]
    time: TimeArgs,
    /// Spin speed (rpm, ≥ 0); with --speed-end-rpm the speed at the start of the recording.
    #[arg(long)]
    speed_rpm: f64,
    /// Ramp the speed linearly from --speed-rpm to this speed (rpm, ≥ 0) over --duration (held
    /// at --speed-rpm through --settle): a run-up or run-down.
    #[arg(long)]
    speed_end_rpm: Option<f64>,
    /// Output prefix: <prefix>.csv, <prefix>_b<i>_rollers.csv, <prefix>_b<i>_trace.csv
    /// (hil-sim trace format), <prefix>_orbit.png, <prefix>_spectrum.png.
    #[arg(long, default_value = "shaft_run")]
    out: PathBuf,
    /// With --reduce: also run the full model and report the envelope differences.
    #[arg(long)]
    compare_full: bool,
}

#[derive(Args, Debug)]
struct SweepArgs {
    #[command(flatten)]
    model: ModelArgs,
    #[command(flatten)]
    time: TimeArgs,
    /// Speeds (rpm, comma separated); default the PHYSICS.md §6.2 list.
    #[arg(long, value_delimiter = ',')]
    speeds_rpm: Option<Vec<f64>>,
    /// Envelope plot.
    #[arg(long, default_value = "shaft_sweep.png")]
    plot: PathBuf,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum FilmArg {
    Int,
    F32,
    Regression,
    Dry,
}

impl FilmArg {
    fn choice(self) -> FilmChoice {
        match self {
            FilmArg::Int => FilmChoice::Int,
            FilmArg::F32 => FilmChoice::F32,
            FilmArg::Regression => FilmChoice::Regression,
            FilmArg::Dry => FilmChoice::Dry,
        }
    }
}

/// Runs `bearing shaft …`.
pub fn run(args: ShaftArgs) -> Result<()> {
    match args.command {
        ShaftCommand::Static(a) => cmd_static(a),
        ShaftCommand::Modes(a) => cmd_modes(a),
        ShaftCommand::Campbell(a) => cmd_campbell(a),
        ShaftCommand::Run(a) => cmd_run(a),
        ShaftCommand::Sweep(a) => cmd_sweep(a),
    }
}

/// A finite value within [lo, hi], or an error naming the flag.
fn check(flag: &str, v: f64, lo: f64, hi: f64, lo_open: bool) -> Result<f64> {
    let ok = v.is_finite() && v <= hi && if lo_open { v > lo } else { v >= lo };
    if !ok {
        let b = if lo_open { "(" } else { "[" };
        bail!("--{flag} = {v} is not allowed: must be finite and in {b}{lo}, {hi}]");
    }
    Ok(v)
}

fn check_count(flag: &str, v: usize, lo: usize, hi: usize) -> Result<usize> {
    if v < lo || v > hi {
        bail!("--{flag} = {v} is not allowed: must be in {lo} … {hi}");
    }
    Ok(v)
}

fn rpm_to_rad(rpm: f64) -> f64 {
    rpm * std::f64::consts::PI / 30.0
}

fn load(m: &ModelArgs) -> Result<RotorModel> {
    let mut model = load_model(&m.config)?;
    if let Some(film) = m.film {
        for b in &mut model.description.bearings {
            b.spec = b.spec.with_film(film.choice());
        }
    }
    if let Some(k) = m.linear_bearings {
        let k = check("linear-bearings", k, 0.0, 1e13, true)?;
        let c = check("linear-damping", m.linear_damping, 0.0, 1e9, false)?;
        for b in &mut model.description.bearings {
            b.spec = BearingSpec::Linear(LinearBearing::isotropic(k, c));
        }
    }
    Ok(model)
}

fn cmd_static(a: StaticArgs) -> Result<()> {
    let model = load(&a.model)?;
    let omega = rpm_to_rad(check("speed-rpm", a.speed_rpm, 0.0, 1e6, false)?);
    let mut bearings = bearing_host::shaft::operating::build_bearings(&model)?;
    let eq = bearing_host::shaft::statics::equilibrium(&model, omega, &mut bearings)?;
    let nodes: Vec<_> = (0..model.n_nodes())
        .map(|i| {
            serde_json::json!({"node": i, "z_m": model.description.node_positions[i],
                "x_m": eq.q[4 * i], "y_m": eq.q[4 * i + 1]})
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

fn cmd_modes(a: ModesArgs) -> Result<()> {
    let model = load(&a.model)?;
    let omega = rpm_to_rad(check("speed-rpm", a.speed_rpm, 0.0, 1e6, false)?);
    let n = check_count("modes", a.modes, 1, 200)?;
    let (_, modes) = operating_modes(&model, omega, n, true)?;
    if let Some(p) = &a.plot {
        plots::mode_shapes(&model.description.node_positions, &modes, p)
            .map_err(|e| anyhow::anyhow!("writing {}: {e}", p.display()))?;
    }
    if a.model.json {
        let f: Vec<f64> = modes.iter().map(|m| m.frequency).collect();
        println!("{}", serde_json::json!({"frequencies_rad_s": f}));
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

/// Gear-mesh orders (teeth) of the model's loads, for plot lines.
fn mesh_orders(model: &RotorModel) -> Vec<f64> {
    model
        .description
        .loads
        .loads
        .iter()
        .filter_map(|l| match l {
            Load::GearMesh(m) => Some(f64::from(m.teeth)),
            _ => None,
        })
        .collect()
}

fn cmd_campbell(a: CampbellArgs) -> Result<()> {
    let model = load(&a.model)?;
    let max = check("max-rpm", a.max_rpm, 0.0, 1e6, true)?;
    let steps = check_count("steps", a.steps, 1, 1000)?;
    let n = check_count("modes", a.modes, 1, 200)?;
    let speeds: Vec<f64> = (0..=steps).map(|k| max * k as f64 / steps as f64).collect();
    let points = campbell(&model, &speeds, n)?;
    plots::campbell(&points, &mesh_orders(&model), &a.plot)
        .map_err(|e| anyhow::anyhow!("writing {}: {e}", a.plot.display()))?;
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
        println!("plot: {}", a.plot.display());
    }
    Ok(())
}

/// Time settings; `omega` the highest speed of the run (sets the default step).
fn settings(model: &RotorModel, t: &TimeArgs, omega: f64) -> Result<RunSettings> {
    let mesh = mesh_orders(model).into_iter().fold(0.0, f64::max);
    let dt = match t.dt {
        Some(dt) => check("dt", dt, 0.0, 1.0, true)?,
        None if mesh > 0.0 && omega > 0.0 => 2.0 * std::f64::consts::PI / (20.0 * mesh * omega),
        None if omega > 0.0 => (2.0 * std::f64::consts::PI / (100.0 * omega)).min(1e-4),
        None => 1e-4,
    };
    let scheme = match t.scheme {
        SchemeArg::Newmark => Scheme::AverageAcceleration,
        SchemeArg::Hht => Scheme::Hht {
            alpha: check("alpha", t.alpha, 0.0, 1.0 / 3.0, true)?,
        },
    };
    if let Some(r) = t.reduce {
        check_count("reduce", r, 0, 500)?;
    }
    let settle = check("settle", t.settle, 0.0, 100.0, false)?;
    let duration = check("duration", t.duration, 0.0, 100.0, true)?;
    let steps = (settle + duration) / dt;
    if steps > 5e7 {
        bail!("--settle + --duration over --dt gives {steps:.3e} steps: at most 5e7 allowed");
    }
    Ok(RunSettings {
        spin_speed: omega,
        spin_speed_end: None,
        dt,
        settle_time: settle,
        record_time: duration,
        record_every: check_count("record-every", t.record_every, 1, 1_000_000)?,
        scheme,
        reduction_modes: t.reduce,
        newton: NewtonSettings {
            model_resolution: check("newton-resolution", t.newton_resolution, 0.0, 1e-6, true)?,
            ..NewtonSettings::default()
        },
    })
}

fn with_suffix(prefix: &Path, suffix: &str) -> PathBuf {
    let mut s = prefix.as_os_str().to_owned();
    s.push(suffix);
    PathBuf::from(s)
}

fn cmd_run(a: RunArgs) -> Result<()> {
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
    let csv = with_suffix(&a.out, ".csv");
    output::write_run_csv(&csv, &r).with_context(|| format!("writing {}", csv.display()))?;
    let n_b = model.description.bearings.len();
    for b in 0..n_b {
        let p = with_suffix(&a.out, &format!("_b{b}_trace.csv"));
        // hil-sim names bearings by their config file stem and knows the thesis oil.
        let id = match &model.description.bearings[b].spec {
            BearingSpec::Roller { config, .. } => config
                .file_stem()
                .map_or("roller".into(), |s| s.to_string_lossy().into_owned()),
            BearingSpec::Linear(_) => "linear".to_string(),
        };
        output::write_kinematics_trace(
            &p,
            &r,
            b,
            (&id, "thesis_oil"),
            s.dt * s.record_every as f64,
        )
        .with_context(|| format!("writing {}", p.display()))?;
        let p = with_suffix(&a.out, &format!("_b{b}_rollers.csv"));
        output::write_roller_csv(&p, &r, b).with_context(|| format!("writing {}", p.display()))?;
    }
    // Plots for the first bearing (inner race): orbit and spectrum of y.
    let orbit: Vec<[f64; 2]> = r.samples.iter().map(|s| s.probes[0][0]).collect();
    let orbit_png = with_suffix(&a.out, "_orbit.png");
    plots::orbit(
        &orbit,
        &format!("orbit, node {} at {} rpm", r.probe_nodes[0], a.speed_rpm),
        &orbit_png,
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
            let f = bearing_host::shaft::roller_bearing::outer_race_pass_hz(config, omega)?;
            markers.push((format!("outer-race pass, bearing {i}"), f));
        }
    }
    let spec_png = with_suffix(&a.out, "_spectrum.png");
    plots::spectrum(
        &spec,
        &markers,
        &format!("spectrum of y, node {}", r.probe_nodes[0]),
        &spec_png,
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
            &png,
        )
        .map_err(|e| anyhow::anyhow!("writing {}: {e}", png.display()))?;
        plotted.push(png.display().to_string());
    }
    let cost = r.cost(s.dt);
    let reduction = match s.reduction_modes {
        None => serde_json::Value::Null,
        Some(k) => reduction_report(&model, &s, k, a.compare_full, &r)?,
    };
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
fn cost_line(c: &bearing_host::shaft::simulate::CostBreakdown) -> String {
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
fn spectrum_orders(model: &RotorModel, omega: f64) -> Result<Vec<(String, f64)>> {
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
            let f = bearing_host::shaft::roller_bearing::outer_race_pass_hz(config, omega)?;
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
    r: &bearing_host::shaft::simulate::RunResult,
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

fn cmd_sweep(a: SweepArgs) -> Result<()> {
    let model = load(&a.model)?;
    let speeds = match &a.speeds_rpm {
        Some(v) => v
            .iter()
            .map(|&s| check("speeds-rpm", s, 0.0, 1e6, true))
            .collect::<Result<Vec<_>>>()?,
        None => hub_motor_speeds_rpm(),
    };
    if speeds.is_empty() {
        bail!("--speeds-rpm is empty: give at least one speed");
    }
    // Validate the time settings once (at the top speed) so a bad flag fails before the runs.
    let top = speeds.iter().copied().fold(0.0, f64::max);
    settings(&model, &a.time, rpm_to_rad(top))?;
    if model.description.bearings.iter().any(|b| {
        matches!(
            b.spec,
            BearingSpec::Roller {
                film: FilmChoice::Dry,
                ..
            }
        )
    }) {
        bail!("--film / the shaft file give dry bearings: sweep runs the lubricated film against dry, choose a film");
    }
    let bar = indicatif::ProgressBar::new(2 * speeds.len() as u64);
    bar.set_style(indicatif::ProgressStyle::with_template(
        "{bar:40} {pos}/{len} runs, {elapsed} (eta {eta})",
    )?);
    if a.model.json {
        bar.set_draw_target(indicatif::ProgressDrawTarget::stderr());
    }
    let done = AtomicUsize::new(0);
    let time = &a.time;
    let settings_at = |omega: f64| settings(&model, time, omega).expect("validated above");
    let points = sweep(&model, &speeds, &settings_at, None, &|| {
        done.fetch_add(1, Ordering::Relaxed);
        bar.inc(1);
    })?;
    bar.finish_and_clear();
    plots::envelopes(&points, &a.plot)
        .map_err(|e| anyhow::anyhow!("writing {}: {e}", a.plot.display()))?;
    let orders = spectrum_orders(&model, 1.0)?;
    let top_hz = top / 60.0;
    let f_max = 1.3 * orders.iter().map(|o| o.1).fold(1.0, f64::max) * top_hz;
    let mut waterfalls = Vec::new();
    for (side, name) in [(0, "lubricated"), (1, "dry")] {
        let rows: Vec<plots::WaterfallRow> = points
            .iter()
            .map(|p| (p.speed_rpm, p.spectra[side].clone()))
            .collect();
        let highest_nyquist = points
            .iter()
            .filter_map(|p| p.spectra[side].last().map(|x| x.0))
            .fold(0.0, f64::max);
        let png = with_suffix(
            &a.plot.with_extension(""),
            &format!("_waterfall_{name}.png"),
        );
        plots::waterfall(
            &rows,
            &orders,
            f_max.min(highest_nyquist),
            &format!("inner-race y displacement, bearing 0, {name}"),
            &png,
        )
        .map_err(|e| anyhow::anyhow!("writing {}: {e}", png.display()))?;
        waterfalls.push(png.display().to_string());
    }
    let mesh = mesh_orders(&model)
        .into_iter()
        .fold(None, |m: Option<f64>, o| Some(m.map_or(o, |m| m.max(o))));
    let comparison = bearing_host::shaft::sweep::compare_films(&points, top, mesh);
    let side = |lub: bool| {
        let e = |p: &bearing_host::shaft::sweep::SweepPoint| if lub { p.lubricated } else { p.dry };
        serde_json::json!({
            "max_contact_force_n": points.iter().map(|p| e(p).max_contact_force_n).collect::<Vec<_>>(),
            "max_contact_stiffness_n_per_m": points.iter().map(|p| e(p).max_contact_stiffness_n_per_m).collect::<Vec<_>>(),
            "max_bearing_stiffness_n_per_m": points.iter().map(|p| e(p).max_bearing_stiffness_n_per_m).collect::<Vec<_>>(),
            "max_central_film_m": points.iter().map(|p| e(p).max_central_film_m).collect::<Vec<_>>(),
            "max_displacement_m": points.iter().map(|p| e(p).max_displacement_m).collect::<Vec<_>>(),
            "max_acceleration_m_s2": points.iter().map(|p| e(p).max_acceleration_m_s2).collect::<Vec<_>>(),
            "steadiness": points.iter().map(|p| p.steadiness[usize::from(!lub)]).collect::<Vec<_>>(),
            "resolution_limited_steps": points.iter().map(|p| p.resolution_limited_steps[usize::from(!lub)]).collect::<Vec<_>>(),
            "natural_frequencies_hz": points.iter().map(|p| p.natural_frequencies_hz[usize::from(!lub)].clone()).collect::<Vec<_>>(),
        })
    };
    if a.model.json {
        let speeds: Vec<f64> = points.iter().map(|p| p.speed_rpm).collect();
        println!(
            "{}",
            serde_json::json!({"speeds_rpm": speeds, "lubricated": side(true), "dry": side(false),
                "comparison": comparison})
        );
        return Ok(());
    }
    println!(
        "{:>8} {:>13} {:>13} {:>11} {:>11} {:>11} {:>11} {:>9} {:>9}",
        "rpm",
        "k_b lub (N/m)",
        "k_b dry (N/m)",
        "h_c (µm)",
        "u lub (µm)",
        "u dry (µm)",
        "f1 lub (Hz)",
        "f1 dry",
        "steady"
    );
    let f1 = |p: &bearing_host::shaft::sweep::SweepPoint, side: usize| {
        p.natural_frequencies_hz[side]
            .first()
            .copied()
            .unwrap_or(f64::NAN)
    };
    for p in &points {
        println!(
            "{:>8.0} {:>13.4e} {:>13.4e} {:>11.4} {:>11.4} {:>11.4} {:>11.2} {:>9.2} {:>9.1e}",
            p.speed_rpm,
            p.lubricated.max_bearing_stiffness_n_per_m,
            p.dry.max_bearing_stiffness_n_per_m,
            p.lubricated.max_central_film_m.unwrap_or(f64::NAN) * 1e6,
            p.lubricated.max_displacement_m * 1e6,
            p.dry.max_displacement_m * 1e6,
            f1(p, 0),
            f1(p, 1),
            p.steadiness[0].max(p.steadiness[1])
        );
    }
    if let Some(c) = &comparison {
        let opt = |v: Option<f64>| v.map_or("none in the sweep".to_string(), |x| format!("{x:.0}"));
        println!("lubricated vs dry at {:.0} rpm:", c.speed_rpm);
        println!(
            "  central film {} µm; bearing stiffness {:.4e} vs {:.4e} N/m ({:+.1} %)",
            c.central_film_m
                .map_or("-".to_string(), |h| format!("{:.4}", h * 1e6)),
            c.bearing_stiffness_n_per_m[0],
            c.bearing_stiffness_n_per_m[1],
            100.0 * c.stiffness_increase
        );
        println!(
            "  first natural frequency {:.2} vs {:.2} Hz (shift {:+.2} Hz, {:+.2} %)",
            c.first_natural_frequency_hz[0],
            c.first_natural_frequency_hz[1],
            c.first_natural_frequency_shift_hz,
            100.0 * c.first_natural_frequency_shift_hz / c.first_natural_frequency_hz[1]
        );
        println!(
            "  {}× crossing of the first natural frequency: {} vs {} rpm; largest response at {:.0} vs {:.0} rpm",
            mesh.unwrap_or(1.0),
            opt(c.order_critical_speed_rpm[0]),
            opt(c.order_critical_speed_rpm[1]),
            c.peak_response_speed_rpm[0],
            c.peak_response_speed_rpm[1]
        );
    }
    println!("plots: {}, {}", a.plot.display(), waterfalls.join(", "));
    Ok(())
}
