//! Firmware replay on an emulated Cortex-M4: build `bearing-hil-firmware`, run it under QEMU
//! (`netduinoplus2`, an STM32F405, with `-icount shift=0` so that virtual time counts
//! instructions), read back what it computed and counted, and compare with the host replay.
//!
//! The working directory of QEMU (the report directory) receives `trace.bin` (the trace in the
//! binary format, whatever form it came in), and the firmware writes `outputs.bin` there
//! through semihosting; its defmt log is QEMU's stdout, kept as `log.defmt` and decoded with
//! `defmt-print` when that is installed.

pub mod compare;
pub mod elf;
pub mod tools;

use crate::kernel::FilmKind;
use crate::trace::{binary, Trace, ValidationOptions};
use bearing_host_common::output::write_file;
use serde::Serialize;
use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// How to run the emulated replay.
#[derive(Clone, Debug, PartialEq)]
pub struct QemuOptions {
    /// Trace file (CSV or binary).
    pub trace: PathBuf,
    /// Working and report directory.
    pub report_dir: PathBuf,
    /// QEMU is killed after this long.
    pub timeout: Duration,
    /// Largest acceptable instruction count per step (30 000 ≈ 5 kHz at 168 MHz).
    pub max_instructions: u32,
    /// Film model of the step (written to `film.txt` for the firmware).
    pub film: FilmKind,
}

/// Minimum, median and maximum of a per-step count.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct CountRange {
    /// Smallest.
    pub min: u32,
    /// 50th percentile (nearest rank).
    pub median: u32,
    /// Largest.
    pub max: u32,
}

impl CountRange {
    fn of(values: impl Iterator<Item = u32>) -> Option<CountRange> {
        let mut sorted: Vec<u32> = values.collect();
        sorted.sort_unstable();
        Some(CountRange {
            min: *sorted.first()?,
            median: crate::replay::stats::percentile_sorted(&sorted, 0.5)?,
            max: *sorted.last()?,
        })
    }
}

/// Counts of a block of 1000 `nop` (the firmware's calibration).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Calibration {
    /// TIM2 counts: 1000 when it counts instructions.
    pub instructions: u32,
    /// SysTick counts: 168 or 169 at 168 MHz of virtual time.
    pub systick: u32,
}

/// Instructions of one building block of the step.
#[derive(Clone, Debug, PartialEq, Eq, Serialize)]
pub struct ProfileEntry {
    /// What was measured.
    pub item: String,
    /// Its instructions.
    pub instructions: u32,
}

/// Parses the firmware's `profile.csv` (`item,instructions` lines after a header).
pub fn parse_profile(text: &str) -> Vec<ProfileEntry> {
    text.lines()
        .skip(1)
        .filter_map(|line| {
            let (item, count) = line.rsplit_once(',')?;
            Some(ProfileEntry {
                item: item.to_string(),
                instructions: count.trim().parse().ok()?,
            })
        })
        .collect()
}

/// The report of an emulated replay (the documented keys first, docs/hil.md).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct QemuReport {
    /// Instructions per step (TIM2 at 1 GHz of virtual time, `-icount shift=0`).
    pub instructions_per_step: CountRange,
    /// Instructions of the friction call after each step (`Bearing::friction`), counted apart
    /// from the step.
    pub friction_instructions_per_step: CountRange,
    /// Flash used by the firmware image (bytes).
    pub flash_bytes: u64,
    /// Static RAM (data + bss) of the firmware image (bytes).
    pub ram_bytes: u64,
    /// Peak stack since reset, by stack painting (bytes).
    pub stack_bytes: u32,
    /// Every output of every step bit-identical to the host replay.
    pub outputs_match: bool,
    /// Steps replayed.
    pub steps: usize,
    /// Peak stack below the replay loop: the step and its I/O (bytes).
    pub loop_stack_bytes: u32,
    /// SysTick counts per step (168 MHz of virtual time), the cross-check.
    pub systick_per_step: CountRange,
    /// TIM2 and SysTick counts of 1000 `nop` (must be 1000 and 168–169).
    pub calibration: Calibration,
    /// Same instruction count for every step, and for every friction call.
    pub deterministic: bool,
    /// The limit on instructions per step.
    pub max_instructions_limit: u32,
    /// Bit-level comparison with the host replay.
    pub comparison: compare::Comparison,
    /// Wall-clock time of the QEMU run (s).
    pub qemu_wall_s: f64,
    /// The firmware ELF.
    pub firmware: PathBuf,
    /// Film model stepped.
    pub film: &'static str,
    /// Instructions of the core's building blocks, each called once on typical hub-motor
    /// values (`profile.csv` of the firmware): what a step is made of.
    pub profile: Vec<ProfileEntry>,
    /// The decoded defmt log, when `defmt-print` is installed.
    pub log: Option<Vec<String>>,
    /// Why the run failed its checks (empty when it passed).
    pub reasons: Vec<String>,
}

