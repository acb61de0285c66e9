//! Host side of the bearing project (std, f64 where it is a reference).

pub mod ann;
pub mod dataset;
