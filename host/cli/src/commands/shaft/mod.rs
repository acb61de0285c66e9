//! `bearing shaft …`: the flexible-shaft simulator's analyses — static equilibrium, modes,
//! Campbell diagram, time response and speed sweep — on a shaft TOML file
//! (see `bearing_shaft::config`).
//!
//! This module holds the arguments, the dispatch and what the subcommands share (flag checks,
//! model loading, time settings); the subcommands live in `analysis` (static, modes, campbell),
//! `run` (time response) and `sweep` (speed sweep).

use std::path::{Path, PathBuf};

use anyhow::{bail, Result};
use bearing_shaft::bearing::{BearingSpec, FilmKind, LinearBearing};
use bearing_shaft::config::load_model;
use bearing_shaft::integrator::{NewtonSettings, Scheme};
use bearing_shaft::loads::Load;
use bearing_shaft::model::RotorModel;
use bearing_shaft::simulate::RunSettings;
use clap::{Args, Subcommand, ValueEnum};

mod analysis;
mod report;
mod run;
mod sweep;
use analysis::{cmd_campbell, cmd_modes, cmd_static};
use run::cmd_run;
use sweep::cmd_sweep;

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
    #[arg(long, value_parser = film_arg())]
    film: Option<FilmKind>,
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
    /// Output PNG; default `campbell.png` with the table, none with --json.
    #[arg(long)]
    plot: Option<PathBuf>,
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
    /// Output prefix P: P.csv, P_bN_rollers.csv, P_bN_trace.csv (N the bearing's number;
    /// hil-sim trace format), P_orbit.png, P_spectrum.png.
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
    /// Speeds (rpm, comma separated); default the docs/physics.md §6.2 list.
    #[arg(long, value_delimiter = ',')]
    speeds_rpm: Option<Vec<f64>>,
    /// Envelope plot.
    #[arg(long, default_value = "shaft_sweep.png")]
    plot: PathBuf,
}

/// The parser of `--film`: one of the names of the core's [`FilmKind`], listed in `--help`.
fn film_arg() -> impl clap::builder::TypedValueParser<Value = FilmKind> {
    use clap::builder::TypedValueParser as _;
    clap::builder::PossibleValuesParser::new(FilmKind::ALL.map(FilmKind::name))
        .try_map(|name| name.parse::<FilmKind>())
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
            b.spec = b.spec.with_film(film);
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
    let record_every = check_count("record-every", t.record_every, 1, 1_000_000)?;
    // A recording needs two samples to have a spectrum, an orbit or a peak-to-peak value.
    let shortest = 2.0 * dt * record_every as f64;
    if duration < shortest {
        bail!(
            "--duration = {duration:e} s records fewer than two samples: allowed {shortest:e} ..= 100 s \
             (two samples of --record-every {record_every} steps of --dt {dt:e} s)"
        );
    }
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
        record_every,
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
