//! Validated parameters: solids, lubricant, bearing geometry and the operating state.
//!
//! Each type can only be built through a constructor that checks every field and returns a
//! [`ParamError`](crate::ParamError) naming the field, the value and the allowed range, so the
//! rest of the core can rely on finite, physically meaningful numbers without checking again.

mod geometry;
mod lubricant;
mod material;
mod operating;

pub use geometry::{BearingGeometry, Crown};
pub use lubricant::Lubricant;
pub use material::{reduced_modulus, Material};
pub use operating::{OperatingState, MAX_SHAFT_SPEED_RAD_S, MAX_TIME_STEP_S};
pub(crate) use operating::{MAX_CAGE_ANGLE_RAD, MAX_TILT_RAD};
