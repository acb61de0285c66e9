//! CLI behaviour of the friction outputs: the JSON keys scripts rely on in `bearing film` and
//! `bearing static`, and `bearing friction`'s curve (docs/physics.md §8, docs/friction.md).

mod common;
use common::{bearing, config};

fn json(args: &[&str]) -> serde_json::Value {
    let (ok, out, err) = bearing(args);
    assert!(ok, "{err}");
    serde_json::from_str(&out).unwrap()
}

#[test]
fn film_json_has_lambda_and_friction_coefficient() {
    let cfg = config("nu205.toml");
    let v = json(&[
        "film",
        "--json",
        "--config",
        &cfg,
        "--speed-rpm",
        "3000",
        "--roller-load",
        "300",
    ]);
    for contact in [&v, &v["outer"]] {
        let lambda = contact["lambda"].as_f64().unwrap();
        let h = contact["friction"]["film_from"].as_str().unwrap();
        assert!(h == "numerical" || h == "regression");
        // λ = h_c/σ with the default σ = 0.15 µm and the numerical central film.
        let numerical = contact["models"]
            .as_array()
            .unwrap()
            .iter()
            .find(|m| m["name"] == "numerical")
            .unwrap();
        if let Some(hc) = numerical["central_film_m"].as_f64() {
            assert!(
                (lambda / (hc / 0.15e-6) - 1.0).abs() < 1e-5,
                "{lambda} {hc}"
            );
        }
        let mu = contact["friction_coefficient"].as_f64().unwrap();
        assert!(mu > 0.0 && mu < 0.2, "{mu}");
    }
}

#[test]
fn static_json_has_torque_power_split_and_lambdas() {
    let cfg = config("nu205.toml");
    let v = json(&[
        "static",
        "--json",
        "--config",
        &cfg,
        "--speed-rpm",
        "3000",
        "--dry",
    ]);
    let power = v["power_loss_w"].as_f64().unwrap();
    let torque = v["friction_torque_nm"].as_f64().unwrap();
    let split = &v["power_loss_split_w"];
    let parts: f64 = ["rolling", "viscous", "boundary"]
        .iter()
        .map(|k| split[k].as_f64().unwrap())
        .sum();
    assert!(power > 0.0);
    assert!((parts / power - 1.0).abs() < 1e-5, "{split} vs {power}");
    // P = M·ω at 3000 rpm.
    let omega = 3000.0 * std::f64::consts::PI / 30.0;
    assert!((power / (torque * omega) - 1.0).abs() < 1e-5);
    for r in v["rollers"].as_array().unwrap() {
        assert!(r["lambda_in"].as_f64().unwrap() > 0.0);
        assert!(r["lambda_out"].as_f64().unwrap() > 0.0);
    }
    // The dry bearing stays under "dry", without friction.
    assert_eq!(v["dry"]["power_loss_w"].as_f64(), Some(0.0));
}

#[test]
fn friction_curve_runs_from_boundary_to_full_film() {
    let cfg = config("nu205.toml");
    let dir = tempfile::tempdir().unwrap();
    let plot = dir.path().join("stribeck.svg");
    let plot_arg = plot.to_str().unwrap().to_owned();
    let v = json(&[
        "friction",
        "--json",
        "--config",
        &cfg,
        "--min-rpm",
        "10",
        "--max-rpm",
        "15000",
        "--points",
        "7",
        "--plot",
        &plot_arg,
    ]);
    let points = v["points"].as_array().unwrap();
    assert_eq!(points.len(), 7);
    let share = |p: &serde_json::Value, k: &str| {
        p["power_loss_split_w"][k].as_f64().unwrap() / p["power_loss_w"].as_f64().unwrap()
    };
    let (first, last) = (&points[0], &points[6]);
    assert_eq!(first["lubrication"], "boundary");
    assert_eq!(last["lubrication"], "full_film");
    assert!(share(first, "boundary") > 0.1 && share(last, "boundary") < 1e-3);
    assert!(last["power_loss_w"].as_f64() > first["power_loss_w"].as_f64());
    assert!(std::fs::read_to_string(&plot).unwrap().starts_with("<svg"));
}
