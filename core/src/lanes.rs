//! Four f32 lanes side by side, and the arithmetic the step's lockstep stages share with the
//! one-number code.
//!
//! Some stages of a step are the same chain of dependent operations for every roller (the
//! film–load Newton iterations: two exponentials, two roots, three divisions each). A
//! superscalar host cannot overlap enough of those chains across rollers to hide their
//! latency, but it can run four of them in the lanes of one SIMD register. [`Real`] is what
//! such a stage is written against: `f32` (one roller; the Cortex-M4 path) and [`F32x4`] (four
//! rollers; SSE on x86-64, a plain lane loop elsewhere) implement it with the same IEEE
//! operations — `+ − × ÷`, square root, compare-and-select, and integer arithmetic on the bit
//! pattern — so a lane's result is the one-roller result bit for bit (no fused or approximate
//! instructions; the tests compare every operation).

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
    /// Item `i` of per-lane items (the default beyond the lanes).
    #[cfg(test)]
    fn item<U: Copy + Default + core::fmt::Debug>(items: &Self::PerLane<U>, i: usize) -> U;
    /// Per-lane items `f(i)` of lanes `i` = 0, 1, ….
    fn build<U: Copy + Default + core::fmt::Debug>(f: impl FnMut(usize) -> U) -> Self::PerLane<U>;
    /// Lanes `f` of a group's items, lane `i` from item `i`: the lanes beyond a short group
    /// repeat its last item (realistic numbers for idle lanes, whose results are discarded);
    /// 0 for an empty group.
    fn gather<U>(items: &[U], f: impl Fn(&U) -> f32) -> Self;
}

impl Real for f32 {
    type Mask = bool;
    type PerLane<U: Copy + Default + core::fmt::Debug> = U;
    #[inline(always)]
    fn splat(v: f32) -> Self {
        v
    }
    #[inline(always)]
    fn gt(self, other: Self) -> bool {
        self > other
    }
    #[inline(always)]
    fn ge(self, other: Self) -> bool {
        self >= other
    }
    #[inline(always)]
    fn le(self, other: Self) -> bool {
        self <= other
    }
    #[inline(always)]
    fn lt(self, other: Self) -> bool {
        self < other
    }
    #[inline(always)]
    fn eq(self, other: Self) -> bool {
        self == other
    }
    #[inline(always)]
    fn indicator(mask: bool) -> Self {
        f32::from(u8::from(mask))
    }
    #[inline(always)]
    fn truncate_index(self) -> (usize, Self) {
        let index = self as usize;
        (index, index as f32)
    }
    #[inline(always)]
    fn select(mask: bool, a: Self, b: Self) -> Self {
        crate::math::select(mask, a, b)
    }
    #[inline(always)]
    fn choose(mask: bool, a: Self, b: Self) -> Self {
        if mask {
            a
        } else {
            b
        }
    }
    #[inline(always)]
    fn max(self, other: Self) -> Self {
        crate::math::max(self, other)
    }
    #[inline(always)]
    fn min(self, other: Self) -> Self {
        crate::math::min(self, other)
    }
    #[inline(always)]
    fn sqrt_non_negative(self) -> Self {
        crate::math::sqrt_non_negative(self)
    }
    #[inline(always)]
    fn split_normal(self) -> (Self, Self) {
        crate::math::split_normal(self)
    }
    #[inline(always)]
    fn round_with_pow2(self) -> (Self, Self) {
        crate::math::round_with_pow2(self)
    }
    #[inline(always)]
    fn from_per_lane<U: Copy + Default + core::fmt::Debug>(
        items: &U,
        mut f: impl FnMut(&U) -> f32,
    ) -> Self {
        f(items)
    }
    #[inline(always)]
    fn lane(self, i: usize) -> f32 {
        if i == 0 {
            self
        } else {
            0.0
        }
    }
    #[cfg(test)]
    #[inline(always)]
    fn item<U: Copy + Default + core::fmt::Debug>(items: &U, i: usize) -> U {
        if i == 0 {
            *items
        } else {
            U::default()
        }
    }
    #[inline(always)]
    fn build<U: Copy + Default + core::fmt::Debug>(mut f: impl FnMut(usize) -> U) -> U {
        f(0)
    }
    #[inline(always)]
    fn gather<U>(items: &[U], f: impl Fn(&U) -> f32) -> Self {
        items.first().map_or(0.0, f)
    }
}

