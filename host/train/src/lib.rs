//! The film network's pipeline on the host: training datasets of contact cases solved by a
//! film solver, and the network's training, quantisation, model file and export into the core;
//! and the generators of the core's other generated files (`generated`).

pub mod ann;
pub mod dataset;
pub mod generated;
pub mod traction_table;
