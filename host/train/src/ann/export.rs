//! Code generation: a model file → the core's generated network
//! (`core/src/generated/model_weights.rs` for the line contact,
//! `core/src/generated/point_model_weights.rs` for the point contact): const arrays and the
//! forward functions of the f32 and integer networks, with layer widths as const generics. The
//! two contacts' files differ in their domain limits and feature selection only; the layers are
//! written by the same code.
//! The output depends only on the network, its normalisation, quantisation and domain (not on
//! the metrics) and is deterministic: `cargo xtask generate --check` regenerates the core's
//! files from the committed model files ([`LINE_MODEL_PATH`], [`POINT_MODEL_PATH`]) and
//! compares them byte for byte.
//!
//! The tanh activation table depends only on the quantiser's table input scale, so the core
//! holds it once, in `core/src/generated/tanh_table.rs` ([`render_tanh_table`]); a network whose
//! quantised table is that one, value for value, refers to it, and any other (a logistic
//! network, or another input scale) gets its own table in its weights file.

use std::fmt::Write;
use std::path::Path;

use anyhow::{bail, Context, Result};
use serde::Serialize;

use super::features::{InputSet, TargetForm};
use super::mlp::Activation;
use super::model::ModelFile;
use super::quant::Quantised;
use super::train::Trained;
use crate::dataset::point_domain::PointDomain;
use tanh_table::write_table_rows;
pub use tanh_table::{render_tanh_table, shares_core_tanh_table, TANH_TABLE_PATH};

mod tanh_table;

/// Where the line contact's network is generated in the core.
pub const LINE_WEIGHTS_PATH: &str = "core/src/generated/model_weights.rs";
/// Where the point contact's network is generated in the core.
pub const POINT_WEIGHTS_PATH: &str = "core/src/generated/point_model_weights.rs";
/// The model file of the core's line-contact network.
pub const LINE_MODEL_PATH: &str = "data/ann/numerical_model.json";
/// The model file of the core's point-contact network.
pub const POINT_MODEL_PATH: &str = "data/ann/point_numerical_model.json";

/// The module the generated networks' layer types, domain limits and input sets come from:
/// the generated files are modules of `film::ann` (`#[path]` from `core/src/generated/`).
const ANN: &str = "super";

/// A model file of either contact, told apart by its input set.
pub enum ContactModel {
    /// A line-contact model (`core::film::ann::AnnF32` / `AnnInt`).
    Line(ModelFile),
    /// A point-contact model (`core::film::ann::PointAnnF32` / `PointAnnInt`).
    Point(ModelFile<PointDomain>),
}

impl ContactModel {
    /// Read a model file, as the contact its input set belongs to.
    pub fn load(path: &Path) -> Result<Self> {
        let text = std::fs::read_to_string(path)
            .with_context(|| format!("reading model {}", path.display()))?;
        let value: serde_json::Value = serde_json::from_str(&text)
            .with_context(|| format!("{} is not a film model file", path.display()))?;
        let inputs = &value["trained"]["options"]["inputs"];
        let point = matches!(inputs.as_str(), Some("mlk" | "mlk-g-eta-modulus"));
        Ok(if point {
            Self::Point(ModelFile::load(path)?)
        } else {
            Self::Line(ModelFile::load(path)?)
        })
    }

    /// The generated source.
    pub fn render(&self) -> Result<String> {
        match self {
            Self::Line(m) => render(m),
            Self::Point(m) => render_point(m),
        }
    }

    /// The generated file's path in the repository.
    pub fn default_out(&self) -> &'static str {
        match self {
            Self::Line(_) => LINE_WEIGHTS_PATH,
            Self::Point(_) => POINT_WEIGHTS_PATH,
        }
    }

    /// The integer layers (for `bearing export`'s notes on the host's requantisation path and
    /// on the activation table).
    pub fn quantised(&self) -> Option<&Quantised> {
        match self {
            Self::Line(m) => m.quantised.as_ref(),
            Self::Point(m) => m.quantised.as_ref(),
        }
    }
}

/// FNV-1a (64 bit) of the parts of a line-contact model the generated code depends on.
pub fn fingerprint(model: &ModelFile) -> Result<String> {
    fingerprint_of(model)
}

