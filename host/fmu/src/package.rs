//! The `.fmu` archive: modelDescription.xml, the shared library for linux64 and the bearing
//! file with the film model as resources, written whole or not at all (a temporary file in the
//! target's directory, renamed over it when complete).

use std::io::Write;
use std::path::{Path, PathBuf};

use bearing_core::FilmKind;
use bearing_host_common::config::BearingConfig;
use zip::write::SimpleFileOptions;

use crate::model_description::model_description;
use crate::{guid, MODEL_IDENTIFIER, RESOURCE_CONFIG, RESOURCE_FILM};

/// The file name cargo gives this crate's shared library on Linux.
pub const LIBRARY_FILE: &str = "libbearing_fmu.so";

/// The FMI platform directory of the library (`binaries/<platform>/`): only linux64 is built.
pub const PLATFORM: &str = "linux64";

/// The shared library next to the executable in `exe_dir`: cargo builds it with the `bearing`
/// binary into `target/release/deps/` (a dependency's cdylib is not copied up), and
/// `cargo build --release -p bearing-fmu` also into `target/release/`. Of the two, the newer.
pub fn find_library(exe_dir: &Path) -> Result<PathBuf, String> {
    let candidates = [
        exe_dir.join(LIBRARY_FILE),
        exe_dir.join("deps").join(LIBRARY_FILE),
    ];
    candidates
        .into_iter()
        .filter_map(|p| {
            let modified = std::fs::metadata(&p).and_then(|m| m.modified()).ok()?;
            Some((modified, p))
        })
        .max()
        .map(|(_, p)| p)
        .ok_or_else(|| {
            format!(
                "--library: {LIBRARY_FILE} is neither in {0} nor in {0}/deps; build it with \
                 `cargo build --release -p bearing-fmu` (or build `bearing` with cargo, which \
                 builds it too) or name it with --library <path>",
                exe_dir.display()
            )
        })
}

/// What was written.
#[derive(Debug)]
pub struct Written {
    /// The FMU's GUID.
    pub guid: String,
    /// Bytes of the archive.
    pub bytes: u64,
}

/// Write the FMU of the bearing file `config_path` stepping with `film` to `out`, with the
/// shared library `library`. Every refusal names the file.
pub fn write_fmu(
    config_path: &Path,
    film: FilmKind,
    library: &Path,
    out: &Path,
) -> Result<Written, String> {
    if !cfg!(all(target_os = "linux", target_arch = "x86_64")) {
        return Err(format!(
            "bearing fmu export builds {PLATFORM} FMUs only, on x86-64 Linux"
        ));
    }
    let text = std::fs::read_to_string(config_path)
        .map_err(|e| format!("{}: cannot read: {e}", config_path.display()))?;
    let (config, _) = BearingConfig::parse(&text, config_path).map_err(|e| e.to_string())?;
    let library_bytes = std::fs::read(library)
        .map_err(|e| format!("--library {}: cannot read: {e}", library.display()))?;
    let guid = guid(&text, film);
    let design = config.design().map_err(|e| e.to_string())?;
    let xml = model_description(&config.name, &design, film, &guid);

    let dir = match out.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    let name_error = |e: &dyn std::fmt::Display| format!("--out {}: {e}", out.display());
    let temp = tempfile::Builder::new()
        .prefix(".bearing-fmu-")
        .suffix(".tmp")
        .tempfile_in(dir)
        .map_err(|e| name_error(&e))?;
    let mut zip = zip::ZipWriter::new(temp);
    let options = SimpleFileOptions::default().compression_method(zip::CompressionMethod::Deflated);
    let film_text = format!("{}\n", film.name());
    let entries: [(String, &[u8]); 4] = [
        ("modelDescription.xml".into(), xml.as_bytes()),
        (
            format!("binaries/{PLATFORM}/{MODEL_IDENTIFIER}.so"),
            &library_bytes,
        ),
        (format!("resources/{RESOURCE_CONFIG}"), text.as_bytes()),
        (format!("resources/{RESOURCE_FILM}"), film_text.as_bytes()),
    ];
    for (name, bytes) in entries {
        zip.start_file(name, options).map_err(|e| name_error(&e))?;
        zip.write_all(bytes).map_err(|e| name_error(&e))?;
    }
    let temp = zip.finish().map_err(|e| name_error(&e))?;
    temp.as_file().sync_all().map_err(|e| name_error(&e))?;
    let file = temp.persist(out).map_err(|e| name_error(&e.error))?;
    let bytes = file.metadata().map_err(|e| name_error(&e))?.len();
    Ok(Written { guid, bytes })
}
