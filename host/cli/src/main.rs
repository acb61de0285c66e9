//! `bearing`: the command-line front end of the host tools.
//!
//! Every subcommand lives in its own module under `cli/` with a clap `Args` type and a
//! `run` function; this file only dispatches.

use clap::Subcommand;

mod cli;

#[derive(clap::Parser)]
#[command(
    name = "bearing",
    version,
    about = "Lubricated roller-bearing model: EHL film, bearing forces, shaft simulation"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Film thickness and Hertz figures of one contact, every film model side by side.
    Film(cli::film::FilmArgs),
    /// Static equilibrium of a bearing under a radial load (lubricated, and dry with --dry).
    Static(cli::statics::StaticArgs),
    /// Stribeck curve of a bearing (friction torque and power loss against speed) or of one
    /// contact (friction coefficient against speed).
    Friction(cli::friction::FrictionArgs),
    /// Flexible-shaft simulator: static, modes, campbell, run, sweep.
    Shaft(cli::shaft::ShaftArgs),
    /// Film training data: generate datasets, check the domain.
    Dataset(cli::dataset::DatasetArgs),
    /// Train the film network, run the architecture sweep, evaluate the core models.
    Train(Box<cli::train::TrainArgs>),
    /// Write a trained film model into the core as const arrays.
    Export(cli::export::ExportArgs),
    /// Full numerical EHL line-contact solver.
    Ehl(cli::ehl::EhlArgs),
    /// FMI 2.0 co-simulation FMU of a bearing file: export.
    Fmu(cli::fmu::FmuArgs),
}

fn main() -> std::process::ExitCode {
    bearing_host_common::closed_pipe::end_quietly_when_the_reader_leaves();
    if let Err(e) = bearing_host_common::cpu::check() {
        eprintln!("error: {e}");
        return std::process::ExitCode::from(1);
    }
    let cli: Cli = bearing_host_common::args::parse();
    let result: anyhow::Result<()> = match cli.command {
        Command::Film(args) => cli::film::run(args),
        Command::Static(args) => cli::statics::run(args),
        Command::Friction(args) => cli::friction::run(args),
        Command::Shaft(args) => cli::shaft::run(args),
        Command::Dataset(args) => cli::dataset::run(args),
        Command::Train(args) => cli::train::run(*args),
        Command::Export(args) => cli::export::run(args),
        Command::Ehl(args) => cli::ehl::run(args),
        Command::Fmu(args) => cli::fmu::run(args),
    };
    match result {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(err) => {
            eprintln!("error: {err:#}");
            std::process::ExitCode::FAILURE
        }
    }
}
