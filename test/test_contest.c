/* SPDX-License-Identifier: BSD-3-Clause */
/* test_contest.c - lm-ihpda with lm_ihpda_variant contest (ALGORITHMS.md
 * §10.4) on hand-built meeting cases, and the amplitude likelihood ratio
 * and its row (ALGORITHMS.md §7.6, docs/TEST_VECTORS.md TV15).
 *
 * The meeting: two tracks 2 sigma apart in y, A at y = 0 and B at y = 2;
 * A's target is missed and B's detection lies at y = 0.9, nearer A.  [S0]
 * (MMR) hands A the detection and leaves B coasting; the contest-aware rule
 * updates both with their LM-IPDA mixtures.  A third track far away shares
 * nothing and keeps the [S0] update bit for bit. */
#include <math.h>
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "tv_fixture.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

static mtt_tracker trk;

#if MTT_WITH_CONTEST

/* A tracker with the given tracks (two-point covariance of sigma 1, dt 1),
 * clutter 1e-3, rho 3, no initiation. */
static void start(mtt_assoc mode, mtt_lm_ihpda_variant variant, const mtt_real (*x)[4], size_t n)
{
    mtt_params p;
    mtt_real P[4][4], P16[16];
    size_t i;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.association = mode;
    p.lm_ihpda_variant = variant;
    p.clutter_density = MTT_R(1e-3);
    p.snr_rho = MTT_R(3.0);
    p.initiate = 0;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_init_two_point_cov(MTT_R(1.0), MTT_R(1.0), MTT_R(1.0), P));
    memcpy(P16, P, sizeof P16);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    for (i = 0; i < n; ++i) {
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x[i], P16, NULL));
    }
}

static void run(mtt_assoc mode, mtt_lm_ihpda_variant variant, const mtt_meas *z, size_t n,
                mtt_track_view v[3])
{
    static const mtt_real x[3][4] = {{MTT_R(0.0), MTT_R(0.0), MTT_R(1.0), MTT_R(0.0)},
                                     {MTT_R(0.0), MTT_R(2.0), MTT_R(1.0), MTT_R(0.0)},
                                     {MTT_R(500.0), MTT_R(500.0), MTT_R(1.0), MTT_R(0.0)}};
    size_t i;
    start(mode, variant, x, 3);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(0.0), z, n));
    for (i = 0; i < 3; ++i) {
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, i, &v[i]));
    }
}

/* B's detection at y = 0.9 and C's own detection; no amplitudes (g = 1). */
static const mtt_meas meet[2] = {{MTT_R(0.0), MTT_R(0.9), MTT_R(0.0), 0},
                                 {MTT_R(500.5), MTT_R(500.2), MTT_R(0.0), 0}};
/* The same with amplitudes: C's detection clutter-like, or strong. */
static const mtt_meas meet_weak[2] = {{MTT_R(0.0), MTT_R(0.9), MTT_R(6.0), 1},
                                      {MTT_R(500.5), MTT_R(500.2), MTT_R(0.5), 1}};
static const mtt_meas meet_strong[2] = {{MTT_R(0.0), MTT_R(0.9), MTT_R(6.0), 1},
                                        {MTT_R(500.5), MTT_R(500.2), MTT_R(6.0), 1}};

static void test_s0_hands_the_missed_track_the_detection(void)
{
    mtt_track_view v[3];
    run(MTT_ASSOC_LM_IHPDA, MTT_LM_IHPDA_S0, meet, 2, v);
    TEST_ASSERT_EQUAL_INT(0, v[0].meas);  /* A took B's detection ... */
    TEST_ASSERT_EQUAL_INT(-1, v[1].meas); /* ... and B coasts */
    TV_ASSERT_REAL(2.0, v[1].x[1]);      /* B learns nothing from its own detection */
    TEST_ASSERT_TRUE(v[0].x[1] > MTT_R(0.2)); /* A is pulled a quarter of the way to B */
}

static void test_contest_updates_both_with_the_lm_ipda_mixture(void)
{
    mtt_track_view v[3], w[3];
    int i, k;
    run(MTT_ASSOC_LM_IHPDA, MTT_LM_IHPDA_CONTEST, meet, 2, v);
    run(MTT_ASSOC_LM_IPDA, MTT_LM_IHPDA_S0, meet, 2, w);
    for (i = 0; i < 2; ++i) {
        for (k = 0; k < 4; ++k) {
            TV_ASSERT_REAL(w[i].x[k], v[i].x[k]);
        }
        TV_ASSERT_REAL(w[i].existence, v[i].existence);
    }
    /* the missed target's track no longer takes the detection alone:
     * B is pulled towards its own detection, A moves less than with [S0] */
    TEST_ASSERT_TRUE(v[1].x[1] < MTT_R(1.8));
    TEST_ASSERT_TRUE(v[0].x[1] < MTT_R(0.3));
    TEST_ASSERT_EQUAL_INT(0, v[1].meas); /* B reports its detection */
}

