//! The film network's pipeline on the host: training datasets of contact cases solved by a
//! film solver, and the network's training, quantisation, model file and export into the core.

pub mod ann;
pub mod dataset;
