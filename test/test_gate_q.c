/* SPDX-License-Identifier: BSD-3-Clause */
/* test_gate_q.c - the gate's arithmetic (ALGORITHMS.md §4) on
 * docs/TEST_VECTORS.md TV3 in every build: gamma, the gate area, the slice
 * half-width, d^2 and the likelihood p = N / PG of the five candidates.
 *
 * Fixed point (docs/FIXED_POINT.md §4): S and S^-1 are mantissas with one
 * exponent, det S one at 2 e(S) + 28, positions Q MTT_FX_POS_FRAC, and the
 * densities are ratios of the declared clutter density lambda (area
 * lambda V_G, likelihood p / lambda, Q16).  Each fixed result is compared
 * with the double formula evaluated on the *quantised* inputs, with a
 * tolerance counted from the roundings of the code (stated at each
 * assertion); the quantised-input formula is compared with TV3 by the
 * float rule of ALGORITHMS.md §16, so the formats' input quantisation is
 * shown to stay inside it.  Float and double builds: TV3 directly. */
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "tv_fixture.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

static const double tv3_S[3] = {9.666666667, 1.3, 10.66666667}; /* TV2 S */
static const double tv3_det = 101.4211111;                       /* TV3 det S */
static const double tv3_gamma = 9.210340372;
static const double tv3_vg = 291.4001257;
static const double tv3_off[5][2] = {{0.8, -0.5}, {-3.5, 2.4}, {5.0, 3.0}, {8.0, -7.0}, {9.0, 0.0}};
static const double tv3_d2[5] = {0.1013924342, 2.052695582, 3.10257562, 12.83690663, 8.518936448};
static const int tv3_gated[5] = {1, 1, 1, 0, 1};
static const double tv3_p[5] = {0.01517412536, 0.005719835949, 0.003383802596, 0.0, 0.0002255574674};

static mtt_real S[MTT_SYM_SLOTS], Si[MTT_SYM_SLOTS], det;

#ifdef MTT_REAL_FIXED
#define E_S (-25)  /* S below 2^29 (mtt_fx_s_exp's bound) */
#define E_SI (-31) /* S^-1 below 2^28 (mtt_fx_si_exp's bound) */
#define DENS MTT_DENS(1e-3)
static double sv(int k)
{
    return ldexp((double)S[k], MTT_SYM_E(S));
}
static double siv(int k)
{
    return ldexp((double)Si[k], MTT_SYM_E(Si));
}
static double detv(void)
{
    return ldexp((double)det, MTT_DET_E(S));
}
static double pos(mtt_pos v)
{
    return ldexp((double)v, -MTT_FX_POS_FRAC);
}
static const double lam = (double)DENS / (double)((uint64_t)1 << MTT_FX_DENS_FRAC); /* the declared density, quantised */
static double lam_or_1(void)
{
    return lam;
}
/* The mantissa of sqrt(det S) that gate.c takes (f = 30 or 31, de - f even). */
static double sqrt_det_mant(void)
{
    return sqrt(ldexp((double)det, ((MTT_DET_E(S) & 1) != 0) ? 31 : 30));
}
#else
#define DENS MTT_DENS(1e-3)
static double sv(int k)
{
    return (double)S[k];
}
static double siv(int k)
{
    return (double)Si[k];
}
static double lam_or_1(void)
{
    return 1.0; /* float: V_G and p themselves */
}
static double pos(mtt_pos v)
{
    return (double)v;
}
#endif

/* TV3's S, S^-1 and det S in the build's formats. */
static void set_s(void)
{
    const double si[3] = {tv3_S[2] / tv3_det, -tv3_S[1] / tv3_det, tv3_S[0] / tv3_det};
    int k;
    memset(S, 0, sizeof S);
    memset(Si, 0, sizeof Si);
    for (k = 0; k < 3; ++k) {
#ifdef MTT_REAL_FIXED
        S[k] = (mtt_real)llround(ldexp(tv3_S[k], -E_S));
        Si[k] = (mtt_real)llround(ldexp(si[k], -E_SI));
#else
        S[k] = (mtt_real)tv3_S[k];
        Si[k] = (mtt_real)si[k];
#endif
    }
#ifdef MTT_REAL_FIXED
    MTT_SYM_E(S) = E_S;
    MTT_SYM_E(Si) = E_SI;
    det = (mtt_real)llround(ldexp(tv3_det, -MTT_DET_E(S)));
#else
    det = (mtt_real)tv3_det;
#endif
}

