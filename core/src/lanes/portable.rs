//! Elsewhere: four lanes in an array, each operation a loop over them (which the compiler may
//! vectorise) calling the one-number operation.

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
    let s = <f32 as super::Real>::select;
    F32x4([s(m0, a0, b0), s(m1, a1, b1), s(m2, a2, b2), s(m3, a3, b3)])
}
#[inline(always)]
pub(super) fn max(a: F32x4, b: F32x4) -> F32x4 {
    a.zip(b, <f32 as super::Real>::max)
}
#[inline(always)]
pub(super) fn min(a: F32x4, b: F32x4) -> F32x4 {
    a.zip(b, <f32 as super::Real>::min)
}
#[inline(always)]
pub(super) fn sqrt_non_negative(a: F32x4) -> F32x4 {
    F32x4(a.0.map(<f32 as super::Real>::sqrt_non_negative))
}
#[inline(always)]
pub(super) fn split_normal(a: F32x4) -> (F32x4, F32x4) {
    let r = a.0.map(<f32 as super::Real>::split_normal);
    (F32x4(r.map(|p| p.0)), F32x4(r.map(|p| p.1)))
}
#[inline(always)]
pub(super) fn round_with_pow2(a: F32x4) -> (F32x4, F32x4) {
    let r = a.0.map(<f32 as super::Real>::round_with_pow2);
    (F32x4(r.map(|p| p.0)), F32x4(r.map(|p| p.1)))
}
