//! Integer inference (TFLite-style symmetric quantisation, docs/embedded.md): int16 weights and
//! activations, exact integer accumulators, per-layer requantisation by a Q23 multiplier and a
//! right shift with rounding and saturation, hidden activations by a 1025-point lookup table
//! with linear interpolation.
//!
//! Scales (real = scale · q): inputs and tanh/logistic activations use 1/32767; a layer's
//! weights `s_w = max|W|/32767`; its biases are stored at the accumulator scale `s_in·s_w`. The
//! requantisation maps the accumulator to the table's input scale (tanh: 8/32768, i.e. the table
//! spans [−8, 8); logistic: 16/32768) or to the output scale, multiplying by
//! `s_in·s_w/s_target = multiplier · 2^−shift`. The host quantiser guarantees
//! `|acc| < 2⁴⁰` and `multiplier < 2²³`, so the product fits in i64.
//!
//! The definition is the plain i64 formula, [`DenseInt::forward_linear_i64`]: each row summed
//! from its bias (i16·i16 products exact in i32, widened to i64), then [`requantize`]. The
//! Cortex-M4 runs it as written (fixed cost, no data-dependent branch). On x86-64 the same
//! integers are carried in f64 lanes (`exact_f64`): SSE2 has no 64-bit integer
//! multiply, while every partial sum here is an integer below 2⁴⁰ and thus exact in f64, and
//! the requantisation is rebuilt from exact f64 steps, and the table look-up too (`exact_lut`),
//! so the activations stay f64 from layer to layer ([`Carried`], [`DenseInt::lut_layer`], the
//! chain the generated `forward_int` runs) — the codes are identical, which the tests check
//! against the i64 formula. All arithmetic is wrapping, saturating or exact, so nothing
//! here can panic.

/// Number of table segments is `2^LUT_SEGMENT_BITS`.
pub const LUT_SEGMENT_BITS: u32 = 10;
/// Table length: one point per segment boundary.
pub const LUT_LEN: usize = (1 << LUT_SEGMENT_BITS) + 1;
/// Input codes per segment (65536 codes / 1024 segments).
const CODES_PER_SEGMENT_BITS: u32 = 16 - LUT_SEGMENT_BITS;

/// An activation lookup table: `table[k] = round(32767 · f(x_k))`, `x_k = (64k − 32768) · s_z`.
pub type Lut = [i16; LUT_LEN];

/// Quantise a normalised input (nominally in [−1, 1]) to Q15 with round-to-nearest and
/// saturation; NaN gives 0.
#[inline]
pub fn quantise_input(x: f32) -> i16 {
    let v = crate::math::series::clamp(x * 32767.0, -32768.0, 32767.0);
    // 1.5·2²³ rounding constant: round half to even, exact for |v| < 2²².
    let shifted = v + 12_582_912.0;
    #[cfg(target_arch = "x86_64")]
    {
        // The sum lies in [2²³, 2²⁴), where the f32 spacing is 1: its mantissa is
        // 2²² + round(v), so its low 16 bits are round(v) in two's complement. Integer
        // operations on the bit pattern vectorise with SSE2, where Rust's saturating `as i32`
        // is a scalar convert-compare-select chain per input. NaN gives 0 as the conversion
        // below does.
        let code = shifted.to_bits() as u16 & u16::from(!v.is_nan()).wrapping_neg();
        code as i16
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        // `r` is integral and inside the i16 range (NaN stays NaN and converts to 0), so the
        // conversion through i32 is exact; it is one `vcvt` on the M4, where a saturating
        // conversion straight to i16 costs a compare-and-select chain per input.
        let r = shifted - 12_582_912.0;
        (r as i32) as i16
    }
}

/// `round(acc · multiplier · 2^−shift)` saturated to i16.
#[inline(always)]
pub fn requantize(acc: i64, multiplier: i32, shift: u32) -> i16 {
    let prod = acc.wrapping_mul(i64::from(multiplier));
    let half = 1i64.wrapping_shl(shift.wrapping_sub(1));
    let q = prod.wrapping_add(half).wrapping_shr(shift);
    q.clamp(i64::from(i16::MIN), i64::from(i16::MAX)) as i16
}

