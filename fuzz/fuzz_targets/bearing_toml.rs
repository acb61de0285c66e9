//! Fuzz target `bearing_toml`: see [`checks::bearing_toml`].
#![no_main]

#[path = "../src/checks.rs"]
mod checks;

libfuzzer_sys::fuzz_target!(|data: &[u8]| checks::bearing_toml(data));
