//! Slicing: the load, moment and stiffness of one roller from its slices (docs/physics.md §3).
//!
//! Slice k (centre x_k from the roller middle, length l/n_s) sees the approach
//! δ_k = δ + x_k·ψ − 2·P(x_k), with δ the roller's approach at its middle, ψ its tilt relative to
//! the raceway (tan ψ ≈ ψ: below 3·10⁻⁵ relative error for |ψ| ≤ 0.01 rad) and P the crown drop
//! (on both contacts, hence 2P). Only slices with δ_k > 0 carry load.

use super::law::{BoundLaw, ContactLaw, MAX_APPROACH_M};
use crate::lanes::Real;
use crate::math::{max, min, ninth_root_two_steps, select};
use crate::params::BearingGeometry;

/// Largest roller tilt the slice pass evaluates (rad): twice the largest the operating state
/// admits, which a roller sees as tilt_y·cos θ − tilt_x·sin θ.
const MAX_TILT_RAD: f32 = 2.0 * crate::params::MAX_TILT_RAD;

/// Load state of one roller, with the slice sums the stiffness matrix needs.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RollerLoad {
    /// Roller load Q = Σ q_k (N).
    pub load_n: f32,
    /// Roller moment T = Σ q_k x_k (N·m).
    pub moment_nm: f32,
    /// Contact stiffness K = dQ/dδ = Σ dq_k/dδ (N/m).
    pub stiffness_n_per_m: f32,
    /// Σ (dq_k/dδ)·x_k = dT/dδ = dQ/dψ (N).
    pub stiffness_moment_n: f32,
    /// Σ (dq_k/dδ)·x_k² = dT/dψ (N·m).
    pub stiffness_tilt_nm: f32,
    /// d²Q/dδ² = Σ d²q_k/dδ² (N/m²): the curvature used to fit a whole-roller power law.
    pub stiffness_derivative_n_per_m2: f32,
}

/// [`RollerLoad`] of one roller (`f32`) or of the rollers in the lanes of `T`, field by
/// field: what the host's lockstep stages pass on in registers.
#[derive(Clone, Copy, Debug)]
pub(crate) struct RollerLoads<T: Real> {
    pub load_n: T,
    pub moment_nm: T,
    pub stiffness_n_per_m: T,
    pub stiffness_moment_n: T,
    pub stiffness_tilt_nm: T,
    pub stiffness_derivative_n_per_m2: T,
}

impl<T: Real> RollerLoads<T> {
    /// The loads of single rollers side by side.
    #[inline(always)]
    pub(crate) fn from_lanes(loads: &T::PerLane<RollerLoad>) -> Self {
        Self {
            load_n: T::from_per_lane(loads, |l| l.load_n),
            moment_nm: T::from_per_lane(loads, |l| l.moment_nm),
            stiffness_n_per_m: T::from_per_lane(loads, |l| l.stiffness_n_per_m),
            stiffness_moment_n: T::from_per_lane(loads, |l| l.stiffness_moment_n),
            stiffness_tilt_nm: T::from_per_lane(loads, |l| l.stiffness_tilt_nm),
            stiffness_derivative_n_per_m2: T::from_per_lane(loads, |l| {
                l.stiffness_derivative_n_per_m2
            }),
        }
    }

    /// The load of the roller in lane `i`.
    #[inline(always)]
    pub(crate) fn lane(&self, i: usize) -> RollerLoad {
        RollerLoad {
            load_n: self.load_n.lane(i),
            moment_nm: self.moment_nm.lane(i),
            stiffness_n_per_m: self.stiffness_n_per_m.lane(i),
            stiffness_moment_n: self.stiffness_moment_n.lane(i),
            stiffness_tilt_nm: self.stiffness_tilt_nm.lane(i),
            stiffness_derivative_n_per_m2: self.stiffness_derivative_n_per_m2.lane(i),
        }
    }
}

