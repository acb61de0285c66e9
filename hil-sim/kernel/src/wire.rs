//! The binary trace format: byte layout, header and record codec, shared by host and firmware.
//!
//! A trace file is a 64-byte header followed by `count` fixed-size records, all little-endian:
//!
//! | offset | size | field |
//! |---:|---:|---|
//! | 0 | 8 | magic `BRGTRACE` |
//! | 8 | 2 | format version (u16, currently 1) |
//! | 10 | 2 | flags (u16; bit 0: records carry tilt about x and y) |
//! | 12 | 4 | record count (u32) |
//! | 16 | 8 | sample rate, Hz (f64) |
//! | 24 | 16 | bearing identifier (ASCII, zero-padded) |
//! | 40 | 16 | lubricant identifier (ASCII, zero-padded) |
//! | 56 | 4 | CRC-32 of all record bytes |
//! | 60 | 4 | CRC-32 of header bytes 0..60 |
//!
//! A record is time (s, f64), shaft speed (rad/s), inner-race displacement x, y (m) and velocity
//! vx, vy (m/s) as f32 — 28 bytes — plus tilt about x and y (rad, f32) when flag bit 0 is set —
//! 36 bytes. Time is f64 because an f32 clock at 100 kHz loses the sample period after a few
//! seconds; the kinematics are f32 because that is what the core computes with.
//!
//! The header carries its own checksum so that a reader that streams the records (the firmware
//! reads them in chunks over semihosting) can trust the count and the flags before reading any
//! record, and checks the records' checksum when the stream ends.
//!
//! This file uses nothing from `std` (no allocation): the firmware uses it through this crate,
//! next to `crc32.rs`, so host and firmware decode with the same code.

use super::crc32::{crc32, Crc32};

/// The first eight bytes of every trace file.
pub const MAGIC: [u8; 8] = *b"BRGTRACE";
/// The format version this code writes and reads.
pub const VERSION: u16 = 1;
/// Header size in bytes.
pub const HEADER_LEN: usize = 64;
/// Capacity of an identifier (bytes).
pub const IDENTIFIER_LEN: usize = 16;
/// Flag bit: records carry tilt about x and y.
pub const FLAG_TILT: u16 = 1;
/// Record size without tilt (bytes).
pub const RECORD_LEN_PLAIN: usize = 28;
/// Record size with tilt (bytes).
pub const RECORD_LEN_TILT: usize = 36;
/// Largest record size, the buffer a streaming reader needs.
pub const RECORD_LEN_MAX: usize = RECORD_LEN_TILT;

/// Names of the record fields in file order (also the CSV column stems).
pub const FIELD_NAMES: [&str; 8] = ["time", "speed", "x", "y", "vx", "vy", "tilt_x", "tilt_y"];

/// One recorded instant of the bearing's kinematics.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// Time since the start of the recording, t (s).
    pub time_s: f64,
    /// Shaft (inner-ring) angular speed, ω (rad/s).
    pub speed_rad_s: f32,
    /// Inner-race displacement in x, relative to the outer race (m).
    pub x_m: f32,
    /// Inner-race displacement in y (m).
    pub y_m: f32,
    /// Inner-race velocity in x (m/s).
    pub vx_m_s: f32,
    /// Inner-race velocity in y (m/s).
    pub vy_m_s: f32,
    /// Inner-race tilt about the x and y axes (rad), when the trace records it.
    pub tilt_rad: Option<[f32; 2]>,
}

/// What is wrong with a binary trace. No allocation, so the firmware can report it too.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DecodeError {
    /// The file ends inside the header or inside a record.
    Truncated {
        /// Bytes the layout needs.
        expected: usize,
        /// Bytes present.
        actual: usize,
    },
    /// The first eight bytes are not `BRGTRACE`.
    BadMagic,
    /// A version this reader does not know.
    UnsupportedVersion(u16),
    /// Flag bits this reader does not know.
    UnknownFlags(u16),
    /// The header's checksum does not match its bytes.
    HeaderChecksum {
        /// Stored in the file.
        stored: u32,
        /// Computed from the bytes.
        computed: u32,
    },
    /// The records' checksum does not match their bytes.
    PayloadChecksum {
        /// Stored in the header.
        stored: u32,
        /// Computed from the bytes.
        computed: u32,
    },
    /// The file holds a different number of whole records than the header states.
    CountMismatch {
        /// Count in the header.
        header: u32,
        /// Whole records in the file.
        found: usize,
    },
    /// The sample rate is not a finite positive number.
    BadSampleRate,
    /// An identifier is empty or holds bytes other than `[A-Za-z0-9_.-]` before its padding.
    BadIdentifier {
        /// Which one: `"bearing"` or `"lubricant"`.
        which: &'static str,
    },
}

