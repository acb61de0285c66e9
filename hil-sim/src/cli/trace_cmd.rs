//! `hil-sim trace validate|convert|info|synth`: work with trace files.

use super::check_range;
use anyhow::{Context, Result};
use bearing_hil::trace::synthetic::Whirl;
use bearing_hil::trace::{Trace, TraceMeta, ValidationOptions};
use clap::{Args, Subcommand};
use std::path::PathBuf;

/// Trace subcommands.
#[derive(Subcommand)]
pub enum TraceCommand {
    /// Read a trace (CSV or binary, by extension) and report the first problem, if any.
    Validate(FileArgs),
    /// Convert between CSV (`.csv`) and binary (any other extension), validating on the way.
    Convert {
        /// Input trace.
        input: PathBuf,
        /// Output trace.
        output: PathBuf,
        #[command(flatten)]
        checks: CheckArgs,
    },
    /// Print a trace's metadata, length and ranges.
    Info(FileArgs),
    /// Write a synthetic trace: a steady circular whirl (closed form, not a recording).
    Synth(SynthArgs),
}

/// Options of the content checks.
#[derive(Args)]
pub struct CheckArgs {
    /// Largest allowed relative deviation of a time step from 1/rate.
    #[arg(long, default_value_t = ValidationOptions::default().gap_tolerance, allow_hyphen_values = true)]
    pub gap_tolerance: f64,
}

impl CheckArgs {
    /// The checked options.
    pub fn options(&self) -> Result<ValidationOptions> {
        Ok(ValidationOptions {
            gap_tolerance: check_range("--gap-tolerance", self.gap_tolerance, 1e-9, 0.5)?,
        })
    }
}

/// A trace file to read.
#[derive(Args)]
pub struct FileArgs {
    /// Trace file (`.csv` is CSV, any other extension binary).
    pub file: PathBuf,
    #[command(flatten)]
    pub checks: CheckArgs,
    /// Machine-readable output.
    #[arg(long)]
    pub json: bool,
}

/// Parameters of a synthetic whirl trace.
#[derive(Args)]
pub struct SynthArgs {
    /// Output file (`.csv` or binary).
    pub output: PathBuf,
    /// Bearing identifier.
    #[arg(long, default_value = "hub_motor")]
    pub bearing: String,
    /// Lubricant identifier.
    #[arg(long, default_value = "thesis_oil")]
    pub lubricant: String,
    /// Sample rate (Hz).
    #[arg(long, default_value_t = 10_000.0, allow_hyphen_values = true)]
    pub rate_hz: f64,
    /// Number of samples.
    #[arg(long, default_value_t = 1000)]
    pub count: usize,
    /// Shaft speed (rpm).
    #[arg(long, default_value_t = 12_000.0, allow_hyphen_values = true)]
    pub speed_rpm: f64,
    /// Shaft speed at the end of the trace (rpm); default: the start speed (constant speed).
    #[arg(long, allow_hyphen_values = true)]
    pub speed_end_rpm: Option<f64>,
    /// Static displacement of the orbit centre in x (m).
    #[arg(long, default_value_t = 0.0, allow_hyphen_values = true)]
    pub offset_x_m: f64,
    /// Static displacement of the orbit centre in y (m).
    #[arg(long, default_value_t = -5.0e-6, allow_hyphen_values = true)]
    pub offset_y_m: f64,
    /// Orbit radius (m).
    #[arg(long, default_value_t = 1.0e-6, allow_hyphen_values = true)]
    pub radius_m: f64,
    /// Whirl frequency (Hz).
    #[arg(long, default_value_t = 200.0, allow_hyphen_values = true)]
    pub whirl_hz: f64,
    /// Tilt amplitude about x and y (rad); omit for a trace without tilt.
    #[arg(long, allow_hyphen_values = true)]
    pub tilt_rad: Option<f64>,
}

/// Runs a trace subcommand.
pub fn run(command: TraceCommand) -> Result<()> {
    match command {
        TraceCommand::Validate(args) => {
            let trace = match read(&args) {
                Ok(trace) => trace,
                Err(error) if args.json => {
                    // Machine-readable verdict on stdout; the exit status still says invalid.
                    println!(
                        "{}",
                        serde_json::json!({"valid": false, "error": format!("{error:#}")})
                    );
                    return Err(error);
                }
                Err(error) => return Err(error),
            };
            if args.json {
                println!(
                    "{}",
                    serde_json::json!({"valid": true, "samples": trace.samples.len()})
                );
            } else {
                println!(
                    "{}: valid, {} samples",
                    args.file.display(),
                    trace.samples.len()
                );
            }
            Ok(())
        }
        TraceCommand::Convert {
            input,
            output,
            checks,
        } => {
            let options = checks.options()?;
            let trace = Trace::read(&input, &options)
                .with_context(|| format!("reading {}", input.display()))?;
            trace
                .write(&output, &options)
                .with_context(|| format!("writing {}", output.display()))?;
            println!(
                "{} -> {}: {} samples",
                input.display(),
                output.display(),
                trace.samples.len()
            );
            Ok(())
        }
        TraceCommand::Info(args) => info(&args),
        TraceCommand::Synth(args) => synth(&args),
    }
}

