//! Files and the exit code over ARM semihosting (the "Semihosting for AArch32 and AArch64"
//! specification, v2.0: SYS_OPEN 0x01, SYS_CLOSE 0x02, SYS_WRITE 0x05, SYS_READ 0x06,
//! SYS_FLEN 0x0C, SYS_EXIT_EXTENDED 0x20). QEMU serves them from the host's file system,
//! relative to its working directory, when run with `-semihosting-config enable=on`.

use cortex_m_semihosting::{nr, syscall};

/// An open host file.
pub struct HostFile {
    handle: usize,
}

/// The semihosting call failed (the host returned −1 or a short transfer).
#[derive(Clone, Copy, Debug, PartialEq, Eq, defmt::Format)]
pub struct IoError;

impl HostFile {
    /// Opens `path` (NUL-terminated) in `mode` (`nr::open::*`).
    pub fn open(path: &[u8], mode: usize) -> Result<HostFile, IoError> {
        // SYS_OPEN takes [name pointer, mode, name length without the NUL].
        let len = path.len().saturating_sub(1);
        let args = [path.as_ptr() as usize, mode, len];
        // SAFETY: the argument block and the name outlive the call; the host only reads them.
        let handle = unsafe { syscall(nr::OPEN, &args) };
        if handle == usize::MAX {
            Err(IoError)
        } else {
            Ok(HostFile { handle })
        }
    }

    /// Length of the file in bytes.
    pub fn len(&self) -> Result<usize, IoError> {
        let args = [self.handle];
        // SAFETY: the argument block outlives the call.
        let len = unsafe { syscall(nr::FLEN, &args) };
        if len == usize::MAX {
            Err(IoError)
        } else {
            Ok(len)
        }
    }

    /// Fills `buf` completely, or fails.
    pub fn read_exact(&mut self, buf: &mut [u8]) -> Result<(), IoError> {
        let args = [self.handle, buf.as_mut_ptr() as usize, buf.len()];
        // SAFETY: the host writes at most `buf.len()` bytes into `buf`, which is exclusively
        // borrowed for the call. SYS_READ returns the number of bytes NOT read.
        let not_read = unsafe { syscall(nr::READ, &args) };
        if not_read == 0 {
            Ok(())
        } else {
            Err(IoError)
        }
    }

    /// Writes all of `bytes`, or fails.
    pub fn write_all(&mut self, bytes: &[u8]) -> Result<(), IoError> {
        let args = [self.handle, bytes.as_ptr() as usize, bytes.len()];
        // SAFETY: the host only reads `bytes.len()` bytes from `bytes`. SYS_WRITE returns the
        // number of bytes NOT written.
        let not_written = unsafe { syscall(nr::WRITE, &args) };
        if not_written == 0 {
            Ok(())
        } else {
            Err(IoError)
        }
    }
}

impl Drop for HostFile {
    fn drop(&mut self) {
        let args = [self.handle];
        // SAFETY: the argument block outlives the call; the handle is not used afterwards.
        unsafe {
            syscall(nr::CLOSE, &args);
        }
    }
}

/// SYS_EXIT_EXTENDED: ends the emulation with any exit code (SYS_EXIT only knows 0 and 1).
pub fn exit(code: u32) -> ! {
    // ADP_Stopped_ApplicationExit (0x20026) with the code as subcode.
    let args = [0x2_0026usize, code as usize];
    loop {
        // SAFETY: the argument block outlives the call; QEMU ends the process here.
        unsafe {
            syscall(0x20, &args);
        }
    }
}
