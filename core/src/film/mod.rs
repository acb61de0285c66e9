//! Film models: the lubricant film thickness of one roller–race line contact, and of one
//! ball–race point contact ([`point`]).
//!
//! Every model — the regression formulas, the hydrodynamic (Martin) film, and the neural
//! networks of `film::ann` — answers the same question through [`FilmModel`]: given the
//! contact's load, geometry, speed and lubricant, what are the central and minimum film
//! thickness? The bearing step only talks to the trait, so a model can be swapped without
//! touching the bearing code.
//!
//! Conventions are those of docs/physics.md §1: `E'` is the reduced modulus
//! `2 / [(1−ν₁²)/E₁ + (1−ν₂²)/E₂]`, `R` the reduced radius in the rolling direction,
//! loads are per roller (N) over the effective length `l` (m).

pub mod ann;
pub mod corrections;
pub mod point;

pub use point::PointContactInput;

/// A contact a film model takes: the line contact's [`ContactInput`] or the point contact's
/// [`PointContactInput`]. The film models' domain tests are bounds on the load once the rest of
/// the contact is fixed, which [`FilmModel::served_loads`] reports; this is how it sets the load.
pub trait FilmContact: Copy {
    /// The same contact carrying `load_n` (N).
    fn with_load_n(&self, load_n: f32) -> Self;
}

impl FilmContact for ContactInput {
    #[inline]
    fn with_load_n(&self, load_n: f32) -> Self {
        Self { load_n, ..*self }
    }
}

/// Everything the isothermal line-contact film depends on (docs/physics.md §5.3: solid density and
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

/// A film thickness model for a loaded contact of kind `C`: the line contact
/// ([`ContactInput`], the default) or the point contact ([`PointContactInput`]).
///
/// The film is the *complete* isothermal film of the contact at any load, as the numerical
/// solver of docs/physics.md §5.2 would give it: elastic–piezoviscous where the contact is loaded,
/// tending to Martin's rigid iso-viscous film (h₀/R = 4.896U/W) as the load vanishes. The bearing's
/// film–load coupling relies on that rise at light load for a continuous separation of the
/// rollers (`bearing::roller::coupling`); a model of the EHL regime alone blends itself with Martin's
/// film, as [`Regression`] does. (The point-contact models of [`point`] serve the EHL regime
/// of Hamrock–Dowson's formulas and their network's training domain; no bearing step relies on
/// their light-load limit yet.)
///
/// Implementations must be total: for any input (NaN, ∞, negative, huge) they return a finite,
/// non-negative film — falling back to a regression formula, or to zero, and saying so through
/// [`Film::source`] — and they must do the same amount of work for every input.
pub trait FilmModel<C: FilmContact = ContactInput> {
    /// Short stable name, used in reports and JSON (`"regression"`, `"ann_f32"`, `"ann_int"`).
    fn name(&self) -> &'static str;
    /// Central and minimum film of one contact.
    fn film(&self, contact: &C) -> Film;

    /// The loads at which this model itself serves contacts like `template` (its load is
    /// ignored): an interval of ln Q (N) and the source it reports there. Outside the interval
    /// the model falls back. Every domain test of a film model is monotone in ln Q once the
    /// other inputs are fixed, so the bearing step asks this once per contact kind and step and
    /// flags each roller with two comparisons. The default serves every load and reports the
    /// source of one call.
    fn served_loads(&self, template: &C) -> ServedLoads {
        ServedLoads {
            ln_load_min: f32::MIN,
            ln_load_max: f32::MAX,
            source: self.film(&template.with_load_n(1000.0)).source,
        }
    }
}

/// Where a film model serves contacts of one kind: ln Q ∈ [`ln_load_min`, `ln_load_max`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ServedLoads {
    /// Smallest ln Q served (ln N).
    pub ln_load_min: f32,
    /// Largest ln Q served (ln N).
    pub ln_load_max: f32,
    /// The source reported for served contacts.
    pub source: FilmSource,
}

impl ServedLoads {
    /// Every load served, reported as `source` (a formula that holds everywhere).
    pub const fn everywhere(source: FilmSource) -> Self {
        Self {
            ln_load_min: f32::MIN,
            ln_load_max: f32::MAX,
            source,
        }
    }

    /// The source of a contact at ln Q: the model's own inside the interval,
    /// [`FilmSource::Fallback`] outside. Two comparisons, no branch.
    #[inline]
    pub fn source_at(&self, ln_load: f32) -> FilmSource {
        let inside = (ln_load >= self.ln_load_min) & (ln_load <= self.ln_load_max);
        if inside {
            self.source
        } else {
            FilmSource::Fallback
        }
    }
}

mod groups;
mod hydrodynamic;
mod regime;
mod regression;

pub use groups::LnGroups;
pub use hydrodynamic::{martin_film_m, martin_load_per_length, Hydrodynamic, MARTIN};
pub use regime::{Regime, RegimeAxis};
pub use regression::{
    dowson_higginson_minimum_m, dowson_toyoda_central_m, moes_central, Regression,
    CENTRAL_LOAD_EXPONENT, MINIMUM_LOAD_EXPONENT,
};
