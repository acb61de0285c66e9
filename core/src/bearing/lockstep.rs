//! The host's roller solve: rollers side by side in SIMD lanes, and groups of them in flight
//! together.
//!
//! A roller's solve after its geometry — predicted approach, slice pass, power-law fit,
//! [`NEWTON_ITERATIONS`] Newton steps, finish and memory (`coupling`) — is the same
//! operations for every roller, so a superscalar host runs four rollers in the lanes of one
//! SIMD register (`crate::lanes`), bit for bit as the Cortex-M4 runs each alone. Most of
//! those stages are chains of dependent operations (exponentials, roots, divisions), whose
//! latency one group of four leaves idle; two groups are therefore taken through the stages
//! together, each stage of the first followed by the same stage of the second, so that the
//! core overlaps their chains (out-of-order execution within a few hundred instructions).
//! The results are the lanes' results, whatever the grouping.

use super::coupling::{
    finish_lanes, predicted_approach, prepare_sliced, CoupledRoller, Prepared, RollerMemory,
    NEWTON_ITERATIONS,
};
use super::film_table::StepFilms;
use super::Place;
use crate::contact::{RollerLoads, SlicedRoller};
use crate::film::RegimeAxis;
use crate::lanes::{Real, Wide, WIDE_LANES as LANES};

/// What the roller solve of a step reads: the roller, the step's films and regime axes.
pub(super) struct Lockstep<'a, const S: usize> {
    pub roller: &'a SlicedRoller<S>,
    pub films: &'a StepFilms<'a>,
    pub regime_axes: &'a [RegimeAxis; 2],
}

impl<const S: usize> Lockstep<'_, S> {
    /// Solve every roller at `places` from its warm start `memory` (updated): `out[j]` is
    /// roller j's result. Two groups at a time; a last group alone if the groups are odd in
    /// number. (A short group fills its idle lanes with copies of its last roller, whose
    /// results are discarded.)
    pub(super) fn solve(
        &self,
        places: &[Place],
        memory: &mut [RollerMemory],
        out: &mut [CoupledRoller],
    ) {
        for ((out, memory), places) in out
            .chunks_mut(2 * LANES)
            .zip(memory.chunks_mut(2 * LANES))
            .zip(places.chunks(2 * LANES))
        {
            if places.len() > LANES {
                let (places_a, places_b) = places.split_at(LANES);
                let (memory_a, memory_b) = memory.split_at_mut(LANES.min(memory.len()));
                let (out_a, out_b) = out.split_at_mut(LANES.min(out.len()));
                self.solve_pair([
                    Group {
                        places: places_a,
                        memory: memory_a,
                        out: out_a,
                    },
                    Group {
                        places: places_b,
                        memory: memory_b,
                        out: out_b,
                    },
                ]);
            } else {
                self.solve_one(Group {
                    places,
                    memory,
                    out,
                });
            }
        }
    }

    /// Two groups, stage by stage. (Spelled out, without arrays of stages built by closures:
    /// in a build of several codegen units — the workspace's release profile — those closures
    /// stayed calls that passed the groups' state through memory.)
    #[inline(always)]
    fn solve_pair(&self, [a, b]: [Group<'_>; 2]) {
        let (mut memory_a, geometric_a, approach_a, loads_a) = self.slice(&a);
        let (mut memory_b, geometric_b, approach_b, loads_b) = self.slice(&b);
        let mut prepared_a = prepare_sliced(loads_a, approach_a, geometric_a, &memory_a);
        let mut prepared_b = prepare_sliced(loads_b, approach_b, geometric_b, &memory_b);
        for _ in 0..NEWTON_ITERATIONS {
            prepared_a.newton.iterate(self.films);
            prepared_b.newton.iterate(self.films);
        }
        self.finish(&prepared_a, &mut memory_a, a);
        self.finish(&prepared_b, &mut memory_b, b);
    }

    /// One group.
    #[inline(always)]
    fn solve_one(&self, group: Group<'_>) {
        let (mut memory, geometric, approach1, loads) = self.slice(&group);
        let mut prepared = prepare_sliced(loads, approach1, geometric, &memory);
        for _ in 0..NEWTON_ITERATIONS {
            prepared.newton.iterate(self.films);
        }
        self.finish(&prepared, &mut memory, group);
    }

    /// A group's warm start and geometric approach in lanes, its predicted approach and its
    /// slice pass there.
    #[inline(always)]
    fn slice(&self, group: &Group<'_>) -> (RollerMemory<Wide>, Wide, Wide, RollerLoads<Wide>) {
        let memory = RollerMemory::gather(group.memory);
        let geometric = Wide::gather(group.places, |p| p.geometric_m);
        let tilt = Wide::gather(group.places, |p| p.tilt_rad);
        let approach1 = predicted_approach(geometric, &memory);
        let loads = self
            .roller
            .evaluate_lanes(approach1.to_array(), tilt.to_array());
        (memory, geometric, approach1, loads)
    }

    /// A group's finish: its rollers' results and new warm starts, each lane taken apart once,
    /// at a lane index known to the compiler.
    #[inline(always)]
    fn finish(
        &self,
        prepared: &Prepared<Wide>,
        memories: &mut RollerMemory<Wide>,
        group: Group<'_>,
    ) {
        let finished = finish_lanes(prepared, self.films, memories);
        let rollers = Wide::build(|i| finished.roller(i, self.regime_axes));
        let new = Wide::build(|i| memories.lane(i));
        for ((o, m), (roller, new)) in group
            .out
            .iter_mut()
            .zip(group.memory.iter_mut())
            .zip(rollers.iter().zip(new.iter()))
        {
            *o = *roller;
            *m = *new;
        }
    }
}

