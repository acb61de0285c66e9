//! One module per `bearing` subcommand.

pub mod dataset;
pub mod export;
pub mod train;
