//! `cargo xtask doc-figures [--all] [FILE …]`: the figures the docs show, checked against the
//! commands that make them.
//!
//! A figure block in a markdown file is an HTML comment (invisible on the rendered page) right
//! before the paragraph or table that shows the figures:
//!
//! ```text
//! <!-- figures: bearing shaft sweep --config configs/shaft_hub_motor.toml --json
//! lubricated.power_loss_w.0 %.1f
//! comparison.stiffness_ratio *100 %.0f
//! -->
//! ```
//!
//! The first line is the command (`bearing` and `hil-sim` are this workspace's release
//! binaries; run in the repository's root; `{tmp}` is a scratch directory); it must print JSON.
//! Each further line takes a value from it — a path of object keys and array indices separated
//! by dots (`-1` is the last element), an optional factor (`*1e6`) — and formats it:
//! `%.Nf` (N decimals), `%d` (an integer), `%'d` (an integer in groups of three digits
//! separated by spaces, as the docs write 27 330), `%.N·e` (N decimals times a power of ten,
//! `1.95·10⁹`), `%.N·eK` (times the power K, `0.99·10⁹` for `%.2·e9`). The text must appear in the block that follows the comment (up to the first
//! blank line after some text), not inside a longer number. `<!-- figures (slow): … -->` marks
//! a command that takes minutes: it runs only with `--all`. The cheap blocks run with every
//! `cargo xtask test`.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

use anyhow::{anyhow, bail, Context, Result};
use serde_json::Value;

/// The markdown files that hold figure blocks.
pub const DOCS: [&str; 3] = ["README.md", "docs", "data/ann/README.md"];

#[derive(clap::Args, Default)]
pub struct Args {
    /// Also run the blocks marked slow (commands that take minutes).
    #[arg(long)]
    pub all: bool,
    /// Only these markdown files (default: README.md, docs/*.md, data/ann/README.md).
    pub files: Vec<PathBuf>,
    /// Use the `bearing` and `hil-sim` binaries as they are, when built (`cargo xtask test` runs this after
    /// `cargo test --workspace`, which built them with the workspace's features; a build with
    /// the two packages' own features would compile part of the workspace again).
    #[arg(long, hide = true)]
    pub no_build: bool,
}

/// The outcome: the figures that matched, and a line for each failed block or figure.
#[derive(Debug, Default)]
pub struct Checked {
    pub passed: usize,
    pub failed: Vec<String>,
}

/// One figure: where its value is in the JSON, its factor and format.
#[derive(Clone, Debug, PartialEq)]
struct Figure {
    path: String,
    factor: f64,
    format: String,
}

/// A figure block: the command, its figures, the text they must appear in, its line.
#[derive(Clone, Debug, PartialEq)]
struct Block {
    line: usize,
    slow: bool,
    command: String,
    figures: Vec<Figure>,
    text: String,
}

/// The figure blocks of a markdown text. Comments stacked one after the other (for figures of
/// several commands in one paragraph or table) share the block that follows the last.
fn blocks(markdown: &str) -> Result<Vec<Block>> {
    let lines: Vec<&str> = markdown.lines().collect();
    let mut out = Vec::new();
    let mut pending: Vec<Block> = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        let line = lines[i].trim_start();
        let comment = if let Some(r) = line.strip_prefix("<!-- figures:") {
            Some((false, r))
        } else {
            line.strip_prefix("<!-- figures (slow):").map(|r| (true, r))
        };
        if let Some((slow, rest)) = comment {
            let start = i + 1;
            let mut figures = Vec::new();
            i += 1;
            loop {
                let Some(l) = lines.get(i) else {
                    bail!("line {start}: the figure block has no closing `-->`");
                };
                let l = l.trim();
                i += 1;
                if l == "-->" {
                    break;
                }
                figures.push(parse_figure(l).with_context(|| format!("line {i}"))?);
            }
            pending.push(Block {
                line: start,
                slow,
                command: rest.trim().to_string(),
                figures,
                text: String::new(),
            });
            continue;
        }
        if pending.is_empty() || line.is_empty() {
            i += 1;
            continue;
        }
        // The block that follows: up to the first blank line.
        let mut text = String::new();
        while let Some(l) = lines.get(i) {
            if l.trim().is_empty() {
                break;
            }
            text.push_str(l);
            text.push('\n');
            i += 1;
        }
        for mut block in pending.drain(..) {
            block.text = text.clone();
            out.push(block);
        }
    }
    if let Some(b) = pending.first() {
        bail!("line {}: the figure block is followed by no text", b.line);
    }
    Ok(out)
}

