//! Deterministic, parallel, resumable dataset generation over any film solver.
//!
//! The design is a pure function of `(n, seed, domain)` ([`plan`]): a maximin Latin hypercube
//! of `m ≥ n` points over the input box, mapped to contacts, of which the first `n` inside the
//! Hertz window and regime are kept (in design order). `m` starts from the feasible fraction
//! of a seeded pilot sample and grows by 25 % until `n` contacts are feasible, so the design
//! stays a Latin hypercube over the box and the constraints only cut it.
//! [`plan`] takes any [`SamplingDomain`] and [`generate`] any [`DatasetContact`] (the line
//! contact's, the point contact's).
//!
//! Cases are solved in chunks with rayon; each chunk is appended in index order and flushed, so
//! an uninterrupted run writes byte-identical files for a deterministic solver, and an
//! interrupted run resumes from the records already written.

use std::io::Write;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::Path;

use anyhow::{bail, Context, Result};
use indicatif::{ProgressBar, ProgressStyle};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;

use super::file::{
    header_line, record_line, Dataset, DatasetContact, Metadata, Record, SolvedFilms, SolverInfo,
    FORMAT_VERSION,
};
use super::lhs::maximin_lhs;
use super::point_domain::PointDomain;
use super::{ContactCase, Domain};
use bearing_ehl::point::PointContactCase;

/// What to generate.
#[derive(Clone, Debug)]
pub struct GenerateOptions<C: DatasetContact = ContactCase> {
    /// Number of feasible cases.
    pub n: usize,
    /// Seed of the design.
    pub seed: u64,
    /// Sampling domain.
    pub domain: C::Domain,
    /// Solver description stored in the header.
    pub solver: SolverInfo,
    /// Command line stored in the header.
    pub command: String,
    /// Draw a progress bar on stderr.
    pub progress: bool,
    /// Cases per written chunk.
    pub chunk: usize,
}

/// A sampling domain over seven inputs: the map from the unit cube to cases and the feasibility
/// test that cuts the design (the line contact's [`Domain`], the point contact's
/// [`PointDomain`]).
pub trait SamplingDomain {
    /// The case type.
    type Case;
    /// The case at unit-cube point `t`.
    fn case_at(&self, t: &[f64; 7]) -> Self::Case;
    /// Whether `case` satisfies the domain's constraints.
    fn feasible(&self, case: &Self::Case) -> bool;
}

impl SamplingDomain for Domain {
    type Case = ContactCase;
    fn case_at(&self, t: &[f64; 7]) -> ContactCase {
        Domain::case_at(self, t)
    }
    fn feasible(&self, case: &ContactCase) -> bool {
        self.check(case).is_ok()
    }
}

impl SamplingDomain for PointDomain {
    type Case = PointContactCase;
    fn case_at(&self, t: &[f64; 7]) -> PointContactCase {
        PointDomain::case_at(self, t)
    }
    fn feasible(&self, case: &PointContactCase) -> bool {
        self.check(case).is_ok()
    }
}

/// The planned cases and the design they come from.
#[derive(Clone, Debug, PartialEq)]
pub struct Plan<C = ContactCase> {
    /// The `n` feasible cases, in design order.
    pub cases: Vec<C>,
    /// Points of the full design.
    pub design_points: usize,
    /// Smallest distance in the unit cube.
    pub design_min_distance: f64,
}

/// Summary of a generation run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Summary {
    /// Records already in the file before this run.
    pub resumed: usize,
    /// Records written by this run.
    pub written: usize,
    /// Failed cases in the whole file.
    pub failed: usize,
}

/// The deterministic design of `n` feasible cases (see the module doc).
pub fn plan<D: SamplingDomain>(n: usize, seed: u64, domain: &D) -> Plan<D::Case> {
    // Pilot: feasible fraction of 4000 uniform points (own stream derived from the seed).
    let mut rng = ChaCha8Rng::seed_from_u64(seed ^ 0x9e37_79b9_7f4a_7c15);
    let pilot = 4000;
    let feasible = (0..pilot)
        .filter(|_| {
            let t: [f64; 7] = std::array::from_fn(|_| rng.random::<f64>());
            domain.feasible(&domain.case_at(&t))
        })
        .count()
        .max(1);
    let fraction = feasible as f64 / pilot as f64;
    let mut m = ((n as f64 / fraction) * 1.1).ceil() as usize + 8;
    loop {
        let design = maximin_lhs::<7>(m, seed, None);
        let cases: Vec<D::Case> = design
            .points
            .iter()
            .map(|t| domain.case_at(t))
            .filter(|c| domain.feasible(c))
            .take(n)
            .collect();
        if cases.len() == n {
            return Plan {
                cases,
                design_points: m,
                design_min_distance: design.min_distance(),
            };
        }
        m = m + m / 4 + 1;
    }
}

