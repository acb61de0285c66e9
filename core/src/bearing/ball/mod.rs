//! The ball bearing: Z balls between a fixed outer ring and an inner ring displaced in five
//! degrees of freedom, each ball with a film-coupled inner and outer Hertz point contact.
//!
//! Geometry and load distribution after Jones (1960) and Harris & Kotzalas (2007, *Rolling
//! Bearing Analysis*, 5th ed., vol. 2, ch. 1 and 3), docs/ball_bearings.md:
//!
//! - Ball j sits at the azimuth ψ_j = cage angle + 2πj/Z, from +x towards +y.
//! - The inner ring is displaced by u = (x, y, z, θ_x, θ_y) (m, m, m, rad, rad). Its
//!   groove-curvature centre at ball j moves radially by δ_r = x cos ψ + y sin ψ and axially by
//!   δ_z = z + R_i (θ_x sin ψ − θ_y cos ψ), R_i = d_m/2 + (f_i − 0.5) D cos α₀ the radius of the
//!   centres' locus (small displacements).
//! - From the outer groove-curvature centre the inner one then lies at (A_r, A_z) =
//!   (A_r0 + δ_r, A_z0 + δ_z): A_r0 = A₀ − P_d/2, A_z0 = 0 for a deep-groove bearing (both
//!   centres in the mid-plane, so the contact angle takes the sign of A_z: either side of the
//!   groove), (A₀ cos α₀, A₀ sin α₀) for an angular-contact bearing, A₀ = (f_i + f_o − 1)D.
//! - Their distance A gives the contact angle α = atan2(A_z, A_r) (from the radial plane,
//!   positive where the ball carries thrust applied to the inner ring in +z) and the
//!   geometric approach δ_g = A − A₀ of the two contacts together.
//! - The films of both contacts act as rigid spacers (docs/physics.md §4, as for rollers):
//!   the steel's elastic approach is δ = δ_g + h_i + h_o, and the ball load solves
//!   Q = (δ/(c_i + c_o))^{3/2} (`contact.rs`), whose films depend on Q.
//! - The ball pushes the inner ring along the line of centres: the force on the inner ring is
//!   F = −Σ_j Q_j (cos α cos ψ, cos α sin ψ, sin α) and the moments M_x = −Σ Q sin α R_i sin ψ,
//!   M_y = Σ Q sin α R_i cos ψ (by virtual work on δ_z, so the stiffness is symmetric).
//!
//! With `centrifugal` on ([`BallBearingDesign::centrifugal`]) each ball also carries its
//! centrifugal force, and its centre is solved between the grooves so that the inner and outer
//! contact angles and loads differ (`centrifugal.rs`); off, the outputs are those above. Ball
//! spin and gyroscopic moments are not modelled (docs/ball_bearings.md, limits).

mod centrifugal;
#[cfg(test)]
mod centrifugal_tests;
mod contact;
mod params;
mod statics;
#[cfg(test)]
mod tests;

pub use centrifugal::NEWTON_STEPS as CENTRIFUGAL_NEWTON_STEPS;
pub use params::{BallBearingDesign, BallBearingKind, BallBearingParams};
pub use statics::{BallLoad, StaticSolution, StaticSolveError};

use crate::error::{Allowed, ParamError};
use crate::film::ann::{PointAnnF32, PointAnnInt};
use crate::film::point::HamrockDowson;
use crate::film::{Film, FilmModel, FilmSource, PointContactInput};
use crate::math::{atan2, ln, max, select, sin_cos, sqrt};
use contact::RaceContact;

/// Number of Newton steps on ln Q of each ball's film coupling (module doc): from the dry load
/// (or 1 N for a ball whose gap the film has to close), two steps meet |ΔQ|/Q ≤ 10⁻⁴ wherever
/// the film is less than a fifth of the elastic approach (tested).
pub const FILM_COUPLING_STEPS: usize = 2;

/// d ln h_c / d ln Q of the film in the coupling's Newton step and the stiffness: Hamrock and
/// Dowson's load exponent of the central film, −0.067 (Hamrock 1994, ch. 22).
const FILM_LOAD_EXPONENT: f32 = -0.067;

/// Newton steps on the local power law of the film after each film call.
const POWER_LAW_STEPS: usize = 3;

