//! Checks every trace passes, whatever its file form: metadata in range, finite numbers,
//! strictly increasing time, and no gaps (each time step equal to 1/rate within a tolerance).
//!
//! A gap means samples were lost; replaying across it would feed the bearing a jump in
//! displacement at the nominal rate, so it is refused instead of silently stretched.

use super::wire::{is_identifier_byte, Sample, FIELD_NAMES, IDENTIFIER_LEN};
use super::{Location, Problem, Trace, TraceError, TraceMeta};

/// Highest sample rate accepted (Hz). 10 MHz is far above any recorder of shaft kinematics
/// (the rig of docs/physics.md §6.1 sampled at 100 kHz); it keeps 1/rate well above f64 rounding
/// of the time stamps of a long trace.
pub const MAX_SAMPLE_RATE_HZ: f64 = 1.0e7;

/// Lowest sample rate accepted (Hz): one sample per 1000 s, the lowest step rate `hil-sim replay
/// --rate-hz` accepts. It keeps the period 1/rate finite (a subnormal rate such as 4·10⁻³²⁰ Hz
/// has an infinite period, which no gap check or pacing can use).
pub const MIN_SAMPLE_RATE_HZ: f64 = 1.0e-3;

/// Tunable limits of the checks.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ValidationOptions {
    /// Largest allowed relative deviation of a time step from 1/rate.
    pub gap_tolerance: f64,
}

impl Default for ValidationOptions {
    /// 1 % of the period: far above the rounding of decimal time stamps (≈ 1e-12 relative),
    /// far below one lost sample (100 %).
    fn default() -> Self {
        Self {
            gap_tolerance: 0.01,
        }
    }
}

/// Checks an identifier: 1–16 characters of `[A-Za-z0-9_.-]`.
pub fn check_identifier(which: &str, id: &str) -> Result<(), Problem> {
    if id.is_empty() || id.len() > IDENTIFIER_LEN || !id.bytes().all(is_identifier_byte) {
        return Err(Problem::BadMeta(format!(
            "{which} identifier {id:?} must be 1-{IDENTIFIER_LEN} characters of [A-Za-z0-9_.-]"
        )));
    }
    Ok(())
}

/// Checks the metadata: identifiers and a finite rate in [1 mHz, 10 MHz].
pub fn check_meta(meta: &TraceMeta) -> Result<(), Problem> {
    check_identifier("bearing", &meta.bearing)?;
    check_identifier("lubricant", &meta.lubricant)?;
    let rate = meta.sample_rate_hz;
    if !(rate.is_finite() && (MIN_SAMPLE_RATE_HZ..=MAX_SAMPLE_RATE_HZ).contains(&rate)) {
        return Err(Problem::BadMeta(format!(
            "sample_rate_hz = {rate:e} is out of range: allowed {MIN_SAMPLE_RATE_HZ:e} ..= {MAX_SAMPLE_RATE_HZ:e} Hz"
        )));
    }
    Ok(())
}

/// Checks one sample against its predecessor. On failure, names the offending field.
pub fn check_sample(
    previous: Option<&Sample>,
    sample: &Sample,
    sample_rate_hz: f64,
    options: &ValidationOptions,
) -> Result<(), (&'static str, Problem)> {
    let tilt = sample.tilt_rad.unwrap_or([0.0; 2]);
    let values: [f64; 8] = [
        sample.time_s,
        f64::from(sample.speed_rad_s),
        f64::from(sample.x_m),
        f64::from(sample.y_m),
        f64::from(sample.vx_m_s),
        f64::from(sample.vy_m_s),
        f64::from(tilt[0]),
        f64::from(tilt[1]),
    ];
    for (value, name) in values.iter().zip(FIELD_NAMES) {
        if !value.is_finite() {
            return Err((
                name,
                Problem::NotFinite {
                    found: value.to_string(),
                },
            ));
        }
    }
    if let Some(previous) = previous {
        let step_s = sample.time_s - previous.time_s;
        if step_s <= 0.0 {
            return Err((
                "time",
                Problem::NonIncreasingTime {
                    previous_s: previous.time_s,
                    time_s: sample.time_s,
                },
            ));
        }
        let expected_s = 1.0 / sample_rate_hz;
        // A NaN deviation (an infinite period) counts as a gap, not a pass.
        let on_time = ((step_s - expected_s) / expected_s).abs() <= options.gap_tolerance;
        if !on_time {
            return Err((
                "time",
                Problem::Gap {
                    step_s,
                    expected_s,
                    tolerance: options.gap_tolerance,
                },
            ));
        }
    }
    Ok(())
}

/// How to name the position of sample `i` in an error.
#[derive(Clone, Copy, Debug)]
pub enum Numbering {
    /// Binary record index.
    Record,
    /// CSV line: sample `i` is on line `first_line + i`.
    CsvLines {
        /// Line of sample 0.
        first_line: usize,
    },
}

/// Checks a whole trace: metadata, at least one sample, every sample, consistent tilt.
pub fn check_trace(
    trace: &Trace,
    options: &ValidationOptions,
    numbering: Numbering,
) -> Result<(), TraceError> {
    check_meta(&trace.meta).map_err(|p| TraceError::new(Location::File, p))?;
    if trace.samples.is_empty() {
        return Err(TraceError::new(Location::File, Problem::Empty));
    }
    let has_tilt = trace.has_tilt();
    let mut previous = None;
    for (index, sample) in trace.samples.iter().enumerate() {
        let locate = |field: Option<&'static str>| match numbering {
            Numbering::Record => Location::Record { index, field },
            Numbering::CsvLines { first_line } => Location::Line {
                line: first_line + index,
                column: field.and_then(|name| {
                    FIELD_NAMES
                        .iter()
                        .position(|n| *n == name)
                        .map(|c| (c + 1, name.to_string()))
                }),
            },
        };
        if sample.tilt_rad.is_some() != has_tilt {
            return Err(TraceError::new(
                locate(Some("tilt_x")),
                Problem::BadMeta("tilt is present in some samples and absent in others".into()),
            ));
        }
        check_sample(previous, sample, trace.meta.sample_rate_hz, options)
            .map_err(|(field, problem)| TraceError::new(locate(Some(field)), problem))?;
        previous = Some(sample);
    }
    Ok(())
}
