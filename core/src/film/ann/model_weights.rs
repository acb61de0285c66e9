//! Bootstrap placeholder, replaced by `bearing export`.
use super::float::{Activation, DenseF32};
use super::int::{DenseInt, Lut};
use super::{DomainLimits, InputSet, TargetForm};
pub const MODEL_FINGERPRINT: &str = "bootstrap";
pub const INPUT_SET: InputSet = InputSet::Wug;
pub const N_IN: usize = 3;
pub const TARGET: TargetForm = TargetForm::LogRatio;
pub const ACTIVATION: Activation = Activation::Tanh;
pub const DOMAIN: DomainLimits = DomainLimits { inputs: [[1.0, 1.0]; 7], ln_hertz_pressure: [0.0, 0.0], piezo_min_log_ratio: 0.0, elastic_max_log_ratio: 0.0 };
pub const INPUT_MIN: [f32; N_IN] = [0.0; 3];
pub const INPUT_SCALE: [f32; N_IN] = [1.0; 3];
pub const OUTPUT_MIN: [f32; 2] = [0.0; 2];
pub const OUTPUT_HALF_RANGE: [f32; 2] = [0.0; 2];
pub const INT_OUTPUT_STEP: f32 = 0.0;
pub fn select_features(f: &[f32; 5]) -> [f32; N_IN] { [f[0], f[1], f[2]] }
pub static F32_LAYER_0: DenseF32<3, 2> = DenseF32 { weights: [[0.0; 3]; 2], bias: [0.0; 2] };
pub fn forward_f32(x: &[f32; N_IN]) -> [f32; 2] { F32_LAYER_0.forward(x, ACTIVATION) }
pub static INT_LAYER_0: DenseInt<3, 2> = DenseInt { weights: [[0; 3]; 2], bias: [0; 2], multiplier: 0, shift: 0 };
pub static LUT: Lut = [0; 1025];
pub fn forward_int(x: &[i16; N_IN]) -> [i16; 2] { INT_LAYER_0.forward_lut(x, &LUT) }
