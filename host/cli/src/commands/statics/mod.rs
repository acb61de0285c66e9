//! `bearing static`: static equilibrium of the inner race under a radial load, lubricated and
//! (on request) dry side by side.

use std::path::{Path, PathBuf};

use anyhow::{bail, Context};
use bearing_core::{DynBearing, FilmKind, OperatingState};
use clap::Args;
use serde_json::json;

mod ball;

use crate::commands::common::{non_negative, print_json, rad_per_s};
use crate::commands::film::{max_load_n, max_speed_rpm, MAX_HERTZ_PRESSURE_PA};
use bearing_host_common::config::BearingConfig;
use bearing_host_common::rolling::{boxed, StepSnapshot};

/// Static equilibrium of the inner race under a radial load along −y (a roller bearing), or
/// under radial, axial and moment loads (a ball bearing: a config with a `[ball]` table).
#[derive(Args, Debug)]
pub struct StaticArgs {
    /// Bearing configuration (TOML).
    #[arg(long)]
    pub config: PathBuf,
    /// Radial load on the inner race (N), acting along −y; default: the config's `[case]`.
    #[arg(long, value_parser = non_negative)]
    pub radial_load: Option<f64>,
    #[command(flatten)]
    pub ball: ball::BallStaticArgs,
    /// Shaft speed (rpm); default: the config's `[case]`. Zero gives the dry bearing.
    #[arg(long, value_parser = non_negative)]
    pub speed_rpm: Option<f64>,
    /// Also solve the dry bearing (film ≡ 0) and show it beside the lubricated one.
    #[arg(long)]
    pub dry: bool,
    /// Machine-readable output.
    #[arg(long)]
    pub json: bool,
}

/// Force residual at which the equilibrium is accepted, relative to the larger of the radial
/// load and the sum of the roller loads (the film and an interference preload the rollers at
/// zero load; see `Bearing::static_equilibrium`).
const TOLERANCE: f32 = 1.0e-6;
/// Newton iterations allowed.
const MAX_ITERATIONS: usize = 300;

/// Ratio of the radial load to the most loaded roller's load that ISO 76 assumes for a radial
/// roller bearing in its static load rating (Stribeck's constant with a normal clearance: the
/// standard's 44 N/mm² is 4 GPa at the inner contact of a steel roller divided by 5).
const ISO_76_LOAD_SHARING: f64 = 5.0;

/// The bearing's static load rating C₀ in the sense of ISO 76 (N): the radial load at which the
/// most loaded roller's inner contact reaches [`MAX_HERTZ_PRESSURE_PA`], with that roller
/// carrying 5/Z of the load. For steel it is ISO 76's C₀r = 44·(1 − D/d_m)·Z·L·D (N, mm) within
/// 1 %. Above it the steel yields and no model here holds.
fn static_load_rating_n(params: &bearing_core::BearingParams) -> f64 {
    let inner = params.contact_input(false, 0.0, 0.0);
    let per_roller = max_load_n(
        f64::from(inner.length_m),
        f64::from(inner.reduced_radius_m),
        f64::from(inner.reduced_modulus_pa),
    );
    f64::from(params.geometry().roller_count()) * per_roller / ISO_76_LOAD_SHARING
}

/// Refuses a radial load above the static load rating or a speed above the core's, naming where
/// the value came from (`source`: the flag, or the config's field).
pub(super) fn check_case(
    params: &bearing_core::BearingParams,
    (load_n, load_source): (f64, &str),
    (speed_rpm, speed_source): (f64, &str),
) -> anyhow::Result<()> {
    let rating = static_load_rating_n(params);
    if load_n > rating {
        bail!(
            "{load_source} = {load_n:e} N is out of range: allowed 0 ..= {rating:.4e} N, this \
             bearing's static load rating (ISO 76: {} GPa at the most loaded contact, where the \
             steel starts to yield)",
            MAX_HERTZ_PRESSURE_PA * 1e-9
        );
    }
    if speed_rpm > max_speed_rpm() {
        bail!(
            "{speed_source} = {speed_rpm:e} rpm is out of range: allowed 0 ..= {:.0} rpm (the \
             core's highest shaft speed, 10⁵ rad/s)",
            max_speed_rpm()
        );
    }
    Ok(())
}

pub(super) struct Solution {
    displacement_m: [f32; 2],
    residual_n: f32,
    iterations: usize,
    pub(super) step: StepSnapshot,
}

