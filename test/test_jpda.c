/* SPDX-License-Identifier: BSD-3-Clause */
/* test_jpda.c - the JPDA family on TV13 (ALGORITHMS.md §13): Cheap JPDA raw and
 * normalised, Suboptimal JPDA (N, D, both B choices), exact JPDA (8 events
 * and their weights), NNJPDA, the 2x2 JPDA* case, JIPDA, the N x N claim
 * checks, the event counts, and the counted fallbacks; TV13b: the gate
 * shrink of adaptive JPDA (§13.7) in jpda-vg, adaptive-jpda-star,
 * adaptive-nnjpda and adaptive-jpda, one tracker step against plain jpda. */
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "tv_fixture.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#if MTT_WITH_BASELINES

static mtt_tracker trk;

#define PD_TV 0.9
#define PG_TV 0.99

/* n tracks x m measurements; a[t*m + j] > 0 is a gated pair with
 * likelihood A (JPDA modes) or likelihood ratio p/lambda (jipda).  B > 0 is
 * jpda_bias; B = 0 forces every B_t to 0 after the weights. */
static void problem(mtt_assoc mode, int n, int m, const double *a, double B, const double *pbar)
{
    mtt_params p;
    int t, j;
    uint16_t k;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.association = mode;
    p.pd = (mtt_real)PD_TV;
    p.pg = (mtt_real)PG_TV;
    p.jpda_bias = (B > 0.0) ? (mtt_real)B : MTT_R(1.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    TV_N_TRACKS(&trk) = (uint16_t)n;
    TV_N_MEAS(&trk) = (uint16_t)m;
    for (j = 0; j < m; ++j) {
        TV_MEAS_X(&trk, j) = (mtt_real)j;
        TV_MEAS_SRC(&trk, j) = (uint32_t)j;
    }
    TV_N_PAIRS(&trk) = 0;
    for (t = 0; t < n; ++t) {
        memset(&TV_FRAME(&trk, t), 0, sizeof TV_FRAME(&trk, t));
        TV_VALID(&trk, t) = 1;
        TV_ASSIGNED(&trk, t) = -1;
        TV_BEST(&trk, t) = -1;
        TV_EX_PRED(&trk, t) = (pbar != NULL) ? (mtt_real)pbar[t] : MTT_R(1.0);
        TV_LAMBDA(&trk, t) = MTT_R(1.0);
        TV_PAIR_FIRST(&trk, t) = TV_N_PAIRS(&trk);
        for (j = 0; j < m; ++j) {
            if (a[t * m + j] > 0.0) {
                const uint16_t kp = TV_N_PAIRS(&trk)++;
                memset(&TV_PAIR(&trk, kp), 0, sizeof TV_PAIR(&trk, kp));
                TV_PAIR_TRACK(&trk, kp) = (uint16_t)t;
                TV_PAIR_MEAS(&trk, kp) = (uint16_t)j;
                TV_PAIR_LAM(&trk, kp) = MTT_R(1.0);
                TV_PAIR_P(&trk, kp) = (mode == MTT_ASSOC_JIPDA) ? (mtt_real)a[t * m + j]
                                                  : (mtt_real)(a[t * m + j] / PG_TV); /* A = PG p */
                TV_PAIR_COUNT(&trk, t)++;
            }
        }
    }
    /* pairs of each measurement (CSR) */
    k = 0;
    for (j = 0; j < m; ++j) {
        uint16_t q;
        TV_MP_FIRST(&trk, j) = k;
        for (q = 0; q < TV_N_PAIRS(&trk); ++q) {
            if (TV_PAIR_MEAS(&trk, q) == j) {
                TV_MP_LIST(&trk, k++) = q;
            }
        }
    }
    TV_MP_FIRST(&trk, m) = k;
    mtt_cluster_frame(&trk);
    mtt_jpda_weights(&trk);
    if (!(B > 0.0) && mode != MTT_ASSOC_JIPDA) {
        for (t = 0; t < n; ++t) {
            TV_JP_TB(&trk, t) = MTT_R(0.0);
        }
    }
}

static double beta(int t, int j)
{
    uint16_t k;
    for (k = 0; k < TV_N_PAIRS(&trk); ++k) {
        if (TV_PAIR_TRACK(&trk, k) == t && TV_PAIR_MEAS(&trk, k) == j) {
            return (double)TV_PAIR_BETA(&trk, k);
        }
    }
    return 0.0; /* not gated */
}

/* Row t against expected (beta_t0, beta_t1..tm). */
static void assert_row(int t, int m, double b0, const double *b, const char *what)
{
    char w[96];
    int j;
    snprintf(w, sizeof w, "%s: T%d beta_t0", what, t + 1);
    tv_assert_real(b0, (double)TV_BETA0(&trk, t), w, __LINE__);
    for (j = 0; j < m; ++j) {
        snprintf(w, sizeof w, "%s: T%d beta_t%d", what, t + 1, j + 1);
        tv_assert_real(b[j], beta(t, j), w, __LINE__);
    }
}

/* TV13 inputs: A = [0.5, 0.3, 0; 0, 0.4, 0.2], B = 0.1. */
static const double A13[6] = {0.5, 0.3, 0, 0, 0.4, 0.2};

static void test_tv13_cheap_raw(void)
{
    static const double r1[3] = {0.5555555556, 0.2307692308, 0}, r2[3] = {0, 0.4, 0.2857142857};
    problem(MTT_ASSOC_CHEAP_JPDA, 2, 3, A13, 0.1, NULL);
    TEST_ASSERT_EQUAL_UINT16(1u, TV_N_CLUSTERS(&trk));
    TV_ASSERT_REAL(0.8, TV_JP_PA(&trk, 0) + TV_JP_PA(&trk, 1)); /* TV13 T_1 */
    TV_ASSERT_REAL(0.6, TV_JP_PA(&trk, 2) + TV_JP_PA(&trk, 3)); /* TV13 T_2 */
    TV_ASSERT_REAL(0.7, TV_JP_PA(&trk, 1) + TV_JP_PA(&trk, 2)); /* TV13 M_2 */
    mtt_cheap_jpda(&trk, 0, 0);
    assert_row(0, 3, 0.1111111111, r1, "TV13 Cheap raw");
    assert_row(1, 3, 0.1428571429, r2, "TV13 Cheap raw");
    TV_ASSERT_REAL(0.8974358974, (double)TV_BETA0(&trk, 0) + beta(0, 0) + beta(0, 1)); /* TV13 row sum */
    TV_ASSERT_REAL(0.8285714286, (double)TV_BETA0(&trk, 1) + beta(1, 1) + beta(1, 2)); /* TV13 row sum */
}

static void test_tv13_cheap_normalised(void)
{
    static const double r1[3] = {0.619047619, 0.2571428571, 0};
    static const double r2[3] = {0, 0.4827586207, 0.3448275862};
    problem(MTT_ASSOC_CHEAP_JPDA, 2, 3, A13, 0.1, NULL);
    mtt_cheap_jpda(&trk, 0, 1);
    assert_row(0, 3, 0.1238095238, r1, "TV13 Cheap normalised");
    assert_row(1, 3, 0.1724137931, r2, "TV13 Cheap normalised");
}

static void test_tv13_suboptimal(void)
{
    static const double N[2][3] = {{0.3, 0.5, 0.5}, {0.4, 0.2, 0.4}}; /* TV13 N[s][j] */
    static const double D[2][3] = {{0.2, 0.06, 0}, {0, 0.2, 0.1}};   /* TV13 D */
    static const double c1[3] = {0.5555555556, 0.1666666667, 0}, c2[3] = {0, 0.5, 0.25};
    static const double p1[3] = {0.6666666667, 0.2, 0}, p2[3] = {0, 0.5714285714, 0.2857142857};
    int s, j;
    problem(MTT_ASSOC_SUBOPT_JPDA, 2, 3, A13, 0.1, NULL);
    mtt_subopt_jpda(&trk, 0, 0); /* constant B */
    for (s = 0; s < 2; ++s) {
        for (j = 0; j < 3; ++j) {
            double n_sj = (TV_JP_ARG1(&trk, s) == j) ? (double)TV_JP_MAX2(&trk, s)
                                                     : (double)TV_JP_MAX1(&trk, s);
            TV_ASSERT_REAL_MSG(N[s][j], n_sj, "TV13 N[s][j]");
            /* D = beta * B / beta_0 (constant B) */
            TV_ASSERT_REAL_MSG(D[s][j], beta(s, j) * 0.1 / (double)TV_BETA0(&trk, s), "TV13 D");
        }
    }
    assert_row(0, 3, 0.2777777778, c1, "TV13 Suboptimal constant B");
    assert_row(1, 3, 0.25, c2, "TV13 Suboptimal constant B");
    problem(MTT_ASSOC_SUBOPT_JPDA, 2, 3, A13, 0.1, NULL);
    mtt_subopt_jpda(&trk, 0, 1); /* library default B_1 = 0.04, B_2 = 0.05 */
    TV_ASSERT_REAL(0.04, 0.1 * (double)TV_JP_MAX1(&trk, 1)); /* TV13 B_1 */
    TV_ASSERT_REAL(0.05, 0.1 * (double)TV_JP_MAX1(&trk, 0)); /* TV13 B_2 */
    assert_row(0, 3, 0.1333333333, p1, "TV13 Suboptimal B_t");
    assert_row(1, 3, 0.1428571429, p2, "TV13 Suboptimal B_t");
}

/* The settings key subopt_jpda_constant_b selects the constant B in the
 * association stage (mtt_associate_frame, as mtt_tracker_step runs it). */
static void test_tv13_suboptimal_key(void)
{
    static const double c1[3] = {0.5555555556, 0.1666666667, 0}, c2[3] = {0, 0.5, 0.25};
    static const double p1[3] = {0.6666666667, 0.2, 0}, p2[3] = {0, 0.5714285714, 0.2857142857};
    size_t k;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_find("subopt_jpda_constant_b", &k));
    problem(MTT_ASSOC_SUBOPT_JPDA, 2, 3, A13, 0.1, NULL);
    trk.par.subopt_jpda_constant_b = 1;
    mtt_associate_frame(&trk);
    assert_row(0, 3, 0.2777777778, c1, "key: constant B");
    assert_row(1, 3, 0.25, c2, "key: constant B");
    problem(MTT_ASSOC_SUBOPT_JPDA, 2, 3, A13, 0.1, NULL);
    TEST_ASSERT_EQUAL_INT(0, trk.par.subopt_jpda_constant_b); /* the default: B_t */
    mtt_associate_frame(&trk);
    assert_row(0, 3, 0.1333333333, p1, "key: B_t");
    assert_row(1, 3, 0.1428571429, p2, "key: B_t");
}

