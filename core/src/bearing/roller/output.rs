//! What one bearing step returns: per-roller states, forces, moments, stiffness and damping.

use crate::film::{FilmSource, Regime};

/// State of one roller after a step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RollerOutput {
    /// Roller angle θ_j from the x axis (rad, wrapped to (−π, π]).
    pub angle_rad: f32,
    /// Geometric approach x·cos θ + y·sin θ − g_r, without film (m).
    pub geometric_approach_m: f32,
    /// Elastic approach of the roller middle, δ_j = geometric approach + film (m).
    pub approach_m: f32,
    /// Central film at the inner contact h_in (m).
    pub central_film_in_m: f32,
    /// Central film at the outer contact h_out (m).
    pub central_film_out_m: f32,
    /// Minimum film at the inner contact (m).
    pub min_film_in_m: f32,
    /// Minimum film at the outer contact (m).
    pub min_film_out_m: f32,
    /// Contact load Q_j = Σ q_k (N), EHL and hydrodynamic alike.
    pub load_n: f32,
    /// Viscous damping force F_d = f_damp·K_j·δ̇_j (N).
    pub damping_force_n: f32,
    /// Roller moment T_j = Σ q_k x_k (N·m).
    pub moment_nm: f32,
    /// Contact stiffness K_j = dQ_j/dδ_j of the solids (N/m).
    pub contact_stiffness_n_per_m: f32,
    /// Film-coupled roller stiffness dQ_j/d(geometric approach) (N/m).
    pub roller_stiffness_n_per_m: f32,
    /// Regime of the inner contact.
    pub regime_in: Regime,
    /// Regime of the outer contact.
    pub regime_out: Regime,
    /// Model that served the inner contact.
    pub film_source_in: FilmSource,
    /// Model that served the outer contact.
    pub film_source_out: FilmSource,
}

impl RollerOutput {
    /// An unloaded roller with no film.
    pub const ZERO: RollerOutput = RollerOutput {
        angle_rad: 0.0,
        geometric_approach_m: 0.0,
        approach_m: 0.0,
        central_film_in_m: 0.0,
        central_film_out_m: 0.0,
        min_film_in_m: 0.0,
        min_film_out_m: 0.0,
        load_n: 0.0,
        damping_force_n: 0.0,
        moment_nm: 0.0,
        contact_stiffness_n_per_m: 0.0,
        roller_stiffness_n_per_m: 0.0,
        regime_in: Regime::Dry,
        regime_out: Regime::Dry,
        film_source_in: FilmSource::None,
        film_source_out: FilmSource::None,
    };
}

/// The sums over the rollers of one step: force, moment, stiffness and damping on the inner
/// race, and the friction. The one copy of these fields: [`BearingOutput`] and [`OutputView`]
/// hold one, and read as one (`out.force_n`), through `Deref`.
///
/// Generalised coordinates of the inner race are (x, y, tilt about x, tilt about y).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RollerTotals {
    /// Force of the rollers on the inner race [F_x, F_y] (N).
    pub force_n: [f32; 2],
    /// Moment of the rollers on the inner race [M_x, M_y] (N·m).
    pub moment_nm: [f32; 2],
    /// Stiffness −∂(F_x, F_y, M_x, M_y)/∂(x, y, tilt_x, tilt_y): N/m, N, N·m per rad.
    pub stiffness: [[f32; 4]; 4],
    /// Damping −∂(F_x, F_y)/∂(ẋ, ẏ) (N·s/m).
    pub damping_n_s_per_m: [[f32; 2]; 2],
    /// Each roller's centrifugal force on the outer race F_c (N; 0 when the bearing leaves it
    /// out, docs/physics.md §4.1): every roller's outer contact carries its `load_n` + F_c.
    pub centrifugal_force_n: f32,
    /// Friction torque on the inner ring (N·m; docs/physics.md §8.4), filled by
    /// [`Bearing::friction`](crate::Bearing::friction) (0 until then, and for the dry model).
    pub friction_torque_nm: f32,
    /// Power loss of the bearing's roller–race contacts (W).
    pub power_loss_w: f32,
    /// The power loss split into [rolling, viscous, boundary] (W).
    pub power_loss_split_w: [f32; 3],
}

impl RollerTotals {
    /// All zero.
    pub const ZERO: Self = Self {
        force_n: [0.0; 2],
        moment_nm: [0.0; 2],
        stiffness: [[0.0; 4]; 4],
        damping_n_s_per_m: [[0.0; 2]; 2],
        centrifugal_force_n: 0.0,
        friction_torque_nm: 0.0,
        power_loss_w: 0.0,
        power_loss_split_w: [0.0; 3],
    };

    /// The 2×2 radial stiffness block −∂(F_x, F_y)/∂(x, y) (N/m).
    pub fn radial_stiffness_n_per_m(&self) -> [[f32; 2]; 2] {
        let [r0, r1, _, _] = self.stiffness;
        [[r0[0], r0[1]], [r1[0], r1[1]]]
    }
}

/// Result of one bearing step for `Z` rollers: the totals, and each roller.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BearingOutput<const Z: usize> {
    /// Forces, moments, stiffness, damping and friction summed over the rollers (also read
    /// directly: `out.force_n`).
    pub totals: RollerTotals,
    /// Film ratios [λ_in, λ_out] = h/σ of each roller's contacts (central film over the
    /// composite roughness; docs/physics.md §8.1), filled by
    /// [`Bearing::friction`](crate::Bearing::friction) like the friction (outside
    /// [`RollerOutput`], which the step writes whole).
    pub lambda: [[f32; 2]; Z],
    /// Per-roller states.
    pub rollers: [RollerOutput; Z],
}

