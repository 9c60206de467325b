/* SPDX-License-Identifier: BSD-3-Clause */
/* test_motion_ct.c - coordinated-turn model (motion_ct.c): the transition
 * f(x) and its Jacobian against `python3 tools/ci/imm_vectors.py` (section
 * "CT model": closed form, Jacobian by complex-step differentiation; the
 * w = 0 case by the first-order expansion), both branches of the turn
 * coefficients (|wT| = 0, 0.04 by series; 0.15, 0.25 in closed form).
 * Each case names its section line of the script's output (ct_turn,
 * ct_slow, ct_neg, ct_zero). */
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#if MTT_WITH_IMM

/* One case: state, interval, expected f(x) and Jacobian (row-major 5x5). */
typedef struct ct_case {
    const char *name;
    double x[5], dt, xp[5], F[25];
} ct_case;

static const ct_case ct_cases[] = {
    {"turn, wT = 0.25 (closed form)", {100, 50, 150, -40, 0.25}, 1.0,
     {253.4163881, 29.06791349, 155.2330216, -1.64590298, 0.25},
     {1, 0, 0.989615837, -0.1243503132, 7.266534191, 0, 1, 0.1243503132, 0.989615837,
      77.14473411, 0, 0, 0.9689124217, -0.2474039593, 1.64590298, 0, 0, 0.2474039593,
      0.9689124217, 155.2330216, 0, 0, 0, 0, 1}},
    {"slow, wT = 0.04 (series)", {100, 50, 150, -40, 0.02}, 2.0,
     {401.5197931, -23.97946833, 151.4795894, -33.96960414, 0.02},
     {1, 0, 1.999466709, -0.03999466695, 71.96928277, 0, 1, 0.03999466695, 1.999466709,
      302.0130027, 0, 0, 0.9992001067, -0.03998933419, 67.93920828, 0, 0, 0.03998933419,
      0.9992001067, 302.9591787, 0, 0, 0, 0, 1}},
    {"right turn, wT = -0.15 (closed form)", {-3, 7, -120, 200, -0.3}, 0.5,
     {-55.28930495, 111.1169905, -88.76490286, 215.6867915, -0.3},
     {1, 0, 0.4981271082, 0.03742974021, -26.35617839, 0, 1, -0.03742974021, 0.4981271082,
      -12.42135089, 0, 0, 0.9887710779, 0.1494381325, -107.8433957, 0, 0, -0.1494381325,
      0.9887710779, -44.38245143, 0, 0, 0, 0, 1}},
    {"w = 0 is CV (series)", {100, 50, 150, -40, 0}, 2.0,
     {400, -30, 150, -40, 0},
     {1, 0, 2, 0, 80, 0, 1, 0, 2, 300, 0, 0, 1, 0, 80, 0, 0, 0, 1, 300, 0, 0, 0, 0, 1}},
};

static void test_ct_transition_and_jacobian(void)
{
    size_t c;
    for (c = 0; c < sizeof ct_cases / sizeof ct_cases[0]; ++c) {
        const ct_case *k = &ct_cases[c];
        mtt_real x[5], xp[5], F[MTT_MAX_STATE][MTT_MAX_STATE];
        int i, j;
        char w[96];
        for (i = 0; i < 5; ++i) {
            x[i] = (mtt_real)k->x[i];
        }
        mtt_ct_f((mtt_real)k->dt, x, xp, F);
        for (i = 0; i < 5; ++i) {
            snprintf(w, sizeof w, "%s: xp[%d]", k->name, i);
            TV_ASSERT_REAL_MSG(k->xp[i], xp[i], w);
            for (j = 0; j < 5; ++j) {
                snprintf(w, sizeof w, "%s: F[%d][%d]", k->name, i, j);
                TV_ASSERT_REAL_MSG(k->F[5 * i + j], F[i][j], w);
            }
        }
    }
}

