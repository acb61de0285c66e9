//! CSV output of a time response: the full record (probe displacements, velocities,
//! accelerations; bearing forces, stiffness and roller diagnostics) and, per bearing, the
//! recorded inner-race kinematics trace (time, displacement, velocity, spin speed) that a
//! bearing-in-the-loop replay feeds to the core's bearing step (hil-sim's trace CSV format).

use std::io::Write;
use std::path::Path;

use crate::analysis::simulate::RunResult;

/// Writes the full record. Columns: `t_s`, then per probe node `n{k}_x_m, n{k}_y_m, n{k}_vx_m_s,
/// n{k}_vy_m_s, n{k}_ax_m_s2, n{k}_ay_m_s2`, then per bearing `b{i}_fx_n, b{i}_fy_n,
/// b{i}_kxx_n_per_m, b{i}_kxy_n_per_m, b{i}_kyx_n_per_m, b{i}_kyy_n_per_m,
/// b{i}_max_contact_force_n, b{i}_max_contact_stiffness_n_per_m, b{i}_max_central_film_m`
/// (the last three empty without roller data).
pub fn write_run_csv(path: &Path, result: &RunResult) -> std::io::Result<()> {
    let mut w = std::io::BufWriter::new(std::fs::File::create(path)?);
    let mut header = vec!["t_s".to_string()];
    for n in &result.probe_nodes {
        for q in ["x_m", "y_m", "vx_m_s", "vy_m_s", "ax_m_s2", "ay_m_s2"] {
            header.push(format!("n{n}_{q}"));
        }
    }
    let n_bearings = result.samples.first().map_or(0, |s| s.bearings.len());
    for b in 0..n_bearings {
        for q in [
            "fx_n",
            "fy_n",
            "kxx_n_per_m",
            "kxy_n_per_m",
            "kyx_n_per_m",
            "kyy_n_per_m",
            "max_contact_force_n",
            "max_contact_stiffness_n_per_m",
            "max_central_film_m",
        ] {
            header.push(format!("b{b}_{q}"));
        }
    }
    writeln!(w, "{}", header.join(","))?;
    for s in &result.samples {
        let mut row = vec![format!("{:.9e}", s.time)];
        for p in &s.probes {
            for v in p.iter().flatten() {
                row.push(format!("{v:.9e}"));
            }
        }
        for r in &s.bearings {
            row.push(format!("{:.9e}", r.force[0]));
            row.push(format!("{:.9e}", r.force[1]));
            for k in r.stiffness.iter().flatten() {
                row.push(format!("{k:.9e}"));
            }
            match r.rollers {
                Some(d) => {
                    row.push(format!("{:.9e}", d.max_contact_force));
                    row.push(format!("{:.9e}", d.max_contact_stiffness));
                    row.push(format!("{:.9e}", d.max_central_film));
                }
                None => row.extend(["".to_string(), "".to_string(), "".to_string()]),
            }
        }
        writeln!(w, "{}", row.join(","))?;
    }
    w.flush()
}

/// Writes the inner-race kinematics of bearing `probe` in the trace CSV format of `hil-sim`
/// (hil-sim/trace/src/csv.rs): `# bearing: <id>`, `# lubricant: <id>`, `# sample_rate_hz: <1/Δt>`,
/// then `time_s,speed_rad_s,x_m,y_m,vx_m_s,vy_m_s`, time from 0 at the first recorded sample,
/// speed the spin speed at each sample (it changes along a ramp).
pub fn write_kinematics_trace(
    path: &Path,
    result: &RunResult,
    probe: usize,
    ids: (&str, &str),
    sample_interval: f64,
) -> std::io::Result<()> {
    let mut w = std::io::BufWriter::new(std::fs::File::create(path)?);
    writeln!(w, "# bearing: {}", ids.0)?;
    writeln!(w, "# lubricant: {}", ids.1)?;
    // 1/Δt rounded to an integer when it is one up to rounding (1/10⁻⁵ s is 99999.99999999999
    // in f64): the header then states the rate that was meant.
    let rate = 1.0 / sample_interval;
    let rate = if (rate - rate.round()).abs() <= 1e-9 * rate {
        rate.round()
    } else {
        rate
    };
    writeln!(w, "# sample_rate_hz: {rate}")?;
    writeln!(w, "# inner-race kinematics from `bearing shaft run`")?;
    writeln!(w, "time_s,speed_rad_s,x_m,y_m,vx_m_s,vy_m_s")?;
    for (k, s) in result.samples.iter().enumerate() {
        let p = s.probes[probe];
        // Time as k·Δt: exact spacing for the replay's gap check.
        writeln!(
            w,
            "{},{},{},{},{},{}",
            k as f64 * sample_interval,
            s.spin_speed as f32,
            p[0][0] as f32,
            p[0][1] as f32,
            p[1][0] as f32,
            p[1][1] as f32
        )?;
    }
    w.flush()
}

/// Writes the per-roller record of bearing `bearing` when its model has rollers: columns `t_s`,
/// then per roller j `r{j}_angle_rad, r{j}_load_n, r{j}_film_in_m, r{j}_film_out_m`.
/// Returns false (and writes nothing) for a model without rollers.
pub fn write_roller_csv(path: &Path, result: &RunResult, bearing: usize) -> std::io::Result<bool> {
    let Some(Some(first)) = result.samples.first().map(|s| &s.rollers[bearing]) else {
        return Ok(false);
    };
    let mut w = std::io::BufWriter::new(std::fs::File::create(path)?);
    let mut header = vec!["t_s".to_string()];
    for j in 0..first.len() {
        for q in ["angle_rad", "load_n", "film_in_m", "film_out_m"] {
            header.push(format!("r{j}_{q}"));
        }
    }
    writeln!(w, "{}", header.join(","))?;
    for s in &result.samples {
        let mut row = vec![format!("{:.9e}", s.time)];
        for r in s.rollers[bearing].iter().flatten() {
            row.push(format!("{:.6e}", r.angle));
            row.push(format!("{:.6e}", r.load));
            row.push(format!("{:.6e}", r.central_film_inner));
            row.push(format!("{:.6e}", r.central_film_outer));
        }
        writeln!(w, "{}", row.join(","))?;
    }
    w.flush()?;
    Ok(true)
}
