//! What the build assumes of the processor.
//!
//! The workspace's `.cargo/config.toml` compiles x86-64 Linux builds with AVX2, for the core's
//! eight-lane bearing step (README, "Host build: AVX2 lanes"). On a processor without it such a
//! binary would stop on an illegal instruction somewhere in its first bearing step; the
//! binaries call [`check`] first and say what to do instead.

/// `Err`, naming the remedy, when this build relies on a processor feature the machine lacks.
pub fn check() -> Result<(), String> {
    #[cfg(all(target_arch = "x86_64", target_feature = "avx2"))]
    if !std::arch::is_x86_feature_detected!("avx2") {
        return Err(
            "this build assumes AVX2 (.cargo/config.toml), which this processor lacks; \
                    rebuild with RUSTFLAGS=\"-C target-feature=-avx2\" (README, \"Host build: \
                    AVX2 lanes\")"
                .into(),
        );
    }
    Ok(())
}
