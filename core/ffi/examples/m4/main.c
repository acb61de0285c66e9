/*
 * Cortex-M4F example of the bearing C library (STM32F405, run on QEMU's netduinoplus2 with
 * semihosting): replays `trace.bin` from the host's working directory and writes
 * `outputs.bin` (whole or not at all), counting the instructions of every bearing_advance with TIM2.
 *
 * QEMU does not model the DWT cycle counter; with `-icount shift=0` every instruction advances
 * virtual time by 1 ns, and TIM2, clocked from virtual time at 1 GHz, counts instructions
 * (hil-sim/counter does the same register accesses for the Rust firmware; RM0090 §7.3.13, §18.4).
 *
 * Build and run (core/ffi/tests/c_examples.rs does this):
 *   cargo build --release -p bearing-ffi --target thumbv7em-none-eabihf
 *   arm-none-eabi-gcc -std=c11 -O2 -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16 \
 *     -I core/ffi/include -I core/ffi/examples/common -T core/ffi/examples/m4/link.ld -nostartfiles \
 *     --specs=nano.specs --specs=rdimon.specs -Wl,--gc-sections core/ffi/examples/m4/main.c \
 *     core/ffi/examples/common/replay.c target/thumbv7em-none-eabihf/release/libbearing_ffi.a -lm -o replay-m4.elf
 *   qemu-system-arm -M netduinoplus2 -nographic -monitor none -serial none \
 *     -semihosting-config enable=on,target=native -icount shift=0 -kernel replay-m4.elf
 */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bearing.h"
#include "replay.h"

/* Samples replayed; 0 replays the whole trace. */
#ifndef REPLAY_MAX_STEPS
#define REPLAY_MAX_STEPS 0
#endif

#define REG(address) (*(volatile uint32_t *)(address))
#define RCC_APB1ENR REG(0x40023840u) /* bit 0: TIM2 clock */
#define TIM2_CR1 REG(0x40000000u)
#define TIM2_EGR REG(0x40000014u)
#define TIM2_CNT REG(0x40000024u)
#define TIM2_PSC REG(0x40000028u)
#define TIM2_ARR REG(0x4000002Cu)
#define SCB_CPACR REG(0xE000ED88u) /* coprocessor access: CP10, CP11 = the FPU */

static uint32_t tim2_now(void) { return TIM2_CNT; }

static void tim2_start(void) {
  RCC_APB1ENR |= 1u;
  TIM2_PSC = 0;
  TIM2_ARR = 0xFFFFFFFFu;
  TIM2_EGR = 1; /* update event: load prescaler and auto-reload */
  TIM2_CR1 = 1;
}

/* TIM2 ticks of 1000 `nop` (2000 minus 1000, so the reads cancel): 1000 when TIM2 counts
   instructions, which the host checks before trusting any count. */
static uint32_t __attribute__((noinline)) nops_1000(void) {
  uint32_t start = tim2_now();
  __asm__ volatile(".rept 1000\n nop\n .endr");
  return tim2_now() - start;
}
static uint32_t __attribute__((noinline)) nops_2000(void) {
  uint32_t start = tim2_now();
  __asm__ volatile(".rept 2000\n nop\n .endr");
  return tim2_now() - start;
}

int main(void) {
  tim2_start();
  uint32_t calibration = nops_2000() - nops_1000();
  FILE *trace = fopen("trace.bin", "rb");
  FILE *outputs = fopen("outputs.bin", "wb");
  if (trace == NULL || outputs == NULL) {
    fprintf(stderr, "cannot open trace.bin or create outputs.bin\n");
    return 2;
  }
  ReplaySummary summary;
  int code = replay(trace, outputs, REPLAY_MAX_STEPS, BEARING_FILM_INT, tim2_now, calibration, &summary);
  fclose(trace);
  if (fclose(outputs) != 0 && code == 0) code = 4;
  /* Whole or not at all: newlib's semihosting layer has no rename(), so a failed replay removes
     the file; a complete one ends with the trailer, which an interrupted one lacks. */
  if (code != 0) remove("outputs.bin");
  if (code == 0) {
    printf("%u steps of %u rollers, %u..%u instructions per step and %u..%u per bearing_friction (calibration %u), "
           "storage %u B aligned to %u\n",
           (unsigned)summary.steps, (unsigned)summary.rollers, (unsigned)summary.fewest_counts,
           (unsigned)summary.most_counts, (unsigned)summary.friction_fewest_counts,
           (unsigned)summary.friction_most_counts, (unsigned)calibration, (unsigned)bearing_storage_size(),
           (unsigned)bearing_storage_align());
  }
  return code;
}

/* Startup: the FPU on, .data from flash, .bss zeroed, newlib's semihosting I/O, main, exit. */
extern uint32_t _stack_top, _data_load, _data_start, _data_end, _bss_start, _bss_end;
extern void initialise_monitor_handles(void);

void reset_handler(void) {
  SCB_CPACR |= 0xFu << 20;
  __asm__ volatile("dsb\n isb");
  memcpy(&_data_start, &_data_load, (size_t)((char *)&_data_end - (char *)&_data_start));
  memset(&_bss_start, 0, (size_t)((char *)&_bss_end - (char *)&_bss_start));
  initialise_monitor_handles();
  exit(main());
}

/* A fault ends the emulation with exit code 99 (newlib: semihosting SYS_EXIT). */
static void fault_handler(void) { _Exit(99); }

__attribute__((section(".vectors"), used)) static void (*const vectors[16])(void) = {
    (void (*)(void))&_stack_top, reset_handler, fault_handler, fault_handler, fault_handler,
    fault_handler, fault_handler, 0, 0, 0, 0, fault_handler, fault_handler, 0, fault_handler,
    fault_handler,
};
