/* SPDX-License-Identifier: BSD-3-Clause */
/* test_kalman.c - CV model, Kalman predict / innovation / Joseph update,
 * PDA combination with one measurement, Cholesky quadratic form.
 * Expected numbers: docs/TEST_VECTORS.md TV1, TV2 (and TV11 for chol4). */
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

/* TV2 inputs */
static const mtt_state tv2_x0 = {MTT_R(100.0), MTT_R(50.0), MTT_R(10.0), MTT_R(-5.0)};
static const mtt_cov tv2_P0 = {{MTT_R(4.0), MTT_R(1.0), MTT_R(1.0), MTT_R(0.0)},
                                      {MTT_R(1.0), MTT_R(4.0), MTT_R(0.0), MTT_R(1.0)},
                                      {MTT_R(1.0), MTT_R(0.0), MTT_R(1.0), MTT_R(0.0)},
                                      {MTT_R(0.0), MTT_R(1.0), MTT_R(0.0), MTT_R(1.0)}};
static const mtt_real tv2_R[3] = {MTT_R(1.0), MTT_R(0.3), MTT_R(2.0)}; /* TV2 R = [1, 0.3; 0.3, 2] */
static const mtt_real tv2_z[2] = {MTT_R(111.5), MTT_R(44.0)};

/* TV2 expected */
static const double tv2_xpred[4] = {110, 45, 10, -5};
static const double tv2_Ppred[16] = {8.666666667, 1, 4.5, 0, 1, 8.666666667, 0, 4.5,
                                     4.5, 0, 6, 0, 0, 4.5, 0, 6};
static const double tv2_S[3] = {9.666666667, 1.3, 10.66666667};
static const double tv2_K[8] = {0.8986732983,  -0.01577580824, -0.005915928089, 0.8132210037,
                                0.4732742471,  -0.05768029886, -0.05768029886,  0.4289047864};
static const double tv2_d2 = 0.3704028309;
static const double tv2_xupd[4] = {111.3637858, 44.1779051, 10.76759167, -5.515425235};
static const double tv2_Pupd[16] = {
    0.8939405559, 0.238050373,  0.4559701574, 0.07099113706, 0.238050373,  1.624667229,
    0.0266216764, 0.8405054832, 0.4559701574, 0.0266216764,  3.870265888,  0.2595613449,
    0.07099113706, 0.8405054832, 0.2595613449, 4.069928461};

static void tv2_predict(mtt_state xp, mtt_cov Pp)
{
    mtt_cov P0;
    memcpy(P0, tv2_P0, sizeof P0);
    mtt_kalman_predict(MTT_R(1.0), MTT_R(5.0), tv2_x0, P0, xp, Pp);
}

/* ---- TV1 ---- */

static void check_F(mtt_real dt, const double F[16])
{
    /* Column k of F is F e_k: predict the unit vectors (the state part does
     * not depend on Sw or P). */
    int k, i;
    for (k = 0; k < 4; ++k) {
        mtt_state e = {MTT_R(0.0), MTT_R(0.0), MTT_R(0.0), MTT_R(0.0)};
        mtt_state xp;
        mtt_cov P, Pp;
        memset(P, 0, sizeof P);
        e[k] = MTT_R(1.0);
        mtt_kalman_predict(dt, MTT_R(5.0), e, P, xp, Pp);
        for (i = 0; i < 4; ++i) {
            TV_ASSERT_REAL_MSG(F[4 * i + k], xp[i], "F column");
        }
    }
}

static void test_tv1_dt1(void)
{
    /* TV1 dt = 1, Sw = 5 */
    static const double F[16] = {1, 0, 1, 0, 0, 1, 0, 1, 0, 0, 1, 0, 0, 0, 0, 1};
    static const double Q[16] = {1.666666667, 0, 2.5, 0, 0, 1.666666667, 0, 2.5,
                                 2.5, 0, 5, 0, 0, 2.5, 0, 5};
    mtt_cov Qa;
    mtt_motion_q(MTT_R(1.0), MTT_R(5.0), Qa);
    TV_ASSERT_MAT4(Q, Qa);
    check_F(MTT_R(1.0), F);
}

