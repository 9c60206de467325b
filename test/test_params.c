/* SPDX-License-Identifier: BSD-3-Clause */
/* test_params.c - defaults (docs/FORMATS.md table), validation naming the first
 * bad field, association names, unsupported modes. */
#include <string.h>

#include "mtt_internal.h"
#include "core/params_table.h" /* MTT_ASSOC_ROWS */
#include "tv_assert.h"
#include "tv_fixture.h"
#include "unity.h"

static mtt_tracker trk;

void setUp(void) {}
void tearDown(void) {}

static void test_defaults_match_formats_table(void)
{
    mtt_params p;
    const char *bad = "x";
    memset(&p, 0xa5, sizeof p);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    TEST_ASSERT_EQUAL_INT(MTT_ASSOC_LM_IHPDA, p.association); /* lm-ihpda */
    TV_ASSERT_REAL(0.0, p.process_psd); /* not given: from max_accel, else 5 (ALGORITHMS.md §2.2) */
    TV_ASSERT_REAL(0.0, p.max_accel);
    TEST_ASSERT_EQUAL_INT(MTT_MOTION_AUTO, p.motion);
    TV_ASSERT_REAL(1.0, p.meas_sigma[0]);
    TV_ASSERT_REAL(1.0, p.meas_sigma[1]);
    TV_ASSERT_REAL(0.9, p.pd);
    TV_ASSERT_REAL(0.999, p.pg);
    TV_ASSERT_REAL(0.0, p.clutter_density);
    TV_ASSERT_REAL(0.0, p.snr_rho);
    TV_ASSERT_REAL(0.98, p.markov_p11);
    TV_ASSERT_REAL(0.0, p.markov_p21);
    TV_ASSERT_REAL(0.1, p.existence_init);
    TV_ASSERT_REAL(0.995, p.confirm_threshold);
    TV_ASSERT_REAL(0.01, p.terminate_threshold);
    TV_ASSERT_REAL(1.0, p.merge_threshold);
    TEST_ASSERT_TRUE(p.initiate != 0);
    TV_ASSERT_REAL(60.0, p.vmax);
    TEST_ASSERT_EQUAL_INT(MTT_INIT_GATE_VMAX, p.init_gate);
    /* [S2] coefficients (ALGORITHMS.md §12.2) */
    TV_ASSERT_REAL(-0.0007, p.intensity_f1[0]);
    TV_ASSERT_REAL(0.5072, p.intensity_f1[1]);
    TV_ASSERT_REAL(39.70, p.intensity_f1[2]);
    TV_ASSERT_REAL(-0.0001, p.intensity_f2[0]);
    TV_ASSERT_REAL(0.2097, p.intensity_f2[1]);
    TV_ASSERT_REAL(57.25, p.intensity_f2[2]);
    TV_ASSERT_REAL(150.0, p.intensity_blend[0]);
    TV_ASSERT_REAL(250.0, p.intensity_blend[1]);
    TV_ASSERT_REAL(0.0, p.jpda_bias); /* "from the spec": 0 selects lambda(1-PD PG)/PD */
    TV_ASSERT_REAL(0.0, p.jpda_star_threshold);
    TV_ASSERT_REAL(0.0, p.nnjpda_threshold);
    TV_ASSERT_REAL(9.0, p.adaptive_jpda_distance);
    TV_ASSERT_REAL(3.0, p.adaptive_jpda_shrink);
    TEST_ASSERT_NULL(p.cycle_counter);
    TEST_ASSERT_NULL(p.cycle_ctx);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_check(&p, &bad));
    TEST_ASSERT_NULL(bad);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_params_default(NULL));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_params_check(NULL, &bad));
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_check(&p, NULL));
}

/* Each case: one field set to one bad value, and the name expected. */
enum field {
    F_PSD, F_SX, F_SY, F_PD, F_PG, F_CLUTTER, F_RHO, F_P11, F_P21, F_EXINIT, F_CONFIRM,
    F_TERMINATE, F_MERGE, F_VMAX, F_JBIAS, F_JSTAR, F_NNJ, F_ADIST, F_ASHRINK,
    F_BLEND0, F_BLEND1, F_F1, F_F2
};

