/* SPDX-License-Identifier: BSD-3-Clause */
/* test_assign2d.c - optimal 2-D assignment (ALGORITHMS.md §10.2) and the ihpda-2d
 * mode's cluster stage: TV9 (static matrix), TV8 (optimal result with the
 * final recomputation of ALGORITHMS.md §10.3), and the solver against brute force. */
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "tv_fixture.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#if MTT_WITH_BASELINES

static mtt_assign_scratch ws;
static mtt_tracker trk;

/* A dense test matrix: w[r][c] (0 = not allowed). */
typedef struct {
    uint16_t m;
    mtt_real w[8][8];
} dense;

static void dense_row(const void *ctx, uint16_t r, mtt_real *w)
{
    const dense *d = (const dense *)ctx;
    uint16_t j;
    for (j = 0; j < d->m; ++j) {
        w[j] = d->w[r][j];
    }
}

/* TV9: B = [0.7, 0.6, 0, 0.1; 0.65, 0.05, 0, 0.2; 0, 0.55, 0.5, 0]. */
static void test_tv9_optimal(void)
{
    static const double B[3][4] = {{0.7, 0.6, 0, 0.1}, {0.65, 0.05, 0, 0.2}, {0, 0.55, 0.5, 0}};
    dense d;
    uint16_t r, j;
    double total = 0.0;
    memset(&d, 0, sizeof d);
    d.m = 4;
    for (r = 0; r < 3; ++r) {
        for (j = 0; j < 4; ++j) {
            d.w[r][j] = (B[r][j] > 0.0) ? (mtt_real)B[r][j] + MTT_R(4.0) : MTT_R(0.0); /* n_c + 1 = 4 */
        }
    }
    mtt_assign2d_solve(&ws, 3, 4, dense_row, &d);
    TEST_ASSERT_EQUAL_INT(1, TV_COL_ROW(&ws, 0)); /* TV9: T1 -> z2 */
    TEST_ASSERT_EQUAL_INT(0, TV_COL_ROW(&ws, 1)); /* TV9: T2 -> z1 */
    TEST_ASSERT_EQUAL_INT(2, TV_COL_ROW(&ws, 2)); /* TV9: T3 -> z3 */
    for (r = 0; r < 3; ++r) {
        total += B[r][TV_COL_ROW(&ws, r)];
    }
    TV_ASSERT_REAL(1.75, total); /* TV9 optimal total */
}

/* Fixed-seed generator (LCG, Numerical Recipes constants). */
static uint32_t rng_state;
static uint32_t rng_u32(void)
{
    rng_state = rng_state * 1664525u + 1013904223u;
    return rng_state;
}
static double rng_unit(void)
{
    return (double)(rng_u32() >> 8) / 16777216.0;
}

/* Best (count, sum) over all partial matchings, by exhaustive search. */
static void brute(double b[8][8], int n, int m, int r, uint32_t used, int cnt, double sum,
                  int *best_cnt, double *best_sum)
{
    int j;
    if (r == n) {
        if (cnt > *best_cnt || (cnt == *best_cnt && sum > *best_sum)) {
            *best_cnt = cnt;
            *best_sum = sum;
        }
        return;
    }
    brute(b, n, m, r + 1, used, cnt, sum, best_cnt, best_sum);
    for (j = 0; j < m; ++j) {
        if (b[r][j] > 0.0 && !(used & (1u << j))) {
            brute(b, n, m, r + 1, used | (1u << j), cnt + 1, sum + b[r][j], best_cnt, best_sum);
        }
    }
}

