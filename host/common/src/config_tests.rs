//! Tests of the bearing configuration file (`super`).

use super::*;

fn bundled(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../configs")
        .join(name)
}

#[test]
fn bundled_configs_load() {
    for name in ["hub_motor.toml", "nu205.toml", "static_check.toml"] {
        let (c, p) = BearingConfig::load(&bundled(name)).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(p.geometry().roller_count(), c.geometry.roller_count);
    }
}

#[test]
fn refused_value_names_file_line_and_field() {
    let text = std::fs::read_to_string(bundled("hub_motor.toml")).unwrap();
    let bad = text.replace("roller_diameter_m = 0.0088", "roller_diameter_m = 0.07");
    let e = BearingConfig::parse(&bad, Path::new("bad.toml")).unwrap_err();
    let expected_line = bad
        .lines()
        .position(|l| l.starts_with("roller_diameter_m"))
        .unwrap()
        + 1;
    assert_eq!(e.line, Some(expected_line));
    assert_eq!(e.field.as_deref(), Some("roller_diameter_m"));
    let shown = e.to_string();
    assert!(
        shown.starts_with(&format!(
            "bad.toml:{expected_line}: field `roller_diameter_m`"
        )),
        "{shown}"
    );
    assert!(shown.contains("pitch_diameter_m"), "{shown}");
}

#[test]
fn friction_table_is_optional_and_its_values_are_checked() {
    let text = std::fs::read_to_string(bundled("nu205.toml")).unwrap();
    let (_, params) = BearingConfig::parse(&text, Path::new("nu205.toml")).unwrap();
    // The core's defaults, but β from `[lubricant]`'s default (an ISO VG 68 oil).
    let expected = FrictionDesign {
        viscosity_temperature_coefficient_k_inv: VG68_TEMPERATURE_VISCOSITY_PER_K,
        ..FrictionDesign::DEFAULT
    };
    assert_eq!(*params.friction(), expected.params().unwrap());
    let rough = format!("{text}\n[friction]\ncomposite_roughness_m = 0.3e-6\n");
    let (_, params) = BearingConfig::parse(&rough, Path::new("rough.toml")).unwrap();
    assert_eq!(params.friction().composite_roughness_m(), 0.3e-6);
    // An oil's conductivity of 1600 W/(m·K) (a metal's order) is refused at its line.
    let bad = text.replace(
        "[lubricant]\n",
        "[lubricant]\nthermal_conductivity_w_per_m_k = 1600.0\n",
    );
    let e = BearingConfig::parse(&bad, Path::new("bad.toml")).unwrap_err();
    assert_eq!(
        e.line,
        Some(line_of(&bad, "thermal_conductivity_w_per_m_k"))
    );
    assert_eq!(e.field.as_deref(), Some("thermal_conductivity_w_per_m_k"));
    assert!(e.to_string().contains("[0.01, 10]"), "{e}");
}

/// β and K are set in `[lubricant]` and reach both the friction and the film corrections; a
/// copy in `[friction]` or `[film_corrections]` is accepted when equal and refused, at its
/// line and field, when it differs.
#[test]
fn the_oil_thermal_properties_have_one_source() {
    let text = std::fs::read_to_string(bundled("nu205.toml")).unwrap();
    let oil = text.replace(
        "[lubricant]\n",
        "[lubricant]\ntemperature_viscosity_per_k = 0.05\nthermal_conductivity_w_per_m_k = 0.12\n",
    );
    let hot = format!("{oil}\n[film_corrections]\nthermal = true\n");
    let (_, params) = BearingConfig::parse(&hot, Path::new("oil.toml")).unwrap();
    let thermal = params.film_corrections().thermal.unwrap();
    assert_eq!(thermal.temperature_viscosity_per_k(), 0.05);
    assert_eq!(thermal.conductivity_w_per_m_k(), 0.12);
    let f = FrictionDesign {
        viscosity_temperature_coefficient_k_inv: 0.05,
        fluid_conductivity_w_mk: 0.12,
        ..FrictionDesign::DEFAULT
    };
    assert_eq!(*params.friction(), f.params().unwrap());
    let same = format!("{oil}\n[friction]\nfluid_conductivity_w_mk = 0.12\n");
    assert!(BearingConfig::parse(&same, Path::new("same.toml")).is_ok());
    for (table, key) in [
        ("friction", "fluid_conductivity_w_mk"),
        ("friction", "viscosity_temperature_coefficient_k_inv"),
        ("film_corrections", "temperature_viscosity_per_k"),
        ("film_corrections", "thermal_conductivity_w_per_m_k"),
    ] {
        let bad = format!("{oil}\n[{table}]\n{key} = 0.2\n");
        let e = BearingConfig::parse(&bad, Path::new("bad.toml")).unwrap_err();
        let lines: Vec<&str> = bad.lines().collect();
        let line = lines.iter().rposition(|l| l.starts_with(key)).unwrap() + 1;
        assert_eq!(e.line, Some(line), "{e}");
        assert_eq!(e.field.as_deref(), Some(key), "{e}");
        assert!(e.to_string().contains("[lubricant]"), "{e}");
    }
}

