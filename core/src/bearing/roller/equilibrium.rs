//! Static equilibrium of the inner race under an applied radial force.
//!
//! Newton's method on the bearing force balance F_bearing(x, y) + F_applied = 0 with the
//! bearing's own radial stiffness as the Jacobian (F_bearing decreases with displacement, so
//! J = −K). At zero clearance the unloaded bearing has zero stiffness, so the Newton matrix is
//! regularised by a small multiple of the nominal roller stiffness and each step is limited to
//! one micrometre-scale trust length; both vanish from the converged answer, which is
//! judged on the force residual alone. Not for the real-time loop: it stops when converged.
//!
//! The residual is a sum of f32 roller forces, so it cannot be resolved finer than a small
//! fraction of the sum of the roller loads Σ|Q_j|, and that sum is not zero at zero applied
//! load: a film or an interference preloads every roller (docs/physics.md §6.2: the hub-motor
//! bearing carries Σ|Q_j| ≈ 2.5 kN dry and ≈ 25 kN at 14 000 rpm with no load at all). The
//! tolerance is therefore relative to the larger of |F_applied| and Σ|Q_j|.

use super::{Bearing, BearingOutput};
use crate::params::OperatingState;

/// Result of a static solve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Equilibrium {
    /// Inner-race displacement [x, y] (m).
    pub displacement_m: [f32; 2],
    /// |F_bearing + F_applied| at the solution (N).
    pub residual_n: f32,
    /// Newton iterations used.
    pub iterations: usize,
    /// Residual ≤ tolerance·max(|F_applied|, Σ|Q_j|) reached.
    pub converged: bool,
}

/// Largest displacement change per Newton iteration (m).
const TRUST_M: f32 = 5.0e-6;

impl<const Z: usize, const S: usize> Bearing<Z, S> {
    /// Solve for the displacement at which the bearing carries `applied_force_n` [F_x, F_y] (N)
    /// acting on the inner race, with the bearing's film model, at the speed of `state` (its
    /// displacement is the start) and the committed cage angle. Stops when the force residual
    /// is below `relative_tolerance·max(|F|, Σ|Q_j|)` (Σ|Q_j|: the sum of the roller loads of
    /// the iterate, 10⁻³ N at least) or after `max_iterations`; a refused state stops it
    /// unconverged. It commits the warm start of its last iterate.
    pub fn static_equilibrium(
        &mut self,
        applied_force_n: [f32; 2],
        state: &OperatingState,
        relative_tolerance: f32,
        max_iterations: usize,
    ) -> Equilibrium {
        let magnitude = crate::math::sqrt(
            applied_force_n[0] * applied_force_n[0] + applied_force_n[1] * applied_force_n[1],
        );
        let nominal = self.roller.nominal_coefficient() * crate::math::pow(1.0e-6, 1.0 / 9.0);
        let regularisation = 1.0e-3 * nominal;
        let mut s = *state;
        let mut result = Equilibrium {
            displacement_m: s.displacement_m,
            residual_n: f32::MAX,
            iterations: 0,
            converged: false,
        };
        for iteration in 0..=max_iterations {
            // `settle(…, SETTLE_STEPS)` renews the whole film table at this speed and steps
            // from the last iterate's warm start as often as a cold start needs: the force is
            // then one function of the state to f32 resolution, as a Newton iteration to 10⁻⁶
            // of the load needs. (One real-time step leaves a few 10⁻⁶ of scatter between
            // calls; three steps still left 1.7·10⁻⁶ at 2 kN on the hub bearing, and the Newton
            // iteration stalled there. A step renews one node of the table, so its force can
            // also depend on the speeds of earlier steps.)
            let out: BearingOutput<Z> = match self.settle(&s, super::SETTLE_STEPS) {
                Ok(out) => *out,
                Err(_) => return result,
            };
            let rx = out.force_n[0] + applied_force_n[0];
            let ry = out.force_n[1] + applied_force_n[1];
            result.displacement_m = s.displacement_m;
            result.residual_n = crate::math::sqrt(rx * rx + ry * ry);
            result.iterations = iteration;
            let roller_load_sum_n = out
                .rollers
                .iter()
                .fold(0.0f32, |sum, r| sum + r.load_n.abs());
            let tolerance = relative_tolerance * magnitude.max(roller_load_sum_n).max(1.0e-3);
            if result.residual_n <= tolerance {
                result.converged = true;
                return result;
            }
            // K·Δx = residual (the bearing force drops by K·Δx when the race moves by Δx).
            let [[kxx, kxy], [kyx, kyy]] = out.radial_stiffness_n_per_m();
            let (kxx, kyy) = (kxx + regularisation, kyy + regularisation);
            let det = kxx * kyy - kxy * kyx;
            if !(det.is_finite() && det > 0.0) {
                return result;
            }
            let mut dx = (kyy * rx - kxy * ry) / det;
            let mut dy = (kxx * ry - kyx * rx) / det;
            let length = crate::math::sqrt(dx * dx + dy * dy);
            if length > TRUST_M {
                dx *= TRUST_M / length;
                dy *= TRUST_M / length;
            }
            s.displacement_m = [s.displacement_m[0] + dx, s.displacement_m[1] + dy];
        }
        result
    }
}
