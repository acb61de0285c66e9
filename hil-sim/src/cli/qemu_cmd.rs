//! `hil-sim qemu`: replay a trace on the emulated Cortex-M4 and compare with the host.

use super::check_range;
use anyhow::{anyhow, Result};
use bearing_hil::qemu::{self, QemuOptions};
use bearing_hil::replay::{film_arg, FilmKind};
use bearing_hil::wiring;
use clap::Args;
use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Duration;

/// Arguments of `qemu`.
#[derive(Args)]
pub struct QemuArgs {
    /// Trace file (`.csv` or binary); default: the bundled hub-motor run-up.
    #[arg(long)]
    pub trace: Option<PathBuf>,
    /// Working and report directory (trace.bin, outputs.bin, log.defmt, qemu.json).
    #[arg(long, default_value = "reports/qemu")]
    pub report: PathBuf,
    /// Kill QEMU after this many seconds.
    #[arg(long, default_value_t = 300.0, allow_hyphen_values = true)]
    pub timeout_s: f64,
    /// Largest acceptable instruction count per step.
    #[arg(long, default_value_t = 30_000)]
    pub max_instructions: u32,
    /// Film model of the bearing step.
    #[arg(long, value_parser = film_arg(), default_value_t = FilmKind::Int)]
    pub film: FilmKind,
    /// Print the JSON report.
    #[arg(long)]
    pub json: bool,
}

/// Runs the emulated replay; exit status 2 when a check fails.
pub fn run(args: &QemuArgs) -> Result<ExitCode> {
    let timeout_s = check_range("--timeout-s", args.timeout_s, 1.0, 86_400.0)?;
    let trace = args.trace.clone().unwrap_or_else(wiring::default_trace);
    if args.trace.is_none() && !trace.exists() {
        anyhow::bail!(
            "the bundled trace {} is missing; pass --trace FILE (`hil-sim trace synth FILE` writes a synthetic one)",
            trace.display()
        );
    }
    let options = QemuOptions {
        trace,
        report_dir: args.report.clone(),
        timeout: Duration::from_secs_f64(timeout_s),
        max_instructions: args.max_instructions,
        film: args.film,
    };
    if !args.json {
        eprintln!("building the firmware and running it under QEMU…");
    }
    let report = qemu::run(&options).map_err(|e| anyhow!(e))?;
    if args.json {
        println!("{}", serde_json::to_string_pretty(&report)?);
    } else {
        if let Some(log) = &report.log {
            for line in log {
                println!("firmware: {line}");
            }
        } else {
            println!(
                "(install defmt-print with `cargo install defmt-print` to decode {}/log.defmt)",
                args.report.display()
            );
        }
        let i = &report.instructions_per_step;
        println!("steps                  {}", report.steps);
        println!(
            "instructions per step  min {} / median {} / max {}",
            i.min, i.median, i.max
        );
        let f = &report.friction_instructions_per_step;
        println!(
            "friction call          min {} / median {} / max {} instructions (after each step, counted apart)",
            f.min, f.median, f.max
        );
        println!(
            "calibration            1000 nop = {} instructions (TIM2), {} SysTick counts",
            report.calibration.instructions, report.calibration.systick
        );
        println!("flash                  {} bytes", report.flash_bytes);
        println!("static RAM             {} bytes", report.ram_bytes);
        println!(
            "peak stack             {} bytes ({} below the replay loop)",
            report.stack_bytes, report.loop_stack_bytes
        );
        println!(
            "outputs match host     {} ({} steps compared bit for bit)",
            report.outputs_match, report.comparison.steps
        );
        if !report.profile.is_empty() {
            println!("where a step goes (instructions, one call each on hub-motor values):");
            for entry in &report.profile {
                println!("  {:>8}  {}", entry.instructions, entry.item);
            }
        }
        println!("report written to {}", args.report.display());
    }
    if report.passed() {
        Ok(ExitCode::SUCCESS)
    } else {
        for reason in &report.reasons {
            eprintln!("hil-sim qemu: {reason}");
        }
        Ok(ExitCode::from(2))
    }
}
