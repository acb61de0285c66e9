//! `bearing static` for a ball bearing (a config with a `[ball]` table): loads → displacement
//! in up to five degrees of freedom, or the forward map of a given displacement, lubricated
//! and (on request) dry side by side.

use anyhow::{bail, Context};
use bearing_core::bearing::ball::{BallBearingState, BallFilm, BallLoad};
use bearing_host_common::ball_config::{ball_query, BallBearingConfig, BallQuery, BallResult};
use clap::Args;
use serde_json::json;

use super::{value_source, StaticArgs};
use crate::commands::common::{print_json, rad_per_s};
use crate::commands::film::max_speed_rpm;
use crate::commands::film::point::source_name;

/// The flags of `bearing static` that apply to ball bearings.
#[derive(Args, Debug, Default)]
pub struct BallStaticArgs {
    /// Ball bearings: direction of the radial load, from +x towards +y (degrees); default −90
    /// (along −y, as for rollers). Ball 0 sits on this line (with --displacement too).
    #[arg(long, allow_hyphen_values = true, value_parser = finite)]
    pub load_angle_deg: Option<f64>,
    /// Ball bearings: axial load on the inner ring along +z (N); default: the config's `[case]`.
    #[arg(long, allow_hyphen_values = true, value_parser = finite)]
    pub axial_load: Option<f64>,
    /// Ball bearings: tilt of the inner ring about x, held (rad; default 0).
    #[arg(long, allow_hyphen_values = true, value_parser = finite)]
    pub tilt_x_rad: Option<f64>,
    /// Ball bearings: tilt of the inner ring about y, held (rad; default 0).
    #[arg(long, allow_hyphen_values = true, value_parser = finite)]
    pub tilt_y_rad: Option<f64>,
    /// Ball bearings: solve the two tilts too, under the moments --moment-x-nm/--moment-y-nm.
    #[arg(long)]
    pub free_tilt: bool,
    /// Ball bearings with --free-tilt: moment applied about x (N·m; default 0).
    #[arg(long, allow_hyphen_values = true, value_parser = finite)]
    pub moment_x_nm: Option<f64>,
    /// Ball bearings with --free-tilt: moment applied about y (N·m; default 0).
    #[arg(long, allow_hyphen_values = true, value_parser = finite)]
    pub moment_y_nm: Option<f64>,
    /// Ball bearings: the forward map at this displacement `x,y,z,tilt_x,tilt_y` (m, rad)
    /// instead of a static solve.
    #[arg(long, allow_hyphen_values = true, value_parser = displacement, value_name = "X,Y,Z,TX,TY")]
    pub displacement: Option<[f64; 5]>,
    /// Ball bearings: the balls' centrifugal force on or off (default: the config's
    /// `[high_speed] centrifugal`).
    #[arg(long, value_parser = ["on", "off"])]
    pub centrifugal: Option<String>,
}

/// clap value parser: a finite number of any sign.
fn finite(s: &str) -> Result<f64, String> {
    let v: f64 = s
        .trim()
        .parse()
        .map_err(|_| format!("`{s}` is not a number"))?;
    if v.is_finite() {
        Ok(v)
    } else {
        Err(format!("{s} is not allowed: it must be a finite number"))
    }
}

/// clap value parser: five finite numbers separated by commas.
fn displacement(s: &str) -> Result<[f64; 5], String> {
    let values: Vec<f64> = s.split(',').map(finite).collect::<Result<_, _>>()?;
    <[f64; 5]>::try_from(values).map_err(|v| {
        format!(
            "`{s}` has {} values: it must be five, x,y,z,tilt_x,tilt_y (m, rad)",
            v.len()
        )
    })
}

