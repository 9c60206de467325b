/* SPDX-License-Identifier: BSD-3-Clause */
/* test_adapt.c - the noise-adaptive process noise of confirmed lm-ihpda
 * contest tracks (ALGORITHMS.md §2.1, src/contest/adapt_q.c).
 *
 * A seeded track on a noise-free straight target: every innovation is 0,
 * the NIS average falls as alpha^k and s as exp(kappa (r_k - 1)), reaching
 * adapt_s_min within the bound of §2.1.  A step manoeuvre (4.5 sigma) then
 * resets s to 1 at once (NIS > adapt_reset_nis); without the reset a
 * constant NIS of 3 n_bar raises s from 0.01 to 1 in the 5 scans the
 * recursion gives.  The
 * [S0] variant and a contest tracker with adapt_s_min = 1 never leave s = 1
 * and give the same tracks. */
#include <math.h>
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "tv_fixture.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#if MTT_WITH_CONTEST

static mtt_tracker trk;

/* sigma 1, q 1, PD 0.9, PG 0.999, lambda 1e-4, no amplitude, no
 * initiation; the floor adapt_s_min = 0.01 (adapt_index large), alpha 0.8,
 * kappa 2, reset at NIS 8 (the defaults but the index). */
static void start(mtt_lm_ihpda_variant variant, mtt_real s_min, mtt_real reset)
{
    static const mtt_real x0[4] = {MTT_R(0.0), MTT_R(0.0), MTT_R(1.0), MTT_R(0.0)};
    mtt_params p;
    mtt_real P[4][4], P16[16];
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.lm_ihpda_variant = variant;
    p.process_psd = MTT_R(1.0);
    p.clutter_density = MTT_R(1e-4);
    p.initiate = 0;
    p.adapt_s_min = s_min;
    p.adapt_index = MTT_R(1e6);
    p.adapt_reset_nis = reset;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_init_two_point_cov(MTT_R(1.0), MTT_R(1.0), MTT_R(1.0), P));
    memcpy(P16, P, sizeof P16);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x0, P16, NULL));
}

/* Frame k: the target at (k, y). */
static void step(int k, mtt_real y)
{
    mtt_meas z;
    z.x = (mtt_real)k;
    z.y = y;
    z.amplitude = MTT_R(0.0);
    z.has_amplitude = 0;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, (mtt_real)k, &z, 1));
    TEST_ASSERT_EQUAL_UINT(1, TV_N_TRACKS(&trk));
}

