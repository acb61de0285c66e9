//! Peak stack by painting: fill the unused stack with a pattern, run, and find the lowest word
//! that no longer holds it.
//!
//! cortex-m-rt's link script places the stack between `_stack_end` (just above the statics,
//! growing towards it) and `_stack_start` (the top of RAM). Everything below the current stack
//! pointer is unused at the moment of painting, so writing there cannot alter any live value.

use core::ptr::{addr_of, read_volatile, write_volatile};

/// The paint: unlikely as data, easy to spot in a memory dump.
const PATTERN: u32 = 0xDEAD_BEEF;
/// Words left unpainted just below the stack pointer, for the painting function's own use.
const MARGIN_WORDS: usize = 32;
/// Distance from the painted top to the stack pointer of `paint` (bytes).
pub const CALLER_OFFSET: usize = MARGIN_WORDS * 4;

extern "C" {
    static _stack_start: u32;
    static _stack_end: u32;
}

/// Address of the current stack pointer.
#[inline(always)]
fn stack_pointer() -> usize {
    cortex_m::register::msp::read() as usize
}

fn stack_bottom() -> usize {
    // Only the address of the linker symbol is taken, never its value.
    addr_of!(_stack_end) as usize
}

/// Top of the stack (the initial stack pointer).
pub fn stack_top() -> usize {
    // Only the address of the linker symbol is taken, never its value.
    addr_of!(_stack_start) as usize
}

/// Paints from the bottom of the stack region up to just below the caller's stack pointer and
/// returns the painted top (exclusive). The caller's own stack use starts at
/// `painted_top + CALLER_OFFSET`.
#[inline(never)]
pub fn paint() -> usize {
    let bottom = (stack_bottom() + 3) & !3;
    let top = (stack_pointer() & !3).saturating_sub(MARGIN_WORDS * 4);
    let mut at = bottom;
    while at < top {
        // SAFETY: `at` is word-aligned and lies between the end of the statics and below the
        // live stack (see the module doc): no Rust object is stored there.
        unsafe { write_volatile(at as *mut u32, PATTERN) };
        at += 4;
    }
    top
}

/// Lowest address (from the bottom up) whose word was overwritten, up to `painted_top`.
#[inline(never)]
pub fn lowest_touched(painted_top: usize) -> usize {
    let mut at = (stack_bottom() + 3) & !3;
    while at < painted_top {
        // SAFETY: as in `paint`; reading a word of unused RAM has no effect.
        if unsafe { read_volatile(at as *const u32) } != PATTERN {
            return at;
        }
        at += 4;
    }
    painted_top
}
