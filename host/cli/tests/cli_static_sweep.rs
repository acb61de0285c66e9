//! `bearing static` over the load range of the bundled bearings: from no load (where only the
//! film and, on the hub-motor bearing, the 2 µm interference preload the rollers) to 20 kN, dry
//! and lubricated at 14 000 and 21 000 rpm. Every solve must converge, and the reported roller
//! loads must balance the applied load (an independent check of the equilibrium: the roller
//! loads Q_j along their angles θ_j sum to the radial load, docs/physics.md §3).

mod common;
use common::{bearing, config};

/// Loads (N): none, light (below the film preload of one roller), medium, and 20 kN.
const LOADS_N: [f64; 4] = [0.0, 10.0, 300.0, 20_000.0];
/// Speeds (rpm): dry (0) and the two lubricated speeds of docs/physics.md §6.
const SPEEDS_RPM: [f64; 3] = [0.0, 14_000.0, 21_000.0];

#[test]
fn static_converges_from_no_load_to_20_kn_for_both_bearings() {
    for file in ["hub_motor.toml", "nu205.toml"] {
        let cfg = config(file);
        for rpm in SPEEDS_RPM {
            for load in LOADS_N {
                let (load_arg, rpm_arg) = (load.to_string(), rpm.to_string());
                let (ok, out, err) = bearing(&[
                    "static",
                    "--config",
                    &cfg,
                    "--radial-load",
                    &load_arg,
                    "--speed-rpm",
                    &rpm_arg,
                    "--json",
                ]);
                let case = format!("{file} at {rpm} rpm, {load} N");
                assert!(ok, "{case}: {err}");
                let v: serde_json::Value = serde_json::from_str(&out).unwrap();
                let rollers = v["rollers"].as_array().unwrap();
                let (mut fx, mut fy, mut roller_load_sum) = (0.0f64, 0.0f64, 0.0f64);
                for r in rollers {
                    let (q, angle) = (
                        r["load_n"].as_f64().unwrap(),
                        r["angle_rad"].as_f64().unwrap(),
                    );
                    fx += q * angle.cos();
                    fy += q * angle.sin();
                    roller_load_sum += q.abs();
                }
                // The solver's tolerance is 10⁻⁶·max(F, ΣQ); the roller loads printed here
                // are f32, whose rounding adds up to ~10⁻⁶·ΣQ more over 17 rollers.
                let allowed = 2e-6 * load.max(roller_load_sum);
                let imbalance = fx.hypot(fy + load);
                assert!(
                    imbalance <= allowed,
                    "{case}: Σ Q_j (cos θ_j, sin θ_j) = ({fx}, {fy}) N, off the load by {imbalance} N > {allowed} N"
                );
                if rpm > 0.0 && load == 0.0 {
                    // The film preloads the rollers: a positive load on every roller without
                    // an applied load.
                    assert!(
                        rollers.iter().all(|r| r["load_n"].as_f64().unwrap() > 0.0),
                        "{case}"
                    );
                }
            }
        }
    }
}