impl<const Z: usize> core::ops::Deref for BearingOutput<Z> {
    type Target = RollerTotals;
    fn deref(&self) -> &RollerTotals {
        &self.totals
    }
}

impl<const Z: usize> BearingOutput<Z> {
    /// All zero.
    pub const ZERO: Self = Self {
        totals: RollerTotals::ZERO,
        lambda: [[0.0; 2]; Z],
        rollers: [RollerOutput::ZERO; Z],
    };

    /// The same output with its rollers as a slice, whatever `Z`.
    pub fn view(&self) -> OutputView<'_> {
        OutputView {
            totals: self.totals,
            lambda: &self.lambda,
            rollers: &self.rollers,
        }
    }

    /// Largest roller load (N).
    pub fn max_roller_load_n(&self) -> f32 {
        self.view().max_roller_load_n()
    }

    /// Number of contacts (inner and outer, all rollers) served by `source`.
    pub fn contacts_served_by(&self, source: FilmSource) -> usize {
        self.view().contacts_served_by(source)
    }
}

/// A [`BearingOutput`] of any roller count: the totals by value, the rollers borrowed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OutputView<'a> {
    /// Forces, moments, stiffness, damping and friction summed over the rollers (also read
    /// directly: `view.force_n`).
    pub totals: RollerTotals,
    /// Film ratios [λ_in, λ_out] of each roller's contacts.
    pub lambda: &'a [[f32; 2]],
    /// Per-roller states, one per roller.
    pub rollers: &'a [RollerOutput],
}

impl core::ops::Deref for OutputView<'_> {
    type Target = RollerTotals;
    fn deref(&self) -> &RollerTotals {
        &self.totals
    }
}

impl OutputView<'_> {
    /// The load of `roller`'s outer contact, Q_out = Q_in + F_c (N).
    pub fn load_out_n(&self, roller: &RollerOutput) -> f32 {
        roller.load_n + self.totals.centrifugal_force_n
    }

    /// Largest roller load (N).
    pub fn max_roller_load_n(&self) -> f32 {
        self.rollers.iter().fold(0.0, |m, r| m.max(r.load_n))
    }

    /// Number of contacts (inner and outer, all rollers) served by `source`.
    pub fn contacts_served_by(&self, source: FilmSource) -> usize {
        self.rollers
            .iter()
            .map(|r| {
                usize::from(r.film_source_in == source) + usize::from(r.film_source_out == source)
            })
            .sum()
    }
}

/// The bearing stiffness summed roller by roller in nine scalars.
///
/// Slice k has approach δ_k = aₖ·g + const with aₖ = u + x_k·v, u = (c, s, 0, 0),
/// v = (0, 0, −s, c); a roller contributes Σ_k q'_k aₖaₖᵀ + c_f·b bᵀ with b = Σ_k q'_k aₖ and the
/// film coupling c_f = H'/(1 − K_j H') (H' = dH/dQ of the film sum, ≤ 0): the roller load depends
/// on the film, which depends on the roller load. With the slice sums S₀ = Σq', S₁ = Σq'x,
/// S₂ = Σq'x² that is A·uuᵀ + B·(uvᵀ + vuᵀ) + C·vvᵀ, A = S₀ + c_f S₀², B = S₁ + c_f S₀S₁,
/// C = S₂ + c_f S₁², and every entry of the 4×4 matrix is one of A, B, C times c², cs or s².
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct StiffnessSums {
    /// Σ A·(c², cs, s²), Σ B·(…), Σ C·(…).
    a: [f32; 3],
    b: [f32; 3],
    c: [f32; 3],
    /// Σ S₀·(c², cs, s²): the contact stiffness alone, which the damping follows.
    contact: [f32; 3],
}

impl StiffnessSums {
    /// Add one roller at direction (c, s) = (cos θ, sin θ) with slice sums [S₀, S₁, S₂] and film
    /// coupling factor c_f.
    #[inline]
    pub(crate) fn add(&mut self, (c, s): (f32, f32), [s0, s1, s2]: [f32; 3], film_coupling: f32) {
        let trig = [c * c, c * s, s * s];
        let a = s0 + film_coupling * s0 * s0;
        let b = s1 + film_coupling * s0 * s1;
        let cc = s2 + film_coupling * s1 * s1;
        for (((sa, sb), sc), t) in self
            .a
            .iter_mut()
            .zip(self.b.iter_mut())
            .zip(self.c.iter_mut())
            .zip(trig)
        {
            *sa += a * t;
            *sb += b * t;
            *sc += cc * t;
        }
        for (d, t) in self.contact.iter_mut().zip(trig) {
            *d += s0 * t;
        }
    }

    /// The damping matrix f_damp·Σ K_j·(c², cs; cs, s²) of damping factor f_damp (s): each
    /// roller's viscous force f_damp·K_j·δ̇_j along its direction.
    pub(crate) fn damping(&self, damping_factor_s: f32) -> [[f32; 2]; 2] {
        let [cc, cs, ss] = self.contact.map(|v| damping_factor_s * v);
        [[cc, cs], [cs, ss]]
    }

    /// −∂(F_x, F_y, M_x, M_y)/∂(x, y, tilt_x, tilt_y).
    pub(crate) fn matrix(&self) -> [[f32; 4]; 4] {
        let [acc, acs, ass] = self.a;
        let [bcc, bcs, bss] = self.b;
        let [ccc, ccs, css] = self.c;
        [
            [acc, acs, -bcs, bcc],
            [acs, ass, -bss, bcs],
            [-bcs, -bss, css, -ccs],
            [bcc, bcs, -ccs, ccc],
        ]
    }
}
