//! The neural film model in the core: a small MLP trained on numerical EHL solutions
//! (docs/physics.md §5.3), in f32 ([`AnnF32`]) and in integers ([`AnnInt`]), both behind
//! [`FilmModel`].
//!
//! Per contact, at a fixed cost:
//! 1. logarithms of the seven inputs (fixed-cost `math::series::ln_atanh`) → `ln W, ln U, ln G`;
//! 2. the domain guard: every input finite and > 0, inside the training box, Hertz pressure
//!    inside its window (`2 ln p_h = ln w + ln E' − ln 2π − ln R`), and the piezoviscous–elastic
//!    regime test of `bearing_train::dataset::domain` as linear inequalities in `ln M, ln L`;
//! 3. the regression films (Dowson–Toyoda / Dowson–Higginson) in logarithms;
//! 4. the network on the normalised features (always evaluated, so the cost never depends on
//!    the guard), giving `ln(h/h_regression)` or `ln(h/R)`;
//! 5. the film `h = exp(…)` from the network inside the domain, from the regression outside it
//!    (flagged [`FilmSource::Fallback`]), zero for non-physical input (also `Fallback`). The
//!    fallback is the [`Regression`](crate::film::Regression) model's complete film: the
//!    regression blended root-sum-square with Martin's rigid iso-viscous film, so that it holds
//!    down to vanishing loads; the network itself is trained on complete numerical films.
//!
//! The weights are generated from the committed model file into
//! `core/src/generated/model_weights.rs` (`cargo xtask generate`; `--check` in CI compares byte
//! for byte). The tanh table of the integer layers is generated once, into
//! `core/src/generated/tanh_table.rs`, and both networks (line and point contact) refer to it.

#[cfg(target_arch = "x86_64")]
mod exact_f64;
#[cfg(target_arch = "x86_64")]
mod exact_lut;
// The layers, the integer arithmetic and the generated weights are public for the host's
// quantisation, code generation and their tests (`bearing-train`, `tests/`), not for
// integrators: hidden from the documentation. An integrator uses `AnnInt` / `AnnF32` through
// `FilmModel`, or `FilmKind` when building a bearing.
#[doc(hidden)]
#[path = "f32.rs"]
pub mod float;
#[doc(hidden)]
pub mod int;
mod regression;

pub mod point;
// Generated, with the core's other generated files, into `core/src/generated/` (its README).
#[doc(hidden)]
#[rustfmt::skip]
#[allow(clippy::excessive_precision, clippy::unreadable_literal)]
#[path = "../../generated/model_weights.rs"]
pub mod model_weights;
#[doc(hidden)]
#[rustfmt::skip]
#[allow(clippy::excessive_precision, clippy::unreadable_literal)]
#[path = "../../generated/point_model_weights.rs"]
pub mod point_model_weights;
#[doc(hidden)]
#[rustfmt::skip]
#[path = "../../generated/tanh_table.rs"]
pub mod tanh_table;

pub use point::{PointAnnF32, PointAnnInt};

use super::{ContactInput, Film, FilmModel, FilmSource, ServedLoads};
use model_weights as model;

/// The network's input set (`bearing_train::ann::features`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum InputSet {
    /// (ln W, ln U, ln G).
    Wug,
    /// (ln W, ln U, ln G, ln η₀, E' in GPa).
    WugEtaModulus,
}

/// The network's output form.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TargetForm {
    /// `ln(h_c/h_DT)`, `ln(h_min/h_DH)`.
    LogRatio,
    /// `ln(h_c/R)`, `ln(h_min/R)`.
    LogHr,
}

/// The training domain as the guard checks it (bounds already widened by a 10⁻⁵ relative
/// slack so the domain's own edges are inside).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DomainLimits {
    /// `[min, max]` of Q, u_m, R, E', α, η₀, l (SI units), in that order.
    pub inputs: [[f32; 2]; 7],
    /// `[ln p_min, ln p_max]` of the Hertz pressure (Pa).
    pub ln_hertz_pressure: [f32; 2],
    /// Minimum of `ln(H_EP / max(H_RI, H_EI))`.
    pub piezo_min_log_ratio: f32,
    /// Maximum of `ln(H_EP / H_RP)`.
    pub elastic_max_log_ratio: f32,
}