static void test_tv13_exact_jpda_events(void)
{
    /* TV13, enumeration order: T1 none / z1 / z2, then T2 none / z2 / z3. */
    static const double w[8] = {0.01, 0.04, 0.02, 0.05, 0.2, 0.1, 0.03, 0.06};
    static const double r1[3] = {0.6862745098, 0.1764705882, 0};
    static const double r2[3] = {0, 0.4705882353, 0.3529411765};
    double sc, total = 0.0;
    int e;
    problem(MTT_ASSOC_JPDA, 2, 3, A13, 0.1, NULL);
    TEST_ASSERT_EQUAL_INT(0, mtt_jpda_exact(&trk, 0, MTT_JPDA_EXACT));
    TEST_ASSERT_EQUAL_UINT32(8u, TV_JP_N_EVENTS(&trk)); /* TV13: 8 feasible events */
    sc = (double)TV_JP_SCALE(&trk, 0) * (double)TV_JP_SCALE(&trk, 1); /* rows are scaled */
    for (e = 0; e < 8; ++e) {
        TV_ASSERT_REAL_MSG(w[e], (double)TV_JP_EV_W(&trk, e) * sc, "TV13 event weight");
        total += (double)TV_JP_EV_W(&trk, e) * sc;
    }
    TV_ASSERT_REAL(0.51, total); /* TV13 total weight */
    assert_row(0, 3, 0.137254902, r1, "TV13 exact JPDA");
    assert_row(1, 3, 0.1764705882, r2, "TV13 exact JPDA");
}

