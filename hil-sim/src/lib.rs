//! Hardware-in-the-loop harness: replays recorded bearing kinematics (traces) through the
//! bearing model on the host and on an emulated Cortex-M4, and checks the timing budget and the
//! accuracy against the full numerical solver.
//!
//! `kernel`, `outputs`, `trace::wire` and `trace::crc32` are the `no_std` crate
//! `bearing-hil-kernel`, which the firmware (`hil-sim/firmware`) runs too; they are re-exported
//! here under their module names. `trace` (the trace formats and their validation) is the crate
//! `bearing-trace`, which the fuzz targets build without the rest of the harness.

pub use bearing_hil_kernel::{kernel, outputs};
pub mod qemu;
pub mod realtime;
pub mod reference;
pub mod replay;
pub use bearing_trace as trace;
pub mod wiring;

pub use trace::{crc32, wire};