/// A roller cut into `S` slices, bound to its contact law.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SlicedRoller<const S: usize> {
    law: BoundLaw,
    slice_length_m: f32,
    /// Slice centres x_k (m).
    positions_m: [f32; S],
    /// −2·P(x_k): the crown's contribution to each slice's approach (m, ≤ 0).
    crown_offsets_m: [f32; S],
    /// Approach at the roller middle where the first slice touches without tilt (m, ≥ 0).
    touch_approach_m: f32,
    /// ln of [`SlicedRoller::nominal_coefficient`].
    ln_nominal_coefficient: f32,
}

impl<const S: usize> SlicedRoller<S> {
    /// Slice a roller of `geometry` with reduced modulus `E'` (Pa) under `law`.
    ///
    /// `S = 0` is allowed and carries no load.
    pub fn new(geometry: &BearingGeometry, reduced_modulus_pa: f32, law: ContactLaw) -> Self {
        let l = geometry.roller_length_m();
        let bound = BoundLaw::new(
            law,
            l,
            reduced_modulus_pa,
            geometry.inner_reduced_radius_m(),
            geometry.outer_reduced_radius_m(),
        );
        let n = S.max(1) as f32;
        let slice_length_m = l / n;
        let mut positions_m = [0.0; S];
        let mut crown_offsets_m = [0.0; S];
        let mut touch = f32::MAX;
        for (k, (x, c)) in positions_m
            .iter_mut()
            .zip(crown_offsets_m.iter_mut())
            .enumerate()
        {
            *x = (k as f32 + 0.5) * slice_length_m - 0.5 * l;
            *c = -2.0 * geometry.crown_drop_m(*x);
            touch = touch.min(-*c);
        }
        let nominal = bound.palmgren_coefficient() * slice_length_m * S as f32;
        Self {
            law: bound,
            slice_length_m,
            positions_m,
            crown_offsets_m,
            touch_approach_m: if S == 0 { 0.0 } else { touch },
            ln_nominal_coefficient: crate::math::ln(nominal),
        }
    }

    /// Slice centres x_k (m).
    pub fn positions_m(&self) -> &[f32; S] {
        &self.positions_m
    }

    /// Approach at which the first slice touches an untilted roller (m).
    pub fn touch_approach_m(&self) -> f32 {
        self.touch_approach_m
    }

    /// Whole-roller coefficient c of Q = c·δ^(10/9) for a straight roller under the Palmgren
    /// law (N/m^(10/9)).
    pub fn nominal_coefficient(&self) -> f32 {
        self.law.palmgren_coefficient() * self.slice_length_m * S as f32
    }

    /// ln of the nominal coefficient (precomputed).
    pub fn ln_nominal_coefficient(&self) -> f32 {
        self.ln_nominal_coefficient
    }

    /// Load, moment and stiffness for approach `δ` (m) at the roller middle and tilt `ψ` (rad).
    /// Every slice is evaluated whatever the input, so the cost is fixed.
    #[inline]
    pub fn evaluate(&self, approach_m: f32, tilt_rad: f32) -> RollerLoad {
        match self.law.kind() {
            ContactLaw::Palmgren => self.evaluate_palmgren(approach_m, tilt_rad),
            ContactLaw::Lundberg => self.evaluate_any(approach_m, tilt_rad),
        }
    }

    /// [`SlicedRoller::evaluate`] for the `L` rollers in the lanes of `T` (the host's: four,
    /// or eight with AVX2), all of this shape, at approaches `approach_m` and tilts
    /// `tilt_rad`, bit for bit, as SIMD lanes: the host's slice pass. The Palmgren pass runs
    /// the rollers side by side (`evaluate_palmgren_lanes`).
    #[inline(always)]
    pub(crate) fn evaluate_lanes<T: Real<PerLane<f32> = [f32; L]>, const L: usize>(
        &self,
        approach_m: [f32; L],
        tilt_rad: [f32; L],
    ) -> RollerLoads<T> {
        match self.law.kind() {
            ContactLaw::Palmgren => self.evaluate_palmgren_lanes(approach_m, tilt_rad),
            ContactLaw::Lundberg => RollerLoads::from_lanes(&T::build(|l| {
                self.evaluate_any(
                    approach_m.get(l).copied().unwrap_or(0.0),
                    tilt_rad.get(l).copied().unwrap_or(0.0),
                )
            })),
        }
    }

