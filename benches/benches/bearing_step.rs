//! The bearing step of the hub-motor bearing (17 rollers, 10 slices): dry against lubricated
//! with the regression film and with the integer network (what the HIL replay runs), and the
//! film-model call alone. The ratio lubricated/dry is the cost of the film coupling (aim: ≤ 3×).

use bearing_core::bearing::SETTLE_STEPS;
use bearing_core::{Bearing, BearingDesign, FilmKind, FilmModel, OperatingState, Regression};
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

/// Sample period of the orbit (s).
const DT_S: f32 = 1.0e-4;

/// The hub-motor bearing (docs/physics.md §6.2: d_m 60 mm, D 8.8 mm × 15 mm, 17 rollers, 2 µm
/// interference) with the film model `film`.
fn hub_motor_bearing(film: FilmKind) -> Bearing<17, 10> {
    let params = BearingDesign::HUB_MOTOR.params().expect("hub-motor preset");
    Bearing::new(params, film).expect("bearing")
}

/// A slowly orbiting inner race at 21 000 rpm: every step sees a new state, as in a loop.
fn states() -> Vec<OperatingState> {
    let omega = 21_000.0f32 * std::f32::consts::PI / 30.0;
    (0..1000)
        .map(|i| {
            let t = i as f32 * DT_S;
            let phase = 2.0 * std::f32::consts::PI * 150.0 * t;
            OperatingState {
                displacement_m: [0.5e-6 * phase.cos(), -6.0e-6 + 0.5e-6 * phase.sin()],
                velocity_m_s: [-4.7e-4 * phase.sin(), 4.7e-4 * phase.cos()],
                tilt_rad: [0.0; 2],
                shaft_speed_rad_s: omega,
            }
        })
        .collect()
}

fn bench_step(c: &mut Criterion) {
    let states = states();
    let mut group = c.benchmark_group("bearing_step_hub_motor_17x10");
    for (name, film) in [
        ("dry", FilmKind::Dry),
        ("lubricated_regression", FilmKind::Regression),
        ("lubricated_ann_int", FilmKind::Int),
    ] {
        let mut bearing = hub_motor_bearing(film);
        bearing
            .settle(&states[0], SETTLE_STEPS)
            .expect("a valid state");
        let mut i = 0usize;
        group.bench_function(name, |b| {
            b.iter(|| {
                i = (i + 1) % states.len();
                black_box(
                    bearing
                        .advance(black_box(&states[i]), DT_S)
                        .map(|o| o.force_n),
                )
            })
        });
    }
    group.finish();

    let bearing = hub_motor_bearing(FilmKind::Regression);
    let contact = bearing.params().contact_input(false, 800.0, 2199.0);
    c.bench_function("film_regression_one_contact", |b| {
        b.iter(|| black_box(Regression.film(black_box(&contact))))
    });
}

criterion_group!(benches, bench_step);
criterion_main!(benches);
