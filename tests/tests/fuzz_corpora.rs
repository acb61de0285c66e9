//! Every saved input of the fuzz targets (`fuzz/corpus/<target>/`: the seeds, and each input a
//! fuzzing run found crashing, kept as a regression) through the target's checks, on the
//! stable toolchain: what CI runs of the fuzzing (docs/reliability.md), without cargo-fuzz.

#[path = "../../fuzz/src/checks.rs"]
mod checks;

use std::path::PathBuf;

fn run_corpus(target: &str, check: fn(&[u8])) {
    let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../fuzz/corpus")
        .join(target);
    let mut count = 0;
    for entry in std::fs::read_dir(&dir).unwrap_or_else(|e| panic!("{}: {e}", dir.display())) {
        let path = entry.unwrap().path();
        let data = std::fs::read(&path).unwrap();
        let result = std::panic::catch_unwind(|| check(&data));
        assert!(result.is_ok(), "{target}: {} fails", path.display());
        count += 1;
    }
    assert!(count > 0, "{target}: empty corpus");
}

#[test]
fn trace_binary_corpus() {
    run_corpus("trace_binary", checks::trace_binary);
}

#[test]
fn trace_csv_corpus() {
    run_corpus("trace_csv", checks::trace_csv);
}

#[test]
fn bearing_toml_corpus() {
    run_corpus("bearing_toml", checks::bearing_toml);
}

#[test]
fn shaft_toml_corpus() {
    run_corpus("shaft_toml", checks::shaft_toml);
}

#[test]
fn core_step_corpus() {
    run_corpus("core_step", checks::core_step);
}
