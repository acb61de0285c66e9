//! AVX/AVX2 (x86-64 built with `target-feature=+avx2`): eight f32 lanes in one 256-bit
//! register, one instruction per operation and lane group — `sse.rs`'s operations at
//! twice the width, so that 17 rollers take three groups instead of five.
//!
//! Each operation is the IEEE operation of the one-number code in every lane (Intel® 64 and
//! IA-32 Architectures Software Developer's Manual, vol. 2: VADDPS … VSQRTPS round each lane
//! as their scalar forms do; VMAXPS/VMINPS return the second operand unless the first is
//! greater/smaller; VCMPPS with the ordered-quiet predicates is false for NaN as Rust's float
//! compares). No fused multiply–add (FMA is a separate feature, not enabled) and no
//! approximate instructions (VRCPPS, VRSQRTPS): `lanes::tests` compares every operation.
//!
//! SAFETY (every `unsafe` block below): the intrinsics are AVX and AVX2 instructions, which
//! this module is only compiled for (`target_feature = "avx2"`, which implies AVX, is enabled
//! for the whole build, so every processor the binary runs on has them); they operate on
//! registers only (no memory access) and cannot fail.

use core::arch::x86_64::{
    __m256, __m256i, _mm256_add_epi32, _mm256_add_ps, _mm256_and_ps, _mm256_and_si256,
    _mm256_blendv_ps, _mm256_castps_si256, _mm256_castsi256_ps, _mm256_cmp_ps, _mm256_cvtepi32_ps,
    _mm256_cvttps_epi32, _mm256_div_ps, _mm256_max_ps, _mm256_min_ps, _mm256_mul_ps,
    _mm256_or_si256, _mm256_set1_epi32, _mm256_set1_ps, _mm256_set_ps, _mm256_slli_epi32,
    _mm256_sqrt_ps, _mm256_srli_epi32, _mm256_sub_epi32, _mm256_sub_ps, _mm256_xor_ps, _CMP_EQ_OQ,
    _CMP_GE_OQ, _CMP_GT_OQ, _CMP_LE_OQ, _CMP_LT_OQ,
};
use core::ops::{Add, BitAnd, Div, Mul, Neg, Sub};

/// Eight f32 lanes.
#[derive(Clone, Copy, Debug)]
pub(crate) struct F32x8(__m256);

/// Eight lane masks (all ones or all zeros), as AVX compares give them.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Mask8(__m256);

impl F32x8 {
    /// The lanes of an array, lane 0 first.
    #[inline(always)]
    pub(crate) fn from_array(v: [f32; 8]) -> Self {
        let [a, b, c, d, e, f, g, h] = v;
        // Built in registers, as `F32x4::from_array` (`_mm256_set_ps` takes the highest lane
        // first).
        Self(unsafe { _mm256_set_ps(h, g, f, e, d, c, b, a) })
    }
    /// The lanes as an array, lane 0 first.
    #[inline(always)]
    pub(crate) fn to_array(self) -> [f32; 8] {
        // SAFETY: `__m256` and `[f32; 8]` are both 32 bytes holding eight f32 in lane
        // order; `transmute` moves the value and assumes no alignment.
        unsafe { core::mem::transmute::<__m256, [f32; 8]>(self.0) }
    }
}

macro_rules! lane_op {
    ($trait:ident, $method:ident, $intrinsic:ident) => {
        impl $trait for F32x8 {
            type Output = Self;
            #[inline(always)]
            fn $method(self, other: Self) -> Self {
                // SAFETY: see the module of `F32x8`.
                Self(unsafe { $intrinsic(self.0, other.0) })
            }
        }
    };
}
lane_op!(Add, add, _mm256_add_ps);
lane_op!(Sub, sub, _mm256_sub_ps);
lane_op!(Mul, mul, _mm256_mul_ps);
lane_op!(Div, div, _mm256_div_ps);

impl BitAnd for Mask8 {
    type Output = Self;
    #[inline(always)]
    fn bitand(self, other: Self) -> Self {
        Self(unsafe { _mm256_and_ps(self.0, other.0) })
    }
}

impl Neg for F32x8 {
    type Output = Self;
    /// The sign bit flipped, as f32 negation does.
    #[inline(always)]
    fn neg(self) -> Self {
        Self(unsafe { _mm256_xor_ps(self.0, _mm256_set1_ps(-0.0)) })
    }
}

