//! `bearing-ffi-header [--write]`: generates the C header of `bearing-ffi` (core/ffi) with
//! cbindgen from the crate's source and `core/ffi/cbindgen.toml`, and compares it with the
//! committed `core/ffi/include/bearing.h`: exit 0 when they are equal, 1 when the committed
//! file is stale (or, with `--write`, rewrites it), 2 when generation fails. Run by `cargo
//! xtask generate [--check]` with the workspace's other generated files.

use std::path::Path;
use std::process::ExitCode;

fn main() -> ExitCode {
    let write = match std::env::args().nth(1).as_deref() {
        None => false,
        Some("--write") => true,
        Some(other) => {
            eprintln!("unknown argument {other}; usage: bearing-ffi-header [--write]");
            return ExitCode::from(2);
        }
    };
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let config = match cbindgen::Config::from_file(crate_dir.join("cbindgen.toml")) {
        Ok(config) => config,
        Err(e) => {
            eprintln!("core/ffi/cbindgen.toml: {e}");
            return ExitCode::from(2);
        }
    };
    let bindings = match cbindgen::Builder::new()
        .with_crate(&crate_dir)
        .with_config(config)
        .generate()
    {
        Ok(bindings) => bindings,
        Err(e) => {
            eprintln!("cbindgen cannot generate the header: {e}");
            return ExitCode::from(2);
        }
    };
    let mut generated = Vec::new();
    bindings.write(&mut generated);
    let path = crate_dir.join("include/bearing.h");
    if write {
        // Whole or not at all: a sibling file renamed over the header.
        let part = path.with_extension("h.part");
        if let Err(e) =
            std::fs::write(&part, &generated).and_then(|()| std::fs::rename(&part, &path))
        {
            eprintln!("cannot write {}: {e}", path.display());
            return ExitCode::from(2);
        }
        println!("wrote core/ffi/include/bearing.h");
        return ExitCode::SUCCESS;
    }
    match std::fs::read(&path) {
        Ok(committed) if committed == generated => ExitCode::SUCCESS,
        _ => {
            eprintln!(
                "core/ffi/include/bearing.h is stale: regenerate it with `cargo xtask generate \
                 c-header` and commit it"
            );
            ExitCode::from(1)
        }
    }
}
