//! A ball with its centrifugal force: its centre found between the grooves, so that the inner
//! and outer contact angles and loads differ (Jones 1960; Harris & Kotzalas 2007, *Rolling
//! Bearing Analysis*, 5th ed., vol. 2, ch. 2–3).
//!
//! In the ball's (r, z) plane the outer groove-curvature centre is the origin and the inner
//! one sits at A = (A_r, A_z); the ball centre X is the unknown. The outer contact's approach
//! is δ_o = |X| − (f_o − ½)D + h_o along n_o = X/|X|, the inner one's
//! δ_i = |A − X| − (f_i − ½)D + h_i along n_i = (A − X)/|A − X| (films as rigid spacers,
//! docs/physics.md §4), Q = δ^1.5/c^1.5 at each. The races push the ball towards their groove
//! centres, so the ball is in equilibrium when
//!
//!   Q_i n_i − Q_o n_o + (F_c, 0) = 0,   F_c = ½ m d_m ω_c²,
//!
//! with the orbital speed of outer-raceway control, outer ring fixed (Harris & Kotzalas vol. 2,
//! ch. 2): ω_c = ω (1 − (D/d_m) cos α_i)/(1 + cos(α_i − α_o)). Newton's method on X, whose
//! Jacobian is −(H_i + H_o), H = k n nᵀ + (Q/Δ)(I − n nᵀ) the gradient of a contact's force
//! vector (k = dQ/dδ with the film's thinning, Δ the centre distance), runs a fixed
//! [`NEWTON_STEPS`] from the centrifugal-free solution pushed out by F_c's own approach; the
//! contact constants, ω_c and F_c are refreshed at the angles the first stage reaches. Each step
//! calls the film model at both contacts' current loads, and each contact solves its load on
//! that film's local power law h ∝ Q^−0.067 in between. The load on the inner ring is Q_i n_i;
//! its stiffness, the ball staying in equilibrium, the condensed H_i (H_i + H_o)⁻¹ H_o.

use super::contact::RaceContact;
use super::{
    BallBearing, BallBearingKind, BallOutput, FILM_LOAD_EXPONENT, MIN_COUPLED_LOAD_N,
    POWER_LAW_STEPS,
};
use crate::film::{Film, FilmSource};
use crate::math::{atan2, exp, ln, max, min, pow, select, sqrt};

/// Newton steps on the ball centre before and after the refresh of the contact constants,
/// orbital speed and centrifugal force (test `contact_angles_split_with_speed`: the ball's
/// force balance then holds to < 10⁻⁵ of its load).
pub const NEWTON_STEPS: [usize; 2] = [8, 4];
/// Stiffness added to the Newton matrix so that an unloaded ball gives a finite step (N/m);
/// loaded contacts of the bundled bearings have 10⁷ … 10⁹ N/m.
const REGULARIZATION_N_PER_M: f32 = 1.0;
/// Largest Newton step per coordinate, in ball diameters.
const MAX_STEP_PER_DIAMETER: f32 = 0.01;

/// A symmetric 2 × 2 matrix (rr, rz, zz).
type Sym2 = [f32; 3];

/// One contact at a ball position.
#[derive(Clone, Copy, Debug)]
struct Spring {
    load_n: f32,
    /// Unit normal (r, z) from the ball centre's side towards the groove centre.
    normal: [f32; 2],
    /// dQ/dδ with the film's thinning (N/m).
    slope: f32,
    /// The film at this load on the anchor's power law (m).
    film_m: f32,
    /// Gradient of the force vector Q n with respect to the centre-distance vector.
    full: Sym2,
}

/// A contact's film as its last film-model call gave it: h_n at ln Q_n. Between calls the film
/// follows the local power law h = h_n (Q/Q_n)^p, p = −0.067 (as without centrifugal force).
#[derive(Clone, Copy, Debug)]
struct Anchor {
    film_m: f32,
    ln_load: f32,
}

