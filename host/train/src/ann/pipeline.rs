//! The training pipeline behind `bearing train`: load a dataset (line or point contacts), split
//! it 70/15/15, train, quantise, and measure on the held-out test set only once the network is
//! final.

use std::path::Path;

use anyhow::{bail, Result};

use super::features::FilmCase;
use super::metrics::Metrics;
use super::model::{ModelFile, Provenance, TestReport, MODEL_FORMAT, MODEL_VERSION};
use super::quant::{quantise, Quantised};
use super::train::{split, train, Samples, TrainOptions, Trained};
use crate::dataset::{Dataset, DatasetContact};

/// Load the solved records of a line-contact dataset.
pub fn load_samples(path: &Path) -> Result<(Dataset, Samples)> {
    load_contact_samples(path)
}

/// Load the solved records of a dataset of contacts `C`.
pub fn load_contact_samples<C: DatasetContact>(path: &Path) -> Result<(Dataset<C>, Samples<C>)> {
    let data = Dataset::<C>::load(path)?;
    let mut samples = Samples::default();
    for (case, films) in data.solved() {
        samples.cases.push(case.clone());
        samples.films.push(films);
    }
    if samples.len() < 20 {
        bail!(
            "{}: only {} solved records; at least 20 are needed to train",
            path.display(),
            samples.len()
        );
    }
    Ok((data, samples))
}

/// The train / validation / test sets of a sample set for a seed.
pub fn split_samples<C: Clone>(
    samples: &Samples<C>,
    seed: u64,
) -> (Samples<C>, Samples<C>, Samples<C>) {
    let (a, b, c) = split(samples.len(), seed);
    (samples.subset(&a), samples.subset(&b), samples.subset(&c))
}

/// Integer-network predictions (host mirror) of films.
pub fn predict_int<C: FilmCase>(
    trained: &Trained,
    q: &Quantised,
    samples: &Samples<C>,
) -> Vec<(f64, f64)> {
    samples
        .cases
        .iter()
        .map(|c| {
            let x = trained
                .input_norm
                .forward(&trained.options.inputs.features(c));
            let y = trained.output_norm.inverse(&q.forward(&x));
            trained.options.target.decode(c, [y[0], y[1]])
        })
        .collect()
}

/// Regression-formula films of the samples (line: Dowson–Toyoda / Dowson–Higginson; point:
/// Hamrock–Dowson).
pub fn predict_regression<C: FilmCase>(samples: &Samples<C>) -> Vec<(f64, f64)> {
    samples
        .cases
        .iter()
        .map(FilmCase::regression_films_m)
        .collect()
}