pub(crate) use simd::{F32x4, Mask4};

/// Each backend (`simd`) gives the per-lane primitives; what handles the lanes as an array is
/// the same for both and lives here once.
impl Real for F32x4 {
    type Mask = Mask4;
    type PerLane<U: Copy + Default + core::fmt::Debug> = [U; 4];
    #[inline(always)]
    fn splat(v: f32) -> Self {
        simd::splat(v)
    }
    #[inline(always)]
    fn gt(self, other: Self) -> Mask4 {
        simd::gt(self, other)
    }
    #[inline(always)]
    fn ge(self, other: Self) -> Mask4 {
        simd::ge(self, other)
    }
    #[inline(always)]
    fn le(self, other: Self) -> Mask4 {
        simd::le(self, other)
    }
    #[inline(always)]
    fn lt(self, other: Self) -> Mask4 {
        simd::lt(self, other)
    }
    #[inline(always)]
    fn eq(self, other: Self) -> Mask4 {
        simd::eq(self, other)
    }
    #[inline(always)]
    fn indicator(mask: Mask4) -> Self {
        simd::indicator(mask)
    }
    #[inline(always)]
    fn truncate_index(self) -> ([usize; 4], Self) {
        simd::truncate_index(self)
    }
    #[inline(always)]
    fn select(mask: Mask4, a: Self, b: Self) -> Self {
        simd::select(mask, a, b)
    }
    #[inline(always)]
    fn choose(mask: Mask4, a: Self, b: Self) -> Self {
        simd::select(mask, a, b)
    }
    #[inline(always)]
    fn max(self, other: Self) -> Self {
        simd::max(self, other)
    }
    #[inline(always)]
    fn min(self, other: Self) -> Self {
        simd::min(self, other)
    }
    #[inline(always)]
    fn sqrt_non_negative(self) -> Self {
        simd::sqrt_non_negative(self)
    }
    #[inline(always)]
    fn split_normal(self) -> (Self, Self) {
        simd::split_normal(self)
    }
    #[inline(always)]
    fn round_with_pow2(self) -> (Self, Self) {
        simd::round_with_pow2(self)
    }
    #[inline(always)]
    fn from_per_lane<U: Copy + Default + core::fmt::Debug>(
        items: &[U; 4],
        f: impl FnMut(&U) -> f32,
    ) -> Self {
        Self::from_array(items.each_ref().map(f))
    }
    #[inline(always)]
    fn lane(self, i: usize) -> f32 {
        self.to_array().get(i).copied().unwrap_or(0.0)
    }
    #[cfg(test)]
    #[inline(always)]
    fn item<U: Copy + Default + core::fmt::Debug>(items: &[U; 4], i: usize) -> U {
        items.get(i).copied().unwrap_or_default()
    }
    #[inline(always)]
    fn build<U: Copy + Default + core::fmt::Debug>(f: impl FnMut(usize) -> U) -> [U; 4] {
        core::array::from_fn(f)
    }
    #[inline(always)]
    fn gather<U>(items: &[U], f: impl Fn(&U) -> f32) -> Self {
        Self::from_array(core::array::from_fn(|i| {
            items.get(i).or(items.last()).map_or(0.0, &f)
        }))
    }
}

