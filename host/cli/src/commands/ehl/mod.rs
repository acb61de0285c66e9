//! `bearing ehl`: the full numerical EHL line-contact solver from the command line.
//!
//! `bearing ehl solve` solves one case given either in SI (`--load N --length M --entrainment
//! M_PER_S --radius M --modulus PA --alpha PER_PA --eta0 PA_S`, the flags of `bearing film`) or
//! by dimensionless groups (`--w --u --g`, or Moes `--m --l`); `bearing ehl convergence` prints
//! the N / 2N / 4N grid-refinement table with the Richardson extrapolation; `bearing ehl
//! compare` runs the formula comparisons ([`compare`]).

use anyhow::{bail, Context, Result};
use bearing_ehl::{
    self as ehl, convergence, ContactCase, EhlError, EhlSolution, SolverOptions, ViscosityLaw,
};
use bearing_host_common::output::OutputFiles;
use clap::{Args, Subcommand};
use std::path::PathBuf;

mod compare;
mod plot;
mod point;
mod trust;

#[derive(Args, Debug)]
pub struct EhlArgs {
    #[command(subcommand)]
    command: EhlCommand,
}

#[derive(Subcommand, Debug)]
enum EhlCommand {
    /// Solve one line contact and print film thickness, pressure and solver figures.
    Solve(SolveArgs),
    /// Grid-refinement table (N, 2N, 4N and Richardson extrapolation) for one case.
    Convergence(ConvergenceArgs),
    /// The solver against Moes' or Pan–Hamrock's formula over a grid of cases (docs/ehl.md).
    Compare(compare::CompareArgs),
}

/// The case: SI flags, or W/U/G, or Moes M/L.
#[derive(Args, Debug, Clone)]
struct CaseArgs {
    /// Roller (contact) load Q in N.
    #[arg(long)]
    load: Option<f64>,
    /// Effective contact length l in m (load per length w = Q/l).
    #[arg(long)]
    length: Option<f64>,
    /// Entrainment speed u_m in m/s.
    #[arg(long)]
    entrainment: Option<f64>,
    /// Reduced radius R in m.
    #[arg(long)]
    radius: Option<f64>,
    /// Reduced modulus E' in Pa.
    #[arg(long)]
    modulus: Option<f64>,
    /// Pressure–viscosity coefficient α in 1/Pa.
    #[arg(long)]
    alpha: Option<f64>,
    /// Ambient viscosity η₀ in Pa·s.
    #[arg(long)]
    eta0: Option<f64>,
    /// Load parameter W = w/(E'R).
    #[arg(long)]
    w: Option<f64>,
    /// Speed parameter U = η₀u_m/(E'R).
    #[arg(long)]
    u: Option<f64>,
    /// Material parameter G = αE'.
    #[arg(long)]
    g: Option<f64>,
    /// Moes load parameter M.
    #[arg(long)]
    m: Option<f64>,
    /// Moes material parameter L.
    #[arg(long)]
    l: Option<f64>,
    /// Barus viscosity instead of Roelands.
    #[arg(long)]
    barus: bool,
    /// Incompressible lubricant instead of Dowson–Higginson density.
    #[arg(long)]
    incompressible: bool,
    /// Number of grid nodes (line: 41..=8193, default 801; point: nodes per direction,
    /// 2^n + 1 in 17..=513; without it and --rolling-nodes the grid is chosen from the case,
    /// 129² to 513 × 257, and a result whose estimated grid error exceeds 2 % is refused).
    #[arg(long)]
    nodes: Option<usize>,
    /// Point contact: nodes along the rolling direction X (2^n + 1, from --nodes to
    /// 4 (nodes - 1) + 1, at most 1025; default --nodes), e.g. 257 with --nodes 129 for
    /// high-M elliptical contacts (docs/point_contact.md).
    #[arg(long)]
    rolling_nodes: Option<usize>,
    /// Point contact: reduced radius across the rolling direction R_y in m (R_y/R_x in [1, 40]).
    #[arg(long)]
    radius_y: Option<f64>,
    /// Point contact: ellipticity k = a/b in [1, 12] (sets R_y from --radius), instead of
    /// --radius-y; with --m --l, the ellipticity of the case (default 1).
    #[arg(long)]
    ellipticity: Option<f64>,
}

