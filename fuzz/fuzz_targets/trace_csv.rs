//! Fuzz target `trace_csv`: see [`checks::trace_csv`].
#![no_main]

#[path = "../src/checks.rs"]
mod checks;

libfuzzer_sys::fuzz_target!(|data: &[u8]| checks::trace_csv(data));
