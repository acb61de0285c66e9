//! The roller loop shared by the lubricated and the dry pass: where each roller is, and the
//! sums of forces, moments, stiffness and damping over the rollers.

use super::coupling::RollerMemory;
use super::output::StiffnessSums;
use super::{BearingOutput, BearingParams, RollerOutput};
use crate::contact::{RollerLoad, SlicedRoller};
use crate::math::{select, sin_cos};
use crate::params::OperatingState;
use core::f32::consts::PI;

/// Whether the lubricated step solves the rollers in SIMD lanes, four at a time (hosts:
/// `lockstep`), or each roller in turn (bare-metal ARM: the in-order Cortex-M).
pub(super) const LOCKSTEP: bool = !cfg!(all(target_arch = "arm", target_os = "none"));

/// A roller's direction (cos, sin of θ_j), geometric approach (m) and tilt (rad) at a step.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Place {
    pub(super) cos: f32,
    pub(super) sin: f32,
    pub(super) geometric_m: f32,
    pub(super) tilt_rad: f32,
}

/// The parts of a bearing the roller loop reads, borrowed apart from the warm start and the
/// output it writes (and from the film table the lubricated step's closure reads).
pub(super) struct Parts<'a, const Z: usize, const S: usize> {
    pub(super) params: &'a BearingParams,
    pub(super) roller: &'a SlicedRoller<S>,
    pub(super) pitch: &'a [(f32, f32, f32); Z],
}

impl<const Z: usize, const S: usize> Parts<'_, Z, S> {
    /// Where each roller is: its direction θ_j = θ_c + 2πj/Z (by the angle-sum identities),
    /// geometric approach and tilt relative to the raceway.
    pub(super) fn places(&self, state: &OperatingState, cage_angle_rad: f32) -> [Place; Z] {
        let [x, y] = state.displacement_m;
        let [tilt_x, tilt_y] = state.tilt_rad;
        let clearance = self.params.geometry.radial_clearance_m();
        let (sin_c, cos_c) = sin_cos(cage_angle_rad);
        let mut places = [Place::default(); Z];
        for (place, &(cp, sp, _)) in places.iter_mut().zip(self.pitch.iter()) {
            let c = cos_c * cp - sin_c * sp;
            let s = sin_c * cp + cos_c * sp;
            *place = Place {
                cos: c,
                sin: s,
                geometric_m: x * c + y * s - clearance,
                tilt_rad: tilt_y * c - tilt_x * s,
            };
        }
        places
    }

    /// Run `roller_step` for every roller and sum forces, moments, stiffness and damping.
    /// `roller_step(roller, its warm start, j, geometric approach, tilt)` returns the slice
    /// load, the roller's film fields and the film coupling factor of the stiffness (see
    /// `StiffnessSums`).
    pub(super) fn assemble(
        &self,
        memory: &mut [RollerMemory; Z],
        out: &mut BearingOutput<Z>,
        state: &OperatingState,
        cage_angle_rad: f32,
        places: &[Place; Z],
        mut roller_step: impl FnMut(
            &SlicedRoller<S>,
            &mut RollerMemory,
            usize,
            f32,
            f32,
        ) -> (RollerLoad, RollerOutput, f32),
    ) {
        let [vx, vy] = state.velocity_m_s;
        let damping = self.params.damping_factor_s;
        // Every roller entry is written below; the sums start from zero (in place: the output
        // is a kilobyte and a half, and a copy of it costs as much as a roller).
        out.totals.force_n = [0.0; 2];
        out.totals.moment_nm = [0.0; 2];
        let mut stiffness = StiffnessSums::default();
        let cage_angle = wrap_angle(cage_angle_rad);
        for (j, ((&(_, _, pitch_angle), place), (slot, roller_memory))) in self
            .pitch
            .iter()
            .zip(places.iter())
            .zip(out.rollers.iter_mut().zip(memory.iter_mut()))
            .enumerate()
        {
            let (c, s, geometric) = (place.cos, place.sin, place.geometric_m);
            let (load, mut roller, coupling) =
                roller_step(self.roller, roller_memory, j, geometric, place.tilt_rad);
            let approach_rate = vx * c + vy * s;
            let damping_force = damping * load.stiffness_n_per_m * approach_rate;
            // A roller pushes, it cannot pull: the total roller force is clamped at zero.
            let roller_force = crate::math::max(load.load_n + damping_force, 0.0);
            out.totals.force_n[0] -= roller_force * c;
            out.totals.force_n[1] -= roller_force * s;
            out.totals.moment_nm[0] += load.moment_nm * s;
            out.totals.moment_nm[1] -= load.moment_nm * c;
            stiffness.add(
                (c, s),
                [
                    load.stiffness_n_per_m,
                    load.stiffness_moment_n,
                    load.stiffness_tilt_nm,
                ],
                coupling,
            );
            // θ_c ∈ [−π, π] plus 2πj/Z ∈ [0, 2π): one turn back at most.
            let angle = cage_angle + pitch_angle;
            roller.angle_rad = angle - select(angle > PI, 2.0 * PI, 0.0);
            roller.geometric_approach_m = geometric;
            roller.load_n = load.load_n;
            roller.damping_force_n = damping_force;
            roller.moment_nm = load.moment_nm;
            roller.contact_stiffness_n_per_m = load.stiffness_n_per_m;
            *slot = roller;
        }
        out.totals.stiffness = stiffness.matrix();
        out.totals.damping_n_s_per_m = stiffness.damping(damping);
    }
}

/// Wrap an angle into [−π, π] at a fixed cost.
fn wrap_angle(angle_rad: f32) -> f32 {
    let turns = angle_rad * (0.5 * core::f32::consts::FRAC_1_PI);
    let whole = (turns + if turns >= 0.0 { 0.5 } else { -0.5 }) as i32;
    angle_rad - whole as f32 * (2.0 * core::f32::consts::PI)
}
