//! The committed header `include/bearing.h` is what cbindgen makes of the crate now; a stale
//! header fails here. `BEARING_FFI_WRITE_HEADER=1 cargo test -p bearing-ffi --test header`
//! rewrites it.

use std::path::Path;

#[test]
fn committed_header_is_current() {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(crate_dir.join("cbindgen.toml")).unwrap();
    let bindings = cbindgen::Builder::new()
        .with_crate(crate_dir)
        .with_config(config)
        .generate()
        .unwrap();
    let mut generated = Vec::new();
    bindings.write(&mut generated);
    let path = crate_dir.join("include/bearing.h");
    if std::env::var_os("BEARING_FFI_WRITE_HEADER").is_some() {
        std::fs::write(&path, &generated).unwrap();
    }
    let committed = std::fs::read(&path).unwrap_or_default();
    assert!(
        committed == generated,
        "{} is stale: regenerate it with `BEARING_FFI_WRITE_HEADER=1 cargo test -p bearing-ffi \
         --test header` and commit it",
        path.display()
    );
}