static void test_tv13_jpda_star_equals_jpda_here(void)
{
    static const double r1[3] = {0.6862745098, 0.1764705882, 0};
    problem(MTT_ASSOC_JPDA_STAR, 2, 3, A13, 0.1, NULL);
    TEST_ASSERT_EQUAL_INT(0, mtt_jpda_exact(&trk, 0, MTT_JPDA_STAR));
    TEST_ASSERT_EQUAL_UINT32(8u, TV_JP_N_KEPT(&trk)); /* TV13: JPDA* prunes nothing here */
    assert_row(0, 3, 0.137254902, r1, "TV13 JPDA*");
}

static void test_tv13_nnjpda(void)
{
    problem(MTT_ASSOC_NNJPDA, 2, 3, A13, 0.1, NULL);
    TEST_ASSERT_EQUAL_INT(0, mtt_jpda_exact(&trk, 0, MTT_JPDA_EXACT));
    mtt_nnjpda_cluster(&trk, 0);
    TEST_ASSERT_TRUE(TV_ASSIGNED(&trk, 0) >= 0 && TV_ASSIGNED(&trk, 1) >= 0);
    TEST_ASSERT_EQUAL_UINT16(0u, TV_PAIR_MEAS(&trk, TV_ASSIGNED(&trk, 0))); /* TV13: T1 -> z1 */
    TEST_ASSERT_EQUAL_UINT16(1u, TV_PAIR_MEAS(&trk, TV_ASSIGNED(&trk, 1))); /* TV13: T2 -> z2 */
    TV_ASSERT_REAL(0.6862745098, TV_PAIR_BETA(&trk, TV_ASSIGNED(&trk, 0)));
    TV_ASSERT_REAL(0.4705882353, TV_PAIR_BETA(&trk, TV_ASSIGNED(&trk, 1)));
}

