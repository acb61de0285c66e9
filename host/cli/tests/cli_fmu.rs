//! CLI behaviour of `bearing fmu export`: the archive holds modelDescription.xml, the linux64
//! library and the bearing file with the film model; every refusal names the flag or the file,
//! line and field, and leaves the output as it was.

// Each test file compiles `common` on its own.
#[allow(dead_code)]
mod common;
use common::{bearing, config};

use std::io::Read;

fn entry(fmu: &std::path::Path, name: &str) -> String {
    let mut archive = zip::ZipArchive::new(std::fs::File::open(fmu).unwrap()).unwrap();
    let mut text = String::new();
    archive
        .by_name(name)
        .unwrap()
        .read_to_string(&mut text)
        .unwrap();
    text
}

#[test]
fn export_writes_a_complete_fmu() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("nu205.fmu");
    let (ok, stdout, err) = bearing(&[
        "fmu",
        "export",
        "--config",
        &config("nu205.toml"),
        "--film",
        "regression",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    let archive = zip::ZipArchive::new(std::fs::File::open(&out).unwrap()).unwrap();
    let mut names: Vec<&str> = archive.file_names().collect();
    names.sort_unstable();
    assert_eq!(
        names,
        [
            "binaries/linux64/bearing_fmu.so",
            "modelDescription.xml",
            "resources/bearing.toml",
            "resources/film_model.txt",
        ]
    );
    assert_eq!(entry(&out, "resources/film_model.txt"), "regression\n");
    assert_eq!(
        entry(&out, "resources/bearing.toml"),
        std::fs::read_to_string(config("nu205.toml")).unwrap()
    );
    let xml = entry(&out, "modelDescription.xml");
    let guid = stdout
        .split("GUID ")
        .nth(1)
        .unwrap()
        .split(',')
        .next()
        .unwrap();
    assert!(xml.contains(&format!("guid=\"{guid}\"")), "{stdout}");
    assert!(xml.contains("name=\"roller_count\""));
    assert!(xml.contains("<Integer min=\"6\" max=\"40\" start=\"12\"/>"));
}

#[test]
fn refusals_name_the_flag_or_the_field_and_leave_the_output() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("kept.fmu");
    std::fs::write(&out, "earlier").unwrap();
    let out_arg = out.to_str().unwrap().to_owned();
    let hub = config("hub_motor.toml");
    let bad_config = dir.path().join("bad.toml");
    let text = std::fs::read_to_string(&hub).unwrap();
    std::fs::write(
        &bad_config,
        text.replace("roller_diameter_m = 0.0088", "roller_diameter_m = 0.07"),
    )
    .unwrap();
    let bad_config = bad_config.to_str().unwrap().to_owned();
    let cases: [(Vec<&str>, &str); 4] = [
        (vec!["--config", &hub, "--film", "wet"], "--film"),
        (
            vec![
                "--config",
                &hub,
                "--library",
                "/nonexistent/libbearing_fmu.so",
            ],
            "--library /nonexistent/libbearing_fmu.so",
        ),
        (
            vec!["--config", &bad_config],
            ":8: field `roller_diameter_m`",
        ),
        (
            vec!["--config", "/nonexistent.toml"],
            "/nonexistent.toml: cannot read",
        ),
    ];
    for (args, named) in cases {
        let mut all = vec!["fmu", "export", "--out", &out_arg];
        all.extend(args);
        let (ok, _, err) = bearing(&all);
        assert!(!ok, "{all:?} was accepted");
        assert!(err.contains(named), "{all:?}: {err}");
        assert_eq!(std::fs::read_to_string(&out).unwrap(), "earlier", "{all:?}");
    }
    let (ok, _, err) = bearing(&[
        "fmu",
        "export",
        "--config",
        &hub,
        "--out",
        "/nonexistent/dir/x.fmu",
    ]);
    assert!(!ok);
    assert!(err.contains("--out /nonexistent/dir/x.fmu"), "{err}");
}