pub(super) fn solve(
    bearing: &mut dyn DynBearing,
    load_n: f32,
    speed: f32,
) -> anyhow::Result<Solution> {
    let lubricated = bearing.film() != FilmKind::Dry;
    // Roller 0 on the load line (−y) gives the symmetric load zone of the textbooks.
    bearing.set_cage_angle(-std::f32::consts::FRAC_PI_2)?;
    let start = OperatingState::new([0.0; 2], [0.0; 2], [0.0; 2], speed)?;
    bearing.reset();
    let force = [0.0, -load_n];
    let eq = bearing.static_equilibrium(force, &start, TOLERANCE, MAX_ITERATIONS);
    if !eq.converged {
        bail!(
            "{} equilibrium not reached after {} Newton iterations: force residual {:.3e} N (tolerance {:.1e}·max(F, Σ roller loads))",
            if lubricated { "lubricated" } else { "dry" },
            eq.iterations,
            eq.residual_n,
            TOLERANCE
        );
    }
    let state = OperatingState {
        displacement_m: eq.displacement_m,
        ..start
    };
    bearing.advance(&state, 0.0)?;
    let step = StepSnapshot::from(bearing.friction(speed)?);
    Ok(Solution {
        displacement_m: eq.displacement_m,
        residual_n: eq.residual_n,
        iterations: eq.iterations,
        step,
    })
}

fn to_json(s: &Solution, film: &str) -> serde_json::Value {
    let k = s.step.radial_stiffness_n_per_m();
    let [rolling, viscous, boundary] = s.step.power_loss_split_w;
    json!({
        "film_model": film,
        "friction_torque_nm": s.step.friction_torque_nm,
        "power_loss_w": s.step.power_loss_w,
        "power_loss_split_w": {"rolling": rolling, "viscous": viscous, "boundary": boundary},
        "displacement_m": s.displacement_m,
        "force_residual_n": s.residual_n,
        "iterations": s.iterations,
        "max_roller_load_n": s.step.max_roller_load_n(),
        "centrifugal_force_n": s.step.centrifugal_force_n,
        "stiffness_n_per_m": k,
        "stiffness_full": s.step.stiffness,
        "rollers": s.step.rollers.iter().zip(&s.step.lambda).map(|(r, [lambda_in, lambda_out])| json!({
            "angle_rad": r.angle_rad,
            "load_n": r.load_n,
            "load_in_n": r.load_n,
            "load_out_n": r.load_n + s.step.centrifugal_force_n,
            "approach_m": r.approach_m,
            "central_film_in_m": r.central_film_in_m,
            "central_film_out_m": r.central_film_out_m,
            "min_film_in_m": r.min_film_in_m,
            "min_film_out_m": r.min_film_out_m,
            "lambda_in": lambda_in,
            "lambda_out": lambda_out,
            "contact_stiffness_n_per_m": r.contact_stiffness_n_per_m,
            "roller_stiffness_n_per_m": r.roller_stiffness_n_per_m,
            "regime": r.regime_in.name(),
            "regime_out": r.regime_out.name(),
        })).collect::<Vec<_>>(),
    })
}

fn print_human(title: &str, s: &Solution) {
    let k = s.step.radial_stiffness_n_per_m();
    println!("{title}");
    println!(
        "  displacement x = {:.4} µm, y = {:.4} µm   (residual {:.2e} N after {} Newton iterations)",
        s.displacement_m[0] * 1e6,
        s.displacement_m[1] * 1e6,
        s.residual_n,
        s.iterations
    );
    println!(
        "  stiffness (N/µm): [[{:.1}, {:.1}], [{:.1}, {:.1}]]   max roller load {:.1} N",
        k[0][0] * 1e-6,
        k[0][1] * 1e-6,
        k[1][0] * 1e-6,
        k[1][1] * 1e-6,
        s.step.max_roller_load_n()
    );
    if s.step.centrifugal_force_n > 0.0 {
        println!(
            "  centrifugal force per roller F_c = {:.1} N: each outer contact carries load + F_c",
            s.step.centrifugal_force_n
        );
    }
    let [rolling, viscous, boundary] = s.step.power_loss_split_w;
    println!(
        "  friction torque {:.4} N·m, power loss {:.2} W (rolling {:.2}, viscous {:.2}, boundary {:.2} W)",
        s.step.friction_torque_nm, s.step.power_loss_w, rolling, viscous, boundary
    );
    println!(
        "  {:>6} {:>9} {:>10} {:>10} {:>10} {:>7} {:>7} {:>12}  regime",
        "roller", "angle°", "load N", "h_in nm", "h_out nm", "λ_in", "λ_out", "k N/µm"
    );
    for (j, (r, [lambda_in, lambda_out])) in s.step.rollers.iter().zip(&s.step.lambda).enumerate() {
        println!(
            "  {:>6} {:>9.1} {:>10.2} {:>10.1} {:>10.1} {:>7.2} {:>7.2} {:>12.2}  {}",
            j,
            r.angle_rad.to_degrees(),
            r.load_n,
            r.central_film_in_m * 1e9,
            r.central_film_out_m * 1e9,
            lambda_in,
            lambda_out,
            r.roller_stiffness_n_per_m * 1e-6,
            r.regime_in.name()
        );
    }
}

