//! f32 inference: dense layers with widths as const generics, hidden activations by the
//! fixed-cost functions of [`super::fastmath`]. Every sum is accumulated from the bias in input
//! order (`b + w₀x₀ + w₁x₁ + …`), which the host mirror repeats so results can be compared.

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

/// A dense layer `y = W x + b` with `I` inputs and `O` outputs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DenseF32<const I: usize, const O: usize> {
    /// `weights[o][i]`.
    pub weights: [[f32; I]; O],
    /// Biases.
    pub bias: [f32; O],
}

impl<const I: usize, const O: usize> DenseF32<I, O> {
    /// `W x + b`.
    #[inline]
    pub fn affine(&self, x: &[f32; I]) -> [f32; O] {
        let mut out = [0.0; O];
        for ((y, row), b) in out.iter_mut().zip(&self.weights).zip(&self.bias) {
            *y = row.iter().zip(x).fold(*b, |acc, (w, v)| acc + w * v);
        }
        out
    }

    /// `f(W x + b)`; the activation is a constant of the generated model, so the `match`
    /// inside [`Activation::apply`] folds away.
    #[inline]
    pub fn forward(&self, x: &[f32; I], activation: Activation) -> [f32; O] {
        let mut y = self.affine(x);
        for v in y.iter_mut() {
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
}
