//! One module per `bearing` subcommand.

pub mod common;
pub mod film;
pub mod shaft;
pub mod statics;