fn parse_figure(line: &str) -> Result<Figure> {
    let words: Vec<&str> = line.split_whitespace().collect();
    let (path, factor, format) = match words.as_slice() {
        [path, format] => (*path, 1.0, *format),
        [path, factor, format] => {
            let f = factor
                .strip_prefix('*')
                .and_then(|f| f.parse().ok())
                .ok_or_else(|| anyhow!("`{factor}` is not a factor like *1e6"))?;
            (*path, f, *format)
        }
        _ => bail!("`{line}` is not `<json path> [*factor] <format>`"),
    };
    format_value(0.0, format)?;
    Ok(Figure {
        path: path.to_string(),
        factor,
        format: format.to_string(),
    })
}

/// Superscript digits of an exponent.
fn superscript(e: i32) -> String {
    let digits = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    let mut s = if e < 0 {
        "⁻".to_string()
    } else {
        String::new()
    };
    for c in e.unsigned_abs().to_string().chars() {
        s.push(digits[c.to_digit(10).unwrap_or(0) as usize]);
    }
    s
}

/// Digits in groups of three separated by spaces.
fn grouped(n: i64) -> String {
    let digits = n.unsigned_abs().to_string();
    let mut out = String::new();
    for (k, c) in digits.chars().enumerate() {
        if k > 0 && (digits.len() - k) % 3 == 0 {
            out.push(' ');
        }
        out.push(c);
    }
    if n < 0 {
        format!("−{out}")
    } else {
        out
    }
}

/// The text of a value in a format.
fn format_value(v: f64, format: &str) -> Result<String> {
    if format == "%d" {
        return Ok(format!("{}", v.round() as i64));
    }
    if format == "%'d" {
        return Ok(grouped(v.round() as i64));
    }
    let decimals = |spec: &str| -> Result<usize> {
        spec.parse()
            .map_err(|_| anyhow!("`{format}`: decimals are a number"))
    };
    if let Some(d) = format.strip_prefix("%.").and_then(|s| s.strip_suffix('f')) {
        return Ok(format!("{v:.*}", decimals(d)?));
    }
    if let Some((d, fixed)) = format.strip_prefix("%.").and_then(|s| s.split_once("·e")) {
        let d = decimals(d)?;
        if !fixed.is_empty() {
            // A fixed power of ten (`%.2·e9`: 0.99·10⁹ as a table column writes it).
            let exponent: i32 = fixed
                .parse()
                .map_err(|_| anyhow!("`{format}`: the power of ten is a number"))?;
            let mantissa = format!("{:.*}", d, v / 10f64.powi(exponent));
            return Ok(format!("{mantissa}·10{}", superscript(exponent)));
        }
        let mut exponent = if v == 0.0 {
            0
        } else {
            v.abs().log10().floor() as i32
        };
        let mut mantissa = format!("{:.*}", d, v / 10f64.powi(exponent));
        // Rounding may carry to 10.0…: one power of ten up.
        if mantissa.trim_start_matches('-').starts_with("10") {
            exponent += 1;
            mantissa = format!("{:.*}", d, v / 10f64.powi(exponent));
        }
        return Ok(format!("{mantissa}·10{}", superscript(exponent)));
    }
    bail!("unknown format `{format}`: %.Nf, %d, %'d, %.N·e or %.N·eK")
}

/// The value at a dotted path of keys and indices.
fn lookup<'a>(json: &'a Value, path: &str) -> Option<&'a Value> {
    path.split('.').try_fold(json, |v, key| match v {
        Value::Array(a) => {
            let i: i64 = key.parse().ok()?;
            let i = if i < 0 { a.len() as i64 + i } else { i };
            a.get(usize::try_from(i).ok()?)
        }
        Value::Object(o) => o.get(key),
        _ => None,
    })
}