/// FNV-1a (64 bit) of the parts of a model of either contact the generated code depends on.
pub fn fingerprint_of<D: Serialize>(model: &ModelFile<D>) -> Result<String> {
    let text = serde_json::to_string(&(
        &model.trained.net,
        &model.trained.input_norm,
        &model.trained.output_norm,
        model.trained.options.inputs,
        model.trained.options.target,
        &model.quantised,
        &model.domain,
    ))?;
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in text.bytes() {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0000_0100_0000_01b3);
    }
    Ok(format!("{h:016x}"))
}

fn f(v: f64) -> String {
    let s = format!("{:?}", v as f32);
    s
}

fn f_list(v: impl IntoIterator<Item = f64>) -> String {
    v.into_iter().map(f).collect::<Vec<_>>().join(", ")
}

fn act_name(a: Activation) -> &'static str {
    match a {
        Activation::Tanh => "Tanh",
        Activation::Logistic => "Logistic",
        Activation::Relu => "Relu",
    }
}

/// The quantised network and the output form's name, or why the model cannot be exported.
fn exportable<D>(model: &ModelFile<D>) -> Result<(&Quantised, &'static str)> {
    let q = match &model.quantised {
        Some(q) => q,
        None => bail!("the model has no quantised network; train it again (quantisation is part of `bearing train`)"),
    };
    let target = match model.trained.options.target {
        TargetForm::LogRatio => "LogRatio",
        TargetForm::LogHr => "LogHr",
        TargetForm::Direct => {
            bail!("a direct-film model cannot be exported: it may predict negative films")
        }
    };
    Ok((q, target))
}

/// The `use` of the integer layer types: the table types only for a network that holds its
/// own table.
fn write_int_use(o: &mut String, q: &Quantised) -> Result<()> {
    if q.lut.is_empty() || shares_core_tanh_table(q) {
        writeln!(o, "use {ANN}::int::DenseInt;")?;
    } else {
        writeln!(o, "use {ANN}::int::{{DenseInt, Lut, LutLanes}};")?;
    }
    Ok(())
}

/// The file's doc header: how it is made, provenance and shape.
fn write_header<D>(o: &mut String, model: &ModelFile<D>, n_in: usize, from: &str) -> Result<()> {
    let t = &model.trained;
    let prov = &model.provenance;
    let bits = model.quantised.as_ref().map_or(0, |q| q.weight_bits);
    writeln!(
        o,
        "//! GENERATED from a model file (the core's: `{from}`) — do not edit."
    )?;
    writeln!(
        o,
        "//! `cargo xtask generate` writes it, `cargo xtask generate --check` compares it."
    )?;
    writeln!(
        o,
        "//! Source: dataset `{}` (seed {}, solver {} {}).",
        prov.dataset_file, prov.dataset_seed, prov.solver.name, prov.solver.version
    )?;
    let widths: Vec<String> = t
        .net
        .layers
        .iter()
        .map(|l| l.bias.len().to_string())
        .collect();
    writeln!(
        o,
        "//! Network: {} inputs → {} ({} hidden, linear output); {}-bit weights.",
        n_in,
        widths.join(" → "),
        t.net.activation.name(),
        bits
    )?;
    writeln!(o)?;
    Ok(())
}

/// Fingerprint, input set, input count, output form and activation.
fn write_identity<D: Serialize>(
    o: &mut String,
    model: &ModelFile<D>,
    input_set: &str,
    n_in: usize,
    target: &str,
) -> Result<()> {
    writeln!(
        o,
        "/// Fingerprint of the model parts this file was generated from."
    )?;
    writeln!(
        o,
        "pub const MODEL_FINGERPRINT: &str = \"{}\";",
        fingerprint_of(model)?
    )?;
    writeln!(o, "/// Input set.")?;
    writeln!(o, "pub const INPUT_SET: {input_set};")?;
    writeln!(o, "/// Number of network inputs.")?;
    writeln!(o, "pub const N_IN: usize = {n_in};")?;
    writeln!(o, "/// Output form.")?;
    writeln!(o, "pub const TARGET: TargetForm = TargetForm::{target};")?;
    writeln!(o, "/// Hidden activation.")?;
    writeln!(
        o,
        "pub const ACTIVATION: Activation = Activation::{};",
        act_name(model.trained.net.activation)
    )?;
    Ok(())
}