static void test_nnjpda_threshold(void)
{
    problem(MTT_ASSOC_NNJPDA, 2, 3, A13, 0.1, NULL);
    TV_PAR(&trk).nnjpda_threshold = MTT_R(0.5);
    TEST_ASSERT_EQUAL_INT(0, mtt_jpda_exact(&trk, 0, MTT_JPDA_EXACT));
    mtt_nnjpda_cluster(&trk, 0);
    TEST_ASSERT_EQUAL_UINT16(0u, TV_PAIR_MEAS(&trk, TV_ASSIGNED(&trk, 0))); /* 0.686 >= 0.5 */
    TEST_ASSERT_EQUAL_INT(-1, TV_ASSIGNED(&trk, 1));                    /* 0.471 < 0.5 */
}

/* TV13 JPDA* two-track / two-measurement case: A = [0.5, 0.4; 0.45, 0.3]. */
static const double A22[4] = {0.5, 0.4, 0.45, 0.3};

static void test_tv13_2x2_jpda_and_star(void)
{
    static const double j1[2] = {0.396039604, 0.4356435644}, j2[2] = {0.4455445545, 0.3564356436};
    static const double s1[2] = {0.1408450704, 0.6197183099}, s2[2] = {0.6338028169, 0.08450704225};
    problem(MTT_ASSOC_JPDA, 2, 2, A22, 0.1, NULL);
    TEST_ASSERT_EQUAL_INT(0, mtt_jpda_exact(&trk, 0, MTT_JPDA_EXACT));
    TEST_ASSERT_EQUAL_UINT32(7u, TV_JP_N_EVENTS(&trk)); /* TV13: JPDA 7 events */
    assert_row(0, 2, 0.1683168317, j1, "TV13 2x2 JPDA");
    assert_row(1, 2, 0.198019802, j2, "TV13 2x2 JPDA");
    problem(MTT_ASSOC_JPDA_STAR, 2, 2, A22, 0.1, NULL);
    TEST_ASSERT_EQUAL_INT(0, mtt_jpda_exact(&trk, 0, MTT_JPDA_STAR));
    TEST_ASSERT_EQUAL_UINT32(6u, TV_JP_N_KEPT(&trk)); /* TV13: 6 kept */
    /* TV13: (T1->z1, T2->z2), the 5th event in enumeration order, is pruned. */
    TEST_ASSERT_EQUAL_INT(0, (TV_JP_EV_KEEP(&trk, 0) >> 4) & 1);
    assert_row(0, 2, 0.2394366197, s1, "TV13 2x2 JPDA*");
    assert_row(1, 2, 0.2816901408, s2, "TV13 2x2 JPDA*");
}

/* Optional pruning: kept weights (TV13) 0.01, 0.045, 0.03, 0.05, 0.04, 0.18
 * (sum 0.355); p_prune = 0.1 drops 0.01 and 0.03, leaving sum 0.315. */
static void test_jpda_star_pruning(void)
{
    static const double s1[2] = {0.05 / 0.315, 0.22 / 0.315}, s2[2] = {0.225 / 0.315, 0.0};
    problem(MTT_ASSOC_JPDA_STAR, 2, 2, A22, 0.1, NULL);
    TV_PAR(&trk).jpda_star_threshold = MTT_R(0.1);
    TEST_ASSERT_EQUAL_INT(0, mtt_jpda_exact(&trk, 0, MTT_JPDA_STAR));
    TEST_ASSERT_EQUAL_UINT32(4u, TV_JP_N_KEPT(&trk));
    assert_row(0, 2, 0.045 / 0.315, s1, "JPDA* pruned");
    assert_row(1, 2, 0.09 / 0.315, s2, "JPDA* pruned");
}

