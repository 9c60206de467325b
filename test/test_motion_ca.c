/* SPDX-License-Identifier: BSD-3-Clause */
/* test_motion_ca.c - nearly constant acceleration model (motion_ca.c):
 * F and Q in closed form against `python3 tools/ci/imm_vectors.py`
 * (section "CA model": F = expm(A T) by its power series, Q by quadrature
 * of the continuous white-noise-jerk integral). */
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#if MTT_WITH_IMM

static void test_ca_axis(void)
{
    static const double F3[9] = {1, 0.5, 0.125, 0, 1, 0.5, 0, 0, 1};
    static const double Q3[9] = {0.0046875, 0.0234375, 0.0625, 0.0234375, 0.125,
                                 0.375,     0.0625,    0.375,  1.5};
    mtt_real F[3][3], Q[3][3];
    int i, j;
    mtt_ca_axis(MTT_R(0.5), MTT_R(3.0), F, Q);
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            TV_ASSERT_REAL_MSG(F3[3 * i + j], F[i][j], "F3");
            TV_ASSERT_REAL_MSG(Q3[3 * i + j], Q[i][j], "Q3");
        }
    }
}

/* A symmetric positive definite 6x6 covariance with every entry nonzero,
 * axes coupled (row-major). */
static const double P6[36] = {
    40, 3, 12, 1.5, 2, 0.4,  3, 35, 1, 10, 0.3, 1.8,  12, 1, 9, 0.6, 1.5, 0.2,
    1.5, 10, 0.6, 8, 0.1, 1.2,  2, 0.3, 1.5, 0.1, 0.9, 0.05,  0.4, 1.8, 0.2, 1.2, 0.05, 0.7};

/* mtt_ca_predict against F P F' + Q formed densely in double, F and Q
 * written out here from the model (not from motion_ca.c), and in place:
 * the same result. */
static void test_ca_predict(void)
{
    const double dt = 0.5, q = 3.0, h = 0.5 * dt * dt;
    const double qa[3][3] = {{q * dt * dt * dt * dt * dt / 20, q * dt * dt * dt * dt / 8, q * dt * dt * dt / 6},
                             {q * dt * dt * dt * dt / 8, q * dt * dt * dt / 3, q * dt * dt / 2},
                             {q * dt * dt * dt / 6, q * dt * dt / 2, q * dt}};
    const double xv[6] = {10, -20, 150, 30, 4, -9};
    double F[6][6] = {{0}}, FP[6][6], e[6][6], ex[6];
    mtt_real x[MTT_MAX_STATE] = {0}, xp[MTT_MAX_STATE], P[MTT_MAX_STATE][MTT_MAX_STATE] = {{0}},
             Pp[MTT_MAX_STATE][MTT_MAX_STATE];
    int i, j, k;
    char w[48];
    for (i = 0; i < 6; ++i) {
        F[i][i] = 1.0;
        if (i < 4) {
            F[i][i + 2] = dt;
        }
        if (i < 2) {
            F[i][i + 4] = h;
        }
        x[i] = (mtt_real)xv[i];
        for (j = 0; j < 6; ++j) {
            P[i][j] = (mtt_real)P6[6 * i + j];
        }
    }
    for (i = 0; i < 6; ++i) {
        ex[i] = 0.0;
        for (k = 0; k < 6; ++k) {
            ex[i] += F[i][k] * xv[k];
        }
        for (j = 0; j < 6; ++j) {
            FP[i][j] = 0.0;
            for (k = 0; k < 6; ++k) {
                FP[i][j] += F[i][k] * P6[6 * k + j];
            }
        }
    }
    for (i = 0; i < 6; ++i) {
        for (j = 0; j < 6; ++j) {
            e[i][j] = ((i - j) % 2 == 0) ? qa[i / 2][j / 2] : 0.0;
            for (k = 0; k < 6; ++k) {
                e[i][j] += FP[i][k] * F[j][k];
            }
        }
    }
    TV_ASSERT_REAL(85.5, ex[0]); /* test_ca_model's F x */
    mtt_ca_predict((mtt_real)dt, (mtt_real)q, x, P, xp, Pp);
    for (i = 0; i < 6; ++i) {
        snprintf(w, sizeof w, "xp[%d]", i);
        TV_ASSERT_REAL_MSG(ex[i], xp[i], w);
        for (j = 0; j < 6; ++j) {
            snprintf(w, sizeof w, "Pp[%d][%d]", i, j);
            TV_ASSERT_REAL_MSG(e[i][j], Pp[i][j], w);
            TEST_ASSERT_TRUE(Pp[i][j] == Pp[j][i]);
        }
    }
    TV_ASSERT_REAL(e[0][0], Pp[0][0]);
    /* in place */
    mtt_ca_predict((mtt_real)dt, (mtt_real)q, x, P, x, P);
    TEST_ASSERT_EQUAL_MEMORY(xp, x, 6 * sizeof x[0]);
    for (i = 0; i < 6; ++i) {
        TEST_ASSERT_EQUAL_MEMORY(Pp[i], P[i], 6 * sizeof P[i][0]);
    }
}

#else

static void test_ca_left_out(void)
{
    TEST_ASSERT_EQUAL_INT(4, MTT_MAX_STATE);
}

#endif

int main(void)
{
    UNITY_BEGIN();
#if MTT_WITH_IMM
    RUN_TEST(test_ca_axis);
    RUN_TEST(test_ca_predict);
#else
    RUN_TEST(test_ca_left_out);
#endif
    return UNITY_END();
}
