//! The host's roller solve: rollers side by side in SIMD lanes, and groups of them in flight
//! together.
//!
//! A roller's solve after its geometry — predicted approach, slice pass, power-law fit,
//! [`NEWTON_ITERATIONS`] Newton steps, finish and memory (`coupling`) — is the same
//! operations for every roller, so a superscalar host runs a group of rollers in the lanes of
//! one SIMD register (`crate::lanes`: eight with AVX2, else four), bit for bit as the
//! Cortex-M4 runs each alone. Most of those stages are chains of dependent operations
//! (exponentials, roots, divisions), whose latency one group leaves idle; several groups are
//! therefore taken through the stages together, each stage of the first followed by the same
//! stage of the next, so that the core overlaps their chains (out-of-order execution within a
//! few hundred instructions). The results are the lanes' results, whatever the grouping.
//!
//! Measured choices (best 1000-step chunk, 17 rollers, 10 slices, integer network, one pinned
//! core of the project's AMD EPYC host; the harness of the README's "Host build: AVX2 lanes"):
//! with four lanes, pairs of groups (pairs 1.43 µs, one group at a time 1.57 µs, three in
//! flight 1.44 µs). With eight lanes, 17
//! rollers took 1.21 µs one group at a time and 1.29 µs in pairs while the results were read
//! out lane by lane through a call per lane; reading each field's register once
//! (`store_rollers`, `store_lanes`, only for the group's rollers) made both ≈ 1.12 µs;
//! a last group of one roller in four lanes instead of eight then saved ≈ 80 ns (half the
//! idle lanes to gather and look up; alone on the scalar path it cost ≈ 20 ns more), taking
//! it through the stages with the group before it ≈ 90 ns more, and all three groups
//! together another ≈ 35 ns (1.02 → 0.99 µs; 13, 16 and 20 rollers gain 30–70 ns).

use super::coupling::{
    finish_lanes, predicted_approach, prepare_sliced, CoupledRoller, Prepared, RollerMemory,
    NEWTON_ITERATIONS,
};
use super::film_table::StepFilms;
use super::Place;
use crate::contact::{RollerLoads, SlicedRoller};
use crate::film::RegimeAxis;
use crate::lanes::{F32x4, Real, Wide, WIDE_LANES as LANES};

/// What the roller solve of a step reads: the roller, the step's films and regime axes.
pub(super) struct Lockstep<'a, const S: usize> {
    pub roller: &'a SlicedRoller<S>,
    pub films: &'a StepFilms<'a>,
    pub regime_axes: &'a [RegimeAxis; 2],
}