/// Smallest ball load (N) the coupling iterates on; a ball held at this load by its film alone
/// carries ≈ 0.
const MIN_COUPLED_LOAD_N: f32 = 1.0e-3;

/// Which film the balls' contacts carry.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BallFilm {
    /// No film: the dry bearing (multi-body practice).
    Dry,
    /// Hamrock–Dowson's point-contact formulas.
    HamrockDowson,
    /// The point-contact network in f32, with its domain guard and Hamrock–Dowson fallback.
    NetworkF32,
    /// The integer point-contact network, with its domain guard and Hamrock–Dowson fallback.
    NetworkInt,
}

impl BallFilm {
    /// Central and minimum film of one contact.
    #[inline]
    fn film(self, contact: &PointContactInput) -> Film {
        match self {
            BallFilm::Dry => Film::ZERO,
            BallFilm::HamrockDowson => HamrockDowson.film(contact),
            BallFilm::NetworkF32 => PointAnnF32.film(contact),
            BallFilm::NetworkInt => PointAnnInt.film(contact),
        }
    }
}

/// The inner ring's motion relative to the fixed outer ring, and the shaft speed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BallBearingState {
    /// (x, y, z, θ_x, θ_y): translations (m) and tilts about x and y (rad).
    pub displacement: [f32; 5],
    /// Their rates (m/s, rad/s), for the damping.
    pub velocity: [f32; 5],
    /// Inner-ring (shaft) speed (rad/s).
    pub shaft_speed_rad_s: f32,
    /// Cage angle: the azimuth of ball 0 (rad).
    pub cage_angle_rad: f32,
}

impl BallBearingState {
    /// A state at rest in the displacement `displacement`, spinning at `shaft_speed_rad_s`
    /// with ball 0 on +x.
    pub fn at(displacement: [f32; 5], shaft_speed_rad_s: f32) -> Self {
        Self {
            displacement,
            velocity: [0.0; 5],
            shaft_speed_rad_s,
            cage_angle_rad: 0.0,
        }
    }

    /// Refuse NaN, infinite or out-of-range fields, naming them.
    pub fn check(&self) -> Result<(), ParamError> {
        const DISPLACEMENT: [(&str, f32); 5] = [
            ("x_m", 1.0e-3),
            ("y_m", 1.0e-3),
            ("z_m", 1.0e-3),
            ("tilt_x_rad", 0.05),
            ("tilt_y_rad", 0.05),
        ];
        const VELOCITY: [&str; 5] = [
            "vx_m_s",
            "vy_m_s",
            "vz_m_s",
            "tilt_rate_x_rad_s",
            "tilt_rate_y_rad_s",
        ];
        for (&v, (field, limit)) in self.displacement.iter().zip(DISPLACEMENT) {
            crate::error::in_range(field, v, -limit, limit)?;
        }
        for (&v, field) in self.velocity.iter().zip(VELOCITY) {
            crate::error::in_range(field, v, -1.0e3, 1.0e3)?;
        }
        crate::error::in_range("shaft_speed_rad_s", self.shaft_speed_rad_s, -1.0e5, 1.0e5)?;
        crate::error::in_range("cage_angle_rad", self.cage_angle_rad, -1.0e4, 1.0e4)?;
        Ok(())
    }
}

/// One ball's contacts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BallOutput {
    /// Azimuth ψ (rad).
    pub azimuth_rad: f32,
    /// Geometric approach δ_g = A − A₀ of both contacts (m; negative: a gap).
    pub geometric_approach_m: f32,
    /// Load of the inner and the outer contact (N): equal without centrifugal force.
    pub load_n: [f32; 2],
    /// Contact angle at the inner and the outer contact (rad, signed, module doc).
    pub contact_angle_rad: [f32; 2],
    /// Semi-axes [a, b] of the inner contact ellipse (m): across and along the rolling direction.
    pub semi_axes_inner_m: [f32; 2],
    /// Semi-axes [a, b] of the outer contact ellipse (m).
    pub semi_axes_outer_m: [f32; 2],
    /// Maximum Hertz pressure of the inner and the outer contact (Pa).
    pub max_pressure_pa: [f32; 2],
    /// Central film of the inner and the outer contact (m).
    pub central_film_m: [f32; 2],
    /// Minimum film of the inner and the outer contact (m).
    pub min_film_m: [f32; 2],
    /// The film model that served the inner and the outer contact.
    pub film_source: [FilmSource; 2],
    /// dQ/dδ_g, the ball's stiffness along its line of centres, film included (N/m).
    pub stiffness_n_per_m: f32,
}