static void test_uncontested_track_keeps_the_s0_update(void)
{
    mtt_track_view v[3], w[3];
    int k;
    run(MTT_ASSOC_LM_IHPDA, MTT_LM_IHPDA_S0, meet, 2, v);
    run(MTT_ASSOC_LM_IHPDA, MTT_LM_IHPDA_CONTEST, meet, 2, w);
    for (k = 0; k < 4; ++k) {
        TEST_ASSERT_TRUE(v[2].x[k] == w[2].x[k]); /* bit-identical: g = 1, m = 1 */
    }
    TEST_ASSERT_TRUE(v[2].existence == w[2].existence);
    TEST_ASSERT_EQUAL_INT(1, w[2].meas);
}

/* L of track C's pair (its row's likelihood ratio: the existence update's
 * input, ALGORITHMS.md §7.4) after run(). */
static mtt_real c_pair_L(void)
{
    TEST_ASSERT_EQUAL_UINT(2, TV_PAIR_TRACK(&trk, TV_N_PAIRS(&trk) - 1u));
    return TV_PAIR_L(&trk, TV_N_PAIRS(&trk) - 1u);
}

static void test_amplitude_enters_the_existence(void)
{
    mtt_track_view v[3];
    mtt_real none, weak, strong;
    run(MTT_ASSOC_LM_IHPDA, MTT_LM_IHPDA_CONTEST, meet, 2, v);
    none = c_pair_L();
    run(MTT_ASSOC_LM_IHPDA, MTT_LM_IHPDA_CONTEST, meet_weak, 2, v);
    weak = c_pair_L();
    run(MTT_ASSOC_LM_IHPDA, MTT_LM_IHPDA_CONTEST, meet_strong, 2, v);
    strong = c_pair_L();
    /* m = 1: L = 1 - PD PG + PD PG p g / lambda; C's detection weak (a = 0.5,
     * g_0.5 = 0.5335) or strong (a = 6, g_0.5 = 1.978) */
    TV_ASSERT_REAL((double)(none - (MTT_R(1.0) - MTT_R(0.9) * MTT_R(0.999))) * 0.5334532372,
                   weak - (MTT_R(1.0) - MTT_R(0.9) * MTT_R(0.999)));
    TEST_ASSERT_TRUE(strong > none);
    /* [S0] with the same amplitudes: m = 1, so the rank row ignores them */
    run(MTT_ASSOC_LM_IHPDA, MTT_LM_IHPDA_S0, meet_weak, 2, v);
    weak = c_pair_L();
    run(MTT_ASSOC_LM_IHPDA, MTT_LM_IHPDA_S0, meet_strong, 2, v);
    TEST_ASSERT_TRUE(weak == c_pair_L());
    TEST_ASSERT_TRUE(weak == none);
}

/* The contest test on a static case: two tracks gate one measurement; the
 * weaker claim's LM-IPDA beta decides, >= contest_beta contests. */