static void test_tv1_dt025(void)
{
    /* TV1 dt = 0.25, Sw = 5 */
    static const double F[16] = {1, 0, 0.25, 0, 0, 1, 0, 0.25, 0, 0, 1, 0, 0, 0, 0, 1};
    static const double Q[16] = {0.02604166667, 0, 0.15625, 0, 0, 0.02604166667, 0, 0.15625,
                                 0.15625, 0, 1.25, 0, 0, 0.15625, 0, 1.25};
    mtt_cov Qa;
    mtt_motion_q(MTT_R(0.25), MTT_R(5.0), Qa);
    TV_ASSERT_MAT4(Q, Qa);
    check_F(MTT_R(0.25), F);
}

static void test_tv1_predict_with_zero_P_is_Q(void)
{
    /* Pp = F 0 F' + Q = Q (TV1 dt = 0.25 Q) */
    static const double Q[16] = {0.02604166667, 0, 0.15625, 0, 0, 0.02604166667, 0, 0.15625,
                                 0.15625, 0, 1.25, 0, 0, 0.15625, 0, 1.25};
    mtt_state xp;
    mtt_cov P, Pp;
    memset(P, 0, sizeof P);
    mtt_kalman_predict(MTT_R(0.25), MTT_R(5.0), tv2_x0, P, xp, Pp);
    TV_ASSERT_MAT4(Q, Pp);
}

/* ---- TV2 ---- */

static void test_tv2_predict(void)
{
    mtt_state xp;
    mtt_cov Pp;
    tv2_predict(xp, Pp);
    TV_ASSERT_VEC(tv2_xpred, xp, 4); /* TV2 x_pred */
    TV_ASSERT_MAT4(tv2_Ppred, Pp);   /* TV2 P_pred */
    TV_ASSERT_SYM4(Pp);
}

static void test_tv2_innovation(void)
{
    mtt_real S[3], Si[3], det, K[MTT_MAX_STATE][2];
    mtt_state xp;
    mtt_cov Pp;
    mtt_real nux, nuy;
    int i;
    tv2_predict(xp, Pp);
    TEST_ASSERT_EQUAL_INT(0, mtt_kalman_innov(Pp, tv2_R, S, Si, &det, K));
    TV_ASSERT_VEC(tv2_S, S, 3); /* TV2 S */
    TV_ASSERT_REAL(101.4211111, det); /* TV3 det S */
    for (i = 0; i < 4; ++i) {
        TV_ASSERT_REAL_MSG(tv2_K[2 * i], K[i][0], "K[i][0]"); /* TV2 K */
        TV_ASSERT_REAL_MSG(tv2_K[2 * i + 1], K[i][1], "K[i][1]");
    }
    /* Si S = I */
    TV_ASSERT_REAL(1.0, S[0] * Si[0] + S[1] * Si[1]);
    TV_ASSERT_REAL(0.0, S[0] * Si[1] + S[1] * Si[2]);
    TV_ASSERT_REAL(1.0, S[1] * Si[1] + S[2] * Si[2]);
    /* TV2 z_hat = [110, 45], nu = [1.5, -1] */
    TV_ASSERT_REAL(110.0, xp[0]);
    TV_ASSERT_REAL(45.0, xp[1]);
    nux = tv2_z[0] - xp[0];
    nuy = tv2_z[1] - xp[1];
    TV_ASSERT_REAL(1.5, nux);
    TV_ASSERT_REAL(-1.0, nuy);
    TV_ASSERT_REAL(tv2_d2, mtt_mahal2(Si, nux, nuy)); /* TV2 d2 */
}

static void test_tv2_joseph_and_standard_form(void)
{
    mtt_real S[3], Si[3], det, K[MTT_MAX_STATE][2];
    mtt_state xp, x;
    mtt_cov Pp, Pc;
    double std_form[16];
    int i, j;
    tv2_predict(xp, Pp);
    TEST_ASSERT_EQUAL_INT(0, mtt_kalman_innov(Pp, tv2_R, S, Si, &det, K));
    /* The PDA update with no measurement and beta0 = 0 is the Joseph form. */
    mtt_kalman_pda(xp, Pp, K, Si, tv2_R, 0, NULL, NULL, MTT_R(0.0), x, Pc);
    TV_ASSERT_MAT4(tv2_Pupd, Pc); /* TV2 P_upd (Joseph) */
    TV_ASSERT_SYM4(Pc);
    /* TV2 check: the standard form (I - K H) P_pred equals the Joseph result. */
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j) {
            std_form[4 * i + j] = (double)Pp[i][j] - (double)K[i][0] * (double)Pp[0][j] -
                                  (double)K[i][1] * (double)Pp[1][j];
        }
    }
    TV_ASSERT_MAT4(tv2_Pupd, Pc);
    for (i = 0; i < 16; ++i) {
        TV_ASSERT_REAL_MSG(tv2_Pupd[i], std_form[i], "(I-KH)P_pred"); /* TV2 Check */
    }
    /* Positive definite: chol succeeds. */
    {
        const mtt_state b = {MTT_R(1.0), MTT_R(0.0), MTT_R(0.0), MTT_R(0.0)};
        mtt_real d2;
        TEST_ASSERT_EQUAL_INT(0, mtt_chol_quad(Pc, b, &d2));
    }
}

