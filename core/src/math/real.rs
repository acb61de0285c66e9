//! [`Real`] for one number: the one-number arithmetic of this module, which the lanes of
//! `crate::lanes` repeat per lane bit for bit.

use super::{max, min, round_with_pow2, select, split_normal, sqrt_non_negative};
use crate::lanes::Real;

impl Real for f32 {
    const LANES: usize = 1;
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
        select(mask, a, b)
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
        max(self, other)
    }
    #[inline(always)]
    fn min(self, other: Self) -> Self {
        min(self, other)
    }
    #[inline(always)]
    fn sqrt_non_negative(self) -> Self {
        sqrt_non_negative(self)
    }
    #[inline(always)]
    fn split_normal(self) -> (Self, Self) {
        split_normal(self)
    }
    #[inline(always)]
    fn round_with_pow2(self) -> (Self, Self) {
        round_with_pow2(self)
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
    #[inline(always)]
    fn to_per_lane(self) -> f32 {
        self
    }
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
