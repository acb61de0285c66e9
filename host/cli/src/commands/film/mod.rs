//! `bearing film`: film thickness and Hertz figures of one line contact, every film model side
//! by side — the numerical solution, the f32 and integer networks (flagged when they fall back),
//! the regression formulas, Moes and Martin — with each model's error against the numerical one.

use std::path::PathBuf;

use anyhow::{bail, Context};
use bearing_core::contact::HertzLineContact;
use bearing_core::film::ann::{AnnF32, AnnInt};
use bearing_core::film::corrections::{corrected_film_m, FilmCorrections};
use bearing_core::film::{martin_film_m, moes_central, Hydrodynamic, LnGroups};
use bearing_core::{ContactInput, FilmModel, FilmSource, FrictionParams, Regime, Regression};
use bearing_ehl::{self as ehl, ContactCase, EhlError, EhlSolution, SolverOptions};
use clap::Args;
use serde_json::json;

mod plot;
pub(crate) mod point;

use crate::commands::common::{non_negative, positive, print_json, rad_per_s};

use bearing_host_common::config::BearingConfig;
use bearing_host_common::output::write_with;
use plot::PlotOver;

/// Film thickness of a line contact from every available film model.
///
/// Give the contact in SI units (`--load --length --entrainment --radius --modulus --alpha
/// --eta0`, E' as docs/physics.md §1 defines it), or a bearing with `--config FILE --speed-rpm RPM
/// --roller-load N` (both contacts of the roller are shown). `--contact point` takes a ball–race
/// point contact instead (`--load --entrainment --radius --radius-y | --ellipticity --modulus
/// --alpha --eta0`, `point`).
#[derive(Args, Debug)]
pub struct FilmArgs {
    /// Contact kind: line (roller) or point (ball; give --radius-y or --ellipticity).
    #[arg(long, value_enum, default_value = "line", conflicts_with = "config")]
    pub contact: FilmContact,
    /// Point contact: reduced radius across the rolling direction R_y (m), R_y/R_x in [1, 40].
    #[arg(long, value_parser = positive)]
    pub radius_y: Option<f64>,
    /// Point contact: ellipticity k = a/b in [1, 12] (sets R_y from --radius), instead of
    /// --radius-y [default: 1].
    #[arg(long)]
    pub ellipticity: Option<f64>,
    /// Point contact: leave the numerical solver out (≈ 1–2 s per contact).
    #[arg(long)]
    pub no_solver: bool,
    /// Roller load Q (N).
    #[arg(long, value_parser = positive, conflicts_with = "config")]
    pub load: Option<f64>,
    /// Effective contact length l (m).
    #[arg(long, value_parser = positive, conflicts_with = "config")]
    pub length: Option<f64>,
    /// Entrainment speed u_m (m/s).
    #[arg(long, value_parser = positive, conflicts_with = "config")]
    pub entrainment: Option<f64>,
    /// Reduced radius R (m).
    #[arg(long, value_parser = positive, conflicts_with = "config")]
    pub radius: Option<f64>,
    /// Reduced modulus E' (Pa).
    #[arg(long, value_parser = positive, conflicts_with = "config")]
    pub modulus: Option<f64>,
    /// Pressure–viscosity coefficient α (1/Pa).
    #[arg(long, value_parser = non_negative, conflicts_with = "config")]
    pub alpha: Option<f64>,
    /// Ambient viscosity η₀ (Pa·s).
    #[arg(long, value_parser = positive, conflicts_with = "config")]
    pub eta0: Option<f64>,
    /// Bearing configuration (TOML).
    #[arg(long, requires = "speed_rpm")]
    pub config: Option<PathBuf>,
    /// Shaft speed (rpm), with --config.
    #[arg(long, value_parser = positive, requires = "config")]
    pub speed_rpm: Option<f64>,
    /// Roller load (N), with --config of a roller bearing.
    #[arg(long, value_parser = positive, requires = "config")]
    pub roller_load: Option<f64>,
    /// Ball load (N), with --config of a ball bearing: both contacts of a ball at the
    /// nominal contact angle.
    #[arg(long, value_parser = positive, requires = "config")]
    pub ball_load: Option<f64>,
    /// Machine-readable output.
    #[arg(long)]
    pub json: bool,
    /// Also draw the central film of every model against load or speed (PNG), with each
    /// model's error against the numerical solution (with --config: the inner contact).
    #[arg(long, value_name = "FILE.png")]
    pub plot: Option<PathBuf>,
    /// What the plot varies about the contact's own value.
    #[arg(long, value_enum, default_value = "load")]
    pub plot_over: PlotOver,
    /// Points of the plot (each is one numerical solve).
    #[arg(long, default_value_t = 25, value_parser = clap::value_parser!(u16).range(2..=400))]
    pub plot_points: u16,
    /// The plot spans value/F … value·F.
    #[arg(long, default_value_t = 10.0, value_parser = positive)]
    pub plot_span: f64,
}

