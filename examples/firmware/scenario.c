/* SPDX-License-Identifier: BSD-3-Clause */
/* scenario.c - the firmware example's built-in scene: 5 constant-velocity
 * targets (two of them cross near frame 50), detection probability 0.9,
 * 0..7 clutter points per frame, measurement noise sigma 1.
 *
 * Determinism across host and target: a 32-bit LCG (Numerical Recipes
 * constants) and integer arithmetic produce every random number; the only
 * float operations are single conversions, products and sums that IEEE-754
 * single precision rounds identically everywhere (the library and this
 * code are built as ISO C, so GCC contracts no a*b+c into an FMA).  The
 * fixed-point build (MTT_REAL_FIXED) computes the same numbers in the
 * position format with integer operations only. */
#include "fw.h"

/* x0, y0, vx, vy per target; targets 0 and 1 meet at (250, 150) at k = 50. */
#ifdef MTT_REAL_FIXED
#define TV(x) MTT_POS(x)
#else
#define TV(x) x##f
#endif
static const scn_real truth0[SCN_TARGETS][4] = {
    {TV(100.0), TV(100.0), TV(3.0), TV(1.0)},
    {TV(100.0), TV(200.0), TV(3.0), TV(-1.0)},
    {TV(400.0), TV(50.0), TV(-2.0), TV(2.0)},
    {TV(50.0), TV(400.0), TV(2.0), TV(0.0)},
    {TV(450.0), TV(450.0), TV(-1.0), TV(-2.5)},
};

void scn_init(scn_state *s, uint32_t seed)
{
    s->lcg = seed;
}

uint32_t scn_u16(scn_state *s)
{
    s->lcg = s->lcg * 1664525u + 1013904223u;
    return s->lcg >> 16; /* the high bits: the LCG's low bits are weak */
}

/* Irwin-Hall: the sum of 12 uniforms minus 6 has mean 0 and variance 1.
 * The sum is an exact integer (< 2^20), so the float result is exact. */
scn_real scn_gauss(scn_state *s)
{
    int32_t sum = 0;
    int i;
    for (i = 0; i < 12; ++i) {
        sum += (int32_t)scn_u16(s);
    }
    sum -= 6 * 65536;
#ifdef MTT_REAL_FIXED
    return SCN_FROM_Q16(sum); /* sum is the Q16 value */
#else
    return (float)sum * (1.0f / 65536.0f);
#endif
}

#ifdef MTT_REAL_FIXED
void scn_truth(int t, int k, scn_real *x, scn_real *y)
{
    *x = truth0[t][0] + truth0[t][2] * (int32_t)k;
    *y = truth0[t][1] + truth0[t][3] * (int32_t)k;
}

/* Uniform in [0, W): u W / 65536, exactly W u in Q16. */
static scn_real scn_unif(scn_state *s)
{
    return SCN_FROM_Q16((int32_t)scn_u16(s) * SCN_WIDTH_INT);
}
#define SCN_UNIF(s) scn_unif(s)
#define SCN_ZERO 0
#else
void scn_truth(int t, int k, float *x, float *y)
{
    *x = truth0[t][0] + truth0[t][2] * (float)k;
    *y = truth0[t][1] + truth0[t][3] * (float)k;
}

static float scn_unif(scn_state *s, float width)
{
    return (float)scn_u16(s) * (width / 65536.0f);
}
#define SCN_UNIF(s) scn_unif((s), SCN_WIDTH)
#define SCN_ZERO 0.0f
#endif

size_t scn_frame(scn_state *s, int k, mtt_meas *out)
{
    size_t n = 0;
    uint32_t nc, c;
    int t;
    for (t = 0; t < SCN_TARGETS; ++t) {
        scn_real x, y, ex, ey;
        uint32_t detect = scn_u16(s);
        ex = scn_gauss(s);
        ey = scn_gauss(s);
        if (detect >= 58982u) { /* PD = 0.9 = 58982 / 65536 */
            continue;
        }
        scn_truth(t, k, &x, &y);
        out[n].x = x + ex;
        out[n].y = y + ey;
        out[n].amplitude = SCN_ZERO;
        out[n].has_amplitude = 0;
        ++n;
    }
    nc = scn_u16(s) % (SCN_MAX_CLUTTER + 1u);
    for (c = 0; c < nc; ++c) {
        out[n].x = SCN_UNIF(s);
        out[n].y = SCN_UNIF(s);
        out[n].amplitude = SCN_ZERO;
        out[n].has_amplitude = 0;
        ++n;
    }
    return n;
}
