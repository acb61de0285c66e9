//! What the tests need besides Rust, checked one by one and installed where this user may:
//! the Cortex-M4F Rust target (`rustup target add`), Debian packages (`apt-get`, as root or
//! with passwordless `sudo`), and a Python environment under the target directory with the
//! packages of `host/xtask/python-requirements.txt` (`python3 -m venv` + `pip`). What cannot be
//! installed is reported with the tests it keeps from running; it is never skipped silently.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use anyhow::{bail, Result};

/// The Cortex-M4F target of the firmware, the QEMU tests and the C library's M4 example.
pub const M4_TARGET: &str = "thumbv7em-none-eabihf";
/// The list of Python packages the tests need (pip's requirements format).
pub const PYTHON_REQUIREMENTS: &str = "host/xtask/python-requirements.txt";
/// The environment variable that hands the tests the Python interpreter with those packages.
pub const PYTHON_VAR: &str = "BEARING_PYTHON";

/// How a Debian package is recognised as present.
#[derive(Clone, Copy)]
enum Present {
    /// An executable on the `PATH`.
    Command(&'static str),
    /// A package that installs no executable (a library, headers, fonts): `dpkg -s`.
    Dpkg,
}

/// A Debian package the build, the tests or CI need.
struct DebianPackage {
    package: &'static str,
    present: Present,
    /// What cannot build or run without it.
    needed_by: &'static str,
}

const DEBIAN_PACKAGES: [DebianPackage; 11] = [
    DebianPackage {
        package: "gcc",
        present: Present::Command("cc"),
        needed_by: "every build (the linker) and the C library's host examples (core/ffi/tests/c_examples.rs)",
    },
    DebianPackage {
        package: "g++",
        present: Present::Command("c++"),
        needed_by: "the fuzz targets' libFuzzer (fuzz/run.sh, run by .ci/run)",
    },
    DebianPackage {
        package: "pkg-config",
        present: Present::Command("pkg-config"),
        needed_by: "the build of every crate with plots (fontconfig, through plotters)",
    },
    DebianPackage {
        package: "libfontconfig1-dev",
        present: Present::Dpkg,
        needed_by: "the build of every crate with plots (bearing-cli, bearing-hil, bearing-shaft, bearing-host-common)",
    },
    DebianPackage {
        package: "fonts-dejavu-core",
        present: Present::Dpkg,
        needed_by: "the text of every plot the tests draw",
    },
    DebianPackage {
        package: "libclang-dev",
        present: Present::Dpkg,
        needed_by: "the build of bearing-fmu (bindgen in fmi-sys) and so of the whole workspace",
    },
    DebianPackage {
        package: "qemu-system-arm",
        present: Present::Command("qemu-system-arm"),
        needed_by: "tests/tests/hil_qemu.rs, the M4 C example of core/ffi/tests/c_examples.rs",
    },
    DebianPackage {
        package: "gcc-arm-none-eabi",
        present: Present::Command("arm-none-eabi-gcc"),
        needed_by: "the M4 C example of core/ffi/tests/c_examples.rs",
    },
    DebianPackage {
        package: "libnewlib-arm-none-eabi",
        present: Present::Dpkg,
        needed_by: "the M4 C example of core/ffi/tests/c_examples.rs",
    },
    DebianPackage {
        package: "python3",
        present: Present::Command("python3"),
        needed_by: "host/fmu/tests/fmpy.rs (FMPy)",
    },
    DebianPackage {
        package: "python3-venv",
        present: Present::Dpkg,
        needed_by: "host/fmu/tests/fmpy.rs (the Python environment under target/)",
    },
];

/// Something missing after the set-up, and what it keeps from running.
#[derive(Clone, Debug)]
pub struct Missing {
    /// What is missing.
    pub what: String,
    /// Why it could not be installed.
    pub reason: String,
    /// The tests (or builds) it keeps from running.
    pub needed_by: String,
}

/// The outcome of the set-up.
#[derive(Debug, Default)]
pub struct Setup {
    /// The Python interpreter with the required packages, when there is one.
    pub python: Option<PathBuf>,
    /// What is still missing.
    pub missing: Vec<Missing>,
}

/// Whether `program` runs (`--version`).
fn runs(program: &str) -> bool {
    Command::new(program)
        .arg("--version")
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
}

fn dpkg_has(package: &str) -> bool {
    Command::new("dpkg-query")
        .args(["-W", "-f=${Status}", package])
        .output()
        .is_ok_and(|o| {
            o.status.success()
                && String::from_utf8_lossy(&o.stdout).contains("install ok installed")
        })
}

fn debian_present(p: &DebianPackage) -> bool {
    match p.present {
        Present::Command(c) => runs(c),
        Present::Dpkg => dpkg_has(p.package),
    }
}

/// Whether this user runs `apt-get` through `sudo -n` (`false`: as root), or why it may not
/// run it at all.
fn apt_through_sudo() -> std::result::Result<bool, String> {
    if !runs("apt-get") {
        return Err("apt-get is not available (not a Debian-based system)".into());
    }
    let uid = Command::new("id").arg("-u").output().ok();
    if uid.is_some_and(|o| String::from_utf8_lossy(&o.stdout).trim() == "0") {
        return Ok(false);
    }
    let sudo = Command::new("sudo")
        .args(["-n", "true"])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .status()
        .is_ok_and(|s| s.success());
    if sudo {
        Ok(true)
    } else {
        Err("neither root nor passwordless sudo: install them with apt-get as root".into())
    }
}

/// `apt-get ARGS`, through `sudo -n` when `sudo`.
fn apt_get(sudo: bool, args: &[&str]) -> std::result::Result<(), String> {
    let env = [("DEBIAN_FRONTEND", "noninteractive")];
    if sudo {
        let mut all = vec!["-n", "DEBIAN_FRONTEND=noninteractive", "apt-get"];
        all.extend_from_slice(args);
        run_shown("sudo", &all, &[])
    } else {
        run_shown("apt-get", args, &env)
    }
}

/// Runs a command with its output shown; `Err` with what failed.
fn run_shown(
    program: &str,
    args: &[&str],
    envs: &[(&str, &str)],
) -> std::result::Result<(), String> {
    eprintln!("  $ {program} {}", args.join(" "));
    let status = Command::new(program)
        .args(args)
        .envs(envs.iter().copied())
        .stdin(Stdio::null())
        .status()
        .map_err(|e| format!("cannot run {program}: {e}"))?;
    if status.success() {
        Ok(())
    } else {
        Err(format!("`{program} {}` failed ({status})", args.join(" ")))
    }
}

/// The Debian packages: the missing ones installed in one `apt-get install` where allowed.
fn debian(missing: &mut Vec<Missing>) {
    if !runs("dpkg-query") {
        eprintln!(
            "Debian packages: no dpkg on this system; install the equivalents of {} by hand",
            DEBIAN_PACKAGES.map(|p| p.package).join(", ")
        );
        return;
    }
    let absent: Vec<&DebianPackage> = DEBIAN_PACKAGES
        .iter()
        .filter(|p| !debian_present(p))
        .collect();
    if absent.is_empty() {
        eprintln!("Debian packages: all {} present", DEBIAN_PACKAGES.len());
        return;
    }
    let names: Vec<&str> = absent.iter().map(|p| p.package).collect();
    eprintln!("Debian packages: installing {}", names.join(" "));
    let installed = apt_through_sudo().and_then(|sudo| {
        apt_get(sudo, &["update"])?;
        let mut install = vec!["install", "-y", "--no-install-recommends"];
        install.extend(&names);
        apt_get(sudo, &install)
    });
    for p in absent {
        if !debian_present(p) {
            let reason = match &installed {
                Err(e) => e.clone(),
                Ok(()) => "installed by apt-get, but still not found".into(),
            };
            missing.push(Missing {
                what: format!("Debian package {}", p.package),
                reason,
                needed_by: p.needed_by.into(),
            });
        }
    }
}

/// The Cortex-M4F target of the Rust toolchain.
fn rust_target(missing: &mut Vec<Missing>) {
    let installed = || {
        Command::new("rustup")
            .args(["target", "list", "--installed"])
            .output()
            .is_ok_and(|o| {
                String::from_utf8_lossy(&o.stdout)
                    .lines()
                    .any(|l| l.trim() == M4_TARGET)
            })
    };
    if installed() {
        eprintln!("Rust target {M4_TARGET}: present");
        return;
    }
    eprintln!("Rust target {M4_TARGET}: adding");
    let added = run_shown("rustup", &["target", "add", M4_TARGET], &[]);
    if !installed() {
        missing.push(Missing {
            what: format!("Rust target {M4_TARGET}"),
            reason: added
                .err()
                .unwrap_or_else(|| "rustup added it, but it is not listed".into()),
            needed_by: "tests/tests/hil_qemu.rs, the M4 C example of core/ffi/tests/c_examples.rs"
                .into(),
        });
    }
}

/// The workspace's target directory (`CARGO_TARGET_DIR` or `target/`).
pub fn target_dir(root: &Path) -> PathBuf {
    std::env::var_os("CARGO_TARGET_DIR").map_or_else(|| root.join("target"), PathBuf::from)
}

/// The Python environment under the target directory, with the listed packages. Its stamp file
/// holds the requirements it was made from; a changed list installs again.
fn python(root: &Path, missing: &mut Vec<Missing>) -> Option<PathBuf> {
    let env = target_dir(root).join("python");
    let python = env.join("bin/python");
    let stamp = env.join("requirements.installed");
    let needed_by = "host/fmu/tests/fmpy.rs (FMPy validates and simulates the FMU)";
    let requirements = match std::fs::read_to_string(root.join(PYTHON_REQUIREMENTS)) {
        Ok(text) => text,
        Err(e) => {
            missing.push(Missing {
                what: PYTHON_REQUIREMENTS.into(),
                reason: e.to_string(),
                needed_by: needed_by.into(),
            });
            return None;
        }
    };
    if runs(python.to_str()?)
        && std::fs::read_to_string(&stamp).ok().as_deref() == Some(requirements.as_str())
    {
        eprintln!("Python environment {}: present", env.display());
        return Some(python);
    }
    eprintln!(
        "Python environment {}: installing {PYTHON_REQUIREMENTS}",
        env.display()
    );
    let made = if runs(python.to_str()?) {
        Ok(())
    } else {
        run_shown("python3", &["-m", "venv", env.to_str()?], &[])
    }
    .and_then(|()| {
        let requirements_path = root.join(PYTHON_REQUIREMENTS);
        run_shown(
            python.to_str().unwrap_or("python"),
            &[
                "-m",
                "pip",
                "install",
                "--quiet",
                "-r",
                requirements_path.to_str().unwrap_or_default(),
            ],
            &[],
        )
    })
    .and_then(|()| std::fs::write(&stamp, &requirements).map_err(|e| e.to_string()));
    match made {
        Ok(()) => Some(python),
        Err(reason) => {
            missing.push(Missing {
                what: format!(
                    "Python environment {} with {PYTHON_REQUIREMENTS}",
                    env.display()
                ),
                reason,
                needed_by: needed_by.into(),
            });
            None
        }
    }
}

/// Checks and installs everything; with `strict`, fails when something is still missing.
pub fn run(root: &Path, strict: bool) -> Result<Setup> {
    let mut missing = Vec::new();
    debian(&mut missing);
    rust_target(&mut missing);
    let python = python(root, &mut missing);
    report_missing(&missing);
    if strict && !missing.is_empty() {
        bail!("{} prerequisite(s) missing", missing.len());
    }
    Ok(Setup { python, missing })
}

/// Prints what is missing and what it keeps from running.
pub fn report_missing(missing: &[Missing]) {
    for m in missing {
        eprintln!(
            "MISSING {}: {}\n  cannot run: {}",
            m.what, m.reason, m.needed_by
        );
    }
}