/// Whether `needle` occurs in `text` other than inside a longer number (a minus sign may be
/// written `-` or `−`).
fn contains_figure(text: &str, needle: &str) -> bool {
    let digit = |c: Option<char>| c.is_some_and(|c| c.is_ascii_digit());
    let found = |needle: &str| {
        text.match_indices(needle).any(|(at, _)| {
            let mut before = text[..at].chars().rev();
            let mut after = text[at + needle.len()..].chars();
            let (b1, b2) = (before.next(), before.next());
            let (a1, a2) = (after.next(), after.next());
            let inside_before = digit(b1) || (b1 == Some('.') && digit(b2));
            let inside_after = digit(a1) || (a1 == Some('.') && digit(a2));
            !inside_before && !inside_after
        })
    };
    found(needle) || (needle.starts_with('-') && found(&needle.replacen('-', "−", 1)))
}

/// Runs a block's command; its JSON output.
fn run_command(root: &Path, command: &str, scratch: &Path) -> Result<Value> {
    let words: Vec<String> = command
        .split_whitespace()
        .map(|w| w.replace("{tmp}", &scratch.to_string_lossy()))
        .collect();
    let (program, args) = words
        .split_first()
        .ok_or_else(|| anyhow!("empty command"))?;
    let program = match program.as_str() {
        "bearing" | "hil-sim" => crate::setup::target_dir(root).join("release").join(program),
        other => PathBuf::from(other),
    };
    let out = Command::new(&program)
        .current_dir(root)
        .args(args)
        .output()
        .with_context(|| format!("running {}", program.display()))?;
    if !out.status.success() {
        bail!(
            "exited with {}: {}",
            out.status,
            String::from_utf8_lossy(&out.stderr).trim()
        );
    }
    serde_json::from_slice(&out.stdout).context("its output is not JSON")
}

/// Builds the binaries the blocks call.
fn build_binaries(root: &Path) -> Result<()> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let status = Command::new(cargo)
        .current_dir(root)
        .args([
            "build",
            "--release",
            "--quiet",
            "-p",
            "bearing-cli",
            "-p",
            "bearing-hil",
            "--bins",
        ])
        .status()?;
    if !status.success() {
        bail!("building bearing and hil-sim failed");
    }
    Ok(())
}

/// The markdown files to read.
fn markdown_files(root: &Path, args: &Args) -> Result<Vec<PathBuf>> {
    if !args.files.is_empty() {
        return Ok(args.files.clone());
    }
    let mut files = Vec::new();
    for entry in DOCS {
        let path = root.join(entry);
        if path.is_dir() {
            let mut md: Vec<PathBuf> = std::fs::read_dir(&path)?
                .filter_map(|e| e.ok().map(|e| e.path()))
                .filter(|p| p.extension().is_some_and(|x| x == "md"))
                .filter_map(|p| p.strip_prefix(root).ok().map(Path::to_path_buf))
                .collect();
            md.sort();
            files.extend(md);
        } else {
            files.push(PathBuf::from(entry));
        }
    }
    Ok(files)
}

