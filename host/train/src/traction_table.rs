//! The generator of the core's traction table (`core/src/generated/traction_table.rs`): ln T,
//! the mean isothermal Eyring stress ratio of a line contact (docs/physics.md §8.3), integrated
//! over the numerical EHL solver's pressure and film ([`bearing_ehl::traction`]) on a grid of
//! Moes' ln M × ln L × z, z = ln N + α·p_h, quantised to i16.
//!
//! Every (ln M, ln L) node that the tricubic read of a contact of the film network's domain
//! touches is solved (generation fails if one is not); the others are solved where
//! α·p_h ≤ 150 and the solver converges, and the nodes left unsolved (outside the domain) copy
//! the nearest solved node of lower ln L in their row, or of lower ln M. The solves run in
//! parallel (rayon) and are collected in node order; each is deterministic, so the text is the
//! same on every run: `cargo xtask generate --check` compares it byte for byte with the
//! committed file. ≈ 2 min on 2 cores.

use std::fmt::Write;

use anyhow::{bail, Result};
use bearing_core::film::ann::model_weights::DOMAIN;
use bearing_core::film::ann::AnnF32;
use bearing_core::{ContactInput, FilmModel, FilmSource};
use bearing_ehl::traction::mean_stress_ratio;
use bearing_ehl::{ContactCase, SolverOptions, ViscosityLaw};
use rayon::prelude::*;

/// Where the table is generated in the core.
pub const TRACTION_TABLE_PATH: &str = "core/src/generated/traction_table.rs";

/// A regular grid: first node, step and node count.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    /// The first node.
    pub first: f64,
    /// The step between nodes.
    pub step: f64,
    /// The number of nodes.
    pub nodes: usize,
}

impl Grid {
    /// The value of node `i`.
    pub fn node(&self, i: usize) -> f64 {
        self.first + self.step * i as f64
    }
}

/// The grid of ln M.
pub const LN_M: Grid = Grid {
    first: -3.5,
    step: 0.25,
    nodes: 47,
};
/// The grid of ln L.
pub const LN_L: Grid = Grid {
    first: 0.0,
    step: 0.25,
    nodes: 22,
};
/// The grid of z = ln N + α·p_h.
pub const Z: Grid = Grid {
    first: -8.0,
    step: 2.0,
    nodes: 57,
};
/// The pressure–viscosity coefficient every node is solved with (1/Pa, the middle of the
/// network's domain). Only α·p_h and, through the density, p_h matter besides M and L.
pub const ALPHA_PA_INV: f64 = 1.732e-8;
/// The reduced modulus every node is solved with (Pa).
pub const MODULUS_PA: f64 = 2.26e11;
/// The reduced radius every node is solved with (m).
pub const RADIUS_M: f64 = 0.01;
/// Nodes outside the domain's reach are solved up to this α·p_h.
const MAX_ALPHA_PEAK: f64 = 150.0;

/// The solver options of the table and of the tests that compare the core's traction with the
/// solver's: Barus viscosity, as the core's.
pub fn barus() -> SolverOptions {
    SolverOptions {
        viscosity: ViscosityLaw::Barus,
        ..SolverOptions::default()
    }
}

/// The i-th point of the Halton sequence in base `base`, in (0, 1).
pub fn halton(mut i: u64, base: u64) -> f64 {
    let (mut f, mut r) = (1.0, 0.0);
    while i > 0 {
        f /= base as f64;
        r += f * (i % base) as f64;
        i /= base;
    }
    r
}

/// Halton points [`domain_contacts`] draws from at most.
pub const DOMAIN_CANDIDATES: u64 = 50_000;

/// Contacts spread over the line-contact network's training domain (log-uniform in each of its
/// seven inputs by a Halton sequence from index `first`): the first `count` of those the
/// network's own guard accepts among [`DOMAIN_CANDIDATES`] points.
pub fn domain_contacts(first: u64, count: usize) -> Vec<ContactInput> {
    const BASES: [u64; 7] = [2, 3, 5, 7, 11, 13, 17];
    let mut out = Vec::new();
    for i in first..first + DOMAIN_CANDIDATES {
        let v: Vec<f32> = DOMAIN
            .inputs
            .iter()
            .zip(BASES)
            .map(|(&[lo, hi], base)| {
                let (lo, hi) = (f64::from(lo) * 1.0001, f64::from(hi) * 0.9999);
                (lo.ln() + halton(i, base) * (hi / lo).ln()).exp() as f32
            })
            .collect();
        let c = ContactInput {
            load_n: v[0],
            entrainment_speed_m_s: v[1],
            reduced_radius_m: v[2],
            reduced_modulus_pa: v[3],
            pressure_viscosity_pa_inv: v[4],
            viscosity_pa_s: v[5],
            length_m: v[6],
        };
        if AnnF32.film(&c).source == FilmSource::NetworkF32 {
            out.push(c);
        }
        if out.len() == count {
            break;
        }
    }
    out
}