/// Whether the host path (x86-64) requantises a layer with this `multiplier` and `shift` in
/// its direct form, 4 dependent operations instead of 9 (`exact_f64` module doc): exact when
/// `shift ≤ 38` and the multiplier's odd part is at least 2¹⁶. Any other layer stays exact on
/// the general path, only slower; `bearing export` says which path each layer takes.
pub const fn direct_requantisation(multiplier: i32, shift: u32) -> bool {
    multiplier > 0 && shift <= 38 && (multiplier >> multiplier.trailing_zeros()) >= 1 << 16
}

/// Table lookup with linear interpolation between the two neighbouring points.
#[inline(always)]
pub fn lut_lookup(table: &Lut, z: i16) -> i16 {
    let u = (i32::from(z) + 32768) as u32; // 0 ..= 65535
    let idx = ((u >> CODES_PER_SEGMENT_BITS) as usize) & ((1 << LUT_SEGMENT_BITS) - 1);
    let frac = (u & ((1 << CODES_PER_SEGMENT_BITS) - 1)) as i32;
    let a = i32::from(table.get(idx).copied().unwrap_or(0));
    let b = i32::from(table.get(idx + 1).copied().unwrap_or(0));
    let step = ((b - a) * frac + (1 << (CODES_PER_SEGMENT_BITS - 1))) >> CODES_PER_SEGMENT_BITS;
    (a + step) as i16
}

/// The activations between layers: the i16 codes, which the host path (x86-64) carries as the
/// same integers in f64 lanes (`exact_lut`), so they never make an i16 round trip there.
#[cfg(target_arch = "x86_64")]
pub type Carried<const N: usize> = [f64; N];
/// The activations between layers: the i16 codes (x86-64 carries them in f64 lanes).
#[cfg(not(target_arch = "x86_64"))]
pub type Carried<const N: usize> = [i16; N];

/// What a layer of the host path accepts as input codes: the network's i16 inputs or the f64
/// [`Carried`] activations, the same integers.
#[cfg(target_arch = "x86_64")]
pub trait Code: Copy {
    /// The code at `v` as an f64 (exact).
    fn load(v: &Self) -> f64;
}
#[cfg(target_arch = "x86_64")]
impl Code for i16 {
    #[inline(always)]
    fn load(v: &Self) -> f64 {
        f64::from(*v)
    }
}
#[cfg(target_arch = "x86_64")]
impl Code for f64 {
    /// An 8-byte load, never widened: with a plain read LLVM loads each activation as the low
    /// half of a 16-byte load, which for every odd input straddles two of the previous layer's
    /// 16-byte stores, and store-to-load forwarding cannot serve a load that straddles stores —
    /// it waits for them to reach the cache (≈ 4 ns per network in the `film_ann` bench).
    /// A volatile read is exactly one load of exactly this width.
    #[inline(always)]
    fn load(v: &Self) -> f64 {
        // SAFETY: `v` is a reference, so the pointer is valid, aligned and initialised for
        // the read.
        unsafe { core::ptr::read_volatile(v) }
    }
}

/// The host path's copy of an activation table: on x86-64 the exact f64 pairs of `exact_lut`
/// (built at compile time); elsewhere empty, the layers reading the i16 table itself.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LutLanes {
    #[cfg(target_arch = "x86_64")]
    exact: super::exact_lut::LutF64,
}

impl LutLanes {
    /// The host path's copy of `table` (a `const fn`: the model's is a static).
    #[cfg_attr(not(target_arch = "x86_64"), allow(unused_variables))]
    pub const fn new(table: &Lut) -> Self {
        Self {
            #[cfg(target_arch = "x86_64")]
            exact: super::exact_lut::LutF64::new(table),
        }
    }
}

/// A quantised dense layer with `I` inputs and `O` outputs. Build it with [`DenseInt::new`]
/// (the generated layers are statics): on x86-64 it also holds the converted copy the host path
/// computes with, so a field changed afterwards would not reach that path.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DenseInt<const I: usize, const O: usize> {
    /// `weights[o][i]`, scale `s_w`.
    pub weights: [[i16; I]; O],
    /// Biases at the accumulator scale `s_in·s_w`.
    pub bias: [i64; O],
    /// Q23 requantisation multiplier.
    pub multiplier: i32,
    /// Right shift of the requantisation.
    pub shift: u32,
    /// The same layer in exact f64 lanes (host path, `exact_f64`).
    #[cfg(target_arch = "x86_64")]
    exact: super::exact_f64::ExactF64<I, O>,
}

