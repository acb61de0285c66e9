//! The NU 205 rig (configs/shaft_nu205_rig.toml) with the core's roller bearing: the
//! varying-compliance line at the outer-race pass frequency in the inner-race displacement,
//! dry and lubricated.

use std::path::Path;

use crate::analysis::integrator::{NewtonSettings, Scheme};
use crate::analysis::simulate::{run, RunSettings};
use crate::analysis::spectrum::amplitude_spectrum;
use crate::bearing::{BearingSpec, FilmKind};
use crate::model::config::load_model;

/// The rig at 14 000 rpm under its 745 N load with the given film: the spectrum of the test
/// bearing's y displacement, f_bpo (Hz), and the fewest loaded rollers (load > 0) of any
/// recorded sample.
///
/// Reference: docs/physics.md §2, f_bpo = (Z f_s / 2)(1 − D/d_m) = 1130.8 Hz for the NU 205
/// (Z = 12, D = 7.5 mm, d_m = 39 mm) at 14 000 rpm.
fn rig(film: FilmKind) -> (Vec<(f64, f64)>, f64, usize) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../configs/shaft_nu205_rig.toml");
    let model = load_model(&path).unwrap();
    let specs: Vec<BearingSpec> = model
        .description
        .bearings
        .iter()
        .map(|b| b.spec.with_film(film))
        .collect();
    let omega = 14_000.0 * std::f64::consts::PI / 30.0;
    let f_bpo = 12.0 * omega / (4.0 * std::f64::consts::PI) * (1.0 - 7.5 / 39.0);
    let dt = 1.0 / (40.0 * f_bpo);
    let settings = RunSettings {
        spin_speed: omega,
        spin_speed_end: None,
        dt,
        settle_time: 0.02,
        record_time: 0.12,
        record_every: 1,
        scheme: Scheme::AverageAcceleration,
        reduction_modes: None,
        newton: NewtonSettings::default(),
    };
    let r = run(&model, &settings, Some(&specs)).unwrap();
    let y: Vec<f64> = r.samples.iter().map(|s| s.probes[0][0][1]).collect();
    let loaded = r
        .samples
        .iter()
        .map(|s| {
            s.rollers[0]
                .as_ref()
                .unwrap()
                .iter()
                .filter(|q| q.load > 0.0)
                .count()
        })
        .min()
        .unwrap();
    (amplitude_spectrum(&y, dt), f_bpo, loaded)
}

/// Largest line within 1.5 bins of f_bpo, and the largest line between 50 Hz and 1.5 f_bpo
/// farther than 5 % from it.
fn line_and_others(spec: &[(f64, f64)], f_bpo: f64) -> (f64, f64, f64) {
    let df = spec[1].0;
    let (f_peak, a_peak) = spec
        .iter()
        .copied()
        .filter(|p| p.0 > 50.0 && p.0 < 1.5 * f_bpo)
        .max_by(|p, q| p.1.total_cmp(&q.1))
        .unwrap();
    let line = spec
        .iter()
        .filter(|p| (p.0 - f_bpo).abs() <= 1.5 * df)
        .map(|p| p.1)
        .fold(0.0, f64::max);
    let other = spec
        .iter()
        .filter(|p| p.0 > 50.0 && p.0 < 1.5 * f_bpo && (p.0 - f_bpo).abs() > 0.05 * f_bpo)
        .map(|p| p.1)
        .fold(0.0, f64::max);
    assert!(
        (f_peak - f_bpo).abs() > 1.5 * df || a_peak == line,
        "inconsistent peak search"
    );
    (f_peak, line, other)
}

/// Dry: the spectrum peaks at f_bpo, 20× above every other line between 50 Hz and 1.5 f_bpo.
#[test]
fn nu205_rig_shows_the_outer_race_pass_line_dry() {
    let (spec, f_bpo, _) = rig(FilmKind::Dry);
    let (f_peak, line, other) = line_and_others(&spec, f_bpo);
    assert!(
        (f_peak - f_bpo).abs() <= 1.5 * spec[1].0,
        "peak at {f_peak} Hz, f_bpo {f_bpo} Hz"
    );
    assert!(line > 20.0 * other, "line {line:e} m vs others {other:e} m");
}

/// Lubricated with the regression film the line all but disappears, and the reason is
/// physical: the film (≈ 1 µm at 14 000 rpm) takes up the zero clearance as an interference,
/// so all 12 rollers carry load at every instant (dry: part of the ring is unloaded), and a
/// fully loaded ring's stiffness Σ k_j cos²θ_j hardly depends on the cage angle. The f_bpo line
/// is below 1 % of the dry one (measured ≈ 2·10⁻⁴ of it, at the numerical noise floor).
/// The integer film network loads every roller as well; its line and the f32 network's
/// (printed, not asserted) stay a quarter of the dry one: the networks' film, like the
/// numerical solver's at these conditions, hardly changes with the load, while the regression
/// film thins with it (docs/shaft.md, where the cause is stated as a hypothesis).
#[test]
fn nu205_rig_lubricated_loads_every_roller_and_the_regression_film_loses_the_line() {
    let (dry, f_bpo, loaded_dry) = rig(FilmKind::Dry);
    let (lub, _, loaded_lub) = rig(FilmKind::Regression);
    let (int, _, loaded_int) = rig(FilmKind::Int);
    assert_eq!(loaded_lub, 12, "rollers loaded, regression film");
    assert_eq!(loaded_int, 12, "rollers loaded, integer network");
    let (_, line_int, other_int) = line_and_others(&int, f_bpo);
    eprintln!("f_bpo line, integer network: {line_int:.3e} m (other lines {other_int:.3e} m)");
    let (f32net, _, _) = rig(FilmKind::F32);
    let (_, line_f32, other_f32) = line_and_others(&f32net, f_bpo);
    eprintln!("f_bpo line, f32 network: {line_f32:.3e} m (other lines {other_f32:.3e} m)");
    assert!(loaded_dry < 12, "rollers loaded, dry: {loaded_dry}");
    let (_, line_dry, _) = line_and_others(&dry, f_bpo);
    let (_, line_lub, other_lub) = line_and_others(&lub, f_bpo);
    eprintln!(
        "f_bpo line: dry {line_dry:.3e} m, regression film {line_lub:.3e} m (other lines {other_lub:.3e} m)"
    );
    assert!(line_lub < 1e-2 * line_dry, "{line_lub:e} vs {line_dry:e} m");
}
