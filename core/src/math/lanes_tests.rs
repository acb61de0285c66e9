//! The lanes of `crate::lanes` against the one-number operations of this module, bit for bit: each test is written once for
//! any lane type and run for every width the build has (four lanes always, eight with AVX2).

use crate::lanes::*;

/// Lanes from a slice of exactly `T::LANES` values, lane i from value i (by `gather`, whose
/// lane order the gather test checks on its own).
fn lanes_of<T: Real>(values: &[f32]) -> T {
    assert_eq!(values.len(), T::LANES);
    T::gather(values, |&v| v)
}

/// Every lane operation gives the one-number operation's bits, over values that cover
/// signs, zeros of both signs, subnormals, large magnitudes, infinities and NaN.
#[test]
fn lanes_are_the_one_number_operations_bit_for_bit() {
    operations_bit_for_bit::<F32x4>();
    #[cfg(all(target_arch = "x86_64", target_feature = "avx2"))]
    operations_bit_for_bit::<F32x8>();
}

fn operations_bit_for_bit<T: Real>() {
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
        *v = specials
            .get(k)
            .copied()
            .unwrap_or(f32::from_bits(state & 0x7fff_ffff) * if k % 2 == 0 { 1.0 } else { -1.0 });
    }
    let bits = |v: f32| if v.is_nan() { u32::MAX } else { v.to_bits() };
    let n = T::LANES;
    for a in values.chunks_exact(n) {
        for b in values.chunks_exact(n) {
            let (va, vb) = (lanes_of::<T>(a), lanes_of::<T>(b));
            let lanes = [
                va + vb,
                va - vb,
                va * vb,
                va / vb,
                -va,
                va.max(vb),
                T::select(va.gt(vb) & vb.le(va), va, vb),
                T::select(va.ge(vb), va, vb),
                va.min(vb),
                T::select(va.lt(vb), va, vb),
                T::indicator(va.eq(vb)),
                T::choose(va.lt(vb), va, vb),
            ];
            for i in 0..n {
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
                    if x < y { x } else { y },
                ];
                for (l, o) in lanes.iter().zip(one) {
                    assert_eq!(bits(l.lane(i)), bits(o), "{x} {y}");
                }
            }
            let map =
                |f: fn(f32) -> f32| -> std::vec::Vec<f32> { a.iter().map(|&v| f(v)).collect() };
            let root = lanes_of::<T>(&map(f32::abs)).sqrt_non_negative();
            let (r, p) = lanes_of::<T>(&map(|v| v.clamp(-126.0, 127.0))).round_with_pow2();
            for (i, &x) in a.iter().enumerate() {
                assert_eq!(
                    bits(root.lane(i)),
                    bits(crate::math::sqrt_non_negative(x.abs()))
                );
                let (r1, p1) = crate::math::round_with_pow2(x.clamp(-126.0, 127.0));
                assert_eq!((bits(r.lane(i)), bits(p.lane(i))), (bits(r1), bits(p1)));
            }
            // Truncation to an index, of lanes in the range of table indices (the values
            // folded into [0, 2²⁴); NaN taken as 0).
            let small = map(|v| if v.is_nan() { 0.0 } else { v.abs().min(1.6e7) });
            let (index, as_float) = lanes_of::<T>(&small).truncate_index();
            for (i, &x) in small.iter().enumerate() {
                let (i1, f1) = x.truncate_index();
                assert_eq!(
                    (T::item(&index, i), bits(as_float.lane(i))),
                    (i1, bits(f1)),
                    "{x}"
                );
            }
            // The bit-field split and the logarithm built on it, of positive normal lanes
            // (the values folded into the normal range; NaN taken as 1).
            let normal = map(|v| {
                if v.is_nan() {
                    1.0
                } else {
                    v.abs().clamp(f32::MIN_POSITIVE, f32::MAX)
                }
            });
            let (m, e) = lanes_of::<T>(&normal).split_normal();
            let log = crate::math::ln_normal(lanes_of::<T>(&normal));
            for (i, &x) in normal.iter().enumerate() {
                let (m1, e1) = crate::math::split_normal(x);
                assert_eq!((bits(m.lane(i)), bits(e.lane(i))), (bits(m1), bits(e1)));
                assert_eq!(bits(log.lane(i)), bits(crate::math::ln_normal(x)), "{x}");
            }
        }
    }
}

/// A group's lanes: lane i from item i, a short group's idle lanes repeating its last item,
/// an empty group zeros; one number takes the first item (references: the items). Read back
/// through `to_array`, which is a plain reinterpretation of the register (`lane` is checked
/// against it), and the lanes built from items by `from_per_lane` and `build`.
#[test]
fn gather_takes_lane_i_from_item_i() {
    let items = [3.0f32, -1.5, 7.25, 0.5, 9.0, 11.0, -4.0, 6.5, 2.25, 8.0];
    for n in 0..=items.len() {
        let group = &items[..n];
        let expected = |i: usize| match (i < n, n) {
            (true, _) => items[i] * 2.0,
            (false, 0) => 0.0,
            (false, _) => items[n - 1] * 2.0,
        };
        let four = F32x4::gather(group, |&v| v * 2.0);
        check_lanes(&four.to_array(), four, expected, n);
        #[cfg(all(target_arch = "x86_64", target_feature = "avx2"))]
        {
            let eight = F32x8::gather(group, |&v| v * 2.0);
            check_lanes(&eight.to_array(), eight, expected, n);
        }
        assert_eq!(
            f32::gather(group, |&v| v * 2.0).to_bits(),
            group.first().map_or(0.0, |&v| v * 2.0).to_bits()
        );
    }
    per_lane_items_in_lane_order::<F32x4>();
    #[cfg(all(target_arch = "x86_64", target_feature = "avx2"))]
    per_lane_items_in_lane_order::<F32x8>();
}

/// `lanes` (the register's array) against `expected(i)` lane by lane, and `lane(i)` against
/// the array, 0 beyond the lanes.
fn check_lanes<T: Real>(lanes: &[f32], register: T, expected: impl Fn(usize) -> f32, n: usize) {
    assert_eq!(lanes.len(), T::LANES);
    for (i, lane) in lanes.iter().enumerate() {
        assert_eq!(lane.to_bits(), expected(i).to_bits(), "{n} items, lane {i}");
        assert_eq!(register.lane(i).to_bits(), lane.to_bits());
    }
    assert_eq!(register.lane(T::LANES).to_bits(), 0);
}

/// `build` calls its function with lanes 0, 1, … in order; `from_per_lane` puts item i in lane
/// i; `item` reads item i back and the default beyond the lanes.
fn per_lane_items_in_lane_order<T: Real>() {
    let mut calls = std::vec::Vec::new();
    let items = T::build(|i| {
        calls.push(i);
        (i as u32) * 3 + 1
    });
    assert_eq!(calls, (0..T::LANES).collect::<std::vec::Vec<_>>());
    let lanes = T::from_per_lane(&items, |&k| k as f32);
    for i in 0..T::LANES {
        assert_eq!(T::item(&items, i), (i as u32) * 3 + 1);
        assert_eq!(lanes.lane(i), ((i as u32) * 3 + 1) as f32);
    }
    assert_eq!(T::item(&items, T::LANES), 0);
}
