/* SPDX-License-Identifier: BSD-3-Clause */
/* fx_stage_cost.c - instructions per track of the prediction stage's
 * arithmetic (mtt_kalman_predict + mtt_kalman_innov: ALGORITHMS.md §2, §3),
 * and of the gate's (ALGORITHMS.md §4: gate area, slice half-widths, the
 * likelihood peak, and d^2 with p for 4 candidates per track), on the
 * Cortex-M0+ under qemu, and of the update's (ALGORITHMS.md §6: the PDA
 * update with 3 measurements and the positive-definiteness test of
 * update.c), compiled once as the float build
 * (soft-float helpers) and once as the fixed-point build (MTT_REAL_FIXED,
 * docs/FIXED_POINT.md).  Built and run by tools/ci/fx-cost.sh; not part of
 * the firmware example.
 *
 * N tracks with different states and covariances are predicted over one
 * frame; SysTick (40 instructions per tick under -icount shift=0) times the
 * loop.  Output: "S <build> predict+innov <instructions per track>" and
 * "S <build> gate (4 candidates) <instructions per track>",
 * "S <build> update (PDA 3 + cov_ok) <instructions per track>" and
 * "S <build> cov_ok <instructions per track>". */
#include <stdint.h>
#include <string.h>

#include "mtt_internal.h"
#include "fw.h"
#include "semihost.h"

#define SYST_CSR (*(volatile uint32_t *)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t *)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t *)0xE000E018u)

#define N 32

static mtt_state x[N], xp[N];
static mtt_cov P[N], Pp[N];
static mtt_real S[N][MTT_SYM_SLOTS], Si[N][MTT_SYM_SLOTS], det[N], K[N][MTT_MAX_STATE][2];
static volatile int sink;
static mtt_real gsink[N];
static mtt_state xu[N];
static mtt_cov Pu[N];

/* Candidate offsets from the prediction (TV3's, gated ones). */
static const mtt_pos off[4][2] = {{MTT_POS(0.8), MTT_POS(-0.5)}, {MTT_POS(-3.5), MTT_POS(2.4)},
                                  {MTT_POS(5.0), MTT_POS(3.0)}, {MTT_POS(9.0), MTT_POS(0.0)}};

/* Timed ticks (SysTick counts down, 24 bits) as instructions per track. */
static void report(const char *what, uint32_t c0, uint32_t c1, int ok)
{
    char buf[80], *p;
    const uint32_t t = (c0 - c1) & 0x00FFFFFFu;
    p = fmt_str(buf, what);
    p = fmt_u32(p, (t * 40u + N / 2u) / N);
    p = fmt_str(p, ok ? " ok\n" : " FAILED\n");
    (void)p;
    semihost_write0(buf);
}

/* Ends a timed loop begun at c0 (its result ok kept from the optimiser)
 * and starts the next one: returns its start. */
static uint32_t lap(const char *what, uint32_t c0, int ok, int good)
{
    const uint32_t c1 = SYST_CVR;
    sink = ok;
    report(what, c0, c1, good);
    return SYST_CVR;
}

/* A TV2-like covariance scaled by 1 + i/8 (position) and 1 + i/16 (velocity). */
static void setup(void)
{
    int i, r, c;
    for (i = 0; i < N; ++i) {
        static const int p0[4][4] = {{4, 1, 1, 0}, {1, 4, 0, 1}, {1, 0, 1, 0}, {0, 1, 0, 1}};
        memset(P[i], 0, sizeof P[i]);
        for (r = 0; r < 4; ++r) {
            for (c = 0; c < 4; ++c) {
#ifdef MTT_REAL_FIXED
                P[i][r][c] = p0[r][c] * (8 + i) * ((int32_t)1 << 20);
#else
                P[i][r][c] = (mtt_real)(p0[r][c] * (8 + i)) * MTT_R(0.125);
#endif
            }
        }
#ifdef MTT_REAL_FIXED
        MTT_COV_E(P[i]) = -23;
        x[i][0] = MTT_POS(100.0) + i * MTT_POS(3.0);
        x[i][1] = MTT_POS(50.0) - i * MTT_POS(2.0);
        x[i][2] = MTT_POS(10.0);
        x[i][3] = MTT_POS(-5.0);
#else
        x[i][0] = MTT_R(100.0) + (mtt_real)i * MTT_R(3.0);
        x[i][1] = MTT_R(50.0) - (mtt_real)i * MTT_R(2.0);
        x[i][2] = MTT_R(10.0);
        x[i][3] = MTT_R(-5.0);
#endif
    }
}