    /// [`SlicedRoller::evaluate`] under the Palmgren law w = c·δ^(10/9), with its derivatives
    /// (10/9)·w/δ and (10/81)·w/δ²: with r = δ^(1/9) the slice sums are taken of w = δ·r,
    /// w/δ = r and w/δ² = r/δ, and the constants (c, the slice length, 10/9, 10/81) applied
    /// once to the sums — the real-time step's slice pass, half the cost of the general loop.
    /// The roller's approach and tilt are held to [`MAX_APPROACH_M`] and [`MAX_TILT_RAD`]
    /// once, so that every slice's approach is ≤ 1.1 cm (in the root's range) and a slice
    /// needs only its sign tested.
    #[inline]
    fn evaluate_palmgren(&self, approach_m: f32, tilt_rad: f32) -> RollerLoad {
        let (approach_m, tilt_rad) = bounded(approach_m, tilt_rad);
        let mut sums = PalmgrenSums::zero();
        for (&x, &c) in self.positions_m.iter().zip(self.crown_offsets_m.iter()) {
            let (d, r) = slice_root(approach_m + x * tilt_rad + c);
            sums.add(d, r, x);
        }
        self.load_from(&sums).lane(0)
    }

    /// [`SlicedRoller::evaluate`] under the Palmgren law for `L` rollers of this shape at
    /// once, with each roller's operations the same and in the same order as alone (so the
    /// results are the same bit for bit). The roots of all slices come first, then the sums:
    /// with no dependence between the slices' roots, the host runs the lanes as SIMD lanes and
    /// overlaps the slices (2.1× the speed of one roller at a time for 17 rollers). The M4
    /// gains nothing and would pay for the staged roots, so it runs one roller at a time.
    #[inline(always)]
    fn evaluate_palmgren_lanes<T: Real<PerLane<f32> = [f32; L]>, const L: usize>(
        &self,
        approach_m: [f32; L],
        tilt_rad: [f32; L],
    ) -> RollerLoads<T> {
        let mut bounds = [(0.0f32, 0.0f32); L];
        for ((b, &a), &t) in bounds
            .iter_mut()
            .zip(approach_m.iter())
            .zip(tilt_rad.iter())
        {
            *b = bounded(a, t);
        }
        let mut approach = [[0.0f32; L]; S];
        let mut root = [[0.0f32; L]; S];
        for (((d, r), &x), &c) in approach
            .iter_mut()
            .zip(root.iter_mut())
            .zip(self.positions_m.iter())
            .zip(self.crown_offsets_m.iter())
        {
            for ((d, r), &(a, t)) in d.iter_mut().zip(r.iter_mut()).zip(bounds.iter()) {
                (*d, *r) = slice_root(a + x * t + c);
            }
        }
        let mut sums = PalmgrenSums::<T>::zero();
        for ((d, r), &x) in approach
            .iter()
            .zip(root.iter())
            .zip(self.positions_m.iter())
        {
            sums.add(
                T::from_per_lane(d, |&v| v),
                T::from_per_lane(r, |&v| v),
                T::splat(x),
            );
        }
        self.load_from(&sums)
    }