fn read(args: &FileArgs) -> Result<Trace> {
    let options = args.checks.options()?;
    Trace::read(&args.file, &options).with_context(|| format!("reading {}", args.file.display()))
}

/// (min, max) of one quantity over the trace.
fn range(trace: &Trace, get: impl Fn(&bearing_hil::trace::Sample) -> f64) -> (f64, f64) {
    trace
        .samples
        .iter()
        .map(get)
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        })
}

fn info(args: &FileArgs) -> Result<()> {
    let trace = read(args)?;
    let speed = range(&trace, |s| f64::from(s.speed_rad_s));
    let x = range(&trace, |s| f64::from(s.x_m));
    let y = range(&trace, |s| f64::from(s.y_m));
    if args.json {
        let value = serde_json::json!({
            "bearing": trace.meta.bearing,
            "lubricant": trace.meta.lubricant,
            "sample_rate_hz": trace.meta.sample_rate_hz,
            "samples": trace.samples.len(),
            "duration_s": trace.duration_s(),
            "tilt": trace.has_tilt(),
            "speed_rad_s": [speed.0, speed.1],
            "x_m": [x.0, x.1],
            "y_m": [y.0, y.1],
        });
        println!("{}", serde_json::to_string_pretty(&value)?);
    } else {
        println!("file        {}", args.file.display());
        println!("bearing     {}", trace.meta.bearing);
        println!("lubricant   {}", trace.meta.lubricant);
        println!("rate        {} Hz", trace.meta.sample_rate_hz);
        println!(
            "samples     {} ({:.6} s)",
            trace.samples.len(),
            trace.duration_s()
        );
        println!(
            "tilt        {}",
            if trace.has_tilt() { "yes" } else { "no" }
        );
        println!("speed       {:.3} .. {:.3} rad/s", speed.0, speed.1);
        println!("x           {:.4e} .. {:.4e} m", x.0, x.1);
        println!("y           {:.4e} .. {:.4e} m", y.0, y.1);
    }
    Ok(())
}

fn synth(args: &SynthArgs) -> Result<()> {
    let rate = check_range("--rate-hz", args.rate_hz, 1.0, 1.0e7)?;
    if args.count == 0 || args.count > 10_000_000 {
        anyhow::bail!(
            "--count = {} is out of range: allowed 1 ..= 10000000",
            args.count
        );
    }
    let speed_rpm = check_range("--speed-rpm", args.speed_rpm, 0.0, 1.0e6)?;
    let speed_end_rpm = match args.speed_end_rpm {
        Some(end) => check_range("--speed-end-rpm", end, 0.0, 1.0e6)?,
        None => speed_rpm,
    };
    let duration_s = args.count.saturating_sub(1).max(1) as f64 / rate;
    let whirl = Whirl {
        speed_rad_s: speed_rpm * std::f64::consts::TAU / 60.0,
        acceleration_rad_s2: (speed_end_rpm - speed_rpm) * std::f64::consts::TAU
            / 60.0
            / duration_s,
        offset_m: [
            check_range("--offset-x-m", args.offset_x_m, -1e-3, 1e-3)?,
            check_range("--offset-y-m", args.offset_y_m, -1e-3, 1e-3)?,
        ],
        radius_m: check_range("--radius-m", args.radius_m, 0.0, 1e-3)?,
        whirl_rad_s: check_range("--whirl-hz", args.whirl_hz, -1e6, 1e6)? * std::f64::consts::TAU,
        tilt_amplitude_rad: args
            .tilt_rad
            .map(|t| check_range("--tilt-rad", t, -0.1, 0.1))
            .transpose()?,
    };
    let meta = TraceMeta {
        bearing: args.bearing.clone(),
        lubricant: args.lubricant.clone(),
        sample_rate_hz: rate,
    };
    let trace = whirl.trace(meta, args.count);
    trace
        .write(&args.output, &ValidationOptions::default())
        .with_context(|| format!("writing {}", args.output.display()))?;
    println!(
        "{}: {} samples of a synthetic whirl",
        args.output.display(),
        args.count
    );
    Ok(())
}
