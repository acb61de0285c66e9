//! The architecture study of docs/physics.md §5.3 (1–4 hidden layers × 10–20 neurons ×
//! tanh/logistic/ReLU × 600–5000 samples): train each combination on the first `N` samples of a
//! dataset (own 70/15/15 split) and tabulate its held-out test accuracy and training time.

use std::io::IsTerminal;

use indicatif::{ProgressBar, ProgressStyle};
use serde::{Deserialize, Serialize};

use super::metrics::FilmErrors;
use super::mlp::Activation;
use super::pipeline::split_samples;
use super::train::{train, Samples, Solver, TrainOptions};

/// The grid.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SweepConfig {
    /// Hidden-layer counts.
    pub layers: Vec<usize>,
    /// Neurons per hidden layer.
    pub neurons: Vec<usize>,
    /// Activations.
    pub activations: Vec<Activation>,
    /// Sample counts (first N solved records).
    pub sample_sizes: Vec<usize>,
    /// Everything else (inputs, target, regularisation, epochs, seed).
    pub base: TrainOptions,
}

impl SweepConfig {
    /// The full published grid: 1–4 layers × {10, 15, 20} × 3 activations × {600, 1000, 2000, 5000}.
    pub fn full(base: TrainOptions) -> Self {
        Self {
            layers: vec![1, 2, 3, 4],
            neurons: vec![10, 15, 20],
            activations: vec![Activation::Tanh, Activation::Logistic, Activation::Relu],
            sample_sizes: vec![600, 1000, 2000, 5000],
            base,
        }
    }

    /// The CI subset: 1–2 layers × {10, 14} × tanh/ReLU × 600 samples, ≤ 100 epochs.
    pub fn quick(mut base: TrainOptions) -> Self {
        base.max_epochs = base.max_epochs.min(100);
        Self {
            layers: vec![1, 2],
            neurons: vec![10, 14],
            activations: vec![Activation::Tanh, Activation::Relu],
            sample_sizes: vec![600],
            base,
        }
    }
}

/// One trained combination.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct SweepRow {
    /// Hidden layers.
    pub layers: usize,
    /// Neurons per layer.
    pub neurons: usize,
    /// Activation.
    pub activation: Activation,
    /// Samples used (train + validation + test).
    pub samples: usize,
    /// Trainable parameters.
    pub parameters: usize,
    /// Epochs run.
    pub epochs: usize,
    /// Training time (s).
    pub train_seconds: f64,
    /// Central-film test errors.
    pub central: FilmErrors,
    /// Minimum-film test errors.
    pub minimum: FilmErrors,
}

/// Run the grid (sample sizes larger than the data are skipped).
pub fn run_sweep(samples: &Samples, config: &SweepConfig, progress: bool) -> Vec<SweepRow> {
    let sizes: Vec<usize> = config
        .sample_sizes
        .iter()
        .copied()
        .filter(|&n| n <= samples.len())
        .collect();
    let total = sizes.len() * config.layers.len() * config.neurons.len() * config.activations.len();
    let log_lines = progress && !std::io::stderr().is_terminal();
    let bar = if progress {
        ProgressBar::new(total as u64)
    } else {
        ProgressBar::hidden()
    };
    bar.set_style(
        ProgressStyle::with_template(
            "{spinner} [{elapsed_precise}] {wide_bar} {pos}/{len} networks {msg}",
        )
        .unwrap_or_else(|_| ProgressStyle::default_bar()),
    );
    let mut rows = Vec::new();
    for &n in &sizes {
        let subset = samples.subset(&(0..n).collect::<Vec<_>>());
        let (tr, va, te) = split_samples(&subset, config.base.seed);
        for &layers in &config.layers {
            for &neurons in &config.neurons {
                for &activation in &config.activations {
                    bar.set_message(format!("{layers}x{neurons} {} n={n}", activation.name()));
                    let options = TrainOptions {
                        hidden: vec![neurons; layers],
                        activation,
                        ..config.base.clone()
                    };
                    let t = train(&tr, &va, &options);
                    let m = t.evaluate(&te);
                    if log_lines {
                        // No terminal to draw the bar on (a background run): one line per
                        // network, so the log shows progress and survives an interruption.
                        eprintln!(
                            "{}/{total} {layers}x{neurons} {} n={n}: {} epochs, {:.1} s, h_c p99 {:.3} %",
                            rows.len() + 1,
                            activation.name(),
                            t.epochs,
                            t.train_seconds,
                            m.central.p99_pct
                        );
                    }
                    rows.push(SweepRow {
                        layers,
                        neurons,
                        activation,
                        samples: n,
                        parameters: t.net.parameter_count(),
                        epochs: t.epochs,
                        train_seconds: t.train_seconds,
                        central: m.central,
                        minimum: m.minimum,
                    });
                    bar.inc(1);
                }
            }
        }
    }
    bar.finish_and_clear();
    rows
}

