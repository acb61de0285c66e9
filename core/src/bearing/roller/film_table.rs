//! Every roller's film as a function of its load: a table over ln Q kept by the bearing and
//! renewed one node per step.
//!
//! **Why a table.** The film–load coupling (`coupling`) needs each roller's film sum H(Q) at
//! every Newton step, and a film-model call per evaluation would cost more than the whole step
//! may. Within one step all contacts of one kind (inner or outer) share speed, radius and
//! lubricant, so their film depends on the roller load alone: one curve per contact kind,
//! sampled at [`TABLE_NODES`] fixed loads λᵢ = ln Qᵢ ([`TABLE_STEP`] apart, 1 N … 144 kN) and
//! interpolated linearly between them. Because the nodes cover every load a roller can reach,
//! a load that jumps by a factor 50 within a few steps (a run-up through a resonance) meets
//! nodes the model has already computed; the previous scheme (a parabola through three nodes
//! about last step's loads, plus per-roller anchors) could not follow such jumps.
//!
//! **Speed.** The speed changes every step, the table only one node of one contact per step. Each node stores
//! its film divided by u^κ (κ = [`SPEED_EXPONENT`], the EHL speed exponent of Dowson–Higginson
//! and Moes, ≈ 0.67–0.75) at the speed it was computed, and the step multiplies by u^κ again;
//! what is left of a speed change is (κ_true − κ)·Δ ln u, and the nodes are renewed in turn,
//! those within the loaded range on every other step (one contact kind per step). At a constant speed
//! the table is the model, node for node.
//!
//! **Light loads.** A film model returns the complete film, which rises like Martin's
//! hydrodynamic film h_RI = B/Q as the load vanishes (`FilmModel`). A table linear in the load
//! cannot follow 1/Q between nodes well, and Martin's part scales as u¹, not u^κ, so the film
//! is split into Martin's part and the rest, in quadrature: e = √(h² − h_RI²) is tabulated and
//! the film at any load is √(e(λ)² + h_RI(λ)²) with h_RI exact. At the nodes this returns the
//! model's film exactly.
//!
//! **High-speed corrections.** The thermal and starvation factors (docs/physics.md §5.4,
//! `film::corrections`) depend on the load (through p_h and the flooded film) and on the speed
//! (through the thermal loading number). They are applied where a node is renewed, at the
//! node's load and the renewing step's speed, so the step pays the factors of one node —
//! fixed work — and reading the table costs nothing more. Between renewals a node carries its
//! factors from the speed it was renewed at, as it carries its film (by u^κ); at a constant
//! speed the table is the corrected model, node for node.
//!
//! **Accuracy.** Linear interpolation of a film e ∝ Q^p between nodes Δλ apart is off by at
//! most (p·Δλ)²/8: 2·10⁻⁵ for EHL films (p ≈ −0.1), 0.2 % even for |p| = 1.

use crate::film::corrections::{ehl_part, FilmCorrections};
use crate::film::{ContactInput, FilmModel};
use crate::lanes::Real;
use crate::math::{exp, exp_in_range, ln, max, min};

/// Nodes of the film table per contact kind.
pub(crate) const TABLE_NODES: usize = 96;
/// Spacing of the nodes in ln Q.
pub(crate) const TABLE_STEP: f32 = 0.125;
/// Table nodes a real-time step renews, each for one contact kind (one film-model call each).
pub(crate) const REFRESHES_PER_STEP: usize = 1;
/// Speed exponent κ by which a node's film is carried from the speed it was computed at to the
/// step's speed: h ∝ u^0.67 (Dowson–Higginson), u^0.7 (Hamrock, *Fundamentals of Fluid Film
/// Lubrication*, 1994, line contacts), Moes' EHL asymptotes u^0.67–0.75.
pub(crate) const SPEED_EXPONENT: f32 = 0.7;

/// ln Q of the first node: 1 N.
const LN_LOAD_FIRST: f32 = 0.0;
/// Half-width in ln Q by which the loaded range is widened when nodes are chosen for renewal.
const LOADED_MARGIN: f32 = 0.5;

