//! The dataset file: JSON lines. Line 1 is `{"metadata": …}` (format name and version, seed,
//! requested size, domain, solver name/version/options, design statistics, the command); every
//! further line is one [`Record`] — a solved case with its films, or a failed case with its
//! reason. The contact type ([`DatasetContact`]: the line contact's [`ContactCase`], the point
//! contact's [`PointContactCase`]) fixes the format name, the domain, the per-row groups and
//! the films a row carries.
//!
//! Records are appended in index order chunk by chunk, so an interrupted run leaves a valid
//! prefix (plus at most one partial line, which [`Dataset::load`] ignores and generation
//! truncates away before resuming).

use std::fmt::Debug;
use std::io::{BufRead, BufReader};
use std::path::Path;

use anyhow::{bail, Context, Result};
use bearing_ehl::point::PointContactCase;
use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};

use super::generate::SamplingDomain;
use super::point_domain::PointDomain;
use super::point_numerical::PointFilms;
use super::{ContactCase, Domain};

/// Format name of a line-contact dataset, written in the header so that other JSON-lines files
/// are refused.
pub const FORMAT_NAME: &str = "bearing-film-dataset";
/// Format name of a point-contact dataset.
pub const POINT_FORMAT_NAME: &str = "bearing-point-film-dataset";
/// Version of the file layout.
pub const FORMAT_VERSION: u32 = 1;

/// The films of a solved row: `(h_c, h_min)` in metres, the training targets.
pub trait SolvedFilms {
    /// `(h_c, h_min)`, m.
    fn central_minimum(&self) -> (f64, f64);
}

/// A contact type a dataset holds: its sampling domain, the films its solver returns, the
/// groups derived from the case and written on every row, and the file's format name.
pub trait DatasetContact:
    Clone + PartialEq + Debug + Serialize + DeserializeOwned + Send + Sync
{
    /// Sampling domain (stored in the header).
    type Domain: SamplingDomain<Case = Self>
        + Copy
        + PartialEq
        + Debug
        + Serialize
        + DeserializeOwned
        + Send
        + Sync;
    /// Films of a solved row (flattened into the row).
    type Films: SolvedFilms + Clone + PartialEq + Debug + Serialize + DeserializeOwned + Send;
    /// Dimensionless groups of the case (flattened into every row).
    type Groups: Clone + PartialEq + Debug + Serialize + DeserializeOwned + Send;
    /// Format name in the header.
    const FORMAT_NAME: &'static str;
    /// The groups of this case.
    fn groups(&self) -> Self::Groups;
}

/// `(h_c, h_min)` of a solved line contact, m.
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct LineFilms {
    /// Central film h_c, m.
    pub central_m: f64,
    /// Minimum film h_min, m.
    pub minimum_m: f64,
}

impl From<(f64, f64)> for LineFilms {
    fn from((central_m, minimum_m): (f64, f64)) -> Self {
        Self {
            central_m,
            minimum_m,
        }
    }
}

impl SolvedFilms for LineFilms {
    fn central_minimum(&self) -> (f64, f64) {
        (self.central_m, self.minimum_m)
    }
}

impl SolvedFilms for PointFilms {
    fn central_minimum(&self) -> (f64, f64) {
        (self.central_m, self.minimum_m)
    }
}

/// No per-row groups (the line contact's rows carry the inputs and films only).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct NoGroups {}

/// Moes' point-contact groups and the ellipticity of a point case (docs/point_contact.md).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct PointGroups {
    /// M = W(2U)^−¾.
    pub moes_m: f64,
    /// L = G(2U)^¼.
    pub moes_l: f64,
    /// Ellipticity k = a/b of the Hertz contact.
    pub ellipticity: f64,
}

impl DatasetContact for ContactCase {
    type Domain = Domain;
    type Films = LineFilms;
    type Groups = NoGroups;
    const FORMAT_NAME: &'static str = FORMAT_NAME;
    fn groups(&self) -> NoGroups {
        NoGroups {}
    }
}