/// The bearing's result for one state.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BallBearingOutput<const Z: usize> {
    /// Force of the balls on the inner ring (N): x, y, z.
    pub force_n: [f32; 3],
    /// Moment of the balls on the inner ring about x and y (N·m), about the point on the axis
    /// in the plane of the inner groove-curvature centres.
    pub moment_nm: [f32; 2],
    /// −∂(force, moment)/∂(x, y, z, θ_x, θ_y): the stiffness (N/m, N/rad, N·m/m, N·m/rad),
    /// equal to d(applied load)/d(displacement).
    pub stiffness: [[f32; 5]; 5],
    /// Damping matrix over the same coordinates (N·s/m, …).
    pub damping: [[f32; 5]; 5],
    /// Cage (ball orbital) speed, outer-raceway control, outer ring fixed (rad/s).
    pub cage_speed_rad_s: f32,
    /// Per ball.
    pub balls: [BallOutput; Z],
}

impl<const Z: usize> BallBearingOutput<Z> {
    /// The load applied to the inner ring that this displacement balances: the negated force
    /// and moment, [F_x, F_y, F_z, M_x, M_y] (N, N·m).
    pub fn applied_load(&self) -> [f32; 5] {
        [
            -self.force_n[0],
            -self.force_n[1],
            -self.force_n[2],
            -self.moment_nm[0],
            -self.moment_nm[1],
        ]
    }

    /// The largest ball load (N).
    pub fn max_ball_load_n(&self) -> f32 {
        self.balls.iter().fold(0.0, |m, b| max(b.load_n[0], m))
    }
}

/// A ball bearing of `Z` balls with its film model: stateless apart from its parameters, so
/// [`BallBearing::evaluate`] is a function of its input alone.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BallBearing<const Z: usize> {
    params: BallBearingParams,
    film: BallFilm,
}

impl<const Z: usize> BallBearing<Z> {
    /// A bearing of `Z` balls; refused when `Z` differs from the design's ball count or lies
    /// outside 3 … 64.
    ///
    /// ```
    /// use bearing_core::bearing::ball::{BallBearing, BallBearingDesign, BallBearingState, BallFilm};
    /// let params = BallBearingDesign::DEEP_GROOVE_6205.params()?;
    /// let bearing = BallBearing::<9>::new(params, BallFilm::NetworkInt)?;
    /// // 20 µm down (clearance 12 µm), 10 000 rpm.
    /// let out = bearing.evaluate(&BallBearingState::at([0.0, -20e-6, 0.0, 0.0, 0.0], 1047.2))?;
    /// assert!(out.force_n[1] > 100.0); // the balls push the inner ring back up
    /// # Ok::<(), bearing_core::ParamError>(())
    /// ```
    pub fn new(params: BallBearingParams, film: BallFilm) -> Result<Self, ParamError> {
        if usize::from(params.ball_count) != Z || !(3..=64).contains(&Z) {
            return Err(ParamError {
                field: "ball_count",
                value: f32::from(params.ball_count),
                allowed: Allowed::Range {
                    min: Z as f32,
                    max: Z as f32,
                },
            });
        }
        Ok(Self { params, film })
    }

    /// The parameters.
    pub fn params(&self) -> &BallBearingParams {
        &self.params
    }

    /// The film model.
    pub fn film(&self) -> BallFilm {
        self.film
    }

