//! The point-contact film models of the core against independent references (the generated
//! weights against the committed model file: `cargo xtask generate --check`): the f32 Hertz ellipticity and Hamrock–Dowson
//! films against the host's f64 formulas (`bearing_ehl::point`); the f32 and integer networks
//! against the solver's Richardson films on the dataset's held-out test rows (the training
//! split); the domain guard against the host's `PointDomain::check`; hostile inputs.

use std::path::PathBuf;

use bearing_core::film::ann::point::{prepare, served_loads};
use bearing_core::film::ann::{PointAnnF32, PointAnnInt};
use bearing_core::film::point::hertz::ellipse_shape;
use bearing_core::film::point::{groups, HamrockDowson};
use bearing_core::film::{FilmModel, FilmSource, PointContactInput};
use bearing_ehl::point::formulas::{hamrock_dowson_central_film_m, hamrock_dowson_min_film_m};
use bearing_ehl::point::hertz::{elliptic_integrals, ellipticity_of_radius_ratio};
use bearing_ehl::point::PointContactCase;
use bearing_train::ann::metrics::Metrics;
use bearing_train::ann::model::ModelFile;
use bearing_train::ann::pipeline::{load_contact_samples, split_samples};
use bearing_train::ann::train::Samples;
use bearing_train::dataset::domain::Interval;
use bearing_train::dataset::point_domain::PointDomain;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

const POINT_MODEL: &str = "data/ann/point_numerical_model.json";
const POINT_DATA: &str = "data/ann/point_numerical_dataset.jsonl";

fn model() -> ModelFile<PointDomain> {
    ModelFile::load(&root().join(POINT_MODEL)).unwrap()
}

fn all_samples() -> Samples<PointContactCase> {
    load_contact_samples::<PointContactCase>(&root().join(POINT_DATA))
        .unwrap()
        .1
}

/// The held-out test rows of the training split (`bearing train`'s seed).
fn test_set(m: &ModelFile<PointDomain>) -> Samples<PointContactCase> {
    split_samples(&all_samples(), m.trained.options.seed).2
}

fn to_core(c: &PointContactCase) -> PointContactInput {
    PointContactInput {
        load_n: c.load_n as f32,
        entrainment_speed_m_s: c.entrainment_speed_m_s as f32,
        radius_x_m: c.radius_x_m as f32,
        radius_y_m: c.radius_y_m as f32,
        reduced_modulus_pa: c.reduced_modulus_pa as f32,
        pressure_viscosity_pa_inv: c.pressure_viscosity_pa_inv as f32,
        viscosity_pa_s: c.viscosity_pa_s as f32,
    }
}

/// The host case of a core input, from the same f32 values (so the references see exactly
/// the inputs the core sees).
fn to_host(c: &PointContactInput) -> PointContactCase {
    PointContactCase {
        load_n: f64::from(c.load_n),
        entrainment_speed_m_s: f64::from(c.entrainment_speed_m_s),
        radius_x_m: f64::from(c.radius_x_m),
        radius_y_m: f64::from(c.radius_y_m),
        reduced_modulus_pa: f64::from(c.reduced_modulus_pa),
        pressure_viscosity_pa_inv: f64::from(c.pressure_viscosity_pa_inv),
        viscosity_pa_s: f64::from(c.viscosity_pa_s),
    }
}

fn core_films<M: FilmModel<PointContactInput>>(
    m: &M,
    s: &Samples<PointContactCase>,
) -> Vec<(f64, f64)> {
    s.cases
        .iter()
        .map(|c| {
            let f = m.film(&to_core(c));
            (f64::from(f.central_m), f64::from(f.minimum_m))
        })
        .collect()
}

