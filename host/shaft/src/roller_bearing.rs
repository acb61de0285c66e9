//! Adapter from the core's film-coupled roller bearing (`bearing_core::Bearing::step`, at a
//! run-time roller count through [`super::core_bearing`]) to the shaft's [`BearingModel`].
//!
//! The core works in f32 with the inner-race state and the cage angle; this adapter keeps the
//! cage angle in f64, advancing it at the cage speed ω_c = (ω/2)(1 − D/d_m) (PHYSICS.md §2)
//! between committed steps (integrated over the step's speed change during a ramp), so Newton
//! iterations inside a step see the cage at the step's time.
//! Tilts are not coupled (the shaft passes x, y only; the core gets zero tilt). The tangent
//! stiffness is the core's radial 2×2 block (film coupling included), the damping the core's
//! f_damp·K_j matrix. A state the core refuses is reported as an error, never used.

use std::path::Path;

use bearing_core::OperatingState;

use super::bearing::{
    BearingError, BearingModel, BearingReaction, BearingState, FilmChoice, RollerState,
};
use super::core_bearing::{new_core_bearing, CoreBearing};
use bearing_host_common::config::BearingConfig;

/// The core roller bearing as a shaft bearing.
pub struct RollerBearing {
    bearing: Box<dyn CoreBearing>,
    film: FilmChoice,
    /// ω_c / ω.
    cage_ratio: f64,
    /// Cage angle at `commit_time` (rad, in [0, 2π)).
    cage_angle: f64,
    commit_time: f64,
    /// Spin speed at `commit_time` (None before the first commit: the evaluated speed is used).
    commit_speed: Option<f64>,
}

impl RollerBearing {
    /// From a bearing configuration file (see `bearing_host_common::config`) and a film model (integer or f32
    /// network, regression formulas, or dry).
    pub fn from_file(path: &Path, film: FilmChoice) -> Result<Self, BearingError> {
        let (_, params) = BearingConfig::load(path).map_err(|e| BearingError(e.to_string()))?;
        let geometry = *params.geometry();
        let bearing = new_core_bearing(params)
            .map_err(|e| BearingError(format!("{}: {e}", path.display())))?;
        let cage_ratio = f64::from(geometry.cage_speed_rad_s(1.0));
        Ok(RollerBearing {
            bearing,
            film,
            cage_ratio,
            cage_angle: 0.0,
            commit_time: 0.0,
            commit_speed: None,
        })
    }

    fn cage_angle_at(&self, state: &BearingState) -> f64 {
        let tau = std::f64::consts::TAU;
        // θ_c = ∫ω_c dt over the step by the trapezoidal rule on the spin speed: exact for a
        // linear speed ramp, and ω_c·Δt at constant speed.
        let mean_speed = 0.5 * (self.commit_speed.unwrap_or(state.spin_speed) + state.spin_speed);
        (self.cage_angle + self.cage_ratio * mean_speed * (state.time - self.commit_time))
            .rem_euclid(tau)
    }
}

impl BearingModel for RollerBearing {
    fn evaluate(&mut self, state: &BearingState) -> Result<BearingReaction, BearingError> {
        let f = |v: f64| v as f32;
        let os = OperatingState {
            displacement_m: state.displacement.map(f),
            velocity_m_s: state.velocity.map(f),
            tilt_rad: [0.0; 2],
            shaft_speed_rad_s: f(state.spin_speed),
            cage_angle_rad: f(self.cage_angle_at(state)),
        };
        let step = self.bearing.step(self.film, &os).map_err(|e| {
            BearingError(format!(
                "the core refused the inner-race state u = {:?} m, v = {:?} m/s: {e}",
                state.displacement, state.velocity
            ))
        })?;
        let g = |m: [[f32; 2]; 2]| m.map(|row| row.map(f64::from));
        Ok(BearingReaction {
            force: step.force.map(f64::from),
            stiffness: g(step.stiffness),
            damping: g(step.damping),
            rollers: Some(step.diagnostics),
        })
    }

    fn commit(&mut self, state: &BearingState, _dt: f64) {
        self.cage_angle = self.cage_angle_at(state);
        self.commit_time = state.time;
        self.commit_speed = Some(state.spin_speed);
    }

    fn roller_states(&self) -> Option<Vec<RollerState>> {
        Some(self.bearing.rollers())
    }
}

/// Outer-race pass (varying-compliance) frequency f_bpo = Z f_c (Hz) of the bearing in the
/// configuration file at spin speed Ω (rad/s) (PHYSICS.md §2).
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

    /// Reference: PHYSICS.md §2 — the roller set turns with the cage, so at a fixed inner-race
    /// displacement the bearing force is periodic in the cage angle with period 2π/Z and varies
    /// within it (varying compliance). NU 205: Z = 12, dry.
    #[test]
    fn force_is_periodic_in_the_roller_pitch_and_varies_within_it() {
        let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../configs/nu205.toml");
        let mut b = RollerBearing::from_file(&path, FilmChoice::Dry).unwrap();
        let omega = 1000.0;
        // Time for the cage to turn one roller pitch.
        let pitch_time = 2.0 * std::f64::consts::PI / 12.0 / (b.cage_ratio * omega);
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