/// Refuse the point-contact flags on a line contact.
fn refuse_point_flags(args: &FilmArgs) -> anyhow::Result<()> {
    if args.radius_y.is_some() || args.ellipticity.is_some() || args.no_solver {
        bail!("--radius-y, --ellipticity and --no-solver are point-contact flags: use `bearing film --contact point` or a ball-bearing --config");
    }
    Ok(())
}

/// The kind of contact `bearing film` reports.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum FilmContact {
    /// Cylindrical roller: line contact.
    Line,
    /// Ball: circular or elliptical point contact (`point`).
    Point,
}

/// Highest peak Hertz pressure accepted (Pa): 4.0 GPa, the contact stress at which ISO 76
/// rates the static load of a roller bearing (a permanent deformation of 10⁻⁴ of the roller
/// diameter). Above it the steel yields and the elastic contact every film model assumes no
/// longer holds; the numerical solver is checked to 3.5 GPa (docs/physics.md §5.2, §5.3).
pub const MAX_HERTZ_PRESSURE_PA: f64 = 4.0e9;

/// Highest shaft speed `--speed-rpm` accepts (rpm): the core's limit
/// [`bearing_core::params::MAX_SHAFT_SPEED_RAD_S`], ≈ 954 930 rpm.
pub(crate) fn max_speed_rpm() -> f64 {
    f64::from(bearing_core::params::MAX_SHAFT_SPEED_RAD_S) * 30.0 / std::f64::consts::PI
}

/// Range of the pressure–viscosity coefficient α (1/Pa): 1–100 GPa⁻¹, lubricating oils (the
/// network's training box is 10–30 GPa⁻¹, docs/physics.md §5.3). The regression formulas, the
/// fallback of every core film model, scale as G^0.56 = (αE')^0.56 (docs/physics.md §5.1), so
/// at α → 0 (an iso-viscous lubricant) they give no film at all.
const ALPHA_RANGE_PA_INV: (f64, f64) = (1.0e-9, 1.0e-7);

/// The value of `flag` as the core's f32, or a refusal naming it when single precision cannot
/// hold it (overflow to infinity or underflow to zero).
pub(super) fn single_precision(flag: &str, value: f64) -> anyhow::Result<f32> {
    let v = value as f32;
    if !(v.is_normal() && v > 0.0) {
        bail!(
            "{flag} = {value:e} does not fit the core's single precision: allowed {:e} ..= {:e}",
            f32::MIN_POSITIVE,
            f32::MAX
        );
    }
    Ok(v)
}

/// Peak Hertz pressure p_h = √(w E' / (2π R)) (Pa, docs/physics.md §1) of a load per length
/// `w`, reduced radius `radius_m` and modulus `modulus_pa`.
fn hertz_pressure_pa(w: f64, radius_m: f64, modulus_pa: f64) -> f64 {
    (w * modulus_pa / (2.0 * std::f64::consts::PI * radius_m)).sqrt()
}

/// The load (N) over `length_m` at which p_h reaches [`MAX_HERTZ_PRESSURE_PA`].
pub(crate) fn max_load_n(length_m: f64, radius_m: f64, modulus_pa: f64) -> f64 {
    2.0 * std::f64::consts::PI * radius_m * MAX_HERTZ_PRESSURE_PA.powi(2) / modulus_pa * length_m
}