    /// The roller's load from its Palmgren slice sums (of the rollers in the lanes of `T`).
    #[inline(always)]
    fn load_from<T: Real>(&self, sums: &PalmgrenSums<T>) -> RollerLoads<T> {
        let PalmgrenSums([sw, swx, sk, skx, skxx, sk2]) = *sums;
        let scale = self.law.palmgren_coefficient() * self.slice_length_m;
        let k_scale = T::splat((10.0 / 9.0) * scale);
        RollerLoads {
            load_n: sw * T::splat(scale),
            moment_nm: swx * T::splat(scale),
            stiffness_n_per_m: sk * k_scale,
            stiffness_moment_n: skx * k_scale,
            stiffness_tilt_nm: skxx * k_scale,
            stiffness_derivative_n_per_m2: sk2 * T::splat((10.0 / 81.0) * scale),
        }
    }

    /// [`SlicedRoller::evaluate`] for any law, slice by slice.
    #[inline]
    fn evaluate_any(&self, approach_m: f32, tilt_rad: f32) -> RollerLoad {
        let mut out = RollerLoad::default();
        for (&x, &c) in self.positions_m.iter().zip(self.crown_offsets_m.iter()) {
            let (w, dw, d2w) = self.law.load_per_length(approach_m + x * tilt_rad + c);
            let q = w * self.slice_length_m;
            let dq = dw * self.slice_length_m;
            out.stiffness_derivative_n_per_m2 += d2w * self.slice_length_m;
            out.load_n += q;
            out.moment_nm += q * x;
            out.stiffness_n_per_m += dq;
            out.stiffness_moment_n += dq * x;
            out.stiffness_tilt_nm += dq * x * x;
        }
        out
    }
}

/// A roller's approach and tilt held to [`MAX_APPROACH_M`] and [`MAX_TILT_RAD`] once, so
/// that every slice's approach is ≤ 1.1 cm (in the root's range) and a slice needs only its
/// sign tested. `min`/`max` take the bound for NaN: hostile input stays finite.
#[inline(always)]
fn bounded(approach_m: f32, tilt_rad: f32) -> (f32, f32) {
    (
        min(approach_m, MAX_APPROACH_M),
        min(max(tilt_rad, -MAX_TILT_RAD), MAX_TILT_RAD),
    )
}

/// A slice's approach δ_k (m), floored where it does not touch, and r = δ_k^(1/9) there
/// (0 where it does not touch), to within 10⁻⁴ (`math::ninth_root_two_steps`).
#[inline(always)]
fn slice_root(slice_approach: f32) -> (f32, f32) {
    let touching = slice_approach > 0.0;
    let d = select(touching, slice_approach, 1.0e-12);
    // The mask multiplies: the root stays in the data flow, the work is fixed.
    (
        d,
        ninth_root_two_steps(d) * if touching { 1.0 } else { 0.0 },
    )
}

/// Σ w, Σ w·x, Σ r, Σ r·x, Σ r·x², Σ r/δ over the slices, with w = δ·r (see
/// [`SlicedRoller::evaluate`] under the Palmgren law), of one roller (`f32`) or of the rollers
/// in SIMD lanes (`crate::lanes`; each lane the one-roller sums bit for bit).
#[derive(Clone, Copy)]
struct PalmgrenSums<T: Real = f32>([T; 6]);

impl<T: Real> PalmgrenSums<T> {
    #[inline(always)]
    fn zero() -> Self {
        Self([T::splat(0.0); 6])
    }