/// The kind of contact `bearing ehl solve` solves.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
enum Contact {
    /// Cylindrical roller: line contact.
    Line,
    /// Ball: circular or elliptical point contact.
    Point,
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
struct SolveArgs {
    #[command(flatten)]
    case: CaseArgs,
    /// Contact kind: line (roller) or point (ball; give --radius-y or --ellipticity).
    #[arg(long, value_enum, default_value = "line")]
    contact: Contact,
    /// Machine-readable JSON output.
    #[arg(long)]
    json: bool,
    /// Write the pressure and film profile to this CSV file.
    #[arg(long)]
    profile: Option<PathBuf>,
    /// Plot pressure (with the Hertz ellipse) and film against X to this PNG file (line), or
    /// the pressure and film maps to this SVG file (point).
    #[arg(long)]
    plot: Option<PathBuf>,
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
struct ConvergenceArgs {
    #[command(flatten)]
    case: CaseArgs,
    /// Machine-readable JSON output.
    #[arg(long)]
    json: bool,
}

impl CaseArgs {
    fn options(&self) -> SolverOptions {
        SolverOptions {
            viscosity: if self.barus {
                ViscosityLaw::Barus
            } else {
                ViscosityLaw::Roelands
            },
            compressible: !self.incompressible,
            nodes: self.nodes.unwrap_or(ehl::DEFAULT_NODES),
            ..Default::default()
        }
    }

    /// The flags that set the case (for messages).
    fn flags(&self) -> &'static str {
        if self.m.is_some() || self.l.is_some() {
            "--m, --l"
        } else if self.w.is_some() || self.u.is_some() || self.g.is_some() {
            "--w, --u, --g"
        } else {
            "--load/--length, --entrainment, --radius, --modulus, --alpha, --eta0"
        }
    }

    fn case(&self) -> Result<ContactCase> {
        if self.radius_y.is_some() || self.ellipticity.is_some() || self.rolling_nodes.is_some() {
            bail!("--radius-y, --ellipticity and --rolling-nodes are point-contact flags: use `bearing ehl solve --contact point`");
        }
        let si = [
            ("--load", self.load),
            ("--length", self.length),
            ("--entrainment", self.entrainment),
            ("--radius", self.radius),
            ("--modulus", self.modulus),
            ("--alpha", self.alpha),
            ("--eta0", self.eta0),
        ];
        let wug = [("--w", self.w), ("--u", self.u), ("--g", self.g)];
        let ml = [("--m", self.m), ("--l", self.l)];
        let given = |set: &[(&str, Option<f64>)]| set.iter().any(|(_, v)| v.is_some());
        let groups = [given(&si), given(&wug), given(&ml)];
        if groups.iter().filter(|g| **g).count() != 1 {
            bail!("give exactly one case: SI flags (--load --length --entrainment --radius --modulus --alpha --eta0), or --w --u --g, or --m --l");
        }
        let need = |set: &[(&str, Option<f64>)]| -> Result<Vec<f64>> {
            set.iter()
                .map(|(name, v)| v.with_context(|| format!("missing {name}")))
                .collect()
        };
        if groups[0] {
            let v = need(&si)?;
            for (i, (name, _)) in si.iter().enumerate() {
                let allowed_zero = *name == "--alpha" && v[i] == 0.0;
                if !(v[i].is_finite() && v[i] > 0.0 || allowed_zero) {
                    bail!("{name} = {} is invalid: must be finite and > 0", v[i]);
                }
            }
            ContactCase::new(v[0] / v[1], v[2], v[3], v[4], v[5], v[6])
                .map_err(|e| name_flags(e, &SI_FIELDS, "--load --length … --eta0"))
        } else if groups[1] {
            let v = need(&wug)?;
            ContactCase::from_dimensionless(v[0], v[1], v[2])
                .map_err(|e| name_flags(e, &["W", "U", "G"], "--w --u --g"))
        } else {
            let v = need(&ml)?;
            ContactCase::from_moes(v[0], v[1]).map_err(|e| name_flags(e, &["M", "L"], "--m --l"))
        }
    }
}

/// The solver fields the SI flags set (load per length from --load / --length).
const SI_FIELDS: [&str; 6] = [
    "load_per_length_n_per_m",
    "entrainment_speed_m_s",
    "reduced_radius_m",
    "reduced_modulus_pa",
    "pressure_viscosity_pa_inv",
    "viscosity_pa_s",
];

/// The flag a solver input or option comes from: the user typed flags, not the solver's field
/// names. `None` for a quantity no single flag sets.
fn flag_of(field: &str) -> Option<&'static str> {
    Some(match field {
        "load_per_length_n_per_m" => "--load / --length (load per length, N/m)",
        "entrainment_speed_m_s" => "--entrainment",
        "reduced_radius_m" => "--radius",
        "reduced_modulus_pa" => "--modulus",
        "pressure_viscosity_pa_inv" => "--alpha",
        "viscosity_pa_s" => "--eta0",
        "W" => "--w",
        "U" => "--u",
        "G" => "--g",
        "M" => "--m",
        "L" => "--l",
        "nodes" => "--nodes",
        _ => return None,
    })
}

