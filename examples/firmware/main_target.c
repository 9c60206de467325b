/* SPDX-License-Identifier: BSD-3-Clause */
/* main_target.c - the firmware example on the target: output through
 * semihosting, SysTick as the tracker's cycle counter (mtt_params
 * .cycle_counter), so mtt_tracker_stats reports ticks per stage.
 *
 * SysTick runs from the processor clock (25 MHz on the mps2 boards) over
 * its full 24-bit range; its interrupt extends the count to 32 bits.
 * Under qemu with -icount shift=0 the virtual clock advances 1 ns per
 * instruction, so one tick is 40 instructions (docs/FIRMWARE.md). */
#include <stdint.h>

#include "fw.h"
#include "semihost.h"

#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)

static volatile uint32_t tick_hi; /* SysTick wraps (2^24 ticks each) */

void SysTick_Handler(void)
{
    tick_hi = tick_hi + 1u;
}

static uint32_t systick_count(void *ctx)
{
    uint32_t hi, lo;
    (void)ctx;
    do {
        hi = tick_hi;
        lo = SYST_CVR;
    } while (hi != tick_hi);
    return (hi << 24) | (0x00FFFFFFu - lo);
}

const mtt_cycle_fn fw_cycle_counter = systick_count;

/* Calibration: a loop of exactly 2 * CAL_LOOPS instructions (subs, bne),
 * timed with the same counter, checks the instructions-per-tick ratio. */
#define CAL_LOOPS 1000000u

static void calibrate(void)
{
    char buf[64], *p;
    uint32_t t0, t1;
    uint32_t n = CAL_LOOPS;
    t0 = systick_count(NULL);
    /* GCC wraps inline asm in divided syntax on ARMv6-M: say unified. */
    __asm__ volatile(".syntax unified\n1:\n\tsubs %0, %0, #1\n\tbne 1b\n\t.syntax divided"
                     : "+l"(n)
                     :
                     : "cc");
    t1 = systick_count(NULL);
    p = fmt_str(buf, "K cal ");
    p = fmt_u32(p, 2u * CAL_LOOPS);
    p = fmt_str(p, " ticks ");
    p = fmt_u32(p, t1 - t0);
    (void)fmt_str(p, "\n");
    semihost_write0(buf);
}

void fw_puts(const char *s)
{
    semihost_write0(s);
}

int main(void)
{
    SYST_RVR = 0x00FFFFFFu;
    SYST_CVR = 0u;
    SYST_CSR = 7u; /* ENABLE | TICKINT | CLKSOURCE = processor clock */
    while (SYST_CVR == 0u) {
        /* the first tick loads RVR; until then CVR reads 0 */
    }
    calibrate();
    return fw_app_run();
}