    /// Loads, films, forces, stiffness and damping at `state`, at the same cost for every
    /// input; a state with a NaN, infinite or out-of-range field is refused naming it.
    pub fn evaluate(&self, state: &BallBearingState) -> Result<BallBearingOutput<Z>, ParamError> {
        state.check()?;
        let p = &self.params;
        let omega = state.shaft_speed_rad_s;
        // Outer-raceway control with the outer ring fixed: the cage turns at
        // ω_c = ω(1 − γ₀)/2 and both contacts entrain at u_m = (d_m ω/4)(1 − γ²)
        // (Harris & Kotzalas, vol. 1, ch. 8), evaluated at each ball's own γ below.
        let (_, cos_nominal) = sin_cos(p.nominal_contact_angle_rad);
        let gamma_nominal = p.ball_diameter_m * cos_nominal / p.pitch_diameter_m;
        let mut out = BallBearingOutput {
            force_n: [0.0; 3],
            moment_nm: [0.0; 2],
            stiffness: [[0.0; 5]; 5],
            damping: [[0.0; 5]; 5],
            cage_speed_rad_s: 0.5 * omega * (1.0 - gamma_nominal),
            balls: [BallOutput::UNLOADED; Z],
        };
        let step = core::f32::consts::TAU / Z as f32;
        let BallBearingOutput {
            force_n,
            moment_nm,
            stiffness,
            damping,
            balls,
            ..
        } = &mut out;
        let (mut orbital_weighted, mut orbital_weight) = (0.0_f32, 0.0_f32);
        let mut totals = Totals {
            force_n,
            moment_nm,
            stiffness,
            damping,
        };
        for (j, ball) in balls.iter_mut().enumerate() {
            let azimuth = wrap_angle(state.cage_angle_rad + step * j as f32);
            let (s, c) = sin_cos(azimuth);
            let ri = p.inner_centre_radius_m;
            // Rows of J: d(δ_r, δ_z)/du.
            let jr = [c, s, 0.0, 0.0, 0.0];
            let jz = [0.0, 0.0, 1.0, ri * s, -ri * c];
            let dot = |row: &[f32; 5], v: &[f32; 5]| -> f32 {
                row.iter().zip(v.iter()).map(|(a, b)| a * b).sum()
            };
            let a_r = p.unloaded_offset_m[0] + dot(&jr, &state.displacement);
            let a_z = p.unloaded_offset_m[1] + dot(&jz, &state.displacement);
            let distance = max(sqrt(a_r * a_r + a_z * a_z), 1.0e-9);
            let (nr, nz) = (a_r / distance, a_z / distance);
            // An angular-contact ball has one shoulder: it carries only while its line of
            // centres points to +z (α > 0), else it runs free of the outer ring's relieved side.
            let one_sided = p.kind == BallBearingKind::AngularContact;
            let approach = select(
                one_sided && a_z <= 0.0,
                -1.0e-3,
                distance - p.centre_distance_m,
            );
            let contact = self.ball_contact(nr, approach, omega);
            if p.centrifugal {
                let solved = self.ball_centrifugal([a_r, a_z], nr, &contact, omega);
                *ball = BallOutput {
                    azimuth_rad: azimuth,
                    ..solved.output
                };
                let k_n = ball.stiffness_n_per_m;
                let [n_r, n_z] = solved.normal;
                let rate = n_r * dot(&jr, &state.velocity) + n_z * dot(&jz, &state.velocity);
                let total = ball.load_n[0] + p.damping_factor_s * k_n * rate;
                let damping = p.damping_factor_s * k_n;
                totals.add([jr, jz], solved.normal, solved.local, total, damping);
                orbital_weighted += ball.load_n[0] * solved.orbital_rad_s;
                orbital_weight += ball.load_n[0];
            } else {
                *ball = BallOutput {
                    azimuth_rad: azimuth,
                    contact_angle_rad: [atan2(a_z, a_r); 2],
                    ..contact
                };
                let q = ball.load_n[0];
                let k_n = ball.stiffness_n_per_m;
                // Normal and transverse stiffness in (r, z): k_n n nᵀ + (Q/A)(I − n nᵀ).
                let k_t = q / distance;
                let local = [
                    [k_n * nr * nr + k_t * (1.0 - nr * nr), (k_n - k_t) * nr * nz],
                    [(k_n - k_t) * nr * nz, k_n * nz * nz + k_t * (1.0 - nz * nz)],
                ];
                let rate = nr * dot(&jr, &state.velocity) + nz * dot(&jz, &state.velocity);
                let total = q + p.damping_factor_s * k_n * rate;
                totals.add([jr, jz], [nr, nz], local, total, p.damping_factor_s * k_n);
            }
        }
        if p.centrifugal {
            // The loaded balls' mean orbital speed; the kinematic one when none is loaded.
            out.cage_speed_rad_s = select(
                orbital_weight > 0.0,
                orbital_weighted / max(orbital_weight, f32::MIN_POSITIVE),
                out.cage_speed_rad_s,
            );
        }
        Ok(out)
    }

