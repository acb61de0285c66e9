//! Locating a semantic error in the shaft file: (table, index, key) → line, and the range checks
//! that produce [`ConfigError`]s naming file, line, field and the allowed range.

use std::path::Path;

use bearing_host_common::toml_lines::TomlLines;

use super::ConfigError;

/// The file's path and its TOML key lines, to turn (table, index, key) into a line number.
pub(super) struct Locator<'a> {
    pub(super) file: &'a Path,
    pub(super) lines: TomlLines<'a>,
}

impl Locator<'_> {
    /// Line of `key` inside the `index`-th `[[table]]` (or `[table]`, or the top level when
    /// `table` is empty); the table's header line when the key is absent.
    pub(super) fn line(&self, table: &str, index: usize, key: &str) -> Option<usize> {
        self.lines.line_in_table(table, index, key)
    }

    pub(super) fn err(&self, table: &str, index: usize, key: &str, message: String) -> ConfigError {
        let field = match table {
            "" => key.to_string(),
            "material" | "damping" | "motor" => format!("{table}.{key}"),
            _ => format!("{table}[{index}].{key}"),
        };
        ConfigError {
            file: self.file.to_path_buf(),
            line: self.line(table, index, key),
            field,
            message,
        }
    }

    /// A finite value in [lo, hi] (inclusive unless `open_lo`).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn range(
        &self,
        table: &str,
        index: usize,
        key: &str,
        value: f64,
        lo: f64,
        hi: f64,
        open_lo: bool,
        unit: &str,
    ) -> Result<f64, ConfigError> {
        let ok = value.is_finite() && value <= hi && if open_lo { value > lo } else { value >= lo };
        if ok {
            Ok(value)
        } else {
            let bracket = if open_lo { "(" } else { "[" };
            Err(self.err(
                table,
                index,
                key,
                format!(
                    "{} is not allowed: must be finite and in {bracket}{lo}, {hi}] {unit}",
                    number(value)
                ),
            ))
        }
    }

    pub(super) fn positive(
        &self,
        t: &str,
        i: usize,
        k: &str,
        v: f64,
        unit: &str,
    ) -> Result<f64, ConfigError> {
        self.range(t, i, k, v, 0.0, f64::MAX, true, unit)
    }

    pub(super) fn non_negative(
        &self,
        t: &str,
        i: usize,
        k: &str,
        v: f64,
        unit: &str,
    ) -> Result<f64, ConfigError> {
        self.range(t, i, k, v, 0.0, f64::MAX, false, unit)
    }

    pub(super) fn finite(
        &self,
        t: &str,
        i: usize,
        k: &str,
        v: f64,
        unit: &str,
    ) -> Result<f64, ConfigError> {
        self.range(t, i, k, v, -f64::MAX, f64::MAX, false, unit)
    }

    pub(super) fn node(
        &self,
        t: &str,
        i: usize,
        node: usize,
        n_nodes: usize,
    ) -> Result<usize, ConfigError> {
        if node < n_nodes {
            Ok(node)
        } else {
            Err(self.err(
                t,
                i,
                "node",
                format!("node {node} does not exist: allowed 0 … {}", n_nodes - 1),
            ))
        }
    }

    pub(super) fn required<T: Copy>(
        &self,
        t: &str,
        i: usize,
        k: &str,
        v: Option<T>,
        why: &str,
    ) -> Result<T, ConfigError> {
        v.ok_or_else(|| self.err(t, i, k, format!("missing: required {why}")))
    }
}

/// `value` as written in a file: plain decimals for ordinary magnitudes, scientific notation
/// otherwise (Rust's `{}` spells 1e200 with 201 digits).
fn number(value: f64) -> String {
    let magnitude = value.abs();
    if magnitude == 0.0 || !value.is_finite() || (1e-4..1e15).contains(&magnitude) {
        format!("{value}")
    } else {
        format!("{value:e}")
    }
}