/// The contact across the centre-distance vector `v` (m) of a groove whose radius exceeds the
/// ball's by `offset_m`, compliance `compliance`, film `anchor`: its load solves
/// Q = ((|v| − offset + h(Q))/c)^1.5 by [`POWER_LAW_STEPS`] Newton steps on ln Q from the
/// anchor's load. `one_sided`: only a positive axial component carries load (angular-contact).
/// The slope includes the film's thinning with load: dQ/dδ = 1.5Q/(δ − 1.5 p h).
fn spring(v: [f32; 2], offset_m: f32, compliance: f32, one_sided: bool, anchor: Anchor) -> Spring {
    let dist = sqrt(v[0] * v[0] + v[1] * v[1]);
    let inv = 1.0 / max(dist, 1.0e-12);
    let n = [v[0] * inv, v[1] * inv];
    let geometric = dist - offset_m;
    let ln_c = ln(compliance);
    let ln_min = ln(MIN_COUPLED_LOAD_N);
    let mut ln_q = anchor.ln_load;
    for _ in 0..POWER_LAW_STEPS {
        let h = anchor.film_m * exp(FILM_LOAD_EXPONENT * (ln_q - anchor.ln_load));
        let elastic = max(geometric + h, 1.0e-12);
        let residual = ln_q - 1.5 * (ln(elastic) - ln_c);
        let slope = 1.0 - 1.5 * FILM_LOAD_EXPONENT * h / elastic;
        ln_q = max(ln_q - residual / slope, ln_min);
    }
    let film_m = anchor.film_m * exp(FILM_LOAD_EXPONENT * (ln_q - anchor.ln_load));
    let approach = max(geometric + film_m, 0.0);
    let active = select(!one_sided || n[1] > 0.0, 1.0, 0.0);
    let load = active * pow(approach / compliance, 1.5);
    let slope = 1.5 * load / max(approach - 1.5 * FILM_LOAD_EXPONENT * film_m, 1.0e-15);
    let tangential = load * inv;
    Spring {
        load_n: load,
        normal: n,
        slope,
        film_m,
        full: [
            slope * n[0] * n[0] + tangential * n[1] * n[1],
            (slope - tangential) * n[0] * n[1],
            slope * n[1] * n[1] + tangential * n[0] * n[0],
        ],
    }
}

/// (h + εI)⁻¹ r.
fn solve(h: Sym2, r: [f32; 2]) -> [f32; 2] {
    let (xx, xy, yy) = (
        h[0] + REGULARIZATION_N_PER_M,
        h[1],
        h[2] + REGULARIZATION_N_PER_M,
    );
    let inv_det = 1.0 / (xx * yy - xy * xy);
    [
        (yy * r[0] - xy * r[1]) * inv_det,
        (xx * r[1] - xy * r[0]) * inv_det,
    ]
}

/// H_i (H_i + H_o + εI)⁻¹ H_o, symmetrized, as a full 2 × 2 matrix.
fn series(hi: Sym2, ho: Sym2) -> [[f32; 2]; 2] {
    let (xx, xy, yy) = (
        hi[0] + ho[0] + REGULARIZATION_N_PER_M,
        hi[1] + ho[1],
        hi[2] + ho[2] + REGULARIZATION_N_PER_M,
    );
    let inv_det = 1.0 / (xx * yy - xy * xy);
    let m = [yy * inv_det, -xy * inv_det, xx * inv_det];
    let t = [
        [hi[0] * m[0] + hi[1] * m[1], hi[0] * m[1] + hi[1] * m[2]],
        [hi[1] * m[0] + hi[2] * m[1], hi[1] * m[1] + hi[2] * m[2]],
    ];
    let p00 = t[0][0] * ho[0] + t[0][1] * ho[1];
    let p01 = t[0][0] * ho[1] + t[0][1] * ho[2];
    let p10 = t[1][0] * ho[0] + t[1][1] * ho[1];
    let p11 = t[1][0] * ho[1] + t[1][1] * ho[2];
    let off = 0.5 * (p01 + p10);
    [[p00, off], [off, p11]]
}

