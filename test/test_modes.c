/* SPDX-License-Identifier: BSD-3-Clause */
/* test_modes.c - every association mode (ALGORITHMS.md §15.1) end to end: invariance
 * to the order of the measurements and of the (seeded) tracks, and a
 * two-target crossing started from measurements alone. */
#include <math.h>
#include <string.h>

#include "mtt/mtt.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

/* 1 when mode m is built into this library (the baselines need
 * MTT_WITH_BASELINES); the tests below run every built mode. */
static int built(int m)
{
    mtt_params p;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.association = (mtt_assoc)m;
    return mtt_params_check(&p, NULL) == MTT_OK;
}

#ifdef MTT_REAL_DOUBLE
#define STATE_TOL 1e-9
#else
#define STATE_TOL 1e-4
#endif

#define FRAMES 30
#define MAXM 40

static mtt_tracker ta, tb;

static uint32_t rng;
static double unit(void)
{
    rng = rng * 1664525u + 1013904223u;
    return ((double)(rng >> 8) + 0.5) / 16777216.0;
}
static double gauss(void)
{
    return sqrt(-2.0 * log(unit())) * cos(6.283185307179586 * unit());
}

/* Scene: 4 targets (two crossing at frame 15), clutter, PD 0.9. */
typedef struct {
    int n[FRAMES];
    mtt_meas z[FRAMES][MAXM];
} scene;
static scene sc;

static const double X0[4][4] = {
    {100, 100, 10, 10}, {100, 400, 10, -10}, {600, 100, -5, 0}, {600, 500, 0, -6}};

static void make_scene(int clutter, double pd)
{
    int k, i;
    rng = 2024u;
    for (k = 0; k < FRAMES; ++k) {
        int n = 0;
        for (i = 0; i < 4; ++i) {
            if (unit() < pd) {
                sc.z[k][n].x = (mtt_real)(X0[i][0] + X0[i][2] * k + gauss());
                sc.z[k][n].y = (mtt_real)(X0[i][1] + X0[i][3] * k + gauss());
                sc.z[k][n].amplitude = (mtt_real)(3.0 + unit());
                sc.z[k][n].has_amplitude = 1;
                ++n;
            }
        }
        for (i = 0; i < clutter; ++i) {
            sc.z[k][n].x = (mtt_real)(800.0 * unit());
            sc.z[k][n].y = (mtt_real)(600.0 * unit());
            sc.z[k][n].amplitude = (mtt_real)(unit() * 2.0);
            sc.z[k][n].has_amplitude = 1;
            ++n;
        }
        sc.n[k] = n;
    }
}

static void params(mtt_params *p, mtt_assoc mode)
{
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(p));
    p->association = mode;
    p->vmax = MTT_R(20.0);
    p->snr_rho = MTT_R(2.0);
}

static void seed_tracks(mtt_tracker *t, int reverse)
{
    int q;
    for (q = 0; q < 4; ++q) {
        const int i = reverse ? 3 - q : q;
        mtt_real x[4], P[16];
        int r;
        for (r = 0; r < 4; ++r) {
            x[r] = (mtt_real)X0[i][r];
        }
        memset(P, 0, sizeof P);
        P[0] = P[5] = MTT_R(2.0);
        P[10] = P[15] = MTT_R(4.0);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(t, x, P, NULL));
    }
}

/* Run the scene; perm 1 permutes every frame's measurements, 2 reverses
 * them; reverse: the seeded tracks in reverse order, -1: none seeded. */
