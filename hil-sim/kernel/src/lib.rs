//! The part of the HIL harness that runs on both sides, `no_std`: the step kernel, its outputs
//! and their file layout, the binary trace wire format and its checksum. The host harness
//! (`bearing-hil`) and the Cortex-M4F firmware (`hil-sim/firmware`) both depend on this crate,
//! so the two replay the same code.

#![cfg_attr(not(test), no_std)]

pub mod crc32;
pub mod kernel;
pub mod outputs;
pub mod wire;
