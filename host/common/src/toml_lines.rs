//! Lines of TOML fields, for error messages that name the line of the offending value.
//!
//! The document is parsed once into the `toml` crate's spanned tree ([`DeTable`]), which keeps
//! the byte span of every key and of every table header; a span's line is the number of
//! newlines before it, plus one.

use toml::de::{DeTable, DeValue};
use toml::Spanned;

/// The key of a `key = value` line (1-based `line`) of `text`: the field a TOML type error on
/// that line is about (the `toml` crate names the line but not the key).
pub fn key_on_line(text: &str, line: usize) -> Option<String> {
    let (key, _) = text.lines().nth(line.checked_sub(1)?)?.split_once('=')?;
    let key = key.trim().trim_matches('"');
    (!key.is_empty() && !key.starts_with('#') && !key.starts_with('[')).then(|| key.to_owned())
}

/// A TOML document with the spans of its keys and table headers.
pub struct TomlLines<'a> {
    text: &'a str,
    /// `None` when the text is not valid TOML (its parse error is reported on its own).
    root: Option<Spanned<DeTable<'a>>>,
}

impl<'a> TomlLines<'a> {
    /// Parses `text`.
    pub fn new(text: &'a str) -> Self {
        Self {
            text,
            root: DeTable::parse(text).ok(),
        }
    }

    /// 1-based line of the byte at `offset` (the newlines before it, plus one; `lines().count()`
    /// would be one short at the start of a line).
    pub fn line_at(&self, offset: usize) -> usize {
        line_at(self.text, offset)
    }

    /// 1-based line of `key` inside the `index`-th `[[table]]` (or inside `[table]`, index 0, or
    /// at the top level when `table` is empty). When the table exists but lacks the key, the
    /// line of the table's header; `None` when the table (or a top-level key) is absent.
    pub fn line_in_table(&self, table: &str, index: usize, key: &str) -> Option<usize> {
        let root = self.root.as_ref()?.get_ref();
        let (scope, header) = if table.is_empty() {
            (root, None)
        } else {
            let entry = root.get(table)?;
            match entry.get_ref() {
                DeValue::Table(t) if index == 0 => (t, Some(entry.span())),
                DeValue::Array(a) => {
                    let element = a.get(index)?;
                    (element.get_ref().as_table()?, Some(element.span()))
                }
                _ => return None,
            }
        };
        match scope.get_key_value(key) {
            Some((k, _)) => Some(self.line_at(k.span().start)),
            None => header.map(|span| self.line_at(span.start)),
        }
    }

    /// 1-based line of the first `key` (by position in the file) in any table of the document.
    pub fn line_of_key(&self, key: &str) -> Option<usize> {
        let root = self.root.as_ref()?.get_ref();
        first_key_offset(root, key).map(|offset| self.line_at(offset))
    }
}

/// 1-based line of the byte at `offset` in `text`.
pub fn line_at(text: &str, offset: usize) -> usize {
    text.as_bytes()[..offset.min(text.len())]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
        + 1
}

/// Smallest byte offset of `key` in `table` or in the tables below it.
fn first_key_offset(table: &DeTable<'_>, key: &str) -> Option<usize> {
    let mut best: Option<usize> = None;
    let mut consider = |offset: Option<usize>| {
        if let Some(o) = offset {
            best = Some(best.map_or(o, |b| b.min(o)));
        }
    };
    for (k, v) in table.iter() {
        if k.get_ref() == key {
            consider(Some(k.span().start));
        }
        match v.get_ref() {
            DeValue::Table(t) => consider(first_key_offset(t, key)),
            DeValue::Array(a) => {
                for element in a.iter() {
                    if let DeValue::Table(t) = element.get_ref() {
                        consider(first_key_offset(t, key));
                    }
                }
            }
            _ => {}
        }
    }
    best
}

#[cfg(test)]
mod tests {
    use super::*;

    const TEXT: &str = "name = \"rig\"\n\
                        \n\
                        [material]\n\
                        density_kg_m3 = 7800.0\n\
                        \n\
                        [[disk]]\n\
                        node = 1\n\
                        mass_kg = 2.0\n\
                        \n\
                        [[disk]]\n\
                        mass_kg = 3.0\n";

    #[test]
    fn keys_tables_and_array_elements_are_located() {
        let lines = TomlLines::new(TEXT);
        assert_eq!(lines.line_in_table("", 0, "name"), Some(1));
        assert_eq!(lines.line_in_table("material", 0, "density_kg_m3"), Some(4));
        assert_eq!(lines.line_in_table("disk", 0, "mass_kg"), Some(8));
        assert_eq!(lines.line_in_table("disk", 1, "mass_kg"), Some(11));
        // A key the element lacks: the element's header.
        assert_eq!(lines.line_in_table("disk", 1, "node"), Some(10));
        assert_eq!(lines.line_in_table("disk", 2, "node"), None);
        assert_eq!(lines.line_in_table("shaft", 0, "node"), None);
        assert_eq!(lines.line_in_table("", 0, "missing"), None);
        assert_eq!(lines.line_of_key("mass_kg"), Some(8));
        assert_eq!(lines.line_of_key("density_kg_m3"), Some(4));
        assert_eq!(lines.line_of_key("missing"), None);
    }

    #[test]
    fn a_key_named_like_another_keys_prefix_is_not_confused() {
        let text = "[geometry]\nroller_diameter_m_extra = 1\nroller_diameter_m = 2\n";
        assert_eq!(
            TomlLines::new(text).line_of_key("roller_diameter_m"),
            Some(3)
        );
    }

    #[test]
    fn invalid_toml_has_no_lines() {
        assert_eq!(TomlLines::new("a = = 1").line_of_key("a"), None);
        assert_eq!(line_at("a\nb\nc", 2), 2);
        assert_eq!(line_at("a\nb\nc", 100), 3);
    }
}
