//! The core's bearing at a run-time roller count, stepped with a *concrete* film model.
//!
//! `bearing_host_common::rolling::DynBearing` passes the film model as `&dyn FilmModel`, so the core's inner
//! film–load iterations call the film through a vtable and nothing is inlined. The shaft calls
//! the bearing a few times per time step at ~10⁵ steps per simulated second, so here the core is
//! instantiated per roller count with `Regression` (or the dry step) as a type: the same
//! `Bearing::step`, monomorphised. No per-call allocation: the outputs are summarised in place.

use bearing_core::bearing::BearingOutput;
use bearing_core::film::ann::{AnnF32, AnnInt};
use bearing_core::{Bearing, BearingParams, OperatingState, ParamError, Regression, StepStatus};

use super::bearing::{FilmChoice, RollerDiagnostics, RollerState};
use bearing_host_common::rolling::{MAX_ROLLERS, MIN_ROLLERS, SLICES};

/// What the shaft needs from one core step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CoreStep {
    /// Force on the inner race (N).
    pub force: [f32; 2],
    /// Radial stiffness −∂F/∂(x, y) (N/m).
    pub stiffness: [[f32; 2]; 2],
    /// Damping −∂F/∂(ẋ, ẏ) (N·s/m).
    pub damping: [[f32; 2]; 2],
    /// Per-roller extremes.
    pub diagnostics: RollerDiagnostics,
}

/// A core bearing of any supported roller count.
pub trait CoreBearing: Send {
    /// One step with the chosen film model (networks, regression) or dry;
    /// the core's refusal of the state is returned as its error.
    fn step(&mut self, film: FilmChoice, state: &OperatingState) -> Result<CoreStep, ParamError>;
    /// Per-roller states of the last step.
    fn rollers(&self) -> Vec<RollerState>;
}

fn summarise<const Z: usize>(o: &BearingOutput<Z>) -> Result<CoreStep, ParamError> {
    if let StepStatus::Rejected(e) = o.status {
        return Err(e);
    }
    let mut d = RollerDiagnostics::default();
    for r in &o.rollers {
        d.max_contact_force = d.max_contact_force.max(f64::from(r.load_n));
        d.max_contact_stiffness = d
            .max_contact_stiffness
            .max(f64::from(r.contact_stiffness_n_per_m));
        if r.load_n > 0.0 {
            d.max_central_film = d
                .max_central_film
                .max(f64::from(r.central_film_in_m.max(r.central_film_out_m)));
        }
    }
    Ok(CoreStep {
        force: o.force_n,
        stiffness: o.radial_stiffness_n_per_m(),
        damping: o.damping_n_s_per_m,
        diagnostics: d,
    })
}

impl<const Z: usize> CoreBearing for Bearing<Z, SLICES> {
    fn step(&mut self, film: FilmChoice, state: &OperatingState) -> Result<CoreStep, ParamError> {
        match film {
            FilmChoice::Dry => summarise(Bearing::step_dry(self, state)),
            FilmChoice::Regression => summarise(Bearing::step(self, &Regression, state)),
            FilmChoice::F32 => summarise(Bearing::step(self, &AnnF32, state)),
            FilmChoice::Int => summarise(Bearing::step(self, &AnnInt, state)),
        }
    }

    fn rollers(&self) -> Vec<RollerState> {
        self.output()
            .rollers
            .iter()
            .map(|r| RollerState {
                angle: f64::from(r.angle_rad),
                load: f64::from(r.load_n),
                central_film_inner: f64::from(r.central_film_in_m),
                central_film_outer: f64::from(r.central_film_out_m),
            })
            .collect()
    }
}

/// The core bearing for `params`, with its roller count as the const generic.
pub fn new_core_bearing(params: BearingParams) -> Result<Box<dyn CoreBearing>, ParamError> {
    macro_rules! counts {
        ($($z:literal)*) => {
            match params.geometry().roller_count() {
                $($z => Ok(Box::new(Bearing::<$z, SLICES>::new(params)?)),)*
                other => Err(ParamError {
                    field: "roller_count",
                    value: f32::from(other),
                    allowed: bearing_core::Allowed::Range {
                        min: f32::from(MIN_ROLLERS),
                        max: f32::from(MAX_ROLLERS),
                    },
                }),
            }
        };
    }
    counts!(6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21 22 23 24 25 26 27 28 29 30 31 32 33 34 35 36 37 38 39 40)
}