/// Up to [`LANES`] rollers solved in the lanes of one register: where they are, their warm
/// starts (updated) and their results.
struct Group<'a> {
    places: &'a [Place],
    memory: &'a mut [RollerMemory],
    out: &'a mut [CoupledRoller],
}

#[cfg(test)]
mod tests {
    use super::super::coupling::{finish_roller, prepare_roller};
    use super::super::film_table::tests::{contacts_with, martin};
    use super::super::film_table::FilmTable;
    use super::*;
    use crate::contact::ContactLaw;
    use crate::film::Regression;
    use crate::params::{reduced_modulus, BearingGeometry, Crown, Material};

    /// The grouped lanes give every roller the result and the memory of its solve alone (the
    /// M4's `prepare_roller`, Newton steps, `finish_roller`), bit for bit: 17 rollers (two
    /// pairs of groups and a last group of one) and 13 (a pair, then a pair whose second
    /// group has one roller), crowned hub-bearing rollers from separated (−9 µm) to heavily
    /// loaded (+12 µm), tilted both ways, over three steps from a cold start with the
    /// geometry moving. Every stage of the host's solve is in the chain: predicted approach,
    /// slice pass (`evaluate_lanes`), power-law fit and start (`prepare_sliced`), Newton
    /// steps, finish and memory (`finish_lanes`), groups and idle lanes.
    #[test]
    fn grouped_lanes_solve_each_roller_bit_for_bit() {
        fn check<const Z: usize>() {
            let geometry = BearingGeometry::new(
                0.060,
                0.0088,
                0.015,
                17,
                Crown::Logarithmic { scale: 1.0 },
                -2.0e-6,
            )
            .unwrap();
            let modulus = reduced_modulus(&Material::STEEL, &Material::STEEL);
            let roller = SlicedRoller::<10>::new(&geometry, modulus, ContactLaw::Palmgren);
            let contacts = contacts_with(6.0, modulus);
            let mut table = FilmTable::default();
            let films = table.step(&Regression, contacts, martin(&contacts), (2.0, 9.0), true);
            let axes = [RegimeAxis::new(6.0, 1.5), RegimeAxis::new(5.5, 1.6)];
            let lockstep = Lockstep {
                roller: &roller,
                films: &films,
                regime_axes: &axes,
            };
            let mut alone = [RollerMemory::cold(&roller); Z];
            let mut grouped = alone;
            let mut carrying = 0;
            for step in 0..3 {
                let places: [Place; Z] = core::array::from_fn(|j| Place {
                    // Moved by ±0.4 µm a step: the warm start's prediction is off both
                    // ways (rollers moving out see their film over-predicted).
                    geometric_m: 1.3e-6 * (j as f32 - 7.0)
                        + 0.4e-6 * step as f32 * if j % 2 == 0 { 1.0 } else { -1.0 },
                    tilt_rad: 2.0e-4 * ((j % 5) as f32 - 2.0),
                    ..Place::default()
                });
                let mut out = [CoupledRoller::default(); Z];
                lockstep.solve(&places, &mut grouped, &mut out);
                for (j, ((place, memory), from_lanes)) in places
                    .iter()
                    .zip(alone.iter_mut())
                    .zip(out.iter())
                    .enumerate()
                {
                    let mut p = prepare_roller(&roller, place.geometric_m, place.tilt_rad, memory);
                    for _ in 0..NEWTON_ITERATIONS {
                        p.newton.iterate(&films);
                    }
                    let one = finish_roller(&p, &films, &axes, memory);
                    carrying += usize::from(one.load.load_n > 1.0);
                    // Debug output prints every field (floats to the last bit that tells them
                    // apart) and the regimes.
                    assert_eq!(
                        std::format!("{from_lanes:?}"),
                        std::format!("{one:?}"),
                        "Z = {Z}, step {step}, roller {j}"
                    );
                    assert_eq!(
                        std::format!("{:?}", grouped[j]),
                        std::format!("{memory:?}"),
                        "Z = {Z}, step {step}, roller {j}"
                    );
                }
            }
            assert!(carrying > 3 && carrying < 3 * Z - 3, "{carrying}");
        }
        check::<17>();
        check::<13>();
        check::<9>();
        check::<8>();
    }
}
