//! Bearings: what every bearing kind shares, and one folder per kind.
//!
//! Shared here: the film model a bearing steps with ([`FilmKind`]), the cage angle's
//! integration (`cage`), and the object-safe interface [`DynBearing`] that host tools, the C
//! library and the FMU call without knowing the kind or the element count (with the `alloc`
//! feature, [`boxed`] builds one from parameters). Each kind lives in a folder of its own:
//!
//! - [`ball`]: the ball bearing, deep-groove or angular-contact, in five degrees of freedom;
//! - [`roller`]: the cylindrical roller bearing ([`Bearing`]), its design and parameters
//!   ([`BearingDesign`], [`BearingParams`]), outputs ([`BearingOutput`], [`RollerOutput`]) and
//!   static solve ([`Equilibrium`]).
//!
//! The roller bearing's items are re-exported here, at the paths they had before the kinds
//! were split into folders.

pub mod ball;
mod cage;
mod dynamic;
mod film_kind;
pub mod roller;

pub use dynamic::DynBearing;
#[cfg(feature = "alloc")]
pub use dynamic::{boxed, MAX_ROLLERS, MIN_ROLLERS, SLICES};
pub use film_kind::{FilmKind, UnknownFilmKind};
pub use roller::{
    Bearing, BearingDesign, BearingOutput, BearingParams, Equilibrium, OutputView, RollerOutput,
    RollerTotals, SETTLE_STEPS, STEEL_DENSITY_KG_M3,
};
