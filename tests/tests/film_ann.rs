//! The film network across crates: both compiled networks share one tanh table, the core's f32
//! and integer networks agree with the host's f64 network and integer mirror, the integer
//! network stays within the accuracy bounds of the f32 one, and the pipeline model meets the
//! accuracy targets on its held-out test set. That the generated weights and the tanh table are
//! the committed model file's and the quantiser's, byte for byte, is `cargo xtask generate
//! --check`'s job.
//!
//! The core holds the model trained on numerical EHL solutions (`data/ann/numerical_*`, Roelands +
//! Dowson–Higginson, 801 nodes; 5000 cases, all solved; see `data/ann/README.md`). The
//! pipeline model trained on the Moes stand-in (`data/ann/pipeline_moes_*`) is checked on the
//! host against its closed-form reference.

use std::path::PathBuf;

use bearing_core::film::ann::{self, AnnF32, AnnInt};
use bearing_core::film::{FilmModel, FilmSource};
use bearing_train::ann::metrics::Metrics;
use bearing_train::ann::model::ModelFile;
use bearing_train::ann::pipeline::{load_samples, predict_int, split_samples};
use bearing_train::ann::train::Samples;

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// The model compiled into the core, and its dataset.
const CORE_MODEL: &str = "data/ann/numerical_model.json";
const CORE_DATA: &str = "data/ann/numerical_dataset.jsonl";

fn model() -> ModelFile {
    ModelFile::load(&root().join(CORE_MODEL)).unwrap()
}

fn test_set_of(model: &ModelFile, data: &str) -> Samples {
    let (_, samples) = load_samples(&root().join(data)).unwrap();
    split_samples(&samples, model.trained.options.seed).2
}

fn test_set(model: &ModelFile) -> Samples {
    test_set_of(model, CORE_DATA)
}

fn core_films<M: FilmModel>(m: &M, s: &Samples) -> Vec<(f64, f64)> {
    s.cases
        .iter()
        .map(|c| {
            let f = m.film(&c.to_core());
            (f64::from(f.central_m), f64::from(f.minimum_m))
        })
        .collect()
}

/// Both compiled networks, line and point contact, use the one tanh table (the same static,
/// not a copy).
#[test]
fn both_networks_share_the_tanh_table() {
    let shared = &ann::tanh_table::TANH_LUT;
    assert!(std::ptr::eq(&ann::model_weights::LUT, shared));
    assert!(std::ptr::eq(&ann::point_model_weights::LUT, shared));
}

/// The core's f32 network (f32 features, fixed-cost ln/exp/tanh) against the host's f64
/// network: the same weights, a different arithmetic; they must agree to 1e-4 relative.
#[test]
fn core_f32_agrees_with_host_f64() {
    let m = model();
    let te = test_set(&m);
    let host: Vec<(f64, f64)> = te.cases.iter().map(|c| m.trained.predict(c)).collect();
    let core = core_films(&AnnF32, &te);
    let d = Metrics::of(&core, &host);
    assert!(
        d.central.max_pct < 1e-2 && d.minimum.max_pct < 1e-2,
        "{d:?}"
    );
}

/// The core's integer network against the host mirror (same integer kernels, f64 vs f32
/// features), and against the core f32 network within the accuracy bounds: at most 0.2 %
/// median and 1 % maximum added relative error.
#[test]
fn core_int_within_bounds_of_f32() {
    let m = model();
    let te = test_set(&m);
    let q = m.quantised.as_ref().unwrap();
    let mirror = predict_int(&m.trained, q, &te);
    let int = core_films(&AnnInt, &te);
    let f32s = core_films(&AnnF32, &te);
    let vs_mirror = Metrics::of(&int, &mirror);
    assert!(
        vs_mirror.central.median_pct < 0.01 && vs_mirror.central.max_pct < 0.2,
        "{vs_mirror:?}"
    );
    let added = Metrics::of(&int, &f32s);
    for e in [added.central, added.minimum] {
        assert!(e.median_pct <= 0.2 && e.max_pct <= 1.0, "{e:?}");
    }
}

