//! A small multilayer perceptron in f64: hidden layers with one activation, linear output,
//! and the exact derivative of every output with respect to every weight (backpropagation),
//! which is what Levenberg–Marquardt needs (one Jacobian row per sample and output).
//!
//! Parameter order (also the order of the flat parameter vector): layer by layer, the weights
//! row-major (`out × in`), then the biases.

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

/// Hidden-layer activation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "kebab-case")]
pub enum Activation {
    /// Hyperbolic tangent.
    Tanh,
    /// Logistic sigmoid 1/(1 + e^−x).
    Logistic,
    /// Rectified linear max(0, x).
    Relu,
}

impl Activation {
    /// `f(x)`.
    pub fn apply(self, x: f64) -> f64 {
        match self {
            Activation::Tanh => x.tanh(),
            Activation::Logistic => 1.0 / (1.0 + (-x).exp()),
            Activation::Relu => x.max(0.0),
        }
    }

    /// `f'(x)` given `x` and `y = f(x)`.
    fn derivative(self, x: f64, y: f64) -> f64 {
        match self {
            Activation::Tanh => 1.0 - y * y,
            Activation::Logistic => y * (1.0 - y),
            Activation::Relu => {
                if x > 0.0 {
                    1.0
                } else {
                    0.0
                }
            }
        }
    }

    /// Stable lower-case name.
    pub fn name(self) -> &'static str {
        match self {
            Activation::Tanh => "tanh",
            Activation::Logistic => "logistic",
            Activation::Relu => "relu",
        }
    }
}

/// One dense layer: `y = W x + b`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Layer {
    /// Weights, `weights[o][i]`.
    pub weights: Vec<Vec<f64>>,
    /// Biases.
    pub bias: Vec<f64>,
}

impl Layer {
    fn inputs(&self) -> usize {
        self.weights.first().map_or(0, Vec::len)
    }

    fn affine(&self, x: &[f64]) -> Vec<f64> {
        self.weights
            .iter()
            .zip(&self.bias)
            .map(|(row, b)| b + row.iter().zip(x).map(|(w, v)| w * v).sum::<f64>())
            .collect()
    }
}

/// The network.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Mlp {
    /// Hidden layers then the output layer.
    pub layers: Vec<Layer>,
    /// Activation of the hidden layers (the output is linear).
    pub activation: Activation,
}

impl Mlp {
    /// Glorot-uniform initial weights (Glorot & Bengio 2010), zero biases, seeded.
    pub fn new(
        inputs: usize,
        hidden: &[usize],
        outputs: usize,
        activation: Activation,
        seed: u64,
    ) -> Self {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let mut widths = vec![inputs];
        widths.extend_from_slice(hidden);
        widths.push(outputs);
        let layers = widths
            .windows(2)
            .map(|w| {
                let limit = (6.0 / (w[0] + w[1]) as f64).sqrt();
                Layer {
                    weights: (0..w[1])
                        .map(|_| (0..w[0]).map(|_| rng.random_range(-limit..limit)).collect())
                        .collect(),
                    bias: vec![0.0; w[1]],
                }
            })
            .collect();
        Self { layers, activation }
    }

    /// Number of parameters.
    pub fn parameter_count(&self) -> usize {
        self.layers
            .iter()
            .map(|l| l.bias.len() * (l.inputs() + 1))
            .sum()
    }

    /// Flat parameter vector.
    pub fn parameters(&self) -> Vec<f64> {
        let mut p = Vec::with_capacity(self.parameter_count());
        for l in &self.layers {
            for row in &l.weights {
                p.extend_from_slice(row);
            }
            p.extend_from_slice(&l.bias);
        }
        p
    }

    /// Set from a flat parameter vector (same order as [`Mlp::parameters`]).
    pub fn set_parameters(&mut self, p: &[f64]) {
        let mut it = p.iter().copied();
        for l in &mut self.layers {
            for row in &mut l.weights {
                for w in row.iter_mut() {
                    *w = it.next().unwrap_or(0.0);
                }
            }
            for b in &mut l.bias {
                *b = it.next().unwrap_or(0.0);
            }
        }
    }

    /// Network output for one input row.
    pub fn forward(&self, x: &[f64]) -> Vec<f64> {
        let last = self.layers.len() - 1;
        let mut a = x.to_vec();
        for (k, l) in self.layers.iter().enumerate() {
            a = l.affine(&a);
            if k < last {
                a.iter_mut().for_each(|v| *v = self.activation.apply(*v));
            }
        }
        a
    }