#[doc(hidden)]
/// What the guard and the feature stage hand to the network and to the output stage.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Prepared {
    /// Normalised network inputs.
    pub features: [f32; model::N_IN],
    /// All inputs finite and > 0.
    pub valid: bool,
    /// Inside the training domain.
    pub in_domain: bool,
    /// `ln R`.
    pub ln_radius: f32,
    /// `ln(h_DT/R)`, `ln(h_DH/R)`.
    pub ln_regression_over_r: [f32; 2],
    /// `ln(h₀/R)` of Martin's rigid iso-viscous film, `ln(4.896U/W)` (central and minimum).
    pub ln_martin_over_r: f32,
}

const LN_2: f32 = core::f32::consts::LN_2;
const LN_2PI: f32 = 1.837_877;
const LN_3: f32 = 1.098_612_3;
const LN_2_621: f32 = 0.963_555_9;
const LN_1_287: f32 = 0.252_313_93;
const LN_1_311: f32 = 0.270_790_2;
/// ln 4.896, Martin's constant (`film::hydrodynamic`).
const LN_4_896: f32 = 1.588_329_6;

/// `lo ≤ v ≤ hi` for `0 < lo ≤ hi` finite, on the bit patterns: positive floats order like
/// their bits read as unsigned integers, and every negative number, NaN and ∞ lies above
/// `hi`'s pattern. One unsigned range test instead of two float comparisons (a quarter of
/// their cost on the M4, where each float compare moves its flags to the core).
#[inline(always)]
pub(crate) fn in_positive_range(v: f32, lo: f32, hi: f32) -> bool {
    v.to_bits().wrapping_sub(lo.to_bits()) <= hi.to_bits().wrapping_sub(lo.to_bits())
}

#[doc(hidden)]
/// Steps 1–3 of the module doc.
pub fn prepare(c: &ContactInput) -> Prepared {
    let raw = [
        c.load_n,
        c.entrainment_speed_m_s,
        c.reduced_radius_m,
        c.reduced_modulus_pa,
        c.pressure_viscosity_pa_inv,
        c.viscosity_pa_s,
        c.length_m,
    ];
    let mut valid = true;
    let mut inside = true;
    for (v, [lo, hi]) in raw.iter().zip(model::DOMAIN.inputs) {
        valid &= in_positive_range(*v, f32::from_bits(1), f32::MAX);
        inside &= in_positive_range(*v, lo, hi);
    }
    let [ln_q, ln_u_m, ln_r, ln_e, ln_alpha, ln_eta, ln_l] = raw.map(crate::math::series::ln_atanh);
    let ln_w = ln_q - ln_l - ln_e - ln_r;
    let ln_u = ln_eta + ln_u_m - ln_e - ln_r;
    let ln_g = ln_alpha + ln_e;
    // Hertz window on 2 ln p_h = ln(Q/l) + ln E' − ln 2π − ln R.
    let two_ln_ph = ln_q - ln_l + ln_e - LN_2PI - ln_r;
    let [ln_pmin, ln_pmax] = model::DOMAIN.ln_hertz_pressure;
    inside &= (two_ln_ph >= 2.0 * ln_pmin) & (two_ln_ph <= 2.0 * ln_pmax);
    // Regime (Moes asymptotes in logarithms, M = W(2U)^−1/2, L = G(2U)^1/4).
    let ln_m = ln_w - 0.5 * (LN_2 + ln_u);
    let ln_l_moes = ln_g + 0.25 * (LN_2 + ln_u);
    let ln_h_ri = LN_3 - ln_m;
    let ln_h_ei = LN_2_621 - 0.2 * ln_m;
    let ln_h_rp = LN_1_287 + (2.0 / 3.0) * ln_l_moes;
    let ln_h_ep = LN_1_311 - 0.125 * ln_m + 0.75 * ln_l_moes;
    let ln_iso = if ln_h_ri > ln_h_ei { ln_h_ri } else { ln_h_ei };
    inside &= ln_h_ep - ln_iso >= model::DOMAIN.piezo_min_log_ratio;
    inside &= ln_h_ep - ln_h_rp <= model::DOMAIN.elastic_max_log_ratio;

    let all = [ln_w, ln_u, ln_g, ln_eta, c.reduced_modulus_pa * 1e-9];
    let selected = model::select_features(&all);
    let mut features = [0.0; model::N_IN];
    for ((x, f), (lo, scale)) in features
        .iter_mut()
        .zip(selected)
        .zip(model::INPUT_MIN.iter().zip(model::INPUT_SCALE))
    {
        *x = (f - lo) * scale - 1.0;
    }
    Prepared {
        features,
        valid,
        in_domain: valid & inside,
        ln_radius: ln_r,
        ln_regression_over_r: [
            regression::ln_central_over_r(ln_w, ln_u, ln_g),
            regression::ln_minimum_over_r(ln_w, ln_u, ln_g),
        ],
        ln_martin_over_r: LN_4_896 + ln_u - ln_w,
    }
}

