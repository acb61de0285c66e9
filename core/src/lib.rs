//! Lubricated cylindrical roller bearing model for real-time loops.
//!
//! `bearing-core` computes, every time step and in a fixed amount of work, the elasto-
//! hydrodynamic (EHL) film of every roller, the film-coupled roller loads by slicing, and the
//! bearing's forces, moments, stiffness and damping. It is `#![no_std]`, never allocates
//! (sizes are const generics), never panics, and uses f32 so it runs on a Cortex-M4F with the
//! same numbers as on a PC.
//!
//! ```
//! use bearing_core::bearing::SETTLE_STEPS;
//! use bearing_core::{Bearing, BearingDesign, FilmKind, OperatingState};
//!
//! // The hub-motor bearing of `configs/hub_motor.toml`, with the integer film network.
//! let params = BearingDesign::HUB_MOTOR.params()?;
//! let mut bearing = Bearing::<17, 10>::new(params, FilmKind::Int)?;
//! // The inner race whirls on a 6 µm circle at the shaft speed (21 000 rpm), sampled at 10 kHz.
//! let (omega, radius, dt) = (2199.0_f32, 6.0e-6_f32, 1.0e-4_f32);
//! let at = |t: f32| {
//!     let (s, c) = (omega * t).sin_cos();
//!     OperatingState::new([radius * c, radius * s], [-radius * omega * s, radius * omega * c], [0.0; 2], omega)
//! };
//! bearing.settle(&at(0.0)?, SETTLE_STEPS)?;
//! for k in 1..=5 {
//!     let out = bearing.advance(&at(k as f32 * dt)?, dt)?;
//!     let loaded = out.rollers.iter().max_by(|a, b| a.load_n.total_cmp(&b.load_n)).unwrap();
//!     println!(
//!         "F = {:?} N, k_xx = {:.3e} N/m, film in/out {:.3}/{:.3} µm",
//!         out.force_n, out.stiffness[0][0],
//!         loaded.central_film_in_m * 1e6, loaded.central_film_out_m * 1e6,
//!     );
//!     assert!(out.force_n[0] * out.force_n[0] + out.force_n[1] * out.force_n[1] > 0.0);
//! }
//! # Ok::<(), bearing_core::ParamError>(())
//! ```
//!
//! A bearing is built once, by name: a [`BearingDesign`] (every field with its unit, or one of
//! the presets [`BearingDesign::HUB_MOTOR`], [`BearingDesign::NU205`]) validated by
//! [`BearingDesign::params`], and the film model as a [`FilmKind`]. Then, per time step,
//! [`Bearing::advance`] (real time: integrates the cage angle, carries the warm start) or
//! [`Bearing::evaluate`] (a trial for implicit integrators, which commits nothing). A refused
//! input is an `Err(`[`ParamError`]`)` naming the field and its allowed range.
//! [`DynBearing`] is the same bearing with the roller count chosen at run time.
//!
//! The pipeline of one step:
//!
//! 1. **kinematics** — roller angles from the cage angle, entrainment speed ([`kinematics`]);
//! 2. **geometry** — each roller's approach from the inner-race displacement and tilt;
//! 3. **film** — central film at the inner and outer contact from the film model
//!    (regression formulas, the neural networks, Martin's hydrodynamic film at separation);
//! 4. **contact** — slice loads and the roller load, solved together with the film, which adds
//!    to the approach ([`contact`], docs/physics.md §3–§4);
//! 5. **bearing** — forces, moments, stiffness and damping matrices summed over the rollers;
//! 6. **friction** — film ratio λ, asperity load, rolling, viscous and boundary friction of
//!    every contact, and the bearing's friction torque and power loss ([`friction`]).
//!
//! Equations and conventions: `docs/physics.md` (sections cited in each module).
#![no_std]
#![deny(missing_docs)]

#[cfg(feature = "alloc")]
extern crate alloc;
#[cfg(test)]
extern crate std;

pub mod bearing;
pub mod contact;
mod error;
pub mod film;
pub mod friction;
pub mod kinematics;
mod lanes;
// Public only for the firmware's profile of their cost (`hil-sim/firmware`); not part of the API.
#[doc(hidden)]
pub mod math;
pub mod params;

pub use bearing::{
    Bearing, BearingDesign, BearingOutput, BearingParams, DynBearing, FilmKind, OutputView,
    RollerOutput, RollerTotals,
};
pub use contact::ContactLaw;
pub use error::{Allowed, ParamError};
pub use film::{ContactInput, Film, FilmModel, FilmSource, Regime, Regression};
pub use friction::{FrictionDesign, FrictionParams, Lubrication};
pub use params::{BearingGeometry, Crown, Lubricant, Material, OperatingState};
