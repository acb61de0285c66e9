//! The film of every contact over one step, from a few calls of the film model.
//!
//! Evaluating a neural network for every contact of every roller would cost more than the
//! whole step may (34 calls for 17 rollers). Within one step all contacts of one kind (inner or
//! outer) share speed, radius and lubricant, so their film depends on the roller load alone.
//! The model is called at three loads spanning the previous step's loaded rollers, and
//! ln h(ln Q) is interpolated by the parabola through them — exact for the power-law regression
//! formulas, and for a smooth network within a fraction of its own error — extended linearly
//! (C¹) beyond the outer nodes.
//!
//! **Light loads.** A film model returns the complete film, which rises like Martin's
//! hydrodynamic film h_RI = B/Q as the load vanishes (`FilmModel`). A parabola in ln Q cannot
//! follow that rise below the lightest node, so the film is split at each node into Martin's
//! part and the rest, in quadrature: e = √(h² − h_RI²) is interpolated, and the film at any load
//! is √(e(λ)² + h_RI(λ)²) with h_RI exact. At the nodes this returns the model's film
//! exactly; beyond them the slowly varying part e is extrapolated and the hydrodynamic part
//! keeps its exact 1/Q growth, so a separating roller keeps a continuous load (see `coupling`).

use crate::film::{ContactInput, FilmModel, MARTIN_CENTRAL, MARTIN_MINIMUM};
use crate::math::{exp, ln, max, min, select, sqrt};

/// Loads at which the film model is evaluated, per contact kind and step.
pub const FILM_NODES: usize = 3;

/// Smallest half-width of the node span in ln Q.
const MIN_HALF_SPAN: f32 = 0.15;
/// Node span limits in ln Q: 1 N … 10⁵ N.
const LN_NODE_MIN: f32 = 0.0;
const LN_NODE_MAX: f32 = 11.512_925;
/// Floor of a film before its logarithm is taken (m).
const FILM_FLOOR_M: f32 = 1.0e-15;
/// Floor of the non-hydrodynamic part e = √(h² − h_RI²) relative to h: a model film at or below
/// Martin's (a purely hydrodynamic model) leaves e at this fraction, and the blend then returns
/// Martin's film within 10⁻⁶.
const EHL_PART_FLOOR: f32 = 1.0e-3;

/// ln h as a function of λ = ln Q: the parabola through three equally spaced nodes, continued
/// by its tangent beyond the outer ones.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct LogParabola {
    centre: f32,
    half_span: f32,
    value: f32,
    slope: f32,
    curvature: f32,
}

impl LogParabola {
    /// Through (centre − d, v₀), (centre, v₁), (centre + d, v₂).
    fn through(centre: f32, half_span: f32, [v0, v1, v2]: [f32; 3]) -> Self {
        Self {
            centre,
            half_span,
            value: v1,
            slope: (v2 - v0) / (2.0 * half_span),
            curvature: (v2 - 2.0 * v1 + v0) / (2.0 * half_span * half_span),
        }
    }

    /// ln h and d ln h/dλ at λ.
    #[inline]
    pub(crate) fn at(&self, ln_load: f32) -> (f32, f32) {
        let offset = ln_load - self.centre;
        let inside = min(max(offset, -self.half_span), self.half_span);
        let slope = self.slope + 2.0 * self.curvature * inside;
        let value = self.value
            + inside * (self.slope + self.curvature * inside)
            + slope * (offset - inside);
        (value, slope)
    }
}

/// The films of both contact kinds for one step.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct StepFilmLaw {
    /// ln of the non-hydrodynamic part e of the central film of the inner and outer contact.
    pub central: [LogParabola; 2],
    /// ln of the non-hydrodynamic part of the sum of both central films (what the coupling
    /// needs).
    pub central_sum: LogParabola,
    /// Martin coefficients B with h_RI = B/Q, per contact (m·N).
    pub martin: [f32; 2],
    /// Their sum (m·N).
    pub martin_sum: f32,
    /// Ratio of the non-hydrodynamic parts of the minimum and the central film per contact at
    /// the node centre, and its slope in λ.
    pub min_ratio: [(f32, f32); 2],
}

/// Film sum of one roller at λ = ln Q.
#[derive(Clone, Copy, Debug)]
pub(crate) struct FilmSum {
    /// H = √(H_EHL² + H_RI²), the film both contacts add to the approach (m).
    pub total_m: f32,
    /// dH/dλ (m).
    pub slope_m: f32,
    /// 1/Q = e^(−λ) (1/N).
    pub inv_load: f32,
}

