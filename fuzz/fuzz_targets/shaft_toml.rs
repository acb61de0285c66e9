//! Fuzz target `shaft_toml`: see [`checks::shaft_toml`].
#![no_main]

#[path = "../src/checks.rs"]
mod checks;

libfuzzer_sys::fuzz_target!(|data: &[u8]| checks::shaft_toml(data));
