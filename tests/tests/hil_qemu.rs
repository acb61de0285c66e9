//! End-to-end firmware replay: build `bearing-hil-firmware`, run it under QEMU, compare with
//! the host replay. Needs `qemu-system-arm` and the thumbv7em-none-eabihf Rust target
//! (`cargo xtask test` installs both); without them the tests fail, naming what is missing.
//!
//! References: the host build of the same kernel source (a different compiler target, x86-64
//! SSE vs the M4's single-precision FPU and soft f64) for the outputs; a block of exactly 1000
//! `nop` instructions for the instruction counter; a second run of the same firmware for
//! determinism; the trace's CRC for the firmware's own input checks.

use bearing_hil::kernel::FilmKind;
use bearing_hil::qemu::{self, tools, QemuOptions};
use bearing_hil::trace::synthetic::Whirl;
use bearing_hil::trace::{binary, TraceMeta, ValidationOptions};
use std::path::Path;
use std::time::Duration;

/// Fails the test, saying how to install them, when QEMU or the M4 target is missing.
fn require_qemu_and_target() {
    if let Err(reason) = tools::check_qemu().and_then(|()| tools::check_target()) {
        panic!("{reason}");
    }
}

fn write_trace(path: &Path, count: usize) {
    Whirl {
        speed_rad_s: 1800.0,
        // A run-up: 1800 → ≈ 3000 rad/s over 120 samples, so the determinism check covers
        // a changing speed.
        acceleration_rad_s2: 1.0e5,
        offset_m: [1.0e-6, -6.0e-6],
        radius_m: 2.0e-6,
        whirl_rad_s: 2.0 * std::f64::consts::PI * 150.0,
        tilt_amplitude_rad: None,
    }
    .trace(
        TraceMeta {
            bearing: "hub_motor".into(),
            lubricant: "thesis_oil".into(),
            sample_rate_hz: 10_000.0,
        },
        count,
    )
    .write(path, &ValidationOptions::default())
    .unwrap();
}

fn options(trace: &Path, report: &Path) -> QemuOptions {
    QemuOptions {
        trace: trace.to_path_buf(),
        report_dir: report.to_path_buf(),
        timeout: Duration::from_secs(300),
        max_instructions: 30_000,
        film: FilmKind::Regression,
    }
}

#[test]
fn firmware_replay_matches_the_host_bit_for_bit_and_counts_deterministically() {
    require_qemu_and_target();
    let dir = tempfile::tempdir().unwrap();
    let trace = dir.path().join("whirl.csv");
    write_trace(&trace, 120);
    let first = qemu::run(&options(&trace, &dir.path().join("a"))).unwrap();
    assert_eq!(first.steps, 120);
    assert!(first.outputs_match, "{:?}", first.comparison);
    assert_eq!(first.calibration.instructions, 1000);
    assert!(
        (168..=169).contains(&first.calibration.systick),
        "{:?}",
        first.calibration
    );
    assert!(first.instructions_per_step.min > 0);
    // The core's fixed-work rule (docs/architecture.md): every step the same instruction count.
    assert!(first.deterministic, "{:?}", first.instructions_per_step);
    // … and every friction call after the step the same count, apart from the step's.
    let friction = first.friction_instructions_per_step;
    assert!(
        friction.min > 0 && friction.min == friction.max,
        "{friction:?}"
    );
    assert!(first.flash_bytes > 1000 && first.flash_bytes < 1024 * 1024);
    assert!(first.stack_bytes > 0 && u64::from(first.stack_bytes) + first.ram_bytes < 128 * 1024);
    assert!(first.loop_stack_bytes > 0 && first.loop_stack_bytes < first.stack_bytes);

    // The profile's single regression step (another state, measured separately) costs what
    // the replayed steps cost, within 5 %: two measurements of the same code agree.
    let profiled = first
        .profile
        .iter()
        .find(|e| e.item.starts_with("Bearing::advance regression"))
        .map(|e| f64::from(e.instructions))
        .unwrap();
    let replayed = f64::from(first.instructions_per_step.median);
    assert!(
        (profiled / replayed - 1.0).abs() < 0.05,
        "{profiled} vs {replayed}"
    );

    // Same firmware, same trace: the same instruction count for every step.
    let second = qemu::run(&options(&trace, &dir.path().join("b"))).unwrap();
    let counts =
        |d: &str| std::fs::read_to_string(dir.path().join(d).join("instructions.csv")).unwrap();
    assert_eq!(counts("a"), counts("b"));
    // … and the same outputs, byte for byte.
    let outputs = |d: &str| std::fs::read(dir.path().join(d).join("outputs.bin")).unwrap();
    assert_eq!(outputs("a"), outputs("b"));
    assert_eq!(first.instructions_per_step, second.instructions_per_step);
}

/// The firmware checks its input itself: a flipped bit in a record (payload checksum, exit 5),
/// a truncated file (length, exit 4) and a bad magic (header, exit 3) end the run with the
/// documented code, never a hang.
#[test]
fn firmware_rejects_corrupted_traces_with_its_exit_code() {
    require_qemu_and_target();
    let elf = tools::build_firmware(&tools::firmware_dir()).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let source = dir.path().join("whirl.bin");
    write_trace(&source, 40);
    let good = std::fs::read(&source).unwrap();
    assert!(binary::decode(&good, &ValidationOptions::default()).is_ok());

    let mut flipped = good.clone();
    let last = flipped.len() - 5;
    flipped[last] ^= 0x10;
    let mut bad_magic = good.clone();
    bad_magic[0] = b'X';
    let cases = [
        (flipped, 5),
        (good[..good.len() - 10].to_vec(), 4),
        (bad_magic, 3),
    ];
    for (bytes, expected) in cases {
        std::fs::write(dir.path().join("trace.bin"), &bytes).unwrap();
        std::fs::write(dir.path().join("film.txt"), "regression").unwrap();
        let (code, _log) = qemu::run_qemu(&elf, dir.path(), Duration::from_secs(60)).unwrap();
        assert_eq!(
            code,
            Some(expected),
            "{}",
            qemu::describe_exit(code.unwrap_or(-1))
        );
    }
}
