//! `bearing ehl solve` says how far a result can be trusted: cases outside the solver's model
//! are refused naming the quantity, its range and the flags, grids too coarse for the case are
//! refused naming `--nodes`, and every result carries its grid-error estimate.

// Each test file compiles `common` on its own; this one uses only `bearing`.
#[allow(dead_code)]
mod common;
use common::bearing;

const CONTACT: [&str; 10] = [
    "--length",
    "0.009",
    "--radius",
    "0.0032",
    "--modulus",
    "2.308e11",
    "--alpha",
    "2.1e-8",
    "--eta0",
    "0.08",
];

fn solve(extra: &[&str]) -> (bool, serde_json::Value, String) {
    let mut args = vec!["ehl", "solve", "--json"];
    args.extend(extra);
    let (ok, out, err) = bearing(&args);
    let v = serde_json::from_str(&out).unwrap_or_else(|e| panic!("{e}: {out}"));
    (ok, v, err)
}

#[test]
fn films_outside_the_model_are_refused_with_the_flags() {
    // 1 mN on 9 mm: a film of centimetres on a 3.2 mm radius.
    let mut args = vec!["--load", "1e-3", "--entrainment", "5"];
    args.extend(CONTACT);
    let (ok, v, err) = solve(&args);
    assert!(!ok && v["converged"] == false, "{v}");
    assert!(
        err.contains("h_c/R") && err.contains("--entrainment"),
        "{err}"
    );
    // 1 µm/s under 800 N: a 10⁻¹¹ m film.
    let mut args = vec!["--load", "800", "--entrainment", "1e-6"];
    args.extend(CONTACT);
    let (ok, _, err) = solve(&args);
    assert!(
        !ok && err.contains("central film h_c (m)") && err.contains("1e-9"),
        "{err}"
    );
}

#[test]
fn coarse_grids_are_refused_and_results_carry_their_grid_error() {
    let (ok, v, err) = solve(&["--m", "30", "--l", "5", "--nodes", "41"]);
    assert!(!ok && v["converged"] == false, "{v}");
    assert!(
        err.contains("--nodes 41") && err.contains("too coarse"),
        "{err}"
    );
    let (ok, v, err) = solve(&["--m", "30", "--l", "5", "--nodes", "401"]);
    assert!(ok && v["converged"] == true, "{err}");
    let e = &v["grid_error_estimate"];
    let (central, minimum) = (
        e["central_film"].as_f64().unwrap(),
        e["min_film"].as_f64().unwrap(),
    );
    assert!(
        central > 0.0 && central < 0.1 && minimum > 0.0 && minimum < 0.1,
        "{e}"
    );
    assert_eq!(e["other_nodes"], 201);
}

/// Point contacts: a grid that does not resolve the film is refused naming the estimate and the
/// flags of a finer grid; without --nodes the grid is chosen from the case and the answer
/// carries an estimate within the 2 % bound.
#[test]
fn point_grids_too_coarse_are_refused_naming_the_estimate() {
    let (ok, v, err) = solve(&[
        "--contact",
        "point",
        "--m",
        "1000",
        "--l",
        "6",
        "--nodes",
        "65",
    ]);
    assert!(!ok && v["converged"] == false, "{v}");
    assert!(
        err.contains("65 × 65 grid does not resolve")
            && err.contains("estimated grid error h_c")
            && err.contains("--rolling-nodes 129")
            && err.contains("--nodes 129"),
        "{err}"
    );
    let (ok, v, err) = solve(&["--contact", "point", "--m", "20", "--l", "10"]);
    assert!(ok && v["converged"] == true, "{err}");
    assert_eq!(v["nodes"], 129 * 129);
    let e = &v["grid_error_estimate"];
    for film in ["central_film", "min_film"] {
        let estimate = e[film].as_f64().unwrap();
        assert!(estimate > 0.0 && estimate <= 0.02, "{e}");
    }
}