static void test_optimal_vs_brute_force(void)
{
    int trial;
    rng_state = 12345u;
    for (trial = 0; trial < 1500; ++trial) {
        double b[8][8];
        dense d;
        const int n = 1 + (int)(rng_u32() % 6u), m = 1 + (int)(rng_u32() % 7u);
        const double density = 0.2 + 0.8 * rng_unit();
        int r, j, best_cnt = -1, cnt = 0;
        double best_sum = -1.0, sum = 0.0;
        uint32_t used = 0;
        memset(&d, 0, sizeof d);
        d.m = (uint16_t)m;
        for (r = 0; r < n; ++r) {
            for (j = 0; j < m; ++j) {
                b[r][j] = (rng_unit() < density) ? 0.001 + 0.999 * rng_unit() : 0.0;
                d.w[r][j] = (b[r][j] > 0.0) ? (mtt_real)b[r][j] + (mtt_real)(n + 1) : MTT_R(0.0);
            }
        }
        brute(b, n, m, 0, 0u, 0, 0.0, &best_cnt, &best_sum);
        mtt_assign2d_solve(&ws, (uint16_t)n, (uint16_t)m, dense_row, &d);
        for (r = 0; r < n; ++r) {
            const int c = TV_COL_ROW(&ws, r);
            if (c < 0) {
                continue;
            }
            TEST_ASSERT_TRUE(c < m);
            TEST_ASSERT_TRUE(b[r][c] > 0.0);          /* only gated pairs */
            TEST_ASSERT_FALSE(used & (1u << c));      /* one-to-one */
            used |= 1u << c;
            ++cnt;
            sum += b[r][c];
        }
        TEST_ASSERT_EQUAL_INT(best_cnt, cnt);         /* cardinality first */
        TEST_ASSERT_TRUE_MESSAGE(tv_close(best_sum, sum) || fabs(best_sum - sum) < 1e-5,
                                 "sum of beta is not the optimum");
    }
}

/* ---- TV8: LM-IHPDA initial matrix, optimal assignment, final recomputation ---- */

static uint16_t add_track_s(double zx, double zy, double s11, double s12, double s22, double ex)
{
    uint16_t i = TV_N_TRACKS(&trk)++;
    memset(&TV_FRAME(&trk, i), 0, sizeof TV_FRAME(&trk, i));
    memset(TV_TRACK(&trk, i), 0, sizeof *TV_TRACK(&trk, i));
    TV_XP(&trk, i)[0] = (mtt_real)zx;
    TV_XP(&trk, i)[1] = (mtt_real)zy;
    TV_PP(&trk, i)[0][0] = (mtt_real)s11 - TV_R(&trk)[0];
    TV_PP(&trk, i)[0][1] = (mtt_real)s12;
    TV_PP(&trk, i)[1][0] = (mtt_real)s12;
    TV_PP(&trk, i)[1][1] = (mtt_real)s22 - TV_R(&trk)[2];
    TV_PP(&trk, i)[2][2] = MTT_R(1.0);
    TV_PP(&trk, i)[3][3] = MTT_R(1.0);
    TV_EX_PRED(&trk, i) = (mtt_real)ex;
    TV_ASSIGNED(&trk, i) = -1;
    TV_BEST(&trk, i) = -1;
    TEST_ASSERT_EQUAL_INT(0, mtt_kalman_innov(TV_PP(&trk, i), TV_R(&trk), TV_S(&trk, i),
                                              TV_SI(&trk, i), &TV_DET_S(&trk, i),
                                              TV_GAIN(&trk, i)));
    TV_VALID(&trk, i) = 1;
    TV_TRACK_MEAS(&trk, i) = -1;
    TV_TRACK_ID(&trk, i) = TV_NEXT_ID(&trk)++;
    return i;
}

static void add_meas(double x, double y, double amp)
{
    const uint16_t j = TV_N_MEAS(&trk);
    memset(&TV_MEAS(&trk, j), 0, sizeof TV_MEAS(&trk, j));
    TV_MEAS_X(&trk, j) = (mtt_real)x;
    TV_MEAS_Y(&trk, j) = (mtt_real)y;
    TV_MEAS_AMP(&trk, j) = (mtt_real)amp;
    TV_HAS_AMP(&trk, j) = 1;
    TV_MEAS_SRC(&trk, j) = TV_N_MEAS(&trk)++;
}

static int pair_of(uint16_t t, uint16_t j)
{
    uint16_t k;
    for (k = 0; k < TV_N_PAIRS(&trk); ++k) {
        if (TV_PAIR_TRACK(&trk, k) == t && TV_PAIR_MEAS(&trk, k) == j) {
            return (int)k;
        }
    }
    return -1;
}