#[inline(always)]
pub(super) fn splat(v: f32) -> F32x8 {
    F32x8(unsafe { _mm256_set1_ps(v) })
}
// The ordered, non-signalling predicates: false where either lane is NaN, as `>`, `>=`, `<=`,
// `<` and `==` on f32 (and as SSE's CMPPS, whose fixed predicates are the same).
#[inline(always)]
pub(super) fn gt(a: F32x8, b: F32x8) -> Mask8 {
    Mask8(unsafe { _mm256_cmp_ps::<_CMP_GT_OQ>(a.0, b.0) })
}
#[inline(always)]
pub(super) fn ge(a: F32x8, b: F32x8) -> Mask8 {
    Mask8(unsafe { _mm256_cmp_ps::<_CMP_GE_OQ>(a.0, b.0) })
}
#[inline(always)]
pub(super) fn le(a: F32x8, b: F32x8) -> Mask8 {
    Mask8(unsafe { _mm256_cmp_ps::<_CMP_LE_OQ>(a.0, b.0) })
}
#[inline(always)]
pub(super) fn lt(a: F32x8, b: F32x8) -> Mask8 {
    Mask8(unsafe { _mm256_cmp_ps::<_CMP_LT_OQ>(a.0, b.0) })
}
#[inline(always)]
pub(super) fn eq(a: F32x8, b: F32x8) -> Mask8 {
    Mask8(unsafe { _mm256_cmp_ps::<_CMP_EQ_OQ>(a.0, b.0) })
}
#[inline(always)]
pub(super) fn indicator(mask: Mask8) -> F32x8 {
    // The mask's all-ones lanes keep 1.0's bits, the others clear them to +0.0.
    F32x8(unsafe { _mm256_and_ps(mask.0, _mm256_set1_ps(1.0)) })
}
#[inline(always)]
pub(super) fn truncate_index(a: F32x8) -> ([usize; 8], F32x8) {
    // VCVTTPS2DQ truncates like `as` for lanes in [0, 2³¹); the integers' conversion back
    // is exact below 2²⁴ (the table's indices are below 100).
    unsafe {
        let index = _mm256_cvttps_epi32(a.0);
        // SAFETY (`transmute`): `__m256i` and `[i32; 8]` are both 32 bytes of eight i32.
        let lanes = core::mem::transmute::<__m256i, [i32; 8]>(index);
        let [a, b, c, d, e, f, g, h] = lanes;
        (
            [
                a as usize, b as usize, c as usize, d as usize, e as usize, f as usize, g as usize,
                h as usize,
            ],
            F32x8(_mm256_cvtepi32_ps(index)),
        )
    }
}
#[inline(always)]
pub(super) fn select(mask: Mask8, a: F32x8, b: F32x8) -> F32x8 {
    // VBLENDVPS takes each lane from its second source where the mask lane's sign bit is set:
    // the mask lanes are all ones or all zeros, so this is the bit-mask select of
    // `math::select` in one instruction.
    F32x8(unsafe { _mm256_blendv_ps(b.0, a.0, mask.0) })
}
#[inline(always)]
pub(super) fn max(a: F32x8, b: F32x8) -> F32x8 {
    // VMAXPS returns its second operand unless the first is greater (also for NaN and
    // equal zeros): `math::max` exactly.
    F32x8(unsafe { _mm256_max_ps(a.0, b.0) })
}
#[inline(always)]
pub(super) fn min(a: F32x8, b: F32x8) -> F32x8 {
    // VMINPS returns its second operand unless the first is smaller (also for NaN and
    // equal zeros): `math::min` exactly.
    F32x8(unsafe { _mm256_min_ps(a.0, b.0) })
}
#[inline(always)]
pub(super) fn sqrt_non_negative(a: F32x8) -> F32x8 {
    F32x8(unsafe { _mm256_sqrt_ps(a.0) })
}
#[inline(always)]
pub(super) fn split_normal(a: F32x8) -> (F32x8, F32x8) {
    // `math::split_normal` lane by lane: the same bit fields, the same compare; the
    // exponent's integer sum is exact (|e| ≤ 128), so converting it once gives its bits.
    unsafe {
        let bits = _mm256_castps_si256(a.0);
        let exponent = _mm256_sub_epi32(
            _mm256_and_si256(_mm256_srli_epi32::<23>(bits), _mm256_set1_epi32(0xff)),
            _mm256_set1_epi32(127),
        );
        let mantissa = _mm256_castsi256_ps(_mm256_or_si256(
            _mm256_and_si256(bits, _mm256_set1_epi32(0x007f_ffff)),
            _mm256_set1_epi32(0x3f80_0000),
        ));
        let high = _mm256_cmp_ps::<_CMP_GT_OQ>(mantissa, _mm256_set1_ps(core::f32::consts::SQRT_2));
        let m = select(
            Mask8(high),
            F32x8(_mm256_mul_ps(mantissa, _mm256_set1_ps(0.5))),
            F32x8(mantissa),
        );
        // The mask is −1 where `high`: subtracting it adds one.
        let e = _mm256_cvtepi32_ps(_mm256_sub_epi32(exponent, _mm256_castps_si256(high)));
        (m, F32x8(e))
    }
}
#[inline(always)]
pub(super) fn round_with_pow2(a: F32x8) -> (F32x8, F32x8) {
    // `math::round_with_pow2` lane by lane: the same float sum and the same integer
    // arithmetic on its bit pattern (wrapping, as there).
    unsafe {
        let rounder = _mm256_set1_ps(super::ROUNDER);
        let shifted = _mm256_add_ps(a.0, rounder);
        let n = _mm256_sub_ps(shifted, rounder);
        let biased = _mm256_add_epi32(
            _mm256_sub_epi32(_mm256_castps_si256(shifted), _mm256_castps_si256(rounder)),
            _mm256_set1_epi32(127),
        );
        let pow2 = _mm256_slli_epi32::<23>(_mm256_and_si256(biased, _mm256_set1_epi32(0xff)));
        (F32x8(n), F32x8(_mm256_castsi256_ps(pow2)))
    }
}
