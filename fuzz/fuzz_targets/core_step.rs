//! Fuzz target `core_step`: see [`checks::core_step`].
#![no_main]

#[path = "../src/checks.rs"]
mod checks;

libfuzzer_sys::fuzz_target!(|data: &[u8]| checks::core_step(data));
