//! Wiring: which bearing model, dry model and accuracy reference the `replay` command drives.
//!
//! This is the one place where the harness meets the product: the core's bearing step (through
//! the shared kernel the firmware runs too) as the [`BearingStepper`], the same step with the
//! dry film as the dry model, and the host's numerical EHL solver as the
//! [`AccuracyReference`]. Until those exist, [`product`] says what is missing instead of
//! replaying a stand-in.

use crate::replay::{AccuracyReference, BearingStepper, FilmChoice};
use crate::trace::TraceMeta;
use std::path::PathBuf;

/// The bundled hub-motor run-up trace (recorded by the shaft simulator), the default of
/// `hil-sim replay` and `hil-sim qemu`.
pub fn default_trace() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("traces/hub_motor_runup.bin")
}

/// The models a replay drives.
pub struct Product {
    /// The real-time bearing step with the chosen film model.
    pub stepper: Box<dyn BearingStepper>,
    /// The same step with the dry model (h ≡ 0).
    pub dry: Option<Box<dyn BearingStepper>>,
    /// The full numerical solver at the same bearing state.
    pub reference: Option<Box<dyn AccuracyReference>>,
}

/// Builds the product's models for the trace's bearing and lubricant.
pub fn product(meta: &TraceMeta, film: FilmChoice) -> Result<Product, String> {
    Err(format!(
        "no bearing model is wired for bearing '{}', lubricant '{}', film '{}': the core's \
         bearing step (bearing_core::bearing::Bearing::step) is not on this branch yet",
        meta.bearing,
        meta.lubricant,
        film.name()
    ))
}
