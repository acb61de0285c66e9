//! `bearing shaft sweep`: steady-state runs over a list of speeds, lubricated and dry side by
//! side, with envelope, waterfall and power-loss plots and the lubricated-versus-dry
//! comparison.

use std::sync::atomic::{AtomicUsize, Ordering};

use anyhow::{bail, Context, Result};
use bearing_host_common::output::OutputFiles;
use bearing_shaft::bearing::{BearingSpec, FilmKind};
use bearing_shaft::model::RotorModel;
use bearing_shaft::plots;
use bearing_shaft::sweep::{hub_motor_speeds_rpm, sweep, FilmComparison, SweepPoint};
use std::path::PathBuf;

use super::run::spectrum_orders;
use super::{check, load, mesh_orders, rpm_to_rad, settings, with_suffix, SweepArgs};

pub(super) fn cmd_sweep(a: SweepArgs) -> Result<()> {
    let model = load(&a.model)?;
    let speeds = match &a.speeds_rpm {
        Some(v) => v
            .iter()
            .map(|&s| check("speeds-rpm", s, 0.0, 1e6, true))
            .collect::<Result<Vec<_>>>()?,
        None => hub_motor_speeds_rpm(),
    };
    if speeds.is_empty() {
        bail!("--speeds-rpm is empty: give at least one speed");
    }
    // Validate the time settings once (at the top speed) so a bad flag fails before the runs.
    let top = speeds.iter().copied().fold(0.0, f64::max);
    settings(&model, &a.time, rpm_to_rad(top))?;
    if model.description.bearings.iter().any(|b| {
        matches!(
            b.spec,
            BearingSpec::Roller {
                film: FilmKind::Dry,
                ..
            }
        )
    }) {
        bail!("--film / the shaft file give dry bearings: sweep runs the lubricated film against dry, choose a film");
    }
    let bar = indicatif::ProgressBar::new(2 * speeds.len() as u64);
    bar.set_style(indicatif::ProgressStyle::with_template(
        "{bar:40} {pos}/{len} runs, {elapsed} (eta {eta})",
    )?);
    if a.model.json {
        bar.set_draw_target(indicatif::ProgressDrawTarget::stderr());
    }
    let done = AtomicUsize::new(0);
    let time = &a.time;
    let settings_at = |omega: f64| settings(&model, time, omega).expect("validated above");
    let points = sweep(&model, &speeds, &settings_at, None, &|| {
        done.fetch_add(1, Ordering::Relaxed);
        bar.inc(1);
    })?;
    bar.finish_and_clear();
    let (waterfalls, power_png) = write_plots(&a, &model, &points, top)?;
    let mesh = mesh_orders(&model)
        .into_iter()
        .fold(None, |m: Option<f64>, o| Some(m.map_or(o, |m| m.max(o))));
    let comparison = bearing_shaft::sweep::compare_films(&points, top, mesh);
    if a.model.json {
        println!("{}", sweep_json(&points, comparison.as_ref()));
        return Ok(());
    }
    print_table(&points, comparison.as_ref(), mesh);
    println!(
        "plots: {}, {}, {}",
        a.plot.display(),
        waterfalls.join(", "),
        power_png.display()
    );
    Ok(())
}

/// The envelope, the two waterfalls and the power-loss plot of a sweep, all or none; returns the
/// waterfalls' paths and the power-loss plot's path.
fn write_plots(
    a: &SweepArgs,
    model: &RotorModel,
    points: &[SweepPoint],
    top: f64,
) -> Result<(Vec<String>, PathBuf)> {
    // The four plots or none: staged under temporary names, renamed at the end.
    let mut files = OutputFiles::new();
    let mut stage = |path: &std::path::Path| {
        files
            .stage(path)
            .with_context(|| format!("writing {}", path.display()))
    };
    plots::envelopes(points, &stage(&a.plot)?)
        .map_err(|e| anyhow::anyhow!("writing {}: {e}", a.plot.display()))?;
    let orders = spectrum_orders(model, 1.0)?;
    let top_hz = top / 60.0;
    let f_max = 1.3 * orders.iter().map(|o| o.1).fold(1.0, f64::max) * top_hz;
    let mut waterfalls = Vec::new();
    for (side, name) in [(0, "lubricated"), (1, "dry")] {
        let rows: Vec<plots::WaterfallRow> = points
            .iter()
            .map(|p| (p.speed_rpm, p.spectra[side].clone()))
            .collect();
        let highest_nyquist = points
            .iter()
            .filter_map(|p| p.spectra[side].last().map(|x| x.0))
            .fold(0.0, f64::max);
        let png = with_suffix(
            &a.plot.with_extension(""),
            &format!("_waterfall_{name}.png"),
        );
        plots::waterfall(
            &rows,
            &orders,
            f_max.min(highest_nyquist),
            &format!("inner-race y displacement, bearing 0, {name}"),
            &stage(&png)?,
        )
        .map_err(|e| anyhow::anyhow!("writing {}: {e}", png.display()))?;
        waterfalls.push(png.display().to_string());
    }
    let power_png = with_suffix(&a.plot.with_extension(""), "_power_loss.png");
    plots::power_loss(points, &stage(&power_png)?)
        .map_err(|e| anyhow::anyhow!("writing {}: {e}", power_png.display()))?;
    files.commit()?;
    Ok((waterfalls, power_png))
}

