//! The shaft TOML loader: the bundled Friswell file reproduces the published frequencies, and
//! hostile input gives errors naming file, line, field and the allowed range.

use std::path::{Path, PathBuf};

use crate::analysis::operating::operating_modes;
use crate::model::config::{load_model, parse_model};

fn configs() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../configs")
}

/// Reference: Friswell et al. (2010) Example 5.9.1 at 4000 rpm (85.39, 87.80, 251.78, 294.71,
/// 600.18 rad/s), through the bundled configs/friswell_5_9_1.toml and the operating-point path.
#[test]
fn bundled_friswell_file_gives_published_frequencies() {
    let model = load_model(&configs().join("friswell_5_9_1.toml")).unwrap();
    let (_, modes) =
        operating_modes(&model, 4000.0 * std::f64::consts::PI / 30.0, 5, false).unwrap();
    for (m, p) in modes.iter().zip([85.39, 87.80, 251.78, 294.71, 600.18]) {
        assert!(
            (m.frequency - p).abs() / p < 0.005,
            "{} vs {p}",
            m.frequency
        );
    }
}

/// Every bundled shaft file parses.
#[test]
fn bundled_shaft_files_parse() {
    for name in [
        "friswell_5_9_1.toml",
        "shaft_hub_motor.toml",
        "shaft_nu205_rig.toml",
    ] {
        let model = load_model(&configs().join(name));
        assert!(
            model.is_ok(),
            "{name}: {}",
            model.err().map(|e| e.to_string()).unwrap_or_default()
        );
    }
}

const GOOD: &str = r#"nodes_m = [0.0, 0.5, 1.0]
[material]
youngs_modulus_pa = 211e9
shear_modulus_pa = 81.2e9
density_kg_m3 = 7810.0
[[section]]
from_node = 0
to_node = 2
outer_diameter_m = 0.05
[[bearing]]
node = 0
kind = "linear"
stiffness_n_per_m = 1e6
"#;

fn error_of(text: &str) -> String {
    parse_model(Path::new("x/shaft.toml"), text)
        .unwrap_err()
        .to_string()
}

#[test]
fn good_text_parses() {
    assert!(parse_model(Path::new("x/shaft.toml"), GOOD).is_ok());
}

#[test]
fn negative_nan_and_infinite_values_are_refused_with_location() {
    for bad in ["-0.05", "nan", "inf", "0.0"] {
        let text = GOOD.replace(
            "outer_diameter_m = 0.05",
            &format!("outer_diameter_m = {bad}"),
        );
        let e = error_of(&text);
        assert!(
            e.starts_with("x/shaft.toml:9: section[0].outer_diameter_m:"),
            "{e}"
        );
        assert!(e.contains("must be finite and in (0"), "{e}");
    }
}

#[test]
fn node_out_of_range_names_the_bearing() {
    let e = error_of(&GOOD.replace("node = 0\nkind", "node = 7\nkind"));
    assert!(e.starts_with("x/shaft.toml:11: bearing[0].node:"), "{e}");
    assert!(e.contains("allowed 0 … 2"), "{e}");
}

#[test]
fn unknown_bearing_kind_lists_the_allowed_ones() {
    let e = error_of(&GOOD.replace("\"linear\"", "\"magnetic\""));
    assert!(
        e.contains("bearing[0].kind") && e.contains("\"linear\", \"roller\""),
        "{e}"
    );
}

#[test]
fn syntax_and_unknown_field_errors_carry_the_line() {
    let e = error_of(&GOOD.replace("density_kg_m3 = 7810.0", "density_kg_m3 = = 7810.0"));
    assert!(e.starts_with("x/shaft.toml:5:"), "{e}");
    let e = error_of(&GOOD.replace("stiffness_n_per_m", "stifness_n_per_m"));
    assert!(
        e.starts_with("x/shaft.toml:13:") && e.contains("stifness_n_per_m"),
        "{e}"
    );
}

/// Finite but beyond any material or shaft (10⁸ × diamond's modulus, 10³⁰⁰ × osmium's density,
/// a 10¹⁹⁸ m shaft): refused at load with file, line and field, not later as a singular
/// stiffness or an eigen-solver that did not converge.
#[test]
fn absurd_finite_values_are_refused_with_location() {
    for (good, bad, line, field, max) in [
        (
            "outer_diameter_m = 0.05",
            "outer_diameter_m = 1e200",
            9,
            "section[0].outer_diameter_m",
            "10]",
        ),
        (
            "density_kg_m3 = 7810.0",
            "density_kg_m3 = 1e308",
            5,
            "material.density_kg_m3",
            "23000]",
        ),
        (
            "youngs_modulus_pa = 211e9",
            "youngs_modulus_pa = 1e20",
            3,
            "material.youngs_modulus_pa",
            "1200000000000]",
        ),
    ] {
        let e = error_of(&GOOD.replace(good, bad));
        let value = bad.split(" = ").nth(1).unwrap();
        assert!(
            e.starts_with(&format!(
                "x/shaft.toml:{line}: {field}: {value} is not allowed"
            )),
            "{e}"
        );
        assert!(e.contains(max), "{e}");
    }
}

/// A gap between two sections is reported against the section that ends where the gap
/// starts, not always against section[0].
#[test]
fn a_gap_between_sections_names_the_section_before_it() {
    let text = GOOD.replace("nodes_m = [0.0, 0.5, 1.0]", "nodes_m = [0.0, 0.25, 0.5, 0.75, 1.0]")
        .replace("from_node = 0\nto_node = 2\n", "from_node = 0\nto_node = 1\n")
        + "[[section]]\nfrom_node = 1\nto_node = 2\nouter_diameter_m = 0.05\n[[section]]\nfrom_node = 3\nto_node = 4\nouter_diameter_m = 0.05\n";
    let e = error_of(&text);
    let line = text.lines().position(|l| l == "to_node = 2").unwrap() + 1;
    assert!(
        e.starts_with(&format!("x/shaft.toml:{line}: section[1].to_node:")),
        "{e}"
    );
    assert!(e.contains("nodes 2 and 3 has no section"), "{e}");
}

