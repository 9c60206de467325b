/* SPDX-License-Identifier: BSD-3-Clause */
/* test_meas_cov.c - a covariance per detection (mtt_tracker_step_cov,
 * ALGORITHMS.md §3.1): gating and likelihood with the detection's own R,
 * the mixture PDA update against an independent double computation, the
 * two-point birth, meas_sigma's R given explicitly against none in every
 * mode (and with the IMM), the order invariance, bad covariances and the
 * refusals (a build without MTT_WITH_MEAS_COV); split takes them. */
#include <math.h>
#include <string.h>

#include "mtt_internal.h"
#include "unity.h"

static mtt_tracker ta;
#if MTT_WITH_MEAS_COV
static mtt_tracker tb;
#endif

void setUp(void) {}
void tearDown(void) {}

#if MTT_WITH_MEAS_COV

static void base_params(mtt_params *p, mtt_assoc mode)
{
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(p));
    p->association = mode;
    p->process_psd = MTT_R(1.0);
    p->meas_sigma[0] = MTT_R(1.0);
    p->meas_sigma[1] = MTT_R(1.0);
    p->pd = MTT_R(0.9);
    p->pg = MTT_R(0.99);
    p->clutter_density = MTT_R(1e-3);
    p->vmax = MTT_R(50.0);
}

static mtt_meas det(double x, double y)
{
    mtt_meas m;
    memset(&m, 0, sizeof m);
    m.x = (mtt_real)x;
    m.y = (mtt_real)y;
    return m;
}

static mtt_meas_cov cv3(double rxx, double rxy, double ryy)
{
    mtt_meas_cov c;
    c.r_xx = (mtt_real)rxx;
    c.r_xy = (mtt_real)rxy;
    c.r_yy = (mtt_real)ryy;
    return c;
}

/* One seeded track at the origin at rest, P = diag(4, 4, 1, 1), stepped
 * at t = 1 (the first frame: no births), initiation off. */
static void one_track(mtt_tracker *t, mtt_assoc mode)
{
    mtt_params p;
    const mtt_real x[4] = {MTT_R(0.0), MTT_R(0.0), MTT_R(0.0), MTT_R(0.0)};
    mtt_real P[16];
    base_params(&p, mode);
    p.initiate = 0;
    p.motion = MTT_MOTION_CV;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(t, &p));
    memset(P, 0, sizeof P);
    P[0] = P[5] = MTT_R(4.0);
    P[10] = P[15] = MTT_R(1.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(t, x, P, NULL));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(t, MTT_R(0.0), NULL, 0u));
}

/* d2 and N(nu; 0, S)/PG in double, S = Pp_pos + R. */
static double gauss(const mtt_track_frame *tf, const double R[3], double pg, double zx, double zy, double *d2)
{
    const double s0 = (double)tf->Pp[0][0] + R[0], s1 = 0.5 * ((double)tf->Pp[0][1] + (double)tf->Pp[1][0]) + R[1];
    const double s2 = (double)tf->Pp[1][1] + R[2], det = s0 * s2 - s1 * s1;
    const double nx = zx - (double)tf->xp[0], ny = zy - (double)tf->xp[1];
    *d2 = (s2 * nx * nx - 2.0 * s1 * nx * ny + s0 * ny * ny) / det;
    return exp(-0.5 * *d2) / (2.0 * 3.14159265358979323846 * sqrt(det) * pg);
}

static void test_gate_and_likelihood_use_the_detections_r(void)
{
    /* z0 near with meas_sigma's R; z1 at 8 m with a wide R of its own,
     * outside the gate of meas_sigma's; z2 the same place without one */
    const mtt_meas z[3] = {det(3.0, 0.0), det(8.0, 1.0), det(8.5, -1.0)};
    const mtt_meas_cov c[3] = {cv3(0, 0, 0), cv3(40.0, 5.0, 30.0), cv3(0, 0, 0)};
    const double R1[3] = {40.0, 5.0, 30.0}, R0[3] = {1.0, 0.0, 1.0};
    double d2, d2_default, p;
    uint16_t k;
    one_track(&ta, MTT_ASSOC_IPDA);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_cov(&ta, MTT_R(1.0), z, c, 3u));
    TEST_ASSERT_EQUAL_UINT(2, ta.n_pairs);
    (void)gauss(&ta.tf[0], R0, 0.99, 8.0, 1.0, &d2_default);
    TEST_ASSERT_TRUE(d2_default > (double)ta.gamma); /* only its own R gates it */
    for (k = 0; k < ta.n_pairs; ++k) {
        const mtt_mstore *ms = &ta.meas[ta.pairs[k].meas];
        p = gauss(&ta.tf[0], ms->src == 1u ? R1 : R0, 0.99, (double)ms->x, (double)ms->y, &d2);
        TEST_ASSERT_TRUE(ms->src == 0u || ms->src == 1u);
        TEST_ASSERT_FLOAT_WITHIN(1e-5 * p, p, (double)ta.pairs[k].p);
    }
}