/// SSE (baseline on every x86-64): one instruction per operation and lane group.
///
/// SAFETY (every `unsafe` block below): the intrinsics are SSE and SSE2 instructions, which
/// every x86-64 processor has and the x86-64 targets always enable; they operate on registers
/// only (no memory access) and cannot fail.
#[cfg(target_arch = "x86_64")]
mod simd {
    use core::arch::x86_64::{
        __m128, __m128i, _mm_add_epi32, _mm_add_ps, _mm_and_ps, _mm_and_si128, _mm_andnot_ps,
        _mm_castps_si128, _mm_castsi128_ps, _mm_cmpeq_ps, _mm_cmpge_ps, _mm_cmpgt_ps, _mm_cmple_ps,
        _mm_cmplt_ps, _mm_cvtepi32_ps, _mm_cvttps_epi32, _mm_div_ps, _mm_max_ps, _mm_min_ps,
        _mm_mul_ps, _mm_or_ps, _mm_or_si128, _mm_set1_epi32, _mm_set1_ps, _mm_set_ps,
        _mm_slli_epi32, _mm_sqrt_ps, _mm_srli_epi32, _mm_sub_epi32, _mm_sub_ps, _mm_xor_ps,
    };
    use core::ops::{Add, BitAnd, Div, Mul, Neg, Sub};

    /// Four f32 lanes.
    #[derive(Clone, Copy, Debug)]
    pub(crate) struct F32x4(__m128);

    /// Four lane masks (all ones or all zeros), as SSE compares give them.
    #[derive(Clone, Copy, Debug)]
    pub(crate) struct Mask4(__m128);

    impl F32x4 {
        /// The lanes of an array, lane 0 first.
        #[inline(always)]
        pub(crate) fn from_array(v: [f32; 4]) -> Self {
            let [a, b, c, d] = v;
            // Built in registers: four scalar stores read back as one vector would stall on
            // store-to-load forwarding. (`_mm_set_ps` takes the highest lane first.)
            Self(unsafe { _mm_set_ps(d, c, b, a) })
        }
        /// The lanes as an array, lane 0 first.
        #[inline(always)]
        pub(crate) fn to_array(self) -> [f32; 4] {
            // SAFETY: `__m128` and `[f32; 4]` are both 16 bytes holding four f32 in lane
            // order; `transmute` moves the value and assumes no alignment.
            unsafe { core::mem::transmute::<__m128, [f32; 4]>(self.0) }
        }
    }

    macro_rules! lane_op {
        ($trait:ident, $method:ident, $intrinsic:ident) => {
            impl $trait for F32x4 {
                type Output = Self;
                #[inline(always)]
                fn $method(self, other: Self) -> Self {
                    // SAFETY: see the module of `F32x4`.
                    Self(unsafe { $intrinsic(self.0, other.0) })
                }
            }
        };
    }
    lane_op!(Add, add, _mm_add_ps);
    lane_op!(Sub, sub, _mm_sub_ps);
    lane_op!(Mul, mul, _mm_mul_ps);
    lane_op!(Div, div, _mm_div_ps);

    impl BitAnd for Mask4 {
        type Output = Self;
        #[inline(always)]
        fn bitand(self, other: Self) -> Self {
            Self(unsafe { _mm_and_ps(self.0, other.0) })
        }
    }

    impl Neg for F32x4 {
        type Output = Self;
        /// The sign bit flipped, as f32 negation does.
        #[inline(always)]
        fn neg(self) -> Self {
            Self(unsafe { _mm_xor_ps(self.0, _mm_set1_ps(-0.0)) })
        }
    }