/// Train, quantise and measure; `weight_bits` selects the stored integer weights. An input set
/// of the other contact is refused.
pub fn train_model<C: DatasetContact + FilmCase>(
    dataset_file: &str,
    data: &Dataset<C>,
    samples: &Samples<C>,
    options: &TrainOptions,
    weight_bits: u32,
    command: String,
) -> Result<ModelFile<C::Domain>> {
    if !C::INPUT_SETS.contains(&options.inputs) {
        bail!(
            "--inputs {:?} is not an input set of this dataset's contact (allowed: {:?})",
            options.inputs,
            C::INPUT_SETS
        );
    }
    let (tr, va, te) = split_samples(samples, options.seed);
    let trained = train(&tr, &va, options);
    let calibration: Vec<Vec<f64>> = tr
        .cases
        .iter()
        .map(|c| trained.input_norm.forward(&options.inputs.features(c)))
        .collect();
    let f64_pred: Vec<(f64, f64)> = te.cases.iter().map(|c| trained.predict(c)).collect();
    let mut int_vs_f64 = Vec::new();
    let mut chosen = None;
    for bits in [8, 16] {
        let q = quantise(&trained.net, bits, &calibration)?;
        let pred = predict_int(&trained, &q, &te);
        int_vs_f64.push((bits, Metrics::of(&pred, &f64_pred)));
        if bits == weight_bits {
            chosen = Some((q, Metrics::of(&pred, &te.films)));
        }
    }
    let Some((quantised, network_int)) = chosen else {
        bail!("weight bits must be 8 or 16, got {weight_bits}")
    };
    Ok(ModelFile {
        format: MODEL_FORMAT.into(),
        version: MODEL_VERSION,
        domain: data.metadata.domain,
        test: TestReport {
            sizes: [tr.len(), va.len(), te.len()],
            network_f64: Metrics::of(&f64_pred, &te.films),
            network_int,
            int_vs_f64,
            regression: Metrics::of(&predict_regression(&te), &te.films),
            core: None,
        },
        quantised: Some(quantised),
        trained,
        provenance: Provenance {
            dataset_file: dataset_file.into(),
            dataset_seed: data.metadata.seed,
            dataset_solved: samples.len(),
            solver: data.metadata.solver.clone(),
            command,
            tool_version: env!("CARGO_PKG_VERSION").into(),
        },
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dataset::generate::{generate, GenerateOptions};
    use crate::dataset::point_domain::PointDomain;
    use crate::dataset::point_numerical::PointFilms;
    use crate::dataset::SolverInfo;
    use bearing_ehl::point::formulas::nijenbanning_central_film_m;
    use bearing_ehl::point::PointContactCase;

    /// The point-contact pipeline end to end on a stand-in: 300 cases of the point domain with
    /// Nijenbanning–Venner–Moes' closed-form central film (and 0.75 of it as the minimum film)
    /// written by the generator, loaded, split, trained (1×8 tanh on (ln M, ln L, ln k, ln G,
    /// ln η₀, E′)), quantised and measured. The network, which learns the ratio to
    /// Hamrock–Dowson, meets the targets against the closed form on the held-out set
    /// (R² ≥ 0.9995, median ≤ 0.5 %, p99 ≤ 2 %), the 16-bit integer network stays within 0.2 %
    /// of the f64 one, a line-contact input set is refused, and the model file round-trips.
    #[test]
    fn point_pipeline_learns_a_closed_form() {
        let dir =
            std::env::temp_dir().join(format!("bearing-point-pipeline-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("nvm.jsonl");
        let _ = std::fs::remove_file(&path);
        // The window this 300-case stand-in is sized for (k ≤ 5.8, M ≤ min(1000, 100·k)); over
        // the full default domain (k to 8, M to 2000) the 1×8 net misses the p99 target.
        let mut domain = PointDomain::default();
        domain.radius_ratio.max = 16.0;
        domain.moes_m.max = 1000.0;
        domain.elongated_m_per_ellipticity = domain.m_per_ellipticity;
        let options = GenerateOptions::<PointContactCase> {
            n: 300,
            seed: 5,
            domain,
            solver: SolverInfo {
                name: "nvm".into(),
                version: "test".into(),
                options: serde_json::Value::Null,
            },
            command: "test".into(),
            progress: false,
            chunk: 100,
        };
        generate(&path, &options, |c: &PointContactCase| {
            let central = nijenbanning_central_film_m(c);
            Ok(PointFilms {
                central_m: central,
                minimum_m: 0.75 * central,
                central_raw_m: central,
                minimum_raw_m: 0.75 * central,
                central_grid_error: 0.0,
                minimum_grid_error: 0.0,
            })
        })
        .unwrap();
        let (data, samples) = load_contact_samples::<PointContactCase>(&path).unwrap();
        assert_eq!(samples.len(), 300);
        let train_options = TrainOptions {
            hidden: vec![8],
            inputs: crate::ann::features::InputSet::MlkGEtaModulus,
            max_epochs: 300,
            ..TrainOptions::default()
        };
        let model = train_model(
            "nvm.jsonl",
            &data,
            &samples,
            &train_options,
            16,
            "test".into(),
        )
        .unwrap();
        for m in [&model.test.network_f64, &model.test.network_int] {
            for e in [&m.central, &m.minimum] {
                assert!(
                    e.r2 >= 0.9995 && e.median_pct <= 0.5 && e.p99_pct <= 2.0,
                    "{e:?}"
                );
            }
        }
        let (_, int16) = model
            .test
            .int_vs_f64
            .iter()
            .find(|(b, _)| *b == 16)
            .unwrap();
        assert!(
            int16.central.max_pct <= 0.2 && int16.minimum.max_pct <= 0.2,
            "{int16:?}"
        );
        let line_inputs = TrainOptions {
            inputs: crate::ann::features::InputSet::Wug,
            ..train_options
        };
        assert!(train_model("nvm.jsonl", &data, &samples, &line_inputs, 16, "t".into()).is_err());
        let file = dir.join("model.json");
        model.save(&file).unwrap();
        assert_eq!(ModelFile::<PointDomain>::load(&file).unwrap(), model);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    /// The committed point-contact model (data/ann/point_numerical_model.json) against the
    /// point solver's Richardson films on the held-out test set of its dataset (the split of
    /// its seed, recomputed here): the targets for h_c and h_min (R² ≥ 0.9995,
    /// median ≤ 0.5 %, p99 ≤ 2 %) for the f64 and the 16-bit integer network, and the integer
    /// network within 0.2 % of the f64 one on every test case.
    #[test]
    fn committed_point_model_meets_the_targets() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/ann");
        let model =
            ModelFile::<PointDomain>::load(&root.join("point_numerical_model.json")).unwrap();
        let (_, samples) =
            load_contact_samples::<PointContactCase>(&root.join("point_numerical_dataset.jsonl"))
                .unwrap();
        let (_, _, te) = split_samples(&samples, model.trained.options.seed);
        assert!(te.len() >= 100, "{} test cases", te.len());
        let f64s: Vec<(f64, f64)> = te.cases.iter().map(|c| model.trained.predict(c)).collect();
        let ints = predict_int(&model.trained, model.quantised.as_ref().unwrap(), &te);
        for films in [&f64s, &ints] {
            let m = Metrics::of(films, &te.films);
            for e in [&m.central, &m.minimum] {
                assert!(
                    e.r2 >= 0.9995 && e.median_pct <= 0.5 && e.p99_pct <= 2.0,
                    "{e:?}"
                );
            }
        }
        let d = Metrics::of(&ints, &f64s);
        assert!(
            d.central.max_pct <= 0.2 && d.minimum.max_pct <= 0.2,
            "{d:?}"
        );
    }
}
