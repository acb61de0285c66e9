//! `bearing` on hostile input: no hang, no panic, a refusal naming the flag and the allowed
//! range, and no new file left behind by a command that fails.

mod common;
use common::{bearing, config};

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Runs `bearing` in `dir`; fails the test if it has not ended after `limit` (a hang), and
/// kills it then. Returns (success, stderr).
fn bearing_within(dir: &Path, args: &[&str], limit: Duration) -> (bool, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_bearing"))
        .args(args)
        .current_dir(dir)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap() {
            let mut err = String::new();
            std::io::Read::read_to_string(&mut child.stderr.take().unwrap(), &mut err).unwrap();
            return (status.success(), err);
        }
        if start.elapsed() > limit {
            child.kill().unwrap();
            child.wait().unwrap();
            panic!("bearing {args:?} still running after {limit:?}");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// `bearing shaft run` of Friswell's Example 5.9.1 rotor (linear bearings, no loads) at `speed`
/// rpm, settling 0.01 s and recording `duration` s, outputs `x*` in `dir`: (success, stderr).
fn friswell_run(dir: &Path, speed: &str, duration: &str) -> (bool, String) {
    let f = config("friswell_5_9_1.toml");
    let args = [
        "shaft",
        "run",
        "--config",
        &f,
        "--speed-rpm",
        speed,
        "--settle",
        "0.01",
        "--duration",
        duration,
        "--out",
        "x",
    ];
    bearing_within(dir, &args, Duration::from_secs(60))
}

/// Names in `dir`, sorted (hidden temporaries included).
fn files_in(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

/// A model without loads (no spectral line in the plotted band) and runs far too slow or too
/// short for one: the spectrum plot's axes stay finite and the run ends (it spun forever on a
/// log axis from 0 to ∞).
#[test]
fn shaft_run_ends_when_no_spectral_line_falls_in_the_plotted_band() {
    for (speed, duration) in [("4000", "0.01"), ("1e-320", "0.01")] {
        let dir = tempfile::tempdir().unwrap();
        let (ok, err) = friswell_run(dir.path(), speed, duration);
        assert!(ok, "--speed-rpm {speed} --duration {duration}: {err}");
        assert!(files_in(dir.path()).contains(&"x_spectrum.png".to_string()));
    }
}

/// A recording shorter than two samples is refused with the shortest allowed, and leaves no
/// file behind.
#[test]
fn shaft_run_refuses_a_recording_of_fewer_than_two_samples() {
    let dir = tempfile::tempdir().unwrap();
    let (ok, err) = friswell_run(dir.path(), "4000", "1e-320");
    assert!(!ok);
    assert!(
        err.contains("--duration = 1e-320 s") && err.contains("fewer than two samples"),
        "{err}"
    );
    assert!(
        files_in(dir.path()).is_empty(),
        "{:?}",
        files_in(dir.path())
    );
}

/// `bearing static` refuses a radial load above the bearing's static load rating (checked
/// against ISO 76's closed form C₀r = 44·(1 − D/d_m)·Z·L·D for the steel hub-motor bearing) and
/// a speed above the core's, naming the flag and the range.
#[test]
fn static_refuses_loads_above_the_static_rating_and_speeds_above_the_core() {
    let hub = config("hub_motor.toml");
    let run = |load: &str, speed: &str| {
        bearing(&[
            "static",
            "--config",
            &hub,
            "--radial-load",
            load,
            "--speed-rpm",
            speed,
        ])
    };
    let (ok, out, err) = run("1e6", "1000");
    assert!(!ok && out.is_empty());
    assert!(err.contains("--radial-load = 1e6 N"), "{err}");
    let allowed: f64 = err
        .split("0 ..= ")
        .nth(1)
        .and_then(|rest| rest.split(' ').next())
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("no allowed range in: {err}"));
    // D = 8.8 mm, d_m = 60 mm, Z = 17, L = 15 mm.
    let iso_76 = 44.0 * (1.0 - 8.8 / 60.0) * 17.0 * 15.0 * 8.8;
    assert!(
        (allowed / iso_76 - 1.0).abs() < 0.011,
        "rating {allowed} N vs ISO 76 {iso_76} N"
    );
    let (ok, _, err) = run("2000", "1e7");
    assert!(!ok);
    assert!(
        err.contains("--speed-rpm = 1e7 rpm") && err.contains("954930"),
        "{err}"
    );
}

/// The reader of stdout goes away before the command prints: the command ends quietly (the
/// default action of SIGPIPE), with no panic message.
#[test]
fn a_closed_pipe_ends_a_printing_command_without_a_panic() {
    for args in [
        &["ehl", "compare", "pan-hamrock"][..],
        &["shaft", "modes", "--config", &config("friswell_5_9_1.toml")][..],
    ] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_bearing"))
            .args(args)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        drop(child.stdout.take());
        let out = child.wait_with_output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!err.contains("panicked"), "{args:?}: {err}");
        assert!(err.is_empty(), "{args:?}: {err}");
        #[cfg(unix)]
        {
            use std::os::unix::process::ExitStatusExt as _;
            let sigpipe = 13;
            assert!(
                out.status.success() || out.status.signal() == Some(sigpipe),
                "{args:?}: {:?}",
                out.status
            );
        }
    }
}