/* Q: the CV block of docs/TEST_VECTORS.md TV1 (dt 1, Sw 5) plus sw_turn dt. */
static void test_ct_q(void)
{
    static const double Q4[16] = {1.666666667, 0, 2.5, 0, 0, 1.666666667, 0, 2.5,
                                  2.5, 0, 5, 0, 0, 2.5, 0, 5};
    mtt_real Q[MTT_MAX_STATE][MTT_MAX_STATE];
    int i;
    mtt_ct_q(MTT_R(1.0), MTT_R(5.0), MTT_R(0.01), Q);
    TV_ASSERT_MAT4(Q4, Q);
    TV_ASSERT_REAL(0.01, Q[4][4]);
    for (i = 0; i < 4; ++i) {
        TEST_ASSERT_TRUE(Q[i][4] == MTT_R(0.0) && Q[4][i] == MTT_R(0.0));
    }
}

/* mtt_ct_predict: xp = f(x) and F P F' + Q with the Jacobian and Q of
 * mtt_ct_f / mtt_ct_q (tested above), formed densely in double; in place
 * the same. */
static void test_ct_predict(void)
{
    static const double P5[25] = {30, 2, 8, 1, 0.05,  2, 28, 0.5, 7, -0.04,  8, 0.5, 6, 0.3, 0.02,
                                  1, 7, 0.3, 5, -0.01,  0.05, -0.04, 0.02, -0.01, 0.004};
    const ct_case *k = &ct_cases[0]; /* turn, wT = 0.25 */
    mtt_real x[MTT_MAX_STATE] = {0}, xp[MTT_MAX_STATE], xf[MTT_CT_N], P[MTT_MAX_STATE][MTT_MAX_STATE] = {{0}},
             Pp[MTT_MAX_STATE][MTT_MAX_STATE], F[MTT_MAX_STATE][MTT_MAX_STATE], Q[MTT_MAX_STATE][MTT_MAX_STATE];
    double FP[5][5], e;
    int i, j, m;
    char w[48];
    for (i = 0; i < 5; ++i) {
        x[i] = (mtt_real)k->x[i];
        for (j = 0; j < 5; ++j) {
            P[i][j] = (mtt_real)P5[5 * i + j];
        }
    }
    mtt_ct_f((mtt_real)k->dt, x, xf, F);
    mtt_ct_q((mtt_real)k->dt, MTT_R(5.0), MTT_R(0.01), Q);
    for (i = 0; i < 5; ++i) {
        for (j = 0; j < 5; ++j) {
            FP[i][j] = 0.0;
            for (m = 0; m < 5; ++m) {
                FP[i][j] += (double)F[i][m] * P5[5 * m + j];
            }
        }
    }
    mtt_ct_predict((mtt_real)k->dt, MTT_R(5.0), MTT_R(0.01), x, P, xp, Pp);
    for (i = 0; i < 5; ++i) {
        snprintf(w, sizeof w, "xp[%d]", i);
        TV_ASSERT_REAL_MSG(k->xp[i], xp[i], w);
        for (j = 0; j < 5; ++j) {
            e = (double)Q[i][j];
            for (m = 0; m < 5; ++m) {
                e += FP[i][m] * (double)F[j][m];
            }
            snprintf(w, sizeof w, "Pp[%d][%d]", i, j);
            TV_ASSERT_REAL_MSG(e, Pp[i][j], w);
            TEST_ASSERT_TRUE(Pp[i][j] == Pp[j][i]);
        }
    }
    /* the turn rate's variance: its own plus sw_turn dt */
    TV_ASSERT_REAL(0.014, Pp[4][4]);
    mtt_ct_predict((mtt_real)k->dt, MTT_R(5.0), MTT_R(0.01), x, P, x, P);
    TEST_ASSERT_EQUAL_MEMORY(xp, x, 5 * sizeof x[0]);
    for (i = 0; i < 5; ++i) {
        TEST_ASSERT_EQUAL_MEMORY(Pp[i], P[i], 5 * sizeof P[i][0]);
    }
}

#else

static void test_ct_left_out(void)
{
    TEST_ASSERT_EQUAL_INT(4, MTT_MAX_STATE);
}

#endif

int main(void)
{
    UNITY_BEGIN();
#if MTT_WITH_IMM
    RUN_TEST(test_ct_transition_and_jacobian);
    RUN_TEST(test_ct_q);
    RUN_TEST(test_ct_predict);
#else
    RUN_TEST(test_ct_left_out);
#endif
    return UNITY_END();
}
