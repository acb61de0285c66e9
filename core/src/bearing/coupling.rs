//! The film-coupled roller load: a scalar fixed point solved in a fixed amount of work.
//!
//! The film adds to the approach (PHYSICS.md §4): δ_j = δ_geo + H(Q_j) with H = h_in + h_out,
//! and Q_j = Q(δ_j) from the slices. H falls with Q (EHL: ∝ Q^−0.1; hydrodynamic: ∝ 1/Q), so
//! the equation has exactly one root for any geometric approach, positive or negative.
//!
//! **Continuity at separation.** Each contact's central film is the root-sum-square of the EHL
//! film and Martin's rigid iso-viscous film, h = √(h_EHL² + h_RI²), h_RI = 6η₀u_mRl/Q. At high
//! load h_RI vanishes and the EHL model rules; as the rollers separate, Q → 0 and Martin's
//! hydrodynamic load takes over smoothly (a C¹ blend, Moes-style; at the crossover it is √2
//! above either asymptote, where Moes' 7/3 blend gives 2^(3/7) ≈ 1.35). Roller forces are
//! therefore continuous — and differentiable — in the displacement across the transition.
//!
//! **Fixed work.** Two passes over the slices per roller and step:
//! 1. slices at the warm-start approach give Q₀ and K₀; the film model is called once per
//!    contact at Q₀ (the *anchor*) and the slices are summarised by the whole-roller power law
//!    Q = L·(δ − δ_off)^n that matches Q₀, dQ/dδ and d²Q/dδ² (exact for a straight untilted
//!    roller under the Palmgren law);
//! 2. the scalar equation δ_off + (Q/L)^(1/n) = δ_geo + H(Q) is solved in λ = ln Q by
//!    [`INNER_ITERATIONS`] safeguarded Newton steps, the film following the local law
//!    h_EHL(Q) = h_EHL(Q_a)·(Q/Q_a)^−0.10 (the Dowson–Toyoda exponent, exact for the regression
//!    model); then the slices are evaluated once more at the new approach, a fresh power law
//!    is fitted there and the scalar equation re-solved in [`REFINE_ITERATIONS`] steps.
//!
//! With a warm start from the previous step this meets |Δh|/h ≤ 10⁻³ (tested against a
//! converged f64 iteration over the PHYSICS.md §5.3 domain).

use crate::contact::{RollerLoad, SlicedRoller};
use crate::film::{
    ContactInput, Film, FilmModel, FilmSource, Regime, CENTRAL_LOAD_EXPONENT, MARTIN_CENTRAL,
    MARTIN_MINIMUM, MINIMUM_LOAD_EXPONENT,
};
use crate::math::{exp, ln, sqrt};

/// Safeguarded Newton steps of the scalar film–load equation per roller and step.
pub const INNER_ITERATIONS: usize = 4;
/// Newton steps of the re-solve after the second slice pass.
pub const REFINE_ITERATIONS: usize = 2;

/// Bracket of the roller load in the scalar solve (N): 10⁻⁴ N … 10⁷ N.
const LN_LOAD_MIN: f32 = -9.210_34;
const LN_LOAD_MAX: f32 = 16.118_095;
/// Smallest load used as the film model's anchor (N); lighter contacts are hydrodynamic.
const ANCHOR_MIN_N: f32 = 1.0;
/// Smallest load at which the slices' (Q, K) are trusted for the power-law fit (N).
const FIT_MIN_N: f32 = 1.0e-3;

/// Per-step data of one contact (inner or outer), shared by all rollers.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ContactContext {
    /// Contact input with the load left to fill in.
    pub template: ContactInput,
    /// Martin coefficient B with h_RI = B/Q: B = 6·η₀·u_m·R·l (m·N).
    pub martin: f32,
    /// ln(l·E'·R) + ½·ln(2U): ln M = ln Q − this.
    pub ln_m_offset: f32,
    /// ln L (Moes) of this contact.
    pub ln_l: f32,
}

/// Per-step film data: the two contacts, and whether there is any entrainment at all.
#[derive(Clone, Copy, Debug)]
pub(crate) struct StepFilm {
    pub contacts: [ContactContext; 2],
    pub lubricated: bool,
}

/// Result of the coupled solve for one roller.
#[derive(Clone, Copy, Debug)]
pub(crate) struct CoupledRoller {
    pub load: RollerLoad,
    /// Elastic approach at the roller middle (m).
    pub approach_m: f32,
    /// Central and minimum film at the inner and outer contact.
    pub films: [Film; 2],
    /// dH/dQ of the film sum at the solution (m/N, ≤ 0).
    pub film_slope_m_per_n: f32,
    pub regimes: [Regime; 2],
}

