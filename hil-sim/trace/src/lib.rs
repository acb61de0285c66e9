//! Traces: recorded kinematics of one bearing, replayed sample by sample.
//!
//! A trace is what the shaft simulator (or a test rig) records at the bearing: for each instant
//! the shaft speed and the inner race's displacement and velocity in both radial directions,
//! optionally its tilt, at a fixed sample rate, together with the bearing and lubricant it was
//! recorded for. The replay engine and the firmware feed those samples to the bearing step.
//!
//! Two file forms: CSV ([`csv`], for people and spreadsheets; the header names the units) and a
//! compact little-endian binary ([`wire`] describes the layout; [`binary`] reads and writes whole
//! files), which is what the firmware streams. Both pass through the same checks
//! ([`validate`]): finite numbers, strictly increasing time, no gaps, valid identifiers and rate.
//! Every error says where (line and column, or record and field, or byte offset) and what.
//!
//! A crate of its own (`bearing-trace`, re-exported by hil-sim as `bearing_hil::trace`) so that
//! the fuzz targets of the decoders build without the harness's solver and plots.

pub mod binary;
pub mod csv;
pub mod synthetic;
pub mod validate;

pub use bearing_hil_kernel::{crc32, wire};

use std::fmt;
use std::path::Path;

pub use validate::{ValidationOptions, MAX_SAMPLE_RATE_HZ, MIN_SAMPLE_RATE_HZ};
pub use wire::Sample;

/// What a trace was recorded for and how fast.
#[derive(Clone, Debug, PartialEq)]
pub struct TraceMeta {
    /// Bearing identifier (`[A-Za-z0-9_.-]`, 1–16 characters), e.g. `hub_motor`, `nu205`.
    pub bearing: String,
    /// Lubricant identifier, same alphabet.
    pub lubricant: String,
    /// Sample rate, f (Hz); consecutive samples are 1/f apart.
    pub sample_rate_hz: f64,
}

/// A whole trace in memory.
#[derive(Clone, Debug, PartialEq)]
pub struct Trace {
    /// Bearing, lubricant and rate.
    pub meta: TraceMeta,
    /// The samples, in time order.
    pub samples: Vec<Sample>,
}

/// Where in a file an error was found.
#[derive(Clone, Debug, PartialEq)]
pub enum Location {
    /// The file as a whole (e.g. a missing header line).
    File,
    /// A CSV line (1-based), optionally a column (1-based) with its name.
    Line {
        /// Line number, from 1.
        line: usize,
        /// Column number from 1 and the column's name, when the problem is in one field.
        column: Option<(usize, String)>,
    },
    /// A binary record (0-based index), optionally a field.
    Record {
        /// Record index, from 0.
        index: usize,
        /// Field name, when the problem is in one field.
        field: Option<&'static str>,
    },
    /// A byte offset in a binary file.
    Byte(usize),
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Location::File => write!(f, "file"),
            Location::Line { line, column: None } => write!(f, "line {line}"),
            Location::Line {
                line,
                column: Some((column, name)),
            } => write!(f, "line {line}, column {column} ({name})"),
            Location::Record { index, field: None } => write!(f, "record {index}"),
            Location::Record {
                index,
                field: Some(name),
            } => write!(f, "record {index}, field {name}"),
            Location::Byte(offset) => write!(f, "byte {offset}"),
        }
    }
}

