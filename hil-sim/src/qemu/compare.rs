//! Reading the firmware's outputs file and comparing it with the host replay of the same trace.
//!
//! Both sides run the same kernel source (`crate::kernel`) on the same decoded f32 inputs, and
//! neither Rust nor LLVM contracts `a * b + c` into a fused multiply-add without being asked, so
//! every f32 output must be bit-identical: the comparison is on the bit patterns, no tolerance.

use crate::kernel::{FilmKind, Kernel};
use crate::outputs::{
    decode_step, record_len, StepCounts, StepOutputs, Trailer, OUTPUT_HEADER_LEN, OUTPUT_MAGIC,
    OUTPUT_VERSION, TRAILER_LEN,
};
use crate::trace::Trace;

/// What the firmware sent back.
#[derive(Clone, Debug, PartialEq)]
pub struct FirmwareRun {
    /// Counters of every step.
    pub counts: Vec<StepCounts>,
    /// Outputs of every step.
    pub outputs: Vec<StepOutputs>,
    /// Stack and calibration.
    pub trailer: Trailer,
}

/// Parses `outputs.bin`, expecting `expected_steps` records.
pub fn parse_outputs(bytes: &[u8], expected_steps: usize) -> Result<FirmwareRun, String> {
    let header = bytes
        .get(..OUTPUT_HEADER_LEN)
        .ok_or("outputs file shorter than its header")?;
    if header.get(..8) != Some(&OUTPUT_MAGIC[..]) {
        return Err("outputs file does not start with BRGSTEPS".into());
    }
    let version = u16::from_le_bytes([header[8], header[9]]);
    if version != OUTPUT_VERSION {
        return Err(format!(
            "outputs format version {version}, expected {OUTPUT_VERSION}"
        ));
    }
    let rollers = usize::from(u16::from_le_bytes([header[10], header[11]]));
    let count = u32::from_le_bytes([header[12], header[13], header[14], header[15]]) as usize;
    if count != expected_steps {
        return Err(format!(
            "the firmware announced {count} steps, the trace has {expected_steps}"
        ));
    }
    let record = record_len(rollers);
    let expected_len = OUTPUT_HEADER_LEN + count * record + TRAILER_LEN;
    if bytes.len() != expected_len {
        return Err(format!(
            "outputs file has {} bytes, {count} steps of {rollers} rollers need {expected_len}",
            bytes.len()
        ));
    }
    let body = &bytes[OUTPUT_HEADER_LEN..OUTPUT_HEADER_LEN + count * record];
    let mut counts = Vec::with_capacity(count);
    let mut outputs = Vec::with_capacity(count);
    for (index, chunk) in body.chunks_exact(record).enumerate() {
        let (c, o) = decode_step(chunk, rollers)
            .ok_or_else(|| format!("step record {index} cannot be decoded"))?;
        counts.push(c);
        outputs.push(o);
    }
    let trailer = Trailer::decode(&bytes[bytes.len() - TRAILER_LEN..])
        .ok_or("outputs file has no BRGEND trailer")?;
    Ok(FirmwareRun {
        counts,
        outputs,
        trailer,
    })
}

/// The host replay of the trace through the same kernel, primed at the first sample and with
/// the friction after every step, as the firmware does.
pub fn host_outputs(trace: &Trace, film: FilmKind) -> Result<Vec<StepOutputs>, String> {
    let mut kernel = Kernel::new(
        &trace.meta.bearing,
        &trace.meta.lubricant,
        trace.meta.sample_rate_hz,
        film,
    )
    .map_err(|e| {
        format!(
            "the kernel refuses the trace: {}",
            crate::wiring::describe(&e)
        )
    })?;
    if let Some(first) = trace.samples.first() {
        kernel.prime(first);
    }
    let mut outputs = vec![StepOutputs::default(); trace.samples.len()];
    for (index, (sample, out)) in trace.samples.iter().zip(outputs.iter_mut()).enumerate() {
        kernel
            .step(sample, out)
            .and_then(|()| kernel.friction(sample, out))
            .map_err(|e| format!("host step {index} failed: {e:?}"))?;
    }
    Ok(outputs)
}

