/* SPDX-License-Identifier: BSD-3-Clause */
/* test_lm_clutter.c - LM clutter density (ALGORITHMS.md §8) on TV8: d2 and p per pair,
 * Ptilde, W_j, lambda_tilde, and LM-IPDA betas and existence; also the
 * per-track lambda of ALGORITHMS.md §5.1 / 5.2; TV8c: lm-ipda-all's density over
 * all tracks (§8.3). */
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "tv_fixture.h"
#include "unity.h"

static mtt_tracker trk;

void setUp(void) {}
void tearDown(void) {}

/* TV8 pairs in (track, measurement) order: (T1,z1) (T1,z2) (T2,z2) (T2,z3) */
static const uint16_t pt[4] = {0, 0, 1, 1}, pm[4] = {0, 1, 1, 2};
static const double tv8_d2[4] = {0.8409090909, 1.472727273, 2.311186441, 1.738983051};
static const double tv8_p[4] = {0.03183372832, 0.02321079044, 0.01318017474, 0.01754581538};
static const double tv8_ptilde[4] = {0.4122314457, 0.3005685543, 0.1911010133, 0.2543989867};
static const double tv8_W[3] = {0.02232658374, 0.01308822926, 0.005986630349};
static const double tv8_lamt[4] = {0.002, 0.005113793921, 0.01197443534, 0.002};

/* TV8 tracker: PD 0.9, PG 0.99, lambda 0.002, rho 3; two tracks by z_hat and S. */
static void tv8_tracker(mtt_assoc mode, mtt_real lambda)
{
    mtt_params p;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.lm_ihpda_variant = MTT_LM_IHPDA_S0; /* the [S0] vectors */
    p.association = mode;
    p.pd = MTT_R(0.9);
    p.pg = MTT_R(0.99);
    p.clutter_density = lambda;
    p.snr_rho = MTT_R(3.0);
    tv_init(&trk, &p);
    (void)tv_add_track_s(&trk, MTT_R(0.0), MTT_R(0.0), MTT_R(4.0), MTT_R(1.0), MTT_R(3.0), MTT_R(0.8));
    (void)tv_add_track_s(&trk, MTT_R(5.0), MTT_R(1.0), MTT_R(3.0), MTT_R(-0.5), MTT_R(5.0), MTT_R(0.5));
    (void)tv_add_meas(&trk, MTT_R(-1.5), MTT_R(0.5), MTT_R(50.0), 1);
    (void)tv_add_meas(&trk, MTT_R(2.4), MTT_R(0.9), MTT_R(120.0), 1);
    (void)tv_add_meas(&trk, MTT_R(6.8), MTT_R(2.5), MTT_R(70.0), 1);
    mtt_gate_frame(&trk);
}

static void test_tv8_pairs(void)
{
    int k;
    tv8_tracker(MTT_ASSOC_LM_IHPDA, MTT_R(0.002));
    TEST_ASSERT_EQUAL_UINT(4, TV_N_PAIRS(&trk));
    for (k = 0; k < 4; ++k) {
        TEST_ASSERT_EQUAL_UINT(pt[k], TV_PAIR_TRACK(&trk, k));
        TEST_ASSERT_EQUAL_UINT(pm[k], TV_PAIR_MEAS(&trk, k));
        TV_ASSERT_REAL_MSG(tv8_d2[k], tv_pair_d2(&trk, (uint16_t)k), "TV8 d2");
        TV_ASSERT_REAL_MSG(tv8_p[k], TV_PAIR_P(&trk, k), "TV8 p");
    }
    TV_ASSERT_REAL(95.96699484, TV_GATE_AREA(&trk, 0)); /* TV8 T1 V_G */
    TV_ASSERT_REAL(111.1275048, TV_GATE_AREA(&trk, 1)); /* TV8 T2 V_G */
}

static void test_tv8_lm_density(void)
{
    int k, j;
    tv8_tracker(MTT_ASSOC_LM_IHPDA, MTT_R(0.002));
    mtt_clutter_frame(&trk, 1);
    TV_ASSERT_REAL(0.002, TV_LAMBDA(&trk, 0));
    TV_ASSERT_REAL(0.002, TV_LAMBDA(&trk, 1));
    for (k = 0; k < 4; ++k) {
        /* w = p Pt / (1 - Pt), so Pt = w / (p + w) (TV8 Ptilde) */
        TV_ASSERT_REAL_MSG(tv8_ptilde[k],
                           TV_PAIR_W(&trk, k) / (TV_PAIR_P(&trk, k) + TV_PAIR_W(&trk, k)),
                           "TV8 Ptilde");
        TV_ASSERT_REAL_MSG(tv8_p[k] * tv8_ptilde[k] / (1.0 - tv8_ptilde[k]), TV_PAIR_W(&trk, k),
                           "TV8 w");
        TV_ASSERT_REAL_MSG(tv8_lamt[k], TV_PAIR_LAM(&trk, k), "TV8 lambda_tilde");
    }
    for (j = 0; j < 3; ++j) {
        TV_ASSERT_REAL_MSG(tv8_W[j], TV_WSUM(&trk, j), "TV8 W_j");
    }
}

