//! `bearing film --contact point`: film thickness and Hertz figures of one ball–race point
//! contact, every film model side by side — the numerical solution (`bearing_ehl::point`,
//! Richardson films), the core's f32 and integer point networks (with their source: network or
//! Hamrock–Dowson fallback), the core's Hamrock–Dowson films and Nijenbanning–Venner–Moes'
//! central film — with each model's error against the numerical one (docs/point_contact.md).

use anyhow::{anyhow, bail, Result};
use bearing_core::film::ann::{PointAnnF32, PointAnnInt};
use bearing_core::film::point::HamrockDowson;
use bearing_core::film::{Film, FilmModel, FilmSource, PointContactInput};
use bearing_ehl::point::{self, formulas, hertz, PointContactCase, PointSolverOptions};
use bearing_ehl::EhlError;
use serde_json::json;

use super::{FilmArgs, MAX_HERTZ_PRESSURE_PA};
use crate::commands::common::print_json;

/// Range of `--ellipticity` (as `bearing ehl solve --contact point`).
const ELLIPTICITY_RANGE: (f64, f64) = (1.0, 12.0);

/// The flag of a `PointContactCase` field.
fn flag_of(field: &str) -> &'static str {
    match field {
        "load_n" => "--load",
        "entrainment_speed_m_s" => "--entrainment",
        "radius_x_m" => "--radius",
        "radius_y_m" => "--radius-y",
        "radius_ratio" => "--radius-y / --radius (R_y/R_x)",
        "reduced_modulus_pa" => "--modulus",
        "pressure_viscosity_pa_inv" => "--alpha",
        "viscosity_pa_s" => "--eta0",
        _ => "the contact",
    }
}

/// The case of the flags, refusals naming the flag and the allowed range.
fn point_case(args: &FilmArgs) -> Result<PointContactCase> {
    if args.length.is_some() {
        bail!("--length is not used by --contact point (--load is the contact force in N)");
    }
    if args.plot.is_some() {
        bail!("--plot draws line contacts only; for a point contact's maps use `bearing ehl solve --contact point --plot`");
    }
    if args.radius_y.is_some() && args.ellipticity.is_some() {
        bail!("give --radius-y or --ellipticity, not both");
    }
    let si = [
        ("--load", args.load),
        ("--entrainment", args.entrainment),
        ("--radius", args.radius),
        ("--modulus", args.modulus),
        ("--alpha", args.alpha),
        ("--eta0", args.eta0),
    ];
    let missing: Vec<&str> = si
        .iter()
        .filter(|(_, v)| v.is_none())
        .map(|(n, _)| *n)
        .collect();
    if !missing.is_empty() {
        bail!("missing {} for --contact point", missing.join(", "));
    }
    let [w, u, rx, e, alpha, eta] = si.map(|(_, v)| v.unwrap_or(0.0));
    let radius_y = match (args.radius_y, args.ellipticity) {
        (Some(r), _) => r,
        (None, k) => {
            let k = k.unwrap_or(1.0);
            let (lo, hi) = ELLIPTICITY_RANGE;
            if !(lo..=hi).contains(&k) {
                bail!("--ellipticity = {k} is out of range: allowed {lo} ..= {hi}");
            }
            rx * hertz::radius_ratio_of_ellipticity(k)
        }
    };
    let case =
        PointContactCase::new(w, u, rx, radius_y, e, alpha, eta).map_err(|err| match err {
            EhlError::InvalidInput {
                field,
                value,
                allowed,
            } => anyhow!(
                "{} = {value:e} is out of range: allowed {allowed}",
                flag_of(field)
            ),
            other => anyhow!("{other}"),
        })?;
    let p_h = case.hertz().max_pressure_pa;
    if p_h > MAX_HERTZ_PRESSURE_PA {
        // p_h ∝ w^⅓ with the rest fixed.
        bail!(
            "--load = {w:e} N gives a peak Hertz pressure of {:.3} GPa: steel carries at most {} GPa \
             (ISO 76 static rating); allowed --load ≤ {:.4e} N for this contact",
            p_h * 1e-9,
            MAX_HERTZ_PRESSURE_PA * 1e-9,
            w * (MAX_HERTZ_PRESSURE_PA / p_h).powi(3)
        );
    }
    Ok(case)
}