static void test_floor_and_nis_mean(void)
{
    mtt_params p;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.process_psd = MTT_R(1.5); /* the dim scenario: Lambda^2 = 1.5 / 25 */
    p.meas_sigma[0] = MTT_R(5.0);
    p.meas_sigma[1] = MTT_R(5.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    TV_ASSERT_REAL(0.06, mtt_adapt_floor(&trk, MTT_R(1.0)));
    TV_ASSERT_REAL(0.48, mtt_adapt_floor(&trk, MTT_R(2.0))); /* dt^3 */
    TV_ASSERT_REAL(1.0, mtt_adapt_floor(&trk, MTT_R(3.0)));  /* at most 1 */
    TV_ASSERT_REAL(0.01, mtt_adapt_floor(&trk, MTT_R(0.1))); /* at least adapt_s_min */
    p.process_psd = MTT_R(250.0); /* the manoeuvre scenario: Lambda^2 = 250 / 225 > 1 */
    p.meas_sigma[0] = MTT_R(15.0);
    p.meas_sigma[1] = MTT_R(15.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    TV_ASSERT_REAL(1.0, mtt_adapt_floor(&trk, MTT_R(1.0)));
    /* E[chi2_2 | chi2_2 < gamma] = 2 - gamma (1 - PG) / PG */
    TV_ASSERT_REAL(1.9069666, mtt_adapt_nis_mean(mtt_gate_gamma(MTT_R(0.99)), MTT_R(0.99)));
    TV_ASSERT_REAL(1.9861706, mtt_adapt_nis_mean(mtt_gate_gamma(MTT_R(0.999)), MTT_R(0.999)));
}

/* r_k = 0.8^(k+1) (frame 0 included: beta ~ 1, NIS 0), s_k = s_{k-1}
 * exp(2 (r_k - 1)) from frame 1 on; frame 0 has no interval, so s stays 1.
 * The bound of ALGORITHMS.md §2.1: s_min by frame
 * ceil(ln(1/s_min)/kappa + rho^2/(1-rho)) = ceil(2.303 + 3.2) = 6. */
static void test_straight_target_falls_to_s_min_within_the_bound(void)
{
    static const double want[5] = {1.0, 0.486752, 0.183418, 0.0563149, 0.0146766};
    int k;
    start(MTT_LM_IHPDA_CONTEST, MTT_R(0.01), MTT_R(8.0));
    for (k = 0; k < 5; ++k) {
        step(k, MTT_R(0.0));
        TEST_ASSERT_FLOAT_WITHIN(2e-3 * want[k], want[k], TV_Q_SCALE(&trk, 0));
    }
    TEST_ASSERT_FLOAT_WITHIN(1e-4, 0.32768, TV_NIS_RATIO(&trk, 0)); /* 0.8^5 */
    step(5, MTT_R(0.0));
    TV_ASSERT_REAL(0.01, TV_Q_SCALE(&trk, 0)); /* frame 5, within the bound 6 */
    step(6, MTT_R(0.0));
    TV_ASSERT_REAL(0.01, TV_Q_SCALE(&trk, 0));
}

/* After frame 6 (s = 0.01) the target steps 4.5 sigma sideways: NIS
 * = 20.25 Si_yy (about 10.2: S_yy is about 2 after 7 scans), inside the
 * gate (gamma 13.8) and above adapt_reset_nis 8: s = 1 in that same scan
 * (N = 1), the average back to 1. */
static void test_step_manoeuvre_resets_at_once(void)
{
    int k;
    mtt_real nis;
    start(MTT_LM_IHPDA_CONTEST, MTT_R(0.01), MTT_R(8.0));
    for (k = 0; k < 7; ++k) {
        step(k, MTT_R(0.0));
    }
    TV_ASSERT_REAL(0.01, TV_Q_SCALE(&trk, 0));
    step(7, MTT_R(4.5));
    TEST_ASSERT_EQUAL_INT(0, TV_TRACK_MEAS(&trk, 0)); /* gated and taken */
    nis = MTT_R(20.25) * TV_SI(&trk, 0)[2];
    TEST_ASSERT_TRUE(nis > MTT_R(8.0) && nis < TV_GAMMA(&trk));
    TV_ASSERT_REAL(1.0, TV_Q_SCALE(&trk, 0));
    TV_ASSERT_REAL(1.0, TV_NIS_RATIO(&trk, 0));
    /* The same step without the reset: s only grows by exp(2 (r - 1)),
     * r = 0.8 * 0.8^7 + 0.2 beta 10.2 / 1.986 = 1.19 for beta ~ 1: s ~ 0.0146. */
    start(MTT_LM_IHPDA_CONTEST, MTT_R(0.01), MTT_R(0.0));
    for (k = 0; k < 7; ++k) {
        step(k, MTT_R(0.0));
    }
    step(7, MTT_R(4.5));
    TEST_ASSERT_TRUE(TV_Q_SCALE(&trk, 0) > MTT_R(0.013) && TV_Q_SCALE(&trk, 0) < MTT_R(0.016));
}

/* Stage level, exact: S = I, the measurement at NIS = 3 n_bar every scan,
 * beta 1, from s = 0.01 and r = 0.5: r_k = 3 - 2.5 0.8^k = 1, 1.4, 1.72,
 * 1.976, 2.181, so ln s grows by 0, 0.8, 1.44, 1.952, 2.362: s = 0.01,
 * 0.02226, 0.09393, 0.6615, then 1 in the fifth scan (N = 5). */
static void test_constant_nis_raises_s_to_1_in_5_scans(void)
{
    static const double want[5] = {0.01, 0.0222554, 0.0939333, 0.661535, 1.0};
    mtt_real nbar;
    int k;
    start(MTT_LM_IHPDA_CONTEST, MTT_R(0.01), MTT_R(0.0));
    step(0, MTT_R(0.0));
    step(1, MTT_R(0.0));
    nbar = mtt_adapt_nis_mean(TV_GAMMA(&trk), TV_PAR(&trk).pg);
    TV_Q_SCALE(&trk, 0) = MTT_R(0.01);
    TV_NIS_RATIO(&trk, 0) = MTT_R(0.5);
    TV_Q_FLOOR(&trk) = MTT_R(0.01);
    TV_SI(&trk, 0)[0] = MTT_R(1.0);
    TV_SI(&trk, 0)[1] = MTT_R(0.0);
    TV_SI(&trk, 0)[2] = MTT_R(1.0);
    TV_XP(&trk, 0)[0] = MTT_R(0.0);
    TV_XP(&trk, 0)[1] = MTT_R(0.0);
    TV_ASSIGNED(&trk, 0) = 0;
    TV_CONTEST(&trk, 0) = MTT_CONTEST_NONE;
    TV_PAIR_MEAS(&trk, 0) = 0;
    TV_PAIR_BETA(&trk, 0) = MTT_R(1.0);
    TV_MEAS_X(&trk, 0) = mtt_sqrt(MTT_R(3.0) * nbar);
    TV_MEAS_Y(&trk, 0) = MTT_R(0.0);
    for (k = 0; k < 5; ++k) {
        mtt_adapt_observe(&trk, 0);
        TEST_ASSERT_FLOAT_WITHIN(1e-4 * want[k], want[k], TV_Q_SCALE(&trk, 0));
    }
    /* a contested or a tentative track, or a miss: nothing moves */
    TV_Q_SCALE(&trk, 0) = MTT_R(0.5);
    TV_CONTEST(&trk, 0) = MTT_CONTEST_YES;
    mtt_adapt_observe(&trk, 0);
    TV_CONTEST(&trk, 0) = MTT_CONTEST_NONE;
    TV_CONFIRMED(&trk, 0) = 0;
    mtt_adapt_observe(&trk, 0);
    TV_CONFIRMED(&trk, 0) = 1;
    TV_ASSIGNED(&trk, 0) = -1;
    mtt_adapt_observe(&trk, 0);
    TV_ASSERT_REAL(0.5, TV_Q_SCALE(&trk, 0));
}

/* [S0] and adapt_s_min = 1: s stays 1, and the tracks are those of the
 * tracker without the adaptation, bit for bit. */
static void test_s0_and_off_keep_s_at_1(void)
{
    mtt_track_view a[8], b[8];
    int k, pass;
    for (pass = 0; pass < 2; ++pass) {
        const mtt_lm_ihpda_variant v = pass == 0 ? MTT_LM_IHPDA_S0 : MTT_LM_IHPDA_CONTEST;
        start(v, MTT_R(0.01), MTT_R(8.0));
        for (k = 0; k < 8; ++k) {
            step(k, k == 7 ? MTT_R(4.5) : MTT_R(0.0));
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 0, &a[k]));
            if (pass == 0) {
                TV_ASSERT_REAL(1.0, TV_Q_SCALE(&trk, 0));
            }
        }
        start(v, MTT_R(1.0), MTT_R(8.0));
        for (k = 0; k < 8; ++k) {
            step(k, k == 7 ? MTT_R(4.5) : MTT_R(0.0));
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 0, &b[k]));
            TV_ASSERT_REAL(1.0, TV_Q_SCALE(&trk, 0));
        }
        if (pass == 0) {
            TEST_ASSERT_EQUAL_MEMORY(b, a, sizeof a); /* s0 ignores the keys */
        } else {
            /* contest with the adaptation predicts with a smaller Q: its
             * position variance after frame 6 is below the plain filter's */
            TEST_ASSERT_TRUE(a[6].P[0][0] < b[6].P[0][0]);
        }
    }
}

#endif /* MTT_WITH_CONTEST */

int main(void)
{
    UNITY_BEGIN();
#if MTT_WITH_CONTEST
    RUN_TEST(test_floor_and_nis_mean);
    RUN_TEST(test_straight_target_falls_to_s_min_within_the_bound);
    RUN_TEST(test_step_manoeuvre_resets_at_once);
    RUN_TEST(test_constant_nis_raises_s_to_1_in_5_scans);
    RUN_TEST(test_s0_and_off_keep_s_at_1);
#endif
    return UNITY_END();
}
