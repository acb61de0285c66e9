//! One module per `bearing` subcommand.

pub mod common;
pub mod dataset;
pub mod export;
pub mod film;
pub mod statics;
pub mod train;
