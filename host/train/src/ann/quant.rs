//! Quantisation of a trained network to the integer format of `bearing_core::film::ann::int`,
//! and a host mirror of the integer inference built on the core's own primitives
//! (`quantise_input`, `requantize`, `lut_lookup`), so its outputs are those of the core.
//!
//! Scales (real = scale·q, zero point 0): see the core module doc. Hidden tanh/logistic layers
//! requantise to the table input scale `s_z` (tanh: 8/32768, the table spans [−8, 8) where
//! tanh saturates to 2·10⁻⁷; logistic: 16/32768); ReLU layers requantise to an activation scale
//! calibrated on the training inputs (max activation × 1.25); the output layer to a step
//! calibrated the same way (at least 1/32767 per unit, i.e. ±1 representable).

use anyhow::{bail, Result};
use bearing_core::film::ann::int::{lut_lookup, quantise_input, requantize, Lut, LUT_LEN};
use serde::{Deserialize, Serialize};

use super::mlp::{Activation, Mlp};

/// One quantised layer.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct QuantLayer {
    /// `weights[o][i]` at scale `weight_scale`.
    pub weights: Vec<Vec<i16>>,
    /// Biases at `input_scale · weight_scale`.
    pub bias: Vec<i64>,
    /// Q23 multiplier of the requantisation.
    pub multiplier: i32,
    /// Right shift of the requantisation.
    pub shift: u32,
    /// Scale of the layer input.
    pub input_scale: f64,
    /// Scale of the weights.
    pub weight_scale: f64,
    /// Scale the accumulator is requantised to.
    pub target_scale: f64,
}

/// The integer network.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Quantised {
    /// Bits of weight precision used (8 or 16; stored as i16 either way).
    pub weight_bits: u32,
    /// Hidden activation.
    pub activation: Activation,
    /// Table input scale `s_z` (tanh/logistic only).
    pub lut_input_scale: f64,
    /// Activation table (empty for ReLU).
    pub lut: Vec<i16>,
    /// Layers, output last.
    pub layers: Vec<QuantLayer>,
    /// Dequantisation step of the output.
    pub output_step: f64,
}

/// `ratio = multiplier · 2^−shift`, multiplier in [2²², 2²³).
fn multiplier_shift(ratio: f64) -> Result<(i32, u32)> {
    if !(ratio > 0.0 && ratio < 1.0) {
        bail!("requantisation ratio {ratio} outside (0, 1)");
    }
    let mut k = 0u32;
    let mut r = ratio;
    while r < 0.5 {
        r *= 2.0;
        k += 1;
    }
    let mut m = (r * (1u64 << 23) as f64).round() as i64;
    if m == 1 << 23 {
        if k == 0 {
            // A ratio within 2⁻²⁴ of 1: m = 2²² at shift 22 would leave the shift range the
            // core's exact host path accepts (≥ 23), so keep shift 23 and the largest
            // multiplier, one unit of 2⁻²³ off (the rounding above errs by up to half that).
            m = (1 << 23) - 1;
        } else {
            m /= 2;
            k -= 1;
        }
    }
    let shift = 23 + k;
    if shift > 62 {
        bail!("requantisation shift {shift} too large");
    }
    Ok((m as i32, shift))
}

/// The table input scale `s_z` of a hidden activation (module doc); 0 for ReLU, which has
/// no table.
pub fn table_input_scale(activation: Activation) -> f64 {
    match activation {
        Activation::Tanh => 8.0 / 32768.0,
        Activation::Logistic => 16.0 / 32768.0,
        Activation::Relu => 0.0,
    }
}

/// The activation table for `s_z`: `round(32767·f(x_k))`, `x_k = (64k − 32768)·s_z`.
pub fn table(activation: Activation, s_z: f64) -> Vec<i16> {
    (0..LUT_LEN)
        .map(|k| {
            let x = ((64 * k) as f64 - 32768.0) * s_z;
            (activation.apply(x) * 32767.0)
                .round()
                .clamp(-32768.0, 32767.0) as i16
        })
        .collect()
}

