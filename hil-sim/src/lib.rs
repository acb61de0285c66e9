//! Hardware-in-the-loop harness: replays recorded bearing kinematics (traces) through the
//! bearing model on the host and on an emulated Cortex-M4, and checks the timing budget and the
//! accuracy against the full numerical solver.

pub mod replay;
pub mod trace;
pub mod wiring;