/// ln Q of node `i`.
fn node_ln_load(i: usize) -> f32 {
    LN_LOAD_FIRST + i as f32 * TABLE_STEP
}

/// The film table of one bearing: both contact kinds, central and minimum film.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct FilmTable {
    /// e/u^κ of the central film at each node, inner and outer contact (m/(m/s)^κ).
    central: [[f32; TABLE_NODES]; 2],
    /// e/u^κ of the minimum film at each node, inner and outer contact.
    minimum: [[f32; TABLE_NODES]; 2],
    /// The node the loaded-range cursor and the all-nodes cursor renewed last.
    cursors: [usize; 2],
    /// Which (cursor, contact) the next step renews: 0 loaded/inner, 1 loaded/outer,
    /// 2 all/inner, 3 all/outer.
    phase: usize,
}

impl Default for FilmTable {
    fn default() -> Self {
        Self {
            central: [[0.0; TABLE_NODES]; 2],
            minimum: [[0.0; TABLE_NODES]; 2],
            cursors: [0; 2],
            phase: 0,
        }
    }
}

/// The film law of one step: the table at this step's speed.
#[derive(Clone, Copy, Debug)]
pub(crate) struct StepFilms<'a> {
    table: &'a FilmTable,
    /// u^κ of this step.
    speed_scale: f32,
    /// Martin coefficients B with h_RI = B/Q, inner and outer, divided by u^κ (m·N/(m/s)^κ):
    /// the films are blended in the table's units, √(e² + (B/u^κ·1/Q)²), and scaled by u^κ
    /// once.
    martin_per_scale: [f32; 2],
    /// A roller's centrifugal force F_c on the outer race (N), when the bearing includes it
    /// (the same branch at every step, whatever the speed): the outer contact carries
    /// Q_out = Q + F_c (`sum_split`).
    centrifugal_n: Option<f32>,
}

/// Film sums of the rollers in the lanes of `T` (one roller: [`FilmSum`]) at their λ = ln Q,
/// with what the rollers' outputs take from them.
#[derive(Clone, Copy, Debug)]
pub(crate) struct FilmSums<T: Real> {
    /// H = Σ √(e² + h_RI²), the film both contacts add to the approach (m).
    pub total_m: T,
    /// dH/dλ (m).
    pub slope_m: T,
    /// 1/Q = e^(−λ) (1/N).
    inv_load: T,
    /// The terms of the sum, each contact's central film, divided by u^κ.
    central: [T; 2],
    /// Where λ fell in the table.
    cell: Cell<T>,
}

/// Film sum of one roller.
pub(crate) type FilmSum = FilmSums<f32>;

impl Default for FilmSum {
    fn default() -> Self {
        Self {
            total_m: 0.0,
            slope_m: 0.0,
            inv_load: 0.0,
            central: [0.0; 2],
            cell: Cell::default(),
        }
    }
}

impl<T: Real> FilmSums<T> {
    /// 1/Q at the evaluation (1/N).
    #[inline(always)]
    pub(crate) fn inv_load(&self) -> T {
        self.inv_load
    }

    /// Empty sums, with λ in the table's first cell: a solve's before its first evaluation.
    #[inline(always)]
    pub(crate) fn zero() -> Self {
        let zero = T::splat(0.0);
        Self {
            total_m: zero,
            slope_m: zero,
            inv_load: zero,
            central: [zero; 2],
            cell: Cell {
                index: T::build(|_| 0),
                fraction: zero,
                slope_scale: zero,
            },
        }
    }

    /// The sum of lane `i` (a zero sum beyond the lanes).
    #[cfg(test)]
    #[inline(always)]
    pub(crate) fn lane(&self, i: usize) -> FilmSum {
        FilmSum {
            total_m: self.total_m.lane(i),
            slope_m: self.slope_m.lane(i),
            inv_load: self.inv_load.lane(i),
            central: self.central.map(|c| c.lane(i)),
            cell: Cell {
                index: T::item(&self.cell.index, i),
                fraction: self.cell.fraction.lane(i),
                slope_scale: self.cell.slope_scale.lane(i),
            },
        }
    }
}

