//! Whole-file reading and writing of the binary trace format described in [`super::wire`].
//!
//! Reading checks, in this order: header length, magic, version, header checksum, flags, rate
//! and identifiers; the file length against the count (a partial record is a truncation, a
//! different number of whole records a count mismatch); the records' checksum; then every
//! sample's content ([`super::validate`]). Nothing is allocated before the length is known to
//! match the header, so a hostile count cannot make the reader reserve gigabytes.

use super::validate::{check_meta, check_trace, Numbering, ValidationOptions};
use super::wire::{self, DecodeError, Header, HEADER_LEN, IDENTIFIER_LEN, RECORD_LEN_MAX};
use super::{Location, Problem, Trace, TraceError, TraceMeta};

/// Byte offset in the header of the field an error is about.
fn offset_of(error: &DecodeError) -> usize {
    match error {
        DecodeError::BadMagic => 0,
        DecodeError::UnsupportedVersion(_) => 8,
        DecodeError::UnknownFlags(_) => 10,
        DecodeError::CountMismatch { .. } => 12,
        DecodeError::BadSampleRate => 16,
        DecodeError::BadIdentifier { which } if *which == "lubricant" => 40,
        DecodeError::BadIdentifier { .. } => 24,
        DecodeError::PayloadChecksum { .. } => 56,
        DecodeError::HeaderChecksum { .. } => 60,
        DecodeError::Truncated { actual, .. } => *actual,
    }
}

fn binary_error(error: DecodeError) -> TraceError {
    TraceError::new(Location::Byte(offset_of(&error)), Problem::Binary(error))
}

/// Zero-padded identifier bytes (the caller has checked the identifier).
fn identifier_bytes(id: &str) -> [u8; IDENTIFIER_LEN] {
    let mut out = [0u8; IDENTIFIER_LEN];
    for (dst, src) in out.iter_mut().zip(id.bytes()) {
        *dst = src;
    }
    out
}

/// Decodes and validates a binary trace.
pub fn decode(bytes: &[u8], options: &ValidationOptions) -> Result<Trace, TraceError> {
    let Some(header_bytes) = bytes.get(..HEADER_LEN) else {
        return Err(binary_error(DecodeError::Truncated {
            expected: HEADER_LEN,
            actual: bytes.len(),
        }));
    };
    let mut header_array = [0u8; HEADER_LEN];
    header_array.copy_from_slice(header_bytes);
    let header = Header::parse(&header_array).map_err(binary_error)?;
    header.check_length(bytes.len()).map_err(binary_error)?;

    let payload = bytes.get(HEADER_LEN..).unwrap_or(&[]);
    let mut check = wire::PayloadCheck::default();
    check.feed(payload);
    check.verify(&header).map_err(binary_error)?;

    let record_len = header.record_len();
    let mut samples = Vec::with_capacity(header.count as usize);
    for (index, record) in payload.chunks_exact(record_len).enumerate() {
        let sample = wire::decode_record(record, header.has_tilt).map_err(|e| {
            TraceError::new(Location::Record { index, field: None }, Problem::Binary(e))
        })?;
        samples.push(sample);
    }
    let trace = Trace {
        meta: TraceMeta {
            bearing: wire::identifier_str(&header.bearing_id).to_string(),
            lubricant: wire::identifier_str(&header.lubricant_id).to_string(),
            sample_rate_hz: header.sample_rate_hz,
        },
        samples,
    };
    check_trace(&trace, options, Numbering::Record)?;
    Ok(trace)
}

/// Encodes a trace (metadata checked; the samples are written as they are).
pub fn encode(trace: &Trace) -> Result<Vec<u8>, TraceError> {
    check_meta(&trace.meta).map_err(|p| TraceError::new(Location::File, p))?;
    let count = u32::try_from(trace.samples.len()).map_err(|_| {
        TraceError::new(
            Location::File,
            Problem::BadMeta(format!(
                "{} samples exceed the format's limit of {}",
                trace.samples.len(),
                u32::MAX
            )),
        )
    })?;
    let has_tilt = trace.has_tilt();
    let mut payload = Vec::with_capacity(trace.samples.len() * RECORD_LEN_MAX);
    let mut record = [0u8; RECORD_LEN_MAX];
    for (index, sample) in trace.samples.iter().enumerate() {
        if sample.tilt_rad.is_some() != has_tilt {
            return Err(TraceError::new(
                Location::Record {
                    index,
                    field: Some("tilt_x"),
                },
                Problem::BadMeta("tilt is present in some samples and absent in others".into()),
            ));
        }
        let len = wire::encode_record(sample, &mut record);
        payload.extend_from_slice(&record[..len]);
    }
    let header = Header {
        version: wire::VERSION,
        has_tilt,
        count,
        sample_rate_hz: trace.meta.sample_rate_hz,
        bearing_id: identifier_bytes(&trace.meta.bearing),
        lubricant_id: identifier_bytes(&trace.meta.lubricant),
        payload_crc: super::crc32::crc32(&payload),
    };
    let mut bytes = Vec::with_capacity(HEADER_LEN + payload.len());
    bytes.extend_from_slice(&header.encode());
    bytes.extend_from_slice(&payload);
    Ok(bytes)
}