#[doc(hidden)]
/// Step 5: the film from the normalised network output `y` (either path) or the fallback.
/// Both are always computed: the work must not depend on the guard.
pub fn finish(p: &Prepared, y: [f32; 2], source: FilmSource) -> Film {
    finish_with_fallback(p, y, fallback_films(p), source)
}

/// The fallback films of step 5: the regression film blended with the rigid-isoviscous (Martin)
/// one. They do not depend on the network, so the host's [`AnnInt`] computes them before it,
/// where they run while the network's latency-bound chain waits instead of after it.
#[inline(always)]
fn fallback_films(p: &Prepared) -> [f32; 2] {
    let mut films = [0.0f32; 2];
    // Martin's gap is the central and the minimum film alike: one exponential for both.
    let hydro = crate::math::series::exp_taylor(p.ln_radius + p.ln_martin_over_r);
    for (k, h) in films.iter_mut().enumerate() {
        let reg = p.ln_regression_over_r.get(k).copied().unwrap_or(0.0);
        let ehl = crate::math::series::exp_taylor(p.ln_radius + reg);
        *h = crate::math::sqrt(ehl * ehl + hydro * hydro);
    }
    films
}

/// Step 5 with the fallback films of [`fallback_films`] already computed: the network film,
/// or the fallback outside the domain; 0 for invalid input or a non-finite value.
#[inline(always)]
fn finish_with_fallback(p: &Prepared, y: [f32; 2], fallback: [f32; 2], source: FilmSource) -> Film {
    let mut films = [0.0f32; 2];
    for (k, ((h, yk), fallback)) in films.iter_mut().zip(y).zip(fallback).enumerate() {
        let lo = model::OUTPUT_MIN.get(k).copied().unwrap_or(0.0);
        let half = model::OUTPUT_HALF_RANGE.get(k).copied().unwrap_or(0.0);
        let reg = p.ln_regression_over_r.get(k).copied().unwrap_or(0.0);
        let t = lo + (yk + 1.0) * half;
        let ln_net = match model::TARGET {
            TargetForm::LogRatio => p.ln_radius + reg + t,
            TargetForm::LogHr => p.ln_radius + t,
        };
        let network = crate::math::series::exp_taylor(ln_net);
        let value = crate::math::select(p.in_domain, network, fallback);
        *h = if p.valid & (0.0..=f32::MAX).contains(&value) {
            value
        } else {
            0.0
        };
    }
    Film {
        central_m: films[0],
        minimum_m: films[1],
        source: if p.in_domain {
            source
        } else {
            FilmSource::Fallback
        },
    }
}

#[doc(hidden)]
/// The loads at which the network serves contacts like `c` (its load ignored): every test of
/// the guard in [`prepare`] is a bound on ln Q once the other inputs are fixed — the load box,
/// the Hertz window (2 ln p_h rises with ln Q) and the three regime inequalities (each linear in
/// ln M = ln Q − ln(l E' R) − ½ ln 2U). An empty interval when another input is outside its box.
pub fn served_loads(c: &ContactInput, source: FilmSource) -> ServedLoads {
    let others = [
        c.entrainment_speed_m_s,
        c.reduced_radius_m,
        c.reduced_modulus_pa,
        c.pressure_viscosity_pa_inv,
        c.viscosity_pa_s,
        c.length_m,
    ];
    let mut inside = true;
    for (v, [lo, hi]) in others.iter().zip(model::DOMAIN.inputs.iter().skip(1)) {
        inside &= (*v > 0.0) & (*v <= f32::MAX) & (*v >= *lo) & (*v <= *hi);
    }
    let [ln_u_m, ln_r, ln_e, ln_alpha, ln_eta, ln_l] = others.map(crate::math::series::ln_atanh);
    let ln_u = ln_eta + ln_u_m - ln_e - ln_r;
    let ln_g = ln_alpha + ln_e;
    let ln_l_moes = ln_g + 0.25 * (LN_2 + ln_u);
    // ln Q = ln M + ln(l E' R) + ½(ln 2 + ln U).
    let ln_q_of_m = ln_l + ln_e + ln_r + 0.5 * (LN_2 + ln_u);
    let [q_min, q_max] = model::DOMAIN.inputs.first().copied().unwrap_or([1.0, 0.0]);
    let [ln_pmin, ln_pmax] = model::DOMAIN.ln_hertz_pressure;
    // 2 ln p_h = ln Q − ln l + ln E' − ln 2π − ln R.
    let hertz_offset = ln_l - ln_e + LN_2PI + ln_r;
    let piezo = model::DOMAIN.piezo_min_log_ratio;
    let elastic = model::DOMAIN.elastic_max_log_ratio;
    // ln H_EP − ln H_RI = c₁ + 0.875 ln M ≥ piezo; ln H_EP − ln H_EI = c₂ + 0.075 ln M ≥ piezo;
    // ln H_EP − ln H_RP = c₃ − 0.125 ln M ≤ elastic.
    let c1 = LN_1_311 + 0.75 * ln_l_moes - LN_3;
    let c2 = LN_1_311 + 0.75 * ln_l_moes - LN_2_621;
    let c3 = LN_1_311 - LN_1_287 + (0.75 - 2.0 / 3.0) * ln_l_moes;
    let ln_m_min = crate::math::max(
        crate::math::max((piezo - c1) / 0.875, (piezo - c2) / 0.075),
        (c3 - elastic) / 0.125,
    );
    let lo = crate::math::max(
        crate::math::max(
            crate::math::series::ln_atanh(q_min),
            2.0 * ln_pmin + hertz_offset,
        ),
        ln_m_min + ln_q_of_m,
    );
    let hi = crate::math::min(
        crate::math::series::ln_atanh(q_max),
        2.0 * ln_pmax + hertz_offset,
    );
    ServedLoads {
        ln_load_min: if inside { lo } else { f32::MAX },
        ln_load_max: if inside { hi } else { f32::MIN },
        source,
    }
}