/// The decoded header.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Header {
    /// Format version.
    pub version: u16,
    /// Records carry tilt.
    pub has_tilt: bool,
    /// Number of records.
    pub count: u32,
    /// Sample rate (Hz).
    pub sample_rate_hz: f64,
    /// Bearing identifier, zero-padded ASCII.
    pub bearing_id: [u8; IDENTIFIER_LEN],
    /// Lubricant identifier, zero-padded ASCII.
    pub lubricant_id: [u8; IDENTIFIER_LEN],
    /// CRC-32 of the record bytes.
    pub payload_crc: u32,
}

/// True for the bytes an identifier may hold.
pub fn is_identifier_byte(byte: u8) -> bool {
    byte.is_ascii_alphanumeric() || byte == b'_' || byte == b'-' || byte == b'.'
}

/// Checks a zero-padded identifier: 1..=16 allowed bytes, then only zeros.
fn check_identifier(id: &[u8; IDENTIFIER_LEN], which: &'static str) -> Result<(), DecodeError> {
    let used = id.iter().position(|&b| b == 0).unwrap_or(IDENTIFIER_LEN);
    let (text, padding) = id.split_at(used);
    if text.is_empty()
        || !text.iter().all(|&b| is_identifier_byte(b))
        || padding.iter().any(|&b| b != 0)
    {
        return Err(DecodeError::BadIdentifier { which });
    }
    Ok(())
}

/// The identifier as text (its bytes are checked ASCII, so this cannot fail on a parsed header).
pub fn identifier_str(id: &[u8; IDENTIFIER_LEN]) -> &str {
    let used = id.iter().position(|&b| b == 0).unwrap_or(IDENTIFIER_LEN);
    let (text, _) = id.split_at(used);
    core::str::from_utf8(text).unwrap_or("")
}

/// Reads `N` bytes at `offset` of the header.
fn field<const N: usize>(bytes: &[u8; HEADER_LEN], offset: usize) -> [u8; N] {
    let mut out = [0u8; N];
    if let Some(src) = bytes.get(offset..offset + N) {
        out.copy_from_slice(src);
    }
    out
}

impl Header {
    /// Size of one record of this trace (bytes).
    pub fn record_len(&self) -> usize {
        if self.has_tilt {
            RECORD_LEN_TILT
        } else {
            RECORD_LEN_PLAIN
        }
    }

    /// Parses and checks a header: magic, version, flags, its checksum, rate and identifiers.
    pub fn parse(bytes: &[u8; HEADER_LEN]) -> Result<Header, DecodeError> {
        if field::<8>(bytes, 0) != MAGIC {
            return Err(DecodeError::BadMagic);
        }
        let version = u16::from_le_bytes(field(bytes, 8));
        if version != VERSION {
            return Err(DecodeError::UnsupportedVersion(version));
        }
        let stored = u32::from_le_bytes(field(bytes, 60));
        let computed = crc32(bytes.get(..60).unwrap_or(&[]));
        if stored != computed {
            return Err(DecodeError::HeaderChecksum { stored, computed });
        }
        let flags = u16::from_le_bytes(field(bytes, 10));
        if flags & !FLAG_TILT != 0 {
            return Err(DecodeError::UnknownFlags(flags));
        }
        let sample_rate_hz = f64::from_le_bytes(field(bytes, 16));
        if !(sample_rate_hz.is_finite() && sample_rate_hz > 0.0) {
            return Err(DecodeError::BadSampleRate);
        }
        let bearing_id = field(bytes, 24);
        check_identifier(&bearing_id, "bearing")?;
        let lubricant_id = field(bytes, 40);
        check_identifier(&lubricant_id, "lubricant")?;
        Ok(Header {
            version,
            has_tilt: flags & FLAG_TILT != 0,
            count: u32::from_le_bytes(field(bytes, 12)),
            sample_rate_hz,
            bearing_id,
            lubricant_id,
            payload_crc: u32::from_le_bytes(field(bytes, 56)),
        })
    }