/// Refuses a contact whose peak Hertz pressure exceeds what bearing steel carries, naming the
/// load flag and the largest load allowed for this contact.
pub(super) fn check_hertz(flag: &str, contact: &ContactInput) -> anyhow::Result<()> {
    let (q, l) = (f64::from(contact.load_n), f64::from(contact.length_m));
    let (r, e) = (
        f64::from(contact.reduced_radius_m),
        f64::from(contact.reduced_modulus_pa),
    );
    let p_h = hertz_pressure_pa(q / l, r, e);
    let steel_carries_it = p_h <= MAX_HERTZ_PRESSURE_PA;
    if !steel_carries_it {
        bail!(
            "{flag} = {q:e} N gives a peak Hertz pressure of {:.3} GPa: steel carries at most {} GPa \
             (ISO 76 static rating); allowed {flag} ≤ {:.4e} N for this contact",
            p_h * 1e-9,
            MAX_HERTZ_PRESSURE_PA * 1e-9,
            max_load_n(l, r, e)
        );
    }
    Ok(())
}

/// Refuses `--alpha` outside [`ALPHA_RANGE_PA_INV`].
fn check_alpha(alpha: f64) -> anyhow::Result<()> {
    let (lo, hi) = ALPHA_RANGE_PA_INV;
    if !(lo..=hi).contains(&alpha) {
        bail!(
            "--alpha = {alpha:e} 1/Pa is out of range: allowed {lo:e} ..= {hi:e} 1/Pa (lubricating \
             oils; the regression formulas every core film model falls back to give no film as \
             α → 0)"
        );
    }
    Ok(())
}

/// Draw `--plot` for `contact` if asked, and say where.
fn maybe_plot(args: &FilmArgs, contact: &ContactInput, title: &str) -> anyhow::Result<()> {
    if let Some(path) = &args.plot {
        if args.plot_span <= 1.0 {
            bail!("--plot-span must exceed 1 (got {})", args.plot_span);
        }
        write_with(path, |temp| {
            plot::plot(
                contact,
                args.plot_over,
                usize::from(args.plot_points),
                args.plot_span,
                title,
                temp,
            )
        })
        .with_context(|| format!("drawing {}", path.display()))?;
        if !args.json {
            println!("plot: {}", path.display());
        }
    }
    Ok(())
}

/// The numerical solution of the contact (docs/physics.md §5.2, default options): the reference
/// of every other film model.
pub(super) fn numerical_solution(contact: &ContactInput) -> Result<EhlSolution, EhlError> {
    ContactCase::new(
        f64::from(contact.load_per_length_n_per_m()),
        f64::from(contact.entrainment_speed_m_s),
        f64::from(contact.reduced_radius_m),
        f64::from(contact.reduced_modulus_pa),
        f64::from(contact.pressure_viscosity_pa_inv),
        f64::from(contact.viscosity_pa_s),
    )
    .and_then(|case| ehl::solve(&case, &SolverOptions::default()))
}

/// The high-speed corrections (docs/physics.md §5.4) of every model's film in `report`: per
/// model its factors φ_T, φ_S and its films corrected by them, as the core's film table serves
/// them (a model without a film is left as it is).
fn add_corrections(
    report: &mut serde_json::Value,
    contact: &ContactInput,
    corrections: &FilmCorrections,
) {
    let martin = martin_film_m(contact);
    for model in report["models"].as_array_mut().into_iter().flatten() {
        let Some(central) = model["central_film_m"].as_f64() else {
            continue;
        };
        let factors = corrections.factors(contact, central as f32);
        let corrected = |h: f64| corrected_film_m(h as f32, martin, factors.product());
        model["correction_factors"] =
            json!({"thermal": factors.thermal, "starvation": factors.starvation});
        model["central_film_corrected_m"] = json!(corrected(central));
        model["min_film_corrected_m"] = json!(model["min_film_m"].as_f64().map(corrected));
    }
    report["film_corrections"] = json!({
        "thermal": corrections.thermal.map(|t| json!({
            "temperature_viscosity_per_k": t.temperature_viscosity_per_k(),
            "thermal_conductivity_w_per_m_k": t.conductivity_w_per_m_k(),
            "thermal_loading_number": t.loading_number(contact),
        })),
        "starvation": corrections.starvation.map(|s| json!({
            "oil_layer_m": s.oil_layer_m(),
            "starvation_exponent": s.transition_exponent(),
        })),
    });
}

