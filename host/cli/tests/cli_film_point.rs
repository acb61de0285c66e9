//! CLI behaviour of `bearing film --contact point`: every model side by side with stable JSON
//! keys, values against the closed forms (Hertz, Hamrock–Dowson, written out here in f64), the
//! numerical solver as the reference, and refusals that name the flag and its range.

#[allow(dead_code)]
mod common;
use common::bearing;

/// docs/point_contact.md's circular case (M = 69, p_h = 1.40 GPa) with α = 12 GPa⁻¹, which
/// brings L = 11.2 inside the network's training window (L ≤ 15).
const CONTACT: [&str; 14] = [
    "--load",
    "40",
    "--entrainment",
    "10",
    "--radius",
    "0.006",
    "--ellipticity",
    "1",
    "--modulus",
    "2.26e11",
    "--alpha",
    "1.2e-8",
    "--eta0",
    "0.02",
];

fn run(extra: &[&str]) -> (bool, String, String) {
    let mut args = vec!["film", "--contact", "point"];
    args.extend(CONTACT);
    args.extend(extra);
    bearing(&args)
}

/// Every model is listed with its source; Hertz and Hamrock–Dowson match the closed forms; the
/// network serves this contact and lies within 5 % of the numerical Richardson film, and the
/// numerical entry is the reference of the relative errors.
#[test]
fn point_film_json_lists_every_model() {
    let (ok, out, err) = run(&["--json"]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["contact"], "point");
    let (w, u, r, e, a, eta) = (40.0f64, 10.0, 0.006, 2.26e11, 1.2e-8, 0.02);
    // Circular contact: a = b = (3wR_x/(2E'))^⅓, p_h = 3w/(2πa²) (Johnson eq. 4.22).
    let radius = (3.0 * w * r / (2.0 * e)).cbrt();
    let ph = 3.0 * w / (2.0 * std::f64::consts::PI * radius * radius);
    let rel = |x: &serde_json::Value, y: f64| (x.as_f64().unwrap() / y - 1.0).abs();
    assert!(
        rel(&v["hertz"]["max_pressure_pa"], ph) < 1e-6,
        "{}",
        v["hertz"]
    );
    assert!(rel(&v["hertz"]["semi_axis_rolling_m"], radius) < 1e-6);
    let (w_, u_, g_) = (w / (e * r * r), eta * u / (e * r), a * e);
    let hd_c = 2.69
        * u_.powf(0.67)
        * g_.powf(0.53)
        * w_.powf(-0.067)
        * (1.0 - 0.61 * (-0.73f64).exp())
        * r;
    let hd_m =
        3.63 * u_.powf(0.68) * g_.powf(0.49) * w_.powf(-0.073) * (1.0 - (-0.68f64).exp()) * r;
    let models = v["models"].as_array().unwrap();
    let names: Vec<&str> = models.iter().map(|m| m["name"].as_str().unwrap()).collect();
    assert_eq!(
        names,
        [
            "numerical",
            "ann_f32",
            "ann_int",
            "hamrock_dowson",
            "nijenbanning"
        ]
    );
    let by = |n: &str| models.iter().find(|m| m["name"] == n).unwrap();
    let hd = by("hamrock_dowson");
    assert!(rel(&hd["central_film_m"], hd_c) < 1e-5, "{hd}");
    assert!(rel(&hd["min_film_m"], hd_m) < 1e-5, "{hd}");
    assert_eq!(hd["source"], "regression");
    let num = by("numerical");
    assert_eq!(num["richardson"], true, "{num}");
    let hc = num["central_film_m"].as_f64().unwrap();
    for (name, source) in [("ann_f32", "network_f32"), ("ann_int", "network_int")] {
        let m = by(name);
        assert_eq!(m["source"], source, "{m}");
        assert_eq!(m["fell_back"], false);
        let err = m["central_rel_err_vs_numerical"].as_f64().unwrap();
        assert!(
            (err - (m["central_film_m"].as_f64().unwrap() / hc - 1.0)).abs() < 1e-9
                && err.abs() < 0.05,
            "{m}"
        );
    }
    assert!(by("nijenbanning")["min_film_m"].is_null());
}

/// Outside the training domain (η₀ = 1 Pa·s, above its 0.1) the networks report the fallback,
/// whose films are Hamrock–Dowson's; `--no-solver` leaves the numerical entry empty.
#[test]
fn point_film_outside_the_domain_falls_back() {
    let mut args = vec!["film", "--contact", "point", "--json", "--no-solver"];
    let mut contact = CONTACT.to_vec();
    contact[13] = "1.0";
    args.extend(contact);
    let (ok, out, err) = bearing(&args);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let models = v["models"].as_array().unwrap();
    let by = |n: &str| models.iter().find(|m| m["name"] == n).unwrap();
    assert!(by("numerical")["central_film_m"].is_null());
    for name in ["ann_f32", "ann_int"] {
        let m = by(name);
        assert_eq!(m["source"], "fallback", "{m}");
        assert_eq!(m["central_film_m"], by("hamrock_dowson")["central_film_m"]);
    }
}

/// Refusals name the flag and the allowed range.
#[test]
fn point_film_refusals_name_the_flag() {
    let replace = |i: usize, v: &'static str| {
        let mut c = CONTACT.to_vec();
        c[i] = v;
        let mut args = vec!["film", "--contact", "point", "--no-solver"];
        args.extend(c);
        bearing(&args)
    };
    for (i, v, want) in [
        (
            7,
            "20",
            "--ellipticity = 20 is out of range: allowed 1 ..= 12",
        ),
        (1, "1e6", "--load = 1e6 N gives a peak Hertz pressure"),
        (11, "1", "--alpha"),
    ] {
        let (ok, _, err) = replace(i, v);
        assert!(!ok && err.contains(want), "{v}: {err}");
    }
    let (ok, _, err) = run(&["--radius-y", "0.01"]);
    assert!(!ok && err.contains("--radius-y or --ellipticity"), "{err}");
    let (ok, _, err) = bearing(&["film", "--ellipticity", "2", "--no-solver"]);
    assert!(!ok && err.contains("point-contact flags"), "{err}");
}

/// `bearing export` tells a point-contact model from a line-contact one: the committed point
/// model regenerates the committed `core/src/generated/point_model_weights.rs` byte for byte.
#[test]
fn export_writes_the_point_model() {
    let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("point_model_weights.rs");
    let model = root.join("data/ann/point_numerical_model.json");
    let (ok, _, err) = bearing(&[
        "export",
        "--model",
        model.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    let committed =
        std::fs::read_to_string(root.join("core/src/generated/point_model_weights.rs")).unwrap();
    assert!(std::fs::read_to_string(&out).unwrap() == committed);
}

/// `bearing export --tanh-table` writes the committed `core/src/generated/tanh_table.rs` byte
/// for byte, and is refused together with `--model`, naming both flags.
#[test]
fn export_writes_the_shared_tanh_table() {
    let root = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("tanh_table.rs");
    let (ok, _, err) = bearing(&["export", "--tanh-table", "--out", out.to_str().unwrap()]);
    assert!(ok, "{err}");
    let committed = std::fs::read_to_string(root.join("core/src/generated/tanh_table.rs")).unwrap();
    assert!(std::fs::read_to_string(&out).unwrap() == committed);
    let model = root.join("data/ann/numerical_model.json");
    let (ok, _, err) = bearing(&["export", "--tanh-table", "--model", model.to_str().unwrap()]);
    assert!(
        !ok && err.contains("--tanh-table") && err.contains("--model"),
        "{err}"
    );
}
