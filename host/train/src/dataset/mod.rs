//! Training data for the film network: contact cases sampled by a maximin Latin hypercube over
//! the domain of docs/physics.md §5.3, solved in parallel by any film solver, written to a resumable
//! JSON-lines file that carries its own metadata.
//!
//! - [`domain`]: input box, Hertz window, regime test.
//! - [`lhs`]: maximin-optimised Latin hypercube.
//! - [`file`](mod@file): the dataset file format (metadata header + one record per case), for
//!   line and point contacts.
//! - [`generate`](mod@generate): deterministic, parallel, resumable generation over a solver closure.
//! - [`formulas`]: regression and Moes formulas (f64), the latter the pipeline stand-in target.
//! - [`numerical`]: the numerical EHL solver as the dataset solver.
//! - [`point_domain`]: the point-contact (ball-bearing) domain.
//! - [`point_numerical`]: the point-contact solver as a dataset solver, with grid-error refusals.
//! - [`reference`](mod@reference): check that the reference machines of docs/physics.md §6 lie in the domain.

pub mod domain;
pub mod file;
pub mod formulas;
pub mod generate;
pub mod lhs;
pub mod numerical;
pub mod point_domain;
pub mod point_numerical;
pub mod reference;

use serde::{Deserialize, Serialize};

pub use domain::Domain;
pub use file::{Dataset, DatasetContact, LineFilms, Metadata, Record, SolverInfo};
pub use generate::{generate, GenerateOptions};

/// One line contact to solve, in SI units (the f64 twin of the core's `ContactInput`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize, Deserialize)]
pub struct ContactCase {
    /// Roller load Q (N).
    pub load_n: f64,
    /// Entrainment speed u_m (m/s).
    pub entrainment_speed_m_s: f64,
    /// Reduced radius R (m).
    pub reduced_radius_m: f64,
    /// Reduced modulus E' (Pa).
    pub reduced_modulus_pa: f64,
    /// Pressure–viscosity coefficient α (1/Pa).
    pub pressure_viscosity_pa_inv: f64,
    /// Ambient viscosity η₀ (Pa·s).
    pub viscosity_pa_s: f64,
    /// Effective contact length l (m).
    pub length_m: f64,
}

impl ContactCase {
    /// Load per unit length w = Q/l (N/m).
    pub fn load_per_length(&self) -> f64 {
        self.load_n / self.length_m
    }

    /// Dimensionless `(W, U, G)` of docs/physics.md §1: `W = w/(E'R)`, `U = η₀u_m/(E'R)`, `G = αE'`.
    pub fn dimensionless(&self) -> (f64, f64, f64) {
        let er = self.reduced_modulus_pa * self.reduced_radius_m;
        (
            self.load_per_length() / er,
            self.viscosity_pa_s * self.entrainment_speed_m_s / er,
            self.pressure_viscosity_pa_inv * self.reduced_modulus_pa,
        )
    }

    /// Maximum Hertz pressure `p_h = √(w E' / (2π R))` (docs/physics.md §1), Pa.
    pub fn hertz_pressure_pa(&self) -> f64 {
        (self.load_per_length() * self.reduced_modulus_pa
            / (2.0 * std::f64::consts::PI * self.reduced_radius_m))
            .sqrt()
    }

    /// Conversion to the core's f32 contact input.
    pub fn to_core(&self) -> bearing_core::film::ContactInput {
        bearing_core::film::ContactInput {
            load_n: self.load_n as f32,
            length_m: self.length_m as f32,
            entrainment_speed_m_s: self.entrainment_speed_m_s as f32,
            reduced_radius_m: self.reduced_radius_m as f32,
            reduced_modulus_pa: self.reduced_modulus_pa as f32,
            pressure_viscosity_pa_inv: self.pressure_viscosity_pa_inv as f32,
            viscosity_pa_s: self.viscosity_pa_s as f32,
        }
    }

    /// Every field finite and strictly positive.
    pub fn is_physical(&self) -> bool {
        [
            self.load_n,
            self.entrainment_speed_m_s,
            self.reduced_radius_m,
            self.reduced_modulus_pa,
            self.pressure_viscosity_pa_inv,
            self.viscosity_pa_s,
            self.length_m,
        ]
        .iter()
        .all(|v| v.is_finite() && *v > 0.0)
    }
}

/// The Moes stand-in solver (docs/physics.md §5.1): `(h_c, h_min)` in metres, see
/// [`formulas::moes_central`] and [`formulas::moes_minimum`]. For pipeline tests only.
pub fn moes_solver(case: &ContactCase) -> Result<(f64, f64), String> {
    if !case.is_physical() {
        return Err("non-physical input (every field must be finite and > 0)".into());
    }
    let (w, u, g) = case.dimensionless();
    let r = case.reduced_radius_m;
    Ok((
        formulas::moes_central(w, u, g) * r,
        formulas::moes_minimum(w, u, g) * r,
    ))
}