/// Checks every block; prints a libtest-like line per block and a summary line.
pub fn run(root: &Path, args: &Args) -> Result<Checked> {
    let release = crate::setup::target_dir(root).join("release");
    let built = ["bearing", "hil-sim"]
        .iter()
        .all(|b| release.join(b).is_file());
    if !(args.no_build && built) {
        build_binaries(root)?;
    }
    let scratch = crate::setup::target_dir(root).join("doc-figures");
    std::fs::create_dir_all(&scratch)?;
    let mut checked = Checked::default();
    let mut slow_left = 0;
    // Blocks that show figures of the same command share one run of it.
    let mut outputs: std::collections::HashMap<String, Value> = std::collections::HashMap::new();
    for file in markdown_files(root, args)? {
        let markdown = std::fs::read_to_string(root.join(&file))
            .with_context(|| format!("reading {}", file.display()))?;
        for block in blocks(&markdown).with_context(|| format!("{}", file.display()))? {
            let name = format!("{}:{}", file.display(), block.line);
            if block.slow && !args.all {
                slow_left += 1;
                continue;
            }
            let started = Instant::now();
            let json = match outputs.get(&block.command) {
                Some(json) => Ok(json.clone()),
                None => run_command(root, &block.command, &scratch),
            };
            let json = match json {
                Ok(json) => {
                    outputs.insert(block.command.clone(), json.clone());
                    json
                }
                Err(e) => {
                    println!("test {name} ... FAILED\n    `{}`: {e:#}", block.command);
                    checked.failed.push(name);
                    continue;
                }
            };
            let mut wrong = Vec::new();
            for figure in &block.figures {
                let value = lookup(&json, &figure.path).and_then(Value::as_f64);
                let Some(value) = value else {
                    wrong.push(format!("{}: no number there", figure.path));
                    continue;
                };
                let text = format_value(value * figure.factor, &figure.format)?;
                if !contains_figure(&block.text, &text) {
                    wrong.push(format!(
                        "{} = {value} shows as `{text}`: not in the text",
                        figure.path
                    ));
                }
            }
            let seconds = started.elapsed().as_secs_f64();
            if wrong.is_empty() {
                println!(
                    "test {name} ... ok ({} figures, {seconds:.1} s)",
                    block.figures.len()
                );
                checked.passed += 1;
            } else {
                println!(
                    "test {name} ... FAILED ({seconds:.1} s)\n    `{}`",
                    block.command
                );
                for w in wrong {
                    println!("    {w}");
                }
                checked.failed.push(name);
            }
        }
    }
    println!(
        "doc figures: {} passed, {} failed{}",
        checked.passed,
        checked.failed.len(),
        if slow_left > 0 {
            format!(" ({slow_left} slow blocks left to `cargo xtask doc-figures --all`)")
        } else {
            String::new()
        }
    );
    Ok(checked)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn formats_as_the_docs_write() {
        assert_eq!(format_value(99.24, "%.1f").unwrap(), "99.2");
        assert_eq!(format_value(27330.0, "%'d").unwrap(), "27 330");
        assert_eq!(format_value(1917.0, "%'d").unwrap(), "1 917");
        assert_eq!(format_value(1917.0, "%d").unwrap(), "1917");
        assert_eq!(format_value(1.951e9, "%.2·e").unwrap(), "1.95·10⁹");
        assert_eq!(format_value(9.996e8, "%.2·e").unwrap(), "1.00·10⁹");
        assert_eq!(format_value(4.7e-10, "%.1·e").unwrap(), "4.7·10⁻¹⁰");
        assert_eq!(format_value(9.856e8, "%.2·e9").unwrap(), "0.99·10⁹");
    }

    #[test]
    fn reads_blocks_and_finds_figures_only_as_whole_numbers() {
        let md = "# T\n\n<!-- figures: bearing x --json\na.0 %.1f\nb *1e6 %.2f\n-->\n<!-- figures (slow): hil-sim y\nc %d\n-->\n| x | 99.2 |\n| y | 1.50 |\n\nlater 7\n";
        let b = blocks(md).unwrap();
        assert_eq!(b.len(), 2);
        assert!(b[1].slow && b[1].text == b[0].text);
        assert_eq!(b[0].command, "bearing x --json");
        assert_eq!(b[0].figures[1].factor, 1e6);
        assert!(b[0].text.contains("1.50") && !b[0].text.contains("later"));
        assert!(contains_figure(&b[0].text, "99.2"));
        assert!(!contains_figure("199.2", "99.2"));
        assert!(!contains_figure("99.25", "99.2"));
        assert!(contains_figure("is 99.2. Then", "99.2"));
        assert!(contains_figure("at −3.5 and", "-3.5"));
        assert!(!contains_figure("1.5", "5"));
        let json: Value = serde_json::json!({"a": [1.0, 2.0], "b": {"c": [3, 4]}});
        assert_eq!(lookup(&json, "a.-1").and_then(Value::as_f64), Some(2.0));
        assert_eq!(lookup(&json, "b.c.0").and_then(Value::as_f64), Some(3.0));
    }
}