static void test_tv8_plain_lambda_when_not_lm(void)
{
    int k;
    tv8_tracker(MTT_ASSOC_IPDA, MTT_R(0.002));
    mtt_clutter_frame(&trk, 0);
    for (k = 0; k < 4; ++k) {
        TV_ASSERT_REAL_MSG(0.002, TV_PAIR_LAM(&trk, k), "TV8 lambda"); /* TV8 lambda */
    }
}

static void test_tv8_lm_ipda(void)
{
    /* TV8 LM-IPDA: IPDA with lambda replaced by lambda_tilde. */
    static const double delta[2] = {-17.33504949, -7.906378035};
    static const double beta[4] = {0.7734871932, 0.2205679087, 0.1101140418, 0.8776475376};
    static const double beta0[2] = {0.005944898053, 0.01223842055};
    static const double ex[2] = {0.9865483275, 0.8990549324};
    uint16_t t;
    tv8_tracker(MTT_ASSOC_LM_IPDA, MTT_R(0.002));
    mtt_clutter_frame(&trk, 1);
    for (t = 0; t < 2; ++t) {
        mtt_real p[2], lam[2], b[2], b0, L;
        int j;
        for (j = 0; j < 2; ++j) {
            p[j] = TV_PAIR_P(&trk, TV_PAIR_FIRST(&trk, t) + j);
            lam[j] = TV_PAIR_LAM(&trk, TV_PAIR_FIRST(&trk, t) + j);
        }
        tv_ipda_betas(TV_PAR(&trk).pd, TV_PAR(&trk).pg, p, lam, 2, b, &b0, &L);
        TV_ASSERT_REAL_MSG(delta[t], MTT_R(1.0) - L, "TV8 LM-IPDA delta");
        TV_ASSERT_REAL_MSG(beta[2 * t], b[0], "TV8 LM-IPDA beta");
        TV_ASSERT_REAL_MSG(beta[2 * t + 1], b[1], "TV8 LM-IPDA beta");
        TV_ASSERT_REAL_MSG(beta0[t], b0, "TV8 LM-IPDA beta_0");
        TV_ASSERT_REAL_MSG(ex[t], mtt_existence_update(TV_EX_PRED(&trk, t), L),
                           "TV8 LM-IPDA existence");
    }
    /* The same through the update stage in lm-ipda mode. */
    mtt_associate_frame(&trk);
    mtt_update_frame(&trk);
    TV_ASSERT_REAL(0.9865483275, TV_EXISTENCE(&trk, 0)); /* TV8 LM-IPDA T1 */
    TV_ASSERT_REAL(0.8990549324, TV_EXISTENCE(&trk, 1)); /* TV8 LM-IPDA T2 */
    TEST_ASSERT_EQUAL_INT(0, TV_TRACK_MEAS(&trk, 0)); /* T1: largest beta on z1 */
    TEST_ASSERT_EQUAL_INT(2, TV_TRACK_MEAS(&trk, 1)); /* T2: largest beta on z3 */
}

