//! The versioned model file (JSON): everything needed to run, check and reproduce a trained film
//! network — weights, normalisation, domain, quantisation, held-out metrics and provenance.

use std::path::Path;

use anyhow::{bail, Context, Result};
use serde::de::DeserializeOwned;
use serde::{Deserialize, Serialize};

use super::metrics::Metrics;
use super::quant::Quantised;
use super::train::Trained;
use crate::dataset::{Domain, SolverInfo};

/// Name in the file, so other JSON files are refused.
pub const MODEL_FORMAT: &str = "bearing-film-ann";
/// Version of the layout.
pub const MODEL_VERSION: u32 = 1;

/// Where the model came from.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Provenance {
    /// Dataset file as given on the command line.
    pub dataset_file: String,
    /// Seed of the dataset design.
    pub dataset_seed: u64,
    /// Solved records in the dataset.
    pub dataset_solved: usize,
    /// Solver that produced the dataset.
    pub solver: SolverInfo,
    /// Command that trained this model.
    pub command: String,
    /// `bearing-host` version.
    pub tool_version: String,
}

/// Held-out test figures.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct TestReport {
    /// Train / validation / test sizes.
    pub sizes: [usize; 3],
    /// f64 network on the test set.
    pub network_f64: Metrics,
    /// Integer network (host mirror of the core's integer inference) on the test set.
    pub network_int: Metrics,
    /// Integer network against the f64 network, for 8- and 16-bit weights (the measurement the
    /// weight precision is chosen by).
    pub int_vs_f64: Vec<(u32, Metrics)>,
    /// Dowson–Toyoda central / Dowson–Higginson minimum on the same test set.
    pub regression: Metrics,
    /// The compiled core models on the test set (`bearing train evaluate --write`).
    pub core: Option<CoreReport>,
}

/// Test-set figures of the core's compiled `AnnF32` / `AnnInt`.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct CoreReport {
    /// `AnnF32` against the reference films.
    pub ann_f32: Metrics,
    /// `AnnInt` against the reference films.
    pub ann_int: Metrics,
    /// `AnnInt` against `AnnF32` (the error quantisation adds in the core).
    pub int_vs_f32: Metrics,
    /// Test cases the core guard sent to the fallback.
    pub fallbacks: usize,
}

/// The model file; `D` is the training domain (the line contact's [`Domain`], which the core
/// guards, or the point contact's).
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct ModelFile<D = Domain> {
    /// Always [`MODEL_FORMAT`].
    pub format: String,
    /// Always [`MODEL_VERSION`].
    pub version: u32,
    /// Network, normalisation, training options and statistics.
    pub trained: Trained,
    /// Training domain (the core's guard uses it).
    pub domain: D,
    /// Integer version of the network.
    pub quantised: Option<Quantised>,
    /// Test-set figures.
    pub test: TestReport,
    /// Provenance.
    pub provenance: Provenance,
}

impl<D: Serialize + DeserializeOwned> ModelFile<D> {
    /// Read and check the format.
    pub fn load(path: &Path) -> Result<Self> {
        let text = std::fs::read_to_string(path)
            .with_context(|| format!("reading model {}", path.display()))?;
        let m: ModelFile<D> = serde_json::from_str(&text)
            .with_context(|| format!("{} is not a film model file", path.display()))?;
        if m.format != MODEL_FORMAT || m.version != MODEL_VERSION {
            bail!(
                "{}: format {} v{} (expected {MODEL_FORMAT} v{MODEL_VERSION})",
                path.display(),
                m.format,
                m.version
            );
        }
        Ok(m)
    }

    /// Write as pretty JSON.
    pub fn save(&self, path: &Path) -> Result<()> {
        let mut text = serde_json::to_string_pretty(self)?;
        text.push('\n');
        std::fs::write(path, text).with_context(|| format!("writing {}", path.display()))
    }
}