    #[inline(always)]
    pub(super) fn splat(v: f32) -> F32x4 {
        F32x4(unsafe { _mm_set1_ps(v) })
    }
    #[inline(always)]
    pub(super) fn gt(a: F32x4, b: F32x4) -> Mask4 {
        Mask4(unsafe { _mm_cmpgt_ps(a.0, b.0) })
    }
    #[inline(always)]
    pub(super) fn ge(a: F32x4, b: F32x4) -> Mask4 {
        Mask4(unsafe { _mm_cmpge_ps(a.0, b.0) })
    }
    #[inline(always)]
    pub(super) fn le(a: F32x4, b: F32x4) -> Mask4 {
        Mask4(unsafe { _mm_cmple_ps(a.0, b.0) })
    }
    #[inline(always)]
    pub(super) fn lt(a: F32x4, b: F32x4) -> Mask4 {
        Mask4(unsafe { _mm_cmplt_ps(a.0, b.0) })
    }
    #[inline(always)]
    pub(super) fn eq(a: F32x4, b: F32x4) -> Mask4 {
        Mask4(unsafe { _mm_cmpeq_ps(a.0, b.0) })
    }
    #[inline(always)]
    pub(super) fn indicator(mask: Mask4) -> F32x4 {
        // The mask's all-ones lanes keep 1.0's bits, the others clear them to +0.0.
        F32x4(unsafe { _mm_and_ps(mask.0, _mm_set1_ps(1.0)) })
    }
    #[inline(always)]
    pub(super) fn truncate_index(a: F32x4) -> ([usize; 4], F32x4) {
        // CVTTPS2DQ truncates like `as` for lanes in [0, 2³¹); the integers' conversion back
        // is exact below 2²⁴ (the table's indices are below 100).
        unsafe {
            let index = _mm_cvttps_epi32(a.0);
            // SAFETY (`transmute`): `__m128i` and `[i32; 4]` are both 16 bytes of four i32.
            let lanes = core::mem::transmute::<__m128i, [i32; 4]>(index);
            (lanes.map(|i| i as usize), F32x4(_mm_cvtepi32_ps(index)))
        }
    }
    #[inline(always)]
    pub(super) fn select(mask: Mask4, a: F32x4, b: F32x4) -> F32x4 {
        F32x4(unsafe { _mm_or_ps(_mm_and_ps(mask.0, a.0), _mm_andnot_ps(mask.0, b.0)) })
    }
    #[inline(always)]
    pub(super) fn max(a: F32x4, b: F32x4) -> F32x4 {
        // MAXPS returns its second operand unless the first is greater (also for NaN and
        // equal zeros): `math::max` exactly.
        F32x4(unsafe { _mm_max_ps(a.0, b.0) })
    }
    #[inline(always)]
    pub(super) fn min(a: F32x4, b: F32x4) -> F32x4 {
        // MINPS returns its second operand unless the first is smaller (also for NaN and
        // equal zeros): `math::min` exactly.
        F32x4(unsafe { _mm_min_ps(a.0, b.0) })
    }
    #[inline(always)]
    pub(super) fn sqrt_non_negative(a: F32x4) -> F32x4 {
        F32x4(unsafe { _mm_sqrt_ps(a.0) })
    }
    #[inline(always)]
    pub(super) fn split_normal(a: F32x4) -> (F32x4, F32x4) {
        // `math::split_normal` lane by lane: the same bit fields, the same compare; the
        // exponent's integer sum is exact (|e| ≤ 128), so converting it once gives its bits.
        unsafe {
            let bits = _mm_castps_si128(a.0);
            let exponent = _mm_sub_epi32(
                _mm_and_si128(_mm_srli_epi32::<23>(bits), _mm_set1_epi32(0xff)),
                _mm_set1_epi32(127),
            );
            let mantissa = _mm_castsi128_ps(_mm_or_si128(
                _mm_and_si128(bits, _mm_set1_epi32(0x007f_ffff)),
                _mm_set1_epi32(0x3f80_0000),
            ));
            let high = _mm_cmpgt_ps(mantissa, _mm_set1_ps(core::f32::consts::SQRT_2));
            let m = select(
                Mask4(high),
                F32x4(_mm_mul_ps(mantissa, _mm_set1_ps(0.5))),
                F32x4(mantissa),
            );
            // The mask is −1 where `high`: subtracting it adds one.
            let e = _mm_cvtepi32_ps(_mm_sub_epi32(exponent, _mm_castps_si128(high)));
            (m, F32x4(e))
        }
    }
    #[inline(always)]
    pub(super) fn round_with_pow2(a: F32x4) -> (F32x4, F32x4) {
        // `math::round_with_pow2` lane by lane: the same float sum and the same integer
        // arithmetic on its bit pattern (wrapping, as there).
        unsafe {
            let rounder = _mm_set1_ps(crate::math::ROUNDER);
            let shifted = _mm_add_ps(a.0, rounder);
            let n = _mm_sub_ps(shifted, rounder);
            let biased = _mm_add_epi32(
                _mm_sub_epi32(_mm_castps_si128(shifted), _mm_castps_si128(rounder)),
                _mm_set1_epi32(127),
            );
            let pow2 = _mm_slli_epi32::<23>(_mm_and_si128(biased, _mm_set1_epi32(0xff)));
            (F32x4(n), F32x4(_mm_castsi128_ps(pow2)))
        }
    }
}