/// A negative value is read as a value (and refused by its flag's range check), not as an
/// unknown flag.
#[test]
fn a_negative_value_is_refused_by_its_flag_with_the_range() {
    let f = config("friswell_5_9_1.toml");
    let (ok, _, err) = bearing(&[
        "shaft",
        "run",
        "--config",
        &f,
        "--speed-rpm",
        "1",
        "--settle",
        "-1",
    ]);
    assert!(!ok);
    assert!(
        err.contains("--settle = -1") && err.contains("[0, 100]"),
        "{err}"
    );
}

/// Minus infinity and minus NaN (which clap does not count as numbers) are values of a
/// floating-point flag too: the refusal names the flag and its range.
#[test]
fn minus_infinity_is_refused_by_its_flag_with_the_range() {
    for (args, flag, range) in [
        (
            &["film", "--load", "-inf"][..],
            "'--load <LOAD>'",
            "finite number > 0",
        ),
        (
            &["film", "--load", "-nan"][..],
            "'--load <LOAD>'",
            "finite number > 0",
        ),
        (
            &["static", "--radial-load", "-inf"][..],
            "'--radial-load <RADIAL_LOAD>'",
            "finite number >= 0",
        ),
    ] {
        let (ok, _, err) = bearing(args);
        assert!(!ok, "{args:?}");
        assert!(err.contains(flag) && err.contains(range), "{args:?}: {err}");
        assert!(!err.contains("unexpected argument"), "{args:?}: {err}");
    }
}

/// `bearing film` refuses speeds the core refuses, loads steel does not carry (peak Hertz
/// pressure above 4 GPa), values single precision cannot hold and α outside lubricating oils,
/// each naming the flag and the allowed range.
#[test]
fn film_refuses_out_of_range_numbers_naming_flag_and_range() {
    let hub = config("hub_motor.toml");
    let with_config = |speed: &str, load: &str| {
        bearing(&[
            "film",
            "--config",
            &hub,
            "--speed-rpm",
            speed,
            "--roller-load",
            load,
            "--json",
        ])
    };
    let (ok, out, err) = with_config("1e308", "800");
    assert!(!ok && out.is_empty());
    assert!(
        err.contains("--speed-rpm = 1e308") && err.contains("954930"),
        "{err}"
    );
    let (ok, _, err) = with_config("1000", "1e23");
    assert!(!ok);
    assert!(
        err.contains("--roller-load") && err.contains("at most 4 GPa"),
        "{err}"
    );
    let explicit = |load: &str, alpha: &str| {
        bearing(&[
            "film",
            "--load",
            load,
            "--length",
            "0.009",
            "--entrainment",
            "5",
            "--radius",
            "0.0032",
            "--modulus",
            "2.308e11",
            "--alpha",
            alpha,
            "--eta0",
            "0.08",
            "--json",
        ])
    };
    // p_h = √(w E' / 2πR) = 11.3 GPa at 10⁵ N on 9 mm.
    let (ok, _, err) = explicit("1e5", "2.1e-8");
    assert!(!ok);
    assert!(
        err.contains("--load = 1e5 N") && err.contains("11.29"),
        "{err}"
    );
    let (ok, _, err) = explicit("1e308", "2.1e-8");
    assert!(!ok);
    assert!(err.contains("--load = 1e308"), "{err}");
    let (ok, _, err) = explicit("1000", "0");
    assert!(!ok);
    assert!(
        err.contains("--alpha = 0") && err.contains("1e-9 ..= 1e-7"),
        "{err}"
    );
    // 1 kN on 9 mm is 3.2 GPa: accepted.
    let (ok, _, err) = explicit("1000", "2.1e-8");
    assert!(ok, "{err}");
}

