//! The workspace's own tasks, run as `cargo xtask …` (the alias in `.cargo/config.toml`):
//!
//! - `test`: installs what the tests need and is missing (the Rust target, Debian packages,
//!   a Python environment under `target/`), runs every test of the workspace and the docs'
//!   figure checks, and ends with one line of totals;
//! - `setup`: the installation alone;
//! - `generate [--check]`: the core's generated files (`core/src/generated/`);
//! - `cycles`: module import cycles inside each crate;
//! - `lengths`: files over 600 lines and functions over 150 (generated files excepted);
//! - `doc-figures [--all]`: the figures the docs show against the commands that make them.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

mod cycles;
mod doc_figures;
mod generate;
mod lengths;
mod rust_files;
mod setup;
mod test;

#[derive(Parser)]
#[command(name = "cargo xtask", about = "The workspace's own tasks")]
struct Cli {
    #[command(subcommand)]
    task: Task,
}

#[derive(Subcommand)]
enum Task {
    /// Install what the tests need and is missing, run every test, print the totals.
    Test(test::TestArgs),
    /// Install what the tests need and is missing (the first step of `test`).
    Setup,
    /// Write the core's generated files from their sources.
    Generate {
        /// Write nothing: regenerate in memory and fail naming every stale file.
        #[arg(long)]
        check: bool,
        /// Only these files (line-network, point-network, tanh-table, traction-table).
        names: Vec<String>,
    },
    /// List the module import cycles inside each crate; fails when there is one.
    Cycles,
    /// List hand-written files over 600 lines and functions over 150; fails when there is one.
    Lengths,
    /// Check the figures the docs show against the commands that make them.
    DocFigures(doc_figures::Args),
}

/// The repository's root (this crate sits in `host/xtask`).
pub fn root() -> PathBuf {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    root.canonicalize().unwrap_or(root)
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let root = root();
    let result = match cli.task {
        Task::Test(args) => test::run(&root, &args),
        Task::Setup => setup::run(&root, true).map(|_| ()),
        Task::Generate { check, names } => generate::run(&root, check, &names),
        Task::Cycles => cycles::run(&root),
        Task::Lengths => lengths::run(&root),
        Task::DocFigures(args) => doc_figures::run(&root, &args).map(|_| ()),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("cargo xtask: {e:#}");
            ExitCode::FAILURE
        }
    }
}