/// Elsewhere: four lanes in an array, each operation a loop over them (which the compiler may
/// vectorise) calling the one-number operation.
#[cfg(not(target_arch = "x86_64"))]
mod simd {
    use core::ops::{Add, BitAnd, Div, Mul, Neg, Sub};

    /// Four f32 lanes.
    #[derive(Clone, Copy, Debug)]
    pub(crate) struct F32x4([f32; 4]);

    /// Four lane masks.
    #[derive(Clone, Copy, Debug)]
    pub(crate) struct Mask4([bool; 4]);

    impl F32x4 {
        /// The lanes of an array, lane 0 first.
        #[inline(always)]
        pub(crate) fn from_array(v: [f32; 4]) -> Self {
            Self(v)
        }
        /// The lanes as an array, lane 0 first.
        #[inline(always)]
        pub(crate) fn to_array(self) -> [f32; 4] {
            self.0
        }
        #[inline(always)]
        fn zip(self, other: Self, f: impl Fn(f32, f32) -> f32) -> Self {
            let [a, b, c, d] = self.0;
            let [e, g, h, k] = other.0;
            Self([f(a, e), f(b, g), f(c, h), f(d, k)])
        }
        #[inline(always)]
        fn compare(self, other: Self, f: impl Fn(f32, f32) -> bool) -> Mask4 {
            let [a, b, c, d] = self.0;
            let [e, g, h, k] = other.0;
            Mask4([f(a, e), f(b, g), f(c, h), f(d, k)])
        }
    }

    impl Add for F32x4 {
        type Output = Self;
        #[inline(always)]
        fn add(self, other: Self) -> Self {
            self.zip(other, |a, b| a + b)
        }
    }
    impl Sub for F32x4 {
        type Output = Self;
        #[inline(always)]
        fn sub(self, other: Self) -> Self {
            self.zip(other, |a, b| a - b)
        }
    }
    impl Mul for F32x4 {
        type Output = Self;
        #[inline(always)]
        fn mul(self, other: Self) -> Self {
            self.zip(other, |a, b| a * b)
        }
    }
    impl Div for F32x4 {
        type Output = Self;
        #[inline(always)]
        fn div(self, other: Self) -> Self {
            self.zip(other, |a, b| a / b)
        }
    }
    impl Neg for F32x4 {
        type Output = Self;
        #[inline(always)]
        fn neg(self) -> Self {
            Self(self.0.map(|v| -v))
        }
    }
    impl BitAnd for Mask4 {
        type Output = Self;
        #[inline(always)]
        fn bitand(self, other: Self) -> Self {
            let [a, b, c, d] = self.0;
            let [e, g, h, k] = other.0;
            Self([a & e, b & g, c & h, d & k])
        }
    }

