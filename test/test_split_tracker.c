/* SPDX-License-Identifier: BSD-3-Clause */
/* test_split_tracker.c - split targets through mtt_tracker_step
 * (ALGORITHMS.md §14.3, src/split/split_track.c): a hand-built split (one seeded
 * track, two diverging measurement streams) spawns exactly one child that
 * records its parent; a target that does not split never spawns; the
 * decoupling test at its threshold (d² = 9.2103 just above and just below),
 * on P_11 + P_22 (the default) and on S_1 + S_2 (split_decouple_r);
 * a detection in a confirmed neighbour's gate starts no split; the
 * settings that refuse split. */
#include <math.h>
#include <string.h>

#include "mtt/mtt.h"
#include "sim.h"
#include "tv_assert.h"
#include "tv_fixture.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

static mtt_tracker trk;

#if MTT_WITH_SPLIT

#define FRAMES 30
#define SPLIT_AT 10

/* One seeded target at (0, 0) moving at (10, 0) per frame, sigma 1 in
 * the units of the test, PD 1; from frame SPLIT_AT a child leaves it at
 * (10, vy_child) per frame; a few clutter points far from both. */
static void split_params(mtt_params *p)
{
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(p));
    p->association = MTT_ASSOC_LM_IHPDA;
    p->motion = MTT_MOTION_IMM;
    p->split = 1;
    p->split_dv = MTT_R(4.0);
    p->process_psd = MTT_R(0.05);
    p->imm_psd[0] = MTT_R(0.05);
    p->imm_psd[1] = MTT_R(0.5);
    p->clutter_density = MTT_R(1e-4);
    p->pd = MTT_R(0.99);
    p->existence_init = MTT_R(0.02);
    p->confirm_threshold = MTT_R(0.97);
    p->vmax = MTT_R(20.0);
}

/* own_r: every detection carries its own covariance r_xx = r_yy = own_r
 * (0: none, mtt_tracker_step; 1 is meas_sigma's R: ALGORITHMS.md §3.1). */
static double own_r = 0.0;

/* One frame: mtt_tracker_step, or with own_r the same detections with
 * their own covariance through mtt_tracker_step_cov. */
static void step_own(mtt_real time, const mtt_meas *z, size_t m)
{
#if MTT_WITH_MEAS_COV
    if (own_r > 0.0) {
        mtt_meas_cov c[8];
        size_t i;
        TEST_ASSERT_TRUE(m <= 8u);
        for (i = 0; i < m; ++i) {
            c[i].r_xx = (mtt_real)own_r;
            c[i].r_xy = MTT_R(0.0);
            c[i].r_yy = (mtt_real)own_r;
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step_cov(&trk, time, z, c, m));
        return;
    }
#endif
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, time, z, m));
}

/* Runs the scene; returns the number of tracks that split off, and the
 * parent id and the number of confirmed tracks at the end. */
static int run_scene(double vy_child, uint32_t *parent_of_child, int *n_confirmed, double *child_dy)
{
    mtt_params p;
    const mtt_real x0[4] = {0, 0, 10, 0};
    const mtt_real P0[16] = {4, 0, 0, 0, 0, 4, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    sim_rng r = {777u};
    mtt_stats st;
    size_t n, i;
    uint32_t seeded;
    int k, children = 0;
    split_params(&p);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x0, P0, &seeded));
    *parent_of_child = MTT_NO_PARENT;
    *child_dy = 0.0;
    for (k = 0; k < FRAMES; ++k) {
        mtt_meas z[8];
        int m = 0, c;
        z[m++] = sim_meas((mtt_real)(10.0 * k + sim_gauss(&r)), (mtt_real)sim_gauss(&r), MTT_R(0.0), 0);
        if (k > SPLIT_AT && vy_child != 0.0) {
            z[m++] = sim_meas((mtt_real)(10.0 * k + sim_gauss(&r)),
                              (mtt_real)(vy_child * (k - SPLIT_AT) + sim_gauss(&r)), MTT_R(0.0), 0);
        }
        for (c = 0; c < 3; ++c) { /* clutter 200 or more away from both */
            z[m++] = sim_meas((mtt_real)(10.0 * k - 200.0 + 400.0 * sim_unif(&r)),
                              (mtt_real)(-400.0 - 200.0 * sim_unif(&r)), MTT_R(0.0), 0);
        }
        step_own((mtt_real)k, z, (size_t)m);
    }
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&trk, &st));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&trk, &n));
    *n_confirmed = 0;
    for (i = 0; i < n; ++i) {
        mtt_track_view v;
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, i, &v));
        TEST_ASSERT_EQUAL_UINT8(1, v.split);
        TEST_ASSERT_TRUE(v.p_split >= MTT_R(0.0) && v.p_split <= MTT_R(1.0));
        *n_confirmed += v.confirmed;
        if (v.parent != MTT_NO_PARENT) {
            ++children;
            *parent_of_child = v.parent;
            /* the child is on the child's stream: y = vy (FRAMES - 1 - SPLIT_AT) */
            *child_dy = (double)v.x[1] - vy_child * (FRAMES - 1 - SPLIT_AT);
        } else {
            TEST_ASSERT_EQUAL_UINT32(seeded, v.id);
            TEST_ASSERT_TRUE(fabs((double)v.x[1]) < 5.0); /* the parent stays on the parent */
        }
    }
    TEST_ASSERT_EQUAL_UINT32((uint32_t)children, st.total.splits);
    TEST_ASSERT_EQUAL_UINT32(0, st.total.split_dropped);
    return children;
}