static void contest_case(mtt_real eps_scale, uint8_t expect)
{
    mtt_params p;
    mtt_real p_[2] = {MTT_R(0.05), MTT_R(0.01)}, lam[2] = {MTT_R(0.02), MTT_R(0.02)}, beta[2], b0, L;
    uint16_t t;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.lm_ihpda_variant = MTT_LM_IHPDA_CONTEST;
    tv_init(&trk, &p);
    (void)tv_add_track_s(&trk, MTT_R(0.0), MTT_R(0.0), MTT_R(2.0), MTT_R(0.0), MTT_R(2.0), MTT_R(0.5));
    (void)tv_add_track_s(&trk, MTT_R(0.0), MTT_R(3.0), MTT_R(2.0), MTT_R(0.0), MTT_R(2.0), MTT_R(0.5));
    (void)tv_add_meas(&trk, MTT_R(0.0), MTT_R(1.0), MTT_R(1.0), 0);
    for (t = 0; t < 2; ++t) {
        tv_add_pair(&trk, t, 0, MTT_R(0.0));
        TV_PAIR_P(&trk, t) = p_[t];
        TV_PAIR_LAM(&trk, t) = lam[t];
    }
    tv_index_pairs(&trk);
    mtt_cluster_frame(&trk);
    /* the weaker claim: track 1's one-measurement LM-IPDA beta */
    tv_ipda_betas(p.pd, p.pg, &p_[1], &lam[1], 1, beta, &b0, &L);
    TV_PAR(&trk).contest_beta = beta[0] * eps_scale;
    mtt_contest_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(expect, TV_CONTEST(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(expect, TV_CONTEST(&trk, 1));
    TV_ASSERT_REAL(beta[0], TV_PAIR_BETA(&trk, 1));
    TV_ASSERT_REAL(b0, TV_BETA0(&trk, 1));
}

static void test_contest_threshold_boundary(void)
{
    contest_case(MTT_R(1.0), MTT_CONTEST_YES);              /* beta == eps: contested */
    contest_case(MTT_R(1.0) + MTT_R(1e-3), MTT_CONTEST_ROW); /* just above: not */
}

static void test_lone_track_is_never_contested(void)
{
    mtt_track_view v[3];
    run(MTT_ASSOC_LM_IHPDA, MTT_LM_IHPDA_CONTEST, meet, 2, v);
    TEST_ASSERT_EQUAL_UINT(MTT_CONTEST_NONE, TV_CONTEST(&trk, 2)); /* C: a cluster of its own */
}

/* Two slow tracks meeting (ALGORITHMS.md §10.4, §12.3): A at y = 0 and B
 * at y = 0.4 with the same velocity, both detected between them.  Both are
 * contested and take the mixture, which brings them within the merge test
 * (d^2 < merge_threshold); [S0] merges such a pair, the contest rule keeps
 * both.  meas 0 and 1 are the detections. */
static size_t meeting_tracks_left(mtt_lm_ihpda_variant variant, mtt_real *d2)
{
    static const mtt_meas z[2] = {{MTT_R(0.0), MTT_R(0.1), MTT_R(0.0), 0},
                                  {MTT_R(0.0), MTT_R(0.3), MTT_R(0.0), 0}};
    static const mtt_real x[2][4] = {{MTT_R(0.0), MTT_R(0.0), MTT_R(1.0), MTT_R(0.0)},
                                     {MTT_R(0.0), MTT_R(0.4), MTT_R(1.0), MTT_R(0.0)}};
    size_t n;
    start(MTT_ASSOC_LM_IHPDA, variant, x, 2);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(1.0), z, 2));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&trk, &n));
    if (n == 2u) {
        TEST_ASSERT_EQUAL_INT(0, mtt_merge_d2(&trk.tracks[0], &trk.tracks[1], d2));
    }
    return n;
}

