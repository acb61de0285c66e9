//! SSE (baseline on every x86-64): one instruction per operation and lane group.
//!
//! SAFETY (every `unsafe` block below): the intrinsics are SSE and SSE2 instructions, which
//! every x86-64 processor has and the x86-64 targets always enable; they operate on registers
//! only (no memory access) and cannot fail.

use core::arch::x86_64::{
    __m128, __m128i, _mm_add_epi32, _mm_add_ps, _mm_and_ps, _mm_and_si128, _mm_andnot_ps,
    _mm_castps_si128, _mm_castsi128_ps, _mm_cmpeq_ps, _mm_cmpge_ps, _mm_cmpgt_ps, _mm_cmple_ps,
    _mm_cmplt_ps, _mm_cvtepi32_ps, _mm_cvttps_epi32, _mm_div_ps, _mm_max_ps, _mm_min_ps,
    _mm_mul_ps, _mm_or_ps, _mm_or_si128, _mm_set1_epi32, _mm_set1_ps, _mm_set_ps, _mm_slli_epi32,
    _mm_sqrt_ps, _mm_srli_epi32, _mm_sub_epi32, _mm_sub_ps, _mm_xor_ps,
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
        let [a, b, c, d] = lanes;
        (
            [a as usize, b as usize, c as usize, d as usize],
            F32x4(_mm_cvtepi32_ps(index)),
        )
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
        let rounder = _mm_set1_ps(super::ROUNDER);
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