static void test_a_hand_built_split_spawns_one_child_with_its_parent(void)
{
    uint32_t parent;
    int conf;
    double dy;
    TEST_ASSERT_EQUAL_INT(1, run_scene(4.0, &parent, &conf, &dy));
    TEST_ASSERT_EQUAL_UINT32(0, parent); /* the seeded track's id */
    TEST_ASSERT_EQUAL_INT(2, conf);      /* parent and child, nothing else */
    TEST_ASSERT_TRUE(fabs(dy) < 5.0);
}

static void test_a_target_that_does_not_split_never_spawns(void)
{
    uint32_t parent;
    int conf;
    double dy;
    TEST_ASSERT_EQUAL_INT(0, run_scene(0.0, &parent, &conf, &dy));
    TEST_ASSERT_EQUAL_UINT32(MTT_NO_PARENT, parent);
    TEST_ASSERT_EQUAL_INT(1, conf);
}

/* A track in the "split" mode (μ_6 = 1) with the halves dx apart, P_tt =
 * diag(4, 4, 1, 1), no cross covariance, equal velocities, then one frame
 * (dt = 1) without measurements: the stacked estimate is the prediction,
 * S_t = 4 + 1 + q/3 per axis (+ r = 1 with split_decouple_r, [S3] eq. 27),
 * d² = dx² / (2 S).  PD 0.5 and p62 = 0.001 keep μ_6 about 0.998 (>= 0.9).
 * Returns the tracks that split off. */
static mtt_real child_confirm = MTT_R(0.97); /* split_confirm of spawn_at */
static int known_speed = 0;                  /* split_known_speed of spawn_at */

static uint32_t spawn_at(double factor, int with_r)
{
    mtt_params p;
    const mtt_real x0[4] = {0, 0, 1, 0};
    const mtt_real P0[16] = {4, 0, 0, 0, 0, 4, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const double q = 0.05, S = 4.0 + 1.0 + q / 3.0 + (with_r ? 1.0 : 0.0);
    const double dx = sqrt(9.2103403719761836 * 2.0 * S) * factor;
    mtt_stats st;
    mtt_split_slot *sl;
    int a;
    split_params(&p);
    p.pd = MTT_R(0.5);
    p.split_p62 = MTT_R(0.001);
    p.split_decouple_r = with_r;
    p.split_confirm = child_confirm;
    p.split_known_speed = known_speed;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x0, P0, NULL));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(0.0), NULL, 0));
    TEST_ASSERT_EQUAL_UINT8(MTT_SPLIT_NONE, TV_SPLIT_SLOT(&trk, 0));
    sl = &TV_SPLIT(&trk, 0);
    memset(sl, 0, sizeof *sl);
    sl->used = 1;
    sl->mu[1] = MTT_R(1.0);
    for (a = 0; a < 4; ++a) {
        sl->xs[1][a] = x0[a];
        sl->xs[1][4 + a] = x0[a];
        sl->Ps[1][a][a] = P0[5 * a];
        sl->Ps[1][4 + a][4 + a] = P0[5 * a];
    }
    sl->xs[1][4] = (mtt_real)dx; /* the child half dx to the right */
    TV_SPLIT_SLOT(&trk, 0) = 0;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(1.0), NULL, 0));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_stats(&trk, &st));
    return st.last.splits;
}

