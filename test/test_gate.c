/* SPDX-License-Identifier: BSD-3-Clause */
/* test_gate.c - gate threshold, gate area, likelihood, gate test and the
 * gate frame stage.  Expected numbers: docs/TEST_VECTORS.md TV3 (and TV8 for the
 * two-track frame). */
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "tv_fixture.h"
#include "unity.h"

static mtt_tracker trk;

void setUp(void) {}
void tearDown(void) {}

/* TV2 prediction and R (TV3 uses S and z_hat of TV2). */
static const mtt_real tv2_R[3] = {MTT_R(1.0), MTT_R(0.3), MTT_R(2.0)};

static void tv2_pred(mtt_state xp, mtt_cov Pp)
{
    const mtt_state x0 = {MTT_R(100.0), MTT_R(50.0), MTT_R(10.0), MTT_R(-5.0)};
    mtt_cov P0 = {{MTT_R(4.0), MTT_R(1.0), MTT_R(1.0), MTT_R(0.0)},
                         {MTT_R(1.0), MTT_R(4.0), MTT_R(0.0), MTT_R(1.0)},
                         {MTT_R(1.0), MTT_R(0.0), MTT_R(1.0), MTT_R(0.0)},
                         {MTT_R(0.0), MTT_R(1.0), MTT_R(0.0), MTT_R(1.0)}};
    mtt_kalman_predict(MTT_R(1.0), MTT_R(5.0), x0, P0, xp, Pp);
}

/* TV3 candidates: offsets from z_hat and expected values (c4 not gated). */
static const mtt_real tv3_off[5][2] = {{MTT_R(0.8), MTT_R(-0.5)}, {MTT_R(-3.5), MTT_R(2.4)},
                                       {MTT_R(5.0), MTT_R(3.0)},  {MTT_R(8.0), MTT_R(-7.0)},
                                       {MTT_R(9.0), MTT_R(0.0)}};
static const double tv3_d2[5] = {0.1013924342, 2.052695582, 3.10257562, 12.83690663, 8.518936448};
static const int tv3_gated[5] = {1, 1, 1, 0, 1};
static const double tv3_N[5] = {0.01502238411, 0.005662637589, 0.00334996457, 0.0, 0.0002233018927};
static const double tv3_p[5] = {0.01517412536, 0.005719835949, 0.003383802596, 0.0, 0.0002255574674};

static void test_tv3_gamma_volume_det(void)
{
    mtt_real S[3], Si[3], det, K[MTT_MAX_STATE][2], gamma;
    mtt_state xp;
    mtt_cov Pp;
    tv2_pred(xp, Pp);
    TEST_ASSERT_EQUAL_INT(0, mtt_kalman_innov(Pp, tv2_R, S, Si, &det, K));
    gamma = mtt_gate_gamma(MTT_R(0.99));
    TV_ASSERT_REAL(9.210340372, gamma);                     /* TV3 gamma */
    TV_ASSERT_REAL(9.210340372, MTT_R(-2.0) * mtt_gate_ln(MTT_R(1.0) - MTT_R(0.99))); /* MTT_SMALL_LOG */
    TV_ASSERT_REAL(101.4211111, det);                       /* TV3 det S */
    TV_ASSERT_REAL(291.4001257, mtt_gate_volume(gamma, det)); /* TV3 V_G */
}

static void test_tv3_candidates(void)
{
    mtt_real S[3], Si[3], det, K[MTT_MAX_STATE][2], gamma;
    mtt_state xp;
    mtt_cov Pp;
    int c;
    tv2_pred(xp, Pp);
    TEST_ASSERT_EQUAL_INT(0, mtt_kalman_innov(Pp, tv2_R, S, Si, &det, K));
    gamma = mtt_gate_gamma(MTT_R(0.99));
    for (c = 0; c < 5; ++c) {
        /* z = z_hat + offset, nu = z - z_hat (as the tracker computes it) */
        mtt_real zx = xp[0] + tv3_off[c][0], zy = xp[1] + tv3_off[c][1];
        mtt_real d2 = mtt_mahal2(Si, zx - xp[0], zy - xp[1]);
        TV_ASSERT_REAL_MSG(tv3_d2[c], d2, "TV3 d2");
        TEST_ASSERT_EQUAL_INT_MESSAGE(tv3_gated[c], d2 <= gamma, "TV3 gated");
        if (tv3_gated[c]) {
            mtt_real p = mtt_gate_likelihood(d2, det, MTT_R(0.99));
            TV_ASSERT_REAL_MSG(tv3_p[c], p, "TV3 p = N/PG");
            TV_ASSERT_REAL_MSG(tv3_N[c], p * MTT_R(0.99), "TV3 N(nu;0,S)");
        }
    }
}