impl StepFilmLaw {
    /// Evaluate `model` at the nodes for contact templates `contacts` (inner, outer; loads
    /// ignored) with Martin coefficients `martin`, spanning ln Q ∈ [`ln_lo`, `ln_hi`]. The
    /// templates always carry some entrainment (see the bearing's standstill floor).
    pub(crate) fn new<F: FilmModel + ?Sized>(
        model: &F,
        contacts: [ContactInput; 2],
        martin: [f32; 2],
        (ln_lo, ln_hi): (f32, f32),
    ) -> Self {
        let centre = min(max(0.5 * (ln_lo + ln_hi), LN_NODE_MIN), LN_NODE_MAX);
        let half_span = max(0.5 * (ln_hi - ln_lo), MIN_HALF_SPAN);
        let mut central = [[0.0f32; FILM_NODES]; 2];
        let mut minimum = [[0.0f32; FILM_NODES]; 2];
        let mut sum = [0.0f32; FILM_NODES];
        let martin_sum = martin[0] + martin[1];
        for (k, s) in sum.iter_mut().enumerate() {
            let ln_load = centre + (k as f32 - 1.0) * half_span;
            let load_n = exp(ln_load);
            let inv_load = exp(-ln_load);
            let mut total = 0.0;
            for (((template, c), m), &b) in contacts
                .iter()
                .zip(central.iter_mut())
                .zip(minimum.iter_mut())
                .zip(martin.iter())
            {
                let film = model.film(&ContactInput {
                    load_n,
                    ..*template
                });
                let hydro = b * inv_load;
                if let (Some(cv), Some(mv)) = (c.get_mut(k), m.get_mut(k)) {
                    *cv = ehl_part(film.central_m, hydro);
                    *mv = ehl_part(film.minimum_m, hydro * (MARTIN_MINIMUM / MARTIN_CENTRAL));
                }
                total += film.central_m;
            }
            *s = ehl_part(total, martin_sum * inv_load);
        }
        let log3 = |v: [f32; FILM_NODES]| {
            let [a, b, c] = v;
            LogParabola::through(
                centre,
                half_span,
                [
                    ln(max(a, FILM_FLOOR_M)),
                    ln(max(b, FILM_FLOOR_M)),
                    ln(max(c, FILM_FLOOR_M)),
                ],
            )
        };
        let central = central.map(log3);
        let [mi, mo] = minimum.map(log3);
        let [ci, co] = central;
        Self {
            central,
            central_sum: log3(sum),
            min_ratio: [min_ratio(&ci, &mi), min_ratio(&co, &mo)],
            martin,
            martin_sum,
        }
    }

    /// H and dH/dλ at λ = ln Q.
    #[inline]
    pub(crate) fn sum_at(&self, ln_load: f32) -> FilmSum {
        let (ln_ehl, ehl_slope) = self.central_sum.at(ln_load);
        let ehl_m = exp(ln_ehl);
        let inv_load = exp(-ln_load);
        let hydro_m = self.martin_sum * inv_load;
        let total_m = sqrt(ehl_m * ehl_m + hydro_m * hydro_m);
        FilmSum {
            inv_load,
            total_m,
            slope_m: (ehl_slope * ehl_m * ehl_m - hydro_m * hydro_m) / max(total_m, 1.0e-30),
        }
    }

    /// Central and minimum film of each contact at λ, consistent with the sum: the per-contact
    /// blends √(h_EHL² + h_RI²) are scaled so that they add up to the sum's total. The minimum
    /// film follows the central one through their ratio, expanded to first order in λ about the
    /// node centre (the ratio varies slowly: ∝ Q^−0.03 for the regression formulas; error below
    /// 10⁻³ within one unit of ln Q of the centre).
    pub(crate) fn contacts_at(&self, ln_load: f32, sum: &FilmSum) -> [(f32, f32); 2] {
        let inv_load = sum.inv_load;
        let mut out = [(0.0, 0.0); 2];
        let mut blended_sum = 0.0;
        for (((o, c), &(r0, r1)), &b) in out
            .iter_mut()
            .zip(self.central.iter())
            .zip(self.min_ratio.iter())
            .zip(self.martin.iter())
        {
            let he = exp(c.at(ln_load).0);
            let ratio = r0 * (1.0 + r1 * (ln_load - c.centre));
            let hm = he * ratio;
            let hr = b * inv_load;
            let hr_min = hr * (MARTIN_MINIMUM / MARTIN_CENTRAL);
            *o = (sqrt(he * he + hr * hr), sqrt(hm * hm + hr_min * hr_min));
            blended_sum += o.0;
        }
        let scale = select(
            blended_sum > 0.0,
            sum.total_m / max(blended_sum, 1.0e-30),
            0.0,
        );
        for o in out.iter_mut() {
            o.0 *= scale;
        }
        out
    }
}

/// The part of a film `h` left after removing the hydrodynamic film `hydro` in quadrature,
/// √(h² − hydro²), floored at [`EHL_PART_FLOOR`]·h.
fn ehl_part(h: f32, hydro: f32) -> f32 {
    let floor = EHL_PART_FLOOR * h;
    sqrt(max(h * h - hydro * hydro, floor * floor))
}

/// (ratio, d ln ratio/dλ) of the minimum to the central film at the centre of the nodes.
fn min_ratio(central: &LogParabola, minimum: &LogParabola) -> (f32, f32) {
    (
        exp(minimum.value - central.value),
        minimum.slope - central.slope,
    )
}
