/* SPDX-License-Identifier: BSD-3-Clause */
/* test_mmr.c - MMR assignment (ALGORITHMS.md §10.1): the static greedy of TV9 and
 * LM-IHPDA with recomputation and the final recomputation of TV8 (10.3). */
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "tv_fixture.h"
#include "unity.h"

static mtt_tracker trk;

void setUp(void) {}
void tearDown(void) {}

/* A state with n tracks and m measurements and the given static beta
 * matrix (0 = not gated), one cluster built by mtt_cluster_frame. */
static void static_matrix(uint16_t n, uint16_t m, const double *B)
{
    mtt_params p;
    uint16_t t, j;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.lm_ihpda_variant = MTT_LM_IHPDA_S0; /* the [S0] vectors */
    tv_init(&trk, &p);
    for (t = 0; t < n; ++t) {
        (void)tv_add_track_s(&trk, MTT_R(0.0), MTT_R(0.0), MTT_R(2.0), MTT_R(0.0), MTT_R(2.0), MTT_R(0.5));
    }
    for (j = 0; j < m; ++j) {
        (void)tv_add_meas(&trk, (mtt_real)j, MTT_R(0.0), MTT_R(1.0), 1);
    }
    for (t = 0; t < n; ++t) {
        for (j = 0; j < m; ++j) {
            if (B[t * m + j] > 0.0) {
                tv_add_pair(&trk, t, j, (mtt_real)B[t * m + j]);
            }
        }
    }
    tv_index_pairs(&trk);
    mtt_cluster_frame(&trk);
}

static int assigned_meas(uint16_t t)
{
    int16_t k = TV_ASSIGNED(&trk, t);
    return (k < 0) ? -1 : (int)TV_PAIR_MEAS(&trk, k);
}