impl<const I: usize, const O: usize> DenseInt<I, O> {
    /// The layer from its generated parts (a `const fn`: the layers are statics).
    pub const fn new(weights: [[i16; I]; O], bias: [i64; O], multiplier: i32, shift: u32) -> Self {
        Self {
            #[cfg(target_arch = "x86_64")]
            exact: super::exact_f64::ExactF64::new(&weights, &bias, multiplier, shift),
            weights,
            bias,
            multiplier,
            shift,
        }
    }

    /// Accumulators `b + Σ w·x` (i16·i16 products are exact in i32).
    #[inline]
    pub fn accumulate(&self, x: &[i16; I]) -> [i64; O] {
        let mut out = [0i64; O];
        for ((acc, row), b) in out.iter_mut().zip(&self.weights).zip(&self.bias) {
            *acc = row.iter().zip(x).fold(*b, |s, (w, v)| {
                s.wrapping_add(i64::from(i32::from(*w) * i32::from(*v)))
            });
        }
        out
    }

    /// Requantised accumulators by the plain i64 formula: [`Self::accumulate`], then
    /// [`requantize`]. The path of every target but x86-64 (the Cortex-M4), and on the host the
    /// reference the f64 lanes are tested against.
    #[inline]
    pub fn forward_linear_i64(&self, x: &[i16; I]) -> [i16; O] {
        let acc = self.accumulate(x);
        let mut out = [0i16; O];
        for (o, a) in out.iter_mut().zip(acc) {
            *o = requantize(a, self.multiplier, self.shift);
        }
        out
    }

    /// Requantised accumulators (the output layer, or the table input), bit for bit
    /// [`Self::forward_linear_i64`]; on x86-64 computed in exact f64 lanes
    /// (`exact_f64`).
    #[inline]
    pub fn forward_linear(&self, x: &[i16; I]) -> [i16; O] {
        #[cfg(target_arch = "x86_64")]
        {
            let mut out = [0i16; O];
            for (o, q) in out.iter_mut().zip(self.exact.forward_linear_bits(x)) {
                // The low 16 bits hold the code (`ExactF64::forward_linear_bits`).
                *o = q as i16;
            }
            out
        }
        #[cfg(not(target_arch = "x86_64"))]
        self.forward_linear_i64(x)
    }

    /// Hidden layer with a table activation.
    #[inline]
    pub fn forward_lut(&self, x: &[i16; I], table: &Lut) -> [i16; O] {
        // On x86-64 the table is read straight from the requantised codes: going through an
        // i16 array first lets LLVM vectorise the lookups into a slower gather by shuffles.
        #[cfg(target_arch = "x86_64")]
        {
            let mut out = [0i16; O];
            for (o, q) in out.iter_mut().zip(self.exact.forward_linear_bits(x)) {
                *o = lut_lookup(table, q as i16);
            }
            out
        }
        #[cfg(not(target_arch = "x86_64"))]
        {
            let mut z = self.forward_linear_i64(x);
            for v in z.iter_mut() {
                *v = lut_lookup(table, *v);
            }
            z
        }
    }

    /// Hidden layer with a table activation on the network's inputs or [`Carried`]
    /// activations: bit for bit [`Self::forward_lut`] — on x86-64 entirely in exact f64 lanes
    /// with `lanes` (`exact_lut`), elsewhere that very function with `table`.
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    pub fn lut_layer<T: Code>(&self, x: &[T; I], _table: &Lut, lanes: &LutLanes) -> Carried<O> {
        self.exact.forward_lut_lanes(x, &lanes.exact)
    }

    /// Hidden layer with a table activation: [`Self::forward_lut`] (x86-64 runs it in f64
    /// lanes).
    #[cfg(not(target_arch = "x86_64"))]
    #[inline(always)]
    pub fn lut_layer(&self, x: &[i16; I], table: &Lut, _lanes: &LutLanes) -> Carried<O> {
        self.forward_lut(x, table)
    }

    /// Hidden ReLU layer on the network's inputs or [`Carried`] activations: bit for bit
    /// [`Self::forward_relu`] (on x86-64 in exact f64 lanes).
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    pub fn relu_layer<T: Code>(&self, x: &[T; I]) -> Carried<O> {
        self.exact.forward_relu_lanes(x)
    }

    /// Hidden ReLU layer: [`Self::forward_relu`] (x86-64 runs it in f64 lanes).
    #[cfg(not(target_arch = "x86_64"))]
    #[inline(always)]
    pub fn relu_layer(&self, x: &[i16; I]) -> Carried<O> {
        self.forward_relu(x)
    }

