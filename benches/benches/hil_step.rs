//! Host time of one step of the HIL kernel (`bearing_hil::kernel`, the code the firmware runs),
//! stepping through a synthetic hub-motor whirl trace one sample per iteration. The host's
//! budget for the bearing step is p99.9 ≤ 10 µs; criterion reports the mean and spread, the
//! percentiles come from `hil-sim replay`.

use bearing_hil::kernel::{FilmKind, Kernel};
use bearing_hil::outputs::StepOutputs;
use bearing_hil::trace::synthetic::Whirl;
use bearing_hil::trace::TraceMeta;
use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;

fn kernel_step(c: &mut Criterion) {
    let trace = Whirl {
        speed_rad_s: 2199.0,
        acceleration_rad_s2: 0.0,
        offset_m: [0.0, -6.0e-6],
        radius_m: 2.0e-6,
        whirl_rad_s: 2.0 * std::f64::consts::PI * 350.0,
        tilt_amplitude_rad: None,
    }
    .trace(
        TraceMeta {
            bearing: "hub_motor".into(),
            lubricant: "thesis_oil".into(),
            sample_rate_hz: 10_000.0,
        },
        4096,
    );
    let mut kernel = Kernel::new("hub_motor", "thesis_oil", 10_000.0, FilmKind::Regression)
        .expect("hub_motor is a known bearing");
    kernel.prime(&trace.samples[0]);
    let mut out = StepOutputs::default();
    let mut index = 0usize;
    c.bench_function(
        "hil kernel step, hub motor (17 rollers), regression film",
        |b| {
            b.iter(|| {
                let sample = &trace.samples[index % trace.samples.len()];
                index += 1;
                let _ = kernel.step(black_box(sample), black_box(&mut out));
            })
        },
    );
}

criterion_group!(benches, kernel_step);
criterion_main!(benches);