/// Run `solver` on one case, turning errors, panics and non-physical films into a failure
/// reason.
fn solve_one<C, F>(solver: &F, index: usize, case: &C) -> Record<C>
where
    C: DatasetContact,
    F: Fn(&C) -> Result<C::Films, String> + Sync,
{
    let outcome = match catch_unwind(AssertUnwindSafe(|| solver(case))) {
        Ok(Ok(films)) => {
            let (c, m) = films.central_minimum();
            if c.is_finite() && m.is_finite() && c > 0.0 && m > 0.0 {
                Ok(films)
            } else {
                Err(format!(
                    "solver returned a non-physical film: h_c = {c:e} m, h_min = {m:e} m"
                ))
            }
        }
        Ok(Err(reason)) => Err(reason),
        Err(panic) => Err(format!(
            "solver panicked: {}",
            panic
                .downcast_ref::<String>()
                .cloned()
                .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
                .unwrap_or_default()
        )),
    };
    let (films, error) = match outcome {
        Ok(films) => (Some(films), None),
        Err(e) => (None, Some(e)),
    };
    Record {
        index,
        case: case.clone(),
        groups: case.groups(),
        films,
        error,
    }
}

/// Generate (or resume) the dataset at `path`.
pub fn generate<C, F>(path: &Path, options: &GenerateOptions<C>, solver: F) -> Result<Summary>
where
    C: DatasetContact,
    F: Fn(&C) -> Result<C::Films, String> + Sync,
{
    if options.n == 0 {
        bail!("--n must be at least 1");
    }
    let plan = plan(options.n, options.seed, &options.domain);
    let metadata = Metadata::<C> {
        format: C::FORMAT_NAME.into(),
        format_version: FORMAT_VERSION,
        seed: options.seed,
        n: options.n,
        domain: options.domain,
        solver: options.solver.clone(),
        design_points: plan.design_points,
        design_min_distance: plan.design_min_distance,
        command: options.command.clone(),
    };
    let mut done = vec![false; options.n];
    let mut resumed = 0;
    let mut failed = 0;
    let mut file = if path.exists() {
        let existing = Dataset::<C>::load(path)?;
        let m = &existing.metadata;
        if m.seed != metadata.seed
            || m.n != metadata.n
            || m.domain != metadata.domain
            || m.solver != metadata.solver
        {
            bail!(
                "{} was made with other settings (seed {}, n {}, solver {} {}); refusing to resume into it",
                path.display(),
                m.seed,
                m.n,
                m.solver.name,
                m.solver.version
            );
        }
        for r in &existing.records {
            match (done.get_mut(r.index), plan.cases.get(r.index)) {
                (Some(slot), Some(case)) if *case == r.case => *slot = true,
                _ => bail!(
                    "{}: record {} does not belong to this design",
                    path.display(),
                    r.index
                ),
            }
            failed += usize::from(r.error.is_some());
        }
        resumed = existing.records.len();
        let f = std::fs::OpenOptions::new().write(true).open(path)?;
        f.set_len(existing.valid_len)?; // drop a partial last line
        let mut f = f;
        std::io::Seek::seek(&mut f, std::io::SeekFrom::End(0))?;
        f
    } else {
        let mut f =
            std::fs::File::create(path).with_context(|| format!("creating {}", path.display()))?;
        f.write_all(header_line(&metadata)?.as_bytes())?;
        f
    };
    let todo: Vec<usize> = (0..options.n).filter(|&i| !done[i]).collect();
    let bar = if options.progress {
        ProgressBar::new(options.n as u64)
    } else {
        ProgressBar::hidden()
    };
    bar.set_style(
        ProgressStyle::with_template(
            "{spinner} [{elapsed_precise}] {wide_bar} {pos}/{len} cases, eta {eta}",
        )
        .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    bar.set_position(resumed as u64);
    let mut written = 0;
    for chunk in todo.chunks(options.chunk.max(1)) {
        let records: Vec<Record<C>> = chunk
            .par_iter()
            .map(|&i| {
                let r = solve_one(&solver, i, &plan.cases[i]);
                bar.inc(1);
                r
            })
            .collect();
        let mut text = String::new();
        for r in &records {
            failed += usize::from(r.error.is_some());
            text.push_str(&record_line(r)?);
        }
        file.write_all(text.as_bytes())?;
        file.flush()?;
        written += records.len();
    }
    bar.finish_and_clear();
    Ok(Summary {
        resumed,
        written,
        failed,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dataset::file::LineFilms;
    use crate::dataset::moes_solver;

    fn options(n: usize) -> GenerateOptions {
        GenerateOptions {
            n,
            seed: 7,
            domain: Domain::default(),
            solver: SolverInfo {
                name: "moes".into(),
                version: "test".into(),
                options: serde_json::Value::Null,
            },
            command: "test".into(),
            progress: false,
            chunk: 8,
        }
    }

    /// Every planned case satisfies the domain constraints, and the plan is deterministic.
    #[test]
    fn plan_is_feasible_and_deterministic() {
        let domain = Domain::default();
        let a = plan(60, 7, &domain);
        assert_eq!(a.cases.len(), 60);
        assert!(a.cases.iter().all(|c| domain.check(c).is_ok()));
        assert_eq!(a, plan(60, 7, &domain));
    }

    /// The point-contact domain plans the same way: every planned case feasible, the design
    /// oversampled to cover the cut, and the plan deterministic.
    #[test]
    fn point_plan_is_feasible_and_deterministic() {
        let domain = PointDomain::default();
        let a = plan(40, 7, &domain);
        assert_eq!(a.cases.len(), 40);
        assert!(a.cases.iter().all(|c| domain.check(c).is_ok()));
        assert!(a.design_points > 40 && a.design_min_distance > 0.0);
        assert_eq!(a, plan(40, 7, &domain));
    }

    /// An interrupted run (a prefix plus half a line) resumes to the same file as an
    /// uninterrupted one; a failing case is recorded with its reason, not dropped.
    #[test]
    fn resume_reproduces_the_uninterrupted_file() {
        let dir = std::env::temp_dir().join(format!("bearing-dataset-test-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let full = dir.join("full.jsonl");
        let part = dir.join("part.jsonl");
        let _ = std::fs::remove_file(&full);
        let _ = std::fs::remove_file(&part);
        // A solver that refuses one specific case, to exercise failure records.
        let solver = |c: &ContactCase| {
            if c.load_n < 300.0 {
                Err("refused: load below 300 N".to_string())
            } else {
                moes_solver(c).map(LineFilms::from)
            }
        };
        let opts = options(40);
        let s = generate(&full, &opts, solver).unwrap();
        assert_eq!((s.resumed, s.written), (0, 40));
        let text = std::fs::read_to_string(&full).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        // Cut after 17 records and half of the 18th.
        let mut cut: String = lines[..18].iter().map(|l| format!("{l}\n")).collect();
        cut.push_str(&lines[18][..lines[18].len() / 2]);
        std::fs::write(&part, cut).unwrap();
        let s = generate(&part, &opts, solver).unwrap();
        assert_eq!((s.resumed, s.written), (17, 23));
        assert_eq!(std::fs::read_to_string(&part).unwrap(), text);
        let data = Dataset::<ContactCase>::load(&full).unwrap();
        let refused = data
            .records
            .iter()
            .filter(|r| r.case.load_n < 300.0)
            .count();
        assert!(refused > 0, "the design should contain loads below 300 N");
        assert_eq!(s.failed, refused);
        assert!(data
            .records
            .iter()
            .filter(|r| r.error.is_some())
            .all(|r| r.error.as_deref() == Some("refused: load below 300 N")));
        // Different settings are refused.
        let mut other = opts.clone();
        other.seed = 8;
        assert!(generate(&full, &other, solver).is_err());
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
