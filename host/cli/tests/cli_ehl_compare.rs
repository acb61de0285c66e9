//! CLI behaviour of `bearing ehl compare`: its ratios are the film of `bearing ehl solve` over
//! the formula computed here from docs/physics.md §5.1, and bad numbers exit non-zero naming the flag.

// Each test file compiles `common` on its own; this one uses only `bearing`.
#[allow(dead_code)]
mod common;
use common::bearing;

/// Moes' central film in Moes units (docs/physics.md §5.1), written out independently of the
/// library's `formulas` module.
fn moes_central(m: f64, l: f64) -> f64 {
    let (ri, ei) = (3.0 / m, 2.621 * m.powf(-0.2));
    let (rp, ep) = (
        1.287 * l.powf(2.0 / 3.0),
        1.311 * m.powf(-0.125) * l.powf(0.75),
    );
    let s = 1.5 * (1.0 + (-1.2 * ei / ri).exp());
    let iso = (ri.powf(7.0 / 3.0) + ei.powf(7.0 / 3.0)).powf(3.0 * s / 7.0);
    let piezo = (rp.powf(-3.5) + ep.powf(-3.5)).powf(-2.0 * s / 7.0);
    (iso + piezo).powf(1.0 / s)
}

#[test]
fn moes_ratios_are_solve_over_the_formula() {
    let (ok, out, err) = bearing(&[
        "ehl", "compare", "moes", "--m", "100", "--l", "3,20", "--json",
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["formula"], "moes");
    assert_eq!(v["cases"], 2);
    let rows = v["rows"].as_array().unwrap();
    for (row, l) in rows.iter().zip(["3", "20"]) {
        let (ok, out, err) = bearing(&[
            "ehl",
            "solve",
            "--m",
            "100",
            "--l",
            l,
            "--barus",
            "--incompressible",
            "--json",
        ]);
        assert!(ok, "{err}");
        let s: serde_json::Value = serde_json::from_str(&out).unwrap();
        let f = |x: &serde_json::Value| x.as_f64().unwrap();
        // R from the Hertz half-width b = R √(8W/π); h = H (2U)^½ R (docs/physics.md §1, §5.1).
        let (w, u) = (f(&row["w"]), f(&row["u"]));
        let r = f(&s["hertz_half_width_m"]) / (8.0 * w / std::f64::consts::PI).sqrt();
        let moes_m = moes_central(100.0, l.parse().unwrap()) * (2.0 * u).sqrt() * r;
        let ratio = f(&s["central_film_m"]) / moes_m;
        assert!(
            (f(&row["central_ratio"]) / ratio - 1.0).abs() < 1e-9,
            "{row} vs {ratio}"
        );
        // The within flag and the refined check follow the 5 % bound.
        let within = (ratio - 1.0).abs() < 0.05;
        assert_eq!(row["within"], within, "{row}");
        assert_eq!(row["refined"].is_null(), within, "{row}");
    }
}

#[test]
fn hostile_lists_are_refused_with_the_flag_name() {
    for (args, flag) in [
        (vec!["moes", "--m", "10,nan"], "--m"),
        (vec!["moes", "--l", "-1"], "--l"),
        (vec!["pan-hamrock", "--g", "0"], "--g"),
        (vec!["pan-hamrock", "--u", "1e-11,"], "--u"),
    ] {
        let mut all = vec!["ehl", "compare"];
        all.extend(args);
        let (ok, _, err) = bearing(&all);
        assert!(!ok && err.contains(flag), "{all:?}: {err}");
    }
    // In range for the parser, outside the case's physical range: the case names it.
    let (ok, _, err) = bearing(&["ehl", "compare", "pan-hamrock", "--w", "0.5"]);
    assert!(!ok && err.contains("W = 0.5"), "{err}");
}