static void run(mtt_tracker *t, mtt_assoc mode, int perm, int reverse)
{
    mtt_params p;
    int k;
    params(&p, mode);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(t, &p));
    if (reverse >= 0) {
        seed_tracks(t, reverse);
    }
    rng = 99u;
    for (k = 0; k < FRAMES; ++k) {
        mtt_meas z[MAXM];
        int n = sc.n[k], i;
        memcpy(z, sc.z[k], sizeof z);
        if (perm == 2) {
            for (i = 0; i < n; ++i) {
                z[i] = sc.z[k][n - 1 - i];
            }
        } else if (perm) {
            for (i = n - 1; i > 0; --i) { /* Fisher-Yates, fixed seed */
                int j = (int)(unit() * (i + 1));
                mtt_meas tmp = z[i];
                z[i] = z[j];
                z[j] = tmp;
            }
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(t, (mtt_real)k, z, (size_t)n));
    }
}

static int close_state(const mtt_track_view *a, const mtt_track_view *b)
{
    int r;
    for (r = 0; r < 4; ++r) {
        double va = (double)a->x[r], vb = (double)b->x[r];
        if (fabs(va - vb) > STATE_TOL * (fabs(va) > 1.0 ? fabs(va) : 1.0)) {
            return 0;
        }
    }
    return fabs((double)a->existence - (double)b->existence) <= STATE_TOL;
}

/* Same set of track states (identities may differ). */
static void assert_same_tracks(const char *name)
{
    size_t na, nb, i, j;
    int matched[MTT_MAX_TRACKS];
    mtt_stats st;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&ta, &na));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&tb, &nb));
    TEST_ASSERT_EQUAL_MESSAGE(na, nb, name);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&ta, &st));
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(0u, st.total.births_dropped, name);
    memset(matched, 0, sizeof matched);
    for (i = 0; i < na; ++i) {
        mtt_track_view va;
        int found = 0;
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&ta, i, &va));
        for (j = 0; j < nb && !found; ++j) {
            mtt_track_view vb;
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&tb, j, &vb));
            if (!matched[j] && close_state(&va, &vb) && va.confirmed == vb.confirmed) {
                matched[j] = 1;
                found = 1;
            }
        }
        TEST_ASSERT_TRUE_MESSAGE(found, name);
    }
}

/* Tracks started from the measurements alone: any order of a frame's
 * detections gives the same tracks, bit for bit, with the same identities
 * in the same slots (measure.c's canonical order, ALGORITHMS.md §15). */
static void assert_same_identities(const char *name)
{
    size_t na, nb, i;
    mtt_stats st;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&ta, &na));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&tb, &nb));
    TEST_ASSERT_EQUAL_MESSAGE(na, nb, name);
    TEST_ASSERT_TRUE_MESSAGE(na >= 4u, name);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&ta, &st));
    TEST_ASSERT_TRUE_MESSAGE(st.total.births > 4u, name); /* more births than targets: clutter ones too */
    for (i = 0; i < na; ++i) {
        mtt_track_view va, vb;
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&ta, i, &va));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&tb, i, &vb));
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(va.id, vb.id, name);
        TEST_ASSERT_EQUAL_INT_MESSAGE(va.confirmed, vb.confirmed, name);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(va.age, vb.age, name);
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(va.x, vb.x, sizeof va.x, name);
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(va.P, vb.P, sizeof va.P, name);
        TEST_ASSERT_EQUAL_MEMORY_MESSAGE(&va.existence, &vb.existence, sizeof va.existence, name);
    }
}

static void test_order_invariance_all_modes(void)
{
    int mode;
    make_scene(6, 0.9);
    for (mode = 0; mode < (int)MTT_ASSOC_COUNT; ++mode) {
        const char *name = NULL;
        if (!built(mode)) {
            continue;
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_assoc_name((mtt_assoc)mode, &name));
        run(&ta, (mtt_assoc)mode, 0, 0);
        run(&tb, (mtt_assoc)mode, 1, 0); /* measurements permuted */
        assert_same_tracks(name);
        run(&tb, (mtt_assoc)mode, 1, 1); /* and seeded tracks in reverse order */
        assert_same_tracks(name);
        /* from the measurements alone: the same identities too */
        run(&ta, (mtt_assoc)mode, 0, -1);
        run(&tb, (mtt_assoc)mode, 1, -1); /* permuted */
        assert_same_identities(name);
        run(&tb, (mtt_assoc)mode, 2, -1); /* reversed */
        assert_same_identities(name);
    }
}