/// Where λ falls in the table: the cell's first node and the fraction across it, held to the
/// table at both ends (the film is continued flat beyond them: below 1 N Martin's film rules,
/// above 144 kN no roller goes). Of one roller, or of the rollers in the lanes of `T`: the
/// host computes the cells of four or eight rollers in SIMD lanes and looks up only the nodes lane by
/// lane.
#[derive(Clone, Copy, Debug)]
struct Cell<T: Real = f32> {
    index: T::PerLane<usize>,
    fraction: T,
    /// 1/Δλ inside the table, 0 beyond it (the slope of the flat continuation).
    slope_scale: T,
}

impl Default for Cell {
    fn default() -> Self {
        Self {
            index: 0,
            fraction: 0.0,
            slope_scale: 0.0,
        }
    }
}

impl<T: Real> Cell<T> {
    #[inline(always)]
    fn at(ln_load: T) -> Self {
        let position = (ln_load - T::splat(LN_LOAD_FIRST)) * T::splat(1.0 / TABLE_STEP);
        let end = (TABLE_NODES - 1) as f32;
        let clamped = position.max(T::splat(0.0)).min(T::splat(end));
        // One float-to-integer conversion at a fixed cost; the clamp keeps it in the table
        // (the last node starts no cell: at the end the fraction is 1 across the last cell).
        let (index, index_f32) = clamped.min(T::splat(end - 1.0)).truncate_index();
        Self {
            index,
            fraction: clamped - index_f32,
            // Beyond the table the film is continued flat: the clamp moved the position.
            slope_scale: T::splat(1.0 / TABLE_STEP) * T::indicator(clamped.eq(position)),
        }
    }

    /// Value and d/dλ of the linear interpolant of `nodes`.
    #[inline(always)]
    fn interpolate(&self, nodes: &[f32; TABLE_NODES]) -> (T, T) {
        // The index is at most TABLE_NODES − 2 by construction (`at`); held there again so
        // that the compiler sees both look-ups in bounds and drops their checks and branches.
        let node = |i: usize, next: usize| {
            nodes
                .get(crate::math::min_index(i, TABLE_NODES - 2) + next)
                .copied()
                .unwrap_or(0.0)
        };
        let a = T::from_per_lane(&self.index, |&i| node(i, 0));
        let b = T::from_per_lane(&self.index, |&i| node(i, 1));
        let d = b - a;
        (a + self.fraction * d, d * self.slope_scale)
    }
}

impl FilmTable {
    /// Renew node `i` of contact `k` (0 inner, 1 outer) from `model` for the contact template
    /// `contact` (load ignored) with Martin coefficient `martin`, its film corrected by
    /// `corrections` (docs/physics.md §5.4): the node's part beyond Martin's film is multiplied
    /// by φ_T·φ_S at the node's load and this step's speed, so a corrected table costs the step
    /// the factors of one node, and an uncorrected one a multiplication by 1.
    fn renew<F: FilmModel + ?Sized>(
        &mut self,
        model: &F,
        contact: &ContactInput,
        (martin, corrections): (f32, &FilmCorrections),
        inv_speed_scale: f32,
        (i, k): (usize, usize),
    ) {
        let load_n = exp(node_ln_load(i));
        let input = ContactInput { load_n, ..*contact };
        let film = model.film(&input);
        let hydro = martin / load_n;
        let factor = if corrections.is_off() {
            1.0
        } else {
            correction_factor(corrections, &input, film.central_m)
        };
        let central = ehl_part(film.central_m, hydro) * factor * inv_speed_scale;
        let minimum = ehl_part(film.minimum_m, hydro) * factor * inv_speed_scale;
        if let Some(slot) = self.central.get_mut(k).and_then(|c| c.get_mut(i)) {
            *slot = central;
        }
        if let Some(slot) = self.minimum.get_mut(k).and_then(|c| c.get_mut(i)) {
            *slot = minimum;
        }
    }