/* x, P of the mixture update in double: x = xp + sum b_j K_j nu_j,
 * P = b0 Pp + sum b_j (I - K_j H) Pp + spread of the K_j nu_j. */
static void mixture(const mtt_track_frame *tf, int m, const double R[][3], const double z[][2], const double b[],
                    double b0, double x[4], double P[4][4])
{
    double d[8][4], c[4] = {0, 0, 0, 0}, Pc[4][4];
    int j, i, k;
    memset(Pc, 0, sizeof Pc);
    for (j = 0; j < m; ++j) {
        const double s0 = (double)tf->Pp[0][0] + R[j][0], s1 = (double)tf->Pp[0][1] + R[j][1];
        const double s2 = (double)tf->Pp[1][1] + R[j][2], det = s0 * s2 - s1 * s1;
        const double si[3] = {s2 / det, -s1 / det, s0 / det};
        const double nx = z[j][0] - (double)tf->xp[0], ny = z[j][1] - (double)tf->xp[1];
        double K[4][2];
        for (i = 0; i < 4; ++i) {
            K[i][0] = (double)tf->Pp[i][0] * si[0] + (double)tf->Pp[i][1] * si[1];
            K[i][1] = (double)tf->Pp[i][0] * si[1] + (double)tf->Pp[i][1] * si[2];
            d[j][i] = K[i][0] * nx + K[i][1] * ny;
            c[i] += b[j] * d[j][i];
        }
        for (i = 0; i < 4; ++i) {
            for (k = 0; k < 4; ++k) {
                const double khp = K[i][0] * (double)tf->Pp[0][k] + K[i][1] * (double)tf->Pp[1][k];
                Pc[i][k] += b[j] * ((double)tf->Pp[i][k] - khp);
            }
        }
    }
    for (i = 0; i < 4; ++i) {
        x[i] = (double)tf->xp[i] + c[i];
        for (k = 0; k < 4; ++k) {
            double v = b0 * (double)tf->Pp[i][k] + Pc[i][k] - c[i] * c[k];
            for (j = 0; j < m; ++j) {
                v += b[j] * d[j][i] * d[j][k];
            }
            P[i][k] = v;
        }
    }
}

