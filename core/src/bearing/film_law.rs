//! The film of every roller's contacts as a function of its load, from a few calls of the film
//! model per step.
//!
//! **Why a law.** The film–load coupling (`coupling`) needs each roller's film sum H(Q) at every
//! Newton step, and a neural network per evaluation would cost more than the whole step may.
//! Within one step all contacts of one kind (inner or outer) share speed, radius and lubricant,
//! so their film depends on the roller load alone.
//!
//! **Shape and level.** Per step the model is called at three loads spanning last step's loaded
//! rollers, and ln h(ln Q) of each contact kind is the parabola through them (exact for the
//! power-law regression formulas). The complete numerical film is not smooth enough in the load
//! for that parabola alone (at M ≈ 1–2 it dips and rises by 6 % within a factor 2 of load; the
//! parabola missed by up to 7 %), so each roller also carries an *anchor*: the model's exact
//! film at one of its own recent loads λ*. A roller's law is the parabola shifted to pass
//! through its anchor — level from the anchor, shape (the change from λ* to λ) from the
//! parabola. A real-time step re-anchors the [`REFRESHES_PER_STEP`] rollers whose load or speed
//! moved farthest since their anchor (two film-model calls each), so its cost is fixed;
//! `Bearing::settle` re-anchors every roller at every step. Between re-anchorings the error is
//! that of the parabola's *shape* over the roller's load change, which vanishes as the load
//! change does.
//!
//! **Light loads.** A film model returns the complete film, which rises like Martin's
//! hydrodynamic film h_RI = B/Q as the load vanishes (`FilmModel`). A parabola in ln Q cannot
//! follow that rise below its nodes, so the film is split into Martin's part and the rest, in
//! quadrature: e = √(h² − h_RI²) is interpolated, and the film at any load is √(e(λ)² + h_RI(λ)²)
//! with h_RI exact. At the nodes and anchors this returns the model's film exactly; away from
//! them the hydrodynamic part keeps its exact 1/Q growth, so a separating roller keeps a
//! continuous load (see `coupling`).

use crate::film::{ContactInput, FilmModel, MARTIN_CENTRAL, MARTIN_MINIMUM};
use crate::math::{exp, ln, max, min, select, sqrt};

/// Loads at which the film model is evaluated, per contact kind and step.
pub const FILM_NODES: usize = 3;
/// Rollers a real-time step re-anchors (one film-model call per contact each).
pub const REFRESHES_PER_STEP: usize = 2;

/// Half-width in ln Q about an anchor within which its line is used (and over which it then
/// fades into the step's parabola).
const TRUST_HALF_SPAN: f32 = 0.3;
/// Step in ln Q of the forward difference that gives an anchor's slope.
pub const SLOPE_STEP: f32 = 0.05;
/// Largest |d ln e/d ln Q| an anchor takes from its forward difference: a difference across the
/// edge of a model's domain (network on one side, fallback on the other) is not a slope.
const NEAR_SLOPE_LIMIT: f32 = 1.0;
/// Smallest half-width of the node span in ln Q.
const MIN_HALF_SPAN: f32 = 0.15;
/// |d ln e/d ln Q| beyond the nodes: EHL films fall as Q^−0.1…Q^−0.13 and the
/// non-hydrodynamic part of a transitional film moves a few tenths at most; a parabola's edge
/// slope continued over units of ln Q can be far off.
const FAR_SLOPE_LIMIT: f32 = 0.25;
/// Node and anchor limits in ln Q: 1 N … 10⁵ N.
const LN_NODE_MIN: f32 = 0.0;
const LN_NODE_MAX: f32 = 11.512_925;
/// Floor of a film before its logarithm is taken (m).
const FILM_FLOOR_M: f32 = 1.0e-15;
/// Floor of the non-hydrodynamic part e = √(h² − h_RI²) relative to h: a model film at or below
/// Martin's (a purely hydrodynamic model) leaves e at this fraction, and the blend then returns
/// Martin's film within 10⁻⁶.
const EHL_PART_FLOOR: f32 = 1.0e-3;

/// ln h as a function of λ = ln Q: the parabola through three equally spaced nodes, continued
/// beyond the outer ones by a line whose slope is held to ±[`FAR_SLOPE_LIMIT`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct LogParabola {
    centre: f32,
    half_span: f32,
    value: f32,
    slope: f32,
    curvature: f32,
    /// A roller's anchor line (λ*, ln e*, slope), used within [`TRUST_HALF_SPAN`] of λ* and
    /// faded into the parabola over the next [`TRUST_HALF_SPAN`]; `anchored` = 0 for none.
    anchor: (f32, f32, f32),
    anchored: f32,
}

