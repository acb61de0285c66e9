//! `bearing ehl solve --contact point`: the point-contact solver (circular and elliptical
//! contacts, `bearing_ehl::point`) from the command line, with the flags of the line contact
//! plus `--radius-y` or `--ellipticity`, and pressure/film maps as SVG.

use super::{flag_of, CaseArgs, SolveArgs};
use anyhow::{anyhow, bail, Context, Result};
use bearing_ehl::point::{
    self, formulas, hertz, PointContactCase, PointSolution, PointSolverOptions,
};
use bearing_ehl::{EhlError, ViscosityLaw};
use bearing_host_common::output::OutputFiles;
use plotters::prelude::*;
use std::path::Path;

/// The flag a point-contact input comes from.
fn point_flag(field: &str) -> Option<&'static str> {
    Some(match field {
        "load_n" => "--load",
        "radius_x_m" => "--radius",
        "radius_y_m" => "--radius-y",
        "radius_ratio" => "--radius-y / --radius (R_y/R_x)",
        "ellipticity" => "--ellipticity",
        "rolling_nodes" => "--rolling-nodes",
        _ => return flag_of(field),
    })
}

fn name_point_flags(error: EhlError) -> anyhow::Error {
    match &error {
        EhlError::InvalidInput {
            field,
            value,
            allowed,
        } => match point_flag(field) {
            Some(flag) => anyhow!("{flag} = {value:e} is out of range: allowed {allowed}"),
            None => anyhow!("{error}"),
        },
        EhlError::InvalidOption { field, message } => match point_flag(field) {
            Some(flag) => anyhow!("{flag}: {message}"),
            None => anyhow!("{error}"),
        },
        _ => anyhow!("{error}"),
    }
}

/// The point-contact case of the flags: SI (`--load` is the contact force) with `--radius-y`
/// or `--ellipticity`, or Moes `--m --l` with `--ellipticity` (default 1).
pub(super) fn point_case(c: &CaseArgs) -> Result<PointContactCase> {
    if c.length.is_some() {
        bail!("--length is not used by --contact point (--load is the contact force in N)");
    }
    if c.w.is_some() || c.u.is_some() || c.g.is_some() {
        bail!(
            "--w/--u/--g are line-contact groups; for --contact point give the SI flags or --m --l"
        );
    }
    if c.radius_y.is_some() && c.ellipticity.is_some() {
        bail!("give --radius-y or --ellipticity, not both");
    }
    if let Some(k) = c.ellipticity {
        if !(k.is_finite() && (1.0..=12.0).contains(&k)) {
            bail!("--ellipticity = {k} is out of range: allowed finite, in [1, 12]");
        }
    }
    let k = c.ellipticity.unwrap_or(1.0);
    if c.m.is_some() || c.l.is_some() {
        let m = c.m.context("missing --m")?;
        let l = c.l.context("missing --l")?;
        if c.load.is_some() || c.radius.is_some() {
            bail!("give one case: SI flags or --m --l");
        }
        return PointContactCase::from_moes(m, l, k).map_err(name_point_flags);
    }
    let si = [
        ("--load", c.load),
        ("--entrainment", c.entrainment),
        ("--radius", c.radius),
        ("--modulus", c.modulus),
        ("--alpha", c.alpha),
        ("--eta0", c.eta0),
    ];
    let mut v = [0.0; 6];
    for (i, (name, value)) in si.iter().enumerate() {
        v[i] = value.with_context(|| format!("missing {name}"))?;
        let zero_ok = *name == "--alpha" && v[i] == 0.0;
        if !(v[i].is_finite() && v[i] > 0.0 || zero_ok) {
            bail!("{name} = {} is invalid: must be finite and > 0", v[i]);
        }
    }
    let radius_y = match c.radius_y {
        Some(r) => r,
        None => v[2] * hertz::radius_ratio_of_ellipticity(k),
    };
    PointContactCase::new(v[0], v[1], v[2], radius_y, v[3], v[4], v[5]).map_err(name_point_flags)
}

fn options(c: &CaseArgs) -> PointSolverOptions {
    PointSolverOptions {
        viscosity: if c.barus {
            ViscosityLaw::Barus
        } else {
            ViscosityLaw::Roelands
        },
        compressible: !c.incompressible,
        nodes: c.nodes.unwrap_or(point::DEFAULT_POINT_NODES),
        rolling_nodes: c.rolling_nodes,
        // Without --nodes and --rolling-nodes the solver chooses the grid from the case; either
        // way a result whose estimated grid error exceeds the default bound is refused.
        grid_from_case: c.nodes.is_none() && c.rolling_nodes.is_none(),
        max_grid_error: Some(point::DEFAULT_MAX_GRID_ERROR),
        ..Default::default()
    }
}