static void test_contested_meeting_tracks_are_not_merged(void)
{
    mtt_real d2 = MTT_R(-1.0);
    TEST_ASSERT_EQUAL_UINT64(1u, (uint64_t)meeting_tracks_left(MTT_LM_IHPDA_S0, &d2)); /* [S0] merges */
    TEST_ASSERT_EQUAL_UINT64(2u, (uint64_t)meeting_tracks_left(MTT_LM_IHPDA_CONTEST, &d2));
    TEST_ASSERT_EQUAL_UINT(MTT_CONTEST_YES, TV_CONTEST(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(MTT_CONTEST_YES, TV_CONTEST(&trk, 1));
    TEST_ASSERT_TRUE(d2 >= MTT_R(0.0) && d2 < MTT_R(1.0)); /* within the merge test */
}

/* docs/TEST_VECTORS.md TV15: g and g_eta, rho = 3. */
static void test_tv15_amplitude_ratio(void)
{
    static const double a[6] = {0, 1, 2, 4, 10, 50};
    static const double g0[6] = {0.25, 0.5292500042, 1.120422268, 5.021384231, 452.0106036, 2.671618645e+12};
    static const double g5[6] = {0.4, 0.6921693676, 1.056791644, 1.66785046, 1.995585092, 2};
    static const double g1[6] = {0.2702702703, 0.5553952346, 1.107090434, 3.581232886, 9.804776725, 10};
    int i;
    for (i = 0; i < 6; ++i) {
        TV_ASSERT_REAL_MSG(g0[i], mtt_amp_ratio(MTT_R(3.0), MTT_R(0.0), (mtt_real)a[i]), "TV15 g");
        TV_ASSERT_REAL_MSG(g5[i], mtt_amp_ratio(MTT_R(3.0), MTT_R(0.5), (mtt_real)a[i]), "TV15 g_0.5");
        TV_ASSERT_REAL_MSG(g1[i], mtt_amp_ratio(MTT_R(3.0), MTT_R(0.1), (mtt_real)a[i]), "TV15 g_0.1");
    }
    TV_ASSERT_REAL(1.0, mtt_amp_ratio(MTT_R(3.0), MTT_R(0.0), MTT_R(1.848392481))); /* a* */
    TV_ASSERT_REAL(1.0, mtt_amp_ratio(MTT_R(0.0), MTT_R(0.5), MTT_R(7.0)));         /* rho = 0 */
}

/* docs/TEST_VECTORS.md TV15: the amplitude row on the TV5 gate. */
static void test_tv15_amplitude_row(void)
{
    static const double p5[3] = {0.01517412536, 0.005719835949, 0.003383802596};
    static const double amp[3] = {0.5, 3.0, 1.5};
    static const double L[3] = {7.196257209, 5.839738745, 4.38706231};
    static const double beta[3] = {0.5011192124, 0.6138911767, 0.2989810436};
    mtt_params p;
    int16_t best;
    uint16_t j;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.lm_ihpda_variant = MTT_LM_IHPDA_CONTEST;
    p.pd = MTT_R(0.9);
    p.pg = MTT_R(0.99);
    p.snr_rho = MTT_R(3.0);
    tv_init(&trk, &p);
    (void)tv_add_track_s(&trk, MTT_R(0.0), MTT_R(0.0), MTT_R(2.0), MTT_R(0.0), MTT_R(2.0), MTT_R(0.6));
    TV_GATE_AREA(&trk, 0) = MTT_R(291.4001257);
    for (j = 0; j < 3; ++j) {
        (void)tv_add_meas(&trk, (mtt_real)j, MTT_R(0.0), (mtt_real)amp[j], 1);
        tv_add_pair(&trk, 0, j, MTT_R(0.0));
        TV_PAIR_G(&trk, j) = mtt_amp_ratio(p.snr_rho, p.amplitude_eta, (mtt_real)amp[j]);
        TV_PAIR_P(&trk, j) = (mtt_real)p5[j] * TV_PAIR_G(&trk, j); /* as lm_clutter.c leaves it */
        TV_PAIR_LAM(&trk, j) = MTT_R(0.002);
    }
    tv_index_pairs(&trk);
    TEST_ASSERT_EQUAL_UINT(3, mtt_ihpda_row(&trk, 0, 0, -1, 0, &best));
    for (j = 0; j < 3; ++j) {
        TV_ASSERT_REAL_MSG(L[j], TV_PAIR_L(&trk, j), "TV15 L");
        TV_ASSERT_REAL_MSG(beta[j], TV_PAIR_BETA(&trk, j), "TV15 beta");
    }
    TEST_ASSERT_EQUAL_INT(1, best); /* z2 */
    TV_ASSERT_REAL(0.8975368695, mtt_existence_update(MTT_R(0.6), TV_PAIR_L(&trk, 1)));
}

#else /* MTT_WITH_CONTEST == 0 */

/* Built without the contest variant: it is refused by name, on every
 * association, and the tracker is not initialised with it; s0 stands. */
static void test_contest_refused_without_the_build(void)
{
    mtt_params p;
    const char *bad = NULL;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_check(&p, &bad));
    p.lm_ihpda_variant = MTT_LM_IHPDA_CONTEST;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_UNSUPPORTED, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("lm_ihpda_variant", bad);
    p.association = MTT_ASSOC_IPDA;
    bad = NULL;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_UNSUPPORTED, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("lm_ihpda_variant", bad);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_UNSUPPORTED, mtt_tracker_init(&trk, &p));
    p.lm_ihpda_variant = MTT_LM_IHPDA_S0;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
}
#endif

int main(void)
{
    UNITY_BEGIN();
#if MTT_WITH_CONTEST
    RUN_TEST(test_s0_hands_the_missed_track_the_detection);
    RUN_TEST(test_contest_updates_both_with_the_lm_ipda_mixture);
    RUN_TEST(test_uncontested_track_keeps_the_s0_update);
    RUN_TEST(test_amplitude_enters_the_existence);
    RUN_TEST(test_contest_threshold_boundary);
    RUN_TEST(test_lone_track_is_never_contested);
    RUN_TEST(test_contested_meeting_tracks_are_not_merged);
    RUN_TEST(test_tv15_amplitude_ratio);
    RUN_TEST(test_tv15_amplitude_row);
#else
    RUN_TEST(test_contest_refused_without_the_build);
#endif
    return UNITY_END();
}
