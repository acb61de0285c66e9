//! `bearing train`: train the film network on a dataset (`bearing train --data … --arch …`,
//! line contacts, or `--contact point` on a point-contact dataset), run the architecture sweep (`bearing train sweep`), or measure the compiled core models on a
//! model's test set (`bearing train evaluate`).

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use bearing_core::film::{ann, FilmModel, FilmSource};
use bearing_ehl::point::PointContactCase;
use bearing_host_common::output::{write_with, OutputFiles};
use bearing_train::ann::export::fingerprint;
use bearing_train::ann::features::{FilmCase, InputSet, TargetForm};
use bearing_train::ann::metrics::Metrics;
use bearing_train::ann::mlp::Activation;
use bearing_train::ann::model::{CoreReport, ModelFile, TestReport};
use bearing_train::ann::pipeline::{
    load_contact_samples, load_samples, split_samples, train_model,
};
use bearing_train::ann::sweep::{heading, markdown, run_sweep, SweepConfig};
use bearing_train::ann::train::{Solver, TrainOptions, Trained};
use bearing_train::dataset::{ContactCase, DatasetContact};
use clap::{Args, Subcommand};

use crate::commands::dataset::ContactKind;

/// `bearing train …`
#[derive(Args)]
#[command(args_conflicts_with_subcommands = true, subcommand_negates_reqs = true)]
pub struct TrainArgs {
    #[command(subcommand)]
    command: Option<TrainCommand>,
    #[command(flatten)]
    train: TrainOne,
}

#[derive(Subcommand)]
enum TrainCommand {
    /// Architecture study: layers × neurons × activation × samples → markdown + JSON.
    Sweep(SweepArgs),
    /// Measure the compiled core networks (`AnnF32`, `AnnInt`) on the model's test set.
    Evaluate(EvaluateArgs),
}

/// Options shared by training and the sweep.
#[derive(Args, Clone)]
struct Common {
    /// Network inputs (default: `wug` for line contacts, `mlk-g-eta-modulus` for point
    /// contacts; `wug`, `wug-eta-modulus` are the line contact's, `mlk`, `mlk-g-eta-modulus`
    /// the point contact's).
    #[arg(long, value_enum)]
    inputs: Option<InputSet>,
    /// Output form.
    #[arg(long, value_enum, default_value = "log-ratio")]
    target: TargetForm,
    /// Weight-decay coefficient λ (0 … 1).
    #[arg(long, default_value_t = 1e-7)]
    reg: f64,
    /// Epoch limit (1 … 100 000).
    #[arg(long, default_value_t = 1000, value_parser = clap::value_parser!(u64).range(1..=100_000))]
    max_epochs: u64,
    /// Early-stopping patience in epochs (1 … 1000).
    #[arg(long, default_value_t = 6, value_parser = clap::value_parser!(u64).range(1..=1000))]
    patience: u64,
    /// Seed of the split and initial weights.
    #[arg(long, default_value_t = 1)]
    seed: u64,
    /// Random restarts (best validation kept, 1 … 100).
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u64).range(1..=100))]
    restarts: u64,
    /// Levenberg–Marquardt implementation: `minpack` (the crate; trains the committed model) or
    /// `trainlm` (MATLAB's normal equations; far faster for nets of hundreds of parameters).
    #[arg(long, value_enum, default_value = "minpack")]
    solver: Solver,
}

impl Common {
    fn options(
        &self,
        hidden: Vec<usize>,
        activation: Activation,
        contact: ContactKind,
    ) -> Result<TrainOptions> {
        if !(self.reg.is_finite() && (0.0..=1.0).contains(&self.reg)) {
            bail!("--reg must be a finite number in [0, 1], got {}", self.reg);
        }
        let allowed = match contact {
            ContactKind::Line => <ContactCase as FilmCase>::INPUT_SETS,
            ContactKind::Point => <PointContactCase as FilmCase>::INPUT_SETS,
        };
        let inputs = self.inputs.unwrap_or(allowed[0]);
        if !allowed.contains(&inputs) {
            bail!("--inputs {inputs:?} is not an input set of the {contact:?} contact (allowed: {allowed:?})");
        }
        Ok(TrainOptions {
            hidden,
            activation,
            inputs,
            target: self.target,
            regularisation: self.reg,
            max_epochs: self.max_epochs as usize,
            patience: self.patience as usize,
            seed: self.seed,
            restarts: self.restarts as usize,
            solver: self.solver,
        })
    }
}

#[derive(Args)]
struct TrainOne {
    /// Dataset file (`bearing dataset generate`).
    #[arg(long, required = true)]
    data: Option<PathBuf>,
    /// Contact kind of the dataset (`bearing export` writes either kind into the core).
    #[arg(long, value_enum, default_value = "line")]
    contact: ContactKind,
    /// Hidden layers as `LxN` (e.g. `3x14`) or widths `14-14-10` (1–8 layers of 1–64).
    #[arg(long, default_value = "2x14")]
    arch: String,
    /// Hidden activation.
    #[arg(long, value_enum, default_value = "tanh")]
    act: Activation,
    /// Integer weight precision stored in the model (8 or 16).
    #[arg(long, default_value_t = 16)]
    weight_bits: u32,
    /// Model file to write.
    #[arg(long, required = true)]
    out: Option<PathBuf>,
    /// Print the test report as JSON.
    #[arg(long)]
    json: bool,
    #[command(flatten)]
    common: Common,
}

