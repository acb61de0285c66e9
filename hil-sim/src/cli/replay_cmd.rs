//! `hil-sim replay`: replay a trace through the bearing model on the host, time every step,
//! check accuracy against the numerical solver, and write the report.

use super::check_range;
use anyhow::{anyhow, Context, Result};
use bearing_hil::realtime::Realtime;
use bearing_hil::replay::engine::Parts;
use bearing_hil::replay::report::ReplayReport;
use bearing_hil::replay::stats::Limits;
use bearing_hil::replay::{film_arg, plots, replay, FilmKind, ReplayConfig};
use bearing_hil::trace::{Trace, ValidationOptions};
use bearing_hil::wiring;
use bearing_host_common::output::OutputFiles;
use clap::Args;
use std::path::PathBuf;
use std::process::ExitCode;

/// Arguments of `replay`.
#[derive(Args)]
pub struct ReplayArgs {
    /// Trace file (`.csv` or binary); default: the bundled hub-motor run-up.
    #[arg(long)]
    pub trace: Option<PathBuf>,
    /// Step rate (Hz) for pacing and the budget; default: the trace's sample rate.
    #[arg(long, allow_hyphen_values = true)]
    pub rate_hz: Option<f64>,
    /// Step-time budget for the 99.9th percentile (µs).
    #[arg(long, default_value_t = Limits::default().budget_us, allow_hyphen_values = true)]
    pub budget_us: f64,
    /// Film model of the bearing step.
    #[arg(long, value_parser = film_arg(), default_value_t = FilmKind::Int)]
    pub film: FilmKind,
    /// Recompute every K-th sample with the full numerical solver (0: no accuracy check). Each
    /// point solves every loaded contact's film–load coupling numerically, about ten cold
    /// solves per roller on all cores (≈ 0.5–1 s of CPU per sample for the 17-roller hub
    /// bearing): the default checks 200 samples of the bundled hub-motor run-up, resonance
    /// crossing included.
    #[arg(long, default_value_t = 100)]
    pub reference_every: usize,
    /// Run at wall-clock rate with a deadline per period; count misses and lateness.
    #[arg(long)]
    pub paced: bool,
    /// Directory for report.json, report.md and the plots.
    #[arg(long, default_value = "reports/replay")]
    pub report: PathBuf,
    /// Print the JSON report instead of the markdown summary.
    #[arg(long)]
    pub json: bool,
    /// Run the timed loop as a real-time thread: SCHED_FIFO, pinned to one CPU, memory
    /// locked (Linux; needs root or CAP_SYS_NICE), so that no other process on the machine can
    /// take the CPU from it for a scheduler slice (4 ms at HZ = 250) in the middle of a step.
    /// `auto` asks for it and, if refused, runs under the ordinary policy and says so in the
    /// report; `on` (also plain `--realtime`) fails when refused. The accuracy pass runs
    /// normally after it.
    #[arg(long, value_enum, default_value_t = RealtimeMode::Auto, num_args = 0..=1, default_missing_value = "on")]
    pub realtime: RealtimeMode,
    /// CPU of the timed loop under real-time scheduling; default: the last one.
    #[arg(long)]
    pub rt_cpu: Option<usize>,
    /// SCHED_FIFO priority under real-time scheduling (1–99).
    #[arg(long, default_value_t = 80)]
    pub rt_priority: i32,
    /// Spin this long (s, 0–60) after the timed loop, on its CPU and policy, counting the
    /// machine's pauses: the report then says how many steps over the budget the machine alone
    /// explains (0: no probe).
    #[arg(long, default_value_t = 0.5, allow_hyphen_values = true)]
    pub pause_probe_s: f64,
    /// Fail a missed timing budget even when the machine's measured pauses alone explain the
    /// steps over it (without this flag such a run leaves the budget "not judged" and exits 0
    /// if the accuracy passed: the model's steps cannot be told from the machine's pauses).
    #[arg(long)]
    pub strict_timing: bool,
}

/// Whether the timed loop runs under real-time scheduling.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum RealtimeMode {
    /// Ask for it; run under the ordinary policy if the system refuses.
    Auto,
    /// Require it: the replay fails if the system refuses.
    On,
    /// The ordinary scheduling policy.
    Off,
}

