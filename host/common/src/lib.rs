//! What the host programs share (std): the bearing configuration file, the lines of TOML fields
//! for error messages, the core's bearing at a run-time roller count, the processor check at
//! start-up and the plot style.

pub mod config;
pub mod cpu;
pub mod plot_style;
pub mod rolling;
pub mod toml_lines;
