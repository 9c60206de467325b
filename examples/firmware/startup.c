/* SPDX-License-Identifier: BSD-3-Clause */
/* startup.c - minimal Cortex-M startup for the firmware example: the
 * vector table, a reset handler that copies .data from flash, zeroes
 * .bss, enables the FPU when the build uses it (Cortex-M4F), calls main
 * and reports its status through semihosting; faults end the run with a
 * failure status.  Symbols come from mps2.ld. */
#include <stdint.h>

#include "semihost.h"

extern uint32_t _sidata[], _sdata[], _edata[], _sbss[], _ebss[], _estack[];
extern int main(void);

void Reset_Handler(void) __attribute__((noreturn));
void Fault_Handler(void) __attribute__((noreturn));
void SysTick_Handler(void) __attribute__((weak));

typedef void (*fw_vector)(void);

/* The Armv6-M / Armv7-M vector table: initial SP, then 15 system exceptions
 * (the mps2 peripherals' interrupts are not used). */
typedef struct fw_vector_table {
    uint32_t *initial_sp;
    fw_vector handler[15];
} fw_vector_table;

__attribute__((section(".isr_vector"), used)) const fw_vector_table fw_vectors = {
    _estack,
    {
        Reset_Handler,  /* 1 reset */
        Fault_Handler,  /* 2 NMI */
        Fault_Handler,  /* 3 HardFault */
        Fault_Handler,  /* 4 MemManage (v7-M) */
        Fault_Handler,  /* 5 BusFault (v7-M) */
        Fault_Handler,  /* 6 UsageFault (v7-M) */
        0, 0, 0, 0,     /* 7-10 reserved */
        Fault_Handler,  /* 11 SVCall */
        Fault_Handler,  /* 12 DebugMonitor (v7-M) */
        0,              /* 13 reserved */
        Fault_Handler,  /* 14 PendSV */
        SysTick_Handler /* 15 SysTick */
    }};

void SysTick_Handler(void)
{
}

void Fault_Handler(void)
{
    semihost_write0("END fail fault\n");
    semihost_exit(1);
}

void Reset_Handler(void)
{
    uint32_t *src = _sidata, *dst;
    for (dst = _sdata; dst < _edata; ++dst) {
        *dst = *src++;
    }
    for (dst = _sbss; dst < _ebss; ++dst) {
        *dst = 0u;
    }
#if defined(__ARM_FP)
    /* CPACR: full access to CP10 and CP11 (the FPU), before any FP instruction. */
    *(volatile uint32_t *)0xE000ED88u |= (0xFu << 20);
    __asm__ volatile("dsb\n\tisb" ::: "memory");
#endif
    semihost_exit(main());
}
