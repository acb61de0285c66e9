//! `hil-sim`: the hardware-in-the-loop harness's command line.
//!
//! Every subcommand lives in its own module under `cli/`; this file only dispatches.

use clap::{Parser, Subcommand};

mod cli;

#[derive(Parser)]
#[command(
    name = "hil-sim",
    version,
    about = "Replay recorded bearing kinematics on the host and on an emulated Cortex-M4"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Inspect, validate, convert and synthesise trace files.
    #[command(subcommand)]
    Trace(cli::trace_cmd::TraceCommand),
}

fn main() -> std::process::ExitCode {
    let cli = Cli::parse();
    let result: anyhow::Result<()> = match cli.command {
        Command::Trace(command) => cli::trace_cmd::run(command),
    };
    match result {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(err) => {
            eprintln!("error: {err:#}");
            std::process::ExitCode::FAILURE
        }
    }
}
