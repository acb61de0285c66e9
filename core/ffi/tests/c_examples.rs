//! The two C examples (core/ffi/examples), built and run: the host program (`cc`, linked with
//! this build's static library) and the Cortex-M4F program (`arm-none-eabi-gcc` with newlib,
//! the library built for thumbv7em-none-eabihf, run on `qemu-system-arm -M netduinoplus2` with
//! semihosting and `-icount shift=0`). Each replays the bundled hub-motor trace
//! (hil-sim/traces/hub_motor_runup.bin, all 20 000 samples) and writes the HIL harness's output
//! records; every value of every step must be bit-identical to the harness's own kernel
//! (hil-sim/kernel, which `hil-sim replay` and the Rust firmware of `hil-sim qemu` run).
//!
//! The M4 program is linked with the library's feature `prove-no-panic` and every exported
//! function kept (`-u`): it links only because no path to the panic handler is left.

use bearing_hil_kernel::kernel::{FilmKind, Kernel};
use bearing_hil_kernel::outputs::{self, StepOutputs, Trailer, OUTPUT_HEADER_LEN, TRAILER_LEN};
use bearing_hil_kernel::wire::{self, Header, HEADER_LEN};
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const TARGET: &str = "thumbv7em-none-eabihf";
/// The Rust firmware's instructions per step for the same trace and film model
/// (`hil-sim qemu --json`, docs/performance.md), for the report line.
const RUST_FIRMWARE_INSTRUCTIONS: u32 = 27_280;

fn workspace() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn ffi_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).to_path_buf()
}

fn trace_path() -> PathBuf {
    workspace().join("hil-sim/traces/hub_motor_runup.bin")
}