/// `bearing ehl solve` names the flags the user typed, not the solver's variables.
#[test]
fn ehl_solve_refusals_name_the_flags() {
    let (ok, _, err) = bearing(&["ehl", "solve", "--m", "1e9", "--l", "5"]);
    assert!(!ok && err.contains("--m = 1e9"), "{err}");
    let (ok, _, err) = bearing(&["ehl", "solve", "--m", "10", "--l", "5", "--nodes", "5"]);
    assert!(
        !ok && err.contains("--nodes: must be in 41..=8193"),
        "{err}"
    );
    let (ok, _, err) = bearing(&[
        "ehl",
        "solve",
        "--load",
        "1",
        "--length",
        "0.01",
        "--entrainment",
        "5",
        "--radius",
        "0.0032",
        "--modulus",
        "2.308e11",
        "--alpha",
        "2.1e-8",
        "--eta0",
        "1e9",
    ]);
    assert!(!ok && err.contains("--eta0 = 1e9"), "{err}");
    assert!(!err.contains("viscosity_pa_s"), "{err}");
}

/// A failed plot leaves neither the profile nor a temporary behind.
#[test]
fn ehl_solve_leaves_no_profile_when_the_plot_cannot_be_written() {
    let dir = tempfile::tempdir().unwrap();
    let (ok, _) = bearing_within(
        dir.path(),
        &[
            "ehl",
            "solve",
            "--m",
            "30",
            "--l",
            "5",
            "--profile",
            "out.csv",
            "--plot",
            "/proc/x.png",
        ],
        Duration::from_secs(120),
    );
    assert!(!ok);
    assert!(
        files_in(dir.path()).is_empty(),
        "{:?}",
        files_in(dir.path())
    );
}

/// When one output of `shaft run` cannot be written (its name is taken by a directory), none
/// is: no CSV, no trace, no temporary.
#[test]
fn shaft_run_writes_all_its_files_or_none() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::create_dir(dir.path().join("x_orbit.png")).unwrap();
    let (ok, err) = friswell_run(dir.path(), "4000", "0.01");
    assert!(!ok);
    assert!(err.contains("x_orbit.png"), "{err}");
    assert_eq!(files_in(dir.path()), ["x_orbit.png"]);
}

/// The JSON of `shaft modes` carries what the table shows (damping ratio, whirl), `shaft
/// static` the node rotations, `shaft campbell --json` writes no PNG unless asked, and a trace
/// from a linear bearing claims no lubricant.
#[test]
fn shaft_json_outputs_carry_what_the_tables_show() {
    let f = config("friswell_5_9_1.toml");
    let (ok, out, err) = bearing(&[
        "shaft",
        "modes",
        "--config",
        &f,
        "--speed-rpm",
        "4000",
        "--json",
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let modes = v["modes"].as_array().unwrap();
    assert_eq!(modes.len(), 8);
    // Friswell et al. (2010) Example 5.9.1: the first mode at 4000 rpm is a backward whirl.
    assert_eq!(modes[0]["whirl"], "backward");
    assert!(modes.iter().all(|m| m["damping_ratio"].is_f64()));

    let (ok, out, err) = bearing(&[
        "shaft",
        "static",
        "--config",
        &f,
        "--linear-bearings",
        "1e7",
        "--json",
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let node = &v["nodes"][3];
    assert!(
        node["theta_x_rad"].is_f64() && node["theta_y_rad"].is_f64(),
        "{node}"
    );

    let dir = tempfile::tempdir().unwrap();
    let (ok, err) = bearing_within(
        dir.path(),
        &[
            "shaft", "campbell", "--config", &f, "--steps", "2", "--json",
        ],
        Duration::from_secs(60),
    );
    assert!(ok, "{err}");
    assert!(
        files_in(dir.path()).is_empty(),
        "{:?}",
        files_in(dir.path())
    );

    let (ok, err) = friswell_run(dir.path(), "4000", "0.01");
    assert!(ok, "{err}");
    let trace = std::fs::read_to_string(dir.path().join("x_b0_trace.csv")).unwrap();
    assert!(trace.contains("# lubricant: none\n"), "{trace}");
}