static void test_tv9_static_greedy(void)
{
    /* TV9 B = [0.7, 0.6, 0, 0.1; 0.65, 0.05, 0, 0.2; 0, 0.55, 0.5, 0] */
    static const double B[12] = {0.7, 0.6, 0, 0.1, 0.65, 0.05, 0, 0.2, 0, 0.55, 0.5, 0};
    double total = 0.0;
    uint16_t t;
    static_matrix(3, 4, B);
    TEST_ASSERT_EQUAL_UINT(1, TV_N_CLUSTERS(&trk));
    mtt_mmr_cluster(&trk, 0, 0);
    TEST_ASSERT_EQUAL_INT(0, assigned_meas(0)); /* TV9 step 1: T1 -> z1 (0.7) */
    TEST_ASSERT_EQUAL_INT(1, assigned_meas(2)); /* TV9 step 2: T3 -> z2 (0.55) */
    TEST_ASSERT_EQUAL_INT(3, assigned_meas(1)); /* TV9 step 3: T2 -> z4 (0.2) */
    for (t = 0; t < 3; ++t) {
        total += (double)TV_PAIR_BETA(&trk, TV_ASSIGNED(&trk, t));
    }
    TV_ASSERT_REAL(1.45, total); /* TV9 total */
    TV_ASSERT_REAL(0.7, TV_PAIR_BETA(&trk, TV_ASSIGNED(&trk, 0)));
    TV_ASSERT_REAL(0.55, TV_PAIR_BETA(&trk, TV_ASSIGNED(&trk, 2)));
    TV_ASSERT_REAL(0.2, TV_PAIR_BETA(&trk, TV_ASSIGNED(&trk, 1)));
    TEST_ASSERT_EQUAL_UINT(1, TV_USED(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(1, TV_USED(&trk, 1));
    TEST_ASSERT_EQUAL_UINT(0, TV_USED(&trk, 2)); /* z3 stays free */
    TEST_ASSERT_EQUAL_UINT(1, TV_USED(&trk, 3));
}

static void test_tv9_tie_break(void)
{
    /* TV9 tie-break: B = [0.5, 0.5; 0.5, 0.2] -> T1 -> z1, T2 -> z2 */
    static const double B[4] = {0.5, 0.5, 0.5, 0.2};
    static_matrix(2, 2, B);
    mtt_mmr_cluster(&trk, 0, 0);
    TEST_ASSERT_EQUAL_INT(0, assigned_meas(0));
    TEST_ASSERT_EQUAL_INT(1, assigned_meas(1));
}

static void test_static_track_left_without_measurement(void)
{
    /* Two tracks that gate only z1: the larger beta takes it, the other gets
     * nothing (m = 0 update).  TV9 row values 0.65 / 0.7 reused. */
    static const double B[2] = {0.65, 0.7};
    static_matrix(2, 1, B);
    mtt_mmr_cluster(&trk, 0, 0);
    TEST_ASSERT_EQUAL_INT(-1, assigned_meas(0));
    TEST_ASSERT_EQUAL_INT(0, assigned_meas(1));
}

/* ---- TV8 with recomputation ---- */

static void tv8_tracker(void)
{
    mtt_params p;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.lm_ihpda_variant = MTT_LM_IHPDA_S0; /* the [S0] vectors */
    p.association = MTT_ASSOC_LM_IHPDA;
    p.pd = MTT_R(0.9);
    p.pg = MTT_R(0.99);
    p.clutter_density = MTT_R(0.002);
    p.snr_rho = MTT_R(3.0);
    tv_init(&trk, &p);
    (void)tv_add_track_s(&trk, MTT_R(0.0), MTT_R(0.0), MTT_R(4.0), MTT_R(1.0), MTT_R(3.0), MTT_R(0.8));
    (void)tv_add_track_s(&trk, MTT_R(5.0), MTT_R(1.0), MTT_R(3.0), MTT_R(-0.5), MTT_R(5.0), MTT_R(0.5));
    (void)tv_add_meas(&trk, MTT_R(-1.5), MTT_R(0.5), MTT_R(50.0), 1);
    (void)tv_add_meas(&trk, MTT_R(2.4), MTT_R(0.9), MTT_R(120.0), 1);
    (void)tv_add_meas(&trk, MTT_R(6.8), MTT_R(2.5), MTT_R(70.0), 1);
    mtt_gate_frame(&trk);
    mtt_clutter_frame(&trk, 1);
    mtt_cluster_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(4, TV_N_PAIRS(&trk));
    TEST_ASSERT_EQUAL_UINT(1, TV_N_CLUSTERS(&trk));
}

static void test_tv8_initial_beta_matrix(void)
{
    /* TV8 LM-IHPDA initial beta matrix (pairs (T1,z1) (T1,z2) (T2,z2) (T2,z3)) */
    static const double beta[4] = {0.4294519828, 0.8856765228, 0.8063539279, 0.3240094191};
    static const double beta0[4] = {0.5705480172, 0.1143234772, 0.1936460721, 0.6759905809};
    static const double delta[4] = {-12.20932401, -6.305824947, -0.9459788052, -8.649917924};
    int16_t best;
    int k;
    tv8_tracker();
    TEST_ASSERT_EQUAL_UINT(2, mtt_ihpda_row(&trk, 0, 0, -1, 0, &best));
    TEST_ASSERT_EQUAL_INT(1, best); /* T1's row max on z2 */
    TEST_ASSERT_EQUAL_UINT(2, mtt_ihpda_row(&trk, 1, 0, -1, 0, &best));
    TEST_ASSERT_EQUAL_INT(2, best); /* T2's row max on z2 */
    for (k = 0; k < 4; ++k) {
        TV_ASSERT_REAL_MSG(beta[k], TV_PAIR_BETA(&trk, k), "TV8 initial beta");
        TV_ASSERT_REAL_MSG(beta0[k], MTT_R(1.0) - TV_PAIR_BETA(&trk, k), "TV8 initial beta_0");
        TV_ASSERT_REAL_MSG(delta[k], MTT_R(1.0) - TV_PAIR_L(&trk, k), "TV8 initial delta");
    }
    /* TV8: m = 2 for both rows, Prank = 0.8 (rank 1) and 0.2 (rank 2) */
    TV_ASSERT_REAL(0.8, TV_PRANK(&trk, MTT_PRANK_ROW(2)));
    TV_ASSERT_REAL(0.2, TV_PRANK(&trk, MTT_PRANK_ROW(2) + 1u));
}

static void test_tv8_mmr_with_recomputation(void)
{
    tv8_tracker();
    mtt_mmr_cluster(&trk, 0, 1);
    /* iteration 1: global max 0.8856765228 at (T1, z2) with m = 2 */
    TEST_ASSERT_EQUAL_INT(1, TV_ASSIGNED(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(1, TV_PAIR_MEAS(&trk, TV_ASSIGNED(&trk, 0)));
    TV_ASSERT_REAL(0.8856765228, TV_PAIR_BETA(&trk, 1)); /* TV8 iteration 1 */
    /* iteration 2: T2's row without z2 (m = 1): 0.9862472034 at (T2, z3) */
    TEST_ASSERT_EQUAL_INT(3, TV_ASSIGNED(&trk, 1));
    TEST_ASSERT_EQUAL_UINT(2, TV_PAIR_MEAS(&trk, TV_ASSIGNED(&trk, 1)));
    TV_ASSERT_REAL(0.9862472034, TV_PAIR_BETA(&trk, 3)); /* TV8 iteration 2 */
    TEST_ASSERT_TRUE(TV_PAIR_BETA(&trk, 2) == MTT_R(0.0)); /* z2 taken by T1 */
    TEST_ASSERT_EQUAL_UINT(0, TV_USED(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(1, TV_USED(&trk, 1));
    TEST_ASSERT_EQUAL_UINT(1, TV_USED(&trk, 2));
}

static void test_tv8_final_recomputation(void)
{
    tv8_tracker();
    mtt_mmr_cluster(&trk, 0, 1);
    mtt_ihpda_final_frame(&trk);
    mtt_update_frame(&trk);
    /* TV8 final: T1 assigned z2, m = 2, beta 0.8856765228, delta -6.305824947 */
    TV_ASSERT_REAL(0.8856765228, TV_PAIR_BETA(&trk, 1));
    TV_ASSERT_REAL(0.1143234772, MTT_R(1.0) - TV_PAIR_BETA(&trk, 1));
    TV_ASSERT_REAL(-6.305824947, MTT_R(1.0) - TV_PAIR_L(&trk, 1));
    TV_ASSERT_REAL(0.9669129444, TV_EXISTENCE(&trk, 0));
    TEST_ASSERT_EQUAL_INT(1, TV_TRACK_MEAS(&trk, 0));
    /* T2 assigned z3, m = 1, beta 0.9862472034, delta -6.925660752 */
    TV_ASSERT_REAL(0.9862472034, TV_PAIR_BETA(&trk, 3));
    TV_ASSERT_REAL(0.01375279657, MTT_R(1.0) - TV_PAIR_BETA(&trk, 3));
    TV_ASSERT_REAL(-6.925660752, MTT_R(1.0) - TV_PAIR_L(&trk, 3));
    TV_ASSERT_REAL(0.8879634766, TV_EXISTENCE(&trk, 1));
    TEST_ASSERT_EQUAL_INT(2, TV_TRACK_MEAS(&trk, 1));
}

static void test_tv8_final_recomputation_by_row(void)
{
    /* The ALGORITHMS.md §10.3 recomputation called directly: T2's set is G minus z2
     * (assigned to T1), keeping its own z3; T1 keeps z1 (unassigned). */
    int16_t best;
    tv8_tracker();
    mtt_mmr_cluster(&trk, 0, 1);
    TEST_ASSERT_EQUAL_UINT(1, mtt_ihpda_row(&trk, 1, 1, 3, 0, &best));
    TV_ASSERT_REAL(0.9862472034, TV_PAIR_BETA(&trk, 3));  /* TV8 final T2 */
    TV_ASSERT_REAL(-6.925660752, MTT_R(1.0) - TV_PAIR_L(&trk, 3));
    TEST_ASSERT_EQUAL_UINT(2, mtt_ihpda_row(&trk, 0, 1, 1, 0, &best));
    TV_ASSERT_REAL(0.8856765228, TV_PAIR_BETA(&trk, 1));  /* TV8 final T1 */
    TV_ASSERT_REAL(-6.305824947, MTT_R(1.0) - TV_PAIR_L(&trk, 1));
}

static void test_tv8_optimal_result_recomputation(void)
{
    /* TV8 final recomputation for the optimal 2-D result (T1 -> z1, T2 -> z2),
     * through the update stage with those assignments given by hand. */
    tv8_tracker();
    TV_ASSIGNED(&trk, 0) = 0; /* (T1, z1) */
    TV_ASSIGNED(&trk, 1) = 2; /* (T2, z2) */
    TV_USED(&trk, 0) = 1;
    TV_USED(&trk, 1) = 1;
    mtt_ihpda_final_frame(&trk);
    mtt_update_frame(&trk);
    TV_ASSERT_REAL(0.9923727825, TV_PAIR_BETA(&trk, 0));              /* TV8 optimal T1 beta */
    TV_ASSERT_REAL(-13.29092596, MTT_R(1.0) - TV_PAIR_L(&trk, 0));    /* T1 delta */
    TV_ASSERT_REAL(0.9828071472, TV_EXISTENCE(&trk, 0));        /* T1 P(exist|Z^k) */
    TV_ASSERT_REAL(0.8063539279, TV_PAIR_BETA(&trk, 2));              /* TV8 optimal T2 beta */
    TV_ASSERT_REAL(-0.9459788052, MTT_R(1.0) - TV_PAIR_L(&trk, 2));   /* T2 delta */
    TV_ASSERT_REAL(0.6605542449, TV_EXISTENCE(&trk, 1));        /* T2 P(exist|Z^k) */
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_tv9_static_greedy);
    RUN_TEST(test_tv9_tie_break);
    RUN_TEST(test_static_track_left_without_measurement);
    RUN_TEST(test_tv8_initial_beta_matrix);
    RUN_TEST(test_tv8_mmr_with_recomputation);
    RUN_TEST(test_tv8_final_recomputation);
    RUN_TEST(test_tv8_final_recomputation_by_row);
    RUN_TEST(test_tv8_optimal_result_recomputation);
    return UNITY_END();
}
