//! `hil-sim`: the hardware-in-the-loop harness's command line.
//!
//! Every subcommand lives in its own module under `cli/`; this file only dispatches.

use clap::Subcommand;

mod cli;

#[derive(clap::Parser)]
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
    /// Replay a trace through the bearing model on the host: timing budget and accuracy.
    Replay(cli::replay_cmd::ReplayArgs),
    /// Replay a trace on the emulated Cortex-M4 (QEMU) and compare with the host.
    Qemu(cli::qemu_cmd::QemuArgs),
}

fn main() -> std::process::ExitCode {
    bearing_host_common::closed_pipe::end_quietly_when_the_reader_leaves();
    if let Err(e) = bearing_host_common::cpu::check() {
        eprintln!("error: {e}");
        return std::process::ExitCode::from(1);
    }
    let cli: Cli = bearing_host_common::args::parse();
    let result: anyhow::Result<std::process::ExitCode> = match cli.command {
        Command::Trace(command) => {
            cli::trace_cmd::run(command).map(|()| std::process::ExitCode::SUCCESS)
        }
        Command::Replay(args) => cli::replay_cmd::run(&args),
        Command::Qemu(args) => cli::qemu_cmd::run(&args),
    };
    match result {
        Ok(code) => code,
        Err(err) => {
            eprintln!("error: {err:#}");
            std::process::ExitCode::FAILURE
        }
    }
}