static void test_tv3_gamma(void)
{
    const mtt_d2 g = mtt_gate_gamma(MTT_P(0.99));
#ifdef MTT_REAL_FIXED
    /* -ln(1 - PG) in Q25 read as Q24: mtt_fx_ln's 2 units (fixed.h) are
     * 2 units of gamma; 1 - PG is exact in Q30 (an integer difference). */
    const double ref = -2.0 * log(1.0 - (double)MTT_P(0.99) / 1073741824.0);
    TV_ASSERT_Q(ref, g, MTT_FX_D2_FRAC, 2.0 * ldexp(1.0, -MTT_FX_D2_FRAC));
    TV_ASSERT_REAL(tv3_gamma, ref); /* PG's quantisation: inside the float rule */
#else
    TV_ASSERT_REAL(tv3_gamma, g); /* TV3 gamma */
#endif
}

static void test_tv3_area_width(void)
{
    const mtt_d2 g = mtt_gate_gamma(MTT_P(0.99));
    mtt_ratio vg;
    mtt_pos w;
    set_s();
    vg = MTT_GATE_AREA(g, det, S, DENS);
    w = MTT_GATE_WIDTH(g, S, 0);
#ifdef MTT_REAL_FIXED
    {
        const double gq = ldexp((double)g, -MTT_FX_D2_FRAC);
        const double ref = 3.14159265358979323846 * gq * sqrt(detv()) * lam;
        const double wt = sqrt(gq * sv(0));
        /* the square root's half unit of its mantissa, three products each
         * rounded to 30 bits (results of at least 29 bits: 2^-29 relative),
         * pi in Q29 (2^-30 relative), the Q16 result's half unit */
        const double tol = ref * (0.5 / sqrt_det_mant() + 4.0 * ldexp(1.0, -29)) + ldexp(1.0, -17);
        TV_ASSERT_RATIO(ref, vg, tol);
        TV_ASSERT_REAL(tv3_vg * lam, ref); /* TV3 V_G, as lambda V_G */
        /* an upper bound from an 8-bit root of T's top 16 bits (gate.c):
         * (root + 1) 2^8 / sqrt(T) <= 1 + 1.5 2^-7 with T >= 2^30, then
         * rounded up and one unit more: at most that and 3 units of the
         * position format above */
        TEST_ASSERT_TRUE(pos(w) >= wt);
        TEST_ASSERT_TRUE(pos(w) <= wt * (1.0 + 1.5 * ldexp(1.0, -7)) + 3.0 * ldexp(1.0, -MTT_FX_POS_FRAC));
        /* a gate wider than the format saturates instead of wrapping */
        MTT_SYM_E(S) = 10;
        TEST_ASSERT_EQUAL_INT32(MTT_FX_MAX, MTT_GATE_WIDTH(g, S, 0));
        MTT_SYM_E(S) = E_S;
    }
#else
    TV_ASSERT_REAL(tv3_vg, vg);                         /* TV3 V_G */
    TV_ASSERT_REAL(sqrt(tv3_gamma * sv(0)), w); /* slice half-width */
#endif
    (void)pos;
}

