//! The §6.2 hub-motor shaft with the core's bearings: the headline of docs/physics.md §4 — with the
//! film, bearing stiffness is higher than dry and rises with speed — at the static operating
//! points of the sweep (bearings linearised at the equilibrium under gravity and gear forces).

use std::path::Path;

use crate::analysis::operating::{build_bearings, linearise};
use crate::analysis::statics::equilibrium;
use crate::bearing::FilmKind;
use crate::model::config::load_model;

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
    use crate::analysis::integrator::{NewtonSettings, Scheme};
    use crate::analysis::system::TimeSystem;
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

/// The start of a run at low speed, where the film is thinnest: the hub shaft at 1000 rpm from
/// its static equilibrium, with the network's film and with the regression formulas, at the
/// CLI's default step (20 per period of the 17-tooth mesh, 176 µs). The integrator settles the
/// bearings' warm start at the initial state, so the first steps' trials start converged, and
/// its Newton on the bearing forces converges at every step (`bearing shaft sweep` starts at
/// this speed).
#[test]
fn lubricated_hub_shaft_runs_from_equilibrium_at_low_speed() {
    use crate::analysis::integrator::{NewtonSettings, Scheme};
    use crate::analysis::simulate::{run, RunSettings};

    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../configs/shaft_hub_motor.toml");
    let model = load_model(&path).unwrap();
    for film in [FilmKind::Int, FilmKind::Regression] {
        let specs: Vec<_> = model
            .description
            .bearings
            .iter()
            .map(|b| b.spec.with_film(film))
            .collect();
        let omega = 1000.0 * std::f64::consts::PI / 30.0;
        let settings = RunSettings {
            spin_speed: omega,
            spin_speed_end: None,
            dt: 2.0 * std::f64::consts::PI / (20.0 * 17.0 * omega),
            settle_time: 0.01,
            record_time: 0.01,
            record_every: 1,
            scheme: Scheme::AverageAcceleration,
            reduction_modes: None,
            newton: NewtonSettings::default(),
        };
        let r = run(&model, &settings, Some(&specs)).unwrap_or_else(|e| panic!("{film:?}: {e}"));
        let per_step = r.totals.evaluations_per_step();
        eprintln!("{film:?}: {per_step:.3} bearing evaluations per step");
        assert!(per_step < 3.0, "{film:?}: {per_step} evaluations per step");
    }
}