    /// One ball's load, films and contact ellipses at cos α = `cos_alpha` and geometric
    /// approach `approach_m`, the shaft at `omega` (rad/s).
    fn ball_contact(&self, cos_alpha: f32, approach_m: f32, omega: f32) -> BallOutput {
        let p = &self.params;
        let inner = RaceContact::new(p, cos_alpha, true);
        let outer = RaceContact::new(p, cos_alpha, false);
        let compliance = inner.compliance + outer.compliance;
        let entrainment = p.entrainment_speed_m_s(cos_alpha, omega);
        // Q = (δ/c)^{3/2}, δ = δ_g + H(Q): Newton on λ = ln Q (module doc). Each film call
        // anchors a local power law H(λ) = H_n e^{p(λ − λ_n)}, p Hamrock–Dowson's load
        // exponent, on which a few Newton steps (no film call) solve the equation.
        let dry_load = crate::math::pow(max(approach_m, 0.0) / compliance, 1.5);
        let ln_min = ln(MIN_COUPLED_LOAD_N);
        let ln_compliance = ln(compliance);
        let mut ln_load = ln(max(dry_load, 1.0));
        let mut films = [Film::ZERO; 2];
        let mut anchor = ln_load;
        for _ in 0..FILM_COUPLING_STEPS {
            let load = crate::math::exp(ln_load);
            films = [
                self.film.film(&inner.film_input(p, load, entrainment)),
                self.film.film(&outer.film_input(p, load, entrainment)),
            ];
            anchor = ln_load;
            let film_sum = films[0].central_m + films[1].central_m;
            for _ in 0..POWER_LAW_STEPS {
                let h = film_sum * crate::math::exp(FILM_LOAD_EXPONENT * (ln_load - anchor));
                let elastic = max(approach_m + h, 1.0e-12);
                let residual = ln_load - 1.5 * (ln(elastic) - ln_compliance);
                let slope = 1.0 - 1.5 * FILM_LOAD_EXPONENT * h / elastic;
                ln_load = max(ln_load - residual / slope, ln_min);
            }
        }
        let is_dry = self.film == BallFilm::Dry;
        // The films at the solved load, on the last anchor's power law.
        let film_scale = crate::math::exp(FILM_LOAD_EXPONENT * (ln_load - anchor));
        let film_sum = select(
            is_dry,
            0.0,
            (films[0].central_m + films[1].central_m) * film_scale,
        );
        let elastic = approach_m + film_sum;
        let load = crate::math::pow(max(elastic, 0.0) / compliance, 1.5);
        // dQ/dδ_g = Q / (δ/1.5 − p H): the film thins as Q grows (docs/physics.md §4).
        let denominator = elastic / 1.5 - FILM_LOAD_EXPONENT * film_sum;
        let stiffness = select(load > 0.0, load / max(denominator, 1.0e-12), 0.0);
        // An unloaded ball reports no film: its contacts are open.
        let shown_scale = select(load > 0.0, film_scale, 0.0);
        for film in films.iter_mut() {
            film.central_m *= shown_scale;
            film.minimum_m *= shown_scale;
        }
        let (axes_in, pressure_in) = inner.ellipse(load);
        let (axes_out, pressure_out) = outer.ellipse(load);
        let loaded = load > 0.0;
        BallOutput {
            geometric_approach_m: approach_m,
            load_n: [load; 2],
            semi_axes_inner_m: axes_in,
            semi_axes_outer_m: axes_out,
            max_pressure_pa: [pressure_in, pressure_out],
            central_film_m: [films[0].central_m, films[1].central_m],
            min_film_m: [films[0].minimum_m, films[1].minimum_m],
            film_source: [
                if loaded {
                    films[0].source
                } else {
                    FilmSource::None
                },
                if loaded {
                    films[1].source
                } else {
                    FilmSource::None
                },
            ],
            stiffness_n_per_m: stiffness,
            ..BallOutput::UNLOADED
        }
    }
}

/// `angle` (rad, |angle| ≤ 10⁴) wrapped into [0, 2π).
#[inline]
fn wrap_angle(angle: f32) -> f32 {
    let tau = core::f32::consts::TAU;
    let wrapped = angle - tau * ((angle / tau) as i32 as f32);
    select(wrapped < 0.0, wrapped + tau, wrapped)
}