static void test_tv13_2x2_suboptimal(void)
{
    static const double c1[2] = {0.3488372093, 0.4186046512}, c2[2] = {0.4186046512, 0.3488372093};
    static const double z1[2] = {0.4545454545, 0.5454545455}, z2[2] = {0.5454545455, 0.4545454545};
    problem(MTT_ASSOC_SUBOPT_JPDA, 2, 2, A22, 0.1, NULL);
    mtt_subopt_jpda(&trk, 0, 0);
    assert_row(0, 2, 0.2325581395, c1, "TV13 2x2 Suboptimal");
    assert_row(1, 2, 0.2325581395, c2, "TV13 2x2 Suboptimal");
    problem(MTT_ASSOC_SUBOPT_JPDA, 2, 2, A22, 0.0, NULL); /* B = 0 */
    mtt_subopt_jpda(&trk, 0, 0);
    assert_row(0, 2, 0.0, z1, "TV13 2x2 Suboptimal B = 0");
    assert_row(1, 2, 0.0, z2, "TV13 2x2 Suboptimal B = 0");
    problem(MTT_ASSOC_JPDA, 2, 2, A22, 0.0, NULL); /* = exact JPDA, PD = 1, no clutter */
    TEST_ASSERT_EQUAL_INT(0, mtt_jpda_exact(&trk, 0, MTT_JPDA_EXACT));
    assert_row(0, 2, 0.0, z1, "exact JPDA B = 0");
}

static void test_tv13_jipda(void)
{
    static const double pbar[2] = {0.8, 0.5};
    static const double r1[3] = {0.5832385648, 0.2740610905, 0};
    static const double r2[3] = {0, 0.4822577193, 0.3212453845};
    problem(MTT_ASSOC_JIPDA, 2, 3, A13, 0.0, pbar); /* A13 read as p_tj / lambda_j */
    TEST_ASSERT_EQUAL_INT(0, mtt_jpda_exact(&trk, 0, MTT_JPDA_JIPDA));
    TV_ASSERT_REAL(0.7534123731, TV_EX_POST(&trk, 0)); /* TV13 JIPDA T1 P(exist|Z^k) */
    TV_ASSERT_REAL(0.356795769, TV_EX_POST(&trk, 1));  /* TV13 JIPDA T2 */
    assert_row(0, 3, 0.1427003447, r1, "TV13 JIPDA");
    assert_row(1, 3, 0.1964968962, r2, "TV13 JIPDA");
}

/* TV13 claim check: N tracks, N measurements, all A = 1, B = 0. */
static void test_tv13_claims_n_by_n(void)
{
    double a[16];
    int N, t, j;
    for (N = 2; N <= 4; ++N) {
        for (j = 0; j < N * N; ++j) {
            a[j] = 1.0;
        }
        problem(MTT_ASSOC_CHEAP_JPDA, N, N, a, 0.0, NULL);
        mtt_cheap_jpda(&trk, 0, 0);
        for (t = 0; t < N; ++t) {
            for (j = 0; j < N; ++j) {
                TV_ASSERT_REAL_MSG(1.0 / (2 * N - 1), beta(t, j), "TV13 Cheap 1/(2N-1)");
            }
        }
        problem(MTT_ASSOC_SUBOPT_JPDA, N, N, a, 0.0, NULL);
        mtt_subopt_jpda(&trk, 0, 1);
        for (t = 0; t < N; ++t) {
            for (j = 0; j < N; ++j) {
                TV_ASSERT_REAL_MSG(1.0 / N, beta(t, j), "TV13 Suboptimal 1/N");
            }
        }
        problem(MTT_ASSOC_JPDA, N, N, a, 0.0, NULL);
        TEST_ASSERT_EQUAL_INT(0, mtt_jpda_exact(&trk, 0, MTT_JPDA_EXACT));
        for (t = 0; t < N; ++t) {
            for (j = 0; j < N; ++j) {
                TV_ASSERT_REAL_MSG(1.0 / N, beta(t, j), "TV13 exact 1/N");
            }
        }
    }
}

