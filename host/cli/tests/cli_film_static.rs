//! CLI behaviour of `bearing film` and `bearing static`: JSON shape, values against closed
//! forms, and clear non-zero exits for bad numbers and bad files.

mod common;
use common::{bearing, config};

const CONTACT: [&str; 14] = [
    "--load",
    "1500",
    "--length",
    "0.015",
    "--entrainment",
    "10",
    "--radius",
    "0.0035",
    "--modulus",
    "2.3077e11",
    "--alpha",
    "2.1e-8",
    "--eta0",
    "0.08",
];

#[test]
fn film_json_matches_the_closed_forms() {
    let mut args = vec!["film", "--json"];
    args.extend(CONTACT);
    let (ok, out, err) = bearing(&args);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    // Hertz (docs/physics.md §1) and Dowson–Toyoda (§5.1) blended root-sum-square with Martin's
    // h₀/R = 4.896U/W (the regression model's complete film), computed here in f64.
    let (q, l, u, r, e, a, eta) = (1500.0f64, 0.015, 10.0, 0.0035, 2.3077e11, 2.1e-8, 0.08);
    let w = q / l;
    let b = (8.0 * w * r / (std::f64::consts::PI * e)).sqrt();
    let ph = (w * e / (2.0 * std::f64::consts::PI * r)).sqrt();
    let rel = |x: &serde_json::Value, y: f64| (x.as_f64().unwrap() / y - 1.0).abs();
    assert!(rel(&v["hertz"]["half_width_m"], b) < 1e-4);
    assert!(rel(&v["hertz"]["max_pressure_pa"], ph) < 1e-4);
    let models = v["models"].as_array().unwrap();
    let regression = models
        .iter()
        .find(|m| m["name"] == "regression")
        .expect("regression entry");
    let dt =
        3.06 * r * (a * e).powf(0.56) * (eta * u / (e * r)).powf(0.69) * (w / (e * r)).powf(-0.10);
    let martin = 4.896 * r * (eta * u / (e * r)) / (w / (e * r));
    let hc = dt.hypot(martin);
    assert!(
        rel(&regression["central_film_m"], hc) < 1e-4,
        "{regression}"
    );
    for m in models {
        assert!(m["central_film_m"].as_f64().unwrap() > 0.0);
        assert!(m["regime"].is_string());
    }
}

