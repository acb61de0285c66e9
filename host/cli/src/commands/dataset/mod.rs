//! `bearing dataset`: generate film training data, and check the domain against the reference
//! machines.

use std::path::PathBuf;

use anyhow::{bail, Result};
use bearing_ehl::point::PointSolverOptions;
use bearing_train::dataset::point_domain::PointDomain;
use bearing_train::dataset::{
    self, numerical, point_numerical, reference, Domain, GenerateOptions, LineFilms, SolverInfo,
};
use clap::{Args, Subcommand, ValueEnum};

/// `bearing dataset …`
#[derive(Args)]
pub struct DatasetArgs {
    #[command(subcommand)]
    command: DatasetCommand,
}

#[derive(Subcommand)]
enum DatasetCommand {
    /// Sample a maximin Latin hypercube over the film domain and solve every case (resumable).
    Generate(GenerateArgs),
    /// Check that the most loaded rollers of the docs/physics.md §6 cases lie in the domain.
    CheckDomain {
        /// Machine-readable output.
        #[arg(long)]
        json: bool,
    },
}

/// Which solver produces the films.
#[derive(Clone, Copy, Debug, ValueEnum)]
enum SolverChoice {
    /// The full numerical EHL solver (`bearing_ehl`).
    Numerical,
    /// Moes' formula (docs/physics.md §5.1): a stand-in target for pipeline tests only.
    Moes,
}

/// Which contact the dataset samples.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ContactKind {
    /// Cylindrical roller: line contact over `Domain` (docs/physics.md §5.3).
    Line,
    /// Ball: point contact over `PointDomain` (docs/point_contact.md, "Dataset"), solved by the
    /// point-contact solver with Richardson targets and per-row grid errors.
    Point,
}

#[derive(Args)]
struct GenerateArgs {
    /// Contact kind.
    #[arg(long, value_enum, default_value = "line")]
    contact: ContactKind,
    /// Point contact: nodes per direction of the finest grid (2ⁿ + 1 in 33 … 513; the dataset
    /// targets are made at 129).
    #[arg(long, default_value_t = 129)]
    nodes: usize,
    /// Number of feasible cases (1 … 1 000 000).
    #[arg(long, value_parser = clap::value_parser!(u64).range(1..=1_000_000))]
    n: u64,
    /// Seed of the Latin hypercube.
    #[arg(long)]
    seed: u64,
    /// Output file (JSON lines); an existing file with the same settings is resumed.
    #[arg(long)]
    out: PathBuf,
    /// Film solver.
    #[arg(long, value_enum, default_value = "numerical")]
    solver: SolverChoice,
    /// Cases solved in parallel between two writes (1 … 100 000).
    #[arg(long, default_value_t = 64, value_parser = clap::value_parser!(u64).range(1..=100_000))]
    chunk: u64,
    /// No progress bar.
    #[arg(long)]
    quiet: bool,
}

/// Run `bearing dataset`.
pub fn run(args: DatasetArgs) -> Result<()> {
    match args.command {
        DatasetCommand::Generate(g) => generate(g),
        DatasetCommand::CheckDomain { json } => check_domain(json),
    }
}

fn generate(args: GenerateArgs) -> Result<()> {
    if args.contact == ContactKind::Point {
        return generate_point(args);
    }
    if args.nodes != 129 {
        bail!(
            "--nodes applies to --contact point only (the line contact's grid sequence is fixed)"
        );
    }
    let command = std::env::args().collect::<Vec<_>>().join(" ");
    // The accuracy-reference settings of the solver (Roelands, Dowson–Higginson density,
    // docs/physics.md §5.2 tolerances), with the whole grid sequence to 801 nodes and the Richardson
    // estimate from its last two levels: the adaptive early stop (estimated error ≤ 1 %) would
    // put up to a percent of grid-dependent scatter into the targets the network learns.
    let ehl_options = bearing_ehl::SolverOptions {
        adaptive: false,
        ..bearing_ehl::SolverOptions::default()
    };
    let solver_info = match args.solver {
        SolverChoice::Moes => SolverInfo {
            name: "moes".into(),
            version: format!("bearing-host {} moes-1992", env!("CARGO_PKG_VERSION")),
            options: serde_json::json!({"formula": "Moes 1992 central; minimum = Moes central x DH/DT"}),
        },
        SolverChoice::Numerical => numerical::solver_info(&ehl_options),
    };
    let options = GenerateOptions {
        n: args.n as usize,
        seed: args.seed,
        domain: Domain::default(),
        solver: solver_info,
        command,
        progress: !args.quiet,
        chunk: args.chunk as usize,
    };
    let summary = match args.solver {
        SolverChoice::Moes => dataset::generate(&args.out, &options, |c| {
            dataset::moes_solver(c).map(LineFilms::from)
        })?,
        SolverChoice::Numerical => dataset::generate(&args.out, &options, |c| {
            numerical::solve(c, &ehl_options).map(LineFilms::from)
        })?,
    };
    report(&args, summary);
    Ok(())
}

