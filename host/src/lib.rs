//! Host side of the bearing project (std, f64 where it is a reference): configuration files,
//! the core's bearing at a run-time roller count, and (in their modules) the numerical EHL
//! solver, datasets and training, and the flexible-shaft simulator.

pub mod ann;
pub mod config;
pub mod cpu;
pub mod dataset;
pub mod ehl;
pub mod plot_style;
pub mod rolling;
pub mod shaft;
