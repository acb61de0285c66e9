//! The §6.2 hub-motor shaft with the core's bearings: the headline of docs/physics.md §4 — with the
//! film, bearing stiffness is higher than dry and rises with speed — at the static operating
//! points of the sweep (bearings linearised at the equilibrium under gravity and gear forces).

use std::path::Path;

use crate::bearing::FilmKind;
use crate::config::load_model;
use crate::operating::{build_bearings, linearise};
use crate::statics::equilibrium;

/// Largest eigenvalue of the symmetric part of the left bearing's 2×2 stiffness (N/m).
fn bearing_stiffness(film: FilmKind, rpm: f64) -> f64 {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../configs/shaft_hub_motor.toml");
    let mut model = load_model(&path).unwrap();
    for b in &mut model.description.bearings {
        b.spec = b.spec.with_film(film);
    }
    let omega = rpm * std::f64::consts::PI / 30.0;
    let mut bearings = build_bearings(&model).unwrap();
    let eq = equilibrium(&model, omega, &mut bearings).unwrap();
    let k = linearise(&model, &mut bearings, &eq.q, omega).unwrap()[0].stiffness;
    let (a, d, b) = (k[0][0], k[1][1], 0.5 * (k[0][1] + k[1][0]));
    0.5 * (a + d) + (0.25 * (a - d).powi(2) + b * b).sqrt()
}

#[test]
fn lubricated_bearing_is_stiffer_than_dry_and_stiffens_with_speed() {
    let speeds = [3000.0, 12_000.0, 21_000.0];
    let lub: Vec<f64> = speeds
        .iter()
        .map(|&s| bearing_stiffness(FilmKind::Regression, s))
        .collect();
    let dry: Vec<f64> = speeds
        .iter()
        .map(|&s| bearing_stiffness(FilmKind::Dry, s))
        .collect();
    eprintln!("bearing stiffness at {speeds:?} rpm: lubricated {lub:?}, dry {dry:?} N/m");
    for i in 0..speeds.len() {
        assert!(
            lub[i] > 1.1 * dry[i],
            "{} rpm: {} vs {} N/m",
            speeds[i],
            lub[i],
            dry[i]
        );
    }
    assert!(lub.windows(2).all(|p| p[1] > p[0]), "{lub:?}");
}

/// The cost claim of the integrator: on the hub shaft at 21 000 rpm with lubricated core
/// bearings (regression film) and the 8.4 µs step, the tangent predictor (the last
/// evaluation's force, stiffness and damping) lands within the Newton tolerance, so nearly every
/// step takes a single core step per bearing (measured 1.0002 evaluations per step; the
/// bound allows one step in a hundred to iterate once more).
#[test]
fn lubricated_hub_shaft_takes_one_bearing_evaluation_per_step() {
    use crate::integrator::{NewtonSettings, Scheme};
    use crate::system::TimeSystem;
    use nalgebra::DVector;

    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../configs/shaft_hub_motor.toml");
    let mut model = load_model(&path).unwrap();
    for b in &mut model.description.bearings {
        b.spec = b.spec.with_film(FilmKind::Regression);
    }
    let omega = 21_000.0 * std::f64::consts::PI / 30.0;
    let dt = 2.0 * std::f64::consts::PI / (20.0 * 17.0 * omega);
    let eq = equilibrium(&model, omega, &mut build_bearings(&model).unwrap()).unwrap();
    let system = TimeSystem::new(&model, None).unwrap();
    let mut it = system
        .integrator(
            Scheme::AverageAcceleration,
            dt,
            omega,
            build_bearings(&model).unwrap(),
            NewtonSettings::default(),
            0.0,
            eq.q.clone(),
            DVector::zeros(model.n_dof()),
        )
        .unwrap();
    let mut f = DVector::zeros(model.n_dof());
    for _ in 0..1000 {
        system.load(it.state.time + dt, omega, &mut f).unwrap();
        it.step(&f).unwrap();
    }
    let t = it.totals;
    assert_eq!(t.steps, 1000);
    assert!(
        t.evaluations_per_step() <= 1.01,
        "{} evaluations per step",
        t.evaluations_per_step()
    );
    assert!(t.bearing_seconds > 0.0 && t.bearing_seconds <= t.step_seconds);
}