    /// The contact kind (0 inner, 1 outer) whose node the next `step` renews.
    pub(crate) fn next_contact(&self) -> usize {
        self.phase & 1
    }

    /// u^κ of a step whose contacts have the entrainment speed of `contacts[0]` (both
    /// contacts share it), by which the table's nodes are scaled.
    pub(crate) fn speed_scale(contacts: &[ContactInput; 2]) -> f32 {
        exp(SPEED_EXPONENT * ln(contacts[0].entrainment_speed_m_s))
    }

    /// Renew every node (`renew_all`) or [`REFRESHES_PER_STEP`] node of one contact from
    /// `model`, for contact templates `contacts` (inner, outer; loads ignored; they always
    /// carry some entrainment, see the bearing's standstill floor) with Martin coefficients
    /// `martin` at the speed of `1/inv_speed_scale` = u^κ ([`FilmTable::speed_scale`]): by
    /// turns the next node of the loaded range `loaded` (ln Q, widened by a margin) for the
    /// inner and the outer contact, then the next node of the whole table for each. Round
    /// robin renews the node computed longest ago, so at the speed farthest from this step's;
    /// the cost is fixed. Inlined into the step, as the renewal was before it became a function
    /// of its own (a call costs the M4 ≈ 100 instructions of spills with the integer network).
    #[inline(always)]
    pub(crate) fn renew_nodes<F: FilmModel + ?Sized>(
        &mut self,
        model: &F,
        (contacts, corrections): ([ContactInput; 2], &FilmCorrections),
        martin: [f32; 2],
        inv_speed_scale: f32,
        loaded: (f32, f32),
        renew_all: bool,
    ) {
        if renew_all {
            for i in 0..TABLE_NODES {
                for (k, (contact, &b)) in contacts.iter().zip(martin.iter()).enumerate() {
                    self.renew(model, contact, (b, corrections), inv_speed_scale, (i, k));
                }
            }
        } else {
            for _ in 0..REFRESHES_PER_STEP {
                let contact = self.next_contact();
                let cursor = self.phase >> 1;
                // The node range of this cursor: the loaded range or the whole table.
                let last = TABLE_NODES - 1;
                let node_of = |ln_load: f32| {
                    min(
                        max((ln_load - LN_LOAD_FIRST) * (1.0 / TABLE_STEP), 0.0),
                        last as f32,
                    ) as usize
                };
                let whole = usize::from(cursor == 1);
                let first = node_of(loaded.0 - LOADED_MARGIN) * (1 - whole);
                let end = node_of(loaded.1 + LOADED_MARGIN) * (1 - whole) + last * whole;
                let previous = self.cursors.get(cursor).copied().unwrap_or(0);
                // The inner contact moves the cursor on; the outer one renews the same node.
                let next = previous + (1 - contact);
                let next = if (next < first) | (next > end) {
                    first
                } else {
                    next
                };
                if let Some(c) = self.cursors.get_mut(cursor) {
                    *c = next;
                }
                let template = contacts.get(contact).copied().unwrap_or(contacts[0]);
                let b = martin.get(contact).copied().unwrap_or(0.0);
                self.renew(
                    model,
                    &template,
                    (b, corrections),
                    inv_speed_scale,
                    (next, contact),
                );
                self.phase = (self.phase + 1) & 3;
            }
        }
    }

