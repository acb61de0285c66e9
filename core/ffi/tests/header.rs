//! The committed header `include/bearing.h` is what cbindgen makes of the crate now; a stale
//! header fails here. The generator is `core/ffi/header`, a workspace of its own (see its
//! Cargo.toml for why), built and run by this test into `target/ffi-header`;
//! `BEARING_FFI_WRITE_HEADER=1 cargo test -p bearing-ffi --test header` rewrites the header.

use std::path::Path;
use std::process::Command;

#[test]
fn committed_header_is_current() {
    let ffi = Path::new(env!("CARGO_MANIFEST_DIR"));
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut command = Command::new(cargo);
    command
        .args(["run", "--release", "--quiet", "--manifest-path"])
        .arg(ffi.join("header/Cargo.toml"))
        .arg("--target-dir")
        .arg(ffi.join("../../target/ffi-header"))
        // The enclosing cargo's settings are not the generator's.
        .env_remove("RUSTFLAGS")
        .env_remove("CARGO_ENCODED_RUSTFLAGS")
        .env_remove("CARGO_BUILD_TARGET")
        .env_remove("CARGO_TARGET_DIR");
    if std::env::var_os("BEARING_FFI_WRITE_HEADER").is_some() {
        command.args(["--", "--write"]);
    }
    let out = command.output().expect("cannot run cargo");
    assert!(
        out.status.success(),
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
}