/// The line of `prefix…` in `text` (1-based).
fn line_of(text: &str, prefix: &str) -> usize {
    text.lines().position(|l| l.starts_with(prefix)).unwrap() + 1
}

/// The high-speed switches reach the core's parameters (off in `hub_motor.toml`, on in
/// `hub_motor_high_speed.toml`), and a refused value names its line and field.
#[test]
fn high_speed_switches_reach_the_params_and_bad_values_are_located() {
    let (_, plain) = BearingConfig::load(&bundled("hub_motor.toml")).unwrap();
    assert!(plain.film_corrections().is_off());
    assert_eq!(plain.centrifugal_force_n(2199.0), None);
    let text = std::fs::read_to_string(bundled("hub_motor_high_speed.toml")).unwrap();
    let (_, on) = BearingConfig::parse(&text, Path::new("h.toml")).unwrap();
    let c = on.film_corrections();
    assert!(c.thermal.is_some() && c.starvation.is_some());
    assert!(on.centrifugal_force_n(2199.0).unwrap() > 180.0);
    for (key, bad) in [
        ("oil_layer_m", "oil_layer_m = -1.0"),
        (
            "thermal_conductivity_w_per_m_k",
            "thermal_conductivity_w_per_m_k = 0.0",
        ),
        ("roller_density_kg_m3", "roller_density_kg_m3 = 1.0e9"),
    ] {
        let original = text.lines().find(|l| l.starts_with(key)).unwrap();
        let bad_text = text.replace(original, bad);
        let e = BearingConfig::parse(&bad_text, Path::new("h.toml")).unwrap_err();
        assert_eq!(e.line, Some(line_of(&bad_text, key)), "{e}");
        assert_eq!(e.field.as_deref(), Some(key), "{e}");
    }
}

#[test]
fn an_unknown_contact_law_is_named_with_the_laws_allowed() {
    let text = std::fs::read_to_string(bundled("hub_motor.toml")).unwrap();
    let bad = text.replace("contact_law = \"palmgren\"", "contact_law = \"hertz\"");
    let e = BearingConfig::parse(&bad, Path::new("c.toml")).unwrap_err();
    assert_eq!(e.line, Some(line_of(&bad, "contact_law")));
    let shown = e.to_string();
    assert!(shown.contains("\"hertz\""), "{shown}");
    assert!(shown.contains("\"palmgren\", \"lundberg\""), "{shown}");
    assert!(!shown.contains("NaN"), "{shown}");
}

#[test]
fn a_roller_count_the_host_cannot_step_is_refused_at_load_with_its_line() {
    let text = std::fs::read_to_string(bundled("hub_motor.toml")).unwrap();
    for count in [3, 5] {
        let bad = text.replace("roller_count = 17", &format!("roller_count = {count}"));
        let e = BearingConfig::parse(&bad, Path::new("r.toml")).unwrap_err();
        assert_eq!(e.line, Some(line_of(&bad, "roller_count")), "{e}");
        assert!(e.to_string().contains("[6, 40]"), "{e}");
    }
}

#[test]
fn a_type_error_names_the_field() {
    let text = std::fs::read_to_string(bundled("hub_motor.toml")).unwrap();
    let bad = text.replace("roller_count = 17", "roller_count = \"x\"");
    let e = BearingConfig::parse(&bad, Path::new("t.toml")).unwrap_err();
    assert_eq!(e.line, Some(line_of(&bad, "roller_count")));
    assert_eq!(e.field.as_deref(), Some("roller_count"), "{e}");
}

#[test]
fn syntax_and_unknown_fields_are_located() {
    let e = BearingConfig::parse(
        "name = \"x\"\n[geometry]\npitch_diameter_m = \"a\"\n",
        Path::new("s.toml"),
    )
    .unwrap_err();
    assert_eq!(e.line, Some(3), "{e}");
    let text = std::fs::read_to_string(bundled("nu205.toml")).unwrap();
    let bad = text.replace("roller_count = 12", "roller_count = 12\nroller_colour = 3");
    let e = BearingConfig::parse(&bad, Path::new("u.toml")).unwrap_err();
    assert!(e.to_string().contains("roller_colour"), "{e}");
    // The unknown key starts its line: the error points at that line, not the one before.
    let expected = bad
        .lines()
        .position(|l| l.starts_with("roller_colour"))
        .unwrap()
        + 1;
    assert_eq!(e.line, Some(expected), "{e}");
    let nan = text.replace("viscosity_pa_s = 0.08", "viscosity_pa_s = nan");
    let e = BearingConfig::parse(&nan, Path::new("n.toml")).unwrap_err();
    assert_eq!(e.field.as_deref(), Some("viscosity_pa_s"), "{e}");
}
