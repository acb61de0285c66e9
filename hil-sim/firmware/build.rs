//! Link setup for cortex-m-rt: put the memory layout where the linker finds it — the
//! workspace's top-level `memory.x` (STM32F405 layout, also QEMU's netduinoplus2), or with the
//! feature `mps2-an500` / `mps2-an505` that of QEMU's MPS2 board — and pass cortex-m-rt's and
//! defmt's scripts.

use std::path::PathBuf;

/// QEMU's `mps2-an500` (Cortex-M7): SSRAM1 at 0 for the code, SSRAM2/3 at 0x2000_0000 for
/// the data (QEMU `hw/arm/mps2.c`, the AN500 application note's memory map), of which as much
/// as the STM32F405 has is used: the stack painting scans all of it.
const MPS2_AN500: &str = "MEMORY
{
  FLASH : ORIGIN = 0x00000000, LENGTH = 1024K
  RAM   : ORIGIN = 0x20000000, LENGTH = 128K
}
";

/// QEMU's `mps2-an505` (Cortex-M33, started in the secure state): the secure aliases of SSRAM1
/// (code; the secure vector table is at 0x1000_0000) and of SSRAM2 (data; at 0x2800_0000,
/// aliased at 0x3800_0000) (QEMU `hw/arm/mps2-tz.c`, AN505), as much as the STM32F405 has.
const MPS2_AN505: &str = "MEMORY
{
  FLASH : ORIGIN = 0x10000000, LENGTH = 1024K
  RAM   : ORIGIN = 0x38000000, LENGTH = 128K
}
";

fn main() {
    let out = PathBuf::from(std::env::var_os("OUT_DIR").expect("cargo sets OUT_DIR"));
    let memory = PathBuf::from(
        std::env::var_os("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR"),
    )
    .join("../../memory.x");
    let board = if std::env::var_os("CARGO_FEATURE_MPS2_AN500").is_some() {
        Some(MPS2_AN500)
    } else if std::env::var_os("CARGO_FEATURE_MPS2_AN505").is_some() {
        Some(MPS2_AN505)
    } else {
        None
    };
    match board {
        Some(layout) => std::fs::write(out.join("memory.x"), layout).expect("write memory.x"),
        None => {
            std::fs::copy(&memory, out.join("memory.x")).expect("copy the top-level memory.x");
        }
    }
    println!("cargo:rustc-link-search={}", out.display());
    println!("cargo:rerun-if-changed={}", memory.display());
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rustc-link-arg=--nmagic");
    println!("cargo:rustc-link-arg=-Tlink.x");
    println!("cargo:rustc-link-arg=-Tdefmt.x");
}
