//! One module per `bearing` subcommand.

pub mod common;
pub mod dataset;
pub mod ehl;
pub mod export;
pub mod film;
pub mod fmu;
pub mod friction;
pub mod shaft;
pub mod statics;
pub mod train;
