//! CLI behaviour of `bearing shaft …`: the `--json` shapes, the Friswell frequencies through
//! the binary, and clear non-zero exits naming the flag or the file for hostile input.

mod common;
use common::{bearing, config};

/// Reference: Friswell et al. (2010) Example 5.9.1 at 4000 rpm.
#[test]
fn modes_json_gives_ascending_friswell_frequencies() {
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
    let w: Vec<f64> = v["frequencies_rad_s"]
        .as_array()
        .unwrap()
        .iter()
        .map(|x| x.as_f64().unwrap())
        .collect();
    assert!(w.windows(2).all(|p| p[0] <= p[1]), "{w:?}");
    for (a, b) in w.iter().zip([85.39, 87.80, 251.78, 294.71, 600.18]) {
        assert!((a - b).abs() / b < 0.005, "{a} vs {b}");
    }
}

#[test]
fn sweep_json_has_both_sides_and_every_array() {
    let f = config("friswell_5_9_1.toml");
    let (ok, out, err) = bearing(&[
        "shaft",
        "sweep",
        "--config",
        &f,
        "--speeds-rpm",
        "1000,2000",
        "--settle",
        "0.01",
        "--duration",
        "0.02",
        "--dt",
        "1e-4",
        "--plot",
        "cli_shaft_sweep_test.png",
        "--json",
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["speeds_rpm"].as_array().unwrap().len(), 2);
    for side in ["lubricated", "dry"] {
        for key in [
            "max_contact_force_n",
            "max_contact_stiffness_n_per_m",
            "max_bearing_stiffness_n_per_m",
            "max_central_film_m",
            "max_displacement_m",
            "max_acceleration_m_s2",
        ] {
            assert_eq!(
                v[side][key].as_array().map(|a| a.len()),
                Some(2),
                "{side}.{key}"
            );
        }
        // Linear 1 MN/m bearings: the bearing stiffness is exactly that.
        assert_eq!(
            v[side]["max_bearing_stiffness_n_per_m"][0].as_f64(),
            Some(1e6)
        );
    }
}

#[test]
fn hostile_flags_exit_non_zero_naming_the_flag() {
    let f = config("friswell_5_9_1.toml");
    for (flag, value) in [
        ("--speed-rpm", "nan"),
        ("--speed-rpm", "-5"),
        ("--speed-rpm", "inf"),
        ("--linear-bearings", "0"),
        ("--modes", "0"),
    ] {
        let arg = format!("{flag}={value}");
        let (ok, _, err) = bearing(&["shaft", "modes", "--config", &f, &arg]);
        assert!(!ok, "{flag} {value} accepted");
        assert!(err.contains(flag), "{flag} {value}: {err}");
    }
    let (ok, _, err) = bearing(&[
        "shaft",
        "run",
        "--config",
        &f,
        "--speed-rpm",
        "100",
        "--dt=-1",
    ]);
    assert!(!ok && err.contains("--dt"), "{err}");
    for (flag, value) in [
        ("--speed-end-rpm", "nan"),
        ("--speed-end-rpm", "-100"),
        ("--record-every", "0"),
        ("--newton-resolution", "0"),
        ("--newton-resolution", "inf"),
    ] {
        let arg = format!("{flag}={value}");
        let (ok, _, err) = bearing(&["shaft", "run", "--config", &f, "--speed-rpm", "100", &arg]);
        assert!(!ok, "{flag} {value} accepted");
        assert!(err.contains(flag), "{flag} {value}: {err}");
    }
}

#[test]
fn missing_and_broken_files_are_named() {
    let (ok, _, err) = bearing(&["shaft", "static", "--config", "/nonexistent/shaft.toml"]);
    assert!(
        !ok && err.contains("/nonexistent/shaft.toml") && err.contains("cannot read"),
        "{err}"
    );
    let bad = std::env::temp_dir().join("cli_shaft_bad.toml");
    std::fs::write(&bad, "nodes_m = [0.0, 1.0]\n[material]\nyoungs_modulus_pa = -1\nshear_modulus_pa = 8e10\ndensity_kg_m3 = 7800\n").unwrap();
    let (ok, _, err) = bearing(&["shaft", "static", "--config", &bad.display().to_string()]);
    assert!(!ok, "accepted");
    assert!(
        err.contains("cli_shaft_bad.toml:3: material.youngs_modulus_pa"),
        "{err}"
    );
}
