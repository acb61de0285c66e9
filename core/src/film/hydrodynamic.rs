//! Hydrodynamic (rigid, iso-viscous) film of a lightly loaded or separated roller.
//!
//! Martin's solution with the Reynolds exit condition (Martin 1916; Hamrock, *Fundamentals of
//! Fluid Film Lubrication*, §21.2): a rigid cylinder on a plane with gap h₀ at the outlet carries
//! w = 4.896·η₀u_mR/h₀ per unit length, i.e. h₀/R = 4.896·U/W (docs/physics.md §5.1). A rigid
//! cylinder's gap h₀ + x²/2R is smallest at X = 0, the contact centre, so its central and
//! minimum films are the same gap: one constant serves both. (Moes' rigid iso-viscous asymptote
//! H_RI = 3/M, i.e. h/R = 6·U/W, is an interpolation end of his fit and 22 % above Martin's
//! solution, which the numerical solver reproduces to < 1 %: `bearing-ehl`'s
//! `martin_rigid_isoviscous_limit`.)

use super::{ContactInput, Film, FilmModel, FilmSource, ServedLoads};

/// Martin's constant: h₀/R = 4.896·U/W (Martin 1916, Reynolds exit condition).
pub const MARTIN: f32 = 4.896;

/// Martin's film h₀ = 4.896·η₀u_m·R·l/Q (m) for load `Q` (N): the central and the minimum gap.
pub fn martin_film_m(contact: &ContactInput) -> f32 {
    MARTIN * contact.viscosity_pa_s * contact.entrainment_speed_m_s * contact.reduced_radius_m
        / contact.load_per_length_n_per_m()
}

/// Load per unit length (N/m) that Martin's solution carries on an outlet gap `h₀` (m).
pub fn martin_load_per_length(
    viscosity_pa_s: f32,
    entrainment_speed_m_s: f32,
    reduced_radius_m: f32,
    gap_m: f32,
) -> f32 {
    MARTIN * viscosity_pa_s * entrainment_speed_m_s * reduced_radius_m / gap_m
}

/// Martin's hydrodynamic film model.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Hydrodynamic;

impl FilmModel for Hydrodynamic {
    fn name(&self) -> &'static str {
        "hydrodynamic"
    }

    fn served_loads(&self, _template: &ContactInput) -> ServedLoads {
        // The formula serves every load; `film` returns zero for an invalid contact.
        ServedLoads::everywhere(FilmSource::Regression)
    }

    fn film(&self, contact: &ContactInput) -> Film {
        let gap_m = martin_film_m(contact);
        let film = Film {
            central_m: gap_m,
            minimum_m: gap_m,
            source: FilmSource::Regression,
        };
        if contact.is_valid() && gap_m.is_finite() {
            film
        } else {
            Film::ZERO
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn load_and_film_are_inverse() {
        let c = ContactInput {
            load_n: 20.0,
            length_m: 0.01,
            entrainment_speed_m_s: 5.0,
            reduced_radius_m: 3e-3,
            reduced_modulus_pa: 2.3e11,
            pressure_viscosity_pa_inv: 2e-8,
            viscosity_pa_s: 0.05,
        };
        let f = Hydrodynamic.film(&c);
        let w = martin_load_per_length(0.05, 5.0, 3e-3, f.minimum_m);
        assert!((w * 0.01 / 20.0 - 1.0).abs() < 1e-5);
    }
}