    #[inline(always)]
    pub(super) fn splat(v: f32) -> F32x4 {
        F32x4([v; 4])
    }
    #[inline(always)]
    pub(super) fn gt(a: F32x4, b: F32x4) -> Mask4 {
        a.compare(b, |a, b| a > b)
    }
    #[inline(always)]
    pub(super) fn ge(a: F32x4, b: F32x4) -> Mask4 {
        a.compare(b, |a, b| a >= b)
    }
    #[inline(always)]
    pub(super) fn le(a: F32x4, b: F32x4) -> Mask4 {
        a.compare(b, |a, b| a <= b)
    }
    #[inline(always)]
    pub(super) fn lt(a: F32x4, b: F32x4) -> Mask4 {
        a.compare(b, |a, b| a < b)
    }
    #[inline(always)]
    pub(super) fn eq(a: F32x4, b: F32x4) -> Mask4 {
        a.compare(b, |a, b| a == b)
    }
    #[inline(always)]
    pub(super) fn indicator(mask: Mask4) -> F32x4 {
        F32x4(mask.0.map(|m| f32::from(u8::from(m))))
    }
    #[inline(always)]
    pub(super) fn truncate_index(a: F32x4) -> ([usize; 4], F32x4) {
        let index = a.0.map(|v| v as usize);
        (index, F32x4(index.map(|i| i as f32)))
    }
    #[inline(always)]
    pub(super) fn select(mask: Mask4, a: F32x4, b: F32x4) -> F32x4 {
        let [m0, m1, m2, m3] = mask.0;
        let [a0, a1, a2, a3] = a.0;
        let [b0, b1, b2, b3] = b.0;
        let s = crate::math::select;
        F32x4([s(m0, a0, b0), s(m1, a1, b1), s(m2, a2, b2), s(m3, a3, b3)])
    }
    #[inline(always)]
    pub(super) fn max(a: F32x4, b: F32x4) -> F32x4 {
        a.zip(b, crate::math::max)
    }
    #[inline(always)]
    pub(super) fn min(a: F32x4, b: F32x4) -> F32x4 {
        a.zip(b, crate::math::min)
    }
    #[inline(always)]
    pub(super) fn sqrt_non_negative(a: F32x4) -> F32x4 {
        F32x4(a.0.map(crate::math::sqrt_non_negative))
    }
    #[inline(always)]
    pub(super) fn split_normal(a: F32x4) -> (F32x4, F32x4) {
        let r = a.0.map(crate::math::split_normal);
        (F32x4(r.map(|p| p.0)), F32x4(r.map(|p| p.1)))
    }
    #[inline(always)]
    pub(super) fn round_with_pow2(a: F32x4) -> (F32x4, F32x4) {
        let r = a.0.map(crate::math::round_with_pow2);
        (F32x4(r.map(|p| p.0)), F32x4(r.map(|p| p.1)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every lane operation gives the one-number operation's bits, over values that cover
    /// signs, zeros of both signs, subnormals, large magnitudes, infinities and NaN.
    #[test]
    fn lanes_are_the_one_number_operations_bit_for_bit() {
        let specials = [
            0.0f32,
            -0.0,
            1.0,
            -1.0,
            0.5,
            1.5e-39,
            -3.0e-41,
            1.0e-30,
            3.4e38,
            -3.4e38,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
            126.7,
            -125.2,
            12.5,
            2.0e22,
            // About the re-centring of `split_normal`: √2 and its neighbours, the ends of the
            // normal range.
            core::f32::consts::SQRT_2,
            f32::from_bits(core::f32::consts::SQRT_2.to_bits() + 1),
            -2.828_427_3,
            f32::MIN_POSITIVE,
            f32::MAX,
        ];
        let mut values = [0.0f32; 64];
        let mut state = 0x2545_f491_u32;
        for (k, v) in values.iter_mut().enumerate() {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            *v = specials.get(k).copied().unwrap_or(
                f32::from_bits(state & 0x7fff_ffff) * if k % 2 == 0 { 1.0 } else { -1.0 },
            );
        }
        let bits = |v: f32| if v.is_nan() { u32::MAX } else { v.to_bits() };
        for a in values.chunks_exact(4) {
            for b in values.chunks_exact(4) {
                let a: [f32; 4] = a.try_into().unwrap();
                let b: [f32; 4] = b.try_into().unwrap();
                let (va, vb) = (F32x4::from_array(a), F32x4::from_array(b));
                let lanes = [
                    (va + vb).to_array(),
                    (va - vb).to_array(),
                    (va * vb).to_array(),
                    (va / vb).to_array(),
                    (-va).to_array(),
                    va.max(vb).to_array(),
                    F32x4::select(va.gt(vb) & vb.le(va), va, vb).to_array(),
                    F32x4::select(va.ge(vb), va, vb).to_array(),
                    va.min(vb).to_array(),
                    F32x4::select(va.lt(vb), va, vb).to_array(),
                    F32x4::indicator(va.eq(vb)).to_array(),
                ];
                for i in 0..4 {
                    let (x, y) = (a[i], b[i]);
                    let one = [
                        x + y,
                        x - y,
                        x * y,
                        x / y,
                        -x,
                        crate::math::max(x, y),
                        crate::math::select((x > y) & (y <= x), x, y),
                        crate::math::select(x >= y, x, y),
                        crate::math::min(x, y),
                        crate::math::select(x < y, x, y),
                        f32::from(u8::from(x == y)),
                    ];
                    for (l, o) in lanes.iter().zip(one) {
                        assert_eq!(bits(l[i]), bits(o), "{x} {y}");
                    }
                }
                let root = F32x4::from_array(a.map(f32::abs))
                    .sqrt_non_negative()
                    .to_array();
                let (n, p) = F32x4::from_array(a.map(|v| v.clamp(-126.0, 127.0))).round_with_pow2();
                for i in 0..4 {
                    assert_eq!(
                        bits(root[i]),
                        bits(crate::math::sqrt_non_negative(a[i].abs()))
                    );
                    let (n1, p1) = crate::math::round_with_pow2(a[i].clamp(-126.0, 127.0));
                    assert_eq!((bits(n.lane(i)), bits(p.lane(i))), (bits(n1), bits(p1)));
                }
                // Truncation to an index, of lanes in the range of table indices (the values
                // folded into [0, 2²⁴); NaN taken as 0).
                let small = a.map(|v| if v.is_nan() { 0.0 } else { v.abs().min(1.6e7) });
                let (index, as_float) = F32x4::from_array(small).truncate_index();
                for (i, &x) in small.iter().enumerate() {
                    let (i1, f1) = x.truncate_index();
                    assert_eq!((index[i], bits(as_float.lane(i))), (i1, bits(f1)), "{x}");
                }
                // The bit-field split and the logarithm built on it, of positive normal lanes
                // (the values folded into the normal range; NaN taken as 1).
                let normal = a.map(|v| {
                    if v.is_nan() {
                        1.0
                    } else {
                        v.abs().clamp(f32::MIN_POSITIVE, f32::MAX)
                    }
                });
                let (m, e) = F32x4::from_array(normal).split_normal();
                let log = crate::math::ln_normal(F32x4::from_array(normal));
                for (i, &x) in normal.iter().enumerate() {
                    let (m1, e1) = crate::math::split_normal(x);
                    assert_eq!((bits(m.lane(i)), bits(e.lane(i))), (bits(m1), bits(e1)));
                    assert_eq!(bits(log.lane(i)), bits(crate::math::ln_normal(x)), "{x}");
                }
            }
        }
    }

    /// A group's lanes: lane i from item i, a short group's idle lanes repeating its last item,
    /// an empty group zeros; one number takes the first item (references: the items).
    #[test]
    fn gather_takes_lane_i_from_item_i() {
        let items = [3.0f32, -1.5, 7.25, 0.5, 9.0];
        for n in 0..=items.len() {
            let group = &items[..n];
            let lanes = F32x4::gather(group, |&v| v * 2.0).to_array();
            for (i, lane) in lanes.iter().enumerate() {
                let expected = match (i < n, n) {
                    (true, _) => items[i] * 2.0,
                    (false, 0) => 0.0,
                    (false, _) => items[n - 1] * 2.0,
                };
                assert_eq!(lane.to_bits(), expected.to_bits(), "{n} items, lane {i}");
            }
            assert_eq!(
                f32::gather(group, |&v| v * 2.0).to_bits(),
                group.first().map_or(0.0, |&v| v * 2.0).to_bits()
            );
        }
    }
}