/// The f32 network.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct AnnF32;

/// The integer network.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct AnnInt;

impl AnnF32 {
    /// Normalised network output for prepared features (exposed for tests and benches).
    #[inline]
    pub fn network(features: &[f32; model::N_IN]) -> [f32; 2] {
        model::forward_f32(features)
    }
}

impl AnnInt {
    /// Normalised network output for prepared features: quantise, integer network, dequantise.
    #[inline]
    pub fn network(features: &[f32; model::N_IN]) -> [f32; 2] {
        let q = features.map(int::quantise_input);
        model::forward_int(&q).map(|v| f32::from(v) * model::INT_OUTPUT_STEP)
    }
}

impl FilmModel for AnnF32 {
    fn name(&self) -> &'static str {
        "ann_f32"
    }

    fn film(&self, contact: &ContactInput) -> Film {
        let p = prepare(contact);
        finish(&p, Self::network(&p.features), FilmSource::NetworkF32)
    }

    fn served_loads(&self, template: &ContactInput) -> ServedLoads {
        served_loads(template, FilmSource::NetworkF32)
    }
}

impl FilmModel for AnnInt {
    fn name(&self) -> &'static str {
        "ann_int"
    }

    fn film(&self, contact: &ContactInput) -> Film {
        let p = prepare(contact);
        #[cfg(target_arch = "x86_64")]
        {
            let fallback = fallback_films(&p);
            finish_with_fallback(
                &p,
                Self::network(&p.features),
                fallback,
                FilmSource::NetworkInt,
            )
        }
        #[cfg(not(target_arch = "x86_64"))]
        finish(&p, Self::network(&p.features), FilmSource::NetworkInt)
    }

    fn served_loads(&self, template: &ContactInput) -> ServedLoads {
        served_loads(template, FilmSource::NetworkInt)
    }
}

#[cfg(test)]
mod served_tests {
    use super::*;
    use proptest::prelude::*;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(3000))]

        /// The served interval and the guard agree on every load (away from the interval's
        /// edges, where f32 rounding of the two formulations may differ).
        #[test]
        fn served_interval_matches_the_guard(
            ln_q in 3.0f32..9.5, u in 0.5f32..32.0, r_mm in 0.08f32..22.0, e_gpa in 195.0f32..255.0,
            alpha in 9.0f32..31.0, ln_eta in -7.7f32..-2.2, l_mm in 0.9f32..52.0,
        ) {
            let c = ContactInput {
                load_n: libm::expf(ln_q),
                length_m: l_mm * 1e-3,
                entrainment_speed_m_s: u,
                reduced_radius_m: r_mm * 1e-3,
                reduced_modulus_pa: e_gpa * 1e9,
                pressure_viscosity_pa_inv: alpha * 1e-9,
                viscosity_pa_s: libm::expf(ln_eta),
            };
            let served = served_loads(&c, FilmSource::NetworkInt);
            let ln_load = crate::math::series::ln_atanh(c.load_n);
            let margin = 1.0e-3;
            let clearly_in = ln_load > served.ln_load_min + margin && ln_load < served.ln_load_max - margin;
            let clearly_out = ln_load < served.ln_load_min - margin || ln_load > served.ln_load_max + margin;
            let guard = prepare(&c).in_domain;
            if clearly_in {
                prop_assert!(guard, "{c:?} inside [{}, {}] but refused", served.ln_load_min, served.ln_load_max);
            }
            if clearly_out {
                prop_assert!(!guard, "{c:?} outside [{}, {}] but served", served.ln_load_min, served.ln_load_max);
            }
        }
    }
}

