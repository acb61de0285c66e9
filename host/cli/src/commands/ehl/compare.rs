//! `bearing ehl compare`: the solver against Moes' or Pan–Hamrock's formula over a grid of
//! cases, one row per case (the tables of docs/ehl.md), with the grid-and-domain check of every
//! case outside the formula's bound ([`bearing_ehl::compare`]).

use crate::commands::common::positive;
use anyhow::{anyhow, Result};
use bearing_ehl::compare::{self, Comparer, Comparison, Formula};
use bearing_ehl::ContactCase;
use clap::{Args, Subcommand};

#[derive(Args, Debug)]
pub struct CompareArgs {
    #[command(subcommand)]
    formula: FormulaArgs,
    /// Machine-readable JSON output.
    #[arg(long, global = true)]
    json: bool,
}

#[derive(Subcommand, Debug)]
enum FormulaArgs {
    /// Central film against Moes' formula (Barus, incompressible), bound 5 %; default grid
    /// M ∈ {10, 30, 100, 300, 1000} × L ∈ {1, 3, 10, 20}.
    #[command(allow_negative_numbers = true)]
    Moes {
        /// Moes load parameters M (comma-separated).
        #[arg(long, value_delimiter = ',', value_parser = positive)]
        m: Vec<f64>,
        /// Moes material parameters L (comma-separated).
        #[arg(long, value_delimiter = ',', value_parser = positive)]
        l: Vec<f64>,
    },
    /// Central and minimum film against Pan & Hamrock (1989) (Roelands + Dowson–Higginson),
    /// bound 10 %; default grid W ∈ {2e-5, 5e-5, 1e-4, 2e-4} × U ∈ {1e-11, 1e-10} × G ∈
    /// {2500, 5000}, η₀ = 0.04 Pa·s.
    #[command(allow_negative_numbers = true)]
    PanHamrock {
        /// Load parameters W = w/(E'R) (comma-separated).
        #[arg(long, value_delimiter = ',', value_parser = positive)]
        w: Vec<f64>,
        /// Speed parameters U = η₀u_m/(E'R) (comma-separated).
        #[arg(long, value_delimiter = ',', value_parser = positive)]
        u: Vec<f64>,
        /// Material parameters G = αE' (comma-separated).
        #[arg(long, value_delimiter = ',', value_parser = positive)]
        g: Vec<f64>,
    },
}

/// An empty list means the default grid's.
fn or_default(given: Vec<f64>, default: Vec<f64>) -> Vec<f64> {
    if given.is_empty() {
        default
    } else {
        given
    }
}

/// Runs `bearing ehl compare …`.
pub fn run(a: CompareArgs) -> Result<()> {
    let (formula, cases) = match a.formula {
        FormulaArgs::Moes { m, l } => {
            let (dm, dl) = compare::moes_grid();
            let (m, l) = (or_default(m, dm), or_default(l, dl));
            let mut cases = Vec::new();
            for &mi in &m {
                for &li in &l {
                    cases.push(ContactCase::from_moes(mi, li).map_err(|e| anyhow!("{e}"))?);
                }
            }
            (Formula::Moes, cases)
        }
        FormulaArgs::PanHamrock { w, u, g } => {
            let (dw, du, dg) = compare::pan_hamrock_grid();
            let (w, u, g) = (or_default(w, dw), or_default(u, du), or_default(g, dg));
            let mut cases = Vec::new();
            for &wi in &w {
                for &ui in &u {
                    for &gi in &g {
                        cases.push(
                            ContactCase::from_dimensionless(wi, ui, gi)
                                .map_err(|e| anyhow!("{e}"))?,
                        );
                    }
                }
            }
            (Formula::PanHamrock, cases)
        }
    };
    let mut comparer = Comparer::new(formula).map_err(|e| anyhow!("{e}"))?;
    let bar = if a.json {
        indicatif::ProgressBar::hidden()
    } else {
        indicatif::ProgressBar::new(cases.len() as u64)
    };
    let mut rows = Vec::with_capacity(cases.len());
    for case in &cases {
        let row = comparer.compare(case).map_err(|e| {
            anyhow!(
                "W = {:e}, U = {:e}, G = {}: {e}",
                case.load_parameter(),
                case.speed_parameter(),
                case.material_parameter()
            )
        })?;
        rows.push(row);
        bar.inc(1);
    }
    bar.finish_and_clear();
    let summary = Summary::of(formula, &rows);
    if a.json {
        let v = serde_json::json!({
            "formula": formula,
            "bound": formula.bound(),
            "refined_check": {
                "nodes": compare::REFINED_NODES,
                "x_start_over_b": compare::REFINED_X_START,
                "converged_within": compare::CONVERGED_WITHIN,
            },
            "rows": rows,
            "cases": summary.cases,
            "central_within": summary.central_within,
            "min_within": summary.min_within,
            "outside_and_converged": summary.outside_and_converged,
        });
        crate::commands::common::print_json(&v)?;
    } else {
        print_table(formula, &rows, &summary);
    }
    Ok(())
}

