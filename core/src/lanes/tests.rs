//! The lanes against the one-number operations, bit for bit.

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
        *v = specials
            .get(k)
            .copied()
            .unwrap_or(f32::from_bits(state & 0x7fff_ffff) * if k % 2 == 0 { 1.0 } else { -1.0 });
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