static mtt_real *field_ptr(mtt_params *p, enum field f)
{
    switch (f) {
    case F_PSD: return &p->process_psd;
    case F_SX: return &p->meas_sigma[0];
    case F_SY: return &p->meas_sigma[1];
    case F_PD: return &p->pd;
    case F_PG: return &p->pg;
    case F_CLUTTER: return &p->clutter_density;
    case F_RHO: return &p->snr_rho;
    case F_P11: return &p->markov_p11;
    case F_P21: return &p->markov_p21;
    case F_EXINIT: return &p->existence_init;
    case F_CONFIRM: return &p->confirm_threshold;
    case F_TERMINATE: return &p->terminate_threshold;
    case F_MERGE: return &p->merge_threshold;
    case F_VMAX: return &p->vmax;
    case F_JBIAS: return &p->jpda_bias;
    case F_JSTAR: return &p->jpda_star_threshold;
    case F_NNJ: return &p->nnjpda_threshold;
    case F_ADIST: return &p->adaptive_jpda_distance;
    case F_ASHRINK: return &p->adaptive_jpda_shrink;
    case F_BLEND0: return &p->intensity_blend[0];
    case F_BLEND1: return &p->intensity_blend[1];
    case F_F1: return &p->intensity_f1[1];
    case F_F2: return &p->intensity_f2[2];
    }
    return NULL;
}

struct bad_case {
    enum field f;
    double v;
    const char *name;
};

static void check_bad(enum field f, mtt_real v, const char *name)
{
    mtt_params p;
    const char *bad = NULL;
    char msg[96];
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    *field_ptr(&p, f) = v;
    snprintf(msg, sizeof msg, "%s = %g", name, (double)v);
    TEST_ASSERT_EQUAL_INT_MESSAGE(MTT_ERR_PARAM, mtt_params_check(&p, &bad), msg);
    TEST_ASSERT_NOT_NULL_MESSAGE(bad, msg);
    TEST_ASSERT_EQUAL_STRING_MESSAGE(name, bad, msg);
    /* and the tracker refuses it */
    TEST_ASSERT_EQUAL_INT_MESSAGE(MTT_ERR_PARAM, mtt_tracker_init(&trk, &p), msg);
}

static void check_good(enum field f, mtt_real v, const char *name)
{
    mtt_params p;
    const char *bad = "x";
    char msg[96];
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    *field_ptr(&p, f) = v;
    snprintf(msg, sizeof msg, "%s = %g should be valid", name, (double)v);
    TEST_ASSERT_EQUAL_INT_MESSAGE(MTT_OK, mtt_params_check(&p, &bad), msg);
    TEST_ASSERT_NULL(bad);
}

static void test_each_field_out_of_range(void)
{
    static const struct bad_case cases[] = {
        {F_PSD, -1.0, "process_psd"},
        {F_SX, 0.0, "meas_sigma"}, {F_SY, -2.0, "meas_sigma"},
        {F_PD, 0.0, "pd"}, {F_PD, 1.5, "pd"}, {F_PD, -0.1, "pd"},
        {F_PG, 0.0, "pg"}, {F_PG, 1.0, "pg"},
        {F_CLUTTER, -1e-3, "clutter_density"},
        {F_RHO, -0.5, "snr_rho"}, {F_RHO, 2e6, "snr_rho"},
        {F_P11, 1.01, "markov_p11"}, {F_P11, -0.01, "markov_p11"},
        {F_P21, 1.5, "markov_p21"}, {F_P21, -0.5, "markov_p21"},
        {F_EXINIT, 0.0, "existence_init"}, {F_EXINIT, 1.0, "existence_init"},
        {F_CONFIRM, 0.0, "confirm_threshold"}, {F_CONFIRM, 1.5, "confirm_threshold"},
        {F_TERMINATE, -0.01, "terminate_threshold"},
        {F_TERMINATE, 0.995, "terminate_threshold"}, /* = confirm_threshold */
        {F_MERGE, -1.0, "merge_threshold"},
        {F_VMAX, 0.0, "vmax"}, {F_VMAX, -60.0, "vmax"},
        {F_JBIAS, -0.1, "jpda_bias"},
        {F_JSTAR, 1.0, "jpda_star_threshold"}, {F_JSTAR, -0.1, "jpda_star_threshold"},
        {F_NNJ, 1.0, "nnjpda_threshold"}, {F_NNJ, -0.1, "nnjpda_threshold"},
        {F_ADIST, 0.0, "adaptive_jpda_distance"},
        {F_ASHRINK, 0.5, "adaptive_jpda_shrink"},
        {F_BLEND1, 150.0, "intensity_gate.blend"}, /* I_hi must exceed I_lo */
        {F_BLEND0, 300.0, "intensity_gate.blend"},
    };
    size_t k;
    for (k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        check_bad(cases[k].f, (mtt_real)cases[k].v, cases[k].name);
    }
}

