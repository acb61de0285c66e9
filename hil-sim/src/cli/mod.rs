//! Subcommands of `hil-sim`, one module each, plus the argument checks they share.

pub mod qemu_cmd;
pub mod replay_cmd;
pub mod trace_cmd;

use anyhow::{bail, Result};

/// Refuses a non-finite value or one outside `[min, max]`, naming the flag and the range.
pub fn check_range(flag: &str, value: f64, min: f64, max: f64) -> Result<f64> {
    if !value.is_finite() || value < min || value > max {
        bail!("{flag} = {value} is out of range: allowed {min} ..= {max}");
    }
    Ok(value)
}