/// The EHL case of a contact.
pub fn case_of(c: &ContactInput) -> ContactCase {
    ContactCase::new(
        f64::from(c.load_n / c.length_m),
        f64::from(c.entrainment_speed_m_s),
        f64::from(c.reduced_radius_m),
        f64::from(c.reduced_modulus_pa),
        f64::from(c.pressure_viscosity_pa_inv),
        f64::from(c.viscosity_pa_s),
    )
    .expect("a contact the network's guard accepts is a valid EHL case")
}

/// The contact of Moes' ln M and ln L at the table's α, E′ and R: u = 10 m/s unless η₀ would
/// leave [10⁻⁴, 10³] Pa·s.
fn node_case(ln_m: f64, ln_l: f64) -> Option<ContactCase> {
    let (alpha, e, r) = (ALPHA_PA_INV, MODULUS_PA, RADIUS_M);
    let two_u = (ln_l.exp() / (alpha * e)).powi(4);
    let eta_u = 0.5 * two_u * e * r;
    let w = ln_m.exp() * two_u.sqrt() * e * r;
    let eta = (eta_u / 10.0).clamp(1.0e-4, 1.0e3);
    ContactCase::new(w, eta_u / eta, r, e, alpha, eta).ok()
}

/// ln T at the z nodes of one (ln M, ln L) node, solved at the table's α; `None` where the
/// solver refuses or fails.
pub fn node_row(ln_m: f64, ln_l: f64) -> Option<Vec<f64>> {
    let sol = bearing_ehl::solve(&node_case(ln_m, ln_l)?, &barus()).ok()?;
    let alpha_peak = ALPHA_PA_INV * sol.hertz_pressure_pa;
    Some(
        (0..Z.nodes)
            .map(|k| {
                let ln_n = Z.node(k) - alpha_peak;
                mean_stress_ratio(&sol, ViscosityLaw::Barus, ln_n).ln()
            })
            .collect(),
    )
}

/// The (ln M, ln L) nodes the tricubic interpolation reads for contacts of the network's
/// domain: the 4 × 4 nodes around the cell of every one of the first [`DOMAIN_CANDIDATES`]
/// Halton points that the guard accepts.
fn nodes_the_domain_reads() -> Vec<bool> {
    let (nm, nl) = (LN_M.nodes, LN_L.nodes);
    let mut needed = vec![false; nm * nl];
    for c in domain_contacts(1, usize::MAX) {
        let case = case_of(&c);
        let fm = ((case.moes_m().ln() - LN_M.first) / LN_M.step).clamp(1.0, (nm - 2) as f64);
        let fl = ((case.moes_l().ln() - LN_L.first) / LN_L.step).clamp(1.0, (nl - 2) as f64);
        let (i, j) = ((fm as usize).min(nm - 3), (fl as usize).min(nl - 3));
        for a in i - 1..=i + 2 {
            for b in j - 1..=j + 2 {
                needed[a * nl + b] = true;
            }
        }
    }
    needed
}

/// What a generation solved, for its progress line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Generated {
    /// (ln M, ln L) nodes solved.
    pub solved: usize,
    /// Of all nodes.
    pub nodes: usize,
    /// Nodes the network's domain reads (all solved).
    pub read_by_the_domain: usize,
    /// Unsolved nodes that copy a solved neighbour.
    pub copied: usize,
}

/// ln T at every node, index (i·L + j)·Z + k, solved as the module documentation says.
pub fn solve_table() -> Result<(Vec<f64>, Generated)> {
    let (nm, nl) = (LN_M.nodes, LN_L.nodes);
    let needed = nodes_the_domain_reads();
    let rows: Vec<Option<Vec<f64>>> = (0..nm * nl)
        .into_par_iter()
        .map(|n| {
            let (ln_m, ln_l) = (LN_M.node(n / nl), LN_L.node(n % nl));
            let alpha_peak = (ln_l + 0.5 * ln_m).exp() / (2.0 * std::f64::consts::PI).sqrt();
            (needed[n] || alpha_peak <= MAX_ALPHA_PEAK)
                .then(|| node_row(ln_m, ln_l))
                .flatten()
        })
        .collect();
    let missing: Vec<_> = (0..nm * nl)
        .filter(|&n| needed[n] && rows[n].is_none())
        .map(|n| (LN_M.node(n / nl), LN_L.node(n % nl)))
        .collect();
    if !missing.is_empty() {
        bail!("the solver failed at (ln M, ln L) nodes the network's domain reads: {missing:?}");
    }
    let mut copied = 0;
    let mut values = Vec::with_capacity(nm * nl * Z.nodes);
    for n in 0..nm * nl {
        let (i, j) = (n / nl, n % nl);
        // The node itself, else the nearest solved one of lower ln L, else of lower ln M.
        let source = std::iter::once(n)
            .chain((0..j).rev().map(|b| i * nl + b))
            .chain((0..i).rev().map(|a| a * nl + j))
            .find_map(|s| rows[s].as_ref().map(|row| (s, row)));
        let Some((s, row)) = source else {
            bail!("no solved node at or below (ln M, ln L) node ({i}, {j})");
        };
        copied += usize::from(s != n);
        values.extend_from_slice(row);
    }
    let generated = Generated {
        solved: rows.iter().filter(|r| r.is_some()).count(),
        nodes: nm * nl,
        read_by_the_domain: needed.iter().filter(|&&n| n).count(),
        copied,
    };
    Ok((values, generated))
}