static void test_pda_update_is_the_mixture_of_the_detections_updates(void)
{
    const mtt_meas z[2] = {det(1.5, -0.5), det(-1.0, 2.0)};
    const mtt_meas_cov c[2] = {cv3(9.0, 2.0, 4.0), cv3(0.25, 0.0, 0.5)};
    const double R[2][3] = {{9.0, 2.0, 4.0}, {0.25, 0.0, 0.5}};
    double zz[2][2], b[2], x[4], P[4][4];
    mtt_track_frame tf;
    mtt_track_view v;
    int j, i, k;
    one_track(&ta, MTT_ASSOC_IPDA);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_cov(&ta, MTT_R(1.0), z, c, 2u));
    TEST_ASSERT_EQUAL_UINT(2, ta.n_pairs);
    tf = ta.tf[0];
    for (j = 0; j < 2; ++j) {
        const mtt_mstore *ms = &ta.meas[ta.pairs[j].meas];
        const int s = (int)ms->src;
        zz[j][0] = (double)ms->x;
        zz[j][1] = (double)ms->y;
        b[j] = (double)ta.pairs[j].beta;
        TEST_ASSERT_EQUAL_FLOAT(R[s][0], ms->R[0]);
    }
    {
        const double Rs[2][3] = {{R[ta.meas[ta.pairs[0].meas].src][0], R[ta.meas[ta.pairs[0].meas].src][1],
                                  R[ta.meas[ta.pairs[0].meas].src][2]},
                                 {R[ta.meas[ta.pairs[1].meas].src][0], R[ta.meas[ta.pairs[1].meas].src][1],
                                  R[ta.meas[ta.pairs[1].meas].src][2]}};
        TEST_ASSERT_TRUE(b[0] > 0.05 && b[1] > 0.05);
        mixture(&tf, 2, (const double(*)[3])Rs, (const double(*)[2])zz, b, (double)tf.beta0, x, P);
    }
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&ta, 0, &v));
    for (i = 0; i < 4; ++i) {
        TEST_ASSERT_FLOAT_WITHIN(1e-4, x[i], (double)v.x[i]);
        for (k = 0; k < 4; ++k) {
            TEST_ASSERT_FLOAT_WITHIN(1e-4 * (fabs(P[i][k]) + 1e-2), P[i][k], (double)v.P[i][k]);
        }
    }
    /* and it is not the one-R update: meas_sigma's R moves the state elsewhere */
    one_track(&tb, MTT_ASSOC_IPDA);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&tb, MTT_R(1.0), z, 2u));
    {
        mtt_track_view w;
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&tb, 0, &w));
        TEST_ASSERT_TRUE(fabs((double)w.x[0] - (double)v.x[0]) > 0.05);
    }
}

static void test_birth_takes_both_detections_r(void)
{
    mtt_params p;
    const mtt_meas a = det(100.0, 100.0), b = det(105.0, 102.0);
    const mtt_meas_cov ca = cv3(4.0, 1.0, 9.0), cb = cv3(16.0, -2.0, 25.0);
    const double Ra[3] = {4.0, 1.0, 9.0}, Rb[3] = {16.0, -2.0, 25.0}, dt = 2.0;
    mtt_track_view v;
    size_t n;
    int i, k;
    base_params(&p, MTT_ASSOC_IPDA);
    p.motion = MTT_MOTION_CV;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&ta, &p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_cov(&ta, MTT_R(0.0), &a, &ca, 1u));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_cov(&ta, (mtt_real)dt, &b, &cb, 1u));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&ta, &n));
    TEST_ASSERT_EQUAL_UINT(1, n);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&ta, 0, &v));
    TEST_ASSERT_FLOAT_WITHIN(1e-4, 2.5, (double)v.x[2]);
    TEST_ASSERT_FLOAT_WITHIN(1e-4, 1.0, (double)v.x[3]);
    for (i = 0; i < 2; ++i) {
        for (k = 0; k < 2; ++k) {
            const int s = i + k; /* R index of (i, k): 0, 1, 2 */
            TEST_ASSERT_FLOAT_WITHIN(1e-4, Rb[s], (double)v.P[i][k]);
            TEST_ASSERT_FLOAT_WITHIN(1e-4, Rb[s] / dt, (double)v.P[i][k + 2]);
            TEST_ASSERT_FLOAT_WITHIN(1e-4, (Ra[s] + Rb[s]) / (dt * dt), (double)v.P[i + 2][k + 2]);
        }
    }
}

static void test_bad_covariance_is_counted(void)
{
    const mtt_meas z[4] = {det(1.0, 1.0), det(2.0, 2.0), det(3.0, 3.0), det(4.0, 4.0)};
    const mtt_meas_cov c[4] = {cv3(-1.0, 0.0, 1.0), cv3(1.0, 2.0, 1.0), cv3(1.0, 0.0, 1.0), cv3(0, 0, 0)};
    mtt_stats st;
    one_track(&ta, MTT_ASSOC_IPDA);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_cov(&ta, MTT_R(1.0), z, c, 4u));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&ta, &st));
    TEST_ASSERT_EQUAL_UINT32(2u, st.last.meas_bad);
    TEST_ASSERT_EQUAL_UINT(2, ta.n_meas);
    TEST_ASSERT_EQUAL_UINT(1, ta.n_own_r);
}

#define FR 30
#define NZ 12
static mtt_meas sz[FR][NZ];
static mtt_meas_cov sc[FR][NZ];
static int sn[FR];