    /// Outputs and `∂y_o/∂θ` for every output `o` (rows in the flat parameter order).
    pub fn forward_with_jacobian(&self, x: &[f64]) -> (Vec<f64>, Vec<Vec<f64>>) {
        let last = self.layers.len() - 1;
        // Forward pass, keeping each layer's input and activation slope.
        let mut inputs: Vec<Vec<f64>> = Vec::with_capacity(self.layers.len());
        let mut slopes: Vec<Vec<f64>> = Vec::with_capacity(last);
        let mut a = x.to_vec();
        for (k, l) in self.layers.iter().enumerate() {
            let z = l.affine(&a);
            inputs.push(a);
            if k < last {
                let y: Vec<f64> = z.iter().map(|v| self.activation.apply(*v)).collect();
                slopes.push(
                    z.iter()
                        .zip(&y)
                        .map(|(zv, yv)| self.activation.derivative(*zv, *yv))
                        .collect(),
                );
                a = y;
            } else {
                a = z;
            }
        }
        let outputs = a;
        // Offsets of each layer's block in the flat vector.
        let mut offsets = Vec::with_capacity(self.layers.len());
        let mut off = 0;
        for l in &self.layers {
            offsets.push(off);
            off += l.bias.len() * (l.inputs() + 1);
        }
        let mut rows = Vec::with_capacity(outputs.len());
        for o in 0..outputs.len() {
            let mut row = vec![0.0; off];
            // δ at the (linear) output: unit vector e_o.
            let mut delta: Vec<f64> = (0..outputs.len())
                .map(|j| if j == o { 1.0 } else { 0.0 })
                .collect();
            for k in (0..self.layers.len()).rev() {
                let l = &self.layers[k];
                let n_in = l.inputs();
                let base = offsets[k];
                for (j, d) in delta.iter().enumerate() {
                    for (i, v) in inputs[k].iter().enumerate() {
                        row[base + j * n_in + i] = d * v;
                    }
                    row[base + l.bias.len() * n_in + j] = *d;
                }
                if k > 0 {
                    let slope = &slopes[k - 1];
                    delta = (0..n_in)
                        .map(|i| {
                            slope[i]
                                * l.weights
                                    .iter()
                                    .zip(&delta)
                                    .map(|(r, d)| r[i] * d)
                                    .sum::<f64>()
                        })
                        .collect();
                }
            }
            rows.push(row);
        }
        (outputs, rows)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Backpropagation against central finite differences (an independent method), for every
    /// activation, at a random point.
    #[test]
    fn jacobian_matches_finite_differences() {
        for act in [Activation::Tanh, Activation::Logistic, Activation::Relu] {
            let mut net = Mlp::new(3, &[5, 4], 2, act, 42);
            let mut p = net.parameters();
            // Non-zero biases so every term is exercised.
            p.iter_mut()
                .enumerate()
                .for_each(|(i, v)| *v += 0.01 * (i as f64).sin());
            net.set_parameters(&p);
            let x = [0.3, -0.7, 0.5];
            let (_, jac) = net.forward_with_jacobian(&x);
            let h = 1e-6;
            for k in 0..p.len() {
                let mut plus = net.clone();
                let mut minus = net.clone();
                let mut pp = p.clone();
                pp[k] += h;
                plus.set_parameters(&pp);
                pp[k] -= 2.0 * h;
                minus.set_parameters(&pp);
                let (yp, ym) = (plus.forward(&x), minus.forward(&x));
                for o in 0..2 {
                    let fd = (yp[o] - ym[o]) / (2.0 * h);
                    assert!(
                        (fd - jac[o][k]).abs() < 1e-7,
                        "{act:?} param {k} output {o}: {fd} vs {}",
                        jac[o][k]
                    );
                }
            }
        }
    }

    /// Parameters round-trip through the flat vector; the count is Σ out·(in + 1).
    #[test]
    fn parameters_round_trip() {
        let net = Mlp::new(3, &[14, 14], 2, Activation::Tanh, 1);
        assert_eq!(net.parameter_count(), 14 * 4 + 14 * 15 + 2 * 15);
        let mut other = Mlp::new(3, &[14, 14], 2, Activation::Tanh, 2);
        other.set_parameters(&net.parameters());
        assert_eq!(other, net);
    }
}
