/* SPDX-License-Identifier: BSD-3-Clause */
/* fw.h - the firmware example's shared pieces: the scenario program
 * (app.c), its deterministic measurement generator (scenario.c) and the
 * text formatting (fmt.c).  The same code is compiled for the target
 * (main_target.c: semihosting, SysTick) and for the host (main_host.c:
 * stdout), so both feed the tracker bit-identical measurements. */
#ifndef MTT_FW_H
#define MTT_FW_H

#include <stddef.h>
#include <stdint.h>

#include "mtt/mtt.h"

#ifdef MTT_REAL_DOUBLE
#error "the firmware example is a float or fixed-point build (mtt_real = float or int32_t)"
#endif

/* The scene's numbers: float, or in the fixed-point build (MTT_REAL_FIXED,
 * docs/FIXED_POINT.md) the position format Q MTT_FX_POS_FRAC: the same
 * values (every random number is an integer count of 2^-16; the truth and
 * the clutter are exact in both), with no float operation at all. */
#ifdef MTT_REAL_FIXED
typedef int32_t scn_real;
/* A Q16 value (the generator's resolution) in the position format. */
#define SCN_FROM_Q16(v)                                                                            \
    ((MTT_FX_POS_FRAC >= 16) ? (int32_t)((v) * ((int32_t)1 << (MTT_FX_POS_FRAC >= 16 ? MTT_FX_POS_FRAC - 16 : 0))) \
                             : (int32_t)((v) >> (MTT_FX_POS_FRAC < 16 ? 16 - MTT_FX_POS_FRAC : 0)))
#else
typedef float scn_real;
#endif

/* ---- platform: provided by main_target.c or main_host.c ---- */
void fw_puts(const char *s);       /* write a NUL-terminated string */
/* Free-running 32-bit tick counter for mtt_params.cycle_counter, or NULL
 * when the platform has none (host).  On the target one tick is one
 * 25 MHz SysTick clock; under qemu -icount shift=0 that is 40 instructions. */
extern const mtt_cycle_fn fw_cycle_counter;

/* ---- fw_params.c: the example's parameters (0, or 1 if the defaults fail) ---- */
int fw_params(mtt_params *par);

/* ---- scenario.c: the built-in scene ---- */
#define SCN_FRAMES 80
#define SCN_TARGETS 5
#define SCN_MAX_CLUTTER 7          /* clutter count per frame: uniform 0..7 */
#define SCN_MAX_MEAS (SCN_TARGETS + SCN_MAX_CLUTTER)
#ifdef MTT_REAL_FIXED
#define SCN_WIDTH_INT 500          /* clutter region [0, W) x [0, W) */
#define SCN_CLUTTER_DENSITY MTT_DENS(3.5 / (500.0 * 500.0))
#else
#define SCN_WIDTH 500.0f           /* clutter region [0, W) x [0, W) */
#define SCN_CLUTTER_DENSITY (3.5f / (SCN_WIDTH * SCN_WIDTH))
#endif

typedef struct scn_state {
    uint32_t lcg;
} scn_state;

void scn_init(scn_state *s, uint32_t seed);
uint32_t scn_u16(scn_state *s);    /* uniform in [0, 65535] */
scn_real scn_gauss(scn_state *s);  /* approximately N(0, 1) */
/* Truth of target t at frame k. */
void scn_truth(int t, int k, scn_real *x, scn_real *y);
/* The measurements of frame k into out[0..SCN_MAX_MEAS-1]; returns their count. */
size_t scn_frame(scn_state *s, int k, mtt_meas *out);

/* ---- fmt.c: small formatting without printf ---- */
/* Each returns a pointer to the terminating NUL it wrote into buf. */
char *fmt_str(char *buf, const char *s);
char *fmt_u32(char *buf, uint32_t v);
char *fmt_i32(char *buf, int32_t v);
#ifdef MTT_REAL_FIXED
/* The Q frac value v with `decimals` (0..6) fractional digits, rounded
 * half away from zero (integer arithmetic only). */
char *fmt_q(char *buf, int32_t v, int frac, int decimals);
/* The 32 bits of v as 8 hex digits. */
char *fmt_hex32(char *buf, uint32_t v);
#else
/* v with `decimals` (0..6) fractional digits, rounded half away from zero;
 * |v| beyond 2e9 / 10^decimals prints as "ovf". */
char *fmt_fixed(char *buf, float v, int decimals);
/* The IEEE-754 bits of v as 8 hex digits. */
char *fmt_hex(char *buf, float v);
#endif

/* ---- app.c ---- */
/* Runs the scenario and prints it; returns 0 on success. */
int fw_app_run(void);

#endif /* MTT_FW_H */
