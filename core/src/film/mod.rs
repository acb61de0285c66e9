//! Film models: the lubricant film thickness of one roller–race line contact.
//!
//! Every model — the regression formulas, the hydrodynamic (Martin) film, and the neural
//! networks of `film::ann` — answers the same question through [`FilmModel`]: given the
//! contact's load, geometry, speed and lubricant, what are the central and minimum film
//! thickness? The bearing step only talks to the trait, so a model can be swapped without
//! touching the bearing code.
//!
//! Conventions are those of PHYSICS.md §1: `E'` is the reduced modulus
//! `2 / [(1−ν₁²)/E₁ + (1−ν₂²)/E₂]`, `R` the reduced radius in the rolling direction,
//! loads are per roller (N) over the effective length `l` (m).

pub mod ann;

/// Everything the isothermal line-contact film depends on (PHYSICS.md §5.3: solid density and
/// Poisson's ratio do not enter once `E'` is given).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactInput {
    /// Roller load carried by this contact, Q (N).
    pub load_n: f32,
    /// Effective contact length, l (m).
    pub length_m: f32,
    /// Entrainment (mean rolling) speed, u_m (m/s).
    pub entrainment_speed_m_s: f32,
    /// Reduced radius in the rolling direction, R (m).
    pub reduced_radius_m: f32,
    /// Reduced modulus, E' (Pa).
    pub reduced_modulus_pa: f32,
    /// Pressure–viscosity coefficient, α (1/Pa).
    pub pressure_viscosity_pa_inv: f32,
    /// Dynamic viscosity at ambient pressure, η₀ (Pa·s).
    pub viscosity_pa_s: f32,
}

/// Which model produced a film value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[repr(u8)]
pub enum FilmSource {
    /// No film: the dry model, or a contact without entrainment.
    None = 0,
    /// A regression formula (Dowson–Toyoda / Dowson–Higginson).
    Regression = 1,
    /// The f32 neural network.
    NetworkF32 = 2,
    /// The integer (quantised) neural network.
    NetworkInt = 3,
    /// A regression formula standing in for a network whose domain the contact left.
    Fallback = 4,
}

/// Film thickness of one contact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Film {
    /// Central film thickness h_c, at X = 0 (m).
    pub central_m: f32,
    /// Minimum film thickness h_min, near the outlet (m).
    pub minimum_m: f32,
    /// Which model served this contact.
    pub source: FilmSource,
}

impl Film {
    /// The film of a dry contact.
    pub const ZERO: Film = Film {
        central_m: 0.0,
        minimum_m: 0.0,
        source: FilmSource::None,
    };
}

/// A film thickness model for a loaded line contact.
///
/// Implementations must be total: for any input (NaN, ∞, negative, huge) they return a finite,
/// non-negative film — falling back to a regression formula, or to zero, and saying so through
/// [`Film::source`] — and they must do the same amount of work for every input.
pub trait FilmModel {
    /// Short stable name, used in reports and JSON (`"regression"`, `"ann_f32"`, `"ann_int"`).
    fn name(&self) -> &'static str;
    /// Central and minimum film of one contact.
    fn film(&self, contact: &ContactInput) -> Film;
}

mod groups;
mod hydrodynamic;
mod regime;
mod regression;

pub use groups::LnGroups;
pub use hydrodynamic::{
    martin_central_m, martin_load_per_length, Hydrodynamic, MARTIN_CENTRAL, MARTIN_MINIMUM,
};
pub use regime::Regime;
pub use regression::{
    dowson_higginson_minimum_m, dowson_toyoda_central_m, moes_central, Regression,
    CENTRAL_LOAD_EXPONENT, MINIMUM_LOAD_EXPONENT,
};
