//! Four or eight f32 lanes side by side, and the arithmetic the step's lockstep stages share
//! with the one-number code.
//!
//! Some stages of a step are the same chain of dependent operations for every roller (the
//! film–load Newton iterations: two exponentials, two roots, three divisions each). A
//! superscalar host cannot overlap enough of those chains across rollers to hide their
//! latency, but it can run four or eight of them in the lanes of one SIMD register. [`Real`] is
//! what such a stage is written against: `f32` (one roller; the Cortex-M4 path; its
//! implementation is the one-number arithmetic of `crate::math`), [`F32x4`]
//! (four rollers; SSE on x86-64, a plain lane loop elsewhere) and, in builds with AVX2,
//! `F32x8` (eight rollers in a 256-bit register) implement it with the same IEEE operations —
//! `+ − × ÷`, square root, compare-and-select, and integer arithmetic on the bit pattern — so
//! a lane's result is the one-roller result bit for bit (no fused or approximate instructions;
//! the tests compare every operation). [`Wide`] is the widest of them the build has: the
//! host's lane type.

use core::ops::{Add, BitAnd, Div, Mul, Neg, Sub};

/// An f32 or f32 lanes: the operations the lockstep stages use, each IEEE-exact per lane.
pub(crate) trait Real:
    Copy
    + core::fmt::Debug
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// Lanes (rollers) side by side: 1 for one number.
    const LANES: usize;
    /// One truth value per lane.
    type Mask: Copy + BitAnd<Output = Self::Mask>;
    /// One `U` per lane.
    type PerLane<U: Copy + Default + core::fmt::Debug>: Copy + core::fmt::Debug;
    /// `v` in every lane.
    fn splat(v: f32) -> Self;
    /// `self > other` per lane (false where either is NaN).
    fn gt(self, other: Self) -> Self::Mask;
    /// `self >= other` per lane.
    fn ge(self, other: Self) -> Self::Mask;
    /// `self <= other` per lane.
    fn le(self, other: Self) -> Self::Mask;
    /// `self < other` per lane.
    fn lt(self, other: Self) -> Self::Mask;
    /// `self == other` per lane.
    fn eq(self, other: Self) -> Self::Mask;
    /// 1.0 where `mask`, else 0.0.
    fn indicator(mask: Self::Mask) -> Self;
    /// Each lane, in [0, 2²⁴), truncated to an integer: as an index, and as a float.
    fn truncate_index(self) -> (Self::PerLane<usize>, Self);
    /// `a` where `mask`, else `b`, by bit masks (`crate::math::select`).
    fn select(mask: Self::Mask, a: Self, b: Self) -> Self;
    /// `a` where `mask`, else `b`: [`Real::select`]'s result, as a plain choice for one
    /// number (a conditional move where `select` spends bit operations).
    fn choose(mask: Self::Mask, a: Self, b: Self) -> Self;
    /// `crate::math::max` per lane: `self` if `self > other`, else `other`.
    fn max(self, other: Self) -> Self;
    /// `crate::math::min` per lane: `self` if `self < other`, else `other`.
    fn min(self, other: Self) -> Self;
    /// IEEE square root of non-negative lanes.
    fn sqrt_non_negative(self) -> Self;
    /// `crate::math::split_normal` per lane: the mantissa re-centred to [√½, √2) and the
    /// matching exponent, as a float, of positive normal lanes (integer arithmetic on the bit
    /// pattern).
    fn split_normal(self) -> (Self, Self);
    /// `crate::math::round_with_pow2` per lane.
    fn round_with_pow2(self) -> (Self, Self);
    /// Lanes from `f` of each per-lane item.
    fn from_per_lane<U: Copy + Default + core::fmt::Debug>(
        items: &Self::PerLane<U>,
        f: impl FnMut(&U) -> f32,
    ) -> Self;
    /// Lane `i` (0 beyond the lanes).
    fn lane(self, i: usize) -> f32;
    /// The lanes as per-lane items, to be read lane by lane with [`Real::item`] (one store of
    /// the register, where [`Real::lane`] of each lane would store it once per lane).
    fn to_per_lane(self) -> Self::PerLane<f32>;
    /// Item `i` of per-lane items (the default beyond the lanes).
    fn item<U: Copy + Default + core::fmt::Debug>(items: &Self::PerLane<U>, i: usize) -> U;
    /// Per-lane items `f(i)` of lanes `i` = 0, 1, ….
    fn build<U: Copy + Default + core::fmt::Debug>(f: impl FnMut(usize) -> U) -> Self::PerLane<U>;
    /// Lanes `f` of a group's items, lane `i` from item `i`: the lanes beyond a short group
    /// repeat its last item (realistic numbers for idle lanes, whose results are discarded);
    /// 0 for an empty group.
    fn gather<U>(items: &[U], f: impl Fn(&U) -> f32) -> Self;
}

pub(crate) use simd::{F32x4, Mask4};

#[cfg(all(target_arch = "x86_64", target_feature = "avx2"))]
pub(crate) use avx::{F32x8, Mask8};

/// 1.5·2²³: adding and subtracting it rounds an f32 of magnitude < 2²² to the nearest integer
/// (`crate::math::round_with_pow2` and its lane copies in the backends).
pub(crate) const ROUNDER: f32 = 12_582_912.0;

