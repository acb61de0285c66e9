//! `cargo xtask test`: the set-up (`setup`), then every test of the workspace
//! (`cargo test --workspace --release --no-fail-fast`, the Python interpreter handed over in
//! `BEARING_PYTHON`), then the docs' figure checks; one closing line with the totals over every
//! test binary. Exits non-zero when a test fails, a prerequisite is missing or a build fails:
//! it never passes by leaving a test out.

use std::io::{BufRead, BufReader, Write};
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::Instant;

use anyhow::{bail, Result};

use crate::doc_figures;
use crate::setup::{self, PYTHON_VAR};

#[derive(clap::Args)]
pub struct TestArgs {
    /// Leave out the docs' figure checks (`cargo xtask doc-figures`).
    #[arg(long)]
    no_doc_figures: bool,
    /// Arguments for `cargo test` after `--` (e.g. `-p bearing-core`; the default is the
    /// whole workspace).
    #[arg(last = true)]
    cargo_args: Vec<String>,
}

/// Passed and failed tests, summed over `test result:` lines.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Totals {
    pub passed: usize,
    pub failed: usize,
    pub ignored: usize,
}

impl Totals {
    /// Adds the counts of one libtest summary line
    /// (`test result: ok. 7 passed; 0 failed; 1 ignored; 0 measured; 0 filtered out; …`).
    pub fn add_line(&mut self, line: &str) -> bool {
        let Some(rest) = line.trim_start().strip_prefix("test result:") else {
            return false;
        };
        let words: Vec<&str> = rest.split_whitespace().collect();
        for pair in words.windows(2) {
            let count = pair[0].parse::<usize>();
            match (count, pair[1].trim_end_matches([';', ','])) {
                (Ok(n), "passed") => self.passed += n,
                (Ok(n), "failed") => self.failed += n,
                (Ok(n), "ignored") => self.ignored += n,
                _ => {}
            }
        }
        true
    }
}

/// Runs `cargo test` with the Python interpreter, echoing its output; returns the totals, the
/// names of the failed tests and whether cargo succeeded.
fn cargo_test(
    root: &Path,
    python: Option<&Path>,
    cargo_args: &[String],
) -> Result<(Totals, Vec<String>, bool)> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut command = Command::new(cargo);
    command
        .current_dir(root)
        .args(["test", "--release", "--no-fail-fast"])
        .stdout(Stdio::piped());
    if cargo_args.is_empty() {
        command.arg("--workspace");
    } else {
        command.args(cargo_args);
    }
    match python {
        Some(p) => command.env(PYTHON_VAR, p),
        None => command.env_remove(PYTHON_VAR),
    };
    let what = if cargo_args.is_empty() {
        "--workspace".to_string()
    } else {
        cargo_args.join(" ")
    };
    eprintln!("\n==> cargo test --release --no-fail-fast {what}");
    let mut child = command.spawn()?;
    let mut totals = Totals::default();
    let mut failed_tests = Vec::new();
    let stdout = child.stdout.take().expect("piped");
    let mut out = std::io::stdout().lock();
    for line in BufReader::new(stdout).lines() {
        let line = line?;
        writeln!(out, "{line}")?;
        totals.add_line(&line);
        if let Some(name) = line
            .strip_prefix("test ")
            .and_then(|l| l.strip_suffix(" ... FAILED"))
        {
            failed_tests.push(name.to_string());
        }
    }
    let status = child.wait()?;
    Ok((totals, failed_tests, status.success()))
}

pub fn run(root: &Path, args: &TestArgs) -> Result<()> {
    let started = Instant::now();
    eprintln!("==> prerequisites");
    let setup = setup::run(root, false)?;
    let (mut totals, mut failed_tests, cargo_ok) =
        cargo_test(root, setup.python.as_deref(), &args.cargo_args)?;
    let mut doc_figures_ok = true;
    if !args.no_doc_figures {
        eprintln!("\n==> the docs' figures (cargo xtask doc-figures)");
        let args = doc_figures::Args {
            no_build: true,
            ..doc_figures::Args::default()
        };
        match doc_figures::run(root, &args) {
            Ok(result) => {
                totals.passed += result.passed;
                totals.failed += result.failed.len();
                failed_tests.extend(result.failed);
            }
            Err(e) => {
                eprintln!("doc figures: {e:#}");
                doc_figures_ok = false;
            }
        }
    }
    eprintln!();
    if !failed_tests.is_empty() {
        eprintln!("failed tests:");
        for name in &failed_tests {
            eprintln!("  {name}");
        }
    }
    if !cargo_ok && totals.failed == 0 {
        eprintln!("cargo test failed before running every test (a build error: see above)");
    }
    setup::report_missing(&setup.missing);
    eprintln!(
        "{} tests ignored (run by hand: generators and long studies); {:.0} s in all",
        totals.ignored,
        started.elapsed().as_secs_f64()
    );
    // The closing line CI reads: `N passed, N failed` alone on the line, after one word.
    println!("tests: {} passed, {} failed", totals.passed, totals.failed);
    if totals.failed > 0 || !cargo_ok || !doc_figures_ok || !setup.missing.is_empty() {
        bail!(
            "not every test passed{}",
            if setup.missing.is_empty() {
                ""
            } else {
                " (prerequisites missing, above)"
            }
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::Totals;

    #[test]
    fn totals_sum_libtest_summaries() {
        let mut t = Totals::default();
        assert!(t.add_line(
            "test result: ok. 7 passed; 0 failed; 1 ignored; 0 measured; 0 filtered out; finished in 0.1s"
        ));
        assert!(t.add_line(
            "test result: FAILED. 2 passed; 1 failed; 0 ignored; 0 measured; 0 filtered out; finished in 6s"
        ));
        assert!(!t.add_line("test foo ... ok"));
        assert_eq!(
            t,
            Totals {
                passed: 9,
                failed: 1,
                ignored: 1
            }
        );
    }
}