/// The core's input for a case (every field checked to fit f32 by `single_precision`).
fn core_input(case: &PointContactCase) -> Result<PointContactInput> {
    let v = |flag: &str, x: f64| super::single_precision(flag, x);
    Ok(PointContactInput {
        load_n: v("--load", case.load_n)?,
        entrainment_speed_m_s: v("--entrainment", case.entrainment_speed_m_s)?,
        radius_x_m: v("--radius", case.radius_x_m)?,
        radius_y_m: v("--radius-y", case.radius_y_m)?,
        reduced_modulus_pa: v("--modulus", case.reduced_modulus_pa)?,
        pressure_viscosity_pa_inv: v("--alpha", case.pressure_viscosity_pa_inv)?,
        viscosity_pa_s: v("--eta0", case.viscosity_pa_s)?,
    })
}

/// Stable name of a film source in the JSON.
pub(crate) fn source_name(s: FilmSource) -> &'static str {
    match s {
        FilmSource::None => "none",
        FilmSource::Regression => "regression",
        FilmSource::NetworkF32 => "network_f32",
        FilmSource::NetworkInt => "network_int",
        FilmSource::Fallback => "fallback",
    }
}

/// Every film model's answer for one point contact.
fn report(case: &PointContactCase, contact: &PointContactInput, solve: bool) -> serde_json::Value {
    let numerical = solve.then(|| point::solve_point(case, &PointSolverOptions::default()));
    let reference = match &numerical {
        Some(Ok(s)) => Some((s.central_film_m, s.min_film_m)),
        _ => None,
    };
    let rel = |h: Option<f64>, r: Option<f64>| match (h, r) {
        (Some(h), Some(r)) => Some((h - r) / r),
        _ => None,
    };
    let entry = |name: &str, central: f64, minimum: Option<f64>, source: &str| {
        json!({
            "name": name, "central_film_m": central, "min_film_m": minimum, "source": source,
            "fell_back": source == "fallback",
            "central_rel_err_vs_numerical": rel(Some(central), reference.map(|r| r.0)),
            "min_rel_err_vs_numerical": rel(minimum, reference.map(|r| r.1)),
        })
    };
    let core_entry = |name: &str, f: Film| {
        entry(
            name,
            f64::from(f.central_m),
            Some(f64::from(f.minimum_m)),
            source_name(f.source),
        )
    };
    let numerical_entry = match &numerical {
        Some(Ok(s)) => json!({
            "name": "numerical", "central_film_m": s.central_film_m, "min_film_m": s.min_film_m,
            "source": "solver", "fell_back": false, "richardson": s.richardson,
            "central_rel_err_vs_numerical": 0.0, "min_rel_err_vs_numerical": 0.0,
            "iterations": s.iterations, "nodes": s.nodes, "wall_time_s": s.wall_time_s,
        }),
        Some(Err(e)) => json!({"name": "numerical", "central_film_m": null, "min_film_m": null,
                               "source": "solver", "fell_back": false, "error": e.to_string()}),
        None => json!({"name": "numerical", "central_film_m": null, "min_film_m": null,
                       "source": "solver", "fell_back": false, "error": "not solved (--no-solver)"}),
    };
    let h = case.hertz();
    json!({
        "contact": "point",
        "input": {
            "load_n": case.load_n, "entrainment_speed_m_s": case.entrainment_speed_m_s,
            "radius_x_m": case.radius_x_m, "radius_y_m": case.radius_y_m,
            "reduced_modulus_pa": case.reduced_modulus_pa,
            "pressure_viscosity_pa_inv": case.pressure_viscosity_pa_inv,
            "viscosity_pa_s": case.viscosity_pa_s,
        },
        "dimensionless": {
            "w": case.load_parameter(), "u": case.speed_parameter(), "g": case.material_parameter(),
            "m": case.moes_m(), "l": case.moes_l(), "ellipticity": h.ellipticity,
        },
        "hertz": {
            "max_pressure_pa": h.max_pressure_pa, "semi_axis_rolling_m": h.semi_axis_rolling_m,
            "semi_axis_transverse_m": h.semi_axis_transverse_m, "ellipticity": h.ellipticity,
        },
        "models": [
            numerical_entry,
            core_entry("ann_f32", PointAnnF32.film(contact)),
            core_entry("ann_int", PointAnnInt.film(contact)),
            core_entry("hamrock_dowson", HamrockDowson.film(contact)),
            entry("nijenbanning", formulas::nijenbanning_central_film_m(case), None, "formula"),
        ],
    })
}