/// Quantise `net`; `calibration` are normalised training inputs (for ReLU and output ranges).
pub fn quantise(net: &Mlp, weight_bits: u32, calibration: &[Vec<f64>]) -> Result<Quantised> {
    if !(weight_bits == 8 || weight_bits == 16) {
        bail!("weight bits must be 8 or 16, got {weight_bits}");
    }
    let qmax = ((1i64 << (weight_bits - 1)) - 1) as f64;
    let s_z = table_input_scale(net.activation);
    // Per-layer activation ranges on the calibration set (f64 network).
    let n_layers = net.layers.len();
    let mut max_abs = vec![0.0f64; n_layers];
    for x in calibration {
        let mut a = x.clone();
        for (k, l) in net.layers.iter().enumerate() {
            a = l
                .weights
                .iter()
                .zip(&l.bias)
                .map(|(row, b)| b + row.iter().zip(&a).map(|(w, v)| w * v).sum::<f64>())
                .collect();
            if k + 1 < n_layers {
                a.iter_mut().for_each(|v| *v = net.activation.apply(*v));
            }
            max_abs[k] = a.iter().fold(max_abs[k], |m, v| m.max(v.abs()));
        }
    }
    let mut layers = Vec::with_capacity(n_layers);
    let mut s_in = 1.0 / 32767.0;
    for (k, l) in net.layers.iter().enumerate() {
        let last = k + 1 == n_layers;
        let wmax = l
            .weights
            .iter()
            .flatten()
            .fold(0.0f64, |m, w| m.max(w.abs()))
            .max(1e-12);
        let s_w = wmax / qmax;
        let target = if last || net.activation == Activation::Relu {
            (1.25 * max_abs[k]).max(1.0) / 32767.0
        } else {
            s_z
        };
        let (multiplier, shift) = multiplier_shift(s_in * s_w / target)?;
        let weights: Vec<Vec<i16>> = l
            .weights
            .iter()
            .map(|row| row.iter().map(|w| (w / s_w).round() as i16).collect())
            .collect();
        let bias: Vec<i64> = l
            .bias
            .iter()
            .map(|b| (b / (s_in * s_w)).round() as i64)
            .collect();
        let acc_bound: i64 = weights
            .iter()
            .zip(&bias)
            .map(|(row, b)| row.iter().map(|w| i64::from(*w).abs() * 32768).sum::<i64>() + b.abs())
            .max()
            .unwrap_or(0);
        if acc_bound >= 1 << 40 {
            bail!("layer {k}: accumulator bound {acc_bound} exceeds 2^40 (bias too large for the scale)");
        }
        layers.push(QuantLayer {
            weights,
            bias,
            multiplier,
            shift,
            input_scale: s_in,
            weight_scale: s_w,
            target_scale: target,
        });
        s_in = if net.activation == Activation::Relu {
            target
        } else {
            1.0 / 32767.0
        };
    }
    let output_step = layers.last().map_or(1.0, |l| l.target_scale);
    Ok(Quantised {
        weight_bits,
        activation: net.activation,
        lut_input_scale: s_z,
        lut: if net.activation == Activation::Relu {
            Vec::new()
        } else {
            table(net.activation, s_z)
        },
        layers,
        output_step,
    })
}

impl Quantised {
    /// Integer inference of normalised inputs → normalised outputs, as the core does it.
    pub fn forward(&self, x: &[f64]) -> Vec<f64> {
        let lut: Option<Lut> = self.lut.as_slice().try_into().ok();
        let mut a: Vec<i16> = x.iter().map(|v| quantise_input(*v as f32)).collect();
        let n = self.layers.len();
        for (k, l) in self.layers.iter().enumerate() {
            let z: Vec<i16> = l
                .weights
                .iter()
                .zip(&l.bias)
                .map(|(row, b)| {
                    let acc = row.iter().zip(&a).fold(*b, |s, (w, v)| {
                        s.wrapping_add(i64::from(i32::from(*w) * i32::from(*v)))
                    });
                    requantize(acc, l.multiplier, l.shift)
                })
                .collect();
            a = if k + 1 == n {
                z
            } else {
                match (self.activation, &lut) {
                    (Activation::Relu, _) => z.into_iter().map(|v| v.max(0)).collect(),
                    (_, Some(t)) => z.into_iter().map(|v| lut_lookup(t, v)).collect(),
                    (_, None) => z,
                }
            };
        }
        let step = self.output_step as f32;
        a.iter().map(|v| f64::from(f32::from(*v) * step)).collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// multiplier·2^−shift reproduces the ratio to Q23 precision (2⁻²³ relative).
    #[test]
    fn multiplier_shift_reproduces_ratio() {
        for ratio in [0.999_999_99, 0.9999999, 0.5, 0.3, 1e-3, 3.7e-9] {
            let (m, s) = multiplier_shift(ratio).unwrap();
            assert!((1 << 22..1 << 23).contains(&m));
            // The core's exact host path needs 23 ≤ shift ≤ 62 (`exact_f64::ExactF64::new`).
            assert!((23..=62).contains(&s), "{ratio}: shift {s}");
            let back = f64::from(m) / 2f64.powi(s as i32);
            assert!(
                (back / ratio - 1.0).abs() < 2.0 / (1u64 << 23) as f64,
                "{ratio}"
            );
        }
        assert!(multiplier_shift(1.5).is_err());
    }

    /// The integer network tracks the f64 network it came from (int16: within 1e-3 of the
    /// output range on random inputs, for every activation).
    #[test]
    fn int16_tracks_float() {
        for act in [Activation::Tanh, Activation::Logistic, Activation::Relu] {
            let net = Mlp::new(3, &[12, 12], 2, act, 9);
            let calib: Vec<Vec<f64>> = (0..200)
                .map(|i| {
                    (0..3)
                        .map(|d| ((i * 7 + d * 13) % 200) as f64 / 100.0 - 1.0)
                        .collect()
                })
                .collect();
            let q = quantise(&net, 16, &calib).unwrap();
            for x in calib.iter().step_by(7) {
                let (f, i) = (net.forward(x), q.forward(x));
                for (a, b) in f.iter().zip(&i) {
                    assert!((a - b).abs() < 1e-3, "{act:?}: {a} vs {b}");
                }
            }
        }
    }
}