static void test_tv3_candidates(void)
{
    const mtt_d2 g = mtt_gate_gamma(MTT_P(0.99));
    mtt_ratio peak;
    int c;
    set_s();
    peak = MTT_GATE_PEAK(det, S, MTT_P(0.99), DENS);
    for (c = 0; c < 5; ++c) {
        mtt_pos nx, ny;
        mtt_d2 d2;
        double x, y, ref_d2;
#ifdef MTT_REAL_FIXED
        nx = MTT_FX_CONST(tv3_off[c][0], MTT_FX_POS_FRAC);
        ny = MTT_FX_CONST(tv3_off[c][1], MTT_FX_POS_FRAC);
#else
        nx = (mtt_pos)tv3_off[c][0];
        ny = (mtt_pos)tv3_off[c][1];
#endif
        x = pos(nx);
        y = pos(ny);
        ref_d2 = siv(0) * x * x + 2.0 * siv(1) * x * y + siv(2) * y * y;
        d2 = mtt_mahal2(Si, nx, ny);
        TEST_ASSERT_EQUAL_INT_MESSAGE(tv3_gated[c], d2 <= g, "TV3 gated");
#ifdef MTT_REAL_FIXED
        {
            /* d^2 (kalman.c, fx_cov.c): nu normalised to 30 bits by s, four
             * mtt_fx_mulq at s = 30 into S^-1 nu (0.5008 of u_w each), two
             * into nu' S^-1 nu (u_q), the Q24 half unit */
            const uint32_t o = (uint32_t)((nx < 0) ? -nx : nx) | (uint32_t)((ny < 0) ? -ny : ny);
            const int s = 30 - (32 - mtt_fx_clz(o));
            const double uw = ldexp(1.0, MTT_SYM_E(Si) - MTT_FX_POS_FRAC - s + 30);
            const double uq = ldexp(1.0, MTT_SYM_E(Si) - 2 * (MTT_FX_POS_FRAC + s) + 60);
            const double tol = (fabs(x) + fabs(y)) * 2.0 * 0.5008 * uw + 2.0 * 0.5008 * uq + ldexp(1.0, -25);
            TV_ASSERT_Q(ref_d2, d2, MTT_FX_D2_FRAC, tol);
            TV_ASSERT_REAL(tv3_d2[c], ref_d2); /* TV3 d2 from the quantised inputs */
        }
        if (tv3_gated[c]) {
            /* p / lambda = exp(-d^2/2) / (2 pi sqrt(det S) PG lambda): the
             * peak's roundings as the area's (relative 0.5/r + 4 2^-29) and
             * its Q16 half unit; d^2/2 rounded to 2^-25 (relative 2^-25 of
             * the exponential); exp in Q30 within 4.5 units (fixed.h), times
             * the peak; the product's Q16 half unit (the fast Q30 multiply:
             * 0.5007 unit). */
            const double e = exp(-0.5 * ldexp((double)d2, -MTT_FX_D2_FRAC));
            const double pk = 1.0 / (2.0 * 3.14159265358979323846 * sqrt(detv()) *
                                     ((double)MTT_P(0.99) / 1073741824.0) * lam);
            const double ref = pk * e;
            const double tol = ref * (0.5 / sqrt_det_mant() + 4.0 * ldexp(1.0, -29) + ldexp(1.0, -25)) +
                               e * ldexp(1.0, -17) + pk * 4.5 * ldexp(1.0, -30) + 1.0015 * ldexp(1.0, -17);
            TV_ASSERT_RATIO(ref, MTT_GATE_LIK(peak, d2), tol);
            TV_ASSERT_REAL(tv3_p[c] / lam, ref); /* TV3 p, as p / lambda */
        }
#else
        TV_ASSERT_REAL(tv3_d2[c], d2); /* TV3 d2 */
        (void)ref_d2;
        if (tv3_gated[c]) {
            TV_ASSERT_REAL(tv3_p[c], MTT_GATE_LIK(peak, d2)); /* TV3 p = N / PG */
        }
#endif
    }
#ifdef MTT_REAL_FIXED
    /* far outside: d^2 saturates, and the likelihood is 0, not a wrap */
    TEST_ASSERT_EQUAL_INT32(0, MTT_GATE_LIK(peak, MTT_FX_MAX));
#endif
}

/* The frame stage on TV3: one track at TV2's prediction, the five
 * candidates as measurements.  Its pairs must be the stage kernels applied
 * to the track's own S, S^-1 (bit for bit: the frame only composes them),
 * and TV3 within the float rule of ALGORITHMS.md §16, the upper bound of
 * every fixed tolerance (docs/FIXED_POINT.md §7). */
static mtt_tracker trk;

static void test_tv3_gate_frame(void)
{
    static const double p2[16] = {8.666666667, 1, 4.5, 0, 1, 8.666666667, 0, 4.5,
                                  4.5, 0, 6, 0, 0, 4.5, 0, 6}; /* TV2 P^ */
    static const double r[3] = {1.0, 0.3, 2.0};                /* TV2 R */
    static const double xp0[4] = {110.0, 45.0, 10.0, -5.0};    /* TV2 x^ */
    static const uint16_t want_meas[4] = {0, 1, 2, 4};         /* TV3: c4 not gated */
    mtt_state xp;
    mtt_cov Pp;
    mtt_ratio peak;
    int i, j, k;
    memset(&trk, 0, sizeof trk);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&trk.par));
    trk.par.pg = MTT_P(0.99);
    trk.par.clutter_density = DENS;
    trk.gamma = mtt_gate_gamma(trk.par.pg);
