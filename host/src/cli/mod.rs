//! One module per `bearing` subcommand.

pub mod dataset;
