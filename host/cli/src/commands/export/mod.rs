//! `bearing export`: write a model file's network into the core as const arrays, or the tanh
//! table the core's integer networks share.

use std::path::PathBuf;

use anyhow::{Context, Result};
use bearing_core::film::ann::int::direct_requantisation;
use bearing_core::film::ann::tanh_table::TANH_LUT_INPUT_SCALE;
use bearing_train::ann::export::{
    render_tanh_table, shares_core_tanh_table, ContactModel, TANH_TABLE_PATH,
};
use clap::Args;

/// `bearing export --model FILE [--out FILE]`, `bearing export --tanh-table [--out FILE]`
#[derive(Args)]
pub struct ExportArgs {
    /// Model file (`bearing train`), of either contact.
    #[arg(long, required_unless_present = "tanh_table")]
    model: Option<PathBuf>,
    /// Write the core's shared tanh table instead of a network.
    #[arg(long, conflicts_with = "model")]
    tanh_table: bool,
    /// Generated Rust file [default: core/src/generated/model_weights.rs for a line-contact
    /// model, core/src/generated/point_model_weights.rs for a point-contact one,
    /// core/src/generated/tanh_table.rs with --tanh-table].
    #[arg(long)]
    out: Option<PathBuf>,
}

/// Run `bearing export`.
pub fn run(args: ExportArgs) -> Result<()> {
    let Some(model_path) = args.model else {
        let out = args.out.unwrap_or_else(|| PathBuf::from(TANH_TABLE_PATH));
        bearing_host_common::output::write_file(&out, render_tanh_table()?)
            .with_context(|| format!("writing {}", out.display()))?;
        eprintln!("wrote {}", out.display());
        return Ok(());
    };
    let model = ContactModel::load(&model_path)?;
    let code = model.render()?;
    let out = args
        .out
        .unwrap_or_else(|| PathBuf::from(model.default_out()));
    bearing_host_common::output::write_file(&out, code)
        .with_context(|| format!("writing {}", out.display()))?;
    eprintln!("wrote {} from {}", out.display(), model_path.display());
    if let Some(q) = model.quantised() {
        if !q.lut.is_empty() && !shares_core_tanh_table(q) {
            eprintln!(
                "note: {}: its {} table (input scale {:e}) is not the core's tanh table (input \
                 scale {TANH_LUT_INPUT_SCALE:e}, core/src/generated/tanh_table.rs): {} holds its \
                 own copy",
                model_path.display(),
                q.activation.name(),
                q.lut_input_scale,
                out.display()
            );
        }
    }
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