/// The friction of `contact` (docs/physics.md §8) at the numerical central film, or the
/// regression's when the solver did not converge.
fn friction_report(
    contact: &ContactInput,
    friction: &FrictionParams,
    numerical_film_m: Option<f64>,
) -> serde_json::Value {
    let (film, film_from) = match numerical_film_m {
        Some(h) => (h as f32, "numerical"),
        None => (Regression.film(contact).central_m, "regression"),
    };
    let c = friction.contact(contact, film);
    json!({
        "film_from": film_from,
        "lambda": c.lambda,
        "lubrication": c.lubrication().name(),
        "friction_coefficient": c.friction_coefficient(),
        "slide_to_roll_ratio": friction.slide_to_roll_ratio(),
        "asperity_load_n": c.asperity_load_n,
        "rolling_n": c.rolling_n,
        "viscous_n": c.viscous_n,
        "boundary_n": c.boundary_n,
    })
}

/// Every film model's answer for one contact, and its friction.
fn report(contact: &ContactInput, friction: &FrictionParams) -> serde_json::Value {
    let hertz = HertzLineContact::new(
        contact.load_per_length_n_per_m(),
        contact.reduced_radius_m,
        contact.reduced_modulus_pa,
    );
    let g = LnGroups::new(contact);
    let regime = Regime::from_ln_moes(g.ln_m(), g.ln_l());
    let (m, l) = (g.ln_m().exp(), g.ln_l().exp());
    // Moes: H_c = (h_c/R)(2U)^−1/2.
    let moes_m = moes_central(m, l) * (2.0 * g.ln_u.exp()).sqrt() * contact.reduced_radius_m;
    let numerical = numerical_solution(contact);
    let reference = numerical.as_ref().ok().map(|n| n.central_film_m);
    let entry = |name: &str, central: f32, minimum: Option<f32>, fell_back: bool| {
        let error = reference.map(|r| (f64::from(central) - r) / r);
        json!({"name": name, "central_film_m": central, "min_film_m": minimum, "regime": regime.name(),
               "fell_back": fell_back, "central_rel_err_vs_numerical": error})
    };
    let regression = Regression.film(contact);
    let hydro = Hydrodynamic.film(contact);
    let ann_f32 = AnnF32.film(contact);
    let ann_int = AnnInt.film(contact);
    let numerical_entry = match &numerical {
        Ok(n) => {
            json!({"name": "numerical", "central_film_m": n.central_film_m, "min_film_m": n.min_film_m,
                        "regime": regime.name(), "fell_back": false, "central_rel_err_vs_numerical": 0.0})
        }
        Err(e) => {
            json!({"name": "numerical", "central_film_m": null, "min_film_m": null, "regime": regime.name(),
                         "fell_back": false, "error": e.to_string()})
        }
    };
    let friction = friction_report(contact, friction, reference);
    json!({
        "lambda": friction["lambda"],
        "friction_coefficient": friction["friction_coefficient"],
        "friction": friction,
        "input": {
            "load_n": contact.load_n, "length_m": contact.length_m,
            "entrainment_speed_m_s": contact.entrainment_speed_m_s, "reduced_radius_m": contact.reduced_radius_m,
            "reduced_modulus_pa": contact.reduced_modulus_pa, "pressure_viscosity_pa_inv": contact.pressure_viscosity_pa_inv,
            "viscosity_pa_s": contact.viscosity_pa_s,
        },
        "dimensionless": {"w": g.ln_w.exp(), "u": g.ln_u.exp(), "g": g.ln_g.exp(), "m": m, "l": l},
        "regime": regime.name(),
        "hertz": {"half_width_m": hertz.half_width_m, "max_pressure_pa": hertz.max_pressure_pa},
        "models": [
            numerical_entry,
            entry("ann_f32", ann_f32.central_m, Some(ann_f32.minimum_m), ann_f32.source == FilmSource::Fallback),
            entry("ann_int", ann_int.central_m, Some(ann_int.minimum_m), ann_int.source == FilmSource::Fallback),
            entry("regression", regression.central_m, Some(regression.minimum_m), false),
            entry("moes", moes_m, None, false),
            entry("hydrodynamic", hydro.central_m, Some(hydro.minimum_m), false),
        ],
    })
}

