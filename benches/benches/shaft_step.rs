//! One implicit time step of the §6.2 hub-motor shaft (configs/shaft_hub_motor.toml) at
//! 21 000 rpm with the step 1/(20 × mesh frequency) = 8.40 µs, full model (68 DOF) and
//! Craig–Bampton reduced (bearing and pinion nodes + 16 modes, 28 DOF; its envelope error against
//! the full model at this speed: 0.4 % displacement, 2 % acceleration, from `bearing shaft run
//! --reduce 16 --compare-full`), with
//! * linear bearings 3·10⁸ N/m, 300 N·s/m (the linear algebra alone), and
//! * the core's roller bearings (configs/hub_motor.toml) with the regression film and with the
//!   integer film network, whose evaluation is also timed on its own (`roller_bearing_evaluate`).
//!
//! Real-time factor = step size / time per step; the setup prints the DOF counts.

use std::path::Path;

use bearing_host::shaft::bearing::{BearingSpec, BearingState, FilmChoice, LinearBearing};
use bearing_host::shaft::config::load_model;
use bearing_host::shaft::integrator::{NewtonSettings, Scheme};
use bearing_host::shaft::operating::build_bearings;
use bearing_host::shaft::statics::equilibrium;
use bearing_host::shaft::system::TimeSystem;
use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::DVector;

fn shaft_step(c: &mut Criterion) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs/shaft_hub_motor.toml");
    let roller = load_model(&path).expect("bundled hub-motor shaft");
    let mut linear = roller.clone();
    for b in &mut linear.description.bearings {
        b.spec = BearingSpec::Linear(LinearBearing::isotropic(3e8, 300.0));
    }
    let mut roller_int = roller.clone();
    for b in &mut roller_int.description.bearings {
        if let BearingSpec::Roller { film, .. } = &mut b.spec {
            *film = FilmChoice::Int;
        }
    }
    let omega = 21_000.0 * std::f64::consts::PI / 30.0;
    let dt = 2.0 * std::f64::consts::PI / (20.0 * 17.0 * omega);
    let mut group = c.benchmark_group("shaft_step");
    for (label, model) in [
        ("linear", &linear),
        ("roller_regression", &roller),
        ("roller_int", &roller_int),
    ] {
        let eq = equilibrium(model, omega, &mut build_bearings(model).unwrap()).unwrap();
        for reduction in [None, Some(16)] {
            let system = TimeSystem::new(model, reduction).unwrap();
            let n = system.n_dof();
            let mut it = system
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
                .unwrap();
            println!(
                "shaft_step: {label}, {n} DOF, dt = {:.3} µs (real time needs a step below that)",
                dt * 1e6
            );
            let mut f = DVector::zeros(n);
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
    let eq = equilibrium(&roller, omega, &mut build_bearings(&roller).unwrap()).unwrap();
    let d = roller.bearing_dofs()[0];
    let mut bearing = roller.description.bearings[0].spec.build().unwrap();
    let state = BearingState {
        displacement: [eq.q[d[0]], eq.q[d[1]]],
        velocity: [0.0; 2],
        spin_speed: omega,
        time: 0.0,
    };
    group.bench_function("roller_bearing_evaluate", |b| {
        b.iter(|| bearing.evaluate(&state).unwrap())
    });
    group.finish();
}

criterion_group!(benches, shaft_step);
criterion_main!(benches);
