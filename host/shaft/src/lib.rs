//! Flexible-shaft rotor-dynamics simulator: a Timoshenko finite-element rotor with rigid disks,
//! material damping, bearings (linear or the core's nonlinear roller bearing) and loads (static,
//! gravity, unbalance, gear mesh driven by a PMSM), with the analyses static equilibrium, modes,
//! Campbell diagram, time response (implicit Newmark / HHT-α with Newton on the bearing forces)
//! and speed sweeps.
//!
//! Reference text: Friswell, Penny, Garvey & Lees, *Dynamics of Rotating Machines*, Cambridge
//! University Press (2010), ch. 5 (finite-element rotor models).

//! Layout: [`bearing`] (the bearing interface, the linear bearing and the adapter to the core's
//! roller bearing), [`model`] (shaft elements, disks, damping, motor, loads, speed profile, the
//! model file and the assembled rotor), [`analysis`] (statics, modes, reduction, time response,
//! sweeps, spectrum), and the outputs ([`output`] CSV, [`plots`] PNG).

pub mod analysis;
pub mod bearing;
pub mod model;
pub mod output;
pub mod plots;

// The paths other crates (CLI, benches, workspace tests, fuzz) use, kept at the crate root.
pub use analysis::{integrator, operating, reduction, simulate, spectrum, statics, sweep, system};
pub use bearing::roller_bearing;
pub use model::{config, element, loads};

#[cfg(test)]
mod tests;
