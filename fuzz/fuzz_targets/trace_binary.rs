//! Fuzz target `trace_binary`: see [`checks::trace_binary`].
#![no_main]

#[path = "../src/checks.rs"]
mod checks;

libfuzzer_sys::fuzz_target!(|data: &[u8]| checks::trace_binary(data));