    #[inline(always)]
    fn add(&mut self, d: T, r: T, x: T) {
        let [sw, swx, sk, skx, skxx, sk2] = &mut self.0;
        let w = d * r;
        *sw = *sw + w;
        *swx = *swx + w * x;
        *sk = *sk + r;
        let rx = r * x;
        *skx = *skx + rx;
        *skxx = *skxx + rx * x;
        *sk2 = *sk2 + r / d;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::Crown;

    fn geometry(crown: Crown) -> BearingGeometry {
        BearingGeometry::new(0.060, 0.0088, 0.015, 17, crown, 0.0).unwrap()
    }

    const E: f32 = 230.77e9;

    /// The lanes of `evaluate_lanes` are the one-roller pass bit for bit: crowned and straight
    /// rollers, both laws, 17 rollers in groups of four lanes and, where the build has AVX2,
    /// of eight (a short last group, idle lanes at zero approach), approaches from separated
    /// to deep, tilts of both signs, and NaN.
    #[test]
    fn evaluate_lanes_is_evaluate_bit_for_bit() {
        for crown in [Crown::None, Crown::Logarithmic { scale: 1.0 }] {
            for law in [ContactLaw::Palmgren, ContactLaw::Lundberg] {
                let roller = SlicedRoller::<10>::new(&geometry(crown), E, law);
                let mut approach = [0.0f32; 17];
                let mut tilt = [0.0f32; 17];
                for (j, (a, t)) in approach.iter_mut().zip(tilt.iter_mut()).enumerate() {
                    *a = 2.0e-6 * (j as f32 - 5.0);
                    *t = 3.0e-4 * ((j % 5) as f32 - 2.0);
                }
                approach[3] = f32::NAN;
                tilt[16] = f32::NAN;
                // Four lanes, and eight where the build has them: each against one roller.
                let mut widths = std::vec![[RollerLoad::default(); 17]];
                lanes_in_groups::<crate::lanes::F32x4, 4, 10>(
                    &roller,
                    &approach,
                    &tilt,
                    &mut widths[0],
                );
                #[cfg(all(target_arch = "x86_64", target_feature = "avx2"))]
                {
                    let mut eight = [RollerLoad::default(); 17];
                    lanes_in_groups::<crate::lanes::F32x8, 8, 10>(
                        &roller, &approach, &tilt, &mut eight,
                    );
                    widths.push(eight);
                }
                for many in &widths {
                    for ((m, &a), &t) in many.iter().zip(&approach).zip(&tilt) {
                        let one = roller.evaluate(a, t);
                        let bits = |l: &RollerLoad| {
                            [
                                l.load_n,
                                l.moment_nm,
                                l.stiffness_n_per_m,
                                l.stiffness_moment_n,
                                l.stiffness_tilt_nm,
                                l.stiffness_derivative_n_per_m2,
                            ]
                            .map(f32::to_bits)
                        };
                        assert_eq!(bits(m), bits(&one), "δ = {a}, ψ = {t}");
                        assert!(m.load_n.is_finite());
                    }
                    assert!(many.iter().any(|m| m.load_n > 0.0));
                }
            }
        }
    }

    /// `out[j]` = the lanes' load of roller j, `L` rollers at a time in the lanes of `T`.
    fn lanes_in_groups<T: Real<PerLane<f32> = [f32; L]>, const L: usize, const S: usize>(
        roller: &SlicedRoller<S>,
        approach: &[f32],
        tilt: &[f32],
        out: &mut [RollerLoad],
    ) {
        for ((out, a), t) in out
            .chunks_mut(L)
            .zip(approach.chunks(L))
            .zip(tilt.chunks(L))
        {
            let lanes = |v: &[f32]| core::array::from_fn(|l| v.get(l).copied().unwrap_or(0.0));
            let loads = roller.evaluate_lanes::<T, L>(lanes(a), lanes(t));
            for (l, o) in out.iter_mut().enumerate() {
                *o = loads.lane(l);
            }
        }
    }

    #[test]
    fn uniform_approach_gives_the_same_load_for_1_10_and_50_slices() {
        let g = geometry(Crown::None);
        for law in [ContactLaw::Palmgren, ContactLaw::Lundberg] {
            let q1 = SlicedRoller::<1>::new(&g, E, law)
                .evaluate(5e-6, 0.0)
                .load_n;
            let q10 = SlicedRoller::<10>::new(&g, E, law)
                .evaluate(5e-6, 0.0)
                .load_n;
            let q50 = SlicedRoller::<50>::new(&g, E, law)
                .evaluate(5e-6, 0.0)
                .load_n;
            assert!(q1 > 100.0);
            assert!((q10 / q1 - 1.0).abs() < 1e-3, "{law:?}: {q1} {q10}");
            assert!((q50 / q1 - 1.0).abs() < 1e-3, "{law:?}: {q1} {q50}");
        }
    }

    #[test]
    fn tilted_roller_moment_matches_the_integral_of_the_load_distribution() {
        // Closed form for a straight roller under the power law w = c·(δ + xψ)^(10/9), fully
        // loaded: Q = c/(ψ·a)·[(δ+ψl/2)^a − (δ−ψl/2)^a] with a = 19/9, and
        // T = ∫x·w dx = c·[ (u^(a+1)/(a+1) − δ·u^a/a) / ψ² ] between the ends, u = δ + xψ.
        let g = geometry(Crown::None);
        let roller = SlicedRoller::<400>::new(&g, E, ContactLaw::Palmgren);
        let c = roller.law.palmgren_coefficient() as f64;
        let (delta, psi, l) = (6e-6f64, 4e-4f64, 0.015f64);
        let a = 19.0 / 9.0;
        let prim_q = |u: f64| c * u.powf(a) / (a * psi);
        let prim_t =
            |u: f64| c * (u.powf(a + 1.0) / (a + 1.0) - delta * u.powf(a) / a) / (psi * psi);
        let (lo, hi) = (delta - psi * l / 2.0, delta + psi * l / 2.0);
        assert!(lo > 0.0, "fully loaded case");
        let q_exact = prim_q(hi) - prim_q(lo);
        let t_exact = prim_t(hi) - prim_t(lo);
        let r = roller.evaluate(delta as f32, psi as f32);
        assert!(
            (r.load_n as f64 / q_exact - 1.0).abs() < 1e-3,
            "{} vs {q_exact}",
            r.load_n
        );
        assert!(
            (r.moment_nm as f64 / t_exact - 1.0).abs() < 2e-3,
            "{} vs {t_exact}",
            r.moment_nm
        );
        // And the 10-slice default is within 1 % of the integral.
        let r10 =
            SlicedRoller::<10>::new(&g, E, ContactLaw::Palmgren).evaluate(delta as f32, psi as f32);
        assert!(
            (r10.moment_nm as f64 / t_exact - 1.0).abs() < 0.01,
            "{} vs {t_exact}",
            r10.moment_nm
        );
    }

    #[test]
    fn stiffness_is_the_derivative_of_load_and_moment() {
        let g = geometry(Crown::Logarithmic { scale: 1.0 });
        let roller = SlicedRoller::<10>::new(&g, E, ContactLaw::Palmgren);
        let (d, p) = (8e-6f32, 3e-4f32);
        let r = roller.evaluate(d, p);
        let h = 1e-8f32;
        let dq = (roller.evaluate(d + h, p).load_n - roller.evaluate(d - h, p).load_n) / (2.0 * h);
        assert!(
            (r.stiffness_n_per_m / dq - 1.0).abs() < 2e-3,
            "{} vs {dq}",
            r.stiffness_n_per_m
        );
        let hp = 1e-6f32;
        let dt = (roller.evaluate(d, p + hp).moment_nm - roller.evaluate(d, p - hp).moment_nm)
            / (2.0 * hp);
        assert!(
            (r.stiffness_tilt_nm / dt - 1.0).abs() < 5e-3,
            "{} vs {dt}",
            r.stiffness_tilt_nm
        );
    }

    #[test]
    fn crown_unloads_the_ends() {
        let g = geometry(Crown::Logarithmic { scale: 1.0 });
        let crowned = SlicedRoller::<10>::new(&g, E, ContactLaw::Palmgren);
        let straight = SlicedRoller::<10>::new(&geometry(Crown::None), E, ContactLaw::Palmgren);
        let a = crowned.evaluate(5e-6, 0.0).load_n;
        let b = straight.evaluate(5e-6, 0.0).load_n;
        assert!(a < b && a > 0.5 * b, "{a} {b}");
        assert!(crowned.touch_approach_m() > 0.0);
    }
}
