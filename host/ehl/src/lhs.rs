//! Latin hypercubes: the stratified design itself ([`latin_hypercube`], over any source of
//! random draws), and the sampling of the docs/physics.md §5.3 input domain (thesis Table 5.1), kept
//! to Hertz pressures 0.3–3.5 GPa — the robustness population of the solver.
//!
//! Each of the seven inputs (Q, u_m, R, E', α, η₀, l) is split into `n` equal-probability strata
//! (uniform in the logarithm for the inputs spanning decades: Q, u_m, R, η₀, l; uniform for E'
//! and α), one point per stratum, strata permuted independently (McKay, Beckman & Conover 1979).
//! Samples whose Hertz pressure falls outside 0.3–3.5 GPa are rejected and the hypercube is
//! redrawn with the next seed offset until `n` samples are kept. The generator is a small
//! SplitMix64 so the sample set is reproducible from the seed alone.

use super::ContactCase;

/// One sampled operating point: the seven physical inputs and the contact case they make.
#[derive(Debug, Clone, Copy, serde::Serialize)]
pub struct Sample {
    pub roller_load_n: f64,
    pub entrainment_speed_m_s: f64,
    pub reduced_radius_m: f64,
    pub reduced_modulus_pa: f64,
    pub pressure_viscosity_pa_inv: f64,
    pub viscosity_pa_s: f64,
    pub contact_length_m: f64,
    pub case: ContactCase,
}

/// (min, max, log-uniform) per input, docs/physics.md §5.3 table.
const RANGES: [(f64, f64, bool); 7] = [
    (150.0, 5000.0, true), // Q, N
    (0.6, 30.0, true),     // u_m, m/s
    (0.1e-3, 20e-3, true), // R, m
    (200e9, 250e9, false), // E', Pa
    (10e-9, 30e-9, false), // α, 1/Pa
    (0.0005, 0.1, true),   // η₀, Pa·s
    (1e-3, 50e-3, true),   // l, m
];

/// Hertz-pressure window of the population, Pa.
pub const HERTZ_PRESSURE_RANGE_PA: (f64, f64) = (0.3e9, 3.5e9);

/// The random draws a Latin hypercube needs; the design is reproducible from the stream.
pub trait StratumDraws {
    /// A uniform index in `0..=i` (for the Fisher–Yates shuffle of the strata).
    fn index_at_most(&mut self, i: usize) -> usize;
    /// A uniform position in [0, 1) inside a stratum.
    fn unit(&mut self) -> f64;
}

/// A random Latin hypercube of `n` points in [0, 1)^D: in every coordinate `d`, point `i` gets
/// stratum `π_d(i)` of a random permutation (Fisher–Yates, Knuth, TAOCP vol. 2, Algorithm P),
/// at a uniform random position inside it (McKay, Beckman & Conover 1979). The draws are taken
/// coordinate by coordinate: the shuffle's, then one position per point.
pub fn latin_hypercube<const D: usize>(n: usize, draws: &mut impl StratumDraws) -> Vec<[f64; D]> {
    let mut points = vec![[0.0; D]; n];
    for d in 0..D {
        let mut strata: Vec<usize> = (0..n).collect();
        for i in (1..n).rev() {
            let j = draws.index_at_most(i);
            strata.swap(i, j);
        }
        for (p, s) in points.iter_mut().zip(strata) {
            p[d] = (s as f64 + draws.unit()) / n as f64;
        }
    }
    points
}

struct SplitMix(u64);

impl StratumDraws for SplitMix {
    fn index_at_most(&mut self, i: usize) -> usize {
        ((self.unit() * (i + 1) as f64) as usize).min(i)
    }

    fn unit(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// `n` Latin-hypercube samples of the domain with p_h in 0.3–3.5 GPa, reproducible from `seed`.
pub fn sample_domain(n: usize, seed: u64) -> Vec<Sample> {
    let mut rng = SplitMix(seed);
    let mut kept = Vec::with_capacity(n);
    while kept.len() < n {
        // One hypercube of n points per round; keep those inside the pressure window.
        for point in latin_hypercube::<7>(n, &mut rng) {
            if kept.len() == n {
                break;
            }
            let mut v = [0.0; 7];
            for ((value, t), &(lo, hi, log)) in v.iter_mut().zip(point).zip(&RANGES) {
                *value = if log {
                    (lo.ln() + t * (hi.ln() - lo.ln())).exp()
                } else {
                    lo + t * (hi - lo)
                };
            }
            let Ok(case) = ContactCase::new(v[0] / v[6], v[1], v[2], v[3], v[4], v[5]) else {
                continue;
            };
            let ph = case.hertz_pressure_pa();
            if ph < HERTZ_PRESSURE_RANGE_PA.0 || ph > HERTZ_PRESSURE_RANGE_PA.1 {
                continue;
            }
            kept.push(Sample {
                roller_load_n: v[0],
                entrainment_speed_m_s: v[1],
                reduced_radius_m: v[2],
                reduced_modulus_pa: v[3],
                pressure_viscosity_pa_inv: v[4],
                viscosity_pa_s: v[5],
                contact_length_m: v[6],
                case,
            });
        }
    }
    kept
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every sample lies in the domain and the pressure window; the set is reproducible.
    #[test]
    fn samples_in_domain_and_reproducible() {
        let a = sample_domain(64, 7);
        let b = sample_domain(64, 7);
        assert_eq!(a.len(), 64);
        for (s, t) in a.iter().zip(&b) {
            assert_eq!(s.case, t.case);
            let ph = s.case.hertz_pressure_pa();
            assert!((0.3e9..=3.5e9).contains(&ph));
            assert!((150.0..=5000.0).contains(&s.roller_load_n));
            assert!((10e-9..=30e-9).contains(&s.pressure_viscosity_pa_inv));
        }
    }
}
