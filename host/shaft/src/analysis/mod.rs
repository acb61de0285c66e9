//! The analyses of an assembled rotor: static equilibrium on the (nonlinear) bearings, modes at
//! an operating point and the Campbell diagram, Craig–Bampton reduction, the time response
//! (implicit Newmark / HHT-α integrator with Newton on the bearing forces), speed sweeps and the
//! amplitude spectrum of a recorded signal.

pub mod integrator;
pub mod modes;
pub mod operating;
pub mod reduction;
pub mod simulate;
pub mod spectrum;
pub mod statics;
pub mod sweep;
pub mod system;