/// A solver error in the words of the command line: the flag that set the refused value, or,
/// for a quantity the solver derives from the flags of the case (`given`), those flags. `direct`
/// lists the solver fields the case's flags set one to one.
fn name_flags(error: EhlError, direct: &[&str], given: &str) -> anyhow::Error {
    match &error {
        EhlError::InvalidInput {
            field,
            value,
            allowed,
        } => match flag_of(field) {
            Some(flag) if direct.contains(field) => {
                anyhow::anyhow!("{flag} = {value:e} is out of range: allowed {allowed}")
            }
            Some(flag) => {
                anyhow::anyhow!("{given} give {flag} = {value:e}, out of range: allowed {allowed}")
            }
            None => anyhow::anyhow!("{given}: {error}"),
        },
        EhlError::InvalidOption { field, message } => match flag_of(field) {
            Some(flag) => anyhow::anyhow!("{flag}: {message}"),
            None => anyhow::anyhow!("{error}"),
        },
        // Names a derived quantity (h_c/R, …); the caller adds the flags that set the case.
        EhlError::OutsideModel { .. }
        | EhlError::NotConverged { .. }
        | EhlError::GridTooCoarse { .. } => {
            anyhow::anyhow!("{error}")
        }
    }
}

/// Runs `bearing ehl …`.
pub fn run(args: EhlArgs) -> Result<()> {
    match args.command {
        EhlCommand::Solve(a) => solve(a),
        EhlCommand::Convergence(a) => convergence_table(a),
        EhlCommand::Compare(a) => compare::run(a),
    }
}

fn solve(a: SolveArgs) -> Result<()> {
    if a.contact == Contact::Point {
        return point::solve(&a);
    }
    let result = a.case.case().and_then(|c| {
        trust::solve(&c, &a.case.options(), a.case.flags(), |e| {
            name_flags(e, &[], "the case")
        })
    });
    let sol = failure_as_json(result, a.json)?;
    // Both files or neither: a failed plot leaves no profile behind.
    let mut files = OutputFiles::new();
    if let Some(path) = &a.profile {
        let temp = files
            .stage(path)
            .with_context(|| format!("--profile {}", path.display()))?;
        let mut csv = Vec::new();
        sol.write_profile_csv(&mut csv)?;
        std::fs::write(temp, csv).with_context(|| format!("--profile {}", path.display()))?;
    }
    if let Some(path) = &a.plot {
        let temp = files
            .stage(path)
            .with_context(|| format!("--plot {}", path.display()))?;
        plot::plot(&sol, &temp).with_context(|| format!("--plot {}", path.display()))?;
    }
    files.commit()?;
    if a.json {
        let v = serde_json::json!({
            "converged": true,
            "grid_error_estimate": sol.grid_error_estimate,
            "central_film_m": sol.central_film_m,
            "min_film_m": sol.min_film_m,
            "central_film_raw_m": sol.central_film_raw_m,
            "min_film_raw_m": sol.min_film_raw_m,
            "richardson": sol.richardson,
            "min_film_x_over_b": sol.min_film_x,
            "max_pressure_pa": sol.max_pressure_pa,
            "max_pressure_x_over_b": sol.max_pressure_x,
            "hertz_pressure_pa": sol.hertz_pressure_pa,
            "hertz_half_width_m": sol.hertz_half_width_m,
            "exit_x_over_b": sol.exit_x,
            "domain_x_over_b": [sol.profile.x[0], sol.profile.x[sol.profile.x.len() - 1]],
            "iterations": sol.iterations,
            "nodes": sol.nodes,
            "wall_time_s": sol.wall_time_s,
            "pressure_change": sol.pressure_change,
            "load_error": sol.load_error,
            "reynolds_residual": sol.reynolds_residual,
            "moes_m": sol.case.moes_m(),
            "moes_l": sol.case.moes_l(),
        });
        println!("{}", serde_json::to_string_pretty(&v)?);
    } else {
        print_solution(&sol);
    }
    Ok(())
}

