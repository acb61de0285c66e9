//! The dry pass of the roller bearing (film ≡ 0): the slicing contact of today's multi-body
//! practice, for comparison with the lubricated pass (`super::Bearing::advance` with
//! [`FilmKind::Dry`](crate::FilmKind::Dry)).

use super::parts::{Parts, LOCKSTEP};
use super::{coupling, Bearing, RollerOutput};
use crate::film::Regime;
use crate::lanes::{Wide, WIDE_LANES};
use crate::params::OperatingState;

impl<const Z: usize, const S: usize> Bearing<Z, S> {
    /// One dry pass (film ≡ 0) at cage angle `cage_angle_rad`: today's multi-body practice,
    /// for comparison. It keeps nothing from one step to the next but the cage angle.
    pub(super) fn dry(&mut self, state: &OperatingState, cage_angle_rad: f32) {
        let centrifugal_n = self.params.centrifugal_force_n(state.shaft_speed_rad_s);
        let parts = Parts {
            params: &self.params,
            roller: &self.roller,
            pitch: &self.pitch,
        };
        let places = parts.places(state, cage_angle_rad);
        // The host runs the slice pass of eight rollers at a time in SIMD lanes (four without
        // AVX2), as the lubricated step does; the M4 one roller after another. Same operations,
        // same results bit for bit (`slicing`'s lane test).
        let mut loads = [crate::contact::RollerLoad::default(); Z];
        if LOCKSTEP {
            for (group, group_places) in loads.chunks_mut(WIDE_LANES).zip(places.chunks(WIDE_LANES))
            {
                let mut approach = [0.0; WIDE_LANES];
                let mut tilt = [0.0; WIDE_LANES];
                for ((a, t), place) in approach.iter_mut().zip(tilt.iter_mut()).zip(group_places) {
                    *a = place.geometric_m;
                    *t = place.tilt_rad;
                }
                let group_loads = self
                    .roller
                    .evaluate_lanes::<Wide, { WIDE_LANES }>(approach, tilt);
                for (i, load) in group.iter_mut().enumerate() {
                    *load = group_loads.lane(i);
                }
            }
        }
        parts.assemble(
            &mut self.memory,
            &mut self.output,
            state,
            cage_angle_rad,
            &places,
            |roller, _, j, geometric, tilt| {
                let slices = if LOCKSTEP {
                    loads.get(j).copied().unwrap_or_default()
                } else {
                    roller.evaluate(geometric, tilt)
                };
                let load = match centrifugal_n {
                    Some(f_c) => coupling::dry_centrifugal(roller, slices, geometric, f_c),
                    None => slices,
                };
                let roller = RollerOutput {
                    approach_m: geometric,
                    roller_stiffness_n_per_m: load.stiffness_n_per_m,
                    regime_in: Regime::Dry,
                    regime_out: Regime::Dry,
                    ..RollerOutput::ZERO
                };
                (load, roller, 0.0)
            },
        );
        self.output.totals.centrifugal_force_n = centrifugal_n.unwrap_or(0.0);
    }
}