#[test]
fn uncovered_elements_and_decreasing_nodes_are_refused() {
    let e = error_of(&GOOD.replace("to_node = 2", "to_node = 1"));
    assert!(e.contains("no section"), "{e}");
    let e = error_of(&GOOD.replace("[0.0, 0.5, 1.0]", "[0.0, 0.5, 0.4]"));
    assert!(
        e.starts_with("x/shaft.toml:1: nodes_m:") && e.contains("increase"),
        "{e}"
    );
}

#[test]
fn roller_bearing_path_is_relative_to_the_shaft_file() {
    let text = GOOD.replace(
        "kind = \"linear\"\nstiffness_n_per_m = 1e6",
        "kind = \"roller\"\nconfig = \"hub_motor.toml\"\nfilm = \"regression\"",
    );
    let model = parse_model(Path::new("x/shaft.toml"), &text).unwrap();
    let spec = &model.description.bearings[0].spec;
    match spec {
        crate::bearing::BearingSpec::Roller { config, .. } => {
            assert_eq!(config, &Path::new("x").join("hub_motor.toml"))
        }
        other => panic!("{other:?}"),
    }
    let e = spec.build().err().unwrap().to_string();
    assert!(
        e.contains("x/hub_motor.toml") && e.contains("cannot read"),
        "{e}"
    );
}

/// The bundled bearing file builds a core bearing with every film model; the integer and the
/// f32 network (the same trained net, quantised or not: ≤ 0.03 % apart on the test set) give
/// nearly the same bearing force, and both differ from the dry bearing.
#[test]
fn roller_bearing_films() {
    use crate::bearing::{roller_bearing, BearingState, FilmKind};
    let path = configs().join("hub_motor.toml");
    let state = BearingState {
        displacement: [0.0, -8.0e-6],
        velocity: [0.0; 2],
        spin_speed: 12_000.0 * std::f64::consts::PI / 30.0,
        time: 0.0,
    };
    let force = |film| {
        let mut b = roller_bearing(&path, film).unwrap();
        let mut f = [0.0; 2];
        for _ in 0..8 {
            f = b.evaluate(&state).unwrap().force;
        }
        f[1]
    };
    let (int, f32_net, dry) = (
        force(FilmKind::Int),
        force(FilmKind::F32),
        force(FilmKind::Dry),
    );
    assert!(roller_bearing(&path, FilmKind::Regression).is_ok());
    assert!(
        (int / f32_net - 1.0).abs() < 5e-3,
        "int {int} N vs f32 {f32_net} N"
    );
    assert!(
        (int / dry - 1.0).abs() > 0.05,
        "network {int} N vs dry {dry} N"
    );
}

/// configs/friswell_5_9_1.toml with its last element (1.25 … 1.5 m) split at 1.5 m − `short_m`:
/// the same rotor, meshed with one element of length `short_m`.
fn friswell_with_short_element(short_m: f64) -> String {
    let text = std::fs::read_to_string(configs().join("friswell_5_9_1.toml")).unwrap();
    let nodes = "nodes_m = [0.0, 0.25, 0.5, 0.75, 1.0, 1.25, 1.5]";
    assert!(text.contains(nodes));
    text.replace(
        nodes,
        &format!(
            "nodes_m = [0.0, 0.25, 0.5, 0.75, 1.0, 1.25, {}, 1.5]",
            1.5 - short_m
        ),
    )
    .replace("to_node = 6", "to_node = 7")
    .replace("node = 6\n", "node = 7\n")
}

/// A 1 µm or 1 nm element (2.5·10⁵ and 2.5·10⁸ times shorter than the others) is refused on
/// the nodes_m line; just inside the allowed ratio (100: a 2.5 mm element) the rotor keeps the
/// frequencies of the uniform mesh (Friswell et al. (2010) Example 5.9.1 at 4000 rpm).
#[test]
fn ill_conditioned_meshes_are_refused_and_the_allowed_ratio_solves_correctly() {
    for short_m in [1e-6, 1e-9] {
        let text = friswell_with_short_element(short_m);
        let e = parse_model(Path::new("x/shaft.toml"), &text)
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("x/shaft.toml:7: nodes_m:") && e.contains("within a factor 100"),
            "{short_m}: {e}"
        );
    }
    let omega = 4000.0 * std::f64::consts::PI / 30.0;
    let uniform = load_model(&configs().join("friswell_5_9_1.toml")).unwrap();
    let (_, reference) = operating_modes(&uniform, omega, 5, false).unwrap();
    // Just inside the allowed ratio (1 % longer than 1/100 of the 0.25 m elements).
    let short_m = 1.01 * 0.25 / crate::model::config::MAX_ELEMENT_LENGTH_RATIO;
    let split = parse_model(
        Path::new("x/shaft.toml"),
        &friswell_with_short_element(short_m),
    )
    .unwrap();
    let (_, modes) = operating_modes(&split, omega, 5, false).unwrap();
    for (m, r) in modes.iter().zip(&reference) {
        assert!(
            (m.frequency / r.frequency - 1.0).abs() < 1e-4,
            "{} vs {} rad/s",
            m.frequency,
            r.frequency
        );
    }
}