#[derive(Args)]
struct SweepArgs {
    /// Dataset file.
    #[arg(long)]
    data: PathBuf,
    /// CI subset (1–2 layers × {10, 14} × tanh/ReLU × 600 samples, ≤ 100 epochs); without it
    /// the full published grid (1–4 layers × {10, 15, 20} × tanh/logistic/ReLU ×
    /// {600, 1000, 2000, 5000} samples).
    #[arg(long)]
    quick: bool,
    /// Comma-separated sample counts (overrides the grid's).
    #[arg(long, value_delimiter = ',')]
    samples: Option<Vec<usize>>,
    /// Comma-separated layer counts (overrides the grid's).
    #[arg(long, value_delimiter = ',')]
    layers: Option<Vec<usize>>,
    /// Comma-separated neuron counts (overrides the grid's).
    #[arg(long, value_delimiter = ',')]
    neurons: Option<Vec<usize>>,
    /// Markdown table output.
    #[arg(long, default_value = "sweep.md")]
    out_md: PathBuf,
    /// JSON output.
    #[arg(long, default_value = "sweep.json")]
    out_json: PathBuf,
    #[command(flatten)]
    common: Common,
}

#[derive(Args)]
struct EvaluateArgs {
    /// Model file (must be the one compiled into the core).
    #[arg(long)]
    model: PathBuf,
    /// Dataset file the model was trained on.
    #[arg(long)]
    data: PathBuf,
    /// Store the figures in the model file.
    #[arg(long)]
    write: bool,
}

/// Parse `LxN` or `a-b-c`.
fn parse_arch(arch: &str) -> Result<Vec<usize>> {
    let widths: Vec<usize> = if let Some((l, n)) = arch.split_once('x') {
        let l: usize = l
            .trim()
            .parse()
            .with_context(|| format!("--arch {arch}: layer count"))?;
        let n: usize = n
            .trim()
            .parse()
            .with_context(|| format!("--arch {arch}: neuron count"))?;
        vec![n; l]
    } else {
        arch.split('-')
            .map(|w| w.trim().parse::<usize>())
            .collect::<Result<_, _>>()
            .with_context(|| format!("--arch {arch}: expected LxN or widths like 14-14"))?
    };
    if widths.is_empty() || widths.len() > 8 || widths.iter().any(|w| !(1..=64).contains(w)) {
        bail!("--arch {arch}: 1–8 hidden layers of 1–64 neurons allowed");
    }
    Ok(widths)
}

/// Run `bearing train`.
pub fn run(args: TrainArgs) -> Result<()> {
    match args.command {
        Some(TrainCommand::Sweep(s)) => sweep(s),
        Some(TrainCommand::Evaluate(e)) => evaluate(e),
        None => train_one(args.train),
    }
}

fn print_metrics(name: &str, m: &Metrics) {
    for (film, e) in [("h_c", &m.central), ("h_min", &m.minimum)] {
        println!(
            "{name:<26} {film:<6} R² {:.6}  R²(ln) {:.6}  |rel| median {:.3} %  p90 {:.3} %  {}p99 {:.3} %  max {:.3} %",
            e.r2,
            e.r2_log,
            e.median_pct,
            e.p90_pct,
            e.p95_pct.map_or(String::new(), |p| format!("p95 {p:.3} %  ")),
            e.p99_pct,
            e.max_pct
        );
    }
}

fn train_one(args: TrainOne) -> Result<()> {
    let (Some(data_path), Some(out)) = (args.data, args.out) else {
        bail!("--data and --out are required")
    };
    let hidden = parse_arch(&args.arch)?;
    let options = args.common.options(hidden, args.act, args.contact)?;
    if !(args.weight_bits == 8 || args.weight_bits == 16) {
        bail!("--weight-bits must be 8 or 16, got {}", args.weight_bits);
    }
    let command = std::env::args().collect::<Vec<_>>().join(" ");
    let train_contact = match args.contact {
        ContactKind::Line => train_and_save::<ContactCase>,
        ContactKind::Point => train_and_save::<PointContactCase>,
    };
    let (trained, test) = train_contact(
        &data_path,
        &out,
        &args.arch,
        &options,
        args.weight_bits,
        command,
    )?;
    if args.json {
        println!("{}", serde_json::to_string_pretty(&test)?);
    } else {
        let t = &trained;
        println!(
            "{}: {} epochs, validation MSE {:.3e}, {:.1} s",
            out.display(),
            t.epochs,
            t.validation_mse,
            t.train_seconds
        );
        println!("test set ({} cases):", test.sizes[2]);
        print_metrics("network f64", &test.network_f64);
        print_metrics(
            &format!("network int{}", args.weight_bits),
            &test.network_int,
        );
        for (bits, m) in &test.int_vs_f64 {
            print_metrics(&format!("int{bits} vs f64"), m);
        }
        let regression = match args.contact {
            ContactKind::Line => "regression (DT / DH)",
            ContactKind::Point => "regression (Hamrock–Dowson)",
        };
        print_metrics(regression, &test.regression);
    }
    Ok(())
}

