/* SPDX-License-Identifier: BSD-3-Clause */
/* test_initiate.c - two-point differencing initiation (ALGORITHMS.md §12.1, TV10) and
 * the intensity-based initial gate f(I) (ALGORITHMS.md §12.2, TV12). */
#include <string.h>

#include "mtt_internal.h"
#include "tv_assert.h"
#include "tv_fixture.h"
#include "unity.h"

static mtt_tracker trk;

void setUp(void) {}
void tearDown(void) {}

static void init_with(mtt_real sx, mtt_real sy, mtt_real vmax)
{
    mtt_params p;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.meas_sigma[0] = sx;
    p.meas_sigma[1] = sy;
    p.vmax = vmax;
    tv_init(&trk, &p);
}

static mtt_mstore ms(mtt_real x, mtt_real y, mtt_real amp, int has_amp)
{
    mtt_mstore m;
    memset(&m, 0, sizeof m);
    TV_REC_X(&m) = x;
    TV_REC_Y(&m) = y;
    TV_REC_AMP(&m) = amp;
    TV_REC_HAS_AMP(&m) = (uint8_t)(has_amp != 0);
    return m;
}

/* ---- TV10 ---- */

static const double tv10_P1[16] = {1, 0, 1, 0, 0, 1, 0, 1, 1, 0, 2, 0, 0, 1, 0, 2};
static const double tv10_P2[16] = {4, 0, 8, 0, 0, 9, 0, 18, 8, 0, 32, 0, 0, 18, 0, 72};

static void test_tv10_two_point_cov(void)
{
    const mtt_real R1[3] = {MTT_R(1.0), MTT_R(0.0), MTT_R(1.0)};
    const mtt_real R2[3] = {MTT_R(4.0), MTT_R(0.0), MTT_R(9.0)};
    mtt_cov P;
    mtt_motion_two_point_cov(R1, MTT_R(1.0), P);
    TV_ASSERT_MAT4(tv10_P1, P); /* TV10 case 1 P_{2|2} */
    mtt_motion_two_point_cov(R2, MTT_R(0.5), P);
    TV_ASSERT_MAT4(tv10_P2, P); /* TV10 case 2 P_{2|2} */
    /* public wrapper, sigmas (2, 3): a 4x4 covariance whatever MTT_MAX_STATE */
    {
        mtt_real P4[4][4];
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_init_two_point_cov(MTT_R(2.0), MTT_R(3.0), MTT_R(0.5), P4));
        TV_ASSERT_MAT4(tv10_P2, P4);
    }
    TEST_ASSERT_EQUAL_INT(MTT_ERR_VALUE, mtt_init_two_point_cov(MTT_R(2.0), MTT_R(3.0), MTT_R(0.0), (mtt_real(*)[4])P));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_init_two_point_cov(MTT_R(2.0), MTT_R(3.0), MTT_R(1.0), NULL));
}

static void test_tv10_full_R(void)
{
    /* [[R, R/dT], [R/dT, 2R/dT^2]] with an off-diagonal R term, dT = 0.5 */
    const mtt_real R[3] = {MTT_R(4.0), MTT_R(1.0), MTT_R(9.0)};
    static const double want[16] = {4, 1, 8, 2, 1, 9, 2, 18, 8, 2, 32, 8, 2, 18, 8, 72};
    mtt_cov P;
    mtt_motion_two_point_cov(R, MTT_R(0.5), P);
    TV_ASSERT_MAT4(want, P);
}

static void test_tv10_velocity_gate(void)
{
    mtt_mstore a, b;
    init_with(MTT_R(1.0), MTT_R(1.0), MTT_R(60.0));
    a = ms(MTT_R(100.0), MTT_R(200.0), MTT_R(0.0), 0);
    b = ms(MTT_R(130.0), MTT_R(190.0), MTT_R(0.0), 0);
    TEST_ASSERT_EQUAL_INT(1, mtt_init_pair_ok(&trk, &a, &b, MTT_R(1.0))); /* TV10 case 1: 31.6 <= 60 */
    b = ms(MTT_R(150.0), MTT_R(240.0), MTT_R(0.0), 0);
    TEST_ASSERT_EQUAL_INT(0, mtt_init_pair_ok(&trk, &a, &b, MTT_R(1.0))); /* TV10 case 3: 64.03 > 60 */
    init_with(MTT_R(2.0), MTT_R(3.0), MTT_R(12.0));
    a = ms(MTT_R(10.0), MTT_R(20.0), MTT_R(0.0), 0);
    b = ms(MTT_R(14.0), MTT_R(17.0), MTT_R(0.0), 0);
    TEST_ASSERT_EQUAL_INT(1, mtt_init_pair_ok(&trk, &a, &b, MTT_R(0.5))); /* TV10 case 2: 5 <= 6 */
    /* the circle's bound is inclusive: |d| = 5 with vmax dT = 10 * 0.5 = 5 exactly */
    TV_PAR(&trk).vmax = MTT_R(10.0);
    TEST_ASSERT_EQUAL_INT(1, mtt_init_pair_ok(&trk, &a, &b, MTT_R(0.5)));
    TV_PAR(&trk).vmax = MTT_R(9.9);
    TEST_ASSERT_EQUAL_INT(0, mtt_init_pair_ok(&trk, &a, &b, MTT_R(0.5)));
}