/// SplitMix64 (Steele, Lea & Flood 2014) as uniform numbers in [0, 1).
fn uniforms(seed: u64) -> impl FnMut() -> f64 {
    let mut state = seed;
    move || {
        state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        (z >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// Contacts log-uniform over a box wider than the training domain by `spread` decades on
/// each side (E' linear over 150–300 GPa), R_y/R_x over 1 … `max_ratio`.
fn random_contacts(seed: u64, n: usize, spread: f64, max_ratio: f64) -> Vec<PointContactInput> {
    let mut u = uniforms(seed);
    let mut log_between = |lo: f64, hi: f64| {
        let (a, b) = (lo.log10() - spread, hi.log10() + spread);
        10f64.powf(a + (b - a) * u())
    };
    (0..n)
        .map(|_| {
            let rx = log_between(1e-3, 1e-2);
            let c = PointContactInput {
                load_n: log_between(5.0, 2000.0) as f32,
                entrainment_speed_m_s: log_between(0.5, 30.0) as f32,
                radius_x_m: rx as f32,
                radius_y_m: 0.0,
                reduced_modulus_pa: 0.0,
                pressure_viscosity_pa_inv: log_between(1e-8, 3e-8) as f32,
                viscosity_pa_s: log_between(5e-4, 0.1) as f32,
            };
            (c, rx)
        })
        .collect::<Vec<_>>()
        .into_iter()
        .map(|(mut c, rx)| {
            c.radius_y_m = (rx * max_ratio.powf(u())) as f32;
            c.reduced_modulus_pa = (150e9 + 150e9 * u()) as f32;
            c
        })
        .collect()
}

/// The core's f32 ellipticity and second elliptic integral against the host's bisection on
/// the exact relation and its AGM (f64), R_y/R_x from 1 to 100: within 2·10⁻⁶ relative.
#[test]
fn ellipticity_matches_the_host() {
    let mut worst = (0.0f64, 0.0f64);
    for i in 0..=2000 {
        let ratio = 100f64.powf(f64::from(i) / 2000.0);
        let core = ellipse_shape((ratio.ln()) as f32);
        let k = ellipticity_of_radius_ratio(ratio);
        let (_, e) = elliptic_integrals(1.0 - 1.0 / (k * k));
        let dk = (f64::from(core.ellipticity) / k - 1.0).abs();
        let de = (f64::from(core.second_integral) / e - 1.0).abs();
        worst = (worst.0.max(dk), worst.1.max(de));
    }
    assert!(worst.0 <= 2e-6 && worst.1 <= 2e-6, "worst k, E: {worst:?}");
}

/// The core's Hamrock–Dowson films (f32, in logarithms) against the host's f64 formulas, and
/// its Hertz pressure, M and L against the host's case, on every dataset row and 20 000
/// contacts over a box a decade wider than the training domain (R_y/R_x up to 40): every
/// film within 10⁻⁵ relative, p_h, M and L within 10⁻⁵.
#[test]
fn hamrock_dowson_matches_the_host_formulas() {
    let mut contacts: Vec<PointContactInput> = all_samples().cases.iter().map(to_core).collect();
    contacts.extend(random_contacts(7, 20_000, 1.0, 40.0));
    let mut worst = [0.0f64; 5];
    for c in &contacts {
        let host = to_host(c);
        let f = HamrockDowson.film(c);
        assert_eq!(f.source, FilmSource::Regression);
        let g = groups(c);
        let rel = |core: f32, host: f64| (f64::from(core) / host - 1.0).abs();
        let errs = [
            rel(f.central_m, hamrock_dowson_central_film_m(&host)),
            rel(f.minimum_m, hamrock_dowson_min_film_m(&host)),
            rel(g.ln_hertz_pressure.exp(), host.hertz().max_pressure_pa),
            rel(g.ln_moes_m.exp(), host.moes_m()),
            rel(g.ln_moes_l.exp(), host.moes_l()),
        ];
        for (w, e) in worst.iter_mut().zip(errs) {
            *w = w.max(e);
        }
    }
    assert!(
        worst.iter().all(|w| *w <= 1e-5),
        "h_c, h_min, p_h, M, L: {worst:?}"
    );
}

/// The accuracy targets, core f32 and int16 networks against the solver's Richardson
/// films on the held-out test rows: R² ≥ 0.9995, median ≤ 0.5 %, p99 ≤ 2 % for h_c and h_min;
/// every test row served by the network.
#[test]
fn core_point_networks_meet_the_targets() {
    let m = model();
    let te = test_set(&m);
    assert!(te.cases.len() >= 100, "{} test rows", te.cases.len());
    for c in &te.cases {
        assert_eq!(
            PointAnnInt.film(&to_core(c)).source,
            FilmSource::NetworkInt,
            "{c:?}"
        );
        assert_eq!(
            PointAnnF32.film(&to_core(c)).source,
            FilmSource::NetworkF32,
            "{c:?}"
        );
    }
    for (name, films) in [
        ("f32", core_films(&PointAnnF32, &te)),
        ("int16", core_films(&PointAnnInt, &te)),
    ] {
        let e = Metrics::of(&films, &te.films);
        eprintln!("{name}: {:?}\n{name}: {:?}", e.central, e.minimum);
        for f in [&e.central, &e.minimum] {
            assert!(
                f.r2 >= 0.9995 && f.median_pct <= 0.5 && f.p99_pct <= 2.0,
                "{name}: {f:?}"
            );
        }
    }
}

/// The int16 network within 0.2 % of the f32 one on every test row, and the f32 network
/// within 0.01 % of the host's f64 network (same weights, f32 features and fixed-cost
/// ln/exp/tanh).
#[test]
fn int_within_bounds_of_f32_and_f32_of_host() {
    let m = model();
    let te = test_set(&m);
    let ints = core_films(&PointAnnInt, &te);
    let f32s = core_films(&PointAnnF32, &te);
    let d = Metrics::of(&ints, &f32s);
    eprintln!("int16 vs f32: {:?}\n{:?}", d.central, d.minimum);
    assert!(
        d.central.max_pct <= 0.2 && d.minimum.max_pct <= 0.2,
        "{d:?}"
    );
    let host: Vec<(f64, f64)> = te.cases.iter().map(|c| m.trained.predict(c)).collect();
    let h = Metrics::of(&f32s, &host);
    assert!(
        h.central.max_pct <= 1e-2 && h.minimum.max_pct <= 1e-2,
        "{h:?}"
    );
}

/// The domain scaled inward (`by` > 0) or outward (< 0) by a relative margin.
fn scaled(d: &PointDomain, by: f64) -> PointDomain {
    let s = |i: Interval| Interval {
        min: i.min * (1.0 + by),
        max: i.max * (1.0 - by),
        log: i.log,
    };
    PointDomain {
        load_n: s(d.load_n),
        entrainment_speed_m_s: s(d.entrainment_speed_m_s),
        radius_x_m: s(d.radius_x_m),
        radius_ratio: s(d.radius_ratio),
        reduced_modulus_pa: s(d.reduced_modulus_pa),
        pressure_viscosity_pa_inv: s(d.pressure_viscosity_pa_inv),
        viscosity_pa_s: s(d.viscosity_pa_s),
        hertz_pressure_pa: s(d.hertz_pressure_pa),
        moes_m: s(d.moes_m),
        m_per_ellipticity: d.m_per_ellipticity * (1.0 - by),
        elongated_from_ellipticity: d.elongated_from_ellipticity * (1.0 + by),
        elongated_m_per_ellipticity: d.elongated_m_per_ellipticity * (1.0 - by),
        moes_l: s(d.moes_l),
    }
}

/// The guard against the host's domain check (the model file's domain), on 20 000 contacts
/// near the dataset's rows (each field scaled by 10^±0.2) and 20 000 over a wider box: a contact inside the domain shrunk by 10⁻⁴ is served by the network,
/// one outside the domain grown by 10⁻⁴ falls back to Hamrock–Dowson — bit for bit its films.
/// The served interval of loads agrees with the guard the same way. Both sides are exercised.
#[test]
fn guard_follows_the_host_domain() {
    let m = model();
    let inner = scaled(&m.domain, 1e-4);
    let outer = scaled(&m.domain, -1e-4);
    let (mut served, mut fell_back) = (0, 0);
    let mut contacts = random_contacts(11, 20_000, 0.3, 25.0);
    let rows = all_samples().cases;
    let mut u = uniforms(13);
    for i in 0..20_000 {
        let mut c = to_core(&rows[i % rows.len()]);
        for k in 0..7 {
            *field(&mut c, k) *= 10f64.powf(0.4 * u() - 0.2) as f32;
        }
        contacts.push(c);
    }
    for c in contacts {
        let host = to_host(&c);
        let net = PointAnnInt.film(&c);
        let f = PointAnnF32.film(&c);
        let hd = HamrockDowson.film(&c);
        let ln_load = f64::from(c.load_n).ln() as f32;
        let interval = served_loads(&c, FilmSource::NetworkInt);
        if inner.check(&host).is_ok() {
            assert_eq!(net.source, FilmSource::NetworkInt, "{c:?}");
            assert_eq!(f.source, FilmSource::NetworkF32, "{c:?}");
            assert!(
                interval.ln_load_min <= ln_load + 1e-4 && ln_load - 1e-4 <= interval.ln_load_max,
                "{c:?}: {interval:?}"
            );
            served += 1;
        }
        if outer.check(&host).is_err() {
            for film in [net, f] {
                assert_eq!(film.source, FilmSource::Fallback, "{c:?}");
                assert_eq!(film.central_m.to_bits(), hd.central_m.to_bits(), "{c:?}");
                assert_eq!(film.minimum_m.to_bits(), hd.minimum_m.to_bits(), "{c:?}");
            }
            let clearly_out =
                ln_load < interval.ln_load_min - 1e-4 || ln_load > interval.ln_load_max + 1e-4;
            let other_out = interval.ln_load_min > interval.ln_load_max;
            assert!(
                clearly_out || other_out || !prepare(&c).in_domain,
                "{c:?}: {interval:?}"
            );
            fell_back += 1;
        }
    }
    assert!(
        served > 1000 && fell_back > 1000,
        "{served} served, {fell_back} fell back"
    );
}

/// Field `k` of a contact, in the struct's order.
fn field(c: &mut PointContactInput, k: usize) -> &mut f32 {
    match k {
        0 => &mut c.load_n,
        1 => &mut c.entrainment_speed_m_s,
        2 => &mut c.radius_x_m,
        3 => &mut c.radius_y_m,
        4 => &mut c.reduced_modulus_pa,
        5 => &mut c.pressure_viscosity_pa_inv,
        _ => &mut c.viscosity_pa_s,
    }
}

/// Hostile inputs: zero, negative, NaN, ±∞, subnormal and huge values in every field, and
/// random bit patterns in all fields: finite, non-negative films; invalid input (a field not
/// finite and > 0) gives zero films flagged `Fallback`.
#[test]
fn hostile_inputs_are_total() {
    let base = to_core(&all_samples().cases[0]);
    let mut contacts = Vec::new();
    let bad = [0.0, -0.0, -1.0, f32::NAN, f32::INFINITY, f32::NEG_INFINITY];
    let odd = [f32::from_bits(1), f32::MIN_POSITIVE, 1e-30, 1e30, f32::MAX];
    for v in bad.iter().chain(&odd) {
        for k in 0..7 {
            let mut c = base;
            *field(&mut c, k) = *v;
            contacts.push((c, bad.iter().any(|b| b.to_bits() == v.to_bits())));
        }
    }
    let mut u = uniforms(3);
    for _ in 0..20_000 {
        let mut c = base;
        let mut invalid = false;
        for k in 0..7 {
            let v = f32::from_bits((u() * 4_294_967_296.0) as u32);
            invalid |= !(v > 0.0 && v.is_finite());
            *field(&mut c, k) = v;
        }
        contacts.push((c, invalid));
    }
    for (c, invalid) in contacts {
        for f in [
            PointAnnF32.film(&c),
            PointAnnInt.film(&c),
            HamrockDowson.film(&c),
        ] {
            for h in [f.central_m, f.minimum_m] {
                assert!(h.is_finite() && h >= 0.0, "{c:?}: {f:?}");
            }
            if invalid {
                assert_eq!(
                    (f.central_m, f.minimum_m, f.source),
                    (0.0, 0.0, FilmSource::Fallback),
                    "{c:?}"
                );
            }
        }
    }
}
