//! What the host programs share (std): command-line parsing, the bearing configuration file, the lines of TOML fields
//! for error messages, the core's bearing at a run-time roller count, the core's friction model
//! at given roller loads with host films, the processor check at start-up, the plot style,
//! output files written whole or not at all and the quiet end on a closed pipe.

pub mod args;
pub mod ball_config;
pub mod closed_pipe;
pub mod config;
pub mod cpu;
pub mod friction;
pub mod output;
pub mod plot_style;
pub mod rolling;
pub mod toml_lines;
