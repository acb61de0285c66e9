//! One implicit time step of the §6.2 hub-motor shaft (configs/shaft_hub_motor.toml) at
//! 21 000 rpm with the step 1/(20 × mesh frequency) = 8.40 µs, full model (68 DOF) and
//! Craig–Bampton reduced (bearing and pinion nodes + 16 modes, 28 DOF; its error against the full
//! model is reported by `bearing shaft run --reduce 16 --compare-full`), with
//! * linear bearings 3·10⁸ N/m, 300 N·s/m (the linear algebra alone, one evaluation per step),
//! * the core's roller bearings (configs/hub_motor.toml) dry, with the regression film and with
//!   the integer film network (the case);
//!
//! one evaluation of one roller bearing is timed on its own (`roller_bearing_evaluate_*`).
//!
//! Real-time factor = step size / time per step. Before the criterion runs, each case is
//! stepped 4000 times after 2000 settling steps and its breakdown is printed (evaluations per
//! step, µs per step in the bearings and in the shaft's linear algebra, real-time factor).

use std::path::Path;

use bearing_shaft::bearing::{BearingSpec, BearingState, FilmKind, LinearBearing};
use bearing_shaft::config::load_model;
use bearing_shaft::integrator::{Integrator, NewtonSettings, Scheme};
use bearing_shaft::model::RotorModel;
use bearing_shaft::operating::build_bearings;
use bearing_shaft::statics::equilibrium;
use bearing_shaft::system::TimeSystem;
use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::DVector;

fn with_film(model: &RotorModel, film: FilmKind) -> RotorModel {
    let mut m = model.clone();
    for b in &mut m.description.bearings {
        b.spec = b.spec.with_film(film);
    }
    m
}

fn integrator(system: &TimeSystem, model: &RotorModel, omega: f64, dt: f64) -> Integrator {
    let eq = equilibrium(model, omega, &mut build_bearings(model).unwrap()).unwrap();
    let n = system.n_dof();
    system
        .integrator(
            Scheme::AverageAcceleration,
            dt,
            omega,
            build_bearings(model).unwrap(),
            NewtonSettings::default(),
            0.0,
            system.from_full(&eq.q),
            DVector::zeros(n),
        )
        .unwrap()
}

fn shaft_step(c: &mut Criterion) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs/shaft_hub_motor.toml");
    let roller = load_model(&path).expect("bundled hub-motor shaft");
    let mut linear = roller.clone();
    for b in &mut linear.description.bearings {
        b.spec = BearingSpec::Linear(LinearBearing::isotropic(3e8, 300.0));
    }
    let omega = 21_000.0 * std::f64::consts::PI / 30.0;
    let dt = 2.0 * std::f64::consts::PI / (20.0 * 17.0 * omega);
    let cases = [
        ("linear", linear),
        ("roller_dry", with_film(&roller, FilmKind::Dry)),
        (
            "roller_regression",
            with_film(&roller, FilmKind::Regression),
        ),
        ("roller_int", with_film(&roller, FilmKind::Int)),
    ];
    let mut group = c.benchmark_group("shaft_step");
    for (label, model) in &cases {
        for reduction in [None, Some(16)] {
            let system = TimeSystem::new(model, reduction).unwrap();
            let n = system.n_dof();
            let mut f = DVector::zeros(n);
            // The breakdown over 4000 steps after 2000 settling steps.
            let mut it = integrator(&system, model, omega, dt);
            for k in 0..6000 {
                if k == 2000 {
                    it.totals = Default::default();
                }
                let t1 = it.state.time + dt;
                system.load(t1, omega, &mut f).unwrap();
                it.step(&f).unwrap();
            }
            let t = it.totals;
            let per = 1e6 / t.steps as f64;
            println!(
                "shaft_step {label}, {n} DOF, dt {:.3} µs: {:.3} evaluations/step, bearings {:.2} µs/step, \
                 linear algebra {:.2} µs/step, real-time factor {:.3} (steps only)",
                dt * 1e6,
                t.evaluations_per_step(),
                t.bearing_seconds * per,
                (t.step_seconds - t.bearing_seconds) * per,
                dt * t.steps as f64 / t.step_seconds
            );
            let name = match reduction {
                None => format!("hub_motor_{label}_full_{n}dof"),
                Some(k) => format!("hub_motor_{label}_craig_bampton_{k}modes_{n}dof"),
            };
            group.bench_function(name, |b| {
                b.iter(|| {
                    let t1 = it.state.time + dt;
                    system.load(t1, omega, &mut f).unwrap();
                    it.step(&f).unwrap();
                })
            });
        }
    }
    // One evaluation of one roller bearing at the equilibrium state (the Newton loop calls it
    // once per iteration per bearing).
    for film in [FilmKind::Dry, FilmKind::Regression, FilmKind::Int] {
        let model = with_film(&roller, film);
        let eq = equilibrium(&model, omega, &mut build_bearings(&model).unwrap()).unwrap();
        let d = model.bearing_dofs()[0];
        let mut bearing = model.description.bearings[0].spec.build().unwrap();
        let state = BearingState {
            displacement: [eq.q[d[0]], eq.q[d[1]]],
            velocity: [0.0; 2],
            spin_speed: omega,
            time: 0.0,
        };
        group.bench_function(format!("roller_bearing_evaluate_{film:?}"), |b| {
            b.iter(|| bearing.evaluate(&state).unwrap())
        });
    }
    group.finish();
}

criterion_group!(benches, shaft_step);
criterion_main!(benches);