/// `[min, max]` of an interval with the 10⁻⁵ relative slack, as f32 literals.
fn slack_interval(i: &crate::dataset::domain::Interval) -> String {
    format!("[{}, {}]", f(i.min * (1.0 - 1e-5)), f(i.max * (1.0 + 1e-5)))
}

/// `[ln min, ln max]` of an interval with the 10⁻⁵ relative slack.
fn slack_ln_interval(i: &crate::dataset::domain::Interval) -> String {
    format!(
        "[{}, {}]",
        f((i.min * (1.0 - 1e-5)).ln()),
        f((i.max * (1.0 + 1e-5)).ln())
    )
}

/// Feature and target normalisation and the integer output step, then a blank line.
fn write_normalisation(o: &mut String, t: &Trained, q: &Quantised) -> Result<()> {
    writeln!(
        o,
        "/// Minimum of each feature (normalisation `x = (f − min)·scale − 1`)."
    )?;
    writeln!(
        o,
        "pub const INPUT_MIN: [f32; N_IN] = [{}];",
        f_list(t.input_norm.min.iter().copied())
    )?;
    writeln!(o, "/// `2/(max − min)` of each feature.")?;
    writeln!(
        o,
        "pub const INPUT_SCALE: [f32; N_IN] = [{}];",
        f_list(
            t.input_norm
                .min
                .iter()
                .zip(&t.input_norm.max)
                .map(|(lo, hi)| 2.0 / (hi - lo))
        )
    )?;
    writeln!(
        o,
        "/// Minimum of each target (`t = min + (y + 1)·half_range`)."
    )?;
    writeln!(
        o,
        "pub const OUTPUT_MIN: [f32; 2] = [{}];",
        f_list(t.output_norm.min.iter().copied())
    )?;
    writeln!(o, "/// Half range of each target.")?;
    writeln!(
        o,
        "pub const OUTPUT_HALF_RANGE: [f32; 2] = [{}];",
        f_list(
            t.output_norm
                .min
                .iter()
                .zip(&t.output_norm.max)
                .map(|(lo, hi)| 0.5 * (hi - lo))
        )
    )?;
    writeln!(o, "/// Dequantisation step of the integer output.")?;
    writeln!(o, "pub const INT_OUTPUT_STEP: f32 = {};", f(q.output_step))?;
    writeln!(o)?;
    Ok(())
}

/// `select_features` out of the contact's full feature list.
fn write_select(o: &mut String, doc: &str, n_all: usize, select: &str) -> Result<()> {
    writeln!(o, "/// The network's features out of {doc}.")?;
    writeln!(o, "#[inline(always)]")?;
    writeln!(
        o,
        "pub fn select_features(f: &[f32; {n_all}]) -> [f32; N_IN] {{"
    )?;
    writeln!(o, "    {select}")?;
    writeln!(o, "}}")?;
    Ok(())
}

/// Render the line contact's generated Rust source.
pub fn render(model: &ModelFile) -> Result<String> {
    let (q, target) = exportable(model)?;
    let (n_in, select, input_set) = match model.trained.options.inputs {
        InputSet::Wug => (3, "[f[0], f[1], f[2]]", "Wug"),
        InputSet::WugEtaModulus => (5, "*f", "WugEtaModulus"),
        InputSet::Mlk | InputSet::MlkGEtaModulus => {
            bail!("a point-contact model: export it with `render_point` (`bearing export` tells the contacts apart)")
        }
    };
    let mut o = String::new();
    write_header(&mut o, model, n_in, LINE_MODEL_PATH)?;
    writeln!(o, "use {ANN}::float::{{Activation, DenseF32}};")?;
    write_int_use(&mut o, q)?;
    writeln!(o, "use {ANN}::{{DomainLimits, InputSet, TargetForm}};")?;
    writeln!(o)?;
    write_identity(
        &mut o,
        model,
        &format!("InputSet = InputSet::{input_set}"),
        n_in,
        target,
    )?;
    let d = &model.domain;
    writeln!(o, "/// Training domain (10⁻⁵ relative slack).")?;
    writeln!(o, "pub const DOMAIN: DomainLimits = DomainLimits {{")?;
    writeln!(
        o,
        "    inputs: [{}, {}, {}, {}, {}, {}, {}],",
        slack_interval(&d.load_n),
        slack_interval(&d.entrainment_speed_m_s),
        slack_interval(&d.reduced_radius_m),
        slack_interval(&d.reduced_modulus_pa),
        slack_interval(&d.pressure_viscosity_pa_inv),
        slack_interval(&d.viscosity_pa_s),
        slack_interval(&d.length_m)
    )?;
    writeln!(
        o,
        "    ln_hertz_pressure: {},",
        slack_ln_interval(&d.hertz_pressure_pa)
    )?;
    writeln!(
        o,
        "    piezo_min_log_ratio: {},",
        f(d.regime.piezo_min_log_ratio - 1e-5)
    )?;
    writeln!(
        o,
        "    elastic_max_log_ratio: {},",
        f(d.regime.elastic_max_log_ratio + 1e-5)
    )?;
    writeln!(o, "}};")?;
    write_normalisation(&mut o, &model.trained, q)?;
    write_select(&mut o, "(ln W, ln U, ln G, ln η₀, E'/GPa)", 5, select)?;
    write_layers(&mut o, &model.trained, q)?;
    Ok(o)
}