/* TV13 event counts sum_k C(n,k) C(m,k) k!: 13, 34, 229, 1045. */
static void test_tv13_event_counts(void)
{
    static const int nm[4][2] = {{2, 3}, {3, 3}, {3, 6}, {4, 6}};
    static const uint32_t count[4] = {13u, 34u, 229u, 1045u};
    double a[24];
    int c, j;
    for (j = 0; j < 24; ++j) {
        a[j] = 1.0;
    }
    for (c = 0; c < 4; ++c) {
        problem(MTT_ASSOC_JPDA, nm[c][0], nm[c][1], a, 0.1, NULL);
        TEST_ASSERT_EQUAL_INT(0, mtt_jpda_exact(&trk, 0, MTT_JPDA_EXACT));
        TEST_ASSERT_EQUAL_UINT32(count[c], TV_JP_N_EVENTS(&trk));
    }
}

/* Over MTT_MAX_JPDA_EVENTS (5 x 8 all gated: 19081 events) the cluster
 * falls back to Cheap JPDA, counted; jipda falls back to per-track IPDA. */
static void test_event_bound_fallback(void)
{
    double a[40];
    double cheap[5][8];
    int t, j;
    for (j = 0; j < 40; ++j) {
        a[j] = 0.1 + 0.01 * j;
    }
    problem(MTT_ASSOC_JPDA, 5, 8, a, 0.1, NULL);
    mtt_cheap_jpda(&trk, 0, 1);
    for (t = 0; t < 5; ++t) {
        for (j = 0; j < 8; ++j) {
            cheap[t][j] = beta(t, j);
        }
    }
    problem(MTT_ASSOC_JPDA, 5, 8, a, 0.1, NULL);
    TEST_ASSERT_EQUAL_INT(-1, mtt_jpda_exact(&trk, 0, MTT_JPDA_EXACT));
    mtt_associate_frame(&trk);
    TEST_ASSERT_EQUAL_UINT32(1u, TV_STATS(&trk).last.jpda_fallbacks);
    for (t = 0; t < 5; ++t) {
        for (j = 0; j < 8; ++j) {
            TV_ASSERT_REAL_MSG(cheap[t][j], beta(t, j), "fallback = Cheap JPDA");
        }
    }
    problem(MTT_ASSOC_JIPDA, 5, 8, a, 0.0, NULL);
    mtt_associate_frame(&trk);
    TEST_ASSERT_EQUAL_UINT32(1u, TV_STATS(&trk).last.jpda_fallbacks);
}

/* TV13b: one step of the tracker (the first frame: no prediction) with
 * three seeded tracks, P = I, S = 2 I; T1 and T2 overlap, T3 does not.  The
 * gate-shrink modes gate T1 and T2 with gamma / 3 (T1 loses z1 and z5);
 * each row: x, P diagonal (position), P[0][1]; NNJPDA also the measurement. */
typedef struct {
    mtt_assoc mode;
    double x[3][2], p[3][3];
    int32_t meas[3];
} tv13b_row;

static const tv13b_row tv13b[5] = {
    {MTT_ASSOC_JPDA,
     {{0.1026787467, 0.13826745}, {2.899862848, 0.2168495777}, {50.4358588, 0.1992402551}},
     {{1.129417612, 0.7234655845, -0.01251444907}, {1.062714506, 0.7151994054, 0.07523455396},
      {0.6624824234, 0.5169854573, -0.03703055431}},
     {-2, -2, -2}},
    {MTT_ASSOC_JPDA_VG,
     {{0.2690088809, 0.2637888296}, {2.923225434, 0.225235214}, {50.4358588, 0.1992402551}},
     {{0.9551560841, 0.614009952, -0.2151481373}, {1.065590812, 0.7218413691, 0.07436360612},
      {0.6624824234, 0.5169854573, -0.03703055431}},
     {-2, -2, -2}},
    {MTT_ASSOC_ADAPTIVE_JPDA_STAR,
     {{0.1988043957, 0.304264213}, {3.014818035, 0.2336059331}, {50.4358588, 0.1992402551}},
     {{0.9565699717, 0.6103320249, -0.210704499}, {1.044728253, 0.7458237434, 0.07497966477},
      {0.6624824234, 0.5169854573, -0.03703055431}},
     {-2, -2, -2}},
    {MTT_ASSOC_ADAPTIVE_NNJPDA,
     {{0.6, 0.15}, {2.4, -0.1}, {50.25, 0.25}},
     {{0.5, 0.5, 0.0}, {0.5, 0.5, 0.0}, {0.5, 0.5, 0.0}},
     {2, 3, 6}},
    {MTT_ASSOC_ADAPTIVE_JPDA,
     {{0.4112503596, 0.1887289929}, {2.69088149, 0.1806637621}, {50.4358588, 0.1992402551}},
     {{0.9107918971, 0.6039926946, -0.2046459813}, {1.010649919, 0.6582892564, 0.0706733375},
      {0.6624824234, 0.5169854573, -0.03703055431}},
     {-2, -2, -2}},
};