impl QemuReport {
    /// True when every check passed.
    pub fn passed(&self) -> bool {
        self.reasons.is_empty()
    }
}

/// What a firmware exit code means (`hil-sim/firmware/src/main.rs`, `Failure`).
pub fn describe_exit(code: i32) -> &'static str {
    match code {
        1 => "QEMU failed to start the firmware, or it exited through plain SYS_EXIT",
        2 => "the firmware cannot open or read trace.bin",
        3 => "the firmware rejected the trace header",
        4 => "the firmware found the trace length inconsistent with its header",
        5 => "the firmware found a trace checksum mismatch",
        6 => "the kernel refuses the trace's bearing or sample rate",
        7 => "a step failed on the firmware",
        8 => "the firmware cannot write outputs.bin",
        9 => "SysTick or TIM2 counted nothing (is -icount missing?)",
        10 => "the core peripherals were unavailable",
        11 => "film.txt is missing or names no film model",
        101 => "the firmware panicked",
        _ => "unknown firmware exit code",
    }
}

/// Runs QEMU on `elf` in `dir` (which must hold `trace.bin` and `film.txt`), killing it after `timeout`;
/// returns the exit code (`None` when killed by a signal) and QEMU's stdout (the defmt log).
pub fn run_qemu(
    elf: &Path,
    dir: &Path,
    timeout: Duration,
) -> Result<(Option<i32>, Vec<u8>), String> {
    let mut child = Command::new("qemu-system-arm")
        .current_dir(dir)
        .args([
            "-machine",
            "netduinoplus2",
            "-cpu",
            "cortex-m4",
            "-nographic",
            "-monitor",
            "none",
            "-serial",
            "none",
            "-semihosting-config",
            "enable=on,target=native",
            "-icount",
            "shift=0",
            "-kernel",
        ])
        .arg(elf)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::inherit())
        .spawn()
        .map_err(|e| format!("cannot start qemu-system-arm: {e}"))?;
    let mut stdout = child.stdout.take().ok_or("no QEMU stdout")?;
    let reader = std::thread::spawn(move || {
        let mut log = Vec::new();
        let _ = stdout.read_to_end(&mut log);
        log
    });
    let deadline = Instant::now() + timeout;
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break status,
            Ok(None) if Instant::now() >= deadline => {
                let _ = child.kill();
                let _ = child.wait();
                return Err(format!(
                    "QEMU did not finish within {} s and was killed",
                    timeout.as_secs_f64()
                ));
            }
            Ok(None) => std::thread::sleep(Duration::from_millis(20)),
            Err(e) => return Err(format!("waiting for QEMU: {e}")),
        }
    };
    let log = reader.join().unwrap_or_default();
    Ok((status.code(), log))
}

/// Decodes the defmt log with `defmt-print`, if installed.
fn decode_log(elf: &Path, log: &[u8]) -> Option<Vec<String>> {
    let mut child = Command::new("defmt-print")
        .arg("-e")
        .arg(elf)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .ok()?;
    let mut stdin = child.stdin.take()?;
    let bytes = log.to_vec();
    let writer = std::thread::spawn(move || {
        use std::io::Write;
        let _ = stdin.write_all(&bytes);
    });
    let out = child.wait_with_output().ok()?;
    let _ = writer.join();
    Some(
        String::from_utf8_lossy(&out.stdout)
            .lines()
            .map(str::to_string)
            .collect(),
    )
}

