//! One module per `bearing` subcommand.
pub mod ehl;
pub mod ehl_plot;
