//! `bearing export`: write a model file's network into the core as const arrays.

use std::path::PathBuf;

use anyhow::{Context, Result};
use bearing_core::film::ann::int::direct_requantisation;
use bearing_train::ann::export::render;
use bearing_train::ann::model::ModelFile;
use clap::Args;

/// `bearing export --model FILE --out core/src/film/ann/model_weights.rs`
#[derive(Args)]
pub struct ExportArgs {
    /// Model file (`bearing train`).
    #[arg(long)]
    model: PathBuf,
    /// Generated Rust file.
    #[arg(long, default_value = "core/src/film/ann/model_weights.rs")]
    out: PathBuf,
}

/// Run `bearing export`.
pub fn run(args: ExportArgs) -> Result<()> {
    let model = ModelFile::load(&args.model)?;
    let code = render(&model)?;
    bearing_host_common::output::write_file(&args.out, code)
        .with_context(|| format!("writing {}", args.out.display()))?;
    eprintln!("wrote {} from {}", args.out.display(), args.model.display());
    // The host's integer path is exact either way; a layer outside the direct requantisation
    // only runs slower there (`bearing_core::film::ann::int::direct_requantisation`).
    let layers = model.quantised.iter().flat_map(|q| q.layers.iter());
    for (k, layer) in layers.enumerate() {
        if !direct_requantisation(layer.multiplier, layer.shift) {
            eprintln!(
                "note: integer layer {k} (multiplier {}, shift {}) takes the host's general \
                 requantisation (direct form needs shift <= 38 and a multiplier odd part >= 2^16): \
                 same bits, ≈ 5 more dependent operations per layer on x86-64",
                layer.multiplier, layer.shift
            );
        }
    }
    Ok(())
}