/// The text of `core/src/generated/traction_table.rs`, solved afresh.
pub fn render_traction_table() -> Result<(String, Generated)> {
    let (ln_t, generated) = solve_table()?;
    Ok((render_values(&ln_t), generated))
}

/// The text of `core/src/generated/traction_table.rs` for ln T at every node, (i·L + j)·Z + k.
pub fn render_values(ln_t: &[f64]) -> String {
    let lo = ln_t.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = ln_t.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    // i16 codes −32 767 … 32 767 over [lo, hi].
    let step = (hi - lo) / 65_534.0;
    let offset = 0.5 * (lo + hi);
    let (m0, dm, nm) = (LN_M.first, LN_M.step, LN_M.nodes);
    let (l0, dl, nl) = (LN_L.first, LN_L.step, LN_L.nodes);
    let (z0, dz, nz) = (Z.first, Z.step, Z.nodes);
    let mut s = String::new();
    let _ = write!(
        s,
        "//! GENERATED from the numerical EHL solver (`bearing_train::traction_table`) — do not edit.\n\
         //! `cargo xtask generate` writes it, `cargo xtask generate --check` compares it.\n\
         //!\n\
         //! ln T, the mean isothermal Eyring stress ratio of a line contact (docs/physics.md §8.3),\n\
         //! integrated over the numerical solver's pressure and film (Barus viscosity,\n\
         //! Dowson–Higginson density; α = {ALPHA_PA_INV:e} 1/Pa, E′ = {MODULUS_PA:e} Pa,\n\
         //! R = {RADIUS_M} m) on a grid of Moes' ln M × ln L × z, z = ln N + α·p_h.\n\n\
         /// First node and step of ln M.\npub const LN_M: (f32, f32) = ({m0:?}, {dm:?});\n\
         /// Nodes of ln M.\npub const M_NODES: usize = {nm};\n\
         /// First node and step of ln L.\npub const LN_L: (f32, f32) = ({l0:?}, {dl:?});\n\
         /// Nodes of ln L.\npub const L_NODES: usize = {nl};\n\
         /// First node and step of z = ln N + α·p_h.\npub const Z: (f32, f32) = ({z0:?}, {dz:?});\n\
         /// Nodes of z.\npub const Z_NODES: usize = {nz};\n\
         /// ln T of code 0 of [`LN_MEAN_STRESS_RATIO`].\npub const LN_T_OFFSET: f32 = {:?};\n\
         /// ln T per unit of [`LN_MEAN_STRESS_RATIO`].\npub const LN_T_STEP: f32 = {:?};\n\
         /// (ln T − [`LN_T_OFFSET`])/[`LN_T_STEP`] at node (i, j, k) of (ln M, ln L, z), index\n\
         /// (i·[`L_NODES`] + j)·[`Z_NODES`] + k; one line per (i, j).\n\
         #[rustfmt::skip]\n\
         pub static LN_MEAN_STRESS_RATIO: [i16; M_NODES * L_NODES * Z_NODES] = [\n",
        offset as f32,
        step as f32
    );
    for row in ln_t.chunks(nz) {
        let codes: Vec<String> = row
            .iter()
            .map(|v| (((v - offset) / step).round() as i16).to_string())
            .collect();
        let _ = writeln!(s, "    {},", codes.join(", "));
    }
    s.push_str("];\n");
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The committed table's grid constants are the generator's, as f32.
    #[test]
    fn the_cores_grid_is_the_generators() {
        use bearing_core::friction::traction_table as t;
        let f32s = |g: Grid| (g.first as f32, g.step as f32, g.nodes);
        assert_eq!((t::LN_M.0, t::LN_M.1, t::M_NODES), f32s(LN_M));
        assert_eq!((t::LN_L.0, t::LN_L.1, t::L_NODES), f32s(LN_L));
        assert_eq!((t::Z.0, t::Z.1, t::Z_NODES), f32s(Z));
    }

    /// The codes span −32 767 … 32 767 and decode to the values within half a step.
    #[test]
    fn rendering_quantises_to_the_full_i16_range_within_half_a_step() {
        let n = LN_M.nodes * LN_L.nodes * Z.nodes;
        let values: Vec<f64> = (0..n)
            .map(|i| (i as f64 * 0.37).sin() * 3.0 - 1.0)
            .collect();
        let text = render_values(&values);
        let body = &text[text.find("] = [\n").unwrap() + 6..text.rfind("];").unwrap()];
        let codes: Vec<i16> = body
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|w| !w.is_empty())
            .map(|w| w.parse().unwrap())
            .collect();
        assert_eq!(codes.len(), n);
        assert_eq!(codes.iter().min(), Some(&-32767));
        assert_eq!(codes.iter().max(), Some(&32767));
        let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let (step, offset) = ((hi - lo) / 65_534.0, 0.5 * (lo + hi));
        for (v, c) in values.iter().zip(&codes) {
            assert!((offset + f64::from(*c) * step - v).abs() <= 0.5 * step * (1.0 + 1e-9));
        }
    }
}
