//! End-to-end host replay with the product's wiring: a trace held at the static equilibrium of
//! the hub-motor bearing under 2 kN must replay to a bearing force of 2 kN.
//!
//! Reference: the core's static-equilibrium solver (Newton on the force balance, run to a
//! 10⁻⁵ relative residual) with the parameters read from `configs/hub_motor.toml` by the host's
//! config loader — independent of the harness's trace formats, kernel parameter table, cage
//! angle, warm-start priming and output plumbing, which are what this test checks. The dry
//! model at the same displacement must carry less (docs/physics.md §4: the film adds approach).

use bearing_core::{Bearing, OperatingState};
use bearing_hil::replay::engine::Parts;
use bearing_hil::replay::stats::Limits;
use bearing_hil::replay::{replay, FilmKind, ReplayConfig};
use bearing_hil::trace::{Sample, Trace, TraceMeta, ValidationOptions};
use bearing_hil::wiring;
use std::path::Path;

#[test]
fn a_trace_at_static_equilibrium_replays_to_the_applied_load() {
    let config = Path::new(env!("CARGO_MANIFEST_DIR")).join("../configs/hub_motor.toml");
    let (_, params) = bearing_host_common::config::BearingConfig::load(&config).unwrap();
    let speed = 21_000.0f32 * std::f32::consts::PI / 30.0;
    let start = OperatingState {
        displacement_m: [0.0, -5.0e-6],
        velocity_m_s: [0.0; 2],
        tilt_rad: [0.0; 2],
        shaft_speed_rad_s: speed,
    };
    let mut bearing: Bearing<17, 10> = Bearing::new(params, FilmKind::Regression).unwrap();
    let applied = [0.0, -2000.0];
    let equilibrium = bearing.static_equilibrium(applied, &start, 1e-5, 100);
    assert!(equilibrium.converged, "{equilibrium:?}");
    let [x, y] = equilibrium.displacement_m;

    // A constant-speed trace held at that displacement, written and read back as binary.
    let samples = (0..50)
        .map(|i| Sample {
            time_s: f64::from(i) * 1e-4,
            speed_rad_s: speed,
            x_m: x,
            y_m: y,
            vx_m_s: 0.0,
            vy_m_s: 0.0,
            tilt_rad: None,
        })
        .collect();
    let trace = Trace {
        meta: TraceMeta {
            bearing: "hub_motor".into(),
            lubricant: "thesis_oil".into(),
            sample_rate_hz: 10_000.0,
        },
        samples,
    };
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("equilibrium.bin");
    trace.write(&path, &ValidationOptions::default()).unwrap();
    let trace = Trace::read(&path, &ValidationOptions::default()).unwrap();

    let mut product =
        wiring::product(&trace.meta, FilmKind::Regression, &trace.samples[0]).unwrap();
    let config = ReplayConfig {
        rate_hz: 10_000.0,
        reference_every: 0,
        paced: false,
        limits: Limits::default(),
        min_reference_force_n: 1.0,
        realtime: None,
        realtime_fallback: false,
        pause_probe_s: 0.0,
        strict_timing: false,
    };
    let run = replay(
        &trace,
        Parts {
            stepper: product.stepper.as_mut(),
            reference: None,
            dry: None,
            warm_up: None,
        },
        &config,
        None,
    )
    .unwrap();
    // Step 0 is at cage angle 0, the state the equilibrium was solved at.
    let force = run.outputs[0].force_n;
    assert!(force[0].abs() < 2.0, "F_x = {} N", force[0]);
    assert!(
        (f64::from(force[1]) - 2000.0).abs() < 2.0,
        "F_y = {} N, expected 2000 N",
        force[1]
    );
    assert_eq!(run.outputs[0].rollers, 17);
    assert!(run.outputs.iter().all(|o| o.cage_angle_rad.is_finite()));

    // The dry model at the same displacement carries less: the film adds approach.
    let mut dry =
        wiring::KernelStepper::new(&trace.meta, bearing_hil::kernel::FilmKind::Dry).unwrap();
    let mut out = bearing_hil::outputs::StepOutputs::default();
    bearing_hil::replay::BearingStepper::step(&mut dry, &trace.samples[0], &mut out).unwrap();
    assert!(
        out.force_n[1] > 0.0 && out.force_n[1] < 0.95 * force[1],
        "dry {} N vs lubricated {} N",
        out.force_n[1],
        force[1]
    );
}
