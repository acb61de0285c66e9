//! f32 inference: dense layers with widths as const generics, hidden activations by the
//! fixed-cost functions of [`super::fastmath`]. Every sum is accumulated from the bias in input
//! order (`b + w₀x₀ + w₁x₁ + …`), which the host mirror repeats so results can be compared.
//!
//! Both loops run over the layer's outputs innermost (all O sums advance by one input at a
//! time, then all O activations), so the O neurons are independent lanes that LLVM vectorises
//! with SSE2 on the host; per neuron the operations and their order are those of the scalar
//! definition (Rust never reassociates or contracts f32 arithmetic into FMA), so the host and
//! the Cortex-M4, which runs the same code one lane at a time, give identical bits.

use super::fastmath;

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
            Activation::Tanh => fastmath::tanh(x),
            Activation::Logistic => fastmath::logistic(x),
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

/// A dense layer `y = W x + b` with `I` inputs and `O` outputs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DenseF32<const I: usize, const O: usize> {
    /// `weights[o][i]`.
    pub weights: [[f32; I]; O],
    /// Biases.
    pub bias: [f32; O],
}

impl<const I: usize, const O: usize> DenseF32<I, O> {
    /// `W x + b`, each sum from the bias in input order (module doc), the outputs as lanes.
    #[inline]
    pub fn affine(&self, x: &[f32; I]) -> [f32; O] {
        let mut out = self.bias;
        for (i, v) in x.iter().enumerate() {
            for (y, row) in out.iter_mut().zip(&self.weights) {
                // `i < I` always: the `None` arm is dead and folds away.
                if let Some(w) = row.get(i) {
                    *y += w * v;
                }
            }
        }
        out
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
        let layer = DenseF32 {
            weights: [[1.0, 2.0], [-3.0, 0.5]],
            bias: [0.5, -1.0],
        };
        assert_eq!(layer.affine(&[1.0, -2.0]), [-2.5, -5.0]);
        assert_eq!(layer.forward(&[1.0, -2.0], Activation::Relu), [0.0, 0.0]);
        let t = layer.forward(&[1.0, -2.0], Activation::Tanh);
        assert!((t[0] + 0.986_614_3).abs() < 1e-6);
    }

    /// The lane-wise loop keeps the documented sum order: bit for bit the sums written out as
    /// `b + w₀x₀ + w₁x₁ + w₂x₂` (reference: the module doc's definition, spelled by hand), on
    /// values whose sums round differently when reordered (`1 + 1e8 + 1 − 1e8` is 0 in f32 in this
    /// order, 2 with the large terms first).
    #[test]
    fn affine_keeps_input_order() {
        let layer = DenseF32 {
            weights: [[1e8, 1.0, -1e8], [0.1, 0.2, 0.3], [-3.5, 1e-3, 7.25]],
            bias: [1.0, 0.7, -2.0],
        };
        let x = [1.0f32, 1.0, 1.0];
        let by_hand = [
            ((1.0f32 + 1e8 * 1.0) + 1.0 * 1.0) + -1e8 * 1.0,
            ((0.7f32 + 0.1 * 1.0) + 0.2 * 1.0) + 0.3 * 1.0,
            ((-2.0f32 + -3.5 * 1.0) + 1e-3 * 1.0) + 7.25 * 1.0,
        ];
        let got = layer.affine(&x);
        assert_eq!(got.map(f32::to_bits), by_hand.map(f32::to_bits));
        // Another order would give 2, so the test can fail.
        assert_eq!(got[0], 0.0);
    }
}
