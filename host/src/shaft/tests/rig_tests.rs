//! The NU 205 rig (configs/shaft_nu205_rig.toml) with the core's roller bearing: the
//! varying-compliance line at the outer-race pass frequency in the inner-race displacement.

use std::path::Path;

use crate::shaft::bearing::{BearingSpec, FilmChoice};
use crate::shaft::config::load_model;
use crate::shaft::integrator::{NewtonSettings, Scheme};
use crate::shaft::simulate::{run, RunSettings};
use crate::shaft::spectrum::amplitude_spectrum;

/// Reference: PHYSICS.md §2, f_bpo = (Z f_s / 2)(1 − D/d_m) = 1130.8 Hz for the NU 205
/// (Z = 12, D = 7.5 mm, d_m = 39 mm) at 14 000 rpm. The spectrum of the test bearing's y
/// displacement under the 745 N load must peak there, 20× above every other line between
/// 50 Hz and 1.5 f_bpo. Dry bearing (see the report for the lubricated case).
#[test]
fn nu205_rig_shows_the_outer_race_pass_line() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs/shaft_nu205_rig.toml");
    let model = load_model(&path).unwrap();
    let specs: Vec<BearingSpec> = model
        .description
        .bearings
        .iter()
        .map(|b| b.spec.with_film(FilmChoice::Dry))
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
    let spec = amplitude_spectrum(&y, dt);
    let df = spec[1].0;
    let (f_peak, a_peak) = spec
        .iter()
        .copied()
        .filter(|p| p.0 > 50.0 && p.0 < 1.5 * f_bpo)
        .max_by(|p, q| p.1.total_cmp(&q.1))
        .unwrap();
    assert!(
        (f_peak - f_bpo).abs() <= 1.5 * df,
        "peak at {f_peak} Hz, f_bpo {f_bpo} Hz"
    );
    let other = spec
        .iter()
        .filter(|p| p.0 > 50.0 && p.0 < 1.5 * f_bpo && (p.0 - f_bpo).abs() > 0.05 * f_bpo)
        .map(|p| p.1)
        .fold(0.0, f64::max);
    assert!(
        a_peak > 20.0 * other,
        "line {a_peak:e} m vs others {other:e} m"
    );
}
