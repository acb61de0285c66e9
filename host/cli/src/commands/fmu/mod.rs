//! `bearing fmu export`: the bearing of a bearing file as an FMI 2.0 co-simulation FMU for
//! linux64 (docs/fmu.md).

use std::path::PathBuf;

use anyhow::{anyhow, Context};
use bearing_core::FilmKind;
use clap::{Args, Subcommand};

/// FMU commands.
#[derive(Args, Debug)]
pub struct FmuArgs {
    #[command(subcommand)]
    pub command: FmuCommand,
}

/// FMU subcommands.
#[derive(Subcommand, Debug)]
pub enum FmuCommand {
    /// Write an FMI 2.0 co-simulation FMU (linux64) of a bearing file.
    Export(ExportArgs),
}

/// `bearing fmu export`.
#[derive(Args, Debug)]
pub struct ExportArgs {
    /// Bearing configuration (TOML); its values become the parameters' start values.
    #[arg(long)]
    pub config: PathBuf,
    /// Film model: int, f32, regression or dry.
    #[arg(long, default_value = "int")]
    pub film: FilmKind,
    /// The FMU to write (written whole or not at all).
    #[arg(long)]
    pub out: PathBuf,
    /// The FMU's shared library (`libbearing_fmu.so`); default: the one beside this executable.
    #[arg(long)]
    pub library: Option<PathBuf>,
}

/// Run `bearing fmu …`.
pub fn run(args: FmuArgs) -> anyhow::Result<()> {
    let FmuCommand::Export(args) = args.command;
    let library = match args.library {
        Some(path) => path,
        None => {
            let exe = std::env::current_exe().context("cannot locate the bearing executable")?;
            let dir = exe.parent().map(PathBuf::from).unwrap_or_default();
            bearing_fmu::package::find_library(&dir).map_err(|e| anyhow!(e))?
        }
    };
    let written = bearing_fmu::package::write_fmu(&args.config, args.film, &library, &args.out)
        .map_err(|e| anyhow!(e))?;
    println!(
        "wrote {} ({} bytes, film model {}, GUID {}, library {})",
        args.out.display(),
        written.bytes,
        args.film,
        written.guid,
        library.display()
    );
    Ok(())
}