static void test_tv13b_gate_shrink(void)
{
    static const double zx[8] = {-2.2, -1.5, 1.2, 1.8, 3.5, 5.2, 50.5, 52.5};
    static const double zy[8] = {-1.5, 1.5, 0.3, -0.2, 2.2, 0.0, 0.5, 0.0};
    static const double x0[3] = {0.0, 3.0, 50.0};
    mtt_meas z[8];
    mtt_real P[16];
    int r, t, j;
    memset(z, 0, sizeof z);
    for (j = 0; j < 8; ++j) {
        z[j].x = (mtt_real)zx[j];
        z[j].y = (mtt_real)zy[j];
    }
    for (j = 0; j < 16; ++j) {
        P[j] = (j % 5 == 0) ? MTT_R(1.0) : MTT_R(0.0);
    }
    for (r = 0; r < 5; ++r) {
        const tv13b_row *e = &tv13b[r];
        mtt_params p;
        mtt_track_view v;
        const char *name = NULL;
        char w[64];
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_assoc_name(e->mode, &name));
        p.association = e->mode;
        p.pd = MTT_R(0.9);
        p.pg = MTT_R(0.99);
        p.clutter_density = MTT_R(0.01);
        p.meas_sigma[0] = p.meas_sigma[1] = MTT_R(1.0);
        p.initiate = 0;
        p.merge_threshold = MTT_R(0.0);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
        for (t = 0; t < 3; ++t) {
            const mtt_real x[4] = {(mtt_real)x0[t], MTT_R(0.0), MTT_R(0.0), MTT_R(0.0)};
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x, P, NULL));
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(0.0), z, 8));
        for (t = 0; t < 3; ++t) {
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, (size_t)t, &v));
            snprintf(w, sizeof w, "TV13b %s T%d", name, t + 1);
            tv_assert_real(e->x[t][0], (double)v.x[0], w, __LINE__);
            tv_assert_real(e->x[t][1], (double)v.x[1], w, __LINE__);
            tv_assert_real(e->p[t][0], (double)v.P[0][0], w, __LINE__);
            tv_assert_real(e->p[t][1], (double)v.P[1][1], w, __LINE__);
            tv_assert_real(e->p[t][2], (double)v.P[0][1], w, __LINE__);
            tv_assert_real(1.0, (double)v.existence, w, __LINE__);
            if (e->meas[t] != -2) {
                TEST_ASSERT_EQUAL_INT32_MESSAGE(e->meas[t], v.meas, w); /* NNJPDA's assignment */
            }
        }
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_tv13_cheap_raw);
    RUN_TEST(test_tv13_cheap_normalised);
    RUN_TEST(test_tv13_suboptimal);
    RUN_TEST(test_tv13_suboptimal_key);
    RUN_TEST(test_tv13_exact_jpda_events);
    RUN_TEST(test_tv13_jpda_star_equals_jpda_here);
    RUN_TEST(test_tv13_nnjpda);
    RUN_TEST(test_nnjpda_threshold);
    RUN_TEST(test_tv13_2x2_jpda_and_star);
    RUN_TEST(test_jpda_star_pruning);
    RUN_TEST(test_tv13_2x2_suboptimal);
    RUN_TEST(test_tv13_jipda);
    RUN_TEST(test_tv13_claims_n_by_n);
    RUN_TEST(test_tv13_event_counts);
    RUN_TEST(test_event_bound_fallback);
    RUN_TEST(test_tv13b_gate_shrink);
    return UNITY_END();
}

#else /* MTT_WITH_BASELINES == 0 */

/* Built without the baselines: they must be refused, not half-run. */
static void test_baselines_refused(void)
{
    tv_assert_mode_refused(MTT_ASSOC_JPDA);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_baselines_refused);
    return UNITY_END();
}
#endif