static void test_decoupling_threshold_edge(void)
{
    mtt_track_view v;
    int with_r;
    for (with_r = 0; with_r <= 1; ++with_r) {
        TEST_ASSERT_EQUAL_UINT32(1, spawn_at(1.0001, with_r)); /* d² = 9.2121 >= 9.2103: two tracks */
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 1, &v));
        TEST_ASSERT_EQUAL_UINT32(0, v.parent);                 /* the child of track 0 ... */
        TEST_ASSERT_EQUAL_UINT32(1, v.id);                     /* ... with the next identity */
        TEST_ASSERT_EQUAL_UINT32(0, spawn_at(0.9999, with_r)); /* d² = 9.2085: still one */
        TEST_ASSERT_EQUAL_UINT8(0, TV_SPLIT_SLOT(&trk, 0));    /* and still in the split mode */
    }
    /* The halves apart by the estimate test's edge (S = 5.017 per axis)
     * are not yet apart by [S3]'s (S = 6.017: d² = 7.68). */
    TEST_ASSERT_EQUAL_UINT32(1, spawn_at(1.0001, 0));
    TEST_ASSERT_EQUAL_UINT32(0, spawn_at(sqrt(5.0 + 0.05 / 3.0) / sqrt(6.0 + 0.05 / 3.0) * 1.0001, 1));
}

/* The child's existence at decoupling is P_parent μ_6, about 0.959 in
 * spawn_at (the parent's existence falls to 0.961 on the empty frame):
 * confirmed at once with split_confirm 0.95, tentative with 0.97. */
static void test_child_confirmed_by_split_confirm(void)
{
    mtt_track_view parent, child;
    const mtt_real lims[2] = {MTT_R(0.95), MTT_R(0.97)};
    int k;
    for (k = 0; k < 2; ++k) {
        child_confirm = lims[k];
        TEST_ASSERT_EQUAL_UINT32(1, spawn_at(1.5, 0));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 0, &parent));
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 1, &child));
        TEST_ASSERT_TRUE(child.existence > MTT_R(0.95) && child.existence < MTT_R(0.97));
        TEST_ASSERT_EQUAL_UINT8(1, parent.confirmed);
        TEST_ASSERT_EQUAL_UINT8(k == 0 ? 1 : 0, child.confirmed);
    }
    child_confirm = MTT_R(0.97);
}

/* split_known_speed's provisional child: a split-off track whose existence
 * is below 0.6 after the update of one of its first 3 scans is deleted.
 * The child of spawn_at (age 0) is given existence 0.62; the next frame is
 * empty (PD 0.5), which takes it to about 0.45 (> terminate_threshold):
 * deleted with the rule at age 1, kept without it and at age 4. */
static void test_provisional_child_deleted(void)
{
    mtt_track_view v;
    size_t n;
    int rule, old;
    for (rule = 0; rule <= 1; ++rule) {
        for (old = 0; old <= 1; ++old) {
            known_speed = rule;
            TEST_ASSERT_EQUAL_UINT32(1, spawn_at(1.5, 0));
            TEST_ASSERT_EQUAL_UINT32(0, TV_TRACK(&trk, 1)->parent);
            TEST_ASSERT_EQUAL_UINT32(0, TV_TRACK(&trk, 1)->age);
            TV_TRACK(&trk, 1)->existence = MTT_R(0.62);
            if (old) {
                TV_TRACK(&trk, 1)->age = 3u; /* 4 after the next prediction: past the first 3 scans */
            }
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, MTT_R(2.0), NULL, 0));
            TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_count(&trk, &n));
            if (rule && !old) {
                TEST_ASSERT_EQUAL_UINT((unsigned)1, (unsigned)n); /* the parent only */
            } else {
                TEST_ASSERT_EQUAL_UINT((unsigned)2, (unsigned)n);
                TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 1, &v));
                TEST_ASSERT_EQUAL_UINT32(0, v.parent);
                TEST_ASSERT_TRUE(v.existence < MTT_R(0.6) && v.existence > MTT_R(0.3));
            }
        }
    }
    known_speed = 0;
}

/* split_known_speed's late look: the seeded target of split_params
 * (split_dv 4) for 10 frames, then one frame with a second detection 15
 * across its course.  Model 5's own gate is about sqrt(9.21 S_y) with S_y =
 * P̄_yy + 1 + split_dv² / 2, under 12 here (the test asserts it from the
 * track's P̄), so the detection is outside it: without the rule model 5
 * has one measurement and P(split) is 0; with it the gate widened by
 * 3.5 split_dv reaches it and P(split) is positive. */