    /// The table as a step's film law at speed scale u^κ = `speed_scale` (its inverse
    /// `inv_speed_scale`) with Martin coefficients `martin` (inner, outer), for rollers without
    /// centrifugal force ([`FilmTable::films_centrifugal`] without one).
    #[cfg(test)]
    pub(crate) fn films(
        &self,
        speed_scale: f32,
        inv_speed_scale: f32,
        martin: [f32; 2],
    ) -> StepFilms<'_> {
        self.films_centrifugal(speed_scale, inv_speed_scale, martin, None)
    }

    /// [`FilmTable::films`] for rollers pressed on the outer race by `centrifugal_n` (N), if
    /// the bearing includes the centrifugal force.
    #[inline(always)]
    pub(crate) fn films_centrifugal(
        &self,
        speed_scale: f32,
        inv_speed_scale: f32,
        martin: [f32; 2],
        centrifugal_n: Option<f32>,
    ) -> StepFilms<'_> {
        StepFilms {
            table: self,
            speed_scale,
            martin_per_scale: martin.map(|b| b * inv_speed_scale),
            centrifugal_n,
        }
    }

    /// [`FilmTable::renew_nodes`] at the speed of `contacts`, then this step's films
    /// (uncorrected).
    #[cfg(test)]
    pub(crate) fn step<F: FilmModel + ?Sized>(
        &mut self,
        model: &F,
        contacts: [ContactInput; 2],
        martin: [f32; 2],
        loaded: (f32, f32),
        renew_all: bool,
    ) -> StepFilms<'_> {
        self.step_corrected(
            model,
            (contacts, &FilmCorrections::OFF),
            martin,
            loaded,
            renew_all,
        )
    }

    /// [`FilmTable::step`] with the film corrections `corrections`.
    #[cfg(test)]
    pub(crate) fn step_corrected<F: FilmModel + ?Sized>(
        &mut self,
        model: &F,
        (contacts, corrections): ([ContactInput; 2], &FilmCorrections),
        martin: [f32; 2],
        loaded: (f32, f32),
        renew_all: bool,
    ) -> StepFilms<'_> {
        let speed_scale = Self::speed_scale(&contacts);
        let inv_speed_scale = 1.0 / speed_scale;
        self.renew_nodes(
            model,
            (contacts, corrections),
            martin,
            inv_speed_scale,
            loaded,
            renew_all,
        );
        self.films(speed_scale, inv_speed_scale, martin)
    }
}