    /// Output layer on the network's inputs or [`Carried`] activations: bit for bit
    /// [`Self::forward_linear`] (on x86-64 in exact f64 lanes).
    #[cfg(target_arch = "x86_64")]
    #[inline(always)]
    pub fn output_layer<T: Code>(&self, x: &[T; I]) -> [i16; O] {
        let mut out = [0i16; O];
        for (o, q) in out.iter_mut().zip(self.exact.forward_linear_bits(x)) {
            // The low 16 bits hold the code (`ExactF64::forward_linear_bits`).
            *o = q as i16;
        }
        out
    }

    /// Output layer: [`Self::forward_linear`] (x86-64 runs it in f64 lanes).
    #[cfg(not(target_arch = "x86_64"))]
    #[inline(always)]
    pub fn output_layer(&self, x: &[i16; I]) -> [i16; O] {
        self.forward_linear(x)
    }

    /// Hidden ReLU layer (requantised straight to the activation scale).
    #[inline]
    pub fn forward_relu(&self, x: &[i16; I]) -> [i16; O] {
        let mut z = self.forward_linear(x);
        for v in z.iter_mut() {
            *v = (*v).max(0);
        }
        z
    }
}

#[cfg(test)]
mod tests {
    use super::super::model_weights as model;
    use super::*;

    /// Random and extreme inputs for a layer of width `I` (SplitMix64, Steele, Lea & Flood
    /// 2014; every other input drawn from {−32768, −32767, 0, 32767}).
    fn inputs<const I: usize>(n: usize) -> impl Iterator<Item = [i16; I]> {
        let mut state = 99u64;
        (0..n).map(move |k| {
            core::array::from_fn(|_| {
                state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
                let mut z = state;
                z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
                z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
                z ^= z >> 31;
                if k % 2 == 0 {
                    [i16::MIN, -32767, 0, 32767][(z % 4) as usize]
                } else {
                    z as i16
                }
            })
        })
    }

    /// The dispatched layer (exact f64 lanes on x86-64) and the plain i64 path give the same
    /// codes on every layer of the compiled model, linear and with the table (reference: the
    /// i64 path, the definition the Cortex-M4 runs).
    #[test]
    fn both_paths_give_the_same_codes() {
        for x in inputs::<5>(3000) {
            let l = &model::INT_LAYER_0;
            assert_eq!(l.forward_linear(&x), l.forward_linear_i64(&x), "{x:?}");
            let mut want = l.forward_linear_i64(&x);
            for v in want.iter_mut() {
                *v = lut_lookup(&model::LUT, *v);
            }
            assert_eq!(l.forward_lut(&x, &model::LUT), want, "{x:?}");
        }
        for x in inputs::<10>(3000) {
            let l = &model::INT_LAYER_1;
            assert_eq!(l.forward_linear(&x), l.forward_linear_i64(&x), "{x:?}");
            let l = &model::INT_LAYER_2;
            assert_eq!(l.forward_linear(&x), l.forward_linear_i64(&x), "{x:?}");
        }
    }

    /// The layers on [`Carried`] activations (exact f64 lanes on x86-64) give the codes of
    /// the plain i64 definition — `forward_linear_i64`, then `lut_lookup` or `max(0, ·)` —
    /// for every layer of the compiled model, fed from the quantised inputs and, for the
    /// later layers, from the carried output of the layer before (reference: the i64 path,
    /// the definition the Cortex-M4 runs).
    #[test]
    fn carried_layers_give_the_i64_codes() {
        let lanes = LutLanes::new(&model::LUT);
        let table = &model::LUT;
        // The i16 codes as the layers carry them.
        let carry = |x: &[i16; 10]| -> Carried<10> { x.map(Into::into) };
        let lut = |mut z: [i16; 10]| {
            for v in z.iter_mut() {
                *v = lut_lookup(&model::LUT, *v);
            }
            z
        };
        let relu = |z: [i16; 10]| z.map(|v| v.max(0));
        for x in inputs::<5>(3000) {
            let l = &model::INT_LAYER_0;
            let want = lut(l.forward_linear_i64(&x));
            let got = l.lut_layer(&x, table, &lanes);
            assert_eq!(got, carry(&want), "{x:?}");
            let want_relu = relu(l.forward_linear_i64(&x));
            assert_eq!(l.relu_layer(&x), carry(&want_relu), "{x:?}");
            // The next layers from the carried activations.
            let l1 = &model::INT_LAYER_1;
            assert_eq!(
                l1.lut_layer(&got, table, &lanes),
                carry(&lut(l1.forward_linear_i64(&want))),
                "{x:?}"
            );
            let l2 = &model::INT_LAYER_2;
            assert_eq!(l2.output_layer(&got), l2.forward_linear_i64(&want), "{x:?}");
        }
        for x in inputs::<10>(3000) {
            let l = &model::INT_LAYER_1;
            let want = lut(l.forward_linear_i64(&x));
            assert_eq!(l.lut_layer(&x, table, &lanes), carry(&want), "{x:?}");
            let want_relu = relu(l.forward_linear_i64(&x));
            assert_eq!(l.relu_layer(&x), carry(&want_relu), "{x:?}");
            let l = &model::INT_LAYER_2;
            assert_eq!(l.output_layer(&x), l.forward_linear_i64(&x), "{x:?}");
        }
    }

