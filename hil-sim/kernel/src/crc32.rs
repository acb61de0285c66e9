//! CRC-32 (IEEE 802.3 / zlib / PNG), the checksum of the binary trace format.
//!
//! Reflected polynomial 0xEDB88320 (the bit-reversed 0x04C11DB7), initial value 0xFFFFFFFF,
//! final XOR 0xFFFFFFFF — the "CRC-32/ISO-HDLC" entry of Greg Cook's *Catalogue of
//! parametrised CRC algorithms*, whose check value (CRC of the ASCII bytes `123456789`) is
//! 0xCBF43926. Byte-wise table lookup: 256 words built at compile time, so the firmware pays
//! 1 KiB of flash and one lookup per byte.
//!
//! This file uses nothing from `std`: the firmware uses it through this crate, so that host and
//! firmware check the same sum with the same code.

/// Reflected generator polynomial of CRC-32/ISO-HDLC.
const POLYNOMIAL_REFLECTED: u32 = 0xEDB8_8320;

/// Lookup table: the CRC remainder of each byte value, computed at compile time.
const TABLE: [u32; 256] = build_table();

const fn build_table() -> [u32; 256] {
    let mut table = [0u32; 256];
    let mut byte = 0usize;
    while byte < 256 {
        let mut remainder = byte as u32;
        let mut bit = 0;
        while bit < 8 {
            remainder = if remainder & 1 == 1 {
                (remainder >> 1) ^ POLYNOMIAL_REFLECTED
            } else {
                remainder >> 1
            };
            bit += 1;
        }
        table[byte] = remainder;
        byte += 1;
    }
    table
}

/// An incremental CRC-32: feed bytes in any number of pieces, then read [`Crc32::finish`].
#[derive(Clone, Copy, Debug)]
pub struct Crc32 {
    state: u32,
}

impl Default for Crc32 {
    fn default() -> Self {
        Self::new()
    }
}

impl Crc32 {
    /// A fresh checksum (nothing fed yet).
    pub const fn new() -> Self {
        Self { state: 0xFFFF_FFFF }
    }

    /// Feeds `bytes` into the checksum.
    pub fn update(&mut self, bytes: &[u8]) {
        let mut state = self.state;
        for &byte in bytes {
            // The index is a u8 widened to usize, always < 256 = TABLE.len().
            let index = ((state ^ u32::from(byte)) & 0xFF) as u8;
            state = (state >> 8) ^ TABLE[usize::from(index)];
        }
        self.state = state;
    }

    /// The checksum of everything fed so far.
    pub const fn finish(&self) -> u32 {
        self.state ^ 0xFFFF_FFFF
    }
}

/// CRC-32 of one byte slice.
pub fn crc32(bytes: &[u8]) -> u32 {
    let mut crc = Crc32::new();
    crc.update(bytes);
    crc.finish()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Reference: the catalogue check value of CRC-32/ISO-HDLC (see module doc).
    #[test]
    fn check_value_of_the_catalogue() {
        assert_eq!(crc32(b"123456789"), 0xCBF4_3926);
    }

    /// Reference: the empty message has CRC 0 (init and final XOR cancel), and the zlib
    /// documentation's example `crc32("The quick brown fox jumps over the lazy dog")`
    /// = 0x414FA339 (also listed in Wikipedia's CRC-32 test vectors).
    #[test]
    fn known_vectors() {
        assert_eq!(crc32(b""), 0);
        assert_eq!(
            crc32(b"The quick brown fox jumps over the lazy dog"),
            0x414F_A339
        );
    }

    /// Feeding in pieces gives the same sum as one call (the firmware streams records).
    #[test]
    fn incremental_equals_one_shot() {
        let message = b"roller bearing trace, split anywhere";
        for split in 0..=message.len() {
            let (a, b) = message.split_at(split);
            let mut crc = Crc32::new();
            crc.update(a);
            crc.update(b);
            assert_eq!(crc.finish(), crc32(message), "split at {split}");
        }
    }
}