impl<const S: usize> Lockstep<'_, S> {
    /// Solve every roller at `places` from its warm start `memory` (updated): `out[j]` is
    /// roller j's result, whatever the grouping. (A short group fills its idle lanes with
    /// copies of its last roller, whose results are discarded.)
    pub(super) fn solve(
        &self,
        places: &[Place],
        memory: &mut [RollerMemory],
        out: &mut [CoupledRoller],
    ) {
        if LANES > 4 {
            self.solve_eights(Group {
                places,
                memory,
                out,
            });
        } else {
            self.solve_fours(Group {
                places,
                memory,
                out,
            });
        }
    }

    /// Eight lanes: up to three groups taken through the stages together (their work hides
    /// each other's chains' latency; 21 rollers, the most a bearing has, are three groups), a
    /// last group of four rollers or fewer in four lanes (`F32x4`: half the idle lanes to
    /// gather and look up).
    #[inline(always)]
    fn solve_eights(&self, rollers: Group<'_>) {
        let mut rest = rollers;
        while !rest.places.is_empty() {
            let (chunk, next) = rest.split_at(3 * LANES);
            rest = next;
            let count = chunk.places.len();
            let (a, b) = chunk.split_at(LANES);
            let (b, c) = b.split_at(LANES);
            if count <= 4 {
                self.solve_group::<F32x4, 4>(a);
            } else if count <= LANES {
                self.solve_group::<Wide, LANES>(a);
            } else if count <= LANES + 4 {
                self.solve_two::<Wide, LANES, F32x4, 4>(a, b);
            } else if count <= 2 * LANES {
                self.solve_two::<Wide, LANES, Wide, LANES>(a, b);
            } else if count <= 2 * LANES + 4 {
                self.solve_three::<Wide, LANES, F32x4, 4>([a, b], c);
            } else {
                self.solve_three::<Wide, LANES, Wide, LANES>([a, b], c);
            }
        }
    }

    /// Four lanes: two groups at a time, a last group alone if the groups are odd in number.
    #[inline(always)]
    fn solve_fours(&self, rollers: Group<'_>) {
        let Group {
            places,
            memory,
            out,
        } = rollers;
        for ((out, memory), places) in out
            .chunks_mut(2 * LANES)
            .zip(memory.chunks_mut(2 * LANES))
            .zip(places.chunks(2 * LANES))
        {
            let (a, b) = Group {
                places,
                memory,
                out,
            }
            .split_at(LANES);
            if b.places.is_empty() {
                self.solve_group::<Wide, LANES>(a);
            } else {
                self.solve_two::<Wide, LANES, Wide, LANES>(a, b);
            }
        }
    }

    /// Two groups, in the lanes of `A` and `B`, stage by stage. (Spelled out, without arrays
    /// of stages built by closures: in a build of several codegen units — the workspace's
    /// release profile — those closures stayed calls that passed the groups' state through
    /// memory.)
    #[inline(always)]
    fn solve_two<
        A: Real<PerLane<f32> = [f32; LA]>,
        const LA: usize,
        B: Real<PerLane<f32> = [f32; LB]>,
        const LB: usize,
    >(
        &self,
        a: Group<'_>,
        b: Group<'_>,
    ) {
        let (mut memory_a, geometric_a, approach_a, loads_a) = self.slice::<A, LA>(&a);
        let (mut memory_b, geometric_b, approach_b, loads_b) = self.slice::<B, LB>(&b);
        let mut prepared_a = prepare_sliced(loads_a, approach_a, geometric_a, &memory_a);
        let mut prepared_b = prepare_sliced(loads_b, approach_b, geometric_b, &memory_b);
        for _ in 0..NEWTON_ITERATIONS {
            prepared_a.newton.iterate_with(self.films);
            prepared_b.newton.iterate_with(self.films);
        }
        self.finish(&prepared_a, &mut memory_a, a);
        self.finish(&prepared_b, &mut memory_b, b);
    }

    /// Three groups, two in the lanes of `A` and the last in those of `C`, stage by stage.
    #[inline(always)]
    fn solve_three<
        A: Real<PerLane<f32> = [f32; LA]>,
        const LA: usize,
        C: Real<PerLane<f32> = [f32; LC]>,
        const LC: usize,
    >(
        &self,
        [a, b]: [Group<'_>; 2],
        c: Group<'_>,
    ) {
        let (mut memory_a, geometric_a, approach_a, loads_a) = self.slice::<A, LA>(&a);
        let (mut memory_b, geometric_b, approach_b, loads_b) = self.slice::<A, LA>(&b);
        let (mut memory_c, geometric_c, approach_c, loads_c) = self.slice::<C, LC>(&c);
        let mut prepared_a = prepare_sliced(loads_a, approach_a, geometric_a, &memory_a);
        let mut prepared_b = prepare_sliced(loads_b, approach_b, geometric_b, &memory_b);
        let mut prepared_c = prepare_sliced(loads_c, approach_c, geometric_c, &memory_c);
        for _ in 0..NEWTON_ITERATIONS {
            prepared_a.newton.iterate_with(self.films);
            prepared_b.newton.iterate_with(self.films);
            prepared_c.newton.iterate_with(self.films);
        }
        self.finish(&prepared_a, &mut memory_a, a);
        self.finish(&prepared_b, &mut memory_b, b);
        self.finish(&prepared_c, &mut memory_c, c);
    }

    /// One group of at most `L` rollers, in the lanes of `T`.
    #[inline(always)]
    fn solve_group<T: Real<PerLane<f32> = [f32; L]>, const L: usize>(&self, group: Group<'_>) {
        let (mut memory, geometric, approach1, loads) = self.slice::<T, L>(&group);
        let mut prepared = prepare_sliced(loads, approach1, geometric, &memory);
        for _ in 0..NEWTON_ITERATIONS {
            prepared.newton.iterate_with(self.films);
        }
        self.finish(&prepared, &mut memory, group);
    }

    /// A group's warm start and geometric approach in lanes, its predicted approach and its
    /// slice pass there.
    #[inline(always)]
    fn slice<T: Real<PerLane<f32> = [f32; L]>, const L: usize>(
        &self,
        group: &Group<'_>,
    ) -> (RollerMemory<T>, T, T, RollerLoads<T>) {
        let memory = RollerMemory::gather(group.memory);
        let geometric = T::gather(group.places, |p| p.geometric_m);
        let tilt = T::gather(group.places, |p| p.tilt_rad);
        let approach1 = predicted_approach(geometric, &memory);
        let loads = self
            .roller
            .evaluate_lanes::<T, L>(approach1.to_per_lane(), tilt.to_per_lane());
        (memory, geometric, approach1, loads)
    }
}

