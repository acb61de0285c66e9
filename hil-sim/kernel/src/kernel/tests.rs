//! Tests of the step kernel. References: the bearing config files (`configs/*.toml`, read by
//! the host's config loader) for the parameters; the core's bearing settled directly at an
//! independently computed cage angle (docs/physics.md §2, integrated in f64) for the step.

use super::*;
use bearing_core::film::FilmSource;
use std::path::Path;

fn sample(x: f32, y: f32, speed: f32) -> Sample {
    Sample {
        time_s: 0.0,
        speed_rad_s: speed,
        x_m: x,
        y_m: y,
        vx_m_s: 1.0e-4,
        vy_m_s: -2.0e-4,
        tilt_rad: None,
    }
}

#[test]
fn parameters_agree_with_the_config_files() {
    for id in ["hub_motor", "nu205"] {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../configs")
            .join(format!("{id}.toml"));
        let (_, from_file) = bearing_host_common::config::BearingConfig::load(&path).unwrap();
        assert_eq!(params(id, "thesis_oil").unwrap(), from_file, "{id}");
    }
    // The high-speed identifiers together: the hub motor's high-speed bearing file, with its
    // centrifugal force and both film corrections.
    let path =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../configs/hub_motor_high_speed.toml");
    let (_, from_file) = bearing_host_common::config::BearingConfig::load(&path).unwrap();
    assert_eq!(params("hub_motor_hs", "thesis_oil_hs").unwrap(), from_file);
    assert_ne!(
        params("hub_motor_hs", "thesis_oil").unwrap(),
        params("hub_motor", "thesis_oil").unwrap()
    );
}

#[test]
fn step_is_the_core_step_at_the_integrated_cage_angle() {
    let rate = 10_000.0;
    let (x, y, speed) = (1.0e-6f32, -6.0e-6f32, 2000.0f32);
    let mut kernel = Kernel::new("hub_motor", "thesis_oil", rate, FilmKind::Regression).unwrap();
    kernel.prime(&sample(x, y, speed));
    let mut out = StepOutputs::default();
    let steps = 40;
    for _ in 0..steps {
        kernel.step(&sample(x, y, speed), &mut out).unwrap();
    }
    // Cage speed (ω/2)(1 − D/d_m) over steps − 1 periods, in f64.
    let cage = (0.5 * (1.0 - 8.8 / 60.0) * 2000.0 * f64::from(steps - 1) / rate)
        .rem_euclid(std::f64::consts::TAU);
    assert!((f64::from(out.cage_angle_rad) - cage).abs() < 1e-4);

    // The core called directly, converged at the kernel's state.
    let mut bearing: Bearing<17, SLICES> = Bearing::new(
        params("hub_motor", "thesis_oil").unwrap(),
        FilmKind::Regression,
    )
    .unwrap();
    bearing.set_cage_angle(out.cage_angle_rad).unwrap();
    let state = OperatingState {
        displacement_m: [x, y],
        velocity_m_s: [1.0e-4, -2.0e-4],
        tilt_rad: [0.0; 2],
        shaft_speed_rad_s: speed,
    };
    let direct = bearing.settle(&state, 20).unwrap();
    assert_eq!(out.rollers, 17);
    let force = f64::from(direct.force_n[0]).hypot(f64::from(direct.force_n[1]));
    assert!(force > 100.0, "the state loads the bearing: {force} N");
    for k in 0..2 {
        // Same state, warm starts converged along different paths: 1e-4 relative.
        assert!(
            (f64::from(out.force_n[k]) - f64::from(direct.force_n[k])).abs() < 1e-4 * force,
            "force {k}: {} vs {}",
            out.force_n[k],
            direct.force_n[k]
        );
    }
    for (j, r) in direct.rollers.iter().enumerate() {
        assert_eq!(
            out.roller_approach_m[j], r.geometric_approach_m,
            "roller {j}"
        );
        assert_eq!(out.source_inner[j], r.film_source_in);
        if r.load_n > 0.0 {
            assert!(out.film_inner_m[j] > 0.0 && out.film_outer_m[j] > 0.0);
        }
    }
}