impl LogParabola {
    /// The line through (centre, v₀) and (centre + d, v₁).
    /// Through (centre − d, v₀), (centre, v₁), (centre + d, v₂).
    fn through(centre: f32, half_span: f32, [v0, v1, v2]: [f32; 3]) -> Self {
        Self {
            centre,
            half_span,
            value: v1,
            slope: (v2 - v0) / (2.0 * half_span),
            curvature: (v2 - 2.0 * v1 + v0) / (2.0 * half_span * half_span),
            anchor: (0.0, 0.0, 0.0),
            anchored: 0.0,
        }
    }

    /// ln h and d ln h/dλ at λ.
    #[inline]
    pub(crate) fn at(&self, ln_load: f32) -> (f32, f32) {
        let offset = ln_load - self.centre;
        let inside = min(max(offset, -self.half_span), self.half_span);
        let slope = self.slope + 2.0 * self.curvature * inside;
        // Beyond the nodes the slope is held to the range of real films.
        let far_slope = min(max(slope, -FAR_SLOPE_LIMIT), FAR_SLOPE_LIMIT);
        let far = offset - inside;
        let value = self.value + inside * (self.slope + self.curvature * inside) + far_slope * far;
        let slope = select(far == 0.0, slope, far_slope);
        // Near the anchor its line, faded into the parabola beyond the trust span.
        let (a_centre, a_value, a_slope) = self.anchor;
        let d = ln_load - a_centre;
        let distance = max(d, -d);
        let fade = min(
            max((distance - TRUST_HALF_SPAN) / TRUST_HALF_SPAN, 0.0),
            1.0,
        );
        let w = 1.0 - self.anchored * (1.0 - fade);
        let line = a_value + a_slope * d;
        let fading = (fade > 0.0) & (fade < 1.0);
        let dw = select(
            fading,
            self.anchored * select(d > 0.0, 1.0, -1.0) / TRUST_HALF_SPAN,
            0.0,
        );
        (
            w * value + (1.0 - w) * line,
            w * slope + (1.0 - w) * a_slope + dw * (value - line),
        )
    }
}

/// The film law of one step (shared) or of one roller (anchored): both contacts.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct StepFilmLaw {
    /// ln of the non-hydrodynamic part e of the central film of the inner and outer contact.
    pub central: [LogParabola; 2],
    /// Martin coefficients B with h_RI = B/Q, per contact (m·N).
    pub martin: [f32; 2],
    /// Ratio of the non-hydrodynamic parts of the minimum and the central film per contact at
    /// the node centre, and its slope in λ.
    pub min_ratio: [(f32, f32); 2],
}

/// A roller's anchor: the film model's exact film at one of its recent loads.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub(crate) struct Anchor {
    /// λ* = ln Q of the anchor (clamped to 1 N … 10⁵ N).
    ln_load: f32,
    /// ln e of the inner and outer contact at λ*.
    ln_ehl: [f32; 2],
    /// d ln e/dλ of each, by a forward difference over [`SLOPE_STEP`].
    slope: [f32; 2],
    /// ln of the inner contact's entrainment speed at the anchor (ln(m/s)).
    ln_speed: f32,
}

impl Anchor {
    /// Call `model` at λ = `ln_load` for the contact templates (inner, outer; loads ignored).
    pub(crate) fn new<F: FilmModel + ?Sized>(
        model: &F,
        contacts: [ContactInput; 2],
        martin: [f32; 2],
        ln_load: f32,
    ) -> Self {
        let at = clamp_ln_load(ln_load);
        let ln_central = |ln_node: f32| {
            ehl_parts(model, &contacts, martin, ln_node).map(|(e, _)| ln(max(e, FILM_FLOOR_M)))
        };
        let (v0, v1) = (ln_central(at), ln_central(at + SLOPE_STEP));
        let slope = |c: usize| {
            let d = (v1.get(c).copied().unwrap_or(0.0) - v0.get(c).copied().unwrap_or(0.0))
                / SLOPE_STEP;
            min(max(d, -NEAR_SLOPE_LIMIT), NEAR_SLOPE_LIMIT)
        };
        Self {
            ln_load: at,
            ln_ehl: v0,
            slope: [slope(0), slope(1)],
            ln_speed: ln(contacts[0].entrainment_speed_m_s),
        }
    }

