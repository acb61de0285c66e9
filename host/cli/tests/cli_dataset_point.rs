//! `bearing dataset generate --contact point`: a few cases of the point-contact domain solved at
//! a coarse grid (65², seconds), every row carrying its inputs, Moes' groups, the Richardson
//! targets and the raw values with their grid errors; an interrupted file resumes to the bytes
//! of an uninterrupted one; foreign settings and bad flags are refused by name.

// Each test file compiles `common` on its own; this one uses only `bearing`.
#[allow(dead_code)]
mod common;
use common::bearing;

use serde_json::Value;

/// The generation command for `out` (6 cases, seed 3, 65² nodes, chunks of 2).
fn generate(out: &str, seed: &str) -> (bool, String, String) {
    bearing(&[
        "dataset",
        "generate",
        "--contact",
        "point",
        "--n",
        "6",
        "--seed",
        seed,
        "--nodes",
        "65",
        "--chunk",
        "2",
        "--quiet",
        "--out",
        out,
    ])
}

fn f(v: &Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("{key} missing in {v}"))
}

#[test]
fn point_dataset_rows_resume_and_refusals() {
    let dir = std::env::temp_dir().join(format!("bearing-point-dataset-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let full = dir.join("full.jsonl");
    let part = dir.join("part.jsonl");
    for p in [&full, &part] {
        let _ = std::fs::remove_file(p);
    }
    let full_s = full.display().to_string();
    let (ok, _, err) = generate(&full_s, "3");
    assert!(ok, "{err}");
    assert!(err.contains("0 records resumed, 6 written"), "{err}");
    let text = std::fs::read_to_string(&full).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len(), 7);
    let header: Value = serde_json::from_str(lines[0]).unwrap();
    assert_eq!(header["metadata"]["format"], "bearing-point-film-dataset");
    assert_eq!(header["metadata"]["solver"]["options"]["nodes"], 65);
    let mut solved = 0;
    for (i, line) in lines[1..].iter().enumerate() {
        let row: Value = serde_json::from_str(line).unwrap();
        assert_eq!(row["index"], i);
        let c = &row["case"];
        // Moes' groups from the inputs (Nijenbanning, Venner & Moes 1994): W = w/(E′R_x²),
        // U = η₀u_m/(E′R_x), G = αE′, M = W(2U)^−¾, L = G(2U)^¼.
        let (e, rx) = (f(c, "reduced_modulus_pa"), f(c, "radius_x_m"));
        let w = f(c, "load_n") / (e * rx * rx);
        let u = f(c, "viscosity_pa_s") * f(c, "entrainment_speed_m_s") / (e * rx);
        let g = f(c, "pressure_viscosity_pa_inv") * e;
        let m = w * (2.0 * u).powf(-0.75);
        let l = g * (2.0 * u).powf(0.25);
        assert!((f(&row, "moes_m") / m - 1.0).abs() < 1e-9, "{row}");
        assert!((f(&row, "moes_l") / l - 1.0).abs() < 1e-9, "{row}");
        // Ellipticity against Hamrock & Brewer's k ≈ (R_y/R_x)^(2/π), a few per cent off.
        let k_approx = (f(c, "radius_y_m") / rx).powf(2.0 / std::f64::consts::PI);
        assert!(
            (f(&row, "ellipticity") / k_approx - 1.0).abs() < 0.05,
            "{row}"
        );
        if row.get("error").is_some() {
            assert!(row.get("central_m").is_none(), "{row}");
            continue;
        }
        solved += 1;
        for (target, raw, error) in [
            ("central_m", "central_raw_m", "central_grid_error"),
            ("minimum_m", "minimum_raw_m", "minimum_grid_error"),
        ] {
            let (t, r, e) = (f(&row, target), f(&row, raw), f(&row, error));
            assert!(t > 0.0 && r > 0.0 && (0.0..=0.073).contains(&e), "{row}");
            // The Richardson value lies the estimated grid error away from the raw value.
            assert!(((t / r - 1.0).abs() - e).abs() < 1e-9, "{row}");
        }
        assert!(f(&row, "minimum_m") < f(&row, "central_m"), "{row}");
    }
    assert!(solved >= 3, "only {solved} of 6 solved:\n{text}");

    // Interrupted after 3 records and half of the 4th: the resumed file is byte-identical.
    let mut cut: String = lines[..4].iter().map(|l| format!("{l}\n")).collect();
    cut.push_str(&lines[4][..lines[4].len() / 2]);
    std::fs::write(&part, cut).unwrap();
    let (ok, _, err) = generate(&part.display().to_string(), "3");
    assert!(ok, "{err}");
    assert!(err.contains("3 records resumed, 3 written"), "{err}");
    assert_eq!(std::fs::read_to_string(&part).unwrap(), text);

    // Another seed into the same file, a bad grid, and a line-contact file are refused.
    let (ok, _, err) = generate(&full_s, "4");
    assert!(!ok && err.contains("refusing to resume"), "{err}");
    let (ok, _, err) = bearing(&[
        "dataset",
        "generate",
        "--contact",
        "point",
        "--n",
        "2",
        "--seed",
        "1",
        "--nodes",
        "100",
        "--out",
        &full_s,
    ]);
    assert!(!ok && err.contains("--nodes 100"), "{err}");
    let line = dir.join("line.jsonl");
    std::fs::write(
        &line,
        "{\"metadata\":{\"format\":\"bearing-film-dataset\",\"format_version\":1}}\n",
    )
    .unwrap();
    let (ok, _, err) = generate(&line.display().to_string(), "3");
    assert!(!ok && err.contains("metadata.format"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}
