//! Flexible-shaft rotor-dynamics simulator: a Timoshenko finite-element rotor with rigid disks,
//! material damping, bearings (linear or the core's nonlinear roller bearing) and loads (static,
//! gravity, unbalance, gear mesh driven by a PMSM), with the analyses static equilibrium, modes,
//! Campbell diagram, time response (implicit Newmark / HHT-α with Newton on the bearing forces)
//! and speed sweeps.
//!
//! Reference text: Friswell, Penny, Garvey & Lees, *Dynamics of Rotating Machines*, Cambridge
//! University Press (2010), ch. 5 (finite-element rotor models).

pub mod bearing;
pub mod config;
pub mod core_bearing;
pub mod damping;
pub mod disk;
pub mod element;
pub mod integrator;
pub mod loads;
pub mod model;
pub mod modes;
pub mod motor;
pub mod operating;
pub mod output;
pub mod plots;
pub mod reduction;
pub mod roller_bearing;
pub mod simulate;
pub mod spectrum;
pub mod speed_profile;
pub mod statics;
pub mod sweep;
pub mod system;

#[cfg(test)]
mod tests;