/// A fresh scratch directory under the target directory.
fn scratch(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs `command`, failing the test with its output when it does not succeed (or is missing:
/// then with the package that provides it).
fn run(command: &mut Command, install_hint: &str) -> std::process::Output {
    let shown = format!("{command:?}");
    let out = command
        .output()
        .unwrap_or_else(|e| panic!("cannot run {shown}: {e} ({install_hint})"));
    assert!(
        out.status.success(),
        "{shown} failed ({:?}):\n{}\n{}",
        out.status,
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    out
}

/// The harness's kernel over the first `steps` samples of the trace: primed at the first,
/// then one `step` and one `friction` per sample, as `hil-sim replay` and the firmware do.
fn harness_outputs(steps: usize) -> Vec<StepOutputs> {
    let bytes = std::fs::read(trace_path()).unwrap();
    let header = Header::parse(bytes[..HEADER_LEN].try_into().unwrap()).unwrap();
    header.check_length(bytes.len()).unwrap();
    let mut kernel = Kernel::new(
        wire::identifier_str(&header.bearing_id),
        wire::identifier_str(&header.lubricant_id),
        header.sample_rate_hz,
        FilmKind::Int,
    )
    .unwrap();
    let mut payload = wire::PayloadCheck::default();
    let mut result = Vec::with_capacity(steps);
    for (index, record) in bytes[HEADER_LEN..]
        .chunks_exact(header.record_len())
        .enumerate()
    {
        payload.feed(record);
        if index >= steps {
            continue;
        }
        let sample = wire::decode_record(record, header.has_tilt).unwrap();
        if index == 0 {
            kernel.prime(&sample);
        }
        let mut out = StepOutputs::default();
        kernel.step(&sample, &mut out).unwrap();
        kernel.friction(&sample, &mut out).unwrap();
        result.push(out);
    }
    payload.verify(&header).unwrap();
    result
}

/// The records of an outputs file: per step the instruction counts of the step and of the
/// friction call, and the outputs.
fn decode_outputs(bytes: &[u8]) -> (Vec<(outputs::StepCounts, StepOutputs)>, Trailer) {
    assert!(
        bytes.len() >= OUTPUT_HEADER_LEN + TRAILER_LEN,
        "outputs file too short"
    );
    assert_eq!(&bytes[..8], &outputs::OUTPUT_MAGIC);
    let rollers = usize::from(u16::from_le_bytes([bytes[10], bytes[11]]));
    let count = u32::from_le_bytes(bytes[12..16].try_into().unwrap()) as usize;
    let record_len = outputs::record_len(rollers);
    let body_end = OUTPUT_HEADER_LEN + count * record_len;
    assert_eq!(bytes.len(), body_end + TRAILER_LEN, "outputs file length");
    let steps = bytes[OUTPUT_HEADER_LEN..body_end]
        .chunks_exact(record_len)
        .map(|record| {
            let (counts, out) = outputs::decode_step(record, rollers).unwrap();
            (counts, out)
        })
        .collect();
    (steps, Trailer::decode(&bytes[body_end..]).unwrap())
}

/// Every value of `c` has the bits of `rust`'s (−0 and 0 differ, NaN payloads count).
fn assert_bit_identical(program: &str, step: usize, c: &StepOutputs, rust: &StepOutputs) {
    let bits = |o: &StepOutputs| {
        let mut v = vec![
            o.force_n[0],
            o.force_n[1],
            o.cage_angle_rad,
            o.friction_torque_nm,
            o.power_loss_w,
        ];
        v.extend(o.power_loss_split_w);
        for j in 0..o.rollers {
            v.extend([
                o.roller_load_n[j],
                o.film_inner_m[j],
                o.film_outer_m[j],
                o.roller_approach_m[j],
            ]);
        }
        v.into_iter().map(f32::to_bits).collect::<Vec<_>>()
    };
    let sources = |o: &StepOutputs| {
        let n = o.rollers;
        (o.source_inner[..n].to_vec(), o.source_outer[..n].to_vec())
    };
    assert_eq!(
        c.rollers, rust.rollers,
        "{program}, step {step}: roller count"
    );
    assert!(
        bits(c) == bits(rust) && sources(c) == sources(rust),
        "{program}, step {step}: outputs differ from the harness's\n C:    {c:?}\n Rust: {rust:?}"
    );
}

/// Checks every step of an outputs file against the harness; returns the instruction counts.
fn compare_with_harness(
    program: &str,
    outputs_file: &Path,
    steps: usize,
) -> Vec<outputs::StepCounts> {
    let (records, trailer) = decode_outputs(&std::fs::read(outputs_file).unwrap());
    assert_eq!(trailer.status, 0, "{program}: trailer status");
    assert_eq!(records.len(), steps, "{program}: steps written");
    let rust = harness_outputs(steps);
    for (step, ((_, c), rust)) in records.iter().zip(&rust).enumerate() {
        assert_bit_identical(program, step, c, rust);
    }
    records.iter().map(|(counts, _)| *counts).collect()
}

/// The static library of this build for the host (cargo puts the staticlib next to the rlib
/// this test links, in the directory of the test executable).
fn host_staticlib() -> PathBuf {
    let exe = std::env::current_exe().unwrap();
    let lib = exe.parent().unwrap().join("libbearing_ffi.a");
    assert!(lib.is_file(), "{} is missing", lib.display());
    lib
}

#[test]
fn host_c_example_replays_the_hub_trace_bit_identically() {
    let dir = scratch("ffi-host-example");
    let exe = dir.join("replay-host");
    let examples = ffi_dir().join("examples");
    run(
        Command::new(std::env::var("CC").unwrap_or_else(|_| "cc".into()))
            .args(["-std=c11", "-O2", "-Wall", "-Wextra", "-Werror", "-I"])
            .arg(ffi_dir().join("include"))
            .arg("-I")
            .arg(examples.join("common"))
            .arg(examples.join("host/main.c"))
            .arg(examples.join("common/replay.c"))
            .arg(host_staticlib())
            .args(["-lpthread", "-ldl", "-lm", "-o"])
            .arg(&exe),
        "install a C compiler: apt-get install gcc",
    );
    let outputs_file = dir.join("outputs.bin");
    run(
        Command::new(&exe).arg(trace_path()).arg(&outputs_file),
        "the example was just built",
    );
    let counts = compare_with_harness("host C example", &outputs_file, 20_000);
    assert!(
        counts
            .iter()
            .all(|c| c.instructions == 0 && c.friction_instructions == 0),
        "the host program counts nothing"
    );
}

/// Builds the library for the Cortex-M4F as a firmware would link it: fat LTO, one codegen unit,
/// no overflow checks (the host profile keeps them for the tests), the panic proof on. Its own
/// target directory, so that the enclosing cargo's is neither locked nor rebuilt.
fn build_m4_staticlib() -> PathBuf {
    let target_dir = workspace().join("target/ffi-m4");
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    run(
        Command::new(cargo)
            .current_dir(workspace())
            .args(["rustc", "--release", "-p", "bearing-ffi", "--lib"])
            .args(["--target", TARGET, "--crate-type", "staticlib"])
            .args(["--features", "prove-no-panic", "--target-dir"])
            .arg(&target_dir)
            .env("CARGO_PROFILE_RELEASE_LTO", "fat")
            .env("CARGO_PROFILE_RELEASE_CODEGEN_UNITS", "1")
            .env("CARGO_PROFILE_RELEASE_OVERFLOW_CHECKS", "false")
            .env_remove("RUSTFLAGS")
            .env_remove("CARGO_ENCODED_RUSTFLAGS")
            .env_remove("CARGO_BUILD_TARGET")
            .env_remove("CARGO_TARGET_DIR"),
        "rustup target add thumbv7em-none-eabihf",
    );
    target_dir.join(TARGET).join("release/libbearing_ffi.a")
}

/// The functions the header declares.
fn exported_functions() -> Vec<String> {
    let header = std::fs::read_to_string(ffi_dir().join("include/bearing.h")).unwrap();
    let mut names: Vec<String> = header
        .lines()
        .filter_map(|line| {
            let start = line.find("bearing_")?;
            let rest = &line[start..];
            let end = rest.find('(')?;
            let name = &rest[..end];
            name.bytes()
                .all(|b| b.is_ascii_alphanumeric() || b == b'_')
                .then(|| name.to_string())
        })
        .collect();
    names.dedup();
    assert!(
        names.len() >= 10,
        "functions found in the header: {names:?}"
    );
    names
}

#[test]
fn m4_c_example_replays_the_hub_trace_bit_identically_under_qemu() {
    let lib = build_m4_staticlib();
    let dir = scratch("ffi-m4-example");
    let elf = dir.join("replay-m4.elf");
    let examples = ffi_dir().join("examples");
    let mut gcc = Command::new("arm-none-eabi-gcc");
    gcc.args(["-std=c11", "-O2", "-Wall", "-Wextra", "-Werror"])
        .args([
            "-mcpu=cortex-m4",
            "-mthumb",
            "-mfloat-abi=hard",
            "-mfpu=fpv4-sp-d16",
        ])
        .arg("-I")
        .arg(ffi_dir().join("include"))
        .arg("-I")
        .arg(examples.join("common"))
        .arg("-T")
        .arg(examples.join("m4/link.ld"))
        .args([
            "-nostartfiles",
            "--specs=nano.specs",
            "--specs=rdimon.specs",
        ])
        .args(["-Wl,--gc-sections", "-Wl,--no-warn-execstack"]);
    // Keep every exported function, so the panic proof covers all of them.
    for name in exported_functions() {
        gcc.arg(format!("-Wl,--undefined={name}"));
    }
    run(
        gcc.arg(examples.join("m4/main.c"))
            .arg(examples.join("common/replay.c"))
            .arg(&lib)
            .args(["-lm", "-o"])
            .arg(&elf),
        "apt-get install gcc-arm-none-eabi libnewlib-arm-none-eabi",
    );
    std::fs::copy(trace_path(), dir.join("trace.bin")).unwrap();

    let started = Instant::now();
    let mut qemu = Command::new("qemu-system-arm")
        .current_dir(&dir)
        .args(["-M", "netduinoplus2", "-nographic", "-monitor", "none"])
        .args([
            "-serial",
            "none",
            "-semihosting-config",
            "enable=on,target=native",
        ])
        .args(["-icount", "shift=0", "-kernel"])
        .arg(&elf)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .spawn()
        .expect("cannot start qemu-system-arm (apt-get install qemu-system-arm)");
    let status = loop {
        if let Some(status) = qemu.try_wait().unwrap() {
            break status;
        }
        if started.elapsed() > Duration::from_secs(300) {
            let _ = qemu.kill();
            panic!("QEMU did not finish the replay within 300 s");
        }
        std::thread::sleep(Duration::from_millis(50));
    };
    let stdout = qemu.wait_with_output().unwrap().stdout;
    println!("{}", String::from_utf8_lossy(&stdout).trim());
    assert!(status.success(), "the M4 program exited with {status:?}");

    let counts = compare_with_harness("M4 C example", &dir.join("outputs.bin"), 20_000);
    let (_, trailer) = decode_outputs(&std::fs::read(dir.join("outputs.bin")).unwrap());
    assert_eq!(
        trailer.calibration_instructions, 1000,
        "TIM2 does not count instructions (is -icount shift=0 in effect?)"
    );
    let range = |values: Vec<u32>| (*values.iter().min().unwrap(), *values.iter().max().unwrap());
    let (fewest, most) = range(counts.iter().map(|c| c.instructions).collect());
    let (friction_fewest, friction_most) =
        range(counts.iter().map(|c| c.friction_instructions).collect());
    println!(
        "M4 C program: {fewest}..{most} instructions per bearing_advance (Rust firmware's \
         kernel step: {RUST_FIRMWARE_INSTRUCTIONS}), {friction_fewest}..{friction_most} per \
         bearing_friction, QEMU {:.1} s",
        started.elapsed().as_secs_f64()
    );
    assert_eq!(fewest, most, "the step's instruction count varies");
    assert_eq!(
        friction_fewest, friction_most,
        "the friction call's instruction count varies"
    );
}

/// The minimal program of docs/c-api.md (which must show core/ffi/examples/minimal.c as it is)
/// builds, runs, and prints the force, stiffness, cage angle and friction the core computes in
/// Rust, as the page shows them.
#[test]
fn minimal_program_of_the_docs_prints_the_cores_numbers() {
    use bearing_core::{Bearing, BearingDesign, FilmKind, OperatingState};

    let source = std::fs::read_to_string(ffi_dir().join("examples/minimal.c")).unwrap();
    let docs = std::fs::read_to_string(workspace().join("docs/c-api.md")).unwrap();
    assert!(
        docs.contains(&source),
        "docs/c-api.md does not show core/ffi/examples/minimal.c as it is"
    );
    let dir = scratch("ffi-minimal");
    let exe = dir.join("minimal");
    run(
        Command::new(std::env::var("CC").unwrap_or_else(|_| "cc".into()))
            .args(["-std=c11", "-O2", "-Wall", "-Wextra", "-Werror", "-I"])
            .arg(ffi_dir().join("include"))
            .arg(ffi_dir().join("examples/minimal.c"))
            .arg(host_staticlib())
            .args(["-lpthread", "-ldl", "-lm", "-o"])
            .arg(&exe),
        "install a C compiler: apt-get install gcc",
    );
    let printed = String::from_utf8(run(&mut Command::new(&exe), "just built").stdout).unwrap();
    assert!(
        docs.contains(&printed),
        "docs/c-api.md does not show what core/ffi/examples/minimal.c prints: {printed}"
    );
    let numbers: Vec<f32> = printed
        .split_whitespace()
        .filter_map(|word| word.parse().ok())
        .collect();

    let mut bearing =
        Bearing::<17, 10>::new(BearingDesign::HUB_MOTOR.params().unwrap(), FilmKind::Int).unwrap();
    let state = OperatingState::new([0.0, -5.0e-6], [0.0; 2], [0.0; 2], 2000.0).unwrap();
    bearing.settle(&state, 6).unwrap();
    for _ in 0..10 {
        bearing.advance(&state, 1.0e-4).unwrap();
    }
    let out = *bearing.output();
    let cage_angle_rad = bearing.cage_angle_rad();
    let friction = bearing.friction(state.shaft_speed_rad_s).unwrap();
    let expected = [
        out.force_n[0],
        out.force_n[1],
        out.stiffness[1][1],
        cage_angle_rad,
        friction.friction_torque_nm,
        friction.power_loss_w,
        friction.power_loss_split_w[0],
        friction.power_loss_split_w[1],
        friction.power_loss_split_w[2],
        friction.lambda[0][0],
        friction.lambda[0][1],
    ];
    // Nine significant digits identify an f32 exactly.
    assert_eq!(
        numbers.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
        expected.iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
        "printed: {printed}"
    );
}