    /// How far the anchor is from a roller at λ = `ln_load` and entrainment ln u = `ln_speed`:
    /// |Δ ln Q| + |Δ ln u| (both move ln h by a fraction of their change). The real-time step
    /// re-anchors the farthest first.
    pub(crate) fn staleness(&self, ln_load: f32, ln_speed: f32) -> f32 {
        let d_load = clamp_ln_load(ln_load) - self.ln_load;
        let d_speed = ln_speed - self.ln_speed;
        max(d_load, -d_load) + max(d_speed, -d_speed)
    }
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
        let centre = clamp_ln_load(0.5 * (ln_lo + ln_hi));
        let half_span = max(0.5 * (ln_hi - ln_lo), MIN_HALF_SPAN);
        let mut central = [[0.0f32; FILM_NODES]; 2];
        let mut minimum = [[0.0f32; FILM_NODES]; 2];
        for k in 0..FILM_NODES {
            let parts = ehl_parts(
                model,
                &contacts,
                martin,
                centre + (k as f32 - 1.0) * half_span,
            );
            for ((c, m), (ce, me)) in central.iter_mut().zip(minimum.iter_mut()).zip(parts) {
                if let (Some(cv), Some(mv)) = (c.get_mut(k), m.get_mut(k)) {
                    *cv = ce;
                    *mv = me;
                }
            }
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
            min_ratio: [min_ratio(&ci, &mi), min_ratio(&co, &mo)],
            martin,
        }
    }

    /// This step's law with a roller's anchor: the anchor's line near its load, the parabola
    /// beyond (see the module doc).
    #[inline]
    pub(crate) fn anchored(&self, anchor: &Anchor) -> Self {
        let mut law = *self;
        for ((c, &e), &s) in law
            .central
            .iter_mut()
            .zip(anchor.ln_ehl.iter())
            .zip(anchor.slope.iter())
        {
            c.anchor = (anchor.ln_load, e, s);
            c.anchored = 1.0;
        }
        law
    }

    /// H and dH/dλ at λ = ln Q: each contact's √(e² + h_RI²), summed. (Blending the sums
    /// instead would save an exponential but is not exact for the regression model, whose e is
    /// an exact power law per contact but not for the sum.)
    #[inline]
    pub(crate) fn sum_at(&self, ln_load: f32) -> FilmSum {
        let inv_load = exp(-ln_load);
        let mut total_m = 0.0;
        let mut slope_m = 0.0;
        for (c, &b) in self.central.iter().zip(self.martin.iter()) {
            let (ln_ehl, ehl_slope) = c.at(ln_load);
            let ehl_m = exp(ln_ehl);
            let hydro_m = b * inv_load;
            let h = sqrt(ehl_m * ehl_m + hydro_m * hydro_m);
            total_m += h;
            slope_m += (ehl_slope * ehl_m * ehl_m - hydro_m * hydro_m) / max(h, 1.0e-30);
        }
        FilmSum {
            inv_load,
            total_m,
            slope_m,
        }
    }

    /// Central and minimum film of each contact at λ, consistent with the sum: the per-contact
    /// blends √(h_EHL² + h_RI²) are scaled so that they add up to the sum's total. The minimum
    /// film follows the central one through their ratio, expanded to first order in λ about
    /// λ* (the ratio varies slowly: ∝ Q^−0.03 for the regression formulas; error below
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

/// ln Q limited to the loads where nodes and anchors are placed.
fn clamp_ln_load(ln_load: f32) -> f32 {
    min(max(ln_load, LN_NODE_MIN), LN_NODE_MAX)
}

/// The non-hydrodynamic parts (central, minimum) of both contacts' films at λ = `ln_load`: one
/// call of `model` per contact, Martin's film removed in quadrature.
fn ehl_parts<F: FilmModel + ?Sized>(
    model: &F,
    contacts: &[ContactInput; 2],
    martin: [f32; 2],
    ln_load: f32,
) -> [(f32, f32); 2] {
    let load_n = exp(ln_load);
    let inv_load = exp(-ln_load);
    let mut out = [(0.0, 0.0); 2];
    for ((o, template), &b) in out.iter_mut().zip(contacts.iter()).zip(martin.iter()) {
        let film = model.film(&ContactInput {
            load_n,
            ..*template
        });
        let hydro = b * inv_load;
        *o = (
            ehl_part(film.central_m, hydro),
            ehl_part(film.minimum_m, hydro * (MARTIN_MINIMUM / MARTIN_CENTRAL)),
        );
    }
    out
}

/// The part of a film `h` left after removing the hydrodynamic film `hydro` in quadrature,
/// √(h² − hydro²), floored at [`EHL_PART_FLOOR`]·h.
fn ehl_part(h: f32, hydro: f32) -> f32 {
    let floor = EHL_PART_FLOOR * h;
    sqrt(max(h * h - hydro * hydro, floor * floor))
}

/// (ratio, d ln ratio/dλ) of the minimum to the central film at λ*.
fn min_ratio(central: &LogParabola, minimum: &LogParabola) -> (f32, f32) {
    (
        exp(minimum.value - central.value),
        minimum.slope - central.slope,
    )
}