#[test]
fn dry_steps_carry_no_film() {
    let mut kernel = Kernel::new("nu205", "thesis_oil", 1e4, FilmKind::Dry).unwrap();
    let mut out = StepOutputs::default();
    kernel
        .step(&sample(0.0, -8.0e-6, 1500.0), &mut out)
        .unwrap();
    assert_eq!(out.rollers, 12);
    assert!(out.roller_load_n[..12].iter().any(|&q| q > 0.0));
    assert!(out.film_inner_m[..12].iter().all(|&h| h == 0.0));
    assert!(out.source_inner[..12]
        .iter()
        .all(|&s| s == FilmSource::None));
}

#[test]
fn refuses_what_it_cannot_step() {
    let new = |b: &str, l: &str, r: f64, f: FilmKind| Kernel::new(b, l, r, f).unwrap_err();
    assert_eq!(
        new("nu999", "thesis_oil", 1e4, FilmKind::Dry),
        KernelError::UnknownBearing
    );
    assert_eq!(
        new("nu205", "water", 1e4, FilmKind::Dry),
        KernelError::UnknownLubricant
    );
    assert_eq!(
        new("nu205", "thesis_oil", f64::NAN, FilmKind::Dry),
        KernelError::BadSampleRate
    );
    let mut kernel = Kernel::new("nu205", "thesis_oil", 1e4, FilmKind::Regression).unwrap();
    let mut out = StepOutputs::default();
    match kernel.step(&sample(f32::NAN, 0.0, 1.0), &mut out) {
        Err(KernelFault::Rejected(e)) => assert_eq!(e.field, "displacement_x_m"),
        other => panic!("expected a rejection, got {other:?}"),
    }
    // A NaN speed is refused and leaves the cage angle usable for the next sample.
    assert!(kernel
        .step(&sample(0.0, -5.0e-6, f32::NAN), &mut out)
        .is_err());
    kernel
        .step(&sample(0.0, -5.0e-6, 1000.0), &mut out)
        .unwrap();
    assert!(out.cage_angle_rad.is_finite());
    assert_eq!(FilmKind::from_name(b" regression\\n"), None);
    assert_eq!(
        FilmKind::from_name(b" regression\n"),
        Some(FilmKind::Regression)
    );
}

/// Determinism on the host: two fresh kernels replaying the same trace give bit-identical
/// outputs (the firmware side of the claim is the QEMU integration test).
#[test]
fn two_replays_are_bit_identical() {
    let replay = || {
        let mut kernel = Kernel::new("hub_motor", "thesis_oil", 1e4, FilmKind::Regression).unwrap();
        let samples: Vec<Sample> = (0..200)
            .map(|i| {
                let phase = i as f32 * 0.2;
                sample(1.5e-6 * phase.cos(), -6.0e-6 + 1.5e-6 * phase.sin(), 2199.0)
            })
            .collect();
        kernel.prime(&samples[0]);
        let mut outputs = vec![StepOutputs::default(); samples.len()];
        for (s, out) in samples.iter().zip(outputs.iter_mut()) {
            kernel.step(s, out).unwrap();
        }
        outputs
    };
    let (a, b) = (replay(), replay());
    let bits = |o: &[StepOutputs]| -> Vec<u32> {
        o.iter()
            .flat_map(|s| {
                s.force_n
                    .iter()
                    .chain(&s.roller_load_n)
                    .chain(&s.film_inner_m)
            })
            .map(|v| v.to_bits())
            .collect()
    };
    assert_eq!(bits(&a), bits(&b));
    assert!(
        a.iter().all(|o| o.force_n[1] > 0.0),
        "the orbit loads the bearing"
    );
}