/// The radial load (N) of a command: `--radial-load`, else the config's `[case]` value.
pub(super) fn radial_load_n(flag: Option<f64>, config: &BearingConfig) -> anyhow::Result<f64> {
    flag.or(config.case.radial_load_n.map(f64::from))
        .context("no radial load: give --radial-load N or set [case] radial_load_n in the config")
}

/// Where a value of a command came from, for its refusal: `flag` when given, else the config
/// file's `[case]` field.
pub(super) fn value_source(given: bool, flag: &str, config: &Path, field: &str) -> String {
    if given {
        flag.to_string()
    } else {
        format!("{} [case] {field}", config.display())
    }
}

/// Run `bearing static`.
pub fn run(args: StaticArgs) -> anyhow::Result<()> {
    let text = std::fs::read_to_string(&args.config)
        .with_context(|| format!("{}: cannot read", args.config.display()))?;
    if bearing_host_common::ball_config::is_ball_config(&text) {
        return ball::run(&args);
    }
    args.ball.refuse_for_rollers()?;
    let (config, params) = BearingConfig::load(&args.config)?;
    let load = radial_load_n(args.radial_load, &config)?;
    let rpm = args
        .speed_rpm
        .or(config.case.speed_rpm.map(f64::from))
        .unwrap_or(0.0);
    let load_source = value_source(
        args.radial_load.is_some(),
        "--radial-load",
        &args.config,
        "radial_load_n",
    );
    let speed_source = value_source(
        args.speed_rpm.is_some(),
        "--speed-rpm",
        &args.config,
        "speed_rpm",
    );
    check_case(&params, (load, &load_source), (rpm.abs(), &speed_source))?;
    let speed = rad_per_s(rpm);
    let lubricated = rpm > 0.0;
    let build =
        |film| boxed(params, film).map_err(|e| anyhow::anyhow!("{}: {e}", args.config.display()));
    let main_film = if lubricated {
        FilmKind::Regression
    } else {
        FilmKind::Dry
    };
    let main = solve(build(main_film)?.as_mut(), load as f32, speed)?;
    let dry = if args.dry && lubricated {
        Some(solve(build(FilmKind::Dry)?.as_mut(), load as f32, speed)?)
    } else {
        None
    };
    let film = if lubricated { "regression" } else { "dry" };
    if args.json {
        let mut value = to_json(&main, film);
        value["bearing"] = json!(config.name);
        value["radial_load_n"] = json!(load);
        value["speed_rpm"] = json!(rpm);
        if let Some(d) = &dry {
            value["dry"] = to_json(d, "dry");
        }
        return print_json(&value);
    }
    print_human(
        &format!(
            "{} — {:.0} N radial at {:.0} rpm, {} film",
            config.name, load, rpm, film
        ),
        &main,
    );
    if let Some(d) = &dry {
        print_human("dry (film ≡ 0), same load", d);
        let (kl, kd) = (main.step.stiffness[1][1], d.step.stiffness[1][1]);
        println!(
            "\nlubricated vs dry: K_yy {:+.1} %, max roller load {:+.1} %, displacement y {:+.3} µm",
            (kl / kd - 1.0) * 100.0,
            (main.step.max_roller_load_n() / d.step.max_roller_load_n() - 1.0) * 100.0,
            (main.displacement_m[1] - d.displacement_m[1]) * 1e6
        );
    }
    Ok(())
}
