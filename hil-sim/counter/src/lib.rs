//! Counting instructions on QEMU's Cortex-M4 (netduinoplus2), for the HIL firmware's steps and
//! the film-network bench (`benches/qemu-film-ann`).
//!
//! QEMU does not implement the DWT cycle counter (it reads 0 while claiming to exist,
//! docs/embedded.md). With `-icount shift=0` every guest instruction advances virtual time by
//! exactly 1 ns, so any timer clocked from virtual time counts instructions deterministically.
//! Two are read here:
//!
//! - **TIM2** (32-bit general-purpose timer, STM32F405 reference manual RM0090 §18). QEMU's
//!   `stm32f2xx-timer` model of netduinoplus2 is clocked at 1 GHz of virtual time, so with the
//!   prescaler at 0 one count is one instruction. This is the instruction count reported.
//! - **SysTick** (24-bit, core clock). On netduinoplus2 it runs at the 168 MHz system clock of
//!   virtual time, i.e. 0.168 counts per instruction (measured: 1000 `nop` → 168–169 counts),
//!   so its reading is quantised to ≈ 6 instructions and depends on the phase of the tick. It is
//!   kept as an independent cross-check: counts × 1000/168 must agree with TIM2 to within one
//!   SysTick period.
//!
//! Both count virtual time, i.e. instructions, not Cortex-M4 cycles: QEMU is not cycle accurate.
//!
//! On QEMU's MPS2 boards (features `mps2-an500`, Cortex-M7, and `mps2-an505`, Cortex-M33),
//! which have no TIM2, the instruction count is read from the FPGA's free-running COUNTER
//! register (MPS2 FPGAIO, clocked at the board's SYSCLK: 25 MHz on AN500, 20 MHz on AN505) and
//! scaled to virtual nanoseconds: exact to one period of that clock (40 or 50 instructions), so
//! the exact per-step counts on those machines come from QEMU's execution log
//! (`hil-sim/tools/profile_functions.py`).

#![no_std]
// On the MPS2 boards TIM2 and its registers are not used.
#![cfg_attr(
    any(feature = "mps2-an500", feature = "mps2-an505"),
    allow(dead_code, unused_imports)
)]

use core::ptr::{read_volatile, write_volatile};
use cortex_m::peripheral::syst::SystClkSource;
use cortex_m::peripheral::SYST;

/// SysTick reload: the largest 24-bit value.
const SYSTICK_RELOAD: u32 = 0x00FF_FFFF;

/// The FPGAIO COUNTER register of QEMU's MPS2 boards and the instructions (virtual ns) per count.
#[cfg(feature = "mps2-an500")]
const FPGAIO_COUNTER: (usize, u32) = (0x4002_8000 + 0x18, 40);
#[cfg(feature = "mps2-an505")]
const FPGAIO_COUNTER: (usize, u32) = (0x5030_2000 + 0x18, 50);

/// RCC APB1 peripheral clock enable register (RM0090 §7.3.13), bit 0 enables TIM2.
const RCC_APB1ENR: usize = 0x4002_3840;
/// TIM2 base address (RM0090 §2.3, memory map).
const TIM2: usize = 0x4000_0000;
/// TIM2 register offsets (RM0090 §18.4): control 1, event generation, counter, prescaler,
/// auto-reload.
const TIM_CR1: usize = 0x00;
const TIM_EGR: usize = 0x14;
const TIM_CNT: usize = 0x24;
const TIM_PSC: usize = 0x28;
const TIM_ARR: usize = 0x2C;

fn write_register(address: usize, value: u32) {
    // SAFETY: `address` is one of the RCC/TIM2 registers above, valid memory-mapped I/O on the
    // STM32F405 and on QEMU's model of it; nothing else in this firmware uses TIM2.
    unsafe { write_volatile(address as *mut u32, value) }
}

/// A reading of both counters.
#[derive(Clone, Copy, Debug)]
pub struct Stamp {
    tim2: u32,
    systick: u32,
}

/// Counts between two stamps.
#[derive(Clone, Copy, Debug, Default)]
pub struct Elapsed {
    /// TIM2 counts: instructions.
    pub instructions: u32,
    /// SysTick counts (168 MHz of virtual time).
    pub systick: u32,
}

/// Starts both counters free-running.
pub fn start(syst: &mut SYST) {
    syst.set_clock_source(SystClkSource::Core);
    syst.set_reload(SYSTICK_RELOAD);
    syst.clear_current();
    syst.enable_counter();

    #[cfg(not(any(feature = "mps2-an500", feature = "mps2-an505")))]
    start_tim2();
}

/// TIM2 free-running at one count per instruction (netduinoplus2).
#[cfg(not(any(feature = "mps2-an500", feature = "mps2-an505")))]
fn start_tim2() {
    write_register(RCC_APB1ENR, 1);
    write_register(TIM2 + TIM_PSC, 0);
    write_register(TIM2 + TIM_ARR, u32::MAX);
    // Update event: load the prescaler and the auto-reload.
    write_register(TIM2 + TIM_EGR, 1);
    write_register(TIM2 + TIM_CR1, 1);
}

/// Reads both counters.
#[inline(always)]
pub fn now() -> Stamp {
    #[cfg(not(any(feature = "mps2-an500", feature = "mps2-an505")))]
    // SAFETY: TIM2's counter register, see `write_register`; reading it has no side effect.
    let tim2 = unsafe { read_volatile((TIM2 + TIM_CNT) as *const u32) };
    #[cfg(any(feature = "mps2-an500", feature = "mps2-an505"))]
    // SAFETY: the FPGAIO COUNTER register of the MPS2 board the firmware is built for; reading
    // it has no side effect.
    let tim2 =
        unsafe { read_volatile(FPGAIO_COUNTER.0 as *const u32) }.wrapping_mul(FPGAIO_COUNTER.1);
    Stamp {
        tim2,
        systick: SYST::get_current(),
    }
}

/// Counts from `start` to `end`: TIM2 counts up (32 bits), SysTick down (24 bits); the modular
/// differences stay right across one wrap.
#[inline(always)]
pub fn elapsed(start: Stamp, end: Stamp) -> Elapsed {
    Elapsed {
        instructions: end.tim2.wrapping_sub(start.tim2),
        systick: start.systick.wrapping_sub(end.systick) & SYSTICK_RELOAD,
    }
}

/// Counts of a block of 2000 `nop` minus those of a block of 1000 `nop`, both measured by the
/// same code shape so that the reads' own instructions cancel. With `-icount shift=0` the
/// instruction count must be exactly 1000, which the host checks before trusting any step count.
pub fn calibrate() -> Elapsed {
    let short = nop_block_1000();
    let long = nop_block_2000();
    Elapsed {
        instructions: long.instructions.wrapping_sub(short.instructions),
        systick: long.systick.wrapping_sub(short.systick),
    }
}

#[inline(never)]
fn nop_block_1000() -> Elapsed {
    let start = now();
    // SAFETY: `nop` instructions only: no memory access, no register or flag changes.
    unsafe {
        core::arch::asm!(
            ".rept 1000",
            "nop",
            ".endr",
            options(nomem, nostack, preserves_flags)
        );
    }
    elapsed(start, now())
}

#[inline(never)]
fn nop_block_2000() -> Elapsed {
    let start = now();
    // SAFETY: as in `nop_block_1000`.
    unsafe {
        core::arch::asm!(
            ".rept 2000",
            "nop",
            ".endr",
            options(nomem, nostack, preserves_flags)
        );
    }
    elapsed(start, now())
}
