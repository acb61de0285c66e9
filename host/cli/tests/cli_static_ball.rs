//! `bearing static` on the bundled ball bearings: the ball loads reported in `--json` balance
//! the applied load in all five coordinates (an independent check of the equilibrium: each
//! ball's load along its line of centres, summed, docs/ball_bearings.md), the forward map
//! returns the load the static solve balanced, and refusals name their flag.

mod common;
use common::{bearing, config};

fn json(args: &[&str]) -> serde_json::Value {
    let (ok, out, err) = bearing(args);
    assert!(ok, "{args:?}: {err}");
    serde_json::from_str(&out).unwrap()
}

/// Σ_j Q_j (cos α cos ψ, cos α sin ψ, sin α, R_i sin α sin ψ, −R_i sin α cos ψ): the load the
/// balls carry, from the per-ball output alone.
fn carried(v: &serde_json::Value, lever_m: f64) -> [f64; 5] {
    let mut f = [0.0; 5];
    for b in v["balls"].as_array().unwrap() {
        let q = b["load_inner_n"].as_f64().unwrap();
        let a = b["contact_angle_inner_deg"].as_f64().unwrap().to_radians();
        let psi = b["azimuth_deg"].as_f64().unwrap().to_radians();
        f[0] += q * a.cos() * psi.cos();
        f[1] += q * a.cos() * psi.sin();
        f[2] += q * a.sin();
        f[3] += q * a.sin() * lever_m * psi.sin();
        f[4] -= q * a.sin() * lever_m * psi.cos();
    }
    f
}

#[test]
fn ball_loads_balance_the_applied_load() {
    // R_i = d_m/2 + (f_i − 0.5) D cos α₀ of each bundled bearing.
    let cases = [
        (
            "deep_groove_6205.toml",
            0.5 * 0.03904 + 0.02 * 0.007938 * (10.0f64.to_radians()).cos(),
            "800",
            "300",
        ),
        (
            "angular_7205.toml",
            0.5 * 0.0385 + 0.02 * 0.007938 * 40f64.to_radians().cos(),
            "500",
            "1500",
        ),
    ];
    for (file, lever, radial, axial) in cases {
        let cfg = config(file);
        for rpm in ["0", "6000", "20000"] {
            let v = json(&[
                "static",
                "--config",
                &cfg,
                "--radial-load",
                radial,
                "--axial-load",
                axial,
                "--speed-rpm",
                rpm,
                "--free-tilt",
                "--json",
            ]);
            let applied = [
                0.0,
                -radial.parse::<f64>().unwrap(),
                axial.parse::<f64>().unwrap(),
                0.0,
                0.0,
            ];
            let got = carried(&v, lever);
            for (i, (g, a)) in got.iter().zip(applied).enumerate() {
                let scale = if i < 3 { 1.0 } else { lever };
                assert!(
                    (g - a).abs() <= 2e-3 * 1500.0 * scale,
                    "{file} {rpm} rpm: component {i}: {got:?}"
                );
            }
            // The forward map at the solved displacement gives the same load back.
            let d: Vec<String> = v["displacement"]
                .as_array()
                .unwrap()
                .iter()
                .map(|x| x.to_string())
                .collect();
            let w = json(&[
                "static",
                "--config",
                &cfg,
                "--speed-rpm",
                rpm,
                "--displacement",
                &d.join(","),
                "--json",
            ]);
            for (a, b) in w["applied_load"]
                .as_array()
                .unwrap()
                .iter()
                .zip(v["applied_load"].as_array().unwrap())
            {
                let (a, b) = (a.as_f64().unwrap(), b.as_f64().unwrap());
                assert!(
                    (a - b).abs() <= 1e-3 * (1.0 + b.abs()),
                    "{file} {rpm}: {a} vs {b}"
                );
            }
        }
    }
}

#[test]
fn lubricated_deep_groove_is_stiffer_than_dry() {
    let cfg = config("deep_groove_6205.toml");
    let v = json(&[
        "static",
        "--config",
        &cfg,
        "--radial-load",
        "1000",
        "--speed-rpm",
        "10000",
        "--dry",
        "--json",
    ]);
    assert_eq!(v["film_model"], "network_int");
    let k = v["stiffness"][0][0].as_f64().unwrap();
    let kd = v["dry"]["stiffness"][0][0].as_f64().unwrap();
    assert!(k > kd, "{k} {kd}");
    assert!(v["balls"][0]["film_central_inner_m"].as_f64().unwrap() > 0.0);
}

#[test]
fn ball_refusals_name_the_flag() {
    let ball = config("angular_7205.toml");
    let roller = config("hub_motor.toml");
    for (args, needle) in [
        (
            vec!["static", "--config", &roller, "--axial-load", "10"],
            "--axial-load",
        ),
        (
            vec!["static", "--config", &ball, "--displacement", "1,2,3"],
            "--displacement",
        ),
        (
            vec!["static", "--config", &ball, "--moment-x-nm", "1"],
            "--free-tilt",
        ),
        (
            vec!["static", "--config", &ball, "--axial-load", "-inf"],
            "--axial-load",
        ),
        (
            vec![
                "static",
                "--config",
                &ball,
                "--axial-load",
                "-100",
                "--radial-load",
                "0",
            ],
            "no equilibrium",
        ),
    ] {
        let (ok, _, err) = bearing(&args);
        assert!(!ok && err.contains(needle), "{args:?}: {err}");
    }
}

/// `bearing film` on a ball config: both contacts, with the 6205 inner contact's Hertz
/// ellipticity (9.32: R_y/R_x = 32.6) and its film source flagged.
#[test]
fn film_of_both_ball_contacts() {
    let cfg = config("deep_groove_6205.toml");
    let v = json(&[
        "film",
        "--config",
        &cfg,
        "--speed-rpm",
        "10000",
        "--ball-load",
        "500",
        "--no-solver",
        "--json",
    ]);
    let k = v["inner"]["dimensionless"]["ellipticity"].as_f64().unwrap();
    assert!((k - 9.32).abs() < 0.01, "{k}");
    assert!(v["outer"]["dimensionless"]["ellipticity"].as_f64().unwrap() < k);
    let (ok, _, err) = bearing(&[
        "film",
        "--config",
        &cfg,
        "--speed-rpm",
        "10000",
        "--roller-load",
        "5",
    ]);
    assert!(!ok && err.contains("--ball-load"), "{err}");
}

/// `--centrifugal on` at speed separates the inner and outer contact angles of the preloaded
/// 7205 (the inner rises, the outer falls), and leaves them equal at rest.
#[test]
fn centrifugal_switch_splits_the_contact_angles() {
    let cfg = config("angular_7205.toml");
    let angles = |rpm: &str, on: &str| {
        let v = json(&[
            "static",
            "--config",
            &cfg,
            "--radial-load",
            "0",
            "--axial-load",
            "500",
            "--speed-rpm",
            rpm,
            "--centrifugal",
            on,
            "--json",
        ]);
        let b = &v["balls"][0];
        (
            b["contact_angle_inner_deg"].as_f64().unwrap(),
            b["contact_angle_outer_deg"].as_f64().unwrap(),
        )
    };
    let (i_off, o_off) = angles("20000", "off");
    assert!((i_off - o_off).abs() < 1e-6);
    let (i_on, o_on) = angles("20000", "on");
    assert!(
        i_on > i_off && o_on < o_off,
        "{i_on} {o_on} against {i_off}"
    );
}