impl StepFilms<'_> {
    /// Whether the rollers are pressed on the outer race by their centrifugal force.
    #[inline(always)]
    pub(crate) fn centrifugal(&self) -> bool {
        self.centrifugal_n.is_some()
    }

    /// A roller's centrifugal force on the outer race F_c (N); 0 when left out.
    #[inline(always)]
    pub(crate) fn centrifugal_n(&self) -> f32 {
        self.centrifugal_n.unwrap_or(0.0)
    }

    /// [`StepFilms::sum_at`] with the outer contact at its own load Q_out = Q·`load_ratio`
    /// (a roller pressed on the outer race by its centrifugal force, docs/physics.md §4.1):
    /// the inner film at λ = `ln_load` (1/Q = `inv_load`), the outer at λ_out = `ln_load_out`,
    /// and dH/dλ with the outer term's dλ_out/dλ = Q/Q_out. The minimum films of the outer
    /// contact are not kept: [`StepFilms::contacts_from_split`] looks them up at the root.
    #[inline(always)]
    pub(crate) fn sum_split<T: Real>(
        &self,
        ln_load: T,
        (ln_load_out, load_ratio): (T, T),
        inv_load: T,
    ) -> FilmSums<T> {
        let one = T::splat(1.0);
        let cell = Cell::at(ln_load);
        let outer_weight = one / load_ratio;
        let per_contact = [
            (cell, inv_load, one),
            (Cell::at(ln_load_out), inv_load * outer_weight, outer_weight),
        ];
        let mut total_m = T::splat(0.0);
        let mut slope_m = T::splat(0.0);
        let mut central = [T::splat(0.0); 2];
        for (((nodes, &b), h_out), (contact_cell, contact_inv_load, weight)) in self
            .table
            .central
            .iter()
            .zip(self.martin_per_scale.iter())
            .zip(central.iter_mut())
            .zip(per_contact.iter())
        {
            let (e, de) = contact_cell.interpolate(nodes);
            let hydro = T::splat(b) * *contact_inv_load;
            let h = (e * e + hydro * hydro).sqrt_non_negative();
            *h_out = h;
            total_m = total_m + h;
            slope_m = slope_m + *weight * (e * de - hydro * hydro) / h.max(T::splat(1.0e-30));
        }
        let speed_scale = T::splat(self.speed_scale);
        FilmSums {
            total_m: total_m * speed_scale,
            slope_m: slope_m * speed_scale,
            inv_load,
            central,
            cell,
        }
    }

    /// [`StepFilms::contacts_from`] for a sum of [`StepFilms::sum_split`]: the outer contact's
    /// minimum film at its own load, λ_out = `ln_load_out` with Q_out/Q = `load_ratio` at the
    /// last evaluation.
    #[inline(always)]
    pub(crate) fn contacts_from_split<T: Real>(
        &self,
        last: &FilmSums<T>,
        total_m: T,
        (ln_load_out, load_ratio): (T, T),
    ) -> [(T, T); 2] {
        let [inner, (outer_central, _)] = self.contacts_from(last, total_m);
        let zero = T::splat(0.0);
        let scale = T::select(
            last.total_m.gt(zero),
            total_m / last.total_m.max(T::splat(1.0e-30)),
            zero,
        ) * T::splat(self.speed_scale);
        let [_, outer_minimum] = &self.table.minimum;
        let [_, outer_martin] = self.martin_per_scale;
        let hm = Cell::at(ln_load_out).interpolate(outer_minimum).0;
        let hr_min = T::splat(outer_martin) * last.inv_load / load_ratio;
        [
            inner,
            (
                outer_central,
                (hm * hm + hr_min * hr_min).sqrt_non_negative() * scale,
            ),
        ]
    }

    /// H and dH/dλ at λ = ln Q, of each roller in the lanes of `T`: each contact's
    /// √(e² + h_RI²), summed. The lanes run the same operations in the same order as one
    /// roller (the same bits); only the table look-ups go lane by lane. Inlined into the
    /// host's lanes (a call would pass the lanes through memory); a call on the M4, whose
    /// registers the inlined sum would overflow into the stack (+400 instructions per step;
    /// `inline(never)`: with the bounds checks gone LLVM would inline it).
    #[cfg_attr(target_arch = "arm", inline(never))]
    #[cfg_attr(not(target_arch = "arm"), inline(always))]
    pub(crate) fn sum_at<T: Real>(&self, ln_load: T) -> FilmSums<T> {
        // λ is bracketed by the scalar solve: in range.
        let inv_load = exp_in_range(-ln_load);
        let cell = Cell::at(ln_load);
        let mut total_m = T::splat(0.0);
        let mut slope_m = T::splat(0.0);
        let mut central = [T::splat(0.0); 2];
        // In the table's units (films divided by u^κ), scaled once at the end.
        for ((nodes, &b), h_out) in self
            .table
            .central
            .iter()
            .zip(self.martin_per_scale.iter())
            .zip(central.iter_mut())
        {
            let (e, de) = cell.interpolate(nodes);
            let hydro = T::splat(b) * inv_load;
            // e and h_RI are finite (table values, and B/Q with λ bracketed): no clamp needed.
            let h = (e * e + hydro * hydro).sqrt_non_negative();
            *h_out = h;
            total_m = total_m + h;
            slope_m = slope_m + (e * de - hydro * hydro) / h.max(T::splat(1.0e-30));
        }
        let speed_scale = T::splat(self.speed_scale);
        FilmSums {
            total_m: total_m * speed_scale,
            slope_m: slope_m * speed_scale,
            inv_load,
            central,
            cell,
        }
    }

    /// Central and minimum film of each contact for a roller whose scalar solve evaluated the
    /// sum `last` at its last iterate and returned the film sum `total_m` at its root (`last`
    /// continued by its tangent). The minimum films are interpolated where `last` was; both
    /// films of both contacts are then scaled by total_m/last.total_m, so that the central
    /// films add up to the root's sum. (The last Newton step is small, and this spares a
    /// second look-up in the table at the root.)
    /// Of one roller, or of the rollers in the lanes of `T`.
    #[inline(always)]
    pub(crate) fn contacts_from<T: Real>(&self, last: &FilmSums<T>, total_m: T) -> [(T, T); 2] {
        // The ratio, and u^κ: `last.central` and the table are in the table's units.
        let zero = T::splat(0.0);
        let scale = T::select(
            last.total_m.gt(zero),
            total_m / last.total_m.max(T::splat(1.0e-30)),
            zero,
        ) * T::splat(self.speed_scale);
        let mut out = [(zero, zero); 2];
        for (((o, minimum), &b), &central) in out
            .iter_mut()
            .zip(self.table.minimum.iter())
            .zip(self.martin_per_scale.iter())
            .zip(last.central.iter())
        {
            let hm = last.cell.interpolate(minimum).0;
            let hr_min = T::splat(b) * last.inv_load;
            *o = (
                central * scale,
                (hm * hm + hr_min * hr_min).sqrt_non_negative() * scale,
            );
        }
        out
    }
}

