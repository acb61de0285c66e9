//! The numerical EHL solver (`bearing_ehl`, docs/physics.md §5.2) as a dataset solver: the film
//! network's real training target.
//!
//! The solver works per unit length (w = Q/l): Q and l enter the isothermal line contact only
//! through w, one more reason the network's inputs are the dimensionless groups. Each rayon
//! thread keeps its own [`bearing_ehl::Solver`] (grid and O(N²) deflection kernel built once); every
//! solve starts from the Hertz pressure, so results do not depend on which thread solved which
//! case, and generation stays deterministic.
//!
//! **Plausibility.** A solve that meets the convergence criteria can still have converged to a
//! wrong solution: at the high-M corner of the domain (M ≈ 900–1500, L ≈ 5, p_h ≈ 3.4 GPa)
//! the solver has returned films 2–40 times below Moes' formula with h_min = h_c, a collapsed
//! film. The formulas and full solutions disagree by tens of percent at most (docs/physics.md §5.1),
//! so a central film outside [½, 2] × Moes' is recorded as a failure with that reason rather
//! than taught to the network — one such case carried most of the training loss.

use std::cell::RefCell;

use super::formulas::moes_central;
use super::{ContactCase, SolverInfo};

/// A converged central film outside `[1/PLAUSIBLE_FACTOR, PLAUSIBLE_FACTOR]` × Moes' formula is
/// refused (see the module doc).
pub const PLAUSIBLE_FACTOR: f64 = 2.0;

thread_local! {
    static SOLVER: RefCell<Option<(bearing_ehl::SolverOptions, bearing_ehl::Solver)>> = const { RefCell::new(None) };
}

/// Dataset header entry for the numerical solver with `options`.
pub fn solver_info(options: &bearing_ehl::SolverOptions) -> SolverInfo {
    SolverInfo {
        name: "numerical".into(),
        version: format!(
            "bearing-host {} ehl::Solver (Newton, active-set cavitation)",
            env!("CARGO_PKG_VERSION")
        ),
        options: serde_json::to_value(options).unwrap_or(serde_json::Value::Null),
    }
}

/// Solve one case: `(h_c, h_min)` in metres, or the solver's error message.
pub fn solve(
    case: &ContactCase,
    options: &bearing_ehl::SolverOptions,
) -> Result<(f64, f64), String> {
    let c = bearing_ehl::ContactCase::new(
        case.load_per_length(),
        case.entrainment_speed_m_s,
        case.reduced_radius_m,
        case.reduced_modulus_pa,
        case.pressure_viscosity_pa_inv,
        case.viscosity_pa_s,
    )
    .map_err(|e| e.to_string())?;
    SOLVER.with(|cell| {
        let mut slot = cell.borrow_mut();
        if slot.as_ref().is_none_or(|(o, _)| o != options) {
            *slot = Some((
                *options,
                bearing_ehl::Solver::new(*options).map_err(|e| e.to_string())?,
            ));
        }
        let Some((_, solver)) = slot.as_mut() else {
            return Err("solver workspace missing".to_string());
        };
        let (central, minimum) = solver
            .solve(&c)
            .map(|s| (s.central_film_m, s.min_film_m))
            .map_err(|e| e.to_string())?;
        plausible(case, central)?;
        Ok((central, minimum))
    })
}

/// `Ok` when the central film `central_m` is within [`PLAUSIBLE_FACTOR`] of Moes' formula.
pub fn plausible(case: &ContactCase, central_m: f64) -> Result<(), String> {
    let (w, u, g) = case.dimensionless();
    let moes_m = moes_central(w, u, g) * case.reduced_radius_m;
    let ratio = central_m / moes_m;
    if ratio.is_finite() && (1.0 / PLAUSIBLE_FACTOR..=PLAUSIBLE_FACTOR).contains(&ratio) {
        Ok(())
    } else {
        Err(format!(
            "implausible converged film: h_c = {central_m:.4e} m is {ratio:.3} × Moes' formula \
             ({moes_m:.4e} m), outside [1/{PLAUSIBLE_FACTOR}, {PLAUSIBLE_FACTOR}]"
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dataset::formulas::dowson_toyoda_central;

    /// The plausibility gate passes a film near Moes' formula and refuses the collapsed film
    /// the solver once returned at M ≈ 1500 (0.024 × Moes), and non-finite films.
    #[test]
    fn plausibility_gate() {
        let case = ContactCase {
            load_n: 1000.0,
            entrainment_speed_m_s: 2.0,
            reduced_radius_m: 10e-3,
            reduced_modulus_pa: 226e9,
            pressure_viscosity_pa_inv: 2e-8,
            viscosity_pa_s: 0.04,
            length_m: 10e-3,
        };
        let (w, u, g) = case.dimensionless();
        let moes_m = moes_central(w, u, g) * case.reduced_radius_m;
        assert!(plausible(&case, 1.3 * moes_m).is_ok());
        assert!(plausible(&case, 0.6 * moes_m).is_ok());
        let err = plausible(&case, 0.024 * moes_m).unwrap_err();
        assert!(err.contains("implausible"), "{err}");
        assert!(plausible(&case, 2.5 * moes_m).is_err());
        assert!(plausible(&case, f64::NAN).is_err());
    }

    /// A moderate contact (1000 N on 10 mm, 2 m/s, R = 10 mm, α = 20 GPa⁻¹, η₀ = 0.04 Pa·s,
    /// p_h ≈ 0.6 GPa): the numerical central film lies within 25 % of Dowson–Toyoda and of Moes
    /// (docs/physics.md §5.1: the formulas disagree with full solutions by several to more than ten
    /// percent), and 0.5 h_c < h_min < h_c.
    #[test]
    fn numerical_film_is_near_the_formulas() {
        let case = ContactCase {
            load_n: 1000.0,
            entrainment_speed_m_s: 2.0,
            reduced_radius_m: 10e-3,
            reduced_modulus_pa: 226e9,
            pressure_viscosity_pa_inv: 2e-8,
            viscosity_pa_s: 0.04,
            length_m: 10e-3,
        };
        let (hc, hmin) = solve(&case, &bearing_ehl::SolverOptions::default()).unwrap();
        let (w, u, g) = case.dimensionless();
        let r = case.reduced_radius_m;
        for reference in [
            dowson_toyoda_central(w, u, g) * r,
            moes_central(w, u, g) * r,
        ] {
            assert!(
                (hc / reference - 1.0).abs() < 0.25,
                "h_c {hc:e} vs {reference:e}"
            );
        }
        assert!(hmin < hc && hmin > 0.5 * hc, "h_min {hmin:e}, h_c {hc:e}");
    }
}