/// The bearing's totals, borrowed from its output while the balls are filled in.
struct Totals<'a> {
    force_n: &'a mut [f32; 3],
    moment_nm: &'a mut [f32; 2],
    stiffness: &'a mut [[f32; 5]; 5],
    damping: &'a mut [[f32; 5]; 5],
}

impl Totals<'_> {
    /// Add one ball: J = the rows d(δ_r, δ_z)/du, n the contact normal in (r, z), `local` its
    /// 2 × 2 stiffness, `total` its normal force (load and damping) and `damping` its normal
    /// damping coefficient (N·s/m).
    #[inline]
    fn add(
        &mut self,
        rows: [[f32; 5]; 2],
        normal: [f32; 2],
        local: [[f32; 2]; 2],
        total: f32,
        damping: f32,
    ) {
        let [jr, jz] = rows;
        // The ball's generalised direction g = Jᵀn: its force on the inner ring is −total·g.
        let mut g = [0.0_f32; 5];
        for ((g, r), z) in g.iter_mut().zip(jr).zip(jz) {
            *g = normal[0] * r + normal[1] * z;
        }
        let [g0, g1, g2, g3, g4] = g;
        self.force_n[0] -= total * g0;
        self.force_n[1] -= total * g1;
        self.force_n[2] -= total * g2;
        self.moment_nm[0] -= total * g3;
        self.moment_nm[1] -= total * g4;
        // K += Jᵀ local J, C += damping g gᵀ.
        for (((k_row, c_row), (ra, za)), ga) in self
            .stiffness
            .iter_mut()
            .zip(self.damping.iter_mut())
            .zip(jr.iter().zip(jz.iter()))
            .zip(g.iter())
        {
            let left = [
                ra * local[0][0] + za * local[1][0],
                ra * local[0][1] + za * local[1][1],
            ];
            for (((k, c), (rb, zb)), gb) in k_row
                .iter_mut()
                .zip(c_row.iter_mut())
                .zip(jr.iter().zip(jz.iter()))
                .zip(g.iter())
            {
                *k += left[0] * rb + left[1] * zb;
                *c += damping * ga * gb;
            }
        }
    }
}

impl BallBearingParams {
    /// Entrainment speed of both contacts of a ball at cos α = `cos_alpha`, outer-raceway
    /// control with the outer ring fixed: u_m = (d_m |ω|/4)(1 − γ²), γ = D cos α / d_m (m/s).
    #[inline]
    fn entrainment_speed_m_s(&self, cos_alpha: f32, shaft_speed_rad_s: f32) -> f32 {
        let gamma = self.ball_diameter_m * cos_alpha / self.pitch_diameter_m;
        0.25 * self.pitch_diameter_m * shaft_speed_rad_s.abs() * (1.0 - gamma * gamma)
    }

    /// The inner and the outer contact of a ball carrying `load_n` at the nominal (deep
    /// groove: free) contact angle, the shaft at `shaft_speed_rad_s`: the point-film inputs
    /// `bearing film --config` reports on.
    pub fn contact_inputs(&self, load_n: f32, shaft_speed_rad_s: f32) -> [PointContactInput; 2] {
        let p = self;
        let (_, cos_alpha) = sin_cos(p.nominal_contact_angle_rad);
        let entrainment = p.entrainment_speed_m_s(cos_alpha, shaft_speed_rad_s);
        [true, false]
            .map(|inner| RaceContact::new(p, cos_alpha, inner).film_input(p, load_n, entrainment))
    }
}

impl BallOutput {
    /// A ball without load or film.
    pub const UNLOADED: BallOutput = BallOutput {
        azimuth_rad: 0.0,
        geometric_approach_m: 0.0,
        load_n: [0.0; 2],
        contact_angle_rad: [0.0; 2],
        semi_axes_inner_m: [0.0; 2],
        semi_axes_outer_m: [0.0; 2],
        max_pressure_pa: [0.0; 2],
        central_film_m: [0.0; 2],
        min_film_m: [0.0; 2],
        film_source: [FilmSource::None; 2],
        stiffness_n_per_m: 0.0,
    };
}
