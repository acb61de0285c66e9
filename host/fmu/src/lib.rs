//! The bearing as an FMI 2.0 co-simulation FMU (docs/fmu.md).
//!
//! One generic shared library (this crate's cdylib) serves every bearing: the FMU carries the
//! bearing file and the film model in `resources/`, which `fmi2Instantiate` reads, and
//! modelDescription.xml carries the same values as the parameters' start values. The `bearing
//! fmu export` command packages both with [`package::write_fmu`].
//!
//! - [`variables`]: the variable table (value references, units, descriptions);
//! - [`model_description`]: modelDescription.xml from that table;
//! - [`instance`]: one instance's state machine and stepping, in plain Rust;
//! - `ffi`: the `fmi2*` functions the standard names, with the standard's types from the
//!   `fmi-sys` crate; no panic crosses them.

pub mod instance;
pub mod model_description;
pub mod package;
pub mod variables;

mod ffi;

use std::path::Path;

use bearing_core::{BearingDesign, FilmKind};
use bearing_host_common::config::BearingConfig;

/// The model identifier: the name of the shared library in `binaries/<platform>/`.
pub const MODEL_IDENTIFIER: &str = "bearing_fmu";
/// The bearing file inside `resources/`.
pub const RESOURCE_CONFIG: &str = "bearing.toml";
/// The film model's name (`int`, `f32`, `regression`, `dry`) inside `resources/`.
pub const RESOURCE_FILM: &str = "film_model.txt";

/// The FMU's GUID: a hash (FNV-1a, 64 bit) of this crate's version, the bearing file's text and
/// the film model, so that `fmi2Instantiate` recognises a modelDescription.xml written for other
/// resources.
pub fn guid(config_text: &str, film: FilmKind) -> String {
    let mut hash: u64 = 0xcbf2_9ce4_8422_2325;
    let parts = [env!("CARGO_PKG_VERSION"), config_text, film.name()];
    for byte in parts.iter().flat_map(|p| p.bytes().chain([0])) {
        hash ^= u64::from(byte);
        hash = hash.wrapping_mul(0x0000_0100_0000_01b3);
    }
    format!("{{bearing-fmu-{hash:016x}}}")
}

/// The bearing file and film model an FMU's `resources/` directory holds, with its GUID.
pub struct Resources {
    /// The design of the bearing file.
    pub design: BearingDesign,
    /// The film model.
    pub film: FilmKind,
    /// [`guid`] of both.
    pub guid: String,
}

impl Resources {
    /// Read `resources/` at `dir`; every refusal names the file (and line and field).
    pub fn load(dir: &Path) -> Result<Self, String> {
        let config_path = dir.join(RESOURCE_CONFIG);
        let text = std::fs::read_to_string(&config_path)
            .map_err(|e| format!("{}: cannot read: {e}", config_path.display()))?;
        let (config, _) = BearingConfig::parse(&text, &config_path).map_err(|e| e.to_string())?;
        let film_path = dir.join(RESOURCE_FILM);
        let film_text = std::fs::read(&film_path)
            .map_err(|e| format!("{}: cannot read: {e}", film_path.display()))?;
        let film = FilmKind::from_name(&film_text).ok_or_else(|| {
            format!(
                "{}: line 1: unknown film model: expected one of int, f32, regression, dry",
                film_path.display()
            )
        })?;
        // The loader has validated every field, so the design is its own.
        let design = config.design().map_err(|e| e.to_string())?;
        Ok(Self {
            design,
            film,
            guid: guid(&text, film),
        })
    }
}

/// The directory of a `file:` URI as FMI importers pass `fmuResourceLocation`
/// (`file:///a/b`, `file:/a/b`, `file://localhost/a/b`, percent-encoded bytes decoded).
///
/// Written here rather than taken from the `url` crate: only local `file:` URIs occur, and
/// their decoding is these few lines.
pub fn path_of_file_uri(uri: &str) -> Option<std::path::PathBuf> {
    let rest = uri.strip_prefix("file:")?;
    let rest = rest
        .strip_prefix("//localhost")
        .or_else(|| rest.strip_prefix("//"))
        .unwrap_or(rest);
    if !rest.starts_with('/') {
        return None;
    }
    let bytes = rest.as_bytes();
    let mut decoded = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while let Some(&b) = bytes.get(i) {
        let hex = bytes
            .get(i + 1..i + 3)
            .and_then(|h| std::str::from_utf8(h).ok())
            .and_then(|h| u8::from_str_radix(h, 16).ok());
        match (b, hex) {
            (b'%', Some(v)) => {
                decoded.push(v);
                i += 3;
            }
            (b'%', None) => return None,
            _ => {
                decoded.push(b);
                i += 1;
            }
        }
    }
    use std::os::unix::ffi::OsStringExt;
    Some(std::ffi::OsString::from_vec(decoded).into())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn file_uris_decode() {
        for (uri, path) in [
            ("file:///tmp/a%20b/resources", "/tmp/a b/resources"),
            ("file:/tmp/x", "/tmp/x"),
            ("file://localhost/tmp/x/", "/tmp/x/"),
        ] {
            assert_eq!(path_of_file_uri(uri).unwrap(), Path::new(path), "{uri}");
        }
        for bad in [
            "http://x/y",
            "file://host/x",
            "file:///a%2",
            "file:relative",
        ] {
            assert!(path_of_file_uri(bad).is_none(), "{bad}");
        }
    }

    #[test]
    fn guid_follows_the_resources() {
        let a = guid("x = 1", FilmKind::Int);
        assert_eq!(a, guid("x = 1", FilmKind::Int));
        assert_ne!(a, guid("x = 2", FilmKind::Int));
        assert_ne!(a, guid("x = 1", FilmKind::Dry));
    }
}