/// Film sum H and dH/dλ at λ = ln Q, from the anchored local laws.
#[inline]
fn film_sum(
    anchor_central: [f32; 2],
    martin: [f32; 2],
    ln_load: f32,
    ln_anchor: f32,
) -> (f32, f32, [f32; 2], [f32; 2]) {
    let s = CENTRAL_LOAD_EXPONENT;
    let ehl_scale = exp(s * (ln_load - ln_anchor));
    let inv_load = exp(-ln_load);
    let mut sum = 0.0;
    let mut slope = 0.0;
    let mut ehl = [0.0; 2];
    let mut hydro = [0.0; 2];
    for (((&ha, &b), e), r) in anchor_central
        .iter()
        .zip(martin.iter())
        .zip(ehl.iter_mut())
        .zip(hydro.iter_mut())
    {
        let he = ha * ehl_scale;
        let hr = b * inv_load;
        let h = sqrt(he * he + hr * hr);
        sum += h;
        slope += (s * he * he - hr * hr) / h.max(1.0e-30);
        *e = he;
        *r = hr;
    }
    (sum, slope, ehl, hydro)
}

/// Whole-roller power law Q = L·(δ − δ_off)^n summarising the slices near one approach.
#[derive(Clone, Copy, Debug)]
struct PowerLaw {
    /// δ_off (m).
    offset_m: f32,
    /// ln L.
    ln_coefficient: f32,
    /// n.
    exponent: f32,
}

impl PowerLaw {
    /// The law through the slices' (Q, K, K') at `approach_m`: K/Q = n/span and
    /// K'/K = (n − 1)/span give span = 1/(K/Q − K'/K), n = span·K/Q. Straight rollers under the
    /// Palmgren law give n = 10/9 exactly; crowned or tilted ones, whose loaded length grows
    /// with the approach, a larger n. An unloaded roller takes the straight roller's law from
    /// its first touching slice.
    fn fit<const S: usize>(
        roller: &SlicedRoller<S>,
        load: &RollerLoad,
        approach_m: f32,
        tilt_rad: f32,
    ) -> Self {
        let q = load.load_n;
        let k = load.stiffness_n_per_m;
        let fit = q > FIT_MIN_N && k > 0.0;
        let rho1 = if fit { k / q } else { 1.0 };
        let rho2 = if fit {
            load.stiffness_derivative_n_per_m2 / k
        } else {
            0.0
        };
        let curvature_fit = fit && rho1 - rho2 > 0.0;
        let span = if curvature_fit {
            1.0 / (rho1 - rho2)
        } else {
            (10.0 / 9.0) / rho1
        };
        let exponent = if curvature_fit {
            (span * rho1).clamp(1.0, 4.0)
        } else {
            10.0 / 9.0
        };
        if fit {
            Self {
                offset_m: approach_m - span,
                ln_coefficient: ln(q) - exponent * ln(span),
                exponent,
            }
        } else {
            Self {
                offset_m: roller.touch_approach_tilted_m(tilt_rad),
                ln_coefficient: ln(roller.nominal_coefficient()),
                exponent: 10.0 / 9.0,
            }
        }
    }
}

/// The films of a roller's two contacts as functions of its load, anchored at one model call.
#[derive(Clone, Copy, Debug)]
struct FilmLaw {
    anchor_central: [f32; 2],
    martin: [f32; 2],
    ln_anchor: f32,
}

impl FilmLaw {
    /// Film sum H, dH/dλ, and the EHL and hydrodynamic parts of each contact at λ = ln Q.
    #[inline]
    fn at(&self, ln_load: f32) -> (f32, f32, [f32; 2], [f32; 2]) {
        film_sum(self.anchor_central, self.martin, ln_load, self.ln_anchor)
    }
}

/// Solve δ_off + (Q/L)^(1/n) = δ_geo + H(Q) for λ = ln Q by `iterations` safeguarded Newton
/// steps from `start`, in the log form Φ(λ) = ln D − ln H with D = δ_off − δ_geo + (Q/L)^(1/n)
/// the elastic approach still missing. Both sides are close to linear in λ (EHL: ln H ≈ −0.1λ,
/// hydrodynamic: ln H ≈ −λ; ln D ≈ λ/n once loaded), so Newton converges in a few steps from
/// anywhere in the bracket; Φ' > 0 throughout. The dry load (film ≡ 0) bounds the root from
/// below: the film only adds approach.
fn solve_load(
    law: &PowerLaw,
    films: &FilmLaw,
    geometric_approach_m: f32,
    start: f32,
    iterations: usize,
) -> f32 {
    let gap = geometric_approach_m - law.offset_m;
    let inverse_exponent = 1.0 / law.exponent;
    let ln_dry = law.ln_coefficient + law.exponent * ln(gap.max(1.0e-30));
    let mut lo = if gap > 0.0 {
        ln_dry.max(LN_LOAD_MIN)
    } else {
        LN_LOAD_MIN
    };
    let mut hi = LN_LOAD_MAX.max(lo);
    let mut lam = if start > lo && start < hi {
        start
    } else {
        lo + 0.5
    };
    for _ in 0..iterations {
        let elastic = exp(inverse_exponent * (lam - law.ln_coefficient));
        let (h, dh, _, _) = films.at(lam);
        let missing = elastic - gap;
        let h = h.max(1.0e-30);
        let defined = missing > 0.0;
        let residual = if defined { ln(missing / h) } else { -1.0 };
        let slope = inverse_exponent * elastic / missing.max(1.0e-30) - dh / h;
        if residual > 0.0 {
            hi = lam;
        } else {
            lo = lam;
        }
        let newton = lam - residual / slope;
        lam = if defined && newton >= lo && newton <= hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
    }
    lam
}

