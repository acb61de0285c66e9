//! The bearing as the shaft model sees it: a (possibly nonlinear) force on the inner race at one
//! node as a function of the inner-race displacement and velocity, with its tangent stiffness and
//! damping for the Newton iterations of the implicit integrator and for the linearised modes.
//!
//! Outer races sit in a rigid housing, so the bearing acts on the x and y DOFs of its node only.
//! Two implementations: [`LinearBearing`] (spring–damper, possibly anisotropic and cross-coupled;
//! used for the textbook cases) and the nonlinear roller bearing of the no_std core, reached
//! through [`roller_bearing()`] (adapter in the module [`mod@crate::bearing::roller_bearing`]).

pub mod core_bearing;
pub mod roller_bearing;

use std::path::{Path, PathBuf};

/// Kinematic state of the inner race at a bearing node.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BearingState {
    /// Inner-race displacement [x, y] relative to the outer race (m).
    pub displacement: [f64; 2],
    /// Inner-race velocity [vx, vy] (m/s).
    pub velocity: [f64; 2],
    /// Shaft spin speed Ω (rad/s).
    pub spin_speed: f64,
    /// Simulation time (s).
    pub time: f64,
}

/// Optional per-roller diagnostics a roller model reports (envelopes of the speed sweep).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RollerDiagnostics {
    /// Largest roller contact force in the bearing (N).
    pub max_contact_force: f64,
    /// Largest roller contact stiffness dQ/dδ (N/m).
    pub max_contact_stiffness: f64,
    /// Largest central film thickness over the loaded rollers (m).
    pub max_central_film: f64,
}

/// State of one roller at the last evaluation (roller models only).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RollerState {
    /// Roller angle θ_j from the x axis (rad).
    pub angle: f64,
    /// Roller contact load Q_j (N).
    pub load: f64,
    /// Central film at the inner contact (m).
    pub central_film_inner: f64,
    /// Central film at the outer contact (m).
    pub central_film_outer: f64,
}

/// Reaction of the bearing on the shaft.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BearingReaction {
    /// Force on the shaft [fx, fy] (N).
    pub force: [f64; 2],
    /// Tangent stiffness −∂F/∂(x, y) (N/m), row = force component.
    pub stiffness: [[f64; 2]; 2],
    /// Tangent damping −∂F/∂(vx, vy) (N·s/m).
    pub damping: [[f64; 2]; 2],
    /// Per-roller figures when the model has rollers.
    pub rollers: Option<RollerDiagnostics>,
}

/// Friction of a bearing at a settled state (docs/physics.md §8).
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct BearingFriction {
    /// Friction torque on the inner ring (N·m).
    pub torque_nm: f64,
    /// Power loss (W).
    pub power_loss_w: f64,
    /// The power loss split into [rolling, viscous, boundary] (W).
    pub power_loss_split_w: [f64; 3],
}

/// A failure of a bearing model (bad input state, a film model outside its domain, …).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("bearing model: {0}")]
pub struct BearingError(pub String);

/// A bearing the shaft integrator can call.
pub trait BearingModel: Send {
    /// Reaction for the given inner-race state (see [`BearingReaction`]).
    fn evaluate(&mut self, state: &BearingState) -> Result<BearingReaction, BearingError>;
    /// Called once per accepted time step (lets a model advance its cage angle / warm start).
    fn commit(&mut self, state: &BearingState, dt: f64);
    /// Reaction at a quasi-static state (static equilibrium, linearisation): a model with a
    /// memory converges it at this state first, so the reaction is one function of the state
    /// however the state was reached. Without memory: [`BearingModel::evaluate`].
    fn settle(&mut self, state: &BearingState) -> Result<BearingReaction, BearingError> {
        self.evaluate(state)
    }
    /// Per-roller states of the last evaluation (None for models without rollers).
    fn roller_states(&self) -> Option<Vec<RollerState>> {
        None
    }
    /// Friction at the last settled state and spin speed Ω (rad/s); None for models without
    /// a friction model.
    fn friction(&mut self, _spin_speed: f64) -> Result<Option<BearingFriction>, BearingError> {
        Ok(None)
    }
}

/// Linear spring–damper bearing: F = −K·u − C·u̇ with constant 2×2 K and C.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearBearing {
    /// Stiffness matrix (N/m), [[kxx, kxy], [kyx, kyy]].
    pub stiffness: [[f64; 2]; 2],
    /// Damping matrix (N·s/m).
    pub damping: [[f64; 2]; 2],
}

impl LinearBearing {
    /// Isotropic bearing: stiffness k (N/m) and damping c (N·s/m) in both directions.
    pub fn isotropic(k: f64, c: f64) -> LinearBearing {
        LinearBearing {
            stiffness: [[k, 0.0], [0.0, k]],
            damping: [[c, 0.0], [0.0, c]],
        }
    }
}

impl BearingModel for LinearBearing {
    fn evaluate(&mut self, state: &BearingState) -> Result<BearingReaction, BearingError> {
        let (u, v) = (state.displacement, state.velocity);
        if !(u.iter().chain(v.iter()).all(|z| z.is_finite())) {
            return Err(BearingError(format!(
                "non-finite inner-race state u = {u:?}, v = {v:?}"
            )));
        }
        let (k, c) = (self.stiffness, self.damping);
        let force = [
            -(k[0][0] * u[0] + k[0][1] * u[1] + c[0][0] * v[0] + c[0][1] * v[1]),
            -(k[1][0] * u[0] + k[1][1] * u[1] + c[1][0] * v[0] + c[1][1] * v[1]),
        ];
        Ok(BearingReaction {
            force,
            stiffness: k,
            damping: c,
            rollers: None,
        })
    }

    fn commit(&mut self, _state: &BearingState, _dt: f64) {}
}

/// Film model of a roller bearing (names as in the shaft TOML `film = "…"`): the core's.
pub use bearing_core::FilmKind;

/// How a bearing of the shaft model is made; turned into a fresh [`BearingModel`] for every
/// simulation (the models carry state, e.g. the cage angle).
#[derive(Debug, Clone, PartialEq)]
pub enum BearingSpec {
    /// Linear spring–damper.
    Linear(LinearBearing),
    /// Nonlinear roller bearing of the core from a bearing TOML file.
    Roller {
        /// Bearing configuration file (already resolved against the shaft file's folder).
        config: PathBuf,
        /// Film model.
        film: FilmKind,
    },
}

impl BearingSpec {
    /// A new model instance for one simulation.
    pub fn build(&self) -> Result<Box<dyn BearingModel>, BearingError> {
        match self {
            BearingSpec::Linear(b) => Ok(Box::new(*b)),
            BearingSpec::Roller { config, film } => roller_bearing(config, *film),
        }
    }

    /// The same bearing with another film model (dry vs lubricated runs); linear ones unchanged.
    pub fn with_film(&self, film: FilmKind) -> BearingSpec {
        match self {
            BearingSpec::Linear(b) => BearingSpec::Linear(*b),
            BearingSpec::Roller { config, .. } => BearingSpec::Roller {
                config: config.clone(),
                film,
            },
        }
    }
}

/// Constructor hook for the core's roller bearing: the bearing TOML at `path` (see
/// `bearing_host_common::config`) with the given film model, through [`crate::bearing::roller_bearing::RollerBearing`].
pub fn roller_bearing(path: &Path, film: FilmKind) -> Result<Box<dyn BearingModel>, BearingError> {
    Ok(Box::new(
        crate::bearing::roller_bearing::RollerBearing::from_file(path, film)?,
    ))
}