/// Point contacts: the point solver at its accuracy settings (Roelands, Dowson–Higginson,
/// default domain) with `--nodes` per direction; h_c and h_min Richardson-extrapolated from the
/// two finest levels, refused above `point_numerical::MAX_GRID_ERROR`.
fn generate_point(args: GenerateArgs) -> Result<()> {
    if !matches!(args.solver, SolverChoice::Numerical) {
        bail!("--solver moes applies to --contact line only; point contacts use the point solver");
    }
    if !(33..=513).contains(&args.nodes) || !(args.nodes - 1).is_power_of_two() {
        bail!(
            "--nodes {}: must be 2ⁿ + 1 in 33 … 513 (two grid levels for the Richardson value)",
            args.nodes
        );
    }
    // The dataset's own grid rule and refusal (`point_numerical`), as the committed file was
    // generated.
    let solver_options = PointSolverOptions {
        nodes: args.nodes,
        grid_from_case: false,
        max_grid_error: None,
        ..PointSolverOptions::default()
    };
    let options = GenerateOptions {
        n: args.n as usize,
        seed: args.seed,
        domain: PointDomain::default(),
        solver: point_numerical::solver_info(&solver_options),
        command: std::env::args().collect::<Vec<_>>().join(" "),
        progress: !args.quiet,
        chunk: args.chunk as usize,
    };
    let summary = dataset::generate(&args.out, &options, |c| {
        point_numerical::solve(c, &solver_options)
    })?;
    report(&args, summary);
    Ok(())
}

fn report(args: &GenerateArgs, summary: dataset::generate::Summary) {
    eprintln!(
        "{}: {} records resumed, {} written, {} failed in total",
        args.out.display(),
        summary.resumed,
        summary.written,
        summary.failed
    );
}

fn check_domain(json: bool) -> Result<()> {
    let domain = Domain::default();
    let contacts = reference::check_reference_cases(&domain);
    if json {
        let rows: Vec<_> = contacts
            .iter()
            .map(|c| {
                serde_json::json!({
                    "case": c.name, "race": c.race, "speed_rpm": c.speed_rpm,
                    "radial_load_n": c.radial_load_n, "contact": c.case,
                    "hertz_pressure_pa": c.case.hertz_pressure_pa(),
                    "in_domain": c.verdict.is_ok(),
                    "reason": c.verdict.err().map(|e| format!("{e:?}")),
                })
            })
            .collect();
        println!("{}", serde_json::to_string_pretty(&rows)?);
        return Ok(());
    }
    println!(
        "{:<22} {:<6} {:>8} {:>8} {:>8} {:>8}  verdict",
        "case", "race", "rpm", "Q_max N", "u_m m/s", "p_h GPa"
    );
    for c in &contacts {
        println!(
            "{:<22} {:<6} {:>8.0} {:>8.1} {:>8.2} {:>8.3}  {}",
            c.name,
            c.race,
            c.speed_rpm,
            c.case.load_n,
            c.case.entrainment_speed_m_s,
            c.case.hertz_pressure_pa() / 1e9,
            match c.verdict {
                Ok(()) => "in domain".to_string(),
                Err(e) => format!("OUT: {e:?}"),
            }
        );
    }
    Ok(())
}