/* Three targets crossing in uniform clutter (a fixed generator). */
static void make_scene(void)
{
    uint32_t s = 12345u;
    int k, i;
    for (k = 0; k < FR; ++k) {
        int n = 0;
        for (i = 0; i < 3; ++i) {
            s = s * 1664525u + 1013904223u;
            if ((s >> 8) % 10u != 0u) { /* PD 0.9 */
                const double e = (double)((s >> 12) % 1000u) / 1000.0 - 0.5;
                sz[k][n] = det(10.0 + 3.0 * k + e, 20.0 + 15.0 * i + (1.0 - i) * 1.0 * k - e);
                sz[k][n].amplitude = MTT_R(4.0);
                sz[k][n].has_amplitude = 1;
                ++n;
            }
        }
        for (i = 0; i < 4; ++i) {
            s = s * 1664525u + 1013904223u;
            sz[k][n] = det((double)((s >> 8) % 1200u) / 10.0, (double)((s >> 4) % 800u) / 10.0);
            sz[k][n].amplitude = MTT_R(1.0);
            sz[k][n].has_amplitude = 1;
            ++n;
        }
        sn[k] = n;
        for (i = 0; i < n; ++i) {
            sc[k][i] = cv3(1.0, 0.0, 1.0); /* meas_sigma's R, given explicitly */
        }
    }
}

static void run_scene(mtt_tracker *t, const mtt_params *p, int with_cov, int reverse)
{
    int k, i;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(t, p));
    for (k = 0; k < FR; ++k) {
        mtt_meas z[NZ];
        mtt_meas_cov c[NZ];
        for (i = 0; i < sn[k]; ++i) {
            z[i] = sz[k][reverse ? sn[k] - 1 - i : i];
            c[i] = sc[k][reverse ? sn[k] - 1 - i : i];
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, with_cov ? mtt_tracker_step_cov(t, (mtt_real)k, z, c, (size_t)sn[k])
                                               : mtt_tracker_step(t, (mtt_real)k, z, (size_t)sn[k]));
    }
}

static void assert_same(const char *what, double tol)
{
    size_t na, nb, i;
    int r;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&ta, &na));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&tb, &nb));
    TEST_ASSERT_EQUAL_MESSAGE(na, nb, what);
    TEST_ASSERT_TRUE_MESSAGE(na >= 3u, what);
    for (i = 0; i < na; ++i) {
        mtt_track_view a, b;
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&ta, i, &a));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&tb, i, &b));
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(a.id, b.id, what);
        TEST_ASSERT_EQUAL_INT_MESSAGE(a.confirmed, b.confirmed, what);
        for (r = 0; r < 4; ++r) {
            TEST_ASSERT_FLOAT_WITHIN_MESSAGE(tol * (1.0 + fabs((double)a.x[r])), (double)a.x[r], (double)b.x[r], what);
            TEST_ASSERT_FLOAT_WITHIN_MESSAGE(tol * (1.0 + fabs((double)a.P[r][r])), (double)a.P[r][r],
                                             (double)b.P[r][r], what);
        }
    }
}

/* meas_sigma's R given as every detection's own covariance takes the
 * per-detection paths (gating, likelihoods, the mixture update, births,
 * the IMM's models) and gives the tracks of no covariance, to rounding. */
static void test_explicit_default_r_gives_the_same_tracks_in_every_mode(void)
{
    int mode;
    make_scene();
    for (mode = 0; mode < (int)MTT_ASSOC_COUNT; ++mode) {
        int motion;
        for (motion = 0; motion < 2; ++motion) {
            mtt_params p;
            base_params(&p, (mtt_assoc)mode);
            p.motion = motion ? MTT_MOTION_IMM : MTT_MOTION_CV;
            if (mtt_params_check(&p, NULL) != MTT_OK) {
                continue; /* not built, or no IMM form */
            }
            run_scene(&ta, &p, 0, 0);
            run_scene(&tb, &p, 1, 0);
            assert_same(motion ? "imm" : "cv", 1e-3);
        }
    }
}

/* One pair of equal positions per frame whose covariances differ in r_xx
 * (v 0), only in r_xy (v 1) or only in r_yy (v 2): the canonical order
 * takes the covariance after the position, so the reversed input gives
 * the same tracks and identities. */