impl BallStaticArgs {
    /// Refuse a ball-bearing flag given with a roller-bearing config, naming it.
    pub fn refuse_for_rollers(&self) -> anyhow::Result<()> {
        let given = [
            ("--load-angle-deg", self.load_angle_deg.is_some()),
            ("--axial-load", self.axial_load.is_some()),
            ("--tilt-x-rad", self.tilt_x_rad.is_some()),
            ("--tilt-y-rad", self.tilt_y_rad.is_some()),
            ("--free-tilt", self.free_tilt),
            ("--moment-x-nm", self.moment_x_nm.is_some()),
            ("--moment-y-nm", self.moment_y_nm.is_some()),
            ("--displacement", self.displacement.is_some()),
            ("--centrifugal", self.centrifugal.is_some()),
        ];
        if let Some((flag, _)) = given.iter().find(|(_, g)| *g) {
            bail!("{flag} applies to ball bearings only (a config with a [ball] table)");
        }
        Ok(())
    }
}

/// Run `bearing static` for a ball-bearing config.
pub fn run(args: &StaticArgs) -> anyhow::Result<()> {
    let b = &args.ball;
    let (config, params) = BallBearingConfig::load(&args.config)?;
    let params = match b.centrifugal.as_deref() {
        Some(on) => params.with_centrifugal(on == "on"),
        None => params,
    };
    let rpm = args
        .speed_rpm
        .or(config.case.speed_rpm.map(f64::from))
        .unwrap_or(0.0);
    if rpm > max_speed_rpm() {
        let source = value_source(
            args.speed_rpm.is_some(),
            "--speed-rpm",
            &args.config,
            "speed_rpm",
        );
        bail!(
            "{source} = {rpm:e} rpm is out of range: allowed 0 ..= {:.0} rpm",
            max_speed_rpm()
        );
    }
    if !b.free_tilt && (b.moment_x_nm.is_some() || b.moment_y_nm.is_some()) {
        bail!("--moment-x-nm and --moment-y-nm need --free-tilt (with the tilts held, the moments are the reactions the output reports)");
    }
    let speed = rad_per_s(rpm);
    // Ball 0 sits on the radial load's line, as rollers do; --displacement uses the same cage.
    let angle = b.load_angle_deg.unwrap_or(-90.0).to_radians();
    let query = match b.displacement {
        Some(u) => BallQuery::Evaluate(BallBearingState {
            cage_angle_rad: angle as f32,
            ..BallBearingState::at(u.map(|v| v as f32), speed)
        }),
        None => {
            let radial = args
                .radial_load
                .or(config.case.radial_load_n.map(f64::from))
                .unwrap_or(0.0);
            let axial = b
                .axial_load
                .or(config.case.axial_load_n.map(f64::from))
                .unwrap_or(0.0);
            let tilts = [b.tilt_x_rad.unwrap_or(0.0), b.tilt_y_rad.unwrap_or(0.0)];
            BallQuery::Static(BallLoad {
                applied: [
                    (radial * angle.cos()) as f32,
                    (radial * angle.sin()) as f32,
                    axial as f32,
                    b.moment_x_nm.unwrap_or(0.0) as f32,
                    b.moment_y_nm.unwrap_or(0.0) as f32,
                ],
                free: [true, true, true, b.free_tilt, b.free_tilt],
                held: [0.0, 0.0, 0.0, tilts[0] as f32, tilts[1] as f32],
                shaft_speed_rad_s: speed,
                cage_angle_rad: angle as f32,
            })
        }
    };
    let lubricated = rpm > 0.0;
    let film = if lubricated {
        BallFilm::NetworkInt
    } else {
        BallFilm::Dry
    };
    let solve = |film| {
        ball_query(params, film, &query)
            .map_err(|e| anyhow::anyhow!("{}: {e}", args.config.display()))
    };
    let main = solve(film).with_context(|| format!("{} film", film_name(film)))?;
    let dry = if args.dry && lubricated {
        Some(solve(BallFilm::Dry).context("dry")?)
    } else {
        None
    };
    if args.json {
        let mut value = to_json(&main, film);
        value["bearing"] = json!(config.name);
        value["speed_rpm"] = json!(rpm);
        if let Some(d) = &dry {
            value["dry"] = to_json(d, BallFilm::Dry);
        }
        return print_json(&value);
    }
    print_human(
        &format!("{} at {rpm:.0} rpm, film: {}", config.name, film_name(film)),
        &main,
    );
    if let Some(d) = &dry {
        print_human("dry (film ≡ 0), same load", d);
    }
    Ok(())
}