fn print_human(title: &str, r: &serde_json::Value) {
    let f = |v: &serde_json::Value| v.as_f64().unwrap_or(f64::NAN);
    println!("{title}");
    let d = &r["dimensionless"];
    println!(
        "  W = {:.3e}  U = {:.3e}  G = {:.0}  M = {:.3}  L = {:.3}  regime: {}",
        f(&d["w"]),
        f(&d["u"]),
        f(&d["g"]),
        f(&d["m"]),
        f(&d["l"]),
        r["regime"].as_str().unwrap_or("?")
    );
    println!(
        "  Hertz: half-width b = {:.2} µm, max pressure p_h = {:.3} GPa",
        f(&r["hertz"]["half_width_m"]) * 1e6,
        f(&r["hertz"]["max_pressure_pa"]) * 1e-9
    );
    let fr = &r["friction"];
    println!(
        "  λ = h_c/σ = {:.2} ({}, {} film)  friction coefficient {:.4} at slide/roll {}: \
         rolling {:.3} N, viscous {:.3} N, boundary {:.3} N, asperity load {:.2} N",
        f(&fr["lambda"]),
        fr["lubrication"].as_str().unwrap_or("?"),
        fr["film_from"].as_str().unwrap_or("?"),
        f(&fr["friction_coefficient"]),
        f(&fr["slide_to_roll_ratio"]),
        f(&fr["rolling_n"]),
        f(&fr["viscous_n"]),
        f(&fr["boundary_n"]),
        f(&fr["asperity_load_n"])
    );
    println!(
        "  {:<14} {:>14} {:>14} {:>14}",
        "model", "central (nm)", "minimum (nm)", "vs numerical"
    );
    for m in r["models"].as_array().into_iter().flatten() {
        let min = m["min_film_m"]
            .as_f64()
            .map_or("–".to_string(), |v| format!("{:.1}", v * 1e9));
        let err = m["central_rel_err_vs_numerical"]
            .as_f64()
            .map_or("–".to_string(), |v| format!("{:+.2} %", v * 100.0));
        let note = if m["fell_back"].as_bool() == Some(true) {
            "  (outside the network's domain: regression fallback)".to_string()
        } else if let Some(e) = m["error"].as_str() {
            format!("  ({e})")
        } else {
            String::new()
        };
        println!(
            "  {:<14} {:>14.1} {:>14} {:>14}{note}",
            m["name"].as_str().unwrap_or("?"),
            f(&m["central_film_m"]) * 1e9,
            min,
            err
        );
    }
    print_corrections(r);
}

/// The corrections' lines of `print_human`: per model φ_T, φ_S and the corrected central film,
/// when the bearing file switches a correction on.
fn print_corrections(r: &serde_json::Value) {
    let c = &r["film_corrections"];
    if c["thermal"].is_null() && c["starvation"].is_null() {
        return;
    }
    let f = |v: &serde_json::Value| v.as_f64().unwrap_or(f64::NAN);
    if !c["thermal"].is_null() {
        println!(
            "  thermal loading number L = {:.3} (docs/physics.md §5.4)",
            f(&c["thermal"]["thermal_loading_number"])
        );
    }
    println!(
        "  {:<14} {:>8} {:>8} {:>22}",
        "corrected", "φ_T", "φ_S", "central (nm)"
    );
    for m in r["models"].as_array().into_iter().flatten() {
        if m["central_film_corrected_m"].is_null() {
            continue;
        }
        println!(
            "  {:<14} {:>8.4} {:>8.4} {:>22.1}",
            m["name"].as_str().unwrap_or("?"),
            f(&m["correction_factors"]["thermal"]),
            f(&m["correction_factors"]["starvation"]),
            f(&m["central_film_corrected_m"]) * 1e9
        );
    }
}

