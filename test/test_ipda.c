/* SPDX-License-Identifier: BSD-3-Clause */
/* test_ipda.c - IPDA on the TV5 inputs (TV6): betas, delta, existence,
 * PDA state update, and the non-parametric clutter density (ALGORITHMS.md §5.2, §6). */
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "tv_fixture.h"
#include "unity.h"

static mtt_tracker trk;

void setUp(void) {}
void tearDown(void) {}

#define PD MTT_R(0.9)
#define PG MTT_R(0.99)
#define LAMBDA MTT_R(0.002)

/* TV5 inputs (TV6 runs on them) */
static const mtt_real tv5_R[3] = {MTT_R(1.0), MTT_R(0.3), MTT_R(2.0)};
static const mtt_real tv5_z[3][2] = {{MTT_R(110.8), MTT_R(44.5)},
                                     {MTT_R(106.5), MTT_R(47.4)},
                                     {MTT_R(115.0), MTT_R(48.0)}};
static const mtt_real tv5_amp[3] = {MTT_R(40.0), MTT_R(95.0), MTT_R(60.0)};

/* TV6 expected, known lambda */
static const double tv6_L = 10.92474382;
static const double tv6_delta = -9.92474382;
static const double tv6_beta[3] = {0.61878548, 0.233249123, 0.1379880464};
static const double tv6_beta0 = 0.009977350664;
static const double tv6_ex = 0.942486148;
static const double tv6_x[4] = {110.320767, 45.53809847, 10.1361263, -4.736309597};
static const double tv6_P[16] = {
    6.286621717,  -0.09786656496, 3.31419463,    -0.4332224045, -0.09786656496, 3.219038845,
    -0.2469598763, 1.699919386,   3.31419463,    -0.2469598763, 5.390980795,   -0.05795771982,
    -0.4332224045, 1.699919386,   -0.05795771982, 4.552799418};
/* TV6 expected, lambda_hat */
static const double tv6_lamhat = 0.008460531697;
static const double tv6h_delta = -1.665752745;
static const double tv6h_beta[3] = {0.5994650249, 0.2259663419, 0.1336796197};
static const double tv6h_beta0 = 0.04088901351;
static const double tv6h_ex = 0.7999451497;

struct tv5 {
    mtt_real S[3], Si[3], det, K[MTT_MAX_STATE][2], vg;
    mtt_state xp;
    mtt_cov Pp;
    mtt_real p[3], nu[3][2];
};

static void tv5_setup(struct tv5 *t)
{
    const mtt_state x0 = {MTT_R(100.0), MTT_R(50.0), MTT_R(10.0), MTT_R(-5.0)};
    mtt_cov P0 = {{MTT_R(4.0), MTT_R(1.0), MTT_R(1.0), MTT_R(0.0)},
                         {MTT_R(1.0), MTT_R(4.0), MTT_R(0.0), MTT_R(1.0)},
                         {MTT_R(1.0), MTT_R(0.0), MTT_R(1.0), MTT_R(0.0)},
                         {MTT_R(0.0), MTT_R(1.0), MTT_R(0.0), MTT_R(1.0)}};
    int j;
    mtt_kalman_predict(MTT_R(1.0), MTT_R(5.0), x0, P0, t->xp, t->Pp);
    TEST_ASSERT_EQUAL_INT(0, mtt_kalman_innov(t->Pp, tv5_R, t->S, t->Si, &t->det, t->K));
    t->vg = mtt_gate_volume(mtt_gate_gamma(PG), t->det);
    TV_ASSERT_REAL(291.4001257, t->vg); /* TV5 V_G */
    for (j = 0; j < 3; ++j) {
        t->nu[j][0] = tv5_z[j][0] - t->xp[0];
        t->nu[j][1] = tv5_z[j][1] - t->xp[1];
        t->p[j] = mtt_gate_likelihood(mtt_mahal2(t->Si, t->nu[j][0], t->nu[j][1]), t->det, PG);
    }
    TV_ASSERT_REAL(0.01517412536, t->p[0]);  /* TV5 z1 p */
    TV_ASSERT_REAL(0.005719835949, t->p[1]); /* TV5 z2 p */
    TV_ASSERT_REAL(0.003383802596, t->p[2]); /* TV5 z3 p */
}

static void test_tv6_betas_and_existence(void)
{
    struct tv5 t;
    const mtt_real lam[3] = {LAMBDA, LAMBDA, LAMBDA};
    mtt_real beta[3], beta0, L;
    int j;
    double sum;
    tv5_setup(&t);
    tv_ipda_betas(PD, PG, t.p, lam, 3, beta, &beta0, &L);
    TV_ASSERT_REAL(tv6_L, L);                  /* TV6 L = 1 - delta */
    TV_ASSERT_REAL(tv6_delta, MTT_R(1.0) - L); /* TV6 delta */
    TV_ASSERT_VEC(tv6_beta, beta, 3);          /* TV6 beta_1..3 */
    TV_ASSERT_REAL(tv6_beta0, beta0);          /* TV6 beta_0 */
    sum = (double)beta0;
    for (j = 0; j < 3; ++j) {
        sum += (double)beta[j];
    }
    TV_ASSERT_REAL(1.0, sum); /* ALGORITHMS.md §6: beta_0 + sum beta_j = 1 */
    TV_ASSERT_REAL(tv6_ex, mtt_existence_update(MTT_R(0.6), L)); /* TV6 P(exist|Z^k) */
}

