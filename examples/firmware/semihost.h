/* SPDX-License-Identifier: BSD-3-Clause */
/* semihost.h - the two Arm semihosting calls the firmware example needs
 * (BKPT 0xAB; Arm "Semihosting for AArch32 and AArch64", v2.0). */
#ifndef MTT_FW_SEMIHOST_H
#define MTT_FW_SEMIHOST_H

/* SYS_WRITE0 (0x04): write a NUL-terminated string to the debug console. */
void semihost_write0(const char *s);
/* SYS_EXIT (0x18): end the run; status 0 reports ADP_Stopped_ApplicationExit
 * (qemu exits 0), anything else ADP_Stopped_RunTimeErrorUnknown (qemu exits 1). */
void semihost_exit(int status) __attribute__((noreturn));

#endif