#[cfg(test)]
mod range_tests {
    use super::*;

    /// The bit-pattern range test agrees with the float comparisons for every kind of value,
    /// on every input box of the compiled model (whose lower limits it needs positive).
    #[test]
    fn bit_range_test_matches_float_comparisons() {
        let mut boxes = model::DOMAIN.inputs.to_vec();
        boxes.push([f32::from_bits(1), f32::MAX]);
        for [lo, hi] in boxes {
            assert!(lo > 0.0 && lo <= hi && hi.is_finite());
            let probes = [
                lo,
                hi,
                lo * 0.999_999,
                hi * 1.000_001,
                0.5 * (lo + hi),
                0.0,
                -0.0,
                -lo,
                -hi,
                f32::NAN,
                -f32::NAN,
                f32::INFINITY,
                f32::NEG_INFINITY,
                f32::MIN_POSITIVE,
                f32::from_bits(1),
                f32::MAX,
            ];
            for v in probes {
                assert_eq!(
                    in_positive_range(v, lo, hi),
                    v >= lo && v <= hi,
                    "{v} in [{lo}, {hi}]"
                );
            }
        }
    }
}

#[cfg(test)]
mod host_path_tests {
    use super::*;

    /// The host's `AnnInt::film` (fallback films before the network) gives the bits of the
    /// plain sequence `prepare`, network, `finish` — the reference the Cortex-M4 runs — on
    /// contacts inside and outside the domain and on hostile inputs (zero, negative, NaN, ∞ in
    /// each field): central and minimum films compared as bit patterns, and the source.
    /// Every input field of a contact.
    fn fields(c: &mut ContactInput) -> [&mut f32; 7] {
        [
            &mut c.load_n,
            &mut c.length_m,
            &mut c.entrainment_speed_m_s,
            &mut c.reduced_radius_m,
            &mut c.reduced_modulus_pa,
            &mut c.pressure_viscosity_pa_inv,
            &mut c.viscosity_pa_s,
        ]
    }

    #[test]
    fn host_film_is_the_plain_sequence() {
        let base = ContactInput {
            load_n: 850.0,
            length_m: 15e-3,
            entrainment_speed_m_s: 9.83,
            reduced_radius_m: 3.029e-3,
            reduced_modulus_pa: 239.6e9,
            pressure_viscosity_pa_inv: 2.1e-8,
            viscosity_pa_s: 0.08,
        };
        let mut contacts = std::vec![base];
        // Log-uniform factors 10^±3 on every field (SplitMix64, Steele, Lea & Flood 2014):
        // most contacts leave the domain through one bound or another.
        let mut state = 5u64;
        let mut factor = || {
            state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            z ^= z >> 31;
            libm::powf(10.0, (z >> 40) as f32 / (1u64 << 24) as f32 * 6.0 - 3.0)
        };
        for k in 0..20_000 {
            let mut c = base;
            // Near the base for the even contacts (mostly in the domain), far for the odd.
            for f in fields(&mut c) {
                let g = factor();
                *f *= if k % 2 == 0 { libm::powf(g, 0.05) } else { g };
            }
            contacts.push(c);
        }
        for hostile in [0.0, -1.0, f32::NAN, f32::INFINITY, f32::NEG_INFINITY] {
            for field in 0..7 {
                let mut c = base;
                if let Some(f) = fields(&mut c).into_iter().nth(field) {
                    *f = hostile;
                }
                contacts.push(c);
            }
        }
        let mut served = 0;
        for c in &contacts {
            let p = prepare(c);
            let want = finish(&p, AnnInt::network(&p.features), FilmSource::NetworkInt);
            let got = AnnInt.film(c);
            assert_eq!(got.central_m.to_bits(), want.central_m.to_bits(), "{c:?}");
            assert_eq!(got.minimum_m.to_bits(), want.minimum_m.to_bits(), "{c:?}");
            assert_eq!(got.source, want.source, "{c:?}");
            served += usize::from(got.source == FilmSource::NetworkInt);
        }
        // Both sides of the guard are exercised.
        assert!(served > 1000 && served < contacts.len() - 1000, "{served}");
    }
}
