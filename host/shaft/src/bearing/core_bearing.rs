//! What the shaft takes from one step of the core's bearing: the force, the radial stiffness
//! and damping, and the per-roller extremes and states, in f64.
//!
//! The core's [`DynBearing`](bearing_core::DynBearing) chooses the roller count at run time and
//! steps with the film model it was built with, as a concrete type (monomorphised, inlined into
//! the film table); it lends its output as an [`OutputView`], summarised here in place, with no
//! per-call allocation.

use bearing_core::OutputView;

use crate::bearing::{RollerDiagnostics, RollerState};

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

/// The shaft's summary of a core output.
pub fn summarise(o: &OutputView<'_>) -> CoreStep {
    let mut d = RollerDiagnostics::default();
    for r in o.rollers {
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
    CoreStep {
        force: o.force_n,
        stiffness: o.radial_stiffness_n_per_m(),
        damping: o.damping_n_s_per_m,
        diagnostics: d,
    }
}

/// The per-roller states of a core output.
pub fn roller_states(o: &OutputView<'_>) -> Vec<RollerState> {
    o.rollers
        .iter()
        .map(|r| RollerState {
            angle: f64::from(r.angle_rad),
            load: f64::from(r.load_n),
            central_film_inner: f64::from(r.central_film_in_m),
            central_film_outer: f64::from(r.central_film_out_m),
        })
        .collect()
}
