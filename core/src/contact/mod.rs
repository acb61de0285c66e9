//! Roller–race line contact: Hertz figures, the load–approach law and slicing.
//!
//! A roller is cut into slices along its length; each slice carries a line-contact load that
//! depends on its own approach, which includes the roller's tilt and crown (docs/physics.md §3).

mod hertz;
mod law;
mod slicing;

pub use hertz::HertzLineContact;
pub use law::{ContactLaw, PALMGREN_K};
pub(crate) use slicing::RollerLoads;
pub use slicing::{RollerLoad, SlicedRoller};
