//! The dataset file: JSON lines. Line 1 is `{"metadata": …}` (format version, seed, requested
//! size, domain, solver name/version/options, design statistics, the command); every further
//! line is one [`Record`] — a solved case with its films, or a failed case with its reason.
//!
//! Records are appended in index order chunk by chunk, so an interrupted run leaves a valid
//! prefix (plus at most one partial line, which [`Dataset::load`] ignores and generation
//! truncates away before resuming).

use std::io::{BufRead, BufReader};
use std::path::Path;

use anyhow::{bail, Context, Result};
use serde::{Deserialize, Serialize};

use super::{ContactCase, Domain};

/// Name written in the header so that other JSON-lines files are refused.
pub const FORMAT_NAME: &str = "bearing-film-dataset";
/// Version of the file layout.
pub const FORMAT_VERSION: u32 = 1;

/// Which solver made the films, and how.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SolverInfo {
    /// `"numerical"` or `"moes"`.
    pub name: String,
    /// Solver version (crate version plus solver revision).
    pub version: String,
    /// Solver options as the solver serialises them.
    pub options: serde_json::Value,
}

/// File header.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Metadata {
    /// Always [`FORMAT_NAME`].
    pub format: String,
    /// Always [`FORMAT_VERSION`].
    pub format_version: u32,
    /// Seed of the Latin hypercube.
    pub seed: u64,
    /// Number of cases requested.
    pub n: usize,
    /// Sampling domain.
    pub domain: Domain,
    /// Solver that produced the films.
    pub solver: SolverInfo,
    /// Points of the (oversampled) hypercube before the domain constraints were applied.
    pub design_points: usize,
    /// Smallest distance between design points in the unit cube.
    pub design_min_distance: f64,
    /// Command line that created the file.
    pub command: String,
}

/// One case and its outcome.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Record {
    /// Position of the case in the design (0-based, unique).
    pub index: usize,
    /// The contact.
    pub case: ContactCase,
    /// Central film h_c (m), when solved.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub central_m: Option<f64>,
    /// Minimum film h_min (m), when solved.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub minimum_m: Option<f64>,
    /// Why the case failed, when it did.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
}

impl Record {
    /// `(h_c, h_min)` of a solved case.
    pub fn films(&self) -> Option<(f64, f64)> {
        match (self.central_m, self.minimum_m, &self.error) {
            (Some(c), Some(m), None) => Some((c, m)),
            _ => None,
        }
    }
}

#[derive(Serialize, Deserialize)]
struct HeaderLine {
    metadata: Metadata,
}

/// A loaded dataset.
#[derive(Clone, Debug, PartialEq)]
pub struct Dataset {
    /// The header.
    pub metadata: Metadata,
    /// Records sorted by index.
    pub records: Vec<Record>,
    /// Byte length of the valid prefix (header and complete record lines).
    pub valid_len: u64,
}

impl Dataset {
    /// Read a dataset file; a partial last line (an interrupted write) is ignored.
    pub fn load(path: &Path) -> Result<Self> {
        let file = std::fs::File::open(path)
            .with_context(|| format!("opening dataset {}", path.display()))?;
        let mut reader = BufReader::new(file);
        let mut line = String::new();
        let mut valid_len = 0u64;
        let n = reader.read_line(&mut line)?;
        if n == 0 || !line.ends_with('\n') {
            bail!("{}: no complete metadata line", path.display());
        }
        let header: HeaderLine = serde_json::from_str(&line).with_context(|| {
            format!(
                "{}: line 1 is not a dataset metadata header",
                path.display()
            )
        })?;
        if header.metadata.format != FORMAT_NAME || header.metadata.format_version != FORMAT_VERSION
        {
            bail!(
                "{}: format {} v{} (expected {FORMAT_NAME} v{FORMAT_VERSION})",
                path.display(),
                header.metadata.format,
                header.metadata.format_version
            );
        }
        valid_len += n as u64;
        let mut records = Vec::new();
        let mut line_no = 1;
        loop {
            line.clear();
            let n = reader.read_line(&mut line)?;
            line_no += 1;
            if n == 0 || !line.ends_with('\n') {
                break; // end, or a partial last line from an interrupted run
            }
            let record: Record = serde_json::from_str(&line)
                .with_context(|| format!("{}: line {line_no} is not a record", path.display()))?;
            valid_len += n as u64;
            records.push(record);
        }
        records.sort_by_key(|r| r.index);
        if records.windows(2).any(|w| w[0].index == w[1].index) {
            bail!("{}: duplicate record index", path.display());
        }
        Ok(Self {
            metadata: header.metadata,
            records,
            valid_len,
        })
    }

    /// Solved records only.
    pub fn solved(&self) -> impl Iterator<Item = (&ContactCase, (f64, f64))> {
        self.records
            .iter()
            .filter_map(|r| r.films().map(|f| (&r.case, f)))
    }
}

/// The header line (with its newline).
pub fn header_line(metadata: &Metadata) -> Result<String> {
    let mut s = serde_json::to_string(&HeaderLine {
        metadata: metadata.clone(),
    })?;
    s.push('\n');
    Ok(s)
}

/// One record line (with its newline).
pub fn record_line(record: &Record) -> Result<String> {
    let mut s = serde_json::to_string(record)?;
    s.push('\n');
    Ok(s)
}