static void run_initiate(mtt_real ax, mtt_real ay, mtt_real bx, mtt_real by, mtt_real dt)
{
    TV_N_PREV(&trk) = 0;
    TV_PREV(&trk, TV_N_PREV(&trk)++) = ms(ax, ay, MTT_R(0.0), 0);
    TV_N_MEAS(&trk) = 0;
    (void)tv_add_meas(&trk, bx, by, MTT_R(0.0), 0);
    mtt_initiate_frame(&trk, dt);
}

static void test_tv10_initiate_frame(void)
{
    static const double x1[4] = {130, 190, 30, -10}; /* TV10 case 1 x_{2|2} */
    static const double x2[4] = {14, 17, 8, -6};     /* TV10 case 2 x_{2|2} */
    init_with(MTT_R(1.0), MTT_R(1.0), MTT_R(60.0));
    run_initiate(MTT_R(100.0), MTT_R(200.0), MTT_R(130.0), MTT_R(190.0), MTT_R(1.0));
    TEST_ASSERT_EQUAL_UINT(1, TV_N_TRACKS(&trk));
    TV_ASSERT_VEC(x1, TV_X(&trk, 0), 4);
    TV_ASSERT_MAT4(tv10_P1, TV_P(&trk, 0));
    TV_ASSERT_REAL(0.1, TV_EXISTENCE(&trk, 0)); /* existence_init default 0.1 (S0) */
    TEST_ASSERT_EQUAL_UINT(0, TV_CONFIRMED(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(1, TV_BORN(&trk, 0));
    TEST_ASSERT_EQUAL_UINT(1, TV_USED(&trk, 0));   /* started a track */
    TEST_ASSERT_EQUAL_UINT(0, TV_N_PREV(&trk));          /* so not in U_{k-1} next frame */
    TEST_ASSERT_EQUAL_UINT(1, TV_STATS(&trk).last.births);

    init_with(MTT_R(2.0), MTT_R(3.0), MTT_R(12.0));
    run_initiate(MTT_R(10.0), MTT_R(20.0), MTT_R(14.0), MTT_R(17.0), MTT_R(0.5));
    TEST_ASSERT_EQUAL_UINT(1, TV_N_TRACKS(&trk));
    TV_ASSERT_VEC(x2, TV_X(&trk, 0), 4);
    TV_ASSERT_MAT4(tv10_P2, TV_P(&trk, 0));

    init_with(MTT_R(1.0), MTT_R(1.0), MTT_R(60.0));
    run_initiate(MTT_R(100.0), MTT_R(200.0), MTT_R(150.0), MTT_R(240.0), MTT_R(1.0));
    TEST_ASSERT_EQUAL_UINT(0, TV_N_TRACKS(&trk));        /* TV10 case 3: initiate = false */
    TEST_ASSERT_EQUAL_UINT(1, TV_N_PREV(&trk));          /* z_k is kept for the next frame */
    TV_ASSERT_REAL(150.0, TV_PREV_X(&trk, 0));
}

static void test_initiate_skips_used_and_disabled(void)
{
    init_with(MTT_R(1.0), MTT_R(1.0), MTT_R(60.0));
    TV_N_PREV(&trk) = 0;
    TV_PREV(&trk, TV_N_PREV(&trk)++) = ms(MTT_R(100.0), MTT_R(200.0), MTT_R(0.0), 0);
    TV_N_MEAS(&trk) = 0;
    (void)tv_add_meas(&trk, MTT_R(130.0), MTT_R(190.0), MTT_R(0.0), 0);
    TV_USED(&trk, 0) = 1; /* assigned to a track: not in U_k */
    mtt_initiate_frame(&trk, MTT_R(1.0));
    TEST_ASSERT_EQUAL_UINT(0, TV_N_TRACKS(&trk));
    TEST_ASSERT_EQUAL_UINT(0, TV_N_PREV(&trk));

    init_with(MTT_R(1.0), MTT_R(1.0), MTT_R(60.0));
    TV_PAR(&trk).initiate = 0;
    run_initiate(MTT_R(100.0), MTT_R(200.0), MTT_R(130.0), MTT_R(190.0), MTT_R(1.0));
    TEST_ASSERT_EQUAL_UINT(0, TV_N_TRACKS(&trk));
}

static void test_tv10_public_api(void)
{
    /* TV10 case 1 end to end: frame at t = 0 with z_(k-1), t = 1 with z_k. */
    mtt_params p;
    mtt_meas m;
    mtt_track_view v;
    size_t n = 99;
    static const double x1[4] = {130, 190, 30, -10};
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    memset(&m, 0, sizeof m);
    m.x = MTT_R(100.0);
    m.y = MTT_R(200.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(0.0), &m, 1));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&trk, &n));
    TEST_ASSERT_EQUAL_UINT(0, n);
    m.x = MTT_R(130.0);
    m.y = MTT_R(190.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(1.0), &m, 1));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&trk, &n));
    TEST_ASSERT_EQUAL_UINT(1, n);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 0, &v));
    TV_ASSERT_VEC(x1, v.x, 4);
    TV_ASSERT_MAT4(tv10_P1, v.P);
    TV_ASSERT_REAL(0.1, v.existence);
    TEST_ASSERT_EQUAL_INT(0, v.confirmed);

    /* TV10 case 3: rejected by the velocity gate, no track. */
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    m.x = MTT_R(100.0);
    m.y = MTT_R(200.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(0.0), &m, 1));
    m.x = MTT_R(150.0);
    m.y = MTT_R(240.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(1.0), &m, 1));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&trk, &n));
    TEST_ASSERT_EQUAL_UINT(0, n);
}

