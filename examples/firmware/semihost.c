/* SPDX-License-Identifier: BSD-3-Clause */
/* semihost.c - SYS_WRITE0 and SYS_EXIT through BKPT 0xAB (Thumb: ARMv6-M
 * and ARMv7-M alike).  The debugger (here qemu with -semihosting-config
 * enable=on,target=native) reads r0 = operation, r1 = argument. */
#include <stdint.h>

#include "semihost.h"

#define SYS_WRITE0 0x04u
#define SYS_EXIT 0x18u
#define ADP_STOPPED_APPLICATION_EXIT 0x20026u
#define ADP_STOPPED_RUNTIME_ERROR_UNKNOWN 0x20023u

static uint32_t semihost_call(uint32_t op, const void *arg)
{
    register uint32_t r0 __asm__("r0") = op;
    register const void *r1 __asm__("r1") = arg;
    __asm__ volatile("bkpt 0xab" : "+r"(r0) : "r"(r1) : "memory");
    return r0;
}

void semihost_write0(const char *s)
{
    (void)semihost_call(SYS_WRITE0, s);
}

void semihost_exit(int status)
{
    /* 32-bit semihosting: r1 holds the reason code itself. */
    uintptr_t reason = (status == 0) ? ADP_STOPPED_APPLICATION_EXIT
                                     : ADP_STOPPED_RUNTIME_ERROR_UNKNOWN;
    (void)semihost_call(SYS_EXIT, (const void *)reason);
    for (;;) {
        /* no debugger: stop here */
    }
}