/// Load the solved contacts `C` of `data_path`, train, quantise and measure, and write the
/// model to `out`: the network and its test-set report.
fn train_and_save<C: DatasetContact + FilmCase>(
    data_path: &Path,
    out: &Path,
    arch: &str,
    options: &TrainOptions,
    weight_bits: u32,
    command: String,
) -> Result<(Trained, TestReport)> {
    let (data, samples) = load_contact_samples::<C>(data_path)?;
    eprintln!("training {arch} on {} solved cases …", samples.len());
    let file = data_path.display().to_string();
    let model = train_model(&file, &data, &samples, options, weight_bits, command)?;
    write_with(out, |temp| model.save(temp))?;
    Ok((model.trained, model.test))
}

fn sweep(args: SweepArgs) -> Result<()> {
    let base = args
        .common
        .options(vec![], Activation::Tanh, ContactKind::Line)?;
    let mut config = if args.quick {
        SweepConfig::quick(base)
    } else {
        SweepConfig::full(base)
    };
    if let Some(s) = args.samples {
        config.sample_sizes = s;
    }
    if let Some(l) = args.layers {
        config.layers = l;
    }
    if let Some(n) = args.neurons {
        config.neurons = n;
    }
    if config.layers.iter().any(|l| !(1..=8).contains(l))
        || config.neurons.iter().any(|n| !(1..=64).contains(n))
    {
        bail!("--layers must be 1–8 and --neurons 1–64");
    }
    let (_, samples) = load_samples(&args.data)?;
    let rows = run_sweep(&samples, &config, true);
    if rows.is_empty() {
        bail!(
            "no sweep row: every --samples value exceeds the {} solved records",
            samples.len()
        );
    }
    let md = format!(
        "{}\n{}",
        heading(&config, &args.data.display().to_string()),
        markdown(&rows)
    );
    let json = serde_json::to_string_pretty(&serde_json::json!({"config": config, "rows": rows}))?;
    let mut files = OutputFiles::new();
    for (path, text) in [(&args.out_md, &md), (&args.out_json, &json)] {
        let temp = files
            .stage(path)
            .with_context(|| format!("writing {}", path.display()))?;
        std::fs::write(temp, text).with_context(|| format!("writing {}", path.display()))?;
    }
    files.commit()?;
    print!("{md}");
    Ok(())
}

fn evaluate(args: EvaluateArgs) -> Result<()> {
    let mut model = ModelFile::load(&args.model)?;
    let fp = fingerprint(&model)?;
    if fp != ann::model_weights::MODEL_FINGERPRINT {
        bail!(
            "{} (fingerprint {fp}) is not the model compiled into the core ({}); run `bearing export` and rebuild",
            args.model.display(),
            ann::model_weights::MODEL_FINGERPRINT
        );
    }
    let (_, samples) = load_samples(&args.data)?;
    let (_, _, test) = split_samples(&samples, model.trained.options.seed);
    let mut f32_pred = Vec::new();
    let mut int_pred = Vec::new();
    let mut fallbacks = 0;
    for c in &test.cases {
        let input = c.to_core();
        let a = ann::AnnF32.film(&input);
        let b = ann::AnnInt.film(&input);
        fallbacks += usize::from(a.source == FilmSource::Fallback);
        f32_pred.push((f64::from(a.central_m), f64::from(a.minimum_m)));
        int_pred.push((f64::from(b.central_m), f64::from(b.minimum_m)));
    }
    let report = CoreReport {
        ann_f32: Metrics::of(&f32_pred, &test.films),
        ann_int: Metrics::of(&int_pred, &test.films),
        int_vs_f32: Metrics::of(&int_pred, &f32_pred),
        fallbacks,
    };
    println!(
        "core models on the test set ({} cases, {} sent to the fallback):",
        test.len(),
        fallbacks
    );
    print_metrics("AnnF32", &report.ann_f32);
    print_metrics("AnnInt", &report.ann_int);
    print_metrics("AnnInt vs AnnF32", &report.int_vs_f32);
    print_metrics("regression (DT / DH)", &model.test.regression);
    if args.write {
        model.test.core = Some(report);
        write_with(&args.model, |temp| model.save(temp))?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::parse_arch;

    /// `LxN` and width lists parse; zero, too many or too wide layers and junk are refused.
    #[test]
    fn arch_parsing() {
        assert_eq!(parse_arch("3x14").unwrap(), vec![14, 14, 14]);
        assert_eq!(parse_arch("14-10").unwrap(), vec![14, 10]);
        for bad in ["0x5", "2x0", "9x5", "2x65", "abc", "", "3x", "-4"] {
            assert!(parse_arch(bad).is_err(), "{bad}");
        }
    }
}
