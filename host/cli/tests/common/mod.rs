//! What the CLI tests share: running the `bearing` binary and finding the bundled configs.

use std::path::PathBuf;
use std::process::Command;

/// Run `bearing` with `args` in the temporary directory (so that files a command writes by
/// default land there, not in the checkout): (success, stdout, stderr).
pub fn bearing(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_bearing"))
        .args(args)
        .current_dir(std::env::temp_dir())
        .output()
        .expect("run bearing");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Absolute path of `configs/<name>`.
pub fn config(name: &str) -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../configs")
        .join(name)
        .display()
        .to_string()
}