static void test_tv8_hand_built_state(void)
{
    /* Drive mtt_clutter_frame on a state filled by hand (no gate stage):
     * tf[] S/vg/ex_pred/pair ranges, pairs with the TV8 p values, CSR lists. */
    mtt_params p;
    int k;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.lm_ihpda_variant = MTT_LM_IHPDA_S0; /* the [S0] vectors */
    p.pd = MTT_R(0.9);
    p.pg = MTT_R(0.99);
    p.clutter_density = MTT_R(0.002);
    tv_init(&trk, &p);
    (void)tv_add_track_s(&trk, MTT_R(0.0), MTT_R(0.0), MTT_R(4.0), MTT_R(1.0), MTT_R(3.0), MTT_R(0.8));
    (void)tv_add_track_s(&trk, MTT_R(5.0), MTT_R(1.0), MTT_R(3.0), MTT_R(-0.5), MTT_R(5.0), MTT_R(0.5));
    (void)tv_add_meas(&trk, MTT_R(-1.5), MTT_R(0.5), MTT_R(50.0), 1);
    (void)tv_add_meas(&trk, MTT_R(2.4), MTT_R(0.9), MTT_R(120.0), 1);
    (void)tv_add_meas(&trk, MTT_R(6.8), MTT_R(2.5), MTT_R(70.0), 1);
    for (k = 0; k < 4; ++k) {
        tv_add_pair(&trk, pt[k], pm[k], MTT_R(0.0));
        TV_PAIR_P(&trk, k) = (mtt_real)tv8_p[k]; /* TV8 p */
    }
    tv_index_pairs(&trk);
    mtt_clutter_frame(&trk, 1);
    for (k = 0; k < 4; ++k) {
        TV_ASSERT_REAL_MSG(tv8_lamt[k], TV_PAIR_LAM(&trk, k), "TV8 lambda_tilde");
    }
}

static void test_lm_many_tracks_uses_sum_minus_own(void)
{
    /* Five identical tracks gate one measurement (more than the direct-sum
     * limit): by symmetry every lambda_tilde = lambda + 4 w, with
     * Pt = PD PG P (the only measurement), w = p Pt / (1 - Pt). */
    mtt_params p;
    uint16_t t;
    double pt_, w;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.lm_ihpda_variant = MTT_LM_IHPDA_S0; /* the [S0] vectors */
    p.pd = MTT_R(0.9);
    p.pg = MTT_R(0.99);
    p.clutter_density = MTT_R(0.002);
    tv_init(&trk, &p);
    for (t = 0; t < 5; ++t) {
        (void)tv_add_track_s(&trk, MTT_R(0.0), MTT_R(0.0), MTT_R(4.0), MTT_R(1.0), MTT_R(3.0), MTT_R(0.8));
    }
    (void)tv_add_meas(&trk, MTT_R(-1.5), MTT_R(0.5), MTT_R(50.0), 1); /* TV8 z1 for T1 */
    mtt_gate_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(5, TV_N_PAIRS(&trk));
    mtt_clutter_frame(&trk, 1);
    pt_ = 0.9 * 0.99 * 0.8;
    w = 0.03183372832 * pt_ / (1.0 - pt_); /* TV8 T1 z1 p */
    TV_ASSERT_REAL(5.0 * w, TV_WSUM(&trk, 0));
    for (t = 0; t < 5; ++t) {
        TV_ASSERT_REAL_MSG(0.002 + 4.0 * w, TV_PAIR_LAM(&trk, t), "lambda_tilde");
    }
}

static void test_unknown_lambda_uses_estimate(void)
{
    /* clutter_density = 0: each track's lambda_hat = (m - PD PG P)/V_G (ALGORITHMS.md §5.2),
     * with TV8's V_G and m = 2. */
    tv8_tracker(MTT_ASSOC_IPDA, MTT_R(0.0));
    mtt_clutter_frame(&trk, 0);
    TV_ASSERT_REAL((2.0 - 0.9 * 0.99 * 0.8) / 95.96699484, TV_LAMBDA(&trk, 0));  /* TV8 T1 V_G */
    TV_ASSERT_REAL((2.0 - 0.9 * 0.99 * 0.5) / 111.1275048, TV_LAMBDA(&trk, 1));  /* TV8 T2 V_G */
    TV_ASSERT_REAL((2.0 - 0.9 * 0.99 * 0.8) / 95.96699484, TV_PAIR_LAM(&trk, 1));
    /* TV6 lambda_hat: m = 3, P = 0.6, V_G = 291.4001257 */
    TV_ASSERT_REAL(0.008460531697, mtt_clutter_estimate(3, MTT_R(0.9), MTT_R(0.99), MTT_R(0.6),
                                                        MTT_R(291.4001257)));
}

