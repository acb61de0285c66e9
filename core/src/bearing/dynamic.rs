//! The bearing with its roller count chosen at run time.
//!
//! [`Bearing<Z, S>`](super::Bearing) sizes its arrays by const generics, as the firmware
//! needs: no heap, and the compiler unrolls and vectorises the roller loops for the exact
//! count. A host tool reads the roller count from a file, so [`DynBearing`] is the same bearing
//! behind an object-safe trait (its output as an [`OutputView`], rollers as a slice), and, with
//! the `alloc` feature, [`boxed`] builds one for any count in [`MIN_ROLLERS`] … [`MAX_ROLLERS`]
//! at [`SLICES`] slices.
//!
//! Why a trait object over the const-generic type rather than a bearing over caller-owned
//! storage (smoltcp-style slices): every `Bearing<Z, S>` behind the trait is the same
//! monomorphised step the firmware runs, so the host loses nothing of the lane code's speed
//! (one virtual call per step, against ≈ 1 µs of work) and the M4 keeps its instruction count;
//! a run-time-sized step would loop over a run-time count in both, and its results would have
//! to be proved bit-identical to the firmware's again. The price is code size on the host:
//! one step per supported count and film model, instantiated here once for every host crate.

use super::{Bearing, BearingOutput, BearingParams, Equilibrium, FilmKind, OutputView};
use crate::error::ParamError;
use crate::params::OperatingState;

/// A [`Bearing`] of any roller count, behind an object-safe trait. Each method is the
/// [`Bearing`] method of the same name.
pub trait DynBearing {
    /// Number of rollers Z.
    fn roller_count(&self) -> usize;
    /// [`Bearing::params`].
    fn params(&self) -> &BearingParams;
    /// [`Bearing::film`].
    fn film(&self) -> FilmKind;
    /// [`Bearing::output`].
    fn output(&self) -> OutputView<'_>;
    /// [`Bearing::cage_angle_rad`].
    fn cage_angle_rad(&self) -> f32;
    /// [`Bearing::set_cage_angle`].
    fn set_cage_angle(&mut self, cage_angle_rad: f32) -> Result<(), ParamError>;
    /// [`Bearing::advance`].
    fn advance(&mut self, state: &OperatingState, dt_s: f32) -> Result<OutputView<'_>, ParamError>;
    /// [`Bearing::evaluate`].
    fn evaluate(&mut self, state: &OperatingState, dt_s: f32)
        -> Result<OutputView<'_>, ParamError>;
    /// [`Bearing::settle`].
    fn settle(
        &mut self,
        state: &OperatingState,
        steps: usize,
    ) -> Result<OutputView<'_>, ParamError>;
    /// [`Bearing::static_equilibrium`].
    fn static_equilibrium(
        &mut self,
        applied_force_n: [f32; 2],
        state: &OperatingState,
        relative_tolerance: f32,
        max_iterations: usize,
    ) -> Equilibrium;
    /// [`Bearing::friction`].
    fn friction(&mut self, shaft_speed_rad_s: f32) -> Result<OutputView<'_>, ParamError>;
    /// [`Bearing::reset`].
    fn reset(&mut self);
    /// A boxed copy, same committed state.
    #[cfg(feature = "alloc")]
    fn boxed_clone(&self) -> alloc::boxed::Box<dyn DynBearing + Send>;
}

impl<const Z: usize, const S: usize> DynBearing for Bearing<Z, S> {
    fn roller_count(&self) -> usize {
        Z
    }
    fn params(&self) -> &BearingParams {
        Bearing::params(self)
    }
    fn film(&self) -> FilmKind {
        Bearing::film(self)
    }
    fn output(&self) -> OutputView<'_> {
        Bearing::output(self).view()
    }
    fn cage_angle_rad(&self) -> f32 {
        Bearing::cage_angle_rad(self)
    }
    fn set_cage_angle(&mut self, cage_angle_rad: f32) -> Result<(), ParamError> {
        Bearing::set_cage_angle(self, cage_angle_rad)
    }
    fn advance(&mut self, state: &OperatingState, dt_s: f32) -> Result<OutputView<'_>, ParamError> {
        Bearing::advance(self, state, dt_s).map(BearingOutput::view)
    }
    fn evaluate(
        &mut self,
        state: &OperatingState,
        dt_s: f32,
    ) -> Result<OutputView<'_>, ParamError> {
        Bearing::evaluate(self, state, dt_s).map(BearingOutput::view)
    }
    fn settle(
        &mut self,
        state: &OperatingState,
        steps: usize,
    ) -> Result<OutputView<'_>, ParamError> {
        Bearing::settle(self, state, steps).map(BearingOutput::view)
    }
    fn static_equilibrium(
        &mut self,
        applied_force_n: [f32; 2],
        state: &OperatingState,
        relative_tolerance: f32,
        max_iterations: usize,
    ) -> Equilibrium {
        Bearing::static_equilibrium(
            self,
            applied_force_n,
            state,
            relative_tolerance,
            max_iterations,
        )
    }
    fn friction(&mut self, shaft_speed_rad_s: f32) -> Result<OutputView<'_>, ParamError> {
        Bearing::friction(self, shaft_speed_rad_s).map(|o| o.view())
    }
    fn reset(&mut self) {
        Bearing::reset(self)
    }
    #[cfg(feature = "alloc")]
    fn boxed_clone(&self) -> alloc::boxed::Box<dyn DynBearing + Send> {
        alloc::boxed::Box::new(self.clone())
    }
}

/// Slices per roller of the bearings [`boxed`] builds (the core's test of slice-count
/// independence covers the choice).
#[cfg(feature = "alloc")]
pub const SLICES: usize = 10;
/// Smallest roller count [`boxed`] builds.
#[cfg(feature = "alloc")]
pub const MIN_ROLLERS: u16 = 6;
/// Largest roller count [`boxed`] builds.
#[cfg(feature = "alloc")]
pub const MAX_ROLLERS: u16 = 40;

/// The bearing of `params` with the film model `film`, at the roller count of its geometry
/// ([`MIN_ROLLERS`] … [`MAX_ROLLERS`]) and [`SLICES`] slices per roller.
///
/// ```
/// use bearing_core::bearing::boxed;
/// use bearing_core::{BearingDesign, FilmKind, OperatingState};
///
/// let design = BearingDesign { roller_count: 14, ..BearingDesign::NU205 };
/// let mut bearing = boxed(design.params()?, FilmKind::Regression)?;
/// let state = OperatingState::new([0.0, -4.0e-6], [0.0; 2], [0.0; 2], 1000.0)?;
/// let out = bearing.settle(&state, 6)?;
/// assert_eq!(out.rollers.len(), 14);
/// # Ok::<(), bearing_core::ParamError>(())
/// ```
#[cfg(feature = "alloc")]
pub fn boxed(
    params: BearingParams,
    film: FilmKind,
) -> Result<alloc::boxed::Box<dyn DynBearing + Send>, ParamError> {
    use alloc::boxed::Box;
    macro_rules! counts {
        ($($z:literal)*) => {
            match params.geometry().roller_count() {
                $($z => Ok(Box::new(Bearing::<$z, SLICES>::new(params, film)?)),)*
                other => Err(ParamError {
                    field: "roller_count",
                    value: f32::from(other),
                    allowed: crate::error::Allowed::Range {
                        min: f32::from(MIN_ROLLERS),
                        max: f32::from(MAX_ROLLERS),
                    },
                }),
            }
        };
    }
    counts!(6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29 30 31 32 33 34 35 36 37 38 39 40)
}
