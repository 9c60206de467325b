/* scenario.c - the firmware example's built-in scene: 5 constant-velocity
 * targets (two of them cross near frame 50), detection probability 0.9,
 * 0..7 clutter points per frame, measurement noise sigma 1.
 *
 * Determinism across host and target: a 32-bit LCG (Numerical Recipes
 * constants) and integer arithmetic produce every random number; the only
 * float operations are single conversions, products and sums that IEEE-754
 * single precision rounds identically everywhere (the library and this
 * code are built as ISO C, so GCC contracts no a*b+c into an FMA). */
#include "fw.h"

/* x0, y0, vx, vy per target; targets 0 and 1 meet at (250, 150) at k = 50. */
static const float truth0[SCN_TARGETS][4] = {
    {100.0f, 100.0f, 3.0f, 1.0f},
    {100.0f, 200.0f, 3.0f, -1.0f},
    {400.0f, 50.0f, -2.0f, 2.0f},
    {50.0f, 400.0f, 2.0f, 0.0f},
    {450.0f, 450.0f, -1.0f, -2.5f},
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
float scn_gauss(scn_state *s)
{
    int32_t sum = 0;
    int i;
    for (i = 0; i < 12; ++i) {
        sum += (int32_t)scn_u16(s);
    }
    sum -= 6 * 65536;
    return (float)sum * (1.0f / 65536.0f);
}

void scn_truth(int t, int k, float *x, float *y)
{
    *x = truth0[t][0] + truth0[t][2] * (float)k;
    *y = truth0[t][1] + truth0[t][3] * (float)k;
}

static float scn_unif(scn_state *s, float width)
{
    return (float)scn_u16(s) * (width / 65536.0f);
}

size_t scn_frame(scn_state *s, int k, mtt_meas *out)
{
    size_t n = 0;
    uint32_t nc, c;
    int t;
    for (t = 0; t < SCN_TARGETS; ++t) {
        float x, y, ex, ey;
        uint32_t detect = scn_u16(s);
        ex = scn_gauss(s);
        ey = scn_gauss(s);
        if (detect >= 58982u) { /* PD = 0.9 = 58982 / 65536 */
            continue;
        }
        scn_truth(t, k, &x, &y);
        out[n].x = x + ex;
        out[n].y = y + ey;
        out[n].amplitude = 0.0f;
        out[n].has_amplitude = 0;
        ++n;
    }
    nc = scn_u16(s) % (SCN_MAX_CLUTTER + 1u);
    for (c = 0; c < nc; ++c) {
        out[n].x = scn_unif(s, SCN_WIDTH);
        out[n].y = scn_unif(s, SCN_WIDTH);
        out[n].amplitude = 0.0f;
        out[n].has_amplitude = 0;
        ++n;
    }
    return n;
}