/* ---- TV12 ---- */

static void test_tv12_f(void)
{
    mtt_params p;
    static const double I[6] = {0, 100, 150, 200, 250, 1000};
    static const double f[6] = {39.7, 83.42, 100.03, 104.165, 103.425, 166.95};
    static const double sp2[6] = {175.1211111, 773.2107111, 1111.777878,
                                  1205.594136, 1188.525625, 3096.9225};
    int k;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    for (k = 0; k < 6; ++k) {
        mtt_real v = mtt_init_intensity_f(&p, (mtt_real)I[k]);
        TV_ASSERT_REAL_MSG(f[k], v, "TV12 f(I)");
        TV_ASSERT_REAL_MSG(sp2[k], (v / MTT_R(3.0)) * (v / MTT_R(3.0)), "TV12 sigma_P^2");
    }
}

static void test_tv12_clamp(void)
{
    mtt_params p;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    TV_ASSERT_REAL(167.185225, mtt_init_intensity_f(&p, MTT_R(1048.5))); /* TV12 f(I_peak) */
    TV_ASSERT_REAL(167.185225, mtt_init_intensity_f(&p, MTT_R(2000.0))); /* TV12 clamped f(2000) */
    TV_ASSERT_REAL(167.185225, mtt_init_intensity_f(&p, MTT_R(1e6)));
    TV_ASSERT_REAL(39.7, mtt_init_intensity_f(&p, MTT_R(-50.0)));        /* I < 0 clamps to 0 */
}

static void test_tv12_intensity_gate_radius(void)
{
    /* TV12: I = 200, R = diag(1, 1), gamma = 9 (pg = 1 - e^-4.5): the pair is
     * accepted inside radius sqrt(gamma (sigma_P^2 + 1)) = 104.2081917. */
    mtt_params p;
    mtt_mstore a, b;
    const double radius = 104.2081917; /* TV12 */
    static const double dir[4][2] = {{1, 0}, {0, -1}, {0.6, 0.8}, {-0.7071067811865476, 0.7071067811865476}};
    int k;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.pg = (mtt_real)(1.0 - exp(-4.5));
    p.init_gate = MTT_INIT_GATE_INTENSITY;
    p.vmax = MTT_R(1.0); /* the vmax circle would reject everything below */
    tv_init(&trk, &p);
    TV_ASSERT_REAL(9.0, TV_GAMMA(&trk));
    a = ms(MTT_R(500.0), MTT_R(300.0), MTT_R(200.0), 1);
    for (k = 0; k < 4; ++k) {
        b = ms((mtt_real)(500.0 + 0.999 * radius * dir[k][0]),
               (mtt_real)(300.0 + 0.999 * radius * dir[k][1]), MTT_R(0.0), 0);
        TEST_ASSERT_EQUAL_INT_MESSAGE(1, mtt_init_pair_ok(&trk, &a, &b, MTT_R(1.0)), "inside radius");
        b = ms((mtt_real)(500.0 + 1.001 * radius * dir[k][0]),
               (mtt_real)(300.0 + 1.001 * radius * dir[k][1]), MTT_R(0.0), 0);
        TEST_ASSERT_EQUAL_INT_MESSAGE(0, mtt_init_pair_ok(&trk, &a, &b, MTT_R(1.0)), "outside radius");
    }
    /* Without amplitude on z_(k-1) the vmax circle applies (vmax dT = 1). */
    TV_REC_HAS_AMP(&a) = 0;
    b = ms(MTT_R(500.5), MTT_R(300.0), MTT_R(0.0), 0);
    TEST_ASSERT_EQUAL_INT(1, mtt_init_pair_ok(&trk, &a, &b, MTT_R(1.0)));
    b = ms(MTT_R(550.0), MTT_R(300.0), MTT_R(0.0), 0);
    TEST_ASSERT_EQUAL_INT(0, mtt_init_pair_ok(&trk, &a, &b, MTT_R(1.0)));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_tv10_two_point_cov);
    RUN_TEST(test_tv10_full_R);
    RUN_TEST(test_tv10_velocity_gate);
    RUN_TEST(test_tv10_initiate_frame);
    RUN_TEST(test_initiate_skips_used_and_disabled);
    RUN_TEST(test_tv10_public_api);
    RUN_TEST(test_tv12_f);
    RUN_TEST(test_tv12_clamp);
    RUN_TEST(test_tv12_intensity_gate_radius);
    return UNITY_END();
}