static void test_tv8_optimal_and_final_recomputation(void)
{
    mtt_params p;
    double sum;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.association = MTT_ASSOC_IHPDA_2D;
    p.pd = MTT_R(0.9);
    p.pg = MTT_R(0.99);
    p.clutter_density = MTT_R(0.002);
    p.snr_rho = MTT_R(3.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    add_track_s(0, 0, 4, 1, 3, 0.8);     /* TV8 T1 */
    add_track_s(5, 1, 3, -0.5, 5, 0.5);  /* TV8 T2 */
    add_meas(-1.5, 0.5, 50);             /* TV8 z1 */
    add_meas(2.4, 0.9, 120);             /* TV8 z2 */
    add_meas(6.8, 2.5, 70);              /* TV8 z3 */
    mtt_gate_frame(&trk);
    mtt_clutter_frame(&trk, 1); /* TV8 uses the LM matrix (ALGORITHMS.md §10.2: lambda~ in LM mode) */
    mtt_cluster_frame(&trk);
    mtt_assign2d_frame(&trk);
    TEST_ASSERT_EQUAL_INT(pair_of(0, 0), TV_ASSIGNED(&trk, 0)); /* TV8: T1 -> z1 */
    TEST_ASSERT_EQUAL_INT(pair_of(1, 1), TV_ASSIGNED(&trk, 1)); /* TV8: T2 -> z2 */
    sum = (double)TV_PAIR_BETA(&trk, TV_ASSIGNED(&trk, 0)) + (double)TV_PAIR_BETA(&trk, TV_ASSIGNED(&trk, 1));
    TV_ASSERT_REAL(1.235805911, sum); /* TV8: sum of beta of the optimal assignment */
    TV_ASSERT_REAL(0.4294519828, TV_PAIR_BETA(&trk, pair_of(0, 0))); /* TV8 initial matrix */
    TV_ASSERT_REAL(0.8063539279, TV_PAIR_BETA(&trk, pair_of(1, 1)));
    mtt_ihpda_final_frame(&trk);
    mtt_update_frame(&trk);
    TV_ASSERT_REAL(0.9923727825, TV_PAIR_BETA(&trk, pair_of(0, 0))); /* TV8 final: T1 beta */
    TV_ASSERT_REAL(0.9828071472, TV_EXISTENCE(&trk, 0));       /* TV8 final: T1 P */
    TV_ASSERT_REAL(0.8063539279, TV_PAIR_BETA(&trk, pair_of(1, 1))); /* TV8 final: T2 beta */
    TV_ASSERT_REAL(0.6605542449, TV_EXISTENCE(&trk, 1));       /* TV8 final: T2 P */
    TEST_ASSERT_EQUAL_INT(0, (int)TV_TRACK_MEAS(&trk, 0));
    TEST_ASSERT_EQUAL_INT(1, (int)TV_TRACK_MEAS(&trk, 1));
    TEST_ASSERT_EQUAL_UINT32(0u, TV_STATS(&trk).last.assign_fallbacks);
}

#if MTT_MAX_TRACKS > MTT_MAX_ASSIGN_TRACKS
/* A cluster over MTT_MAX_ASSIGN_TRACKS falls back to MMR, counted. */
static void test_large_cluster_falls_back_to_mmr(void)
{
    mtt_params p;
    uint16_t i;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.association = MTT_ASSOC_IHPDA_2D;
    p.clutter_density = MTT_R(0.001);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    for (i = 0; i <= MTT_MAX_ASSIGN_TRACKS; ++i) {
        add_track_s(0.1 * i, 0, 4, 0, 4, 0.9);
        add_meas(0.1 * i + 0.05, 0.1, 1);
    }
    mtt_gate_frame(&trk);
    mtt_clutter_frame(&trk, 0);
    mtt_cluster_frame(&trk);
    TEST_ASSERT_EQUAL_UINT16(1u, TV_N_CLUSTERS(&trk));
    mtt_assign2d_frame(&trk);
    TEST_ASSERT_EQUAL_UINT32(1u, TV_STATS(&trk).last.assign_fallbacks);
    for (i = 0; i <= MTT_MAX_ASSIGN_TRACKS; ++i) {
        TEST_ASSERT_TRUE(TV_ASSIGNED(&trk, i) >= 0); /* one measurement each */
    }
}
#endif

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_tv9_optimal);
    RUN_TEST(test_optimal_vs_brute_force);
    RUN_TEST(test_tv8_optimal_and_final_recomputation);
#if MTT_MAX_TRACKS > MTT_MAX_ASSIGN_TRACKS
    RUN_TEST(test_large_cluster_falls_back_to_mmr);
#endif
    return UNITY_END();
}

#else /* MTT_WITH_BASELINES == 0 */

/* Built without the baselines: they must be refused, not half-run. */
static void test_baselines_refused(void)
{
    tv_assert_mode_refused(MTT_ASSOC_IHPDA_2D);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_baselines_refused);
    return UNITY_END();
}
#endif