/// Builds the firmware, replays the trace on it and on the host, and compares.
pub fn run(options: &QemuOptions) -> Result<QemuReport, String> {
    tools::check_qemu()?;
    tools::check_target()?;
    let trace = Trace::read(&options.trace, &ValidationOptions::default())
        .map_err(|e| format!("reading trace {}: {e}", options.trace.display()))?;
    let host = compare::host_outputs(&trace, options.film)?;

    let elf = tools::build_firmware(&tools::firmware_dir())?;
    let image = std::fs::read(&elf).map_err(|e| format!("reading {}: {e}", elf.display()))?;
    let memory = elf::memory_use(&image)
        .ok_or_else(|| format!("{} is not a 32-bit little-endian ELF", elf.display()))?;

    let dir = &options.report_dir;
    std::fs::create_dir_all(dir).map_err(|e| format!("creating {}: {e}", dir.display()))?;
    let bytes = binary::encode(&trace).map_err(|e| e.to_string())?;
    write_file(&dir.join("trace.bin"), bytes).map_err(|e| e.to_string())?;
    write_file(&dir.join("film.txt"), options.film.name()).map_err(|e| e.to_string())?;
    let _ = std::fs::remove_file(dir.join("outputs.bin"));
    let _ = std::fs::remove_file(dir.join("profile.csv"));

    let started = Instant::now();
    let (code, log) = run_qemu(&elf, dir, options.timeout)?;
    let qemu_wall_s = started.elapsed().as_secs_f64();
    // The raw log is a diagnostic copy: a failure to keep it does not fail the run.
    let _ = write_file(&dir.join("log.defmt"), &log);
    let decoded = decode_log(&elf, &log);
    match code {
        Some(0) => {}
        Some(code) => {
            let tail = decoded
                .as_ref()
                .map(|lines| format!("\nfirmware log:\n{}", lines.join("\n")))
                .unwrap_or_default();
            return Err(format!(
                "the firmware exited with code {code}: {}{tail}",
                describe_exit(code)
            ));
        }
        None => return Err("QEMU was terminated by a signal".into()),
    }

    let out_bytes = std::fs::read(dir.join("outputs.bin"))
        .map_err(|e| format!("the firmware wrote no outputs.bin: {e}"))?;
    let firmware = compare::parse_outputs(&out_bytes, trace.samples.len())?;
    let comparison = compare::compare(&host, &firmware.outputs);
    let instructions = CountRange::of(firmware.counts.iter().map(|c| c.instructions))
        .ok_or("the firmware reported no steps")?;
    let friction = CountRange::of(firmware.counts.iter().map(|c| c.friction_instructions))
        .ok_or("the firmware reported no steps")?;
    let systick = CountRange::of(firmware.counts.iter().map(|c| c.systick))
        .ok_or("the firmware reported no steps")?;
    let calibration = Calibration {
        instructions: firmware.trailer.calibration_instructions,
        systick: firmware.trailer.calibration_systick,
    };

    let mut reasons = Vec::new();
    if calibration.instructions != 1000 {
        reasons.push(format!(
            "calibration: 1000 nop counted as {} instructions (TIM2 is not counting instructions; is -icount shift=0 in effect?)",
            calibration.instructions
        ));
    }
    // SysTick at 168 MHz of virtual time: 0.168 counts per instruction, ±1 for the tick phase.
    if let Some((index, c)) = firmware
        .counts
        .iter()
        .enumerate()
        .find(|(_, c)| (f64::from(c.systick) - 0.168 * f64::from(c.instructions)).abs() > 1.5)
    {
        reasons.push(format!(
            "cross-check: step {index} counted {} instructions by TIM2 but {} SysTick counts (expected {:.1} ± 1)",
            c.instructions,
            c.systick,
            0.168 * f64::from(c.instructions)
        ));
    }
    if comparison.mismatched_steps > 0 {
        reasons.push(format!(
            "outputs differ from the host replay in {} of {} steps; first: {}",
            comparison.mismatched_steps,
            comparison.steps,
            comparison.first_mismatch.as_deref().unwrap_or("?")
        ));
    }
    let deterministic = instructions.min == instructions.max && friction.min == friction.max;
    if instructions.min != instructions.max {
        reasons.push(format!(
            "instruction count varies with the data: {} ..= {} per step (must be equal)",
            instructions.min, instructions.max
        ));
    }
    if friction.min != friction.max {
        reasons.push(format!(
            "the friction call's instruction count varies with the data: {} ..= {} (must be equal)",
            friction.min, friction.max
        ));
    }
    if instructions.max > options.max_instructions {
        reasons.push(format!(
            "{} instructions per step exceed the limit of {}",
            instructions.max, options.max_instructions
        ));
    }
    let report = QemuReport {
        instructions_per_step: instructions,
        friction_instructions_per_step: friction,
        flash_bytes: memory.flash_bytes,
        ram_bytes: memory.ram_bytes,
        stack_bytes: firmware.trailer.stack_bytes,
        outputs_match: comparison.mismatched_steps == 0,
        steps: trace.samples.len(),
        loop_stack_bytes: firmware.trailer.loop_stack_bytes,
        systick_per_step: systick,
        calibration,
        deterministic,
        max_instructions_limit: options.max_instructions,
        comparison,
        qemu_wall_s,
        firmware: elf,
        film: options.film.name(),
        profile: std::fs::read_to_string(dir.join("profile.csv"))
            .map(|text| parse_profile(&text))
            .unwrap_or_default(),
        log: decoded,
        reasons,
    };
    // Per-step counts for plots or later analysis.
    let mut csv = String::from("step,instructions,systick,friction_instructions\n");
    for (index, c) in firmware.counts.iter().enumerate() {
        csv.push_str(&format!(
            "{index},{},{},{}\n",
            c.instructions, c.systick, c.friction_instructions
        ));
    }
    // Both written whole or not at all: a reader never finds a half-written report.
    let json = serde_json::to_string_pretty(&report).map_err(|e| format!("qemu.json: {e}"))?;
    write_file(&dir.join("instructions.csv"), csv).map_err(|e| e.to_string())?;
    write_file(&dir.join("qemu.json"), json).map_err(|e| e.to_string())?;
    Ok(report)
}
