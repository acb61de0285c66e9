//! Hardware-in-the-loop harness: replays recorded bearing kinematics (traces) through the
//! bearing model on the host and on an emulated Cortex-M4, and checks the timing budget and the
//! accuracy against the full numerical solver.
//!
//! `outputs`, `kernel`, `trace::wire` and `trace::crc32` use nothing from `std`: the firmware
//! (`hil-sim/firmware`) includes those files with `#[path]` at its crate root, which is why
//! `wire` and `crc32` are also re-exported here at the root (the shared files name each other
//! through `super::`).

pub mod kernel;
pub mod outputs;
pub mod qemu;
pub mod realtime;
pub mod reference;
pub mod replay;
pub mod trace;
pub mod wiring;

pub use trace::{crc32, wire};
