//! CSV form of a trace: metadata comment lines, a header naming each column with its unit, then
//! one sample per line.
//!
//! ```text
//! # bearing: hub_motor
//! # lubricant: mineral_iso68
//! # sample_rate_hz: 10000
//! time_s,speed_rad_s,x_m,y_m,vx_m_s,vy_m_s
//! 0,2199.11,1.2e-6,-3.4e-6,0.001,-0.002
//! ```
//!
//! Two more columns, `tilt_x_rad,tilt_y_rad`, carry tilt. Other `#` lines are comments; blank
//! lines are skipped. Numbers are written with Rust's shortest round-trip formatting, so a
//! binary → CSV → binary conversion is lossless. Errors name the line and column (both from 1).

use super::validate::{check_identifier, check_meta, check_sample, ValidationOptions};
use super::wire::Sample;
use super::{Location, Problem, Trace, TraceError, TraceMeta};
use std::fmt::Write as _;

/// Column names (with units) in file order; the last two only with tilt.
pub const COLUMNS: [&str; 8] = [
    "time_s",
    "speed_rad_s",
    "x_m",
    "y_m",
    "vx_m_s",
    "vy_m_s",
    "tilt_x_rad",
    "tilt_y_rad",
];

/// Metadata keys, in the order they are written.
const META_KEYS: [&str; 3] = ["bearing", "lubricant", "sample_rate_hz"];

fn at_line(line: usize, problem: Problem) -> TraceError {
    TraceError::new(Location::Line { line, column: None }, problem)
}

fn at_column(line: usize, column: usize, problem: Problem) -> TraceError {
    let name = COLUMNS.get(column).copied().unwrap_or("?").to_string();
    TraceError::new(
        Location::Line {
            line,
            column: Some((column + 1, name)),
        },
        problem,
    )
}

/// Parses one numeric field; f32 fields that overflow become infinite and are refused.
fn parse_field(text: &str, line: usize, column: usize) -> Result<f64, TraceError> {
    let as_f64 = text.parse::<f64>().map_err(|_| {
        at_column(
            line,
            column,
            Problem::NotANumber {
                found: text.to_string(),
            },
        )
    })?;
    // Column 0 (time) stays f64; the kinematics are stored as f32 like the binary form.
    let value = if column == 0 {
        as_f64
    } else {
        f64::from(as_f64 as f32)
    };
    if !value.is_finite() {
        return Err(at_column(
            line,
            column,
            Problem::NotFinite {
                found: text.to_string(),
            },
        ));
    }
    Ok(value)
}

/// Parses and validates a CSV trace.
pub fn parse(text: &str, options: &ValidationOptions) -> Result<Trace, TraceError> {
    let mut meta_values: [Option<(usize, String)>; 3] = [None, None, None];
    let mut columns: Option<usize> = None;
    let mut samples: Vec<Sample> = Vec::new();
    let mut meta: Option<TraceMeta> = None;

    for (index, raw) in text.lines().enumerate() {
        let line = index + 1;
        let content = raw.trim();
        if content.is_empty() {
            continue;
        }
        if let Some(comment) = content.strip_prefix('#') {
            if let Some((key, value)) = comment.split_once(':') {
                let key = key.trim();
                if let Some(slot) = META_KEYS.iter().position(|k| *k == key) {
                    if columns.is_some() {
                        return Err(at_line(
                            line,
                            Problem::BadHeader(format!(
                                "metadata '{key}' must come before the column header"
                            )),
                        ));
                    }
                    if let Some(entry) = meta_values.get_mut(slot) {
                        if let Some((first, _)) = entry {
                            return Err(at_line(
                                line,
                                Problem::BadHeader(format!(
                                    "metadata '{key}' repeated (first on line {first})"
                                )),
                            ));
                        }
                        *entry = Some((line, value.trim().to_string()));
                    }
                }
            }
            continue;
        }
        let Some(width) = columns else {
            // The first non-comment line is the column header.
            let names: Vec<&str> = content.split(',').map(str::trim).collect();
            let plain = COLUMNS.get(..6).unwrap_or(&[]);
            let width = if names == plain {
                6
            } else if names == COLUMNS {
                8
            } else {
                return Err(at_line(
                    line,
                    Problem::BadHeader(format!(
                        "columns must be '{}' (optionally followed by ',tilt_x_rad,tilt_y_rad'), found '{content}'",
                        plain.join(",")
                    )),
                ));
            };
            meta = Some(parse_meta(&meta_values, line)?);
            columns = Some(width);
            continue;
        };
        let fields: Vec<&str> = content.split(',').map(str::trim).collect();
        if fields.len() != width {
            return Err(at_line(
                line,
                Problem::FieldCount {
                    found: fields.len(),
                    expected: width,
                },
            ));
        }
        let mut values = [0f64; 8];
        for (column, (text, slot)) in fields.iter().zip(values.iter_mut()).enumerate() {
            *slot = parse_field(text, line, column)?;
        }
        let [time_s, speed, x, y, vx, vy, tilt_x, tilt_y] = values;
        let sample = Sample {
            time_s,
            speed_rad_s: speed as f32,
            x_m: x as f32,
            y_m: y as f32,
            vx_m_s: vx as f32,
            vy_m_s: vy as f32,
            tilt_rad: (width == 8).then_some([tilt_x as f32, tilt_y as f32]),
        };
        let rate = meta.as_ref().map_or(1.0, |m| m.sample_rate_hz);
        check_sample(samples.last(), &sample, rate, options).map_err(|(field, problem)| {
            let column = super::wire::FIELD_NAMES
                .iter()
                .position(|n| *n == field)
                .unwrap_or(0);
            at_column(line, column, problem)
        })?;
        samples.push(sample);
    }
    let Some(meta) = meta else {
        return Err(TraceError::new(
            Location::File,
            Problem::BadHeader(format!(
                "no column header line '{}'",
                COLUMNS.get(..6).unwrap_or(&[]).join(",")
            )),
        ));
    };
    if samples.is_empty() {
        return Err(TraceError::new(Location::File, Problem::Empty));
    }
    Ok(Trace { meta, samples })
}

