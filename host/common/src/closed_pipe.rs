//! What a printing command does when its reader goes away (`bearing … | head -1`).
//!
//! The Rust runtime ignores SIGPIPE, so a write to a closed pipe returns `EPIPE` and `println!`
//! panics on it. Both binaries call [`end_quietly_when_the_reader_leaves`] first thing in
//! `main`: SIGPIPE gets its default action back and the process ends on that signal, silently,
//! as `cat`, `ls` and every C filter do (status 141 in the shell, which pipelines ignore). One
//! call covers every `print!`, `eprint!` and progress bar of the program, and the children it
//! starts.
//!
//! Output files are committed before a command prints its summary (`output::OutputFiles`), so
//! the end by signal cannot leave a staged temporary behind.

/// Restores the default action of SIGPIPE (end the process) on Unix; nothing elsewhere
/// (Windows reports a closed pipe as an error, with no signal).
pub fn end_quietly_when_the_reader_leaves() {
    #[cfg(unix)]
    // SAFETY: `signal` with SIG_DFL installs no handler, so no code runs in signal context; it
    // is called at the start of `main`, before any thread is started.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
}