static void tv3_tracker(void)
{
    mtt_params p;
    mtt_state xp;
    mtt_cov Pp;
    int c;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.pg = MTT_R(0.99); /* TV3 PG */
    tv_init(&trk, &p);
    TV_R(&trk)[0] = tv2_R[0];
    TV_R(&trk)[1] = tv2_R[1];
    TV_R(&trk)[2] = tv2_R[2];
    tv2_pred(xp, Pp);
    (void)tv_add_track_xp(&trk, xp, Pp, MTT_R(0.6));
    for (c = 0; c < 5; ++c) {
        (void)tv_add_meas(&trk, xp[0] + tv3_off[c][0], xp[1] + tv3_off[c][1], MTT_R(1.0), 1);
    }
}

static void test_tv3_gate_frame(void)
{
    static const uint16_t want_meas[4] = {0, 1, 2, 4}; /* TV3: c4 not gated */
    int k;
    tv3_tracker();
    TV_GATE_AREA(&trk, 0) = MTT_R(0.0); /* gate_frame must compute it */
    mtt_gate_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(4, TV_N_PAIRS(&trk));
    TEST_ASSERT_EQUAL_UINT(0, TV_PAIR_FIRST(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(4, TV_PAIR_COUNT(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(1, TV_ALL_AMP(&trk, 0));
    TV_ASSERT_REAL(9.210340372, TV_GAMMA(&trk));    /* TV3 gamma */
    TV_ASSERT_REAL(291.4001257, TV_GATE_AREA(&trk, 0)); /* TV3 V_G */
    for (k = 0; k < 4; ++k) {
        TEST_ASSERT_EQUAL_UINT(0, TV_PAIR_TRACK(&trk, k));
        TEST_ASSERT_EQUAL_UINT(want_meas[k], TV_PAIR_MEAS(&trk, k));
        TV_ASSERT_REAL_MSG(tv3_d2[want_meas[k]], tv_pair_d2(&trk, (uint16_t)k), "TV3 d2");
        TV_ASSERT_REAL_MSG(tv3_p[want_meas[k]], TV_PAIR_P(&trk, k), "TV3 p");
    }
    /* CSR: each gated measurement lists its one pair, c4 none. */
    TEST_ASSERT_EQUAL_UINT(0, TV_MP_FIRST(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(1, TV_MP_FIRST(&trk, 1));
    TEST_ASSERT_EQUAL_UINT(2, TV_MP_FIRST(&trk, 2));
    TEST_ASSERT_EQUAL_UINT(3, TV_MP_FIRST(&trk, 3));
    TEST_ASSERT_EQUAL_UINT(3, TV_MP_FIRST(&trk, 4)); /* c4: empty */
    TEST_ASSERT_EQUAL_UINT(4, TV_MP_FIRST(&trk, 5));
    TEST_ASSERT_EQUAL_UINT(3, TV_MP_LIST(&trk, 3));
    TEST_ASSERT_EQUAL_UINT(4, TV_STATS(&trk).last.pairs);
}

static void test_gate_frame_has_all_amp(void)
{
    tv3_tracker();
    TV_HAS_AMP(&trk, 2) = 0;
    mtt_gate_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(0, TV_ALL_AMP(&trk, 0));
    /* An ungated measurement without amplitude does not matter (c4). */
    tv3_tracker();
    TV_HAS_AMP(&trk, 3) = 0;
    mtt_gate_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(1, TV_ALL_AMP(&trk, 0));
}

static void test_gate_frame_skips_invalid_track(void)
{
    tv3_tracker();
    TV_VALID(&trk, 0) = 0;
    mtt_gate_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(0, TV_N_PAIRS(&trk));
    TEST_ASSERT_EQUAL_UINT(0, TV_PAIR_COUNT(&trk, 0));
}

static void test_gate_bound_is_inclusive(void)
{
    /* ALGORITHMS.md §4: gated iff d2 <= gamma.  With gamma = 4 and S = I a measurement
     * at distance exactly 2 has d2 = gamma exactly; one ulp-ish further out
     * does not. */
    mtt_params p;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    tv_init(&trk, &p);
    (void)tv_add_track_s(&trk, MTT_R(0.0), MTT_R(0.0), MTT_R(1.0), MTT_R(0.0), MTT_R(1.0), MTT_R(0.5));
    TV_GAMMA(&trk) = MTT_R(4.0);
    (void)tv_add_meas(&trk, MTT_R(2.0), MTT_R(0.0), MTT_R(1.0), 1);   /* d2 = 4: in */
    (void)tv_add_meas(&trk, MTT_R(0.0), MTT_R(-2.0), MTT_R(1.0), 1);  /* d2 = 4: in */
    (void)tv_add_meas(&trk, MTT_R(2.0001), MTT_R(0.0), MTT_R(1.0), 1); /* out */
    (void)tv_add_meas(&trk, MTT_R(0.0), MTT_R(2.0001), MTT_R(1.0), 1); /* out */
    (void)tv_add_meas(&trk, MTT_R(-1.5), MTT_R(1.5), MTT_R(1.0), 1);  /* d2 = 4.5: out */
    mtt_gate_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(2, TV_N_PAIRS(&trk));
    TEST_ASSERT_EQUAL_UINT(0, TV_PAIR_MEAS(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(1, TV_PAIR_MEAS(&trk, 1));
    TEST_ASSERT_TRUE(tv_pair_d2(&trk, 0) == MTT_R(4.0));
}

static void test_tv8_two_track_gate_frame(void)
{
    /* TV8: tracks given by z_hat and S, PG = 0.99. */
    mtt_params p;
    int k;
    static const uint16_t pt[4] = {0, 0, 1, 1}, pm[4] = {0, 1, 1, 2};
    static const double d2[4] = {0.8409090909, 1.472727273, 2.311186441, 1.738983051};
    static const double pv[4] = {0.03183372832, 0.02321079044, 0.01318017474, 0.01754581538};
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.pg = MTT_R(0.99);
    tv_init(&trk, &p);
    (void)tv_add_track_s(&trk, MTT_R(0.0), MTT_R(0.0), MTT_R(4.0), MTT_R(1.0), MTT_R(3.0), MTT_R(0.8));
    (void)tv_add_track_s(&trk, MTT_R(5.0), MTT_R(1.0), MTT_R(3.0), MTT_R(-0.5), MTT_R(5.0), MTT_R(0.5));
    /* Input order deliberately not sorted in x: z3 first would be fine too. */
    (void)tv_add_meas(&trk, MTT_R(-1.5), MTT_R(0.5), MTT_R(50.0), 1);
    (void)tv_add_meas(&trk, MTT_R(2.4), MTT_R(0.9), MTT_R(120.0), 1);
    (void)tv_add_meas(&trk, MTT_R(6.8), MTT_R(2.5), MTT_R(70.0), 1);
    mtt_gate_frame(&trk);
    TV_ASSERT_REAL(95.96699484, TV_GATE_AREA(&trk, 0));  /* TV8 T1 V_G */
    TV_ASSERT_REAL(111.1275048, TV_GATE_AREA(&trk, 1));  /* TV8 T2 V_G */
    TEST_ASSERT_EQUAL_UINT(4, TV_N_PAIRS(&trk));     /* TV8: T1 {z1, z2}, T2 {z2, z3} */
    for (k = 0; k < 4; ++k) {
        TEST_ASSERT_EQUAL_UINT(pt[k], TV_PAIR_TRACK(&trk, k));
        TEST_ASSERT_EQUAL_UINT(pm[k], TV_PAIR_MEAS(&trk, k));
        TV_ASSERT_REAL_MSG(d2[k], tv_pair_d2(&trk, (uint16_t)k), "TV8 d2");
        TV_ASSERT_REAL_MSG(pv[k], TV_PAIR_P(&trk, k), "TV8 p");
    }
    /* TV8 ungated: T1 z3 d2 = 11.79272727, T2 z1 d2 = 14.59322034 > gamma */
    TV_ASSERT_REAL(11.79272727, mtt_mahal2(TV_SI(&trk, 0), MTT_R(6.8), MTT_R(2.5)));
    TV_ASSERT_REAL(14.59322034, mtt_mahal2(TV_SI(&trk, 1), MTT_R(-6.5), MTT_R(-0.5)));
    TEST_ASSERT_EQUAL_UINT(0, TV_PAIR_FIRST(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(2, TV_PAIR_COUNT(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(2, TV_PAIR_FIRST(&trk, 1));
    TEST_ASSERT_EQUAL_UINT(2, TV_PAIR_COUNT(&trk, 1));
    /* CSR: z1 -> {pair 0}, z2 -> {pairs 1, 2} (ascending track), z3 -> {3} */
    TEST_ASSERT_EQUAL_UINT(0, TV_MP_FIRST(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(1, TV_MP_FIRST(&trk, 1));
    TEST_ASSERT_EQUAL_UINT(3, TV_MP_FIRST(&trk, 2));
    TEST_ASSERT_EQUAL_UINT(4, TV_MP_FIRST(&trk, 3));
    TEST_ASSERT_EQUAL_UINT(0, TV_MP_LIST(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(1, TV_MP_LIST(&trk, 1));
    TEST_ASSERT_EQUAL_UINT(2, TV_MP_LIST(&trk, 2));
    TEST_ASSERT_EQUAL_UINT(3, TV_MP_LIST(&trk, 3));
}

static void test_gate_frame_unsorted_input(void)
{
    /* Same as TV8 with the measurements in reverse input order: measure.c
     * stores them in the canonical (x) order, so the pairs are TV8's, and
     * each stored measurement keeps its input index. */
    mtt_params p;
    mtt_meas in[3];
    in[0].x = MTT_R(6.8), in[0].y = MTT_R(2.5), in[0].amplitude = MTT_R(70.0);   /* z3 */
    in[1].x = MTT_R(2.4), in[1].y = MTT_R(0.9), in[1].amplitude = MTT_R(120.0);  /* z2 */
    in[2].x = MTT_R(-1.5), in[2].y = MTT_R(0.5), in[2].amplitude = MTT_R(50.0);  /* z1 */
    in[0].has_amplitude = in[1].has_amplitude = in[2].has_amplitude = 1;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.pg = MTT_R(0.99);
    tv_init(&trk, &p);
    (void)tv_add_track_s(&trk, MTT_R(0.0), MTT_R(0.0), MTT_R(4.0), MTT_R(1.0), MTT_R(3.0), MTT_R(0.8));
    (void)tv_add_track_s(&trk, MTT_R(5.0), MTT_R(1.0), MTT_R(3.0), MTT_R(-0.5), MTT_R(5.0), MTT_R(0.5));
    mtt_measure_select(&trk, in, NULL, NULL, 3u);
    TEST_ASSERT_EQUAL_UINT32(2u, TV_MEAS_SRC(&trk, 0)); /* z1 */
    TEST_ASSERT_EQUAL_UINT32(1u, TV_MEAS_SRC(&trk, 1)); /* z2 */
    TEST_ASSERT_EQUAL_UINT32(0u, TV_MEAS_SRC(&trk, 2)); /* z3 */
    mtt_gate_frame(&trk);
    TEST_ASSERT_EQUAL_UINT(4, TV_N_PAIRS(&trk));
    TEST_ASSERT_EQUAL_UINT(0, TV_PAIR_MEAS(&trk, 0)); /* T1 z1 */
    TEST_ASSERT_EQUAL_UINT(1, TV_PAIR_MEAS(&trk, 1)); /* T1 z2 */
    TEST_ASSERT_EQUAL_UINT(1, TV_PAIR_MEAS(&trk, 2)); /* T2 z2 */
    TEST_ASSERT_EQUAL_UINT(2, TV_PAIR_MEAS(&trk, 3)); /* T2 z3 */
    TV_ASSERT_REAL(1.472727273, tv_pair_d2(&trk, 1)); /* TV8 T1 z2 */
    TV_ASSERT_REAL(1.738983051, tv_pair_d2(&trk, 3)); /* TV8 T2 z3 */
}

/* MTT_SMALL_LOG's ln against libm's over 1 - PG in [1e-7, 1) and beyond:
 * within 4 ulp of the result in float (a few roundings of the series);
 * in double the truncated series bounds it, 1e-9 relative. */
static void test_gate_ln_matches_libm(void)
{
    static const double xs[] = {1e-7, 1e-4, 0.001, 0.01, 0.05, 0.1, 0.2937, 0.5, 0.7071, 0.7072,
                                0.9, 0.99, 0.999999, 1.0, 1.4142, 1.4143, 2.0, 3.0, 1e3, 1e30};
    size_t i;
    for (i = 0; i < sizeof xs / sizeof xs[0]; ++i) {
        const mtt_real x = (mtt_real)xs[i];
        const mtt_real ref = mtt_log(x), got = mtt_gate_ln(x);
        const mtt_real rel = (MTT_REAL_KIND == 1) ? MTT_R(4.0) * MTT_REAL_EPS : MTT_R(1e-9);
        const mtt_real tol = rel * (mtt_fabs(ref) > MTT_R(1.0) ? mtt_fabs(ref) : MTT_R(1.0));
        TEST_ASSERT_TRUE_MESSAGE(mtt_fabs(got - ref) <= tol, "mtt_gate_ln vs libm log");
    }
    TEST_ASSERT_TRUE(mtt_gate_ln(MTT_R(1.0)) == MTT_R(0.0));
    TEST_ASSERT_TRUE(mtt_gate_ln(MTT_R(0.5)) == -MTT_R(0.69314718055994531));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_tv3_gamma_volume_det);
    RUN_TEST(test_tv3_candidates);
    RUN_TEST(test_tv3_gate_frame);
    RUN_TEST(test_gate_frame_has_all_amp);
    RUN_TEST(test_gate_frame_skips_invalid_track);
    RUN_TEST(test_gate_bound_is_inclusive);
    RUN_TEST(test_tv8_two_track_gate_frame);
    RUN_TEST(test_gate_frame_unsorted_input);
    RUN_TEST(test_gate_ln_matches_libm);
    return UNITY_END();
}