static double late_look(int rule, double *gate)
{
    mtt_params p;
    mtt_track_view v;
    const mtt_real x0[4] = {0, 0, 10, 0};
    const mtt_real P0[16] = {4, 0, 0, 0, 0, 4, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    sim_rng r = {4242u};
    int k;
    split_params(&p);
    p.split_known_speed = rule;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x0, P0, NULL));
    for (k = 0; k <= 10; ++k) {
        mtt_meas z[2];
        int m = 0;
        z[m++] = sim_meas((mtt_real)(10.0 * k + 0.5 * sim_gauss(&r)), (mtt_real)(0.5 * sim_gauss(&r)), MTT_R(0.0), 0);
        if (k == 10) {
            z[m++] = sim_meas(MTT_R(100.0), MTT_R(15.0), MTT_R(0.0), 0);
        }
        step_own((mtt_real)k, z, (size_t)m);
    }
    *gate = sqrt(9.2103403719761836 * ((double)TV_PP(&trk, 0)[1][1] + 1.0 + 16.0 / 2.0));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 0, &v));
    TEST_ASSERT_EQUAL_UINT32(0, v.id);
    return (double)v.p_split;
}

#if MTT_WITH_MEAS_COV
/* Every detection with its own covariance equal to meas_sigma's R: the
 * split modes take the mixture of single-detection updates (§3.1), equal
 * to the shared-R forms, so the split, the child and P(split) are those of
 * the plain run, through models 5 and 6, the decoupling and the late look. */
static void test_own_r_equal_to_meas_sigma_splits_the_same(void)
{
    uint32_t parent, parent_own;
    int conf, conf_own;
    double dy, dy_own, gate, p1, p1_own;
    TEST_ASSERT_EQUAL_INT(1, run_scene(4.0, &parent, &conf, &dy));
    p1 = late_look(1, &gate);
    own_r = 1.0;
    TEST_ASSERT_EQUAL_INT(1, run_scene(4.0, &parent_own, &conf_own, &dy_own));
    p1_own = late_look(1, &gate);
    own_r = 0.0;
    TEST_ASSERT_EQUAL_UINT32(parent, parent_own);
    TEST_ASSERT_EQUAL_INT(conf, conf_own);
    TEST_ASSERT_TRUE(fabs(dy - dy_own) < 1e-3);
    TEST_ASSERT_TRUE(p1 > 1e-3);
    TEST_ASSERT_TRUE(fabs(p1 - p1_own) <= 1e-3 * p1);
}

/* The late look's scene (late_look, rule 1) with an own R 25 times
 * meas_sigma's on every detection: the split modes weigh the far
 * detection on its own, wider S_j, where it is no longer far out in the
 * tails, and P(split) rises (0.09 to 0.40 in the double build). */
static void test_own_r_moves_the_split_probability(void)
{
    double gate, p1, p1_own;
    p1 = late_look(1, &gate);
    own_r = 25.0;
    p1_own = late_look(1, &gate);
    own_r = 0.0;
    TEST_ASSERT_TRUE(p1_own >= 0.0 && p1_own <= 1.0);
    TEST_ASSERT_TRUE(p1 > 0.05 && p1 < 0.15);
    TEST_ASSERT_TRUE(p1_own > 3.0 * p1);
}
#endif

static void test_late_look_reaches_a_far_child(void)
{
    double gate, p0, p1;
    p0 = late_look(0, &gate);
    TEST_ASSERT_TRUE(gate < 12.0); /* 15 is outside model 5's own gate */
    p1 = late_look(1, &gate);
    TEST_ASSERT_EQUAL_DOUBLE(0.0, p0);
    TEST_ASSERT_TRUE(p1 > 1e-3);
}

/* One measurement, one target: a detection in the gate of another confirmed
 * track is not the second half of this track's split.  The seeded target
 * of split_params (split_dv 4) and a confirmed neighbour 8 above it on a
 * parallel course, each detected every frame, for 10 frames; then a frame
 * with a third detection 6 across the parent's course: inside model 5's
 * gate (about 9, late_look) and outside the parent's own (about 3), and
 * (mode 0) 2 from the neighbour, in its gate, which reports its own
 * detection instead.  Mode 0: held by the neighbour, so model 5 of the
 * parent has one measurement and P(split) is 0.  Controls: the detection
 * mirrored to -6 (mode 1, no track holds it) and the neighbour made
 * tentative before the last frame (mode 2, a tentative track holds
 * nothing) start the split: P(split) > 1e-3.  Returns the parent's
 * P(split). */