static void test_tv6_state_update(void)
{
    struct tv5 t;
    const mtt_real lam[3] = {LAMBDA, LAMBDA, LAMBDA};
    mtt_real beta[3], beta0, L;
    mtt_state x;
    mtt_cov P;
    tv5_setup(&t);
    tv_ipda_betas(PD, PG, t.p, lam, 3, beta, &beta0, &L);
    mtt_kalman_pda(t.xp, t.Pp, t.K, t.Si, tv5_R, 3, t.nu, beta, beta0, x, P);
    TV_ASSERT_VEC(tv6_x, x, 4); /* TV6 x_upd */
    TV_ASSERT_MAT4(tv6_P, P);   /* TV6 P_upd */
    TV_ASSERT_SYM4(P);
}

static void test_tv6_m0(void)
{
    /* m = 0: L = 1 - PD PG, beta_0 = 1 (TV5 m = 0: delta = 0.891). */
    mtt_real beta[1], beta0, L;
    tv_ipda_betas(PD, PG, NULL, NULL, 0, beta, &beta0, &L);
    TV_ASSERT_REAL(0.891, MTT_R(1.0) - L);
    TV_ASSERT_REAL(1.0, beta0);
    TV_ASSERT_REAL(0.1405242802, mtt_existence_update(MTT_R(0.6), L)); /* TV5 m = 0 */
}

static void test_tv6_lambda_hat(void)
{
    struct tv5 t;
    mtt_real lh, lam[3], beta[3], beta0, L;
    tv5_setup(&t);
    lh = mtt_clutter_estimate(3, PD, PG, MTT_R(0.6), t.vg);
    TV_ASSERT_REAL(tv6_lamhat, lh); /* TV6 lambda_hat */
    lam[0] = lh;
    lam[1] = lh;
    lam[2] = lh;
    tv_ipda_betas(PD, PG, t.p, lam, 3, beta, &beta0, &L);
    TV_ASSERT_REAL(tv6h_delta, MTT_R(1.0) - L); /* TV6 IPDA with lambda_hat: delta */
    TV_ASSERT_VEC(tv6h_beta, beta, 3);
    TV_ASSERT_REAL(tv6h_beta0, beta0);
    TV_ASSERT_REAL(tv6h_ex, mtt_existence_update(MTT_R(0.6), L));
}

/* Through the tracker stages in `ipda` mode. */
static void tv6_tracker(mtt_real clutter_density)
{
    mtt_params p;
    struct tv5 t;
    int j;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.association = MTT_ASSOC_IPDA;
    p.pd = PD;
    p.pg = PG;
    p.clutter_density = clutter_density;
    tv_init(&trk, &p);
    TV_R(&trk)[0] = tv5_R[0];
    TV_R(&trk)[1] = tv5_R[1];
    TV_R(&trk)[2] = tv5_R[2];
    tv5_setup(&t);
    (void)tv_add_track_xp(&trk, t.xp, t.Pp, MTT_R(0.6));
    for (j = 0; j < 3; ++j) {
        (void)tv_add_meas(&trk, tv5_z[j][0], tv5_z[j][1], tv5_amp[j], 1);
    }
    (void)tv_add_meas(&trk, MTT_R(118.0), MTT_R(38.0), MTT_R(1.0), 1); /* TV3 c4: outside */
    mtt_gate_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(3, TV_PAIR_COUNT(&trk, 0));
    mtt_clutter_frame(&trk, 0);
    mtt_associate_frame(&trk);
    mtt_update_frame(&trk);
}

static void test_tv6_ipda_mode_known_lambda(void)
{
    tv6_tracker(LAMBDA);
    TV_ASSERT_REAL(0.002, TV_LAMBDA(&trk, 0));
    TV_ASSERT_VEC(tv6_x, TV_X(&trk, 0), 4);            /* TV6 x_upd */
    TV_ASSERT_MAT4(tv6_P, TV_P(&trk, 0));              /* TV6 P_upd */
    TV_ASSERT_REAL(tv6_ex, TV_EXISTENCE(&trk, 0));     /* TV6 P(exist|Z^k) */
    TEST_ASSERT_EQUAL_INT(0, TV_TRACK_MEAS(&trk, 0));        /* largest beta: z1 */
    /* PDA modes: gated measurements are used, the ungated one is not. */
    TEST_ASSERT_EQUAL_UINT(1, TV_USED(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(1, TV_USED(&trk, 2));
    TEST_ASSERT_EQUAL_UINT(0, TV_USED(&trk, 3));
}

static void test_tv6_ipda_mode_estimated_lambda(void)
{
    tv6_tracker(MTT_R(0.0));
    TV_ASSERT_REAL(tv6_lamhat, TV_LAMBDA(&trk, 0));        /* TV6 lambda_hat */
    TV_ASSERT_REAL(tv6_lamhat, TV_PAIR_LAM(&trk, 1));
    TV_ASSERT_REAL(tv6h_ex, TV_EXISTENCE(&trk, 0));    /* TV6 with lambda_hat */
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_tv6_betas_and_existence);
    RUN_TEST(test_tv6_state_update);
    RUN_TEST(test_tv6_m0);
    RUN_TEST(test_tv6_lambda_hat);
    RUN_TEST(test_tv6_ipda_mode_known_lambda);
    RUN_TEST(test_tv6_ipda_mode_estimated_lambda);
    return UNITY_END();
}