/// Render the point contact's generated Rust source (`core::film::ann::point`).
pub fn render_point(model: &ModelFile<PointDomain>) -> Result<String> {
    let (q, target) = exportable(model)?;
    let (n_in, select, input_set) = match model.trained.options.inputs {
        InputSet::Mlk => (3, "[f[0], f[1], f[2]]", "Mlk"),
        InputSet::MlkGEtaModulus => (6, "*f", "MlkGEtaModulus"),
        InputSet::Wug | InputSet::WugEtaModulus => {
            bail!("a line-contact model: export it with `render`")
        }
    };
    let mut o = String::new();
    write_header(&mut o, model, n_in, POINT_MODEL_PATH)?;
    writeln!(o, "use {ANN}::float::{{Activation, DenseF32}};")?;
    write_int_use(&mut o, q)?;
    writeln!(o, "use {ANN}::point::{{PointDomainLimits, PointInputSet}};")?;
    writeln!(o, "use {ANN}::TargetForm;")?;
    writeln!(o)?;
    write_identity(
        &mut o,
        model,
        &format!("PointInputSet = PointInputSet::{input_set}"),
        n_in,
        target,
    )?;
    let d = &model.domain;
    writeln!(o, "/// Training domain (10⁻⁵ relative slack).")?;
    writeln!(
        o,
        "pub const DOMAIN: PointDomainLimits = PointDomainLimits {{"
    )?;
    writeln!(
        o,
        "    inputs: [{}, {}, {}, {}, {}, {}, {}],",
        slack_interval(&d.load_n),
        slack_interval(&d.entrainment_speed_m_s),
        slack_interval(&d.radius_x_m),
        slack_interval(&d.radius_ratio),
        slack_interval(&d.reduced_modulus_pa),
        slack_interval(&d.pressure_viscosity_pa_inv),
        slack_interval(&d.viscosity_pa_s)
    )?;
    writeln!(
        o,
        "    ln_hertz_pressure: {},",
        slack_ln_interval(&d.hertz_pressure_pa)
    )?;
    writeln!(o, "    ln_moes_m: {},", slack_ln_interval(&d.moes_m))?;
    writeln!(
        o,
        "    ln_m_per_ellipticity: {},",
        f((d.m_per_ellipticity * (1.0 + 1e-5)).ln())
    )?;
    writeln!(
        o,
        "    ln_elongated_from_ellipticity: {},",
        f((d.elongated_from_ellipticity * (1.0 - 1e-5)).ln())
    )?;
    writeln!(
        o,
        "    ln_elongated_m_per_ellipticity: {},",
        f((d.elongated_m_per_ellipticity * (1.0 + 1e-5)).ln())
    )?;
    writeln!(o, "    ln_moes_l: {},", slack_ln_interval(&d.moes_l))?;
    writeln!(o, "}};")?;
    write_normalisation(&mut o, &model.trained, q)?;
    write_select(&mut o, "(ln M, ln L, ln k, ln G, ln η₀, E'/GPa)", 6, select)?;
    write_layers(&mut o, &model.trained, q)?;
    Ok(o)
}

