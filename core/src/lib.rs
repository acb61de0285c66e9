//! Lubricated cylindrical roller bearing model for real-time loops.
#![no_std]

pub mod film;
