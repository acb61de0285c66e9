//! `bearing`: the command-line front end of the host tools.
//!
//! Every subcommand lives in its own folder under `commands/` with a clap `Args` type and a
//! `run` function; this file only dispatches.

use clap::Subcommand;

mod commands;

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
    Film(commands::film::FilmArgs),
    /// Static equilibrium of a bearing under a radial load (lubricated, and dry with --dry).
    Static(commands::statics::StaticArgs),
    /// Stribeck curve of a bearing (friction torque and power loss against speed) or of one
    /// contact (friction coefficient against speed).
    Friction(commands::friction::FrictionArgs),
    /// Flexible-shaft simulator: static, modes, campbell, run, sweep.
    Shaft(commands::shaft::ShaftArgs),
    /// Film training data: generate datasets, check the domain.
    Dataset(commands::dataset::DatasetArgs),
    /// Train the film network, run the architecture sweep, evaluate the core models.
    Train(Box<commands::train::TrainArgs>),
    /// Write a trained film model into the core as const arrays.
    Export(commands::export::ExportArgs),
    /// Full numerical EHL line-contact solver.
    Ehl(commands::ehl::EhlArgs),
    /// FMI 2.0 co-simulation FMU of a bearing file: export.
    Fmu(commands::fmu::FmuArgs),
}

fn main() -> std::process::ExitCode {
    bearing_host_common::closed_pipe::end_quietly_when_the_reader_leaves();
    if let Err(e) = bearing_host_common::cpu::check() {
        eprintln!("error: {e}");
        return std::process::ExitCode::from(1);
    }
    let cli: Cli = bearing_host_common::args::parse();
    let result: anyhow::Result<()> = match cli.command {
        Command::Film(args) => commands::film::run(args),
        Command::Static(args) => commands::statics::run(args),
        Command::Friction(args) => commands::friction::run(args),
        Command::Shaft(args) => commands::shaft::run(args),
        Command::Dataset(args) => commands::dataset::run(args),
        Command::Train(args) => commands::train::run(*args),
        Command::Export(args) => commands::export::run(args),
        Command::Ehl(args) => commands::ehl::run(args),
        Command::Fmu(args) => commands::fmu::run(args),
    };
    match result {
        Ok(()) => std::process::ExitCode::SUCCESS,
        Err(err) => {
            eprintln!("error: {err:#}");
            std::process::ExitCode::FAILURE
        }
    }
}