/// The refusal of a grid that does not resolve the film, naming the estimate and the flags
/// that give a finer grid (X alone up to 4 (nodes − 1) + 1, both directions up to 513).
fn grid_refusal(error: &EhlError) -> Option<anyhow::Error> {
    let EhlError::GridTooCoarse {
        central,
        min,
        limit,
        nodes_x,
        nodes_y,
    } = *error
    else {
        return None;
    };
    let mut remedies = Vec::new();
    let along = 2 * nodes_x - 1;
    if along <= 1025 && along - 1 <= 4 * (nodes_y - 1) {
        remedies.push(format!(
            "--nodes {nodes_y} --rolling-nodes {along} (finer along X)"
        ));
    }
    if nodes_y < 513 {
        let across = 2 * nodes_y - 1;
        remedies.push(format!(
            "--nodes {across} --rolling-nodes {} (finer in both directions)",
            along.max(across).min(4 * (across - 1) + 1).min(1025)
        ));
    }
    let remedy = if remedies.is_empty() {
        "no finer grid is available (--nodes at most 513, --rolling-nodes at most 1025)".into()
    } else {
        format!("try {}", remedies.join(" or "))
    };
    Some(anyhow!(
        "the {nodes_x} × {nodes_y} grid does not resolve this film: estimated grid error h_c \
         {:.1} %, h_min {:.1} %, allowed ≤ {:.0} %; {remedy}",
        100.0 * central,
        100.0 * min,
        100.0 * limit
    ))
}

/// Runs `bearing ehl solve --contact point …`.
pub(super) fn solve(a: &SolveArgs) -> Result<()> {
    if a.profile.is_some() {
        bail!("--profile is a line-contact output; for --contact point use --plot (SVG maps)");
    }
    let result = point_case(&a.case).and_then(|case| {
        point::solve_point(&case, &options(&a.case)).map_err(|e| match e {
            EhlError::InvalidOption { .. } => name_point_flags(e),
            EhlError::GridTooCoarse { .. } => grid_refusal(&e).unwrap_or_else(|| anyhow!("{e}")),
            other => anyhow!("{other}; the case is set by {}", a.case.flags()),
        })
    });
    let sol = super::failure_as_json(result, a.json)?;
    let mut files = OutputFiles::new();
    if let Some(path) = &a.plot {
        let temp = files
            .stage(path)
            .with_context(|| format!("--plot {}", path.display()))?;
        plot_maps(&sol, &temp).with_context(|| format!("--plot {}", path.display()))?;
    }
    files.commit()?;
    let c = &sol.case;
    if a.json {
        let v = serde_json::json!({
            "converged": true,
            "contact": "point",
            "central_film_m": sol.central_film_m,
            "min_film_m": sol.min_film_m,
            "central_film_raw_m": sol.central_film_raw_m,
            "min_film_raw_m": sol.min_film_raw_m,
            "richardson": sol.richardson,
            "grid_error_estimate": sol.grid_error_estimate.map(|(c, m)| serde_json::json!({"central_film": c, "min_film": m})),
            "max_pressure_pa": sol.max_pressure_pa,
            "hertz_pressure_pa": sol.hertz_pressure_pa,
            "ellipticity": sol.hertz.ellipticity,
            "semi_axis_rolling_m": sol.hertz.semi_axis_rolling_m,
            "semi_axis_transverse_m": sol.hertz.semi_axis_transverse_m,
            "iterations": sol.iterations,
            "nodes": sol.nodes,
            "wall_time_s": sol.wall_time_s,
            "pressure_change": sol.pressure_change,
            "load_error": sol.load_error,
            "moes_m": c.moes_m(),
            "moes_l": c.moes_l(),
            "hamrock_dowson_central_film_m": formulas::hamrock_dowson_central_film_m(c),
            "hamrock_dowson_min_film_m": formulas::hamrock_dowson_min_film_m(c),
            "nijenbanning_central_film_m": formulas::nijenbanning_central_film_m(c),
        });
        println!("{}", serde_json::to_string_pretty(&v)?);
    } else {
        print_solution(&sol);
    }
    Ok(())
}

