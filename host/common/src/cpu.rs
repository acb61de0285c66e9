//! What the build assumes of the processor.
//!
//! The workspace's `.cargo/config.toml` compiles x86-64 Linux builds with AVX2, for the core's
//! eight-lane bearing step (README, "Host build: AVX2 lanes"). On a processor without it such a
//! binary would stop on an illegal instruction somewhere in its first bearing step; the
//! binaries call [`check`] first and say what to do instead.
//!
//! `is_x86_feature_detected!` cannot tell: in a build with the feature enabled it is `true` at
//! compile time. The kernel's view is asked instead: `/proc/cpuinfo` lists `avx2` among a
//! processor's flags only when the processor has it and the kernel saves its registers.

/// `Err`, naming the remedy, when this build relies on a processor feature the machine lacks.
pub fn check() -> Result<(), String> {
    #[cfg(all(target_arch = "x86_64", target_feature = "avx2", target_os = "linux"))]
    if let Ok(cpuinfo) = std::fs::read_to_string("/proc/cpuinfo") {
        if !lists_flag(&cpuinfo, "avx2") {
            return Err(
                "this build assumes AVX2 (.cargo/config.toml), which this processor lacks; \
                 rebuild with RUSTFLAGS=\"-C target-feature=-avx2\" (README, \"Host build: \
                 AVX2 lanes\")"
                    .into(),
            );
        }
    }
    Ok(())
}

/// Whether the first processor's `flags` line of a `/proc/cpuinfo` text names `flag`.
pub fn lists_flag(cpuinfo: &str, flag: &str) -> bool {
    cpuinfo
        .lines()
        .find(|line| line.starts_with("flags"))
        .and_then(|line| line.split_once(':'))
        .is_some_and(|(_, flags)| flags.split_whitespace().any(|f| f == flag))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Reference: the `flags` line format of Linux's `/proc/cpuinfo` on x86 (`flags\t\t: fpu …`),
    /// with a processor that has AVX but not AVX2 (Sandy Bridge) and one that has both.
    #[test]
    fn finds_whole_flags_only() {
        let sandy = "processor\t: 0\nmodel name\t: Intel(R) Core(TM) i7-2600\nflags\t\t: fpu sse2 avx xsave\n";
        assert!(lists_flag(sandy, "avx"));
        assert!(!lists_flag(sandy, "avx2"));
        let zen = "processor\t: 0\nflags\t\t: fpu avx avx2 fma\nbugs\t\t: sysret_ss_attrs\n";
        assert!(lists_flag(zen, "avx2"));
        assert!(!lists_flag("processor\t: 0\n", "avx2"));
        // This machine runs this very test binary, built with the workspace's flags.
        assert!(check().is_ok());
    }
}
