//! Lubricated cylindrical roller bearing model for real-time loops.
//!
//! `bearing-core` computes, every time step and in a fixed amount of work, the elasto-
//! hydrodynamic (EHL) film of every roller, the film-coupled roller loads by slicing, and the
//! bearing's forces, moments, stiffness and damping. It is `#![no_std]`, never allocates
//! (the caller owns every buffer; sizes are const generics), never panics, and uses f32 so it
//! runs on a Cortex-M4F with the same numbers as on a PC.
//!
//! The pipeline of one step (see [`bearing::Bearing::step`]):
//!
//! 1. **kinematics** — roller angles from the cage angle, entrainment speed ([`kinematics`]);
//! 2. **geometry** — each roller's approach from the inner-race displacement and tilt;
//! 3. **film** — central film at the inner and outer contact from a [`film::FilmModel`]
//!    (regression formulas, the neural networks, Martin's hydrodynamic film at separation);
//! 4. **contact** — slice loads and the roller load, solved together with the film, which adds
//!    to the approach ([`contact`], PHYSICS.md §3–§4);
//! 5. **bearing** — forces, moments, stiffness and damping matrices summed over the rollers.
//!
//! Equations and conventions: `shared/design/PHYSICS.md` (sections cited in each module).
#![no_std]
#![deny(missing_docs)]

#[cfg(test)]
extern crate std;

pub mod bearing;
pub mod contact;
mod error;
pub mod film;
pub mod kinematics;
mod lanes;
pub mod math;
pub mod params;

pub use bearing::{Bearing, BearingOutput, BearingParams, RollerOutput, StepStatus};
pub use contact::ContactLaw;
pub use error::{Allowed, ParamError};
pub use film::{ContactInput, Film, FilmModel, FilmSource, Regime, Regression};
pub use params::{BearingGeometry, Crown, Lubricant, Material, OperatingState};
