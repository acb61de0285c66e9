//! Tests of the shaft simulator against independent references (closed forms, published
//! numbers). Each test names its reference.

mod analysis_tests;
mod config_tests;
mod element_tests;
mod hub_tests;
mod integrator_tests;
mod modes_tests;
mod ramp_tests;
mod response_tests;
mod rig_tests;
mod statics_tests;
