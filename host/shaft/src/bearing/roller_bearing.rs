//! Adapter from the core's film-coupled roller bearing (`bearing_core::DynBearing`, at a
//! run-time roller count) to the shaft's [`BearingModel`].
//!
//! The core keeps the committed state: the cage angle, which it turns at the cage speed
//! ω_c = (ω/2)(1 − D/d_m) (docs/physics.md §2) of the state's spin speed over the time since the
//! last commit, the warm start and the film table. [`BearingModel::evaluate`] is the core's
//! trial evaluation (`evaluate`: it commits nothing, so the force at a state does not depend on
//! how many Newton iterations came before); [`BearingModel::commit`] is its real-time step
//! (`advance`) at the accepted state. Tilts are not coupled (the shaft passes x, y only; the
//! core gets zero tilt). The tangent stiffness is the core's radial 2×2 block (film coupling
//! included), the damping the core's f_damp·K_j matrix. A state the core refuses is reported
//! as an error, never used.

use std::path::Path;

use bearing_core::bearing::SETTLE_STEPS;
use bearing_core::{DynBearing, FilmKind, OperatingState, OutputView, ParamError};

use crate::bearing::core_bearing::{roller_states, summarise};
use crate::bearing::{
    BearingError, BearingFriction, BearingModel, BearingReaction, BearingState, RollerState,
};
use bearing_host_common::config::BearingConfig;
use bearing_host_common::friction::{bearing_friction_at_loads, LoadSharing};
use bearing_host_common::rolling::boxed;

/// The core roller bearing as a shaft bearing.
pub struct RollerBearing {
    bearing: Box<dyn DynBearing + Send>,
    /// Time of the last commit (s; 0 before the first).
    commit_time: f64,
}

impl RollerBearing {
    /// From a bearing configuration file (see `bearing_host_common::config`) and a film model (integer or f32
    /// network, regression formulas, or dry).
    pub fn from_file(path: &Path, film: FilmKind) -> Result<Self, BearingError> {
        let (_, params) = BearingConfig::load(path).map_err(|e| BearingError(e.to_string()))?;
        let bearing =
            boxed(params, film).map_err(|e| BearingError(format!("{}: {e}", path.display())))?;
        Ok(RollerBearing {
            bearing,
            commit_time: 0.0,
        })
    }

    /// The core's inner-race state and the time since the last commit (s).
    fn core_state(&self, state: &BearingState) -> (OperatingState, f32) {
        let f = |v: f64| v as f32;
        let os = OperatingState {
            displacement_m: state.displacement.map(f),
            velocity_m_s: state.velocity.map(f),
            tilt_rad: [0.0; 2],
            shaft_speed_rad_s: f(state.spin_speed),
        };
        (os, f(state.time - self.commit_time))
    }

    fn refused(state: &BearingState, e: ParamError) -> BearingError {
        BearingError(format!(
            "the core refused the inner-race state u = {:?} m, v = {:?} m/s at t = {} s: {e}",
            state.displacement, state.velocity, state.time
        ))
    }
}

/// The shaft's reaction from a core output.
fn reaction(o: &OutputView<'_>) -> BearingReaction {
    let step = summarise(o);
    let g = |m: [[f32; 2]; 2]| m.map(|row| row.map(f64::from));
    BearingReaction {
        force: step.force.map(f64::from),
        stiffness: g(step.stiffness),
        damping: g(step.damping),
        rollers: Some(step.diagnostics),
    }
}

impl BearingModel for RollerBearing {
    fn evaluate(&mut self, state: &BearingState) -> Result<BearingReaction, BearingError> {
        let (os, dt) = self.core_state(state);
        let out = self
            .bearing
            .evaluate(&os, dt)
            .map_err(|e| Self::refused(state, e))?;
        Ok(reaction(&out))
    }

    /// The core's `settle` at the state (no time passes): film table filled at its speed, warm
    /// start converged from the last one in `SETTLE_STEPS` steps, committed at the state's time.
    fn settle(&mut self, state: &BearingState) -> Result<BearingReaction, BearingError> {
        let (os, _) = self.core_state(state);
        let out = self
            .bearing
            .settle(&os, SETTLE_STEPS)
            .map_err(|e| Self::refused(state, e))?;
        self.commit_time = state.time;
        Ok(reaction(&out))
    }

