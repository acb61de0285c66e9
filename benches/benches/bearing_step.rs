//! The bearing step of the hub-motor bearing (17 rollers, 10 slices): dry against lubricated
//! with the regression film and with the integer network (what the HIL replay runs), and the
//! film-model call alone. The ratio lubricated/dry is the cost of the film coupling (aim: ≤ 3×).

use bearing_core::film::ann::AnnInt;
use bearing_core::{
    Bearing, BearingGeometry, BearingParams, ContactLaw, Crown, FilmModel, Lubricant, Material,
    OperatingState, Regression,
};
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

fn hub_motor_bearing() -> Bearing<17, 10> {
    // PHYSICS.md §6.2: d_m 60 mm, D 8.8 mm × 15 mm, 17 rollers, 2 µm interference.
    let geometry = BearingGeometry::new(
        0.060,
        0.0088,
        0.015,
        17,
        Crown::Logarithmic { scale: 1.0 },
        -2.0e-6,
    )
    .expect("hub-motor geometry");
    let oil = Lubricant::new(0.08, 2.1e-8, 833.8).expect("oil");
    let params = BearingParams::new(
        geometry,
        Material::STEEL,
        Material::STEEL,
        oil,
        ContactLaw::Palmgren,
        1.0e-5,
    )
    .expect("params");
    Bearing::new(params).expect("bearing")
}

/// A slowly orbiting inner race at 21 000 rpm: every step sees a new state, as in a loop.
fn states() -> Vec<OperatingState> {
    let omega = 21_000.0f32 * std::f32::consts::PI / 30.0;
    (0..1000)
        .map(|i| {
            let t = i as f32 * 1.0e-4;
            let phase = 2.0 * std::f32::consts::PI * 150.0 * t;
            OperatingState {
                displacement_m: [0.5e-6 * phase.cos(), -6.0e-6 + 0.5e-6 * phase.sin()],
                velocity_m_s: [-4.7e-4 * phase.sin(), 4.7e-4 * phase.cos()],
                tilt_rad: [0.0; 2],
                shaft_speed_rad_s: omega,
                cage_angle_rad: (0.5 * omega * (1.0 - 8.8 / 60.0) * t)
                    % (2.0 * std::f32::consts::PI),
            }
        })
        .collect()
}

fn bench_step(c: &mut Criterion) {
    let states = states();
    let mut group = c.benchmark_group("bearing_step_hub_motor_17x10");
    let mut dry = hub_motor_bearing();
    let mut i = 0usize;
    group.bench_function("dry", |b| {
        b.iter(|| {
            i = (i + 1) % states.len();
            black_box(dry.step_dry(black_box(&states[i])).force_n)
        })
    });
    let mut lubricated = hub_motor_bearing();
    lubricated.settle(&Regression, &states[0], bearing_core::bearing::SETTLE_STEPS);
    let mut j = 0usize;
    group.bench_function("lubricated_regression", |b| {
        b.iter(|| {
            j = (j + 1) % states.len();
            black_box(lubricated.step(&Regression, black_box(&states[j])).force_n)
        })
    });
    let mut network = hub_motor_bearing();
    network.settle(&AnnInt, &states[0], bearing_core::bearing::SETTLE_STEPS);
    let mut k = 0usize;
    group.bench_function("lubricated_ann_int", |b| {
        b.iter(|| {
            k = (k + 1) % states.len();
            black_box(network.step(&AnnInt, black_box(&states[k])).force_n)
        })
    });
    group.finish();

    let bearing = hub_motor_bearing();
    let contact = bearing.params().contact_input(false, 800.0, 2199.0);
    c.bench_function("film_regression_one_contact", |b| {
        b.iter(|| black_box(Regression.film(black_box(&contact))))
    });
}

criterion_group!(benches, bench_step);
criterion_main!(benches);