/// Builds the metadata from the `# key: value` lines seen before the header on `header_line`.
fn parse_meta(
    values: &[Option<(usize, String)>; 3],
    header_line: usize,
) -> Result<TraceMeta, TraceError> {
    let get = |slot: usize| -> Result<(usize, &str), TraceError> {
        match values.get(slot).and_then(Option::as_ref) {
            Some((line, value)) => Ok((*line, value.as_str())),
            None => Err(at_line(
                header_line,
                Problem::BadHeader(format!(
                    "missing metadata line '# {}: ...' before the column header",
                    META_KEYS.get(slot).copied().unwrap_or("?")
                )),
            )),
        }
    };
    let (bearing_line, bearing) = get(0)?;
    check_identifier("bearing", bearing).map_err(|p| at_line(bearing_line, p))?;
    let (lubricant_line, lubricant) = get(1)?;
    check_identifier("lubricant", lubricant).map_err(|p| at_line(lubricant_line, p))?;
    let (rate_line, rate_text) = get(2)?;
    let sample_rate_hz = rate_text.parse::<f64>().map_err(|_| {
        at_line(
            rate_line,
            Problem::BadMeta(format!("sample_rate_hz {rate_text:?} is not a number")),
        )
    })?;
    let meta = TraceMeta {
        bearing: bearing.to_string(),
        lubricant: lubricant.to_string(),
        sample_rate_hz,
    };
    check_meta(&meta).map_err(|p| at_line(rate_line, p))?;
    Ok(meta)
}

/// Renders a trace as CSV (shortest round-trip number formatting).
pub fn render(trace: &Trace) -> String {
    let has_tilt = trace.has_tilt();
    let width = if has_tilt { 8 } else { 6 };
    let mut out = String::with_capacity(128 + trace.samples.len() * 96);
    let _ = writeln!(out, "# bearing: {}", trace.meta.bearing);
    let _ = writeln!(out, "# lubricant: {}", trace.meta.lubricant);
    let _ = writeln!(out, "# sample_rate_hz: {}", trace.meta.sample_rate_hz);
    let _ = writeln!(out, "{}", COLUMNS.get(..width).unwrap_or(&[]).join(","));
    for s in &trace.samples {
        let _ = write!(
            out,
            "{},{},{},{},{},{}",
            s.time_s, s.speed_rad_s, s.x_m, s.y_m, s.vx_m_s, s.vy_m_s
        );
        if let Some([tilt_x, tilt_y]) = s.tilt_rad {
            let _ = write!(out, ",{tilt_x},{tilt_y}");
        }
        out.push('\n');
    }
    out
}