#ifdef MTT_REAL_FIXED
    mtt_fx_gate_consts(trk.gamma, trk.par.pg, trk.par.clutter_density, trk.gc); /* as mtt_tracker_init */
#endif
    memset(Pp, 0, sizeof Pp);
    for (i = 0; i < 4; ++i) {
#ifdef MTT_REAL_FIXED
        xp[i] = MTT_FX_CONST(xp0[i], MTT_FX_POS_FRAC);
        for (j = 0; j < 4; ++j) {
            Pp[i][j] = (mtt_real)llround(ldexp(p2[4 * i + j], 24)); /* largest below 2^28 */
        }
#else
        xp[i] = (mtt_real)xp0[i];
        for (j = 0; j < 4; ++j) {
            Pp[i][j] = (mtt_real)p2[4 * i + j];
        }
#endif
    }
#ifdef MTT_REAL_FIXED
    MTT_COV_E(Pp) = -24;
    for (k = 0; k < 3; ++k) {
        trk.R[k] = (mtt_real)llround(ldexp(r[k], MTT_FX_VAR_FRAC));
    }
#else
    for (k = 0; k < 3; ++k) {
        trk.R[k] = (mtt_real)r[k];
    }
#endif
    (void)tv_add_track_xp(&trk, xp, Pp, MTT_P(0.6));
    for (k = 0; k < 5; ++k) {
#ifdef MTT_REAL_FIXED
        (void)tv_add_meas(&trk, MTT_FX_CONST(xp0[0] + tv3_off[k][0], MTT_FX_POS_FRAC),
                          MTT_FX_CONST(xp0[1] + tv3_off[k][1], MTT_FX_POS_FRAC), MTT_AMP(1.0), 1);
#else
        (void)tv_add_meas(&trk, (mtt_real)(xp0[0] + tv3_off[k][0]), (mtt_real)(xp0[1] + tv3_off[k][1]),
                          MTT_AMP(1.0), 1);
#endif
    }
    TV_GATE_AREA(&trk, 0) = MTT_ZERO; /* gate_frame must compute it */
    mtt_gate_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(4, TV_N_PAIRS(&trk));
    TEST_ASSERT_EQUAL_UINT(4, TV_PAIR_COUNT(&trk, 0));
    TEST_ASSERT_TRUE(MTT_GATE_AREA(trk.gamma, trk.tf[0].det_s, trk.tf[0].S, DENS) == TV_GATE_AREA(&trk, 0));
    TV_ASSERT_REAL(tv3_vg * lam_or_1(), TV_Q(TV_GATE_AREA(&trk, 0), MTT_FX_RATIO_FRAC)); /* TV3 V_G */
    peak = MTT_GATE_PEAK(trk.tf[0].det_s, trk.tf[0].S, trk.par.pg, DENS);
    for (k = 0; k < 4; ++k) {
        const mtt_mstore *m = &trk.meas[want_meas[k]];
        const mtt_d2 d2 = mtt_mahal2(trk.tf[0].Si, m->x - trk.tf[0].xp[0], m->y - trk.tf[0].xp[1]);
        TEST_ASSERT_EQUAL_UINT(want_meas[k], TV_PAIR_MEAS(&trk, k));
        TEST_ASSERT_TRUE(MTT_GATE_LIK(peak, d2) == TV_PAIR_P(&trk, k));
        TV_ASSERT_REAL_MSG(tv3_d2[want_meas[k]], TV_Q(d2, MTT_FX_D2_FRAC), "TV3 d2");
        TV_ASSERT_REAL_MSG(tv3_p[want_meas[k]] / lam_or_1(), TV_Q(TV_PAIR_P(&trk, k), MTT_FX_RATIO_FRAC),
                           "TV3 p");
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_tv3_gamma);
    RUN_TEST(test_tv3_area_width);
    RUN_TEST(test_tv3_candidates);
    RUN_TEST(test_tv3_gate_frame);
    return UNITY_END();
}
