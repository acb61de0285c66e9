//! f32 inference: dense layers with widths as const generics, hidden activations by the
//! fixed-cost functions of `math::series`. Every sum is two partial sums in input order,
//! the even inputs from the bias and the odd ones, added last:
//! `(b + w₀x₀ + w₂x₂ + …) + (w₁x₁ + w₃x₃ + …)`. The same number of additions as one sum, but
//! half the chain of dependent ones: the network is latency-bound (each layer waits for the
//! previous one's activations).
//!
//! Both loops run over the layer's outputs innermost (all O sums advance by one input at a
//! time, then all O activations), so the O neurons are independent lanes that LLVM vectorises
//! with SSE2 on the host; per neuron the operations and their order are those of the scalar
//! definition (Rust never reassociates or contracts f32 arithmetic into FMA), so the host and
//! the Cortex-M4, which runs the same code one lane at a time, give identical bits.

use crate::math::series;

/// Hidden-layer activation of the network.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Activation {
    /// Hyperbolic tangent.
    Tanh,
    /// Logistic sigmoid.
    Logistic,
    /// max(0, x).
    Relu,
}

impl Activation {
    /// `f(x)` at a fixed cost.
    #[inline(always)]
    pub fn apply(self, x: f32) -> f32 {
        match self {
            Activation::Tanh => series::tanh(x),
            Activation::Logistic => series::logistic(x),
            Activation::Relu => {
                if x > 0.0 {
                    x
                } else {
                    0.0
                }
            }
        }
    }
}

/// Neurons whose activations are written as one group of straight-line code, which LLVM's
/// superword-level-parallelism vectoriser turns into one SSE2 vector per operation: its loop
/// vectoriser leaves a 10-iteration loop scalar (trip count below its minimum of 16), so the
/// layer is cut into groups of 4 explicitly; the 2 left of a 10-wide layer form the remainder.
const LANES: usize = 4;

/// A dense layer `y = W x + b` with `I` inputs and `O` outputs. Build it with
/// [`DenseF32::new`] (the generated layers are statics).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DenseF32<const I: usize, const O: usize> {
    /// `W` input-major, `columns[i][o] = W[o][i]`: the affine loop advances all O sums by one
    /// input at a time, so it reads one column per input as contiguous lanes. (Stored
    /// output-major, each column had to be gathered by shuffles on every call: a third of the
    /// network's time on the host.)
    columns: [[f32; O]; I],
    /// Biases.
    bias: [f32; O],
}

impl<const I: usize, const O: usize> DenseF32<I, O> {
    /// The layer from its weights `W[o][i]` (output-major, as trained) and biases; a `const
    /// fn` so that the generated layers are statics transposed at compile time.
    #[allow(clippy::indexing_slicing)] // const fn: index loops bounded by I and O.
    pub const fn new(weights: [[f32; I]; O], bias: [f32; O]) -> Self {
        let mut columns = [[0.0; O]; I];
        let mut o = 0;
        while o < O {
            let mut i = 0;
            while i < I {
                columns[i][o] = weights[o][i];
                i += 1;
            }
            o += 1;
        }
        Self { columns, bias }
    }

    /// `W x + b`, each sum as two partial sums (module doc), the outputs as lanes.
    #[inline]
    pub fn affine(&self, x: &[f32; I]) -> [f32; O] {
        let mut even = self.bias;
        // −0 is the identity of f32 addition (−0 + x = x for every x, zeros included), so the
        // compiler folds the first odd addition into a plain product: no extra operation.
        let mut odd = [-0.0f32; O];
        // Inputs in pairs, so that which sum an input joins is known at compile time. Chosen at
        // run time by the input's parity, it keeps both sums in memory on the M4 wherever LLVM
        // does not unroll the input loop (14 inputs): a load and a store around every
        // multiply–add.
        let mut x_pairs = x.chunks_exact(2);
        let mut column_pairs = self.columns.chunks_exact(2);
        for pair in (&mut x_pairs).zip(&mut column_pairs) {
            // Always two of each (`chunks_exact`): the pattern folds away.
            if let ([x_even, x_odd], [column_even, column_odd]) = pair {
                for (y, w) in even.iter_mut().zip(column_even) {
                    *y += w * x_even;
                }
                for (y, w) in odd.iter_mut().zip(column_odd) {
                    *y += w * x_odd;
                }
            }
        }
        for (v, column) in x_pairs.remainder().iter().zip(column_pairs.remainder()) {
            for (y, w) in even.iter_mut().zip(column) {
                *y += w * v;
            }
        }
        for (e, o) in even.iter_mut().zip(odd) {
            *e += o;
        }
        even
    }