static void test_each_field_nan_and_inf(void)
{
    static const struct {
        enum field f;
        const char *name;
    } fields[] = {
        {F_PSD, "process_psd"}, {F_SX, "meas_sigma"}, {F_SY, "meas_sigma"}, {F_PD, "pd"},
        {F_PG, "pg"}, {F_CLUTTER, "clutter_density"}, {F_RHO, "snr_rho"},
        {F_P11, "markov_p11"}, {F_P21, "markov_p21"}, {F_EXINIT, "existence_init"},
        {F_CONFIRM, "confirm_threshold"}, {F_TERMINATE, "terminate_threshold"},
        {F_MERGE, "merge_threshold"}, {F_VMAX, "vmax"}, {F_JBIAS, "jpda_bias"},
        {F_JSTAR, "jpda_star_threshold"}, {F_NNJ, "nnjpda_threshold"},
        {F_ADIST, "adaptive_jpda_distance"}, {F_ASHRINK, "adaptive_jpda_shrink"},
        {F_BLEND0, "intensity_gate.blend"}, {F_BLEND1, "intensity_gate.blend"},
        {F_F1, "intensity_gate.f1"}, {F_F2, "intensity_gate.f2"},
    };
    size_t k;
    for (k = 0; k < sizeof fields / sizeof fields[0]; ++k) {
        check_bad(fields[k].f, (mtt_real)NAN, fields[k].name);
        check_bad(fields[k].f, (mtt_real)INFINITY, fields[k].name);
        check_bad(fields[k].f, (mtt_real)-INFINITY, fields[k].name);
    }
}

static void test_boundary_values_accepted(void)
{
    check_good(F_CLUTTER, MTT_R(0.0), "clutter_density");
    check_good(F_RHO, MTT_R(0.0), "snr_rho");
    check_good(F_RHO, MTT_R(1e6), "snr_rho");
    check_good(F_P11, MTT_R(1.0), "markov_p11");
    check_good(F_P11, MTT_R(0.0), "markov_p11");
    check_good(F_P21, MTT_R(1.0), "markov_p21");
    check_good(F_CONFIRM, MTT_R(1.0), "confirm_threshold");
    check_good(F_TERMINATE, MTT_R(0.0), "terminate_threshold");
    check_good(F_MERGE, MTT_R(0.0), "merge_threshold");
    check_good(F_ASHRINK, MTT_R(1.0), "adaptive_jpda_shrink");
    check_good(F_F1, MTT_R(-1e9), "intensity_gate.f1");
}

static void test_first_bad_field_is_named(void)
{
    mtt_params p;
    const char *bad = NULL;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.vmax = MTT_R(-1.0);
    p.pd = MTT_R(2.0);
    p.adaptive_jpda_shrink = MTT_R(0.0);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("pd", bad);
    p.pd = MTT_R(0.9);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("vmax", bad);
    p.vmax = MTT_R(1.0);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("adaptive_jpda_shrink", bad);
    p.adaptive_jpda_shrink = MTT_R(1.0);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_check(&p, &bad));
    TEST_ASSERT_NULL(bad);
}

static void test_init_gate_and_association_range(void)
{
    mtt_params p;
    const char *bad = NULL;
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.init_gate = (mtt_init_gate)2;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("init_gate", bad);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
    p.association = MTT_ASSOC_COUNT;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("association", bad);
    p.association = (mtt_assoc)-1;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_PARAM, mtt_params_check(&p, &bad));
    TEST_ASSERT_EQUAL_STRING("association", bad);
}

static void test_supported_and_unsupported_modes(void)
{
    /* The four core modes are always built.  Any other mode is either built
     * (MTT_OK) or refused consistently: MTT_ERR_UNSUPPORTED naming
     * "association" from both mtt_params_check and mtt_tracker_init, which
     * then leaves the tracker uninitialised. */
    mtt_params p;
    const char *bad = NULL;
    int a;
    for (a = 0; a < (int)MTT_ASSOC_COUNT; ++a) {
        int core = a == MTT_ASSOC_LM_IHPDA || a == MTT_ASSOC_IHPDA ||
                   a == MTT_ASSOC_LM_IPDA || a == MTT_ASSOC_IPDA;
        mtt_status st;
        char msg[48];
        snprintf(msg, sizeof msg, "association %d", a);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_params_default(&p));
        p.association = (mtt_assoc)a;
        bad = "x";
        st = mtt_params_check(&p, &bad);
        if (core) {
            TEST_ASSERT_EQUAL_INT_MESSAGE(MTT_OK, st, msg);
        }
        if (st == MTT_OK) {
            TEST_ASSERT_NULL_MESSAGE(bad, msg);
            TEST_ASSERT_EQUAL_INT_MESSAGE(MTT_OK, mtt_tracker_init(&trk, &p), msg);
            TEST_ASSERT_TRUE(TV_MAGIC(&trk) == MTT_MAGIC);
        } else {
            /* a mode this build does not know at all (MTT_ASSOC_ROWS): out of range */
            const mtt_status want = a < MTT_ASSOC_ROWS ? MTT_ERR_UNSUPPORTED : MTT_ERR_PARAM;
            TEST_ASSERT_EQUAL_INT_MESSAGE(want, st, msg);
            TEST_ASSERT_EQUAL_STRING_MESSAGE("association", bad, msg);
            memset(&trk, 0, sizeof trk);
            TEST_ASSERT_EQUAL_INT_MESSAGE(want, mtt_tracker_init(&trk, &p), msg);
            TEST_ASSERT_TRUE(TV_MAGIC(&trk) != MTT_MAGIC); /* left uninitialised */
        }
    }
}