/// Solve one roller: geometric approach `δ_geo` (m), tilt `ψ` (rad), warm-start approach (m).
pub(crate) fn solve_roller<F: FilmModel + ?Sized, const S: usize>(
    roller: &SlicedRoller<S>,
    film: &F,
    step: &StepFilm,
    geometric_approach_m: f32,
    tilt_rad: f32,
    warm_approach_m: f32,
) -> CoupledRoller {
    // Pass 1: slices at the warm start, film model at the anchor load.
    let r0 = roller.evaluate(warm_approach_m, tilt_rad);
    let anchor = r0.load_n.max(ANCHOR_MIN_N);
    let [inner, outer] = step.contacts;
    let with_load = |c: &ContactContext| ContactInput {
        load_n: anchor,
        ..c.template
    };
    let anchor_films = [film.film(&with_load(&inner)), film.film(&with_load(&outer))];
    let lubricated = step.lubricated;
    let films = FilmLaw {
        anchor_central: [
            if lubricated {
                anchor_films[0].central_m
            } else {
                0.0
            },
            if lubricated {
                anchor_films[1].central_m
            } else {
                0.0
            },
        ],
        martin: [inner.martin, outer.martin],
        ln_anchor: ln(anchor),
    };
    let law0 = PowerLaw::fit(roller, &r0, warm_approach_m, tilt_rad);
    let lam1 = solve_load(
        &law0,
        &films,
        geometric_approach_m,
        ln(r0.load_n.max(1.0e-4)),
        INNER_ITERATIONS,
    );
    let approach1 = geometric_approach_m + films.at(lam1).0;

    // Pass 2: slices at that approach, a fresh power law there and a short re-solve. The law
    // matches the slices in load, stiffness and curvature at `approach1`, so the remaining
    // error is third order in the step from `approach1`; load and moment follow the law.
    let r1 = roller.evaluate(approach1, tilt_rad);
    let law1 = PowerLaw::fit(roller, &r1, approach1, tilt_rad);
    let lam2 = solve_load(
        &law1,
        &films,
        geometric_approach_m,
        ln(r1.load_n.max(1.0e-4)),
        REFINE_ITERATIONS,
    );
    let (h2, _, _, _) = films.at(lam2);
    let approach_m = geometric_approach_m + h2;
    let dry_pass = approach_m <= law1.offset_m;
    let mut load = r1;
    load.load_n = if dry_pass {
        0.0
    } else {
        exp(law1.ln_coefficient + law1.exponent * ln(approach_m - law1.offset_m))
    };
    load.moment_nm += load.stiffness_moment_n * (approach_m - approach1);
    let ln_load = ln(load.load_n.max(1.0e-4));
    let (_, dh, ehl, hydro) = films.at(ln_load);
    let min_scale = exp(MINIMUM_LOAD_EXPONENT * (ln_load - films.ln_anchor));
    let mut films = [Film::ZERO; 2];
    let mut regimes = [Regime::Dry; 2];
    for ((((f, r), a), (&he, &hr)), c) in films
        .iter_mut()
        .zip(regimes.iter_mut())
        .zip(anchor_films.iter())
        .zip(ehl.iter().zip(hydro.iter()))
        .zip(step.contacts.iter())
    {
        let he_min = if lubricated {
            a.minimum_m * min_scale
        } else {
            0.0
        };
        let hr_min = hr * (MARTIN_MINIMUM / MARTIN_CENTRAL);
        *f = Film {
            central_m: sqrt(he * he + hr * hr),
            minimum_m: sqrt(he_min * he_min + hr_min * hr_min),
            source: if lubricated {
                a.source
            } else {
                FilmSource::None
            },
        };
        *r = if lubricated {
            Regime::from_ln_moes(ln_load - c.ln_m_offset, c.ln_l)
        } else {
            Regime::Dry
        };
    }
    CoupledRoller {
        load,
        approach_m,
        films,
        film_slope_m_per_n: dh / load.load_n.max(1.0e-4),
        regimes,
    }
}