impl<const S: usize> Lockstep<'_, S> {
    /// A group's finish: its rollers' results and new warm starts, read out of the lanes once
    /// per field and only for the group's rollers.
    #[inline(always)]
    fn finish<T: Real>(
        &self,
        prepared: &Prepared<T>,
        memories: &mut RollerMemory<T>,
        group: Group<'_>,
    ) {
        let finished = if self.films.centrifugal() {
            finish_lanes::<T, true>(prepared, self.films, memories)
        } else {
            finish_lanes::<T, false>(prepared, self.films, memories)
        };
        finished.store_rollers(self.regime_axes, group.out);
        memories.store_lanes(group.memory);
    }
}

/// Rollers solved together — up to [`LANES`] in the lanes of one register, or a run of such
/// groups: where they are, their warm starts (updated) and their results.
struct Group<'a> {
    places: &'a [Place],
    memory: &'a mut [RollerMemory],
    out: &'a mut [CoupledRoller],
}

impl<'a> Group<'a> {
    /// The first `at` rollers (all if fewer) and the rest.
    #[inline(always)]
    fn split_at(self, at: usize) -> (Group<'a>, Group<'a>) {
        let (places_a, places_b) = self.places.split_at(at.min(self.places.len()));
        let (memory_a, memory_b) = self.memory.split_at_mut(at.min(self.memory.len()));
        let (out_a, out_b) = self.out.split_at_mut(at.min(self.out.len()));
        (
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
        )
    }
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
    /// M4's `prepare_roller`, Newton steps, `finish_roller`), bit for bit, for 25, 21, 17, 13,
    /// 20, 12, 9, 8 and 4 rollers: with eight lanes every grouping of `solve_eights` — three
    /// groups of eight and then one roller in four lanes, two of eight and five, two of eight
    /// and one or four in four lanes, eight and five, eight and one or four in four lanes, one
    /// group of eight, four in four lanes — and with four lanes pairs of groups, with a last
    /// group alone or short. Crowned hub-bearing rollers from separated (−9 µm) to heavily
    /// loaded (+12 µm at 17 rollers, +22 µm at 25), tilted both ways, over three steps from a
    /// cold start with the geometry moving. Every stage of the host's solve is in the chain: predicted approach,
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
                    let one = finish_roller::<false>(&p, &films, &axes, memory);
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
        check::<25>();
        check::<21>();
        check::<17>();
        check::<13>();
        check::<20>();
        check::<12>();
        check::<9>();
        check::<8>();
        check::<4>();
    }
}