fn print_solution(s: &EhlSolution) {
    let c = &s.case;
    println!(
        "EHL line contact (isothermal, Newtonian), {} nodes",
        s.nodes
    );
    println!(
        "  W = {:.4e}  U = {:.4e}  G = {:.1}  M = {:.3}  L = {:.3}",
        c.load_parameter(),
        c.speed_parameter(),
        c.material_parameter(),
        c.moes_m(),
        c.moes_l()
    );
    println!(
        "  Hertz pressure p_h     {:>12.4} GPa   half-width b {:.4} mm",
        s.hertz_pressure_pa / 1e9,
        s.hertz_half_width_m * 1e3
    );
    println!(
        "  central film h_c       {:>12.4} µm   (this grid {:.4} µm, Richardson {})",
        s.central_film_m * 1e6,
        s.central_film_raw_m * 1e6,
        if s.richardson { "on" } else { "off" }
    );
    println!(
        "  minimum film h_min     {:>12.4} µm   at x/b = {:.4}",
        s.min_film_m * 1e6,
        s.min_film_x
    );
    println!(
        "  maximum pressure       {:>12.4} GPa   at x/b = {:.4}",
        s.max_pressure_pa / 1e9,
        s.max_pressure_x
    );
    println!("  film exit              x/b = {:.4}", s.exit_x);
    if let Some(e) = &s.grid_error_estimate {
        println!(
            "  grid error (estimated) h_c {:.3} %, h_min {:.3} % on this grid (from {} nodes)",
            100.0 * e.central_film,
            100.0 * e.min_film,
            e.other_nodes
        );
    }
    println!(
        "  Moes h_c / Pan–Hamrock h_c, h_min: {:.4} / {:.4}, {:.4} µm",
        ehl::formulas::moes_central_film_m(c) * 1e6,
        ehl::formulas::pan_hamrock_central_film_m(c) * 1e6,
        ehl::formulas::pan_hamrock_min_film_m(c) * 1e6
    );
    println!(
        "  iterations {}  ΣΔP/ΣP {:.2e}  load error {:.2e}  wall time {:.1} ms",
        s.iterations,
        s.pressure_change,
        s.load_error,
        s.wall_time_s * 1e3
    );
}

