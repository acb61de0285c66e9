//! The Rust sources of the repository for the layout checks: every tracked `.rs` file, the
//! crates with the root file of each of their targets, and each target's module tree (files
//! found from `mod` declarations as rustc finds them, `#[path]` included).

use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{bail, Context, Result};

/// Files whose text a generator writes: exempt from the length limits.
pub const GENERATED_DIRS: [&str; 1] = ["core/src/generated/"];

/// Every `.rs` file git tracks (or would track: untracked, not ignored), relative to `root`.
pub fn tracked_rust_files(root: &Path) -> Result<Vec<PathBuf>> {
    let out = Command::new("git")
        .current_dir(root)
        .args([
            "ls-files",
            "-z",
            "--cached",
            "--others",
            "--exclude-standard",
            "*.rs",
        ])
        .output()
        .context("running git ls-files")?;
    if !out.status.success() {
        bail!(
            "git ls-files failed: {}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let mut files: Vec<PathBuf> = out
        .stdout
        .split(|&b| b == 0)
        .filter(|p| !p.is_empty())
        .map(|p| PathBuf::from(String::from_utf8_lossy(p).into_owned()))
        .filter(|p| root.join(p).is_file())
        .collect();
    files.sort();
    files.dedup();
    Ok(files)
}

/// Whether a repository path is a generated file.
pub fn is_generated(path: &Path) -> bool {
    let p = path.to_string_lossy();
    GENERATED_DIRS.iter().any(|d| p.starts_with(d))
}

/// One compilation target of a package: its label (`package (kind name)`) and root file.
#[derive(Clone, Debug)]
pub struct Target {
    pub label: String,
    pub root_file: PathBuf,
}

/// The targets of every package of the workspace and of the workspaces it excludes (the
/// firmware's, the header generator's, the fuzz targets'), from `cargo metadata --no-deps`.
pub fn targets(root: &Path) -> Result<Vec<Target>> {
    let mut manifests = vec![root.join("Cargo.toml")];
    for extra in [
        "hil-sim/firmware",
        "hil-sim/counter",
        "core/ffi/header",
        "fuzz",
    ] {
        let m = root.join(extra).join("Cargo.toml");
        if m.is_file() {
            manifests.push(m);
        }
    }
    let mut targets = Vec::new();
    for manifest in manifests {
        let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
        let out = Command::new(cargo)
            .args([
                "metadata",
                "--no-deps",
                "--format-version",
                "1",
                "--offline",
                "--manifest-path",
            ])
            .arg(&manifest)
            .output()
            .with_context(|| format!("cargo metadata for {}", manifest.display()))?;
        if !out.status.success() {
            // A package outside every workspace (hil-sim/counter, a path dependency of the
            // firmware's): its library by the usual layout.
            let dir = manifest.parent().unwrap_or(root);
            let lib = dir.join("src/lib.rs");
            let Ok(rel) = lib.strip_prefix(root) else {
                continue;
            };
            if lib.is_file() {
                targets.push(Target {
                    label: format!(
                        "{} (lib)",
                        rel.parent().and_then(Path::parent).unwrap_or(rel).display()
                    ),
                    root_file: rel.to_path_buf(),
                });
                continue;
            }
            bail!(
                "cargo metadata for {} failed: {}",
                manifest.display(),
                String::from_utf8_lossy(&out.stderr)
            );
        }
        let meta: serde_json::Value = serde_json::from_slice(&out.stdout)?;
        let root_abs = root.canonicalize()?;
        for package in meta["packages"].as_array().into_iter().flatten() {
            let name = package["name"].as_str().unwrap_or("?");
            for t in package["targets"].as_array().into_iter().flatten() {
                let kind = t["kind"][0].as_str().unwrap_or("?");
                let tname = t["name"].as_str().unwrap_or("?");
                let Some(src) = t["src_path"].as_str() else {
                    continue;
                };
                let src = PathBuf::from(src);
                let Ok(rel) = src.strip_prefix(&root_abs) else {
                    continue;
                };
                targets.push(Target {
                    label: format!("{name} ({kind} {tname})"),
                    root_file: rel.to_path_buf(),
                });
            }
        }
    }
    Ok(targets)
}

/// A module of a target's tree: its path from the crate root (inline modules included) and the
/// file that holds it.
#[derive(Clone)]
pub struct Module {
    pub path: Vec<String>,
    pub file: PathBuf,
    /// The module's own items (inline submodules' items excluded).
    pub items: Vec<syn::Item>,
}

/// Parses a repository file.
pub fn parse(root: &Path, file: &Path) -> Result<syn::File> {
    let text = std::fs::read_to_string(root.join(file))
        .with_context(|| format!("reading {}", file.display()))?;
    syn::parse_file(&text).with_context(|| format!("parsing {}", file.display()))
}

/// The value of a `#[path = "…"]` attribute.
fn path_attribute(attrs: &[syn::Attribute]) -> Option<String> {
    attrs.iter().find_map(|a| {
        if !a.path().is_ident("path") {
            return None;
        }
        match &a.meta {
            syn::Meta::NameValue(nv) => match &nv.value {
                syn::Expr::Lit(syn::ExprLit {
                    lit: syn::Lit::Str(s),
                    ..
                }) => Some(s.value()),
                _ => None,
            },
            _ => None,
        }
    })
}

/// The module tree of one target, every module with its items.
pub fn module_tree(root: &Path, root_file: &Path) -> Result<Vec<Module>> {
    let mut modules = Vec::new();
    let file = parse(root, root_file)?;
    let dir = root_file.parent().unwrap_or(Path::new("")).to_path_buf();
    collect(root, root_file, dir, Vec::new(), file.items, &mut modules)?;
    Ok(modules)
}

/// Adds the module `path` (held in `file`, whose children's files sit in `child_dir`) and its
/// submodules.
fn collect(
    root: &Path,
    file: &Path,
    child_dir: PathBuf,
    path: Vec<String>,
    items: Vec<syn::Item>,
    out: &mut Vec<Module>,
) -> Result<()> {
    let mut own = Vec::new();
    for item in items {
        let syn::Item::Mod(m) = item else {
            own.push(item);
            continue;
        };
        let name = m.ident.to_string();
        let mut sub = path.clone();
        sub.push(name.clone());
        if let Some((_, content)) = m.content {
            collect(root, file, child_dir.join(&name), sub, content, out)?;
            continue;
        }
        let (sub_file, sub_dir) = if let Some(p) = path_attribute(&m.attrs) {
            // A file named by `#[path]` holds its children beside it, as a `mod.rs` does.
            let f = file.parent().unwrap_or(Path::new("")).join(p);
            let d = f.parent().unwrap_or(Path::new("")).to_path_buf();
            (f, d)
        } else {
            let flat = child_dir.join(format!("{name}.rs"));
            if root.join(&flat).is_file() {
                (flat, child_dir.join(&name))
            } else {
                (child_dir.join(&name).join("mod.rs"), child_dir.join(&name))
            }
        };
        if !root.join(&sub_file).is_file() {
            // A module behind a `cfg` for a file that does not exist here: nothing to read.
            continue;
        }
        let parsed = parse(root, &sub_file)?;
        collect(root, &sub_file, sub_dir, sub, parsed.items, out)?;
    }
    out.push(Module {
        path,
        file: file.to_path_buf(),
        items: own,
    });
    Ok(())
}
