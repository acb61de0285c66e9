//! Every file generated into the core (`core/src/generated/`), with its path, its source and
//! its renderer: the one list `cargo xtask generate` writes and `cargo xtask generate --check`
//! compares byte for byte.

use std::path::Path;

use anyhow::Result;

use crate::ann::export::{self, ContactModel};

/// One generated file of the core.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CoreFile {
    /// The line-contact film network (`film::ann::model_weights`).
    LineNetwork,
    /// The point-contact film network (`film::ann::point_model_weights`).
    PointNetwork,
    /// The tanh table the integer networks share (`film::ann::tanh_table`).
    TanhTable,
    /// The friction's mean Eyring stress ratio (`friction::traction_table`).
    TractionTable,
}

impl CoreFile {
    /// Every generated file, the cheap ones first.
    pub const ALL: [CoreFile; 4] = [
        CoreFile::TanhTable,
        CoreFile::LineNetwork,
        CoreFile::PointNetwork,
        CoreFile::TractionTable,
    ];

    /// The short name a command line selects it by.
    pub fn name(self) -> &'static str {
        match self {
            CoreFile::LineNetwork => "line-network",
            CoreFile::PointNetwork => "point-network",
            CoreFile::TanhTable => "tanh-table",
            CoreFile::TractionTable => "traction-table",
        }
    }

    /// Its path in the repository.
    pub fn path(self) -> &'static str {
        match self {
            CoreFile::LineNetwork => export::LINE_WEIGHTS_PATH,
            CoreFile::PointNetwork => export::POINT_WEIGHTS_PATH,
            CoreFile::TanhTable => export::TANH_TABLE_PATH,
            CoreFile::TractionTable => crate::traction_table::TRACTION_TABLE_PATH,
        }
    }

    /// What it is generated from, and how long that takes.
    pub fn source(self) -> &'static str {
        match self {
            CoreFile::LineNetwork => export::LINE_MODEL_PATH,
            CoreFile::PointNetwork => export::POINT_MODEL_PATH,
            CoreFile::TanhTable => "the quantiser's tanh table",
            CoreFile::TractionTable => {
                "the numerical EHL solver (≈ 1 000 solutions, about 2 min on 2 cores)"
            }
        }
    }

    /// The file's text as the generator writes it now; `root` is the repository.
    pub fn render(self, root: &Path) -> Result<String> {
        match self {
            CoreFile::LineNetwork | CoreFile::PointNetwork => {
                ContactModel::load(&root.join(self.source()))?.render()
            }
            CoreFile::TanhTable => export::render_tanh_table(),
            CoreFile::TractionTable => Ok(crate::traction_table::render_traction_table()?.0),
        }
    }
}