fn convergence_table(a: ConvergenceArgs) -> Result<()> {
    let case = a.case.case()?;
    let study =
        convergence::study(&case, &a.case.options()).map_err(|e| name_flags(e, &[], "the case"))?;
    if a.json {
        println!("{}", serde_json::to_string_pretty(&study)?);
        return Ok(());
    }
    println!(
        "grid refinement (M = {:.3}, L = {:.3})",
        case.moes_m(),
        case.moes_l()
    );
    println!(
        "{:>8} {:>14} {:>14} {:>14} {:>10}",
        "nodes", "h_c [µm]", "h_min [µm]", "p_max [GPa]", "time [s]"
    );
    for k in 0..3 {
        println!(
            "{:>8} {:>14.6} {:>14.6} {:>14.6} {:>10.3}",
            study.nodes[k],
            study.central_film_m.values[k] * 1e6,
            study.min_film_m.values[k] * 1e6,
            study.max_pressure_pa.values[k] / 1e9,
            study.wall_time_s[k]
        );
    }
    println!(
        "{:>8} {:>14.6} {:>14.6} {:>14.6}",
        "Richardson",
        study.central_film_m.extrapolated * 1e6,
        study.min_film_m.extrapolated * 1e6,
        study.max_pressure_pa.extrapolated / 1e9
    );
    println!(
        "{:>8} {:>14.2} {:>14.2} {:>14.2}",
        "order p", study.central_film_m.order, study.min_film_m.order, study.max_pressure_pa.order
    );
    println!(
        "error vs Richardson: {} nodes h_c {:.3} %, h_min {:.3} %; {} nodes h_c {:.3} %, h_min {:.3} %",
        study.nodes[0],
        100.0 * study.central_film_m.coarse_error(),
        100.0 * study.min_film_m.coarse_error(),
        study.nodes[1],
        100.0 * study.central_film_m.middle_error(),
        100.0 * study.min_film_m.middle_error()
    );
    println!("(the default solver reports h_c, h_min extrapolated from its last two grid levels)");
    Ok(())
}

/// A failed solve of `ehl solve` is also reported on stdout as `{"converged": false,
/// "error": …}` under `--json`, so that scripts reading stdout see it; the error is returned
/// as it was.
fn failure_as_json<T>(result: Result<T>, json: bool) -> Result<T> {
    if let (Err(e), true) = (&result, json) {
        println!(
            "{}",
            serde_json::json!({"converged": false, "error": format!("{e:#}")})
        );
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;

    #[derive(Parser)]
    struct Cli {
        #[command(subcommand)]
        command: EhlCommand,
    }

    fn case_of(args: &[&str]) -> Result<ContactCase> {
        let mut argv = vec!["bearing-ehl", "solve"];
        argv.extend_from_slice(args);
        match Cli::try_parse_from(argv)?.command {
            EhlCommand::Solve(a) => a.case.case(),
            EhlCommand::Convergence(a) => a.case.case(),
            EhlCommand::Compare(_) => unreachable!("parsed as `solve`"),
        }
    }

    const SI: [&str; 14] = [
        "--load",
        "740",
        "--length",
        "0.009",
        "--entrainment",
        "5",
        "--radius",
        "0.0032",
        "--modulus",
        "2.308e11",
        "--alpha",
        "2.1e-8",
        "--eta0",
        "0.08",
    ];

    /// The SI flags build w = Q/l and the other inputs unchanged (docs/physics.md §1 definitions).
    #[test]
    fn si_flags_build_the_case() {
        let c = case_of(&SI).unwrap();
        assert!((c.load_per_length_n_per_m - 740.0 / 0.009).abs() < 1e-9);
        assert_eq!(c.viscosity_pa_s, 0.08);
    }

    /// Hostile values (NaN, inf, zero, negative) are refused naming the flag; mixing or
    /// omitting case groups is refused.
    #[test]
    fn hostile_flags_refused_with_the_flag_name() {
        for (i, flag) in SI.iter().enumerate().step_by(2) {
            for bad in ["nan", "inf", "0", "-2"] {
                if *flag == "--alpha" && bad == "0" {
                    continue; // α = 0 is a valid (iso-viscous) input
                }
                let mut args = SI;
                args[i + 1] = bad;
                let e = case_of(&args).unwrap_err().to_string();
                assert!(e.contains(&flag[2..]), "{flag}={bad}: {e}");
            }
        }
        let e = case_of(&["--m", "nan", "--l", "5"])
            .unwrap_err()
            .to_string();
        assert!(e.contains("--m = NaN"), "{e}");
        assert!(case_of(&["--m", "30"])
            .unwrap_err()
            .to_string()
            .contains("--l"));
        assert!(case_of(&["--m", "30", "--l", "5", "--w", "1e-4"]).is_err());
        assert!(case_of(&[]).is_err());
    }
}