static void test_any_order_gives_the_same_identities(void)
{
    int v;
    for (v = 0; v < 3; ++v) {
        mtt_params p;
        int k;
        make_scene();
        for (k = 0; k < FR; ++k) {
            int i;
            for (i = 0; i < sn[k]; ++i) {
                const double d = 0.25 * i;
                sc[k][i] = cv3(0.5 + (v == 0 ? d : 0.0), 0.1 + (v == 1 ? 0.1 * d : 0.0), 1.0 + (v == 2 ? d : 0.0));
            }
            sz[k][1] = sz[k][0];
        }
        base_params(&p, MTT_ASSOC_LM_IHPDA);
        run_scene(&ta, &p, 1, 0);
        run_scene(&tb, &p, 1, 1);
        assert_same("reversed", 0.0);
    }
}

static void test_split_takes_a_covariance(void)
{
#if MTT_WITH_SPLIT
    /* split takes a covariance per detection (ALGORITHMS.md §3.1, §14.3;
     * its arithmetic: test_split.c, test_split_tracker.c): a seeded track
     * moves towards a detection with meas_sigma's R, less with an own R 100
     * times it */
    mtt_params p;
    const mtt_meas z = det(6.0, 0.0);
    const mtt_meas_cov big = cv3(100.0, 0.0, 100.0);
    const mtt_real x0[4] = {0, 0, 0, 0};
    const mtt_real P0[16] = {4, 0, 0, 0, 0, 4, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    mtt_track_view va, vb;
    base_params(&p, MTT_ASSOC_LM_IHPDA);
    p.motion = MTT_MOTION_IMM;
    p.split = 1;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&ta, &p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&tb, &p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&ta, x0, P0, NULL));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&tb, x0, P0, NULL));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_cov(&ta, MTT_R(1.0), &z, NULL, 1u));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_cov(&tb, MTT_R(1.0), &z, &big, 1u));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&ta, 0, &va));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&tb, 0, &vb));
    TEST_ASSERT_TRUE(va.x[0] > MTT_R(1.0));
    TEST_ASSERT_TRUE(vb.x[0] > MTT_R(0.0) && vb.x[0] < MTT_R(0.5) * va.x[0]);
#else
    TEST_IGNORE_MESSAGE("no split models in this build");
#endif
}

#else /* MTT_WITH_MEAS_COV 0 */

static void test_build_without_it_refuses_a_covariance(void)
{
    /* raw values: the test also runs in the fixed-point build */
    mtt_params p;
    mtt_meas z;
    mtt_meas_cov c, none;
    mtt_stats st;
    memset(&z, 0, sizeof z);
    memset(&none, 0, sizeof none);
    c = none;
    c.r_xx = c.r_yy = (mtt_real)4;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.association = MTT_ASSOC_IPDA;
    p.motion = MTT_MOTION_CV;
    {
        const double dens = 1e-4, q = 0.05; /* the fixed build needs both given */
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_set(&p, "clutter_density", &dens, 1));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_set(&p, "process_psd", &q, 1));
    }
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&ta, &p));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_UNSUPPORTED, mtt_tracker_step_cov(&ta, (mtt_real)0, &z, &c, 1u));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&ta, &st));
    TEST_ASSERT_EQUAL_UINT32(0u, st.total.frames); /* nothing changed */
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_cov(&ta, (mtt_real)0, &z, &none, 1u));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_cov(&ta, (mtt_real)65536, &z, NULL, 1u));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&ta, &st));
    TEST_ASSERT_EQUAL_UINT32(2u, st.total.frames);
}

#endif

int main(void)
{
    UNITY_BEGIN();
#if MTT_WITH_MEAS_COV
    RUN_TEST(test_gate_and_likelihood_use_the_detections_r);
    RUN_TEST(test_pda_update_is_the_mixture_of_the_detections_updates);
    RUN_TEST(test_birth_takes_both_detections_r);
    RUN_TEST(test_bad_covariance_is_counted);
    RUN_TEST(test_explicit_default_r_gives_the_same_tracks_in_every_mode);
    RUN_TEST(test_any_order_gives_the_same_identities);
    RUN_TEST(test_split_takes_a_covariance);
#else
    RUN_TEST(test_build_without_it_refuses_a_covariance);
#endif
    return UNITY_END();
}
