//! The tanh activation table the core's integer networks share (`core/src/generated/tanh_table.rs`)
//! and the test of whether a quantised network's table is that one.

use std::fmt::Write;

use anyhow::Result;
use bearing_core::film::ann::tanh_table::{TANH_LUT, TANH_LUT_INPUT_SCALE};

use crate::ann::mlp::Activation;
use crate::ann::quant::{table, table_input_scale, Quantised};

/// Where the tanh table both networks share is generated in the core.
pub const TANH_TABLE_PATH: &str = "core/src/generated/tanh_table.rs";

/// Whether the quantised network's activation table is the core's tanh table
/// (`tanh_table::TANH_LUT`, input scale `TANH_LUT_INPUT_SCALE`), value for value: then its
/// generated file refers to that table instead of holding a copy.
pub fn shares_core_tanh_table(q: &Quantised) -> bool {
    q.activation == Activation::Tanh
        && q.lut_input_scale == TANH_LUT_INPUT_SCALE
        && q.lut.as_slice() == TANH_LUT.as_slice()
}

/// The rows of an activation table, 16 values a line.
pub(super) fn write_table_rows(o: &mut String, lut: &[i16]) -> Result<()> {
    for chunk in lut.chunks(16) {
        writeln!(
            o,
            "    {},",
            chunk
                .iter()
                .map(|v| v.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        )?;
    }
    Ok(())
}

/// The core's tanh table (`core/src/generated/tanh_table.rs`), as the quantiser makes it.
pub fn render_tanh_table() -> Result<String> {
    let s_z = table_input_scale(Activation::Tanh);
    let mut o = String::new();
    writeln!(
        o,
        "//! GENERATED from the quantiser's table definition (`bearing_train::ann::quant`) — do not"
    )?;
    writeln!(
        o,
        "//! edit. `cargo xtask generate` writes it, `cargo xtask generate --check` compares it."
    )?;
    writeln!(
        o,
        "//! The tanh table of the integer networks (`int`): `TANH_LUT[k] = round(32767·tanh(x_k))`,"
    )?;
    writeln!(
        o,
        "//! `x_k = (64k − 32768)·s_z` on [−8, 8), as the quantiser makes it. The generated networks"
    )?;
    writeln!(
        o,
        "//! whose quantised table is this one, value for value, refer to it (`bearing export`)."
    )?;
    writeln!(o)?;
    writeln!(o, "use super::int::{{Lut, LutLanes}};")?;
    writeln!(o)?;
    writeln!(o, "/// Input scale `s_z` of the table (real = s_z · code).")?;
    writeln!(o, "pub const TANH_LUT_INPUT_SCALE: f64 = {s_z:e};")?;
    writeln!(o, "/// The tanh table.")?;
    writeln!(o, "pub static TANH_LUT: Lut = [")?;
    write_table_rows(&mut o, &table(Activation::Tanh, s_z))?;
    writeln!(o, "];")?;
    writeln!(
        o,
        "/// The host path's copy of the table (`int::LutLanes`)."
    )?;
    writeln!(
        o,
        "pub static TANH_LUT_LANES: LutLanes = LutLanes::new(&TANH_LUT);"
    )?;
    Ok(o)
}

#[cfg(test)]
mod tests {
    use super::super::render;
    use super::*;
    use crate::ann::model::ModelFile;
    use std::path::Path;

    fn line_model() -> ModelFile {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
        ModelFile::load(&root.join("data/ann/numerical_model.json")).unwrap()
    }

    /// The committed line model's quantised table is the core's tanh table: its generated file
    /// refers to that table and holds no copy.
    #[test]
    fn a_network_with_the_core_table_refers_to_it() {
        let m = line_model();
        assert!(shares_core_tanh_table(m.quantised.as_ref().unwrap()));
        let code = render(&m).unwrap();
        assert!(code.contains(
            "pub use super::tanh_table::{TANH_LUT as LUT, TANH_LUT_LANES as LUT_LANES};"
        ));
        assert!(code.contains("use super::int::DenseInt;\n"));
        assert!(!code.contains("pub static LUT"));
    }

    /// A logistic network (the quantiser's table at its input scale) and a tanh network at
    /// another input scale do not share the core's table: the file holds the model's own,
    /// row for row, with its host copy, and does not refer to the core's.
    #[test]
    fn a_network_with_another_table_holds_its_own() {
        for (activation, s_z) in [
            (
                Activation::Logistic,
                table_input_scale(Activation::Logistic),
            ),
            (Activation::Tanh, 4.0 / 32768.0),
        ] {
            let mut m = line_model();
            let lut = table(activation, s_z);
            if let Some(q) = m.quantised.as_mut() {
                q.activation = activation;
                q.lut_input_scale = s_z;
                q.lut = lut.clone();
                assert!(!shares_core_tanh_table(q), "{activation:?}");
            }
            let code = render(&m).unwrap();
            let mut rows = String::new();
            write_table_rows(&mut rows, &lut).unwrap();
            assert!(
                code.contains(&format!("pub static LUT: Lut = [\n{rows}];\n")),
                "{activation:?}"
            );
            assert!(code.contains("pub static LUT_LANES: LutLanes = LutLanes::new(&LUT);"));
            assert!(code.contains("use super::int::{DenseInt, Lut, LutLanes};\n"));
            assert!(!code.contains("tanh_table"), "{activation:?}");
        }
    }
}