/// The accuracy targets on the held-out numerical test set (750 cases), core models:
/// central film R² ≥ 0.9995, median ≤ 0.5 %, p99 ≤ 2 %, max ≤ 5 %; minimum film with twice
/// the error bounds; every test case served by the network, not the fallback.
#[test]
fn numerical_model_meets_accuracy_targets() {
    let m = model();
    let te = test_set(&m);
    for c in &te.cases {
        assert_eq!(
            AnnInt.film(&c.to_core()).source,
            FilmSource::NetworkInt,
            "{c:?} fell back"
        );
    }
    for films in [core_films(&AnnF32, &te), core_films(&AnnInt, &te)] {
        let e = Metrics::of(&films, &te.films);
        assert!(
            e.central.r2 >= 0.9995
                && e.central.median_pct <= 0.5
                && e.central.p99_pct <= 2.0
                && e.central.max_pct <= 5.0,
            "{:?}",
            e.central
        );
        assert!(
            e.minimum.r2 >= 0.9995
                && e.minimum.median_pct <= 1.0
                && e.minimum.p99_pct <= 4.0
                && e.minimum.max_pct <= 10.0,
            "{:?}",
            e.minimum
        );
    }
}

/// The pipeline model (Moes stand-in), host f64 network and integer mirror, against its
/// closed-form reference on its held-out test set: all of the accuracy targets (central film
/// R² ≥ 0.9995, median ≤ 0.5 %, p99 ≤ 2 %, max ≤ 5 %; minimum film twice the error bounds).
#[test]
fn pipeline_model_meets_accuracy_targets() {
    let m = ModelFile::load(&root().join("data/ann/pipeline_moes_model.json")).unwrap();
    let te = test_set_of(&m, "data/ann/pipeline_moes_dataset.jsonl");
    let f64s: Vec<(f64, f64)> = te.cases.iter().map(|c| m.trained.predict(c)).collect();
    let ints = predict_int(&m.trained, m.quantised.as_ref().unwrap(), &te);
    for films in [f64s, ints] {
        let e = Metrics::of(&films, &te.films);
        assert!(
            e.central.r2 >= 0.9995
                && e.central.median_pct <= 0.5
                && e.central.p99_pct <= 2.0
                && e.central.max_pct <= 5.0,
            "{:?}",
            e.central
        );
        assert!(
            e.minimum.r2 >= 0.9995
                && e.minimum.median_pct <= 1.0
                && e.minimum.p99_pct <= 4.0
                && e.minimum.max_pct <= 10.0,
            "{:?}",
            e.minimum
        );
    }
}

/// The core's integer network (on x86-64 computed in exact f64 lanes, `exact_f64`) gives the
/// output codes of the plain definition, written out here from the model file's quantised
/// layers: i64 sums row by row from the bias, `⌊(A·m + 2^(s−1))/2^s⌋` in i128 saturated to
/// i16, the table lookup between hidden layers. Inputs: every test-set contact (prepared and
/// quantised as `AnnInt` does), 4⁵ corner inputs from {−32768, −32767, 0, 32767} and 5000
/// random codes.
#[test]
fn core_int_codes_match_the_i64_definition() {
    use bearing_core::film::ann::int::{lut_lookup, quantise_input, Lut};
    let m = model();
    let q = m.quantised.as_ref().unwrap();
    let lut: Lut = q.lut.as_slice().try_into().unwrap();
    let reference = |x: &[i16; 5]| -> [i16; 2] {
        let mut a: Vec<i16> = x.to_vec();
        for (k, l) in q.layers.iter().enumerate() {
            a = l
                .weights
                .iter()
                .zip(&l.bias)
                .map(|(row, b)| {
                    let mut acc: i64 = *b;
                    for (w, v) in row.iter().zip(&a) {
                        acc += i64::from(*w) * i64::from(*v);
                    }
                    let p = i128::from(acc) * i128::from(l.multiplier) + (1i128 << (l.shift - 1));
                    let z = (p >> l.shift).clamp(-32768, 32767) as i16;
                    if k + 1 < q.layers.len() {
                        lut_lookup(&lut, z)
                    } else {
                        z
                    }
                })
                .collect();
        }
        [a[0], a[1]]
    };
    let mut inputs: Vec<[i16; 5]> = test_set(&m)
        .cases
        .iter()
        .map(|c| ann::prepare(&c.to_core()).features.map(quantise_input))
        .collect();
    assert_eq!(inputs.len(), 750);
    let corners = [i16::MIN, -32767, 0, 32767];
    for k in 0..4usize.pow(5) {
        inputs.push(core::array::from_fn(|i| corners[(k >> (2 * i)) % 4]));
    }
    // SplitMix64 (Steele, Lea & Flood 2014).
    let mut state = 20261121u64;
    for _ in 0..5000 {
        inputs.push(core::array::from_fn(|_| {
            state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
            let mut z = state;
            z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
            z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
            (z ^ (z >> 31)) as i16
        }));
    }
    for x in &inputs {
        assert_eq!(
            ann::model_weights::forward_int(x),
            reference(x),
            "input {x:?}"
        );
    }
}