#if MTT_WITH_BASELINES
/* TV8c: three tracks, four measurements, lambda 1e-6 (ALGORITHMS.md §8.3). */
static void tv8c_tracker(void)
{
    mtt_params p;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.association = MTT_ASSOC_LM_IPDA_ALL;
    p.pd = MTT_R(0.9);
    p.pg = MTT_R(0.99);
    p.clutter_density = MTT_R(1e-6);
    tv_init(&trk, &p);
    (void)tv_add_track_s(&trk, MTT_R(0.0), MTT_R(0.0), MTT_R(1.0), MTT_R(0.2), MTT_R(0.8), MTT_R(0.9));
    (void)tv_add_track_s(&trk, MTT_R(4.0), MTT_R(0.5), MTT_R(1.2), MTT_R(-0.1), MTT_R(1.0), MTT_R(0.6));
    (void)tv_add_track_s(&trk, MTT_R(20.0), MTT_R(20.0), MTT_R(1.0), MTT_R(0.0), MTT_R(1.0), MTT_R(0.5));
    (void)tv_add_meas(&trk, MTT_R(0.3), MTT_R(-0.2), MTT_R(0.0), 0);
    (void)tv_add_meas(&trk, MTT_R(2.0), MTT_R(0.3), MTT_R(0.0), 0);
    (void)tv_add_meas(&trk, MTT_R(4.8), MTT_R(1.0), MTT_R(0.0), 0);
    (void)tv_add_meas(&trk, MTT_R(20.5), MTT_R(19.8), MTT_R(0.0), 0);
    mtt_gate_frame(&trk);
}

/* TV8c pairs (T1,z1) (T1,z2) (T2,z2) (T2,z3) (T3,z4): lambda~ / lambda. */
static const uint16_t c_pt[5] = {0, 0, 1, 1, 2}, c_pm[5] = {0, 1, 1, 2, 3};
static const double tv8c_cluster[5] = {1.0, 3346.531941, 2841.501134, 1.0, 1.0};
static const double tv8c_all[5] = {1.378536026, 3346.531941, 2841.501134, 1.000013871, 1.0};

static void test_tv8c_all_tracks_adds_the_tracks_outside_the_gate(void)
{
    int k;
    tv8c_tracker();
    TEST_ASSERT_EQUAL_UINT(5, TV_N_PAIRS(&trk));
    for (k = 0; k < 5; ++k) {
        TEST_ASSERT_EQUAL_UINT(c_pt[k], TV_PAIR_TRACK(&trk, k));
        TEST_ASSERT_EQUAL_UINT(c_pm[k], TV_PAIR_MEAS(&trk, k));
    }
    mtt_clutter_frame(&trk, mtt_modes[MTT_ASSOC_LM_IPDA_ALL].lm); /* the mode's own row */
    for (k = 0; k < 5; ++k) {
        TV_ASSERT_REAL_MSG(tv8c_all[k], TV_PAIR_LAM(&trk, k) / MTT_R(1e-6), "TV8c lm-ipda-all lambda~/lambda");
    }
    /* lm-ipda on the same frame: the tracks of the gate only (TV8c) */
    mtt_clutter_frame(&trk, mtt_modes[MTT_ASSOC_LM_IPDA].lm);
    for (k = 0; k < 5; ++k) {
        TV_ASSERT_REAL_MSG(tv8c_cluster[k], TV_PAIR_LAM(&trk, k) / MTT_R(1e-6), "TV8c lm-ipda lambda~/lambda");
    }
}

static void test_tv8c_lm_ipda_all_delta(void)
{
    /* TV8c lm-ipda-all: delta of T1 and T2 from their pairs' p and lambda~. */
    static const double delta[2] = {-108993.9897, -85544.83918};
    uint16_t t;
    tv8c_tracker();
    mtt_clutter_frame(&trk, 2);
    for (t = 0; t < 2; ++t) {
        mtt_real p[2], lam[2], b[2], b0, L;
        int j;
        for (j = 0; j < 2; ++j) {
            p[j] = TV_PAIR_P(&trk, TV_PAIR_FIRST(&trk, t) + j);
            lam[j] = TV_PAIR_LAM(&trk, TV_PAIR_FIRST(&trk, t) + j);
        }
        tv_ipda_betas(TV_PAR(&trk).pd, TV_PAR(&trk).pg, p, lam, 2, b, &b0, &L);
        TV_ASSERT_REAL_MSG(delta[t], MTT_R(1.0) - L, "TV8c lm-ipda-all delta");
    }
}
#endif

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_tv8_pairs);
    RUN_TEST(test_tv8_lm_density);
    RUN_TEST(test_tv8_plain_lambda_when_not_lm);
    RUN_TEST(test_tv8_lm_ipda);
    RUN_TEST(test_tv8_hand_built_state);
    RUN_TEST(test_lm_many_tracks_uses_sum_minus_own);
    RUN_TEST(test_unknown_lambda_uses_estimate);
#if MTT_WITH_BASELINES
    RUN_TEST(test_tv8c_all_tracks_adds_the_tracks_outside_the_gate);
    RUN_TEST(test_tv8c_lm_ipda_all_delta);
#endif
    return UNITY_END();
}