/// φ_T·φ_S of a node (`FilmCorrections::factors`), kept out of the step's inlined code: its
/// powers would otherwise take registers from the whole step of a bearing without corrections.
#[inline(never)]
#[cold]
fn correction_factor(corrections: &FilmCorrections, contact: &ContactInput, flooded_m: f32) -> f32 {
    corrections.factors(contact, flooded_m).product()
}

/// Also the fixture of the other film-table users' tests (`coupling`, `lockstep`).
#[cfg(test)]
pub(super) mod tests {
    use super::*;
    use crate::film::Regression;

    /// The reduced modulus of the tests' contacts (Pa).
    pub(in crate::bearing::roller) const MODULUS_PA: f32 = 2.3e11;

    /// The inner and outer contact templates of a hub-bearing-like roller (15 mm, R 3.7 and
    /// 5.1 mm, α 21 GPa⁻¹, η₀ 0.08 Pa·s) at entrainment speed `speed_m_s` and reduced modulus
    /// `modulus_pa`.
    pub(in crate::bearing::roller) fn contacts_with(
        speed_m_s: f32,
        modulus_pa: f32,
    ) -> [ContactInput; 2] {
        let c = |r: f32| ContactInput {
            load_n: 0.0,
            length_m: 0.015,
            entrainment_speed_m_s: speed_m_s,
            reduced_radius_m: r,
            reduced_modulus_pa: modulus_pa,
            pressure_viscosity_pa_inv: 2.1e-8,
            viscosity_pa_s: 0.08,
        };
        [c(3.7e-3), c(5.1e-3)]
    }

    fn contacts(speed_m_s: f32) -> [ContactInput; 2] {
        contacts_with(speed_m_s, MODULUS_PA)
    }

    /// Martin's coefficients B = MARTIN·η₀·u·R·l of the contacts.
    pub(in crate::bearing::roller) fn martin(c: &[ContactInput; 2]) -> [f32; 2] {
        c.map(|c| {
            crate::film::MARTIN
                * c.viscosity_pa_s
                * c.entrainment_speed_m_s
                * c.reduced_radius_m
                * c.length_m
        })
    }

    /// The regression's central films of both contacts at λ, summed: what the table stands for.
    fn model_sum(contacts: &[ContactInput; 2], ln_load: f32) -> f32 {
        contacts
            .iter()
            .map(|t| {
                Regression
                    .film(&ContactInput {
                        load_n: exp(ln_load),
                        ..*t
                    })
                    .central_m
            })
            .sum()
    }