    /// `f(W x + b)`; the activation is a constant of the generated model, so the `match`
    /// inside [`Activation::apply`] folds away.
    #[inline]
    pub fn forward(&self, x: &[f32; I], activation: Activation) -> [f32; O] {
        let mut y = self.affine(x);
        let mut lanes = y.chunks_exact_mut(LANES);
        for chunk in &mut lanes {
            for v in chunk.iter_mut() {
                *v = activation.apply(*v);
            }
        }
        for v in lanes.into_remainder() {
            *v = activation.apply(*v);
        }
        y
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Hand-computed 2×2 layer: W = [[1, 2], [−3, 0.5]], b = [0.5, −1], x = [1, −2]:
    /// W x + b = [1 − 4 + 0.5, −3 − 1 − 1] = [−2.5, −5]; ReLU gives [0, 0], tanh(−2.5) = −0.98661.
    #[test]
    fn hand_layer() {
        let layer = DenseF32::new([[1.0, 2.0], [-3.0, 0.5]], [0.5, -1.0]);
        assert_eq!(layer.affine(&[1.0, -2.0]), [-2.5, -5.0]);
        assert_eq!(layer.forward(&[1.0, -2.0], Activation::Relu), [0.0, 0.0]);
        let t = layer.forward(&[1.0, -2.0], Activation::Tanh);
        assert!((t[0] + 0.986_614_3).abs() < 1e-6);
    }

    /// The lane-wise loop keeps the documented sum order: bit for bit the sums written out as
    /// `(b + w₀x₀ + w₂x₂) + w₁x₁` (reference: the module doc's definition, spelled by hand), on
    /// values whose sums round differently when reordered (`(1 + 1e8) − 1e8` is 0 in f32, so
    /// the documented order gives 1; one sum in input order, `1 + 1e8 + 1 − 1e8`, gives 0, and
    /// `1 + 1 + 1e8 − 1e8` gives 2).
    #[test]
    fn affine_keeps_the_documented_order() {
        let layer = DenseF32::new(
            [[1e8, 1.0, -1e8], [0.1, 0.2, 0.3], [-3.5, 1e-3, 7.25]],
            [1.0, 0.7, -2.0],
        );
        let x = [1.0f32, 1.0, 1.0];
        let by_hand = [
            ((1.0f32 + 1e8 * 1.0) + -1e8 * 1.0) + 1.0 * 1.0,
            ((0.7f32 + 0.1 * 1.0) + 0.3 * 1.0) + 0.2 * 1.0,
            ((-2.0f32 + -3.5 * 1.0) + 7.25 * 1.0) + 1e-3 * 1.0,
        ];
        let got = layer.affine(&x);
        assert_eq!(got.map(f32::to_bits), by_hand.map(f32::to_bits));
        // The other orders give 0 or 2, so the test can fail.
        assert_eq!(got[0], 1.0);
    }

    /// The module doc's definition, one output at a time: the even inputs summed from the
    /// bias and the odd ones from −0, in input order, then added.
    fn definition<const I: usize, const O: usize>(
        layer: &DenseF32<I, O>,
        x: &[f32; I],
    ) -> [f32; O] {
        core::array::from_fn(|o| {
            let mut even = layer.bias[o];
            let mut odd = -0.0f32;
            for (i, (column, v)) in layer.columns.iter().zip(x).enumerate() {
                let product = column[o] * v;
                if i % 2 == 0 {
                    even += product;
                } else {
                    odd += product;
                }
            }
            even + odd
        })
    }

    /// Every layer of both compiled networks (line and point contact: odd and even input
    /// counts, 2 to 14 outputs) gives the bits of the definition written out one output at a
    /// time, on 2000 random inputs per layer spanning [−1.5, 1.5] (the activations' range and
    /// beyond) and on signed zeros.
    #[test]
    fn compiled_layers_give_the_definition_bits() {
        fn check<const I: usize, const O: usize>(layer: &DenseF32<I, O>) {
            // SplitMix64 (Steele, Lea & Flood 2014).
            let mut state = 17u64;
            let mut uniform = || {
                state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
                let mut z = state;
                z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
                z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
                z ^= z >> 31;
                (z >> 40) as f32 / (1u64 << 24) as f32
            };
            let mut inputs = std::vec![[0.0f32; I], [-0.0f32; I]];
            for _ in 0..2000 {
                inputs.push(core::array::from_fn(|_| 3.0 * uniform() - 1.5));
            }
            for x in &inputs {
                let got = layer.affine(x).map(f32::to_bits);
                assert_eq!(got, definition(layer, x).map(f32::to_bits), "{x:?}");
            }
        }
        use super::super::{model_weights as line, point_model_weights as point};
        check(&line::F32_LAYER_0);
        check(&line::F32_LAYER_1);
        check(&line::F32_LAYER_2);
        check(&point::F32_LAYER_0);
        check(&point::F32_LAYER_1);
        check(&point::F32_LAYER_2);
    }
}
