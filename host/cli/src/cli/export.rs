//! `bearing export`: write a model file's network into the core as const arrays.

use std::path::PathBuf;

use anyhow::{Context, Result};
use bearing_core::film::ann::int::direct_requantisation;
use bearing_train::ann::export::ContactModel;
use clap::Args;

/// `bearing export --model FILE [--out FILE]`
#[derive(Args)]
pub struct ExportArgs {
    /// Model file (`bearing train`), of either contact.
    #[arg(long)]
    model: PathBuf,
    /// Generated Rust file [default: core/src/film/ann/model_weights.rs for a line-contact
    /// model, core/src/film/ann/point_model_weights.rs for a point-contact one].
    #[arg(long)]
    out: Option<PathBuf>,
}

/// Run `bearing export`.
pub fn run(args: ExportArgs) -> Result<()> {
    let model = ContactModel::load(&args.model)?;
    let code = model.render()?;
    let out = args
        .out
        .unwrap_or_else(|| PathBuf::from(model.default_out()));
    bearing_host_common::output::write_file(&out, code)
        .with_context(|| format!("writing {}", out.display()))?;
    eprintln!("wrote {} from {}", out.display(), args.model.display());
    // The host's integer path is exact either way; a layer outside the direct requantisation
    // only runs slower there (`bearing_core::film::ann::int::direct_requantisation`).
    let layers = model.quantised().into_iter().flat_map(|q| q.layers.iter());
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