/// Runs the replay; exit status 2 when the budget or the accuracy limits are missed.
pub fn run(args: &ReplayArgs) -> Result<ExitCode> {
    let budget_us = check_range("--budget-us", args.budget_us, 1e-3, 1e6)?;
    let pause_probe_s = check_range("--pause-probe-s", args.pause_probe_s, 0.0, 60.0)?;
    let path = args.trace.clone().unwrap_or_else(wiring::default_trace);
    if args.trace.is_none() && !path.exists() {
        anyhow::bail!(
            "the bundled trace {} is missing; pass --trace FILE (`hil-sim trace synth FILE` writes a synthetic one)",
            path.display()
        );
    }
    let trace = Trace::read(&path, &ValidationOptions::default())
        .with_context(|| format!("reading trace {}", path.display()))?;
    let rate_hz = match args.rate_hz {
        Some(rate) => check_range("--rate-hz", rate, 1e-3, 1e7)?,
        None => trace.meta.sample_rate_hz,
    };
    let period_us = 1e6 / rate_hz;
    if budget_us > period_us {
        anyhow::bail!(
            "--budget-us = {budget_us} exceeds the period 1/--rate-hz = {period_us:.3} µs: such a budget cannot be met in real time"
        );
    }
    let first = trace
        .samples
        .first()
        .ok_or_else(|| anyhow!("the trace has no samples"))?;
    let mut product = wiring::product(&trace.meta, args.film, first).map_err(|e| anyhow!(e))?;
    // A second, identical stepper that warms the caches before the timed loop (engine doc);
    // it needs neither the dry model nor the reference.
    let mut warm_up =
        wiring::primed_stepper(&trace.meta, args.film, first).map_err(|e| anyhow!(e))?;
    // The request is checked in every mode, `off` included: a CPU or priority no machine can
    // grant is a mistake on the command line whatever the policy asked for.
    let default = Realtime::default_for_this_machine();
    let request = Realtime {
        cpu: args.rt_cpu.unwrap_or(default.cpu),
        priority: args.rt_priority,
    };
    request.check().map_err(|e| anyhow!(e))?;
    let realtime = match args.realtime {
        RealtimeMode::Off => None,
        RealtimeMode::Auto | RealtimeMode::On => Some(request),
    };
    let config = ReplayConfig {
        rate_hz,
        reference_every: args.reference_every,
        paced: args.paced,
        limits: Limits {
            budget_us,
            ..Limits::default()
        },
        min_reference_force_n: 1.0,
        realtime,
        realtime_fallback: args.realtime == RealtimeMode::Auto,
        pause_probe_s,
        strict_timing: args.strict_timing,
    };
    let points = if args.reference_every == 0 || product.reference.is_none() {
        0
    } else {
        trace.samples.len().div_ceil(args.reference_every)
    };
    let bar = indicatif::ProgressBar::new(points as u64);
    if args.json || points == 0 {
        bar.set_draw_target(indicatif::ProgressDrawTarget::hidden());
    } else {
        bar.set_style(
            indicatif::ProgressStyle::with_template(
                "reference solver {bar:40} {pos}/{len} samples, eta {eta}",
            )
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar()),
        );
    }
    let stepper_name = product.stepper.name();
    let run = replay(
        &trace,
        Parts {
            stepper: product.stepper.as_mut(),
            reference: product
                .reference
                .as_mut()
                .map(|r| r.as_mut() as &mut dyn bearing_hil::replay::AccuracyReference),
            dry: product
                .dry
                .as_mut()
                .map(|d| d.as_mut() as &mut dyn bearing_hil::replay::BearingStepper),
            warm_up: Some(&mut warm_up),
        },
        &config,
        Some(&bar),
    )?;
    bar.finish_and_clear();
    let report = ReplayReport::build(&trace.meta, args.film, stepper_name, &config, &run)
        .ok_or_else(|| anyhow!("the trace has no samples"))?;
    // The report and its plots together or not at all: a report.json reading `budget_ok` must
    // not stand without the plots it describes.
    let mut files = OutputFiles::new();
    report
        .write(&mut files, &args.report, &trace, &run)
        .with_context(|| format!("writing the report into {}", args.report.display()))?;
    plots::write_all(&mut files, &args.report, &trace, &run, budget_us)
        .map_err(|e| anyhow!("writing the report into {}: {e}", args.report.display()))?;
    files
        .commit()
        .with_context(|| format!("writing the report into {}", args.report.display()))?;
    if args.json {
        println!("{}", serde_json::to_string_pretty(&report)?);
    } else {
        println!("{}", report.markdown());
        println!("report written to {}", args.report.display());
    }
    for note in &report.notes {
        eprintln!("hil-sim replay: {note}");
    }
    if report.passed() {
        Ok(ExitCode::SUCCESS)
    } else {
        for reason in &report.reasons {
            eprintln!("hil-sim replay: {reason}");
        }
        Ok(ExitCode::from(2))
    }
}
