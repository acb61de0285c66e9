//! The training pipeline behind `bearing train`: load a dataset, split it 70/15/15, train,
//! quantise, and measure on the held-out test set only once the network is final.

use std::path::Path;

use anyhow::{bail, Result};

use super::features::regression_films_over_r;
use super::metrics::Metrics;
use super::model::{ModelFile, Provenance, TestReport, MODEL_FORMAT, MODEL_VERSION};
use super::quant::{quantise, Quantised};
use super::train::{split, train, Samples, TrainOptions, Trained};
use crate::dataset::Dataset;

/// Load the solved records of a dataset.
pub fn load_samples(path: &Path) -> Result<(Dataset, Samples)> {
    let data = Dataset::load(path)?;
    let mut samples = Samples::default();
    for (case, films) in data.solved() {
        samples.cases.push(*case);
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
pub fn split_samples(samples: &Samples, seed: u64) -> (Samples, Samples, Samples) {
    let (a, b, c) = split(samples.len(), seed);
    (samples.subset(&a), samples.subset(&b), samples.subset(&c))
}

/// Integer-network predictions (host mirror) of films.
pub fn predict_int(trained: &Trained, q: &Quantised, samples: &Samples) -> Vec<(f64, f64)> {
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

/// Regression-formula films of the samples.
pub fn predict_regression(samples: &Samples) -> Vec<(f64, f64)> {
    samples
        .cases
        .iter()
        .map(|c| {
            let (dt, dh) = regression_films_over_r(c);
            (dt * c.reduced_radius_m, dh * c.reduced_radius_m)
        })
        .collect()
}

/// Train, quantise and measure; `weight_bits` selects the stored integer weights.
pub fn train_model(
    dataset_file: &str,
    data: &Dataset,
    samples: &Samples,
    options: &TrainOptions,
    weight_bits: u32,
    command: String,
) -> Result<ModelFile> {
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