static void test_tv2_update_through_pda(void)
{
    /* One measurement with beta = 1, beta0 = 0: the ordinary Kalman update. */
    mtt_real S[3], Si[3], det, K[MTT_MAX_STATE][2];
    mtt_state xp, x;
    mtt_cov Pp, P;
    mtt_real nu[1][2];
    const mtt_real beta[1] = {MTT_R(1.0)};
    tv2_predict(xp, Pp);
    TEST_ASSERT_EQUAL_INT(0, mtt_kalman_innov(Pp, tv2_R, S, Si, &det, K));
    nu[0][0] = tv2_z[0] - xp[0];
    nu[0][1] = tv2_z[1] - xp[1];
    mtt_kalman_pda(xp, Pp, K, Si, tv2_R, 1, nu, beta, MTT_R(0.0), x, P);
    TV_ASSERT_VEC(tv2_xupd, x, 4); /* TV2 x_upd */
    TV_ASSERT_MAT4(tv2_Pupd, P);   /* TV2 P_upd */
    TV_ASSERT_SYM4(P);
}

static void test_tv2_pda_no_measurement_keeps_prediction(void)
{
    /* m = 0, beta0 = 1: x = x_pred, P = P_pred (TV2 x_pred, P_pred). */
    mtt_real S[3], Si[3], det, K[MTT_MAX_STATE][2];
    mtt_state xp, x;
    mtt_cov Pp, P;
    mtt_real nu[1][2] = {{MTT_R(0.0), MTT_R(0.0)}};
    const mtt_real beta[1] = {MTT_R(0.0)};
    tv2_predict(xp, Pp);
    TEST_ASSERT_EQUAL_INT(0, mtt_kalman_innov(Pp, tv2_R, S, Si, &det, K));
    mtt_kalman_pda(xp, Pp, K, Si, tv2_R, 0, nu, beta, MTT_R(1.0), x, P);
    TV_ASSERT_VEC(tv2_xpred, x, 4);
    TV_ASSERT_MAT4(tv2_Ppred, P);
}

static void test_innov_rejects_singular_and_nan(void)
{
    mtt_cov Pp;
    mtt_real S[3], Si[3], det = MTT_R(-7.0), K[MTT_MAX_STATE][2];
    const mtt_real Rs[3] = {MTT_R(1.0), MTT_R(1.0), MTT_R(1.0)}; /* det S = 0 */
    memset(Pp, 0, sizeof Pp);
    TEST_ASSERT_EQUAL_INT(-1, mtt_kalman_innov(Pp, Rs, S, Si, &det, K));
    TEST_ASSERT_TRUE(det == MTT_R(-7.0)); /* not written on failure */
    {
        const mtt_real Rn[3] = {MTT_R(1.0), MTT_R(2.0), MTT_R(1.0)}; /* det S < 0 */
        TEST_ASSERT_EQUAL_INT(-1, mtt_kalman_innov(Pp, Rn, S, Si, &det, K));
    }
    Pp[0][0] = (mtt_real)NAN;
    TEST_ASSERT_EQUAL_INT(-1, mtt_kalman_innov(Pp, tv2_R, S, Si, &det, K));
}

/* ---- symmetrisation ---- */

static void test_sym4(void)
{
    mtt_cov A;
    int i, j;
    for (i = 0; i < 4; ++i) {
        for (j = 0; j < 4; ++j) {
            A[i][j] = (mtt_real)(4 * i + j);
        }
    }
    mtt_sym(A);
    TV_ASSERT_SYM4(A);
    TV_ASSERT_REAL(2.5, A[0][1]); /* (1 + 4) / 2 */
    TV_ASSERT_REAL(2.5, A[1][0]);
    TV_ASSERT_REAL(5.0, A[1][1]); /* diagonal untouched */
    TV_ASSERT_REAL(12.5, A[2][3]); /* (11 + 14) / 2 */
}

/* ---- mtt_chol4_quad ---- */

