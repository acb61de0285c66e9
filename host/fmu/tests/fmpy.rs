//! The FMU in a real importer: FMPy (PyPI) validates it and simulates it driven by a whirl and by
//! the bundled hub-motor trace's kinematics (`tests/fmpy_run.py`); every output at every
//! communication point equals, bit for bit, the core's output stepped here through its Rust API
//! with the same inputs (settled at the first row, then one `advance` per communication step,
//! each followed by `friction` at the row's shaft speed: the friction torque, power loss and
//! its split are outputs too).
//!
//! Needs a Python interpreter with FMPy and numpy, named by the environment variable
//! `BEARING_PYTHON`: `cargo xtask test` makes one under `target/python` (the packages of
//! `host/xtask/python-requirements.txt`) and sets it. The test fails, naming what is missing,
//! when the variable is unset or the interpreter lacks the packages.

use std::path::{Path, PathBuf};
use std::process::Command;

use bearing_core::bearing::{boxed, SETTLE_STEPS};
use bearing_core::FilmKind;
use bearing_fmu::package::{find_library, write_fmu};
use bearing_fmu::variables::{operating_state, output_values, Causality, INPUTS, REALS};
use bearing_hil_kernel::wire::{decode_record, Header, HEADER_LEN};

fn repo(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .join(path)
}

/// Input rows: (time, the seven inputs), every value an f32 widened to f64.
type Rows = Vec<(f64, [f64; INPUTS])>;

/// The inner race on a 6 µm whirl at the shaft speed (21 000 rpm, the hub motor's case), tilts
/// of 0.1 mrad turning with it, sampled every `h` seconds.
fn whirl(steps: usize, h: f64) -> Rows {
    let (omega, radius, tilt) = (2199.0_f32, 6.0e-6_f32, 1.0e-4_f32);
    (0..=steps)
        .map(|k| {
            let t = k as f64 * h;
            let (s, c) = (omega * t as f32).sin_cos();
            let inputs = [
                radius * c,
                radius * s,
                -radius * omega * s,
                radius * omega * c,
                tilt * s,
                -tilt * c,
                omega,
            ];
            (t, inputs.map(f64::from))
        })
        .collect()
}

/// The bundled hub-motor trace's kinematics (no tilt recorded: tilts 0), one row per sample at
/// the trace's rate, the first `count` samples.
fn hub_trace(count: usize) -> (Rows, f64) {
    let bytes = std::fs::read(repo("hil-sim/traces/hub_motor_runup.bin")).unwrap();
    let header = Header::parse(bytes[..HEADER_LEN].try_into().unwrap()).unwrap();
    let h = 1.0 / header.sample_rate_hz;
    let rows = bytes[HEADER_LEN..]
        .chunks_exact(header.record_len())
        .take(count)
        .enumerate()
        .map(|(k, record)| {
            let s = decode_record(record, header.has_tilt).unwrap();
            let [tx, ty] = s.tilt_rad.unwrap_or([0.0; 2]);
            let inputs = [s.x_m, s.y_m, s.vx_m_s, s.vy_m_s, tx, ty, s.speed_rad_s];
            (k as f64 * h, inputs.map(f64::from))
        })
        .collect();
    (rows, h)
}

fn write_inputs(path: &Path, rows: &Rows) {
    let names: Vec<&str> = REALS[..INPUTS].iter().map(|v| v.name).collect();
    let mut text = format!("time,{}\n", names.join(","));
    for (t, inputs) in rows {
        let values: Vec<String> = inputs.iter().map(|v| format!("{v:e}")).collect();
        text += &format!("{t:e},{}\n", values.join(","));
    }
    std::fs::write(path, text).unwrap();
}

/// The core stepped as the FMU steps it under FMPy: settled at the first row's inputs, then
/// each step advanced by t[k+1] − t[k] to the inputs of row k (held over the step). One row of
/// outputs per communication point.
fn reference(film: FilmKind, rows: &Rows) -> Vec<Vec<f64>> {
    let params = bearing_core::BearingDesign::HUB_MOTOR.params().unwrap();
    let mut bearing = boxed(params, film).unwrap();
    let first = operating_state(&rows[0].1);
    bearing.settle(&first, SETTLE_STEPS).unwrap();
    bearing.friction(first.shaft_speed_rad_s).unwrap();
    let mut out = vec![output_values(&bearing.output(), bearing.cage_angle_rad()).to_vec()];
    for pair in rows.windows(2) {
        let step = pair[1].0 - pair[0].0;
        let state = operating_state(&pair[0].1);
        bearing.advance(&state, step as f32).unwrap();
        bearing.friction(state.shaft_speed_rad_s).unwrap();
        out.push(output_values(&bearing.output(), bearing.cage_angle_rad()).to_vec());
    }
    out
}

