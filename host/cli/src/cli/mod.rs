//! One module per `bearing` subcommand.

pub mod common;
pub mod dataset;
pub mod ehl;
pub mod ehl_compare;
pub mod ehl_plot;
mod ehl_trust;
pub mod export;
pub mod film;
mod film_plot;
mod film_point;
pub mod fmu;
pub mod friction;
pub mod friction_contact;
pub mod shaft;
pub mod statics;
pub mod statics_ball;
pub mod train;
