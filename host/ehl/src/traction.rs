//! Viscous traction of a converged solution: the Eyring shear stress of the film integrated
//! over the solver's pressure and film profile — the host reference of the core's viscous
//! friction (docs/physics.md §8.3).
//!
//! At a sliding speed u_s the film of local thickness h(x) shears at u_s/h, and an Eyring fluid
//! of Eyring stress τ₀ carries τ = τ₀·asinh(η(p)·u_s/(h·τ₀)) (Johnson & Tevaarwerk, Proc. R.
//! Soc. A 356 (1977) 215–236), with the viscosity η(p) of the solver's pressure–viscosity law.
//! The integral is isothermal — no shear heating — and Newtonian-Reynolds: the pressure and
//! film are the solver's, which assumes a Newtonian film (at the small slide-to-roll ratios
//! of a roller bearing the Eyring stress barely alters them). It runs from the inlet to the
//! film exit (the cavitated outlet carries no full film).

use crate::rheology::{Rheology, ViscosityLaw};
use crate::EhlSolution;

/// The traction (N) over a contact of length `length_m` of a solution solved with the viscosity
/// law `law` (and the solver's compressibility, which does not enter here), at sliding speed
/// `sliding_speed_m_s` (m/s) and Eyring stress `eyring_stress_pa` (Pa).
pub fn eyring_traction_n(
    sol: &EhlSolution,
    law: ViscosityLaw,
    length_m: f64,
    sliding_speed_m_s: f64,
    eyring_stress_pa: f64,
) -> f64 {
    let case = &sol.case;
    let rheology = Rheology::new(
        law,
        false,
        sol.hertz_pressure_pa,
        case.pressure_viscosity_pa_inv,
        case.viscosity_pa_s,
    );
    let b = sol.hertz_half_width_m;
    let scale = case.film_scale_m();
    let stress = |i: usize| -> Option<(f64, f64)> {
        let x = *sol.profile.x.get(i)?;
        let p = *sol.profile.pressure.get(i)?;
        let h = sol.profile.film.get(i)? * scale;
        let (ln_eta_ratio, _) = rheology.ln_viscosity(p);
        let newtonian = case.viscosity_pa_s * sliding_speed_m_s / (h * eyring_stress_pa);
        // asinh(A·e^{ln η̄}) without forming e^{ln η̄} where it would overflow: for large
        // arguments asinh y = ln 2y.
        let ln_y = newtonian.ln() + ln_eta_ratio;
        let tau = if ln_y > 30.0 {
            eyring_stress_pa * (std::f64::consts::LN_2 + ln_y)
        } else {
            eyring_stress_pa * ln_y.exp().asinh()
        };
        Some((x * b, tau))
    };
    let mut force_per_length = 0.0;
    let mut previous: Option<(f64, f64)> = None;
    for i in 0..sol.profile.x.len() {
        let Some((x, tau)) = stress(i) else { break };
        if x > sol.exit_x * b {
            break;
        }
        if let Some((x0, tau0)) = previous {
            force_per_length += 0.5 * (tau + tau0) * (x - x0);
        }
        previous = Some((x, tau));
    }
    force_per_length * length_m
}

/// The mean Eyring stress ratio T = (1/(b·τ₀))·∫τ dx of a solution at the Newtonian stress
/// ratio N = η₀·u_s/(h_c·τ₀) = e^`ln_newtonian` (b the Hertz half-width, h_c the central film):
/// the isothermal traction per length is b·τ₀·T. With the viscosity law `law`, T depends on
/// the solution's Moes M and L and on N (and, through the Dowson–Higginson density, weakly on
/// p_h): the quantity the core tabulates (docs/physics.md §8.3).
pub fn mean_stress_ratio(sol: &EhlSolution, law: ViscosityLaw, ln_newtonian: f64) -> f64 {
    // τ₀ = 1 Pa and l = 1 m: u_s = N·h_c/η₀.
    let sliding = ln_newtonian.exp() * sol.central_film_m / sol.case.viscosity_pa_s;
    eyring_traction_n(sol, law, 1.0, sliding, 1.0) / sol.hertz_half_width_m
}
