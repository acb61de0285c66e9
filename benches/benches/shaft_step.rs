//! One implicit time step of the §6.2 hub-motor shaft (configs/shaft_hub_motor.toml) at
//! 21 000 rpm with the step 1/(20 × mesh frequency) = 8.40 µs, full model (68 DOF) and
//! Craig–Bampton reduced (bearing and pinion nodes + 8 modes, 20 DOF). Bearings: linear
//! 3·10⁸ N/m, 300 N·s/m (the roller bearing of the core is not wired into the shaft yet).
//! Real-time factor = step size / time per step; the setup prints the DOF counts.

use std::path::Path;

use bearing_host::shaft::bearing::{BearingSpec, LinearBearing};
use bearing_host::shaft::config::load_model;
use bearing_host::shaft::integrator::{NewtonSettings, Scheme};
use bearing_host::shaft::operating::build_bearings;
use bearing_host::shaft::statics::equilibrium;
use bearing_host::shaft::system::TimeSystem;
use criterion::{criterion_group, criterion_main, Criterion};
use nalgebra::DVector;

fn shaft_step(c: &mut Criterion) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs/shaft_hub_motor.toml");
    let mut model = load_model(&path).expect("bundled hub-motor shaft");
    for b in &mut model.description.bearings {
        b.spec = BearingSpec::Linear(LinearBearing::isotropic(3e8, 300.0));
    }
    let omega = 21_000.0 * std::f64::consts::PI / 30.0;
    let dt = 2.0 * std::f64::consts::PI / (20.0 * 17.0 * omega);
    let eq = equilibrium(&model, omega, &mut build_bearings(&model).unwrap()).unwrap();
    let mut group = c.benchmark_group("shaft_step");
    for reduction in [None, Some(8)] {
        let system = TimeSystem::new(&model, reduction).unwrap();
        let n = system.n_dof();
        let mut it = system
            .integrator(
                Scheme::AverageAcceleration,
                dt,
                omega,
                build_bearings(&model).unwrap(),
                NewtonSettings::default(),
                0.0,
                system.from_full(&eq.q),
                DVector::zeros(n),
            )
            .unwrap();
        println!(
            "shaft_step: {n} DOF, dt = {:.3} µs (real time needs a step below that)",
            dt * 1e6
        );
        let mut f = DVector::zeros(n);
        let name = match reduction {
            None => format!("hub_motor_full_{n}dof"),
            Some(k) => format!("hub_motor_craig_bampton_{k}modes_{n}dof"),
        };
        group.bench_function(name, |b| {
            b.iter(|| {
                let t1 = it.state.time + dt;
                system.load(t1, omega, &mut f).unwrap();
                it.step(&f).unwrap();
            })
        });
    }
    group.finish();
}

criterion_group!(benches, shaft_step);
criterion_main!(benches);