/// The paragraph above the table: what was trained and how, so that a capped run (fewer
/// epochs than the published 1000) says so where the numbers are read.
pub fn heading(config: &SweepConfig, dataset: &str) -> String {
    let b = &config.base;
    let kebab = |v: Option<clap::builder::PossibleValue>| {
        v.map(|p| p.get_name().to_string()).unwrap_or_default()
    };
    format!(
        "Architecture sweep on `{dataset}`: inputs `{}`, target `{}`, weight decay λ = {:e}, \
         at most {} Levenberg–Marquardt epochs ({}), early-stopping patience {}, {} \
         restart(s), seed {}. Each network is trained on the first N solved records (its own 70/15/15 \
         split) and measured on its held-out test set; `time s` is the training wall time.\n",
        kebab(clap::ValueEnum::to_possible_value(&b.inputs)),
        kebab(clap::ValueEnum::to_possible_value(&b.target)),
        b.regularisation,
        b.max_epochs,
        match b.solver {
            Solver::Minpack => "MINPACK, the `levenberg-marquardt` crate",
            Solver::Trainlm => "MATLAB `trainlm`'s normal equations",
        },
        b.patience,
        b.restarts,
        b.seed
    )
}

/// Markdown table of the rows.
pub fn markdown(rows: &[SweepRow]) -> String {
    let mut s = String::from(
        "| samples | layers × neurons | act | params | epochs | time s | h_c R² | h_c med % | h_c p99 % | h_c max % | h_min R² | h_min med % | h_min p99 % | h_min max % |\n\
         |---:|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
    );
    for r in rows {
        s.push_str(&format!(
            "| {} | {}×{} | {} | {} | {} | {:.1} | {:.6} | {:.3} | {:.3} | {:.3} | {:.6} | {:.3} | {:.3} | {:.3} |\n",
            r.samples,
            r.layers,
            r.neurons,
            r.activation.name(),
            r.parameters,
            r.epochs,
            r.train_seconds,
            r.central.r2,
            r.central.median_pct,
            r.central.p99_pct,
            r.central.max_pct,
            r.minimum.r2,
            r.minimum.median_pct,
            r.minimum.p99_pct,
            r.minimum.max_pct
        ));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ann::features::InputSet;

    /// The full grid is the published one (4 × 3 × 3 × 4 = 144 networks); the heading states
    /// the epoch cap, inputs and restarts the table was made with.
    #[test]
    fn full_grid_and_heading() {
        let base = TrainOptions {
            inputs: InputSet::WugEtaModulus,
            max_epochs: 12,
            ..TrainOptions::default()
        };
        let c = SweepConfig::full(base);
        let networks =
            c.layers.len() * c.neurons.len() * c.activations.len() * c.sample_sizes.len();
        assert_eq!(networks, 144);
        assert_eq!(c.sample_sizes, vec![600, 1000, 2000, 5000]);
        let h = heading(&c, "data/x.jsonl");
        for part in [
            "`data/x.jsonl`",
            "inputs `wug-eta-modulus`",
            "target `log-ratio`",
            "at most 12 Levenberg–Marquardt epochs (MINPACK",
            "patience 6",
            "1 restart(s)",
        ] {
            assert!(h.contains(part), "{part:?} missing from {h:?}");
        }
        assert!(heading(&SweepConfig::quick(TrainOptions::default()), "d").contains("at most 100 "));
        let trainlm = TrainOptions {
            solver: Solver::Trainlm,
            ..TrainOptions::default()
        };
        assert!(heading(&SweepConfig::full(trainlm), "d").contains("(MATLAB `trainlm`"));
    }
}
