//! Replay: step a bearing model once per trace sample, time every step, and compare a subset of
//! steps with the full numerical solver.
//!
//! The harness does not know the bearing model: it talks to a [`BearingStepper`] (the real-time
//! model, e.g. the core's bearing step with one film model) and optionally to an
//! [`AccuracyReference`] (the same bearing state recomputed with the numerical EHL solver in
//! every loaded contact, f64) and a second stepper running the dry model (h ≡ 0), whose error
//! against the reference shows what the film buys (docs/physics.md §4). `crate::wiring` builds the
//! product's stepper and reference; tests use closed-form doubles.
//!
//! [`engine`] runs the timed loop (free-running or paced at wall-clock rate), then [`pauses`]
//! measures how often the machine pauses that CPU, and then, outside the timed loop so that it
//! cannot disturb the timings, the accuracy pass. [`stats`] turns the
//! timings and errors into the distribution and the verdicts; [`report`] and [`plots`] write
//! them out.

pub mod engine;
pub mod pauses;
pub mod plots;
pub mod report;
pub mod stats;

#[cfg(test)]
mod tests;

pub use crate::outputs::{FilmSource, StepOutputs, MAX_ROLLERS};
pub use engine::{replay, ReplayConfig, ReplayRun};

use crate::trace::Sample;
use std::fmt;

/// The film model the stepper uses (`--film`): the core's choice, by name.
pub use bearing_core::FilmKind;

/// The parser of a `--film` argument: one of the names of [`FilmKind`], listed in `--help`.
pub fn film_arg() -> impl clap::builder::TypedValueParser<Value = FilmKind> {
    use clap::builder::TypedValueParser as _;
    clap::builder::PossibleValuesParser::new(FilmKind::ALL.map(FilmKind::name))
        .try_map(|name| name.parse::<FilmKind>())
}

/// Why a step or a reference computation failed.
#[derive(Clone, Debug, PartialEq)]
pub struct StepFault {
    /// What went wrong, for the user.
    pub reason: String,
}

impl fmt::Display for StepFault {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.reason)
    }
}

impl std::error::Error for StepFault {}

/// A real-time bearing model stepped once per sample.
pub trait BearingStepper {
    /// Short name for reports, e.g. `"core/int"`.
    fn name(&self) -> String;
    /// Advances the model to `sample` and writes its outputs into `out` (every field the
    /// stepper knows, `out.rollers` included). This call is what the replay times.
    fn step(&mut self, sample: &Sample, out: &mut StepOutputs) -> Result<(), StepFault>;
    /// Adds the friction of the step just taken to `out` (torque, power loss and its split),
    /// at `sample`'s shaft speed; the replay times it apart from the step. A model without
    /// friction leaves those fields as they are.
    fn friction(&mut self, _sample: &Sample, _out: &mut StepOutputs) -> Result<(), StepFault> {
        Ok(())
    }
}

/// The accuracy reference at one sample (f64).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct ReferenceOutputs {
    /// Bearing force (F_x, F_y) (N).
    pub force_n: [f64; 2],
    /// Roller loads Q_j (N), one per roller.
    pub roller_load_n: Vec<f64>,
    /// Central film at the inner contact, one per roller (m).
    pub film_inner_m: Vec<f64>,
    /// Central film at the outer contact, one per roller (m).
    pub film_outer_m: Vec<f64>,
}

/// Recomputes a sample's bearing state with the full numerical solver (converged film–load
/// coupling in every loaded contact, f64). Called every K-th sample, outside the timed loop.
pub trait AccuracyReference {
    /// Short name for reports.
    fn name(&self) -> String;
    /// The reference state at `sample`, with the rollers where the stepper had them
    /// (`stepped.cage_angle_rad`, `stepped.rollers`).
    fn reference(
        &mut self,
        sample: &Sample,
        stepped: &StepOutputs,
    ) -> Result<ReferenceOutputs, StepFault>;
}