    /// Requantisation against exact rational arithmetic: acc · m / 2^s rounded half up, and
    /// saturation at the i16 limits.
    #[test]
    fn requantize_rounds_and_saturates() {
        let m = 5_000_000; // ≈ 0.596 in Q23
        for acc in [-1_000_000_007i64, -12345, -1, 0, 1, 77, 99_999_999, 1 << 39] {
            let exact = (acc as f64) * (m as f64) / 2f64.powi(23 + 10);
            let want = (exact + 0.5).floor().clamp(-32768.0, 32767.0) as i16;
            assert_eq!(requantize(acc, m, 33), want, "acc {acc}");
        }
    }

    /// A table of the identity f(x) = x/8 on [−8, 8) interpolates exactly (linear data), and the
    /// end points are reached.
    #[test]
    fn lut_interpolates_linear_data_exactly() {
        let table: Lut =
            core::array::from_fn(|k| ((64 * k as i32 - 32768) / 8).clamp(-32768, 32767) as i16);
        for z in [-32768i16, -32767, -100, -1, 0, 1, 63, 64, 12345, 32767] {
            let want = (f64::from(z) / 8.0).round() as i16;
            assert!((lut_lookup(&table, z) - want).abs() <= 1, "z {z}");
        }
    }

    /// Input quantisation: ±1 → ±32767, saturation beyond, NaN → 0, round to nearest.
    #[test]
    fn input_quantisation() {
        assert_eq!(quantise_input(1.0), 32767);
        assert_eq!(quantise_input(-1.0), -32767);
        assert_eq!(quantise_input(5.0), 32767);
        assert_eq!(quantise_input(-5.0), -32768);
        assert_eq!(quantise_input(f32::NAN), 0);
        assert_eq!(quantise_input(0.25), 8192); // 8191.75 → 8192
        assert_eq!(quantise_input(-0.25), -8192);
    }

    /// The bit-pattern quantisation of x86-64 is the M4's conversion, bit for bit: against
    /// `round_ties_even` of the clamped value (the definition, computed in f64) over every
    /// half-code and its neighbours in [−1.1, 1.1], random bit patterns (NaN with payloads,
    /// infinities, subnormals) and signed zeros.
    #[test]
    fn input_quantisation_is_the_rounded_clamp() {
        let definition = |x: f32| -> i16 {
            let v = f64::from(x) * 32767.0;
            if v.is_nan() {
                0
            } else {
                // x·32767 rounds to f32 first, as in the core.
                let v = f64::from((x * 32767.0).clamp(-32768.0, 32767.0));
                v.round_ties_even() as i16
            }
        };
        let mut state = 0x9e37_79b9_u32;
        let random = core::iter::from_fn(|| {
            state ^= state << 13;
            state ^= state >> 17;
            state ^= state << 5;
            Some(f32::from_bits(state))
        });
        let half_codes = (-72_000i32..72_000).flat_map(|k| {
            let x = (k as f32 + 0.5) / 32767.0;
            [
                x,
                f32::from_bits(x.to_bits() + 1),
                f32::from_bits(x.to_bits() - 1),
            ]
        });
        let specials = [
            0.0f32,
            -0.0,
            f32::INFINITY,
            f32::NEG_INFINITY,
            f32::NAN,
            -f32::NAN,
        ];
        for x in half_codes.chain(random.take(200_000)).chain(specials) {
            assert_eq!(
                quantise_input(x),
                definition(x),
                "{x:e} ({:#x})",
                x.to_bits()
            );
        }
    }
}