    fn commit(&mut self, state: &BearingState, _dt: f64) {
        let (os, dt) = self.core_state(state);
        // The integrator commits a state it has just evaluated, which the core accepted; a
        // refusal here would leave the committed state as it was.
        let _ = self.bearing.advance(&os, dt);
        self.commit_time = state.time;
    }

    fn roller_states(&self) -> Option<Vec<RollerState>> {
        Some(roller_states(&self.bearing.output()))
    }

    /// The core's friction pass on the lubricated bearing (its own loads and films). The dry
    /// bearing has no film: its roller loads, with the films the regression formulas give at
    /// those loads (and the bearing's film corrections), go through the same pass on the host
    /// (`bearing_host_common::friction`), so that lubricated against dry shows what the
    /// film-coupled load sharing does to the loss (docs/shaft.md).
    fn friction(&mut self, spin_speed: f64) -> Result<Option<BearingFriction>, BearingError> {
        let omega = spin_speed as f32;
        let (torque, power, split) = if self.bearing.film() == FilmKind::Dry {
            let o = self.bearing.output();
            let loads: Vec<f32> = o.rollers.iter().map(|r| r.load_n).collect();
            let f = bearing_friction_at_loads(
                self.bearing.params(),
                &loads,
                o.centrifugal_force_n,
                omega,
                LoadSharing::WholeLoadFilm,
            )
            .bearing;
            (f.torque_nm, f.power_loss_w, f.power_loss_split_w)
        } else {
            let o = self
                .bearing
                .friction(omega)
                .map_err(|e| BearingError(format!("friction at {spin_speed} rad/s: {e}")))?;
            (o.friction_torque_nm, o.power_loss_w, o.power_loss_split_w)
        };
        Ok(Some(BearingFriction {
            torque_nm: f64::from(torque),
            power_loss_w: f64::from(power),
            power_loss_split_w: split.map(f64::from),
        }))
    }
}

/// Outer-race pass (varying-compliance) frequency f_bpo = Z f_c (Hz) of the bearing in the
/// configuration file at spin speed Ω (rad/s) (docs/physics.md §2).
pub fn outer_race_pass_hz(path: &Path, spin_speed: f64) -> Result<f64, BearingError> {
    let (_, params) = BearingConfig::load(path).map_err(|e| BearingError(e.to_string()))?;
    Ok(f64::from(
        params
            .geometry()
            .pass_frequencies(spin_speed as f32)
            .outer_race_hz,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Reference: docs/physics.md §2 — the roller set turns with the cage, so at a fixed inner-race
    /// displacement the bearing force is periodic in the cage angle with period 2π/Z and varies
    /// within it (varying compliance). NU 205: Z = 12, dry.
    #[test]
    fn force_is_periodic_in_the_roller_pitch_and_varies_within_it() {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../configs/nu205.toml");
        let mut b = RollerBearing::from_file(&path, FilmKind::Dry).unwrap();
        let omega = 1000.0;
        // Time for the cage to turn one roller pitch.
        let cage_ratio = f64::from(b.bearing.params().geometry().cage_speed_rad_s(1.0));
        let pitch_time = 2.0 * std::f64::consts::PI / 12.0 / (cage_ratio * omega);
        let mut at = |t: f64| {
            b.evaluate(&BearingState {
                displacement: [0.3e-6, -2.0e-6],
                velocity: [0.0; 2],
                spin_speed: omega,
                time: t,
            })
            .unwrap()
            .force
        };
        let (f0, f_half, f_pitch) = (
            at(0.1 * pitch_time),
            at(0.6 * pitch_time),
            at(1.1 * pitch_time),
        );
        let scale = f0[1].abs();
        assert!(
            (f0[1] - f_pitch[1]).abs() < 1e-5 * scale,
            "{f0:?} vs {f_pitch:?}"
        );
        assert!(
            (f0[1] - f_half[1]).abs() > 1e-3 * scale,
            "{f0:?} vs {f_half:?}"
        );
    }
}
