//! `cargo xtask generate [--check] [NAME …]`: writes the core's generated files
//! (`core/src/generated/`, `bearing_train::generated`) and the C library's header
//! (`core/ffi/include/bearing.h`, cbindgen) from their sources, or with `--check` regenerates
//! them in memory and names every file that differs, byte for byte, from the committed one.

use std::path::Path;
use std::process::Command;
use std::time::Instant;

use anyhow::{bail, Result};
use bearing_train::generated::CoreFile;

/// The C header's name on the command line, and its path.
const C_HEADER: (&str, &str) = ("c-header", "core/ffi/include/bearing.h");

/// The core's files `names` select (all when empty) and whether the C header is selected, or
/// the unknown name with the known ones.
fn selected(names: &[String]) -> Result<(Vec<CoreFile>, bool)> {
    if names.is_empty() {
        return Ok((CoreFile::ALL.to_vec(), true));
    }
    let mut files = Vec::new();
    let mut header = false;
    for name in names {
        if name == C_HEADER.0 {
            header = true;
        } else if let Some(f) = CoreFile::ALL.into_iter().find(|f| f.name() == name) {
            files.push(f);
        } else {
            let mut known: Vec<_> = CoreFile::ALL.iter().map(|f| f.name()).collect();
            known.push(C_HEADER.0);
            bail!(
                "unknown generated file `{name}`: one of {}",
                known.join(", ")
            );
        }
    }
    Ok((files, header))
}

/// The C header by its generator (`core/ffi/header`, a workspace of its own so that cbindgen's
/// dependencies stay out of the workspace's builds; built into `target/ffi-header`): `true`
/// when the committed header is current (or, without `check`, rewritten).
fn c_header(root: &Path, check: bool) -> Result<bool> {
    let started = Instant::now();
    eprintln!("{}: from core/ffi's source by cbindgen …", C_HEADER.1);
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut command = Command::new(cargo);
    command
        .current_dir(root)
        .args([
            "run",
            "--release",
            "--quiet",
            "--manifest-path",
            "core/ffi/header/Cargo.toml",
        ])
        .arg("--target-dir")
        .arg(crate::setup::target_dir(root).join("ffi-header"))
        // The workspace's settings are not the generator's.
        .env_remove("RUSTFLAGS")
        .env_remove("CARGO_ENCODED_RUSTFLAGS")
        .env_remove("CARGO_TARGET_DIR");
    if !check {
        command.args(["--", "--write"]);
    }
    let status = command.status()?;
    let seconds = started.elapsed().as_secs_f64();
    match status.code() {
        Some(0) if check => eprintln!("{}: up to date ({seconds:.1} s)", C_HEADER.1),
        Some(0) => eprintln!("{}: written ({seconds:.1} s)", C_HEADER.1),
        Some(1) => {
            eprintln!("{}: STALE ({seconds:.1} s)", C_HEADER.1);
            return Ok(false);
        }
        _ => bail!("the header generator (core/ffi/header) failed: {status}"),
    }
    Ok(true)
}

/// Writes `text` to `path` whole or not at all (a temporary file renamed over it).
fn write_whole(path: &Path, text: &str) -> Result<()> {
    let tmp = path.with_extension("rs.tmp");
    std::fs::write(&tmp, text)?;
    std::fs::rename(&tmp, path)?;
    Ok(())
}

/// Regenerates the selected files; with `check`, writes nothing and fails naming the stale ones.
pub fn run(root: &Path, check: bool, names: &[String]) -> Result<()> {
    let (files, header) = selected(names)?;
    let mut stale: Vec<(&str, &str)> = Vec::new();
    if header && !c_header(root, check)? {
        stale.push(C_HEADER);
    }
    for file in files {
        let started = Instant::now();
        eprintln!("{}: from {} …", file.path(), file.source());
        let text = file.render(root)?;
        let path = root.join(file.path());
        let committed = std::fs::read(&path).ok();
        let same = committed.as_deref() == Some(text.as_bytes());
        let seconds = started.elapsed().as_secs_f64();
        match (same, check) {
            (true, _) => eprintln!("{}: up to date ({seconds:.1} s)", file.path()),
            (false, true) => {
                eprintln!(
                    "{}: STALE, differs from what its generator writes ({seconds:.1} s)",
                    file.path()
                );
                stale.push((file.name(), file.path()));
            }
            (false, false) => {
                write_whole(&path, &text)?;
                eprintln!("{}: written ({seconds:.1} s)", file.path());
            }
        }
    }
    if !stale.is_empty() {
        let names: Vec<_> = stale.iter().map(|f| f.0).collect();
        let paths: Vec<_> = stale.iter().map(|f| f.1).collect();
        bail!(
            "stale generated files: {}; regenerate with `cargo xtask generate {}` and commit them",
            paths.join(", "),
            names.join(" ")
        );
    }
    Ok(())
}
