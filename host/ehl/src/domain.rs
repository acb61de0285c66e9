//! Where the solver's model holds, and refusals outside it.
//!
//! The solver integrates Reynolds' thin-film equation over the parabolic gap h₀ + x²/2R of a
//! continuum lubricant with a fully flooded inlet (docs/physics.md §5.2). Three limits follow:
//!
//! - **Continuum film.** Below about a nanometre the film is a few molecules thick and the
//!   Reynolds equation (a continuum with no-slip walls) no longer describes it:
//!   h_min ≥ [`MIN_FILM_M`].
//! - **Thin film on a parabolic gap.** The fully flooded inlet reaches x ≈ 10√(h_c R) (where
//!   Martin's rigid-inlet pressure has decayed to ~0.3 % of its peak, see [`super::driver`]).
//!   Keeping that inside R/2, where the parabola is within 6 % of the circle's gap
//!   (R − √(R² − x²) = x²/2R·(1 + x²/4R² + …)), gives h_c ≤ R/400 =
//!   [`MAX_FILM_OVER_RADIUS`]·R; the film is then also thin against every length of the gap.
//! - **An EHL contact on the grid.** The grid stretches its inlet to 10√H_c Hertz half-widths
//!   (H_c = h_c R/b²) up to 20 times its default 4.5 b; a film thicker than that (H_c > 81:
//!   a load so light that the film is 81 times the Hertz deflection scale b²/R) has an inlet
//!   the grid cannot hold flooded.

use super::{formulas, ContactCase, EhlError, EhlSolution, SolverOptions};

/// Thinnest film the continuum model is used for (m).
pub const MIN_FILM_M: f64 = 1e-9;
/// Thickest central film relative to the reduced radius.
pub const MAX_FILM_OVER_RADIUS: f64 = 1.0 / 400.0;
/// Largest stretch of the grid's inlet (the clamp of the driver's domain scale).
pub const MAX_DOMAIN_STRETCH: f64 = 20.0;

/// The central film the solver starts from (Moes' formula; Martin's gap when rigid), m.
fn predicted_central_film_m(case: &ContactCase, opts: &SolverOptions) -> f64 {
    if opts.elastic {
        formulas::moes_central_film_m(case)
    } else {
        formulas::martin_gap_m(case)
    }
}

fn outside(quantity: &'static str, value: f64, allowed: String, reason: &'static str) -> EhlError {
    EhlError::OutsideModel {
        quantity,
        value,
        allowed,
        reason,
    }
}

/// Central film h_c (m) against the three limits of the module docs.
fn check_central_film(case: &ContactCase, opts: &SolverOptions, h_c: f64) -> Result<(), EhlError> {
    if h_c < MIN_FILM_M {
        return Err(outside(
            "central film h_c (m)",
            h_c,
            format!("≥ {MIN_FILM_M:e} m"),
            "a film of a few molecules is not a continuum: raise the speed or the viscosity, or lower the load",
        ));
    }
    let r = case.reduced_radius_m;
    if h_c > MAX_FILM_OVER_RADIUS * r {
        return Err(outside(
            "central film over reduced radius h_c/R",
            h_c / r,
            format!("≤ {MAX_FILM_OVER_RADIUS} (the thin-film, parabolic-gap approximation)"),
            "the film is not thin against the radius: raise the load or lower the speed or the viscosity",
        ));
    }
    let h_dimensionless = h_c / case.film_scale_m();
    let stretch = 10.0 * h_dimensionless.sqrt() / -opts.x_start;
    if stretch > MAX_DOMAIN_STRETCH {
        return Err(outside(
            "central film in Hertz units H_c = h_c R/b²",
            h_dimensionless,
            format!(
                "≤ {:.0} (a flooded inlet within {MAX_DOMAIN_STRETCH} × {} b)",
                (MAX_DOMAIN_STRETCH * -opts.x_start / 10.0).powi(2),
                -opts.x_start
            ),
            "the load is too light to make an elastohydrodynamic contact",
        ));
    }
    Ok(())
}

/// Refuses a case whose predicted central film (Moes; Martin when rigid) is outside the
/// model's domain, before solving it.
pub fn check_case(case: &ContactCase, opts: &SolverOptions) -> Result<(), EhlError> {
    check_central_film(case, opts, predicted_central_film_m(case, opts))
}

/// Refuses a solution whose films are outside the model's domain.
pub fn check_solution(sol: &EhlSolution, opts: &SolverOptions) -> Result<(), EhlError> {
    check_central_film(&sol.case, opts, sol.central_film_m)?;
    if sol.min_film_m < MIN_FILM_M {
        return Err(outside(
            "minimum film h_min (m)",
            sol.min_film_m,
            format!("≥ {MIN_FILM_M:e} m"),
            "a film of a few molecules is not a continuum: raise the speed or the viscosity, or lower the load",
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn si(load_n: f64, length_m: f64, speed: f64) -> ContactCase {
        ContactCase::new(load_n / length_m, speed, 0.0032, 2.308e11, 2.1e-8, 0.08).unwrap()
    }

    /// The two cases of a hostile user: a 1 mN load (film of millimetres on a 3.2 mm radius)
    /// and 1 µm/s (a 10⁻¹¹ m film) are refused; a bearing contact (1.5 kN, 10 m/s) is not.
    #[test]
    fn films_outside_the_model_are_refused() {
        let opts = SolverOptions::default();
        let e = check_case(&si(1e-3, 0.009, 5.0), &opts).unwrap_err();
        assert!(e.to_string().contains("h_c/R"), "{e}");
        let e = check_case(&si(800.0, 0.009, 1e-6), &opts).unwrap_err();
        assert!(e.to_string().contains("central film h_c (m)"), "{e}");
        check_case(&si(1500.0, 0.015, 10.0), &opts).unwrap();
    }

    /// A light load with a film thin against the radius but thick against the Hertz
    /// deflection (H_c > 81) is refused as not an EHL contact.
    #[test]
    fn light_loads_are_not_an_ehl_contact() {
        let opts = SolverOptions::default();
        let case = si(0.05, 0.009, 0.01);
        let h = formulas::moes_central_film_m(&case);
        assert!(
            h < MAX_FILM_OVER_RADIUS * case.reduced_radius_m && h > MIN_FILM_M,
            "{h}"
        );
        let e = check_case(&case, &opts).unwrap_err();
        assert!(e.to_string().contains("H_c"), "{e}");
    }
}
