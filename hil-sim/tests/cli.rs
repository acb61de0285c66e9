//! The `hil-sim` command line on hostile input: a clear message naming the place or the flag,
//! a non-zero exit, never a panic. Reference: the error contract of the trace module docs.

use std::process::{Command, Output};

fn hil_sim(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_hil-sim"))
        .args(args)
        .output()
        .unwrap()
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

#[test]
fn validate_names_line_and_column_of_a_nan() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bad.csv");
    std::fs::write(
        &path,
        "# bearing: nu205\n# lubricant: oil\n# sample_rate_hz: 1000\ntime_s,speed_rad_s,x_m,y_m,vx_m_s,vy_m_s\n0,1,0,0,0,0\n0.001,1,0,0,nan,0\n",
    )
    .unwrap();
    let out = hil_sim(&["trace", "validate", path.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(1));
    let err = stderr(&out);
    assert!(
        err.contains("line 6, column 5 (vx_m_s): not a finite number"),
        "{err}"
    );
}

#[test]
fn random_and_truncated_binary_files_fail_cleanly() {
    let dir = tempfile::tempdir().unwrap();
    let good = dir.path().join("good.bin");
    let out = hil_sim(&["trace", "synth", good.to_str().unwrap(), "--count", "50"]);
    assert!(out.status.success(), "{}", stderr(&out));
    let bytes = std::fs::read(&good).unwrap();
    // A deterministic pseudo-random file (xorshift32, Marsaglia 2003) and a truncation.
    let mut state = 0x1234_5678u32;
    let noise: Vec<u8> = (0..700)
        .map(|_| {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            state as u8
        })
        .collect();
    for (name, content) in [
        ("noise.bin", noise),
        ("cut.bin", bytes[..bytes.len() / 2].to_vec()),
    ] {
        let path = dir.path().join(name);
        std::fs::write(&path, content).unwrap();
        for command in ["validate", "info"] {
            let out = hil_sim(&["trace", command, path.to_str().unwrap()]);
            assert_eq!(out.status.code(), Some(1), "{name}");
            let err = stderr(&out);
            assert!(err.starts_with("error: reading"), "{err}");
            assert!(!err.contains("panicked"), "{err}");
        }
    }
}

#[test]
fn convert_round_trips_binary_through_csv() {
    let dir = tempfile::tempdir().unwrap();
    let bin = dir.path().join("a.bin");
    let csv = dir.path().join("a.csv");
    let back = dir.path().join("b.bin");
    assert!(hil_sim(&[
        "trace",
        "synth",
        bin.to_str().unwrap(),
        "--tilt-rad",
        "1e-4"
    ])
    .status
    .success());
    assert!(hil_sim(&[
        "trace",
        "convert",
        bin.to_str().unwrap(),
        csv.to_str().unwrap()
    ])
    .status
    .success());
    assert!(hil_sim(&[
        "trace",
        "convert",
        csv.to_str().unwrap(),
        back.to_str().unwrap()
    ])
    .status
    .success());
    assert_eq!(std::fs::read(&bin).unwrap(), std::fs::read(&back).unwrap());
}

#[test]
fn out_of_range_flags_are_named() {
    let dir = tempfile::tempdir().unwrap();
    let bin = dir.path().join("a.bin");
    assert!(hil_sim(&["trace", "synth", bin.to_str().unwrap()])
        .status
        .success());
    for (flag, value) in [
        ("--budget-us", "nan"),
        ("--budget-us", "-1"),
        ("--rate-hz", "inf"),
    ] {
        let out = hil_sim(&["replay", "--trace", bin.to_str().unwrap(), flag, value]);
        assert_eq!(out.status.code(), Some(1));
        let err = stderr(&out);
        assert!(err.contains(flag) && err.contains("allowed"), "{err}");
    }
    // A real-time request no machine can grant is the user's error under the default
    // `--realtime auto` and `off` too (only the system's refusal of a valid request falls back).
    for (flag, value, says) in [
        ("--rt-cpu", "4096", "--rt-cpu 4096 does not exist"),
        ("--rt-priority", "100", "--rt-priority 100 is outside"),
    ] {
        for mode in ["auto", "off"] {
            let out = hil_sim(&[
                "replay",
                "--trace",
                bin.to_str().unwrap(),
                "--realtime",
                mode,
                flag,
                value,
            ]);
            assert_eq!(out.status.code(), Some(1), "--realtime {mode}");
            assert!(stderr(&out).contains(says), "{}", stderr(&out));
        }
    }
    let out = hil_sim(&[
        "trace",
        "validate",
        bin.to_str().unwrap(),
        "--gap-tolerance",
        "0",
    ]);
    assert_eq!(out.status.code(), Some(1));
    assert!(stderr(&out).contains("--gap-tolerance"));
    let out = hil_sim(&[
        "qemu",
        "--trace",
        bin.to_str().unwrap(),
        "--timeout-s",
        "nan",
    ]);
    assert_eq!(out.status.code(), Some(1));
    assert!(stderr(&out).contains("--timeout-s"));
}

/// When one plot of the report cannot be written (its name is taken by a directory), the
/// report is not written either: no report.json that could read `budget_ok: true` alone.
#[test]
fn replay_writes_the_report_and_its_plots_or_nothing() {
    let dir = tempfile::tempdir().unwrap();
    let trace = dir.path().join("t.csv");
    let trace = trace.to_str().unwrap();
    assert!(hil_sim(&["trace", "synth", trace, "--count", "200"])
        .status
        .success());
    let report = dir.path().join("report");
    std::fs::create_dir_all(report.join("step_time_histogram.png")).unwrap();
    let out = hil_sim(&[
        "replay",
        "--trace",
        trace,
        "--reference-every",
        "0",
        "--pause-probe-s",
        "0",
        "--realtime",
        "off",
        "--report",
        report.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(1), "{}", stderr(&out));
    assert!(
        stderr(&out).contains("step_time_histogram.png"),
        "{}",
        stderr(&out)
    );
    let left: Vec<_> = std::fs::read_dir(&report)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    assert_eq!(left, ["step_time_histogram.png"]);
}

/// A subnormal sample rate (its period 1/rate is infinite) is refused by `trace validate`
/// and by `replay`, which must not panic converting that period to a `Duration`.
#[test]
fn a_subnormal_sample_rate_is_refused_by_validate_and_replay() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("sub.csv");
    std::fs::write(
        &path,
        "# bearing: hub_motor\n# lubricant: thesis_oil\n# sample_rate_hz: 4e-320\ntime_s,speed_rad_s,x_m,y_m,vx_m_s,vy_m_s\n0,100,0,0,0,0\n1,100,0,0,0,0\n",
    )
    .unwrap();
    let path = path.to_str().unwrap();
    for args in [
        &["trace", "validate", path][..],
        &["replay", "--trace", path, "--reference-every", "0"][..],
    ] {
        let out = hil_sim(args);
        assert_eq!(out.status.code(), Some(1), "{args:?}");
        let err = stderr(&out);
        assert!(
            err.contains("line 3") && err.contains("sample_rate_hz"),
            "{err}"
        );
        assert!(!err.contains("panicked"), "{err}");
    }
}

/// The reader of stdout goes away before `trace info` prints: a quiet end, no panic.
#[test]
fn a_closed_pipe_ends_trace_info_without_a_panic() {
    let dir = tempfile::tempdir().unwrap();
    let bin = dir.path().join("a.bin");
    assert!(hil_sim(&["trace", "synth", bin.to_str().unwrap()])
        .status
        .success());
    let mut child = Command::new(env!("CARGO_BIN_EXE_hil-sim"))
        .args(["trace", "info", bin.to_str().unwrap()])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    drop(child.stdout.take());
    let out = child.wait_with_output().unwrap();
    let err = stderr(&out);
    assert!(err.is_empty(), "{err}");
}
