//! `bearing friction`'s refusals (the static load rating and speed of `bearing static`), its
//! single-contact Stribeck curve, the load-sharing comparison it reports and the power loss of
//! `bearing shaft sweep` (docs/friction.md, docs/shaft.md).

mod common;
use common::{bearing, config};

fn json(args: &[&str]) -> serde_json::Value {
    let (ok, out, err) = bearing(args);
    assert!(ok, "{err}");
    serde_json::from_str(&out).unwrap()
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

/// A radial load above the static load rating is refused naming `--radial-load`, or the
/// config's `[case] radial_load_n` with the file when the load comes from there; a speed above
/// the core's naming `--max-rpm`; with the range allowed.
#[test]
fn friction_refuses_what_static_refuses_naming_the_flag_or_the_field() {
    let hub = config("hub_motor.toml");
    let (ok, out, err) = bearing(&["friction", "--config", &hub, "--radial-load", "1e6"]);
    assert!(!ok && out.is_empty());
    assert!(
        err.contains("--radial-load = 1e6 N") && err.contains("static load rating"),
        "{err}"
    );
    assert!(err.contains("allowed 0 ..= "), "{err}");
    let (ok, _, err) = bearing(&["friction", "--config", &hub, "--max-rpm", "1e7"]);
    assert!(!ok);
    assert!(
        err.contains("--max-rpm = 1e7 rpm") && err.contains("954930"),
        "{err}"
    );
    // The load from the file's [case].
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("heavy.toml");
    let text = std::fs::read_to_string(&hub)
        .unwrap()
        .replace("radial_load_n = 2000.0", "radial_load_n = 1.0e6");
    assert!(text.contains("radial_load_n = 1.0e6"));
    std::fs::write(&path, text).unwrap();
    let heavy = path.to_str().unwrap();
    let (ok, _, err) = bearing(&["friction", "--config", heavy]);
    assert!(!ok);
    assert!(
        err.contains(&format!("{heavy} [case] radial_load_n = 1e6 N")),
        "{err}"
    );
    // One contact: its load against the steel's Hertz limit.
    let (ok, _, err) = bearing(&[
        "friction",
        "--config",
        &hub,
        "--contact",
        "inner",
        "--roller-load",
        "1e6",
    ]);
    assert!(!ok && err.contains("--roller-load = 1e6 N"), "{err}");
    let (ok, _, err) = bearing(&[
        "friction",
        "--config",
        &hub,
        "--contact",
        "outer",
        "--roller-load",
        "100",
        "--max-rpm",
        "1e7",
    ]);
    assert!(!ok && err.contains("--max-rpm = 1e7 rpm"), "{err}");
}

/// One contact from standstill to speed: λ rises, the regime runs boundary → mixed → full film,
/// the boundary part of μ falls to nothing, μ is its viscous plus boundary part, the film is
/// the one `bearing film` gives from the regression formulas, and the film re-solved for
/// Q − W_a is at least the whole-load film.
#[test]
fn single_contact_stribeck_curve_from_boundary_to_full_film() {
    let cfg = config("nu205.toml");
    let dir = tempfile::tempdir().unwrap();
    let plot = dir.path().join("contact.svg");
    let v = json(&[
        "friction",
        "--json",
        "--config",
        &cfg,
        "--contact",
        "outer",
        "--roller-load",
        "300",
        "--min-rpm",
        "10",
        "--max-rpm",
        "15000",
        "--points",
        "9",
        "--plot",
        plot.to_str().unwrap(),
    ]);
    assert_eq!(v["contact"], "outer");
    let points = v["points"].as_array().unwrap();
    assert_eq!(points.len(), 9);
    let whole = |p: &serde_json::Value| p["whole_load_film"].clone();
    assert_eq!(whole(&points[0])["lubrication"], "boundary");
    assert_eq!(whole(&points[8])["lubrication"], "full_film");
    assert!(points.iter().any(|p| whole(p)["lubrication"] == "mixed"));
    let boundary = |p: &serde_json::Value| f(&whole(p)["friction_coefficient_split"]["boundary"]);
    assert!(boundary(&points[0]) > 1e-3 && boundary(&points[8]) == 0.0);
    for w in points.windows(2) {
        assert!(f(&whole(&w[1])["lambda"]) > f(&whole(&w[0])["lambda"]));
        assert!(boundary(&w[1]) <= boundary(&w[0]));
    }
    for p in points {
        for key in ["whole_load_film", "resolved_film"] {
            let c = &p[key];
            let split = &c["friction_coefficient_split"];
            let sum = f(&split["viscous"]) + f(&split["boundary"]);
            assert!(
                (sum / f(&c["friction_coefficient"]) - 1.0).abs() < 1e-5,
                "{c}"
            );
        }
        assert!(f(&p["resolved_film"]["central_film_m"]) >= f(&whole(p)["central_film_m"]));
        assert!(f(&p["resolved_film"]["asperity_load_n"]) <= f(&whole(p)["asperity_load_n"]));
    }
    // The film at 15 000 rpm against `bearing film`'s regression model of the same contact.
    let film = json(&[
        "film",
        "--json",
        "--config",
        &cfg,
        "--speed-rpm",
        "15000",
        "--roller-load",
        "300",
    ]);
    let regression = film["outer"]["models"]
        .as_array()
        .unwrap()
        .iter()
        .find(|m| m["name"] == "regression")
        .unwrap()["central_film_m"]
        .clone();
    let h = f(&whole(&points[8])["central_film_m"]);
    assert!(
        (h / f(&regression) - 1.0).abs() < 1e-5,
        "{h} vs {regression}"
    );
    assert!(std::fs::read_to_string(&plot).unwrap().starts_with("<svg"));
}

/// The host's friction pass at the step's roller loads (regression films, the film of the
/// whole load) reproduces the core's torque, and re-solving the film for Q − W_a moves the
/// torque by less than 1 % over the NU 205 Stribeck sweep (docs/friction.md).
#[test]
fn load_sharing_comparison_reproduces_the_core_and_stays_within_one_percent() {
    let v = json(&[
        "friction",
        "--json",
        "--config",
        &config("nu205.toml"),
        "--min-rpm",
        "1",
    ]);
    for p in v["points"].as_array().unwrap() {
        let core = f(&p["friction_torque_nm"]);
        let sharing = &p["load_sharing"];
        let host = f(&sharing["whole_load_film"]["friction_torque_nm"]);
        assert!((host / core - 1.0).abs() < 1e-4, "{host} vs {core}");
        let change = f(&sharing["torque_change"]);
        assert!(change <= 0.0 && change > -0.01, "{p}");
    }
}

/// `bearing shaft sweep` gives the roller bearings' power loss per speed on both sides, with
/// its split summing to it, rising with speed, and a fourth plot.
#[test]
fn shaft_sweep_reports_power_loss_lubricated_and_dry() {
    let dir = tempfile::tempdir().unwrap();
    let plot = dir.path().join("sweep.png");
    let v = json(&[
        "shaft",
        "sweep",
        "--config",
        &config("shaft_nu205_rig.toml"),
        "--speeds-rpm",
        "1000,8000",
        "--settle",
        "0.005",
        "--duration",
        "0.005",
        "--plot",
        plot.to_str().unwrap(),
        "--json",
    ]);
    for side in ["lubricated", "dry"] {
        let power: Vec<f64> = v[side]["power_loss_w"]
            .as_array()
            .unwrap()
            .iter()
            .map(f)
            .collect();
        assert_eq!(power.len(), 2);
        assert!(power[0] > 0.0 && power[1] > power[0], "{side}: {power:?}");
        for (i, total) in power.iter().enumerate() {
            let parts: f64 = ["rolling", "viscous", "boundary"]
                .iter()
                .map(|k| f(&v[side]["power_loss_split_w"][k][i]))
                .sum();
            assert!((parts / total - 1.0).abs() < 1e-5, "{side} {i}");
        }
        let torque = f(&v[side]["friction_torque_nm"][1]);
        let omega = 8000.0 * std::f64::consts::PI / 30.0;
        assert!((power[1] / (torque * omega) - 1.0).abs() < 1e-5);
    }
    assert!(dir.path().join("sweep_power_loss.png").exists());
}