static void test_assoc_names_round_trip(void)
{
    static const char *const names[MTT_ASSOC_COUNT] = {
        "lm-ihpda", "ihpda", "lm-ipda", "ipda", "ihpda-2d", "jipda", "jpda",
        "cheap-jpda", "suboptimal-jpda", "nnjpda", "jpda-star", "adaptive-jpda",
        "lm-ipda-all", "jpda-vg", "adaptive-nnjpda", "adaptive-jpda-star"}; /* docs/FORMATS.md */
    int a;
    for (a = 0; a < (int)MTT_ASSOC_COUNT; ++a) {
        const char *name = NULL;
        mtt_assoc back = (mtt_assoc)-1;
        if (a >= MTT_ASSOC_ROWS) { /* the last four without the baselines: unknown */
            TEST_ASSERT_EQUAL_INT(MTT_ERR_RANGE, mtt_assoc_name((mtt_assoc)a, &name));
            TEST_ASSERT_EQUAL_INT(MTT_ERR_RANGE, mtt_assoc_parse(names[a], &back));
            continue;
        }
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_assoc_name((mtt_assoc)a, &name));
        TEST_ASSERT_EQUAL_STRING(names[a], name);
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_assoc_parse(name, &back));
        TEST_ASSERT_EQUAL_INT(a, back);
    }
}

static void test_assoc_errors(void)
{
    const char *name = "keep";
    mtt_assoc a = MTT_ASSOC_IPDA;
    TEST_ASSERT_EQUAL_INT(MTT_ERR_RANGE, mtt_assoc_parse("LM-IHPDA", &a)); /* case matters */
    TEST_ASSERT_EQUAL_INT(MTT_ERR_RANGE, mtt_assoc_parse("", &a));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_RANGE, mtt_assoc_parse("lm-ihpda ", &a));
    TEST_ASSERT_EQUAL_INT(MTT_ASSOC_IPDA, a); /* unchanged */
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_assoc_parse(NULL, &a));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_assoc_parse("ipda", NULL));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_RANGE, mtt_assoc_name(MTT_ASSOC_COUNT, &name));
    TEST_ASSERT_EQUAL_STRING("keep", name);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_assoc_name(MTT_ASSOC_IPDA, NULL));
}

static void test_status_text(void)
{
    const char *t = NULL;
    int s;
    for (s = 0; s >= (int)MTT_ERR_CONFIG; --s) {
        t = NULL;
        TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_status_text((mtt_status)s, &t));
        TEST_ASSERT_NOT_NULL(t);
        TEST_ASSERT_TRUE(strlen(t) > 0u);
    }
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_status_text(MTT_OK, &t));
    TEST_ASSERT_EQUAL_STRING("ok", t);
    TEST_ASSERT_EQUAL_INT(MTT_OK, mtt_status_text(MTT_ERR_CONFIG, &t));
    TEST_ASSERT_EQUAL_STRING("configuration mismatch", t);
    TEST_ASSERT_EQUAL_INT(MTT_ERR_RANGE, mtt_status_text((mtt_status)1, &t));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_RANGE, mtt_status_text((mtt_status)-10, &t));
    TEST_ASSERT_EQUAL_INT(MTT_ERR_NULL, mtt_status_text(MTT_OK, NULL));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_defaults_match_formats_table);
    RUN_TEST(test_each_field_out_of_range);
    RUN_TEST(test_each_field_nan_and_inf);
    RUN_TEST(test_boundary_values_accepted);
    RUN_TEST(test_first_bad_field_is_named);
    RUN_TEST(test_init_gate_and_association_range);
    RUN_TEST(test_supported_and_unsupported_modes);
    RUN_TEST(test_assoc_names_round_trip);
    RUN_TEST(test_assoc_errors);
    RUN_TEST(test_status_text);
    return UNITY_END();
}