    /// Between the nodes the table returns the model's film within the bound of linear
    /// interpolation ((p·Δλ)²/8 on e, plus the blend), checked against the model itself at
    /// loads between the nodes, 2 N … 50 kN.
    #[test]
    fn table_matches_the_model_between_nodes() {
        let c = contacts(8.0);
        let m = martin(&c);
        let mut table = FilmTable::default();
        let films = table.step(&Regression, c, m, (0.0, 10.0), true);
        let mut worst = 0.0f32;
        for k in 0..400 {
            let lambda = 0.7 + k as f32 * 0.025;
            let sum = films.sum_at(lambda);
            let direct = model_sum(&c, lambda);
            worst = worst.max((sum.total_m / direct - 1.0).abs());
        }
        assert!(worst < 2.0e-3, "worst {worst}");
    }

    /// With corrections on, the table serves each contact's film corrected as
    /// `corrected_film_m` computes it from the model's film and the factors, at the nodes
    /// (checked at every tenth node, 1 N … 100 kN), and with corrections off the same bits as
    /// the uncorrected table.
    #[test]
    fn corrected_table_serves_the_corrected_model_film() {
        use crate::film::corrections::{corrected_film_m, Starvation, ThermalCorrection};
        let c = contacts(30.0);
        let m = martin(&c);
        let on = FilmCorrections {
            thermal: Some(ThermalCorrection::new(0.034, 0.14).unwrap()),
            starvation: Some(Starvation::new(0.3e-6, 2.0).unwrap()),
        };
        let mut table = FilmTable::default();
        let films = table.step_corrected(&Regression, (c, &on), m, (0.0, 10.0), true);
        for i in (0..93).step_by(10) {
            let lambda = node_ln_load(i);
            let load_n = exp(lambda);
            let served = films.sum_at(lambda).total_m;
            let direct: f32 = c
                .iter()
                .zip(m.iter())
                .map(|(t, &b)| {
                    let input = ContactInput { load_n, ..*t };
                    let h = Regression.film(&input).central_m;
                    corrected_film_m(h, b / load_n, on.factors(&input, h).product())
                })
                .sum();
            let flooded = model_sum(&c, lambda);
            assert!(
                (served / direct - 1.0).abs() < 1.0e-5,
                "node {i}: {served} vs {direct}"
            );
            assert!(served < flooded, "node {i}: corrections lower the film");
        }
        let mut plain = FilmTable::default();
        let mut off = FilmTable::default();
        let a = plain.step(&Regression, c, m, (0.0, 10.0), true).sum_at(5.3);
        let b = off
            .step_corrected(
                &Regression,
                (c, &FilmCorrections::OFF),
                m,
                (0.0, 10.0),
                true,
            )
            .sum_at(5.3);
        assert_eq!(a.total_m.to_bits(), b.total_m.to_bits());
        assert_eq!(plain, off);
    }

    /// A speed change is carried by u^κ until the nodes are renewed; renewing every loaded
    /// node brings the table back to the model exactly.
    #[test]
    fn renewal_follows_a_speed_change() {
        let (c1, c2) = (contacts(8.0), contacts(12.0));
        let mut table = FilmTable::default();
        let _ = table.step(&Regression, c1, martin(&c1), (6.0, 7.0), true);
        let lambda = 6.5;
        let model = model_sum(&c2, lambda);
        let stale = table
            .step(&Regression, c2, martin(&c2), (6.0, 7.0), false)
            .sum_at(lambda)
            .total_m;
        // Regression films scale as u^0.69 (Dowson–Toyoda) against κ = 0.7: 0.4 % off after a
        // 50 % speed change.
        assert!((stale / model - 1.0).abs() < 0.01, "{stale} vs {model}");
        assert!(
            (stale / model - 1.0).abs() > 1.0e-4,
            "κ is not the model's exponent"
        );
        let mut renewed = 0.0;
        // 17 loaded nodes, each renewed for both contacts on two of every four steps.
        for _ in 0..70 {
            renewed = table
                .step(&Regression, c2, martin(&c2), (6.0, 7.0), false)
                .sum_at(lambda)
                .total_m;
        }
        assert!(
            (renewed / model - 1.0).abs() < 2.0e-5,
            "{renewed} vs {model}"
        );
    }
}