/// FMPy's output table: the header's names and the rows.
fn read_outputs(path: &Path) -> (Vec<String>, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let names = lines.next().unwrap().split(',').map(String::from).collect();
    let rows = lines
        .map(|l| l.split(',').map(|v| v.parse().unwrap()).collect())
        .collect();
    (names, rows)
}

#[test]
fn fmpy_validates_and_simulates_the_fmu_bit_for_bit() {
    let exe = std::env::current_exe().unwrap();
    let library = find_library(exe.parent().unwrap()).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let fmu = dir.path().join("hub_motor.fmu");
    write_fmu(
        &repo("configs/hub_motor.toml"),
        FilmKind::Int,
        &library,
        &fmu,
    )
    .unwrap();

    let (trace, trace_h) = hub_trace(usize::MAX);
    let cases = [("whirl", whirl(400, 1.0e-4)), ("hub_trace", trace)];
    let mut args = vec![repo("host/fmu/tests/fmpy_run.py"), fmu.clone()];
    for (name, rows) in &cases {
        write_inputs(&dir.path().join(format!("{name}_in.csv")), rows);
        args.push(dir.path().join(format!("{name}_in.csv")));
        args.push(dir.path().join(format!("{name}_out.csv")));
    }
    let python = std::env::var_os("BEARING_PYTHON").unwrap_or_else(|| {
        panic!(
            "BEARING_PYTHON is not set: it names the Python interpreter with FMPy and numpy \
             (`cargo xtask test` makes one in target/python and sets it; or \
             `BEARING_PYTHON=$PWD/target/python/bin/python cargo test …` after `cargo xtask setup`)"
        )
    });
    let run = Command::new(&python).args(&args).output();
    let run = run.unwrap_or_else(|e| panic!("cannot run BEARING_PYTHON = {python:?}: {e}"));
    let stdout = String::from_utf8_lossy(&run.stdout);
    let stderr = String::from_utf8_lossy(&run.stderr);
    assert!(
        run.status.success(),
        "fmpy_run.py under {python:?} failed (FMPy or numpy missing? they are listed in \
         host/xtask/python-requirements.txt)\n{stdout}\n{stderr}"
    );
    println!("{stdout}");
    assert!(stdout.contains("fmpy.validate_fmu: no problems"));
    assert!(
        stdout.contains("displacement_x_m = 0.002 is not allowed"),
        "the refused input is named in the log:\n{stdout}"
    );

    let output_names: Vec<&str> = REALS
        .iter()
        .filter(|v| v.causality == Causality::Output)
        .map(|v| v.name)
        .collect();
    for (name, rows) in &cases {
        let expected = reference(FilmKind::Int, rows);
        let (names, got) = read_outputs(&dir.path().join(format!("{name}_out.csv")));
        assert_eq!(names[0], "time");
        assert_eq!(&names[1..], &output_names[..]);
        assert_eq!(
            got.len(),
            rows.len(),
            "{name}: one row per communication point"
        );
        for (k, (g, e)) in got.iter().zip(&expected).enumerate() {
            assert_eq!(g[0], rows[k].0, "{name}: time of row {k}");
            for ((value, reference), output) in g[1..].iter().zip(e).zip(&output_names) {
                assert_eq!(
                    value.to_bits(),
                    reference.to_bits(),
                    "{name}: {output} at row {k}: FMPy {value:e}, core {reference:e}"
                );
            }
        }
        // Not a trivial run: the bearing carried load and the network served films.
        let max_load = output_names.iter().position(|n| *n == "max_roller_load_n");
        let peak = got
            .iter()
            .map(|r| r[1 + max_load.unwrap()])
            .fold(0.0, f64::max);
        assert!(peak > 100.0, "{name}: peak roller load {peak} N");
        // The friction outputs are the bearing's: power loss = torque × shaft speed of the
        // step, and the sum of its split, to f32 rounding; positive wherever the shaft turns.
        let column = |n: &str| 1 + output_names.iter().position(|o| *o == n).unwrap();
        let [torque, power, speed] = ["friction_torque_nm", "power_loss_w", "shaft_speed_rad_s"];
        let (torque, power) = (column(torque), column(power));
        let split =
            ["rolling", "viscous", "boundary"].map(|p| column(&format!("power_loss_{p}_w")));
        let speed = REALS.iter().position(|v| v.name == speed).unwrap();
        for (k, g) in got.iter().enumerate() {
            // Row k's outputs end the step driven by row k − 1's inputs (row 0: settled there).
            let omega = rows[k.saturating_sub(1)].1[speed].abs();
            if omega < 1.0 {
                continue;
            }
            assert!(g[power] > 0.0, "{name}: no power loss at row {k}");
            assert!(
                (g[power] / (g[torque] * omega) - 1.0).abs() < 1e-5,
                "{name}: row {k}"
            );
            let sum: f64 = split.iter().map(|&c| g[c]).sum();
            assert!(
                (sum / g[power] - 1.0).abs() < 1e-5,
                "{name}: split at row {k}"
            );
        }
    }
    assert!(trace_h > 0.0);
}