int main(void)
{
#ifdef MTT_REAL_FIXED
    const mtt_real dt = MTT_FX_CONST(1.0, MTT_FX_T_FRAC), sw = MTT_FX_CONST(5.0, MTT_FX_VAR_FRAC);
    const mtt_real R[3] = {MTT_FX_CONST(1.0, MTT_FX_VAR_FRAC), MTT_FX_CONST(0.3, MTT_FX_VAR_FRAC),
                           MTT_FX_CONST(2.0, MTT_FX_VAR_FRAC)};
    const char *build = "S fixed predict+innov ";
    const char *gbuild = "S fixed gate (4 candidates) ";
    const char *ubuild = "S fixed update (PDA 3 + cov_ok) ";
    const char *cbuild = "S fixed cov_ok ";
#else
    const mtt_real dt = MTT_R(1.0), sw = MTT_R(5.0);
    const mtt_real R[3] = {MTT_R(1.0), MTT_R(0.3), MTT_R(2.0)};
    const char *build = "S float predict+innov ";
    const char *gbuild = "S float gate (4 candidates) ";
    const char *ubuild = "S float update (PDA 3 + cov_ok) ";
    const char *cbuild = "S float cov_ok ";
#endif
    const mtt_d2 gamma = mtt_gate_gamma(MTT_P(0.99));
    /* the update's input: TV6-like betas over the first three candidates */
    const mtt_prob beta[3] = {MTT_P(0.62), MTT_P(0.23), MTT_P(0.14)};
    mtt_real nu[3][2];
    uint32_t c0;
    int i, k, ok = 0;
    for (k = 0; k < 3; ++k) {
        nu[k][0] = off[k][0];
        nu[k][1] = off[k][1];
    }
    SYST_RVR = 0x00FFFFFFu;
    SYST_CVR = 0u;
    SYST_CSR = 5u;
    while (SYST_CVR == 0u) {
        /* the first tick loads RVR */
    }
    setup();
    c0 = SYST_CVR;
    for (i = 0; i < N; ++i) {
        mtt_kalman_predict(dt, sw, x[i], P[i], xp[i], Pp[i]);
        ok += mtt_kalman_innov(Pp[i], R, S[i], Si[i], &det[i], K[i]) == 0;
    }
    c0 = lap(build, c0, ok, ok == N);
    ok = 0;
    for (i = 0; i < N; ++i) {
        const mtt_ratio vg = MTT_GATE_AREA(gamma, det[i], S[i], MTT_DENS(1e-3));
        const mtt_pos wx = MTT_GATE_WIDTH(gamma, S[i], 0), wy = MTT_GATE_WIDTH(gamma, S[i], 2);
        const mtt_ratio peak = MTT_GATE_PEAK(det[i], S[i], MTT_P(0.99), MTT_DENS(1e-3));
        mtt_ratio sum = vg;
        for (k = 0; k < 4; ++k) {
            const mtt_d2 d2 = mtt_mahal2(Si[i], off[k][0], off[k][1]);
            if (d2 <= gamma) {
                sum = MTT_ADD(sum, MTT_GATE_LIK(peak, d2));
                ++ok;
            }
        }
        gsink[i] = MTT_ADD(sum, MTT_ADD(wx, wy));
    }
    c0 = lap(gbuild, c0, ok, ok > 0);
    ok = 0;
    for (i = 0; i < N; ++i) {
        mtt_kalman_pda(xp[i], Pp[i], K[i], Si[i], R, 3, nu, beta, MTT_P(0.01), xu[i], Pu[i]);
        ok += mtt_cov_ok(Pu[i], MTT_FRAME_COV_MARGIN);
    }
    c0 = lap(ubuild, c0, ok, ok == N);
    ok = 0;
    for (i = 0; i < N; ++i) {
        ok += mtt_cov_ok(Pu[i], MTT_FRAME_COV_MARGIN);
    }
    (void)lap(cbuild, c0, ok, ok == N);
    semihost_write0("END ok\n");
    return 0;
}