/// The outcome of comparing host and firmware outputs.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Comparison {
    /// Steps compared.
    pub steps: usize,
    /// Steps whose outputs differ in any bit.
    pub mismatched_steps: usize,
    /// The first difference, described.
    pub first_mismatch: Option<String>,
}

/// Names the first differing field of two step outputs, comparing f32 bit patterns.
fn first_difference(host: &StepOutputs, firmware: &StepOutputs) -> Option<String> {
    if host.rollers != firmware.rollers {
        return Some(format!("rollers {} vs {}", host.rollers, firmware.rollers));
    }
    let mut fields: Vec<(String, f32, f32)> = vec![
        ("force_x".into(), host.force_n[0], firmware.force_n[0]),
        ("force_y".into(), host.force_n[1], firmware.force_n[1]),
        (
            "cage_angle".into(),
            host.cage_angle_rad,
            firmware.cage_angle_rad,
        ),
        (
            "friction_torque".into(),
            host.friction_torque_nm,
            firmware.friction_torque_nm,
        ),
        (
            "power_loss".into(),
            host.power_loss_w,
            firmware.power_loss_w,
        ),
    ];
    for (k, part) in ["rolling", "viscous", "boundary"].iter().enumerate() {
        fields.push((
            format!("power_loss_{part}"),
            host.power_loss_split_w[k],
            firmware.power_loss_split_w[k],
        ));
    }
    for j in 0..host.rollers.min(crate::outputs::MAX_ROLLERS) {
        fields.push((
            format!("roller {j} load"),
            host.roller_load_n[j],
            firmware.roller_load_n[j],
        ));
        fields.push((
            format!("roller {j} inner film"),
            host.film_inner_m[j],
            firmware.film_inner_m[j],
        ));
        fields.push((
            format!("roller {j} outer film"),
            host.film_outer_m[j],
            firmware.film_outer_m[j],
        ));
        fields.push((
            format!("roller {j} approach"),
            host.roller_approach_m[j],
            firmware.roller_approach_m[j],
        ));
        if host.source_inner[j] != firmware.source_inner[j]
            || host.source_outer[j] != firmware.source_outer[j]
        {
            return Some(format!("roller {j} film source differs"));
        }
    }
    let differing: Vec<String> = fields
        .into_iter()
        .filter(|(_, h, f)| h.to_bits() != f.to_bits())
        .map(|(name, h, f)| format!("{name}: host {h:e}, firmware {f:e}"))
        .collect();
    match differing.len() {
        0 => None,
        n if n <= 6 => Some(differing.join("; ")),
        n => Some(format!(
            "{}; … ({n} fields differ)",
            differing[..6].join("; ")
        )),
    }
}

