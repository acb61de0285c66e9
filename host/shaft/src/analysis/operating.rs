//! Modes at an operating point and the Campbell diagram: the bearings are linearised at the
//! static equilibrium of the running speed (their tangent stiffness and damping, −∂F/∂u and
//! −∂F/∂u̇), the gyroscopic matrix is scaled by that speed, and the state-space eigenproblem of
//! [`crate::analysis::modes`] is solved (Friswell et al. (2010) §5.8: Campbell diagrams).

use crate::analysis::modes::{damped_modes, Mode, ModesError};
use crate::analysis::statics::{equilibrium, Equilibrium, StaticError};
use crate::bearing::{BearingError, BearingModel, BearingReaction, BearingState};
use crate::model::RotorModel;

/// Errors of the operating-point analyses.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum OperatingError {
    /// Building a bearing model failed.
    #[error(transparent)]
    Bearing(#[from] BearingError),
    /// The equilibrium failed.
    #[error(transparent)]
    Static(#[from] StaticError),
    /// The eigenproblem failed.
    #[error(transparent)]
    Modes(#[from] ModesError),
}

/// Fresh bearing models of the rotor.
pub fn build_bearings(model: &RotorModel) -> Result<Vec<Box<dyn BearingModel>>, BearingError> {
    model
        .description
        .bearings
        .iter()
        .map(|b| b.spec.build())
        .collect()
}

/// Linearised bearings (tangent stiffness and damping) at a displacement state, zero velocity.
pub fn linearise(
    model: &RotorModel,
    bearings: &mut [Box<dyn BearingModel>],
    q: &nalgebra::DVector<f64>,
    spin_speed: f64,
) -> Result<Vec<BearingReaction>, BearingError> {
    model
        .bearing_dofs()
        .iter()
        .zip(bearings.iter_mut())
        .map(|(d, b)| {
            b.settle(&BearingState {
                displacement: [q[d[0]], q[d[1]]],
                velocity: [0.0; 2],
                spin_speed,
                time: 0.0,
            })
        })
        .collect()
}

/// Modes at spin speed Ω (rad/s) about the static equilibrium at that speed.
pub fn operating_modes(
    model: &RotorModel,
    spin_speed: f64,
    max_modes: usize,
    with_shapes: bool,
) -> Result<(Equilibrium, Vec<Mode>), OperatingError> {
    let mut bearings = build_bearings(model)?;
    let eq = equilibrium(model, spin_speed, &mut bearings)?;
    let lin = linearise(model, &mut bearings, &eq.q, spin_speed)?;
    let kb: Vec<_> = lin.iter().map(|r| r.stiffness).collect();
    let cb: Vec<_> = lin.iter().map(|r| r.damping).collect();
    let (k, d) = model.linearised(spin_speed, &kb, &cb);
    let modes = damped_modes(&model.mass, &k, &d, max_modes, with_shapes)?;
    Ok((eq, modes))
}

/// One speed of a Campbell diagram.
#[derive(Debug, Clone, serde::Serialize)]
pub struct CampbellPoint {
    /// Spin speed (rpm).
    pub speed_rpm: f64,
    /// Natural frequencies (rad/s), ascending.
    pub frequencies_rad_s: Vec<f64>,
    /// Damping ratios.
    pub damping_ratios: Vec<f64>,
    /// Whirl direction of each mode.
    pub whirl: Vec<crate::analysis::modes::Whirl>,
}

/// Campbell diagram over the given speeds (rpm); shapes are computed to classify the whirl.
pub fn campbell(
    model: &RotorModel,
    speeds_rpm: &[f64],
    max_modes: usize,
) -> Result<Vec<CampbellPoint>, OperatingError> {
    use rayon::prelude::*;
    speeds_rpm
        .par_iter()
        .map(|&rpm| {
            let (_, modes) =
                operating_modes(model, rpm * std::f64::consts::PI / 30.0, max_modes, true)?;
            Ok(CampbellPoint {
                speed_rpm: rpm,
                frequencies_rad_s: modes.iter().map(|m| m.frequency).collect(),
                damping_ratios: modes.iter().map(|m| m.damping_ratio).collect(),
                whirl: modes.iter().map(|m| m.whirl).collect(),
            })
        })
        .collect()
}
