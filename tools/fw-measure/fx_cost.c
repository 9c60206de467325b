/* SPDX-License-Identifier: BSD-3-Clause */
/* fx_cost.c - instructions per call of the fixed-point kernels
 * (include/mtt/fixed.h) beside the soft-float helpers they replace, on the
 * Cortex-M0+ build under qemu (docs/FIXED_POINT.md, "Cost").
 * Built and run by tools/ci/fx-cost.sh; not part of the firmware example.
 *
 * Each kernel runs N times through the same indirect call on N different
 * inputs; SysTick (processor clock, -icount shift=0: 40 instructions per
 * tick) times the loop, and the same loop around an empty body is
 * subtracted.  Output: "C <name> <instructions per call x 10>". */
#include <math.h>
#include <stdint.h>

#include "fw.h"
#include "real_ops.h" /* the kernels: private (src/) */
#include "semihost.h"

#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)

#define N 1024

static uint32_t ia[N], ib[N];
static float fa[N], fb[N], fe[N], fl[N];
static volatile int32_t sink_i;
static volatile float sink_f;
static volatile int64_t sink_l;

typedef void (*kern)(int i);

static void k_base(int i) { sink_i = (int32_t)(ia[i] ^ ib[i]); }
static void k_clz(int i) { sink_i = mtt_fx_clz(ia[i] >> (ib[i] & 31u)); }
static void k_add(int i) { sink_i = mtt_fx_add((int32_t)ia[i], (int32_t)ib[i]); }
static void k_mul30(int i) { sink_i = mtt_fx_mul((int32_t)ia[i], (int32_t)ib[i], 30); }
static void k_mul31(int i) { sink_i = mtt_fx_mul((int32_t)ia[i], (int32_t)ib[i], 31); }
static void k_mulq(int i) { sink_i = mtt_fx_mulq((int32_t)ia[i] >> 1, (int32_t)ib[i] >> 1, 30); }
static void k_div(int i) { sink_i = mtt_fx_div((int32_t)ia[i], (int32_t)(ib[i] | 1u), 30); }
static void k_sqrt(int i) { sink_i = (int32_t)mtt_fx_sqrt(ia[i], 30); }
static void k_exp(int i) { sink_i = mtt_fx_exp_neg_q30(ia[i] & 0x0FFFFFFFu); } /* y < 16 */
static void k_log(int i) { sink_i = mtt_fx_ln(ia[i] | 1u, 30); }
static void k_lmul(int i) { sink_l = ((int64_t)(int32_t)ia[i] * (int32_t)ib[i]) >> 30; }
static void k_idiv(int i) { sink_i = (int32_t)ia[i] / (int32_t)(ib[i] | 1u); }
static void k_fadd(int i) { sink_f = fa[i] + fb[i]; }
static void k_fmul(int i) { sink_f = fa[i] * fb[i]; }
static void k_fdiv(int i) { sink_f = fa[i] / fb[i]; }
static void k_fcmp(int i) { sink_i = fa[i] < fb[i]; }
static void k_sqrtf(int i) { sink_f = sqrtf(fl[i]); }
static void k_expf(int i) { sink_f = expf(fe[i]); } /* exp of [-16, 0] */
static void k_logf(int i) { sink_f = logf(fl[i]); }

/* Ticks of N calls; SysTick counts down over 24 bits. */
static uint32_t ticks(kern k)
{
    uint32_t c0, c1;
    int i;
    c0 = SYST_CVR;
    for (i = 0; i < N; ++i) {
        k(i);
    }
    c1 = SYST_CVR;
    return (c0 - c1) & 0x00FFFFFFu;
}

static void report(const char *name, kern k, uint32_t base)
{
    char buf[64], *p;
    const uint32_t t = ticks(k);
    /* instructions per call x 10: ticks * 40 * 10 / N */
    const uint32_t x10 = (t > base) ? ((t - base) * 400u + N / 2u) / N : 0u;
    p = fmt_str(buf, "C ");
    p = fmt_str(p, name);
    p = fmt_str(p, " ");
    p = fmt_u32(p, x10);
    (void)fmt_str(p, "\n");
    semihost_write0(buf);
}

int main(void)
{
    uint32_t s = 12345u, base;
    int i;
    SYST_RVR = 0x00FFFFFFu;
    SYST_CVR = 0u;
    SYST_CSR = 5u; /* ENABLE | CLKSOURCE = processor clock, no interrupt */
    while (SYST_CVR == 0u) {
        /* the first tick loads RVR */
    }
    for (i = 0; i < N; ++i) {
        s = s * 1664525u + 1013904223u;
        ia[i] = s;
        s = s * 1664525u + 1013904223u;
        ib[i] = s >> (s & 3u); /* magnitudes 2^28..2^31 */
        fa[i] = (float)(int32_t)(ia[i] >> 12) * (1.0f / 1024.0f); /* about +-1e3 */
        fb[i] = (float)(int32_t)((ib[i] >> 14) | 1u) * (1.0f / 65536.0f);
        fe[i] = -(float)(ia[i] >> 8) * (16.0f / 16777216.0f);
        fl[i] = (float)((ia[i] >> 10) | 1u) * (1.0f / 1024.0f); /* (0, 4e6) */
    }
    base = ticks(k_base);
    report("loop_overhead_raw", k_base, 0u); /* the empty loop itself */
    report("fx_clz", k_clz, base);
    report("fx_add", k_add, base);
    report("fx_mul_q30", k_mul30, base);
    report("fx_mul_q31", k_mul31, base);
    report("fx_mulq_q30", k_mulq, base);
    report("fx_div_q30", k_div, base);
    report("fx_sqrt_q30", k_sqrt, base);
    report("fx_exp_neg_q30", k_exp, base);
    report("fx_ln_q30", k_log, base);
    report("int64_mul_shift(__aeabi_lmul)", k_lmul, base);
    report("int32_div(__aeabi_idiv)", k_idiv, base);
    report("__aeabi_fadd", k_fadd, base);
    report("__aeabi_fmul", k_fmul, base);
    report("__aeabi_fdiv", k_fdiv, base);
    report("__aeabi_fcmplt", k_fcmp, base);
    report("sqrtf", k_sqrtf, base);
    report("expf", k_expf, base);
    report("logf", k_logf, base);
    semihost_write0("END ok\n");
    return 0;
}
