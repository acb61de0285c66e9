//! Speed sweep (PHYSICS.md §6.2): at each speed, run to steady state with the lubricated
//! bearings and again with dry ones, and keep the envelopes. Speeds run in parallel (rayon) with
//! a progress bar; each run owns fresh bearing models.

use rayon::prelude::*;

use super::bearing::{BearingSpec, FilmChoice};
use super::model::RotorModel;
use super::simulate::{run, Envelope, RunError, RunSettings};

/// The sweep speeds of PHYSICS.md §6.2: 1000 → 21 000 rpm every 1000 rpm, plus every 250 rpm
/// from 12 000 to 14 000 rpm.
pub fn hub_motor_speeds_rpm() -> Vec<f64> {
    let mut v: Vec<f64> = (1..=21).map(|k| 1000.0 * k as f64).collect();
    v.extend((0..=8).map(|k| 12_000.0 + 250.0 * k as f64));
    v.sort_by(f64::total_cmp);
    v.dedup();
    v
}

/// How the run settings depend on speed (step, settling and record length).
pub type SettingsAt<'a> = dyn Fn(f64) -> RunSettings + Sync + 'a;

/// One speed of the sweep.
#[derive(Debug, Clone)]
pub struct SweepPoint {
    /// Speed (rpm).
    pub speed_rpm: f64,
    /// Envelopes with the lubricated bearings.
    pub lubricated: Envelope,
    /// Envelopes with dry bearings.
    pub dry: Envelope,
    /// Steadiness measure of the two runs (see [`super::simulate::STEADY_TOLERANCE`]).
    pub steadiness: [f64; 2],
    /// Wall time of the two runs (s) and simulated time per run (s).
    pub wall_seconds: f64,
    /// Simulated time per run (s).
    pub simulated_seconds: f64,
    /// Steps converged only to the bearing model's resolution (lubricated, dry).
    pub resolution_limited_steps: [usize; 2],
}

/// Runs the sweep. `lubricated_film` replaces the film of every roller bearing on the lubricated
/// side (None keeps each bearing's configured film); the dry side uses `FilmChoice::Dry`.
/// `progress` is called once per finished run.
pub fn sweep(
    model: &RotorModel,
    speeds_rpm: &[f64],
    settings_at: &SettingsAt<'_>,
    lubricated_film: Option<FilmChoice>,
    progress: &(dyn Fn() + Sync),
) -> Result<Vec<SweepPoint>, RunError> {
    let specs: Vec<BearingSpec> = model
        .description
        .bearings
        .iter()
        .map(|b| match lubricated_film {
            Some(film) => b.spec.with_film(film),
            None => b.spec.clone(),
        })
        .collect();
    let dry: Vec<BearingSpec> = specs.iter().map(|s| s.with_film(FilmChoice::Dry)).collect();
    speeds_rpm
        .par_iter()
        .map(|&rpm| {
            let settings = settings_at(rpm * std::f64::consts::PI / 30.0);
            let lub = run(model, &settings, Some(&specs))?;
            progress();
            let dr = run(model, &settings, Some(&dry))?;
            progress();
            Ok(SweepPoint {
                speed_rpm: rpm,
                lubricated: lub.envelope,
                dry: dr.envelope,
                steadiness: [lub.steadiness, dr.steadiness],
                wall_seconds: lub.wall_seconds + dr.wall_seconds,
                simulated_seconds: settings.settle_time + settings.record_time,
                resolution_limited_steps: [
                    lub.resolution_limited_steps,
                    dr.resolution_limited_steps,
                ],
            })
        })
        .collect()
}