/// The f32 and integer layers, the activation table and the two forward functions.
fn write_layers(o: &mut String, t: &Trained, q: &Quantised) -> Result<()> {
    // f32 layers.
    let n_layers = t.net.layers.len();
    for (k, l) in t.net.layers.iter().enumerate() {
        let (i, out) = (l.weights.first().map_or(0, Vec::len), l.bias.len());
        writeln!(o)?;
        writeln!(o, "/// f32 layer {k}.")?;
        writeln!(
            o,
            "pub static F32_LAYER_{k}: DenseF32<{i}, {out}> = DenseF32::new("
        )?;
        writeln!(o, "    [")?;
        for row in &l.weights {
            writeln!(o, "        [{}],", f_list(row.iter().copied()))?;
        }
        writeln!(o, "    ],")?;
        writeln!(o, "    [{}],", f_list(l.bias.iter().copied()))?;
        writeln!(o, ");")?;
    }
    writeln!(o)?;
    writeln!(o, "/// The f32 network on normalised features.")?;
    writeln!(o, "#[inline]")?;
    writeln!(o, "pub fn forward_f32(x: &[f32; N_IN]) -> [f32; 2] {{")?;
    for k in 0..n_layers {
        let src = if k == 0 { "x" } else { "&a" };
        if k + 1 < n_layers {
            writeln!(o, "    let a = F32_LAYER_{k}.forward({src}, ACTIVATION);")?;
        } else {
            writeln!(o, "    F32_LAYER_{k}.affine({src})")?;
        }
    }
    writeln!(o, "}}")?;
    // Integer layers.
    for (k, l) in q.layers.iter().enumerate() {
        let (i, out) = (l.weights.first().map_or(0, Vec::len), l.bias.len());
        writeln!(o)?;
        writeln!(
            o,
            "/// Integer layer {k} (weight scale {:e}, requantised to {:e}).",
            l.weight_scale, l.target_scale
        )?;
        writeln!(
            o,
            "pub static INT_LAYER_{k}: DenseInt<{i}, {out}> = DenseInt::new("
        )?;
        writeln!(o, "    [")?;
        for row in &l.weights {
            writeln!(
                o,
                "        [{}],",
                row.iter()
                    .map(|v| v.to_string())
                    .collect::<Vec<_>>()
                    .join(", ")
            )?;
        }
        writeln!(o, "    ],")?;
        writeln!(
            o,
            "    [{}],",
            l.bias
                .iter()
                .map(|v| v.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        )?;
        writeln!(o, "    {},", l.multiplier)?;
        writeln!(o, "    {},", l.shift)?;
        writeln!(o, ");")?;
    }
    if shares_core_tanh_table(q) {
        writeln!(o)?;
        writeln!(
            o,
            "/// Activation table: the core's tanh table (`tanh_table`), input scale {:e}.",
            q.lut_input_scale
        )?;
        writeln!(
            o,
            "pub use super::tanh_table::{{TANH_LUT as LUT, TANH_LUT_LANES as LUT_LANES}};"
        )?;
    } else if !q.lut.is_empty() {
        writeln!(o)?;
        writeln!(
            o,
            "/// Activation table, input scale {:e}.",
            q.lut_input_scale
        )?;
        writeln!(o, "pub static LUT: Lut = [")?;
        write_table_rows(o, &q.lut)?;
        writeln!(o, "];")?;
        writeln!(
            o,
            "/// The host path's copy of the activation table (`int::LutLanes`)."
        )?;
        writeln!(o, "pub static LUT_LANES: LutLanes = LutLanes::new(&LUT);")?;
    }
    writeln!(o)?;
    writeln!(o, "/// The integer network on quantised features.")?;
    writeln!(o, "#[inline]")?;
    writeln!(o, "pub fn forward_int(x: &[i16; N_IN]) -> [i16; 2] {{")?;
    for k in 0..n_layers {
        let src = if k == 0 { "x" } else { "&a" };
        if k + 1 < n_layers {
            if q.activation == Activation::Relu {
                writeln!(o, "    let a = INT_LAYER_{k}.relu_layer({src});")?;
            } else {
                writeln!(
                    o,
                    "    let a = INT_LAYER_{k}.lut_layer({src}, &LUT, &LUT_LANES);"
                )?;
            }
        } else {
            writeln!(o, "    INT_LAYER_{k}.output_layer({src})")?;
        }
    }
    writeln!(o, "}}")?;
    Ok(())
}