fn print_solution(s: &PointSolution) {
    let c = &s.case;
    let (along, across) = (s.maps.x.len(), s.maps.y.len());
    println!("EHL point contact (isothermal, Newtonian), {along} × {across} nodes");
    println!(
        "  W = {:.4e}  U = {:.4e}  G = {:.1}  M = {:.3}  L = {:.3}  k = a/b = {:.4}",
        c.load_parameter(),
        c.speed_parameter(),
        c.material_parameter(),
        c.moes_m(),
        c.moes_l(),
        s.hertz.ellipticity
    );
    println!(
        "  Hertz pressure p_h     {:>12.4} GPa   semi-axes b = {:.4} mm (rolling), a = {:.4} mm",
        s.hertz_pressure_pa / 1e9,
        s.hertz.semi_axis_rolling_m * 1e3,
        s.hertz.semi_axis_transverse_m * 1e3
    );
    println!(
        "  central film h_c       {:>12.4} µm   (this grid {:.4} µm, Richardson {})",
        s.central_film_m * 1e6,
        s.central_film_raw_m * 1e6,
        if s.richardson { "on" } else { "off" }
    );
    println!(
        "  minimum film h_min     {:>12.4} µm   (this grid {:.4} µm)",
        s.min_film_m * 1e6,
        s.min_film_raw_m * 1e6
    );
    println!(
        "  maximum pressure       {:>12.4} GPa",
        s.max_pressure_pa / 1e9
    );
    if let Some((hc, hmin)) = s.grid_error_estimate {
        println!(
            "  grid error (estimated) h_c {:.3} %, h_min {:.3} % on this grid",
            100.0 * hc,
            100.0 * hmin
        );
    }
    println!(
        "  Hamrock–Dowson h_c, h_min: {:.4}, {:.4} µm; Nijenbanning–Venner–Moes h_c: {:.4} µm",
        formulas::hamrock_dowson_central_film_m(c) * 1e6,
        formulas::hamrock_dowson_min_film_m(c) * 1e6,
        formulas::nijenbanning_central_film_m(c) * 1e6
    );
    println!(
        "  iterations {}  ΣΔP/ΣP {:.2e}  load error {:.2e}  wall time {:.1} ms",
        s.iterations,
        s.pressure_change,
        s.load_error,
        s.wall_time_s * 1e3
    );
}

/// Colour of a value in [0, 1]: blue (0) through green to red (1).
fn colour(t: f64) -> RGBColor {
    let t = t.clamp(0.0, 1.0);
    let hue = (1.0 - t) * 240.0 / 360.0;
    let c = HSLColor(hue, 0.9, 0.5).to_rgba();
    RGBColor(c.0, c.1, c.2)
}

/// Two maps side by side over (x/b, y/a): p/p_h (with the Hertz circle r = 1) and h in µm
/// (colour scale from h_min to 3 h_c), as SVG.
fn plot_maps(s: &PointSolution, path: &Path) -> Result<()> {
    let root = SVGBackend::new(path, (1200, 560)).into_drawing_area();
    root.fill(&WHITE).map_err(|e| anyhow!("{e}"))?;
    let (left, right) = root.split_horizontally(600);
    let m = &s.maps;
    let nx = m.x.len();
    let (dx, dy) = (m.x[1] - m.x[0], m.y[1] - m.y[0]);
    let film_scale = s.central_film_raw_m / film_at_centre(s);
    let pmax = m.pressure.iter().cloned().fold(1.0, f64::max);
    let hmin = s.min_film_raw_m;
    let hmax = 3.0 * s.central_film_raw_m;
    let value = |panel: usize, q: usize| {
        if panel == 0 {
            m.pressure[q] / pmax
        } else {
            (m.film[q] * film_scale - hmin) / (hmax - hmin)
        }
    };
    let captions = [
        format!(
            "p/p_h (max {:.3}), p_h = {:.3} GPa",
            pmax,
            s.hertz_pressure_pa / 1e9
        ),
        format!(
            "h: {:.3} (blue) … {:.3} µm (red); h_c = {:.4} µm",
            hmin * 1e6,
            hmax * 1e6,
            s.central_film_m * 1e6
        ),
    ];
    for (panel, (area, caption)) in [&left, &right].into_iter().zip(captions).enumerate() {
        let mut chart = ChartBuilder::on(area)
            .caption(caption, ("sans-serif", 18))
            .margin(10)
            .x_label_area_size(40)
            .y_label_area_size(50)
            .build_cartesian_2d(m.x[0]..m.x[nx - 1], m.y[0]..m.y[m.y.len() - 1])
            .map_err(|e| anyhow!("{e}"))?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc("x / b")
            .y_desc("y / a")
            .draw()
            .map_err(|e| anyhow!("{e}"))?;
        chart
            .draw_series((0..m.pressure.len()).map(|q| {
                let (x, y) = (m.x[q % nx], m.y[q / nx]);
                Rectangle::new(
                    [(x - dx / 2.0, y - dy / 2.0), (x + dx / 2.0, y + dy / 2.0)],
                    colour(value(panel, q)).filled(),
                )
            }))
            .map_err(|e| anyhow!("{e}"))?;
        chart
            .draw_series(LineSeries::new(
                (0..=200).map(|i| {
                    let t = std::f64::consts::TAU * i as f64 / 200.0;
                    (t.cos(), t.sin())
                }),
                BLACK.stroke_width(1),
            ))
            .map_err(|e| anyhow!("{e}"))?;
    }
    root.present().map_err(|e| anyhow!("{e}"))?;
    Ok(())
}

/// Dimensionless film at the centre node (the raw h_c in film units).
fn film_at_centre(s: &PointSolution) -> f64 {
    let m = &s.maps;
    let nx = m.x.len();
    let i = m.x.iter().position(|x| x.abs() < 1e-9).unwrap_or(nx / 2);
    m.film[(m.y.len() / 2) * nx + i]
}