fn print_human(r: &serde_json::Value) {
    let f = |v: &serde_json::Value| v.as_f64().unwrap_or(f64::NAN);
    let d = &r["dimensionless"];
    println!("Point contact");
    println!(
        "  W = {:.3e}  U = {:.3e}  G = {:.0}  M = {:.3}  L = {:.3}  k = {:.4}",
        f(&d["w"]),
        f(&d["u"]),
        f(&d["g"]),
        f(&d["m"]),
        f(&d["l"]),
        f(&d["ellipticity"])
    );
    let h = &r["hertz"];
    println!(
        "  Hertz: semi-axes b = {:.2} µm (rolling), a = {:.2} µm, max pressure p_h = {:.3} GPa",
        f(&h["semi_axis_rolling_m"]) * 1e6,
        f(&h["semi_axis_transverse_m"]) * 1e6,
        f(&h["max_pressure_pa"]) * 1e-9
    );
    println!(
        "  {:<15} {:>13} {:>13} {:>13} {:>13}  source",
        "model", "central (nm)", "minimum (nm)", "h_c vs num.", "h_min vs num."
    );
    let pct = |v: &serde_json::Value| {
        v.as_f64()
            .map_or("–".to_string(), |e| format!("{:+.2} %", e * 100.0))
    };
    for m in r["models"].as_array().into_iter().flatten() {
        let nm = |v: &serde_json::Value| {
            v.as_f64()
                .map_or("–".to_string(), |h| format!("{:.1}", h * 1e9))
        };
        let note = match (m["fell_back"].as_bool(), m["error"].as_str()) {
            (Some(true), _) => {
                " (outside the network's domain: Hamrock–Dowson fallback)".to_string()
            }
            (_, Some(e)) => format!(" ({e})"),
            _ => String::new(),
        };
        println!(
            "  {:<15} {:>13} {:>13} {:>13} {:>13}  {}{note}",
            m["name"].as_str().unwrap_or("?"),
            nm(&m["central_film_m"]),
            nm(&m["min_film_m"]),
            pct(&m["central_rel_err_vs_numerical"]),
            pct(&m["min_rel_err_vs_numerical"]),
            m["source"].as_str().unwrap_or("?"),
        );
    }
}

/// Run `bearing film --contact point`.
pub fn run(args: &FilmArgs) -> Result<()> {
    let case = point_case(args)?;
    let contact = core_input(&case)?;
    let r = report(&case, &contact, !args.no_solver);
    if args.json {
        print_json(&r)
    } else {
        print_human(&r);
        Ok(())
    }
}

/// `bearing film --config <ball config> --speed-rpm R --ball-load N`: both contacts of a ball
/// at the nominal contact angle, every film model side by side.
pub fn run_ball(args: &FilmArgs, path: &std::path::Path) -> Result<()> {
    let (config, params) = bearing_host_common::ball_config::BallBearingConfig::load(path)?;
    let Some(load) = args.ball_load else {
        bail!("--ball-load N is required with a ball-bearing --config");
    };
    if args.roller_load.is_some() {
        bail!("--roller-load applies to roller-bearing configs: give --ball-load N");
    }
    let rpm = args.speed_rpm.unwrap_or(0.0);
    if rpm > super::max_speed_rpm() {
        bail!(
            "--speed-rpm = {rpm:e} is out of range: allowed (0, {:.0}] rpm",
            super::max_speed_rpm()
        );
    }
    let contacts = params.contact_inputs(load as f32, crate::commands::common::rad_per_s(rpm));
    let mut reports = Vec::new();
    for contact in contacts {
        let case = PointContactCase {
            load_n: f64::from(contact.load_n),
            entrainment_speed_m_s: f64::from(contact.entrainment_speed_m_s),
            radius_x_m: f64::from(contact.radius_x_m),
            radius_y_m: f64::from(contact.radius_y_m),
            reduced_modulus_pa: f64::from(contact.reduced_modulus_pa),
            pressure_viscosity_pa_inv: f64::from(contact.pressure_viscosity_pa_inv),
            viscosity_pa_s: f64::from(contact.viscosity_pa_s),
        };
        reports.push(report(&case, &contact, !args.no_solver));
    }
    let [inner, outer] = <[serde_json::Value; 2]>::try_from(reports)
        .map_err(|_| anyhow!("two contacts expected"))?;
    if args.json {
        return print_json(&json!({
            "bearing": config.name,
            "speed_rpm": rpm,
            "ball_load_n": load,
            "inner": inner,
            "outer": outer,
        }));
    }
    println!("{}: ball load {load} N at {rpm} rpm", config.name);
    println!("inner contact:");
    print_human(&inner);
    println!("outer contact:");
    print_human(&outer);
    Ok(())
}
