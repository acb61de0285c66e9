//! The tools the emulated replay needs — the `thumbv7em-none-eabihf` Rust target and
//! `qemu-system-arm` — with a message saying how to install each one that is missing, and the
//! firmware build.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The Cortex-M4F target.
pub const TARGET: &str = "thumbv7em-none-eabihf";

/// Directory of the firmware crate.
pub fn firmware_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("firmware")
}

/// `Ok` when `qemu-system-arm` runs; otherwise how to install it.
pub fn check_qemu() -> Result<(), String> {
    match Command::new("qemu-system-arm").arg("--version").output() {
        Ok(out) if out.status.success() => Ok(()),
        _ => Err(
            "qemu-system-arm is not installed or does not run; install it with \
                  `sudo apt-get update && sudo apt-get install -y qemu-system-arm` \
                  (Debian/Ubuntu; `cargo xtask setup` does this)"
                .to_string(),
        ),
    }
}

/// `Ok` when the Rust standard library for the target is installed; otherwise how to add it.
pub fn check_target() -> Result<(), String> {
    let missing = || {
        format!(
            "the Rust target {TARGET} is not installed; add it with `rustup target add {TARGET}` \
             (`cargo xtask setup` does this)"
        )
    };
    let out = Command::new("rustc")
        .args(["--print", "sysroot"])
        .output()
        .map_err(|e| format!("cannot run rustc: {e}"))?;
    let sysroot = String::from_utf8_lossy(&out.stdout).trim().to_string();
    let lib = Path::new(&sysroot)
        .join("lib/rustlib")
        .join(TARGET)
        .join("lib");
    let has_files = std::fs::read_dir(&lib).is_ok_and(|mut entries| entries.next().is_some());
    if has_files {
        Ok(())
    } else {
        Err(missing())
    }
}

/// Builds the firmware in release mode and returns the path of its ELF.
pub fn build_firmware(dir: &Path) -> Result<PathBuf, String> {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let out = Command::new(cargo)
        .current_dir(dir)
        .args([
            "build",
            "--release",
            "--target",
            TARGET,
            "--message-format=json-render-diagnostics",
        ])
        // Settings of an enclosing cargo invocation (e.g. `cargo test` of the host workspace)
        // must not leak into the firmware's own workspace.
        .env_remove("CARGO_TARGET_DIR")
        .env_remove("RUSTFLAGS")
        .env_remove("CARGO_ENCODED_RUSTFLAGS")
        .env_remove("CARGO_BUILD_TARGET")
        .output()
        .map_err(|e| format!("cannot run cargo for the firmware: {e}"))?;
    if !out.status.success() {
        return Err(format!(
            "building the firmware in {} failed:\n{}",
            dir.display(),
            String::from_utf8_lossy(&out.stderr)
        ));
    }
    // The last compiler-artifact message with an executable is the firmware.
    let stdout = String::from_utf8_lossy(&out.stdout);
    stdout
        .lines()
        .filter_map(|line| serde_json::from_str::<serde_json::Value>(line).ok())
        .filter_map(|msg| msg.get("executable")?.as_str().map(PathBuf::from))
        .next_back()
        .ok_or_else(|| "cargo built the firmware but reported no executable".to_string())
}
