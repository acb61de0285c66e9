//! Static equilibrium of the rotor on its (nonlinear) bearings under the steady loads (static
//! forces, gravity, mean gear forces): K q − Σ Pᵀ F_b(P q) = f_static, solved by Newton with the
//! bearings' tangent stiffness (K + Σ Pᵀ K_b P). Iterations are bounded and a failure is reported.

use nalgebra::DVector;

use crate::bearing::{BearingError, BearingModel, BearingReaction, BearingState};
use crate::model::motor::SpeedOutOfRange;
use crate::model::RotorModel;

/// Converged when the largest residual force is below this fraction of the largest load. The
/// core computes in f32 with a fixed number of film-coupling iterations from a warm start, so
/// repeated calls at one state scatter by ~10⁻⁵ of the force: 10⁻⁴ sits above that.
pub const RESIDUAL_TOLERANCE: f64 = 1e-4;

/// Newton iterations allowed.
pub const MAX_ITERATIONS: usize = 200;

/// Step halvings allowed in one line search: 2⁻⁶⁰ of a Newton step is far below any
/// displacement the f64 state resolves, so a search that gets there has stalled.
const MAX_HALVINGS: usize = 60;

/// Armijo's sufficient-decrease constant for the line search (Dennis & Schnabel (1996)
/// §6.3: any small value; 10⁻⁴ is theirs).
const SUFFICIENT_DECREASE: f64 = 1e-4;

/// Errors of the static solution.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum StaticError {
    /// A bearing model failed.
    #[error(transparent)]
    Bearing(#[from] BearingError),
    /// The loads cannot be evaluated at this speed.
    #[error(transparent)]
    Speed(#[from] SpeedOutOfRange),
    /// The model has no bearing: the shaft is a free body and has no static equilibrium.
    #[error("no bearing supports the rotor: the shaft file has no [[bearing]] table (the static equilibrium, and the modes about it, need at least one)")]
    NoBearing,
    /// The tangent stiffness is singular (rotor not held, or all bearings unloaded).
    #[error("singular tangent stiffness at Newton iteration {iteration}: is the rotor held by its bearings?")]
    Singular {
        /// Iteration.
        iteration: usize,
    },
    /// Newton did not converge (iteration limit, or a line search that found no decrease).
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

/// Residual and tangent of the force balance at one state.
struct Balance {
    /// f_static − K q + Σ Pᵀ F_b (N, N·m).
    residual: DVector<f64>,
    /// K + Σ Pᵀ K_b P.
    tangent: nalgebra::DMatrix<f64>,
    reactions: Vec<BearingReaction>,
}

fn balance(
    model: &RotorModel,
    load: &DVector<f64>,
    q: &DVector<f64>,
    spin_speed: f64,
    bearings: &mut [Box<dyn BearingModel>],
) -> Result<Balance, BearingError> {
    let mut tangent = model.stiffness.clone();
    let mut residual = load - &model.stiffness * q;
    let mut reactions = Vec::with_capacity(bearings.len());
    for (d, model_b) in model.bearing_dofs().iter().zip(bearings.iter_mut()) {
        let react = model_b.settle(&BearingState {
            displacement: [q[d[0]], q[d[1]]],
            velocity: [0.0; 2],
            spin_speed,
            time: 0.0,
        })?;
        for i in 0..2 {
            residual[d[i]] += react.force[i];
            for j in 0..2 {
                tangent[(d[i], d[j])] += react.stiffness[i][j];
            }
        }
        reactions.push(react);
    }
    Ok(Balance {
        residual,
        tangent,
        reactions,
    })
}

/// Solves the equilibrium at spin speed Ω (rad/s) with the given bearing models.
///
/// Newton's method with a backtracking line search on ‖r‖₂ (Dennis & Schnabel (1996) §6.3):
/// the full step is tried first, so a rotor on linear bearings lands in one step whatever its
/// sag, and the step is halved while it does not decrease the residual enough. That is what
/// keeps a nonlinear bearing in check: one nearly unloaded at the start (clearance, film, or a
/// dry contact at the centre) has a soft tangent, its full step flies far into the contact,
/// the contact force there overshoots, and the search pulls the step back; a state a bearing
/// refuses counts as no decrease.
pub fn equilibrium(
    model: &RotorModel,
    spin_speed: f64,
    bearings: &mut [Box<dyn BearingModel>],
) -> Result<Equilibrium, StaticError> {
    if bearings.is_empty() {
        return Err(StaticError::NoBearing);
    }
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
    let mut current = balance(model, &load, &q, spin_speed, bearings)?;
    for iteration in 0..MAX_ITERATIONS {
        let residual = current.residual.amax();
        if residual <= RESIDUAL_TOLERANCE * force_scale {
            return Ok(Equilibrium {
                q,
                reactions: current.reactions,
                load,
                iterations: iteration,
            });
        }
        // An unloaded bearing without clearance (dry, at the centre) has no stiffness and the
        // tangent is singular: retry with a small spring on the bearing DOFs (10⁻⁶ of the
        // largest diagonal term). The residual still uses the true forces, so the equilibrium
        // found is unchanged; only the path to it differs.
        let mut k = current.tangent.clone();
        let dq = match k.clone().lu().solve(&current.residual) {
            Some(dq) if dq.iter().all(|x| x.is_finite()) => dq,
            _ => {
                let eps = 1e-6 * k.diagonal().amax();
                for d in &dofs {
                    k[(d[0], d[0])] += eps;
                    k[(d[1], d[1])] += eps;
                }
                k.lu()
                    .solve(&current.residual)
                    .filter(|dq| dq.iter().all(|x| x.is_finite()))
                    .ok_or(StaticError::Singular { iteration })?
            }
        };
        let norm = current.residual.norm();
        let mut step = 1.0;
        let mut accepted = None;
        for _ in 0..MAX_HALVINGS {
            let trial = &q + step * &dq;
            if let Ok(b) = balance(model, &load, &trial, spin_speed, bearings) {
                if b.residual.norm() <= (1.0 - SUFFICIENT_DECREASE * step) * norm {
                    accepted = Some((trial, b));
                    break;
                }
            }
            step *= 0.5;
        }
        let Some((next_q, next)) = accepted else {
            return Err(StaticError::NotConverged {
                iterations: iteration + 1,
                residual,
            });
        };
        q = next_q;
        current = next;
    }
    Err(StaticError::NotConverged {
        iterations: MAX_ITERATIONS,
        residual: current.residual.amax(),
    })
}