/// The host's lane type for the lockstep stages: the widest register the build may use —
/// eight lanes (`F32x8`) where AVX2 is enabled (the workspace's `.cargo/config.toml` enables
/// it for x86-64 Linux hosts), else four ([`F32x4`]: SSE on any x86-64, an array elsewhere).
#[cfg(all(target_arch = "x86_64", target_feature = "avx2"))]
pub(crate) type Wide = F32x8;
/// The host's lane type for the lockstep stages (four lanes: this build has no AVX2).
#[cfg(not(all(target_arch = "x86_64", target_feature = "avx2")))]
pub(crate) type Wide = F32x4;

/// Rollers in the lanes of one [`Wide`] register.
pub(crate) const WIDE_LANES: usize = <Wide as Real>::LANES;

/// `Real` for a lane type whose backend module `$simd` gives the per-lane primitives; what
/// handles the lanes as an array is the same for every width and is written here once, with
/// the lanes spelled out (`$v` bound to lane `$i`).
macro_rules! real_lanes {
    ($lanes:ty, $mask:ty, $simd:ident, $n:literal, [$($v:ident = $i:literal),+]) => {
        impl Real for $lanes {
            const LANES: usize = $n;
            type Mask = $mask;
            type PerLane<U: Copy + Default + core::fmt::Debug> = [U; $n];
            #[inline(always)]
            fn splat(v: f32) -> Self {
                $simd::splat(v)
            }
            #[inline(always)]
            fn gt(self, other: Self) -> $mask {
                $simd::gt(self, other)
            }
            #[inline(always)]
            fn ge(self, other: Self) -> $mask {
                $simd::ge(self, other)
            }
            #[inline(always)]
            fn le(self, other: Self) -> $mask {
                $simd::le(self, other)
            }
            #[inline(always)]
            fn lt(self, other: Self) -> $mask {
                $simd::lt(self, other)
            }
            #[inline(always)]
            fn eq(self, other: Self) -> $mask {
                $simd::eq(self, other)
            }
            #[inline(always)]
            fn indicator(mask: $mask) -> Self {
                $simd::indicator(mask)
            }
            #[inline(always)]
            fn truncate_index(self) -> ([usize; $n], Self) {
                $simd::truncate_index(self)
            }
            #[inline(always)]
            fn select(mask: $mask, a: Self, b: Self) -> Self {
                $simd::select(mask, a, b)
            }
            #[inline(always)]
            fn choose(mask: $mask, a: Self, b: Self) -> Self {
                $simd::select(mask, a, b)
            }
            #[inline(always)]
            fn max(self, other: Self) -> Self {
                $simd::max(self, other)
            }
            #[inline(always)]
            fn min(self, other: Self) -> Self {
                $simd::min(self, other)
            }
            #[inline(always)]
            fn sqrt_non_negative(self) -> Self {
                $simd::sqrt_non_negative(self)
            }
            #[inline(always)]
            fn split_normal(self) -> (Self, Self) {
                $simd::split_normal(self)
            }
            #[inline(always)]
            fn round_with_pow2(self) -> (Self, Self) {
                $simd::round_with_pow2(self)
            }
            #[inline(always)]
            fn from_per_lane<U: Copy + Default + core::fmt::Debug>(
                items: &[U; $n],
                mut f: impl FnMut(&U) -> f32,
            ) -> Self {
                // Spelled out, here and below: `array::map` and `array::from_fn` go through
                // closures that a build in several codegen units (the workspace's release
                // profile) may leave as calls, passing the lanes through memory (+0.7 µs on
                // the host step).
                let [$($v),+] = items;
                Self::from_array([$(f($v)),+])
            }
            #[inline(always)]
            fn lane(self, i: usize) -> f32 {
                self.to_array().get(i).copied().unwrap_or(0.0)
            }
            #[inline(always)]
            fn to_per_lane(self) -> [f32; $n] {
                self.to_array()
            }
            #[inline(always)]
            fn item<U: Copy + Default + core::fmt::Debug>(items: &[U; $n], i: usize) -> U {
                items.get(i).copied().unwrap_or_default()
            }
            #[inline(always)]
            fn build<U: Copy + Default + core::fmt::Debug>(
                f: impl FnMut(usize) -> U,
            ) -> [U; $n] {
                let mut f = f;
                $(let $v = f($i);)+
                [$($v),+]
            }
            #[inline(always)]
            fn gather<U>(items: &[U], f: impl Fn(&U) -> f32) -> Self {
                let lane = |i: usize| items.get(i).or(items.last()).map_or(0.0, &f);
                Self::from_array([$(lane($i)),+])
            }
        }
    };
}

real_lanes!(F32x4, Mask4, simd, 4, [l0 = 0, l1 = 1, l2 = 2, l3 = 3]);
#[cfg(all(target_arch = "x86_64", target_feature = "avx2"))]
real_lanes!(
    F32x8,
    Mask8,
    avx,
    8,
    [
        l0 = 0,
        l1 = 1,
        l2 = 2,
        l3 = 3,
        l4 = 4,
        l5 = 5,
        l6 = 6,
        l7 = 7
    ]
);

/// SSE (baseline on every x86-64): one instruction per operation and lane group. (Builds with
/// AVX2 use them for a last group of four rollers or fewer.)
#[cfg(target_arch = "x86_64")]
#[path = "sse.rs"]
mod simd;

/// Elsewhere: four lanes in an array, each operation the one-number operation per lane.
#[cfg(not(target_arch = "x86_64"))]
#[path = "portable.rs"]
mod simd;

/// AVX2 where the build enables it: eight lanes, one instruction per operation and lane group.
#[cfg(all(target_arch = "x86_64", target_feature = "avx2"))]
mod avx;