/// The solved ball: its output (loads, angles, ellipses, films), the inner contact's normal
/// (the direction of its load on the inner ring) and its condensed 2 × 2 stiffness in (r, z).
pub(super) struct CentrifugalBall {
    pub output: BallOutput,
    pub normal: [f32; 2],
    pub local: [[f32; 2]; 2],
    pub orbital_rad_s: f32,
}

impl<const Z: usize> BallBearing<Z> {
    /// Ball with inner groove centre at `a` = (A_r, A_z) (m) from its outer one, the
    /// centrifugal-free solution `start` (its load, films and `cos_alpha`), shaft at `omega`.
    pub(super) fn ball_centrifugal(
        &self,
        a: [f32; 2],
        cos_alpha: f32,
        start: &BallOutput,
        omega: f32,
    ) -> CentrifugalBall {
        let p = &self.params;
        let d = p.ball_diameter_m;
        let (off_i, off_o) = (
            (p.inner_groove_ratio - 0.5) * d,
            (p.outer_groove_ratio - 0.5) * d,
        );
        let one_sided = p.kind == BallBearingKind::AngularContact;
        let dist = max(sqrt(a[0] * a[0] + a[1] * a[1]), 1.0e-9);
        let n = [a[0] / dist, a[1] / dist];
        let mut races = [
            RaceContact::new(p, cos_alpha, true),
            RaceContact::new(p, cos_alpha, false),
        ];
        let start_ln_load = ln(max(start.load_n[0], MIN_COUPLED_LOAD_N));
        let mut anchors = start.central_film_m.map(|film_m| Anchor {
            film_m,
            ln_load: start_ln_load,
        });
        let mut film_out = [Film::ZERO; 2];
        let gamma_ball = d / p.pitch_diameter_m;
        let orbital_of = |ni: [f32; 2], no: [f32; 2]| {
            let cos_diff = ni[0] * no[0] + ni[1] * no[1];
            omega * (1.0 - gamma_ball * ni[0]) / (1.0 + cos_diff)
        };
        let mut orbital = orbital_of(n, n);
        let fc_per_w2 = 0.5 * p.ball_mass_kg * p.pitch_diameter_m;
        let mut fc = fc_per_w2 * orbital * orbital;
        // Start: the centrifugal-free ball centre, pushed out radially by F_c's own approach.
        let q0 = start.load_n[0];
        let inner_dist = off_i - anchors[0].film_m + races[0].compliance * pow(q0, 2.0 / 3.0);
        let x0 = [a[0] - inner_dist * n[0], a[1] - inner_dist * n[1]];
        let mut x = [x0[0] + races[1].compliance * pow(fc, 2.0 / 3.0), x0[1]];
        let limit = MAX_STEP_PER_DIAMETER * d;
        let lubricated = self.film != super::BallFilm::Dry;
        for (stage, steps) in NEWTON_STEPS.iter().enumerate() {
            for step in 0..*steps {
                let si = spring(
                    [a[0] - x[0], a[1] - x[1]],
                    off_i,
                    races[0].compliance,
                    one_sided,
                    anchors[0],
                );
                let so = spring(x, off_o, races[1].compliance, one_sided, anchors[1]);
                if stage == 1 && step == 0 {
                    races = [
                        RaceContact::new(p, si.normal[0], true),
                        RaceContact::new(p, so.normal[0], false),
                    ];
                    orbital = orbital_of(si.normal, so.normal);
                    fc = fc_per_w2 * orbital * orbital;
                }
                if lubricated {
                    // Re-anchor both films at the current loads (one model call each).
                    film_out = self.contact_films(&races, [si, so], omega, orbital);
                    anchors = [
                        Anchor {
                            film_m: film_out[0].central_m,
                            ln_load: ln(max(si.load_n, MIN_COUPLED_LOAD_N)),
                        },
                        Anchor {
                            film_m: film_out[1].central_m,
                            ln_load: ln(max(so.load_n, MIN_COUPLED_LOAD_N)),
                        },
                    ];
                }
                let r = [
                    si.load_n * si.normal[0] - so.load_n * so.normal[0] + fc,
                    si.load_n * si.normal[1] - so.load_n * so.normal[1],
                ];
                let h = [
                    si.full[0] + so.full[0],
                    si.full[1] + so.full[1],
                    si.full[2] + so.full[2],
                ];
                let dx = solve(h, r);
                x = [
                    x[0] + min(max(dx[0], -limit), limit),
                    x[1] + min(max(dx[1], -limit), limit),
                ];
            }
        }
        let si = spring(
            [a[0] - x[0], a[1] - x[1]],
            off_i,
            races[0].compliance,
            one_sided,
            anchors[0],
        );
        let so = spring(x, off_o, races[1].compliance, one_sided, anchors[1]);
        // The films at the final loads, on the last anchors' power laws.
        for (f, (anchor, spring)) in film_out.iter_mut().zip(anchors.iter().zip([si, so])) {
            let scale = select(
                anchor.film_m > 0.0,
                spring.film_m / max(anchor.film_m, 1.0e-30),
                0.0,
            );
            f.central_m *= scale;
            f.minimum_m *= scale;
        }
        let (axes_in, pressure_in) = races[0].ellipse(si.load_n);
        let (axes_out, pressure_out) = races[1].ellipse(so.load_n);
        let loaded = [si.load_n > 0.0, so.load_n > 0.0];
        let source = |c: usize| {
            let (l, f) = (
                loaded.get(c).copied().unwrap_or(false),
                film_out.get(c).copied().unwrap_or(Film::ZERO),
            );
            if l {
                f.source
            } else {
                FilmSource::None
            }
        };
        // Normal slopes in series: the ball's stiffness along its line of centres.
        let series_slope = si.slope * so.slope / max(si.slope + so.slope, 1.0e-12);
        CentrifugalBall {
            output: BallOutput {
                geometric_approach_m: dist - p.centre_distance_m,
                load_n: [si.load_n, so.load_n],
                contact_angle_rad: [
                    atan2(si.normal[1], si.normal[0]),
                    atan2(so.normal[1], so.normal[0]),
                ],
                semi_axes_inner_m: axes_in,
                semi_axes_outer_m: axes_out,
                max_pressure_pa: [pressure_in, pressure_out],
                central_film_m: [
                    select(loaded[0], film_out[0].central_m, 0.0),
                    select(loaded[1], film_out[1].central_m, 0.0),
                ],
                min_film_m: [
                    select(loaded[0], film_out[0].minimum_m, 0.0),
                    select(loaded[1], film_out[1].minimum_m, 0.0),
                ],
                film_source: [source(0), source(1)],
                stiffness_n_per_m: series_slope,
                ..BallOutput::UNLOADED
            },
            normal: si.normal,
            local: series(si.full, so.full),
            orbital_rad_s: orbital,
        }
    }

    /// The films of the inner and outer contact at their own loads and pure-rolling
    /// entrainment speeds: the race surface at radius (d_m ∓ D cos α)/2 (inner −, outer +)
    /// moves at |ω_race − ω_c| relative to the cage, the ball's surface with it (with the
    /// kinematic cage speed this is u_m = (d_m ω/4)(1 − γ²), as without centrifugal force).
    fn contact_films(
        &self,
        races: &[RaceContact; 2],
        springs: [Spring; 2],
        omega: f32,
        orbital: f32,
    ) -> [Film; 2] {
        let p = &self.params;
        let [ri, ro] = races;
        let [si, so] = springs;
        let u_i =
            (omega - orbital).abs() * 0.5 * (p.pitch_diameter_m - p.ball_diameter_m * si.normal[0]);
        let u_o = orbital.abs() * 0.5 * (p.pitch_diameter_m + p.ball_diameter_m * so.normal[0]);
        [
            self.film
                .film(&ri.film_input(p, max(si.load_n, super::MIN_COUPLED_LOAD_N), u_i)),
            self.film
                .film(&ro.film_input(p, max(so.load_n, super::MIN_COUPLED_LOAD_N), u_o)),
        ]
    }
}