static void test_chol4_full_matrix(void)
{
    /* A = TV2 P_pred (full, not diagonal), b = A e1: b' A^-1 b = e1' A e1 =
     * P_pred[1,1] = 8.666666667 (TV2). */
    mtt_real d2 = MTT_R(-1.0);
    mtt_state xp, b;
    mtt_cov A;
    int i;
    tv2_predict(xp, A);
    for (i = 0; i < 4; ++i) {
        b[i] = A[i][0];
    }
    TEST_ASSERT_EQUAL_INT(0, mtt_chol_quad(A, b, &d2));
    TV_ASSERT_REAL(8.666666667, d2); /* TV2 P_pred[1,1] */
    /* b = A e4: d2 = P_pred[4,4] = 6 (TV2). */
    for (i = 0; i < 4; ++i) {
        b[i] = A[i][3];
    }
    TEST_ASSERT_EQUAL_INT(0, mtt_chol_quad(A, b, &d2));
    TV_ASSERT_REAL(6.0, d2); /* TV2 P_pred[4,4] */
}

static void test_chol4_innovation_block(void)
{
    /* A = blockdiag(S, I) with S of TV2, b = [nu, 0, 0]: d2 = TV2 d2. */
    mtt_cov A;
    mtt_real d2 = MTT_R(0.0);
    const mtt_state b = {MTT_R(1.5), MTT_R(-1.0), MTT_R(0.0), MTT_R(0.0)};
    memset(A, 0, sizeof A);
    A[0][0] = MTT_R(9.666666667);
    A[0][1] = MTT_R(1.3);
    A[1][0] = MTT_R(1.3);
    A[1][1] = MTT_R(10.66666667);
    A[2][2] = MTT_R(1.0);
    A[3][3] = MTT_R(1.0);
    TEST_ASSERT_EQUAL_INT(0, mtt_chol_quad(A, b, &d2));
    TV_ASSERT_REAL(0.3704028309, d2); /* TV2 d2 */
}

static void test_chol4_rejects_non_pd(void)
{
    mtt_cov A;
    mtt_real d2 = MTT_R(42.0);
    const mtt_state b = {MTT_R(1.0), MTT_R(1.0), MTT_R(1.0), MTT_R(1.0)};
    memset(A, 0, sizeof A);
    /* indefinite: [[1, 2], [2, 1]] block has eigenvalue -1 */
    A[0][0] = MTT_R(1.0);
    A[0][1] = MTT_R(2.0);
    A[1][0] = MTT_R(2.0);
    A[1][1] = MTT_R(1.0);
    A[2][2] = MTT_R(1.0);
    A[3][3] = MTT_R(1.0);
    TEST_ASSERT_EQUAL_INT(-1, mtt_chol_quad(A, b, &d2));
    TEST_ASSERT_TRUE(d2 == MTT_R(42.0)); /* untouched */
    /* singular (last pivot 0) */
    A[0][1] = MTT_R(0.0);
    A[1][0] = MTT_R(0.0);
    A[3][3] = MTT_R(0.0);
    TEST_ASSERT_EQUAL_INT(-1, mtt_chol_quad(A, b, &d2));
    /* NaN */
    A[3][3] = (mtt_real)NAN;
    TEST_ASSERT_EQUAL_INT(-1, mtt_chol_quad(A, b, &d2));
    /* negative definite */
    memset(A, 0, sizeof A);
    A[0][0] = MTT_R(-1.0);
    A[1][1] = MTT_R(1.0);
    A[2][2] = MTT_R(1.0);
    A[3][3] = MTT_R(1.0);
    TEST_ASSERT_EQUAL_INT(-1, mtt_chol_quad(A, b, &d2));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_tv1_dt1);
    RUN_TEST(test_tv1_dt025);
    RUN_TEST(test_tv1_predict_with_zero_P_is_Q);
    RUN_TEST(test_tv2_predict);
    RUN_TEST(test_tv2_innovation);
    RUN_TEST(test_tv2_joseph_and_standard_form);
    RUN_TEST(test_tv2_update_through_pda);
    RUN_TEST(test_tv2_pda_no_measurement_keeps_prediction);
    RUN_TEST(test_innov_rejects_singular_and_nan);
    RUN_TEST(test_sym4);
    RUN_TEST(test_chol4_full_matrix);
    RUN_TEST(test_chol4_innovation_block);
    RUN_TEST(test_chol4_rejects_non_pd);
    return UNITY_END();
}