/* Two targets crossing, started from measurements only: both confirmed. */
static void test_crossing_every_mode_confirms_both(void)
{
    int mode;
    for (mode = 0; mode < (int)MTT_ASSOC_COUNT; ++mode) {
        mtt_params p;
        const char *name = NULL;
        int k, i, found[2] = {0, 0};
        size_t n, q;
        if (!built(mode)) {
            continue;
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_assoc_name((mtt_assoc)mode, &name));
        params(&p, (mtt_assoc)mode);
        p.clutter_density = MTT_R(1e-5);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&ta, &p));
        rng = 7u;
        for (k = 0; k < FRAMES; ++k) {
            mtt_meas z[2];
            for (i = 0; i < 2; ++i) {
                /* (0,0) -> (+10,+5)/frame and (0,150) -> (+10,-5)/frame: cross at k = 15 */
                z[i].x = (mtt_real)(10.0 * k + 0.5 * gauss());
                z[i].y = (mtt_real)((i == 0 ? 5.0 * k : 150.0 - 5.0 * k) + 0.5 * gauss());
                z[i].amplitude = MTT_R(5.0);
                z[i].has_amplitude = 1;
            }
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&ta, (mtt_real)k, z, 2));
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&ta, &n));
        for (q = 0; q < n; ++q) {
            mtt_track_view v;
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&ta, q, &v));
            for (i = 0; i < 2; ++i) {
                const double ex = 10.0 * (FRAMES - 1), ey = (i == 0) ? 5.0 * (FRAMES - 1)
                                                                      : 150.0 - 5.0 * (FRAMES - 1);
                if (v.confirmed && fabs((double)v.x[0] - ex) < 5.0 && fabs((double)v.x[1] - ey) < 5.0) {
                    found[i] = 1;
                }
            }
        }
        TEST_ASSERT_TRUE_MESSAGE(found[0] && found[1], name);
    }
}

/* The four core modes are always built; the baselines exactly when
 * MTT_WITH_BASELINES is 1, and an unbuilt mode is refused by
 * mtt_params_check and mtt_tracker_init. */
static void test_built_modes(void)
{
    static mtt_tracker t;
    const mtt_assoc core[4] = {MTT_ASSOC_LM_IHPDA, MTT_ASSOC_IHPDA, MTT_ASSOC_LM_IPDA, MTT_ASSOC_IPDA};
    int m, k, n_built = 0;
    for (m = 0; m < (int)MTT_ASSOC_COUNT; ++m) {
        mtt_params p;
        const char *field = NULL;
        int is_core = 0;
        for (k = 0; k < 4; ++k) {
            is_core |= (core[k] == (mtt_assoc)m);
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
        p.association = (mtt_assoc)m;
        if (is_core || MTT_WITH_BASELINES) {
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_check(&p, &field));
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&t, &p));
            ++n_built;
        } else {
            /* lm-ipda-all is not even a value without the baselines */
            const mtt_status want = m < (int)MTT_ASSOC_LM_IPDA_ALL ? MTT_ERR_UNSUPPORTED : MTT_ERR_PARAM;
            TEST_ASSERT_EQUAL_INT(want, mtt_params_check(&p, &field));
            TEST_ASSERT_EQUAL_STRING("association", field);
            TEST_ASSERT_EQUAL_INT(want, mtt_tracker_init(&t, &p));
        }
    }
    TEST_ASSERT_EQUAL_INT(MTT_WITH_BASELINES ? (int)MTT_ASSOC_COUNT : 4, n_built);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_built_modes);
    RUN_TEST(test_order_invariance_all_modes);
    RUN_TEST(test_crossing_every_mode_confirms_both);
    return UNITY_END();
}
