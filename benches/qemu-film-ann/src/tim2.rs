//! Instruction counting on QEMU's Cortex-M4 (netduinoplus2) with `-icount shift=0`: every guest
//! instruction is 1 ns of virtual time (EMBEDDED.md), and TIM2 of QEMU's STM32F405 model counts
//! virtual nanoseconds at prescaler 0, so a difference of its counter is an instruction count
//! (not Cortex-M4 cycles). [`calibration`] checks this on 1000 `nop`. Shared by the QEMU benches
//! (`qemu-micromath` includes this file by path).

use core::hint::black_box;
use core::ptr::{read_volatile, write_volatile};

/// RCC APB1 clock enable (RM0090 §7.3.13, bit 0 = TIM2) and TIM2 registers (RM0090 §18.4).
const RCC_APB1ENR: usize = 0x4002_3840;
const TIM2: usize = 0x4000_0000;
const TIM_CR1: usize = 0x00;
const TIM_EGR: usize = 0x14;
const TIM_CNT: usize = 0x24;
const TIM_PSC: usize = 0x28;
const TIM_ARR: usize = 0x2C;

fn write(address: usize, value: u32) {
    // SAFETY: RCC/TIM2 registers of the STM32F405 (and QEMU's model), used by nothing else here.
    unsafe { write_volatile(address as *mut u32, value) }
}

/// Starts TIM2 free-running over the full 32-bit range at prescaler 0.
pub fn start() {
    write(RCC_APB1ENR, 1);
    write(TIM2 + TIM_PSC, 0);
    write(TIM2 + TIM_ARR, u32::MAX);
    write(TIM2 + TIM_EGR, 1);
    write(TIM2 + TIM_CR1, 1);
}

#[inline(always)]
pub fn now() -> u32 {
    // SAFETY: TIM2's counter register; reading it has no side effect.
    unsafe { read_volatile((TIM2 + TIM_CNT) as *const u32) }
}

#[inline(never)]
fn nops_1000() -> u32 {
    let s = now();
    // SAFETY: `nop` only.
    unsafe {
        core::arch::asm!(
            ".rept 1000",
            "nop",
            ".endr",
            options(nomem, nostack, preserves_flags)
        )
    };
    now().wrapping_sub(s)
}

#[inline(never)]
fn nops_2000() -> u32 {
    let s = now();
    // SAFETY: `nop` only.
    unsafe {
        core::arch::asm!(
            ".rept 2000",
            "nop",
            ".endr",
            options(nomem, nostack, preserves_flags)
        )
    };
    now().wrapping_sub(s)
}

/// Counts of 2000 `nop` minus 1000 `nop`: 1000 when the counter counts instructions.
pub fn calibration() -> u32 {
    nops_2000().wrapping_sub(nops_1000())
}

/// The count of an empty measurement, to subtract from [`count`]'s.
pub fn empty() -> u32 {
    count(|| 0u32, 0)
}

/// Instructions of `f()` (its result kept by `black_box`), less `empty`.
pub fn count<T>(f: impl FnOnce() -> T, empty: u32) -> u32 {
    let s = now();
    let _ = black_box(f());
    now().wrapping_sub(s).wrapping_sub(empty)
}