impl DatasetContact for PointContactCase {
    type Domain = PointDomain;
    type Films = PointFilms;
    type Groups = PointGroups;
    const FORMAT_NAME: &'static str = POINT_FORMAT_NAME;
    fn groups(&self) -> PointGroups {
        PointGroups {
            moes_m: self.moes_m(),
            moes_l: self.moes_l(),
            ellipticity: self.hertz().ellipticity,
        }
    }
}

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
#[serde(bound = "C: DatasetContact")]
pub struct Metadata<C: DatasetContact = ContactCase> {
    /// Always `C::FORMAT_NAME`.
    pub format: String,
    /// Always [`FORMAT_VERSION`].
    pub format_version: u32,
    /// Seed of the Latin hypercube.
    pub seed: u64,
    /// Number of cases requested.
    pub n: usize,
    /// Sampling domain.
    pub domain: C::Domain,
    /// Solver that produced the films.
    pub solver: SolverInfo,
    /// Points of the (oversampled) hypercube before the domain constraints were applied.
    pub design_points: usize,
    /// Smallest distance between design points in the unit cube.
    pub design_min_distance: f64,
    /// Command line that created the file.
    pub command: String,
}

/// One case and its outcome: the case, its groups, and its films or the reason it failed.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
#[serde(bound = "C: DatasetContact")]
pub struct Record<C: DatasetContact = ContactCase> {
    /// Position of the case in the design (0-based, unique).
    pub index: usize,
    /// The contact.
    pub case: C,
    /// Dimensionless groups of the case.
    #[serde(flatten)]
    pub groups: C::Groups,
    /// The films, when solved (flattened: `central_m`, `minimum_m`, …).
    #[serde(flatten)]
    pub films: Option<C::Films>,
    /// Why the case failed, when it did.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
}

impl<C: DatasetContact> Record<C> {
    /// `(h_c, h_min)` of a solved case.
    pub fn films(&self) -> Option<(f64, f64)> {
        match (&self.films, &self.error) {
            (Some(f), None) => Some(f.central_minimum()),
            _ => None,
        }
    }
}

#[derive(Serialize, Deserialize)]
#[serde(bound = "C: DatasetContact")]
struct HeaderLine<C: DatasetContact> {
    metadata: Metadata<C>,
}

/// A loaded dataset.
#[derive(Clone, Debug, PartialEq)]
pub struct Dataset<C: DatasetContact = ContactCase> {
    /// The header.
    pub metadata: Metadata<C>,
    /// Records sorted by index.
    pub records: Vec<Record<C>>,
    /// Byte length of the valid prefix (header and complete record lines).
    pub valid_len: u64,
}

impl<C: DatasetContact> Dataset<C> {
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
        // The format name first, so that a dataset of the other contact is refused by name.
        let format: FormatLine = serde_json::from_str(&line).with_context(|| {
            format!(
                "{}: line 1 is not a dataset metadata header",
                path.display()
            )
        })?;
        if format.metadata.format != C::FORMAT_NAME
            || format.metadata.format_version != FORMAT_VERSION
        {
            bail!(
                "{}: line 1, field metadata.format: {} v{} (expected {} v{FORMAT_VERSION})",
                path.display(),
                format.metadata.format,
                format.metadata.format_version,
                C::FORMAT_NAME
            );
        }
        let header: HeaderLine<C> = serde_json::from_str(&line).with_context(|| {
            format!(
                "{}: line 1 is not a dataset metadata header",
                path.display()
            )
        })?;
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
            let record: Record<C> = serde_json::from_str(&line)
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
    pub fn solved(&self) -> impl Iterator<Item = (&C, (f64, f64))> {
        self.records
            .iter()
            .filter_map(|r| r.films().map(|f| (&r.case, f)))
    }
}

#[derive(Deserialize)]
struct FormatOnly {
    format: String,
    format_version: u32,
}

#[derive(Deserialize)]
struct FormatLine {
    metadata: FormatOnly,
}

/// The header line (with its newline).
pub fn header_line<C: DatasetContact>(metadata: &Metadata<C>) -> Result<String> {
    let mut s = serde_json::to_string(&HeaderLine {
        metadata: metadata.clone(),
    })?;
    s.push('\n');
    Ok(s)
}

/// One record line (with its newline).
pub fn record_line<C: DatasetContact>(record: &Record<C>) -> Result<String> {
    let mut s = serde_json::to_string(record)?;
    s.push('\n');
    Ok(s)
}
