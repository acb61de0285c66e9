//! One module per `bearing` subcommand.

pub mod common;
pub mod ehl;
pub mod ehl_plot;
pub mod film;
pub mod shaft;
pub mod statics;
