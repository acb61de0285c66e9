//! What each fuzz target checks, on one input. Shared by the libFuzzer targets
//! (`fuzz/fuzz_targets/*.rs`) and by the corpus replay in the main workspace's tests
//! (`tests/tests/fuzz_corpora.rs`), which runs every saved input of `fuzz/corpus/<target>/`
//! on the stable toolchain.

// Each fuzz target uses one of these functions.
#![allow(dead_code)]

use bearing_core::{Bearing, BearingDesign, BearingOutput, FilmKind, OperatingState};
use bearing_trace::{binary, csv, ValidationOptions};

/// Binary trace decoder (header, records, CRC, validation): a trace or an error, never a
/// panic; an accepted trace re-encodes to the same bytes.
pub fn trace_binary(data: &[u8]) {
    if let Ok(trace) = binary::decode(data, &ValidationOptions::default()) {
        let again = binary::encode(&trace).expect("an accepted trace encodes");
        assert_eq!(again, data, "decode/encode round trip");
    }
}

/// CSV trace reader: a trace or an error, never a panic; an accepted trace renders to CSV that
/// reads back with the same samples.
pub fn trace_csv(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let options = ValidationOptions::default();
    if let Ok(trace) = csv::parse(text, &options) {
        let again = csv::parse(&csv::render(&trace), &options).expect("a rendered trace reads");
        assert_eq!(again.samples.len(), trace.samples.len());
    }
}

/// Bearing configuration loader: validated parameters or an error, never a panic; accepted
/// parameters build a bearing of every film model.
pub fn bearing_toml(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let path = std::path::Path::new("fuzz.toml");
    if let Ok((_, params)) = bearing_host_common::config::BearingConfig::parse(text, path) {
        for film in FilmKind::ALL {
            let _ = bearing_host_common::rolling::boxed(params, film);
        }
    }
}

/// Shaft model loader: an assembled model or an error naming file, line and field, never a
/// panic. Relative bearing files resolve against configs/.
pub fn shaft_toml(data: &[u8]) {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let path = std::path::Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/../configs/fuzz.toml"));
    let _ = bearing_shaft::config::parse_model(path, text);
}

const SLICES: usize = bearing_core::bearing::SLICES;
/// Bytes per step: 7 state fields and the time step as f32 bit patterns, and a selector byte.
const STEP_BYTES: usize = 33;

/// The core's step on raw bytes: the first byte picks the bearing (hub motor or NU 205) and
/// the film model, the rest is a sequence of [`STEP_BYTES`]-byte steps (the selector's low bit
/// picks `advance` or `evaluate`) with the warm start carried. Nothing panics, and an accepted
/// step has finite outputs and non-negative films and loads.
pub fn core_step(data: &[u8]) {
    let Some((&pick, steps)) = data.split_first() else {
        return;
    };
    let film = FilmKind::ALL[(pick & 3) as usize];
    if pick & 4 == 0 {
        run::<17>(BearingDesign::HUB_MOTOR, film, steps);
    } else {
        run::<12>(BearingDesign::NU205, film, steps);
    }
}

fn run<const Z: usize>(design: BearingDesign, film: FilmKind, steps: &[u8]) {
    let params = design.params().expect("a bundled design");
    let mut b = Bearing::<Z, SLICES>::new(params, film).expect("a bundled design");
    for chunk in steps.chunks_exact(STEP_BYTES) {
        let f = |i: usize| {
            f32::from_le_bytes([
                chunk[4 * i],
                chunk[4 * i + 1],
                chunk[4 * i + 2],
                chunk[4 * i + 3],
            ])
        };
        let state = OperatingState {
            displacement_m: [f(0), f(1)],
            velocity_m_s: [f(2), f(3)],
            tilt_rad: [f(4), f(5)],
            shaft_speed_rad_s: f(6),
        };
        let out = if chunk[32] & 1 == 0 {
            b.advance(&state, f(7)).ok().copied()
        } else {
            b.evaluate(&state, f(7)).ok().copied()
        };
        if let Some(out) = out {
            check_output(&out);
        }
    }
}

fn check_output<const Z: usize>(out: &BearingOutput<Z>) {
    assert!(out
        .force_n
        .iter()
        .chain(&out.moment_nm)
        .chain(out.stiffness.iter().flatten())
        .chain(out.damping_n_s_per_m.iter().flatten())
        .all(|x| x.is_finite()));
    for r in &out.rollers {
        for h in [
            r.central_film_in_m,
            r.central_film_out_m,
            r.min_film_in_m,
            r.min_film_out_m,
            r.load_n,
        ] {
            assert!(h.is_finite() && h >= 0.0, "{r:?}");
        }
    }
}
