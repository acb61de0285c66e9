//! Static equilibrium of the rotor on its (nonlinear) bearings under the steady loads (static
//! forces, gravity, mean gear forces): K q − Σ Pᵀ F_b(P q) = f_static, solved by Newton with the
//! bearings' tangent stiffness (K + Σ Pᵀ K_b P). Iterations are bounded and a failure is reported.

use nalgebra::DVector;

use super::bearing::{BearingError, BearingModel, BearingReaction, BearingState};
use super::model::RotorModel;
use super::motor::SpeedOutOfRange;

/// Converged when the largest residual force is below this fraction of the largest load. The
/// core computes in f32 with a fixed number of film-coupling iterations from a warm start, so
/// repeated calls at one state scatter by ~10⁻⁵ of the force: 10⁻⁴ sits above that.
pub const RESIDUAL_TOLERANCE: f64 = 1e-4;

/// Largest bearing displacement change per Newton iteration (m).
pub const MAX_BEARING_STEP: f64 = 5e-6;

/// Errors of the static solution.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StaticError {
    /// A bearing model failed.
    #[error(transparent)]
    Bearing(#[from] BearingError),
    /// The loads cannot be evaluated at this speed.
    #[error(transparent)]
    Speed(#[from] SpeedOutOfRange),
    /// The tangent stiffness is singular (rotor not held, or all bearings unloaded).
    #[error("singular tangent stiffness at Newton iteration {iteration}: is the rotor held by its bearings?")]
    Singular {
        /// Iteration.
        iteration: usize,
    },
    /// Newton did not converge.
    #[error("static equilibrium did not converge in {iterations} iterations (residual {residual:.3e} N)")]
    NotConverged {
        /// Iterations done.
        iterations: usize,
        /// Largest residual force (N).
        residual: f64,
    },
}

/// Equilibrium state.
#[derive(Debug, Clone)]
pub struct Equilibrium {
    /// Displacements (m, rad).
    pub q: DVector<f64>,
    /// Bearing reactions at the equilibrium (one per bearing).
    pub reactions: Vec<BearingReaction>,
    /// The static load vector (N).
    pub load: DVector<f64>,
    /// Newton iterations used.
    pub iterations: usize,
}

/// Solves the equilibrium at spin speed Ω (rad/s) with the given bearing models.
pub fn equilibrium(
    model: &RotorModel,
    spin_speed: f64,
    bearings: &mut [Box<dyn BearingModel>],
) -> Result<Equilibrium, StaticError> {
    let n = model.n_dof();
    let mut load = DVector::zeros(n);
    model.description.loads.add_forces(
        0.0,
        spin_speed,
        model.gravity_vector.as_slice(),
        false,
        load.as_mut_slice(),
    )?;
    let dofs = model.bearing_dofs();
    let force_scale = load.amax().max(1.0);
    let mut q = DVector::zeros(n);
    let max_iterations = 200;
    let mut residual = f64::INFINITY;
    for iteration in 0..max_iterations {
        let mut k = model.stiffness.clone();
        let mut r = &load - &model.stiffness * &q;
        let mut reactions = Vec::with_capacity(dofs.len());
        for (b, model_b) in bearings.iter_mut().enumerate() {
            let d = dofs[b];
            let react = model_b.settle(&BearingState {
                displacement: [q[d[0]], q[d[1]]],
                velocity: [0.0; 2],
                spin_speed,
                time: 0.0,
            })?;
            for i in 0..2 {
                r[d[i]] += react.force[i];
                for j in 0..2 {
                    k[(d[i], d[j])] += react.stiffness[i][j];
                }
            }
            reactions.push(react);
        }
        residual = r.amax();
        if residual <= RESIDUAL_TOLERANCE * force_scale {
            return Ok(Equilibrium {
                q,
                reactions,
                load,
                iterations: iteration,
            });
        }
        // An unloaded bearing without clearance (dry, at the centre) has no stiffness and the
        // tangent is singular: retry with a small spring on the bearing DOFs (10⁻⁶ of the
        // largest diagonal term). The residual still uses the true forces, so the equilibrium
        // found is unchanged; only the path to it (limited by MAX_BEARING_STEP) differs.
        let dq = match k.clone().lu().solve(&r) {
            Some(dq) if dq.iter().all(|x| x.is_finite()) => dq,
            _ => {
                let eps = 1e-6 * k.diagonal().amax();
                for d in &dofs {
                    k[(d[0], d[0])] += eps;
                    k[(d[1], d[1])] += eps;
                }
                k.lu()
                    .solve(&r)
                    .filter(|dq| dq.iter().all(|x| x.is_finite()))
                    .ok_or(StaticError::Singular { iteration })?
            }
        };
        // Bearings with clearance or a film can be nearly unloaded at the start, so their
        // tangent is soft and a full Newton step can fly far out: limit the bearing-DOF move
        // to MAX_BEARING_STEP per iteration (the rest of the shaft follows proportionally).
        let largest = dofs
            .iter()
            .flat_map(|d| [dq[d[0]].abs(), dq[d[1]].abs()])
            .fold(0.0, f64::max);
        let scale = if largest > MAX_BEARING_STEP {
            MAX_BEARING_STEP / largest
        } else {
            1.0
        };
        q.axpy(scale, &dq, 1.0);
    }
    Err(StaticError::NotConverged {
        iterations: max_iterations,
        residual,
    })
}