/// What is wrong.
#[derive(Clone, Debug, PartialEq)]
pub enum Problem {
    /// A value is NaN or infinite.
    NotFinite {
        /// The text or value found.
        found: String,
    },
    /// A field is not a number at all.
    NotANumber {
        /// The text found.
        found: String,
    },
    /// Time does not increase from the previous sample.
    NonIncreasingTime {
        /// Previous time (s).
        previous_s: f64,
        /// This time (s).
        time_s: f64,
    },
    /// The time step differs from 1/rate by more than the tolerance.
    Gap {
        /// Step found (s).
        step_s: f64,
        /// Step the rate implies (s).
        expected_s: f64,
        /// Allowed relative deviation.
        tolerance: f64,
    },
    /// A data line has the wrong number of fields.
    FieldCount {
        /// Fields found.
        found: usize,
        /// Fields the header names.
        expected: usize,
    },
    /// The CSV header line or a metadata line is wrong.
    BadHeader(String),
    /// Metadata (rate, identifiers) is missing or out of range.
    BadMeta(String),
    /// The trace holds no samples.
    Empty,
    /// The binary layout is broken (magic, version, checksums, length, count).
    Binary(wire::DecodeError),
    /// The file could not be read or written.
    Io(String),
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use wire::DecodeError as D;
        match self {
            Problem::NotFinite { found } => {
                write!(f, "not a finite number: {found} (NaN and infinity are refused)")
            }
            Problem::NotANumber { found } => write!(f, "not a number: {found:?}"),
            Problem::NonIncreasingTime { previous_s, time_s } => write!(
                f,
                "time {time_s} s does not increase from the previous sample's {previous_s} s"
            ),
            Problem::Gap {
                step_s,
                expected_s,
                tolerance,
            } => write!(
                f,
                "gap: time step {step_s} s differs from 1/rate = {expected_s} s by more than {:.3} %",
                tolerance * 100.0
            ),
            Problem::FieldCount { found, expected } => {
                write!(f, "{found} fields, the header names {expected}")
            }
            Problem::BadHeader(what) => write!(f, "bad header: {what}"),
            Problem::BadMeta(what) => write!(f, "bad metadata: {what}"),
            Problem::Empty => write!(f, "the trace holds no samples"),
            Problem::Binary(D::Truncated { expected, actual }) => write!(
                f,
                "truncated: the layout needs {expected} bytes, the file has {actual}"
            ),
            Problem::Binary(D::BadMagic) => {
                write!(f, "not a binary trace (the first 8 bytes are not \"BRGTRACE\")")
            }
            Problem::Binary(D::UnsupportedVersion(v)) => write!(
                f,
                "format version {v} is not supported (this reader knows version {})",
                wire::VERSION
            ),
            Problem::Binary(D::UnknownFlags(flags)) => {
                write!(f, "unknown flag bits {flags:#06x} (only bit 0, tilt, is defined)")
            }
            Problem::Binary(D::HeaderChecksum { stored, computed }) => write!(
                f,
                "header checksum mismatch: stored {stored:#010x}, computed {computed:#010x}"
            ),
            Problem::Binary(D::PayloadChecksum { stored, computed }) => write!(
                f,
                "record checksum mismatch: stored {stored:#010x}, computed {computed:#010x}"
            ),
            Problem::Binary(D::CountMismatch { header, found }) => write!(
                f,
                "count mismatch: the header states {header} records, the file holds {found}"
            ),
            Problem::Binary(D::BadSampleRate) => {
                write!(f, "sample rate is not a finite positive number")
            }
            Problem::Binary(D::BadIdentifier { which }) => write!(
                f,
                "{which} identifier must be 1-16 characters of [A-Za-z0-9_.-], zero-padded"
            ),
            Problem::Io(what) => write!(f, "{what}"),
        }
    }
}

/// A trace error: where and what.
#[derive(Clone, Debug, PartialEq)]
pub struct TraceError {
    /// Where in the file.
    pub location: Location,
    /// What is wrong.
    pub problem: Problem,
}

impl TraceError {
    /// Builds an error.
    pub fn new(location: Location, problem: Problem) -> Self {
        Self { location, problem }
    }
}

impl fmt::Display for TraceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.location, self.problem)
    }
}

impl std::error::Error for TraceError {}

/// File format, chosen from the extension: `.csv` is CSV, anything else binary.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Text, see [`csv`].
    Csv,
    /// Little-endian binary, see [`wire`].
    Binary,
}

impl Format {
    /// The format a path's extension implies (`.csv` → CSV, otherwise binary).
    pub fn of_path(path: &Path) -> Format {
        match path.extension().and_then(|e| e.to_str()) {
            Some(ext) if ext.eq_ignore_ascii_case("csv") => Format::Csv,
            _ => Format::Binary,
        }
    }
}

impl Trace {
    /// True when the samples carry tilt.
    pub fn has_tilt(&self) -> bool {
        self.samples.first().is_some_and(|s| s.tilt_rad.is_some())
    }

    /// Duration from the first to the last sample (s).
    pub fn duration_s(&self) -> f64 {
        match (self.samples.first(), self.samples.last()) {
            (Some(first), Some(last)) => last.time_s - first.time_s,
            _ => 0.0,
        }
    }

    /// Reads and validates a trace file (format from the extension).
    pub fn read(path: &Path, options: &ValidationOptions) -> Result<Trace, TraceError> {
        let bytes = std::fs::read(path).map_err(|e| {
            TraceError::new(
                Location::File,
                Problem::Io(format!("cannot read {}: {e}", path.display())),
            )
        })?;
        match Format::of_path(path) {
            Format::Csv => {
                let text = String::from_utf8(bytes).map_err(|e| {
                    TraceError::new(
                        Location::Byte(e.utf8_error().valid_up_to()),
                        Problem::BadHeader("the CSV file is not UTF-8 text".into()),
                    )
                })?;
                csv::parse(&text, options)
            }
            Format::Binary => binary::decode(&bytes, options),
        }
    }

    /// Writes the trace (format from the extension) after validating it.
    #[cfg(feature = "write")]
    pub fn write(&self, path: &Path, options: &ValidationOptions) -> Result<(), TraceError> {
        validate::check_trace(self, options, validate::Numbering::Record)?;
        let bytes = match Format::of_path(path) {
            Format::Csv => csv::render(self).into_bytes(),
            Format::Binary => binary::encode(self)?,
        };
        // Whole or not at all: a half-written trace would fail validation later, far from here.
        bearing_host_common::output::write_file(path, bytes)
            .map_err(|e| TraceError::new(Location::File, Problem::Io(e.to_string())))
    }
}

#[cfg(test)]
mod tests;