/// The `--json` form of a sweep: each quantity as one array over the speeds, per film.
fn sweep_json(points: &[SweepPoint], comparison: Option<&FilmComparison>) -> serde_json::Value {
    let split = |lub: bool| {
        let part = |i: usize| {
            points
                .iter()
                .map(|p| p.friction[usize::from(!lub)].map(|f| f.power_loss_split_w[i]))
                .collect::<Vec<_>>()
        };
        serde_json::json!({"rolling": part(0), "viscous": part(1), "boundary": part(2)})
    };
    let side = |lub: bool| {
        let e = |p: &bearing_shaft::sweep::SweepPoint| if lub { p.lubricated } else { p.dry };
        serde_json::json!({
            "max_contact_force_n": points.iter().map(|p| e(p).max_contact_force_n).collect::<Vec<_>>(),
            "max_contact_stiffness_n_per_m": points.iter().map(|p| e(p).max_contact_stiffness_n_per_m).collect::<Vec<_>>(),
            "max_bearing_stiffness_n_per_m": points.iter().map(|p| e(p).max_bearing_stiffness_n_per_m).collect::<Vec<_>>(),
            "max_central_film_m": points.iter().map(|p| e(p).max_central_film_m).collect::<Vec<_>>(),
            "max_displacement_m": points.iter().map(|p| e(p).max_displacement_m).collect::<Vec<_>>(),
            "max_acceleration_m_s2": points.iter().map(|p| e(p).max_acceleration_m_s2).collect::<Vec<_>>(),
            "steadiness": points.iter().map(|p| p.steadiness[usize::from(!lub)]).collect::<Vec<_>>(),
            "resolution_limited_steps": points.iter().map(|p| p.resolution_limited_steps[usize::from(!lub)]).collect::<Vec<_>>(),
            "natural_frequencies_hz": points.iter().map(|p| p.natural_frequencies_hz[usize::from(!lub)].clone()).collect::<Vec<_>>(),
            "friction_torque_nm": points.iter().map(|p| p.friction[usize::from(!lub)].map(|f| f.torque_nm)).collect::<Vec<_>>(),
            "power_loss_w": points.iter().map(|p| p.friction[usize::from(!lub)].map(|f| f.power_loss_w)).collect::<Vec<_>>(),
            "power_loss_split_w": split(lub),
        })
    };
    let speeds: Vec<f64> = points.iter().map(|p| p.speed_rpm).collect();
    serde_json::json!({"speeds_rpm": speeds, "lubricated": side(true), "dry": side(false),
        "comparison": comparison})
}

/// The text form of a sweep: one row per speed, then the lubricated-versus-dry comparison.
fn print_table(points: &[SweepPoint], comparison: Option<&FilmComparison>, mesh: Option<f64>) {
    println!(
        "{:>8} {:>13} {:>13} {:>11} {:>11} {:>11} {:>11} {:>9} {:>11} {:>11} {:>9}",
        "rpm",
        "k_b lub (N/m)",
        "k_b dry (N/m)",
        "h_c (µm)",
        "u lub (µm)",
        "u dry (µm)",
        "f1 lub (Hz)",
        "f1 dry",
        "P lub (W)",
        "P dry (W)",
        "steady"
    );
    let power = |p: &bearing_shaft::sweep::SweepPoint, side: usize| {
        p.friction[side].map_or(f64::NAN, |f| f.power_loss_w)
    };
    let f1 = |p: &bearing_shaft::sweep::SweepPoint, side: usize| {
        p.natural_frequencies_hz[side]
            .first()
            .copied()
            .unwrap_or(f64::NAN)
    };
    for p in points {
        println!(
            "{:>8.0} {:>13.4e} {:>13.4e} {:>11.4} {:>11.4} {:>11.4} {:>11.2} {:>9.2} {:>11.2} {:>11.2} {:>9.1e}",
            p.speed_rpm,
            p.lubricated.max_bearing_stiffness_n_per_m,
            p.dry.max_bearing_stiffness_n_per_m,
            p.lubricated.max_central_film_m.unwrap_or(f64::NAN) * 1e6,
            p.lubricated.max_displacement_m * 1e6,
            p.dry.max_displacement_m * 1e6,
            f1(p, 0),
            f1(p, 1),
            power(p, 0),
            power(p, 1),
            p.steadiness[0].max(p.steadiness[1])
        );
    }
    if let Some(c) = comparison {
        let opt = |v: Option<f64>| v.map_or("none in the sweep".to_string(), |x| format!("{x:.0}"));
        println!("lubricated vs dry at {:.0} rpm:", c.speed_rpm);
        println!(
            "  central film {} µm; bearing stiffness {:.4e} vs {:.4e} N/m ({:+.1} %)",
            c.central_film_m
                .map_or("-".to_string(), |h| format!("{:.4}", h * 1e6)),
            c.bearing_stiffness_n_per_m[0],
            c.bearing_stiffness_n_per_m[1],
            100.0 * c.stiffness_increase
        );
        println!(
            "  first natural frequency {:.2} vs {:.2} Hz (shift {:+.2} Hz, {:+.2} %)",
            c.first_natural_frequency_hz[0],
            c.first_natural_frequency_hz[1],
            c.first_natural_frequency_shift_hz,
            100.0 * c.first_natural_frequency_shift_hz / c.first_natural_frequency_hz[1]
        );
        println!(
            "  {}× crossing of the first natural frequency: {} vs {} rpm; largest response at {:.0} vs {:.0} rpm",
            mesh.unwrap_or(1.0),
            opt(c.order_critical_speed_rpm[0]),
            opt(c.order_critical_speed_rpm[1]),
            c.peak_response_speed_rpm[0],
            c.peak_response_speed_rpm[1]
        );
    }
    println!(
        "P: power loss of the roller bearings at the static equilibrium of each speed; dry: the \
         dry bearing's roller loads with the regression film at those loads (docs/shaft.md)"
    );
}
