//! The film network on the host: features and targets, the MLP, Levenberg–Marquardt training
//! with early stopping, accuracy metrics, the architecture sweep, quantisation to integers, the
//! versioned model file and the code generator that writes the weights into the core.

pub mod export;
pub mod features;
pub mod metrics;
pub mod mlp;
pub mod model;
pub mod pipeline;
pub mod quant;
pub mod sweep;
pub mod train;
pub mod trainlm;