    /// Writes the header, computing its own checksum (the payload checksum must be set).
    pub fn encode(&self) -> [u8; HEADER_LEN] {
        let mut out = [0u8; HEADER_LEN];
        let flags = if self.has_tilt { FLAG_TILT } else { 0 };
        let parts: [(usize, &[u8]); 8] = [
            (0, &MAGIC),
            (8, &self.version.to_le_bytes()),
            (10, &flags.to_le_bytes()),
            (12, &self.count.to_le_bytes()),
            (16, &self.sample_rate_hz.to_le_bytes()),
            (24, &self.bearing_id),
            (40, &self.lubricant_id),
            (56, &self.payload_crc.to_le_bytes()),
        ];
        for (offset, part) in parts {
            if let Some(dst) = out.get_mut(offset..offset + part.len()) {
                dst.copy_from_slice(part);
            }
        }
        let header_crc = crc32(out.get(..60).unwrap_or(&[]));
        if let Some(dst) = out.get_mut(60..64) {
            dst.copy_from_slice(&header_crc.to_le_bytes());
        }
        out
    }

    /// Checks that a file of `file_len` bytes holds exactly `count` records after the header.
    /// A partial record is a truncation; a different number of whole records a count mismatch.
    pub fn check_length(&self, file_len: usize) -> Result<(), DecodeError> {
        let record_len = self.record_len();
        let expected = (self.count as usize)
            .saturating_mul(record_len)
            .saturating_add(HEADER_LEN);
        if file_len == expected {
            return Ok(());
        }
        let payload = file_len.saturating_sub(HEADER_LEN);
        if payload % record_len != 0 {
            return Err(DecodeError::Truncated {
                expected,
                actual: file_len,
            });
        }
        Err(DecodeError::CountMismatch {
            header: self.count,
            found: payload / record_len,
        })
    }
}

/// Reads a little-endian f32 at `offset` of a record (zero when out of range, which the fixed
/// record layout excludes).
fn f32_at(record: &[u8], offset: usize) -> f32 {
    let mut word = [0u8; 4];
    if let Some(src) = record.get(offset..offset + 4) {
        word.copy_from_slice(src);
    }
    f32::from_le_bytes(word)
}

/// Decodes one record; `record` must hold at least [`Header::record_len`] bytes.
pub fn decode_record(record: &[u8], has_tilt: bool) -> Result<Sample, DecodeError> {
    let needed = if has_tilt {
        RECORD_LEN_TILT
    } else {
        RECORD_LEN_PLAIN
    };
    let Some(time_bytes) = record.get(0..8) else {
        return Err(DecodeError::Truncated {
            expected: needed,
            actual: record.len(),
        });
    };
    if record.len() < needed {
        return Err(DecodeError::Truncated {
            expected: needed,
            actual: record.len(),
        });
    }
    let mut time = [0u8; 8];
    time.copy_from_slice(time_bytes);
    Ok(Sample {
        time_s: f64::from_le_bytes(time),
        speed_rad_s: f32_at(record, 8),
        x_m: f32_at(record, 12),
        y_m: f32_at(record, 16),
        vx_m_s: f32_at(record, 20),
        vy_m_s: f32_at(record, 24),
        tilt_rad: if has_tilt {
            Some([f32_at(record, 28), f32_at(record, 32)])
        } else {
            None
        },
    })
}

/// Encodes one record into `out`, returning the bytes written (28, or 36 with tilt).
pub fn encode_record(sample: &Sample, out: &mut [u8; RECORD_LEN_MAX]) -> usize {
    let mut words = [0f32; 7];
    words[0] = sample.speed_rad_s;
    words[1] = sample.x_m;
    words[2] = sample.y_m;
    words[3] = sample.vx_m_s;
    words[4] = sample.vy_m_s;
    let mut len = RECORD_LEN_PLAIN;
    if let Some([tilt_x, tilt_y]) = sample.tilt_rad {
        words[5] = tilt_x;
        words[6] = tilt_y;
        len = RECORD_LEN_TILT;
    }
    out[..8].copy_from_slice(&sample.time_s.to_le_bytes());
    for (chunk, word) in out[8..].chunks_exact_mut(4).zip(words) {
        chunk.copy_from_slice(&word.to_le_bytes());
    }
    len
}

/// Running checksum of the records, for a reader that streams them.
#[derive(Clone, Copy, Debug, Default)]
pub struct PayloadCheck {
    crc: Crc32,
}

impl PayloadCheck {
    /// Feeds the bytes of one record (or any piece of the record stream).
    pub fn feed(&mut self, bytes: &[u8]) {
        self.crc.update(bytes);
    }

    /// Compares the sum of everything fed with the header's payload checksum.
    pub fn verify(&self, header: &Header) -> Result<(), DecodeError> {
        let computed = self.crc.finish();
        if computed == header.payload_crc {
            Ok(())
        } else {
            Err(DecodeError::PayloadChecksum {
                stored: header.payload_crc,
                computed,
            })
        }
    }
}
