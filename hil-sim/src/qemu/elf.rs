//! Flash and RAM use of the firmware, read from its ELF section headers.
//!
//! ELF32 little-endian layout per the System V ABI (Tool Interface Standard, *Executable and
//! Linking Format*, v1.2, "Sections"): the file header gives the section-header table offset
//! (`e_shoff` at byte 32), entry size (`e_shentsize`, byte 46) and count (`e_shnum`, byte 48);
//! each 40-byte entry gives `sh_type` (byte 4), `sh_flags` (8), `sh_size` (20). Sections with
//! SHF_ALLOC occupy the target: those with file contents (not SHT_NOBITS) are stored in flash
//! (`.vector_table`, `.text`, `.rodata`, and `.data`'s initial values); those with SHF_WRITE
//! occupy RAM (`.data`, `.bss`, `.uninit`). The stack is the rest of RAM, measured separately.

/// SHT_NOBITS: a section without file contents (`.bss`).
const SHT_NOBITS: u32 = 8;
/// SHF_WRITE: writable at run time.
const SHF_WRITE: u32 = 0x1;
/// SHF_ALLOC: occupies memory on the target.
const SHF_ALLOC: u32 = 0x2;

/// Static memory use of a firmware image.
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
pub struct MemoryUse {
    /// Bytes stored in flash.
    pub flash_bytes: u64,
    /// Bytes of statically allocated RAM (data, bss), without the stack.
    pub ram_bytes: u64,
}

fn u16_at(bytes: &[u8], at: usize) -> Option<u16> {
    Some(u16::from_le_bytes(bytes.get(at..at + 2)?.try_into().ok()?))
}

fn u32_at(bytes: &[u8], at: usize) -> Option<u32> {
    Some(u32::from_le_bytes(bytes.get(at..at + 4)?.try_into().ok()?))
}

/// Flash and RAM use of a 32-bit little-endian ELF image; `None` if it is not one.
pub fn memory_use(elf: &[u8]) -> Option<MemoryUse> {
    // Magic, ELFCLASS32 (1), ELFDATA2LSB (1).
    if elf.get(..6)? != [0x7F, b'E', b'L', b'F', 1, 1] {
        return None;
    }
    let table = u32_at(elf, 32)? as usize;
    let entry = usize::from(u16_at(elf, 46)?);
    let count = usize::from(u16_at(elf, 48)?);
    if entry < 40 {
        return None;
    }
    let mut usage = MemoryUse {
        flash_bytes: 0,
        ram_bytes: 0,
    };
    for index in 0..count {
        let at = table.checked_add(index.checked_mul(entry)?)?;
        let kind = u32_at(elf, at + 4)?;
        let flags = u32_at(elf, at + 8)?;
        let size = u64::from(u32_at(elf, at + 20)?);
        if flags & SHF_ALLOC == 0 {
            continue;
        }
        if kind != SHT_NOBITS {
            usage.flash_bytes += size;
        }
        if flags & SHF_WRITE != 0 {
            usage.ram_bytes += size;
        }
    }
    Some(usage)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Builds an ELF32 image with the given (type, flags, size) sections.
    fn image(sections: &[(u32, u32, u32)]) -> Vec<u8> {
        let mut elf = vec![0u8; 52];
        elf[..6].copy_from_slice(&[0x7F, b'E', b'L', b'F', 1, 1]);
        elf[32..36].copy_from_slice(&52u32.to_le_bytes());
        elf[46..48].copy_from_slice(&40u16.to_le_bytes());
        elf[48..50].copy_from_slice(&(sections.len() as u16).to_le_bytes());
        for &(kind, flags, size) in sections {
            let mut header = [0u8; 40];
            header[4..8].copy_from_slice(&kind.to_le_bytes());
            header[8..12].copy_from_slice(&flags.to_le_bytes());
            header[20..24].copy_from_slice(&size.to_le_bytes());
            elf.extend_from_slice(&header);
        }
        elf
    }

    /// Reference: the classification of the module doc, applied by hand to a synthetic image:
    /// text 1000 (flash), rodata 200 (flash), data 16 (flash and RAM), bss 300 (RAM),
    /// debug info 5000 (neither).
    #[test]
    fn classifies_sections_by_alloc_write_and_nobits() {
        let elf = image(&[
            (1, SHF_ALLOC | 0x4, 1000),
            (1, SHF_ALLOC, 200),
            (1, SHF_ALLOC | SHF_WRITE, 16),
            (SHT_NOBITS, SHF_ALLOC | SHF_WRITE, 300),
            (1, 0, 5000),
        ]);
        assert_eq!(
            memory_use(&elf),
            Some(MemoryUse {
                flash_bytes: 1216,
                ram_bytes: 316
            })
        );
        assert_eq!(memory_use(b"not an elf"), None);
        assert_eq!(memory_use(&elf[..60]), None);
    }
}