#[test]
fn steps_the_networks_and_flags_their_contacts() {
    // The hub-motor bearing loaded downward at 12 000 rpm: the integer and f32 networks serve
    // the loaded contacts (docs/physics.md §5.3 domain) and give films within a few percent of each
    // other; every contact is flagged by the network or its fallback.
    let mut films = Vec::new();
    for kind in [FilmKind::Int, FilmKind::F32] {
        let mut kernel = Kernel::new("hub_motor", "thesis_oil", 1e4, kind).unwrap();
        let s = sample(0.0, -6.0e-6, 1256.6);
        kernel.prime(&s);
        let mut out = StepOutputs::default();
        kernel.step(&s, &mut out).unwrap();
        let network = if kind == FilmKind::Int {
            FilmSource::NetworkInt
        } else {
            FilmSource::NetworkF32
        };
        assert!(
            out.source_inner[..17].contains(&network),
            "{kind:?}: no contact served by the network"
        );
        assert!(out.source_inner[..17]
            .iter()
            .all(|&s| s == network || s == FilmSource::Fallback));
        films.push(out.film_inner_m[..17].to_vec());
    }
    for (a, b) in films[0].iter().zip(films[1].iter()) {
        assert!((a / b - 1.0).abs() < 0.02, "int {a} vs f32 {b}");
    }
}

#[test]
fn friction_is_the_cores_and_leaves_the_step_alone() {
    // Along an orbit: a kernel that computes the friction after every step, one that does
    // not, and the core's bearing stepped directly as the kernel does (settled at the first
    // sample, then advanced by 0 and by the period). The friction must be the core's
    // `Bearing::friction` bit for bit, and the step's outputs must not see it.
    let rate = 1e4;
    let samples: Vec<Sample> = (0..60)
        .map(|i| {
            let phase = i as f32 * 0.3;
            sample(1.5e-6 * phase.cos(), -6.0e-6 + 1.5e-6 * phase.sin(), 1500.0)
        })
        .collect();
    let mut with = Kernel::new("hub_motor", "thesis_oil", rate, FilmKind::Int).unwrap();
    let mut without = with.clone();
    let mut bearing: Bearing<17, SLICES> =
        Bearing::new(params("hub_motor", "thesis_oil").unwrap(), FilmKind::Int).unwrap();
    with.prime(&samples[0]);
    without.prime(&samples[0]);
    bearing
        .settle(&Kernel::state(&samples[0]), PRIME_STEPS)
        .unwrap();
    let period_s = (1.0 / rate) as f32;
    for (i, s) in samples.iter().enumerate() {
        let (mut a, mut b) = (StepOutputs::default(), StepOutputs::default());
        with.step(s, &mut a).unwrap();
        with.friction(s, &mut a).unwrap();
        without.step(s, &mut b).unwrap();
        let dt_s = if i == 0 { 0.0 } else { period_s };
        bearing.advance(&Kernel::state(s), dt_s).unwrap();
        let core = bearing.friction(s.speed_rad_s).unwrap();
        let friction = |o: &StepOutputs| {
            [o.friction_torque_nm, o.power_loss_w]
                .into_iter()
                .chain(o.power_loss_split_w)
                .map(f32::to_bits)
                .collect::<Vec<_>>()
        };
        let expected: Vec<u32> = [core.friction_torque_nm, core.power_loss_w]
            .into_iter()
            .chain(core.power_loss_split_w)
            .map(f32::to_bits)
            .collect();
        assert_eq!(friction(&a), expected, "step {i}");
        assert!(a.power_loss_w > 0.0, "step {i}: no power loss");
        // The step's fields alike; the record without friction keeps zeros there.
        let step_part = StepOutputs {
            friction_torque_nm: 0.0,
            power_loss_w: 0.0,
            power_loss_split_w: [0.0; 3],
            ..a
        };
        assert_eq!(step_part, b, "step {i}");
    }
}