/// Counts over the rows.
struct Summary {
    cases: usize,
    central_within: usize,
    min_within: Option<usize>,
    outside_and_converged: usize,
}

impl Summary {
    fn of(formula: Formula, rows: &[Comparison]) -> Self {
        let count = |f: &dyn Fn(&Comparison) -> bool| rows.iter().filter(|r| f(r)).count();
        Self {
            cases: rows.len(),
            central_within: count(&|r| r.central_within(formula)),
            min_within: (formula == Formula::PanHamrock).then(|| count(&|r| r.min_within(formula))),
            outside_and_converged: count(&|r| r.refined.is_some_and(|c| c.converged)),
        }
    }
}

fn print_table(formula: Formula, rows: &[Comparison], s: &Summary) {
    let bound = 100.0 * formula.bound();
    println!("{} — bound ±{bound:.0} %", formula.name());
    let min_col = formula == Formula::PanHamrock;
    print!(
        "{:>9} {:>9} {:>6} {:>8} {:>7} {:>6} {:>8}",
        "W", "U", "G", "M", "L", "nodes", "h_c"
    );
    if min_col {
        print!(" {:>8}", "h_min");
    }
    println!("   refined Δh_c, Δh_min");
    for r in rows {
        let mark = |within: bool| if within { ' ' } else { '*' };
        print!(
            "{:>9.2e} {:>9.2e} {:>6.0} {:>8.3} {:>7.3} {:>6} {:>7.3}{}",
            r.w,
            r.u,
            r.g,
            r.m,
            r.l,
            r.nodes,
            r.central_ratio,
            mark(r.central_within(formula))
        );
        if let Some(m) = r.min_ratio {
            print!(" {:>7.3}{}", m, mark(r.min_within(formula)));
        }
        if let Some(c) = r.refined {
            print!(
                "   {:+.2} %, {:+.2} %{}",
                100.0 * c.central_change,
                100.0 * c.min_change,
                if c.converged { "" } else { "  NOT converged" }
            );
        }
        println!();
    }
    println!("(ratios solver/formula; * outside ±{bound:.0} %, then solved again on {} nodes with the inlet at X = {}: Δ = default/refined − 1)", compare::REFINED_NODES, compare::REFINED_X_START);
    print!(
        "within ±{bound:.0} %: h_c {} of {}",
        s.central_within, s.cases
    );
    if let Some(m) = s.min_within {
        print!(", h_min {m} of {}", s.cases);
    }
    let outside = rows.iter().filter(|r| r.refined.is_some()).count();
    println!(
        "; outside the bound and converged within {:.0} %: {} of {outside}",
        100.0 * compare::CONVERGED_WITHIN,
        s.outside_and_converged
    );
}
