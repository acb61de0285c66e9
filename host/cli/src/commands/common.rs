//! Helpers shared by the subcommands: number parsing with clear messages, JSON output.

/// clap value parser: a finite number > 0.
pub fn positive(s: &str) -> Result<f64, String> {
    let v: f64 = s
        .trim()
        .parse()
        .map_err(|_| format!("`{s}` is not a number"))?;
    if v.is_finite() && v > 0.0 {
        Ok(v)
    } else {
        Err(format!(
            "{s} is not allowed: it must be a finite number > 0"
        ))
    }
}

/// clap value parser: a finite number ≥ 0.
pub fn non_negative(s: &str) -> Result<f64, String> {
    let v: f64 = s
        .trim()
        .parse()
        .map_err(|_| format!("`{s}` is not a number"))?;
    if v.is_finite() && v >= 0.0 {
        Ok(v)
    } else {
        Err(format!(
            "{s} is not allowed: it must be a finite number >= 0"
        ))
    }
}

/// Print a JSON value, pretty, on stdout.
pub fn print_json(value: &serde_json::Value) -> anyhow::Result<()> {
    println!("{}", serde_json::to_string_pretty(value)?);
    Ok(())
}

/// rpm → rad/s.
pub fn rad_per_s(rpm: f64) -> f32 {
    (rpm * std::f64::consts::PI / 30.0) as f32
}