static double held_by_neighbour(int mode)
{
    mtt_params p;
    mtt_track_view v;
    const mtt_real x0[4] = {0, 0, 10, 0}, x1[4] = {0, 8, 10, 0};
    const mtt_real P0[16] = {4, 0, 0, 0, 0, 4, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const double extra = (mode == 1) ? -6.0 : 6.0;
    sim_rng r = {4242u};
    uint16_t k;
    int f, in_gate = 0;
    split_params(&p);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_init(&trk, &p));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x0, P0, NULL));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_add_track(&trk, x1, P0, NULL));
    for (f = 0; f <= 10; ++f) {
        mtt_meas z[3];
        int m = 0;
        z[m++] = sim_meas((mtt_real)(10.0 * f + 0.5 * sim_gauss(&r)), (mtt_real)(0.5 * sim_gauss(&r)), MTT_R(0.0), 0);
        z[m++] = sim_meas((mtt_real)(10.0 * f + 0.5 * sim_gauss(&r)), (mtt_real)(8.0 + 0.5 * sim_gauss(&r)), MTT_R(0.0), 0);
        if (f == 10) {
            z[m++] = sim_meas(MTT_R(100.0), (mtt_real)extra, MTT_R(0.0), 0);
            if (mode == 2) {
                TV_TRACK(&trk, 1)->confirmed = 0;
            }
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_step(&trk, (mtt_real)f, z, (size_t)m));
    }
    for (k = 0; k < TV_PAIR_COUNT(&trk, 1); ++k) {
        in_gate |= TV_MEAS_SRC(&trk, TV_PAIR_MEAS(&trk, TV_PAIR_FIRST(&trk, 1) + k)) == 2u; /* input 2 */
    }
    TEST_ASSERT_EQUAL_INT(mode != 1, in_gate);               /* +6 is in the neighbour's gate, -6 not */
    TEST_ASSERT_EQUAL_INT32(1, TV_TRACK(&trk, 1)->meas);    /* the neighbour reports its own detection */
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_tracker_track(&trk, 0, &v));
    TEST_ASSERT_EQUAL_UINT32(0, v.id);
    return (double)v.p_split;
}

static void test_a_confirmed_neighbours_detection_starts_no_split(void)
{
    TEST_ASSERT_EQUAL_DOUBLE(0.0, held_by_neighbour(0));
    TEST_ASSERT_EQUAL_UINT8(MTT_SPLIT_NONE, TV_SPLIT_SLOT(&trk, 0));
    TEST_ASSERT_TRUE(held_by_neighbour(1) > 1e-3);
    TEST_ASSERT_TRUE(held_by_neighbour(2) > 1e-3);
}

static void test_split_needs_imm_with_a_cv_model(void)
{
    mtt_params p;
    const char *bad = NULL;
    split_params(&p);
    p.motion = MTT_MOTION_CV;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_UNSUPPORTED, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("split", bad);
    split_params(&p);
    p.imm_model[0] = MTT_MODEL_CA;
    p.imm_model[1] = MTT_MODEL_CA;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_UNSUPPORTED, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("split", bad);
    split_params(&p);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_check(&p, &bad));
}

#else

static void test_split_is_refused_without_mtt_with_split(void)
{
    mtt_params p;
    const char *bad = NULL;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.split = 1;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_UNSUPPORTED, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("split", bad);
    (void)trk;
}

#endif

int main(void)
{
    UNITY_BEGIN();
#if MTT_WITH_SPLIT
    RUN_TEST(test_a_hand_built_split_spawns_one_child_with_its_parent);
    RUN_TEST(test_a_target_that_does_not_split_never_spawns);
    RUN_TEST(test_decoupling_threshold_edge);
    RUN_TEST(test_child_confirmed_by_split_confirm);
    RUN_TEST(test_provisional_child_deleted);
    RUN_TEST(test_late_look_reaches_a_far_child);
#if MTT_WITH_MEAS_COV
    RUN_TEST(test_own_r_equal_to_meas_sigma_splits_the_same);
    RUN_TEST(test_own_r_moves_the_split_probability);
#endif
    RUN_TEST(test_a_confirmed_neighbours_detection_starts_no_split);
    RUN_TEST(test_split_needs_imm_with_a_cv_model);
#else
    RUN_TEST(test_split_is_refused_without_mtt_with_split);
#endif
    return UNITY_END();
}