#[test]
fn film_from_a_config_shows_both_contacts() {
    let cfg = config("hub_motor.toml");
    let (ok, out, err) = bearing(&[
        "film",
        "--config",
        &cfg,
        "--speed-rpm",
        "10000",
        "--roller-load",
        "800",
        "--json",
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let inner = v["models"][0]["central_film_m"].as_f64().unwrap();
    let outer = v["outer"]["models"][0]["central_film_m"].as_f64().unwrap();
    // The outer contact has the larger reduced radius, so the thicker film.
    assert!(outer > inner && inner > 0.0);
}

#[test]
fn film_refuses_bad_numbers_and_missing_flags() {
    let mut args = vec!["film"];
    args.extend(CONTACT);
    for (flag, bad) in [
        ("--load", "nan"),
        ("--radius", "-1"),
        ("--eta0", "0"),
        ("--modulus", "abc"),
    ] {
        let mut a = args.clone();
        let i = a.iter().position(|x| *x == flag).unwrap();
        a[i + 1] = bad;
        let (ok, _, err) = bearing(&a);
        assert!(!ok, "{flag} {bad} accepted");
        assert!(err.contains(flag) || err.contains(bad), "{err}");
    }
    let (ok, _, err) = bearing(&["film", "--load", "100"]);
    assert!(!ok);
    assert!(err.contains("--length") && err.contains("--eta0"), "{err}");
}

#[test]
fn static_json_lubricated_is_stiffer_than_dry() {
    let cfg = config("hub_motor.toml");
    let (ok, out, err) = bearing(&[
        "static",
        "--config",
        &cfg,
        "--radial-load",
        "2000",
        "--speed-rpm",
        "12000",
        "--dry",
        "--json",
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["displacement_m"].as_array().unwrap().len(), 2);
    assert_eq!(v["rollers"].as_array().unwrap().len(), 17);
    let k = |s: &serde_json::Value| s["stiffness_n_per_m"][1][1].as_f64().unwrap();
    assert!(
        k(&v) > k(&v["dry"]),
        "lubricated {} vs dry {}",
        k(&v),
        k(&v["dry"])
    );
    // The rollers carry the load: Σ Q_j sin θ_j balances the applied 2 kN (to the stated tolerance).
    let sum: f64 = v["rollers"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| -r["load_n"].as_f64().unwrap() * r["angle_rad"].as_f64().unwrap().sin())
        .sum();
    assert!((sum / 2000.0 - 1.0).abs() < 1e-4, "Σ Q sin θ = {sum}");
    for r in v["rollers"].as_array().unwrap() {
        for key in [
            "angle_rad",
            "load_n",
            "central_film_in_m",
            "central_film_out_m",
            "regime",
        ] {
            assert!(!r[key].is_null(), "missing {key}");
        }
    }
}

#[test]
fn static_reports_bad_files_with_file_line_and_field() {
    let (ok, _, err) = bearing(&["static", "--config", "/nonexistent/bearing.toml"]);
    assert!(!ok);
    assert!(err.contains("/nonexistent/bearing.toml"), "{err}");
    let text = std::fs::read_to_string(config("nu205.toml")).unwrap();
    let dir = std::env::temp_dir().join(format!("bearing-cli-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let bad = dir.join("bad.toml");
    std::fs::write(
        &bad,
        text.replace("poisson_ratio = 0.3", "poisson_ratio = 0.7"),
    )
    .unwrap();
    let (ok, _, err) = bearing(&["static", "--config", bad.to_str().unwrap()]);
    assert!(!ok);
    assert!(
        err.contains("bad.toml:") && err.contains("poisson_ratio"),
        "{err}"
    );
    let (ok, _, err) = bearing(&[
        "static",
        "--config",
        &config("nu205.toml"),
        "--radial-load",
        "-5",
    ]);
    assert!(!ok);
    assert!(err.contains("-5"), "{err}");
}

#[test]
fn film_lists_the_numerical_solution_and_the_networks_with_their_fallback() {
    // In the network's domain (1.5 kN, 10 m/s): every model answers and carries its error
    // against the numerical solution; at 20 N the contact leaves the domain (load below the
    // 50 N floor of `dataset::domain`) and both networks report the regression fallback.
    let mut args = vec!["film", "--json"];
    args.extend(CONTACT);
    let (ok, out, err) = bearing(&args);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let models = v["models"].as_array().unwrap();
    let by = |name: &str| {
        models
            .iter()
            .find(|m| m["name"] == name)
            .unwrap_or_else(|| panic!("no {name}"))
            .clone()
    };
    let numerical = by("numerical");
    assert!(
        numerical["central_film_m"].as_f64().unwrap() > 0.0,
        "{numerical}"
    );
    for name in ["ann_f32", "ann_int"] {
        let m = by(name);
        assert_eq!(m["fell_back"], false, "{m}");
        assert!(m["central_rel_err_vs_numerical"]
            .as_f64()
            .unwrap()
            .is_finite());
    }
    let mut light = args.clone();
    light[3] = "20";
    let (ok, out, err) = bearing(&light);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    for name in ["ann_f32", "ann_int"] {
        let m = v["models"]
            .as_array()
            .unwrap()
            .iter()
            .find(|m| m["name"] == name)
            .unwrap()
            .clone();
        assert_eq!(m["fell_back"], true, "{m}");
    }
}

#[test]
fn film_plot_draws_a_png_and_refuses_a_bad_span() {
    let dir = std::env::temp_dir().join(format!("bearing-film-plot-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let png = dir.join("film.png");
    let cfg = config("hub_motor.toml");
    let png_arg = png.to_str().unwrap();
    let common = [
        "film",
        "--config",
        cfg.as_str(),
        "--speed-rpm",
        "21000",
        "--roller-load",
        "800",
        "--plot",
        png_arg,
        "--plot-points",
        "5",
    ];
    let (ok, stdout, stderr) = bearing(&common);
    assert!(ok, "{stderr}");
    assert!(stdout.contains("plot:"), "{stdout}");
    let bytes = std::fs::read(&png).unwrap();
    assert!(
        bytes.len() > 10_000 && bytes.starts_with(b"\x89PNG"),
        "{} bytes",
        bytes.len()
    );
    let mut bad = common.to_vec();
    bad.extend(["--plot-span", "0.5"]);
    let (ok, _, stderr) = bearing(&bad);
    assert!(!ok && stderr.contains("--plot-span"), "{stderr}");
    std::fs::remove_dir_all(&dir).ok();
}