/// The film model's stable name.
fn film_name(film: BallFilm) -> &'static str {
    match film {
        BallFilm::Dry => "dry",
        BallFilm::HamrockDowson => "hamrock_dowson",
        BallFilm::NetworkF32 => "network_f32",
        BallFilm::NetworkInt => "network_int",
    }
}

fn to_json(r: &BallResult, film: BallFilm) -> serde_json::Value {
    json!({
        "film_model": film_name(film),
        "displacement": r.displacement,
        "applied_load": r.applied_load,
        "stiffness": r.stiffness,
        "damping": r.damping,
        "cage_speed_rad_s": r.cage_speed_rad_s,
        "iterations": r.iterations,
        "balls": r.balls.iter().map(|b| json!({
            "azimuth_deg": b.azimuth_rad.to_degrees(),
            "load_inner_n": b.load_n[0],
            "load_outer_n": b.load_n[1],
            "contact_angle_inner_deg": b.contact_angle_rad[0].to_degrees(),
            "contact_angle_outer_deg": b.contact_angle_rad[1].to_degrees(),
            "max_pressure_inner_pa": b.max_pressure_pa[0],
            "max_pressure_outer_pa": b.max_pressure_pa[1],
            "semi_axes_inner_m": b.semi_axes_inner_m,
            "semi_axes_outer_m": b.semi_axes_outer_m,
            "film_central_inner_m": b.central_film_m[0],
            "film_central_outer_m": b.central_film_m[1],
            "film_minimum_inner_m": b.min_film_m[0],
            "film_minimum_outer_m": b.min_film_m[1],
            "film_source": source_name(b.film_source[0]),
            "film_source_outer": source_name(b.film_source[1]),
            "stiffness_n_per_m": b.stiffness_n_per_m,
        })).collect::<Vec<_>>(),
    })
}

fn print_human(title: &str, r: &BallResult) {
    let [x, y, z, tx, ty] = r.displacement;
    let [fx, fy, fz, mx, my] = r.applied_load;
    println!("{title}");
    println!(
        "  displacement x = {:.4} µm, y = {:.4} µm, z = {:.4} µm, tilt x = {:.3e} rad, tilt y = {:.3e} rad ({} Newton steps)",
        x * 1e6, y * 1e6, z * 1e6, tx, ty, r.iterations
    );
    println!("  applied load F = ({fx:.2}, {fy:.2}, {fz:.2}) N, M = ({mx:.4}, {my:.4}) N·m");
    let k = &r.stiffness;
    println!(
        "  stiffness k_xx {:.2} N/µm, k_yy {:.2} N/µm, k_zz {:.2} N/µm, k_θxθx {:.1} N·m/mrad; cage {:.1} rad/s",
        k[0][0] * 1e-6, k[1][1] * 1e-6, k[2][2] * 1e-6, k[3][3] * 1e-3, r.cage_speed_rad_s
    );
    println!(
        "  {:>4} {:>8} {:>9} {:>8} {:>9} {:>9} {:>9}  film",
        "ball", "ψ °", "Q N", "α °", "p_i GPa", "h_i nm", "h_o nm"
    );
    for (j, b) in r.balls.iter().enumerate() {
        println!(
            "  {:>4} {:>8.1} {:>9.2} {:>8.3} {:>9.3} {:>9.1} {:>9.1}  {}",
            j,
            b.azimuth_rad.to_degrees(),
            b.load_n[0],
            b.contact_angle_rad[0].to_degrees(),
            b.max_pressure_pa[0] * 1e-9,
            b.central_film_m[0] * 1e9,
            b.central_film_m[1] * 1e9,
            source_name(b.film_source[0]),
        );
    }
}