/// Run `bearing film`.
pub fn run(args: FilmArgs) -> anyhow::Result<()> {
    if args.contact == FilmContact::Point {
        return point::run(&args);
    }
    if let Some(path) = &args.config {
        let text = std::fs::read_to_string(path)
            .with_context(|| format!("{}: cannot read", path.display()))?;
        if bearing_host_common::ball_config::is_ball_config(&text) {
            return point::run_ball(&args, path);
        }
        if args.ball_load.is_some() {
            bail!("--ball-load applies to ball-bearing configs: give --roller-load N");
        }
        refuse_point_flags(&args)?;
        let (config, params) = BearingConfig::load(path)?;
        let speed_rpm = args
            .speed_rpm
            .context("--speed-rpm is required with --config")?;
        if speed_rpm > max_speed_rpm() {
            bail!(
                "--speed-rpm = {speed_rpm:e} is out of range: allowed (0, {:.0}] rpm (the core's \
                 highest shaft speed, 10⁵ rad/s)",
                max_speed_rpm()
            );
        }
        let speed = rad_per_s(speed_rpm);
        let load = single_precision(
            "--roller-load",
            args.roller_load
                .context("--roller-load is required with --config")?,
        )?;
        let inner_contact = params.contact_input(false, load, speed);
        // Both contacts must hold the load; the smaller reduced radius (the inner) is the
        // stricter, but each is checked.
        check_hertz("--roller-load", &inner_contact)?;
        check_hertz("--roller-load", &params.contact_input(true, load, speed))?;
        let outer_contact = params.contact_input(true, load, speed);
        let mut inner = report(&inner_contact, params.friction());
        let mut outer = report(&outer_contact, params.friction());
        add_corrections(&mut inner, &inner_contact, params.film_corrections());
        add_corrections(&mut outer, &outer_contact, params.film_corrections());
        maybe_plot(
            &args,
            &inner_contact,
            &format!("{}, inner contact", config.name),
        )?;
        if args.json {
            let mut value = inner.clone();
            value["contact"] = json!("inner");
            value["bearing"] = json!(config.name);
            value["outer"] = outer;
            return print_json(&value);
        }
        print_human(&format!("{}: inner contact", config.name), &inner);
        print_human(&format!("{}: outer contact", config.name), &outer);
        return Ok(());
    }
    refuse_point_flags(&args)?;
    let missing: Vec<&str> = [
        ("--load", args.load),
        ("--length", args.length),
        ("--entrainment", args.entrainment),
        ("--radius", args.radius),
        ("--modulus", args.modulus),
        ("--alpha", args.alpha),
        ("--eta0", args.eta0),
    ]
    .iter()
    .filter(|(_, v)| v.is_none())
    .map(|(n, _)| *n)
    .collect();
    if !missing.is_empty() {
        bail!(
            "missing {} (or give --config FILE --speed-rpm RPM --roller-load N)",
            missing.join(", ")
        );
    }
    let v = |flag: &str, o: Option<f64>| single_precision(flag, o.unwrap_or(0.0));
    check_alpha(args.alpha.unwrap_or(0.0))?;
    let contact = ContactInput {
        load_n: v("--load", args.load)?,
        length_m: v("--length", args.length)?,
        entrainment_speed_m_s: v("--entrainment", args.entrainment)?,
        reduced_radius_m: v("--radius", args.radius)?,
        reduced_modulus_pa: v("--modulus", args.modulus)?,
        pressure_viscosity_pa_inv: v("--alpha", args.alpha)?,
        viscosity_pa_s: v("--eta0", args.eta0)?,
    };
    check_hertz("--load", &contact)?;
    if !contact.is_valid() {
        bail!("the contact is not valid in f32 (a value overflows or underflows single precision)");
    }
    let mut r = report(&contact, &FrictionParams::DEFAULT);
    add_corrections(&mut r, &contact, &FilmCorrections::OFF);
    maybe_plot(&args, &contact, "line contact")?;
    if args.json {
        print_json(&r)
    } else {
        print_human("Line contact", &r);
        Ok(())
    }
}