/// Compares every step, bit for bit.
pub fn compare(host: &[StepOutputs], firmware: &[StepOutputs]) -> Comparison {
    let mut comparison = Comparison {
        steps: host.len().min(firmware.len()),
        mismatched_steps: host.len().abs_diff(firmware.len()),
        first_mismatch: (host.len() != firmware.len()).then(|| {
            format!(
                "{} host steps, {} firmware steps",
                host.len(),
                firmware.len()
            )
        }),
    };
    for (index, (h, f)) in host.iter().zip(firmware).enumerate() {
        if let Some(difference) = first_difference(h, f) {
            comparison.mismatched_steps += 1;
            comparison
                .first_mismatch
                .get_or_insert_with(|| format!("step {index}: {difference}"));
        }
    }
    comparison
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::outputs::{encode_output_header, encode_step, FilmSource, OUTPUT_RECORD_MAX};

    fn outputs(rollers: usize, seed: f32) -> StepOutputs {
        let mut o = StepOutputs {
            force_n: [seed, -2.0 * seed],
            cage_angle_rad: 0.25 * seed,
            rollers,
            friction_torque_nm: 0.01 * seed,
            power_loss_w: 20.0 * seed,
            power_loss_split_w: [12.0 * seed, 5.0 * seed, 3.0 * seed],
            ..StepOutputs::default()
        };
        for j in 0..rollers {
            o.roller_load_n[j] = seed * j as f32;
            o.film_inner_m[j] = 1.0e-6 * seed;
            o.film_outer_m[j] = 1.1e-6 * seed;
            o.roller_approach_m[j] = -1.0e-6 * j as f32;
            o.source_inner[j] = FilmSource::Regression;
            o.source_outer[j] = FilmSource::Fallback;
        }
        o
    }

    /// The file layout of `crate::outputs`, written by hand here as the firmware writes it.
    fn file(steps: &[StepOutputs], rollers: usize) -> Vec<u8> {
        let mut bytes = encode_output_header(rollers as u16, steps.len() as u32).to_vec();
        let mut record = [0u8; OUTPUT_RECORD_MAX];
        for (i, s) in steps.iter().enumerate() {
            let counts = StepCounts {
                instructions: 1000 + i as u32,
                systick: 168,
                friction_instructions: 30_000 + i as u32,
            };
            let len = encode_step(&counts, s, &mut record);
            bytes.extend_from_slice(&record[..len]);
        }
        let trailer = Trailer {
            status: 0,
            stack_bytes: 4096,
            loop_stack_bytes: 512,
            calibration_instructions: 1000,
            calibration_systick: 168,
        };
        bytes.extend_from_slice(&trailer.encode());
        bytes
    }

    #[test]
    fn outputs_file_round_trips_and_rejects_damage() {
        let steps: Vec<StepOutputs> = (1..=5).map(|i| outputs(17, i as f32)).collect();
        let bytes = file(&steps, 17);
        let run = parse_outputs(&bytes, 5).unwrap();
        assert_eq!(run.outputs, steps);
        assert_eq!(run.counts[3].instructions, 1003);
        assert_eq!(run.counts[3].friction_instructions, 30_003);
        assert_eq!(run.trailer.stack_bytes, 4096);
        assert!(parse_outputs(&bytes, 6).is_err(), "wrong step count");
        assert!(
            parse_outputs(&bytes[..bytes.len() - 1], 5).is_err(),
            "truncated"
        );
        let mut bad_source = bytes.clone();
        // First roller's inner film source of the first record: header 16 + fixed 44 + 16.
        bad_source[16 + 44 + 16] = 9;
        assert!(
            parse_outputs(&bad_source, 5).is_err(),
            "unknown film source"
        );
    }

    /// Reference: a single flipped mantissa bit in one field of one step must be found.
    #[test]
    fn comparison_finds_a_single_bit() {
        let host: Vec<StepOutputs> = (1..=4).map(|i| outputs(12, i as f32)).collect();
        let mut firmware = host.clone();
        assert_eq!(compare(&host, &firmware).mismatched_steps, 0);
        firmware[2].film_outer_m[7] = f32::from_bits(firmware[2].film_outer_m[7].to_bits() ^ 1);
        let c = compare(&host, &firmware);
        assert_eq!(c.mismatched_steps, 1);
        let first = c.first_mismatch.unwrap();
        assert!(first.starts_with("step 2: roller 7 outer film"), "{first}");
        assert_eq!(compare(&host, &firmware[..3]).mismatched_steps, 2);
        let mut firmware = host.clone();
        firmware[1].power_loss_split_w[2] =
            f32::from_bits(firmware[1].power_loss_split_w[2].to_bits() ^ 1);
        let first = compare(&host, &firmware).first_mismatch.unwrap();
        assert!(first.starts_with("step 1: power_loss_boundary"), "{first}");
    }
}
